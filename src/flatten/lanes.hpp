// Private interface between the plane flattening walk (plane.cpp) and its lane kernels,
// which lanes.inc defines once per instruction set (lanes_<isa>.cpp), as src/batch does
// for evaluation (docs/decisions/0004, 0006). Plain data and function pointers only.
#pragma once

#include "casteljau/algo/flatten/plane_plan.hpp"

namespace casteljau::detail::flatten_lanes {

/// A block of small_optimal_batched (4 or 8 vertices; see small_optimal_block_plain): the
/// plan, its power-form coefficients a = {a0x, a0y, a1x, a1y, a2x, a2y, a3x, a3y} (plain
/// doubles, so that the per-ISA files instantiate no accessor of the point types), the
/// count's base and step, the first vertex's index, tol^2, and the arrays [0 .. block].
using Block = unsigned (*)(const SmallOptimalPlan<double>& plan, const double* a, double f_base, double df, double first, double tol2,
                           double* bt, double* bx, double* by, double* bdx, double* bdy);
/// A block of the parabola walk (optimal_block vertices, arrays [0 .. optimal_block)).
using ParabolaBlock = unsigned (*)(const SmallOptimalPlan<double>& plan, const double* a, double f_base, double df, double first, double tp,
                                   double* bt, double* bx, double* by);

struct Table {
  Block block4;
  Block block8;
  ParabolaBlock parabola;
};

#if defined(__GNUC__)
namespace baseline { extern const Table table; }
#endif
#if CASTELJAU_KERNELS_MULTI
namespace avx2 { extern const Table table; }
namespace avx512 { extern const Table table; }
#endif

}  // namespace casteljau::detail::flatten_lanes
