// Intersections of plane curves for the run-time interfaces (the `intersect` command):
// compiled once in src/io/intersect.cpp.
#pragma once

#include <array>
#include <vector>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// The highest piece degree `intersect` accepts: a pair of random degree-500 curves (160
/// crossings) takes about 0.7 s of CPU (degree 200: 45 ms, 300: 0.18 s; measured on the
/// shared 2-core machine under load), about what degree 200 took before fat-line
/// rejection (0.73 s). Arcs, subdivision and refinement all grow with the degree.
inline constexpr int max_intersect_degree = 500;

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
/// InvalidArgument("curves[i]", ...) for a curve that is not 2-D or has a piece above
/// max_intersect_degree, NumericalError when the subdivision limit is reached.
[[nodiscard]] AnyIntersections intersect(const AnyCurve& a, const AnyCurve& b);

/// The self-intersections of one 2-D curve (ta < tb).
[[nodiscard]] AnyIntersections self_intersect(const AnyCurve& a);

}  // namespace casteljau::io
