// Textbook reference values: closed forms and worked examples from [Farin02], [PT97] and
// [Forrest72], each with its source, checked exactly where the arithmetic is exact in
// binary floating point and with a stated tolerance elsewhere.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;
using casteljau::test::eps;

// --- de Casteljau ----------------------------------------------------------------------

// [Farin02, 3.1]: P(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8. With small integer coordinates
// every lerp at t = 1/2 is exact in binary, so the comparison is exact.
TEST(Textbook, CubicAtHalfIsOneThreeThreeOneOverEight) {
  const Bezier<double, 2> c{{0, 0}, {1, 2}, {3, 3}, {4, 0}};
  const P2 p = c(0.5);
  EXPECT_EQ(p[0], (0 + 3 * 1 + 3 * 3 + 4) / 8.0);
  EXPECT_EQ(p[1], (0 + 3 * 2 + 3 * 3 + 0) / 8.0);
}

// Same identity on random data: both sides are sums of 4 terms of size <= 1, so they agree
// to a few ulps of 1 (the formula's own rounding is 4 eps, de Casteljau's 3 levels ~3 eps).
TEST(Textbook, CubicAtHalfRandomData) {
  test::SplitMix64 rng(1);
  for (int rep = 0; rep < 100; ++rep) {
    const auto P = test::random_points<double, 3>(rng, 3, -1, 1);
    const Bezier<double, 3> c(P);
    const auto p = c(0.5);
    for (int d = 0; d < 3; ++d) {
      const double expected = (P[0][d] + 3 * P[1][d] + 3 * P[2][d] + P[3][d]) / 8;
      EXPECT_NEAR(p[d], expected, 8 * eps);
    }
  }
}

// End point interpolation is exact by construction of de Casteljau ((1-t) a + t b with
// t = 0 or 1 multiplies by exact 0 and 1).
TEST(Textbook, EndPointsExact) {
  const Bezier<double, 2> c{{0.1, 0.7}, {1.3, -2}, {3.3, 3.1}, {4.9, 0.3}};
  EXPECT_EQ(c(0.0), c.points().front());
  EXPECT_EQ(c(1.0), c.points().back());
}

// --- matrix form [Farin02, 5.8] -----------------------------------------------------------

// Written out by hand: degree 2 and 3 Bernstein-to-power matrices, integer entries (exact).
TEST(Textbook, BernsteinToPowerMatrices) {
  const double m2[3][3] = {{1, 0, 0}, {-2, 2, 0}, {1, -2, 1}};
  const double m3[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  const auto a = bernstein_to_power_matrix<double>(2);
  const auto b = bernstein_to_power_matrix<double>(3);
  ASSERT_EQ(a.rows(), 3);
  ASSERT_EQ(b.rows(), 4);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(a(i, j), m2[i][j]) << i << "," << j;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(b(i, j), m3[i][j]) << i << "," << j;
  const auto m0 = bernstein_to_power_matrix<double>(0);
  ASSERT_EQ(m0.rows(), 1);
  EXPECT_EQ(m0(0, 0), 1.0);
}

// The inverses, by hand (M^-1(i,j) = C(i,j) / C(n,j)): degree 2 [[1,0,0],[1,1/2,0],[1,1,1]],
// degree 3 [[1,0,0,0],[1,1/3,0,0],[1,2/3,1/3,0],[1,1,1,1]]. Thirds are rounded once
// (1/2 ulp); M M^-1 is the identity to a few ulps of the entries (|M| <= 6).
TEST(Textbook, PowerToBernsteinMatrices) {
  const double i2[3][3] = {{1, 0, 0}, {1, 0.5, 0}, {1, 1, 1}};
  const double i3[4][4] = {{1, 0, 0, 0}, {1, 1.0 / 3, 0, 0}, {1, 2.0 / 3, 1.0 / 3, 0}, {1, 1, 1, 1}};
  const auto a = power_to_bernstein_matrix<double>(2);
  const auto b = power_to_bernstein_matrix<double>(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(a(i, j), i2[i][j]) << i << "," << j;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(b(i, j), i3[i][j], eps) << i << "," << j;
  for (int n = 0; n <= 8; ++n) {
    const Matrix<double> prod = bernstein_to_power_matrix<double>(n) * power_to_bernstein_matrix<double>(n);
    // Row sums of |M| are at most 3^n (<= 6561 at n = 8), each product term rounded once.
    const double tol = std::pow(3.0, n) * 4 * eps;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) EXPECT_NEAR(prod(i, j), i == j ? 1.0 : 0.0, tol) << "n=" << n;
  }
}

// to_power of a cubic, by hand: a0 = P0, a1 = 3(P1-P0), a2 = 3(P0-2P1+P2),
// a3 = -P0+3P1-3P2+P3. Integer data: exact.
TEST(Textbook, CubicToPowerAndBack) {
  const Bezier<double, 2> c{{0, 0}, {1, 2}, {3, 3}, {4, 0}};
  const auto a = c.to_power();
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0], V2(0, 0));
  EXPECT_EQ(a[1], V2(3, 6));
  EXPECT_EQ(a[2], V2(3, -3));
  EXPECT_EQ(a[3], V2(-2, -3));
  const auto back = Bezier<double, 2>::from_power(a);
  for (int i = 0; i <= 3; ++i) EXPECT_LE(test::max_coord_diff(back.points()[i], c.points()[i]), 4 * 4 * eps);
}

// --- subdivision [Farin02, 3.3] ------------------------------------------------------------

// Splitting the basis "curves" e_j (1D Bezier with one coefficient 1) at 1/2 gives the
// columns of the subdivision matrices. Left: 1/8 [8 0 0 0; 4 4 0 0; 2 4 2 0; 1 3 3 1];
// right: 1/8 [1 3 3 1; 0 2 4 2; 0 0 4 4; 0 0 0 8]. Dyadic values: exact.
TEST(Textbook, SubdivisionMatricesAtHalf) {
  const double L[4][4] = {{8, 0, 0, 0}, {4, 4, 0, 0}, {2, 4, 2, 0}, {1, 3, 3, 1}};
  const double R[4][4] = {{1, 3, 3, 1}, {0, 2, 4, 2}, {0, 0, 4, 4}, {0, 0, 0, 8}};
  for (int j = 0; j < 4; ++j) {
    std::vector<Point<double, 1>> e(4, Point<double, 1>(0.0));
    e[static_cast<std::size_t>(j)][0] = 1;
    const auto s = Bezier<double, 1>(e).split(0.5);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(s.left.points()[i][0], L[i][j] / 8) << i << "," << j;
      EXPECT_EQ(s.right.points()[i][0], R[i][j] / 8) << i << "," << j;
    }
  }
}

// --- degree elevation [Forrest72; Farin02, 5.1] -------------------------------------------

// Quadratic to cubic: Q0 = P0, Q1 = (P0 + 2 P1)/3, Q2 = (2 P1 + P2)/3, Q3 = P2. The data
// make every expected value an integer; the library's 2/3 factor rounds once, so allow
// 2 ulps of the coordinates (<= 9).
TEST(Textbook, ForrestElevationOfQuadratic) {
  const Bezier<double, 2> q{{0, 0}, {3, 6}, {9, 3}};
  const auto c = q.elevate();
  ASSERT_EQ(c.degree(), 3);
  const P2 expected[4] = {{0, 0}, {2, 4}, {5, 5}, {9, 3}};
  for (int i = 0; i < 4; ++i) EXPECT_LE(test::max_coord_diff(c.points()[i], expected[i]), 2 * 9 * eps) << i;
  EXPECT_EQ(c.points().front(), q.points().front());
  EXPECT_EQ(c.points().back(), q.points().back());
  // Elevating by 0 is the identity.
  EXPECT_EQ(q.elevate(0), q);
  // By 2 at once equals twice by 1 (both are the unique degree-4 representation).
  const auto a = q.elevate(2), b = q.elevate().elevate();
  for (int i = 0; i <= 4; ++i) EXPECT_LE(test::max_coord_diff(a.points()[i], b.points()[i]), 4 * 9 * eps);
}

// --- derivatives [Farin02, 5.3] ------------------------------------------------------------

// Hodograph control points n (P_{i+1} - P_i) and the second derivative n(n-1) Delta^2 P_i,
// integers here: exact.
TEST(Textbook, HodographControlPoints) {
  const Bezier<double, 2> c{{0, 0}, {1, 2}, {3, 3}, {4, 0}};
  const auto h = c.derivative();
  ASSERT_EQ(h.degree(), 2);
  EXPECT_EQ(h.points()[0], P2(3, 6));
  EXPECT_EQ(h.points()[1], P2(6, 3));
  EXPECT_EQ(h.points()[2], P2(3, -9));
  const auto h2 = c.derivative(2);
  ASSERT_EQ(h2.degree(), 1);
  EXPECT_EQ(h2.points()[0], P2(6, -6));
  EXPECT_EQ(h2.points()[1], P2(-6, -24));
  const auto h3 = c.derivative(3);
  ASSERT_EQ(h3.degree(), 0);
  EXPECT_EQ(h3.points()[0], P2(-12, -18));  // 6 (P3 - 3P2 + 3P1 - P0)
  const auto h4 = c.derivative(4);
  ASSERT_EQ(h4.degree(), 0);
  EXPECT_EQ(h4.points()[0], P2(0, 0));
  // End tangents n(P1 - P0) and n(P3 - P2), exact.
  EXPECT_EQ(c.derivative_at(0.0), V2(3, 6));
  EXPECT_EQ(c.derivative_at(1.0), V2(3, -9));
  EXPECT_EQ(c.derivative_at(0.0, 5), V2(0, 0));
  // At t = 1/2 the hodograph value (3,6)/4 + (6,3)/2 + (3,-9)/4 = (4.5, 0.75) is exact.
  EXPECT_EQ(c.derivative_at(0.5), V2(4.5, 0.75));
}

// --- Bernstein polynomials ------------------------------------------------------------------

// Values at known points, by hand: B(1,3)(1/2) = 3/8, B(0,3)(1/4) = 27/64, B(2,4)(1/2) = 6/16
// (dyadic, exact); B(2,5)(0.3) = 10 * 0.09 * 0.343 = 0.3087 (0.3 is inexact: a few ulps).
TEST(Textbook, BernsteinValues) {
  EXPECT_EQ(bernstein(1, 3, 0.5), 0.375);
  EXPECT_EQ(bernstein(0, 3, 0.25), 27.0 / 64);
  EXPECT_EQ(bernstein(2, 4, 0.5), 0.375);
  EXPECT_NEAR(bernstein(2, 5, 0.3), 0.3087, 8 * eps);
  EXPECT_EQ(bernstein(0, 5, 0.0), 1.0);
  EXPECT_EQ(bernstein(3, 5, 0.0), 0.0);
  EXPECT_EQ(bernstein(5, 5, 1.0), 1.0);
  EXPECT_EQ(bernstein(4, 5, 1.0), 0.0);
  EXPECT_EQ(bernstein(-1, 5, 0.5), 0.0);
  EXPECT_EQ(bernstein(6, 5, 0.5), 0.0);
  EXPECT_EQ(bernstein(0, 0, 0.7), 1.0);
  const auto all = bernstein_all(3, 0.5);
  const double expected[4] = {0.125, 0.375, 0.375, 0.125};
  for (int i = 0; i < 4; ++i) EXPECT_EQ(all[static_cast<std::size_t>(i)], expected[i]);
  // On [a, b] = [2, 4]: B(1,2)((3-2)/2) = 2 * 1/2 * 1/2.
  EXPECT_EQ(bernstein(1, 2, 3.0, Interval<double>{2, 4}), 0.5);
  std::vector<double> out(3);
  bernstein_all(2, 2.5, Interval<double>{2, 4}, std::span<double>(out));
  EXPECT_EQ(out[0], 0.5625);  // (3/4)^2
  EXPECT_EQ(out[1], 0.375);   // 2 (1/4)(3/4)
  EXPECT_EQ(out[2], 0.0625);  // (1/4)^2
}

// d/dt B(1,2) = 2 - 4t, d^2/dt^2 B(1,2) = -4, d/dt B(0,3) = -3(1-t)^2, d^2/dt^2 B(1,3) = 18t - 12
// (by differentiating 3t(1-t)^2 = 3t - 6t^2 + 3t^3); on [a, b] the chain rule divides
// by (b - a)^k. Dyadic arguments: exact.
TEST(Textbook, BernsteinDerivatives) {
  EXPECT_EQ(bernstein_derivative(1, 2, 1, 0.25), 1.0);
  EXPECT_EQ(bernstein_derivative(1, 2, 2, 0.25), -4.0);
  EXPECT_EQ(bernstein_derivative(0, 3, 1, 0.5), -0.75);
  EXPECT_EQ(bernstein_derivative(1, 3, 2, 0.5), -3.0);
  EXPECT_EQ(bernstein_derivative(1, 3, 4, 0.5), 0.0);
  EXPECT_EQ(bernstein_derivative(1, 3, 0, 0.5), 0.375);
  EXPECT_EQ(bernstein_derivative(1, 2, 1, 2.5, Interval<double>{2, 4}), 0.5);   // (2 - 4/4)/2
  EXPECT_EQ(bernstein_derivative(1, 2, 2, 2.5, Interval<double>{2, 4}), -1.0);  // -4/4
  for (int k = 0; k <= 5; ++k) {
    std::vector<double> all(5);
    bernstein_all_derivatives(4, k, 0.375, std::span<double>(all));
    for (int i = 0; i <= 4; ++i) {
      // The two implementations use different summation orders: a few ulps of the result,
      // whose size is bounded by n!/(n-k)! 2^k.
      EXPECT_NEAR(all[static_cast<std::size_t>(i)], bernstein_derivative(i, 4, k, 0.375), 64 * 24 * 16 * eps)
          << "i=" << i << " k=" << k;
    }
  }
}

// --- binomial coefficients ------------------------------------------------------------------

// Reference integers (exact, computed by hand with arbitrary-precision integers):
// C(56,28) = 7648690600760440 < 2^53, so exact in double; C(62,31) = 465428353255261088
// needs 59 bits: exact in long double (64-bit mantissa), and correctly rounded in double
// to 465428353255261056.
TEST(Textbook, BinomialExactness) {
  EXPECT_EQ(binomial<double>(56, 28), 7648690600760440.0);
  EXPECT_EQ(binomial<double>(62, 31), 465428353255261056.0);
  if constexpr (std::numeric_limits<long double>::digits >= 64) {
    EXPECT_EQ(binomial<long double>(62, 31), 465428353255261088.0L);
  }
  EXPECT_EQ(binomial<double>(5, 2), 10.0);
  EXPECT_EQ(binomial<double>(0, 0), 1.0);
  EXPECT_EQ(binomial<double>(7, -1), 0.0);
  EXPECT_EQ(binomial<double>(7, 8), 0.0);
  // Past n = 62 the floating point path: C(100, 50) = 100891344545564193334812497256,
  // relative error <= about 2k eps (k multiplications and divisions).
  EXPECT_NEAR(binomial<double>(100, 50) / 1.00891344545564193334812497256e29, 1.0, 100 * eps);
  // Pascal's rule holds exactly for the rows (exact integers below 2^53 up to n = 56).
  for (int n = 1; n <= 56; ++n) {
    const auto row = binomial_row<double>(n);
    for (int k = 0; k <= n; ++k) EXPECT_EQ(row[static_cast<std::size_t>(k)], binomial<double>(n, k)) << n << "," << k;
  }
  const auto r56 = binomial_row<double>(56);
  EXPECT_EQ(r56[28], 7648690600760440.0);
}

// --- rational Bézier: the quarter circle [PT97, 7.3; Farin02, 13.4] ---------------------------

// Points (1,0), (1,1), (0,1) with weights 1, sqrt(2)/2, 1 trace the unit quarter circle.
// The rational de Casteljau steps are convex combinations, so |R(t)| = 1 to a few ulps:
// 8 eps allows for the weight's own rounding (sqrt(2)/2 is not representable) and ~2 ulps
// per level and in the norm.
TEST(Textbook, RationalQuarterCircle) {
  const RationalBezier<double, 2> q({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(2.0) / 2, 1});
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    const P2 p = q(t);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 8 * eps) << "t=" << t;
  }
  // Tight bounds [0, 1]^2: the end points are the extremes.
  const auto b = bounds(q);
  EXPECT_NEAR(b.lo[0], 0.0, 4 * eps);
  EXPECT_NEAR(b.lo[1], 0.0, 4 * eps);
  EXPECT_NEAR(b.hi[0], 1.0, 4 * eps);
  EXPECT_NEAR(b.hi[1], 1.0, 4 * eps);
  // By symmetry R(1/2) = (sqrt(2)/2, sqrt(2)/2).
  EXPECT_NEAR(q(0.5)[0], std::sqrt(0.5), 4 * eps);
  EXPECT_NEAR(q(0.5)[1], std::sqrt(0.5), 4 * eps);
}

// A circular arc of radius 2.5 spanning 3pi/4 around (1, -2): every point at distance r,
// tight bounds from the arc's known extremes (the arc from -pi/4 to pi/2 touches x = cx + r
// at angle 0 and y = cy + r at pi/2).
TEST(Textbook, CircularArcFactory) {
  const double r = 2.5, pi = std::numbers::pi;
  const P2 center{1, -2};
  const auto arc = RationalBezier<double, 2>::circular_arc(center, r, -pi / 4, pi / 2);
  for (int i = 0; i <= 200; ++i) {
    const double t = i / 200.0;
    EXPECT_NEAR(distance(arc(t), center), r, 16 * r * eps);
  }
  const auto b = bounds(arc);
  EXPECT_NEAR(b.hi[0], center[0] + r, 16 * r * eps);
  EXPECT_NEAR(b.hi[1], center[1] + r, 16 * r * eps);
  EXPECT_NEAR(b.lo[0], center[0], 16 * r * eps);  // x at angle pi/2
  EXPECT_NEAR(b.lo[1], center[1] - r * std::sqrt(0.5), 16 * r * eps);
}

// --- curvature [Farin02, 10.2] ----------------------------------------------------------------

// A circle of radius r has curvature 1/r everywhere: positive (turning left) for a
// counter-clockwise arc, negative clockwise; unsigned in 3D. Derivatives of the rational
// form involve a few divisions by the weight: a relative 64 eps allows for them.
TEST(Textbook, CurvatureOfCircleArcIsOneOverRadius) {
  const double pi = std::numbers::pi;
  for (double r : {0.5, 1.0, 3.0, 1000.0}) {
    const auto ccw = RationalBezier<double, 2>::circular_arc({0.5, 0.25}, r, 0.3, 0.3 + pi / 2);
    const auto cw = ccw.reverse();
    for (int i = 0; i <= 20; ++i) {
      const double t = i / 20.0;
      const auto k = curvature(ccw, t), kr = curvature(cw, t);
      ASSERT_TRUE(k.has_value());
      ASSERT_TRUE(kr.has_value());
      EXPECT_NEAR(*k, 1 / r, 64 * eps / r) << "r=" << r << " t=" << t;
      EXPECT_NEAR(*kr, -1 / r, 64 * eps / r);
    }
  }
  // The unit quarter circle lifted into the plane z = 7 of 3-space.
  const RationalBezier<double, 3> q3({{1, 0, 7}, {1, 1, 7}, {0, 1, 7}}, {1, std::sqrt(2.0) / 2, 1});
  for (int i = 0; i <= 20; ++i) EXPECT_NEAR(*curvature(q3, i / 20.0), 1.0, 64 * eps);
  // A straight segment has curvature 0; a point has none.
  const Bezier<double, 2> line{{0, 0}, {1, 1}, {2, 2}};
  EXPECT_EQ(*curvature(line, 0.3), 0.0);
  EXPECT_FALSE(curvature(Bezier<double, 2>{{1, 1}, {1, 1}}, 0.5).has_value());
}

// A parabola y = x^2 as a quadratic: (-1,1), (0,-1), (1,1) gives x = 2t - 1, y = x^2; its
// curvature 2 / (1 + 4x^2)^(3/2) at x = 0 is 2, and at x = 1/2 it is 2 / 2^(3/2).
TEST(Textbook, CurvatureOfParabola) {
  const Bezier<double, 2> p{{-1, 1}, {0, -1}, {1, 1}};
  EXPECT_NEAR(*curvature(p, 0.5), 2.0, 8 * eps);
  EXPECT_NEAR(*curvature(p, 0.75), 2.0 / std::pow(2.0, 1.5), 8 * eps);
}

}  // namespace
