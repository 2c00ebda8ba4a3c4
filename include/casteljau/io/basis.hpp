// The run-time face of basis/basis_kinds.hpp: the `basis` command's request read into a
// BasisSpec, checked, and tabulated. Compiled once, in src/io/basis.cpp.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/basis_kinds.hpp"

namespace casteljau::io {

/// The kinds' names, in the order of BasisKind: bernstein, bspline, lagrange, hermite,
/// catmull_rom, cardinal, uniform_bspline.
[[nodiscard]] std::span<const std::string_view> basis_kind_names();

/// The table of the basis `kind` (one of basis_kind_names) at t with derivatives 0..k
/// (basis_table). Each kind takes only its own fields: degree (bernstein, bspline),
/// knots (bspline), params (lagrange), tension (cardinal). Errors: InvalidArgument
/// "kind" (unknown), "degree" / "knots" / "params" / "tension" (missing, given to a
/// kind that has no such field, or invalid: check_basis), "t[i]" (not finite),
/// "derivatives" (< 0), "t" (more than 1e7 numbers to answer).
[[nodiscard]] BasisTable basis(const std::string& kind, std::optional<int> degree, const std::optional<std::vector<double>>& knots,
                               const std::optional<std::vector<double>>& params, std::optional<double> tension,
                               std::span<const double> t, int k);

}  // namespace casteljau::io
