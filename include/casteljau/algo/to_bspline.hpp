// Any curve as one B-spline (a NURBS when a piece is rational) with the same parameter:
// its exact Bézier pieces elevated to one degree, joined, and every joint's knot removed
// as often as the curve's continuity there allows.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/nurbs.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// Relative tolerance of to_bspline's continuity decisions: two pieces meet (C^0) when
/// their end points are within this fraction of the curve's size (the largest distance of
/// a control point from the first), and a joint's knot is removed once more while the
/// removal moves the curve by at most this fraction of its size (BSpline::remove_knot's
/// guaranteed bound). Pieces of exact data agree to a few eps; the derivative that
/// breaks continuity differs by far more than 1e-9 of the size in any curve a user means.
template <class T>
inline constexpr T to_bspline_tolerance = T(1e-9);

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

/// Removes each knot of `joints` (each p times in U0) as often as it can while the form
/// moves by at most `tolerance` (removal_deviation: a guaranteed bound), left to right on
/// a SlidingWindow, so that the cost is O(N p^2) for N points, not O(N) per removal. A
/// removal that gives a point `valid` refuses (a weight <= 0) is not made.
template <class T, class V, class Valid>
KnotForm<T, V> remove_joint_knots(const std::vector<T>& U0, const std::vector<V>& P0, int p, const std::vector<T>& joints,
                                  T tolerance, Valid valid) {
  SlidingWindow<T, V> win(U0, P0, p);
  for (const T x : joints) {
    win.reach(x);
    const KnotForm<T, V> f = win.W;  // the window: O(p) points
    for (int j = 1; j <= p; ++j) {
      KnotForm<T, V> g = remove_knot_once(win.W, x);
      bool finite = true;
      for (const auto& q : g.P) finite = finite && all_finite_point(q) && valid(q);
      if (!finite || !(removal_deviation(f, g, x, j) <= tolerance)) break;
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
///    (end points within to_bspline_tolerance of the curve's size: the shared point is the
///    left piece's end); where they do not (a path with a gap: the curve is not even C^0,
///    k = -1) the break is repeated p + 1 times and both end points are kept, so the
///    B-spline jumps there exactly as the curve does (the right limit answers at the break);
/// 3. each joint's knot is removed as often as BSpline::remove_knot (Nurbs::remove_knot)
///    can within to_bspline_tolerance times the size ([PT97] A5.8, remove_knot_once, with
///    the guaranteed bound of removal_deviation; for a rational curve on the homogeneous
///    points about the control box's centre, the bound carried to the Cartesian curve by
///    [PT97, eq. 5.30] as Nurbs::remove_knot does), left to right on a sliding window:
///    k removals where the (homogeneous) curve is C^k there, so the knot keeps
///    multiplicity p - k, and disappears where the two pieces are one polynomial.
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
  // The curve's size: the largest distance of a control point from the first.
  T size = 0;
  std::optional<Point<T, D>> first;
  for (const auto& s : pc.segments()) {
    std::visit(
        [&](const auto& x) {
          for (const auto& q : x.points()) {
            if (!first) first = q;
            size = std::max(size, norm(q - *first));
          }
        },
        s);
  }
  // A curve that is one point: every removal is exact, any positive tolerance will do.
  const T tolerance = size > 0 ? to_bspline_tolerance<T> * size : std::numeric_limits<T>::min();
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
    const bool meet = p > 0 && norm(detail::cartesian<T, D>(P.back()) - detail::cartesian<T, D>(Q.front())) <= tolerance;
    if (meet) {
      P.insert(P.end(), Q.begin() + 1, Q.end());
      U.insert(U.end(), static_cast<std::size_t>(p), breaks[i]);
      joints.push_back(i);
    } else if (p == 0) {
      // degree 0: a knot per break (multiplicity p + 1 = 1); equal neighbours are one piece.
      if (norm(detail::cartesian<T, D>(P.back()) - detail::cartesian<T, D>(Q.front())) > tolerance) {
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
    KnotForm<T, Point<T, D>> f = detail::remove_joint_knots<T, Point<T, D>>(U, Pc, p, X, tolerance, [](const auto&) { return true; });
    return BSpline<T, D>(p, std::move(f.U), std::move(f.P));
  }
  // Rational: the homogeneous points taken about the centre c of the control box and the
  // weights scaled to a largest of 1 (the chain of scalings in step 1 may have drifted);
  // neither changes the curve. A homogeneous deviation d moves the Cartesian curve by at
  // most d sqrt(1 + R^2) / w_min ([PT97, eq. 5.30], R the largest |P_i - c|), so the
  // removals are made within tolerance w_min / sqrt(1 + R^2).
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
  T R = 0, wmin = 1;
  std::vector<H> Hc(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    const T w = P[i][D] / wmax;
    const Vector<T, D> r = detail::cartesian<T, D>(P[i]) - centre;
    R = std::max(R, norm(r));
    wmin = std::min(wmin, w);
    for (int d = 0; d < D; ++d) Hc[i][d] = w * r[d];
    Hc[i][D] = w;
  }
  KnotForm<T, H> f = detail::remove_joint_knots<T, H>(U, Hc, p, X, tolerance * wmin / std::sqrt(1 + R * R),
                                                        [](const H& q) { return q[D] > 0; });
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
