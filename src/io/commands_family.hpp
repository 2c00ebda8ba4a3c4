// The command families of the registry (io/commands.hpp), one source file each, and the
// small JSON writers they share (internal: not installed).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "casteljau/io/commands.hpp"

namespace casteljau::io::detail {

/// src/io/commands_curve.cpp: eval, split, elevate, to_bezier, flatten, insert_knot,
/// remove_knot, render.
std::span<const Command> curve_commands();
/// src/io/commands_query.cpp: bounds, length, param_at_length, project, features,
/// distance, area, intersect.
std::span<const Command> query_commands();
/// src/io/commands_points.cpp: subdivide, fit.
std::span<const Command> point_commands();

/// Points as an array of coordinate arrays.
inline OrderedJson points_json(const PointList& P) {
  OrderedJson a = OrderedJson::array();
  for (std::size_t i = 0; i < P.size(); ++i) {
    OrderedJson p = OrderedJson::array();
    for (const double x : P[i]) p.push_back(x);
    a.push_back(std::move(p));
  }
  return a;
}

inline OrderedJson numbers_json(const std::vector<double>& v) {
  OrderedJson a = OrderedJson::array();
  for (const double x : v) a.push_back(x);
  return a;
}

/// A finite number as JSON writes it (shortest round-trip form), for messages.
inline std::string number_text(double v) { return Json(v).dump(); }

}  // namespace casteljau::io::detail
