// Piecewise cubic Hermite curves: points and derivatives given at parameters u_0 < ... <
// u_n, one cubic per interval, and their exact Bézier pieces.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/hermite_basis.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

namespace detail {
/// Whether every coordinate of v is finite: the cheap test, so that the message (and its
/// string) is built only for the element that fails.
template <class V>
bool all_coordinates_finite(const V& v) {
  for (int d = 0; d < V::dimension; ++d)
    if (!std::isfinite(v[d])) return false;
  return true;
}
}  // namespace detail

/// The piecewise cubic Hermite curve through P_0..P_n at the parameters u_0 < ... < u_n
/// (n >= 1): on [u_i, u_(i+1)], with h = u_(i+1) - u_i and t = (u - u_i) / h,
///   C(u) = h00(t) P_i + h01(t) P_(i+1) + h (h10(t) m_i + h11(t) m'_(i+1))
/// (basis/hermite_basis.hpp), so that C(u_i) = P_i, C'(u_i) = m_i (the outgoing tangent)
/// and C'(u_(i+1)-) = m'_(i+1) (the incoming tangent at the piece's end). Tangents are
/// derivatives with respect to the parameter u. Usually m' = m (one tangent per point,
/// the curve is C^1); Kochanek-Bartels continuity gives one-sided tangents (a corner).
/// Its exact Bézier form on each interval is P_i, P_i + h m_i / 3, P_(i+1) - h m'_(i+1) / 3,
/// P_(i+1) [Farin02, 7.5]. At a parameter inside the domain the right piece answers
/// (points and derivatives), at u_n the last one; outside the domain the first or last
/// cubic is extrapolated. Invariants (checked in the constructors, naming the field):
/// n + 1 >= 2 finite, strictly increasing params with a finite domain length, one finite
/// point and one finite tangent (of each side) per param.
template <class T, int D>
class Hermite {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  /// One tangent per point. Throws InvalidArgument naming "params", "params[i]",
  /// "points", "points[i][j]", "tangents", "tangents[i][j]".
  Hermite(std::vector<T> params, std::vector<PointType> points, std::vector<VectorType> tangents)
      : u_(std::move(params)), P_(std::move(points)), out_(std::move(tangents)) {
    in_ = out_;
    validate();
  }

  /// One-sided tangents: `incoming[i]` is the derivative at u_i from the left (the end of
  /// piece i - 1), `outgoing[i]` the one from the right (the start of piece i).
  /// incoming[0] and outgoing[n] belong to no piece: they are kept as given (and must be
  /// finite). Throws as the other constructor, naming "incoming_tangents" and
  /// "tangents" (the outgoing ones).
  Hermite(std::vector<T> params, std::vector<PointType> points, std::vector<VectorType> incoming, std::vector<VectorType> outgoing)
      : u_(std::move(params)), P_(std::move(points)), in_(std::move(incoming)), out_(std::move(outgoing)) {
    validate();
  }

  [[nodiscard]] const std::vector<T>& params() const { return u_; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  /// The outgoing tangents m_i (the only tangents unless one_sided()).
  [[nodiscard]] const std::vector<VectorType>& tangents() const { return out_; }
  /// The incoming tangents m'_i.
  [[nodiscard]] const std::vector<VectorType>& incoming_tangents() const { return in_; }
  /// Whether some interior point has different incoming and outgoing tangents (a corner
  /// unless they are parallel).
  [[nodiscard]] bool one_sided() const {
    for (std::size_t i = 1; i + 1 < P_.size(); ++i)
      if (!(in_[i] == out_[i])) return true;
    return false;
  }
  /// The number of cubic pieces, n.
  [[nodiscard]] std::size_t size() const { return u_.size() - 1; }
  [[nodiscard]] Interval<T> domain() const { return {u_.front(), u_.back()}; }

  /// The piece that answers at u: i with u_i <= u < u_(i+1), the last piece at u_n and
  /// beyond, the first one before u_0. O(log n).
  [[nodiscard]] std::size_t segment_index(T u) const {
    const auto it = std::upper_bound(u_.begin() + 1, u_.end() - 1, u);
    return static_cast<std::size_t>(it - (u_.begin() + 1));
  }

  /// C(u) for any finite u: the Hermite form of the piece (exact at the params: h00, h01
  /// are exactly 0 or 1 there), written about the nearer end so that the point
  /// differences, not the coordinates, carry the rounding. Error a few eps of max(|P|,
  /// h |m|) inside the domain. Throws InvalidArgument("t", ...) for a non-finite u or a
  /// value that overflows. Cost O(log n).
  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    return point_on(segment_index(u), u);
  }

  /// The k-th derivative (k >= 0) with respect to u: the point for k = 0, zero for k > 3;
  /// the right piece answers at an interior param, the last at u_n. For k >= 1,
  /// ((P_(i+1) - P_i) / h h01^(k)(t) + m_i h10^(k)(t) + m'_(i+1) h11^(k)(t)) / h^(k-1).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 0) return (*this)(u).to_vector();
    if (k > 3) return VectorType{};
    return derivative_on(segment_index(u), u, k);
  }

  /// The points at the parameters u (any finite values), found by a linear merge: when u
  /// is sorted the cost is O(n + len(u)) instead of O(len(u) log n); an unsorted value
  /// falls back to the binary search (correct for any order). Throws as operator().
  [[nodiscard]] std::vector<PointType> evaluate_sorted(std::span<const T> u) const {
    std::vector<PointType> out;
    out.reserve(u.size());
    std::size_t i = 0;
    const std::size_t last = size() - 1;
    for (const T x : u) {
      require_finite(x, "t");
      if (x < u_[i]) {
        i = segment_index(x);
      } else {
        while (i < last && x >= u_[i + 1]) ++i;
      }
      out.push_back(point_on(i, x));
    }
    return out;
  }

  /// Piece i (0 <= i < n) as a cubic Bézier curve on [0, 1] (its own parameter t).
  [[nodiscard]] Bezier<T, D> piece(std::size_t i) const {
    const T h3 = (u_[i + 1] - u_[i]) / 3;
    return Bezier<T, D>({P_[i], P_[i] + h3 * out_[i], P_[i + 1] - h3 * in_[i + 1], P_[i + 1]});
  }

  /// The same curve traversed backwards on the same domain: u -> u_0 + u_n - u; params
  /// reflected, points reversed, tangents reversed and negated (incoming and outgoing
  /// swap roles).
  [[nodiscard]] Hermite reverse() const {
    const std::size_t m = u_.size();
    std::vector<T> v(m);
    std::vector<PointType> Q(P_.rbegin(), P_.rend());
    std::vector<VectorType> in(m), out(m);
    for (std::size_t i = 0; i < m; ++i) {
      v[i] = u_.front() + u_.back() - u_[m - 1 - i];
      in[i] = -out_[m - 1 - i];
      out[i] = -in_[m - 1 - i];
    }
    v.front() = u_.front();  // exact ends despite rounding
    v.back() = u_.back();
    return Hermite(std::move(v), std::move(Q), std::move(in), std::move(out));
  }

  /// The image under an affine map: points mapped, tangents mapped by the linear part.
  [[nodiscard]] Hermite transform(const Affine<T, D>& m) const {
    std::vector<VectorType> in(in_.size()), out(out_.size());
    for (std::size_t i = 0; i < in_.size(); ++i) {
      in[i] = m(in_[i]);
      out[i] = m(out_[i]);
    }
    return Hermite(u_, mapped_points(m, P_), std::move(in), std::move(out));
  }

  /// The box of the Bézier control points of every piece: contains the curve over its
  /// domain (convex hull property of each piece).
  [[nodiscard]] Box<T, D> control_bounds() const {
    Box<T, D> b = Box<T, D>::empty_box();
    for (std::size_t i = 0; i < size(); ++i) b.add(box_of<T, D>(piece(i).points()));
    return b;
  }

  friend bool operator==(const Hermite&, const Hermite&) = default;

 private:
  PointType point_on(std::size_t i, T u) const {
    const T h = u_[i + 1] - u_[i];
    const T t = (u - u_[i]) / h;  // exactly 1 at u = u_(i+1): the same rounded h
    const HermiteBasis<T> b = hermite_basis(t, 0);
    const VectorType tangent_part = h * (b.h10 * out_[i] + b.h11 * in_[i + 1]);
    PointType p = t <= T(0.5) ? P_[i] + (b.h01 * (P_[i + 1] - P_[i]) + tangent_part)
                              : P_[i + 1] + (b.h00 * (P_[i] - P_[i + 1]) + tangent_part);
    check_representable(p, u, "the curve's point");
    return p;
  }

  VectorType derivative_on(std::size_t i, T u, int k) const {
    const T h = u_[i + 1] - u_[i];
    const T t = (u - u_[i]) / h;
    const HermiteBasis<T> b = hermite_basis(t, k);
    VectorType v = b.h01 * ((P_[i + 1] - P_[i]) / h) + b.h10 * out_[i] + b.h11 * in_[i + 1];
    for (int j = 1; j < k; ++j) v /= h;
    check_representable(v, u, "the derivative");
    return v;
  }

  template <class V>
  static void check_representable(const V& v, T u, const char* what) {
    for (int d = 0; d < D; ++d) {
      if (!std::isfinite(v[d])) {
        throw InvalidArgument("t", std::string(what) + " at t = " + detail::format_number(u) + " overflows a double");
      }
    }
  }

  void validate() const {
    if (u_.size() < 2) throw InvalidArgument("params", "a Hermite curve needs at least 2 params, got " + std::to_string(u_.size()));
    for (std::size_t i = 0; i < u_.size(); ++i) {
      if (std::isfinite(u_[i]) && (i == 0 || u_[i] > u_[i - 1])) continue;  // no string unless it fails
      const std::string where = "params[" + std::to_string(i) + "]";
      require_finite(u_[i], where);
      throw InvalidArgument(where, "params must be strictly increasing (" + detail::format_number(u_[i]) + " after " +
                                       detail::format_number(u_[i - 1]) + ")");
    }
    if (!std::isfinite(u_.back() - u_.front())) {
      throw InvalidArgument("params", "the domain [" + detail::format_number(u_.front()) + ", " + detail::format_number(u_.back()) +
                                          "] is longer than the largest double");
    }
    const auto count = [&](std::size_t got, const char* field, const char* noun) {
      if (got != u_.size()) {
        throw InvalidArgument(field, "needs one " + std::string(noun) + " per param: " + std::to_string(u_.size()) + " params but " +
                                         std::to_string(got) + " " + noun + "s");
      }
    };
    count(P_.size(), "points", "point");
    count(out_.size(), "tangents", "tangent");
    count(in_.size(), "incoming_tangents", "tangent");
    for (std::size_t i = 0; i < P_.size(); ++i)
      if (!detail::all_coordinates_finite(P_[i])) require_finite_point(P_[i], "points[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < out_.size(); ++i)
      if (!detail::all_coordinates_finite(out_[i])) require_finite_point(out_[i], "tangents[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < in_.size(); ++i)
      if (!detail::all_coordinates_finite(in_[i])) require_finite_point(in_[i], "incoming_tangents[" + std::to_string(i) + "]");
    // The Bézier form must exist too: P_i + h m_i / 3 and P_(i+1) - h m'_(i+1) / 3 finite.
    for (std::size_t i = 0; i + 1 < u_.size(); ++i) {
      const T h3 = (u_[i + 1] - u_[i]) / 3;
      const PointType a = P_[i] + h3 * out_[i], b = P_[i + 1] - h3 * in_[i + 1];
      for (int d = 0; d < D; ++d) {
        if (!std::isfinite(a[d]) || !std::isfinite(b[d])) {
          throw InvalidArgument("tangents[" + std::to_string(std::isfinite(a[d]) ? i + 1 : i) + "]",
                                "the tangent times the param spacing overflows a double");
        }
      }
    }
  }

  std::vector<T> u_;
  std::vector<PointType> P_;
  std::vector<VectorType> in_;
  std::vector<VectorType> out_;
};

/// The exact Bézier pieces: one cubic per interval, breaks at the params.
template <class T, int D>
Pieces<T, D> pieces(const Hermite<T, D>& c) {
  std::vector<BezierPiece<T, D>> segs;
  segs.reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) segs.emplace_back(c.piece(i));
  return Pieces<T, D>(std::move(segs), c.params());
}

static_assert(DifferentiableCurve<Hermite<double, 2>>);

}  // namespace casteljau
