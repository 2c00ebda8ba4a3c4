// The surface registry and the run-time operations on surfaces (compiled once, in the
// `surfaces` unity group of casteljau::io: src/io/surface_json.cpp and
// src/io/commands_surface.cpp).
//
// A run-time surface is its kind (one registry entry per type: bezier_surface,
// rational_bezier_surface, bspline_surface, nurbs_surface) and its checked
// casteljau::detail::SurfaceForm<double>, whose dimension is a run-time value: the algorithms of
// surfaces/surface_form.hpp are compiled once for every type and dimension 1..4, instead
// of once per (type x dimension) as the curves' variant does.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/json.hpp"
#include "casteljau/surfaces/surface.hpp"

namespace casteljau::io {

/// A surface of any registered kind at dimension 1..max_dimension.
struct AnySurface {
  SurfaceKind kind = SurfaceKind::bezier;
  casteljau::detail::SurfaceForm<double> form;  ///< checked (casteljau::detail::check_surface_form)

  [[nodiscard]] int dim() const { return static_cast<int>(form.cartesian()); }
  [[nodiscard]] bool is_bezier() const { return kind == SurfaceKind::bezier || kind == SurfaceKind::rational_bezier; }
};

/// The registry's names: "bezier_surface", "rational_bezier_surface", "bspline_surface",
/// "nurbs_surface".
[[nodiscard]] std::string_view type_name(SurfaceKind k);
[[nodiscard]] std::span<const std::string_view> surface_type_names();

/// One registered surface type as the bindings see it: its kind, surface-JSON name and the
/// fields of its object ("type" first, in the order the reader lists them; the Python
/// constructor's arguments).
struct SurfaceTypeInfo {
  SurfaceKind kind;
  std::string_view name;
  std::span<const std::string_view> fields;
};
/// Every registered surface type (the reader checks surface JSON against the same lists).
[[nodiscard]] std::span<const SurfaceTypeInfo> surface_types();

/// The surface of a form of the kind (rationality must agree; a Bézier kind's knots are
/// put on [0, 1]); checked, errors naming the grid.
[[nodiscard]] AnySurface make_surface(SurfaceKind kind, casteljau::detail::SurfaceForm<double> form);

/// A surface object (surface JSON): type, points grid, weights, degree, knots, dim; every
/// error names its path relative to the object ("points[2]", "knots[1][4]").
[[nodiscard]] AnySurface surface_from_json(const Json& j);
[[nodiscard]] OrderedJson to_json(const AnySurface& s);

/// The limit normal of a 3-D surface at (u, v) (casteljau::detail::limit_normal: the unit
/// normal where defined, else the limit at a degenerate edge where it exists); error
/// InvalidArgument("normal") for another dimension.
[[nodiscard]] std::optional<std::array<double, 3>> limit_normal(const AnySurface& s, double u, double v);

/// Any curve as one B-spline form (degree, knots, homogeneous points when rational), the
/// same curve on its domain (io::to_bspline).
[[nodiscard]] casteljau::detail::CurveForm<double> curve_form(const AnyCurve& c);
/// A curve form as curve JSON of the kind's isocurve type (bezier, rational_bezier,
/// bspline, nurbs).
[[nodiscard]] OrderedJson curve_form_json(const casteljau::detail::CurveForm<double>& c, bool bezier);

}  // namespace casteljau::io
