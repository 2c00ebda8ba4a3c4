// Invariants of rational Bézier curves [Farin02, ch. 13; PT97, ch. 4]: weights scaled by
// a constant change nothing, unit weights give the polynomial curve, and split, elevate,
// reverse and affine maps reproduce the curve; derivatives match finite differences.
//
// Tolerances: weights lie in [1/4, 4], so a rational de Casteljau step's ratio
// b / (a + b) carries ~3 eps, and the point error per level is a few eps of the control
// points' size (<= 1): `16 n eps` covers one or two evaluations with room.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "generators.hpp"

namespace {

using namespace casteljau;
using casteljau::prop::eps;

using casteljau::prop::diff;

template <int D>
RationalBezier<double, D> random_rational(int n) {
  return RationalBezier<double, D>(prop::control_points<D>(n), prop::weights(n));
}

using casteljau::prop::degree;

RC_GTEST_PROP(RationalProperty, ScalingWeightsLeavesCurveUnchanged, ()) {
  const int n = degree();
  const auto r = random_rational<2>(n);
  const double lambda = *prop::coordinate(0.1, 10);
  std::vector<double> w = r.weights();
  for (double& x : w) x *= lambda;  // one rounding per weight: relative eps/2
  const RationalBezier<double, 2> s(r.points(), w);
  const double t = *prop::parameter();
  RC_ASSERT(diff(s(t), r(t)) <= 16.0 * n * eps);
}

// All weights 1: the rational algorithm's ratios t / ((1-t) + t) differ from t by an ulp.
RC_GTEST_PROP(RationalProperty, UnitWeightsEqualBezier, ()) {
  const int n = degree();
  const auto P = prop::control_points<3>(n);
  const RationalBezier<double, 3> r(P, std::vector<double>(P.size(), 1.0));
  const Bezier<double, 3> b(P);
  const double t = *prop::parameter();
  RC_ASSERT(diff(r(t), b(t)) <= 4.0 * n * eps);
  // Derivatives too: the quotient rule with w = 1, w' = 0; differences of the numerator
  // reach 2n per coordinate, relative rounding ~ n eps.
  RC_ASSERT(diff(r.derivative_at(t), b.derivative_at(t)) <= 8.0 * n * n * eps);
}

// Elevation by r at once equals r single elevations: both are the unique degree-(n + r)
// form of the curve. Each single step is a convex combination (error a few eps of the
// control points' size <= 1), the direct one too: 16 (n + r) eps covers both.
RC_GTEST_PROP(RationalProperty, ElevateAtOnceEqualsStepwise, ()) {
  const int n = *rc::gen::inRange(1, 11), r = *rc::gen::inRange(1, 41);
  const auto c = random_rational<2>(n);
  const auto once = c.elevate(r);
  auto steps = c;
  for (int i = 0; i < r; ++i) steps = steps.elevate(1);
  RC_ASSERT(once.degree() == n + r);
  const double t = *prop::parameter();
  RC_ASSERT(diff(once(t), steps(t)) <= 16.0 * (n + r) * eps);
  RC_ASSERT(diff(once(t), c(t)) <= 16.0 * (n + r) * eps);
}

// Split: left(s) = r(s t), right(s) = r(t + s(1 - t)); three evaluations' worth plus the
// parameter rounding (|r'| <= 2n * 16 for weights within a factor 16): 16 n eps * 4.
RC_GTEST_PROP(RationalProperty, SplitReproducesCurve, ()) {
  const int n = degree();
  const auto r = random_rational<2>(n);
  const double t = *prop::parameter(), s = *prop::parameter();
  const auto h = r.split(t);
  RC_ASSERT(diff(h.left(s), r(s * t)) <= 64.0 * n * eps);
  RC_ASSERT(diff(h.right(s), r(t + s * (1 - t))) <= 64.0 * n * eps);
}

RC_GTEST_PROP(RationalProperty, ElevationLeavesCurveUnchanged, ()) {
  const int n = degree(), k = *rc::gen::inRange(1, 5);
  const auto r = random_rational<2>(n);
  const auto e = r.elevate(k);
  RC_ASSERT(e.degree() == n + k);
  const double t = *prop::parameter();
  RC_ASSERT(diff(e(t), r(t)) <= 32.0 * (n + k) * eps);
}

// reverse twice is the identity; reverse(1 - t) = r(t) (1 - t exact on the grid).
RC_GTEST_PROP(RationalProperty, Reverse, ()) {
  const int n = degree();
  const auto r = random_rational<2>(n);
  RC_ASSERT(r.reverse().reverse() == r);
  const double t = *prop::parameter();
  RC_ASSERT(diff(r.reverse()(1 - t), r(t)) <= 16.0 * n * eps);
}

// Affine invariance (weights untouched): entries in [-2, 2] make coordinates <= 6.
RC_GTEST_PROP(RationalProperty, AffineInvariance, ()) {
  const int n = degree();
  const auto r = random_rational<2>(n);
  Affine<double, 2> m;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) m.linear[i][j] = *prop::coordinate(-2, 2);
    m.translation[i] = *prop::coordinate(-2, 2);
  }
  const double t = *prop::parameter();
  RC_ASSERT(diff(r.transform(m)(t), m(r(t))) <= 16.0 * n * eps * 6);
}

// Convex hull: inside the control box within evaluation rounding.
RC_GTEST_PROP(RationalProperty, InsideControlBox, ()) {
  const int n = degree();
  const auto r = random_rational<3>(n);
  const auto box = r.control_bounds();
  for (int i = 0; i <= 20; ++i) RC_ASSERT(box.contains(r(i / 20.0), 16.0 * n * eps));
}

// First derivative against central differences, degree <= 10 (rational derivatives grow
// with the weight ratio, up to 16 here): h = 1e-4, truncation h^2 |r'''| / 6 with |r'''|
// below (16 * 2n)^3 as a crude bound, rounding 16 n eps / h.
RC_GTEST_PROP(RationalProperty, DerivativeMatchesFiniteDifference, ()) {
  const int n = *rc::gen::inRange(1, 11);
  const auto r = random_rational<2>(n);
  const double t = *prop::coordinate(0.01, 0.99), h = 1e-4;
  const auto fd = (r(t + h) - r(t - h)) / (2 * h);
  const double g = 32.0 * n;
  RC_ASSERT(diff(fd, r.derivative_at(t)) <= h * h * g * g * g / 6 + 16.0 * n * eps / h);
}

// Tight bounds of a rational curve contain its samples and lie in the control box.
RC_GTEST_PROP(RationalProperty, TightBounds, ()) {
  const int n = *rc::gen::inRange(1, 16);
  const auto r = random_rational<2>(n);
  const auto b = bounds(r), cb = r.control_bounds();
  const double round = 16.0 * n * eps;
  for (int i = 0; i <= 500; ++i) RC_ASSERT(b.contains(r(i / 500.0), round));
  for (int d = 0; d < 2; ++d) {
    RC_ASSERT(b.lo[d] >= cb.lo[d] - round);
    RC_ASSERT(b.hi[d] <= cb.hi[d] + round);
  }
}

}  // namespace
