// B-spline and NURBS curves of any degree p >= 1 and dimension: evaluation by de Boor's
// algorithm, derivatives from the basis-function derivatives, and the exact Bézier pieces
// by blossoming [PT97, chapters 2-4; Ramshaw87].
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

namespace detail {

/// The blossom of span s of the B-spline (U, p, P) at the p arguments u[0..p-1] by de
/// Boor's recurrence with one argument per level [Ramshaw87; PT97, A3.1 for equal
/// arguments]: d_j = P_{s-p+j}; at level r, d_j = lerp(d_{j-1}, d_j, (u_r - U_i) /
/// (U_{i+p+1-r} - U_i)), i = s - p + j. Symmetric in its arguments; equal arguments u
/// give the curve point. Every denominator is a knot difference >= U_{s+1} - U_s > 0.
/// Convex combinations for arguments in [U_s, U_{s+1}]. Cost O(p^2).
template <class V, class T>
V de_boor_blossom(std::span<const T> U, int p, std::size_t s, std::span<const V> P, std::span<const T> u) {
  Scratch<V> scratch(static_cast<std::size_t>(p) + 1);
  V* d = scratch.data();
  for (int j = 0; j <= p; ++j) d[j] = P[s - static_cast<std::size_t>(p) + static_cast<std::size_t>(j)];
  for (int r = 1; r <= p; ++r) {
    for (int j = p; j >= r; --j) {
      const std::size_t i = s - static_cast<std::size_t>(p) + static_cast<std::size_t>(j);
      const T alpha = (u[static_cast<std::size_t>(r - 1)] - U[i]) / (U[i + static_cast<std::size_t>(p + 1 - r)] - U[i]);
      d[j] = lerp(d[j - 1], d[j], alpha);
    }
  }
  return d[p];
}

/// The Bézier control points of span s: the blossom at (a^(p-j), b^j), j = 0..p, with
/// [a, b] = [U_s, U_{s+1}] [Ramshaw87; Farin02, 8.4]. Exact up to rounding: the piece is
/// the same polynomial.
template <class V, class T>
std::vector<V> span_bezier_points(std::span<const T> U, int p, std::size_t s, std::span<const V> P) {
  std::vector<V> Q(static_cast<std::size_t>(p) + 1);
  std::vector<T> args(static_cast<std::size_t>(p));
  for (int j = 0; j <= p; ++j) {
    std::fill(args.begin(), args.end() - j, U[s]);
    std::fill(args.end() - j, args.end(), U[s + 1]);
    Q[static_cast<std::size_t>(j)] = de_boor_blossom<V, T>(U, p, s, P, args);
  }
  return Q;
}

/// The non-empty spans s = p..n-1 (U_s < U_{s+1}) of a valid knot vector.
template <class T>
std::vector<std::size_t> nonempty_spans(std::span<const T> U, int p) {
  std::vector<std::size_t> spans;
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  for (std::size_t s = static_cast<std::size_t>(p); s < n; ++s) {
    if (U[s] < U[s + 1]) spans.push_back(s);
  }
  return spans;
}

template <class V>
void require_representable(const V& v, double u, const char* what) {
  for (int d = 0; d < V::dimension; ++d) {
    if (!std::isfinite(v[d])) {
      throw InvalidArgument("t", std::string(what) + " at t = " + format_number(u) + " is not representable (overflow)");
    }
  }
}

}  // namespace detail

/// A B-spline curve C(u) = sum_i N_{i,p}(u) P_i with degree p >= 1, knots U_0..U_{n+p}
/// and control points P_0..P_{n-1}, on the domain [U_p, U_n]. Invariants (checked in the
/// constructor, naming "degree", "knots", "knots[i]", "points[i][j]"): the knot rules of
/// check_knots, n + p + 1 knots, finite points. Clamped or not: nothing assumes the end
/// knots are repeated. At a knot inside the domain the right limit answers, at U_n the
/// left one; outside the domain the first or last piece is extrapolated.
template <class T, int D>
class BSpline {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  BSpline(int degree, std::vector<T> knots, std::vector<PointType> points)
      : p_(degree), U_(std::move(knots)), P_(std::move(points)) {
    if (p_ < 1) throw InvalidArgument("degree", "a B-spline needs degree >= 1, got " + std::to_string(p_));
    if (P_.size() < static_cast<std::size_t>(p_) + 1) {
      throw InvalidArgument("points", "degree " + std::to_string(p_) + " needs at least " + std::to_string(p_ + 1) +
                                          " control points, got " + std::to_string(P_.size()));
    }
    if (U_.size() != P_.size() + static_cast<std::size_t>(p_) + 1) {
      throw InvalidArgument("knots", "needs len(points) + degree + 1 = " + std::to_string(P_.size() + static_cast<std::size_t>(p_) + 1) +
                                         " knots, got " + std::to_string(U_.size()));
    }
    check_knots<T>(U_, p_);
    for (std::size_t i = 0; i < P_.size(); ++i) require_finite_point(P_[i], "points[" + std::to_string(i) + "]");
  }

  [[nodiscard]] int degree() const { return p_; }
  [[nodiscard]] const std::vector<T>& knots() const { return U_; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] Interval<T> domain() const { return {U_[static_cast<std::size_t>(p_)], U_[P_.size()]}; }

  /// C(u) by de Boor's algorithm [PT97, A3.1 in its de Boor form]: convex combinations
  /// inside the domain, error a few eps of max |P|. Throws InvalidArgument("t", ...) for
  /// a non-finite u or an extrapolated point that overflows. Cost O(log n + p^2).
  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    const std::size_t s = find_span<T>(U_, p_, u);
    detail::Scratch<T> args(static_cast<std::size_t>(p_));
    std::fill(args.data(), args.data() + p_, u);
    const PointType c = detail::de_boor_blossom<PointType, T>(U_, p_, s, P_, std::span<const T>(args.data(), static_cast<std::size_t>(p_)));
    detail::require_representable(c, static_cast<double>(u), "the curve's point");
    return c;
  }

  /// The k-th derivative (k >= 0; zero for k > p) at u: sum_j N^(k)_{s-p+j,p}(u) P_{s-p+j}
  /// [PT97, A3.2], with the same span rule as evaluation. Cost O(p^2 + k p).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 0) return (*this)(u).to_vector();
    if (k > p_) return VectorType{};
    const std::size_t s = find_span<T>(U_, p_, u);
    const auto ders = basis_function_derivatives<T>(U_, p_, s, u, k);
    // Differences from the span's first point: the derivative weights sum to 0, so the
    // origin cancels and translations do not cost accuracy.
    const PointType& base = P_[s - static_cast<std::size_t>(p_)];
    VectorType v{};
    for (int j = 1; j <= p_; ++j) {
      v += ders[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] * (P_[s - static_cast<std::size_t>(p_) + static_cast<std::size_t>(j)] - base);
    }
    detail::require_representable(v, static_cast<double>(u), "the derivative");
    return v;
  }

  /// The same curve traversed backwards on the same domain: u -> U_p + U_n - u, knots
  /// reflected and reversed, points reversed.
  [[nodiscard]] BSpline reverse() const {
    const T a = domain().lo, b = domain().hi;
    std::vector<T> V(U_.size());
    for (std::size_t i = 0; i < U_.size(); ++i) V[i] = a + b - U_[U_.size() - 1 - i];
    V[static_cast<std::size_t>(p_)] = a;  // exact domain ends despite rounding
    V[P_.size()] = b;
    return BSpline(p_, std::move(V), std::vector<PointType>(P_.rbegin(), P_.rend()));
  }

  /// The image under an affine map (affine invariance: map the control points).
  [[nodiscard]] BSpline transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    return BSpline(p_, U_, std::move(Q));
  }

  /// The box of the control points: contains the curve over its domain.
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }

  friend bool operator==(const BSpline&, const BSpline&) = default;

 private:
  int p_;
  std::vector<T> U_;
  std::vector<PointType> P_;
};

/// The exact Bézier pieces of a B-spline: one degree-p piece per non-empty knot span of
/// the domain, breaks at the distinct knots U_p .. U_n (blossoming; cost O(p^3) a span).
template <class T, int D>
Pieces<T, D> pieces(const BSpline<T, D>& c) {
  const std::span<const T> U(c.knots());
  std::vector<BezierPiece<T, D>> segs;
  std::vector<T> breaks;
  for (const std::size_t s : detail::nonempty_spans(U, c.degree())) {
    segs.emplace_back(Bezier<T, D>(detail::span_bezier_points<Point<T, D>, T>(U, c.degree(), s, c.points())));
    breaks.push_back(U[s]);
  }
  breaks.push_back(c.domain().hi);
  return Pieces<T, D>(std::move(segs), std::move(breaks));
}

static_assert(DifferentiableCurve<BSpline<double, 2>>);
static_assert(ControlPolygonCurve<BSpline<double, 3>>);

/// A NURBS curve: C(u) = sum N_{i,p}(u) w_i P_i / sum N_{i,p}(u) w_i with Cartesian
/// control points P_i and weights w_i > 0, evaluated in homogeneous coordinates
/// (w_i P_i, w_i) [PT97, chapter 4]. The knots, degree and domain rules are those of
/// BSpline. Computations use the weights scaled by one power of two so that the largest
/// lies in [0.5, 1) (exact, and the same curve), so that w_i P_i cannot overflow.
template <class T, int D>
class Nurbs {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using Homogeneous = BSpline<T, D + 1>;
  static constexpr int dimension = D;

  Nurbs(int degree, std::vector<T> knots, std::vector<PointType> points, std::vector<T> weights)
      : P_(std::move(points)), w_(std::move(weights)), h_(make_homogeneous(degree, std::move(knots), P_, w_)) {}

  [[nodiscard]] int degree() const { return h_.degree(); }
  [[nodiscard]] const std::vector<T>& knots() const { return h_.knots(); }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] const std::vector<T>& weights() const { return w_; }
  [[nodiscard]] Interval<T> domain() const { return h_.domain(); }
  /// The homogeneous B-spline (w_i P_i, w_i), weights scaled as the class comment says.
  [[nodiscard]] const Homogeneous& homogeneous() const { return h_; }

  /// C(u): de Boor on the homogeneous points, then the projection. Inside the domain the
  /// weight sum is >= min w_i > 0 (convex combination), so there is no pole there.
  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    return project(h_(u).to_vector(), u);
  }

  /// The k-th derivative (k >= 0) by the quotient rule on the homogeneous derivatives
  /// A^(j), w^(j): C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w [PT97, A4.2].
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    std::vector<Point<T, D + 1>> hd(static_cast<std::size_t>(k) + 1);
    for (int j = 0; j <= k; ++j) hd[static_cast<std::size_t>(j)] = Point<T, D + 1>::from_vector(h_.derivative_at(u, j));
    project(hd[0].to_vector(), u);  // the pole check
    std::vector<VectorType> r(static_cast<std::size_t>(k) + 1);
    detail::quotient_rule<T, D>(hd, k, r.data());
    detail::require_representable(r[static_cast<std::size_t>(k)], static_cast<double>(u), "the derivative");
    return r[static_cast<std::size_t>(k)];
  }

  [[nodiscard]] Nurbs reverse() const {
    const Homogeneous r = h_.reverse();
    return Nurbs(degree(), r.knots(), std::vector<PointType>(P_.rbegin(), P_.rend()), std::vector<T>(w_.rbegin(), w_.rend()));
  }

  /// Affine maps act on the Cartesian control points; weights are unchanged.
  [[nodiscard]] Nurbs transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    return Nurbs(degree(), knots(), std::move(Q), w_);
  }

  /// The box of the control points: contains the curve over its domain (weights > 0).
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }

  friend bool operator==(const Nurbs&, const Nurbs&) = default;

 private:
  static Homogeneous make_homogeneous(int degree, std::vector<T> knots, const std::vector<PointType>& P, const std::vector<T>& w) {
    if (w.size() != P.size()) {
      throw InvalidArgument("weights", "needs one weight per control point: " + std::to_string(P.size()) + " points but " +
                                           std::to_string(w.size()) + " weights");
    }
    T wmax = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      const std::string where = "weights[" + std::to_string(i) + "]";
      require_finite(w[i], where);
      if (!(w[i] > 0)) throw InvalidArgument(where, "weight must be > 0, got " + detail::format_number(w[i]));
      wmax = std::max(wmax, w[i]);
    }
    for (std::size_t i = 0; i < P.size(); ++i) require_finite_point(P[i], "points[" + std::to_string(i) + "]");
    int e = 0;
    if (wmax > 0) std::frexp(wmax, &e);
    std::vector<Point<T, D + 1>> H(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
      const T wi = std::ldexp(w[i], -e);
      if (!(wi > 0)) {
        throw InvalidArgument("weights[" + std::to_string(i) + "]",
                              "weight " + detail::format_number(w[i]) + " is too small next to the largest weight " +
                                  detail::format_number(wmax) + " (their ratio underflows)");
      }
      for (int d = 0; d < D; ++d) H[i][d] = wi * P[i][d];
      H[i][D] = wi;
    }
    // The homogeneous points are finite products of finite values: only the degree and
    // knot errors can come from here, and they name the fields as they are.
    return Homogeneous(degree, std::move(knots), std::move(H));
  }

  PointType project(const Vector<T, D + 1>& h, T u) const {
    PointType c;
    if (!(h[D] > 0) || !std::isfinite(h[D])) {
      throw InvalidArgument("t", "the curve has a pole at t = " + detail::format_number(u) + " (its weight function vanishes there)");
    }
    for (int d = 0; d < D; ++d) c[d] = h[d] / h[D];
    detail::require_representable(c, static_cast<double>(u), "the curve's point");
    return c;
  }

  std::vector<PointType> P_;
  std::vector<T> w_;
  Homogeneous h_;
};

/// The exact rational Bézier pieces of a NURBS curve (the pieces of its homogeneous
/// B-spline, projected).
template <class T, int D>
Pieces<T, D> pieces(const Nurbs<T, D>& c) {
  const auto& h = c.homogeneous();
  const std::span<const T> U(h.knots());
  std::vector<BezierPiece<T, D>> segs;
  std::vector<T> breaks;
  for (const std::size_t s : detail::nonempty_spans(U, h.degree())) {
    const Bezier<T, D + 1> hb(detail::span_bezier_points<Point<T, D + 1>, T>(U, h.degree(), s, h.points()));
    segs.emplace_back(RationalBezier<T, D>::from_homogeneous(hb));
    breaks.push_back(U[s]);
  }
  breaks.push_back(c.domain().hi);
  return Pieces<T, D>(std::move(segs), std::move(breaks));
}

static_assert(DifferentiableCurve<Nurbs<double, 2>>);
static_assert(ControlPolygonCurve<Nurbs<double, 3>>);

}  // namespace casteljau
