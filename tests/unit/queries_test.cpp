// The geometric queries on hand-solved examples: the root engine with multiplicities, the
// Bernstein polynomial algebra, the Gauss-Kronrod rule, arc length and its inverse, closest
// and farthest points, area, features and curve-curve distance, and the shared degenerate
// fixtures through every query.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "degenerate_fixtures.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;
using R2 = RationalBezier<double, 2>;
using casteljau::test::eps;
constexpr double pi = std::numbers::pi;

/// (t - a) on [0, 1] in Bernstein form of degree 1: the values at t = 0 and t = 1.
std::vector<double> linear_factor(double a) { return {-a, 1 - a}; }

std::vector<double> product_of(const std::vector<double>& roots) {
  std::vector<double> p = {1.0};
  for (double a : roots) p = bernstein_product<double>(p, linear_factor(a));
  return p;
}

/// A full circle of radius r about (cx, cy), counter-clockwise, as four exact rational
/// quarter arcs on [0, 4] [PT97, 7.3].
Pieces<double, 2> circle(double r, double cx = 0, double cy = 0) {
  std::vector<BezierPiece<double, 2>> segs;
  for (int i = 0; i < 4; ++i) segs.emplace_back(R2::circular_arc(P2(cx, cy), r, i * pi / 2, (i + 1) * pi / 2));
  return Pieces<double, 2>(std::move(segs));
}

// --- root engine ------------------------------------------------------------------------------

// (t - 1/4)(t - 1/2)^2(t - 3/4)^3: roots of multiplicity 1, 2 and 3. The double and triple
// roots have no sign change at even order, and rounding splits or removes them; the
// engine finds each once, located as the simple root of a derivative.
TEST(RootEngine, MultiplicitiesOneTwoThree) {
  const auto p = product_of({0.25, 0.5, 0.5, 0.75, 0.75, 0.75});
  const auto r = bernstein_roots_with_multiplicity<double>(p);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0].t, 0.25, 16 * eps);
  EXPECT_EQ(r[0].multiplicity, 1);
  // A root of multiplicity m is located as the simple root of p^(m-1), whose
  // coefficients carry the rounding of the product: a few hundred eps here.
  EXPECT_NEAR(r[1].t, 0.5, 1e-12);
  EXPECT_EQ(r[1].multiplicity, 2);
  EXPECT_NEAR(r[2].t, 0.75, 1e-12);
  EXPECT_EQ(r[2].multiplicity, 3);
}

// (t - 1/3)^2: 1/3 is not a double, so the coefficients are rounded and the rounded
// polynomial may not touch 0 at all; the double root is still reported.
TEST(RootEngine, EvenMultiplicityWithoutSignChange) {
  const auto p = product_of({1.0 / 3, 1.0 / 3});
  const auto r = bernstein_roots_with_multiplicity<double>(p);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0].t, 1.0 / 3, 1e-14);
  EXPECT_EQ(r[0].multiplicity, 2);
  // A polynomial bounded away from 0 has none: (t - 1/3)^2 + 1e-6.
  std::vector<double> q = p;
  for (double& c : q) c += 1e-6;  // sum of Bernstein polynomials is 1: adds the constant
  EXPECT_TRUE(bernstein_roots_with_multiplicity<double>(q).empty());
}

TEST(RootEngine, IntervalAndEnds) {
  // On [2, 4]: p(x) = (s - 0)(s - 1/2) with s = (x - 2)/2: roots x = 2 and x = 3.
  const auto p = product_of({0.0, 0.5});
  const auto r = bernstein_roots_with_multiplicity<double>(p, {2.0, 4.0});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].t, 2.0);
  EXPECT_NEAR(r[1].t, 3.0, 8 * eps);
  EXPECT_TRUE(bernstein_roots_with_multiplicity<double>(std::vector<double>{0, 0, 0}).empty());
  EXPECT_TRUE(bernstein_negligible<double>(std::vector<double>{1e-20, -1e-20}, 1e-18));
  EXPECT_INVALID_ARGUMENT(bernstein_roots_with_multiplicity<double>(p, {1.0, 1.0}), "interval", "lo < hi");
}

// Wilkinson-like: 12 simple roots close together, all found to a few hundred eps.
TEST(RootEngine, ManySimpleRoots) {
  std::vector<double> want;
  for (int i = 1; i <= 12; ++i) want.push_back(i / 13.0);
  const auto r = bernstein_roots_with_multiplicity<double>(product_of(want));
  ASSERT_EQ(r.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(r[i].t, want[i], 1e-11);
    EXPECT_EQ(r[i].multiplicity, 1);
  }
}

// --- polynomial algebra [Farin02, 5.1-5.4] ----------------------------------------------------

TEST(BernsteinPoly, ElevateSumDerivativeIntegral) {
  const std::vector<double> t = {0, 1}, t2 = {0, 0, 1};  // t and t^2
  EXPECT_EQ(bernstein_elevate<double>(t, 1), (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(bernstein_sum<double>(t, t2), (std::vector<double>{0, 0.5, 2}));
  EXPECT_EQ(bernstein_difference<double>(t2, t), (std::vector<double>{0, -0.5, 0}));
  EXPECT_EQ(bernstein_derivative_coefficients<double>(t2), (std::vector<double>{0, 2}));
  EXPECT_EQ(bernstein_derivative_coefficients<double>(std::vector<double>{5}), (std::vector<double>{0}));
  EXPECT_NEAR(bernstein_integral<double>(t2), 1.0 / 3, eps);
  // (1 - t)^3 integrates to 1/4; its value at 1/2 is 1/8.
  const std::vector<double> c = {1, 0, 0, 0};
  EXPECT_DOUBLE_EQ(bernstein_integral<double>(c), 0.25);
  EXPECT_DOUBLE_EQ(bernstein_value<double>(c, 0.5), 0.125);
  EXPECT_INVALID_ARGUMENT(bernstein_elevate<double>(c, -1), "r", ">= 0");
}

// --- quadrature [Kronrod65; Piessens83] --------------------------------------------------------

// The Kronrod rule is exact for t^k up to k = 22 and the embedded Gauss rule up to k = 13
// (their difference, the error estimate, vanishes there): this checks every constant.
TEST(Quadrature, GaussKronrodExactness) {
  for (int k = 0; k <= 22; ++k) {
    const auto q = gauss_kronrod_15<double>([k](double t) { return std::pow(t, k); }, 0.0, 1.0);
    EXPECT_NEAR(q.value, 1.0 / (k + 1), 4 * eps) << k;
    if (k <= 13) {
      EXPECT_LE(q.error, 4 * eps) << k;
    }
  }
  const auto q = gauss_kronrod_15<double>([](double t) { return std::pow(t, 30); }, 0.0, 1.0);
  EXPECT_GT(q.error, 1e-6);  // degree 30: the estimate sees the Gauss rule's error
}

TEST(Quadrature, AdaptiveMeetsItsTargetOrSaysSo) {
  const auto q = integrate_adaptive<double>([](double t) { return std::sqrt(t); }, 0.0, 1.0, 1e-13);
  EXPECT_NEAR(q.value, 2.0 / 3, 1e-13);
  EXPECT_LE(q.error, 1e-13);
  EXPECT_THROW((void)integrate_adaptive<double>([](double t) { return 1 / std::sqrt(t + 1e-300); }, 0.0, 1.0, 1e-15, 0.0, 50),
               NumericalError);
}

// --- arc length -------------------------------------------------------------------------------

TEST(ArcLength, ClosedForms) {
  EXPECT_DOUBLE_EQ(arc_length(B2{{0, 0}, {1, 0}, {2, 0}, {3, 0}}), 3.0);
  // A straight cubic with uneven control points runs back: length |x'| integrated.
  // x(t) = 9t - 18t^2 + 12t^3 (0, 3, 0, 3): x' = 9 - 36t + 36t^2 > 0, so length 3.
  EXPECT_NEAR(arc_length(B2{{0, 0}, {3, 0}, {0, 0}, {3, 0}}), 3.0, 4 * eps);
  // Quarter circle of radius 2: pi.
  EXPECT_NEAR(arc_length(R2::circular_arc(P2(0, 0), 2, 0, pi / 2)), pi, 4 * eps * pi);
  EXPECT_NEAR(arc_length(circle(1.5)), 3 * pi, 16 * eps * pi);
  EXPECT_NEAR(arc_length(circle(1.5), 0.5, 2.5), 1.5 * pi, 16 * eps * pi);
  // y = x^2 from 0 to 1 as a quadratic (0,0), (1/2,0), (1,1): (2 sqrt5 + asinh 2) / 4.
  EXPECT_NEAR(arc_length(B2{{0, 0}, {0.5, 0}, {1, 1}}), (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4, 8 * eps);
  EXPECT_INVALID_ARGUMENT(arc_length(B2{{0, 0}, {1, 0}}, 0.5, 0.25), "to", ">= from");
  EXPECT_INVALID_ARGUMENT(arc_length(B2{{0, 0}, {1, 0}}, -0.5, 0.25), "from", "domain");
}

TEST(ArcLength, InverseAndResampling) {
  // x(t) = 2t + 2t^2 (control points 0, 1, 4): the parameter at s is (sqrt(4 + 8s) - 2) / 4.
  const B2 c{{0, 0}, {1, 0}, {4, 0}};
  const ArcLengthTable<double, 2> table(c);
  EXPECT_NEAR(table.total(), 4.0, 4 * eps);
  for (double s : {0.0, 0.3, 1.0, 2.2, 3.9, 4.0}) EXPECT_NEAR(table.parameter_at(s), (std::sqrt(4 + 8 * s) - 2) / 4, 8 * eps) << s;
  EXPECT_INVALID_ARGUMENT(table.parameter_at(4.1), "s", "[0, 4");
  // Equal steps along a circle are equal steps of its (arc-length proportional) parameter.
  const auto u = equal_length_parameters(circle(1.0), 9);
  for (int k = 0; k <= 8; ++k) EXPECT_NEAR(u[static_cast<std::size_t>(k)], k * 0.5, 1e-13) << k;
}

// --- project -----------------------------------------------------------------------------------

TEST(Project, NearestFarthestTiesAndIntervals) {
  // Nearest point on y = x^2 (quadratic (-1,1), (0,-1), (1,1)) to (0, 1/4) with the focal
  // distance: the vertex (0, 0) at t = 1/2, distance 1/4 (x^2 + (x^2 - 1/4)^2 is minimal at 0).
  const B2 parabola{{-1, 1}, {0, -1}, {1, 1}};
  const auto r = project(parabola, P2(0, 0.25));
  EXPECT_NEAR(r.t, 0.5, 1e-8);  // a flat minimum: located to about sqrt(eps)
  EXPECT_NEAR(r.distance, 0.25, 2 * eps);
  EXPECT_TRUE(r.all_t.empty());
  // From (0, 2): x^2 = 3/2 would be the minimum, outside; the ends tie at sqrt 2.
  const auto e = project(parabola, P2(0, 2));
  EXPECT_EQ(e.all_t, (std::vector<double>{0, 1}));
  EXPECT_NEAR(e.distance, std::sqrt(2.0), 2 * eps);
  const auto f = project(parabola, P2(0, 2), true);
  EXPECT_EQ(f.t, 0.5);
  EXPECT_NEAR(f.distance, 2.0, 2 * eps);
  // The centre of a circle: every parameter, one interval over the four pieces.
  const auto c = project(circle(2, 1, 1), P2(1, 1));
  ASSERT_EQ(c.intervals.size(), 1u);
  EXPECT_EQ(c.intervals[0].lo, 0.0);
  EXPECT_EQ(c.intervals[0].hi, 4.0);
  EXPECT_EQ(c.t, 0.0);
  EXPECT_NEAR(c.distance, 2.0, 4 * eps);
  EXPECT_INVALID_ARGUMENT(project(parabola, P2(std::nan(""), 0)), "point[0]", "finite");
}

// A flat minimum is one answer at its true location. From the centre of curvature at a
// vertex (an extremum of the curvature) the distance is flat to fourth order: (C - q) . C'
// has a triple root there, which rounding splits into a cluster of sign changes. The
// symmetric cubic (0,0), (1,2), (2,2), (3,0) has C(1/2) = (3/2, 3/2), C'(1/2) = (3, 0),
// C''(1/2) = (0, -12): curvature -36 / 27, radius 3/4, centre (3/2, 3/4). y = x^2 (the
// quadratic (-1,1), (0,-1), (1,1)) has radius 1/2 at its vertex: centre (0, 1/2).
TEST(Project, FlatMinimumAtTheCentreOfCurvature) {
  const auto r = project(B2{{0, 0}, {1, 2}, {2, 2}, {3, 0}}, P2(1.5, 0.75));
  EXPECT_TRUE(r.all_t.empty());
  // The triple root located as the simple root of the derivative's derivative: a few eps
  // (the cluster it replaces spread over 1e-8).
  EXPECT_NEAR(r.t, 0.5, 1e-12);
  EXPECT_NEAR(r.distance, 0.75, 4 * eps);
  const auto p = project(B2{{-1, 1}, {0, -1}, {1, 1}}, P2(0, 0.5));
  EXPECT_TRUE(p.all_t.empty());
  EXPECT_NEAR(p.t, 0.5, 1e-12);
  EXPECT_NEAR(p.distance, 0.5, 4 * eps);
  // The same seen through a B-spline on a huge domain and a path: still one answer.
  const BSpline<double, 2> bs(3, {0, 0, 0, 0, 1e6, 1e6, 1e6, 1e6}, {{0, 0}, {1, 2}, {2, 2}, {3, 0}});
  const auto b = project(bs, P2(1.5, 0.75));
  EXPECT_TRUE(b.all_t.empty());
  EXPECT_NEAR(b.t, 5e5, 1e-6);  // 1e-12 of the domain
}

// A rational quadratic (1,0), (1,1), (0,1) with weights 1, W, 1 hugs its control polygon:
// it lies in the triangle (convex hull), is convex, and passes C(1/2) = P1 - (1, 1) / (2 (1 + W)).
// So its length lies in [2 - 2 / W, 2] (between the two chords through C(1/2) and the
// polygon), its distance from (1, 3/2) in [1/2, 1/2 + 1 / W] (y <= 1 on the curve), and by
// the symmetry t -> 1 - t, (x, y) -> (y, x), the arc length to C(1/2) is half the length.
// For W >= 1e16 these bounds pin the answers to rounding; in double the curve passes its
// second leg within 1e-30 of t = 1 (for W = 1e30), where t has no digits left.
TEST(ExtremeWeights, RationalQuadraticHuggingItsPolygon) {
  for (const double w : {1e16, 1e30}) {
    SCOPED_TRACE(w);
    const R2 c({{1, 0}, {1, 1}, {0, 1}}, {1, w, 1});
    // 1e-12 relative is the contract; the bounds above are tighter than that.
    EXPECT_NEAR(arc_length(c), 2.0, 2e-12);
    EXPECT_NEAR(arc_length(c, 0.0, 0.5), 1.0, 1e-12);
    EXPECT_NEAR(arc_length(c, 0.5, 1.0), 1.0, 1e-12);
    const auto r = project(c, P2(1, 1.5));
    EXPECT_NEAR(r.distance, 0.5, 1e-12);
    EXPECT_TRUE(r.all_t.empty());
    // The point reported is on the curve near the corner, at the distance reported.
    EXPECT_NEAR(norm(r.point - P2(1, 1.5)), r.distance, 4 * eps);
    // Half the length is reached at the corner (within 1e-12 of the length along the legs).
    const double t = ArcLengthTable<double, 2>(c).parameter_at(1.0);
    EXPECT_LE(norm(c(t) - P2(1, 1)), 4e-12) << t;
  }
  // A NURBS of the same data (one piece) gives the same answers.
  const Nurbs<double, 2> n(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, 1e30, 1});
  EXPECT_NEAR(arc_length(n), 2.0, 2e-12);
  EXPECT_NEAR(project(n, P2(1, 1.5)).distance, 0.5, 1e-12);
}

// Curvature and the frame do not depend on the scale of the parameter: the cubic above as a
// B-spline on [0, L] has curvature -36 / 45^(3/2) at its start (C' = 3 (1, 2), C'' = (0, -12)
// per unit parameter) and -4/3 at its middle, for any L.
TEST(Curvature, IndependentOfTheDomainsScale) {
  for (const double len : {1e-300, 1e-200, 1e-160, 1.0, 1e160, 1e200, 1e300}) {
    SCOPED_TRACE(len);
    const BSpline<double, 2> bs(3, {0, 0, 0, 0, len, len, len, len}, {{0, 0}, {1, 2}, {2, 2}, {3, 0}});
    const auto p = pieces(bs);
    const auto k0 = curvature(p, 0.0), km = curvature(p, len / 2);
    ASSERT_TRUE(k0 && km);
    // A few roundings of the derivatives and of one division chain.
    EXPECT_NEAR(*k0, -36 / std::pow(45.0, 1.5), 8 * eps);
    EXPECT_NEAR(*km, -4.0 / 3, 8 * eps);
    const auto f = frame(bs, len / 2);
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(f->curvature, -4.0 / 3, 8 * eps);
    EXPECT_NEAR(f->tangent[0], 1.0, 4 * eps);
  }
}

// The shared degenerate fixtures through every query: finite answers, the closest point
// no farther than any of 2001 samples, the length between the chord and the control
// polygon's length.
TEST(Queries, DegenerateFixtures) {
  for (const auto& f : test::degenerate_fixtures()) {
    SCOPED_TRACE(f.name);
    const auto& P = f.curve.points();
    const P2 q(P.front()[0] * 0.5 + f.scale * 0.3, P.front()[1] * 0.5 - f.scale * 0.2);
    const auto r = project(f.curve, q);
    ASSERT_TRUE(std::isfinite(r.distance));
    for (int i = 0; i <= 2000; ++i) {
      const double t = i / 2000.0;
      EXPECT_LE(r.distance, distance(f.curve(t), q) * (1 + 1e-12) + 64 * eps * f.scale) << t;
    }
    const double len = arc_length(f.curve);
    ASSERT_TRUE(std::isfinite(len));
    double polygon = 0;
    for (std::size_t i = 0; i + 1 < P.size(); ++i) polygon += distance(P[i], P[i + 1]);
    EXPECT_GE(len, distance(P.front(), P.back()) * (1 - 1e-12));
    EXPECT_LE(len, polygon * (1 + 1e-12));
    const auto ft = features(f.curve);
    for (double t : ft.inflections) EXPECT_TRUE(t > 0 && t < 1);
    const ArcLengthTable<double, 2> table(f.curve);
    const double mid = table.parameter_at(table.total() / 2);
    EXPECT_TRUE(mid >= 0 && mid <= 1);
  }
}

// --- area (Green's theorem) ---------------------------------------------------------------------

TEST(Area, ClosedForms) {
  EXPECT_NEAR(area(circle(3, 5, -2)), 9 * pi, 16 * eps * 9 * pi);
  const Polyline<double, 2> square({{0, 0}, {2, 0}, {2, 1}, {0, 1}, {0, 0}});
  EXPECT_EQ(area(square), 2.0);
  EXPECT_EQ(area(square.reverse()), -2.0);
  // The closed cubic (0,0), (1,0), (1,1), (0,0): x = 3t - 3t^2, y = 3t^2 - 3t^3, so
  // x y' - y x' = 9t^2 - 18t^3 + 9t^4 (by hand), whose integral is 3/10: area 3/20.
  EXPECT_NEAR(area(B2{{0, 0}, {1, 0}, {1, 1}, {0, 0}}), 0.15, 2 * eps);
  EXPECT_INVALID_ARGUMENT(area(B2{{0, 0}, {1, 0}, {1, 1}}), "curve", "closed");
}

// --- features -----------------------------------------------------------------------------------

TEST(Features, InflectionCuspExtrema) {
  // y = 3t(1-t)(1-2t), x = 3t: inflection at 1/2, y' = 0 at 1/2 -+ sqrt(3)/6.
  const auto f = features(B2{{0, 0}, {1, 1}, {2, -1}, {3, 0}});
  ASSERT_EQ(f.inflections.size(), 1u);
  EXPECT_NEAR(f.inflections[0], 0.5, 4 * eps);
  ASSERT_EQ(f.extrema[1].size(), 2u);
  EXPECT_NEAR(f.extrema[1][0], 0.5 - std::sqrt(3.0) / 6, 4 * eps);
  EXPECT_NEAR(f.extrema[1][1], 0.5 + std::sqrt(3.0) / 6, 4 * eps);
  EXPECT_TRUE(f.extrema[0].empty());
  const auto c = features(B2{{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  ASSERT_EQ(c.cusps.size(), 1u);
  EXPECT_NEAR(c.cusps[0], 0.5, 1e-12);
  EXPECT_TRUE(c.inflections.empty());
}

// --- distance between curves --------------------------------------------------------------------

TEST(Distance, ClosedForms) {
  const auto d = distance(B2{{0, 0}, {2, 0}}, B2{{1, 1}, {1, 3}});
  EXPECT_EQ(d.distance, 1.0);
  EXPECT_EQ(d.t[0], 0.5);
  EXPECT_EQ(d.t[1], 0.0);
  // Concentric circles: the difference of the radii.
  EXPECT_NEAR(distance(circle(1), circle(2.5)).distance, 1.5, 8 * eps);
  // A parabola and a line above its vertex: y = x^2 and y = -1 at distance 1.
  EXPECT_NEAR(distance(B2{{-1, 1}, {0, -1}, {1, 1}}, B2{{-2, -1}, {2, -1}}).distance, 1.0, 4 * eps);
  // Crossing: 0.
  EXPECT_LE(distance(B2{{0, 0}, {1, 2}, {2, 0}}, B2{{0, 0.5}, {2, 0.5}}).distance, 4 * eps);
}

// A unit-size problem 10^12 from the origin keeps its digits (distances are measured
// relative to q, or to a's control box): y = x^2 (x in [-1, 1]) seen from (0, 5/4) is
// nearest at x = +-sqrt(3)/2, t = (1 +- sqrt(3)/2) / 2, at distance exactly 1; y = x^2
// and the line y = -1 are 1 apart. Every input below is an integer or a quarter:
// representable, so the shifted problems are the same problems.
TEST(Queries, FarFromTheOrigin) {
  for (const double o : {0.0, 1e6, 1e9, 1e12}) {
    const B2 parabola{{o - 1, o + 1}, {o, o - 1}, {o + 1, o + 1}};
    const auto r = project(parabola, P2(o, o + 1.25));
    EXPECT_NEAR(r.distance, 1.0, 8 * eps) << o;
    ASSERT_EQ(r.all_t.size(), 2u) << o;
    EXPECT_NEAR(r.all_t[0], (1 - std::sqrt(0.75)) / 2, 1e-7) << o;  // a flat minimum: sqrt(eps)
    EXPECT_NEAR(r.all_t[1], (1 + std::sqrt(0.75)) / 2, 1e-7) << o;
    const auto d = distance(parabola, B2{{o - 2, o - 1}, {o + 2, o - 1}});
    EXPECT_NEAR(d.distance, 1.0, 8 * eps) << o;
    EXPECT_NEAR(d.t[0], 0.5, 1e-7) << o;
  }
}

}  // namespace
