// Run-time operations on plain arrays of numbers, for front ends that hold arrays rather
// than JSON values (the Python package, python/_casteljau.cpp): a curve built from its
// arrays, and surface points at many parameters. Compiled in the io library next to the
// readers that instantiate the same templates (src/io/curve_json.cpp,
// src/io/surface_json.cpp), so that a front end instantiates none of them.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

struct AnySurface;  // io/surfaces.hpp

/// The curve of {"type": "cubic_spline", "params": params, "points": points, "boundary":
/// boundary} built from the arrays themselves: points row-major, params.size() rows of d
/// coordinates, boundary "natural", "not-a-knot" or "periodic". The caller checks the
/// values finite, at least 2 rows and d in 1..max_dimension; the spline's constructor
/// checks the rest (with its own messages: a caller wanting the reader's reads the JSON
/// form instead).
[[nodiscard]] AnyCurve cubic_spline_from_arrays(std::span<const double> params, const double* points, int d,
                                                std::string_view boundary);

/// The surface's points at (u[j], v[j]), j < n, into out (n rows of s.dim() numbers).
/// Outside the domain the end patches extrapolate, as the eval command. Throws
/// InvalidArgument naming "u[j]" for a parameter pair that is not finite.
void surface_points(const AnySurface& s, const double* u, const double* v, std::size_t n, double* out);

/// The partial derivatives of total order 0..k at (u[j], v[j]), j < n, into out: n blocks
/// of (k + 1)^2 s.dim() numbers in casteljau::detail::partials' layout (block j, entry
/// (a (k + 1) + b) s.dim() + c: coordinate c of d^(a+b) S / du^a dv^b; zero where a + b >
/// k), the eval command's values. Throws InvalidArgument naming "uv[j]" (a parameter pair
/// that is not finite, a pole of a rational surface).
void surface_partials(const AnySurface& s, const double* u, const double* v, std::size_t n, int k, double* out);

}  // namespace casteljau::io
