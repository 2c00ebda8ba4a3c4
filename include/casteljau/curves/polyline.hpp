// Polylines: straight segments through points P_0..P_{n-1}, point i at parameter i.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The polyline through P_0..P_{n-1} (n >= 2) on the domain [0, n - 1]: on [i, i + 1] the
/// segment from P_i to P_{i+1}, P(u) = P_i + (u - i) (P_{i+1} - P_i). Outside the domain
/// the first or last segment is extended. Invariants (checked in the constructor): at
/// least two points, every coordinate finite. Consecutive equal points are allowed (the
/// curve then rests there for one unit of parameter).
template <class T, int D>
class Polyline {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  explicit Polyline(std::vector<PointType> points) : P_(std::move(points)) {
    if (P_.size() < 2) {
      throw InvalidArgument("points", "a polyline needs at least 2 points, got " + std::to_string(P_.size()));
    }
    require_finite_points(P_, "points");
  }
  Polyline(std::initializer_list<PointType> points) : Polyline(std::vector<PointType>(points)) {}

  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  /// The number of straight segments, n - 1.
  [[nodiscard]] std::size_t size() const { return P_.size() - 1; }
  [[nodiscard]] Interval<T> domain() const { return {T(0), static_cast<T>(size())}; }

  /// The segment that answers at u: segment i on [i, i + 1), the last one at the end of
  /// the domain, the first or last one outside it. O(1).
  [[nodiscard]] std::size_t segment_index(T u) const {
    const std::size_t last = size() - 1;
    if (!(u >= 1)) return 0;
    if (u >= static_cast<T>(last)) return last;
    return static_cast<std::size_t>(u);  // floor, since 1 <= u < last
  }

  /// P(u), exact at the vertices. Throws InvalidArgument("t", ...) for a non-finite u or
  /// when an extrapolated point overflows a double.
  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    const std::size_t i = segment_index(u);
    const T s = u - static_cast<T>(i);
    if (s == 0) return P_[i];
    if (s == 1) return P_[i + 1];
    PointType p = P_[i] + s * (P_[i + 1] - P_[i]);
    check_representable(p, u);
    return p;
  }

  /// The k-th derivative (k >= 0): the point for k = 0, P_{i+1} - P_i on segment i for
  /// k = 1 (the right segment at a vertex, the last at the end), zero for k >= 2.
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 0) return (*this)(u).to_vector();
    if (k > 1) return VectorType{};
    const std::size_t i = segment_index(u);
    VectorType v = P_[i + 1] - P_[i];
    check_representable(v, u);
    return v;
  }

  /// The same polyline traversed from the last point to the first: Q(u) = P(n - 1 - u).
  [[nodiscard]] Polyline reverse() const { return Polyline(std::vector<PointType>(P_.rbegin(), P_.rend())); }

  /// The image under an affine map (the polyline through the mapped points).
  [[nodiscard]] Polyline transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    return Polyline(std::move(Q));
  }

  /// The box of the points: for a polyline it is tight.
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }
  [[nodiscard]] Box<T, D> bounds() const { return control_bounds(); }

  friend bool operator==(const Polyline&, const Polyline&) = default;

 private:
  template <class V>
  static void check_representable(const V& v, T u) {
    for (int d = 0; d < D; ++d) {
      if (!std::isfinite(v[d])) {
        throw InvalidArgument("t", "the polyline's value at t = " + detail::format_number(u) + " overflows a double");
      }
    }
  }

  std::vector<PointType> P_;
};

/// The piecewise Bézier form: one degree-1 piece per segment, breaks 0, 1, ..., n - 1.
template <class T, int D>
Pieces<T, D> pieces(const Polyline<T, D>& c) {
  std::vector<BezierPiece<T, D>> segs;
  segs.reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) segs.emplace_back(Bezier<T, D>({c.points()[i], c.points()[i + 1]}));
  return Pieces<T, D>(std::move(segs));
}

static_assert(DifferentiableCurve<Polyline<double, 2>>);
static_assert(Curve<Polyline<double, 1>>);
static_assert(PiecewiseBezierCurve<Polyline<double, 2>>);

}  // namespace casteljau
