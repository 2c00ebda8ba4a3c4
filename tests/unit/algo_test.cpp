// Algorithms on hand-solved examples: tight bounds, Bernstein root finding, continuity
// checks and C^r joins, end tangents at cusps, degree reduction and flattening.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;
using casteljau::test::eps;

// --- tight bounds ------------------------------------------------------------------------------

// P = (0,0), (-1,3), (2,-2), (1,0.5). By hand (power form):
//   x(t) = -3t + 12t^2 - 8t^3,  x'(t) = -3 + 24t - 24t^2 = 0 at t = (2 -+ sqrt 2)/4,
//          where x = (1 -+ sqrt 2)/2 (both interior extremes: x(0) = 0, x(1) = 1);
//   y(t) = 9t - 24t^2 + 15.5t^3, y'(t) = 9 - 48t + 46.5t^2 = 0 at t = (48 -+ sqrt 630)/93.
// The box is the end points plus these four values; the root finder locates simple roots
// to a few eps and the value is flat there, so the bound is good to a few ulps of |P|.
TEST(Bounds, CubicWithInteriorExtremaFromQuadratic) {
  const Bezier<double, 2> c{{0, 0}, {-1, 3}, {2, -2}, {1, 0.5}};
  auto y = [](long double t) { return 9 * t - 24 * t * t + 15.5L * t * t * t; };
  const long double ty1 = (48 - std::sqrt(630.0L)) / 93, ty2 = (48 + std::sqrt(630.0L)) / 93;
  const double xmin = static_cast<double>((1 - std::sqrt(2.0L)) / 2);
  const double xmax = static_cast<double>((1 + std::sqrt(2.0L)) / 2);
  const double ymax = static_cast<double>(y(ty1)), ymin = static_cast<double>(y(ty2));
  ASSERT_GT(ymax, 0.5);  // interior, not an end point
  ASSERT_LT(ymin, 0.0);
  const auto b = bounds(c);
  EXPECT_NEAR(b.lo[0], xmin, 8 * eps);
  EXPECT_NEAR(b.hi[0], xmax, 8 * eps);
  EXPECT_NEAR(b.lo[1], ymin, 8 * eps);
  EXPECT_NEAR(b.hi[1], ymax, 8 * eps);
  // control_bounds is the conservative box of the points.
  const auto cb = c.control_bounds();
  EXPECT_EQ(cb.lo, P2(-1, -2));
  EXPECT_EQ(cb.hi, P2(2, 3));
}

// A quadratic with its extremum at t = 1/2: (0,0), (1,2), (2,0) peaks at y = 1 (exact).
TEST(Bounds, QuadraticPeak) {
  const auto b = bounds(Bezier<double, 2>{{0, 0}, {1, 2}, {2, 0}});
  EXPECT_EQ(b.lo, P2(0, 0));
  EXPECT_EQ(b.hi, P2(2, 1));
}

// Path bounds are the union of the segments' boxes.
TEST(Bounds, PathUnion) {
  using Path2 = Path<double, 2>;
  const Path2 p({Bezier<double, 2>{{0, 0}, {1, 2}, {2, 0}}, Bezier<double, 2>{{2, 0}, {3, -2}, {4, 0}}});
  const auto b = bounds(p);
  EXPECT_EQ(b.lo, P2(0, -1));
  EXPECT_EQ(b.hi, P2(4, 1));
}

// --- Bernstein roots [LaneRiesenfeld81] -------------------------------------------------------

/// Bernstein coefficients of the power form a_0..a_n (b_i = sum_j C(i,j)/C(n,j) a_j),
/// computed here in long double with its own binomials, independent of the library.
std::vector<double> to_bernstein(const std::vector<long double>& a) {
  const int n = static_cast<int>(a.size()) - 1;
  auto C = [](int m, int k) {
    long double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (m - k + i) / i;
    return r;
  };
  std::vector<double> b(a.size());
  for (int i = 0; i <= n; ++i) {
    long double s = 0;
    for (int j = 0; j <= i; ++j) s += C(i, j) / C(n, j) * a[static_cast<std::size_t>(j)];
    b[static_cast<std::size_t>(i)] = static_cast<double>(s);
  }
  return b;
}

/// Power coefficients of prod (t - r_k).
std::vector<long double> from_roots(const std::vector<long double>& roots) {
  std::vector<long double> a{1};
  for (long double r : roots) {
    std::vector<long double> next(a.size() + 1, 0);
    for (std::size_t j = 0; j < a.size(); ++j) {
      next[j + 1] += a[j];
      next[j] -= r * a[j];
    }
    a = next;
  }
  return a;
}

std::vector<double> roots_of(const std::vector<double>& c) { return bernstein_roots<double>(std::span<const double>(c)); }

// Simple roots: located to a few eps (the solver's bracket ends at 4 eps); the
// coefficients are rounded from long double, which moves well separated roots by a few eps.
TEST(Roots, SimpleRoots) {
  {
    const auto r = roots_of({-0.3, 0.7});  // t - 0.3
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NEAR(r[0], 0.3, 4 * eps);
  }
  const std::vector<std::vector<long double>> cases = {
      {0.2L, 0.7L}, {0.1L, 0.5L, 0.9L}, {0.1L, 0.3L, 0.5L, 0.7L, 0.9L}, {0.05L, 0.33L, 0.61L, 0.83L}};
  for (const auto& roots : cases) {
    const auto r = roots_of(to_bernstein(from_roots(roots)));
    ASSERT_EQ(r.size(), roots.size());
    for (std::size_t k = 0; k < roots.size(); ++k) EXPECT_NEAR(r[k], static_cast<double>(roots[k]), 1e-13) << k;
  }
  // Roots outside [0, 1] are not reported: (t + 1)(t - 2)(t - 0.4).
  const auto r = roots_of(to_bernstein(from_roots({-1.0L, 2.0L, 0.4L})));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], 0.4, 1e-14);
}

// A double root at a dyadic point is hit exactly by the halving. At a non-dyadic point
// the rounded coefficients of an even-multiplicity root may have no real root at all
// (-(t - r)^2 + delta with delta < 0), so that is not asserted; an odd multiplicity keeps
// its sign change and is located to about eps^(1/m): for m = 3, (2 eps / 4)^(1/3) ~ 5e-6.
TEST(Roots, MultipleRoots) {
  {
    const auto r = roots_of({1.0 / 16, -3.0 / 16, 9.0 / 16});  // (t - 1/4)^2, exact data
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0], 0.25);
  }
  {
    const auto r = roots_of(to_bernstein(from_roots({0.3L, 0.3L, 0.3L, 0.8L})));
    ASSERT_GE(r.size(), 2u);
    EXPECT_NEAR(r.front(), 0.3, 2e-5);
    EXPECT_NEAR(r[r.size() - 2], 0.3, 2e-5);  // at most a cluster within the error bound
    EXPECT_NEAR(r.back(), 0.8, 1e-12);
  }
}

// Roots at the end points are reported exactly (the coefficient there is exactly zero).
TEST(Roots, RootsAtEndPoints) {
  {
    const auto r = roots_of({0.0, 0.5, 0.0});  // t (1 - t)
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0], 0.0);
    EXPECT_EQ(r[1], 1.0);
  }
  {
    const auto r = roots_of({0.0, 0.0, 1.0});  // t^2: a double root at 0, reported once
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0], 0.0);
  }
  {
    const auto r = roots_of(to_bernstein(from_roots({0.0L, 0.5L, 1.0L})));
    ASSERT_EQ(r.size(), 3u);
    EXPECT_EQ(r[0], 0.0);
    EXPECT_NEAR(r[1], 0.5, 4 * eps);
    EXPECT_EQ(r[2], 1.0);
  }
}

// Documented: an identically zero polynomial gives no roots; neither does a positive one
// or a constant.
TEST(Roots, IdenticallyZeroAndNoRoots) {
  EXPECT_TRUE(roots_of({0.0, 0.0, 0.0}).empty());
  EXPECT_TRUE(roots_of({0.0}).empty());
  EXPECT_TRUE(roots_of({}).empty());
  EXPECT_TRUE(roots_of({1.0, 2.0, 1.0}).empty());
  EXPECT_TRUE(roots_of({3.0}).empty());
  EXPECT_TRUE(roots_of({1.0, -0.1, 1.0}).empty());  // min 0.45 at t = 1/2: no real root
}

// bernstein_product by hand: t * (1 - t) = B(1,2)/2 -> coefficients (0, 1/2, 0); and
// (1 + t)(2 - t) = 2 + t - t^2 -> degree 2 Bernstein (2, 2.5, 2).
TEST(Roots, BernsteinProduct) {
  const std::vector<double> t{0, 1}, s{1, 0}, a{1, 2}, b{2, 1};
  const auto ts = bernstein_product<double>(t, s);
  ASSERT_EQ(ts.size(), 3u);
  EXPECT_EQ(ts[0], 0.0);
  EXPECT_EQ(ts[1], 0.5);
  EXPECT_EQ(ts[2], 0.0);
  const auto ab = bernstein_product<double>(a, b);
  EXPECT_EQ(ab[0], 2.0);
  EXPECT_EQ(ab[1], 2.5);
  EXPECT_EQ(ab[2], 2.0);
}

// --- continuity [Farin02, 7.1] ----------------------------------------------------------------

using Path2 = Path<double, 2>;

// C1 and C2 joins built with cr_join_points, a cubic on [0, 1] followed by a quintic on
// [1, 3] (g/h = 2, so the derivative scaling matters). The free points are chosen so that
// the next order is not matched. The construction solves for Q_k from derivatives of size
// <= 100 or so; 1e-12 absolute is far above its rounding and far below the mismatch.
TEST(Continuity, CrJoinPointsGiveCrJoins) {
  const Bezier<double, 2> a{{0, 0}, {1, 2}, {3, 3}, {4, 1}};
  for (int r : {0, 1, 2, 3}) {
    auto Q = cr_join_points(a, 1.0, 5, 2.0, r);
    ASSERT_EQ(Q.size(), static_cast<std::size_t>(r) + 1);
    EXPECT_EQ(Q[0], a.points().back());
    while (Q.size() < 6) Q.push_back(P2(10.0 + static_cast<double>(Q.size()), -5.0 * static_cast<double>(Q.size())));
    const Path2 p({a, Bezier<double, 2>(Q)}, {0.0, 1.0, 3.0});
    EXPECT_TRUE(is_cr(p, 1, r, 1e-12)) << "r=" << r;
    EXPECT_FALSE(is_cr(p, 1, r + 1, 1e-12)) << "r=" << r;
    EXPECT_EQ(parametric_continuity(p, 1, 5, 1e-12), r);
    // Directly: derivative k w.r.t. the path parameter, k <= r, from both sides.
    for (int k = 0; k <= r; ++k) {
      const auto jd = joint_derivatives(p, 1, k);
      EXPECT_LE(norm(jd.left - jd.right), 1e-12) << "k=" << k;
    }
    // By hand for k = 1: left 3 (P3 - P2) / 1 = (3, -6); right 5 (Q1 - Q0) / 2.
    if (r >= 1) {
      EXPECT_LE(norm(5.0 * (Q[1] - Q[0]) / 2.0 - V2(3, -6)), 1e-14);
    }
  }
}

// The same construction for a C2 join of two cubics on unit intervals has a closed form:
// Q1 = 2 P3 - P2, Q2 = P1 - 4 P2 + 4 P3 (the A-frame construction). Small integers: exact.
TEST(Continuity, C2CubicJoinClosedForm) {
  const Bezier<double, 2> a{{0, 0}, {1, 2}, {3, 3}, {4, 1}};
  const auto Q = cr_join_points(a, 1.0, 3, 1.0, 2);
  EXPECT_EQ(Q[1], P2(5, -1));                  // 2 (4,1) - (3,3)
  EXPECT_EQ(Q[2], P2(1 - 12 + 16, 2 - 12 + 4));  // (1,2) - 4 (3,3) + 4 (4,1)
  const Path2 p({a, Bezier<double, 2>{Q[0], Q[1], Q[2], {9, 9}}});
  EXPECT_TRUE(is_cr(p, 1, 2, 0.0));  // exact: tolerance 0
  EXPECT_EQ(parametric_continuity(p, 1, 3, 0.0), 2);
}

// G1 but not C1: the tangents at the joint point the same way with different lengths.
// Every joint of one path reported in order, each with a known answer:
// joint 1: (3, 0) then (3.5, 0): a gap, so C^-1 and not G1;
// joint 2: a line with derivative (2, 0) then a half-cubic with start derivative
//   0.5 * 3 * (0.5, 0) = (0.75, 0): same point and direction, different speed: C0 and G1;
// joint 3: the two halves of one cubic on unit intervals, i.e. one polynomial: C^inf,
//   reported as the max_order asked for (3).
TEST(Continuity, JointReportOverAWholePath) {
  using B = Bezier<double, 2>;
  const B c({{5.5, 0}, {6, 0}, {7, 1}, {8, 1}});
  const auto halves = c.split(0.5);
  const Path2 p({B({{0, 0}, {1, 1}, {2, 1}, {3, 0}}), B({{3.5, 0}, {5.5, 0}}), halves.left, halves.right}, {0, 1, 2, 3, 4});
  const auto report = joint_continuity(p, 3, 1e-12, 1e-12);
  ASSERT_EQ(report.size(), 3u);
  const int parametric[] = {-1, 0, 3};
  const bool g1[] = {false, true, true};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(report[i].joint, i + 1);
    EXPECT_EQ(report[i].parameter, static_cast<double>(i + 1));
    EXPECT_EQ(report[i].parametric, parametric[i]) << "joint " << i + 1;
    EXPECT_EQ(report[i].g1, g1[i]) << "joint " << i + 1;
  }
  EXPECT_TRUE(joint_continuity(Path2({halves.left}), 2, 1e-12, 1e-12).empty());
}

TEST(Continuity, G1ButNotC1) {
  const Bezier<double, 2> a{{0, 0}, {1, 1}, {2, 1}, {3, 1}};  // end derivative 3 (1, 0)
  const Bezier<double, 2> b{{3, 1}, {5, 1}, {6, 0}, {7, 2}};  // start derivative 3 (2, 0)
  const Path2 p({a, b});
  EXPECT_TRUE(is_g1(p, 1, 1e-12, 1e-12));
  EXPECT_FALSE(is_cr(p, 1, 1, 1e-9));
  EXPECT_TRUE(is_cr(p, 1, 0, 0.0));
  EXPECT_EQ(parametric_continuity(p, 1, 3, 1e-9), 0);
  // Reparametrising by the breaks can make it C1: h = 1, g = 2 doubles... the right side's
  // path derivative 3 (2,0) / g equals the left one (3,0) when g = 2.
  const Path2 q({a, b}, {0.0, 1.0, 3.0});
  EXPECT_EQ(parametric_continuity(q, 1, 3, 1e-12), 1);
  // A kink is not G1; a gap is not C0.
  const Path2 kink({a, Bezier<double, 2>{{3, 1}, {3, 2}, {4, 3}, {5, 3}}});
  EXPECT_FALSE(is_g1(kink, 1, 1e-12, 1e-6));
  const Path2 gap({a, Bezier<double, 2>{{3, 1.5}, {5, 1.5}, {6, 0}, {7, 2}}});
  EXPECT_FALSE(is_g1(gap, 1, 1e-12, 1e-6));
  EXPECT_EQ(parametric_continuity(gap, 1, 3, 1e-12), -1);
}

// A cusp-like end: P0 = P1 makes c'(0) = 0; the tangent is the limit of c'/|c'|, the
// direction of c''(0) = 6 (P2 - P0). At the end, P2 = P3 gives c''(1) = 6 (P1 - P3), and
// approaching from the left c'(t) ~ -c''(1) (1 - t): the tangent is P3 - P1.
TEST(Continuity, EndTangentWithVanishingFirstDerivative) {
  const Bezier<double, 2> c{{0, 0}, {0, 0}, {3, 4}, {6, 0}};
  EXPECT_EQ(c.derivative_at(0.0), V2(0, 0));
  const Path2 p({c});
  const auto t0 = end_tangent(p, 0, false);
  ASSERT_TRUE(t0.has_value());
  EXPECT_NEAR((*t0)[0], 0.6, 4 * eps);
  EXPECT_NEAR((*t0)[1], 0.8, 4 * eps);
  const Bezier<double, 2> d{{0, 0}, {3, 4}, {6, 0}, {6, 0}};
  const auto t1 = end_tangent(Path2({d}), 0, true);
  ASSERT_TRUE(t1.has_value());
  EXPECT_NEAR((*t1)[0], 0.6, 4 * eps);  // (6,0) - (3,4) = (3,-4) -> (0.6, -0.8)
  EXPECT_NEAR((*t1)[1], -0.8, 4 * eps);
  // The limit direction agrees with c'(t)/|c'(t)| just inside the end.
  const V2 near_end = d.derivative_at(1 - 1e-6);
  EXPECT_NEAR(near_end[0] / norm(near_end), 0.6, 1e-5);
  EXPECT_NEAR(near_end[1] / norm(near_end), -0.8, 1e-5);
  // Third-order vanishing: P0 = P1 = P2 -> direction of P3 - P0 from c'''.
  const auto t2 = end_tangent(Path2({Bezier<double, 2>{{1, 1}, {1, 1}, {1, 1}, {1, 3}}}), 0, false);
  ASSERT_TRUE(t2.has_value());
  EXPECT_EQ(*t2, V2(0, 1));
  const auto t3 = end_tangent(Path2({Bezier<double, 2>{{1, 3}, {1, 1}, {1, 1}, {1, 1}}}), 0, true);
  ASSERT_TRUE(t3.has_value());
  EXPECT_EQ(*t3, V2(0, -1));
  // A point has no tangent, and a G1 check through it fails.
  EXPECT_FALSE(end_tangent(Path2({Bezier<double, 2>{{1, 1}, {1, 1}}}), 0, true).has_value());
  // G1 across a joint where the right segment starts with P0 = P1.
  const Bezier<double, 2> left{{-6, 0}, {-3, 0}, {-1, 0}, {0, 0}};
  const Bezier<double, 2> right{{0, 0}, {0, 0}, {2, 0}, {3, 5}};
  EXPECT_TRUE(is_g1(Path2({left, right}), 1, 0.0, 1e-15));
}

// --- degree reduction [Eck93; Farin02, 5.9] -----------------------------------------------------

// Elevate a cubic then reduce: the least-squares problem has the exact answer, recovered
// to rounding (Gram matrix of degree 3 has condition number ~ 4^3: errors ~1e-15).
TEST(Reduction, ElevateThenReduceRoundTrip) {
  const Bezier<double, 2> c{{0.1, 0.2}, {0.9, 1.7}, {2.3, -0.4}, {3.0, 0.6}};
  for (int r : {1, 2, 5}) {
    const auto e = c.elevate(r);
    for (Endpoints ends : {Endpoints::keep, Endpoints::free}) {
      const auto red = reduce_degree(e, 3, ends);
      ASSERT_EQ(red.curve.degree(), 3);
      for (int i = 0; i <= 3; ++i) EXPECT_LE(test::max_coord_diff(red.curve.points()[i], c.points()[i]), 2e-14) << i;
      EXPECT_LE(red.max_error, 1e-14);
      EXPECT_LE(red.error_bound, 2e-14);
      if (ends == Endpoints::keep) {
        EXPECT_EQ(red.curve.points().front(), c.points().front());
        EXPECT_EQ(red.curve.points().back(), c.points().back());
      }
    }
  }
  // m == n is the identity to rounding; degree 0 (free) gives the mean of a constant.
  const auto same = reduce_degree(c, 3, Endpoints::free);
  for (int i = 0; i <= 3; ++i) EXPECT_LE(test::max_coord_diff(same.curve.points()[i], c.points()[i]), 2e-14);
  const auto pt = reduce_degree(Bezier<double, 2>{{2, 3}, {2, 3}, {2, 3}}, 0, Endpoints::free);
  EXPECT_LE(test::max_coord_diff(pt.curve.points()[0], P2(2, 3)), 4 * 3 * eps);
}

// A genuine quintic reduced to a cubic: the reported sampled error is at most the
// guaranteed bound, and an independent dense sampling (10^4 points) agrees with both.
TEST(Reduction, GenuineReductionReportsErrorWithinBound) {
  const Bezier<double, 2> c{{0, 0}, {1, 3}, {2, -1}, {3, 4}, {4, -2}, {5, 1}};
  for (Endpoints ends : {Endpoints::keep, Endpoints::free}) {
    for (int m : {1, 2, 3, 4}) {
      const auto red = reduce_degree(c, m, ends);
      EXPECT_GT(red.max_error, 0.0);
      EXPECT_LE(red.max_error, red.error_bound);
      double dense = 0;
      for (int i = 0; i <= 10000; ++i) dense = std::max(dense, distance(c(i / 1e4), red.curve(i / 1e4)));
      // The control-point bound holds for every t (convex hull of the differences).
      EXPECT_LE(dense, red.error_bound * (1 + 1e-12));
      // The reported max is a sampled estimate from below: the dense one can only be a
      // little larger (max over 64 (n+1) samples of a smooth function).
      EXPECT_LE(red.max_error, dense * (1 + 1e-12));
      EXPECT_GE(red.max_error, 0.9 * dense);
    }
  }
  // keep with m = 1 is the chord.
  const auto chord = reduce_degree(c, 1, Endpoints::keep);
  EXPECT_EQ(chord.curve.points()[0], P2(0, 0));
  EXPECT_EQ(chord.curve.points()[1], P2(5, 1));
}

// --- flattening -----------------------------------------------------------------------------------

/// Distance from p to the curve, by dense sampling and then golden-section refinement.
template <class C>
double distance_to_curve(const C& c, const P2& p) {
  const int N = 2000;
  int best = 0;
  double bd = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= N; ++i) {
    const double d = distance(c(static_cast<double>(i) / N), p);
    if (d < bd) bd = d, best = i;
  }
  double lo = std::max(0.0, (best - 1.0) / N), hi = std::min(1.0, (best + 1.0) / N);
  for (int it = 0; it < 100; ++it) {
    const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
    if (distance(c(m1), p) < distance(c(m2), p)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  return std::min(bd, distance(c((lo + hi) / 2), p));
}

template <class C>
void check_flatten(const C& c, double tol) {
  const auto poly = flatten(c, tol);
  ASSERT_GE(poly.size(), 2u);
  EXPECT_EQ(poly.front(), c(0.0));
  EXPECT_EQ(poly.back(), c(1.0));
  // Every dense sample of the curve is within tolerance of the polyline (guaranteed).
  for (int i = 0; i <= 5000; ++i) EXPECT_LE(test::polyline_distance(c(i / 5000.0), poly), tol) << i;
  // Vertices lie on the curve (they are subdivision end points): to rounding, 1e-12.
  for (const auto& v : poly) EXPECT_LE(distance_to_curve(c, v), 1e-12);
}

TEST(Flatten, CubicWithinToleranceAndVerticesOnCurve) {
  const Bezier<double, 2> c{{0, 0}, {1, 3}, {3, -1}, {4, 2}};
  for (double tol : {0.5, 1e-2, 1e-4}) check_flatten(c, tol);
  // Tighter tolerances need more vertices.
  EXPECT_LT(flatten(c, 1e-2).size(), flatten(c, 1e-4).size());
  // A straight line with collinear control points is a single segment.
  EXPECT_EQ(flatten(Bezier<double, 2>{{0, 0}, {1, 1}, {3, 3}}, 1e-9).size(), 2u);
}

TEST(Flatten, RationalAndPath) {
  const RationalBezier<double, 2> q({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(2.0) / 2, 1});
  check_flatten(q, 1e-3);
  // Against the exact circle: every vertex at radius 1, every segment midpoint inside by
  // at most the tolerance (a chord of the circle lies within the disc).
  const auto poly = flatten(q, 1e-3);
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const P2 mid = P2::from_vector((poly[i].to_vector() + poly[i + 1].to_vector()) / 2.0);
    const double r = norm(mid.to_vector());
    EXPECT_LE(r, 1 + 1e-15);
    EXPECT_GE(r, 1 - 1e-3);
  }
  const Path2 p({Bezier<double, 2>{{0, 0}, {1, 2}, {2, 0}}, q.transform(Affine<double, 2>::translate({1, 0}))});
  const auto pp = flatten(p, 1e-3);
  EXPECT_EQ(pp.front(), P2(0, 0));
  for (int i = 0; i <= 4000; ++i) EXPECT_LE(test::polyline_distance(p(2.0 * i / 4000), pp), 1e-3);
  // The joint vertex (2,0) = (1,0) + (1,0) is written once.
  for (std::size_t i = 0; i + 1 < pp.size(); ++i) EXPECT_NE(pp[i], pp[i + 1]);
}

TEST(Flatten, BadToleranceThrows) {
  const Bezier<double, 2> c{{0, 0}, {1, 3}, {3, -1}, {4, 2}};
  EXPECT_INVALID_ARGUMENT(flatten(c, 0.0), "tolerance", "> 0");
  EXPECT_INVALID_ARGUMENT(flatten(c, -1.0), "tolerance", "> 0");
  EXPECT_INVALID_ARGUMENT(flatten(c, std::nan("")), "tolerance", "finite");
  EXPECT_INVALID_ARGUMENT(flatten(c, std::numeric_limits<double>::infinity()), "tolerance", "finite");
  EXPECT_INVALID_ARGUMENT(flatten(Path2({c}), -1e-3), "tolerance", "> 0");
  // Below the coordinates' resolution: reported, not silently hit.
  const Bezier<double, 2> far{{1e6, 1e6}, {1e6 + 1, 1e6 + 3}, {1e6 + 3, 1e6 - 1}, {1e6 + 4, 1e6 + 2}};
  EXPECT_THROW((void)flatten(far, 1e-14), NumericalError);
  // Just above the resolution (ulp(1e6) ~ 1.2e-10) it works.
  const auto poly = flatten(far, 1e-6);
  for (int i = 0; i <= 1000; ++i) EXPECT_LE(test::polyline_distance(far(i / 1000.0), poly), 1e-6);
}

// Scaling every weight by one constant leaves a rational curve unchanged, so its tight
// box must not change either, even when the products of weights would overflow (1e300^2).
TEST(Bounds, RationalWithHugeWeights) {
  const double h = std::sqrt(0.5);
  const RationalBezier<double, 2> unit({{1, 0}, {1, 1}, {0, 1}}, {1, h, 1});
  const RationalBezier<double, 2> huge({{1, 0}, {1, 1}, {0, 1}}, {1e300, h * 1e300, 1e300});
  const auto a = bounds(unit), b = bounds(huge);
  for (int d = 0; d < 2; ++d) {
    // The quarter circle's box is [0, 1]^2 (the arc is monotone in both coordinates).
    EXPECT_NEAR(b.lo[d], 0.0, 1e-15);
    EXPECT_NEAR(b.hi[d], 1.0, 1e-15);
    EXPECT_NEAR(a.hi[d], b.hi[d], 1e-15);
  }
}

// Past degree 1029 the binomials of Forrest's formula would overflow a double; elevation
// uses the hypergeometric ratio recurrence instead, which has no such limit. The curve
// must be unchanged: the degree-1203 curve must reproduce the cubic's Bernstein sum,
// written out by hand below, to about r eps.
TEST(Elevation, BeyondDegreeOneThousandKeepsTheCurve) {
  const Bezier<double, 2> c{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const auto e = c.elevate(1200);
  ASSERT_EQ(e.degree(), 1203);
  for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    const double s = 1 - t;
    // sum B(i,3)(t) P_i by hand.
    const double x = 3 * s * s * t * 1 + 3 * s * t * t * 3 + t * t * t * 4;
    const double y = 3 * s * s * t * 2 + 3 * s * t * t * 2;
    const auto p = e(t);
    // One convex combination per control point, weights accurate to ~10 eps: far below
    // the 1e-12 allowed for the former 1200 stepwise elevations (2 eps of max|P| = 4 each).
    EXPECT_NEAR(p[0], x, 1e-12) << t;
    EXPECT_NEAR(p[1], y, 1e-12) << t;
  }
}

}  // namespace
