// Properties of the geometric queries on random curves: the closest point is no farther
// than any sample (and the farthest no nearer), the arc length lies between the chord and
// the control polygon's length and is additive, param_at_length inverts length, the
// distance between curves is no larger than any sampled pair, and roots with their
// multiplicities are recovered from products of linear factors.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "generators.hpp"

namespace {

using namespace casteljau;
constexpr double eps = std::numeric_limits<double>::epsilon();

// project() is global: no sample of the curve is nearer (farther) than its answer, beyond
// the distance's rounding (a few eps of the control points' size, which is <= 2 here).
RC_GTEST_PROP(QueriesProperty, ProjectBeatsEverySample, ()) {
  const int n = *rc::gen::inRange(1, 8);
  const bool rational = *rc::gen::arbitrary<bool>();
  const auto P = prop::control_points<2>(n);
  const auto q = *prop::point<2>(-1.5, 1.5);
  const Pieces<double, 2> c = rational ? pieces(RationalBezier<double, 2>(P, prop::weights(n))) : pieces(Bezier<double, 2>(P));
  const auto near = project(c, q), far = project(c, q, true);
  for (int i = 0; i <= 1000; ++i) {
    const double d = distance(c(i / 1000.0), q);
    RC_ASSERT(near.distance <= d + 64 * eps);
    RC_ASSERT(far.distance >= d - 64 * eps);
  }
  RC_ASSERT(std::abs(distance(near.point, q) - near.distance) <= 4 * eps);
}

// |P_n - P_0| <= length <= sum |P_(i+1) - P_i| (the curve is at least its chord and at most
// its control polygon, a convex-hull argument [Farin02, 5.5]), length is additive over a
// split point, and the parameter at length(0, u) is u again (where the speed is not 0).
RC_GTEST_PROP(QueriesProperty, LengthBoundsAdditivityAndInverse, ()) {
  const int n = *rc::gen::inRange(1, 8);
  const auto P = prop::control_points<3>(n);
  const Bezier<double, 3> c(P);
  const double len = arc_length(c);
  double polygon = 0;
  for (int i = 0; i < n; ++i) polygon += distance(P[static_cast<std::size_t>(i)], P[static_cast<std::size_t>(i) + 1]);
  RC_ASSERT(len >= distance(P.front(), P.back()) * (1 - 1e-12));
  RC_ASSERT(len <= polygon * (1 + 1e-12) + eps);
  const double u = *rc::gen::map(rc::gen::inRange(1, 1000), [](int k) { return k / 1000.0; });
  const double a = arc_length(c, 0.0, u), b = arc_length(c, u, 1.0);
  RC_ASSERT(std::abs(a + b - len) <= 1e-12 * len + eps);
  if (norm(c.derivative_at(u)) > 1e-3) {
    const double back = parameter_at_length(c, a);
    RC_ASSERT(std::abs(back - u) <= 1e-10);
  }
}

// distance() is no larger than the distance of any sampled pair (and not smaller than
// the global minimum: it is attained at its own points).
RC_GTEST_PROP(QueriesProperty, CurveDistanceBeatsEverySampledPair, ()) {
  const auto A = prop::control_points<2>(3), B = prop::control_points<2>(3, 0, 2);
  const Bezier<double, 2> a(A), b(B);
  const auto d = distance(a, b);
  RC_ASSERT(std::abs(distance(a(d.t[0]), b(d.t[1])) - d.distance) <= 8 * eps);
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) RC_ASSERT(d.distance <= distance(a(i / 60.0), b(j / 60.0)) + 8 * eps);
}

// Roots of prod (t - r_i)^(m_i) with distinct r_i on a grid of 1/64 (exact in binary, at
// least 1/16 apart) and m_i <= 3: every root once, with its multiplicity.
RC_GTEST_PROP(QueriesProperty, RootsWithMultiplicities, ()) {
  const int k = *rc::gen::inRange(1, 4);
  std::vector<int> slots = *rc::gen::unique<std::vector<int>>(static_cast<std::size_t>(k), rc::gen::inRange(1, 16));
  std::sort(slots.begin(), slots.end());
  std::vector<double> p = {1.0};
  std::vector<int> mult;
  for (int s : slots) {
    const double r = s / 16.0;
    const int m = *rc::gen::inRange(1, 4);
    mult.push_back(m);
    for (int j = 0; j < m; ++j) p = bernstein_product<double>(p, std::vector<double>{-r, 1 - r});
  }
  const auto roots = bernstein_roots_with_multiplicity<double>(p);
  RC_ASSERT(roots.size() == slots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    // A root of multiplicity m is located to about eps^(1/m) at worst (here the grid
    // values are exact, and the engine locates it as a simple root of p^(m-1)).
    RC_ASSERT(std::abs(roots[i].t - slots[i] / 16.0) <= 1e-9);
    RC_ASSERT(roots[i].multiplicity == mult[i]);
  }
}

}  // namespace
