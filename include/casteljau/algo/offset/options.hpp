// The options of offset() (algo/offset.hpp): the join at the input's corners, the placement
// of the cubics, the distance and tolerance, the trim and the work limit. A header of their
// own because the phases read them (joins.hpp the join and miter limit, place.hpp the
// placement); algo/offset.hpp includes it, so users see them there. Depends on nothing of
// the library.
#pragma once

#include <cstddef>

namespace casteljau {

/// How the outer side of a corner of the input (a G0 joint) is closed.
enum class OffsetJoin {
  round,  ///< a circular arc of radius |d| about the corner (as cubics within the tolerance)
  miter,  ///< the two offset tangent lines extended to their meeting point (bevel past miter_limit)
  bevel,  ///< one straight line between the two offset end points
};

/// How the cubics are placed along each smooth stretch of the offset.
enum class OffsetFit {
  greedy,   ///< each cubic as long as the tolerance allows (near the fewest); the default
  uniform,  ///< the reference: n equal parameter parts, Hermite cubics, n = 1, 2, ... until within the tolerance
};

template <class T>
struct OffsetOptions {
  T distance = 0;   ///< d: positive to the left of the direction of travel
  T tolerance = 0;  ///< the largest distance allowed between the cubics and the exact offset (both ways)
  bool trim = true;
  OffsetJoin join = OffsetJoin::round;
  T miter_limit = 4;  ///< miter length over |d| (SVG's stroke-miterlimit), >= 1
  OffsetFit fit = OffsetFit::greedy;
  std::size_t max_segments = 20000;  ///< the work limit: more cubics than this are refused
};

}  // namespace casteljau
