// The plan of the plane near-optimal flattening of a line, quadratic or cubic (its count
// function and segment count, told before any vertex is placed), and the parabola
// integral it is built on [Levien19]. Plain data and scalar functions: the compiled lane
// kernels (src/flatten) read the plan.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "casteljau/core/point.hpp"

namespace casteljau::detail {

/// The approximate inverse of the parabola integral I(x) = integral_0^x (1 + 4 u^2)^(-1/4)
/// du, after [Levien19]: a (1 - B + sqrt(B^2 + a^2 / 4)), B = 0.39 (slope 1 at 0 and the
/// asymptote a^2 / 2 + 0.61 a of the true inverse (a + 0.599)^2 / 2); within 0.2% of the
/// true inverse for all a (checked against scipy's hyp2f1 form of I). Odd in a.
template <class T>
inline T parabola_integral_inverse(T a) {
  constexpr T B = T(0.39);
  return a * (1 - B + std::sqrt(B * B + T(0.25) * a * a));
}

/// The parabola integral I(x) as the exact inverse of parabola_integral_inverse (so that
/// the counts and the vertices placed from them agree), to about 1e-5 relative: a start
/// x / (A + ((1 - A)^4 + C x^2 / (1 + x^2) + x^2 / 4)^(1/4)) (A = 0.34136, C = 0.16191,
/// fitted for this code: within 0.45% of the true I, where Levien's one-parameter form is
/// within 3.3%, which put the counts 2% high) and one Newton step on
/// parabola_integral_inverse(a) = x. |x| is capped at 2^250 (x^2 stays finite; the caller's
/// count vanishes as 1 / |x| there). Odd in x.
template <class T>
inline T parabola_integral(T x) {
  constexpr T A = T(0.34136), A4 = (1 - A) * (1 - A) * (1 - A) * (1 - A), C = T(0.16191), B = T(0.39), cap = T(0x1p250);
  x = std::clamp(x, -cap, cap);
  const T x2 = x * x;
  T a = x / (A + std::sqrt(std::sqrt(A4 + C * x2 / (1 + x2) + T(0.25) * x2)));
  const T S = std::sqrt(B * B + T(0.25) * a * a);
  a -= (a * (1 - B + S) - x) / (1 - B + S + T(0.25) * a * a / S);
  return a;
}

/// Approximately x^(-1/2) for a double x >= 0 (finite for 0 and denormals, accurate for
/// normal x): a guess from the bits of x (the exponent halved and negated) and two
/// Newton steps y (3 - x y^2) / 2, multiplications only (so loops of it vectorise):
/// relative error below 5e-6 (checked over 1e-290 .. 1e290). Only for estimates.
inline double fast_rsqrt(double x) {
  double y = std::bit_cast<double>(std::uint64_t{0x5FE6EB50C7B537A9} - (std::bit_cast<std::uint64_t>(x) >> 1));
  y = y * (1.5 - 0.5 * x * y * y);
  y = y * (1.5 - 0.5 * x * y * y);
  return y;
}

/// Approximately x^(-1/4) for a double x > 1e-280, as fast_rsqrt: the exponent quartered
/// and negated, two Newton steps z (5 - x z^4) / 4; relative error below 2e-5 (checked
/// over 1e-280 .. 1e290 against numpy). Only for estimates.
inline double fast_rqrt4(double x) {
  double z = std::bit_cast<double>(std::uint64_t{0x4FEB000000000000} - (std::bit_cast<std::uint64_t>(x) >> 2));
  for (int k = 0; k < 2; ++k) {
    const double z2 = z * z;
    z = z * (1.25 - 0.25 * x * (z2 * z2));
  }
  return z;
}

/// Cells of the sampled density of a cubic in small_optimal (two Gauss-Legendre nodes each).
inline constexpr int optimal_cells = 12;

/// The count function of a piece that is one parabola in small_optimal: the count's
/// fraction u maps to the parameter t = (I^-1(a0 + u da) - x0) sx (sx != 0; else t = u).
template <class T>
struct CountSpan {
  T a0, da, x0, sx;  ///< I(x0), I(x1) - I(x0), x0, 1 / (x1 - x0)

  /// The count's fraction reached at the parameter t (the inverse of the map above): where
  /// a repaired vertex moved, the rest of the count is spread again from it.
  T fraction_at(T t) const { return sx != 0 && da != 0 ? (parabola_integral(x0 + t / sx) - a0) / da : t; }
};

/// small_optimal's plan of a plane polynomial piece of degree 1..3: its power form, its
/// count function and the planned segment count n (see small_optimal).
template <class T>
struct SmallOptimalPlan {
  Point<T, 2> a0;
  Vector<T, 2> a1, a2, a3;
  CountSpan<T> span{};  ///< one parabola (not sampled)
  /// Sampled: cell i = [i, i + 1] / optimal_cells, over which the count grows from f0[i]
  /// to f1[i] (inv[i] = 1 / (f1[i] - f0[i]), 0 for an empty cell) with a density linear
  /// across the cell (slope[i], relative to the mean, in [-2, 2]). Arrays, so that the
  /// placement loads them without a stride.
  T f0[optimal_cells], f1[optimal_cells], inv[optimal_cells], slope[optimal_cells];
  bool sampled = false;
  T F = 0;  ///< the count function's total
  int n = 1;
  /// One parabola standing for the piece within 1e-3 tol (|a3| / 8 <= 1e-3 tol / 4): each
  /// step may be checked on the parabola in closed form (small_optimal): its scale
  /// squared, its x over [0, 1] (xa + t xspan) and the limit of its deviation squared.
  bool closed = false;
  T scale2 = 0, xa = 0, xspan = 0, lim2 = 0;
};

/// Vertices placed and checked together by small_optimal_batched (one block).
inline constexpr int optimal_block = 8;

}  // namespace casteljau::detail

