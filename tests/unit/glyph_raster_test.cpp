// The glyph command's outlines (io/glyph.hpp) against FreeType's own rasterisation: each
// glyph is rendered by FreeType (unhinted, 8-bit anti-aliased coverage) and our contours are
// rasterised here by the non-zero winding number at pixel centres; the two must agree.
// Fonts from Debian packages the build set installs: fonts-dejavu-core (TrueType) and
// fonts-urw-base35 (CFF and Type 1).
#include <ft2build.h>
#include FT_FREETYPE_H

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/io/glyph.hpp"

namespace {

using casteljau::Point;
using P2 = Point<double, 2>;

/// The non-zero winding number of the closed polylines around q (crossings of the ray to
/// +x, signed by direction).
int winding(const std::vector<std::vector<P2>>& rings, const P2& q) {
  int w = 0;
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
      const P2 a = ring[i], b = ring[i + 1];
      const double side = (b[0] - a[0]) * (q[1] - a[1]) - (q[0] - a[0]) * (b[1] - a[1]);
      if (a[1] <= q[1] && b[1] > q[1] && side > 0) ++w;
      if (a[1] > q[1] && b[1] <= q[1] && side < 0) --w;
    }
  }
  return w;
}

struct Agreement {
  int pixels = 0;      ///< compared
  int edge = 0;        ///< with coverage strictly between 0 and 255
  int mismatched = 0;  ///< inside (winding) != coverage >= 128
  int violations = 0;  ///< full coverage outside, or zero coverage inside
};

/// Compares the outline of one character at `px` pixels per em with FreeType's bitmap.
Agreement compare(const std::string& font, const std::string& ch, int px) {
  const auto run = casteljau::io::glyph_outlines(font, ch, px);
  // Each piece flattened into 64 chords: at 128 px per em a piece spans at most a few dozen
  // pixels, and its chord error (length^2 curvature / (8 * 64^2)) stays below 0.01 px.
  std::vector<std::vector<P2>> rings;
  for (const auto& contour : run.glyphs.at(0).contours) {
    std::vector<P2> ring;
    for (const auto& b : contour)
      for (int k = 0; k < 64; ++k) ring.push_back(b(k / 64.0));
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
  Agreement a;
  // The bitmap and a margin of 2 pixels around it (coverage 0 there).
  for (int i = -2; i < static_cast<int>(bm.rows) + 2; ++i) {
    for (int j = -2; j < static_cast<int>(bm.width) + 2; ++j) {
      const bool in_bitmap = i >= 0 && j >= 0 && i < static_cast<int>(bm.rows) && j < static_cast<int>(bm.width);
      const int cov = in_bitmap ? bm.buffer[i * bm.pitch + j] : 0;
      const P2 centre(face->glyph->bitmap_left + j + 0.5, face->glyph->bitmap_top - i - 0.5);
      const bool inside = winding(rings, centre) != 0;
      ++a.pixels;
      if (cov > 0 && cov < 255) ++a.edge;
      if (inside != (cov >= 128)) ++a.mismatched;
      if ((cov == 255 && !inside) || (cov == 0 && inside)) ++a.violations;
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
    for (const char* ch : {"a", "g", "o", "S", "8", "@", "B", "e", "%", "Q"}) {
      const Agreement a = compare(font, ch, 128);
      // A pixel that FreeType covers fully lies inside our outline and one it does not
      // touch lies outside: no exception (the outlines are the same curves, so only a
      // sliver thinner than 1/512 of a pixel could escape FreeType's 8-bit coverage).
      EXPECT_EQ(a.violations, 0) << font << " '" << ch << "'";
      // At the 50% threshold, a centre sample and an area coverage may disagree only on
      // edge pixels where the outline bends or turns a corner inside the pixel: at most
      // 5% of the edge pixels (measured: see the printed figures).
      EXPECT_LE(a.mismatched, a.edge / 20) << font << " '" << ch << "'";
      total.pixels += a.pixels;
      total.edge += a.edge;
      total.mismatched += a.mismatched;
      total.violations += a.violations;
    }
    std::printf("glyph raster %s: %d pixels, %d edge, %d disagree at 50%%, %d violations\n", font, total.pixels, total.edge,
                total.mismatched, total.violations);
  }
}

}  // namespace
