// The flattening methods, named apart from algo/flatten.hpp so that the run-time
// interfaces (io/any_curve.hpp) can name them without including the algorithm.
#pragma once

namespace casteljau {

/// How flatten() chooses its vertices (each guarantees the tolerance; see flatten()).
enum class FlattenMethod {
  uniform,      ///< equal parameter steps, their count from Wang's bound
  subdivision,  ///< recursive halving until the control points are within tolerance of the chord
  optimal,      ///< near the fewest segments: steps from the integral of sqrt(curvature), each checked exactly
};

}  // namespace casteljau
