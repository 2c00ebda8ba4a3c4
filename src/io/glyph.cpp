// Font glyphs as curves (io/glyph.hpp): FreeType opens the font, maps characters to
// glyphs and gives the unscaled outlines (FT_Outline_Decompose); the pair kerning comes
// from GPOS's `kern` feature through HarfBuzz, else from FreeType (the `kern` table, a
// Type 1 font's AFM file).
#include "casteljau/io/glyph.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_FONT_FORMATS_H
#include <hb-ot.h>
#include <hb.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace casteljau::io {

namespace {

using casteljau::detail::format_number;
using P2 = Point<double, 2>;

/// The most characters one request may lay out.
constexpr std::size_t max_characters = 10000;

struct LibraryCloser {
  void operator()(FT_Library l) const { FT_Done_FreeType(l); }
};
struct FaceCloser {
  void operator()(FT_Face f) const { FT_Done_Face(f); }
};

/// The code points of UTF-8 text, each with its bytes; throws InvalidArgument("text") at
/// the first ill-formed sequence (overlong forms, surrogates and values past U+10FFFF
/// included, as RFC 3629 says).
std::vector<std::pair<char32_t, std::string>> decode_utf8(const std::string& s) {
  std::vector<std::pair<char32_t, std::string>> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b0 = byte(i);
    int n = 0;
    char32_t cp = 0, min = 0;
    if (b0 < 0x80) {
      n = 1;
      cp = b0;
    } else if ((b0 & 0xE0) == 0xC0) {
      n = 2;
      cp = b0 & 0x1F;
      min = 0x80;
    } else if ((b0 & 0xF0) == 0xE0) {
      n = 3;
      cp = b0 & 0x0F;
      min = 0x800;
    } else if ((b0 & 0xF8) == 0xF0) {
      n = 4;
      cp = b0 & 0x07;
      min = 0x10000;
    } else {
      throw InvalidArgument("text", "not UTF-8: byte " + std::to_string(i) + " cannot start a character");
    }
    if (i + static_cast<std::size_t>(n) > s.size()) throw InvalidArgument("text", "not UTF-8: the character at byte " + std::to_string(i) + " is cut off");
    for (int k = 1; k < n; ++k) {
      const unsigned char b = byte(i + static_cast<std::size_t>(k));
      if ((b & 0xC0) != 0x80) throw InvalidArgument("text", "not UTF-8: byte " + std::to_string(i + static_cast<std::size_t>(k)) + " should continue a character");
      cp = (cp << 6) | (b & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
      throw InvalidArgument("text", "not UTF-8: the sequence at byte " + std::to_string(i) + " is not a valid character");
    }
    out.emplace_back(cp, s.substr(i, static_cast<std::size_t>(n)));
    i += static_cast<std::size_t>(n);
  }
  return out;
}

std::string code_point_name(char32_t cp) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
  return buf;
}

/// The outline being read by FT_Outline_Decompose's callbacks.
struct Reader {
  double scale = 1;
  P2 origin;
  int degree = 2;  ///< of every piece: straight edges (and conics in a cubic font) are elevated
  std::vector<std::vector<Bezier<double, 2>>> contours;
  P2 current;  ///< in font units

  [[nodiscard]] P2 place(const P2& p) const { return P2(origin[0] + scale * p[0], origin[1] + scale * p[1]); }

  void piece(std::vector<P2> P) {
    if (contours.empty()) return;  // FreeType always moves first; defensive
    current = P.back();
    bool moves = false;
    for (const P2& q : P) moves = moves || q != P.front();
    if (!moves) return;  // a zero-length edge adds nothing
    for (P2& q : P) q = place(q);
    Bezier<double, 2> b(std::move(P));
    while (b.degree() < degree) b = b.elevate(1);
    contours.back().push_back(std::move(b));
  }
};

/// A point of the outline in font units: FreeType gives 26.6 fixed point at one pixel per
/// font unit (see glyph_outlines), so 1/64 is exact.
P2 point(const FT_Vector* v) { return P2(static_cast<double>(v->x) / 64, static_cast<double>(v->y) / 64); }
Reader& reader(void* user) { return *static_cast<Reader*>(user); }

int move_to(const FT_Vector* to, void* user) {
  Reader& r = reader(user);
  r.contours.emplace_back();
  r.current = point(to);
  return 0;
}
int line_to(const FT_Vector* to, void* user) {
  Reader& r = reader(user);
  r.piece({r.current, point(to)});
  return 0;
}
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
  Reader& r = reader(user);
  r.piece({r.current, point(control), point(to)});
  return 0;
}
int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  Reader& r = reader(user);
  r.piece({r.current, point(c1), point(c2), point(to)});
  return 0;
}

/// Closes every contour exactly (an edge back to its start when it ends elsewhere) and
/// drops the empty ones.
void close_contours(Reader& r) {
  std::vector<std::vector<Bezier<double, 2>>> kept;
  for (auto& c : r.contours) {
    if (c.empty()) continue;
    const P2 start = c.front().points().front(), end = c.back().points().back();
    if (start != end) {
      Bezier<double, 2> b(std::vector<P2>{end, start});
      while (b.degree() < r.degree) b = b.elevate(1);
      c.push_back(std::move(b));
    }
    kept.push_back(std::move(c));
  }
  r.contours = std::move(kept);
}

FT_Face open_face(FT_Library lib, const std::string& path) {
  if (path.empty()) throw InvalidArgument("font", "the font file's path is empty");
  if (path.find('\0') != std::string::npos) throw InvalidArgument("font", "the font file's path contains a NUL character");
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw InvalidArgument("font", "no such file: '" + path + "'");
  if (!std::filesystem::is_regular_file(status)) throw InvalidArgument("font", "not a regular file: '" + path + "'");
  FT_Face face = nullptr;
  const FT_Error e = FT_New_Face(lib, path.c_str(), 0, &face);
  if (e == FT_Err_Unknown_File_Format) {
    throw InvalidArgument("font", "not a font file that FreeType reads (TrueType, OpenType/CFF, Type 1): '" + path + "'");
  }
  if (e != 0) throw InvalidArgument("font", "FreeType could not open '" + path + "' (FreeType error " + std::to_string(e) + ")");
  return face;
}


// ---------------------------------------------------------------------------------------
// GPOS pair kerning through HarfBuzz.
//
// HarfBuzz shapes, and shaping may change the glyph sequence (ligatures, contextual forms,
// Unicode composition and decomposition, mark reordering, hidden default-ignorables,
// inserted dotted circles). The response is one glyph per character, so HarfBuzz is given
// a view of the font and of Unicode in which none of that can happen, and only positions:
// - the face hides GSUB and AAT morx/mort (no substitution at all) and every kerning
//   source other than GPOS (the `kern`, `kerx` and `trak` tables: FreeType reads `kern`
//   when the font has no GPOS kern feature);
// - the font maps each character to FreeType's glyph for it, and no variation sequence to
//   a variant glyph;
// - the Unicode functions neither compose, decompose nor reorder marks;
// - the buffer keeps default-ignorables and inserts no dotted circle; each glyph keeps its
//   character's index as its cluster (cluster level "characters": no merging).
// Each script run is shaped twice, with only the `kern` feature and with nothing (every
// other positioning feature off in both: mark, mkmk, curs, dist, abvm, blwm): the
// differences of the x advances and x offsets are the kern feature's adjustments, whatever
// else HarfBuzz does the same in both (mark widths zeroed by GDEF class, a script's
// required feature). Positions are in font units (the font's scale is unitsPerEm), so
// GPOS's integer values come through exactly.

template <class T, void (*destroy)(T*)>
struct HbDestroy {
  void operator()(T* p) const { destroy(p); }
};
template <class T, void (*destroy)(T*)>
using HbPtr = std::unique_ptr<T, HbDestroy<T, destroy>>;

/// The kern feature's adjustment of one glyph, in font units: `after` is added to the pen
/// after its advance, `shift` moves the glyph alone along the baseline.
struct PairAdjustment {
  double after = 0;
  double shift = 0;
};

constexpr hb_tag_t kern_tag = HB_TAG('k', 'e', 'r', 'n');

bool font_has_gpos_kern(hb_face_t* face) {
  unsigned count = hb_ot_layout_table_get_feature_tags(face, HB_OT_TAG_GPOS, 0, nullptr, nullptr);
  std::vector<hb_tag_t> tags(count);
  hb_ot_layout_table_get_feature_tags(face, HB_OT_TAG_GPOS, 0, &count, tags.data());
  tags.resize(count);
  return std::find(tags.begin(), tags.end(), kern_tag) != tags.end();
}

hb_blob_t* visible_table(hb_face_t*, hb_tag_t tag, void* font_face) {
  constexpr hb_tag_t hidden[] = {HB_OT_TAG_GSUB,         HB_TAG('m', 'o', 'r', 'x'), HB_TAG('m', 'o', 'r', 't'),
                                 HB_TAG('k', 'e', 'r', 'n'), HB_TAG('k', 'e', 'r', 'x'), HB_TAG('t', 'r', 'a', 'k')};
  if (std::find(std::begin(hidden), std::end(hidden), tag) != std::end(hidden)) return hb_blob_get_empty();
  return hb_face_reference_table(static_cast<hb_face_t*>(font_face), tag);
}

/// FreeType's glyph of each character of the text, sorted by character (the font data of
/// the HarfBuzz font's nominal-glyph function).
using GlyphMap = std::vector<std::pair<hb_codepoint_t, hb_codepoint_t>>;

hb_bool_t nominal_glyph(hb_font_t*, void* font_data, hb_codepoint_t unicode, hb_codepoint_t* glyph, void*) {
  const auto& map = *static_cast<const GlyphMap*>(font_data);
  const auto it = std::lower_bound(map.begin(), map.end(), std::pair<hb_codepoint_t, hb_codepoint_t>(unicode, 0));
  if (it == map.end() || it->first != unicode) return false;
  *glyph = it->second;
  return true;
}
hb_bool_t no_variation_glyph(hb_font_t*, void*, hb_codepoint_t, hb_codepoint_t, hb_codepoint_t*, void*) { return false; }
hb_bool_t no_compose(hb_unicode_funcs_t*, hb_codepoint_t, hb_codepoint_t, hb_codepoint_t*, void*) { return false; }
hb_bool_t no_decompose(hb_unicode_funcs_t*, hb_codepoint_t, hb_codepoint_t*, hb_codepoint_t*, void*) { return false; }
hb_unicode_combining_class_t not_reordered(hb_unicode_funcs_t*, hb_codepoint_t, void*) {
  return HB_UNICODE_COMBINING_CLASS_NOT_REORDERED;
}

/// A run of characters [begin, end) of one script; characters of no script of their own
/// (common, inherited, unknown: spaces, digits, punctuation, combining marks) join the run
/// they are in, HB_SCRIPT_INVALID when it has no script (HarfBuzz's default script then).
struct ScriptRun {
  std::size_t begin = 0, end = 0;
  hb_script_t script = HB_SCRIPT_INVALID;
};

std::vector<ScriptRun> script_runs(const std::vector<hb_codepoint_t>& text, hb_unicode_funcs_t* unicode) {
  std::vector<ScriptRun> runs;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const hb_script_t s = hb_unicode_script(unicode, text[i]);
    const bool own = s != HB_SCRIPT_COMMON && s != HB_SCRIPT_INHERITED && s != HB_SCRIPT_UNKNOWN;
    if (!runs.empty() && (!own || s == runs.back().script || runs.back().script == HB_SCRIPT_INVALID)) {
      runs.back().end = i + 1;
      if (own) runs.back().script = s;
      continue;
    }
    runs.push_back({i, i + 1, own ? s : HB_SCRIPT_INVALID});
  }
  return runs;
}

/// HarfBuzz's x advance and x offset of each glyph of the run (font units, by character
/// index), with the kern feature on or off, shaped as `script` (the run's, or Common with
/// `language` naming the run's OpenType script tag, see gpos_kerning); false when HarfBuzz
/// did not answer one glyph per character with FreeType's glyphs (a script shaper that
/// rewrites the text itself: Thai's SARA AM, Hangul jamo composed into a syllable).
bool shape_run(hb_font_t* font, hb_unicode_funcs_t* unicode, const std::vector<hb_codepoint_t>& text,
               const std::vector<FT_UInt>& glyphs, const ScriptRun& run, hb_script_t script, hb_language_t language, bool kern,
               std::vector<hb_position_t>& advance, std::vector<hb_position_t>& offset) {
  const HbPtr<hb_buffer_t, hb_buffer_destroy> buffer(hb_buffer_create());
  hb_buffer_set_unicode_funcs(buffer.get(), unicode);
  hb_buffer_set_flags(buffer.get(), static_cast<hb_buffer_flags_t>(HB_BUFFER_FLAG_PRESERVE_DEFAULT_IGNORABLES |
                                                                   HB_BUFFER_FLAG_DO_NOT_INSERT_DOTTED_CIRCLE));
  hb_buffer_set_cluster_level(buffer.get(), HB_BUFFER_CLUSTER_LEVEL_CHARACTERS);
  hb_buffer_set_direction(buffer.get(), HB_DIRECTION_LTR);
  hb_buffer_set_script(buffer.get(), script);
  // The whole text is the context (clusters are indices into it); the language is left
  // unset (or holds only a script tag), so the script's default language system applies
  // whatever the process locale.
  hb_buffer_set_language(buffer.get(), language);
  hb_buffer_add_codepoints(buffer.get(), text.data(), static_cast<int>(text.size()), static_cast<unsigned>(run.begin),
                           static_cast<int>(run.end - run.begin));
  const auto feature = [](hb_tag_t tag, bool on) {
    return hb_feature_t{tag, on ? 1u : 0u, HB_FEATURE_GLOBAL_START, HB_FEATURE_GLOBAL_END};
  };
  const hb_feature_t features[] = {feature(kern_tag, kern),
                                   feature(HB_TAG('m', 'a', 'r', 'k'), false),
                                   feature(HB_TAG('m', 'k', 'm', 'k'), false),
                                   feature(HB_TAG('c', 'u', 'r', 's'), false),
                                   feature(HB_TAG('d', 'i', 's', 't'), false),
                                   feature(HB_TAG('a', 'b', 'v', 'm'), false),
                                   feature(HB_TAG('b', 'l', 'w', 'm'), false)};
  hb_shape(font, buffer.get(), features, static_cast<unsigned>(std::size(features)));
  unsigned count = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buffer.get(), &count);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buffer.get(), nullptr);
  if (count != run.end - run.begin) return false;
  std::vector<bool> seen(count, false);
  for (unsigned k = 0; k < count; ++k) {
    const std::size_t i = info[k].cluster;
    if (i < run.begin || i >= run.end || seen[i - run.begin] || info[k].codepoint != glyphs[i]) return false;
    seen[i - run.begin] = true;
    advance[i] = pos[k].x_advance;
    offset[i] = pos[k].x_offset;
  }
  return true;
}

/// The GPOS `kern` feature's adjustment of each glyph of the text (`glyphs`: FreeType's
/// glyph of each character), in font units; nullopt when the font (face 0 of the file)
/// has no GPOS kern feature or HarfBuzz cannot read the file.
std::optional<std::vector<PairAdjustment>> gpos_kerning(const std::string& font_path,
                                                        const std::vector<hb_codepoint_t>& text,
                                                        const std::vector<FT_UInt>& glyphs) {
  const HbPtr<hb_blob_t, hb_blob_destroy> blob(hb_blob_create_from_file_or_fail(font_path.c_str()));
  if (!blob) return std::nullopt;
  hb_face_t* const whole = hb_face_create(blob.get(), 0);
  if (!font_has_gpos_kern(whole)) {
    hb_face_destroy(whole);
    return std::nullopt;
  }
  // The visible face owns `whole` from here (destroyed with it).
  const HbPtr<hb_face_t, hb_face_destroy> face(hb_face_create_for_tables(
      visible_table, whole, [](void* f) { hb_face_destroy(static_cast<hb_face_t*>(f)); }));
  GlyphMap map;
  for (std::size_t i = 0; i < text.size(); ++i) map.emplace_back(text[i], glyphs[i]);
  std::sort(map.begin(), map.end());
  map.erase(std::unique(map.begin(), map.end()), map.end());

  const HbPtr<hb_font_t, hb_font_destroy> parent(hb_font_create(face.get()));  // OpenType metrics, scale unitsPerEm
  const HbPtr<hb_font_t, hb_font_destroy> font(hb_font_create_sub_font(parent.get()));
  const HbPtr<hb_font_funcs_t, hb_font_funcs_destroy> font_funcs(hb_font_funcs_create());
  hb_font_funcs_set_nominal_glyph_func(font_funcs.get(), nominal_glyph, nullptr, nullptr);
  hb_font_funcs_set_variation_glyph_func(font_funcs.get(), no_variation_glyph, nullptr, nullptr);
  hb_font_funcs_make_immutable(font_funcs.get());
  hb_font_set_funcs(font.get(), font_funcs.get(), &map, nullptr);

  const HbPtr<hb_unicode_funcs_t, hb_unicode_funcs_destroy> unicode(hb_unicode_funcs_create(hb_unicode_funcs_get_default()));
  hb_unicode_funcs_set_compose_func(unicode.get(), no_compose, nullptr, nullptr);
  hb_unicode_funcs_set_decompose_func(unicode.get(), no_decompose, nullptr, nullptr);
  hb_unicode_funcs_set_combining_class_func(unicode.get(), not_reordered, nullptr, nullptr);
  hb_unicode_funcs_make_immutable(unicode.get());

  std::vector<PairAdjustment> adjust(text.size());
  std::vector<hb_position_t> advance_on(text.size()), offset_on(text.size()), advance_off(text.size()), offset_off(text.size());
  const auto shaped = [&](const ScriptRun& run, hb_script_t script, hb_language_t language) {
    return shape_run(font.get(), unicode.get(), text, glyphs, run, script, language, true, advance_on, offset_on) &&
           shape_run(font.get(), unicode.get(), text, glyphs, run, script, language, false, advance_off, offset_off);
  };
  for (const ScriptRun& run : script_runs(text, unicode.get())) {
    if (!shaped(run, run.script, HB_LANGUAGE_INVALID)) {
      // The script's own shaper rewrote the text (Thai decomposes SARA AM into NIKHAHIT
      // and SARA AA; Hangul composes conjoining jamo into a syllable the text also holds).
      // Those steps belong to the script's shaper, not to its GPOS lookups: the run is
      // shaped again by HarfBuzz's default shaper (script Common), with the OpenType
      // script tag the script's shaper would have used (the first of the script's tags
      // that the font's GPOS lists) passed as HarfBuzz's private language subtag
      // "x-hbsc<tag>", so that the same kern lookups of the same language system apply.
      unsigned count = HB_OT_MAX_TAGS_PER_SCRIPT;
      hb_tag_t tags[HB_OT_MAX_TAGS_PER_SCRIPT];
      hb_ot_tags_from_script_and_language(run.script, HB_LANGUAGE_INVALID, &count, tags, nullptr, nullptr);
      unsigned index = 0;
      hb_tag_t chosen = HB_OT_TAG_DEFAULT_SCRIPT;
      hb_ot_layout_table_select_script(face.get(), HB_OT_TAG_GPOS, count, tags, &index, &chosen);
      char tag[5] = {};
      hb_tag_to_string(chosen, tag);
      const std::string private_tag = "x-hbsc" + std::string(tag);
      if (!shaped(run, HB_SCRIPT_COMMON, hb_language_from_string(private_tag.c_str(), -1))) {
        continue;  // this run is laid out without kerning
      }
    }
    for (std::size_t i = run.begin; i < run.end; ++i) {
      adjust[i].after = advance_on[i] - advance_off[i];
      adjust[i].shift = offset_on[i] - offset_off[i];
    }
  }
  return adjust;
}

}  // namespace

GlyphRun glyph_outlines(const std::string& font_path, const std::string& text, std::optional<double> size) {
  if (size) {
    require_finite(*size, "size");
    if (!(*size > 0)) throw InvalidArgument("size", "must be > 0, got " + format_number(*size));
  }
  const auto chars = decode_utf8(text);
  if (chars.size() > max_characters) {
    throw InvalidArgument("text", "at most " + std::to_string(max_characters) + " characters, got " + std::to_string(chars.size()));
  }
  FT_Library raw_lib = nullptr;
  if (FT_Init_FreeType(&raw_lib) != 0) throw std::runtime_error("FreeType could not start");
  const std::unique_ptr<FT_LibraryRec_, LibraryCloser> lib(raw_lib);
  const std::unique_ptr<FT_FaceRec_, FaceCloser> face(open_face(lib.get(), font_path));
  if (!FT_IS_SCALABLE(face.get()) || face->units_per_EM == 0) {
    throw InvalidArgument("font", "the font has no outlines (a bitmap font): '" + font_path + "'");
  }
  GlyphRun run;
  run.format = FT_Get_Font_Format(face.get()) ? FT_Get_Font_Format(face.get()) : "";
  run.units_per_em = face->units_per_EM;
  if (run.format == "Type 1") {
    // Type 1 kerning lives in the AFM file beside the font (same name, .afm): attached
    // when it is there; a failure leaves the font without kerning.
    std::filesystem::path afm(font_path);
    afm.replace_extension(".afm");
    std::error_code ec;
    if (std::filesystem::is_regular_file(afm, ec)) FT_Attach_File(face.get(), afm.c_str());
  }
  // One pixel per font unit: FreeType's scale is then exactly 64 (26.6 fixed point per
  // unit), so outlines come in font units with 1/64 resolution. Not FT_LOAD_NO_SCALE:
  // unscaled, FT_Outline_Decompose computes TrueType's implied on-curve points (the
  // midpoints of two off-curve points) in integers and truncates half units; at 64 steps
  // per unit they are exact.
  if (FT_Set_Char_Size(face.get(), 0, static_cast<FT_F26Dot6>(face->units_per_EM) * 64, 72, 72) != 0) {
    throw InvalidArgument("font", "FreeType cannot scale the font's outlines: '" + font_path + "'");
  }
  const double scale = size ? *size / face->units_per_EM : 1.0;
  const int degree = run.format == "TrueType" ? 2 : 3;

  FT_Outline_Funcs funcs{};
  funcs.move_to = move_to;
  funcs.line_to = line_to;
  funcs.conic_to = conic_to;
  funcs.cubic_to = cubic_to;

  std::vector<hb_codepoint_t> code_points;
  std::vector<FT_UInt> indices;
  for (std::size_t i = 0; i < chars.size(); ++i) {
    const char32_t cp = chars[i].first;
    const FT_UInt index = FT_Get_Char_Index(face.get(), cp);
    if (index == 0) throw InvalidArgument("text[" + std::to_string(i) + "]", "character " + code_point_name(cp) + " is not in the font");
    code_points.push_back(cp);
    indices.push_back(index);
  }
  // Pair kerning: GPOS's kern feature when the font has one; else what FreeType reads (the
  // `kern` table, or the AFM file attached above), in font units after each glyph.
  std::optional<std::vector<PairAdjustment>> adjust;
  if (FT_IS_SFNT(face.get())) adjust = gpos_kerning(font_path, code_points, indices);
  run.kerning = adjust.has_value() || FT_HAS_KERNING(face.get());
  if (!adjust) {
    adjust.emplace(chars.size());
    if (FT_HAS_KERNING(face.get())) {
      for (std::size_t i = 0; i + 1 < chars.size(); ++i) {
        FT_Vector k{};
        if (FT_Get_Kerning(face.get(), indices[i], indices[i + 1], FT_KERNING_UNSCALED, &k) == 0) (*adjust)[i].after = static_cast<double>(k.x);
      }
    }
  }

  double pen = 0;
  for (std::size_t i = 0; i < chars.size(); ++i) {
    const auto& [cp, bytes] = chars[i];
    const FT_UInt index = indices[i];
    const std::string where = "text[" + std::to_string(i) + "]";
    if (i > 0) pen += scale * (*adjust)[i - 1].after;
    // A glyph the kern feature moves (a second glyph's x placement) moves alone.
    const double x = (*adjust)[i].shift != 0 ? pen + scale * (*adjust)[i].shift : pen;
    if (FT_Load_Glyph(face.get(), index, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
        face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
      throw InvalidArgument(where, "the font's glyph for character " + code_point_name(cp) + " could not be read as an outline");
    }
    Reader r;
    r.scale = scale;
    r.origin = P2(x, 0);
    r.degree = degree;
    if (FT_Outline_Decompose(&face->glyph->outline, &funcs, &r) != 0) {
      throw InvalidArgument(where, "the font's outline for character " + code_point_name(cp) + " is malformed");
    }
    close_contours(r);
    GlyphOutline g;
    g.character = bytes;
    g.origin = P2(x, 0);
    // The unrounded advance: 16.16 fixed point in pixels, here font units.
    g.advance = scale * (static_cast<double>(face->glyph->linearHoriAdvance) / 65536);
    g.contours = std::move(r.contours);
    pen += g.advance;
    run.glyphs.push_back(std::move(g));
  }
  return run;
}

}  // namespace casteljau::io
