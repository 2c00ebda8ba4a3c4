// Run-time operations of issue 20 on curves (AnyCurve): the level sets of a coordinate or
// a linear functional (solve), knot refinement (refine), conversion to one B-spline,
// degree reduction and offsets. Compiled once, in
// src/io/ops.cpp: solve on the curves' exact Bézier pieces (one instantiation per
// dimension), refine on the B-spline and NURBS types.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "casteljau/algo/solve.hpp"
#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// Where coordinate `axis` of the curve (or a . C(t) for `direction` a) equals `value`
/// (algo/solve.hpp): isolated parameters and whole intervals. Exactly one of axis and
/// direction is given. Errors: InvalidArgument "axis" (neither given, or outside
/// 0..d-1), "direction" (both given; not d coordinates; the zero vector), "curve" (the
/// work limit of the queries).
[[nodiscard]] LevelSet<double> solve(const AnyCurve& c, std::optional<int> axis, std::optional<std::span<const double>> direction,
                                     double value);

/// The curve (bspline or nurbs) with every knot of X inserted at once ([PT97] A5.4).
/// Errors: InvalidArgument "curve.type" for other types, "knots[i]" for a knot that is
/// not finite, smaller than the one before it, outside the domain, or that would repeat
/// more than the degree.
[[nodiscard]] AnyCurve refine(const AnyCurve& c, std::span<const double> X);

/// The curve as one bspline (nurbs when a piece is rational) on the same parameter
/// (algo/to_bspline.hpp: pieces elevated to the highest degree, each joint's knot
/// repeated p - k times for continuity C^k there, decided to rounding: to_bspline_rounding).
/// Errors: "curve" (the work limit of the queries).
[[nodiscard]] AnyCurve to_bspline(const AnyCurve& c);

/// The result of reduce: the curve of degree p - r and the largest distance between it
/// and the original at equal parameters (algo/deviation.hpp).
struct AnyReduction {
  AnyCurve curve;
  double max_error = 0;
};

/// Degree reduction of a bezier, bspline or nurbs by `times` r (1 <= r <= p) within
/// `tolerance`: a bezier by least squares with its end points kept (free for a constant
/// result: the mean); a bspline or nurbs by the library's reduce_spline
/// (algo/reduce_spline.hpp: the least max_error among candidates, a degree-0 result the
/// curve's mean), none of them depending on the tolerance; the work limit is
/// reduce_spline_work's units (a bezier one piece) at most 3e7. max_error is measured
/// (dense sampling and local maximisation, to about 1e-9 relative); a result farther than
/// the tolerance is refused. Errors: "curve.type"
/// for other types, "times" outside 1..p, "tolerance" (not > 0, or exceeded: the message
/// gives the measured figure), "curve" (the work limit; no finite reduction found).
[[nodiscard]] AnyReduction reduce(const AnyCurve& c, int times, double tolerance);

/// The offset of a 2-D curve at signed distance `distance` (positive to the left of the
/// direction of travel) as a path of cubic bezier segments within `tolerance` of the exact
/// offset (algo/offset.hpp), with `join` ("round", "miter", "bevel") at the input's
/// corners and, with `trim`, its loops cut away. Compiled in src/io/offset.cpp, in the
/// unity group that instantiates the intersections it trims with. Errors: "curve" (not
/// 2-D: "offset needs a 2-D curve"; a single point; a gap; the work limits), "distance",
/// "tolerance" (not > 0; too small for the curve's size; more cubics than the limit, with
/// the estimate), "join", "miter_limit" (< 1).
[[nodiscard]] AnyCurve offset(const AnyCurve& c, double distance, double tolerance, bool trim, std::string_view join,
                              double miter_limit);
/// The most quadratic segments to_quadratic makes (about the response size of flatten's
/// limit: three points a segment).
inline constexpr std::size_t max_quadratic_segments = 300'000;

/// The curve as a path of quadratic bezier segments within `tolerance` of it (Hausdorff),
/// tangent-continuous where the curve is (algo/to_quadratic.hpp), breaks at the curve's
/// parameters of the joints. Errors: "tolerance" (not finite and > 0; more than
/// max_quadratic_segments segments, estimated beforehand from each piece's third
/// differences or met while working: the message gives the figures), "curve" (the work
/// limit of the queries).
[[nodiscard]] AnyCurve to_quadratic(const AnyCurve& c, double tolerance);

}  // namespace casteljau::io
