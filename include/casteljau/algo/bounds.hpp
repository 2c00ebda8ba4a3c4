// Tight axis-aligned bounds of curves over their domain, from the roots of the derivative.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/path.hpp"

namespace casteljau {

/// The tight box of a Bézier curve over [0, 1]: the end points plus the curve at every
/// root in (0, 1) of each coordinate of the hodograph (Bernstein root finding, on a copy
/// scaled by a power of two so that the differences cannot overflow). Accurate to a few
/// eps of the coordinates at simple extrema; at a multiple root of the derivative the
/// coordinate is flat, so the location error does not matter to the value. Cost O(D n^2)
/// per subdivision step and per extremum. See control_bounds() for the cheap
/// conservative box. Throws NumericalError if a root solve does not converge.
template <class T, int D>
Box<T, D> bounds(const Bezier<T, D>& c) {
  Box<T, D> b = Box<T, D>::empty_box();
  b.add(c(T(0)));
  b.add(c(T(1)));
  const auto& P = c.points();
  const int n = c.degree();
  if (n < 2) return b;
  const int e = detail::scale_exponent<Point<T, D>>(P);
  std::vector<T> d(static_cast<std::size_t>(n));
  for (int k = 0; k < D; ++k) {
    for (int i = 0; i < n; ++i) d[i] = std::ldexp(P[i + 1][k], -e) - std::ldexp(P[i][k], -e);  // hodograph / n
    for (T r : bernstein_roots<T>(d)) {
      if (r > 0 && r < 1) b.add(c(r));
    }
  }
  return b;
}

/// The tight box of a rational Bézier curve over [0, 1]. Coordinate k has derivative
/// (A_k' W - A_k W') / W^2 with A_k = sum w_i P_ik B(i,n), W = sum w_i B(i,n); the roots
/// of the numerator (a Bernstein product of degree 2n - 1) are the candidates. Computed
/// with the weights divided by the largest and the points scaled by a power of two, so
/// that no product overflows for weights and coordinates of any size, and with binomial-
/// free Bernstein products (degree 1000 and more). Cost O(D n^2) for the products plus
/// the root finding on degree 2n - 1. Throws NumericalError if a root solve does not
/// converge.
template <class T, int D>
Box<T, D> bounds(const RationalBezier<T, D>& c) {
  Box<T, D> b = Box<T, D>::empty_box();
  b.add(c(T(0)));
  b.add(c(T(1)));
  const int n = c.degree();
  if (n < 1) return b;
  const auto& P = c.points();
  const int e = detail::scale_exponent<Point<T, D>>(P);
  // Scaling all weights by one constant leaves the curve unchanged; dividing by the
  // largest keeps the products of weights below from overflowing (weights up to 1e308).
  const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
  std::vector<T> w(c.weights());
  for (T& x : w) x /= wmax;
  std::vector<T> dW(static_cast<std::size_t>(n)), A(w.size()), dA(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) dW[i] = w[i + 1] - w[i];
  for (int k = 0; k < D; ++k) {
    for (int i = 0; i <= n; ++i) A[i] = w[i] * std::ldexp(P[i][k], -e);
    for (int i = 0; i < n; ++i) dA[i] = A[i + 1] - A[i];
    const auto p1 = bernstein_product<T>(dA, w), p2 = bernstein_product<T>(A, dW);
    std::vector<T> num(p1.size());
    for (std::size_t i = 0; i < num.size(); ++i) num[i] = p1[i] - p2[i];
    for (T r : bernstein_roots<T>(num)) {
      if (r > 0 && r < 1) b.add(c(r));
    }
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
    const auto p = pieces(c);
    for (const auto& s : p.segments()) b.add(std::visit([](const auto& piece) { return bounds(piece); }, s));
    return b;
  }
}

}  // namespace casteljau
