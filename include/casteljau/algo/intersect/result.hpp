// The answer of intersect() and self_intersect() (algo/intersect.hpp): isolated common
// points with their kind, and overlaps.
#pragma once

#include <vector>

#include "casteljau/core/interval.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau {

/// How two curves meet at an isolated common point.
enum class IntersectionKind {
  crossing,  ///< the tangents differ (sine of their angle above 1e-6)
  tangent,   ///< the tangents are parallel: a touch, or a crossing with parallel tangents
};

/// An isolated common point: a(ta) = b(tb) (for self-intersections ta < tb).
template <class T>
struct CurveIntersection {
  T ta{};
  T tb{};
  Point<T, 2> point;  ///< a(ta)
  IntersectionKind kind = IntersectionKind::crossing;
};

/// A stretch where the curves coincide: a over [a.lo, a.hi] (a.lo < a.hi) traces the same
/// points as b from b_start to b_end (b_start > b_end when b runs the other way).
template <class T>
struct CurveOverlap {
  Interval<T> a;
  T b_start{};
  T b_end{};
};

/// The result of intersect(): isolated points sorted by ta, and overlaps sorted by a.lo.
template <class T>
struct Intersections {
  std::vector<CurveIntersection<T>> points;
  std::vector<CurveOverlap<T>> overlaps;
};

}  // namespace casteljau
