// Evaluation of Bézier forms anywhere on the real line: de Casteljau on [0, 1], the
// Taylor (power) form about the nearer end point outside it, with power-of-two scaling so
// that no intermediate overflows when the result does not.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "casteljau/basis/de_casteljau.hpp"
#include "casteljau/core/unit_frame.hpp"

namespace casteljau {

namespace detail {

/// The exponent e with max |coordinate| of c in [2^(e-1), 2^e) (0 when all are 0), so
/// that scaling by 2^-e brings the largest coordinate into [0.5, 1). Scaling by a power
/// of two is exact while the results stay normal numbers. Cost O(n D).
template <class P>
int scale_exponent(std::span<const P> c) {
  using T = typename P::Scalar;
  T m = 0;
  for (const auto& p : c)
    for (int d = 0; d < P::dimension; ++d) m = std::max(m, std::abs(p[d]));
  return abs_exponent(m);  // the origin-0 unit frame (core/unit_frame.hpp)
}

template <class P>
P scaled(const P& p, int e) {
  P q;
  for (int d = 0; d < P::dimension; ++d) q[d] = times_pow2(p[d], e);
  return q;
}

template <class P>
bool all_finite(const P& p) {
  for (int d = 0; d < P::dimension; ++d)
    if (!std::isfinite(p[d])) return false;
  return true;
}

/// Replaces the Bézier coefficients c[0..n] (a span of points) by the Taylor
/// coefficients a_0..a_n of the same polynomial about t = 0 (at_one false: p(s) = sum a_j
/// s^j, a_j = C(n,j) Delta^j c_0) or about t = 1 (at_one true: p(1 + s) = sum a_j s^j,
/// a_j = C(n,j) Delta^j c_(n-j)) [Farin02, 5.3]: the derivatives at the end point over j!.
/// Cost n(n+1)/2 subtractions. Returns false when a coefficient overflows (possible only
/// past degree ~600 for unit-sized data, where C(n,j) 2^j exceeds the range).
template <class P>
bool taylor_coefficients(std::span<P> c, bool at_one) {
  using T = typename P::Scalar;
  const std::size_t m = c.size(), n = m - 1;
  for (std::size_t r = 1; r < m; ++r) {
    if (at_one) {
      // After step r, c[i] = Delta^r c_i for i <= n - r: c[n-j] ends as Delta^j c_(n-j).
      for (std::size_t i = 0; i + r < m; ++i)
        for (int d = 0; d < P::dimension; ++d) c[i][d] = c[i + 1][d] - c[i][d];
    } else {
      // After step r, c[i] = Delta^r c_(i-r) for i >= r: c[j] ends as Delta^j c_0.
      for (std::size_t i = n; i >= r; --i)
        for (int d = 0; d < P::dimension; ++d) c[i][d] = c[i][d] - c[i - 1][d];
    }
  }
  if (at_one) std::reverse(c.begin(), c.end());  // a_j at index j
  T binom = 1;                                   // C(n, j), by the exact-ish recurrence
  for (std::size_t j = 0; j <= n; ++j) {
    for (int d = 0; d < P::dimension; ++d) c[j][d] *= binom;
    if (!all_finite(c[j])) return false;
    binom = binom * static_cast<T>(n - j) / static_cast<T>(j + 1);
  }
  return true;
}

[[noreturn]] inline void throw_not_representable(const std::string& what, const std::string& t) {
  throw InvalidArgument("t", what + " at t = " + t + " is not representable (a coordinate exceeds the largest finite number)");
}

/// The value at any finite t of the Bézier form c (points of any dimension), or
/// InvalidArgument("t", ...) when the value is not representable. On [0, 1] de Casteljau
/// (see de_casteljau; a copy scaled by a power of two only if the direct evaluation
/// overflows near the largest double). Outside, with s = t (t < 0) or s = t - 1 (t > 1):
/// Horner's rule on the Taylor coefficients about that end, of a copy scaled by 2^-e
/// (max |c| in [0.5, 1)), the result scaled back by 2^e.
///
/// Accuracy outside [0, 1]: the error is about eps max|c| sum_j C(n,j) 2^j |s|^j =
/// eps max|c| (1 + 2|s|)^n in the worst case (the condition number of the Bernstein
/// form there), and exact when the differences and the Horner steps are (integer data,
/// e.g. the line 0, 1, 2, 3 gives 3t exactly even at t = 1e200). Unlike de Casteljau,
/// whose lerps with weights 1 - t and t cancel terms of size |t|^n, nothing overflows
/// unless the value does. Cost O(n^2) (differences) + O(n) (Horner).
template <class P, class T>
P evaluate_anywhere(std::span<const P> c, T t, const char* what = "the curve's value") {
  if (t >= 0 && t <= 1) {
    const P p = de_casteljau<P, T>(c, t);
    if (all_finite(p)) return p;
  }
  const int e = scale_exponent(c);
  Scratch<P> buf(c.size());
  std::span<P> a(buf.data(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i) a[i] = scaled(c[i], -e);
  P r;
  if (t >= 0 && t <= 1) {
    r = de_casteljau<P, T>(std::span<const P>(a), t);
  } else {
    const bool at_one = t > 1;
    const T s = at_one ? t - 1 : t;
    if (!taylor_coefficients(a, at_one)) {
      throw InvalidArgument("t", std::string("extrapolating a degree-") + std::to_string(c.size() - 1) +
                                     " Bézier form to t = " + format_number(t) +
                                     " exceeds the range of the floating point type (its Taylor coefficients overflow)");
    }
    r = a.back();
    for (std::size_t j = a.size() - 1; j-- > 0;)
      for (int d = 0; d < P::dimension; ++d) r[d] = r[d] * s + a[j][d];
  }
  r = scaled(r, e);
  if (!all_finite(r)) throw_not_representable(what, format_number(t));
  return r;
}

/// Where derivatives_for_ratio evaluated: in t itself, or in u = 1/s (see there).
enum class DerivativeVariable { t, u };

/// Derivatives 0..k of the Bézier form c at any finite t, for use in ratios (the rational
/// derivative formula), where numerator and denominator may each overflow at large |t|
/// while their quotient does not. out has k + 1 entries.
/// - On [0, 1]: the j-th derivative in t, n!/(n-j)! times de Casteljau on Delta^j c.
/// - Outside, with a_m the Taylor coefficients about the nearer end and s = t or t - 1:
///   for |s| <= 1, the derivatives in t, p^(j)(s) = sum_m a_m m!/(m-j)! s^(m-j) by
///   Horner; for |s| > 1, the derivatives in u = 1/s of the reversed polynomial
///   q(u) = u^n p(1/u) = sum_i a_(n-i) u^i (returns DerivativeVariable::u): q / q_w is the
///   same ratio as p / p_w, |u| < 1 keeps every term bounded by |a|, and the ratio's
///   derivatives in u are well conditioned near u = 0, where those in t would cancel
///   (R' ~ 1/t^2). The caller converts with d/dt = -u^2 d/du.
/// Precondition: c scaled so that the Taylor coefficients do not overflow (see
/// scale_exponent); returns nullopt otherwise. Cost O(n^2 + k n) outside, O(k n^2) on [0, 1].
template <class P, class T>
std::optional<DerivativeVariable> derivatives_for_ratio(std::span<const P> c, T t, int k, std::span<P> out) {
  const int n = static_cast<int>(c.size()) - 1;
  Scratch<P> buf(c.size());
  std::span<P> a(buf.data(), c.size());
  std::copy(c.begin(), c.end(), a.begin());
  auto falling = [](int m, int j) {
    T f = 1;
    for (int i = 0; i < j; ++i) f *= static_cast<T>(m - i);
    return f;
  };
  if (t >= 0 && t <= 1) {
    for (int j = 0; j <= k; ++j) {
      if (j > n) {
        out[static_cast<std::size_t>(j)] = P{};
        continue;
      }
      // a holds Delta^j c_0..c_(n-j) after j difference steps.
      if (j > 0)
        for (int i = 0; i + j <= n; ++i)
          for (int d = 0; d < P::dimension; ++d) a[static_cast<std::size_t>(i)][d] = a[static_cast<std::size_t>(i) + 1][d] - a[static_cast<std::size_t>(i)][d];
      P v = de_casteljau<P, T>(std::span<const P>(a.data(), static_cast<std::size_t>(n - j + 1)), t);
      const T f = falling(n, j);
      for (int d = 0; d < P::dimension; ++d) v[d] *= f;
      out[static_cast<std::size_t>(j)] = v;
    }
    return DerivativeVariable::t;
  }
  const bool at_one = t > 1;
  const T s = at_one ? t - 1 : t;
  if (!taylor_coefficients(a, at_one)) return std::nullopt;
  const bool big = std::abs(s) > 1;
  const T u = 1 / s;
  for (int j = 0; j <= k; ++j) {
    P v{};
    if (j <= n) {
      if (!big) {
        for (int m = n; m >= j; --m) {
          const T f = falling(m, j);
          for (int d = 0; d < P::dimension; ++d) v[d] = v[d] * s + a[static_cast<std::size_t>(m)][d] * f;
        }
      } else {
        // q^(j)(u) = sum_(i >= j) a_(n-i) i!/(i-j)! u^(i-j).
        for (int i = n; i >= j; --i) {
          const T f = falling(i, j);
          for (int d = 0; d < P::dimension; ++d) v[d] = v[d] * u + a[static_cast<std::size_t>(n - i)][d] * f;
        }
      }
    }
    out[static_cast<std::size_t>(j)] = v;
  }
  return big ? DerivativeVariable::u : DerivativeVariable::t;
}

}  // namespace detail

}  // namespace casteljau
