// The unit frame of a set of points: origin at the first point, scale the power of two
// that brings the largest |P - origin| into [0.5, 1). Algorithms that compare distances
// with a tolerance (flattening, intersection) work in it, so that huge and tiny
// coordinates behave as unit ones and scaling the input by 2^k changes nothing but the
// exponent. Also the frame with origin 0 (max_abs, abs_exponent, times_pow2) for those
// that scale but do not translate (to_quadratic, extrapolation). One copy of this step
// for the library (issue 15).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include "casteljau/core/point.hpp"

namespace casteljau::detail {

/// 2^k exactly: for double from its bits when 2^k is a normal number (std::ldexp is a
/// library call; with frexp about 3% of the optimal flattening's time on W3's cubics),
/// else std::ldexp.
template <class T>
inline T pow2(int k) {
  if constexpr (std::is_same_v<T, double>) {
    if (k >= -1022 && k <= 1023) return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
  }
  return std::ldexp(T(1), k);
}

/// The exponent e of x > 0 with x = m 2^e, m in [0.5, 1) (std::frexp's), for a normal
/// double from its bits.
template <class T>
inline int frexp_exponent(T x) {
  if constexpr (std::is_same_v<T, double>) {
    if (x >= std::numeric_limits<double>::min()) return static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7FF) - 1022;
  }
  int e = 0;
  (void)std::frexp(x, &e);
  return e;
}

/// Half the extent of the points P about `origin`: max over points and coordinates of
/// |P[d] / 2 - origin[d] / 2|. Halved first so that no difference of finite coordinates
/// overflows (exact for normal numbers). 0 when every point is the origin; NaN is skipped
/// by max (the callers reject non-finite points before).
template <class T, int D>
T half_extent(std::span<const Point<T, D>> P, const Point<T, D>& origin) {
  T extent = 0;
  for (const auto& p : P)
    for (int d = 0; d < D; ++d) extent = std::max(extent, std::abs(p[d] / 2 - origin[d] / 2));
  return extent;
}

/// The frame's exponent e for a half extent h > 0 (half_extent): 2^(e-1) <= 2 h < 2^e, so
/// the largest |P - origin| 2^-e lies in [0.5, 1).
template <class T>
int unit_exponent(T h) {
  return frexp_exponent(h) + 1;  // h was halved
}

/// x 2^k, correctly rounded (as std::ldexp): for double by one multiplication while 2^k
/// is a normal number (|k| <= 1022), else by ldexp (for float 2^k itself may overflow or
/// underflow where x 2^k does not).
template <class T>
T times_pow2(T x, int k) {
  if constexpr (std::is_same_v<T, double>) {
    if (k >= -1022 && k <= 1022) return x * pow2<T>(k);
  }
  return std::ldexp(x, k);
}

/// The coordinate x in the frame (origin o, exponent e): (x - o) 2^-e, correctly rounded.
/// When the difference of two finite coordinates overflows they are halved first (exact
/// for normal numbers) and scaled by one power of two less.
template <class T>
T to_unit(T x, T o, int e) {
  const T q = x - o;
  if (!std::isfinite(q)) return std::ldexp(x / 2 - o / 2, 1 - e);
  return times_pow2(q, -e);
}

/// The point p in the frame (to_unit per coordinate).
template <class T, int D>
Point<T, D> to_unit(const Point<T, D>& p, const Point<T, D>& origin, int e) {
  Point<T, D> q;
  for (int d = 0; d < D; ++d) q[d] = to_unit(p[d], origin[d], e);
  return q;
}

/// The frame with origin 0 (for algorithms whose answer is not invariant under
/// translation but should be under scaling by 2^k): the largest |P[d]| over the points
/// P and coordinates, folded into m (so that several point sets share one frame).
template <class T, int D>
void max_abs(std::span<const Point<T, D>> P, T& m) {
  for (const auto& p : P)
    for (int d = 0; d < D; ++d) m = std::max(m, std::abs(p[d]));
}

/// The exponent e of the origin-0 frame for m = max |P| (max_abs): m 2^-e lies in
/// [0.5, 1). 0 when m is 0 (or not finite: the callers reject such points before).
template <class T>
int abs_exponent(T m) {
  if (!(m > 0) || !std::isfinite(m)) return 0;
  return frexp_exponent(m);
}

/// The point p 2^k (times_pow2 per coordinate).
template <class T, int D>
Point<T, D> times_pow2(const Point<T, D>& p, int k) {
  Point<T, D> q;
  for (int d = 0; d < D; ++d) q[d] = times_pow2(p[d], k);
  return q;
}

}  // namespace casteljau::detail
