// Tests of SVG reading (io/svg_import.hpp): the path-data grammar's corner cases with
// control points derived by hand, arcs against the circle and ellipse they lie on (the
// four arcs the flags choose between), shapes, transforms and errors. The renderer's own
// SVG read back and real drawings against librsvg: tests/cli/test_import_svg.py. Only
// io/svg_import.hpp is included (no curve templates: a cheap translation unit).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/core/error.hpp"
#include "casteljau/io/svg_import.hpp"

namespace {

using namespace casteljau;
using io::SvgPoint;
using io::SvgSegment;
using io::SvgSubpath;

const double w45 = std::sqrt(0.5);  // cos(45 degrees): the weight of a quarter arc

/// Control points equal to `tol` (the exact cases: 0 or a few ulps of the arithmetic).
void expect_points(const SvgSegment& s, const std::vector<SvgPoint>& P, double tol = 0) {
  ASSERT_EQ(s.points.size(), P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_NEAR(s.points[i][0], P[i][0], tol) << "point " << i;
    EXPECT_NEAR(s.points[i][1], P[i][1], tol) << "point " << i;
  }
}

void expect_line(const SvgSegment& s, SvgPoint a, SvgPoint b) {
  EXPECT_TRUE(s.weights.empty());
  expect_points(s, {a, b});
}

/// A rational quadratic with weights {1, w, 1}, evaluated by its definition (independent
/// of the code under test).
SvgPoint eval(const SvgSegment& s, double t) {
  const std::size_t n = s.points.size() - 1;
  double x = 0, y = 0, wsum = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    const double b = std::tgamma(n + 1.0) / (std::tgamma(i + 1.0) * std::tgamma(n - i + 1.0)) * std::pow(t, double(i)) *
                     std::pow(1 - t, double(n - i));
    const double w = s.weights.empty() ? 1.0 : s.weights[i];
    x += b * w * s.points[i][0];
    y += b * w * s.points[i][1];
    wsum += b * w;
  }
  return {x / wsum, y / wsum};
}

std::vector<SvgSubpath> parse(const std::string& d) { return io::parse_path_data(d); }

std::string error_of(const std::string& d) {
  try {
    (void)io::parse_path_data(d);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

std::string document_error(const std::string& svg) {
  try {
    (void)io::import_svg(svg);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

// ---------------------------------------------------------------------------------------
// Path-data grammar

TEST(SvgImportPathData, NumbersWithoutSeparators) {
  // ".5.5" is 0.5 and 0.5; "10-5" is 10 and -5; exponents with and without signs.
  auto p = parse("M.5.5L10-5l1e-3-.5e+2");
  ASSERT_EQ(p.size(), 1u);
  ASSERT_EQ(p[0].segments.size(), 2u);
  expect_line(p[0].segments[0], {0.5, 0.5}, {10, -5});
  expect_line(p[0].segments[1], {10, -5}, {10.001, -55});
  // A trailing '.' belongs to the number ("1." is 1), an exponent needs digits: "1e" is
  // the number 1 then the letter e (not a command).
  p = parse("M1.,2.L+3,+4");
  expect_line(p[0].segments[0], {1, 2}, {3, 4});
  EXPECT_EQ(error_of("M1 1e L 2 2"), "d[4]: expected a path command (MLHVCSQTAZ, or a number continuing the previous one), got 'e'");
}

TEST(SvgImportPathData, ImplicitRepeatsAfterMovetoAreLines) {
  auto p = parse("M 1 2 3 4 5 6");
  ASSERT_EQ(p.size(), 1u);
  ASSERT_EQ(p[0].segments.size(), 2u);
  expect_line(p[0].segments[0], {1, 2}, {3, 4});
  expect_line(p[0].segments[1], {3, 4}, {5, 6});
  // Relative: each pair from the current point; a first m is absolute.
  p = parse("m 1 2 3 4, 1 1");
  expect_line(p[0].segments[0], {1, 2}, {4, 6});
  expect_line(p[0].segments[1], {4, 6}, {5, 7});
  // Repeated C.
  p = parse("M0 0 C 1 1 2 1 3 0 4 -1 5 -1 6 0");
  ASSERT_EQ(p[0].segments.size(), 2u);
  expect_points(p[0].segments[1], {{3, 0}, {4, -1}, {5, -1}, {6, 0}});
}

TEST(SvgImportPathData, HorizontalAndVertical) {
  auto p = parse("M 1 1 H 5 V 3 h -2 v -1");
  ASSERT_EQ(p[0].segments.size(), 4u);
  expect_line(p[0].segments[0], {1, 1}, {5, 1});
  expect_line(p[0].segments[1], {5, 1}, {5, 3});
  expect_line(p[0].segments[2], {5, 3}, {3, 3});
  expect_line(p[0].segments[3], {3, 3}, {3, 2});
}

TEST(SvgImportPathData, SmoothCubicReflectsOnlyAfterCubic) {
  // After C: the first control point is 2 * (3, 0) - (2, 1) = (4, -1).
  auto p = parse("M0 0 C 1 1 2 1 3 0 S 5 -1 6 0");
  expect_points(p[0].segments[1], {{3, 0}, {4, -1}, {5, -1}, {6, 0}});
  // S after S reflects the S's own second control point: 2 * (6, 0) - (5, -1) = (7, 1).
  p = parse("M0 0 C 1 1 2 1 3 0 s 2 -1 3 0 s 2 1 3 0");
  expect_points(p[0].segments[2], {{6, 0}, {7, 1}, {8, 1}, {9, 0}});
  // After L or Q: the current point.
  p = parse("M0 0 L 1 0 S 2 1 3 0");
  expect_points(p[0].segments[1], {{1, 0}, {1, 0}, {2, 1}, {3, 0}});
  p = parse("M0 0 Q 1 1 2 0 S 3 1 4 0");
  expect_points(p[0].segments[1], {{2, 0}, {2, 0}, {3, 1}, {4, 0}});
}

TEST(SvgImportPathData, SmoothQuadraticReflectsOnlyAfterQuadratic) {
  auto p = parse("M0 0 Q 1 1 2 0 T 4 0 T 6 0");
  expect_points(p[0].segments[1], {{2, 0}, {3, -1}, {4, 0}});
  expect_points(p[0].segments[2], {{4, 0}, {5, 1}, {6, 0}});
  p = parse("M0 0 Q 1 1 2 0 t 2 0");
  expect_points(p[0].segments[1], {{2, 0}, {3, -1}, {4, 0}});
  // After C, L or at the start: the control point is the current point.
  p = parse("M0 0 C 1 1 2 1 3 0 T 5 0");
  expect_points(p[0].segments[1], {{3, 0}, {3, 0}, {5, 0}});
  p = parse("M1 1 T 5 0");
  expect_points(p[0].segments[0], {{1, 1}, {1, 1}, {5, 0}});
}

TEST(SvgImportPathData, ClosepathAndTheSubpathAfterIt) {
  auto p = parse("M 0 0 L 1 0 L 1 1 Z");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(p[0].closed);
  ASSERT_EQ(p[0].segments.size(), 3u);
  expect_line(p[0].segments[2], {1, 1}, {0, 0});
  // Ending at the start already: no closing segment.
  p = parse("M 0 0 L 1 0 L 0 0 z");
  EXPECT_TRUE(p[0].closed);
  EXPECT_EQ(p[0].segments.size(), 2u);
  // A command after Z without M starts a new subpath at the start point; a relative m
  // after z is relative to that start.
  p = parse("M 5 5 L 6 5 Z L 5 6");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_FALSE(p[1].closed);
  expect_line(p[1].segments[0], {5, 5}, {5, 6});
  p = parse("M 10 10 l 5 0 l 0 5 z m 1 1 l 1 0");
  ASSERT_EQ(p.size(), 2u);
  expect_line(p[1].segments[0], {11, 11}, {12, 11});
  // Two M in a row: the first draws nothing; lone moves and "M Z" are left out.
  p = parse("M 1 1 M 2 2 L 3 3 M 4 4");
  ASSERT_EQ(p.size(), 1u);
  expect_line(p[0].segments[0], {2, 2}, {3, 3});
  EXPECT_TRUE(parse("M 1 1 Z").empty());
  EXPECT_TRUE(parse("").empty());
  EXPECT_TRUE(parse("  \n ").empty());
}

// ---------------------------------------------------------------------------------------
// Arcs

TEST(SvgImportPathData, ArcFlagsWithoutSeparatorsPickTheArc) {
  // From (0, 0) to (1, 1) on circles of radius 1: the centres are (1, 0) and (0, 1).
  // large 0, sweep 0: centre (1, 0), angle pi down to pi/2 (one quarter; the tangents at
  // the ends, x = 0 and y = 1, meet at (0, 1)).
  auto p = parse("M0 0 a1 1 0 00 1 1");
  ASSERT_EQ(p[0].segments.size(), 1u);
  expect_points(p[0].segments[0], {{0, 0}, {0, 1}, {1, 1}}, 1e-15);
  EXPECT_EQ(p[0].segments[0].weights, (std::vector<double>{1, w45, 1}));
  // large 0, sweep 1: centre (0, 1), -pi/2 up to 0: control point (1, 0).
  p = parse("M0 0 a1 1 0 0 1 1 1");
  expect_points(p[0].segments[0], {{0, 0}, {1, 0}, {1, 1}}, 1e-15);
  // large 1, sweep 1: centre (1, 0), pi up to 5 pi / 2: three quarters through (1, -1),
  // (2, 0); the control points at the bisecting angles, sqrt(2) from the centre.
  p = parse("M0 0 A1 1 0 1 1 1 1");
  ASSERT_EQ(p[0].segments.size(), 3u);
  expect_points(p[0].segments[0], {{0, 0}, {0, -1}, {1, -1}}, 1e-15);
  expect_points(p[0].segments[1], {{1, -1}, {2, -1}, {2, 0}}, 1e-15);
  expect_points(p[0].segments[2], {{2, 0}, {2, 1}, {1, 1}}, 1e-15);
  // large 1, sweep 0: centre (0, 1), -pi/2 down to -2 pi through (-1, 1), (0, 2).
  p = parse("M0 0 A1 1 0 1 0 1 1");
  ASSERT_EQ(p[0].segments.size(), 3u);
  expect_points(p[0].segments[0], {{0, 0}, {-1, 0}, {-1, 1}}, 1e-15);
  expect_points(p[0].segments[1], {{-1, 1}, {-1, 2}, {0, 2}}, 1e-15);
  expect_points(p[0].segments[2], {{0, 2}, {1, 2}, {1, 1}}, 1e-15);
  for (const auto& s : p[0].segments) EXPECT_NEAR(s.weights[1], w45, 1e-16);
}

TEST(SvgImportPathData, ArcRadiiTooSmallAreScaledUp) {
  // F.6.6: radius 1 between (0, 0) and (4, 0) becomes 2, centre (2, 0), a half circle
  // (sweep 1: angle pi up to 2 pi through (2, -2)): two quarters with control points
  // (0, -2) and (4, -2).
  auto p = parse("M0 0 A 1 1 0 0 1 4 0");
  ASSERT_EQ(p[0].segments.size(), 2u);
  expect_points(p[0].segments[0], {{0, 0}, {0, -2}, {2, -2}}, 1e-15);
  expect_points(p[0].segments[1], {{2, -2}, {4, -2}, {4, 0}}, 1e-15);
  // Negative radii are their absolute values (the same arc).
  auto q = parse("M0 0 A -1 -1 0 0 1 4 0");
  expect_points(q[0].segments[1], {{2, -2}, {4, -2}, {4, 0}}, 1e-15);
  // An ellipse scaled keeps its ratio: rx 2, ry 1 from (0, 0) to (8, 0): Lambda = 16 / 4
  // = 4, radii (4, 2), centre (4, 0); sweep 0: the angle from pi down to 0, through pi/2,
  // the point (4, 2); control points at 3 pi / 4 and pi / 4, (-1, 1) and (1, 1) on the
  // unit circle's tangent square, scaled by the radii.
  p = parse("M0 0 A 2 1 0 0 0 8 0");
  ASSERT_EQ(p[0].segments.size(), 2u);
  expect_points(p[0].segments[0], {{0, 0}, {0, 2}, {4, 2}}, 1e-14);
  expect_points(p[0].segments[1], {{4, 2}, {8, 2}, {8, 0}}, 1e-14);
}

TEST(SvgImportPathData, ArcZeroRadiusIsALineCoincidentEndsAreLeftOut) {
  auto p = parse("M0 0 A 0 5 0 0 1 3 4");
  expect_line(p[0].segments[0], {0, 0}, {3, 4});
  p = parse("M1 1 A 5 5 0 1 1 1 1 L 2 2");
  ASSERT_EQ(p[0].segments.size(), 1u);
  expect_line(p[0].segments[0], {1, 1}, {2, 2});
}

/// The arc from p to q with the flags, checked against the ellipse it must lie on: in the
/// frame where the ellipse is the unit circle (rotate by -phi, divide by the radii), the
/// two candidate centres are mid +- h n; the pieces must lie on one of them, turn the way
/// sweep says and cover more than half the circle exactly when large says.
void check_arc(double rx, double ry, double phi_deg, bool large, bool sweep, SvgPoint from, SvgPoint to) {
  std::vector<SvgSegment> segs;
  io::append_arc(segs, from, rx, ry, phi_deg, large, sweep, to);
  ASSERT_FALSE(segs.empty());
  const double phi = phi_deg * std::numbers::pi / 180;
  const auto frame = [&](SvgPoint p) {
    const double x = std::cos(phi) * p[0] + std::sin(phi) * p[1], y = -std::sin(phi) * p[0] + std::cos(phi) * p[1];
    return SvgPoint{x / rx, y / ry};
  };
  const SvgPoint a = frame(from), b = frame(to);
  const double dx = b[0] - a[0], dy = b[1] - a[1], d = std::hypot(dx, dy);
  ASSERT_LT(d, 2) << "the test wants radii large enough";
  const double h = std::sqrt(1 - d * d / 4);
  const SvgPoint mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
  const SvgPoint centres[] = {{mid[0] - h * dy / d, mid[1] + h * dx / d}, {mid[0] + h * dy / d, mid[1] - h * dx / d}};
  int found = -1;
  for (int c = 0; c < 2; ++c) {
    bool on = true;
    for (const auto& s : segs) {
      for (double t = 0; t <= 1; t += 1.0 / 16) {
        const SvgPoint e = frame(eval(s, t));
        on = on && std::abs(std::hypot(e[0] - centres[c][0], e[1] - centres[c][1]) - 1) < 1e-12;
      }
    }
    if (on) found = c;
  }
  ASSERT_NE(found, -1) << "the arc is on neither candidate ellipse";
  // The signed angle swept, summed over small steps.
  double turned = 0;
  SvgPoint prev = frame(from);
  for (const auto& s : segs) {
    EXPECT_LE(std::acos(s.weights[1]) * 2, std::numbers::pi / 2 + 1e-12) << "a piece of more than 90 degrees";
    for (double t = 1.0 / 64; t <= 1 + 1e-12; t += 1.0 / 64) {
      const SvgPoint e = frame(eval(s, t));
      const double ux = prev[0] - centres[found][0], uy = prev[1] - centres[found][1];
      const double vx = e[0] - centres[found][0], vy = e[1] - centres[found][1];
      turned += std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
      prev = e;
    }
  }
  // rx, ry > 0 keep orientation in the frame, so the sweep's sign is the frame's.
  EXPECT_EQ(turned > 0, sweep) << "turned " << turned;
  EXPECT_EQ(std::abs(turned) > std::numbers::pi, large) << "turned " << turned;
  EXPECT_EQ(segs.front().points.front(), from);
  EXPECT_EQ(segs.back().points.back(), to);
}

TEST(SvgImportPathData, RotatedEllipticalArcsOnTheirEllipse) {
  for (int large = 0; large < 2; ++large) {
    for (int sweep = 0; sweep < 2; ++sweep) {
      SCOPED_TRACE("large " + std::to_string(large) + " sweep " + std::to_string(sweep));
      check_arc(30, 10, 30, large, sweep, {10, 20}, {40, 35});
      check_arc(5, 12, -75, large, sweep, {-3, 1}, {2, 7});
      check_arc(1, 1, 0, large, sweep, {0, 0}, {1.5, 0.2});
    }
  }
}

// ---------------------------------------------------------------------------------------
// Errors

TEST(SvgImportPathData, ErrorsNameTheOffsetAndWhatWasExpected) {
  EXPECT_EQ(error_of("M 10 10 L 20"), "d[12]: expected a number after 'L'");
  EXPECT_EQ(error_of("M 10 10 L 20 x"), "d[13]: expected a number after 'L'");
  EXPECT_EQ(error_of("L 10 10"), "d[0]: path data must start with a moveto ('M' or 'm'), got 'L'");
  EXPECT_EQ(error_of("M 1 1 X 2"), "d[6]: expected a path command (MLHVCSQTAZ, or a number continuing the previous one), got 'X'");
  EXPECT_EQ(error_of("M 1 1 L 2 2,"), "d[12]: expected a number after ',' (at 11)");
  EXPECT_EQ(error_of("M 1 1 L ,2 2"), "d[8]: expected a number after 'L'");
  EXPECT_EQ(error_of("M0 0 A 1 1 0 2 1 3 3"), "d[13]: expected a flag (0 or 1) after 'A', got '2'");
  EXPECT_EQ(error_of("M 1 1 Z 3"), "d[8]: expected a path command (MLHVCSQTAZ, or a number continuing the previous one), got '3'");
  EXPECT_EQ(error_of("M 1e400 0"), "d[2]: the number 1e400 is out of range");
  EXPECT_EQ(error_of("M -1e400 0"), "d[2]: the number -1e400 is out of range");
  // 1e327 written out: no exponent, too large all the same.
  const std::string huge = "1" + std::string(327, '0');
  EXPECT_EQ(error_of("M 0 " + huge), "d[4]: the number " + huge.substr(0, 32) + "\u2026 is out of range");
  EXPECT_EQ(error_of("M 1e308 0 l 1e308 0"), "d[10]: a coordinate overflows (is not finite)");
  // Underflow is zero, not an error.
  EXPECT_EQ(parse("M 1e-400 0 L 1 1")[0].segments[0].points[0][0], 0.0);
  EXPECT_EQ(parse("M -0.0000000001e-320 0 L 1 1")[0].segments[0].points[0][0], 0.0);
}

// ---------------------------------------------------------------------------------------
// Transforms and documents

TEST(SvgImportTransform, FunctionsAndLists) {
  const auto m = io::parse_transform("translate(10 20) scale(2)");
  EXPECT_EQ(m(SvgPoint{1, 1}), (SvgPoint{12, 22}));
  const auto r = io::parse_transform(" rotate(90, 1 1) ");  // about (1, 1): (2, 1) -> (1, 2)
  EXPECT_EQ(r(SvgPoint{2, 1}), (SvgPoint{1, 2}));
  const auto k = io::parse_transform("skewX(45)");  // x += y tan 45
  EXPECT_NEAR(k(SvgPoint{0, 1})[0], 1, 1e-15);
  const auto ky = io::parse_transform("skewY(45)");
  EXPECT_NEAR(ky(SvgPoint{1, 0})[1], 1, 1e-15);
  const auto mat = io::parse_transform("matrix(1,2,3,4,5,6),translate(1)");
  EXPECT_EQ(mat(SvgPoint{0, 0}), (SvgPoint{6, 8}));  // matrix applied to (1, 0)
  EXPECT_EQ(io::parse_transform("scale(2,3)")(SvgPoint{1, 1}), (SvgPoint{2, 3}));
  const auto error = [](const std::string& t) {
    try {
      (void)io::parse_transform(t);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("rotate(1 2)"), "transform[10]: rotate takes 1 or 3 numbers, got 2");
  EXPECT_EQ(error("turn(1)"), "transform[0]: unknown transform function 'turn' (matrix, translate, scale, rotate, skewX, skewY)");
  EXPECT_EQ(error("scale(1"), "transform[7]: expected ')' to close scale(");
  EXPECT_EQ(error("skewX()"), "transform[6]: skewX takes 1 number, got 0");
  EXPECT_EQ(error("skewY(1 2)"), "transform[8]: expected ')': skewY takes at most 1 number, got '2'");
  EXPECT_EQ(error("skewX(90)"), "transform[0]: skewX(90) is not a finite transform");
  EXPECT_EQ(error("skewY(-270)"), "transform[0]: skewY(-270) is not a finite transform");
}

TEST(SvgImportDocument, NestedGroupsComposeTransforms) {
  const auto doc = io::import_svg(R"svg(<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(10,0)">
      <g transform="scale(2)"><rect id="r" x="1" y="1" width="2" height="3"/></g></g></svg>)svg");
  ASSERT_EQ(doc.paths.size(), 1u);
  EXPECT_EQ(doc.paths[0].id, "r");
  ASSERT_EQ(doc.paths[0].subpaths.size(), 1u);
  const auto& s = doc.paths[0].subpaths[0];
  EXPECT_TRUE(s.closed);
  ASSERT_EQ(s.segments.size(), 4u);
  // (1, 1), (3, 1), (3, 4), (1, 4) scaled by 2 then moved by 10 in x.
  expect_line(s.segments[0], {12, 2}, {16, 2});
  expect_line(s.segments[1], {16, 2}, {16, 8});
  expect_line(s.segments[2], {16, 8}, {12, 8});
  expect_line(s.segments[3], {12, 8}, {12, 2});
}

TEST(SvgImportDocument, RoundedRectCircleEllipse) {
  const auto doc = io::import_svg(R"svg(<svg><rect width="10" height="6" rx="2"/><rect width="10" height="6" rx="8"/>
      <circle cx="1" cy="2" r="3"/><ellipse cx="0" cy="0" rx="2" ry="1"/><rect width="0" height="5"/></svg>)svg");
  ASSERT_EQ(doc.paths.size(), 5u);
  // ry auto = rx = 2: lines along the sides between quarter arcs whose control points
  // are the rectangle's corners.
  const auto& r = doc.paths[0].subpaths[0].segments;
  ASSERT_EQ(r.size(), 8u);
  expect_line(r[0], {2, 0}, {8, 0});
  expect_points(r[1], {{8, 0}, {10, 0}, {10, 2}}, 1e-15);
  expect_line(r[2], {10, 2}, {10, 4});
  expect_points(r[3], {{10, 4}, {10, 6}, {8, 6}}, 1e-15);
  expect_line(r[4], {8, 6}, {2, 6});
  expect_points(r[5], {{2, 6}, {0, 6}, {0, 4}}, 1e-15);
  expect_line(r[6], {0, 4}, {0, 2});
  expect_points(r[7], {{0, 2}, {0, 0}, {2, 0}}, 1e-15);
  EXPECT_NEAR(r[7].weights[1], w45, 1e-16);
  // rx 8 (ry auto 8) clamped to 5 and 3: no straight side is left, four quarter arcs.
  const auto& c = doc.paths[1].subpaths[0].segments;
  ASSERT_EQ(c.size(), 4u);
  expect_points(c[0], {{5, 0}, {10, 0}, {10, 3}}, 1e-15);
  expect_points(c[1], {{10, 3}, {10, 6}, {5, 6}}, 1e-15);
  // The circle from (cx + r, cy), clockwise on screen: (4, 2), (1, 5), (-2, 2), (1, -1).
  const auto& o = doc.paths[2].subpaths[0].segments;
  ASSERT_EQ(o.size(), 4u);
  expect_points(o[0], {{4, 2}, {4, 5}, {1, 5}}, 1e-15);
  expect_points(o[1], {{1, 5}, {-2, 5}, {-2, 2}}, 1e-15);
  expect_points(o[2], {{-2, 2}, {-2, -1}, {1, -1}}, 1e-15);
  expect_points(o[3], {{1, -1}, {4, -1}, {4, 2}}, 1e-15);
  const auto& e = doc.paths[3].subpaths[0].segments;
  expect_points(e[0], {{2, 0}, {2, 1}, {0, 1}}, 1e-15);
  // Zero width: drawn nothing, still listed (indices match the elements).
  EXPECT_TRUE(doc.paths[4].subpaths.empty());
}

TEST(SvgImportDocument, LinesPolylinesPolygonsAndUnits) {
  const auto doc = io::import_svg(R"svg(<svg><line x1="1" y1="2" x2="3px" y2="1in"/><polyline points="0,0 1,1 2,0"/>
      <polygon points="0 0,4 0 4 3"/><line x2="2.54cm" y2="72pt"/></svg>)svg");
  ASSERT_EQ(doc.paths.size(), 4u);
  expect_line(doc.paths[0].subpaths[0].segments[0], {1, 2}, {3, 96});
  EXPECT_FALSE(doc.paths[1].subpaths[0].closed);
  EXPECT_EQ(doc.paths[1].subpaths[0].segments.size(), 2u);
  EXPECT_TRUE(doc.paths[2].subpaths[0].closed);
  ASSERT_EQ(doc.paths[2].subpaths[0].segments.size(), 3u);
  expect_line(doc.paths[2].subpaths[0].segments[2], {4, 3}, {0, 0});
  expect_line(doc.paths[3].subpaths[0].segments[0], {0, 0}, {96, 96});
}

TEST(SvgImportDocument, SkippedAndUnreadElements) {
  const auto doc = io::import_svg(R"svg(<svg xmlns:sodipodi="x"><sodipodi:namedview/><text id="t">hi</text><image/>
      <use href="#a"/><defs><path id="a" d="M0 0 L1 1"/></defs><foo/><a><path d="M0 0 h 1"/></a>
      <clipPath><rect width="1" height="1"/></clipPath><svg:circle xmlns:svg="http://www.w3.org/2000/svg" r="1"/>
      <s:line xmlns:s="http://www.w3.org/2000/svg"/><x:line xmlns:x="urn:other"/><svg:line xmlns:svg="urn:not-svg"/>
      <g xmlns="http://www.w3.org/1999/xhtml"><path d="M0 0 h 1"/></g></svg>)svg");
  // Elements of other namespaces (by their prefix's declaration, or the default xmlns in
  // scope) are neither read nor listed.
  ASSERT_EQ(doc.paths.size(), 3u);
  EXPECT_EQ(doc.paths[0].element, "path");
  EXPECT_EQ(doc.paths[1].element, "circle");
  EXPECT_EQ(doc.paths[2].element, "line");
  ASSERT_EQ(doc.skipped.size(), 4u);
  EXPECT_EQ(doc.skipped[0].element, "text");
  EXPECT_EQ(doc.skipped[0].id, "t");
  EXPECT_EQ(doc.skipped[1].element, "image");
  EXPECT_EQ(doc.skipped[2].element, "use");
  EXPECT_EQ(doc.skipped[3].element, "foo");
  EXPECT_FALSE(doc.skipped[3].id.has_value());
}

TEST(SvgImportDocument, NestedSvgViewport) {
  // x, y move; the viewBox 0 0 10 10 onto 20 x 40 (xMidYMid meet): scale 2, centred
  // vertically (10 px down).
  const auto doc = io::import_svg(R"svg(<svg><svg x="5" y="1" width="20" height="40" viewBox="0 0 10 10">
      <line x1="0" y1="0" x2="10" y2="10"/></svg></svg>)svg");
  expect_line(doc.paths[0].subpaths[0].segments[0], {5, 11}, {25, 31});
}

TEST(SvgImportDocument, ErrorsNameTheElement) {
  EXPECT_EQ(document_error(R"svg(<svg><path/><path id="p" d="M 10 10 L 20"/></svg>)svg"), "svg.paths[1](#p).d[12]: expected a number after 'L'");
  EXPECT_EQ(document_error(R"svg(<svg><rect width="50%" height="1"/></svg>)svg"),
            "svg.paths[0].width: '50%': the unit '%' is relative or unknown (read: px, in, cm, mm, pt, pc, Q)");
  EXPECT_EQ(document_error(R"svg(<svg><rect width="-1" height="1"/></svg>)svg"), "svg.paths[0].width: must be >= 0, got -1");
  EXPECT_EQ(document_error(R"svg(<svg><polygon points="1 2 3"/></svg>)svg"),
            "svg.paths[0].points: an odd number of coordinates (3): the last point has no y");
  EXPECT_EQ(document_error(R"svg(<svg><g id="L" transform="rotate(1 2)"><path d="M0 0"/></g></svg>)svg"),
            "svg.g[0](#L).transform[10]: rotate takes 1 or 3 numbers, got 2");
  EXPECT_EQ(document_error(R"svg(<svg><path d="M0 0"></svg>)svg"), "svg[22]: malformed XML: Start-end tags mismatch");
  EXPECT_EQ(document_error(R"svg(<html/>)svg"), "svg: the document's root element is <html>, not <svg>");
  EXPECT_EQ(document_error(R"svg(<svg xmlns="urn:x"/>)svg"), "svg: the document's root element is <svg> in namespace 'urn:x', not <svg>");
  std::string deep = "<svg>";
  for (int i = 0; i < 300; ++i) deep += "<g>";
  for (int i = 0; i < 300; ++i) deep += "</g>";
  EXPECT_EQ(document_error(deep + "</svg>"), "svg: elements nest deeper than 256 levels");
}

}  // namespace
