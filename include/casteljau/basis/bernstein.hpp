// Bernstein polynomials B(i,n)(t) = C(n,i) t^i (1-t)^(n-i): single values, all values of one
// degree in O(n), derivatives of any order, and the same on an arbitrary interval [a, b].
// Plain functions over spans, callable without a curve object; degree elevation of
// Bézier points of any point type (detail::elevate_bezier_points).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

namespace detail {
inline void require_degree(int n) {
  if (n < 0) throw InvalidArgument("n", "degree must be >= 0, got " + std::to_string(n));
}
template <class T>
void require_interval(Interval<T> ab) {
  require_finite(ab.lo, "interval.lo");
  require_finite(ab.hi, "interval.hi");
  if (!(ab.lo < ab.hi)) {
    throw InvalidArgument("interval", "needs lo < hi, got [" + format_number(ab.lo) + ", " +
                                          format_number(ab.hi) + "]");
  }
}
template <class T>
T ipow(T x, int k) {
  T r = 1;
  for (; k > 0; --k) r *= x;  // repeated multiplication: relative error <= k eps
  return r;
}
}  // namespace detail

/// B(i,n)(t). Zero for i outside 0..n. Relative error about (n + 2) eps for t in [0, 1].
template <class T>
T bernstein(int i, int n, T t) {
  detail::require_degree(n);
  require_finite(t, "t");
  if (i < 0 || i > n) return T(0);
  return binomial<T>(n, i) * detail::ipow(t, i) * detail::ipow(T(1) - t, n - i);
}

/// All n+1 values B(0..n, n)(t) into out (size n+1) in O(n): B(0,n) = (1-t)^n, then
/// B(i+1,n) = B(i,n) (n-i)/(i+1) t/(1-t). The running value is kept as a mantissa and a
/// separate power-of-two exponent (frexp after every step), so no intermediate over- or
/// underflows at any degree: a value is 0 only if it is below the smallest subnormal.
/// Relative error about (n + 4 i) eps for B(i,n). They sum to 1 (partition of unity) up
/// to rounding and are >= 0 on [0, 1]. t = 1 (where t/(1-t) is undefined) is exact: the
/// unit vector e_n. Throws InvalidArgument for n < 0 ("n"), a non-finite t ("t") or a
/// wrong out size ("out").
template <class T>
void bernstein_all(int n, T t, std::span<T> out) {
  detail::require_degree(n);
  require_finite(t, "t");
  if (out.size() != static_cast<std::size_t>(n) + 1) {
    throw InvalidArgument("out", "needs n + 1 = " + std::to_string(n + 1) + " entries, got " + std::to_string(out.size()));
  }
  const T s = T(1) - t;
  if (s == 0) {
    std::fill(out.begin(), out.end(), T(0));
    out[static_cast<std::size_t>(n)] = 1;
    return;
  }
  // (mant, ex) holds mant 2^ex; start with s^n by repeated squaring-free multiplication.
  T mant = 1;
  long ex = 0;
  auto renormalise = [&] {
    int e = 0;
    mant = std::frexp(mant, &e);
    ex += e;
  };
  for (int i = 0; i < n; ++i) {
    mant *= s;
    renormalise();
  }
  const T ratio = t / s;
  for (int i = 0; i <= n; ++i) {
    out[static_cast<std::size_t>(i)] = ex < -100000 ? T(0) : std::ldexp(mant, static_cast<int>(std::max(ex, -100000L)));
    if (i == n) break;
    mant *= static_cast<T>(n - i) / static_cast<T>(i + 1) * ratio;
    if (mant == 0) {  // t = 0: every later value is 0
      std::fill(out.begin() + i + 1, out.end(), T(0));
      return;
    }
    renormalise();
  }
}

template <class T>
std::vector<T> bernstein_all(int n, T t) {
  std::vector<T> out(static_cast<std::size_t>(n) + 1);
  bernstein_all<T>(n, t, out);
  return out;
}

/// d^k/dt^k B(i,n)(t) = n!/(n-k)! sum_j (-1)^(k-j) C(k,j) B(i-j, n-k)(t) [Farin02, 5.3];
/// zero when k > n.
template <class T>
T bernstein_derivative(int i, int n, int k, T t) {
  detail::require_degree(n);
  require_finite(t, "t");
  if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  if (k > n) return T(0);
  T falling = 1;
  for (int j = 0; j < k; ++j) falling *= static_cast<T>(n - j);
  T s = 0;
  for (int j = 0; j <= k; ++j) {
    const T term = binomial<T>(k, j) * bernstein<T>(i - j, n - k, t);
    s += ((k - j) % 2 == 0) ? term : -term;
  }
  return falling * s;
}

/// All derivatives d^k/dt^k B(0..n, n)(t) into out (size n+1), O(n k).
template <class T>
void bernstein_all_derivatives(int n, int k, T t, std::span<T> out) {
  detail::require_degree(n);
  require_finite(t, "t");
  if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  if (out.size() != static_cast<std::size_t>(n) + 1) {
    throw InvalidArgument("out", "needs n + 1 = " + std::to_string(n + 1) + " entries, got " + std::to_string(out.size()));
  }
  std::fill(out.begin(), out.end(), T(0));
  if (k > n) return;
  std::vector<T> low(static_cast<std::size_t>(n - k) + 1);
  bernstein_all<T>(n - k, t, low);
  T falling = 1;
  for (int j = 0; j < k; ++j) falling *= static_cast<T>(n - j);
  // Each low-degree value B(m, n-k) feeds B(m+j, n) with weight (-1)^(k-j) C(k,j).
  for (int m = 0; m <= n - k; ++m) {
    for (int j = 0; j <= k; ++j) {
      const T term = binomial<T>(k, j) * low[static_cast<std::size_t>(m)];
      out[static_cast<std::size_t>(m + j)] += ((k - j) % 2 == 0) ? term : -term;
    }
  }
  for (auto& v : out) v *= falling;
}

/// B(i,n) on [a, b]: B(i,n)((x - a)/(b - a)).
template <class T>
T bernstein(int i, int n, T x, Interval<T> ab) {
  detail::require_interval(ab);
  return bernstein<T>(i, n, ab.fraction(x));
}

/// d^k/dx^k of B(i,n)((x - a)/(b - a)) = (b - a)^-k B(i,n)^(k)((x - a)/(b - a)).
template <class T>
T bernstein_derivative(int i, int n, int k, T x, Interval<T> ab) {
  detail::require_interval(ab);
  return bernstein_derivative<T>(i, n, k, ab.fraction(x)) / detail::ipow(ab.length(), k);
}

/// All values B(0..n, n) on [a, b] at x.
template <class T>
void bernstein_all(int n, T x, Interval<T> ab, std::span<T> out) {
  detail::require_interval(ab);
  bernstein_all<T>(n, ab.fraction(x), out);
}

namespace detail {

/// The Bézier points of degree n + r (r >= 1) of the Bézier points P of degree n, for
/// any point type V (a Point, a homogeneous point, a surface's row of points: V - V, a
/// scalar times that, += and V + that), by Forrest's equations [Forrest72; Farin02, 5.1]:
/// Q_i = sum_j h_ij P_j with the hypergeometric weights h_ij = C(r, i-j) C(n, j) /
/// C(n+r, i) (a convex combination), computed by their ratio recurrence and normalised to
/// sum 1 (hypergeometric_row), so no binomial overflows at any degree. Written as
/// P_lo + sum h_ij (P_j - P_lo): exact for a constant curve. Error about
/// (2 min(n, r) + 4) eps of the control polygon's extent. The one elevation of Bézier
/// points: Bezier::elevate, the B-spline and NURBS elevation (knot_form.hpp) and the
/// surfaces' (per row). Cost O((n + r) min(n, r)).
template <class T, class V>
std::vector<V> elevate_bezier_points(std::span<const V> P, int r) {
  const int n = static_cast<int>(P.size()) - 1;
  std::vector<V> Q(P.size() + static_cast<std::size_t>(r));
  std::vector<T> h(static_cast<std::size_t>(std::min(n, r)) + 1);
  for (int i = 0; i <= n + r; ++i) {
    const int lo = std::max(0, i - r), hi = std::min(n, i);
    hypergeometric_row<T>(n + r, n, i, std::span<T>(h.data(), static_cast<std::size_t>(hi - lo + 1)));
    const V& base = P[static_cast<std::size_t>(lo)];
    auto s = T(0) * (base - base);  // a zero of the difference type (and of its size)
    for (int j = lo + 1; j <= hi; ++j) s += h[static_cast<std::size_t>(j - lo)] * (P[static_cast<std::size_t>(j)] - base);
    Q[static_cast<std::size_t>(i)] = base + s;
  }
  return Q;
}

}  // namespace detail

}  // namespace casteljau
