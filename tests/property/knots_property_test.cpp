// Properties of the B-spline basis [PT97, ch. 2]: non-negativity, partition of unity,
// local support, agreement with the recursive Cox-de Boor definition; of the knot
// operations [PT97, ch. 5]: knot insertion, refinement, degree elevation, splitting and
// Bézier decomposition leave the curve unchanged; removal undoes insertion; the closed
// Lane-Riesenfeld limit closes with C^(p-1). Random degrees 1..5, clamped and
// unclamped knot vectors on a grid of 1/16 (so repeated knots are frequent).
#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/algo/subdivision.hpp"
#include "generators.hpp"

namespace {

using namespace casteljau;
using C2 = BSpline<double, 2>;

/// A random valid B-spline in the plane on prop::knot_vector's knots (up to 8 interior
/// knots).
C2 random_bspline() {
  KnotVector<double> U = prop::knot_vector(9);
  const int n = static_cast<int>(U.points());
  return C2(std::move(U), prop::control_points<2>(n - 1));
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

/// N_{i,p}(u) by the recursive definition [PT97, eq. 2.5] with 0/0 = 0 and the half-open
/// spans [U_i, U_{i+1}), except that the last non-empty span is closed at its right end
/// (the domain's end belongs to it). Written here from the definition, independently of
/// basis_functions' triangular scheme.
double cox_de_boor(const std::vector<double>& U, int i, int p, double u, double right_end) {
  const std::size_t I = static_cast<std::size_t>(i), P = static_cast<std::size_t>(p);
  if (p == 0) {
    if (u == right_end) return U[I] < U[I + 1] && U[I + 1] == right_end ? 1 : 0;
    return U[I] <= u && u < U[I + 1] ? 1 : 0;
  }
  double v = 0;
  if (U[I + P] != U[I]) v += (u - U[I]) / (U[I + P] - U[I]) * cox_de_boor(U, i, p - 1, u, right_end);
  if (U[I + P + 1] != U[I + 1]) v += (U[I + P + 1] - u) / (U[I + P + 1] - U[I + 1]) * cox_de_boor(U, i + 1, p - 1, u, right_end);
  return v;
}

// The p + 1 functions of A2.2 on span s are N_{s-p..s} of the definition; the others
// vanish there (local support); all are >= 0 and they sum to 1 on the domain.
RC_GTEST_PROP(KnotProperty, BasisIsTheCoxDeBoorDefinition, ()) {
  const C2 c = random_bspline();
  const std::vector<double>& U = c.knots();
  const int p = c.degree(), n = static_cast<int>(c.points().size());
  const auto [a, b] = c.domain();
  const double u = a + (b - a) * *rc::gen::inRange(0, 257) / 256.0;  // knots included
  const std::size_t s = find_span<double>(U, p, u);
  std::vector<double> N(static_cast<std::size_t>(p) + 1);
  basis_functions<double>(U, p, s, u, N);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double reference = cox_de_boor(U, i, p, u, b);
    RC_ASSERT(reference >= 0);
    const int r = i - (static_cast<int>(s) - p);
    const double ours = r >= 0 && r <= p ? N[static_cast<std::size_t>(r)] : 0.0;
    RC_ASSERT(std::abs(ours - reference) <= 1e-13);
    if (r < 0 || r > p) RC_ASSERT(reference == 0);  // local support: zero off span s's p + 1
    sum += ours;
  }
  RC_ASSERT(std::abs(sum - 1) <= 1e-14);
}

// Moving control point i changes the curve only on [U_i, U_(i+p+1)]: elsewhere de Boor
// reads the same p + 1 points, so the values are identical, not just close.
RC_GTEST_PROP(KnotProperty, MovingOnePointChangesOnlyItsSupport, ()) {
  const C2 c = random_bspline();
  const std::vector<double>& U = c.knots();
  const int p = c.degree();
  const std::size_t i = static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(c.points().size())));
  std::vector<Point<double, 2>> P = c.points();
  P[i] = P[i] + Vector<double, 2>{0.5, -0.25};
  const C2 moved(p, U, P);
  const auto [a, b] = c.domain();
  bool changed_inside = false;
  for (int k = 0; k <= 256; ++k) {
    const double u = a + (b - a) * k / 256.0;
    const bool inside = U[i] <= u && u <= U[i + static_cast<std::size_t>(p) + 1];
    if (!inside) RC_ASSERT(c(u) == moved(u));
    if (inside && distance(c(u), moved(u)) > 0) changed_inside = true;
  }
  RC_ASSERT(changed_inside || U[i + static_cast<std::size_t>(p) + 1] <= a || U[i] >= b);
}

// Bézier decomposition and back: the pieces trace the curve, and joining them again
// (each interior break p times, C^0) gives the same curve.
RC_GTEST_PROP(KnotProperty, BezierDecompositionKeepsTheCurve, ()) {
  const C2 c = random_bspline();
  const auto pc = pieces(c);
  std::vector<Bezier<double, 2>> segs;
  for (const auto& s : pc.segments()) segs.push_back(std::get<Bezier<double, 2>>(s));
  const auto [a, b] = c.domain();
  RC_ASSERT(gap(c, pc, a, b) <= 1e-12);
  RC_ASSERT(gap(c, C2::from_pieces(segs, pc.breaks()), a, b) <= 1e-12);
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

/// A random B-spline of degree 0..5 whose interior knots (on the 1/16 grid) may repeat
/// p + 1 times: breaks where the curve may jump (degree 0: every knot).
C2 random_jumping_bspline() {
  const int p = *rc::gen::inRange(0, 6);
  std::vector<double> X;
  for (int i = *rc::gen::inRange(0, 6); i > 0; --i) {
    const double x = *rc::gen::inRange(1, 16) / 16.0;
    X.insert(X.end(), static_cast<std::size_t>(*rc::gen::inRange(1, p + 2)), x);
  }
  std::sort(X.begin(), X.end());
  for (const double x : X) RC_PRE(std::count(X.begin(), X.end(), x) <= p + 1);
  const bool clamped = *rc::gen::arbitrary<bool>();
  std::vector<double> U;
  for (int i = p; i >= 0; --i) U.push_back(clamped ? 0.0 : -i / 16.0);
  U.insert(U.end(), X.begin(), X.end());
  for (int i = 0; i <= p; ++i) U.push_back(clamped ? 1.0 : 1 + i / 16.0);
  KnotVector<double> kv(p, std::move(U));
  const int n = static_cast<int>(kv.points());
  return C2(std::move(kv), prop::control_points<2>(n - 1));
}

// With jumps and at degree 0: the basis is still the Cox-de Boor definition (right
// limits at every knot, a break too); insertion up to p + 1, elevation and split keep the
// curve (parameters on the 1/64 grid hit the knots: the right limits agree as well); the
// left half of a split at a jump ends at the left limit. Bounds as the properties above.
RC_GTEST_PROP(KnotProperty, JumpsAndDegreeZeroKeepTheCurve, ()) {
  const C2 c = random_jumping_bspline();
  const std::vector<double>& U = c.knots();
  const int p = c.degree(), n = static_cast<int>(c.points().size());
  const auto [a, b] = c.domain();
  const double u = a + (b - a) * *rc::gen::inRange(0, 65) / 64.0;
  const std::size_t s = find_span<double>(U, p, u);
  std::vector<double> N(static_cast<std::size_t>(p) + 1);
  basis_functions<double>(U, p, s, u, N);
  for (int i = 0; i < n; ++i) {
    const int r = i - (static_cast<int>(s) - p);
    const double ours = r >= 0 && r <= p ? N[static_cast<std::size_t>(r)] : 0.0;
    RC_ASSERT(std::abs(ours - cox_de_boor(U, i, p, u, b)) <= 1e-13);
  }
  const int m = static_cast<int>(knot_multiplicity<double>(U, u));
  if (m <= p) RC_ASSERT(gap(c, c.insert_knot(u, *rc::gen::inRange(1, p + 2 - m)), a, b) <= 1e-12);
  RC_ASSERT(gap(c, c.elevate(*rc::gen::inRange(1, 4)), a - 0.05, b + 0.05) <= 1e-12);
  if (u > a && u < b) {
    const auto [l, r] = c.split(u);
    RC_ASSERT(gap(c, r, u, b) <= 1e-12);
    RC_ASSERT(gap(c, l, a, u - (u - a) / 1024) <= 1e-12);  // not at u itself: a jump's left limit
    if (m == p + 1) RC_ASSERT(distance(l(u), c(std::nextafter(u, a))) <= 1e-12);
  }
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
