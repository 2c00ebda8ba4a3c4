// The operations of issue 20 in the library: solve (level sets of a coordinate or a linear
// functional), to_bspline (pieces back to one B-spline with the continuity they have) and
// max_deviation (the largest distance at equal parameters), on closed forms and curves
// built in the test with known roots, knots and distances; offset against closed forms.
// (to_quadratic's tests sample densely: tests/unit/to_quadratic_test.cpp, built at -O1.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "test_support.hpp"  // the whole library (casteljau.hpp: solve, to_bspline, deviation)

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;
using B2 = Bezier<double, 2>;
using R2 = RationalBezier<double, 2>;

TEST(Solve, ExactDoubleRootReportedOnce) {
  // y(t) = 12 (t - 3/8)^2 (t - 13/16) in Bernstein form (exact in double): power form
  // 12t^3 - 18.75t^2 + 9t - 1.37109375, b_i = sum_k C(i,k)/C(3,k) a_k (a1/3, a2/3 exact).
  const double a0 = -1.37109375, a1 = 9, a2 = -18.75, a3 = 12;
  const double b0 = a0, b1 = a0 + a1 / 3, b2 = a0 + 2 * a1 / 3 + a2 / 3, b3 = a0 + a1 + a2 + a3;
  const B2 c({P2(0, b0), P2(1.0 / 3, b1), P2(2.0 / 3, b2), P2(1, b3)});
  const auto s = solve(c, V2(0, 1), 0.0);
  EXPECT_TRUE(s.intervals.empty());
  ASSERT_EQ(s.t.size(), 2u);
  EXPECT_NEAR(s.t[0], 0.375, 4 * casteljau::test::eps);  // exact data: a few eps
  EXPECT_NEAR(s.t[1], 0.8125, 4 * casteljau::test::eps);
}

TEST(Solve, IntervalsMergeAcrossPiecesAndSwallowTheirRoots) {
  // Breaks 0, 1, 2, 3: a parabola ending on the axis, two straight pieces on it, a rise.
  Pieces<double, 2> p({B2({P2(0, 1), P2(1, -1), P2(2, 0)}), B2({P2(2, 0), P2(3, 0)}), B2({P2(3, 0), P2(4, 0)}),
                       B2({P2(4, 0), P2(5, 1)})});
  const auto s = solve(p, V2(0, 1), 0.0);
  ASSERT_EQ(s.intervals.size(), 1u);
  EXPECT_EQ(s.intervals[0].lo, 1.0);
  EXPECT_EQ(s.intervals[0].hi, 3.0);
  // (3u - 1)(u - 1) = 0 on the first piece: u = 1/3 (u = 1 is the interval's end).
  ASSERT_EQ(s.t.size(), 1u);
  EXPECT_NEAR(s.t[0], 1.0 / 3, 4 * casteljau::test::eps);
}

TEST(Solve, RationalCircleAtItsBreaksAndTangencies) {
  std::vector<BezierPiece<double, 2>> segs;
  for (int i = 0; i < 4; ++i) segs.emplace_back(R2::circular_arc(P2(0, 0), 1.0, i * std::numbers::pi / 2, (i + 1) * std::numbers::pi / 2));
  const Pieces<double, 2> circle(std::move(segs));  // breaks 0..4
  EXPECT_EQ(solve(circle, V2(1, 0), 0.0).t, (std::vector<double>{1, 3}));  // joints, once each
  EXPECT_EQ(solve(circle, V2(0, 1), -1.0).t, (std::vector<double>{3}));    // tangency at a joint
  EXPECT_EQ(solve(circle, V2(1, 0), 1.0).t, (std::vector<double>{0, 4}));  // both ends
  EXPECT_TRUE(solve(circle, V2(1, 0), 1.5).t.empty());
}

TEST(Solve, RandomCubicsMatchSignChangesOfDenseSamples) {
  // Property: every reported root is a root (|y| small), and their count equals the sign
  // changes of y over 4001 samples (random data: simple roots, no tangency).
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const B2 c({P2(0, u(rng)), P2(1, u(rng)), P2(2, u(rng)), P2(3, u(rng))});
    const double v = 0.5 * u(rng);
    const auto s = solve(c, V2(0, 1), v);
    int changes = 0;
    double prev = c(0.0)[1] - v;
    for (int j = 1; j <= 4000; ++j) {
      const double y = c(j / 4000.0)[1] - v;
      if ((y > 0) != (prev > 0) && y != 0 && prev != 0) ++changes;
      prev = y;
    }
    EXPECT_EQ(static_cast<int>(s.t.size()), changes) << "trial " << trial;
    for (double t : s.t) EXPECT_NEAR(c(t)[1], v, 1e-13) << "trial " << trial;  // a few eps of |P| <= 1
  }
}

TEST(Solve, BadDirection) {
  const B2 c({P2(0, 0), P2(1, 1)});
  EXPECT_THROW((void)solve(c, V2(0, 0), 1.0), InvalidArgument);
  EXPECT_THROW((void)solve(c, V2(1, 0), std::nan("")), InvalidArgument);
}

// A level near large coordinates (audit D20): y - value has the exact control values
// [-1, 1, 1, -1] at 1e13, so the roots are those of -1 + 6t - 6t^2, (3 -+ sqrt 3) / 6,
// whatever type holds the curve (a Bézier's pieces are its points; a B-spline's are
// blossoms, within (4 p + 1) eps of the span's largest control coordinate). At a jump (D3)
// only the right limit is the curve's value.
TEST(Solve, LevelNearLargeCoordinatesAndJumps) {
  const double big = 1e13;
  const std::vector<P2> P{P2(0, big), P2(1, big + 2), P2(3, big + 2), P2(4, big)};
  const std::vector<double> want{(3 - std::sqrt(3.0)) / 6, (3 + std::sqrt(3.0)) / 6};
  EXPECT_TRUE(detail::piece_errors(B2(P), pieces(B2(P))).empty());
  const BSpline<double, 2> spline(3, {0, 0, 0, 0, 1, 1, 1, 1}, P);
  const auto errors = detail::piece_errors(spline, pieces(spline));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].coordinate[0], 13 * casteljau::test::eps * 4);
  EXPECT_EQ(errors[0].coordinate[1], 13 * casteljau::test::eps * (big + 2));
  for (const auto& s : {solve(B2(P), V2(0, 1), big + 1), solve(BSpline<double, 2>(3, {0, 0, 0, 0, 1, 1, 1, 1}, P), V2(0, 1), big + 1)}) {
    EXPECT_TRUE(s.intervals.empty());
    ASSERT_EQ(s.t.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(s.t[i], want[i], 4 * casteljau::test::eps);
  }
  // x = 2t on [0, 1), 3 - 2 (t - 1) on [1, 2]: 2 only at 1.5 (1 is the left limit's).
  const BSpline<double, 1> j(1, {0, 0, 1, 1, 2, 2}, {Point<double, 1>(0), Point<double, 1>(2), Point<double, 1>(3), Point<double, 1>(1)});
  EXPECT_EQ(solve(j, Vector<double, 1>(1), 2.0).t, (std::vector<double>{1.5}));
  EXPECT_EQ(solve(j, Vector<double, 1>(1), 3.0).t, (std::vector<double>{1.0}));
}

TEST(ToBSpline, UniformCubicComesBackWithSimpleKnots) {
  // A clamped cubic B-spline with simple interior knots: C^2 at each, so its pieces come
  // back with every interior knot once and the same control points.
  const std::vector<double> U{0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4};
  const std::vector<P2> P{P2(0, 0), P2(1, 2), P2(2, -1), P2(3, 3), P2(4, 0), P2(5, 1), P2(6, -2)};
  const BSpline<double, 2> b(3, U, P);
  const auto r = to_bspline(pieces(b));
  ASSERT_TRUE((std::holds_alternative<BSpline<double, 2>>(r)));
  const auto& g = std::get<BSpline<double, 2>>(r);
  EXPECT_EQ(g.knots(), U);
  ASSERT_EQ(g.points().size(), P.size());
  // Blossoming into pieces and 2 removals per knot: a few hundred eps of |P| <= 6.
  for (std::size_t i = 0; i < P.size(); ++i) EXPECT_LT(norm(g.points()[i] - P[i]), 1e-12) << i;
}

TEST(ToBSpline, ContinuityDecidesMultiplicity) {
  // One cubic cut in two at a dyadic parameter (exact halves): the knot disappears.
  const B2 c({P2(0, 0), P2(1, 3), P2(3, 3), P2(4, 0)});
  const auto [l, rr] = c.split(0.5);
  const auto one = std::get<BSpline<double, 2>>(to_bspline(Pieces<double, 2>({l, rr})));
  EXPECT_EQ(one.knots(), (std::vector<double>{0, 0, 0, 0, 2, 2, 2, 2}));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT(norm(one.points()[i] - c.points()[i]), 1e-14);
  // A line then a parabola, C^0: the quadratic's knot twice; a gap (not even C^0): the
  // knot p + 1 = 3 times and both pieces whole, the B-spline jumps there as the path does.
  const Pieces<double, 2> corner({B2({P2(0, 0), P2(1, 1)}), B2({P2(1, 1), P2(2, 2), P2(3, 0)})});
  EXPECT_EQ((std::get<BSpline<double, 2>>(to_bspline(corner)).knots()), (std::vector<double>{0, 0, 0, 1, 1, 2, 2, 2}));
  const Pieces<double, 2> gap({B2({P2(0, 0), P2(1, 1)}), B2({P2(1, 2), P2(2, 2), P2(3, 0)})});
  const auto jump = std::get<BSpline<double, 2>>(to_bspline(gap));
  EXPECT_EQ(jump.knots(), (std::vector<double>{0, 0, 0, 1, 1, 1, 2, 2, 2}));
  EXPECT_EQ(jump(1.0), P2(1, 2));  // the right limit at the break
  EXPECT_LT(norm(jump(0.5) - P2(0.5, 0.5)), 1e-15);
  EXPECT_LT(norm(jump(1.5) - gap(1.5)), 1e-15);
}

TEST(ToBSpline, CircleIsANurbsWithDoubleKnots) {
  std::vector<BezierPiece<double, 2>> segs;
  for (int i = 0; i < 4; ++i) segs.emplace_back(R2::circular_arc(P2(0, 0), 1.0, i * std::numbers::pi / 2, (i + 1) * std::numbers::pi / 2));
  const Pieces<double, 2> circle(std::move(segs));
  const auto r = to_bspline(circle);
  ASSERT_TRUE((std::holds_alternative<Nurbs<double, 2>>(r)));
  const auto& n = std::get<Nurbs<double, 2>>(r);
  // The homogeneous quarter arcs meet with C^0 only (their middle weights are 1/sqrt 2).
  EXPECT_EQ(n.knots(), (std::vector<double>{0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}));
  for (int j = 0; j <= 64; ++j) {
    const double t = j / 16.0;
    EXPECT_LT(norm(n(t) - circle(t)), 1e-15) << t;  // the same curve, same parameter: rounding
  }
}

TEST(MaxDeviation, FindsAPeakBetweenSamples) {
  // |a(u) - b(u)| = u (1 - u): maximum 1/4 at u = 1/2, not a sample for 7 samples.
  const auto a = [](double u) { return P2(u, 0); };
  const auto b = [](double u) { return P2(u, u * (1 - u)); };
  EXPECT_NEAR(max_deviation<double>(a, b, {0.0, 1.0}, 7), 0.25, 1e-15);  // golden section to 1e-13 in u: quadratic peak
}

// ---------------------------------------------------------------------------------------
// reduce_spline: the library's degree reduction of B-splines and NURBS (the command line's
// `reduce`), on curves with known answers.

TEST(ReduceSpline, ElevatedParabolaComesBackExactly) {
  // The parabola (2t, 4t (1 - t)): its cubic Bezier form (0,0) (2/3,4/3) (4/3,4/3) (2,0)
  // with the knot 1/2 inserted by Boehm's rule (every alpha 1/2: the midpoints), by hand.
  const BSpline<double, 2> cubic(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                                 {P2(0, 0), P2(1.0 / 3, 2.0 / 3), P2(1, 4.0 / 3), P2(5.0 / 3, 2.0 / 3), P2(2, 0)});
  const auto r = reduce_spline(cubic, 1);
  EXPECT_EQ(r.curve.degree(), 2);
  EXPECT_EQ(r.curve.knots(), (std::vector<double>{0, 0, 0, 0.5, 1, 1, 1}));  // the break kept, C1
  EXPECT_LT(r.max_error, 1e-14);                                             // rounding of the data and the fit
  for (const double t : {0.0, 0.1, 0.37, 0.5, 0.8, 1.0}) EXPECT_LT(norm(r.curve(t) - P2(2 * t, 4 * t * (1 - t))), 1e-14) << t;
}

TEST(ReduceSpline, QuarterCircleToItsChord) {
  // Degree 2 to 1 with the ends kept: the chord; the largest distance at equal parameters
  // is at t = 1/2 (symmetry), |(1, 1) / sqrt(2) - (1, 1) / 2| = 1 - sqrt(2) / 2.
  const Nurbs<double, 2> quarter(2, {0, 0, 0, 1, 1, 1}, {P2(1, 0), P2(1, 1), P2(0, 1)}, {1, std::sqrt(0.5), 1});
  const auto r = reduce_spline(quarter, 1);
  EXPECT_EQ(r.curve.degree(), 1);
  EXPECT_EQ(r.curve.points().front(), P2(1, 0));
  EXPECT_EQ(r.curve.points().back(), P2(0, 1));
  EXPECT_NEAR(r.max_error, 1 - std::sqrt(2.0) / 2, 4 * casteljau::test::eps);
}

TEST(ReduceSpline, NoWorseThanKnotRemovalAndTheMeanAtDegreeZero) {
  // The cubic of two pieces of docs/cli.md: [PT97] A5.11 alone (the member reduce_degree)
  // is 0.2039 off; the best candidate is no worse, with the same ends.
  const BSpline<double, 2> c(3, {0, 0, 0, 0, 1, 2, 2, 2, 2}, {P2(0, 0), P2(1, 2), P2(2, 2), P2(3, 0), P2(4, 1)});
  const auto r = reduce_spline(c, 1);
  const BSpline<double, 2> a511 = c.reduce_degree(std::numeric_limits<double>::max()).curve;
  EXPECT_LE(r.max_error, max_deviation<double>(c, a511, {0.0, 1.0, 2.0}, 128));
  EXPECT_EQ(r.curve.points().front(), P2(0, 0));
  EXPECT_EQ(r.curve.points().back(), P2(4, 1));
  EXPECT_EQ(reduce_spline_work(c), 2 * (64.0 + 1000));
  // The segment (0,0)-(4,3) in two pieces, to degree 0: its mean (2, 1.5), 2.5 from its ends.
  const BSpline<double, 2> line(1, {0, 0, 0.5, 1, 1}, {P2(0, 0), P2(2, 1.5), P2(4, 3)});
  const auto z = reduce_spline(line, 1);
  ASSERT_EQ(z.curve.points().size(), 1u);
  EXPECT_LT(norm(z.curve.points()[0] - P2(2, 1.5)), 1e-14);
  EXPECT_NEAR(z.max_error, 2.5, 1e-14);
  EXPECT_THROW((void)reduce_spline(line, 2), InvalidArgument);  // times outside 1..p
  EXPECT_THROW((void)reduce_spline(line, 0), InvalidArgument);
}

// ---------------------------------------------------------------------------------------
// offset: closed forms (concentric circles, parallel lines, the parabola's offset
// (x - 2 d x / s, x^2 + d / s), s = sqrt(1 + 4 x^2)), measured on dense samples of the
// output against them.

/// The largest |f(B(u))| over 200 samples of every cubic (a signed distance's residual).
template <class F>
double worst_on(const std::vector<B2>& cubics, const F& residual) {
  double worst = 0;
  for (const auto& B : cubics)
    for (int j = 0; j <= 200; ++j) worst = std::max(worst, std::abs(residual(B(j / 200.0))));
  return worst;
}

OffsetOptions<double> offset_options(double d, double tol, bool trim = true) {
  OffsetOptions<double> o;
  o.distance = d;
  o.tolerance = tol;
  o.trim = trim;
  return o;
}

TEST(Offset, CircleArcIsConcentric) {
  const Pieces<double, 2> arc(std::vector<BezierPiece<double, 2>>{R2::circular_arc(P2(0, 0), 2.0, 0.0, 2.0)});
  for (const double d : {0.5, -0.5, 1.5}) {
    const auto r = offset(arc, offset_options(d, 1e-7));
    ASSERT_FALSE(r.segments.empty());
    // Left of a counter-clockwise arc is inward: radius 2 - d.
    EXPECT_LE(worst_on(r.segments, [&](const P2& p) { return norm(p - P2(0, 0)) - (2 - d); }), 1e-7) << d;
    EXPECT_LT(norm(r.segments.front().points().front() - P2(2 - d, 0)), 1e-14);
    EXPECT_LT(norm(r.segments.back().points().back() - P2((2 - d) * std::cos(2.0), (2 - d) * std::sin(2.0))), 1e-14);
    EXPECT_LE(r.max_error, 1e-7);
    for (std::size_t i = 1; i < r.segments.size(); ++i) EXPECT_EQ(r.segments[i].points().front(), r.segments[i - 1].points().back());
  }
}

TEST(Offset, LineIsParallel) {
  const auto r = offset(pieces(B2({P2(0, 0), P2(3, 4)})), offset_options(5, 1e-9));
  ASSERT_EQ(r.segments.size(), 1u);
  // Left of (3, 4) / 5 is (-4, 3) / 5: the line moved by (-4, 3), to rounding.
  for (const auto& p : r.segments[0].points()) EXPECT_NEAR(cross(V2(3, 4), p - P2(-4, 3)), 0.0, 1e-14);
  EXPECT_LT(norm(r.segments[0].points().front() - P2(-4, 3)), 1e-15);
  EXPECT_LT(norm(r.segments[0].points().back() - P2(-1, 7)), 1e-14);
}

TEST(Offset, ParabolaAgainstItsClosedForm) {
  // y = x^2 on [-1, 1]: the quadratic Bézier (-1, 1), (0, -1), (1, 1) with x = 2t - 1.
  const auto parabola = pieces(B2({P2(-1, 1), P2(0, -1), P2(1, 1)}));
  const double d = 0.3, tol = 1e-5;  // below the radius of curvature 1/2 at the vertex: no cusp
  const auto r = offset(parabola, offset_options(d, tol));
  std::vector<P2> exact;
  for (int j = 0; j <= 4000; ++j) {
    const double x = -1 + j / 2000.0, s = std::sqrt(1 + 4 * x * x);
    exact.push_back(P2(x - 2 * d * x / s, x * x + d / s));
  }
  // Distance to the dense polyline of the exact offset: its chords (at most 1.2e-3 long)
  // have a sagitta below (1.2e-3)^2 kappa / 8 < 1e-6 (kappa < 5 here), the margin below.
  const auto to_exact = [&](const P2& p) {
    double best = 1e300;
    for (std::size_t k = 0; k + 1 < exact.size(); ++k) {
      const V2 a = p - exact[k], e = exact[k + 1] - exact[k];
      const double s = std::clamp(dot(a, e) / dot(e, e), 0.0, 1.0);
      best = std::min(best, norm(a - e * s));
    }
    return best;
  };
  double worst = 0;
  for (const auto& B : r.segments)
    for (int j = 0; j <= 20; ++j) worst = std::max(worst, to_exact(B(j / 20.0)));
  EXPECT_LE(worst, tol + 1e-6);
}

TEST(Offset, ParabolaLoopTrimmedAtItsSelfIntersection) {
  // d = 1 beyond the radius 1/2 at the vertex: cusps at x = +-0.383 and a swallowtail
  // closing on the axis at (0, 3/4 + 1/2) (where sqrt(1 + 4 x^2) = 2 d).
  const auto parabola = pieces(B2({P2(-1, 1), P2(0, -1), P2(1, 1)}));
  const double tol = 1e-6;
  const auto raw = offset(parabola, offset_options(1.0, tol, false));
  const auto cut = offset(parabola, offset_options(1.0, tol, true));
  EXPECT_EQ(raw.loops_cut, 0u);
  EXPECT_EQ(cut.loops_cut, 1u);
  EXPECT_LT(cut.segments.size(), raw.segments.size());
  bool meets = false;
  // The cubics' crossing: each branch within tol of its exact branch, the branches
  // crossing at 120 degrees (60 between the lines): the points within tol of both lines
  // form a rhombus about the exact crossing whose farthest corners, on the bisector of the
  // 60-degree angle, are tol / sin(30 degrees) = 2 tol away (tol / sin(60 degrees) holds
  // only along the other diagonal).
  for (const auto& B : cut.segments) meets = meets || norm(B.points().back() - P2(0, 1.25)) < tol / std::sin(std::numbers::pi / 6);
  EXPECT_TRUE(meets);
  // Everything kept is at least d - tol from the parabola (the loop's points are closer).
  const auto to_parabola = [](const P2& p) {
    double best = 1e300;
    for (int j = 0; j <= 4000; ++j) {
      const double x = -1.5 + 3.0 * j / 4000;
      best = std::min(best, norm(p - P2(x, x * x)));
    }
    return best;
  };
  double nearest = 1e300;
  for (const auto& B : cut.segments)
    for (int j = 0; j <= 20; ++j) nearest = std::min(nearest, to_parabola(B(j / 20.0)));
  EXPECT_GE(nearest, 1.0 - tol - 1e-6);  // the sampled parabola's spacing 7.5e-4: its error is below 1e-6 near the minimum
}

TEST(Offset, FewerCubicsThanUniformSubdivision) {
  // The reference of issue 20: uniform subdivision (n equal parameter parts, Hermite
  // cubics, n = 1, 2, ... until within the tolerance). The greedy fit takes no more.
  const auto s_curve = pieces(B2({P2(0, 0), P2(1, 3), P2(3, -2), P2(4, 1)}));
  const auto arc = Pieces<double, 2>(std::vector<BezierPiece<double, 2>>{R2::circular_arc(P2(0, 0), 1.0, 0.0, 3.0)});
  for (const auto* c : {&s_curve, &arc}) {
    for (const double tol : {1e-3, 1e-4}) {
      auto o = offset_options(0.2, tol, false);
      const auto greedy = offset(*c, o);
      o.fit = OffsetFit::uniform;
      const auto uniform = offset(*c, o);
      EXPECT_LE(greedy.segments.size(), uniform.segments.size()) << tol;
      EXPECT_LE(greedy.max_error, tol);
      EXPECT_LE(uniform.max_error, tol);
    }
  }
}

TEST(Offset, CornersAndErrors) {
  // The polyline (0,0) -> (2,0) -> (2,2) at d = -0.5: a miter at (2.5, -0.5).
  const Pieces<double, 2> L(std::vector<BezierPiece<double, 2>>{B2({P2(0, 0), P2(2, 0)}), B2({P2(2, 0), P2(2, 2)})});
  auto o = offset_options(-0.5, 1e-6);
  o.join = OffsetJoin::miter;
  const auto m = offset(L, o);
  ASSERT_EQ(m.segments.size(), 4u);
  EXPECT_LT(norm(m.segments[1].points().back() - P2(2.5, -0.5)), 1e-15);  // a unit vector and a cosine: a few ulps
  o.join = OffsetJoin::round;
  const auto r = offset(L, o);
  EXPECT_LE(worst_on({r.segments.begin() + 1, r.segments.end() - 1}, [](const P2& p) { return norm(p - P2(2, 0)) - 0.5; }), 1e-6);
  EXPECT_THROW((void)offset(L, offset_options(1, 0)), InvalidArgument);
  EXPECT_THROW((void)offset(pieces(B2({P2(1, 1), P2(1, 1)})), offset_options(1, 1e-3)), InvalidArgument);
  o.miter_limit = 0.5;
  EXPECT_THROW((void)offset(L, o), InvalidArgument);
}


// The offset's phases alone (algo/offset/: detail::offset), against closed forms.

TEST(OffsetPhases, StretchesCutAtTheParabolasOffsetCusps) {
  // y = x^2, x = 2t - 1: curvature kappa(x) = 2 / (1 + 4 x^2)^(3/2), radius 1/2 at the vertex.
  // At d = 1 the offset's cusps are where kappa = 1: x = +-sqrt(2^(2/3) - 1) / 2; between
  // them 1 - d kappa < 0 (the offset runs backwards).
  const B2 parabola({P2(-1, 1), P2(0, -1), P2(1, 1)});
  const double tiny = 64 * std::numeric_limits<double>::epsilon();
  const double x = std::sqrt(std::cbrt(4.0) - 1) / 2;
  const auto s = detail::offset::stretches<double>(parabola, 1.0, tiny);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].lo, 0.0);
  EXPECT_NEAR(s[0].hi, (1 - x) / 2, 1e-12);
  EXPECT_NEAR(s[1].hi, (1 + x) / 2, 1e-12);
  EXPECT_EQ(s[2].hi, 1.0);
  EXPECT_EQ(s[0].hi, s[1].lo);
  EXPECT_EQ(s[1].hi, s[2].lo);
  EXPECT_FALSE(s[0].reversed);
  EXPECT_TRUE(s[1].reversed);
  EXPECT_FALSE(s[2].reversed);
  // The curve's unit tangent (1, 2x) / sqrt(1 + 4 x^2) at the ends: (1, -2) / sqrt(5) at x = -1.
  EXPECT_LT(norm(s[0].t_lo - V2(1, -2) / std::sqrt(5.0)), 1e-15);
  EXPECT_LT(norm(s[2].t_hi - V2(1, 2) / std::sqrt(5.0)), 1e-15);
  // Below the radius at the vertex: one stretch; at it (d = 1/2, a touch of 1 - d kappa =
  // 24 (t - 1/2)^2 + O((t - 1/2)^4)): cut at the vertex, neither half reversed.
  const auto below = detail::offset::stretches<double>(parabola, 0.3, tiny);
  ASSERT_EQ(below.size(), 1u);
  EXPECT_FALSE(below[0].reversed);
  const auto touch = detail::offset::stretches<double>(parabola, 0.5, tiny);
  ASSERT_EQ(touch.size(), 2u);
  EXPECT_NEAR(touch[0].hi, 0.5, 1e-6);  // a minimum of |1 - d kappa| by golden section: sqrt(eps)
  EXPECT_FALSE(touch[0].reversed);
  EXPECT_FALSE(touch[1].reversed);
}

TEST(OffsetPhases, MeasuresOfTheClassicQuarterCircleCubic) {
  // The cubic (1, 0), (1, k), (k, 1), (0, 1), k = 4 (sqrt 2 - 1) / 3, against the unit
  // quarter circle: it lies outside, its ends and middle on the circle, and its distance
  // |B(u)| - 1 (each point's to the circle, along the radii: the circle's normal lines) is
  // largest at u = 1/2 -+ sqrt(3) / 6, 2.7253e-4 (the textbook figure).
  const double k = 4 * (std::sqrt(2.0) - 1) / 3;
  const detail::offset::CubicForm<double> F(P2(1, 0), P2(1, k), P2(k, 1), P2(0, 1));
  const double u = 0.5 - std::sqrt(3.0) / 6;
  const P2 top = B2({P2(1, 0), P2(1, k), P2(k, 1), P2(0, 1)})(u);
  const double exact = norm(top.to_vector()) - 1;
  EXPECT_NEAR(exact, 2.7253e-4, 1e-8);
  detail::offset::Source<double> arc;
  arc.point = [](double s) { return P2(std::cos(s), std::sin(s)); };
  arc.velocity = [](double s) { return V2(-std::sin(s), std::cos(s)); };
  arc.tangent = arc.velocity;
  arc.frame = [](double s) { return std::pair{P2(std::cos(s), std::sin(s)), V2(-std::sin(s), std::cos(s))}; };
  arc.lo = 0, arc.hi = std::numbers::pi / 2;
  const double inf = std::numeric_limits<double>::infinity();
  // The projections both ways (hausdorff, and from partners) find the bumps' tops to about
  // 1e-5 relative, as their refinement promises. The normal-line measure counts the top of
  // each parabola through three feet (the first 1/20 of the arc apart), which errs high
  // (the safe side): on this bump by 6e-4 of its height, within 1e-3 and never below. The
  // distance at equal parameters (the arc's angle against the cubic's u) bounds them all.
  const double scan = detail::offset::measured(F, arc, arc.lo, arc.hi, inf);
  const double proj = detail::offset::hausdorff(F, arc, arc.lo, arc.hi, inf);
  const double partners = detail::offset::partner_distance(F, arc, arc.lo, arc.hi, inf);
  const double param = detail::offset::parametric(F, arc, arc.lo, arc.hi, inf);
  EXPECT_GE(scan, exact * (1 - 1e-5));
  EXPECT_LE(scan, exact * (1 + 1e-3));
  EXPECT_NEAR(proj, exact, 1e-5 * exact);
  EXPECT_NEAR(partners, exact, 1e-5 * exact);
  EXPECT_GE(param, exact * (1 - 1e-5));
  // A stop above: the measure stops once a sample exceeds it (a value above it).
  EXPECT_GT(detail::offset::measured(F, arc, arc.lo, arc.hi, 1e-4), 1e-4);
}

TEST(OffsetPhases, JoinsAtARightAngle) {
  // The corner (2, 0) turning left from (1, 0) to (0, 1), by 90 degrees.
  const detail::offset::Corner<double> c{P2(2, 0), V2(1, 0), V2(0, 1)};
  const auto joined = [&](double d, OffsetJoin kind, double limit) {
    detail::offset::Raw<double> raw;
    raw.tolerance = 1e-9, raw.max_segments = 100;
    OffsetOptions<double> o;
    o.join = kind, o.miter_limit = limit;
    detail::offset::join(c, o, d, raw);
    return raw;
  };
  // Inside (d > 0, the side of the turn): the line from (2, 0.5) back to (1.5, 0), reversed.
  const auto inner = joined(0.5, OffsetJoin::round, 4);
  ASSERT_EQ(inner.cubics.size(), 1u);
  EXPECT_TRUE(inner.reversed[0]);
  EXPECT_EQ(inner.kind[0], detail::offset::RawKind::inner_join);
  EXPECT_LT(norm(inner.cubics[0][0] - P2(2, 0.5)), 1e-15);
  EXPECT_LT(norm(inner.cubics[0][3] - P2(1.5, 0)), 1e-15);
  // Outside (d < 0): a miter to the meeting point (2.5, -0.5) of the offset lines while
  // 1 / cos(45 degrees) = sqrt(2) is within the limit, a bevel (one line) past it.
  const auto miter = joined(-0.5, OffsetJoin::miter, 1.5);
  ASSERT_EQ(miter.cubics.size(), 2u);
  EXPECT_LT(norm(miter.cubics[0][3] - P2(2.5, -0.5)), 1e-15);
  EXPECT_EQ(miter.kind[0], detail::offset::RawKind::outer_join);
  EXPECT_EQ(miter.corner[0], P2(2, 0));
  const auto bevel = joined(-0.5, OffsetJoin::miter, 1.4);
  ASSERT_EQ(bevel.cubics.size(), 1u);
  EXPECT_LT(norm(bevel.cubics[0][0] - P2(2, -0.5)), 1e-15);
  EXPECT_LT(norm(bevel.cubics[0][3] - P2(2.5, 0)), 1e-15);
  // Round: cubics of the quarter circle of radius 0.5 about the corner, within the
  // tolerance (their control points' distance is no bound; the cubics' is sampled).
  const auto round = joined(-0.5, OffsetJoin::round, 4);
  ASSERT_FALSE(round.cubics.empty());
  EXPECT_LE(round.max_error, 1e-9);
  for (const auto& Q : round.cubics) {
    const B2 b({Q[0], Q[1], Q[2], Q[3]});
    for (int j = 0; j <= 64; ++j) EXPECT_NEAR(norm(b(j / 64.0) - P2(2, 0)), 0.5, 1e-9 * (1 + 1e-3));
  }
  EXPECT_LT(norm(round.cubics.front()[0] - P2(2, -0.5)), 1e-15);
  EXPECT_LT(norm(round.cubics.back()[3] - P2(2.5, 0)), 1e-15);
}

}  // namespace
