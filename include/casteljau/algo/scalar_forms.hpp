// The scalar Bernstein polynomials of a Bézier piece that the queries build on: its
// coordinates relative to an origin (homogeneous numerators and the weight function for
// a rational piece), scaled by one power of two so that every product stays in range,
// and the numerators of the coordinates' derivatives.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/basis/bernstein_poly.hpp"
#include "casteljau/basis/extrapolate.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau::detail {

/// A piece as scalar Bernstein forms on [0, 1]: coordinate k of the piece minus the
/// origin is x[k] / w, times 2^e. For a polynomial piece w is the constant 1 (degree 0)
/// and `rational` is false; for a rational piece x[k][i] = w_i (P_ik - origin_k) 2^-e
/// with the weights divided by the largest (which leaves the curve unchanged). The
/// differences P_ik - origin_k are taken on halved values (no overflow) and the result
/// renormalised so that the largest |x| lies in [0.5, 1): products of these forms then
/// neither overflow nor underflow for coordinates of any size.
template <class T, int D>
struct ScalarForms {
  std::vector<std::vector<T>> x;  // D forms of degree n
  std::vector<T> w;               // weight function (degree n), or {1}
  bool rational = false;
  int e = 0;                      // the scale: coordinates are x / w times 2^e
  int degree = 0;
};

template <class T, int D, class Piece>
ScalarForms<T, D> scalar_forms(const Piece& c, const Point<T, D>& origin) {
  ScalarForms<T, D> f;
  const auto& P = c.points();
  f.degree = static_cast<int>(P.size()) - 1;
  f.x.assign(D, std::vector<T>(P.size()));
  T m = 0;
  for (const auto& p : P)
    for (int k = 0; k < D; ++k) m = std::max({m, std::abs(p[k]), std::abs(origin[k])});
  int e0 = 0;
  if (m > 0) (void)std::frexp(m, &e0);
  T big = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int k = 0; k < D; ++k) {
      f.x[k][i] = std::ldexp(P[i][k], -e0) - std::ldexp(origin[k], -e0);  // |x| <= 2
      big = std::max(big, std::abs(f.x[k][i]));
    }
  int e1 = 0;
  if (big > 0) (void)std::frexp(big, &e1);
  for (auto& xk : f.x)
    for (T& v : xk) v = std::ldexp(v, -e1);
  f.e = e0 + e1;
  if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) {
    f.rational = true;
    const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
    f.w = c.weights();
    for (T& v : f.w) v /= wmax;
    for (auto& xk : f.x)
      for (std::size_t i = 0; i < xk.size(); ++i) xk[i] *= f.w[i];
  } else {
    f.w = {T(1)};
  }
  return f;
}

/// The numerator of the derivative of coordinate k: x_k' for a polynomial piece (degree
/// n - 1), x_k' w - x_k w' for a rational one (degree 2n - 1; the derivative is this over
/// w^2). With `absolute`, the same expression on absolute values, which bounds the
/// rounding error of each coefficient (see bernstein_abs).
template <class T>
std::vector<T> abs_derivative_bound(const std::vector<T>& c) {
  const std::size_t n = c.size() - 1;
  if (n == 0) return {T(0)};
  std::vector<T> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<T>(n) * (std::abs(c[i]) + std::abs(c[i + 1]));
  return d;
}

template <class T, int D>
std::vector<T> derivative_numerator(const ScalarForms<T, D>& f, int k, bool absolute = false) {
  if (absolute) {
    // Bound of the rounding error of each coefficient: the same sums and products of
    // absolute values, with |a - b| bounded by |a| + |b|.
    const std::vector<T> dxa = abs_derivative_bound<T>(f.x[k]);
    if (!f.rational) return dxa;
    return bernstein_sum<T>(bernstein_product<T>(dxa, f.w),
                            bernstein_product<T>(bernstein_abs<T>(f.x[k]), abs_derivative_bound<T>(f.w)));
  }
  const std::vector<T> dx = bernstein_derivative_coefficients<T>(f.x[k]);
  if (!f.rational) return dx;
  return bernstein_difference<T>(bernstein_product<T>(dx, f.w),
                                 bernstein_product<T>(f.x[k], bernstein_derivative_coefficients<T>(f.w)));
}

/// Per-coefficient test that a form vanishes identically: |c_i| <= slack eps a_i for the
/// absolute-value form a of the same expression (its rounding error bound).
template <class T>
bool vanishes(const std::vector<T>& c, const std::vector<T>& a, T slack) {
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!(std::abs(c[i]) <= slack * std::numeric_limits<T>::epsilon() * a[i])) return false;
  return true;
}

}  // namespace casteljau::detail
