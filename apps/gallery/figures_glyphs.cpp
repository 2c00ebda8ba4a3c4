// Gallery figure of issue 17's font outlines: one word set in a TrueType font (quadratic
// pieces) and a CFF font (cubic pieces), read by io::glyph_outlines (FreeType), with the
// flattening of every contour at one tolerance.
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/algo/flatten.hpp"
#include "casteljau/io/glyph.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

Figure glyph_outlines_figure() {
  const std::string word = "Curves";
  struct Row {
    const char* font;
    const char* name;
  };
  // Debian's fonts-dejavu-core and fonts-urw-base35 (the build set installs both).
  const Row rows[] = {{"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "DejaVu Sans (TrueType: quadratics)"},
                      {"/usr/share/fonts/opentype/urw-base35/NimbusSans-Regular.otf", "Nimbus Sans (CFF: cubics)"}};
  const double size = 100;   // the em in model units: one unit is about a pixel below
  const double tol = 1.5;    // flattening tolerance in those units: coarse enough to see
  SvgDocument doc(width, 300);
  doc.title("A word in two fonts, with its flattening");
  std::string counts;
  for (int r = 0; r < 2; ++r) {
    const auto run = io::glyph_outlines(rows[r].font, word, size);
    const double y0 = 140.0 * r;
    const double end = run.glyphs.back().origin[0] + run.glyphs.back().advance;
    doc.set_map(PageMap::fit(Box<double, 2>(P2(-5, -25), P2(end + 5, 80)), {20, 10 + y0, 840, 125}));
    std::size_t pieces = 0, vertices = 0;
    for (const auto& g : run.glyphs) {
      for (const auto& contour : g.contours) {
        std::vector<P2> poly;
        for (const auto& b : contour) {
          doc.curve(b, Paint{.stroke = grey, .stroke_width = 4, .opacity = 0.45});
          const std::size_t before = poly.size();
          flatten(b, tol, FlattenMethod::optimal, poly);
          if (before > 0) poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(before));  // the shared joint
          ++pieces;
        }
        doc.polyline(poly, thin(ink, 1));
        for (const P2& v : poly) doc.circle(v, 1.3, Paint{.fill = accent});
        vertices += poly.size();
      }
    }
    doc.set_map(PageMap{});
    doc.text(P2(860, 135 + y0), rows[r].name, label(12, Anchor::end));
    counts += std::string(r ? "; " : "") + rows[r].name + ": " + std::to_string(pieces) + " pieces, " +
              std::to_string(vertices) + " polyline vertices";
  }
  const std::string cap =
      "The word &ldquo;" + word + "&rdquo; from <code>casteljau glyph</code> (FreeType reads the font; each contour a closed "
      "path, laid out with the fonts' advances and pair kerning), at an em of " + fixed(size, 0) +
      " units, drawn wide and grey, and flattened by <code>flatten</code> (optimal) at tolerance " + fixed(tol, 2) +
      " (the dark polylines, vertices in red): " + counts + ".";
  return {"glyphs", "Font outlines: TrueType quadratics and CFF cubics", doc.str(), cap};
}

}  // namespace casteljau::gallery
