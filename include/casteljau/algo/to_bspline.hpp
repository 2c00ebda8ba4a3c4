// Any curve as one B-spline (a NURBS when a piece is rational) with the same parameter:
// its exact Bézier pieces elevated to one degree, joined, and every joint's knot removed
// as often as the curve's continuity there allows.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/nurbs.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// to_bspline's rounding factor K: two pieces meet when their end points differ by at most
/// K eps (|a| + |b|) (largest coordinates), and a joint's knot is removed once more only
/// when the removal moves the curve by at most K eps times the rounding that the points'
/// own magnitudes carry through the removal and back (detail::removal_rounding_bound): the
/// pieces agree there to the rounding of their computation, and the result reproduces
/// them to that rounding. Measured (session 17) on about 9000 joints of cubic_spline
/// (natural, not-a-knot), hermite (given tangents and the tangent rules), catmull_rom
/// (alpha 0, 0.5, 1, closed, reflect) and random B-splines of degree 1..5 and their
/// to_bezier paths: exactly C^k joints reached 10.8 times the bound (99% below 1.4), a
/// derivative that jumps at least 8e7 times; K = 64 leaves a factor 6 of room. Knot
/// intervals of very different lengths (ratios 1e3..1e6) amplify a spline's own rounding
/// beyond the bound: there about 5% of a natural spline's C^2 joints keep a double knot
/// (still traced exactly).
template <class T>
inline constexpr T to_bspline_rounding = T(64);

/// The result of to_bspline: a BSpline when every piece is polynomial, else a Nurbs.
template <class T, int D>
using BSplineForm = std::variant<BSpline<T, D>, Nurbs<T, D>>;

namespace detail {

/// The homogeneous points (w P, w) of a piece elevated to degree p, weights scaled by s.
template <class T, int D, class Piece>
std::vector<Point<T, D + 1>> elevated_homogeneous(const Piece& c, int p, T s) {
  const auto e = c.elevate(p - c.degree());
  std::vector<Point<T, D + 1>> H(e.points().size());
  for (std::size_t i = 0; i < H.size(); ++i) {
    T w = s;
    if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) w = s * e.weights()[i];
    for (int d = 0; d < D; ++d) H[i][d] = w * e.points()[i][d];
    H[i][D] = w;
  }
  return H;
}

template <class T, int D>
Point<T, D> cartesian(const Point<T, D + 1>& h) {
  Point<T, D> q;
  for (int d = 0; d < D; ++d) q[d] = h[d] / h[D];
  return q;
}

/// The largest |coordinate| of a point (the magnitude its rounding is relative to).
template <class V>
auto max_abs(const V& q) {
  std::remove_cvref_t<decltype(q[0])> m = 0;
  for (int d = 0; d < V::dimension; ++d) m = std::max(m, std::abs(q[d]));
  return m;
}

/// remove_knot_once carried out on error bounds instead of points: e holds, for each point
/// of a form, a bound on its error; the result bounds the errors of the points that
/// remove_knot_once computes from them (Q_i = (1 - 1/a) Q_(i-1) + P_i / a and its mirror:
/// |1 - 1/a| e + e / |a|), the same knots, recurrences and sides. Rounding inside the
/// recurrence is of the same order and is taken into to_bspline_rounding's factor.
template <class T>
KnotForm<T, T> removal_rounding_once(const KnotForm<T, T>& e, T u) {
  const std::span<const T> U(e.U);
  const int p = e.p;
  const int r = static_cast<int>(last_knot_at_or_below(U, u));
  const int s = static_cast<int>(knot_multiplicity<T>(U, u));
  const int first = r - p, last = r - s;
  KnotForm<T, T> g{p, {}, std::vector<T>(e.P.size() - 1)};
  for (int j = 0; j < static_cast<int>(U.size()); ++j)
    if (j != r) g.U.push_back(U[sz(j)]);
  auto& Q = g.P;
  for (int i = 0; i < first; ++i) Q[sz(i)] = e.P[sz(i)];
  for (int i = last + 1; i < static_cast<int>(e.P.size()); ++i) Q[sz(i - 1)] = e.P[sz(i)];
  if (s == p + 1) {
    Q[sz(first - 1)] = std::max(e.P[sz(first - 1)], e.P[sz(first)]);
    return g;
  }
  const auto alpha = [&](int i) { return (u - U[sz(i)]) / (U[sz(i + p + 1)] - U[sz(i)]); };
  const int left_count = (last - first) / 2;
  for (int i = first; i < first + left_count; ++i) {
    const T a = alpha(i);
    Q[sz(i)] = std::abs(1 - 1 / a) * Q[sz(i - 1)] + e.P[sz(i)] / std::abs(a);
  }
  for (int i = last; i > first + left_count; --i) {
    const T a = alpha(i);
    Q[sz(i - 1)] = std::abs(1 - 1 / (1 - a)) * Q[sz(i)] + e.P[sz(i)] / std::abs(1 - a);
  }
  return g;
}

/// A bound on the rounding in removal_deviation(f, g, u, times) when f's points are exact
/// to within e (their magnitudes: relative rounding): the errors carried through the
/// removals (removal_rounding_once) and back through the insertions (convex combinations:
/// insert_knot_once on the bounds), plus f's own; the largest over the points.
template <class T>
T removal_rounding_bound(const KnotForm<T, T>& e, T u, int times) {
  KnotForm<T, T> g = e;
  for (int j = 0; j < times; ++j) g = removal_rounding_once(g, u);
  for (int j = 0; j < times; ++j) g = insert_knot_once(g, u);
  T b = 0;
  for (std::size_t i = 0; i < e.P.size(); ++i) b = std::max(b, e.P[i] + g.P[i]);
  return b;
}

/// Removes each knot of `joints` (each p times in U0) as often as the pieces agree to
/// rounding: a removal is made when it moves the form (removal_deviation: a guaranteed
/// bound) by at most to_bspline_rounding eps times removal_rounding_bound of the window's
/// magnitudes (`magnitude` of each point), left to right on a SlidingWindow, so that the
/// cost is O(N p^2) for N points, not O(N) per removal. A removal that gives a point
/// `valid` refuses (a weight <= 0) is not made.
template <class T, class V, class Magnitude, class Valid>
KnotForm<T, V> remove_joint_knots(const std::vector<T>& U0, const std::vector<V>& P0, int p, const std::vector<T>& joints,
                                  Magnitude magnitude, Valid valid) {
  SlidingWindow<T, V> win(U0, P0, p);
  for (const T x : joints) {
    win.reach(x);
    const KnotForm<T, V> f = win.W;  // the window: O(p) points
    // The magnitudes relative to the largest (m), so that the bound cannot overflow near
    // the largest doubles; the deviation is divided by m in turn.
    KnotForm<T, T> e{p, f.U, std::vector<T>(f.P.size())};
    T m = 0;
    for (std::size_t i = 0; i < f.P.size(); ++i) m = std::max(m, e.P[i] = magnitude(f.P[i]));
    if (m > 0)
      for (T& v : e.P) v /= m;
    for (int j = 1; j <= p; ++j) {
      KnotForm<T, V> g = remove_knot_once(win.W, x);
      bool finite = true;
      for (const auto& q : g.P) finite = finite && all_finite_point(q) && valid(q);
      const T dev = removal_deviation(f, g, x, j);
      const bool within = m > 0 ? dev / m <= to_bspline_rounding<T> * std::numeric_limits<T>::epsilon() * removal_rounding_bound(e, x, j)
                                : dev == 0;
      if (!finite || !within) break;
      win.W = std::move(g);
    }
    win.settle(x);
  }
  return win.finish();
}

}  // namespace detail

/// The curve as one B-spline of degree p (the highest degree of its Bézier pieces) on the
/// same parameter, a Nurbs when a piece is rational:
/// 1. every piece is elevated to degree p (Forrest's equations, exact up to rounding) and,
///    for a rational curve, taken in homogeneous form (w P, w) with its weights scaled so
///    that its first weight equals the last weight of the piece before (a rational Bézier
///    is unchanged by scaling its weights; this makes the homogeneous curve continuous
///    wherever the Cartesian one is);
/// 2. the pieces are joined with each interior break repeated p times where they meet
///    (end points equal to rounding, to_bspline_rounding: the shared point is the left
///    piece's end); where they do not (a path with a gap: the curve is not even C^0,
///    k = -1) the break is repeated p + 1 times and both end points are kept, so the
///    B-spline jumps there exactly as the curve does (the right limit answers at the break);
/// 3. each joint's knot is removed as often as the removal ([PT97] A5.8, remove_knot_once)
///    moves the curve by no more than rounding (the guaranteed bound of removal_deviation
///    against to_bspline_rounding's bound; for a rational curve on the homogeneous points
///    about the control box's centre), left to right on a sliding window:
///    k removals where the (homogeneous) curve is C^k there, so the knot keeps
///    multiplicity p - k, and disappears where the two pieces are one polynomial. A
///    defect above rounding (a control point 1e-12 off its C^2 position) keeps its copy of
///    the knot: the result traces the curve exactly, never approximately.
/// A curve of degree 0 (constant pieces) is a degree-0 B-spline whose equal neighbours
/// are merged. Cost: O(k p^2) for k pieces (elevation and p removals of O(p) per joint).
template <class C>
  requires PiecewiseBezierCurve<C>
BSplineForm<typename C::Scalar, C::dimension> to_bspline(const C& c) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  using H = Point<T, D + 1>;
  const auto& pc = pieces(c);
  int p = 0;
  bool rational = false;
  for (const auto& s : pc.segments()) {
    std::visit(
        [&]<class Piece>(const Piece& x) {
          p = std::max(p, x.degree());
          rational = rational || std::is_same_v<Piece, RationalBezier<T, D>>;
        },
        s);
  }
  // Two end points meet when they agree to rounding: within K eps of their magnitudes.
  const auto meet_at = [](const Point<T, D>& a, const Point<T, D>& b) {
    // Halved, so that neither side overflows near the largest doubles.
    return detail::max_abs(b - a) / 2 <=
           to_bspline_rounding<T> * std::numeric_limits<T>::epsilon() * (detail::max_abs(a) / 2 + detail::max_abs(b) / 2);
  };
  const std::vector<T>& breaks = pc.breaks();
  std::vector<T> U(static_cast<std::size_t>(p) + 1, breaks.front());
  std::vector<H> P;
  std::vector<std::size_t> joints;  // interior breaks where the pieces meet
  for (std::size_t i = 0; i < pc.size(); ++i) {
    const T scale = P.empty() ? T(1) : P.back()[D];
    std::vector<H> Q = std::visit(
        [&]<class Piece>(const Piece& x) {
          T s = scale;
          if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) s = scale / x.weights().front();
          return detail::elevated_homogeneous<T, D>(x, p, s);
        },
        pc.segments()[i]);
    if (i == 0) {
      P.insert(P.end(), Q.begin(), Q.end());
      continue;
    }
    const bool meet = p > 0 && meet_at(detail::cartesian<T, D>(P.back()), detail::cartesian<T, D>(Q.front()));
    if (meet) {
      P.insert(P.end(), Q.begin() + 1, Q.end());
      U.insert(U.end(), static_cast<std::size_t>(p), breaks[i]);
      joints.push_back(i);
    } else if (p == 0) {
      // degree 0: a knot per break (multiplicity p + 1 = 1); equal neighbours are one piece.
      if (!meet_at(detail::cartesian<T, D>(P.back()), detail::cartesian<T, D>(Q.front()))) {
        P.push_back(Q.front());
        U.push_back(breaks[i]);
      }
    } else {
      // A jump: the break p + 1 times, both pieces whole (no knot of it is removed).
      P.insert(P.end(), Q.begin(), Q.end());
      U.insert(U.end(), static_cast<std::size_t>(p) + 1, breaks[i]);
    }
  }
  U.insert(U.end(), static_cast<std::size_t>(p) + 1, breaks.back());
  std::vector<T> X;
  for (std::size_t i : joints) X.push_back(breaks[i]);
  if (!rational) {
    std::vector<Point<T, D>> Pc(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) Pc[i] = detail::cartesian<T, D>(P[i]);
    KnotForm<T, Point<T, D>> f = detail::remove_joint_knots<T, Point<T, D>>(
        U, Pc, p, X, [](const Point<T, D>& q) { return detail::max_abs(q); }, [](const auto&) { return true; });
    return BSpline<T, D>(p, std::move(f.U), std::move(f.P));
  }
  // Rational: the homogeneous points taken about the centre c of the control box and the
  // weights scaled to a largest of 1 (the chain of scalings in step 1 may have drifted);
  // neither changes the curve. The removals are decided on these points (a homogeneous
  // curve C^k where the Cartesian one is, by the scaling of step 1).
  T wmax = 0;
  for (const auto& h : P) wmax = std::max(wmax, h[D]);
  Point<T, D> lo = detail::cartesian<T, D>(P.front()), hi = lo;
  for (const auto& h : P) {
    const Point<T, D> q = detail::cartesian<T, D>(h);
    for (int d = 0; d < D; ++d) {
      lo[d] = std::min(lo[d], q[d]);
      hi[d] = std::max(hi[d], q[d]);
    }
  }
  const Point<T, D> centre = lerp(lo, hi, T(0.5));
  std::vector<H> Hc(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    const T w = P[i][D] / wmax;
    const Vector<T, D> r = detail::cartesian<T, D>(P[i]) - centre;
    for (int d = 0; d < D; ++d) Hc[i][d] = w * r[d];
    Hc[i][D] = w;
  }
  // A homogeneous point w (P - c) carries the rounding of w P: magnitude w (|P - c| + |c|).
  const T centre_size = detail::max_abs(centre);
  KnotForm<T, H> f = detail::remove_joint_knots<T, H>(
      U, Hc, p, X, [&](const H& q) { return detail::max_abs(q) + q[D] * centre_size; }, [](const H& q) { return q[D] > 0; });
  std::vector<Point<T, D>> Pc(f.P.size());
  std::vector<T> w(f.P.size());
  for (std::size_t i = 0; i < f.P.size(); ++i) {
    const T wi = f.P[i][D];  // > 0: removals that would not keep it so were not made
    for (int d = 0; d < D; ++d) Pc[i][d] = f.P[i][d] / wi + centre[d];
    w[i] = wi;
  }
  return Nurbs<T, D>(p, std::move(f.U), std::move(Pc), std::move(w));
}

}  // namespace casteljau
