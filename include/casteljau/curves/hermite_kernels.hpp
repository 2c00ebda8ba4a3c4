// The compiled kernels of Hermite<double, D> evaluation (curves/hermite.hpp), defined in
// src/hermite and built into casteljau::kernels: the searches with their prefetches, and
// the Hermite forms in vector lanes per instruction set, chosen at run time. Plain
// declarations, so that the public header carries no compiler builtins or vector types.
#pragma once

#include <cstddef>
#include <type_traits>

namespace casteljau::detail {

/// Params per entry of a Hermite curve's coarse index (u_0, u_64, u_128, ...).
inline constexpr std::size_t hermite_stride = 64;

/// Whether Hermite<T, D> evaluates through the compiled kernels below: double at the
/// dimensions the run-time interfaces serve (1..4). Other scalars and dimensions use the
/// portable templates of Hermite itself (the same expressions, no prefetching).
template <class T, int D>
inline constexpr bool hermite_compiled = std::is_same_v<T, double> && D >= 1 && D <= 4;

/// A Hermite<double, D> curve's arrays as plain doubles for the compiled kernels
/// (src/hermite, in casteljau::kernels): params u_0..u_n (`count` = n + 1), the coarse
/// index, and the points and the outgoing and incoming tangents, D doubles each.
struct HermiteArrays {
  const double* params;
  std::size_t count;
  const double* coarse;
  std::size_t coarse_count;
  const double* points;
  const double* outgoing;
  const double* incoming;
  int dimension;
};
/// Hermite::segment_index for double: the two branch-free searches, the block's cache
/// lines and both next probes prefetched.
std::size_t hermite_segment_index(const HermiteArrays& c, double u);
/// piece[j] = hermite_segment_index(c, u[j]) for j < count (finite u), the searches of up
/// to 16 queries side by side in stages, each prefetching what the next one needs (the
/// blocks, then the pieces' params, points and tangents), so that their misses overlap.
void hermite_locate(const HermiteArrays& c, const double* u, std::size_t count, std::size_t* piece);
/// Hermite::points_of for double: the points (D doubles each) at u[0..count) of the pieces
/// piece[0..count) into out; whether all are finite. Four queries per vector, with the
/// instruction set chosen at run time (batch::active_isa), one rounding per operation in
/// every set.
bool hermite_points(const HermiteArrays& c, const std::size_t* piece, const double* u, double* out, std::size_t count);
/// Hermite::operator() for double: the point at u (finite) into out (D doubles), its
/// piece into *piece; whether it is finite (hermite_segment_index, then hermite_points).
bool hermite_point(const HermiteArrays& c, double u, double* out, std::size_t* piece);

}  // namespace casteljau::detail
