// Private interface between the Hermite kernels compiled once (hermite.cpp) and their
// lane kernels, which lanes.inc defines once per instruction set (lanes_<isa>.cpp), as
// src/batch does for evaluation (docs/decisions/0004, 0006). Plain data and function
// pointers only.
#pragma once

#include <cstddef>

namespace casteljau::detail::hermite_lanes {

/// Hermite<double, D>::points_of for one D: the points at u[0..count) of the pieces
/// piece[0..count) into out (D doubles each), from the params uu, the points P and the
/// outgoing and incoming tangents mo, mi (D doubles each); whether all are finite.
using Points = bool (*)(const double* uu, const double* P, const double* mo, const double* mi, const std::size_t* piece, const double* u,
                        double* out, std::size_t count);

/// The kernels for D = 1..4 (points[D - 1]).
struct Table {
  Points points[4];
};

namespace baseline { extern const Table table; }
#if CASTELJAU_KERNELS_MULTI
namespace avx2 { extern const Table table; }
namespace avx512 { extern const Table table; }
#endif

}  // namespace casteljau::detail::hermite_lanes
