// Closed parameter intervals and axis-aligned boxes.
#pragma once

#include <algorithm>
#include <limits>

#include "casteljau/core/point.hpp"

namespace casteljau {

/// The closed interval [lo, hi] (lo <= hi).
template <class T>
struct Interval {
  T lo{};
  T hi{};

  [[nodiscard]] constexpr T length() const { return hi - lo; }
  [[nodiscard]] constexpr bool contains(T x) const { return lo <= x && x <= hi; }
  /// The parameter lo + s (hi - lo) of the fraction s.
  [[nodiscard]] constexpr T at(T s) const { return lerp(lo, hi, s); }
  /// The fraction s with at(s) == x.
  [[nodiscard]] constexpr T fraction(T x) const { return (x - lo) / (hi - lo); }
  friend constexpr bool operator==(const Interval&, const Interval&) = default;
};

/// An axis-aligned box [lo, hi] (per coordinate, as Interval), empty() until a point is added.
template <class T, int D>
struct Box {
  Point<T, D> lo;
  Point<T, D> hi;

  static constexpr Box empty_box() {
    Box b;
    for (int i = 0; i < D; ++i) {
      b.lo[i] = std::numeric_limits<T>::infinity();
      b.hi[i] = -std::numeric_limits<T>::infinity();
    }
    return b;
  }
  [[nodiscard]] constexpr bool empty() const { return lo[0] > hi[0]; }
  constexpr void add(const Point<T, D>& p) {
    for (int i = 0; i < D; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  constexpr void add(const Box& b) {
    if (b.empty()) return;
    add(b.lo);
    add(b.hi);
  }
  [[nodiscard]] constexpr bool contains(const Point<T, D>& p, T tolerance = 0) const {
    for (int i = 0; i < D; ++i) {
      if (p[i] < lo[i] - tolerance || p[i] > hi[i] + tolerance) return false;
    }
    return true;
  }
};

}  // namespace casteljau
