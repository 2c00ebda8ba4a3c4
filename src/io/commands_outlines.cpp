// The outline interchange commands of issue 17 going out of casteljau's curves and in from
// fonts: to_svg_path (any 2-D curve as SVG path data) and glyph (a text's outlines from a
// font file). Each is one entry of the registry (io/commands.hpp); the io functions are
// in io/svg_path.hpp and io/glyph.hpp. Examples are real responses (tests/cli).
#include <optional>
#include <string>

#include "casteljau/io/glyph.hpp"
#include "casteljau/io/json.hpp"
#include "casteljau/io/svg_path.hpp"
#include "commands_family.hpp"

namespace casteljau::io::detail {

namespace {

Response to_svg_path(const Args& a) {
  const SvgPathData p = io::to_svg_path(a.curve("curve"), a.optional_number("tolerance"));
  OrderedJson r;
  r["d"] = p.d;
  r["exact"] = p.exact;
  r["max_deviation"] = p.max_deviation;
  r["cubics"] = p.cubics;
  return {r};
}

constexpr Field to_svg_path_fields[] = {
    {"curve", FieldType::curve, true, {}, "a 2-D curve"},
    {"tolerance", FieldType::number, false, {},
     "> 0: how far (at equal parameters) an approximating cubic may stray; required when a piece has no exact SVG form"},
};

Response glyph(const Args& a) {
  const GlyphRun run = io::glyph_outlines(a.string("font"), a.string("text"), a.optional_number("size"));
  OrderedJson glyphs = OrderedJson::array();
  for (const GlyphOutline& g : run.glyphs) {
    OrderedJson j;
    j["char"] = g.character;
    j["origin"] = to_json(g.origin);
    j["advance"] = g.advance;
    if (g.contours.empty()) {
      j["curve"] = nullptr;
    } else {
      // The pieces through the curve writer; the two path levels are built here, as a
      // Path is flat (the writer would splice the contours into one path with breaks,
      // where the answer is a path of closed contour paths on the default breaks).
      OrderedJson contours = OrderedJson::array();
      for (const auto& contour : g.contours) {
        OrderedJson segments = OrderedJson::array();
        for (const auto& b : contour) segments.push_back(to_json(AnyCurve(b)));
        OrderedJson c;
        c["type"] = "path";
        c["segments"] = std::move(segments);
        contours.push_back(std::move(c));
      }
      OrderedJson curve;
      curve["type"] = "path";
      curve["segments"] = std::move(contours);
      j["curve"] = std::move(curve);
    }
    glyphs.push_back(std::move(j));
  }
  OrderedJson r;
  r["glyphs"] = std::move(glyphs);
  r["units_per_em"] = run.units_per_em;
  r["format"] = run.format;
  r["kerning"] = run.kerning;
  return {r};
}

constexpr Field glyph_fields[] = {
    {"font", FieldType::string, true, {}, "the path of a TrueType, OpenType/CFF or Type 1 font file (read only)"},
    {"text", FieldType::string, true, {}, "the characters (UTF-8, one line, at most 10000), each in the font"},
    {"size", FieldType::number, false, {}, "> 0: the em size in output units (default: the font's design units)"},
};

constexpr Command outline_family[] = {
    {"to_svg_path", "A 2-D curve as SVG path data (exact where SVG can hold it)",
     "The curve's exact Bezier pieces as SVG path data: degree 0..3 as M, L, Q, C; a rational\n"
     "quadratic that is an elliptical arc (middle weight < 1 in standard form) as A with its\n"
     "radii, rotation and flags (split in two beyond about 91 degrees); a parabolic one as Q.\n"
     "Every other piece (degree > 3, general rational, hyperbolic arcs) needs `tolerance`: it\n"
     "becomes Hermite cubics, each reaching as far along the piece as the tolerance allows\n"
     "(distance at equal parameters, measured). Pieces that meet (within 1e-12 of the curve's\n"
     "size) continue the subpath, a gap starts a new one (M); a subpath that ends at its\n"
     "start is closed with Z. Numbers in shortest round-trip form.",
     "d: the path data; exact: true when no piece was approximated; max_deviation: the\n"
     "          largest measured distance of a cubic from its piece (0 when exact); cubics:\n"
     "          how many approximating cubics were written",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}}' | casteljau to_svg_path
  {"d":"M 0 0 C 1 2 3 2 4 0","exact":true,"max_deviation":0.0,"cubics":0})",
     to_svg_path_fields, to_svg_path},
    {"glyph", "The outlines of a text's characters in a font file, laid out",
     "Reads the font with FreeType (TrueType, OpenType/CFF, Type 1; face 0) and gives each\n"
     "character's unhinted outline: one closed path per contour, of quadratic pieces for\n"
     "TrueType and cubic ones for CFF and Type 1 (straight edges elevated), in design\n"
     "coordinates (y up) times size / unitsPerEm, at its pen position on the baseline. The pen\n"
     "moves by each advance plus the pair kerning: the GPOS `kern` feature (HarfBuzz, nothing\n"
     "else of shaping: one glyph per character), else the `kern` table, else a Type 1 font's\n"
     "AFM file beside it. A character the font lacks is an error (no .notdef box). The font\n"
     "file is only read.",
     "glyphs: [{char, origin, advance, curve (a path of closed contour paths; null for a\n"
     "          blank)}]; units_per_em, format (FreeType's name: TrueType, CFF, Type 1),\n"
     "          kerning (whether the font has pair kerning that is read)",
     R"(  echo '{"font": "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "text": " "}' | casteljau glyph
  {"glyphs":[{"char":" ","origin":[0.0,0.0],"advance":651.0,"curve":null}],"units_per_em":2048,"format":"TrueType","kerning":true})",
     glyph_fields, glyph, "font", ""},
};

}  // namespace

std::span<const Command> outline_commands() { return outline_family; }

}  // namespace casteljau::io::detail
