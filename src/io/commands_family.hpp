// The command families of the registry (io/commands.hpp), one source file each
// (internal: not installed). Results are written by the to_json of io/results.hpp.
#pragma once

#include <span>
#include <string>

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
/// src/io/commands_ops.cpp: solve, refine, to_bspline, reduce, basis, frames, offset (issue 20).
std::span<const Command> ops_commands();
/// src/io/commands_svg_import.cpp: import_svg (issue 17).
std::span<const Command> svg_import_commands();
/// src/io/commands_outlines.cpp: to_svg_path, glyph (issue 17).
std::span<const Command> outline_commands();

/// src/io/commands_surface.cpp: surface, isocurve (issue 19).
std::span<const Command> surface_commands();
/// src/io/commands_surface.cpp: the surface forms of eval, split, elevate, insert_knot,
/// to_bezier, bounds, area (io::surface_form).
std::span<const Command> surface_forms();
/// src/io/commands_surface_mesh.cpp: tessellate (issue 19).
std::span<const Command> surface_mesh_commands();
/// src/io/commands_surface_mesh.cpp: the surface form of render.
std::span<const Command> surface_mesh_forms();

/// A finite number as JSON writes it (shortest round-trip form), for messages.
inline std::string number_text(double v) { return Json(v).dump(); }

}  // namespace casteljau::io::detail
