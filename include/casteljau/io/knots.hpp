// Run-time knot operations on B-spline and NURBS curves (insert_knot, remove_knot) and
// the run-time entries of the subdivision schemes and fitting, compiled once in
// src/io/knots.cpp.
#pragma once

#include <optional>
#include <string_view>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// The curve (bspline or nurbs) with the knot u inserted `times` times. Errors:
/// InvalidArgument "curve.type" for other types, "knot" outside the domain, "times" for a
/// count < 1 or a multiplicity past the degree.
[[nodiscard]] AnyCurve insert_knot(const AnyCurve& c, double u, int times);

/// The result of remove_knot: the curve and how many times the knot was removed.
struct AnyKnotRemoval {
  AnyCurve curve;
  int removed = 0;
};

/// Removes the interior knot u of a bspline or nurbs curve up to `times` times while the
/// curve moves by at most `tolerance` (a guaranteed bound over the domain, see
/// BSpline::remove_knot). Errors: "curve.type", "knot" (not an interior knot), "times"
/// (< 1 or above the multiplicity), "tolerance" (not > 0).
[[nodiscard]] AnyKnotRemoval remove_knot(const AnyCurve& c, double u, int times, double tolerance);

/// The subdivision schemes of algo/subdivision.hpp.
enum class SubdivisionScheme { chaikin, lane_riesenfeld, four_point };

/// The polygon after the steps, and the limit curve where the scheme has one (a bspline;
/// none for four_point).
struct AnySubdivision {
  PointList points;
  std::optional<AnyCurve> limit;
};

/// `iterations` steps of the scheme on the polygon P (dimension 1..max_dimension); degree
/// is used by lane_riesenfeld only, tension by four_point only. Errors name "points",
/// "degree", "tension", "iterations" (see algo/subdivision.hpp).
[[nodiscard]] AnySubdivision subdivide(const PointList& P, SubdivisionScheme scheme, int degree, double tension, int iterations,
                                       bool closed);

}  // namespace casteljau::io
