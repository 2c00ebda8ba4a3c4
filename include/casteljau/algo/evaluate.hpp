// Batch evaluation: one curve at many parameters, or many curves at the same parameters,
// into structure-of-arrays or array-of-points output. Pure functions over the caller's
// buffers: safe to call from several threads on disjoint outputs.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "casteljau/basis/batch.hpp"
#include "casteljau/curves/bezier.hpp"

namespace casteljau {

/// How batch evaluation writes its output. `streaming` bypasses the caches with
/// non-temporal stores (x86 SSE2 and up, double only; elsewhere the same as cached): the
/// right choice for outputs much larger than the caches that are not read back at once.
/// `automatic` streams when one call writes at least 8 MiB (so the many-curves overload
/// decides on its whole output, not per curve).
enum class Store { automatic, cached, streaming };

/// The batch fast path: the power form with Horner's rule for degree <= 3, where the
/// conversion is accurate (max error 7.7e-16 measured at degree 3 on unit-box data against
/// MPFR, tests/reference; docs/accuracy.md); above that, de Casteljau vectorised across parameters, which keeps
/// de Casteljau's accuracy at every degree (6.7e-16 at degree 40 on unit-box data).
inline constexpr int horner_max_degree = 3;

namespace detail {

/// 8 MiB: well past the per-core L2 (1-2 MiB on current x86), so output this large would
/// only evict the caller's working set. Below it, cached stores are as fast and leave the
/// result in cache for a caller that reads it back.
inline constexpr std::size_t streaming_threshold_bytes = std::size_t{8} << 20;

template <class T>
bool use_streaming(Store s, std::size_t bytes) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>) {
    return s == Store::streaming || (s == Store::automatic && bytes >= streaming_threshold_bytes);
  }
#endif
  (void)s;
  (void)bytes;
  return false;
}

#if defined(__SSE2__)
/// Non-temporal copies of m doubles from src to dst, with regular stores up to the first
/// address aligned to the vector width and after the last full vector. The caller issues
/// the fence. The widest store wins: with 64-byte (full cache line) streaming stores W1
/// runs about 15% faster than with 16-byte ones (docs/performance.md).
inline std::size_t stream_head(const double* dst, std::size_t m, std::size_t align) {
  const std::size_t mis = static_cast<std::size_t>(reinterpret_cast<std::uintptr_t>(dst) % align);
  if (mis % sizeof(double) != 0) return m;  // not even double-aligned: store it all normally
  return mis == 0 ? 0 : std::min(m, (align - mis) / sizeof(double));
}

inline void stream_doubles_sse2(double* dst, const double* src, std::size_t m) {
  std::size_t l = stream_head(dst, m, 16);
  for (std::size_t k = 0; k < l; ++k) dst[k] = src[k];
  for (; l + 2 <= m; l += 2) _mm_stream_pd(dst + l, _mm_loadu_pd(src + l));
  for (; l < m; ++l) dst[l] = src[l];
}

// AVX-512 stores: compiled in when the target has AVX-512F; with GCC or Clang on x86-64
// also compiled for a generic target (function-level target attribute) and chosen at run
// time, so that a distribution build gets full-line stores on CPUs that have them.
#if defined(__AVX512F__)
#define CASTELJAU_STREAM_AVX512 1
#define CASTELJAU_TARGET_AVX512
#elif defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CASTELJAU_STREAM_AVX512 2
#define CASTELJAU_TARGET_AVX512 __attribute__((target("avx512f")))
#endif

#if defined(CASTELJAU_STREAM_AVX512)
CASTELJAU_TARGET_AVX512 inline void stream_doubles_avx512(double* dst, const double* src, std::size_t m) {
  std::size_t l = stream_head(dst, m, 64);
  for (std::size_t k = 0; k < l; ++k) dst[k] = src[k];
  for (; l + 8 <= m; l += 8) _mm512_stream_pd(dst + l, _mm512_loadu_pd(src + l));
  for (; l < m; ++l) dst[l] = src[l];
}
#endif

inline void stream_doubles(double* dst, const double* src, std::size_t m) {
#if defined(CASTELJAU_STREAM_AVX512) && CASTELJAU_STREAM_AVX512 == 1
  stream_doubles_avx512(dst, src, m);
#elif defined(CASTELJAU_STREAM_AVX512) && CASTELJAU_STREAM_AVX512 == 2
  if (__builtin_cpu_supports("avx512f")) {
    stream_doubles_avx512(dst, src, m);
  } else {
    stream_doubles_sse2(dst, src, m);
  }
#else
  stream_doubles_sse2(dst, src, m);
#endif
}
#undef CASTELJAU_STREAM_AVX512
#undef CASTELJAU_TARGET_AVX512
#endif

/// Copies m values to dst, with non-temporal stores when `stream` (double on x86; the
/// caller issues the fence).
template <class T>
inline void store_block(T* dst, const T* src, std::size_t m, bool stream) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>) {
    if (stream) {
      stream_doubles(dst, src, m);
      return;
    }
  }
#endif
  (void)stream;
  std::memcpy(dst, src, m * sizeof(T));
}

inline void store_fence(bool stream) {
#if defined(__SSE2__)
  if (stream) _mm_sfence();
#else
  (void)stream;
#endif
}

/// Per-curve coefficients for the kernels, laid out coefficient-major per coordinate: the
/// power coefficients for Horner (degree <= horner_max_degree, held inline: no allocation,
/// which matters when many small curves are evaluated), else the control point
/// coordinates.
template <class T, int D>
struct Prepared {
  int n;
  bool horner;
  std::array<std::array<T, horner_max_degree + 1>, std::size_t(D)> power{};
  std::vector<T> points;  // de Casteljau path: coordinate d at points[d * (n + 1) + i]

  explicit Prepared(const Bezier<T, D>& c) : n(c.degree()), horner(n <= horner_max_degree) {
    const auto& P = c.points();
    if (horner) {
      // a_j = sum_{i <= j} (-1)^(j-i) C(n, j) C(j, i) P_i, the same sum in the same order as
      // Bezier::to_power() (M from bernstein_to_power_matrix), without its heap matrices.
      constexpr int binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
      for (int j = 0; j <= n; ++j)
        for (int d = 0; d < D; ++d) {
          T s{};
          for (int i = 0; i <= j; ++i) {
            const T v = static_cast<T>(binom[n][j]) * static_cast<T>(binom[j][i]);
            s += ((j - i) % 2 == 0 ? v : -v) * P[static_cast<std::size_t>(i)][d];
          }
          power[static_cast<std::size_t>(d)][static_cast<std::size_t>(j)] = s;
        }
    } else {
      const std::size_t m = P.size();
      points.resize(m * std::size_t(D));
      for (std::size_t i = 0; i < m; ++i)
        for (int d = 0; d < D; ++d) points[static_cast<std::size_t>(d) * m + i] = P[i][d];
    }
  }

  /// Scratch values block_eval needs: none for Horner, (n + 1) x block for de Casteljau.
  [[nodiscard]] std::size_t work_size() const { return horner ? 0 : (static_cast<std::size_t>(n) + 1) * batch::block; }

  /// Coordinate d at ts[0..m), m <= block, into out (which may be ts itself).
  void block_eval(int d, const T* ts, T* out, std::size_t m, T* work) const {
    if (horner) {
      const T* a = power[static_cast<std::size_t>(d)].data();
      const auto o = reinterpret_cast<std::uintptr_t>(out), t = reinterpret_cast<std::uintptr_t>(ts);
      if (m == batch::block && (o + m * sizeof(T) <= t || t + m * sizeof(T) <= o)) {  // full block, no overlap
        switch (n) {
          case 0: for (std::size_t l = 0; l < batch::block; ++l) out[l] = a[0]; break;
          case 1: batch::horner_fixed_block<1>(a, ts, out); break;
          case 2: batch::horner_fixed_block<2>(a, ts, out); break;
          default: batch::horner_fixed_block<3>(a, ts, out); break;
        }
        return;
      }
      switch (n) {
        case 0: for (std::size_t l = 0; l < m; ++l) out[l] = a[0]; break;
        case 1: batch::horner_fixed<1>(a, ts, out, m); break;
        case 2: batch::horner_fixed<2>(a, ts, out, m); break;
        default: batch::horner_fixed<3>(a, ts, out, m); break;
      }
    } else {
      batch::de_casteljau_block(points.data() + static_cast<std::size_t>(d) * (static_cast<std::size_t>(n) + 1), n, ts, out, m, work);
    }
  }
};

/// Throws for the first non-finite parameter, naming t[j]. The scan is branch-free so that
/// it vectorises (t - t is 0 for finite t, NaN for an infinity or NaN): a loop that may exit
/// early at each element cost 20% of W1's per-curve calls. The message is built only on
/// failure.
template <class T>
void require_finite_params(std::span<const T> ts) {
  std::uint64_t bad = 0;  // a bool accumulator does not vectorise with GCC 12
  for (std::size_t j = 0; j < ts.size(); ++j) bad |= !(ts[j] - ts[j] == T(0));
  if (bad == 0) return;
  for (std::size_t j = 0; j < ts.size(); ++j)
    if (!std::isfinite(ts[j])) require_finite(ts[j], "t[" + std::to_string(j) + "]");
}

/// The kernels (plain C++ that the compiler vectorises) write each block into an L1 buffer
/// that is then copied out, with non-temporal stores when `stream`: only the copy needs
/// intrinsics, and the buffer cannot overlap ts, so full blocks take the check-free kernels.
template <class T, int D>
void evaluate_soa_prepared(const Prepared<T, D>& p, std::span<const T> ts, const std::array<T*, std::size_t(D)>& out, bool stream,
                           std::vector<T>& work) {
  alignas(64) T buf[batch::block];
  for (std::size_t off = 0; off < ts.size(); off += batch::block) {
    const std::size_t m = std::min(batch::block, ts.size() - off);
    for (int d = 0; d < D; ++d) {
      p.block_eval(d, ts.data() + off, buf, m, work.data());
      store_block(out[static_cast<std::size_t>(d)] + off, buf, m, stream);
    }
  }
}

}  // namespace detail

/// Evaluates c at every ts[j] into out[d][j] (structure of arrays: one span per
/// coordinate, each of ts.size() values). Same results as c(t) up to the fast path's
/// accuracy (see horner_max_degree). Throws InvalidArgument for a non-finite parameter
/// or a wrongly sized output span. Cost O(n) per parameter for n <= 3, O(n^2) above.
template <class T, int D>
void evaluate(const Bezier<T, D>& c, std::span<const T> ts, std::array<std::span<T>, std::size_t(D)> out, Store store = Store::automatic) {
  detail::require_finite_params(ts);
  std::array<T*, std::size_t(D)> ptr;
  for (int d = 0; d < D; ++d) {
    if (out[d].size() != ts.size()) {
      throw InvalidArgument("out[" + std::to_string(d) + "]", "needs one value per parameter: " + std::to_string(ts.size()) +
                                                                  " parameters, " + std::to_string(out[d].size()) + " values");
    }
    ptr[d] = out[d].data();
  }
  const detail::Prepared<T, D> p(c);
  std::vector<T> work(p.work_size());
  const bool stream = detail::use_streaming<T>(store, ts.size() * D * sizeof(T));
  detail::evaluate_soa_prepared(p, ts, ptr, stream, work);
  detail::store_fence(stream);
}

/// Evaluates every curve at the same parameters, curve-major: out[d][i * ts.size() + j] is
/// coordinate d of curves[i] at ts[j]. The curves may have different degrees.
template <class T, int D>
void evaluate(std::span<const Bezier<T, D>> curves, std::span<const T> ts, std::array<std::span<T>, std::size_t(D)> out,
              Store store = Store::automatic) {
  detail::require_finite_params(ts);
  const std::size_t total = curves.size() * ts.size();
  for (int d = 0; d < D; ++d) {
    if (out[d].size() != total) {
      throw InvalidArgument("out[" + std::to_string(d) + "]", "needs curves x parameters = " + std::to_string(total) +
                                                                  " values, got " + std::to_string(out[d].size()));
    }
  }
  const bool stream = detail::use_streaming<T>(store, total * D * sizeof(T));
  std::vector<T> work;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const detail::Prepared<T, D> p(curves[i]);
    if (work.size() < p.work_size()) work.resize(p.work_size());
    std::array<T*, std::size_t(D)> ptr;
    for (int d = 0; d < D; ++d) ptr[d] = out[d].data() + i * ts.size();
    detail::evaluate_soa_prepared(p, ts, ptr, stream, work);
  }
  detail::store_fence(stream);
}

/// Evaluates c at every ts[j] into out[j] (array of points).
template <class T, int D>
void evaluate(const Bezier<T, D>& c, std::span<const T> ts, std::span<Point<T, D>> out) {
  detail::require_finite_params(ts);
  if (out.size() != ts.size()) {
    throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                     std::to_string(out.size()) + " points");
  }
  const detail::Prepared<T, D> p(c);
  std::vector<T> work(p.work_size());
  alignas(64) T buf[D][batch::block];
  for (std::size_t off = 0; off < ts.size(); off += batch::block) {
    const std::size_t m = std::min(batch::block, ts.size() - off);
    for (int d = 0; d < D; ++d) p.block_eval(d, ts.data() + off, buf[d], m, work.data());
    for (std::size_t l = 0; l < m; ++l)
      for (int d = 0; d < D; ++d) out[off + l][d] = buf[d][l];
  }
}

/// Any curve at many parameters, one call of c(t) each: the generic fallback.
template <Curve C>
void evaluate(const C& c, std::span<const typename C::Scalar> ts, std::span<Point<typename C::Scalar, C::dimension>> out) {
  if (out.size() != ts.size()) {
    throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                     std::to_string(out.size()) + " points");
  }
  for (std::size_t j = 0; j < ts.size(); ++j) out[j] = c(ts[j]);
}

}  // namespace casteljau
