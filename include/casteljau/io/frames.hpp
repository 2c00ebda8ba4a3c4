// The `frames` command's library call: the moving frames of a space curve at increasing
// parameters, rotation-minimizing (algo/rmf.hpp) or Frenet (algo/frame.hpp). Compiled
// once, in src/io/frames.cpp.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/queries.hpp"

namespace casteljau::io {

/// As frames() of io/queries.hpp, but where the curvature is zero in 3-D or 4-D the frame
/// keeps its tangent and has no normal nor binormal: errors ("t[j]") only where the
/// velocity vanishes or a derivative is not representable. With `stopped` given, where
/// the velocity vanishes no error: stopped[j] = 1 and frame j has a zero tangent and no
/// normal (stopped[j] = 0 elsewhere). Defined in src/io/queries.cpp.
[[nodiscard]] AnyFrames frenet_frames(const AnyCurve& c, std::span<const double> t, std::vector<char>* stopped = nullptr);

/// Unit vectors, one per parameter; normals and binormals std::nullopt where the Frenet
/// frame has none, tangents too where the velocity vanishes (method frenet only).
struct MovingFrames {
  std::vector<std::optional<std::array<double, 3>>> tangents;
  std::vector<std::optional<std::array<double, 3>>> normals, binormals;
};

/// The frames of the 3-D curve c at the increasing parameters t, binormal = tangent x
/// normal. method "rotation_minimizing": double reflection (rotation_minimizing_normals_at)
/// on an internal grid of the curve's pieces refined until the frame carried across each
/// changes by less than 1e-10 rad, then onto the plane normal to the tangent at each t
/// (the frames do not depend on which other t are asked), from initial_normal projected onto the
/// plane normal to the tangent at t[0] and normalised, or without it from the Frenet
/// normal there; "frenet": the Frenet frames (io::frames), all three vectors null where
/// the velocity is zero. Errors: InvalidArgument "curve" (not 3-D), "method" (unknown),
/// "t[i]" (not after t[i-1]; rotation_minimizing: the velocity is zero there: no tangent), "initial_normal" (not 3 numbers, given with frenet, parallel
/// to the tangent at t[0] or zero; missing where the curve has no Frenet normal at t[0]).
[[nodiscard]] MovingFrames moving_frames(const AnyCurve& c, std::span<const double> t, const std::string& method,
                                         std::optional<std::span<const double>> initial_normal);

}  // namespace casteljau::io
