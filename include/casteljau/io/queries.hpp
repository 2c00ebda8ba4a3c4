// The geometric queries on a run-time curve (AnyCurve): closest and farthest point, arc
// length and its inverse, bounds over a parameter range, curvature, the Frenet frame,
// signed area, features and the distance between two curves. Compiled once, in
// src/io/queries.cpp, on the curves' exact Bézier pieces (one instantiation per
// dimension, not per curve type).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "casteljau/algo/distance.hpp"
#include "casteljau/algo/features.hpp"
#include "casteljau/algo/frame.hpp"
#include "casteljau/algo/project.hpp"
#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// One frame per parameter.
template <class T, int D>
using Frames = std::vector<Frame<T, D>>;

// The results are the library's structs at the curve's dimension (their JSON:
// io/results.hpp), and AnyBox (io/any_curve.hpp).
using AnyProjection = PerDimension<Projection>;
using AnyFeatures = PerDimension<Features>;
using AnyDistance = PerDimension<CurveDistance>;
using AnyFrames = PerDimension<Frames>;

/// The nearest (farthest with `farthest`) point of the curve to `point` over its whole
/// domain, global. Throws InvalidArgument("point", ...) when the point's dimension is not
/// the curve's or a coordinate is not finite.
[[nodiscard]] AnyProjection project(const AnyCurve& c, std::span<const double> point, bool farthest);

/// project at each of the n points in `points` (n rows of d = dimension(c) coordinates),
/// the curve's pieces made once for all of them: row i's parameter, point and distance in
/// t[i], point[i d .. i d + d) and distance[i] (each span sized n, n d, n). Throws
/// InvalidArgument("points[i][k]", ...) for a coordinate that is not finite.
void project_rows(const AnyCurve& c, std::span<const double> points, bool farthest, std::span<double> t,
                  std::span<double> point, std::span<double> distance);

/// A curve's exact Bézier pieces and domain, made once for any number of projections
/// (the Python package keeps them with its curve object: one point on a curve of 2000
/// pieces no longer makes its pieces again).
struct ProjectionPieces {
  AnyPieces pieces;
  Interval<double> domain;
};

/// The pieces of c for project: throws as project does for a curve past the work limit.
[[nodiscard]] std::unique_ptr<const ProjectionPieces> projection_pieces(const AnyCurve& c);

/// project and project_rows on pieces made before (the same answers).
[[nodiscard]] AnyProjection project(const ProjectionPieces& p, std::span<const double> point, bool farthest);
void project_rows(const ProjectionPieces& p, std::span<const double> points, bool farthest, std::span<double> t,
                  std::span<double> point, std::span<double> distance);

/// The arc length between `from` and `to` (default: the domain's ends), relative accuracy
/// 1e-12 (algo/length.hpp). Throws InvalidArgument("from"/"to", ...) for a range outside
/// the domain or reversed.
[[nodiscard]] double length(const AnyCurve& c, std::optional<double> from, std::optional<double> to);

/// The tight box of the curve over [from, to] (default: the domain's ends; algo/bounds.hpp
/// on the curve's pieces). Throws InvalidArgument("from"/"to", ...) for a range outside
/// the domain or reversed.
[[nodiscard]] AnyBox bounds(const AnyCurve& c, std::optional<double> from, std::optional<double> to);

/// The parameter at each arc length (from the domain's start), each in [0, length].
/// Throws InvalidArgument("lengths[i]", ...) for a length outside that range.
[[nodiscard]] std::vector<double> param_at_length(const AnyCurve& c, std::span<const double> lengths);

/// The curvature at each parameter (signed in 2-D, >= 0 otherwise; algo/curvature.hpp).
/// Throws InvalidArgument("t[j]", ...) where it is undefined (zero velocity) or a
/// derivative is not representable.
[[nodiscard]] std::vector<double> curvature(const AnyCurve& c, std::span<const double> t);

/// The Frenet frame (algo/frame.hpp) at each parameter (any finite t; at a break the right-hand piece, at the
/// domain's end the last). Throws InvalidArgument("t[j]", ...) where it is undefined: the
/// velocity vanishes (a cusp or a stop), or in 3-D and 4-D the curvature does (no
/// principal normal: a straight stretch, a point of zero curvature).
[[nodiscard]] AnyFrames frames(const AnyCurve& c, std::span<const double> t);

/// The signed area of a closed plane curve (algo/area.hpp). Throws
/// InvalidArgument("curve", ...) for a curve that is not 2-D or not closed.
[[nodiscard]] double area(const AnyCurve& c);

/// Inflections and cusps (2-D; empty otherwise) and per-axis extrema (algo/features.hpp).
[[nodiscard]] AnyFeatures features(const AnyCurve& c);

/// The minimum distance between two curves of one dimension (algo/distance.hpp).
/// Throws InvalidArgument("curves[1]", ...) when the dimensions differ.
[[nodiscard]] AnyDistance distance(const AnyCurve& a, const AnyCurve& b);

}  // namespace casteljau::io
