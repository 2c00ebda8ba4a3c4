// Invariants of Bézier curves of degree 1..30 in dimensions 1..4 [Farin02, ch. 3-5]:
// end points and end tangents, affine invariance, convex hull, subdivision, portions,
// elevation, reduction, derivatives, reversal and tight bounds.
//
// Tolerances: control points lie in [-1, 1]^D. De Casteljau's rounding is at most about
// 1.5 eps per level (two products and a sum of a convex combination), so one evaluation
// of degree n is within 1.5 n eps of exact; |c'| <= 2n per coordinate turns a parameter
// rounding of eps/2 into n eps. Each tolerance below adds up those terms with a factor of
// about 2 of room, as `k * n * eps`.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "generators.hpp"

namespace {

using namespace casteljau;
using casteljau::prop::eps;

/// Calls f.template operator()<D>() for a random D in 1..4.

using casteljau::prop::diff;

using casteljau::prop::degree;

// c(0) = P0 and c(1) = Pn exactly; c'(0) = n (P1 - P0), c'(1) = n (Pn - Pn-1): the same
// one subtraction and one multiplication, so exactly equal.
RC_GTEST_PROP(BezierProperty, EndPointsAndEndTangents, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const auto P = prop::control_points<D>(n);
    const Bezier<double, D> c(P);
    RC_ASSERT(c(0.0) == P.front());
    RC_ASSERT(c(1.0) == P.back());
    RC_ASSERT(c.derivative_at(0.0) == (P[1] - P[0]) * static_cast<double>(n));
    RC_ASSERT(c.derivative_at(1.0) == (P[static_cast<std::size_t>(n)] - P[static_cast<std::size_t>(n - 1)]) * static_cast<double>(n));
  });
}

// transform(A)(t) = A(c(t)): with |A| entries and translation in [-2, 2], mapped
// coordinates are <= 2D + 2 in size; both sides carry an evaluation error (1.5 n eps of
// that size) and the map's D-term sums (D eps): 4 (n + D) eps (2D + 2).
RC_GTEST_PROP(BezierProperty, AffineInvariance, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const Bezier<double, D> c(prop::control_points<D>(n));
    Affine<double, D> m;
    for (int i = 0; i < D; ++i) {
      for (int j = 0; j < D; ++j) m.linear[i][j] = *prop::coordinate(-2, 2);
      m.translation[i] = *prop::coordinate(-2, 2);
    }
    const auto tc = c.transform(m);
    const double t = *prop::parameter();
    RC_ASSERT(diff(tc(t), m(c(t))) <= 4.0 * (n + D) * eps * (2 * D + 2));
  });
}

/// Convex hull of plane points (Andrew's monotone chain), counter-clockwise.
std::vector<Point<double, 2>> hull(std::vector<Point<double, 2>> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Point<double, 2>> h(2 * p.size());
  std::size_t k = 0;
  auto turn = [](const auto& o, const auto& a, const auto& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lo = k + 1; i-- > 0;) {
    while (k >= lo && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// How far p lies outside the convex polygon h (<= 0 inside), by the edges' half planes.
double outside(const std::vector<Point<double, 2>>& h, const Point<double, 2>& p) {
  if (h.size() == 1) return std::hypot(p[0] - h[0][0], p[1] - h[0][1]);
  if (h.size() == 2) {
    // A segment: distance to it.
    const double ax = h[1][0] - h[0][0], ay = h[1][1] - h[0][1];
    const double s = std::clamp(((p[0] - h[0][0]) * ax + (p[1] - h[0][1]) * ay) / (ax * ax + ay * ay), 0.0, 1.0);
    return std::hypot(p[0] - h[0][0] - s * ax, p[1] - h[0][1] - s * ay);
  }
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < h.size(); ++i) {
    const auto& a = h[i];
    const auto& b = h[(i + 1) % h.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    // Signed distance to the right of edge a->b (outside for a counter-clockwise polygon).
    worst = std::max(worst, ((p[0] - a[0]) * ey - (p[1] - a[1]) * ex) / std::hypot(ex, ey));
  }
  return worst;
}

// The curve lies in the convex hull of its control points: in the control box in every
// dimension (within one evaluation's rounding, 2 n eps), and in 2D inside the hull
// polygon within that rounding plus the half-plane test's own (a few eps).
RC_GTEST_PROP(BezierProperty, ConvexHull, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const auto P = prop::control_points<D>(n);
    const Bezier<double, D> c(P);
    const auto box = c.control_bounds();
    const double tol = 2.0 * n * eps + 8 * eps;
    for (int i = 0; i <= 20; ++i) RC_ASSERT(box.contains(c(i / 20.0), tol));
    if constexpr (D == 2) {
      const auto h = hull(P);
      for (int i = 0; i <= 20; ++i) RC_ASSERT(outside(h, c(i / 20.0)) <= tol);
    }
  });
}

// split(t): left(s) = c(s t), right(s) = c(t + s (1 - t)). The halves' control points
// are n levels of de Casteljau (1.5 n eps), evaluating them adds 1.5 n eps, the reference
// evaluation 1.5 n eps, and the rounded parameter n eps: 8 n eps.
RC_GTEST_PROP(BezierProperty, SplitReproducesCurve, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const Bezier<double, D> c(prop::control_points<D>(n));
    const double t = *prop::parameter(), s = *prop::parameter();
    const auto h = c.split(t);
    RC_ASSERT(h.left.points().back() == h.right.points().front());
    RC_ASSERT(diff(h.left(s), c(s * t)) <= 8.0 * n * eps);
    RC_ASSERT(diff(h.right(s), c(t + s * (1 - t))) <= 8.0 * n * eps);
  });
}

// portion(a, b)(s) = c(a + s (b - a)), with a and b anywhere in [-0.5, 1.5]. Outside
// [0, 1] the blossom's lerps are no longer convex: each level can multiply the error by
// L = |1 - u| + |u| <= 2, so the tolerance is 8 n eps L^n, i.e. exponential in the degree
// (this is why extrapolation is documented as losing accuracy). Inside [0, 1], L = 1.
RC_GTEST_PROP(BezierProperty, PortionReproducesCurve, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const Bezier<double, D> c(prop::control_points<D>(n));
    const double a = *prop::coordinate(-0.5, 1.5), b = *prop::coordinate(-0.5, 1.5), s = *prop::parameter();
    const auto p = c.portion(a, b);
    const double u = a + s * (b - a);
    double L = 1;
    for (double x : {a, b, u}) L = std::max(L, std::abs(1 - x) + std::abs(x));
    RC_ASSERT(diff(p(s), c(u)) <= 8.0 * n * eps * std::pow(L, n));
    // Inside [0, 1], a portion's ends are exactly the curve at a and b (both computed
    // as the blossom b(a, ..., a) = de Casteljau at a, the same arithmetic).
    if (a >= 0 && a <= 1 && b >= 0 && b <= 1) RC_ASSERT(diff(p(0.0), c(a)) <= 4.0 * n * eps);
  });
}

// Degree elevation leaves the curve unchanged: its points are convex combinations (a
// few eps each), then two evaluations of degrees n and n + r: 4 (n + r) eps.
RC_GTEST_PROP(BezierProperty, ElevationLeavesCurveUnchanged, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree(), r = *rc::gen::inRange(1, 6);
    const Bezier<double, D> c(prop::control_points<D>(n));
    const auto e = c.elevate(r);
    RC_ASSERT(e.degree() == n + r);
    RC_ASSERT(e.points().front() == c.points().front());
    RC_ASSERT(e.points().back() == c.points().back());
    for (int i = 0; i <= 10; ++i) RC_ASSERT(diff(e(i / 10.0), c(i / 10.0)) <= 4.0 * (n + r) * eps);
  });
}

// Elevate then reduce returns the original control points. The least-squares system is a
// Gram matrix whose condition number grows like 4^m (documented: reliable to m ~ 25), so
// the error is bounded by ~ 4^m eps times the data size; degrees 1..12 keep it below 1e-8.
RC_GTEST_PROP(BezierProperty, ElevateThenReduceRoundTrip, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = *rc::gen::inRange(1, 13), r = *rc::gen::inRange(1, 5);
    const Bezier<double, D> c(prop::control_points<D>(n));
    const bool keep = *rc::gen::arbitrary<bool>();
    const auto red = reduce_degree(c.elevate(r), n, keep ? Endpoints::keep : Endpoints::free);
    const double tol = 16 * std::pow(4.0, n) * eps;
    for (int i = 0; i <= n; ++i) RC_ASSERT(diff(red.curve.points()[static_cast<std::size_t>(i)], c.points()[static_cast<std::size_t>(i)]) <= tol);
    RC_ASSERT(red.max_error <= tol);
    RC_ASSERT(red.max_error <= red.error_bound + 4.0 * (n + r) * eps);
  });
}

// Derivatives against central differences with step h = 1e-3 / n: truncation h^2 |c'''|/6
// with |c'''| <= 8 n^3 (three differences of coordinates in [-1, 1]); rounding
// 2 (1.5 n eps) / (2h) from the two evaluations.
RC_GTEST_PROP(BezierProperty, DerivativeMatchesFiniteDifference, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const Bezier<double, D> c(prop::control_points<D>(n));
    const double h = 1e-3 / n;
    const double t = *prop::coordinate(-0.25, 1.25);
    const auto fd = (c(t + h) - c(t - h)) / (2 * h);
    // Outside [0, 1] the values themselves can reach L^n (L = 1.5): scale by it.
    const double grow = std::pow(std::abs(1 - t) + std::abs(t), n);
    const double tol = (h * h * 8.0 * n * n * n / 6 + 3.0 * n * eps / h) * grow;
    RC_ASSERT(diff(fd, c.derivative_at(t)) <= tol);
  });
}

// The k-th derivative curve evaluated at t equals derivative_at(t, k): both are n!/(n-k)!
// times de Casteljau on the k-th differences (size <= 2^k), in a different order of the
// scaling: relative 4 n eps of n^k 2^k.
RC_GTEST_PROP(BezierProperty, DerivativeCurveMatchesDerivativeAt, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree(), k = *rc::gen::inRange(1, 4);
    const Bezier<double, D> c(prop::control_points<D>(n));
    const double t = *prop::parameter();
    const auto h = c.derivative(k);
    RC_ASSERT(h.degree() == std::max(n - k, 0));
    RC_ASSERT(diff(h(t).to_vector(), c.derivative_at(t, k)) <= 4.0 * n * eps * std::pow(2.0 * n, k));
  });
}

// reverse twice is the identity (exactly), and reverse(1 - t) = c(t): with 1 - t exact on
// the grid, the lerps (1-t) a + t b and t b + (1-t) a have the same two products, so
// the values agree to rounding of the sums' order (bitwise equal without FMA contraction).
RC_GTEST_PROP(BezierProperty, Reverse, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const Bezier<double, D> c(prop::control_points<D>(n));
    RC_ASSERT(c.reverse().reverse() == c);
    const double t = *prop::parameter();
    RC_ASSERT(diff(c.reverse()(1 - t), c(t)) <= 2.0 * n * eps);
  });
}

// Tight bounds: contain every dense sample (within evaluation rounding), lie inside the
// control box (within the rounding of the extreme point evaluation), and each face is
// touched by some sample: with N + 1 uniform samples an interior extremum is at most
// 1/(2N) from one, where the coordinate is within |c''| (1/2N)^2 / 2 <= 4 n^2 / (8 N^2)
// of the extreme value (|c''| <= 4 n^2 for coordinates in [-1, 1]).
RC_GTEST_PROP(BezierProperty, TightBounds, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = degree();
    const Bezier<double, D> c(prop::control_points<D>(n));
    const auto b = bounds(c), cb = c.control_bounds();
    const int N = 2000;
    const double round = 4.0 * n * eps;
    const double touch = 4.0 * n * n / (8.0 * N * N) + round;
    Box<double, D> seen = Box<double, D>::empty_box();
    for (int i = 0; i <= N; ++i) {
      const auto p = c(static_cast<double>(i) / N);
      RC_ASSERT(b.contains(p, round));
      seen.add(p);
    }
    for (int d = 0; d < D; ++d) {
      RC_ASSERT(b.lo[d] >= cb.lo[d] - round);
      RC_ASSERT(b.hi[d] <= cb.hi[d] + round);
      RC_ASSERT(seen.lo[d] - b.lo[d] <= touch);
      RC_ASSERT(b.hi[d] - seen.hi[d] <= touch);
    }
  });
}

}  // namespace
