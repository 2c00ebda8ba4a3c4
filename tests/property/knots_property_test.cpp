// Properties of the B-spline knot operations [PT97, ch. 5]: knot insertion, refinement,
// degree elevation and splitting leave the curve unchanged; removal undoes insertion; the
// closed Lane-Riesenfeld limit closes with C^(p-1). Random degrees 1..5, clamped and
// unclamped knot vectors on a grid of 1/16 (so repeated knots are frequent).
#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/algo/subdivision.hpp"
#include "generators.hpp"

namespace {

using namespace casteljau;
using C2 = BSpline<double, 2>;

/// A random valid B-spline in the plane: degree 1..5, up to 8 interior knots on the grid
/// k/16 of (0, 1) (each at most p times), clamped or with outer knots -k/16 and 1 + k/16.
C2 random_bspline() {
  const int p = *rc::gen::inRange(1, 6);
  const int inner = *rc::gen::inRange(0, 9);
  std::vector<double> X;
  for (int i = 0; i < inner; ++i) X.push_back(*rc::gen::inRange(1, 16) / 16.0);
  std::sort(X.begin(), X.end());
  for (const double x : X) RC_PRE(std::count(X.begin(), X.end(), x) <= p);
  const bool clamped = *rc::gen::arbitrary<bool>();
  std::vector<double> U;
  for (int i = p; i >= 0; --i) U.push_back(clamped ? 0.0 : -i / 16.0);
  U.insert(U.end(), X.begin(), X.end());
  for (int i = 0; i <= p; ++i) U.push_back(clamped ? 1.0 : 1 + i / 16.0);
  const int n = static_cast<int>(U.size()) - p - 1;
  return C2(p, std::move(U), prop::control_points<2>(n - 1));
}

/// max |a(u) - b(u)| over 65 parameters of [lo, hi].
template <class A, class B>
double gap(const A& a, const B& b, double lo, double hi) {
  double d = 0;
  for (int i = 0; i <= 64; ++i) {
    const double u = lo + (hi - lo) * i / 64;
    d = std::max(d, distance(a(u), b(u)));
  }
  return d;
}

// Each new point is a convex combination of two old ones (insertion, refinement) or the
// same blossom value reached another way (split): a few eps of the unit box. The bound
// 1e-12 is the issue's, far above those few eps.
RC_GTEST_PROP(KnotProperty, InsertionAndRefinementKeepTheCurve, ()) {
  const C2 c = random_bspline();
  const auto [a, b] = c.domain();
  const double u = a + (b - a) * *rc::gen::inRange(0, 65) / 64.0;
  const int s = static_cast<int>(knot_multiplicity<double>(c.knots(), u));
  RC_PRE(s < c.degree());
  const int times = *rc::gen::inRange(1, c.degree() - s + 1);
  RC_ASSERT(gap(c, c.insert_knot(u, times), a, b) <= 1e-12);
  std::vector<double> candidates, X;
  for (int i = 0; i < 6; ++i) candidates.push_back(a + (b - a) * *rc::gen::inRange(1, 32) / 32.0);
  std::sort(candidates.begin(), candidates.end());
  // Keep each knot while its multiplicity stays within the degree.
  for (const double x : candidates) {
    const std::size_t m = knot_multiplicity<double>(c.knots(), x) + static_cast<std::size_t>(std::count(X.begin(), X.end(), x));
    if (m < static_cast<std::size_t>(c.degree())) X.push_back(x);
  }
  RC_ASSERT(gap(c, c.refine_knots(X), a, b) <= 1e-12);
}

// Elevation: Forrest's combinations per piece and p - m exact removals per knot; the
// removals divide by knot-ratio factors, which on this grid stay below about 16^p, so the
// error stays far below 1e-12. Also beyond the domain (the same end pieces).
RC_GTEST_PROP(KnotProperty, ElevationKeepsTheCurve, ()) {
  const C2 c = random_bspline();
  const int r = *rc::gen::inRange(1, 4);
  const C2 e = c.elevate(r);
  RC_ASSERT(e.degree() == c.degree() + r);
  const auto [a, b] = c.domain();
  RC_ASSERT(gap(c, e, a - 0.05, b + 0.05) <= 1e-12);
}

RC_GTEST_PROP(KnotProperty, SplitHalvesTraceTheCurve, ()) {
  const C2 c = random_bspline();
  const auto [a, b] = c.domain();
  const double u = a + (b - a) * *rc::gen::inRange(1, 64) / 64.0;
  const auto [l, r] = c.split(u);
  RC_ASSERT(gap(c, l, a, u) <= 1e-12);
  RC_ASSERT(gap(c, r, u, b) <= 1e-12);
}

// Removal undoes insertion: the knot comes out as many times as it went in, and the
// points come back (removal divides by alpha or 1 - alpha, at least 1/64 here).
RC_GTEST_PROP(KnotProperty, RemovalUndoesInsertion, ()) {
  const C2 c = random_bspline();
  const auto [a, b] = c.domain();
  const double u = a + (b - a) * (2 * *rc::gen::inRange(0, 32) + 1) / 64.0;  // off the 1/16 grid: not a knot
  RC_PRE(knot_multiplicity<double>(c.knots(), u) == 0);
  const int times = *rc::gen::inRange(1, c.degree() + 1);
  const auto r = c.insert_knot(u, times).remove_knot(u, times, 1e-10);
  RC_ASSERT(r.removed == times);
  RC_ASSERT(r.curve.knots() == c.knots());
  for (std::size_t i = 0; i < c.points().size(); ++i) RC_ASSERT(distance(r.curve.points()[i], c.points()[i]) <= 1e-10);
}

// The closed Lane-Riesenfeld limit is periodic: value and derivatives 1..p-1 agree at the
// two ends of its domain (derivatives of order k scale like 2^k times the coordinates on
// unit knot spacing: 1e-12 covers the rounding).
RC_GTEST_PROP(KnotProperty, ClosedLimitClosesSmoothly, ()) {
  const int p = *rc::gen::inRange(1, 6);
  const int n = *rc::gen::inRange(3, 10);
  const C2 L = lane_riesenfeld_limit(prop::control_points<2>(n - 1), p, true);
  const auto [a, b] = L.domain();
  for (int k = 0; k < p; ++k) RC_ASSERT(norm(L.derivative_at(a, k) - L.derivative_at(b, k)) <= 1e-12 * std::pow(2.0, k));
}

}  // namespace
