// Run-time entry of B-spline fitting (algo/fit.hpp), compiled once in src/io/fit.cpp.
#pragma once

#include <optional>
#include <vector>

#include "casteljau/curves/parametrization.hpp"
#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// The `fit` request at run time; derivatives have the points' dimension.
struct AnyFitRequest {
  int degree = 3;
  std::optional<std::size_t> control_points;
  std::optional<double> tolerance;
  Parametrization parametrization = Parametrization::chord;
  std::optional<std::vector<double>> start_derivative;
  std::optional<std::vector<double>> end_derivative;
  bool closed = false;
  /// A smoothing spline (algo/smoothing.hpp) instead of control_points / tolerance:
  /// lambda >= 0, or chosen by generalised cross-validation (smoothing_gcv).
  std::optional<double> smoothing;
  bool smoothing_gcv = false;
};

struct AnyFit {
  AnyCurve curve;
  double max_error = 0;
  std::optional<double> smoothing;  ///< the lambda of a smoothing fit (chosen, for gcv)
};

/// Fits a bspline to the points (dimension 1..max_dimension) as casteljau::fit does.
/// Errors name the request's fields ("points[k]", "degree", "control_points", ...).
[[nodiscard]] AnyFit fit(const PointList& points, const AnyFitRequest& request);

}  // namespace casteljau::io
