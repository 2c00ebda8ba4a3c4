// Rational Bézier curves: R(t) = sum w_i B(i,n)(t) P_i / sum w_i B(i,n)(t), weights > 0,
// handled in homogeneous coordinates (w P, w) through Bezier<T, D+1>.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/curves/bezier.hpp"

namespace casteljau {

/// A rational Bézier curve with control points P_0..P_n and weights w_0..w_n > 0 over the
/// domain [0, 1]. Invariants (checked in the constructor): as many weights as points, at
/// least one, all finite, weights > 0. With positive weights the curve lies in the
/// convex hull of its control points and is invariant under affine maps of them.
template <class T, int D>
class RationalBezier {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using Homogeneous = Bezier<T, D + 1>;
  static constexpr int dimension = D;

  RationalBezier(std::vector<PointType> points, std::vector<T> weights) : P_(std::move(points)), w_(std::move(weights)) {
    if (P_.empty()) throw InvalidArgument("points", "a rational Bézier curve needs at least one control point");
    for (std::size_t i = 0; i < P_.size(); ++i) require_finite_point(P_[i], "points[" + std::to_string(i) + "]");
    if (w_.size() != P_.size()) {
      throw InvalidArgument("weights", "needs one weight per control point: " + std::to_string(P_.size()) +
                                           " points but " + std::to_string(w_.size()) + " weights");
    }
    for (std::size_t i = 0; i < w_.size(); ++i) {
      const std::string where = "weights[" + std::to_string(i) + "]";
      require_finite(w_[i], where);
      if (!(w_[i] > 0)) throw InvalidArgument(where, "weight must be > 0, got " + detail::format_number(w_[i]));
    }
  }

  /// The curve whose homogeneous control points are h (last coordinate the weight).
  /// Throws InvalidArgument if a weight is not > 0.
  static RationalBezier from_homogeneous(const Homogeneous& h) {
    std::vector<PointType> P(h.points().size());
    std::vector<T> w(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
      const auto& q = h.points()[i];
      w[i] = q[D];
      // Check the weight before dividing by it, so that a zero weight is reported as such
      // rather than as the non-finite coordinate it would produce.
      if (!(w[i] > 0)) {
        throw InvalidArgument("weights[" + std::to_string(i) + "]", "weight must be > 0, got " + detail::format_number(w[i]));
      }
      for (int d = 0; d < D; ++d) P[i][d] = q[d] / w[i];
    }
    return RationalBezier(std::move(P), std::move(w));
  }

  /// The exact circular arc of the given radius about center from angle a0 to a1
  /// (radians, counter-clockwise when a1 > a0), |a1 - a0| < pi: a quadratic with middle
  /// weight cos(theta/2), theta = a1 - a0 [PT97, 7.3; Farin02, 13.4].
  static RationalBezier circular_arc(const PointType& center, T radius, T a0, T a1)
    requires(D == 2)
  {
    require_finite(radius, "radius");
    require_finite(a0, "start_angle");
    require_finite(a1, "end_angle");
    if (!(radius > 0)) throw InvalidArgument("radius", "must be > 0, got " + detail::format_number(radius));
    const T theta = a1 - a0;
    if (!(std::abs(theta) < std::numbers::pi_v<T>)) {
      throw InvalidArgument("end_angle", "one arc spans less than pi radians; got a sweep of " + detail::format_number(theta));
    }
    const T half = theta / 2, mid = a0 + half, c = std::cos(half);
    auto on = [&](T a, T r) { return center + Vector<T, 2>(r * std::cos(a), r * std::sin(a)); };
    return RationalBezier({on(a0, radius), on(mid, radius / c), on(a1, radius)}, {T(1), c, T(1)});
  }

  [[nodiscard]] int degree() const { return static_cast<int>(P_.size()) - 1; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] const std::vector<T>& weights() const { return w_; }
  [[nodiscard]] static constexpr Interval<T> domain() { return {T(0), T(1)}; }

  /// The homogeneous Bézier curve with control points (w_i P_i, w_i).
  [[nodiscard]] Homogeneous homogeneous() const {
    std::vector<Point<T, D + 1>> H(P_.size());
    for (std::size_t i = 0; i < P_.size(); ++i) {
      for (int d = 0; d < D; ++d) H[i][d] = w_[i] * P_[i][d];
      H[i][D] = w_[i];
    }
    return Homogeneous(std::move(H));
  }

  /// R(t) by the rational de Casteljau algorithm [Farin02, 13.2]: every step is a convex
  /// combination of points (weights (1-t) w_i and t w_{i+1}), so the result stays in the
  /// control hull and its error is a few eps of max |P| for t in [0, 1]. Cost O(n^2).
  [[nodiscard]] PointType operator()(T t) const {
    require_finite(t, "t");
    std::vector<PointType> p(P_);
    std::vector<T> w(w_);
    const T s = 1 - t;
    for (std::size_t r = 1; r < p.size(); ++r) {
      for (std::size_t i = 0; i + r < p.size(); ++i) {
        const T a = s * w[i], b = t * w[i + 1], ab = a + b;
        // For t outside [0, 1] the new weight may vanish: R has a pole there only if the
        // full denominator does, so fall back to the homogeneous form.
        if (ab == 0 || !std::isfinite(ab)) return checked_projection(homogeneous()(t), t);
        p[i] = lerp(p[i], p[i + 1], b / ab);
        w[i] = ab;
      }
    }
    for (int d = 0; d < D; ++d) {
      if (!std::isfinite(p[0][d])) return checked_projection(homogeneous()(t), t);
    }
    return p[0];
  }

  /// The k-th derivative at t, k >= 1, from the homogeneous derivatives A^(j), w^(j) by
  /// R^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) R^(k-i)) / w [PT97, eq. 4.8].
  [[nodiscard]] VectorType derivative_at(T t, int k = 1) const {
    require_finite(t, "t");
    if (k < 1) throw InvalidArgument("k", "derivative order must be >= 1, got " + std::to_string(k));
    const Homogeneous h = homogeneous();
    std::vector<Vector<T, D + 1>> hd(static_cast<std::size_t>(k) + 1);
    hd[0] = h(t).to_vector();
    for (int j = 1; j <= k; ++j) hd[j] = h.derivative_at(t, j);
    const T w = hd[0][D];
    if (w == 0) {
      throw InvalidArgument("t", "the curve has a pole at t = " + detail::format_number(t) + " (its weight function vanishes there)");
    }
    std::vector<VectorType> r(static_cast<std::size_t>(k) + 1);
    for (int d = 0; d < D; ++d) r[0][d] = hd[0][d] / w;
    for (int j = 1; j <= k; ++j) {
      VectorType a;
      for (int d = 0; d < D; ++d) a[d] = hd[j][d];
      for (int i = 1; i <= j; ++i) a -= (binomial<T>(j, i) * hd[i][D]) * r[j - i];
      r[j] = a / w;
    }
    return r[k];
  }

  /// Subdivision at t in [0, 1] (homogeneous de Casteljau).
  [[nodiscard]] Split<RationalBezier> split(T t) const {
    auto s = homogeneous().split(t);
    return {from_homogeneous(s.left), from_homogeneous(s.right)};
  }

  /// The curve on [a, b] reparametrised to [0, 1] (see Bezier::portion). Throws if a
  /// weight of the result is not positive, which happens when [a, b] reaches a pole of
  /// the extended curve.
  [[nodiscard]] RationalBezier portion(T a, T b) const { return from_homogeneous(homogeneous().portion(a, b)); }

  /// Degree elevation by r of the homogeneous curve; the curve is unchanged.
  [[nodiscard]] RationalBezier elevate(int r = 1) const { return from_homogeneous(homogeneous().elevate(r)); }

  [[nodiscard]] RationalBezier reverse() const {
    return RationalBezier(std::vector<PointType>(P_.rbegin(), P_.rend()), std::vector<T>(w_.rbegin(), w_.rend()));
  }

  /// Affine maps act on the control points; weights are unchanged.
  [[nodiscard]] RationalBezier transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q(P_.size());
    std::transform(P_.begin(), P_.end(), Q.begin(), [&](const PointType& p) { return m(p); });
    return RationalBezier(std::move(Q), w_);
  }

  /// The box of the control points; contains the curve on [0, 1] since all weights > 0.
  [[nodiscard]] Box<T, D> control_bounds() const {
    Box<T, D> b = Box<T, D>::empty_box();
    for (const auto& p : P_) b.add(p);
    return b;
  }

  friend bool operator==(const RationalBezier&, const RationalBezier&) = default;

 private:
  /// The point of homogeneous h, or InvalidArgument("t", ...) where the weight function
  /// vanishes (a pole: possible only for t outside [0, 1], since all weights are > 0).
  static PointType checked_projection(const Point<T, D + 1>& h, T t) {
    PointType p;
    for (int d = 0; d < D; ++d) p[d] = h[d] / h[D];
    for (int d = 0; d < D; ++d) {
      if (!std::isfinite(p[d])) {
        throw InvalidArgument("t", "the curve has a pole at t = " + detail::format_number(t) +
                                       " (its weight function vanishes there)");
      }
    }
    return p;
  }

  std::vector<PointType> P_;
  std::vector<T> w_;
};

static_assert(DifferentiableCurve<RationalBezier<double, 2>>);
static_assert(SplittableCurve<RationalBezier<double, 3>>);
static_assert(ControlPolygonCurve<RationalBezier<double, 2>>);

}  // namespace casteljau
