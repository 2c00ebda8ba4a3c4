// Intersections of plane curves for the run-time interfaces (the `intersect` command):
// compiled once in src/io/intersect.cpp.
#pragma once

#include <array>
#include <vector>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// An isolated common point a(ta) = b(tb) (see casteljau::intersect).
struct AnyIntersection {
  double ta = 0;
  double tb = 0;
  std::array<double, 2> point{};
  bool tangent = false;
};

/// a over [a0, a1] (a0 < a1) traces b from b0 to b1.
struct AnyOverlap {
  double a0 = 0, a1 = 0, b0 = 0, b1 = 0;
};

struct AnyIntersections {
  std::vector<AnyIntersection> points;
  std::vector<AnyOverlap> overlaps;
};

/// The intersections of two 2-D curves (algo/intersect.hpp). Throws
/// InvalidArgument("curves[i]", ...) for a curve that is not 2-D, NumericalError when the
/// subdivision limit is reached.
[[nodiscard]] AnyIntersections intersect(const AnyCurve& a, const AnyCurve& b);

/// The self-intersections of one 2-D curve (ta < tb).
[[nodiscard]] AnyIntersections self_intersect(const AnyCurve& a);

}  // namespace casteljau::io
