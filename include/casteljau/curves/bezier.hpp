// Bézier curves of any degree n in D dimensions: P(t) = sum_i B(i,n)(t) P_i on [0, 1].
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "casteljau/basis/bernstein.hpp"
#include "casteljau/basis/de_casteljau.hpp"
#include "casteljau/basis/extrapolate.hpp"
#include "casteljau/basis/power.hpp"
#include "casteljau/core/affine.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

namespace detail {
/// Tag of the private constructors that curve operations use for results whose
/// invariants the operation itself guarantees (split, elevate, reverse: convex
/// combinations or permutations of valid data), so that they are not checked twice.
struct Trusted {};
}  // namespace detail

/// A Bézier curve with control points P_0..P_n, n >= 0, over the domain [0, 1].
///
/// Invariants (checked once, in the constructor): at least one control point, every
/// coordinate finite. The hodograph (derivative curve) is returned as a Bezier whose
/// control "points" are the tips of the derivative vectors placed at the origin.
template <class T, int D>
class Bezier {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  /// Throws InvalidArgument("points", ...) for no points, ("points[i][j]", ...) for a
  /// non-finite coordinate.
  explicit Bezier(std::vector<PointType> points) : P_(std::move(points)) {
    if (P_.empty()) throw InvalidArgument("points", "a Bézier curve needs at least one control point");
    require_finite_points(P_, "points");
  }
  Bezier(std::initializer_list<PointType> points) : Bezier(std::vector<PointType>(points)) {}

  /// The curve with power-basis coefficients a_0..a_n (a_j the vector multiplying t^j;
  /// a_0 is the start point as a vector from the origin): P = M^-1 a. Well conditioned
  /// (M^-1 has entries in [0, 1]).
  static Bezier from_power(std::span<const VectorType> a) {
    if (a.empty()) throw InvalidArgument("coefficients", "needs at least one power coefficient");
    require_finite_points(a, "coefficients");
    const int n = static_cast<int>(a.size()) - 1;
    const Matrix<T> m = power_to_bernstein_matrix<T>(n);
    std::vector<PointType> P(a.size());
    for (int i = 0; i <= n; ++i) {
      VectorType s{};
      for (int j = 0; j <= i; ++j) s += m(i, j) * a[static_cast<std::size_t>(j)];
      P[static_cast<std::size_t>(i)] = PointType::from_vector(s);
    }
    return Bezier(std::move(P));
  }

  [[nodiscard]] int degree() const { return static_cast<int>(P_.size()) - 1; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] static constexpr Interval<T> domain() { return {T(0), T(1)}; }

  /// P(t) for any finite t. On [0, 1] by de Casteljau (see de_casteljau for accuracy:
  /// a few eps of max |P|, exact at 0 and 1). Outside [0, 1] the same polynomial is
  /// extended, by its Taylor form about the nearer end point on a power-of-two-scaled
  /// copy (see detail::evaluate_anywhere: error about eps max|P| (1 + 2 d)^n at distance
  /// d from the domain, in practice far less; see docs/accuracy.md). Never returns NaN
  /// or infinity: throws InvalidArgument("t", ...) for a non-finite t or when the value
  /// is not representable (it overflows). Cost O(n^2).
  [[nodiscard]] PointType operator()(T t) const {
    require_finite(t, "t");
    return detail::evaluate_anywhere<PointType, T>(P_, t);
  }

  /// The k-th derivative vector at t (k >= 0; k = 0 is the point as a vector from the
  /// origin): n!/(n-k)! times the value of the k-th forward differences [Farin02, 5.3],
  /// computed on a copy scaled by a power of two so that the differences cannot
  /// overflow. Zero when k > n. Any finite t, as operator(); throws InvalidArgument("t",
  /// ...) when the derivative is not representable, ("k", ...) for k < 0.
  [[nodiscard]] VectorType derivative_at(T t, int k = 1) const {
    require_finite(t, "t");
    require_order(k);
    if (k == 0) return (*this)(t).to_vector();
    const int n = degree();
    if (k > n) return VectorType{};
    const int e = detail::scale_exponent<PointType>(P_);
    std::vector<PointType> d(P_.size());
    for (std::size_t i = 0; i < P_.size(); ++i) d[i] = detail::scaled(P_[i], -e);
    for (int r = 1; r <= k; ++r)
      for (int i = 0; i + r <= n; ++i) {
        const auto iu = static_cast<std::size_t>(i);
        d[iu] = PointType::from_vector(d[iu + 1] - d[iu]);
      }
    d.resize(static_cast<std::size_t>(n - k + 1));
    PointType v = detail::evaluate_anywhere<PointType, T>(d, t, "the derivative");
    for (int j = 0; j < k; ++j)
      for (int c = 0; c < D; ++c) v[c] *= static_cast<T>(n - j);
    v = detail::scaled(v, e);
    if (!detail::all_finite(v)) detail::throw_not_representable("the derivative of order " + std::to_string(k), detail::format_number(t));
    return v.to_vector();
  }

  /// The k-th derivative curve (hodograph for k = 1; the curve itself for k = 0), degree
  /// max(n - k, 0), with control points n!/(n-k)! Delta^k P_i. For k > n, the zero curve
  /// of degree 0. Throws InvalidArgument("k", ...) when a control point of the result is
  /// not representable (the differences of coordinates near the largest double).
  [[nodiscard]] Bezier derivative(int k = 1) const {
    require_order(k);
    if (k == 0) return *this;
    const int n = degree();
    if (k > n) return Bezier({PointType{}});
    std::vector<VectorType> d = differences(k);
    T f = 1;
    for (int j = 0; j < k; ++j) f *= static_cast<T>(n - j);
    std::vector<PointType> Q(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) Q[i] = PointType::from_vector(d[i] * f);
    return checked(std::move(Q), "k", "the derivative curve of order ", k);
  }

  /// The halves on [0, t] and [t, 1], each reparametrised to [0, 1] (de Casteljau
  /// subdivision). Requires t in [0, 1]; for other intervals use portion().
  [[nodiscard]] Split<Bezier> split(T t) const {
    require_finite(t, "t");
    if (t < 0 || t > 1) throw InvalidArgument("t", "split parameter must lie in [0, 1], got " + detail::format_number(t));
    std::vector<PointType> L(P_.size()), R(P_.size());
    de_casteljau_split<PointType, T>(P_, t, L, R);
    // Convex combinations of finite points: finite, except that rounding may step past
    // the largest double when coordinates are within an ulp of it; checked (O(n)).
    return {checked(std::move(L), "t", "the left part"), checked(std::move(R), "t", "the right part")};
  }

  /// The same curve restricted to [a, b] and reparametrised to [0, 1]: Q_i is the blossom
  /// b(a^(n-i), b^i) [Farin02, 4.3]. Works for any finite a, b: inside [0, 1] it cuts the
  /// curve, outside it extends the polynomial (extrapolation loses accuracy in proportion
  /// to how far beyond [0, 1] the interval reaches); a > b reverses the direction.
  /// Throws InvalidArgument naming a or b when a control point of the extension is not
  /// representable. Cost O(n^3).
  [[nodiscard]] Bezier portion(T a, T b) const {
    require_finite(a, "a");
    require_finite(b, "b");
    const int n = degree();
    std::vector<PointType> Q(P_.size());
    std::vector<T> u(static_cast<std::size_t>(n));
    for (int i = 0; i <= n; ++i) {
      std::fill(u.begin(), u.end() - i, a);
      std::fill(u.end() - i, u.end(), b);
      Q[static_cast<std::size_t>(i)] = blossom<PointType, T>(P_, u);
    }
    return checked(std::move(Q), std::abs(a) > std::abs(b) ? "a" : "b", "the portion");
  }

  /// The same curve traversed from P_n to P_0: Q(t) = P(1 - t).
  [[nodiscard]] Bezier reverse() const { return Bezier(std::vector<PointType>(P_.rbegin(), P_.rend()), detail::Trusted{}); }

  /// The image under an affine map: by affine invariance, the curve of the mapped control
  /// points is the mapped curve (exactly, up to rounding).
  [[nodiscard]] Bezier transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    return checked(std::move(Q), "m", "the transformed curve");
  }

  /// The same curve at degree n + r (r >= 0), by Forrest's equations with normalised
  /// hypergeometric weights (detail::elevate_bezier_points: no binomial overflows at any
  /// degree; exact for a constant curve). Error about (2 min(n, r) + 4) eps of the control
  /// polygon's extent. Cost O((n + r) min(n, r)).
  [[nodiscard]] Bezier elevate(int r = 1) const {
    if (r < 0) throw InvalidArgument("r", "degree elevation count must be >= 0, got " + std::to_string(r));
    if (r == 0) return *this;
    return checked(detail::elevate_bezier_points<T, PointType>(std::span<const PointType>(P_), r), "r", "the elevated curve");
  }

  /// Power-basis coefficients a_0..a_n with P(t) = sum_j a_j t^j: a = M P. Exact
  /// arithmetic would give the same curve, but in floating point the conversion loses
  /// about log10(3^n) digits at degree n; use only at low degree (see docs/accuracy.md).
  [[nodiscard]] std::vector<VectorType> to_power() const {
    const int n = degree();
    const Matrix<T> m = bernstein_to_power_matrix<T>(n);
    std::vector<VectorType> a(P_.size());
    for (int j = 0; j <= n; ++j) {
      VectorType s{};
      for (int i = 0; i <= j; ++i) s += m(j, i) * P_[static_cast<std::size_t>(i)].to_vector();
      a[static_cast<std::size_t>(j)] = s;
    }
    return a;
  }

  /// The box of the control points: contains the curve on [0, 1] (convex hull property),
  /// not tight in general; see bounds() in algo/bounds.hpp for the tight box.
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }

  friend bool operator==(const Bezier&, const Bezier&) = default;

 private:
  Bezier(std::vector<PointType> points, detail::Trusted) : P_(std::move(points)) {}

  static void require_order(int k) {
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  }
  /// The curve of Q, whose points are finite unless the arithmetic that made them
  /// overflowed: then InvalidArgument(where, "<what> is not representable ..."), naming
  /// the operation's argument rather than a finite input value. O(n D).
  // `what` names the curve in the message (with `order` appended when >= 0); the text is
  // built only when a point is not finite.
  static Bezier checked(std::vector<PointType> Q, const char* where, const char* what, int order = -1) {
    for (std::size_t i = 0; i < Q.size(); ++i) {
      if (!detail::all_finite(Q[i])) {
        throw InvalidArgument(where, std::string(what) + (order >= 0 ? std::to_string(order) : std::string()) +
                                         " is not representable: its control point " + std::to_string(i) +
                                         " has a coordinate beyond the largest finite number");
      }
    }
    return Bezier(std::move(Q), detail::Trusted{});
  }
  /// Delta^k P_i, i = 0..n-k, as vectors.
  [[nodiscard]] std::vector<VectorType> differences(int k) const {
    const int n = degree();
    std::vector<VectorType> d(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) d[static_cast<std::size_t>(i)] = P_[static_cast<std::size_t>(i) + 1] - P_[static_cast<std::size_t>(i)];
    for (int r = 2; r <= k; ++r) {
      for (int i = 0; i + r <= n; ++i) d[static_cast<std::size_t>(i)] = d[static_cast<std::size_t>(i) + 1] - d[static_cast<std::size_t>(i)];
    }
    d.resize(static_cast<std::size_t>(n - k + 1));
    return d;
  }
  std::vector<PointType> P_;
};

static_assert(Curve<Bezier<double, 2>>);
static_assert(DifferentiableCurve<Bezier<double, 3>>);
static_assert(SplittableCurve<Bezier<double, 1>>);

}  // namespace casteljau
