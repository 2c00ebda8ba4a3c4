// Rational Bézier curves: R(t) = sum w_i B(i,n)(t) P_i / sum w_i B(i,n)(t), weights > 0,
// handled in homogeneous coordinates (w P, w) through Bezier<T, D+1>.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "casteljau/curves/bezier.hpp"
#include "casteljau/curves/rational_jet.hpp"

namespace casteljau {

namespace detail {
/// The derivatives 0..k of the rational curve A / w from those of its homogeneous form,
/// hd[j] = (A^(j), w^(j)) with w = hd[0][D] != 0, by the quotient rule
/// C^(j) = (A^(j) - sum_{i=1..j} C(j, i) w^(i) C^(j-i)) / w [PT97, eq. 4.8]. Shared by
/// every rational curve type. Cost O(k^2 D).
template <class T, int D>
void quotient_rule(std::span<const Point<T, D + 1>> hd, int k, Vector<T, D>* out) {
  const T w = hd[0][D];
  for (int d = 0; d < D; ++d) out[0][d] = hd[0][d] / w;
  for (int j = 1; j <= k; ++j) {
    Vector<T, D> a;
    for (int d = 0; d < D; ++d) a[d] = hd[static_cast<std::size_t>(j)][d];
    for (int i = 1; i <= j; ++i) a -= (binomial<T>(j, i) * hd[static_cast<std::size_t>(i)][D]) * out[j - i];
    out[j] = a / w;
  }
}
}  // namespace detail

/// A rational Bézier curve with control points P_0..P_n and weights w_0..w_n > 0 over the
/// domain [0, 1]. Invariants (checked in the constructor): as many weights as points, at
/// least one, all finite, weights > 0, and largest / smallest weight within the range of
/// T (so that the normalised weights below are all > 0). With positive weights the
/// curve lies in the convex hull of its control points and is invariant under affine
/// maps of them.
///
/// Multiplying every weight by one constant leaves the curve unchanged. Every
/// computation uses the normalised weights w_i 2^-e, with e chosen so that the largest
/// is in [0.5, 1) (exact: a power of two), so that weights of any size give the same
/// results: equal subnormal weights are the polynomial curve, weights up to 1e308 never
/// overflow w P. weights() returns the weights as given.
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
    require_finite_points(P_, "points");
    if (w_.size() != P_.size()) {
      throw InvalidArgument("weights", "needs one weight per control point: " + std::to_string(P_.size()) +
                                           " points but " + std::to_string(w_.size()) + " weights");
    }
    for (std::size_t i = 0; i < w_.size(); ++i) {
      const std::string where = "weights[" + std::to_string(i) + "]";
      require_finite(w_[i], where);
      if (!(w_[i] > 0)) throw InvalidArgument(where, "weight must be > 0, got " + detail::format_number(w_[i]));
    }
    normalise();
    for (std::size_t i = 0; i < wn_.size(); ++i) {
      if (!(wn_[i] > 0)) {
        const T wmax = *std::max_element(w_.begin(), w_.end());
        throw InvalidArgument("weights[" + std::to_string(i) + "]",
                              "weights must lie within the range of the floating point type of one another: " +
                                  detail::format_number(wmax) + " / " + detail::format_number(w_[i]) + " overflows");
      }
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

  /// The homogeneous Bézier curve with control points (w_i P_i, w_i), w_i the normalised
  /// weights (largest in [0.5, 1)): |w_i P_i| <= |P_i|, so it never overflows.
  [[nodiscard]] Homogeneous homogeneous() const { return Homogeneous(homogeneous_points(0)); }

  /// R(t) for any finite t. On [0, 1] by the rational de Casteljau algorithm [Farin02,
  /// 13.2] on the normalised weights: every step is a convex combination of points
  /// (weights (1-t) w_i and t w_(i+1)), so the result stays in the control hull and its
  /// error is a few eps of max |P|. No allocation up to degree 15 (a stack buffer).
  /// Outside [0, 1] (or if the convex steps fail near the largest double), the
  /// homogeneous numerator and denominator by detail::derivatives_for_ratio (Taylor
  /// form about the nearer end; for |s| > 1 reversed in u = 1/s, i.e. both divided by
  /// s^n, so that neither overflows) on a copy whose points are scaled by a power of two; see Bezier's
  /// operator() for the accuracy. Throws InvalidArgument("t", ...) at a pole (the weight
  /// function vanishes: possible only outside [0, 1]) and when the value is not
  /// representable; never returns NaN or infinity. Cost O(n^2).
  [[nodiscard]] PointType operator()(T t) const {
    require_finite(t, "t");
    if (t >= 0 && t <= 1) {
      const std::size_t m = P_.size();
      detail::Scratch<PointType> pb(m);
      detail::Scratch<T> wb(m);
      PointType* p = pb.data();
      T* w = wb.data();
      std::copy(P_.begin(), P_.end(), p);
      std::copy(wn_.begin(), wn_.end(), w);
      const T s = 1 - t;
      bool ok = true;
      for (std::size_t r = 1; r < m && ok; ++r) {
        for (std::size_t i = 0; i + r < m; ++i) {
          const T a = s * w[i], b = t * w[i + 1], ab = a + b;
          // ab > 0 on [0, 1] unless both products underflow (weights near 2^-1074).
          if (!(ab > 0)) {
            ok = false;
            break;
          }
          p[i] = lerp(p[i], p[i + 1], b / ab);
          w[i] = ab;
        }
      }
      if (ok && detail::all_finite(p[0])) return p[0];
    }
    Vector<T, D> v[1];
    evaluate_derivatives(t, 0, v);
    return PointType::from_vector(v[0]);
  }

  /// The k-th derivative at t (k >= 0; k = 0 gives the point as a vector from the
  /// origin). k = 1 on [0, 1] (degree <= 24): by detail::rational_jet, a sum over pairs
  /// of control points with positive coefficients (no cancellation at any weights); k >= 2
  /// there, when the weights spread beyond 2^20, by detail::rational_pair_derivative, over
  /// pairs of control points too (their differences only: right where the curve hugs its
  /// control polygon).
  /// Otherwise from the homogeneous derivatives A^(j), w^(j) by R^(k) = (A^(k) -
  /// sum_{i=1..k} C(k,i) w^(i) R^(k-i)) / w [PT97, eq. 4.8], all computed with the
  /// normalised weights and power-of-two-scaled points; far outside [0, 1] in the reversed
  /// variable u = 1/s (detail::derivatives_for_ratio, evaluate_derivatives). Throws
  /// InvalidArgument("t", ...) at a pole or when the derivative is not representable,
  /// ("k", ...) for k < 0. Cost O(k n^2 + k^2).
  [[nodiscard]] VectorType derivative_at(T t, int k = 1) const {
    require_finite(t, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 0) return (*this)(t).to_vector();
    if (k == 1 && t >= 0 && t <= 1 && degree() <= detail::rational_jet_max_degree) {
      // Without cancellation (detail::rational_jet): the quotient rule below loses R'
      // where the curve hugs its control polygon (weights 1, 1e30, 1 at t = 1/2).
      const auto j = jet(t, false);
      VectorType v;
      for (int d = 0; d < D; ++d) v[d] = std::ldexp(j.r[d], j.er);
      if (!detail::all_finite(v)) detail::throw_not_representable("the derivative of order 1", detail::format_number(t));
      return v;
    }
    if (k >= 2 && t >= 0 && t <= 1 && degree() <= detail::rational_jet_max_degree &&
        detail::extreme_weight_spread(std::span<const T>(wn_))) {
      // Over pairs of control points (detail::rational_pair_derivative): the quotient
      // rule below gives 0 for R''(1/2) = (-8, -8) / w at weights 1, w = 1e30, 1.
      const VectorType v = detail::rational_pair_derivative<T, D>(std::span<const PointType>(P_), std::span<const T>(wn_), t, k);
      if (detail::all_finite(v)) return v;
    }
    std::vector<VectorType> r(static_cast<std::size_t>(k) + 1);
    evaluate_derivatives(t, k, r.data());
    return r[static_cast<std::size_t>(k)];
  }

  /// R'(t) and, with `second`, R' ^ R'' at t in [0, 1] for degree <= 24, computed
  /// without cancellation from the normalised weights (see detail::rational_jet).
  [[nodiscard]] detail::RationalJet<T, D> jet(T t, bool second) const {
    return detail::rational_jet<T, D>(std::span<const PointType>(P_), std::span<const T>(wn_), detail::JetParameter<T>::of(t), second);
  }

  /// Subdivision at t in [0, 1] by the rational de Casteljau algorithm on points and
  /// normalised weights (the two outer edges of its triangle): convex combinations, so
  /// finite data give finite results for weights of any size. The weights of the halves
  /// are scaled back by the normalising power of two when that stays in range.
  [[nodiscard]] Split<RationalBezier> split(T t) const {
    require_finite(t, "t");
    if (t < 0 || t > 1) throw InvalidArgument("t", "split parameter must lie in [0, 1], got " + detail::format_number(t));
    const std::size_t m = P_.size();
    std::vector<PointType> p(P_), L(m), R(m);
    std::vector<T> w(wn_), wl(m), wr(m);
    L[0] = p[0];
    wl[0] = w[0];
    R[m - 1] = p[m - 1];
    wr[m - 1] = w[m - 1];
    const T s = 1 - t;
    for (std::size_t r = 1; r < m; ++r) {
      for (std::size_t i = 0; i + r < m; ++i) {
        const T a = s * w[i], b = t * w[i + 1], ab = a + b;
        p[i] = lerp(p[i], p[i + 1], b / ab);
        w[i] = ab;
      }
      L[r] = p[0];
      wl[r] = w[0];
      R[m - 1 - r] = p[m - 1 - r];
      wr[m - 1 - r] = w[m - 1 - r];
    }
    return {finish(std::move(L), std::move(wl), "t", "the left part"), finish(std::move(R), std::move(wr), "t", "the right part")};
  }

  /// The curve on [a, b] reparametrised to [0, 1] (see Bezier::portion), by the blossom
  /// of the homogeneous curve (normalised weights, points scaled by a power of two).
  /// Throws InvalidArgument("weights[i]", ...) if a weight of the result is not positive,
  /// which happens when [a, b] reaches a pole of the extended curve, and naming a or b
  /// when a control point of the result is not representable.
  [[nodiscard]] RationalBezier portion(T a, T b) const {
    const int e = detail::scale_exponent<PointType>(P_);
    const auto h = Homogeneous(homogeneous_points(e)).portion(a, b);
    const RationalBezier q = from_homogeneous(h);
    std::vector<PointType> Q(q.P_.size());
    for (std::size_t i = 0; i < Q.size(); ++i) Q[i] = detail::scaled(q.P_[i], e);
    return finish(std::move(Q), q.wn_, std::abs(a) > std::abs(b) ? "a" : "b", "the portion");
  }

  /// The same curve at degree n + r, by Forrest's equations on the homogeneous curve
  /// written in Cartesian form: W_i = sum_j h_ij w_j and Q_i = sum_j (h_ij w_j / W_i) P_j,
  /// h_ij the hypergeometric weights of Bezier::elevate (normalised, no binomials). All
  /// terms are positive, so neither the weights nor the points cancel: for weights
  /// spanning 1e-8..1e8 elevated by 300 at once the curve moves by about 1e-15 relative
  /// (measured in tests/unit/robustness_test.cpp). Cost O((n + r) min(n, r)).
  [[nodiscard]] RationalBezier elevate(int r = 1) const {
    if (r < 0) throw InvalidArgument("r", "degree elevation count must be >= 0, got " + std::to_string(r));
    if (r == 0) return *this;
    const int n = degree();
    std::vector<PointType> Q(P_.size() + static_cast<std::size_t>(r));
    std::vector<T> W(Q.size());
    std::vector<T> h(static_cast<std::size_t>(std::min(n, r)) + 1);
    for (int i = 0; i <= n + r; ++i) {
      const int lo = std::max(0, i - r), hi = std::min(n, i);
      detail::hypergeometric_row<T>(n + r, n, i, std::span<T>(h.data(), static_cast<std::size_t>(hi - lo + 1)));
      T wi = 0;
      for (int j = lo; j <= hi; ++j) {
        h[static_cast<std::size_t>(j - lo)] *= wn_[static_cast<std::size_t>(j)];
        wi += h[static_cast<std::size_t>(j - lo)];
      }
      // Q_i = P_lo + sum (h_ij w_j / W_i) (P_j - P_lo): exact for coincident points.
      const PointType& base = P_[static_cast<std::size_t>(lo)];
      VectorType sum{};
      for (int j = lo + 1; j <= hi; ++j) sum += (h[static_cast<std::size_t>(j - lo)] / wi) * (P_[static_cast<std::size_t>(j)] - base);
      Q[static_cast<std::size_t>(i)] = base + sum;
      W[static_cast<std::size_t>(i)] = wi;
    }
    return finish(std::move(Q), std::move(W), "r", "the elevated curve");
  }

  [[nodiscard]] RationalBezier reverse() const {
    return RationalBezier(std::vector<PointType>(P_.rbegin(), P_.rend()), std::vector<T>(w_.rbegin(), w_.rend()),
                          detail::Trusted{});
  }

  /// Affine maps act on the control points; weights are unchanged. Throws
  /// InvalidArgument("m", ...) when a mapped control point is not representable.
  [[nodiscard]] RationalBezier transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    for (std::size_t i = 0; i < Q.size(); ++i) {
      if (!detail::all_finite(Q[i])) {
        throw InvalidArgument("m", "the transformed curve is not representable: its control point " + std::to_string(i) +
                                       " has a coordinate beyond the largest finite number");
      }
    }
    return RationalBezier(std::move(Q), w_, detail::Trusted{});
  }

  /// The box of the control points; contains the curve on [0, 1] since all weights > 0.
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }

  friend bool operator==(const RationalBezier&, const RationalBezier&) = default;

 private:
  RationalBezier(std::vector<PointType> points, std::vector<T> weights, detail::Trusted)
      : P_(std::move(points)), w_(std::move(weights)) {
    normalise();
  }

  /// wn_ = w_ 2^-wexp_ with the largest in [0.5, 1) (exact unless a weight more than
  /// 2^1021 times smaller than the largest underflows; the constructor rejects a zero).
  void normalise() {
    const T wmax = *std::max_element(w_.begin(), w_.end());
    (void)std::frexp(wmax, &wexp_);
    wn_.resize(w_.size());
    for (std::size_t i = 0; i < w_.size(); ++i) wn_[i] = std::ldexp(w_[i], -wexp_);
  }

  /// (wn_i P_i 2^-e, wn_i): the homogeneous points with normalised weights, the
  /// Cartesian part scaled by 2^-e.
  [[nodiscard]] std::vector<Point<T, D + 1>> homogeneous_points(int e) const {
    std::vector<Point<T, D + 1>> H(P_.size());
    for (std::size_t i = 0; i < P_.size(); ++i) {
      for (int d = 0; d < D; ++d) H[i][d] = wn_[i] * std::ldexp(P_[i][d], -e);
      H[i][D] = wn_[i];
    }
    return H;
  }

  /// Derivatives 0..k of R at t into out[0..k] (see derivative_at). Far outside [0, 1]
  /// (|s| > 1) the derivatives of R in u = 1/s come first, then those in t by the chain
  /// rule for t = 1/u (+ 1): d^k R/dt^k = (-1)^k sum_(j=1..k) L(k,j) u^(k+j) d^j R/du^j,
  /// with the Lah numbers L(k,j) = C(k-1, j-1) k!/j!, so that R' ~ 1/t^2 is computed
  /// without cancelling terms of size 1 (accurate to a few eps relative at t = 1e100).
  void evaluate_derivatives(T t, int k, VectorType* out) const {
    const int e = detail::scale_exponent<PointType>(P_);
    const auto H = homogeneous_points(e);
    detail::Scratch<Point<T, D + 1>> hb(static_cast<std::size_t>(k) + 1);
    std::span<Point<T, D + 1>> hd(hb.data(), static_cast<std::size_t>(k) + 1);
    const auto var = detail::derivatives_for_ratio<Point<T, D + 1>, T>(H, t, k, hd);
    if (!var) {
      throw InvalidArgument("t", "extrapolating a degree-" + std::to_string(degree()) + " rational curve to t = " +
                                     detail::format_number(t) +
                                     " exceeds the range of the floating point type (its Taylor coefficients overflow)");
    }
    const T w = hd[0][D];
    if (w == 0) {
      throw InvalidArgument("t", "the curve has a pole at t = " + detail::format_number(t) + " (its weight function vanishes there)");
    }
    // [PT97, eq. 4.8] in whichever variable the homogeneous derivatives are.
    detail::quotient_rule<T, D>(hd, k, out);
    if (*var == detail::DerivativeVariable::u && k >= 1) {
      const T s = t > 1 ? t - 1 : t, u = 1 / s;
      VectorType r{};
      for (int j = 1; j <= k; ++j) {
        // L(k,j) = C(k-1, j-1) k!/j!; u^(k+j) by repeated multiplication (k small).
        T lah = binomial<T>(k - 1, j - 1);
        for (int i = j + 1; i <= k; ++i) lah *= static_cast<T>(i);
        T uk = 1;
        for (int i = 0; i < k + j; ++i) uk *= u;
        r += (lah * uk) * out[j];
      }
      out[k] = (k % 2 == 0) ? r : -r;
    }
    const std::string what = k == 0 ? "the curve's value" : "the derivative of order " + std::to_string(k);
    for (int d = 0; d < D; ++d) out[k][d] = std::ldexp(out[k][d], e);
    if (!detail::all_finite(out[k])) {
      // Finite homogeneous values, so an overflow here comes from dividing by a tiny
      // weight function: t is within rounding of a pole, or the value is just too large.
      detail::throw_not_representable(what, detail::format_number(t) + " (at or next to a pole, or beyond the range)");
    }
  }

  /// The curve with points Q and weights W (normalised scale, all > 0), the weights
  /// scaled back by 2^wexp_ when none under- or overflows; InvalidArgument(where, ...)
  /// naming the operation's argument when a point is not representable.
  [[nodiscard]] RationalBezier finish(std::vector<PointType> Q, std::vector<T> W, const char* where, const char* what) const {
    for (std::size_t i = 0; i < Q.size(); ++i) {
      if (!detail::all_finite(Q[i])) {
        throw InvalidArgument(where, std::string(what) + " is not representable: its control point " + std::to_string(i) +
                                         " has a coordinate beyond the largest finite number");
      }
      if (!(W[i] > 0)) {
        throw InvalidArgument(where, std::string(what) + " is not representable: its weight " + std::to_string(i) + " underflows to 0");
      }
    }
    std::vector<T> back(W.size());
    bool ok = true;
    for (std::size_t i = 0; i < W.size() && ok; ++i) {
      back[i] = std::ldexp(W[i], wexp_);
      ok = back[i] > 0 && std::isfinite(back[i]) && std::ldexp(back[i], -wexp_) == W[i];
    }
    return RationalBezier(std::move(Q), ok ? std::move(back) : std::move(W), detail::Trusted{});
  }

  std::vector<PointType> P_;
  std::vector<T> w_;   ///< as given
  std::vector<T> wn_;  ///< w_ 2^-wexp_, the largest in [0.5, 1)
  int wexp_ = 0;
};

static_assert(DifferentiableCurve<RationalBezier<double, 2>>);
static_assert(SplittableCurve<RationalBezier<double, 3>>);

}  // namespace casteljau
