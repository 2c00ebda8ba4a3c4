// Composite (piecewise) curves: segments joined at breaks t0 < t1 < ... < tk, segment i
// mapped affinely from [0, 1] onto [t_i, t_{i+1}].
#pragma once

#include <algorithm>
#include <variant>
#include <vector>

#include "casteljau/curves/bezier.hpp"
#include "casteljau/curves/rational_bezier.hpp"

namespace casteljau {

/// One segment of a Path: a concrete curve type (kurbo's path element enum, not a
/// virtual hierarchy). Later curve types join the variant.
template <class T, int D>
using Segment = std::variant<Bezier<T, D>, RationalBezier<T, D>>;

/// A composite curve. Invariants (checked in the constructor): at least one segment,
/// k + 1 finite, strictly increasing breaks for k segments.
template <class T, int D>
class Path {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using SegmentType = Segment<T, D>;
  static constexpr int dimension = D;

  /// Segments with the default breaks 0, 1, ..., k.
  explicit Path(std::vector<SegmentType> segments)
      : segments_(std::move(segments)), breaks_(default_breaks(segments_.size())) {
    validate();
  }

  Path(std::vector<SegmentType> segments, std::vector<T> breaks) : segments_(std::move(segments)), breaks_(std::move(breaks)) {
    validate();
  }

  [[nodiscard]] const std::vector<SegmentType>& segments() const { return segments_; }
  [[nodiscard]] const std::vector<T>& breaks() const { return breaks_; }
  [[nodiscard]] std::size_t size() const { return segments_.size(); }
  [[nodiscard]] Interval<T> domain() const { return {breaks_.front(), breaks_.back()}; }
  [[nodiscard]] Interval<T> segment_domain(std::size_t i) const { return {breaks_[i], breaks_[i + 1]}; }

  /// The segment whose interval holds u: the right one at an interior break, the first
  /// or last one outside the domain (extrapolation). O(log k).
  [[nodiscard]] std::size_t segment_index(T u) const {
    const auto it = std::upper_bound(breaks_.begin() + 1, breaks_.end() - 1, u);
    return static_cast<std::size_t>(it - (breaks_.begin() + 1));
  }

  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    const std::size_t i = segment_index(u);
    const T t = segment_domain(i).fraction(u);
    return std::visit([&](const auto& s) { return s(t); }, segments_[i]);
  }

  /// The k-th derivative with respect to the path parameter: the segment's derivative
  /// divided by (t_{i+1} - t_i)^k (chain rule).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 1) throw InvalidArgument("k", "derivative order must be >= 1, got " + std::to_string(k));
    const std::size_t i = segment_index(u);
    return one_sided_derivative(i, segment_domain(i).fraction(u), k);
  }

  /// The k-th derivative (k >= 0 gives the point as a vector) of segment i at its local
  /// parameter t, scaled to the path parameter: what continuity checks compare.
  [[nodiscard]] VectorType one_sided_derivative(std::size_t i, T t, int k) const {
    if (i >= segments_.size()) {
      throw InvalidArgument("segment", "must name a segment 0.." + std::to_string(segments_.size() - 1) + ", got " +
                                           std::to_string(i));
    }
    require_finite(t, "t");
    const T h = segment_domain(i).length();
    return std::visit(
        [&](const auto& s) {
          if (k == 0) return s(t).to_vector();
          VectorType v = s.derivative_at(t, k);
          for (int j = 0; j < k; ++j) v /= h;
          return v;
        },
        segments_[i]);
  }

  /// Box of all control points; contains the curve over its domain.
  [[nodiscard]] Box<T, D> control_bounds() const {
    Box<T, D> b = Box<T, D>::empty_box();
    for (const auto& s : segments_) b.add(std::visit([](const auto& c) { return c.control_bounds(); }, s));
    return b;
  }

  [[nodiscard]] Path reverse() const {
    std::vector<SegmentType> segs;
    std::vector<T> br;
    for (auto it = segments_.rbegin(); it != segments_.rend(); ++it)
      segs.push_back(std::visit([](const auto& c) { return SegmentType(c.reverse()); }, *it));
    // u -> t0 + tk - u maps the domain onto itself reversed.
    for (auto it = breaks_.rbegin(); it != breaks_.rend(); ++it) br.push_back(breaks_.front() + breaks_.back() - *it);
    return Path(std::move(segs), std::move(br));
  }

  [[nodiscard]] Path transform(const Affine<T, D>& m) const {
    std::vector<SegmentType> segs;
    for (const auto& s : segments_) segs.push_back(std::visit([&](const auto& c) { return SegmentType(c.transform(m)); }, s));
    return Path(std::move(segs), breaks_);
  }

  friend bool operator==(const Path&, const Path&) = default;

 private:
  void validate() const {
    if (segments_.empty()) throw InvalidArgument("segments", "a path needs at least one segment");
    if (breaks_.size() != segments_.size() + 1) {
      throw InvalidArgument("breaks", "needs one more break than segments: " + std::to_string(segments_.size()) +
                                          " segments but " + std::to_string(breaks_.size()) + " breaks");
    }
    for (std::size_t i = 0; i < breaks_.size(); ++i) {
      const std::string where = "breaks[" + std::to_string(i) + "]";
      require_finite(breaks_[i], where);
      if (i > 0 && !(breaks_[i] > breaks_[i - 1])) {
        throw InvalidArgument(where, "breaks must be strictly increasing (" + detail::format_number(breaks_[i]) +
                                         " after " + detail::format_number(breaks_[i - 1]) + ")");
      }
    }
  }

  static std::vector<T> default_breaks(std::size_t k) {
    std::vector<T> b(k + 1);
    for (std::size_t i = 0; i <= k; ++i) b[i] = static_cast<T>(i);
    return b;
  }

  std::vector<SegmentType> segments_;
  std::vector<T> breaks_;
};

static_assert(DifferentiableCurve<Path<double, 2>>);

/// Every curve as a Path of Bézier and rational Bézier segments with the curve's own
/// parametrisation (the `to_bezier` command). A single Bézier becomes one segment on
/// its domain [0, 1].
template <class T, int D>
Path<T, D> to_bezier_path(const Bezier<T, D>& c) {
  return Path<T, D>({Segment<T, D>(c)}, {T(0), T(1)});
}
template <class T, int D>
Path<T, D> to_bezier_path(const RationalBezier<T, D>& c) {
  return Path<T, D>({Segment<T, D>(c)}, {T(0), T(1)});
}
template <class T, int D>
Path<T, D> to_bezier_path(const Path<T, D>& c) {
  return c;
}

}  // namespace casteljau
