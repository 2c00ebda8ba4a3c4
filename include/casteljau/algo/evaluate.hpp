// Batch evaluation: one curve at many parameters, or many curves at the same parameters,
// into structure-of-arrays or array-of-points output. Pure functions over the caller's
// buffers: safe to call from several threads on disjoint outputs.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/basis/batch.hpp"
#include "casteljau/curves/bezier.hpp"

namespace casteljau {

/// How batch evaluation writes its output. `streaming` bypasses the caches with
/// non-temporal stores (x86, float and double; elsewhere the same as cached): the right
/// choice for outputs much larger than the caches that are not read back at once.
/// `automatic` streams when one call writes at least 8 MiB (so the many-curves overload
/// decides on its whole output, not per curve).
enum class Store { automatic, cached, streaming };

/// The batch fast path's methods by degree (basis/batch.hpp): the power form with
/// Horner's rule up to this degree, then Bernstein-Horner, then de Casteljau.
inline constexpr int horner_max_degree = batch::horner_max_degree;

namespace detail {

/// 8 MiB: well past the per-core L2 (1-2 MiB on current x86), so output this large would
/// only evict the caller's working set. Below it, cached stores are as fast and leave the
/// result in cache for a caller that reads it back.
inline constexpr std::size_t streaming_threshold_bytes = std::size_t{8} << 20;

inline bool use_streaming(Store s, std::size_t bytes) {
  return s == Store::streaming || (s == Store::automatic && bytes >= streaming_threshold_bytes);
}

/// The scalar types the compiled kernels take; any other type evaluates point by point.
template <class T>
inline constexpr bool has_kernels = std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, long double>;

/// The control point coordinates, point-major (P_i[d] at [i * D + d]), as the kernels take
/// them: on the stack up to 256 values (degree 63 in the plane), else on the heap.
template <class T, int D>
class PackedPoints {
 public:
  explicit PackedPoints(const Bezier<T, D>& c) {
    const auto& P = c.points();
    const std::size_t size = P.size() * std::size_t(D);
    T* p = local_.data();
    if (size > local_.size()) {
      heap_.resize(size);
      p = heap_.data();
    }
    for (std::size_t i = 0; i < P.size(); ++i)
      for (int d = 0; d < D; ++d) p[i * std::size_t(D) + static_cast<std::size_t>(d)] = P[i][d];
    data_ = p;
  }
  PackedPoints(const PackedPoints&) = delete;
  PackedPoints& operator=(const PackedPoints&) = delete;
  [[nodiscard]] const T* data() const { return data_; }

 private:
  std::array<T, 256> local_;
  std::vector<T> heap_;
  const T* data_ = nullptr;
};

/// Throws for the first non-finite parameter, naming t[j]. The common case (all finite)
/// is one vectorised scan in the compiled kernels (batch::all_finite); the message is
/// built only on failure.
template <class T>
void require_finite_params(std::span<const T> ts) {
  if constexpr (has_kernels<T>) {
    if (batch::all_finite(ts.data(), ts.size())) return;
  }
  for (std::size_t j = 0; j < ts.size(); ++j)
    if (!std::isfinite(ts[j])) require_finite(ts[j], "t[" + std::to_string(j) + "]");
}

/// The indices j with ts[j] outside [0, 1]. There the kernels' de Casteljau (or power
/// form) extrapolates without the scaling of Bezier::operator() and can overflow to NaN
/// far out (3t at t = 1e200); those points are recomputed by c(t), which is exact there
/// or throws when the value is not representable. One scan of the parameters per call.
template <class T>
std::vector<std::size_t> outside_unit_interval(std::span<const T> ts) {
  std::vector<std::size_t> idx;
  for (std::size_t j = 0; j < ts.size(); ++j) {
    if (!(ts[j] >= 0 && ts[j] <= 1)) idx.push_back(j);
  }
  return idx;
}

/// Rewrites the points of curve c at the parameters `outside` through c(t), naming t[j]
/// in an error.
template <class T, int D, class Write>
void extrapolate_exactly(const Bezier<T, D>& c, std::span<const T> ts, const std::vector<std::size_t>& outside, Write&& write) {
  for (const std::size_t j : outside) {
    try {
      write(j, c(ts[j]));
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("t[" + std::to_string(j) + "]", e.problem());
    }
  }
}

}  // namespace detail

/// Evaluates c at every ts[j] into out[d][j] (structure of arrays: one span per
/// coordinate, each of ts.size() values). Same results as c(t) up to the fast path's
/// accuracy (basis/batch.hpp: within a few eps of max |P| for t in [0, 1]); parameters
/// outside [0, 1] are evaluated as c(t) does (exact extrapolation, or InvalidArgument
/// naming t[j] when the value is not representable). Throws InvalidArgument for a
/// non-finite parameter or a wrongly sized output span. Cost O(n)
/// per parameter up to batch::bernstein_horner_max_degree and for t in [0, 1], O(n^2)
/// otherwise. float, double and long double run the compiled kernels
/// (casteljau::kernels, chosen for the CPU at run time); other scalar types call c(t).
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
  const bool stream = detail::use_streaming(store, ts.size() * D * sizeof(T));
  if constexpr (detail::has_kernels<T>) {
    const detail::PackedPoints<T, D> P(c);
    batch::evaluate_soa(P.data(), c.degree(), D, ts.data(), ts.size(), ptr.data(), stream);
    if (stream) batch::store_fence();
    detail::extrapolate_exactly(c, ts, detail::outside_unit_interval(ts), [&](std::size_t j, const Point<T, D>& p) {
      for (int d = 0; d < D; ++d) ptr[static_cast<std::size_t>(d)][j] = p[d];
    });
  } else {
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const auto p = c(ts[j]);
      for (int d = 0; d < D; ++d) ptr[static_cast<std::size_t>(d)][j] = p[d];
    }
  }
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
  const bool stream = detail::use_streaming(store, total * D * sizeof(T));
  std::vector<std::size_t> outside;
  if constexpr (detail::has_kernels<T>) outside = detail::outside_unit_interval(ts);
  for (std::size_t i = 0; i < curves.size(); ++i) {
    std::array<T*, std::size_t(D)> ptr;
    for (int d = 0; d < D; ++d) ptr[static_cast<std::size_t>(d)] = out[static_cast<std::size_t>(d)].data() + i * ts.size();
    if constexpr (detail::has_kernels<T>) {
      const detail::PackedPoints<T, D> P(curves[i]);
      batch::evaluate_soa(P.data(), curves[i].degree(), D, ts.data(), ts.size(), ptr.data(), stream);
      detail::extrapolate_exactly(curves[i], ts, outside, [&](std::size_t j, const Point<T, D>& p) {
        for (int d = 0; d < D; ++d) ptr[static_cast<std::size_t>(d)][j] = p[d];
      });
    } else {
      for (std::size_t j = 0; j < ts.size(); ++j) {
        const auto p = curves[i](ts[j]);
        for (int d = 0; d < D; ++d) ptr[static_cast<std::size_t>(d)][j] = p[d];
      }
    }
  }
  if constexpr (detail::has_kernels<T>) {
    if (stream) batch::store_fence();
  }
}

/// Evaluates c at every ts[j] into out[j] (array of points).
template <class T, int D>
void evaluate(const Bezier<T, D>& c, std::span<const T> ts, std::span<Point<T, D>> out) {
  detail::require_finite_params(ts);
  if (out.size() != ts.size()) {
    throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                     std::to_string(out.size()) + " points");
  }
  if constexpr (detail::has_kernels<T>) {
    // Through the SoA kernel in chunks of 512 parameters on the stack (8 KiB in the plane),
    // then interleaved: no allocation, and the chunk stays in L1.
    constexpr std::size_t chunk = 8 * batch::block;
    std::array<std::array<T, chunk>, std::size_t(D)> buf;
    std::array<T*, std::size_t(D)> ptr;
    for (int d = 0; d < D; ++d) ptr[static_cast<std::size_t>(d)] = buf[static_cast<std::size_t>(d)].data();
    const detail::PackedPoints<T, D> P(c);
    for (std::size_t off = 0; off < ts.size(); off += chunk) {
      const std::size_t k = std::min(chunk, ts.size() - off);
      batch::evaluate_soa(P.data(), c.degree(), D, ts.data() + off, k, ptr.data(), false);
      for (std::size_t l = 0; l < k; ++l)
        for (int d = 0; d < D; ++d) out[off + l][d] = buf[static_cast<std::size_t>(d)][l];
    }
    detail::extrapolate_exactly(c, ts, detail::outside_unit_interval(ts), [&](std::size_t j, const Point<T, D>& p) { out[j] = p; });
  } else {
    for (std::size_t j = 0; j < ts.size(); ++j) out[j] = c(ts[j]);
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
