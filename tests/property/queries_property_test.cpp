// Properties of the geometric queries on random curves: the closest point is no farther
// than any sample (and the farthest no nearer), the arc length lies between the chord and
// the control polygon's length and is additive, param_at_length inverts length, the
// distance between curves is no larger than any sampled pair, roots with their
// multiplicities are recovered from products of linear factors, bounds over a range hold
// their samples, and the Frenet frame is orthonormal with the textbook curvature and torsion.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "generators.hpp"

namespace {

using namespace casteljau;
using casteljau::prop::eps;

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

// bounds(c, from, to) holds every sample of the range, lies inside the whole box, and
// touches the curve: each face equals the extreme sample refined by a ternary search over
// its two neighbouring sample gaps (the coordinate is unimodal there unless two extrema
// lie within 2/1000 of the range, when their values differ by far less than 1e-9).
RC_GTEST_PROP(QueriesProperty, BoundsOverARangeHoldsAndTouchesItsSamples, ()) {
  const int n = *rc::gen::inRange(1, 8);
  const bool rational = *rc::gen::arbitrary<bool>();
  const auto P = prop::control_points<2>(n);
  const Pieces<double, 2> c = rational ? pieces(RationalBezier<double, 2>(P, prop::weights(n))) : pieces(Bezier<double, 2>(P));
  double a = *prop::parameter(), b = *prop::parameter();
  if (a > b) std::swap(a, b);
  const auto box = bounds(c, a, b), whole = bounds(c);
  auto at = [&](int i) { return a + (b - a) * i / 1000.0; };
  for (int k = 0; k < 2; ++k) {
    RC_ASSERT(box.lo[k] >= whole.lo[k] - 8 * eps && box.hi[k] <= whole.hi[k] + 8 * eps);
    for (const double sign : {1.0, -1.0}) {  // the min of sign * x_k
      int best = 0;
      for (int i = 0; i <= 1000; ++i) {
        const double v = sign * c(at(i))[k];
        RC_ASSERT(v >= sign * (sign > 0 ? box.lo[k] : box.hi[k]) - 8 * eps);
        if (v < sign * c(at(best))[k]) best = i;
      }
      double lo = at(std::max(best - 1, 0)), hi = at(std::min(best + 1, 1000));
      for (int it = 0; it < 200 && hi - lo > 4 * eps; ++it) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (sign * c(m1)[k] <= sign * c(m2)[k]) hi = m2; else lo = m1;
      }
      const double refined = std::min(sign * c(lo)[k], sign * c(hi)[k]);
      RC_ASSERT(std::abs(refined - sign * (sign > 0 ? box.lo[k] : box.hi[k])) <= 1e-9);
    }
  }
}

// The Frenet frame of a random space cubic: T, N, B orthonormal and right-handed where
// defined, curvature |c' x c''| / |c'|^3 and torsion det(c', c'', c''') / |c' x c''|^2
// computed here from the derivatives by the textbook formulas.
RC_GTEST_PROP(QueriesProperty, FrenetFrameIsOrthonormal, ()) {
  const Bezier<double, 3> c(prop::control_points<3>(3));
  const double t = *prop::parameter();
  const auto f = frame(c, t);
  const auto d1 = c.derivative_at(t, 1), d2 = c.derivative_at(t, 2), d3 = c.derivative_at(t, 3);
  const Vector<double, 3> x(d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]);
  // Well-conditioned points only (c'' at least 1/100 rad off c'): there the frame's
  // directions are accurate to about 100 eps and the comparisons below are fair.
  // One bool: RC_PRE decomposes its expression (an overloaded &&, no short circuit), and
  // f->normal must not be read when f is empty.
  const bool well_conditioned = f.has_value() && f->normal.has_value() && norm(x) > 1e-2 * norm(d1) * norm(d2);
  RC_PRE(well_conditioned);
  RC_ASSERT(std::abs(norm(f->tangent) - 1) <= 4 * eps);
  RC_ASSERT(std::abs(norm(*f->normal) - 1) <= 4 * eps);
  RC_ASSERT(std::abs(dot(f->tangent, *f->normal)) <= 1e-14);
  RC_ASSERT(std::abs(dot(*f->binormal, x) / norm(x) - 1) <= 1e-12);  // B along c' x c''
  const double s = norm(d1);
  RC_ASSERT(std::abs(f->curvature - norm(x) / (s * s * s)) <= 1e-10 * f->curvature);
  RC_ASSERT(std::abs(*f->torsion - dot(x, d3) / dot(x, x)) <= 1e-8 * (1 + std::abs(*f->torsion)));
}

}  // namespace
