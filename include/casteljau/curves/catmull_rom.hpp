// Catmull-Rom splines: the C1 piecewise cubic through points with knot intervals
// |P_(i+1) - P_i|^alpha (uniform, centripetal, chordal and any alpha in [0, 1]), open or
// closed, held as its exact Bézier pieces [CatmullRom74; BarryGoldman88; Yuksel11].
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The Catmull-Rom spline through points P_0..P_(N-1) with the parametrisation of
/// shared/spec/cli.md: knot intervals d_i = |P_(i+1) - P_i|^alpha (1 for alpha = 0), knots
/// s_0 = 0, s_(i+1) = s_i + d_i.
/// - Open (N >= 4): segment j = 0..N-4 runs from P_(j+1) to P_(j+2) on [s_(j+1), s_(j+2)]
///   shifted by -s_1, so the domain is [0, s_(N-2) - s_1]; P_0 and P_(N-1) only shape the
///   end tangents.
/// - Closed (N >= 3): the points wrap (P_N = P_0); segment j runs from P_j to P_(j+1) on
///   [s_j, s_(j+1)], domain [0, s_N]; the curve closes with C1 continuity.
/// Each segment is the cubic Hermite interpolant of its end points with the tangent of the
/// non-uniform Catmull-Rom spline, which is the derivative of the Barry-Goldman pyramid:
/// m_i = (P_i - P_(i-1)) / d_(i-1) - (P_(i+1) - P_(i-1)) / (d_(i-1) + d_i) + (P_(i+1) - P_i) / d_i,
/// computed as d_i / (d_(i-1) (d_(i-1) + d_i)) (P_i - P_(i-1)) + d_(i-1) / (d_i (d_(i-1) +
/// d_i)) (P_(i+1) - P_i) (the same, without cancellation); for alpha = 0 it is
/// (P_(i+1) - P_(i-1)) / 2. Its Bézier points are P_i, P_i + d_i m_i / 3, P_(i+1) -
/// d_i m_(i+1) / 3, P_(i+1), built once in the constructor (O(N)); evaluation and
/// derivatives (with respect to the parameter s) run on those pieces, so the right
/// segment answers at a joint and the end segments extrapolate.
/// Invariants (checked in the constructor): alpha finite in [0, 1] ("alpha"), enough points
/// ("points"), finite coordinates ("points[i][d]"), and for alpha > 0 no two consecutive
/// points equal (a zero knot interval, "points[i]").
template <class T, int D>
class CatmullRom {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  explicit CatmullRom(std::vector<PointType> points, T alpha = T(0.5), bool closed = false)
      : P_(std::move(points)), alpha_(alpha), closed_(closed), d_(intervals_of(P_, alpha_, closed_)), pieces_(build(P_, d_, closed_)) {}

  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] T alpha() const { return alpha_; }
  [[nodiscard]] bool closed() const { return closed_; }
  /// The knot intervals d_i: N - 1 of them when open, N when closed (d_(N-1) from P_(N-1)
  /// back to P_0).
  [[nodiscard]] const std::vector<T>& intervals() const { return d_; }
  /// Whether the intervals are |P_(i+1) - P_i|^alpha of the points, to 8 eps relative (true
  /// unless the curve is the image under a map that is not a similarity: transform keeps
  /// the knots).
  [[nodiscard]] bool knots_follow_points() const { return follow_; }
  /// The exact Bézier pieces (one cubic per segment; breaks at the segments' knots).
  [[nodiscard]] const Pieces<T, D>& bezier_pieces() const { return pieces_; }
  [[nodiscard]] const std::vector<T>& breaks() const { return pieces_.breaks(); }
  [[nodiscard]] Interval<T> domain() const { return pieces_.domain(); }

  /// The point at parameter s (de Casteljau on the segment's cubic). O(log N).
  [[nodiscard]] PointType operator()(T s) const { return pieces_(s); }
  /// The k-th derivative (k >= 0; zero above 3) with respect to s. O(log N).
  [[nodiscard]] VectorType derivative_at(T s, int k = 1) const { return pieces_.derivative_at(s, k); }

  /// The same curve backwards on the same domain (up to the rounding of the knot sums):
  /// the points reversed (closed: P_0, P_(N-1), ..., P_1, so that it starts where the curve
  /// ends) with their intervals. Reversing twice gives the same curve exactly.
  [[nodiscard]] CatmullRom reverse() const {
    std::vector<PointType> Q;
    std::vector<T> e;
    const std::size_t N = P_.size();
    if (closed_) {
      Q.push_back(P_[0]);
      for (std::size_t i = N - 1; i >= 1; --i) Q.push_back(P_[i]);
      for (std::size_t i = N; i-- > 0;) e.push_back(d_[i]);
    } else {
      Q.assign(P_.rbegin(), P_.rend());
      e.assign(d_.rbegin(), d_.rend());
    }
    return CatmullRom(std::move(Q), alpha_, closed_, std::move(e), follow_);
  }

  /// The exact image under an affine map: the mapped points with the same knot intervals
  /// (with fixed knots the spline is linear in its points). Unless the map is a
  /// similarity, the intervals then differ from those the mapped points would give
  /// (knots_follow_points() is false): chordal and centripetal parametrisations commute
  /// only with similarities.
  [[nodiscard]] CatmullRom transform(const Affine<T, D>& m) const {
    return CatmullRom(mapped_points(m, P_), alpha_, closed_, d_, follow_);
  }

  /// The box of the Bézier control points: it contains the curve over its domain.
  [[nodiscard]] Box<T, D> control_bounds() const { return pieces_.control_bounds(); }

  friend bool operator==(const CatmullRom& a, const CatmullRom& b) {
    return a.P_ == b.P_ && a.alpha_ == b.alpha_ && a.closed_ == b.closed_ && a.d_ == b.d_ && a.follow_ == b.follow_;
  }

 private:
  CatmullRom(std::vector<PointType> points, T alpha, bool closed, std::vector<T> intervals, bool follow)
      : P_(std::move(points)), alpha_(alpha), closed_(closed), d_(std::move(intervals)), follow_(follow), pieces_(build(P_, d_, closed_)) {
    if (follow_) {
      // Whether the points still give these intervals, to rounding (8 eps relative: a
      // rotation or uniform scaling moves each distance by a few ulps).
      const std::vector<T> e = intervals_of(P_, alpha_, closed_);
      for (std::size_t i = 0; i < e.size(); ++i)
        follow_ = follow_ && std::abs(e[i] - d_[i]) <= 8 * std::numeric_limits<T>::epsilon() * d_[i];
    }
  }

  static std::vector<T> intervals_of(const std::vector<PointType>& P, T alpha, bool closed) {
    require_finite(alpha, "alpha");
    if (!(alpha >= 0 && alpha <= 1)) throw InvalidArgument("alpha", "alpha must lie in [0, 1], got " + detail::format_number(alpha));
    const std::size_t need = closed ? 3 : 4;
    if (P.size() < need) {
      throw InvalidArgument("points", std::string("a") + (closed ? " closed" : "n open") + " catmull_rom curve needs at least " +
                                          std::to_string(need) + " points, got " + std::to_string(P.size()));
    }
    for (std::size_t i = 0; i < P.size(); ++i) require_finite_point(P[i], "points[" + std::to_string(i) + "]");
    const std::size_t N = P.size(), m = closed ? N : N - 1;
    std::vector<T> d(m);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t next = (i + 1) % N;
      const T len = distance(P[next], P[i]);
      d[i] = alpha == 0 ? T(1) : std::pow(len, alpha);
      if (!(d[i] > 0)) {
        throw InvalidArgument("points[" + std::to_string(next) + "]",
                              "equals points[" + std::to_string(i) + "]: with alpha > 0 consecutive points must differ (a zero knot interval)" +
                                  std::string(closed && next == 0 ? " (the curve is closed: the last point is followed by the first)" : ""));
      }
    }
    return d;
  }

  /// The Catmull-Rom tangent at P_i from its neighbours and the two intervals around it.
  static VectorType tangent(const PointType& prev, const PointType& p, const PointType& next, T d0, T d1) {
    const T sum = d0 + d1;
    return (d1 / (d0 * sum)) * (p - prev) + (d0 / (d1 * sum)) * (next - p);
  }

  static Pieces<T, D> build(const std::vector<PointType>& P, const std::vector<T>& d, bool closed) {
    const std::size_t N = P.size();
    std::vector<BezierPiece<T, D>> segs;
    std::vector<T> breaks{T(0)};
    // Segment from P_a to P_b (indices mod N) with interval d_a; tangents at P_a and P_b.
    const auto add = [&](std::size_t a, std::size_t b, const VectorType& ma, const VectorType& mb) {
      const T h = d[a] / 3;
      segs.emplace_back(Bezier<T, D>({P[a], P[a] + h * ma, P[b] - h * mb, P[b]}));
      const T next = breaks.back() + d[a];
      if (!(next > breaks.back())) {
        throw InvalidArgument("points[" + std::to_string(b) + "]", "the knot interval " + detail::format_number(d[a]) +
                                                                       " vanishes next to the knot " + detail::format_number(breaks.back()));
      }
      breaks.push_back(next);
    };
    if (closed) {
      std::vector<VectorType> m(N);
      for (std::size_t i = 0; i < N; ++i) {
        const std::size_t prev = (i + N - 1) % N, next = (i + 1) % N;
        m[i] = tangent(P[prev], P[i], P[next], d[prev], d[i]);
      }
      for (std::size_t j = 0; j < N; ++j) add(j, (j + 1) % N, m[j], m[(j + 1) % N]);
    } else {
      std::vector<VectorType> m(N);
      for (std::size_t i = 1; i + 1 < N; ++i) m[i] = tangent(P[i - 1], P[i], P[i + 1], d[i - 1], d[i]);
      for (std::size_t j = 1; j + 2 < N; ++j) add(j, j + 1, m[j], m[j + 1]);
    }
    return Pieces<T, D>(std::move(segs), std::move(breaks));
  }

  std::vector<PointType> P_;
  T alpha_;
  bool closed_;
  std::vector<T> d_;
  bool follow_ = true;
  Pieces<T, D> pieces_;
};

/// The exact Bézier form: the cubic pieces built in the constructor.
template <class T, int D>
const Pieces<T, D>& pieces(const CatmullRom<T, D>& c) {
  return c.bezier_pieces();
}

static_assert(DifferentiableCurve<CatmullRom<double, 2>>);

}  // namespace casteljau
