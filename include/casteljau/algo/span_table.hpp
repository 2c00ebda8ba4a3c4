// Batch evaluation of a piecewise polynomial curve (a B-spline, a spline, a path of
// Bézier curves of one degree, a polyline): its exact Bézier pieces in one flat table, a
// span search that costs O(1) per parameter, and the Bernstein form evaluated as a convex
// combination. What OpenCASCADE's per-span cache does for one span, for all of them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The pieces of a curve whose Bézier pieces are all polynomial and of one degree, laid
/// out for evaluation at many parameters:
///
/// - piece i's control points, point-major, at coefficients()[i * (p + 1) * D ...];
/// - a bucket grid over the domain (one bucket per piece, at most 2^20): bucket j holds
///   the piece at the bucket's left edge, so a parameter's piece is found by one multiply,
///   one load and a short scan (a binary search when one bucket holds more than eight
///   breaks: very uneven breaks cost O(log k), never O(k)); sorted parameters first try
///   the previous parameter's piece;
/// - the local parameter s = (u - u_i) / (u_(i+1) - u_i) by a stored reciprocal, then the
///   p + 1 Bernstein values at s and one dot product per coordinate. Inside the domain the
///   weights are non-negative and sum to one, so the point is a convex combination of the
///   piece's control points: error about (p + 2) eps max |P| (docs/accuracy.md).
///
/// The right piece answers at an interior break, the last one at the domain's end, as
/// for c(t). Parameters outside the domain go through the curve's own extrapolation
/// (exact at any distance), not through the table.
template <class T, int D>
class SpanTable {
 public:
  /// The highest degree the table takes: above it the Bernstein values by powers lose
  /// accuracy against de Casteljau, and evaluation is O(p^2) anyway.
  static constexpr int max_degree = 24;

  /// The table of p's pieces, or nothing when a piece is rational, the degrees differ or
  /// exceed max_degree (the caller then evaluates point by point).
  [[nodiscard]] static std::optional<SpanTable> of(Pieces<T, D> p) {
    const auto* first = std::get_if<Bezier<T, D>>(&p.segments().front());
    if (first == nullptr || first->degree() > max_degree) return std::nullopt;
    const int degree = first->degree();
    SpanTable table(std::move(p), degree);
    const auto& segs = table.pieces_.segments();
    const std::size_t n1 = static_cast<std::size_t>(degree) + 1;
    table.coef_.resize(segs.size() * n1 * std::size_t(D));
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const auto* b = std::get_if<Bezier<T, D>>(&segs[i]);
      if (b == nullptr || b->degree() != degree) return std::nullopt;
      // A piece's own domain is [0, 1] (Bézier): the local parameter is the fraction.
      for (std::size_t k = 0; k < n1; ++k)
        for (int d = 0; d < D; ++d) table.coef_[(i * n1 + k) * std::size_t(D) + std::size_t(d)] = b->points()[k][d];
    }
    return table;
  }

  [[nodiscard]] int degree() const { return degree_; }
  [[nodiscard]] std::size_t size() const { return pieces_.size(); }
  [[nodiscard]] Interval<T> domain() const { return pieces_.domain(); }
  [[nodiscard]] const std::vector<T>& coefficients() const { return coef_; }

  /// The index of the piece that answers at u (u inside the domain), starting from the
  /// guess `hint` (any index; the previous answer for sorted parameters).
  [[nodiscard]] std::size_t piece_at(T u, std::size_t hint) const {
    const std::vector<T>& breaks = pieces_.breaks();
    const std::size_t k = pieces_.size();
    if (hint < k && breaks[hint] <= u && (u < breaks[hint + 1] || hint + 1 == k)) return hint;
    const T x = (u - breaks.front()) * bucket_scale_;
    std::size_t j = x > 0 ? static_cast<std::size_t>(x) : 0;
    if (j >= buckets_.size() - 1) j = buckets_.size() - 2;
    std::size_t lo = buckets_[j], hi = buckets_[j + 1];
    // The bucket's rounding may be one off at its edges: widen by one piece each way.
    if (lo > 0) --lo;
    hi = std::min(hi + 1, k - 1);
    if (hi - lo > 8) {
      // breaks[lo + 1 .. hi] holds the first break above u, or u is in the last piece.
      const auto it = std::upper_bound(breaks.begin() + static_cast<std::ptrdiff_t>(lo) + 1,
                                       breaks.begin() + static_cast<std::ptrdiff_t>(hi) + 1, u);
      const std::size_t i = static_cast<std::size_t>(it - breaks.begin()) - 1;
      if (breaks[i] > u || (i + 1 < k && breaks[i + 1] <= u)) return pieces_.segment_index(u);
      return i;
    }
    std::size_t i = lo;
    while (i < hi && breaks[i + 1] <= u) ++i;
    // Breaks a few ulps apart can defeat the widening: check, and search all breaks then.
    if (breaks[i] > u || (i + 1 < k && breaks[i + 1] <= u)) return pieces_.segment_index(u);
    return i;
  }

  /// The points at the parameters ts (any finite values) into out, one per parameter.
  /// Throws InvalidArgument naming "t[j]" for a non-finite parameter, "out" for a size
  /// mismatch.
  void evaluate(std::span<const T> ts, std::span<Point<T, D>> out) const {
    if (out.size() != ts.size()) {
      throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                       std::to_string(out.size()) + " points");
    }
    switch (degree_) {
      case 1: run<1>(ts, out); break;
      case 2: run<2>(ts, out); break;
      case 3: run<3>(ts, out); break;
      default: run<0>(ts, out); break;
    }
  }

 private:
  SpanTable(Pieces<T, D> p, int degree) : degree_(degree), pieces_(std::move(p)) {
    const std::vector<T>& breaks = pieces_.breaks();
    const std::size_t k = pieces_.size();
    // C(p, j), for the degrees without an unrolled case.
    for (int j = 0; j <= degree_; ++j) binomial_.push_back(binomial<T>(degree_, j));
    inv_length_.resize(k);
    for (std::size_t i = 0; i < k; ++i) inv_length_[i] = T(1) / (breaks[i + 1] - breaks[i]);
    // Bucket j covers [lo + j w, lo + (j + 1) w); buckets_[j] is the piece at its left
    // edge, buckets_[nb] = k - 1 closes the grid.
    const std::size_t nb = std::clamp<std::size_t>(k, 1, std::size_t{1} << 20);
    const T lo = breaks.front(), len = breaks.back() - lo;
    bucket_scale_ = T(nb) / len;
    if (!std::isfinite(bucket_scale_)) bucket_scale_ = 0;  // a domain too short or too long for the grid: one bucket
    buckets_.resize(nb + 1);
    std::size_t i = 0;
    for (std::size_t j = 0; j < nb; ++j) {
      const T edge = lo + len * (T(j) / T(nb));
      while (i + 1 < k && breaks[i + 1] <= edge) ++i;
      buckets_[j] = static_cast<std::uint32_t>(i);
    }
    buckets_[nb] = static_cast<std::uint32_t>(k - 1);
    if (bucket_scale_ == 0) std::fill(buckets_.begin(), buckets_.end() - 1, 0u);
  }

  /// The Bernstein values B_0..B_p at s; P is the degree when known at compile time
  /// (P = 0: the run-time degree_).
  template <int P>
  void bernstein_values(T s, T* b) const {
    const int p = P > 0 ? P : degree_;
    const T r = 1 - s;
    if constexpr (P == 1) {
      b[0] = r;
      b[1] = s;
    } else if constexpr (P == 2) {
      b[0] = r * r;
      b[1] = 2 * r * s;
      b[2] = s * s;
    } else if constexpr (P == 3) {
      const T rr = r * r, ss = s * s;
      b[0] = rr * r;
      b[1] = 3 * rr * s;
      b[2] = 3 * r * ss;
      b[3] = ss * s;
    } else {
      // B_i = C(p, i) s^i r^(p-i): powers of s forward, of r backward.
      T sp = 1;
      for (int i = 0; i <= p; ++i) {
        b[i] = binomial_[static_cast<std::size_t>(i)] * sp;
        sp *= s;
      }
      T rp = 1;
      for (int i = p; i >= 0; --i) {
        b[i] *= rp;
        rp *= r;
      }
    }
  }

  template <int P>
  void run(std::span<const T> ts, std::span<Point<T, D>> out) const {
    const std::vector<T>& breaks = pieces_.breaks();
    const std::size_t n1 = static_cast<std::size_t>(P > 0 ? P : degree_) + 1;
    const T lo = breaks.front(), hi = breaks.back();
    std::array<T, max_degree + 1> b;
    std::size_t i = 0;
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const T u = ts[j];
      if (!(u >= lo && u <= hi)) {
        // Outside the domain (or not a number): the curve's own exact extrapolation, and
        // its error naming the parameter.
        require_finite(u, "t[" + std::to_string(j) + "]");
        out[j] = pieces_(u);
        continue;
      }
      i = piece_at(u, i);
      T s = (u - breaks[i]) * inv_length_[i];
      s = std::clamp(s, T(0), T(1));
      bernstein_values<P>(s, b.data());
      const T* c = coef_.data() + i * n1 * std::size_t(D);
      Point<T, D> q;
      for (int d = 0; d < D; ++d) {
        T acc = 0;
        for (std::size_t k = 0; k < n1; ++k) acc += b[k] * c[k * std::size_t(D) + std::size_t(d)];
        q[d] = acc;
      }
      out[j] = q;
    }
  }

  int degree_;
  Pieces<T, D> pieces_;
  std::vector<T> inv_length_;
  std::vector<T> coef_;
  std::vector<std::uint32_t> buckets_;
  T bucket_scale_ = 0;
  std::vector<T> binomial_;
};

/// Any piecewise polynomial curve at many parameters through its SpanTable (built once
/// per call: O(k p^2) for k pieces); curves with rational pieces or pieces of different
/// degrees evaluate point by point (B-splines and NURBS through their own batch
/// evaluate, which searches each span from the previous one). Build a SpanTable yourself
/// to evaluate one curve in many calls.
template <PiecewiseBezierCurve C>
void evaluate_pieces(const C& c, std::span<const typename C::Scalar> ts,
                     std::span<Point<typename C::Scalar, C::dimension>> out) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  if (out.size() != ts.size()) {
    throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                     std::to_string(out.size()) + " points");
  }
  if (ts.empty()) return;
  if (const auto table = SpanTable<T, D>::of(pieces(c))) {
    table->evaluate(ts, out);
    return;
  }
  if constexpr (requires { c.evaluate(ts, out); }) {
    c.evaluate(ts, out);  // B-splines and NURBS: de Boor with the span search hinted
  } else {
    for (std::size_t j = 0; j < ts.size(); ++j) {
      require_finite(ts[j], "t[" + std::to_string(j) + "]");
      out[j] = c(ts[j]);
    }
  }
}

}  // namespace casteljau
