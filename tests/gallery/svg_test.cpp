// Tests of the SVG io layer: render_svg (curve kinds, errors, degenerate inputs), the
// document writer, number formatting, escaping and PageMap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>

#include <unistd.h>
#include <string>
#include <vector>

#include "casteljau/io/svg.hpp"

namespace {

using namespace casteljau;
using io::AnyCurve;
using io::RenderStyle;
using P1 = Point<double, 1>;
using P2 = Point<double, 2>;

std::string render(const AnyCurve& c, const RenderStyle& s = {}) { return io::render_svg(std::span<const AnyCurve>(&c, 1), s); }

/// NaN or infinity anywhere, as printf, streams or to_chars write them.
bool has_bad_number(const std::string& svg) {
  static const std::regex bad("(^|[^A-Za-z])[-+]?(nan|inf)([^A-Za-z]|$)", std::regex::icase);
  return std::regex_search(svg, bad);
}

/// The d attributes of all <path> elements.
std::vector<std::string> path_data(const std::string& svg) {
  std::vector<std::string> out;
  static const std::regex d_attr("<path d=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), d_attr); it != std::sregex_iterator(); ++it) out.push_back((*it)[1]);
  return out;
}

/// The drawn coordinates, for range checks: every number of the point lists and
/// positions, and the end point of each path command (the inner control points of a C or
/// Q command may lie off the page while the curve does not).
std::vector<double> coordinates(const std::string& svg) {
  std::vector<double> out;
  static const std::regex attr("(?: points| cx| cy| x1| y1| x2| y2)=\"([^\"]*)\"");
  static const std::regex num("[-+]?[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?");
  auto numbers = [&](const std::string& v) {
    std::vector<double> r;
    for (auto jt = std::sregex_iterator(v.begin(), v.end(), num); jt != std::sregex_iterator(); ++jt) r.push_back(std::stod(jt->str()));
    return r;
  };
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), attr); it != std::sregex_iterator(); ++it) {
    for (const double v : numbers((*it)[1])) out.push_back(v);
  }
  static const std::regex command("[MLQC]([^MLQC]*)");
  for (const std::string& d : path_data(svg)) {
    for (auto it = std::sregex_iterator(d.begin(), d.end(), command); it != std::sregex_iterator(); ++it) {
      const auto v = numbers((*it)[1]);
      if (v.size() >= 2) out.insert(out.end(), v.end() - 2, v.end());
    }
  }
  return out;
}

/// Every drawn coordinate lies on the page (with a margin for point markers).
void expect_on_page(const std::string& svg, const RenderStyle& s = {}) {
  for (const double v : coordinates(svg)) {
    EXPECT_GE(v, -1e-9);
    EXPECT_LE(v, std::max(s.width, s.height) + 1e-9);
  }
}

std::string checked(const std::string& svg) {
  EXPECT_FALSE(has_bad_number(svg)) << svg;
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  return svg;
}

template <class F>
void expect_invalid(F&& f, const std::string& where) {
  try {
    f();
    ADD_FAILURE() << "no exception, expected InvalidArgument at " << where;
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.where(), where) << e.what();
  }
}

Bezier<double, 2> cubic() { return Bezier<double, 2>({{0.0, 0.0}, {1.0, 2.0}, {3.0, 2.0}, {4.0, 0.0}}); }

// ---------------------------------------------------------------------------------------
// Curve kinds.

TEST(RenderSvg, WritesCubicQuadraticAndLineExactly) {
  EXPECT_NE(path_data(checked(render(cubic())))[0].find('C'), std::string::npos);
  const std::string q = checked(render(Bezier<double, 2>({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}})));
  EXPECT_NE(path_data(q)[0].find('Q'), std::string::npos);
  const std::string l = checked(render(Bezier<double, 2>({{0.0, 0.0}, {1.0, 1.0}})));
  EXPECT_EQ(path_data(l)[0].find_first_of("CQ"), std::string::npos);
  EXPECT_NE(path_data(l)[0].find('L'), std::string::npos);
}

TEST(RenderSvg, FlattensHighDegreeAndRationalSegments) {
  const Bezier<double, 2> quintic({{0.0, 0.0}, {1.0, 3.0}, {2.0, -1.0}, {3.0, 3.0}, {4.0, -1.0}, {5.0, 0.0}});
  const std::string d = path_data(checked(render(quintic)))[0];
  EXPECT_EQ(d.find_first_of("CQ"), std::string::npos);
  EXPECT_GT(std::count(d.begin(), d.end(), 'L'), 8);
  const auto arc = RationalBezier<double, 2>::circular_arc({0.0, 0.0}, 1.0, 0.0, 1.5);
  const std::string a = path_data(checked(render(arc)))[0];
  EXPECT_EQ(a.find_first_of("CQ"), std::string::npos);
  // Equal weights: the polynomial curve, written exactly.
  const RationalBezier<double, 2> flat(cubic().points(), {2.0, 2.0, 2.0, 2.0});
  EXPECT_NE(path_data(checked(render(flat)))[0].find('C'), std::string::npos);
}

TEST(RenderSvg, ToleranceControlsVertexCount) {
  const auto arc = RationalBezier<double, 2>::circular_arc({0.0, 0.0}, 1.0, 0.0, 3.0);
  RenderStyle coarse, fine;
  coarse.tolerance = 0.05;  // model units: a few segments
  fine.tolerance = 1e-5;    // below the default quarter pixel: many more
  const auto n = [](const std::string& d) { return std::count(d.begin(), d.end(), 'L'); };
  const auto c = n(path_data(checked(render(arc, coarse)))[0]), f = n(path_data(checked(render(arc, fine)))[0]);
  EXPECT_LT(c, 12);
  EXPECT_GT(f, 2 * c);
}

TEST(RenderSvg, PathIsOneSubpathWhenSegmentsMeet) {
  const Bezier<double, 2> a = cubic();
  const Bezier<double, 2> b({{4.0, 0.0}, {5.0, -2.0}, {6.0, 0.0}});
  const Path<double, 2> p({Segment<double, 2>(a), Segment<double, 2>(b)});
  const std::string d = path_data(checked(render(p)))[0];
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 1);
  EXPECT_NE(d.find('C'), std::string::npos);
  EXPECT_NE(d.find('Q'), std::string::npos);
  // A gap starts a new subpath.
  const Path<double, 2> gap({Segment<double, 2>(a), Segment<double, 2>(Bezier<double, 2>({{5.0, 0.0}, {6.0, 1.0}}))});
  const std::string g = path_data(checked(render(gap)))[0];
  EXPECT_EQ(std::count(g.begin(), g.end(), 'M'), 2);
}

TEST(RenderSvg, DrawsOneDimensionalCurvesAsGraphs) {
  const Bezier<double, 1> y({P1(0.0), P1(3.0), P1(-1.0), P1(2.0)});
  RenderStyle s;
  s.control_polygon = false;
  s.padding = 0;
  const std::string svg = checked(render(y, s));
  // Graph of a cubic function: a cubic in the plane, stretched to fill the page: starts
  // at the left edge and ends at the right edge.
  const std::string d = path_data(svg)[0];
  EXPECT_NE(d.find('C'), std::string::npos);
  EXPECT_EQ(d.rfind("M0,", 0), 0u) << d;
  EXPECT_NE(d.find("640,"), std::string::npos) << d;
  expect_on_page(svg, s);

  const RationalBezier<double, 1> r({P1(0.0), P1(1.0), P1(0.0)}, {1.0, 3.0, 1.0});
  expect_on_page(checked(render(r, s)), s);
  const Path<double, 1> p({Segment<double, 1>(y), Segment<double, 1>(r)}, {-2.0, 0.5, 1.0});
  expect_on_page(checked(render(p, s)), s);
}

TEST(RenderSvg, RationalGraphIsTheFunction) {
  // y = A/W on [0, 1]; its graph has x = t exactly, so sampled page points of the graph
  // must match the function: checked through the flattened vertices.
  const RationalBezier<double, 1> r({P1(0.0), P1(2.0), P1(1.0)}, {1.0, 4.0, 0.5});
  RenderStyle s;
  s.control_polygon = false;
  s.padding = 0;
  s.width = 1000;
  s.height = 1000;
  const std::string d = path_data(checked(render(r, s)))[0];
  const Box<double, 1> b = [&] {
    Box<double, 1> bb = Box<double, 1>::empty_box();
    for (int k = 0; k <= 10000; ++k) bb.add(r(k / 10000.0));
    return bb;
  }();
  static const std::regex pt("([-0-9.]+),([-0-9.]+)");
  int checked_points = 0;
  for (auto it = std::sregex_iterator(d.begin(), d.end(), pt); it != std::sregex_iterator(); ++it) {
    const double t = std::stod((*it)[1]) / 1000, y_page = std::stod((*it)[2]);
    const double y = b.hi[0] - y_page / 1000 * (b.hi[0] - b.lo[0]);
    EXPECT_NEAR(r(t)[0], y, 2e-3 * (b.hi[0] - b.lo[0])) << "t = " << t;
    ++checked_points;
  }
  EXPECT_GT(checked_points, 10);
}

TEST(RenderSvg, PaletteForSeveralCurvesUnlessStrokeIsSet) {
  const std::vector<AnyCurve> cs = {cubic(), Bezier<double, 2>({{0.0, 1.0}, {4.0, 1.0}}), Bezier<double, 2>({{0.0, 2.0}, {4.0, 3.0}})};
  const std::string multi = checked(io::render_svg(cs));
  for (std::size_t i = 0; i < cs.size(); ++i) EXPECT_NE(multi.find("stroke=\"" + std::string(io::palette(i)) + "\""), std::string::npos);
  RenderStyle s;
  s.stroke = "black";
  const std::string one = checked(io::render_svg(cs, s));
  EXPECT_EQ(one.find(std::string(io::palette(1))), std::string::npos);
  EXPECT_NE(one.find("stroke=\"black\""), std::string::npos);
}

TEST(RenderSvg, ControlPolygonAndAxesAreOptional) {
  RenderStyle s;
  s.control_polygon = false;
  const std::string bare = checked(render(cubic(), s));
  EXPECT_EQ(bare.find("<circle"), std::string::npos);
  s.control_polygon = true;
  s.axes = true;
  const std::string full = checked(render(Bezier<double, 2>({{-2.0, -1.0}, {1.0, 3.0}, {3.0, -2.0}}), s));
  EXPECT_NE(full.find("<circle"), std::string::npos);
  EXPECT_NE(full.find("<text"), std::string::npos);  // tick labels
  expect_on_page(full, s);
}

TEST(RenderSvg, EscapesColourStrings) {
  RenderStyle s;
  s.background = "<x>&\"'";
  s.stroke = "red\" onload=\"alert(1)";
  const std::string svg = checked(render(cubic(), s));
  EXPECT_EQ(svg.find("<x>"), std::string::npos);
  EXPECT_EQ(svg.find("\" onload"), std::string::npos);
  EXPECT_NE(svg.find("&lt;x&gt;&amp;&quot;&#39;"), std::string::npos);
}

// ---------------------------------------------------------------------------------------
// Errors.

TEST(RenderSvg, RejectsThreeAndFourDimensionalCurves) {
  const Bezier<double, 3> c3({{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}});
  const Bezier<double, 4> c4({{0.0, 0.0, 0.0, 0.0}, {1.0, 1.0, 1.0, 1.0}});
  expect_invalid([&] { render(c3); }, "curve");
  expect_invalid([&] { render(c4); }, "curve");
  const std::vector<AnyCurve> cs = {cubic(), c3};
  expect_invalid([&] { io::render_svg(cs); }, "curves[1]");
  try {
    render(c3);
  } catch (const InvalidArgument& e) {
    EXPECT_NE(e.problem().find("3D"), std::string::npos) << e.what();
  }
}

TEST(RenderSvg, RejectsBadStyleFieldsByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto with = [](auto set) {
    RenderStyle s;
    set(s);
    return s;
  };
  for (const double v : {0.0, -1.0, nan, inf}) {
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.width = v; })); }, "width");
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.height = v; })); }, "height");
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.stroke_width = v; })); }, "stroke_width");
  }
  for (const double v : {-1.0, nan, inf, -inf}) {
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.padding = v; })); }, "padding");
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.tolerance = v; })); }, "tolerance");
  }
  // A padding that leaves no room is named too.
  expect_invalid([&] { render(cubic(), with([](RenderStyle& s) { s.padding = 240; })); }, "padding");
  // A huge tolerance is a chord, not an overflow.
  const Bezier<double, 2> quintic({{0.0, 0.0}, {1.0, 3.0}, {2.0, -1.0}, {3.0, 3.0}, {4.0, -1.0}, {5.0, 0.0}});
  const std::string chord = path_data(checked(render(quintic, with([](RenderStyle& s) { s.tolerance = 1e300; }))))[0];
  EXPECT_EQ(std::count(chord.begin(), chord.end(), 'L'), 1) << chord;
  // Zero padding and zero tolerance are fine.
  checked(render(cubic(), with([](RenderStyle& s) {
    s.padding = 0;
    s.tolerance = 0;
  })));
}

// ---------------------------------------------------------------------------------------
// Degenerate inputs: every one renders, on the page, without NaN.

TEST(RenderSvg, DegenerateInputsRenderSensibly) {
  RenderStyle axes;
  axes.axes = true;
  const std::vector<AnyCurve> fixtures = {
      Bezier<double, 2>({{3.0, 4.0}}),                                        // a single point
      Bezier<double, 2>({{0.0, 0.0}}),                                        // the origin
      Bezier<double, 2>({{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}}),    // zero length cubic
      Bezier<double, 2>({{0.0, 2.0}, {5.0, 2.0}}),                            // horizontal line
      Bezier<double, 2>({{2.0, -1.0}, {2.0, 1.0}, {2.0, 7.0}}),               // vertical line
      Bezier<double, 2>({{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {3.0, 3.0}}),    // collinear
      Bezier<double, 2>({{0.0, 0.0}, {4.0, 4.0}, {0.0, 4.0}, {4.0, 0.0}}),    // cusp-like loop
      Bezier<double, 2>({{1e-200, 1e-200}, {2e-200, 3e-200}, {3e-200, 1e-200}}),  // tiny
      Bezier<double, 2>({{-1e300, -1e300}, {1e300, 1e300}, {1e300, -1e300}}),     // huge
      Bezier<double, 2>({{1e12, 1e12}, {1e12 + 1, 1e12 + 2}, {1e12 + 3, 1e12}}),  // far from the origin
      Bezier<double, 2>({{1e15, 0.0}, {1e15, 1e-10}}),                            // below resolution
      Bezier<double, 1>({P1(5.0)}),                                               // constant 1D, degree 0
      Bezier<double, 1>({P1(2.0), P1(2.0), P1(2.0)}),                             // constant 1D
      Bezier<double, 1>({P1(-1e300), P1(1e300)}),                                 // huge 1D
      RationalBezier<double, 2>({{1.0, 1.0}, {1.0, 1.0}}, {1.0, 5.0}),            // rational point
      Path<double, 1>({Segment<double, 1>(Bezier<double, 1>({P1(0.0)}))}, {1e9, 1e9 + 1}),  // 1D path far along t
  };
  for (std::size_t i = 0; i < fixtures.size(); ++i) {
    SCOPED_TRACE("fixture " + std::to_string(i));
    for (const RenderStyle& s : {RenderStyle{}, axes}) {
      const std::string svg = checked(render(fixtures[i], s));
      ASSERT_FALSE(path_data(svg).empty());
      expect_on_page(svg, s);
    }
  }
}

TEST(RenderSvg, EmptyInputIsAnEmptyPage) {
  const std::string svg = checked(io::render_svg({}));
  EXPECT_TRUE(path_data(svg).empty());
  RenderStyle s;
  s.axes = true;
  s.background = "";
  const std::string a = checked(io::render_svg({}, s));
  EXPECT_EQ(a.find("<rect"), std::string::npos);
  EXPECT_NE(a.find("<line"), std::string::npos);
}

TEST(RenderSvg, SinglePointIsCentred) {
  RenderStyle s;
  s.control_polygon = false;
  const std::string d = path_data(checked(render(Bezier<double, 2>({{7.0, -3.0}}), s)))[0];
  EXPECT_EQ(d, "M320,240L320,240");
}

/// Every point of the first <path>'s data (command end points and inner control points):
/// where the curve is drawn.
std::vector<P2> path_points(const std::string& svg) {
  static const std::regex num("[-+]?[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?");
  const std::string d = path_data(svg).at(0);
  std::vector<double> all;
  for (auto it = std::sregex_iterator(d.begin(), d.end(), num); it != std::sregex_iterator(); ++it) all.push_back(std::stod(it->str()));
  std::vector<P2> out;
  for (std::size_t i = 0; i + 1 < all.size(); i += 2) out.emplace_back(all[i], all[i + 1]);
  return out;
}

/// The drawn extent of the first path along x and y, in px.
P2 drawn_extent(const std::string& svg) {
  const auto pts = path_points(svg);
  double x0 = pts.at(0)[0], x1 = x0, y0 = pts.at(0)[1], y1 = y0;
  for (const P2& p : pts) {
    x0 = std::min(x0, p[0]);
    x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]);
    y1 = std::max(y1, p[1]);
  }
  return {x1 - x0, y1 - y0};
}

// Issue 5, defect 5: views whose extent overflows, or is small against its position.

TEST(RenderSvg, ExtentBeyondTheRangeOfDoubleSpansTheView) {
  // hi - lo = 2e308 overflows; the curve must fill the view, not collapse to a dot.
  const Bezier<double, 2> c({{-1e308, 0.0}, {0.0, 1e308}, {1e308, 0.0}});
  RenderStyle axes;
  axes.axes = true;
  RenderStyle bare;
  bare.control_polygon = false;
  for (const RenderStyle& s : {RenderStyle{}, axes, bare}) {
    const std::string svg = checked(render(c, s));
    expect_on_page(svg, s);
    const P2 e = drawn_extent(svg);
    // The view (the control box, or the tight box) is 2e308 x 1e308 (or x 0.5e308):
    // fitted into 592 x 432 px, x sets the scale, 592 px for 2e308; the control point
    // is 1e308 = 296 px above the ends.
    EXPECT_NEAR(e[0], 592, 1e-3) << svg;
    EXPECT_NEAR(e[1], 296, 1e-3) << svg;
  }
  // Corners at +-DBL_MAX, with a wide padding and axes (view beyond the doubles).
  const double big = std::numeric_limits<double>::max();
  RenderStyle wide = axes;
  wide.padding = 200;
  const std::string svg = checked(render(Bezier<double, 2>({{-big, -big}, {big, big}}), wide));
  EXPECT_NEAR(drawn_extent(svg)[0], 80, 1e-3) << svg;  // 480 - 2 * 200
  // A 1D path on breaks [-0.8e308, 0.8e308]: its graph spans t over the page width (the
  // break interval's length is near the largest double). A longer domain is refused when
  // the path is made.
  EXPECT_THROW((Path<double, 1>({Segment<double, 1>(Bezier<double, 1>({P1(0.0), P1(1.0)}))}, {-1e308, 1e308})), InvalidArgument);
  const Path<double, 1> p({Segment<double, 1>(Bezier<double, 1>({P1(0.0), P1(1.0)}))}, {-0.8e308, 0.8e308});
  const std::string g = checked(render(p));
  EXPECT_NEAR(drawn_extent(g)[0], 592, 1e-3) << g;
  EXPECT_NEAR(drawn_extent(g)[1], 432, 1e-3) << g;
}

TEST(RenderSvg, SmallCurveFarFromTheOriginIsDrawnAtFullSize) {
  // 4 units at 1e13: the ulp of 1e13 is 0.002, so 2000 ulps across. It was taken for a
  // point (extents below 1e-12 of the position counted as flat).
  const double e = 1e13;
  const Bezier<double, 2> both({{e, e}, {e + 2, e + 4}, {e + 4, e}});
  const Bezier<double, 2> along_x({{e, 0.0}, {e + 2, 4.0}, {e + 4, 0.0}});
  RenderStyle bare;
  bare.control_polygon = false;
  for (const RenderStyle& s : {RenderStyle{}, bare}) {
    for (const auto& c : {both, along_x}) {
      const std::string svg = checked(render(c, s));
      expect_on_page(svg, s);
      // Control box 4 x 4 fitted into 592 x 432: 432 px; tight box 4 x 2: 592 px wide.
      EXPECT_NEAR(drawn_extent(svg)[0], s.control_polygon ? 432 : 592, 1e-3) << svg;
    }
  }
  // A 1D graph far from the origin is stretched to the page height.
  const std::string g = checked(render(Bezier<double, 1>({P1(e), P1(e + 8), P1(e)})));
  EXPECT_NEAR(drawn_extent(g)[1], 432, 1e-3) << g;
}

TEST(PageMap, ExtentsAtTheLimitsOfDouble) {
  const double big = std::numeric_limits<double>::max();
  const io::PageRect page{0, 0, 400, 300};
  const auto m = io::PageMap::fit({{-big, -big}, {big, big}}, page);
  EXPECT_GT(m.scale_x(), 0);
  EXPECT_NEAR(m({-big, 0.0})[0], 50, 1e-9);  // 300 x 300 square, centred
  EXPECT_NEAR(m({big, 0.0})[0], 350, 1e-9);
  const Box<double, 2> v = m.view(page);
  EXPECT_EQ(v.lo[0], -big);  // beyond the doubles: clamped
  EXPECT_EQ(v.hi[0], big);
  // A point far out on the opposite side of the centre: p - c overflows.
  const auto off = io::PageMap::fit({{big / 2, 0.0}, {big, 1.0}}, page);
  EXPECT_TRUE(std::isfinite(off({-big, 0.0})[0]));
  // Rounding-level extents are flat (a point), a few thousand ulps are not.
  const double e = 1e13;
  const auto point = io::PageMap::fit({{e, e}, {e + 0.002, e + 0.002}}, page);  // 1 ulp
  EXPECT_DOUBLE_EQ(point.scale_x(), 150 / (e * 1e-3));
  const auto small = io::PageMap::fit({{e, e}, {e + 4, e + 4}}, page);
  EXPECT_DOUBLE_EQ(small.scale_x(), 75);
}

TEST(Ticks, HugeAndNarrowIntervals) {
  const double big = std::numeric_limits<double>::max();
  for (const auto& [lo, hi] : {std::pair{-1e308, 1e308}, std::pair{-big, big}, std::pair{0.0, big}}) {
    for (const double v : io::nice_ticks(lo, hi, 5)) EXPECT_TRUE(std::isfinite(v)) << lo << " " << hi;
  }
  const auto t = io::nice_ticks(-1e308, 1e308, 2);  // step 1e308 (hi - lo overflowed)
  ASSERT_EQ(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t[0], -1e308);
  EXPECT_EQ(t[1], 0);
  EXPECT_DOUBLE_EQ(t[2], 1e308);
  // One ulp wide at 1e17: multiples of the step are beyond 2^53; this must end (it looped
  // forever on k += 1) and give no ticks.
  EXPECT_TRUE(io::nice_ticks(1e17, 1e17 + 16, 5).empty());
}

TEST(RenderSvg, StyleLimits) {
  auto with = [](auto set) {
    RenderStyle s;
    set(s);
    return s;
  };
  for (const double v : {1e308, 1e7, 0.5}) {
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.width = v; s.padding = 0; })); }, "width");
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.height = v; s.padding = 0; })); }, "height");
  }
  for (const double v : {1e308, std::numeric_limits<double>::max(), 240.0, 239.75}) {
    expect_invalid([&] { render(cubic(), with([&](RenderStyle& s) { s.padding = v; })); }, "padding");
  }
  checked(render(cubic(), with([](RenderStyle& s) { s.padding = 239.5; s.axes = true; })));  // 1 px to draw in
  checked(render(cubic(), with([](RenderStyle& s) { s.stroke_width = 1e308; s.axes = true; })));
}

// ---------------------------------------------------------------------------------------
// The writer's pieces.

TEST(SvgNumber, CompactAndPrecise) {
  EXPECT_EQ(io::svg_number(3), "3");
  EXPECT_EQ(io::svg_number(2.5), "2.5");
  EXPECT_EQ(io::svg_number(-0.0001), "0");
  EXPECT_EQ(io::svg_number(-12.3456), "-12.346");
  EXPECT_EQ(io::svg_number(1e20), "1e+20");
  expect_invalid([] { io::svg_number(std::nan(""), "x"); }, "x");
  expect_invalid([] { io::svg_number(-std::numeric_limits<double>::infinity(), "y"); }, "y");
}

TEST(SvgText, EscapesAndDropsForbiddenControls) {
  EXPECT_EQ(io::xml_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(io::xml_escape(std::string("x\x01y\tz", 5)), "xy\tz");
  io::SvgDocument doc(100, 50);
  doc.title("P<sub> & co");
  doc.text({10.0, 10.0}, "</svg><script>");
  const std::string s = checked(doc.str());
  EXPECT_EQ(s.find("<script>"), std::string::npos);
  EXPECT_NE(s.find("&lt;/svg&gt;&lt;script&gt;"), std::string::npos);
}

TEST(SvgDocument, RejectsNonFiniteGeometry) {
  io::SvgDocument doc(100, 100);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(doc.circle({nan, 0.0}, 2, {}), InvalidArgument);
  EXPECT_THROW(doc.line({0.0, 0.0}, {std::numeric_limits<double>::infinity(), 0.0}, {}), InvalidArgument);
  EXPECT_THROW(io::SvgDocument(0, 10), InvalidArgument);
  expect_invalid([&] { io::SvgDocument(10, nan); }, "height");
}

TEST(SvgDocument, GroupsAreClosed) {
  io::SvgDocument doc(10, 10);
  doc.begin_group("a");
  doc.begin_group("b");
  doc.end_group();
  const std::string s = checked(doc.str());
  std::size_t closes = 0;
  for (std::size_t at = s.find("</g>"); at != std::string::npos; at = s.find("</g>", at + 1)) ++closes;
  EXPECT_EQ(closes, 2u);
}

TEST(PageMap, FitsKeepingAspectWithYUp) {
  const Box<double, 2> model{{0.0, 0.0}, {4.0, 1.0}};
  const io::PageRect page{10, 20, 400, 300};
  const auto m = io::PageMap::fit(model, page);
  EXPECT_DOUBLE_EQ(m.scale_x(), 100);
  EXPECT_DOUBLE_EQ(m.scale_y(), 100);
  const P2 lo = m({0.0, 0.0}), hi = m({4.0, 1.0});
  EXPECT_DOUBLE_EQ(lo[0], 10);
  EXPECT_DOUBLE_EQ(hi[0], 410);
  EXPECT_GT(lo[1], hi[1]);                    // y up
  EXPECT_DOUBLE_EQ((lo[1] + hi[1]) / 2, 170);  // centred vertically
  const P2 back = m.to_model(m({1.5, 0.25}));
  EXPECT_NEAR(back[0], 1.5, 1e-12);
  EXPECT_NEAR(back[1], 0.25, 1e-12);
  const auto s = io::PageMap::fit(model, page, io::Aspect::stretch);
  EXPECT_DOUBLE_EQ(s.scale_y(), 300);
  expect_invalid([&] { io::PageMap::fit(model, {0, 0, 0, 10}); }, "page.width");
}

TEST(Ticks, NiceValuesAndLabels) {
  EXPECT_EQ(io::nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(io::nice_ticks(-0.3, 0.3, 3), (std::vector<double>{-0.2, 0, 0.2}));
  EXPECT_TRUE(io::nice_ticks(1, 1, 5).empty());
  EXPECT_TRUE(io::nice_ticks(0, std::numeric_limits<double>::infinity(), 5).empty());
  EXPECT_EQ(io::tick_label(0.25, 0.25), "0.25");
  EXPECT_EQ(io::tick_label(1, 0.25), "1");
  EXPECT_EQ(io::tick_label(-0.5, 0.5), "\u22120.5");
  EXPECT_EQ(io::tick_label(-1e-17, 0.1), "0");
}

// Every kind of document the renderer and the writer produce parses as XML (Python's
// xml.etree, an independent parser). The test renders its own documents, so it does not
// depend on which other tests ran before it (gtest_filter, shuffling).
TEST(SvgXml, EverySvgParsesAsXml) {
  RenderStyle axes;
  axes.axes = true;
  RenderStyle bare;
  bare.control_polygon = false;
  RenderStyle hostile;
  hostile.background = "<x>&\"'";
  hostile.stroke = "red\" onload=\"alert(1)";
  const Bezier<double, 1> graph({P1(0.0), P1(3.0), P1(-1.0), P1(2.0)});
  const RationalBezier<double, 1> rational_graph({P1(0.0), P1(1.0), P1(0.0)}, {1.0, 3.0, 1.0});
  const Path<double, 2> gap({Segment<double, 2>(cubic()), Segment<double, 2>(Bezier<double, 2>({{5.0, 0.0}, {6.0, 1.0}}))});
  const std::vector<AnyCurve> several = {cubic(), Bezier<double, 2>({{0.0, 1.0}, {4.0, 1.0}}),
                                         RationalBezier<double, 2>::circular_arc({0.0, 0.0}, 1.0, 0.0, 1.5)};
  std::vector<std::string> docs = {
      render(cubic()),                                                                  // C command
      render(Bezier<double, 2>({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}}), axes),            // Q, ticks
      render(Bezier<double, 2>({{0.0, 0.0}, {1.0, 1.0}}), bare),                        // L only
      render(Bezier<double, 2>({{0.0, 0.0}, {1.0, 3.0}, {2.0, -1.0}, {3.0, 3.0}, {4.0, -1.0}, {5.0, 0.0}})),
      render(RationalBezier<double, 2>::circular_arc({0.0, 0.0}, 1.0, 0.0, 3.0), axes),  // flattened
      render(gap),                                                                      // two subpaths
      render(graph, axes),                                                              // 1-D graphs
      render(rational_graph),
      render(Bezier<double, 2>({{7.0, -3.0}}), axes),                                   // a point
      render(Bezier<double, 2>({{-1e300, -1e300}, {1e300, 1e300}, {1e300, -1e300}})),   // huge
      render(cubic(), hostile),                                                         // escaped colours
      io::render_svg(several),                                                          // palette
      io::render_svg({}),                                                               // empty page
      io::render_svg({}, axes),
  };
  io::SvgDocument doc(100, 50);
  doc.title("P<sub> & co");
  doc.text({10.0, 10.0}, "</svg><script>");
  doc.begin_group("a");
  doc.begin_group("b");
  doc.end_group();
  docs.push_back(doc.str());
  for (const auto& d : docs) checked(d);

  const auto dir = std::filesystem::temp_directory_path() / ("casteljau_svg_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (std::size_t i = 0; i < docs.size(); ++i) std::ofstream(dir / (std::to_string(i) + ".svg")) << docs[i];
  // The script fails (non-zero status) on the first document that does not parse, and on
  // a directory holding fewer documents than were written.
  const std::string cmd = std::string(CASTELJAU_TEST_PYTHON) +
                          " -c \"import sys, glob, xml.etree.ElementTree as E; fs = glob.glob(sys.argv[1] + '/*.svg'); "
                          "[E.parse(f) for f in fs]; sys.exit(0 if len(fs) == int(sys.argv[2]) else 3)\" " +
                          dir.string() + " " + std::to_string(docs.size());
  const int rc = std::system(cmd.c_str());
  std::filesystem::remove_all(dir);
  EXPECT_EQ(rc, 0) << "an SVG is not well-formed XML";
}

}  // namespace
