// Lagrange interpolating curves: the polynomial of degree n - 1 through n points at n
// distinct parameters, evaluated by the barycentric formulas (basis/barycentric.hpp), and
// its Bézier form (one piece, by collocation at Chebyshev points: refused above
// lagrange_max_bezier_degree, where the conversion stops being accurate to 1e-12).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "casteljau/basis/barycentric.hpp"
#include "casteljau/basis/bernstein.hpp"
#include "casteljau/basis/power.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The highest degree whose Bézier form pieces(Lagrange) gives. The Bernstein coefficients
/// of an interpolant of bounded data grow like 2^n relative to the curve (for data on
/// Chebyshev nodes most of all), and every query on the Bézier form (de Casteljau) then
/// loses eps times their size, whatever the conversion method: solving the collocation
/// system in long double changes nothing (docs/accuracy.md, "Lagrange curves"). Measured
/// over random data on equispaced and Chebyshev nodes, the worst disagreement between
/// the Bézier form and the barycentric evaluation, relative to max |p| on the domain, is
/// 6.2e-13 at degree 15 and first exceeds 1e-12 at degree 16. Above this degree bounds,
/// flatten, to_bezier and render refuse the curve rather than answer for another one.
inline constexpr int lagrange_max_bezier_degree = 15;

/// The polynomial curve P(u) of degree <= n - 1 with P(u_j) = P_j for n >= 1 points at
/// distinct finite parameters u_j in any order (n = 1: the constant P_0, as
/// scipy.interpolate.BarycentricInterpolator gives). Domain [min u_j, max u_j] (one point
/// for n = 1); outside it the
/// same polynomial is extrapolated. Evaluation by the second barycentric formula in O(n)
/// (exact at the parameters u_j), derivatives of every order in O(n k) (zero from order n
/// on), both with the weights computed once: O(n^2) in the constructor, O(n) through
/// on_nodes for Chebyshev nodes. Invariants (checked in the constructor, naming "params",
/// "params[j]", "points", "points[j][d]"): as many params as points, at least 1, finite,
/// params distinct, weights representable (barycentric_weights).
template <class T, int D>
class Lagrange {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  Lagrange(std::vector<T> params, std::vector<PointType> points) : u_(std::move(params)), P_(std::move(points)) {
    validate();
    set_domain();
    w_ = barycentric_weights<T>(u_);
  }

  /// The curve through points P_j at the n nodes of a family on [a, b]
  /// (interpolation_nodes), with the O(n) closed-form weights for Chebyshev nodes.
  static Lagrange on_nodes(Nodes kind, Interval<T> ab, std::vector<PointType> points) {
    std::vector<T> u = interpolation_nodes<T>(kind, points.size(), ab.lo, ab.hi);
    if (kind == Nodes::equispaced) return Lagrange(std::move(u), std::move(points));
    std::vector<T> w = chebyshev_weights<T>(kind, points.size());
    return Lagrange(std::move(u), std::move(points), std::move(w));
  }

  [[nodiscard]] const std::vector<T>& params() const { return u_; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  /// The barycentric weights (any common scale; see barycentric_weights).
  [[nodiscard]] const std::vector<T>& weights() const { return w_; }
  /// n - 1: the degree of the polynomial space (the actual degree may be lower).
  [[nodiscard]] int degree() const { return static_cast<int>(P_.size()) - 1; }
  [[nodiscard]] Interval<T> domain() const { return dom_; }

  /// P(u) by the barycentric formula (see barycentric_taylor): exact at the params, error
  /// a few eps times the Lebesgue function at u times max |P_j|. Throws
  /// InvalidArgument("t", ...) for a non-finite u or a value that overflows.
  [[nodiscard]] PointType operator()(T u) const { return PointType::from_vector(derivative_at(u, 0)); }

  /// The k-th derivative (k >= 0; k = 0 the point as a vector; zero for k >= n) at u,
  /// k! times the Taylor coefficient of barycentric_taylor. Cost O(n (k + 1)).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k >= static_cast<int>(P_.size())) return VectorType{};
    std::vector<VectorType> c(static_cast<std::size_t>(k) + 1);
    barycentric_taylor<VectorType, T, PointType>(u_, w_, P_, u, k, c.data());
    VectorType v = c[static_cast<std::size_t>(k)];
    for (int j = 2; j <= k; ++j) v *= static_cast<T>(j);
    for (int d = 0; d < D; ++d) {
      if (!std::isfinite(v[d])) {
        throw InvalidArgument("t", std::string(k == 0 ? "the curve's point" : "the derivative") + " at t = " +
                                       detail::format_number(u) + " is not representable (overflow)");
      }
    }
    return v;
  }

  /// P(u) by Neville's scheme (basis/barycentric.hpp): O(n^2), independent of the weights.
  [[nodiscard]] PointType neville(T u) const {
    require_finite(u, "t");
    return PointType::from_vector(casteljau::neville<VectorType, T, PointType>(u_, P_, u));
  }

  /// The same curve traversed backwards on the same domain: params u_j -> lo + hi - u_j,
  /// the same points and weights (reflection multiplies every weight by (-1)^(n-1), a
  /// common factor). O(n).
  [[nodiscard]] Lagrange reverse() const {
    std::vector<T> v(u_.size());
    for (std::size_t j = 0; j < u_.size(); ++j) {
      v[j] = u_[j] == dom_.lo ? dom_.hi : u_[j] == dom_.hi ? dom_.lo : dom_.lo + dom_.hi - u_[j];
    }
    return Lagrange(std::move(v), P_, w_);
  }

  /// The image under an affine map: the interpolant of the mapped points (interpolation
  /// on fixed params is linear in the data). O(n).
  [[nodiscard]] Lagrange transform(const Affine<T, D>& m) const { return Lagrange(u_, mapped_points(m, P_), w_); }

  /// The box of the Bézier control points of pieces(): it contains the curve over its
  /// domain. Throws as pieces() does above lagrange_max_bezier_degree. Cost O(n^3).
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(bezier().points()); }

  /// The curve as one Bézier curve of degree n - 1 on its domain (mapped to [0, 1]): the
  /// Bernstein coefficients b solve the collocation system sum_k B(k, n-1)(s_i) b_k =
  /// P(lo + s_i (hi - lo)) at the Chebyshev points s_i = (1 - cos(i pi / (n-1))) / 2 of
  /// [0, 1] (LU with partial pivoting); b_0 and b_(n-1) are then set to the exact end
  /// values. Accuracy in docs/accuracy.md; throws InvalidArgument("curve", ...) above
  /// lagrange_max_bezier_degree. Cost O(n^3).
  [[nodiscard]] Bezier<T, D> bezier() const {
    const int m = degree();
    if (m > lagrange_max_bezier_degree) {
      throw InvalidArgument("curve", "a lagrange curve of degree " + std::to_string(m) + " has no accurate Bézier form (the conversion " +
                                         "is trusted up to degree " + std::to_string(lagrange_max_bezier_degree) +
                                         "): evaluate it instead, or use fewer points");
    }
    const std::size_t n = P_.size();
    if (n == 1) return Bezier<T, D>({P_[0]});  // the constant
    Matrix<T> A(n, n);
    Eigen::Matrix<T, Eigen::Dynamic, D> rhs(static_cast<Eigen::Index>(n), D);
    std::vector<T> row(n);
    for (std::size_t i = 0; i < n; ++i) {
      const T s = (1 - std::cos(std::numbers::pi_v<T> * static_cast<T>(i) / static_cast<T>(m))) / 2;
      bernstein_all<T>(m, s, std::span<T>(row));
      for (std::size_t k = 0; k < n; ++k) A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = row[k];
      const PointType p = (*this)(i == 0 ? dom_.lo : i == n - 1 ? dom_.hi : dom_.at(s));
      for (int d = 0; d < D; ++d) rhs(static_cast<Eigen::Index>(i), d) = p[d];
    }
    const Eigen::Matrix<T, Eigen::Dynamic, D> b = A.partialPivLu().solve(rhs);
    std::vector<PointType> Q(n);
    for (std::size_t k = 0; k < n; ++k)
      for (int d = 0; d < D; ++d) Q[k][d] = b(static_cast<Eigen::Index>(k), d);
    Q.front() = (*this)(dom_.lo);
    Q.back() = (*this)(dom_.hi);
    return Bezier<T, D>(std::move(Q));
  }

  friend bool operator==(const Lagrange&, const Lagrange&) = default;

 private:
  /// Trusted weights (closed forms, or a reflection/affine image of a valid curve).
  Lagrange(std::vector<T> params, std::vector<PointType> points, std::vector<T> weights)
      : u_(std::move(params)), P_(std::move(points)), w_(std::move(weights)) {
    validate();
    set_domain();
  }

  void validate() const {
    if (u_.size() != P_.size()) {
      throw InvalidArgument("params", "needs one parameter per point: " + std::to_string(P_.size()) + " points but " +
                                          std::to_string(u_.size()) + " params");
    }
    if (P_.empty()) throw InvalidArgument("points", "a lagrange curve needs at least 1 point, got 0");
    detail::check_distinct_nodes<T>(u_, "params");
    require_finite_points(P_, "points");
  }

  void set_domain() {
    const auto [lo, hi] = std::minmax_element(u_.begin(), u_.end());
    if (!std::isfinite(*hi - *lo)) {
      throw InvalidArgument("params", "the domain [" + detail::format_number(*lo) + ", " + detail::format_number(*hi) +
                                          "] is longer than the largest double");
    }
    dom_ = Interval<T>(*lo, *hi);
  }

  std::vector<T> u_;
  std::vector<PointType> P_;
  std::vector<T> w_;
  Interval<T> dom_;
};

/// The exact Bézier form: one piece of degree n - 1 on the domain (Lagrange::bezier()).
/// Through one point the domain is the single parameter u_0, which pieces (their breaks
/// increase) cannot hold: the constant piece then spans [u_0, the next double] (the
/// previous one and u_0 at the largest double), so that the queries on the pieces answer
/// for the same point set and parameters within one ulp of u_0.
template <class T, int D>
Pieces<T, D> pieces(const Lagrange<T, D>& c) {
  const Interval<T> dom = c.domain();
  if (dom.lo == dom.hi) {
    const T up = std::nextafter(dom.lo, std::numeric_limits<T>::infinity());
    const std::vector<T> breaks = std::isfinite(up) ? std::vector<T>{dom.lo, up}
                                                    : std::vector<T>{std::nextafter(dom.lo, -std::numeric_limits<T>::infinity()), dom.lo};
    return Pieces<T, D>({BezierPiece<T, D>(c.bezier())}, breaks);
  }
  return Pieces<T, D>({BezierPiece<T, D>(c.bezier())}, {dom.lo, dom.hi});
}

static_assert(DifferentiableCurve<Lagrange<double, 2>>);
static_assert(Curve<Lagrange<double, 1>>);
static_assert(PiecewiseBezierCurve<Lagrange<double, 2>>);

}  // namespace casteljau
