// Evaluation kernels for one coordinate of a polynomial at many parameters, written so
// that the compiler vectorises them across parameters (inner loops over a block of
// parameters with no dependence between lanes; checked with -fopt-info-vec).
#pragma once

#include <cstddef>

namespace casteljau::batch {

/// Parameters are processed in blocks of this many: 64 doubles = 512 bytes per buffer,
/// so the de Casteljau work array of degree 40 (41 x 64 doubles, 21 KiB) stays in L1.
inline constexpr std::size_t block = 64;

/// out[l] = sum_j a[j] ts[l]^j by Horner's rule, degree N fixed at compile time so the
/// coefficients stay in registers, for l < m <= block.
/// The coefficients are copied to locals first, so the loop reads only ts and writes only
/// out: out may even be ts itself (element l is read before it is written).
template <int N, class T>
inline void horner_fixed(const T* a, const T* ts, T* out, std::size_t m) {
  T c[N + 1];
  for (int j = 0; j <= N; ++j) c[j] = a[j];
  for (std::size_t l = 0; l < m; ++l) {
    const T t = ts[l];
    T r = c[N];
    for (int j = N - 1; j >= 0; --j) r = r * t + c[j];
    out[l] = r;
  }
}

/// horner_fixed on a full block (m = block) into out, which must not overlap ts or a. The
/// constant trip count and the no-overlap promise let compilers vectorise this without
/// run-time checks, so it vectorises even under GCC's -O2 "very cheap" cost model.
template <int N, class T>
inline void horner_fixed_block(const T* __restrict a, const T* __restrict ts, T* __restrict out) {
  T c[N + 1];
  for (int j = 0; j <= N; ++j) c[j] = a[j];
  for (std::size_t l = 0; l < block; ++l) {
    const T t = ts[l];
    T r = c[N];
    for (int j = N - 1; j >= 0; --j) r = r * t + c[j];
    out[l] = r;
  }
}

/// out[l] = the Bernstein form c[0..n] at ts[l] by de Casteljau, vectorised across the
/// parameters of one block (m <= block). Same arithmetic, so the same accuracy, as the
/// scalar de Casteljau. work must hold (n + 1) * block values. Cost n(n+1)/2 lerps per
/// parameter.
template <class T>
inline void de_casteljau_block(const T* c, int n, const T* ts, T* out, std::size_t m, T* work) {
  for (int i = 0; i <= n; ++i)
    for (std::size_t l = 0; l < m; ++l) work[static_cast<std::size_t>(i) * block + l] = c[i];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i + r <= n; ++i) {
      T* __restrict w0 = work + static_cast<std::size_t>(i) * block;
      const T* __restrict w1 = work + static_cast<std::size_t>(i + 1) * block;
      for (std::size_t l = 0; l < m; ++l) w0[l] = (1 - ts[l]) * w0[l] + ts[l] * w1[l];
    }
  }
  for (std::size_t l = 0; l < m; ++l) out[l] = work[l];
}

}  // namespace casteljau::batch
