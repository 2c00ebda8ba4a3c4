// Font glyphs as curves (issue 17): the outlines of a text's characters read with FreeType
// (TrueType, OpenType/CFF, Type 1), laid out along a baseline with the font's pair
// kerning. Compiled once, in src/io/glyph.cpp (FreeType and HarfBuzz are private
// dependencies of casteljau::io).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "casteljau/curves/bezier.hpp"

namespace casteljau::io {

/// One character of the text, placed.
struct GlyphOutline {
  std::string character;         ///< the character (UTF-8)
  Point<double, 2> origin;       ///< its pen position on the baseline (y = 0)
  double advance = 0;            ///< its advance width (scaled; kerning is in the next origin)
  /// Its contours, each closed (the last piece ends where the first starts), of Bézier
  /// pieces all of one degree: 2 for TrueType outlines, 3 for CFF and Type 1 (straight
  /// edges elevated), in the font's design coordinates (y up) times the scale, moved to
  /// origin. Orientation as in the font (TrueType outer contours clockwise, CFF and
  /// Type 1 counter-clockwise). Empty for a blank (space).
  std::vector<std::vector<Bezier<double, 2>>> contours;
};

/// The text's glyphs and facts about the font.
struct GlyphRun {
  std::vector<GlyphOutline> glyphs;
  int units_per_em = 0;
  std::string format;  ///< FreeType's name of the font format: "TrueType", "CFF", "Type 1", ...
  bool kerning = false;  ///< whether the font has pair kerning that is read (GPOS kern, kern table, AFM)
};

/// The glyphs of `text` (UTF-8, at most 10000 characters, one line) in the font file
/// `font_path` (face 0), scaled by size / unitsPerEm (no size: design units). Outlines are
/// unhinted, loaded at one pixel per font unit (FreeType's 26.6 coordinates are then
/// font units times 64, exactly) and read with FT_Outline_Decompose, which supplies the
/// implied on-curve points of TrueType (exact at that scale; FT_LOAD_NO_SCALE would
/// truncate their half units). Layout: the pen starts at (0, 0) and moves by each
/// glyph's advance plus the pair kerning between it and the next: the GPOS `kern`
/// feature when the font has one (HarfBuzz, with nothing else of shaping: no
/// substitution, no other positioning feature, one glyph per character; per script run,
/// the script's default language system), else what FreeType reads (FT_Get_Kerning: the
/// TrueType `kern` table, or a Type 1 font's AFM file beside it, same name with `.afm`).
/// The file is only read. Errors: InvalidArgument "font" (no such
/// file, not a regular file, not a font FreeType reads, a font without outlines),
/// "text" (not UTF-8, more than 10000 characters), "text[i]" (character i, counted in
/// code points, is not in the font: the font's .notdef box is not substituted), "size"
/// (not > 0). Cost: linear in the text and its outlines' points.
[[nodiscard]] GlyphRun glyph_outlines(const std::string& font_path, const std::string& text, std::optional<double> size);

}  // namespace casteljau::io
