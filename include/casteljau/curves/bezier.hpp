// Bézier curves of any degree n in D dimensions: P(t) = sum_i B(i,n)(t) P_i on [0, 1].
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "casteljau/basis/bernstein.hpp"
#include "casteljau/basis/de_casteljau.hpp"
#include "casteljau/basis/power.hpp"
#include "casteljau/core/affine.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

template <class T, int D>
class Bezier;

/// Result of Bezier::reduce: the lower-degree curve and how far it is from the original.
template <class T, int D>
struct Reduction {
  Bezier<T, D> curve;
  T max_error;    ///< max distance at 64 (n + 1) + 1 uniform parameters (an estimate, from below)
  T error_bound;  ///< guaranteed: max control point distance after elevating back to degree n
};

/// Whether degree reduction keeps the end points (and so C0 joins of a composite curve).
enum class Endpoints { keep, free };

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
    for (std::size_t i = 0; i < P_.size(); ++i) require_finite_point(P_[i], "points[" + std::to_string(i) + "]");
  }
  Bezier(std::initializer_list<PointType> points) : Bezier(std::vector<PointType>(points)) {}

  /// The curve with power-basis coefficients a_0..a_n (a_j the vector multiplying t^j;
  /// a_0 is the start point as a vector from the origin): P = M^-1 a. Well conditioned
  /// (M^-1 has entries in [0, 1]).
  static Bezier from_power(std::span<const VectorType> a) {
    if (a.empty()) throw InvalidArgument("coefficients", "needs at least one power coefficient");
    for (std::size_t j = 0; j < a.size(); ++j) require_finite_point(a[j], "coefficients[" + std::to_string(j) + "]");
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

  /// P(t) by de Casteljau (see de_casteljau for accuracy). Any finite t: outside [0, 1]
  /// the same polynomial is extrapolated. Throws for a non-finite t. Cost O(n^2).
  [[nodiscard]] PointType operator()(T t) const {
    require_finite(t, "t");
    return de_casteljau<PointType, T>(P_, t);
  }

  /// The k-th derivative vector at t (k >= 1): n!/(n-k)! times de Casteljau on the k-th
  /// forward differences [Farin02, 5.3]. Zero when k > n.
  [[nodiscard]] VectorType derivative_at(T t, int k = 1) const {
    require_finite(t, "t");
    require_order(k);
    const int n = degree();
    if (k > n) return VectorType{};
    std::vector<VectorType> d = differences(k);
    VectorType v = de_casteljau<VectorType, T>(d, t);
    for (int j = 0; j < k; ++j) v *= static_cast<T>(n - j);
    return v;
  }

  /// The k-th derivative curve (hodograph for k = 1), degree max(n - k, 0), with control
  /// points n!/(n-k)! Delta^k P_i. For k > n, the zero curve of degree 0.
  [[nodiscard]] Bezier derivative(int k = 1) const {
    require_order(k);
    const int n = degree();
    if (k > n) return Bezier({PointType{}});
    std::vector<VectorType> d = differences(k);
    T f = 1;
    for (int j = 0; j < k; ++j) f *= static_cast<T>(n - j);
    std::vector<PointType> Q(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) Q[i] = PointType::from_vector(d[i] * f);
    return Bezier(std::move(Q));
  }

  /// The halves on [0, t] and [t, 1], each reparametrised to [0, 1] (de Casteljau
  /// subdivision). Requires t in [0, 1]; for other intervals use portion().
  [[nodiscard]] Split<Bezier> split(T t) const {
    require_finite(t, "t");
    if (t < 0 || t > 1) throw InvalidArgument("t", "split parameter must lie in [0, 1], got " + detail::format_number(t));
    std::vector<PointType> L(P_.size()), R(P_.size());
    de_casteljau_split<PointType, T>(P_, t, L, R);
    return {Bezier(std::move(L)), Bezier(std::move(R))};
  }

  /// The same curve restricted to [a, b] and reparametrised to [0, 1]: Q_i is the blossom
  /// b(a^(n-i), b^i) [Farin02, 4.3]. Works for any finite a, b: inside [0, 1] it cuts the
  /// curve, outside it extends the polynomial (extrapolation loses accuracy in proportion
  /// to how far beyond [0, 1] the interval reaches); a > b reverses the direction.
  /// Cost O(n^3).
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
    return Bezier(std::move(Q));
  }

  /// The same curve traversed from P_n to P_0: Q(t) = P(1 - t).
  [[nodiscard]] Bezier reverse() const { return Bezier(std::vector<PointType>(P_.rbegin(), P_.rend())); }

  /// The image under an affine map: by affine invariance, the curve of the mapped control
  /// points is the mapped curve (exactly, up to rounding).
  [[nodiscard]] Bezier transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q(P_.size());
    std::transform(P_.begin(), P_.end(), Q.begin(), [&](const PointType& p) { return m(p); });
    return Bezier(std::move(Q));
  }

  /// The same curve at degree n + r (r >= 0), by Forrest's equations [Forrest72;
  /// Farin02, 5.1]: Q_i = sum_j C(r, i-j) C(n, j) / C(n+r, i) P_j, a convex combination.
  /// Past degree 1000, where C(n+r, i) would overflow a double, one degree at a time
  /// (Q_i = i/(k+1) P_{i-1} + (1 - i/(k+1)) P_i, also convex; error about r eps).
  /// Cost O((n + r) min(n, r)), or O(r (n + r)) stepwise.
  [[nodiscard]] Bezier elevate(int r = 1) const {
    if (r < 0) throw InvalidArgument("times", "degree elevation count must be >= 0, got " + std::to_string(r));
    const int n = degree();
    if (n + r > 1000) {
      std::vector<PointType> cur(P_);
      for (int k = n; k < n + r; ++k) {
        std::vector<PointType> next(cur.size() + 1);
        next.front() = cur.front();
        next.back() = cur.back();
        for (int i = 1; i <= k; ++i) next[i] = lerp(cur[i], cur[i - 1], static_cast<T>(i) / static_cast<T>(k + 1));
        cur.swap(next);
      }
      return Bezier(std::move(cur));
    }
    std::vector<PointType> Q(P_.size() + static_cast<std::size_t>(r));
    for (int i = 0; i <= n + r; ++i) {
      // Affine combination of the P_j written as P_lo + sum c_j (P_j - P_lo), exact for
      // a constant curve.
      const int lo = std::max(0, i - r), hi = std::min(n, i);
      const T denom = binomial<T>(n + r, i);
      const PointType& base = P_[static_cast<std::size_t>(lo)];
      VectorType s{};
      for (int j = lo + 1; j <= hi; ++j) {
        s += (binomial<T>(r, i - j) * binomial<T>(n, j) / denom) * (P_[static_cast<std::size_t>(j)] - base);
      }
      Q[static_cast<std::size_t>(i)] = base + s;
    }
    return Bezier(std::move(Q));
  }

  /// The least-squares degree-m approximation (0 <= m <= n) in the L2 norm over [0, 1]:
  /// solves the Bernstein Gram system G_mm Q = G_mn P [Eck93; Farin02, 5.9], with the end
  /// points fixed when `endpoints` is keep (then m >= 1). Exact when the curve is a
  /// degree-elevated degree-m curve. The Gram matrix's condition number grows like 4^m, so
  /// results are reliable for m up to about 25 in double. Reports the error (see Reduction).
  [[nodiscard]] Reduction<T, D> reduce(int m, Endpoints endpoints = Endpoints::keep) const {
    const int n = degree();
    if (m < 0 || m > n) {
      throw InvalidArgument("degree", "target degree must lie in [0, " + std::to_string(n) + "], got " + std::to_string(m));
    }
    if (endpoints == Endpoints::keep && m < 1) {
      throw InvalidArgument("degree", "keeping both end points needs target degree >= 1, got " + std::to_string(m));
    }
    const auto cm = binomial_row<T>(m), cn = binomial_row<T>(n), c2m = binomial_row<T>(2 * m),
               cmn = binomial_row<T>(m + n);
    // int B(j,m) B(k,m) dt = C(m,j) C(m,k) / (C(2m, j+k) (2m+1)); likewise for (m, n).
    auto gmm = [&](int j, int k) {
      return cm[j] * cm[k] / (c2m[j + k] * static_cast<T>(2 * m + 1));
    };
    auto gmn = [&](int j, int i) {
      return cm[j] * cn[i] / (cmn[j + i] * static_cast<T>(m + n + 1));
    };
    // Reduced curves are built as offsets from P_0 so that translations cancel exactly.
    const PointType origin = P_.front();
    Eigen::Matrix<T, Eigen::Dynamic, D> rhs(m + 1, D);
    for (int j = 0; j <= m; ++j) {
      VectorType s{};
      for (int i = 0; i <= n; ++i) s += gmn(j, i) * (P_[static_cast<std::size_t>(i)] - origin);
      for (int d = 0; d < D; ++d) rhs(j, d) = s[d];
    }
    std::vector<PointType> Q(static_cast<std::size_t>(m) + 1);
    if (endpoints == Endpoints::free) {
      Matrix<T> g(m + 1, m + 1);
      for (int j = 0; j <= m; ++j)
        for (int k = 0; k <= m; ++k) g(j, k) = gmm(j, k);
      const Eigen::Matrix<T, Eigen::Dynamic, D> x = g.ldlt().solve(rhs);
      for (int j = 0; j <= m; ++j) Q[static_cast<std::size_t>(j)] = origin + row_vector(x, j);
    } else {
      const VectorType qm = P_.back() - origin;  // Q_0 = P_0 (offset 0), Q_m = P_n
      Q.front() = P_.front();
      Q.back() = P_.back();
      const int u = m - 1;  // unknowns Q_1..Q_{m-1}
      if (u > 0) {
        Matrix<T> g(u, u);
        Eigen::Matrix<T, Eigen::Dynamic, D> r(u, D);
        for (int j = 1; j <= u; ++j) {
          for (int k = 1; k <= u; ++k) g(j - 1, k - 1) = gmm(j, k);
          for (int d = 0; d < D; ++d) r(j - 1, d) = rhs(j, d) - gmm(j, m) * qm[d];
        }
        const Eigen::Matrix<T, Eigen::Dynamic, D> x = g.ldlt().solve(r);
        for (int j = 1; j <= u; ++j) Q[static_cast<std::size_t>(j)] = origin + row_vector(x, j - 1);
      }
    }
    Bezier reduced(std::move(Q));
    const Bezier back = reduced.elevate(n - m);
    T bound = 0;
    for (int i = 0; i <= n; ++i) bound = std::max(bound, distance(back.P_[static_cast<std::size_t>(i)], P_[static_cast<std::size_t>(i)]));
    T sampled = 0;
    const int samples = 64 * (n + 1);
    for (int s = 0; s <= samples; ++s) {
      const T t = static_cast<T>(s) / static_cast<T>(samples);
      sampled = std::max(sampled, distance((*this)(t), reduced(t)));
    }
    return {std::move(reduced), sampled, bound};
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
  [[nodiscard]] Box<T, D> control_bounds() const {
    Box<T, D> b = Box<T, D>::empty_box();
    for (const auto& p : P_) b.add(p);
    return b;
  }

  friend bool operator==(const Bezier&, const Bezier&) = default;

 private:
  static void require_order(int k) {
    if (k < 1) throw InvalidArgument("k", "derivative order must be >= 1, got " + std::to_string(k));
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
  template <class M>
  static VectorType row_vector(const M& x, int row) {
    VectorType v;
    for (int d = 0; d < D; ++d) v[d] = x(row, d);
    return v;
  }

  std::vector<PointType> P_;
};

static_assert(Curve<Bezier<double, 2>>);
static_assert(DifferentiableCurve<Bezier<double, 3>>);
static_assert(SplittableCurve<Bezier<double, 1>>);
static_assert(ControlPolygonCurve<Bezier<double, 4>>);

}  // namespace casteljau
