// Tight axis-aligned bounds of curves over their domain, from the roots of the derivative.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/path.hpp"

namespace casteljau {

namespace detail {

/// Adds to coordinate k of box b the extreme values among the candidate parameters rs,
/// given their O(n) estimates (relative error about n eps of the scale `size`; see
/// bernstein_value_fast): only the candidates within 16 (n + 1) eps size of the best
/// estimate, which are the only ones that can be the extremum, are evaluated by
/// `exact` (de Casteljau, O(n^2)). So bounds costs O(n^2) per coordinate for the
/// evaluations however many extrema there are, instead of O(n^2) per extremum.
template <class T, int D, class Exact>
void add_extremes(Box<T, D>& b, int k, const std::vector<T>& rs, const std::vector<T>& est, int n, T size, Exact&& exact) {
  if (rs.empty()) return;
  const T slack = 16 * static_cast<T>(n + 1) * std::numeric_limits<T>::epsilon() * size;
  const T top = *std::max_element(est.begin(), est.end()), bottom = *std::min_element(est.begin(), est.end());
  for (std::size_t i = 0; i < rs.size(); ++i) {
    // Comparisons written so that a NaN estimate selects the candidate (it is then
    // evaluated exactly) rather than dropping it.
    if (!(est[i] < top - slack) || !(est[i] > bottom + slack)) {
      const T v = exact(rs[i]);
      b.lo[k] = std::min(b.lo[k], v);
      b.hi[k] = std::max(b.hi[k], v);
    }
  }
}

}  // namespace detail

/// The tight box of a Bézier curve over [0, 1]: the end points plus the curve at every
/// root in (0, 1) of each coordinate of the hodograph (Bernstein root finding, on a copy
/// scaled by a power of two so that the differences cannot overflow). Accurate to a few
/// eps of the coordinates at simple extrema; at a multiple root of the derivative the
/// coordinate is flat, so the location error does not matter to the value.
/// Cost per coordinate: the root isolation (O(n^2) per subdivision step, O(n) per solve
/// step past degree 32) plus O(n) per extremum to estimate its value and O(n^2) for the
/// one or two that can be the min or max (detail::add_extremes). Measured on random
/// curves: 0.5 ms at degree 125, 0.07 s at degree 1000 (docs/accuracy.md). See
/// control_bounds() for the cheap conservative box. Throws NumericalError if a root
/// solve does not converge.
template <class T, int D>
Box<T, D> bounds(const Bezier<T, D>& c) {
  return bounds(c, T(0), T(1));
}

/// The tight box of a Bézier curve over [from, to] within [0, 1]: c(from), c(to) and the
/// curve at the roots of the hodograph's coordinates inside (from, to) (the same root
/// finding as over [0, 1], filtered; accuracy and cost as bounds(c)). from == to gives
/// the one point. Throws InvalidArgument("from"/"to", ...) unless 0 <= from <= to <= 1.
template <class T, int D>
Box<T, D> bounds(const Bezier<T, D>& c, std::type_identity_t<T> from, std::type_identity_t<T> to) {
  detail::check_range<T>({T(0), T(1)}, from, to);
  Box<T, D> b = Box<T, D>::empty_box();
  b.add(c(from));
  b.add(c(to));
  if (from == to) return b;
  const auto& P = c.points();
  const int n = c.degree();
  if (n < 2) return b;
  const int e = detail::scale_exponent<Point<T, D>>(P);
  std::vector<T> d(static_cast<std::size_t>(n)), x(P.size()), rs, est;
  for (int k = 0; k < D; ++k) {
    T size = 0;
    for (int i = 0; i <= n; ++i) {
      x[i] = P[i][k];
      size = std::max(size, std::abs(x[i]));
    }
    for (int i = 0; i < n; ++i) d[i] = std::ldexp(P[i + 1][k], -e) - std::ldexp(P[i][k], -e);  // hodograph / n
    rs.clear();
    est.clear();
    for (T r : bernstein_roots<T>(d)) {
      if (r > from && r < to) {
        rs.push_back(r);
        est.push_back(detail::bernstein_value_fast<T>(x, r));
      }
    }
    detail::add_extremes(b, k, rs, est, n, size, [&](T r) { return de_casteljau<T, T>(std::span<const T>(x), r); });
  }
  return b;
}

/// The tight box of a rational Bézier curve over [0, 1]. Coordinate k has derivative
/// (A_k' W - A_k W') / W^2 with A_k = sum w_i P_ik B(i,n), W = sum w_i B(i,n); the roots
/// of the numerator (a Bernstein product of degree 2n - 1) are the candidates. Computed
/// with the weights divided by the largest and the points scaled by a power of two, so
/// that no product overflows for weights and coordinates of any size, and with binomial-
/// free Bernstein products (degree 1000 and more). Candidates are estimated in O(n) as
/// A_k / W and only the possible extremes evaluated by the rational de Casteljau
/// algorithm (see detail::add_extremes). Cost O(D n^2) for the products plus the root
/// finding on degree 2n - 1; measured on random curves: 3 ms at degree 125, 0.4 s at
/// degree 1000. Throws NumericalError if a root solve does not converge.
template <class T, int D>
Box<T, D> bounds(const RationalBezier<T, D>& c) {
  return bounds(c, T(0), T(1));
}

/// The tight box of a rational Bézier curve over [from, to] within [0, 1]: the ends and
/// the candidates of bounds(c) inside (from, to). Accuracy and cost as bounds(c).
/// Throws InvalidArgument("from"/"to", ...) unless 0 <= from <= to <= 1.
template <class T, int D>
Box<T, D> bounds(const RationalBezier<T, D>& c, std::type_identity_t<T> from, std::type_identity_t<T> to) {
  detail::check_range<T>({T(0), T(1)}, from, to);
  Box<T, D> b = Box<T, D>::empty_box();
  b.add(c(from));
  b.add(c(to));
  const int n = c.degree();
  if (n < 1 || from == to) return b;
  const auto& P = c.points();
  const int e = detail::scale_exponent<Point<T, D>>(P);
  // Scaling all weights by one constant leaves the curve unchanged; dividing by the
  // largest keeps the products of weights below from overflowing (weights up to 1e308).
  const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
  std::vector<T> w(c.weights());
  for (T& x : w) x /= wmax;
  std::vector<T> dW(static_cast<std::size_t>(n)), A(w.size()), dA(static_cast<std::size_t>(n)), rs, est;
  for (int i = 0; i < n; ++i) dW[i] = w[i + 1] - w[i];
  for (int k = 0; k < D; ++k) {
    T size = 0;
    for (int i = 0; i <= n; ++i) {
      A[i] = w[i] * std::ldexp(P[i][k], -e);
      size = std::max(size, std::abs(P[i][k]));
    }
    for (int i = 0; i < n; ++i) dA[i] = A[i + 1] - A[i];
    const auto p1 = bernstein_product<T>(dA, w), p2 = bernstein_product<T>(A, dW);
    std::vector<T> num(p1.size());
    for (std::size_t i = 0; i < num.size(); ++i) num[i] = p1[i] - p2[i];
    rs.clear();
    est.clear();
    for (T r : bernstein_roots<T>(num)) {
      if (r > from && r < to) {
        rs.push_back(r);
        est.push_back(std::ldexp(detail::bernstein_value_fast<T>(A, r) / detail::bernstein_value_fast<T>(w, r), e));
      }
    }
    // The rational estimate's error is relative to max |P| as well (A / W is a convex
    // combination of the P_ik), up to the weight ratio's effect; 4x the polynomial slack.
    detail::add_extremes(b, k, rs, est, 4 * n, size, [&](T r) { return c(r)[k]; });
  }
  return b;
}

/// The tight box of any other curve over its domain: its own closed form when it has one
/// (a member bounds(), e.g. a polyline's points), else the union of the tight boxes of
/// its Bézier pieces. Accuracy and cost as for the pieces.
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
Box<typename C::Scalar, C::dimension> bounds(const C& c) {
  if constexpr (requires { { c.bounds() } -> std::same_as<Box<typename C::Scalar, C::dimension>>; }) {
    return c.bounds();
  } else {
    Box<typename C::Scalar, C::dimension> b = Box<typename C::Scalar, C::dimension>::empty_box();
    const auto& p = pieces(c);  // a reference to c itself when c is Pieces
    p.for_each_piece([&](std::size_t, const auto& piece, const auto&) { b.add(bounds(piece)); });
    return b;
  }
}

/// The tight box of any curve over the parameter range [from, to] of its domain: the
/// union over the Bézier pieces meeting [from, to] of their tight boxes over the part
/// inside it (Pieces::for_each_piece clips the range, so the range's ends are evaluated
/// on the piece that holds them). Ends at a break give the break's point
/// from both sides (the same point for a continuous curve; both for a path with a gap).
/// from == to gives the curve's point there (the right piece at a break). Accuracy and
/// cost as for the pieces, only the pieces meeting the range examined. Throws
/// InvalidArgument("from"/"to", ...) for a range outside the domain or reversed.
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
Box<typename C::Scalar, C::dimension> bounds(const C& c, typename C::Scalar from, typename C::Scalar to) {
  using T = typename C::Scalar;
  const auto& p = pieces(c);  // a reference to c itself when c is Pieces
  detail::check_range<T>(p.domain(), from, to);
  Box<T, C::dimension> b = Box<T, C::dimension>::empty_box();
  // from == to: the one piece holding it, over [t, t]: the curve's point.
  p.for_each_piece({from, to}, [&](std::size_t, const auto& piece, const Interval<T>& own) { b.add(bounds(piece, own.lo, own.hi)); });
  return b;
}

}  // namespace casteljau
