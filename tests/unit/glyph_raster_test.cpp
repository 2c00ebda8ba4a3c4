// The glyph command's outlines (io/glyph.hpp) against FreeType's own rasterisation: each
// glyph is rendered by FreeType (unhinted, 8-bit anti-aliased coverage) and our contours are
// rasterised here (non-zero winding number at pixel centres, scanline crossings); every
// pixel that no edge of ours crosses must be fully covered or empty in FreeType's bitmap.
// Fonts from Debian packages the build set installs: fonts-dejavu-core (TrueType) and
// fonts-urw-base35 (CFF and Type 1).
#include <ft2build.h>
#include FT_FREETYPE_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/io/glyph.hpp"

namespace {

using casteljau::Point;
using P2 = Point<double, 2>;

/// The outline flattened: closed polylines.
using Rings = std::vector<std::vector<P2>>;

/// The non-zero winding numbers at the pixel centres of one row (y), for pixels whose
/// centres are x0 + 0.5 + j, j = 0..n-1: the crossings of the row with every edge, each
/// counting +1 upwards and -1 downwards for the centres to its left (the ray to +x).
std::vector<int> row_winding(const Rings& rings, double y, double x0, int n) {
  std::vector<int> w(static_cast<std::size_t>(n), 0);
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
      const P2 a = ring[i], b = ring[i + 1];
      const bool up = a[1] <= y && b[1] > y, down = a[1] > y && b[1] <= y;
      if (!up && !down) continue;
      const double x = a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
      for (int j = 0; j < n && x0 + j + 0.5 < x; ++j) w[static_cast<std::size_t>(j)] += up ? 1 : -1;
    }
  }
  return w;
}

struct Agreement {
  int pixels = 0;      ///< compared
  int touched = 0;     ///< pixels an edge of our outline passes through
  int mismatched = 0;  ///< touched pixels where inside (winding at the centre) != coverage >= 128
  int violations = 0;  ///< untouched pixels not fully covered (inside) or not empty (outside)
};

/// Compares the outline of one character at `px` pixels per em with FreeType's bitmap.
Agreement compare(const std::string& font, const std::string& ch, int px) {
  const auto run = casteljau::io::glyph_outlines(font, ch, px);
  // Each piece flattened into 32 chords: at 96 px per em a piece spans at most a few dozen
  // pixels, and its chord error (length^2 curvature / (8 * 32^2)) stays below 0.03 px.
  Rings rings;
  for (const auto& contour : run.glyphs.at(0).contours) {
    std::vector<P2> ring;
    for (const auto& b : contour)
      for (int k = 0; k < 32; ++k) ring.push_back(b(k / 32.0));
    ring.push_back(contour.front()(0.0));
    rings.push_back(std::move(ring));
  }
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  EXPECT_EQ(FT_Init_FreeType(&lib), 0);
  EXPECT_EQ(FT_New_Face(lib, font.c_str(), 0, &face), 0);
  EXPECT_EQ(FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(px)), 0);
  const FT_UInt index = FT_Get_Char_Index(face, static_cast<FT_ULong>(static_cast<unsigned char>(ch[0])));
  EXPECT_EQ(FT_Load_Glyph(face, index, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP), 0);
  EXPECT_EQ(FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL), 0);
  const FT_Bitmap& bm = face->glyph->bitmap;
  // The bitmap and a margin of 2 pixels around it (coverage 0 there): pixel (i, j) covers
  // x in [left + j, left + j + 1], y in [top - i - 1, top - i].
  const int rows = static_cast<int>(bm.rows) + 4, cols = static_cast<int>(bm.width) + 4;
  const double left = face->glyph->bitmap_left - 2, top = face->glyph->bitmap_top + 2;
  // Pixels an edge passes through: each chord's box, grown by 0.05 px for the chord
  // error and FreeType's 26.6 rounding, marks the pixels it overlaps.
  std::vector<char> touched(static_cast<std::size_t>(rows * cols), 0);
  for (const auto& ring : rings) {
    for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
      const double g = 0.05;
      const double x0 = std::min(ring[k][0], ring[k + 1][0]) - g, x1 = std::max(ring[k][0], ring[k + 1][0]) + g;
      const double y0 = std::min(ring[k][1], ring[k + 1][1]) - g, y1 = std::max(ring[k][1], ring[k + 1][1]) + g;
      for (int i = std::max(0, static_cast<int>(std::floor(top - y1))); i <= std::min(rows - 1, static_cast<int>(std::floor(top - y0))); ++i)
        for (int j = std::max(0, static_cast<int>(std::floor(x0 - left))); j <= std::min(cols - 1, static_cast<int>(std::floor(x1 - left))); ++j)
          touched[static_cast<std::size_t>(i * cols + j)] = 1;
    }
  }
  Agreement a;
  for (int i = 0; i < rows; ++i) {
    const std::vector<int> w = row_winding(rings, top - i - 0.5, left, cols);
    for (int j = 0; j < cols; ++j) {
      const int bi = i - 2, bj = j - 2;
      const bool in_bitmap = bi >= 0 && bj >= 0 && bi < static_cast<int>(bm.rows) && bj < static_cast<int>(bm.width);
      const int cov = in_bitmap ? bm.buffer[bi * bm.pitch + bj] : 0;
      const bool inside = w[static_cast<std::size_t>(j)] != 0;
      ++a.pixels;
      if (touched[static_cast<std::size_t>(i * cols + j)]) {
        ++a.touched;
        if (inside != (cov >= 128)) ++a.mismatched;
      } else if (inside ? cov < 254 : cov > 1) {
        ++a.violations;  // 1/255 allowed for the rounding of FreeType's cell areas
      }
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
  return a;
}

TEST(GlyphRaster, OutlinesAgreeWithFreeTypeRendering) {
  const char* fonts[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                         "/usr/share/fonts/opentype/urw-base35/NimbusSans-Regular.otf",
                         "/usr/share/fonts/type1/urw-base35/NimbusSans-Regular.t1"};
  for (const char* font : fonts) {
    Agreement total;
    for (const char* ch : {"a", "g", "S", "8", "@", "Q"}) {
      const Agreement a = compare(font, ch, 96);
      // A pixel that no edge of our outline passes through lies wholly inside or outside
      // it: FreeType must cover it fully or not at all. This holds everywhere only if the
      // two outlines are the same curves (to about 0.05 px).
      EXPECT_EQ(a.violations, 0) << font << " '" << ch << "'";
      // On the pixels an edge crosses, a centre sample and FreeType's area coverage differ
      // at the 50% threshold only where the edge passes within a few hundredths of a pixel
      // of the centre (coverage quantised to 1/255, edges bent inside the pixel): a small
      // share, at most 10% of those pixels (the measured figures are printed).
      EXPECT_LE(a.mismatched, a.touched / 10) << font << " '" << ch << "'";
      total.pixels += a.pixels;
      total.touched += a.touched;
      total.mismatched += a.mismatched;
      total.violations += a.violations;
    }
    std::printf("glyph raster %s: %d pixels, %d crossed by an edge, %d of them disagree at 50%%, %d violations\n", font,
                total.pixels, total.touched, total.mismatched, total.violations);
  }
}

}  // namespace
