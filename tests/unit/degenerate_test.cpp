// Every degenerate fixture (degenerate_fixtures.hpp) through evaluation, bounds, split,
// elevation, derivatives, curvature, end tangents, flattening and batch evaluation:
// finite results, no crash, and the usual invariants at a tolerance relative to the
// fixture's scale.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "degenerate_fixtures.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using casteljau::test::eps;

class DegenerateFixture : public ::testing::TestWithParam<test::Degenerate> {};

INSTANTIATE_TEST_SUITE_P(All, DegenerateFixture, ::testing::ValuesIn(test::degenerate_fixtures()),
                         [](const auto& info) { return info.param.name; });

std::vector<double> ts(int n = 100) {
  std::vector<double> v;
  for (int i = 0; i <= n; ++i) v.push_back(static_cast<double>(i) / n);
  return v;
}

// Relative tolerance for a degree-n evaluation: de Casteljau's error stays within a few
// eps of max |P| (convex combinations); 64 (n + 1) eps covers every fixture with room.
double tol_for(const test::Degenerate& f) { return 64.0 * (f.curve.degree() + 1) * eps * f.scale; }

TEST_P(DegenerateFixture, EvaluationFiniteAndInsideControlBox) {
  const auto& f = GetParam();
  const auto box = f.curve.control_bounds();
  for (double t : ts()) {
    const P2 p = f.curve(t);
    ASSERT_TRUE(test::all_finite(p)) << t;
    EXPECT_TRUE(box.contains(p, tol_for(f))) << t;
  }
  EXPECT_EQ(f.curve(0.0), f.curve.points().front());
  EXPECT_EQ(f.curve(1.0), f.curve.points().back());
}

TEST_P(DegenerateFixture, TightBounds) {
  const auto& f = GetParam();
  const auto b = bounds(f.curve), cb = f.curve.control_bounds();
  ASSERT_TRUE(test::all_finite(b.lo));
  ASSERT_TRUE(test::all_finite(b.hi));
  for (int d = 0; d < 2; ++d) {
    EXPECT_GE(b.lo[d], cb.lo[d]);
    EXPECT_LE(b.hi[d], cb.hi[d]);
  }
  for (double t : ts(1000)) EXPECT_TRUE(b.contains(f.curve(t), tol_for(f))) << t;
}

TEST_P(DegenerateFixture, Split) {
  const auto& f = GetParam();
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    const auto s = f.curve.split(t);
    EXPECT_EQ(s.left.points().back(), s.right.points().front());
    EXPECT_EQ(s.left.points().front(), f.curve.points().front());
    EXPECT_EQ(s.right.points().back(), f.curve.points().back());
    for (double u : ts(20)) {
      ASSERT_TRUE(test::all_finite(s.left(u)));
      ASSERT_TRUE(test::all_finite(s.right(u)));
      EXPECT_LE(test::max_coord_diff(s.left(u), f.curve(u * t)), tol_for(f)) << t << " " << u;
      EXPECT_LE(test::max_coord_diff(s.right(u), f.curve(t + u * (1 - t))), tol_for(f)) << t << " " << u;
    }
  }
}

TEST_P(DegenerateFixture, ElevateAndReduce) {
  const auto& f = GetParam();
  for (int r : {1, 3}) {
    const auto e = f.curve.elevate(r);
    ASSERT_EQ(e.degree(), f.curve.degree() + r);
    for (double t : ts(50)) EXPECT_LE(test::max_coord_diff(e(t), f.curve(t)), tol_for(f)) << t;
    // Back down with free end points: finite, and exact up to the Gram system's rounding
    // (condition ~4^n: at most ~4^11 eps relative for the degree-11 fixture).
    const auto red = reduce_degree(e, f.curve.degree(), Endpoints::free);
    for (const auto& p : red.curve.points()) ASSERT_TRUE(test::all_finite(p));
    EXPECT_LE(red.max_error, 1e-6 * f.scale);
    EXPECT_LE(red.max_error, red.error_bound + tol_for(f));
  }
}

TEST_P(DegenerateFixture, Derivatives) {
  const auto& f = GetParam();
  const int n = f.curve.degree();
  for (int k = 1; k <= 3; ++k) {
    const auto h = f.curve.derivative(k);
    for (double t : ts(50)) {
      const auto v = f.curve.derivative_at(t, k);
      ASSERT_TRUE(test::all_finite(v));
      // The hodograph curve and derivative_at do the same arithmetic in another order;
      // derivatives reach n^k |P| in size.
      EXPECT_LE(test::max_coord_diff(h(t).to_vector(), v), std::pow(2.0 * n + 2, k) * tol_for(f)) << k << " " << t;
    }
  }
}

// Curvature is scale-covariant: kappa(s c) = kappa(c) / s. The fixtures with huge and tiny
// coordinates are 1e150 and 1e-150 times a unit curve; their curvature must be that of
// the unit curve scaled, not overflowed to 0 or inf. Zero speed gives nullopt, never NaN.
// Absent only where it must be: a constant curve (all control points equal) has zero
// speed everywhere; any other curve of degree n has a hodograph whose coordinates are
// polynomials of degree n - 1, not both identically zero, so its speed vanishes at no more
// than n - 1 parameters, and curvature is present at all other samples.
TEST_P(DegenerateFixture, CurvatureFiniteOrAbsent) {
  const auto& f = GetParam();
  const auto& P = f.curve.points();
  const bool constant = std::all_of(P.begin(), P.end(), [&](const P2& p) { return p == P.front(); });
  const auto samples = ts(50);
  int present = 0;
  for (double t : samples) {
    const auto k = curvature(f.curve, t);
    if (k) {
      EXPECT_TRUE(std::isfinite(*k)) << t;
      ++present;
    }
  }
  if (constant) {
    EXPECT_EQ(present, 0) << "a constant curve has no curvature";
  } else {
    const int n = f.curve.degree();
    EXPECT_GE(present, static_cast<int>(samples.size()) - std::max(n - 1, 0)) << "curvature missing at regular points";
  }
}

TEST(Degenerate, CurvatureOfHugeAndTinyCurvesScales) {
  const Bezier<double, 2> unit{{1, -2}, {3, 1}, {-1, 2}, {2, 0}};
  for (double s : {1e150, 1e-150, 1e300, 1e-300}) {
    const auto scaled = unit.transform(Affine<double, 2>::scale(s));
    for (double t : ts(20)) {
      const auto k1 = curvature(unit, t), ks = curvature(scaled, t);
      ASSERT_TRUE(k1.has_value());
      ASSERT_TRUE(ks.has_value()) << "s=" << s << " t=" << t;
      // kappa(s c) * s = kappa(c): the scaling by a power of ten rounds each control point
      // once, so a relative 1e-13 bounds it.
      EXPECT_NEAR(*ks * s, *k1, 1e-13 * std::abs(*k1) + 1e-300) << "s=" << s << " t=" << t;
    }
  }
}

TEST_P(DegenerateFixture, EndTangentsAreUnitOrAbsent) {
  const auto& f = GetParam();
  const Path<double, 2> p({f.curve});
  for (bool at_end : {false, true}) {
    const auto tan = end_tangent(p, 0, at_end);
    if (tan) {
      EXPECT_NEAR(norm(*tan), 1.0, 4 * eps);
    }
  }
  // A curve with all points equal has no tangent; one with distinct points has one.
  bool all_equal = true;
  for (const auto& q : f.curve.points()) all_equal = all_equal && q == f.curve.points().front();
  EXPECT_EQ(end_tangent(p, 0, false).has_value(), !all_equal);
}

TEST_P(DegenerateFixture, Flatten) {
  const auto& f = GetParam();
  const double tol = 1e-3 * f.scale;
  const auto poly = flatten(f.curve, tol);
  ASSERT_GE(poly.size(), 2u);
  for (const auto& v : poly) ASSERT_TRUE(test::all_finite(v));
  EXPECT_EQ(poly.front(), f.curve.points().front());
  EXPECT_EQ(poly.back(), f.curve.points().back());
  for (double t : ts(2000)) EXPECT_LE(test::polyline_distance(f.curve(t), poly), tol * (1 + 1e-12)) << t;
}

TEST_P(DegenerateFixture, BatchEvaluate) {
  const auto& f = GetParam();
  const auto t = ts(300);
  std::vector<double> x(t.size()), y(t.size());
  evaluate(f.curve, std::span<const double>(t), {std::span<double>(x), std::span<double>(y)});
  for (std::size_t j = 0; j < t.size(); ++j) {
    ASSERT_TRUE(std::isfinite(x[j]) && std::isfinite(y[j]));
    // The fast path (power form at degree <= 3) agrees with de Casteljau to a few eps of
    // max |P| (the power coefficients are at most 8 max |P|).
    EXPECT_LE(test::max_coord_diff(P2(x[j], y[j]), f.curve(t[j])), 64 * eps * f.scale) << t[j];
  }
}

// The same fixtures as rational curves with uneven weights.
TEST_P(DegenerateFixture, RationalVersion) {
  const auto& f = GetParam();
  std::vector<double> w;
  for (std::size_t i = 0; i < f.curve.points().size(); ++i) w.push_back(i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 3.0 : 0.25));
  const RationalBezier<double, 2> r(f.curve.points(), w);
  const auto box = r.control_bounds(), b = bounds(r);
  for (double t : ts()) {
    const P2 p = r(t);
    ASSERT_TRUE(test::all_finite(p));
    EXPECT_TRUE(box.contains(p, tol_for(f)));
    EXPECT_TRUE(b.contains(p, tol_for(f))) << t;
    ASSERT_TRUE(test::all_finite(r.derivative_at(t, 1)));
    ASSERT_TRUE(test::all_finite(r.derivative_at(t, 2)));
  }
  const auto s = r.split(0.4);
  EXPECT_LE(test::max_coord_diff(s.left(0.5), r(0.2)), 4 * tol_for(f));
  const auto e = r.elevate(2);
  EXPECT_LE(test::max_coord_diff(e(0.7), r(0.7)), 4 * tol_for(f));
  const double tol = 1e-3 * f.scale;
  const auto poly = flatten(r, tol);
  for (double t : ts(1000)) EXPECT_LE(test::polyline_distance(r(t), poly), tol * (1 + 1e-12)) << t;
}

}  // namespace
