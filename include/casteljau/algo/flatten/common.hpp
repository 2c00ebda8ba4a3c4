// Flattening's shared parts for every method: the tolerance check, the segment limit, a
// distance without overflow. (The chord tests on curve pieces: chord.hpp.)
#pragma once

#include <algorithm>
#include <cmath>

#include "casteljau/core/error.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau::detail {

template <class T>
void require_tolerance(T tolerance) {
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(tolerance));
}

/// Most segments one piece may be flattened into (2^26: far beyond any polyline worth
/// drawing; the CLI refuses responses over 10^6 vertices long before). A request past it
/// is reported, never silently truncated.
inline constexpr double max_piece_segments = 67108864.0;

/// |a - b| without overflow or underflow in the squares (inf only when a coordinate
/// difference itself overflows).
template <class T, int D>
T scaled_distance(const Point<T, D>& a, const Point<T, D>& b) {
  T m = 0;
  for (int d = 0; d < D; ++d) m = std::max(m, std::abs(a[d] - b[d]));
  if (!(m > 0) || !std::isfinite(m)) return m;
  T s = 0;
  for (int d = 0; d < D; ++d) {
    const T x = (a[d] - b[d]) / m;
    s += x * x;
  }
  return m * std::sqrt(s);
}

}  // namespace casteljau::detail
