// Hermite<double, D> evaluation's search and lanes (curves/hermite.hpp, the declarations
// in its detail namespace), compiled once so that the public header carries no compiler
// builtins: the searches with their prefetches here, with the baseline flags (they are
// scalar), and the Hermite forms in the lane kernels of the instruction set chosen at run
// time (the one the batch evaluation kernels use: batch::active_isa, src/batch/dispatch.cpp).
#include "casteljau/curves/hermite_kernels.hpp"

#include <algorithm>

#include "casteljau/basis/batch.hpp"
#include "lanes.hpp"

namespace casteljau::detail {

namespace {

/// Requests the cache line of p (no effect on compilers without the builtin).
inline void prefetch(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

/// The number of first[0..len) that are <= x (first sorted): a branch-free binary search
/// keeping [base, base + len] around the answer, the two possible next probes prefetched.
std::size_t count_at_most(const double* first, std::size_t len, double x) {
  if (len == 0) return 0;
  const double* base = first;
  while (len > 1) {
    const std::size_t half = len / 2;
    len -= half;
    prefetch(base + len / 2);
    prefetch(base + half + len / 2);
    base = base[half] <= x ? base + half : base;
  }
  return static_cast<std::size_t>(base - first) + (*base <= x ? 1 : 0);
}

/// The answer of segment_index(u) lies in [start, start + len]: start + the number of
/// u_(start+1..start+len) that are <= u. Found in the coarse index (which stays in the
/// cache); the block's cache lines are requested at once, so that its search waits for
/// memory once.
struct Block {
  std::size_t start, len;
};
Block coarse_block(const HermiteArrays& c, double u) {
  const std::size_t m = count_at_most(c.coarse, c.coarse_count, u);  // coarse[j] = u_(64 j)
  if (m == 0) return {0, 0};  // before u_0
  const std::size_t start = hermite_stride * (m - 1);  // u_start <= u (< u_(start + 64) if sampled)
  const std::size_t stop = std::min(start + hermite_stride, c.count - 1);  // interior params below stop
  const std::size_t len = stop - start - 1;
  const double* block = c.params + start + 1;
  for (std::size_t k = 0; k < len; k += 64 / sizeof(double)) prefetch(block + k);
  return {start, len};
}

const hermite_lanes::Table& lanes() {
  switch (batch::active_isa()) {
#if CASTELJAU_KERNELS_MULTI
    case batch::Isa::avx512: return hermite_lanes::avx512::table;
    case batch::Isa::avx2: return hermite_lanes::avx2::table;
#endif
    default: return hermite_lanes::baseline::table;
  }
}

}  // namespace

std::size_t hermite_segment_index(const HermiteArrays& c, double u) {
  const Block b = coarse_block(c, u);
  return b.start + count_at_most(c.params + b.start + 1, b.len, u);
}

void hermite_locate(const HermiteArrays& c, const double* u, std::size_t count, std::size_t* piece) {
  constexpr std::size_t group = 16;
  const std::size_t D = static_cast<std::size_t>(c.dimension);
  Block blocks[group];
  for (std::size_t k0 = 0; k0 < count; k0 += group) {
    const std::size_t g = std::min(group, count - k0);
    for (std::size_t j = 0; j < g; ++j) blocks[j] = coarse_block(c, u[k0 + j]);  // prefetches the block
    for (std::size_t j = 0; j < g; ++j) {
      const std::size_t i = blocks[j].start + count_at_most(c.params + blocks[j].start + 1, blocks[j].len, u[k0 + j]);
      piece[k0 + j] = i;
      prefetch(c.params + i + 1);
      prefetch(c.points + i * D);
      prefetch(c.points + (i + 1) * D);
      prefetch(c.outgoing + i * D);
      prefetch(c.incoming + (i + 1) * D);
    }
  }
}

bool hermite_points(const HermiteArrays& c, const std::size_t* piece, const double* u, double* out, std::size_t count) {
  return lanes().points[c.dimension - 1](c.params, c.points, c.outgoing, c.incoming, piece, u, out, count);
}

bool hermite_point(const HermiteArrays& c, double u, double* out, std::size_t* piece) {
  *piece = hermite_segment_index(c, u);
  return hermite_points(c, piece, &u, out, 1);
}

}  // namespace casteljau::detail
