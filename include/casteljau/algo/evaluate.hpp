// Batch evaluation: one curve at many parameters, or many curves at the same parameters,
// into structure-of-arrays or array-of-points output. Pure functions over the caller's
// buffers: safe to call from several threads on disjoint outputs.
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "casteljau/basis/batch.hpp"
#include "casteljau/curves/bezier.hpp"

namespace casteljau {

/// How batch evaluation writes its output. `streaming` bypasses the caches with
/// non-temporal stores (x86 SSE2, double only; elsewhere the same as cached): the right
/// choice for outputs much larger than the caches that are not read back at once.
/// `automatic` streams when one call writes at least 8 MiB.
enum class Store { automatic, cached, streaming };

/// The batch fast path: the power form with Horner's rule for degree <= 3, where the
/// conversion is accurate (max error 4.4e-16 x max |P| measured at degree 3, documented in
/// docs/accuracy.md); above that, de Casteljau vectorised across parameters, which keeps
/// de Casteljau's accuracy at every degree (6.7e-16 at degree 40 on unit-box data).
inline constexpr int horner_max_degree = 3;

namespace detail {

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

/// Copies m values to dst, with non-temporal stores when `stream` and dst is 16-byte
/// aligned (the caller issues the fence).
template <class T>
inline void store_block(T* dst, const T* src, std::size_t m, bool stream) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>) {
    if (stream && (reinterpret_cast<std::uintptr_t>(dst) % 16) == 0) {
      std::size_t l = 0;
      for (; l + 2 <= m; l += 2) _mm_stream_pd(dst + l, _mm_loadu_pd(src + l));
      for (; l < m; ++l) dst[l] = src[l];
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

/// Per-curve coefficients for the kernels: power coefficients for Horner, else the
/// control point coordinates, laid out coefficient-major per coordinate.
template <class T, int D>
struct Prepared {
  int n;
  bool horner;
  std::array<std::vector<T>, D> coef;

  explicit Prepared(const Bezier<T, D>& c) : n(c.degree()), horner(n <= horner_max_degree) {
    for (auto& v : coef) v.resize(static_cast<std::size_t>(n) + 1);
    if (horner) {
      const auto a = c.to_power();
      for (int j = 0; j <= n; ++j)
        for (int d = 0; d < D; ++d) coef[d][j] = a[j][d];
    } else {
      for (int j = 0; j <= n; ++j)
        for (int d = 0; d < D; ++d) coef[d][j] = c.points()[j][d];
    }
  }

  /// Coordinate d at ts[0..m), m <= block, into out.
  void block_eval(int d, const T* ts, T* out, std::size_t m, T* work) const {
    const T* a = coef[d].data();
    if (horner) {
      switch (n) {
        case 0: for (std::size_t l = 0; l < m; ++l) out[l] = a[0]; break;
        case 1: batch::horner_fixed<1>(a, ts, out, m); break;
        case 2: batch::horner_fixed<2>(a, ts, out, m); break;
        default: batch::horner_fixed<3>(a, ts, out, m); break;
      }
    } else {
      batch::de_casteljau_block(a, n, ts, out, m, work);
    }
  }
};

template <class T>
void require_finite_params(std::span<const T> ts) {
  for (std::size_t j = 0; j < ts.size(); ++j) require_finite(ts[j], "t[" + std::to_string(j) + "]");
}

template <class T, int D>
void evaluate_soa_prepared(const Prepared<T, D>& p, std::span<const T> ts, const std::array<T*, std::size_t(D)>& out, bool stream,
                           std::vector<T>& work) {
  alignas(64) T buf[batch::block];
  for (std::size_t off = 0; off < ts.size(); off += batch::block) {
    const std::size_t m = std::min(batch::block, ts.size() - off);
    for (int d = 0; d < D; ++d) {
      p.block_eval(d, ts.data() + off, buf, m, work.data());
      store_block(out[d] + off, buf, m, stream);
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
  std::vector<T> work((static_cast<std::size_t>(c.degree()) + 1) * batch::block);
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
    work.resize((static_cast<std::size_t>(p.n) + 1) * batch::block);
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
  std::vector<T> work((static_cast<std::size_t>(c.degree()) + 1) * batch::block);
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
