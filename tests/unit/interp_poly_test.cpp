// Interpolating polynomial curves: barycentric weights (closed forms against the O(n^2)
// products), Lagrange evaluation and derivatives against closed-form polynomials, Neville's
// scheme, extrapolation, the Runge phenomenon, the Bézier form and its degree cap, errors.
// Expected values are closed forms computed here, never the code under test.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "casteljau/io/json.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P1 = Point<double, 1>;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;

// ---------------------------------------------------------------------------------------
// Barycentric weights and nodes.

// The closed forms equal the O(n^2) products up to one positive factor. The products are
// those of the rounded nodes: each node moves by eps of the interval, which is up to
// ~n^2 / 5 eps of the smallest spacing near the ends, so a weight moves by up to ~n^2 eps
// relative (measured worst: 2.5e-14 at n = 29); the bound is 2 n^2 eps.
TEST(Barycentric, ChebyshevClosedFormsMatchTheProducts) {
  for (Nodes kind : {Nodes::chebyshev1, Nodes::chebyshev2}) {
    for (std::size_t n = 2; n <= 60; ++n) {
      const auto x = interpolation_nodes<double>(kind, n, -3.0, 5.5);
      const auto w = barycentric_weights<double>(x);
      const auto c = chebyshev_weights<double>(kind, n);
      const double ratio = w[0] / c[0];
      EXPECT_GT(ratio, 0);
      for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(w[j] / c[j], ratio, 2.0 * n * n * 2.2e-16 * ratio) << "n=" << n << " j=" << j;
    }
  }
}

// Equispaced nodes: w_j proportional to (-1)^(n-1-j) C(n-1, j) [BerrutTrefethen04 (5.1)].
TEST(Barycentric, EquispacedWeightsAreSignedBinomials) {
  const std::size_t n = 11;
  const auto w = barycentric_weights<double>(interpolation_nodes<double>(Nodes::equispaced, n, 0.0, 7.0));
  const double C[] = {1, 10, 45, 120, 210, 252, 210, 120, 45, 10, 1};
  const double s = w[0] / C[0];
  for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(w[j], ((n - 1 - j) % 2 ? -1 : 1) * C[j] * s, 1e-14 * std::abs(s) * C[j]);
  // Scaled so that the largest magnitude lies in (0.5, 1].
  EXPECT_GT(std::abs(w[5]), 0.5);
  EXPECT_LE(std::abs(w[5]), 1.0);
}

// Products of many tiny or huge differences neither overflow nor underflow: 500 nodes in
// an interval of length 1e-200, or spread over 1e300. 1100 equispaced nodes need a weight
// ratio C(1099, 549) ~ 2^1093, beyond the double range: refused.
TEST(Barycentric, WeightsOfExtremeNodes) {
  for (double len : {1e-200, 1e300}) {
    const auto x = interpolation_nodes<double>(Nodes::equispaced, 500, 0.0, len);
    const auto w = barycentric_weights<double>(x);
    for (double v : w) EXPECT_TRUE(std::isfinite(v) && v != 0);
    // Ratio w_0 / w_1 = -C(499, 0) / C(499, 1) = -1/499.
    EXPECT_NEAR(w[0] / w[1], -1.0 / 499, 1e-12);
  }
  const auto many = interpolation_nodes<double>(Nodes::equispaced, 1100, 0.0, 1.0);
  EXPECT_INVALID_ARGUMENT(barycentric_weights<double>(many), "params", "underflows");
}

// The nodes: symmetric about the middle, in increasing order, the second kind and the
// equispaced ones including the ends; first-kind nodes are the roots of T_n.
TEST(Barycentric, Nodes) {
  const auto c1 = interpolation_nodes<double>(Nodes::chebyshev1, 7, -1.0, 1.0);
  for (std::size_t j = 0; j < 7; ++j) {
    EXPECT_NEAR(std::cos(7 * std::acos(c1[j])), 0.0, 1e-14);  // T_7(x_j) = 0
    EXPECT_EQ(c1[j], -c1[6 - j]);
    if (j > 0) {
      EXPECT_LT(c1[j - 1], c1[j]);
    }
  }
  EXPECT_EQ(c1[3], 0.0);
  const auto c2 = interpolation_nodes<double>(Nodes::chebyshev2, 5, 2.0, 6.0);
  const std::vector<double> want{2, 4 - 2 * std::sqrt(0.5), 4, 4 + 2 * std::sqrt(0.5), 6};
  for (std::size_t j = 0; j < 5; ++j) EXPECT_NEAR(c2[j], want[j], 1e-15 * 6);
  EXPECT_EQ(c2.front(), 2.0);
  EXPECT_EQ(c2.back(), 6.0);
  EXPECT_EQ(interpolation_nodes<double>(Nodes::equispaced, 5, -1.0, 1.0), (std::vector<double>{-1, -0.5, 0, 0.5, 1}));
  EXPECT_INVALID_ARGUMENT(interpolation_nodes<double>(Nodes::chebyshev2, 1, 0.0, 1.0), "n", "at least 2");
  EXPECT_INVALID_ARGUMENT(interpolation_nodes<double>(Nodes::equispaced, 3, 1.0, 1.0), "interval", "a < b");
}

// ---------------------------------------------------------------------------------------
// Lagrange curves against closed forms.

/// p(x) = (x^3 - 2x + 1, 0.5 x^2 - x) and its derivatives: a cubic, so 4 or more
/// interpolation points reproduce it exactly (to rounding).
P2 cubic(double x) { return {x * x * x - 2 * x + 1, 0.5 * x * x - x}; }
V2 cubic_d(double x, int k) {
  switch (k) {
    case 0: return cubic(x).to_vector();
    case 1: return {3 * x * x - 2, x - 1};
    case 2: return {6 * x, 1};
    case 3: return {6, 0};
    default: return {0, 0};
  }
}

Lagrange<double, 2> cubic_through(const std::vector<double>& u) {
  std::vector<P2> P;
  for (double x : u) P.push_back(cubic(x));
  return Lagrange<double, 2>(u, P);
}

// Six uneven params in scrambled order: the interpolant is the cubic. Values at |x| <= 3
// are <= ~25, derivatives of order k are computed with about (n^2 / spread)^k growth:
// tolerances 1e-13, 1e-12, 1e-11, 1e-10 of the size.
TEST(Lagrange, ReproducesPolynomialsAndDerivatives) {
  const auto c = cubic_through({0.3, -2, 1.7, -0.6, 3, 1});
  EXPECT_EQ(c.domain(), (Interval<double>{-2, 3}));
  EXPECT_EQ(c.degree(), 5);
  for (double x = -2; x <= 3; x += 0.0625) {
    EXPECT_LE(test::max_coord_diff(c(x), cubic(x)), 1e-13 * 25) << x;
    for (int k = 1; k <= 7; ++k) {
      const double tol = std::pow(10.0, -13 + k) * 25;
      EXPECT_LE(test::max_coord_diff(c.derivative_at(x, k), cubic_d(x, k)), k <= 3 ? tol : 1e-9) << "x=" << x << " k=" << k;
    }
  }
  // Order >= n is exactly zero (the polynomial space has degree n - 1 = 5).
  EXPECT_EQ(c.derivative_at(0.1, 6), V2(0, 0));
  EXPECT_EQ(c.derivative_at(0.1, 60), V2(0, 0));
}

// Exact hits at the params (the node term drops out of the formula), for values and the
// order-0 derivative; derivatives at and near a node are accurate (no eps |y| / h loss).
TEST(Lagrange, ExactAtNodesAndAccurateNearThem) {
  const std::vector<double> u{0.3, -2, 1.7, -0.6, 3, 1};
  const auto c = cubic_through(u);
  for (std::size_t j = 0; j < u.size(); ++j) {
    EXPECT_EQ(c(u[j]), c.points()[j]);
    for (double h : {0.0, 1e-15, -1e-12, 1e-9}) {
      const double x = u[j] + h;
      for (int k = 1; k <= 3; ++k)
        EXPECT_LE(test::max_coord_diff(c.derivative_at(x, k), cubic_d(x, k)), std::pow(10.0, -12 + k) * 25) << x << " " << k;
    }
  }
}

// Neville's scheme (no weights) agrees with the barycentric formula; both reproduce the cubic.
TEST(Lagrange, NevilleAgrees) {
  const auto c = cubic_through({0.3, -2, 1.7, -0.6, 3, 1});
  for (double x = -2.5; x <= 3.5; x += 0.1) {
    EXPECT_LE(test::max_coord_diff(c.neville(x), cubic(x)), 1e-12) << x;
    EXPECT_LE(test::max_coord_diff(c.neville(x), c(x)), 1e-12) << x;
  }
}

// Extrapolation is the same polynomial, far out too: p(x) = x^9 - 2 x^3 + 1 through ten
// Chebyshev points of [-1, 1], at x = 10 and 1e3, to 1e-12 relative (the first-form
// denominator has no cancellation; the interpolant's condition there is modest since all
// data come from one polynomial).
TEST(Lagrange, ExtrapolatesTheSamePolynomial) {
  const auto f = [](double x) { return std::pow(x, 9) - 2 * x * x * x + 1; };
  const auto df = [](double x) { return 9 * std::pow(x, 8) - 6 * x * x; };
  std::vector<P1> P;
  const auto x = interpolation_nodes<double>(Nodes::chebyshev1, 10, -1.0, 1.0);
  for (double v : x) P.emplace_back(f(v));
  for (const auto& c : {Lagrange<double, 1>::on_nodes(Nodes::chebyshev1, {-1.0, 1.0}, P), Lagrange<double, 1>(x, P)}) {
    for (double t : {-1.5, 2.0, 10.0, -1e3, 1e3}) {
      EXPECT_NEAR(c(t)[0], f(t), 1e-12 * std::abs(f(t))) << t;
      EXPECT_NEAR(c.derivative_at(t)[0], df(t), 1e-11 * std::abs(df(t))) << t;
    }
  }
  // Far beyond the double range of the value: refused, not inf.
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 1>(x, P)(1e40)), "t", "overflow");
}

// The Runge phenomenon on f(x) = 1/(1 + 25 x^2) over [-1, 1], max error on 4001 points:
// on equispaced nodes it grows with n from n = 10 (0.30) to n = 40 (1.4e4); on Chebyshev
// nodes of both kinds it falls for every step n = 5..40 (to 7.1e-4 and 8.5e-4). The
// numbers agree with scipy.interpolate.BarycentricInterpolator (docs/accuracy.md).
TEST(Lagrange, RungePhenomenon) {
  const auto f = [](double x) { return 1 / (1 + 25 * x * x); };
  const auto max_error = [&](Nodes kind, std::size_t n) {
    std::vector<P1> P;
    for (double v : interpolation_nodes<double>(kind, n, -1.0, 1.0)) P.emplace_back(f(v));
    const auto c = Lagrange<double, 1>::on_nodes(kind, {-1.0, 1.0}, P);
    double e = 0;
    for (int i = 0; i <= 4000; ++i) {
      const double x = -1 + i / 2000.0;
      e = std::max(e, std::abs(c(x)[0] - f(x)));
    }
    return e;
  };
  double prev_eq = 0, prev_c1 = 1, prev_c2 = 1;
  for (std::size_t n = 5; n <= 40; n += 5) {
    const double eq = max_error(Nodes::equispaced, n), c1 = max_error(Nodes::chebyshev1, n), c2 = max_error(Nodes::chebyshev2, n);
    if (n >= 15) {
      EXPECT_GT(eq, prev_eq) << n;
    }
    EXPECT_LT(c1, prev_c1) << n;
    EXPECT_LT(c2, prev_c2) << n;
    prev_eq = eq;
    prev_c1 = c1;
    prev_c2 = c2;
  }
  EXPECT_GT(prev_eq, 1e4);
  EXPECT_LT(prev_c1, 1e-3);
  EXPECT_LT(prev_c2, 1e-3);
}

// The Bézier form: one piece of degree n - 1 on the domain, equal to the curve to 1e-12 of
// max |p| up to the cap (the measured worst case is 6.2e-13 at degree 15); refused above it.
TEST(Lagrange, BezierFormAndItsCap) {
  test::SplitMix64 rng(6);
  for (int n : {2, 3, 8, lagrange_max_bezier_degree + 1}) {
    for (Nodes kind : {Nodes::equispaced, Nodes::chebyshev1, Nodes::chebyshev2}) {
      auto P = test::random_points<double, 2>(rng, n - 1, -1, 1);
      const auto c = Lagrange<double, 2>::on_nodes(kind, {-2.0, 5.0}, P);
      const auto p = pieces(c);
      ASSERT_EQ(p.size(), 1u);
      // The domain is the nodes' hull: [-2, 5] but for the first kind (ends not nodes).
      EXPECT_EQ(p.breaks(), (std::vector<double>{c.domain().lo, c.domain().hi}));
      EXPECT_EQ(c.domain().lo == -2.0, kind != Nodes::chebyshev1);
      EXPECT_EQ((std::get<Bezier<double, 2>>(p.segments()[0]).degree()), n - 1);
      double size = 0, err = 0;
      for (int i = 0; i <= 500; ++i) {
        const double t = c.domain().at(i / 500.0);
        size = std::max(size, norm(c(t).to_vector()));
        err = std::max(err, test::max_coord_diff(p(t), c(t)));
      }
      EXPECT_LE(err, 1e-12 * size) << n;
    }
  }
  std::vector<double> u(lagrange_max_bezier_degree + 2);
  std::vector<P1> P(u.size());
  for (std::size_t j = 0; j < u.size(); ++j) u[j] = static_cast<double>(j);
  const Lagrange<double, 1> big(u, P);
  EXPECT_INVALID_ARGUMENT(pieces(big), "curve", "no accurate Bézier form");
  EXPECT_INVALID_ARGUMENT(big.control_bounds(), "curve", "no accurate Bézier form");
  EXPECT_EQ(big(3.5), P1(0.0));  // evaluation still works
}

TEST(Lagrange, Errors) {
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 2>({0, 1, 0.5, 1}, {P2(0, 0), P2(1, 1), P2(2, 2), P2(3, 3)})), "params[3]",
                          "distinct");
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 2>({0, NAN}, {P2(0, 0), P2(1, 1)})), "params[1]", "finite");
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 2>({0, 1, 2}, {P2(0, 0), P2(1, 1)})), "params", "one parameter per point");
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 2>({}, {})), "points", "at least 1");
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 2>({0, 1}, {P2(0, 0), P2(INFINITY, 1)})), "points[1][0]", "finite");
  EXPECT_INVALID_ARGUMENT((Lagrange<double, 2>({-1e308, 1e308}, {P2(0, 0), P2(1, 1)})), "params", "longer than");
  const auto c = cubic_through({0, 1, 2, 3});
  EXPECT_INVALID_ARGUMENT(c.derivative_at(0.5, -1), "k", ">= 0");
}

// Through one point: the constant polynomial (degree 0), as
// scipy.interpolate.BarycentricInterpolator([2], [[3, 4]]) gives; its domain is the one
// param, and every query on it sees that point.
TEST(Lagrange, OnePointIsTheConstant) {
  const Lagrange<double, 2> c({2.0}, {P2(3, 4)});
  EXPECT_EQ(c.degree(), 0);
  EXPECT_EQ(c.domain(), (Interval<double>{2, 2}));
  for (double u : {-1e300, -5.0, 2.0, 2.5, 1e300}) {
    EXPECT_EQ(c(u), P2(3, 4));
    EXPECT_EQ(c.neville(u), P2(3, 4));
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(c.derivative_at(u, k), V2(0, 0));
  }
  EXPECT_EQ(c.bezier().points(), std::vector<P2>{P2(3, 4)});
  EXPECT_EQ(c.control_bounds().lo, P2(3, 4));
  EXPECT_EQ(c.control_bounds().hi, P2(3, 4));
  const Pieces<double, 2> p = pieces(c);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p.domain().lo, 2.0);  // the next double above: pieces need increasing breaks
  EXPECT_EQ(p.domain().hi, std::nextafter(2.0, 3.0));
  EXPECT_EQ(p(2.0), P2(3, 4));
  const Box<double, 2> b = bounds(c);
  EXPECT_EQ(b.lo, P2(3, 4));
  EXPECT_EQ(b.hi, P2(3, 4));
  EXPECT_EQ(arc_length(c), 0.0);
  EXPECT_EQ(c.reverse(), c);
  EXPECT_EQ(c.transform(Affine<double, 2>::translate(V2(1, -1)))(7.0), P2(4, 3));
  // At the largest double the piece takes the double below (there is none above).
  const double top = std::numeric_limits<double>::max();
  const Lagrange<double, 1> e({top}, {P1(1)});
  EXPECT_EQ(pieces(e).domain().hi, top);
  EXPECT_EQ(pieces(e)(top), P1(1));
}

// ---------------------------------------------------------------------------------------
// Catmull-Rom splines.

const std::vector<P2> kCr{{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}, {5, -2}};

// Uniform (alpha 0): segment j on [j, j + 1] runs from p[j+1] to p[j+2] with the tangents
// (p[j+2] - p[j]) / 2 and (p[j+3] - p[j+1]) / 2 (the contract's closed form).
TEST(CatmullRom, UniformSegmentsFollowTheContract) {
  const CatmullRom<double, 2> c(kCr, 0.0);
  EXPECT_EQ(c.domain(), (Interval<double>{0, 3}));
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(c(j), kCr[j + 1]);
    // The derivative 3 (B_1 - B_0) with B_1 = B_0 + m / 3: a few ulps of the coordinates.
    EXPECT_LE(test::max_coord_diff(c.derivative_at(j), (kCr[j + 2] - kCr[j]) / 2.0), 4e-15);
    // The left limit at j + 1 (from inside segment j): the next tangent.
    EXPECT_LE(test::max_coord_diff(c.bezier_pieces().one_sided_derivative(j, 1.0, 1), (kCr[j + 3] - kCr[j + 1]) / 2.0), 4e-15);
  }
  EXPECT_EQ(c(3.0), kCr[4]);
  EXPECT_LE(test::max_coord_diff(c.derivative_at(3.0), (kCr[5] - kCr[3]) / 2.0), 4e-15);
  // Zero above the cubic.
  EXPECT_EQ(c.derivative_at(1.5, 4), V2(0, 0));
}

// Any alpha: the curve passes through the points at the knots s_i - s_1, with the
// Barry-Goldman tangent there, and is C1 at every joint.
TEST(CatmullRom, KnotsTangentsAndContinuity) {
  for (double alpha : {0.0, 0.25, 0.5, 1.0}) {
    const CatmullRom<double, 2> c(kCr, alpha);
    std::vector<double> d;
    for (std::size_t i = 0; i + 1 < kCr.size(); ++i) d.push_back(alpha == 0 ? 1.0 : std::pow(distance(kCr[i], kCr[i + 1]), alpha));
    double s = 0;
    for (std::size_t i = 1; i + 1 < kCr.size(); ++i) {
      EXPECT_NEAR(c.breaks()[i - 1], s, 1e-15 * (1 + s));
      EXPECT_LE(test::max_coord_diff(c(c.breaks()[i - 1]), kCr[i]), 1e-14);
      // m_i = (P_i - P_{i-1}) / d_{i-1} - (P_{i+1} - P_{i-1}) / (d_{i-1} + d_i) + (P_{i+1} - P_i) / d_i
      const V2 m = (kCr[i] - kCr[i - 1]) / d[i - 1] - (kCr[i + 1] - kCr[i - 1]) / (d[i - 1] + d[i]) + (kCr[i + 1] - kCr[i]) / d[i];
      EXPECT_LE(test::max_coord_diff(c.derivative_at(c.breaks()[i - 1]), m), 1e-13) << alpha << " " << i;
      if (i + 2 < kCr.size()) s += d[i];
    }
    const auto& p = c.bezier_pieces();
    for (std::size_t j = 0; j + 1 < p.size(); ++j) {
      EXPECT_LE(test::max_coord_diff(p.one_sided_derivative(j, 1.0, 1), p.one_sided_derivative(j + 1, 0.0, 1)), 1e-13);
    }
  }
}

// Closed: N segments, the domain [0, s_N], and the curve closes with C1 continuity.
TEST(CatmullRom, ClosedCurvesCloseWithC1) {
  for (double alpha : {0.0, 0.5, 1.0}) {
    const CatmullRom<double, 2> c(kCr, alpha, true);
    const auto& p = c.bezier_pieces();
    ASSERT_EQ(p.size(), kCr.size());
    EXPECT_EQ(c(c.domain().lo), kCr[0]);
    EXPECT_EQ(c(c.domain().hi), kCr[0]);
    EXPECT_LE(test::max_coord_diff(p.one_sided_derivative(p.size() - 1, 1.0, 1), p.one_sided_derivative(0, 0.0, 1)), 1e-13);
    for (std::size_t j = 0; j < kCr.size(); ++j) EXPECT_EQ(c(p.breaks()[j]), kCr[j]);
  }
}

// Affine maps: the image keeps the knots (exact image); only a similarity leaves them
// equal to the mapped points' own.
TEST(CatmullRom, TransformKeepsTheKnots) {
  const CatmullRom<double, 2> c(kCr, 0.5);
  Affine<double, 2> shear = Affine<double, 2>::identity();
  shear.linear[0][1] = 2;
  const auto s = c.transform(shear);
  EXPECT_FALSE(s.knots_follow_points());
  for (double t = 0; t <= c.domain().hi; t += 0.25) EXPECT_LE(test::max_coord_diff(s(t), shear(c(t))), 1e-13);
  EXPECT_TRUE(c.transform(rotation(0.7)).knots_follow_points());
  EXPECT_INVALID_ARGUMENT(io::to_json(io::AnyCurve(s)), "curve", "cannot express");
}

TEST(CatmullRom, Errors) {
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0), P2(1, 1), P2(2, 0)})), "points", "at least 4");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0), P2(1, 1)}, 0.5, true)), "points", "at least 3");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0), P2(1, 1), P2(1, 1), P2(2, 0)})), "points[2]", "equals points[1]");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0), P2(1, 1), P2(0, 0)}, 1.0, true)), "points[0]", "closed");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>(kCr, 1.5)), "alpha", "[0, 1]");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>(kCr, NAN)), "alpha", "finite");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0), P2(1, NAN), P2(1, 1), P2(2, 0)})), "points[1][1]", "finite");
  // Uniform knots allow repeated points (the curve rests there).
  const CatmullRom<double, 2> rest({P2(0, 0), P2(1, 1), P2(1, 1), P2(2, 0)}, 0.0);
  EXPECT_EQ(rest(0.0), P2(1, 1));
  EXPECT_EQ(rest(1.0), P2(1, 1));
}

// ends reflect: the curve of the points with the phantoms 2 P_0 - P_1 and 2 P_(N-1) -
// P_(N-2) around them (written out here), from P_0 to P_(N-1).
TEST(CatmullRom, ReflectedEndsRunThroughEveryPoint) {
  for (double alpha : {0.0, 0.5, 1.0}) {
    const CatmullRom<double, 2> c(kCr, alpha, false, CatmullRomEnds::reflect);
    std::vector<P2> E{kCr[0] + (kCr[0] - kCr[1])};
    E.insert(E.end(), kCr.begin(), kCr.end());
    E.push_back(kCr.back() + (kCr.back() - kCr[kCr.size() - 2]));
    const CatmullRom<double, 2> inner(E, alpha);
    ASSERT_EQ(c.bezier_pieces().size(), kCr.size() - 1);
    EXPECT_EQ(c.bezier_pieces(), inner.bezier_pieces());
    EXPECT_EQ(c.points(), kCr);
    EXPECT_EQ(c.intervals().size(), kCr.size() + 1);
    EXPECT_EQ(c(0.0), kCr[0]);
    EXPECT_EQ(c(c.domain().hi), kCr.back());
    // Reversal and transforms keep the ends.
    EXPECT_EQ(c.reverse().ends(), CatmullRomEnds::reflect);
    EXPECT_EQ(c.reverse().reverse(), c);
    EXPECT_LE(test::max_coord_diff(c.reverse()(0.0), kCr.back()), 0.0);
    EXPECT_EQ(c.transform(Affine<double, 2>::translate(V2(1, 1))).ends(), CatmullRomEnds::reflect);
  }
  // Two points: the segment.
  const CatmullRom<double, 2> two({P2(0, 0), P2(3, 4)}, 0.5, false, CatmullRomEnds::reflect);
  EXPECT_LE(test::max_coord_diff(two(two.domain().hi / 2), P2(1.5, 2)), 1e-15);
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0)}, 0.5, false, CatmullRomEnds::reflect)), "points", "at least 2");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>(kCr, 0.5, true, CatmullRomEnds::reflect)), "ends", "open");
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 2>({P2(0, 0), P2(0, 0), P2(1, 1)}, 0.5, false, CatmullRomEnds::reflect)), "points[1]",
                          "equals points[0]");
}

// The Barry-Goldman pyramid [BarryGoldman88] of the segment from P_1 to P_2 with knots
// t_0..t_3, in long double (whose range, to 1e4932, holds every product of the scaled
// data below): the reference the scaled curves are checked against, written here.
template <int D>
Point<double, D> barry_goldman(const std::array<Point<double, D>, 4>& P, const std::array<long double, 4>& t, long double u) {
  Point<double, D> out;
  for (int k = 0; k < D; ++k) {
    const auto lerp = [&](long double a, long double b, long double ta, long double tb) { return ((tb - u) * a + (u - ta) * b) / (tb - ta); };
    const long double A1 = lerp(P[0][k], P[1][k], t[0], t[1]), A2 = lerp(P[1][k], P[2][k], t[1], t[2]), A3 = lerp(P[2][k], P[3][k], t[2], t[3]);
    const long double B1 = lerp(A1, A2, t[0], t[2]), B2 = lerp(A2, A3, t[1], t[3]);
    out[k] = static_cast<double>(lerp(B1, B2, t[1], t[2]));
  }
  return out;
}

// Issue 15: the tangents divided by products of intervals, which overflow from about 1e154
// (alpha 1: the curve became its control polygon) and underflow below 1e-154 (an error of
// 6.7e-6 at 1e-160, a false "got inf" at 1e-200). Now the same curve at every scale from
// 1e-300 to 1e300 and every alpha, against the pyramid in long double.
TEST(CatmullRom, AnyScaleAgainstTheBarryGoldmanPyramid) {
  const std::vector<P2> unit{{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}};
  for (double scale : {1.0, 1e154, 1e200, 1e300, 1.7e308 / 8, 1e-154, 1e-160, 1e-200, 1e-300}) {
    for (double alpha : {0.0, 0.5, 0.75, 1.0}) {
      std::vector<P2> P;
      for (const P2& q : unit) P.emplace_back(q[0] * scale, q[1] * scale);
      const CatmullRom<double, 2> c(P, alpha);
      std::vector<long double> s{0};
      for (std::size_t i = 0; i + 1 < P.size(); ++i) {
        const long double dx = static_cast<long double>(P[i + 1][0]) - P[i][0], dy = static_cast<long double>(P[i + 1][1]) - P[i][1];
        s.push_back(s.back() + (alpha == 0 ? 1.0L : std::pow(std::sqrt(dx * dx + dy * dy), static_cast<long double>(alpha))));
      }
      // The domain's end: s_(N-2) - s_1 to a few ulps (the knots are sums of rounded intervals).
      EXPECT_NEAR(c.domain().hi, static_cast<double>(s[3] - s[1]), 1e-15 * c.domain().hi) << scale << " " << alpha;
      for (std::size_t j = 0; j < 2; ++j) {
        for (double f : {0.0, 0.1, 0.5, 0.9}) {
          const long double u = s[j + 1] + f * (s[j + 2] - s[j + 1]);
          const P2 ref = barry_goldman<2>({P[j], P[j + 1], P[j + 2], P[j + 3]}, {s[j], s[j + 1], s[j + 2], s[j + 3]}, u);
          // The parameter in double (rounded knots) moves the point by eps |C'| du: a few
          // eps of the scale; the Bézier form adds a few more.
          EXPECT_LE(test::max_coord_diff(c(static_cast<double>(u - s[1])), ref), 1e-14 * scale) << scale << " " << alpha << " " << j << " " << f;
        }
      }
    }
  }
}

// Coordinates near the largest double whose differences overflow: the intervals are
// formed at half scale. 1-D +-1e308 alternating, alpha 0.5: every interval is
// sqrt(2e308) = 1.41e154, so the tangents at P_1 and P_2 vanish (uniform-like:
// (P_2 - P_0) / 2 = 0) and the middle segment is the smooth step from 1e308 to -1e308
// through 0 at its middle.
TEST(CatmullRom, DifferencesBeyondTheLargestDouble) {
  const std::vector<P1> P{P1(-1e308), P1(1e308), P1(-1e308), P1(1e308)};
  const CatmullRom<double, 1> c(P, 0.5);
  EXPECT_NEAR(c.domain().hi, std::sqrt(2.0) * 1e154, 1e139);  // 1e-15 relative
  EXPECT_EQ(c(0.0), P1(1e308));
  EXPECT_EQ(c(c.domain().hi), P1(-1e308));
  EXPECT_LE(std::abs(c(c.domain().hi / 2)[0]), 1e293);  // 0 to 1e-15 of the coordinates
  // Smooth step: h00 - h01 at t = 1/4 is 27/32 - 5/32 = 0.6875 of 1e308.
  EXPECT_NEAR(c(c.domain().hi / 4)[0], 0.6875e308, 1e293);
}

// The parameter itself not a double: refused naming points (issue 15: never a silent
// control polygon, never a false "got inf").
TEST(CatmullRom, UnrepresentableParameterIsRefused) {
  // |dP| = 2e308 overflows at alpha 1 (at alpha 0.5 it is 1.41e154: served above).
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 1>({P1(-1e308), P1(1e308), P1(-1e308), P1(1e308)}, 1.0)), "points", "overflows");
  // |dP| = 1e-310 at alpha 1: below the normal range.
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 1>({P1(0), P1(1e-310), P1(2e-310), P1(3e-310)}, 1.0)), "points", "underflows");
  // ... but 1e-310^0.5 = 1e-155 is a normal double: served, the uniform-spaced line.
  const CatmullRom<double, 1> tiny({P1(0), P1(1e-310), P1(2e-310), P1(3e-310)}, 0.5);
  EXPECT_NEAR(tiny(tiny.domain().hi / 2)[0], 1.5e-310, 1e-323);
  // Knots that sum beyond the largest double: 1e308 + 1e308.
  EXPECT_INVALID_ARGUMENT((CatmullRom<double, 1>({P1(0), P1(1e308), P1(0), P1(1e308), P1(0)}, 1.0)), "points", "largest double");
}

// ---------------------------------------------------------------------------------------
// The matrix view.

constexpr CubicForm kForms[] = {CubicForm::bezier, CubicForm::hermite, CubicForm::catmull_rom, CubicForm::bspline};

// B = C^-1 exactly (rational arithmetic), both ways, for every form.
TEST(BasisMatrix, BasisIsTheInverseOfTheConstraints) {
  for (CubicForm f : kForms) {
    EXPECT_EQ(basis_matrix(f) * constraint_matrix(f), RationalMatrix4::identity());
    EXPECT_EQ(constraint_matrix(f) * basis_matrix(f), RationalMatrix4::identity());
    EXPECT_EQ(conversion_matrix(f, f), RationalMatrix4::identity());
  }
}

// The seed's Catmull-Rom B, the Bézier B of [Farin02, 5.8] (bernstein_to_power_matrix), the
// Hermite B from h00 = 1 - 3t^2 + 2t^3, h01 = 3t^2 - 2t^3, h10 = t - 2t^2 + t^3,
// h11 = t^3 - t^2, and the uniform B-spline B (1 4 1 0 / -3 0 3 0 / 3 -6 3 0 / -1 3 -3 1) / 6.
TEST(BasisMatrix, TextbookNumbers) {
  const double cr[4][4] = {{0, 1, 0, 0}, {-0.5, 0, 0.5, 0}, {1, -2.5, 2, -0.5}, {-0.5, 1.5, -1.5, 0.5}};
  const double he[4][4] = {{1, 0, 0, 0}, {0, 0, 1, 0}, {-3, 3, -2, -1}, {2, -2, 1, 1}};
  const double bs[4][4] = {{1, 4, 1, 0}, {-3, 0, 3, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  const Matrix<double> bz = bernstein_to_power_matrix<double>(3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      EXPECT_EQ(basis_matrix(CubicForm::catmull_rom).at<double>(i, j), cr[i][j]);
      EXPECT_EQ(basis_matrix(CubicForm::hermite).at<double>(i, j), he[i][j]);
      EXPECT_EQ(basis_matrix(CubicForm::bspline).at<double>(i, j), bs[i][j] / 6);
      EXPECT_EQ(basis_matrix(CubicForm::bezier).at<double>(i, j), bz(i, j));
    }
  // Catmull-Rom to Bézier: P_1, P_1 + (P_2 - P_0) / 6, P_2 - (P_3 - P_1) / 6, P_2.
  const RationalMatrix4 want{{{{0, 6, 0, 0}, {-1, 6, 1, 0}, {0, 1, 6, -1}, {0, 0, 6, 0}}}, 6};
  EXPECT_EQ(conversion_matrix(CubicForm::catmull_rom, CubicForm::bezier), want);
}

/// [1 t t^2 t^3] B G: the segment by its matrix form.
V2 matrix_form(CubicForm f, const std::array<V2, 4>& g, double t) {
  const double tp[4] = {1, t, t * t, t * t * t};
  V2 s{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s += tp[i] * basis_matrix(f).at<double>(i, j) * g[static_cast<std::size_t>(j)];
  return s;
}

// Converted geometry describes the same cubic: the Bézier curve of the converted points
// equals the matrix form of the original, for every pair of forms (rounding of O(10)
// coordinates through two 4 x 4 products: 1e-13).
TEST(BasisMatrix, ConversionsKeepTheCurve) {
  const std::array<V2, 4> g{V2(0, 0), V2(1, 3), V2(4, 2.5), V2(5, -1)};
  for (CubicForm from : kForms) {
    const auto b = convert_geometry<double>(from, CubicForm::bezier, g);
    const Bezier<double, 2> c({P2::from_vector(b[0]), P2::from_vector(b[1]), P2::from_vector(b[2]), P2::from_vector(b[3])});
    for (double t = 0; t <= 1; t += 0.125) EXPECT_LE(test::max_coord_diff(c(t).to_vector(), matrix_form(from, g, t)), 1e-13);
    for (CubicForm to : kForms) {
      const auto h = convert_geometry<double>(from, to, g);
      for (double t = 0; t <= 1; t += 0.25) EXPECT_LE(test::max_coord_diff(matrix_form(to, h, t), matrix_form(from, g, t)), 1e-12);
    }
  }
  // The uniform B-spline span's Bézier points are those of the B-spline's own pieces
  // (blossoming), and the Catmull-Rom ones those of the uniform CatmullRom curve.
  const std::vector<P2> P{P2(0, 0), P2(1, 3), P2(4, 2.5), P2(5, -1)};
  const auto bs = convert_geometry<double>(CubicForm::bspline, CubicForm::bezier, g);
  const auto bs_pieces = pieces(BSpline<double, 2>(3, {0, 1, 2, 3, 4, 5, 6, 7}, P));  // a local: no dangling reference
  const auto& piece = std::get<Bezier<double, 2>>(bs_pieces.segments()[0]);
  const auto cr = convert_geometry<double>(CubicForm::catmull_rom, CubicForm::bezier, g);
  const CatmullRom<double, 2> crc(P, 0.0);
  const auto& crp = std::get<Bezier<double, 2>>(crc.bezier_pieces().segments()[0]);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LE(test::max_coord_diff(piece.points()[i].to_vector(), bs[i]), 1e-14);
    EXPECT_LE(test::max_coord_diff(crp.points()[i].to_vector(), cr[i]), 1e-14);
  }
}

}  // namespace
