// Font glyphs as curves (io/glyph.hpp): FreeType opens the font, maps characters to
// glyphs, gives the unscaled outlines (FT_Outline_Decompose) and the pair kerning.
#include "casteljau/io/glyph.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_FONT_FORMATS_H

#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
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
  run.kerning = FT_HAS_KERNING(face.get());
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

  double pen = 0;
  FT_UInt previous = 0;
  for (std::size_t i = 0; i < chars.size(); ++i) {
    const auto& [cp, bytes] = chars[i];
    const FT_UInt index = FT_Get_Char_Index(face.get(), cp);
    const std::string where = "text[" + std::to_string(i) + "]";
    if (index == 0) throw InvalidArgument(where, "character " + code_point_name(cp) + " is not in the font");
    if (previous != 0 && run.kerning) {
      FT_Vector k{};
      if (FT_Get_Kerning(face.get(), previous, index, FT_KERNING_UNSCALED, &k) == 0) pen += scale * static_cast<double>(k.x);
    }
    if (FT_Load_Glyph(face.get(), index, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
        face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
      throw InvalidArgument(where, "the font's glyph for character " + code_point_name(cp) + " could not be read as an outline");
    }
    Reader r;
    r.scale = scale;
    r.origin = P2(pen, 0);
    r.degree = degree;
    if (FT_Outline_Decompose(&face->glyph->outline, &funcs, &r) != 0) {
      throw InvalidArgument(where, "the font's outline for character " + code_point_name(cp) + " is malformed");
    }
    close_contours(r);
    GlyphOutline g;
    g.character = bytes;
    g.origin = P2(pen, 0);
    // The unrounded advance: 16.16 fixed point in pixels, here font units.
    g.advance = scale * (static_cast<double>(face->glyph->linearHoriAdvance) / 65536);
    g.contours = std::move(r.contours);
    pen += g.advance;
    previous = index;
    run.glyphs.push_back(std::move(g));
  }
  return run;
}

}  // namespace casteljau::io
