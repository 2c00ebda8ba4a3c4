// Straight segments: the distance from a point and the closest points of two segments,
// shared by flattening (the chord tests), distance between curves and intersection.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "casteljau/core/point.hpp"

namespace casteljau {

/// Distance from p to the segment [a, b], without overflow or underflow (norm() scales
/// by the largest coordinate) and with NaN propagated, never turned into a pass.
template <class T, int D>
T distance_to_segment(const Point<T, D>& p, const Point<T, D>& a, const Point<T, D>& b) {
  const Vector<T, D> ab = b - a, ap = p - a;
  const T len = norm(ab);
  if (len == 0) return norm(ap);
  // Projection parameter s = (ap . ab) / |ab|^2, computed on unit-length ab so that
  // neither the dot product nor the squared length over- or underflows.
  const Vector<T, D> u = ab / len;
  const T s = dot(ap, u) / len;
  if (!(s > 0)) return s == s ? norm(ap) : s;  // NaN stays NaN
  if (s >= 1) return norm(p - b);
  return norm(ap - (s * len) * u);
}

/// Closest points of the segments [p1, q1] and [p2, q2]: the parameters (s, t) in
/// [0, 1]^2 minimising |p1 + s (q1 - p1) - p2 - t (q2 - p2)|, by clamping the
/// unconstrained minimiser one parameter at a time [Ericson05, 5.1.9]. A segment of
/// length zero takes parameter 0.
template <class T, int D>
std::array<T, 2> closest_on_segments(const Point<T, D>& p1, const Point<T, D>& q1, const Point<T, D>& p2,
                                     const Point<T, D>& q2) {
  const Vector<T, D> d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const T a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  const T tiny = std::numeric_limits<T>::min();
  if (a <= tiny && e <= tiny) return {T(0), T(0)};
  if (a <= tiny) return {T(0), std::clamp(f / e, T(0), T(1))};
  const T c = dot(d1, r);
  if (e <= tiny) return {std::clamp(-c / a, T(0), T(1)), T(0)};
  const T b = dot(d1, d2), denom = a * e - b * b;
  T s = denom > 0 ? std::clamp((b * f - c * e) / denom, T(0), T(1)) : T(0);
  T t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, T(0), T(1));
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, T(0), T(1));
  }
  return {s, t};
}

}  // namespace casteljau
