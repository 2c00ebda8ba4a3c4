// Adaptive Gauss-Kronrod quadrature (7-point Gauss, 15-point Kronrod) with a global error
// estimate: the integrals that arc length and area need, as plain functions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <vector>

#include "casteljau/core/error.hpp"

namespace casteljau {

/// One interval of an adaptive quadrature: the integral over [a, b] and its error estimate.
template <class T>
struct QuadratureInterval {
  T a, b, value, error;
};

/// The result of integrate_adaptive: the integral, the sum of the error estimates, and
/// the final partition of [a, b] ordered by a (so that a caller can integrate again from
/// any point without starting over, as param_at_length does).
template <class T>
struct Quadrature {
  T value = 0;
  T error = 0;
  std::vector<QuadratureInterval<T>> intervals;
};

namespace detail {

// The 15-point Gauss-Kronrod rule on [-1, 1] [Kronrod65; Piessens83 (QUADPACK qk15)]:
// nodes +-gk_x[i] (gk_x[7] = 0), Kronrod weights gk_w, and the weights g_w of the
// 7-point Gauss rule on the odd-indexed nodes gk_x[1], gk_x[3], gk_x[5] and 0. Checked in
// tests/unit/queries_test.cpp: the Kronrod rule integrates t^k exactly to k = 22, the
// Gauss rule to k = 13. Stored in long double (33 digits), so that a long double
// integral is not limited by nodes rounded to double; each rounds to the same double as
// its decimal literal would (checked for all 19), so double results are unchanged.
inline constexpr std::array<long double, 8> gk_x = {
    0.991455371120812639206854697526329L, 0.949107912342758524526189684047851L, 0.864864423359769072789712788640926L,
    0.741531185599394439863864773280788L, 0.586087235467691130294144845693013L, 0.405845151377397166906606412076961L,
    0.207784955007898467600689403773245L, 0.0L};
inline constexpr std::array<long double, 8> gk_w = {
    0.022935322010529224963732008058970L, 0.063092092629978553290700663189204L, 0.104790010322250183839876322541518L,
    0.140653259715525918745189590510238L, 0.169004726639267902826583426598550L, 0.190350578064785409913256402421014L,
    0.204432940075298892414161999234649L, 0.209482141084727828012999174891714L};
inline constexpr std::array<long double, 4> g_w = {0.129484966168869693270611432679082L, 0.279705391489276667901467771423780L,
                                              0.381830050505118944950369775488975L, 0.417959183673469387755102040816327L};

/// A relative accuracy target stated for double (e.g. 1e-13), at the scalar T: scaled by
/// T's epsilon over double's, so that it asks the same number of units in the last place
/// at every scalar (float: 2^29 times looser, which adaptive quadrature can meet; long
/// double: 2^11 times tighter). Exactly `target` for double.
template <class T>
constexpr T target_at(double target) {
  return static_cast<T>(target) * (std::numeric_limits<T>::epsilon() / static_cast<T>(std::numeric_limits<double>::epsilon()));
}

}  // namespace detail

/// The Gauss-Kronrod 7-15 estimate of the integral of f over [a, b] and its error
/// estimate |K15 - G7| (pessimistic for smooth f: K15 is exact to degree 22, G7 only to
/// degree 13, so the true error of K15 is far below the estimate). 15 evaluations.
template <class T, class F>
QuadratureInterval<T> gauss_kronrod_15(F&& f, T a, T b) {
  const T c = (a + b) / 2, h = (b - a) / 2;
  const T f0 = f(c);
  T k = static_cast<T>(detail::gk_w[7]) * f0, g = static_cast<T>(detail::g_w[3]) * f0;
  for (int i = 0; i < 7; ++i) {
    const T x = h * static_cast<T>(detail::gk_x[static_cast<std::size_t>(i)]);
    const T s = f(c - x) + f(c + x);
    k += static_cast<T>(detail::gk_w[static_cast<std::size_t>(i)]) * s;
    if (i % 2 == 1) g += static_cast<T>(detail::g_w[static_cast<std::size_t>(i / 2)]) * s;
  }
  return {a, b, k * h, std::abs((k - g) * h)};
}

/// The integral of f over [a, b] (a <= b) to the error estimate max(rel_tol |value|,
/// abs_tol): globally adaptive (the interval with the largest error estimate is halved
/// until the sum of the estimates meets the target) [Piessens83, QAG]. The estimate is
/// |K15 - G7| per interval, an upper bound in practice for integrands smooth on each
/// interval (callers split at kinks). Throws NumericalError when the target is not met
/// after max_intervals intervals (a kink or singularity the caller did not split at, or
/// a target below the integrand's rounding): never returns an unverified value.
/// a == b gives 0. Cost 15 evaluations per interval.
template <class T, class F>
Quadrature<T> integrate_adaptive(F&& f, T a, T b, T rel_tol, T abs_tol = T(0), std::size_t max_intervals = 4000) {
  Quadrature<T> out;
  if (!(a < b)) return out;
  auto worse = [](const QuadratureInterval<T>& x, const QuadratureInterval<T>& y) { return x.error < y.error; };
  std::priority_queue<QuadratureInterval<T>, std::vector<QuadratureInterval<T>>, decltype(worse)> heap(worse);
  const auto first = gauss_kronrod_15<T>(f, a, b);
  heap.push(first);
  T value = first.value, error = first.error;
  while (!(error <= std::max(rel_tol * std::abs(value), abs_tol))) {
    if (heap.size() >= max_intervals) {
      throw NumericalError("the integral cannot be computed to its accuracy target: the adaptive quadrature's error estimate " +
                           detail::format_number(error) + " is above the target " +
                           detail::format_number(std::max(rel_tol * std::abs(value), abs_tol)) + " after " +
                           std::to_string(max_intervals) + " intervals (the integrand varies too sharply)");
    }
    const auto worst = heap.top();
    heap.pop();
    const T mid = worst.a + (worst.b - worst.a) / 2;
    if (!(mid > worst.a && mid < worst.b)) {
      throw NumericalError("the integral cannot be computed to its accuracy target: an interval of the adaptive quadrature "
                           "reached the resolution of the parameter with error estimate " +
                           detail::format_number(worst.error));
    }
    const auto left = gauss_kronrod_15<T>(f, worst.a, mid), right = gauss_kronrod_15<T>(f, mid, worst.b);
    value += left.value + right.value - worst.value;
    error += left.error + right.error - worst.error;
    heap.push(left);
    heap.push(right);
  }
  // The sums carried along lose a few ulps per update: recompute them from the partition.
  out.intervals.reserve(heap.size());
  while (!heap.empty()) {
    out.intervals.push_back(heap.top());
    heap.pop();
  }
  std::sort(out.intervals.begin(), out.intervals.end(), [](const auto& x, const auto& y) { return x.a < y.a; });
  for (const auto& iv : out.intervals) {
    out.value += iv.value;
    out.error += iv.error;
  }
  return out;
}

}  // namespace casteljau
