// Tensor-product surfaces of scalar T and dimension D: BezierSurface,
// RationalBezierSurface, BSplineSurface and NurbsSurface, one class template over the
// kind. Each validates its data once (errors naming the grid position) and holds it as a
// detail::SurfaceForm (surfaces/surface_form.hpp), where the algorithms live once per
// scalar: evaluation and partial derivatives, normals and curvatures, splitting, degree
// elevation, knot insertion, isocurves, affine maps (`transform`) and the exact Bézier
// patches (`patches()`, the common form of every kind).
//
// The control grid is points[i][j]: i along u (the rows), j along v (the columns).
// Domains: [0, 1] x [0, 1] for the Bézier kinds, [U_p, U_rows] x [V_q, V_cols] for the
// B-spline kinds; outside, the end patches extrapolate.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/core/affine.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point.hpp"
#include "casteljau/curves/bezier.hpp"
#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/nurbs.hpp"
#include "casteljau/curves/rational_bezier.hpp"
#include "casteljau/surfaces/surface_form.hpp"

namespace casteljau {

enum class SurfaceKind { bezier, rational_bezier, bspline, nurbs };

/// Gaussian, mean and principal curvatures (k1 >= k2) at a point, with the unit normal
/// they are signed by (n = S_u x S_v / |S_u x S_v|).
template <class T>
struct SurfaceCurvature {
  Vector<T, 3> normal;
  T gaussian, mean, k1, k2;
};

template <class T, int D, SurfaceKind K>
class Surface;

template <class T, int D>
using BezierSurface = Surface<T, D, SurfaceKind::bezier>;
template <class T, int D>
using RationalBezierSurface = Surface<T, D, SurfaceKind::rational_bezier>;
template <class T, int D>
using BSplineSurface = Surface<T, D, SurfaceKind::bspline>;
template <class T, int D>
using NurbsSurface = Surface<T, D, SurfaceKind::nurbs>;

/// The exact Bézier patches of a surface and their breaks: patches[a][b] is the surface
/// on [ubreaks[a], ubreaks[a+1]] x [vbreaks[b], vbreaks[b+1]], reparametrised to [0, 1]^2.
template <class Patch>
struct PatchGrid {
  std::vector<typename Patch::Scalar> ubreaks, vbreaks;
  std::vector<std::vector<Patch>> patches;
};

template <class T, int D, SurfaceKind K>
class Surface {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using Grid = std::vector<std::vector<PointType>>;
  using Weights = std::vector<std::vector<T>>;
  static constexpr int dimension = D;
  static constexpr SurfaceKind kind = K;
  static constexpr bool is_rational = K == SurfaceKind::rational_bezier || K == SurfaceKind::nurbs;
  static constexpr bool is_bezier = K == SurfaceKind::bezier || K == SurfaceKind::rational_bezier;
  using Patch = Surface<T, D, is_rational ? SurfaceKind::rational_bezier : SurfaceKind::bezier>;
  /// The curve type of an isocurve.
  using Curve = std::conditional_t<is_bezier, std::conditional_t<is_rational, RationalBezier<T, D>, Bezier<T, D>>,
                                   std::conditional_t<is_rational, Nurbs<T, D>, BSpline<T, D>>>;

  /// A Bézier surface of degrees (rows - 1, columns - 1).
  explicit Surface(const Grid& points)
    requires(K == SurfaceKind::bezier)
      : f_(make(bezier_knots(points.size()), bezier_knots(points.empty() ? 0 : points.front().size()), points, nullptr)) {}
  Surface(const Grid& points, const Weights& weights)
    requires(K == SurfaceKind::rational_bezier)
      : f_(make(bezier_knots(points.size()), bezier_knots(points.empty() ? 0 : points.front().size()), points, &weights)) {}
  /// A B-spline surface of degrees p (along u) and q, knots U and V.
  Surface(int p, int q, std::vector<T> U, std::vector<T> V, const Grid& points)
    requires(K == SurfaceKind::bspline)
      : f_(make({p, std::move(U)}, {q, std::move(V)}, points, nullptr)) {}
  Surface(int p, int q, std::vector<T> U, std::vector<T> V, const Grid& points, const Weights& weights)
    requires(K == SurfaceKind::nurbs)
      : f_(make({p, std::move(U)}, {q, std::move(V)}, points, &weights)) {}

  /// The surface of a form (checked; its rationality must be the kind's, and a Bézier
  /// kind's knots are put on [0, 1]).
  static Surface from_form(detail::SurfaceForm<T> f) {
    if (f.rational != is_rational || f.cartesian() != static_cast<std::size_t>(D)) {
      throw InvalidArgument("surface", "form does not match the surface type");
    }
    if constexpr (is_bezier) {
      f.U = bezier_knots(f.rows).second;
      f.V = bezier_knots(f.cols).second;
      f.p = static_cast<int>(f.rows) - 1;
      f.q = static_cast<int>(f.cols) - 1;
    }
    detail::check_surface_form(f);
    return Surface(std::move(f));
  }

  [[nodiscard]] const detail::SurfaceForm<T>& form() const { return f_; }
  [[nodiscard]] int degree_u() const { return f_.p; }
  [[nodiscard]] int degree_v() const { return f_.q; }
  [[nodiscard]] std::size_t rows() const { return f_.rows; }
  [[nodiscard]] std::size_t columns() const { return f_.cols; }
  [[nodiscard]] const std::vector<T>& knots_u() const { return f_.U; }
  [[nodiscard]] const std::vector<T>& knots_v() const { return f_.V; }
  [[nodiscard]] Interval<T> domain_u() const { return {f_.U[static_cast<std::size_t>(f_.p)], f_.U[f_.rows]}; }
  [[nodiscard]] Interval<T> domain_v() const { return {f_.V[static_cast<std::size_t>(f_.q)], f_.V[f_.cols]}; }
  /// Control point (i, j), Cartesian.
  [[nodiscard]] PointType point(std::size_t i, std::size_t j) const {
    const T* x = f_.at(i, j);
    PointType P;
    for (int c = 0; c < D; ++c) P[c] = x[c];
    return P;
  }
  [[nodiscard]] T weight(std::size_t i, std::size_t j) const { return is_rational ? f_.at(i, j)[D] : T(1); }

  [[nodiscard]] PointType operator()(T u, T v) const {
    const std::vector<T> x = detail::partials(f_, u, v, 0);
    PointType P;
    for (int c = 0; c < D; ++c) P[c] = x[static_cast<std::size_t>(c)];
    return P;
  }
  /// d^(a+b) S / du^a dv^b at (u, v), a, b >= 0.
  [[nodiscard]] VectorType derivative(T u, T v, int a, int b) const {
    if (a < 0 || b < 0) throw InvalidArgument("derivatives", "derivative orders must be >= 0");
    const int k = a + b;
    const std::vector<T> x = detail::partials(f_, u, v, k);
    VectorType d;
    for (int c = 0; c < D; ++c) d[c] = x[(static_cast<std::size_t>(a) * static_cast<std::size_t>(k + 1) + static_cast<std::size_t>(b)) * D + static_cast<std::size_t>(c)];
    return d;
  }
  /// Every partial up to total order k (see detail::partials for the layout).
  [[nodiscard]] std::vector<T> partials(T u, T v, int k) const { return detail::partials(f_, u, v, k); }

  /// The unit normal S_u x S_v / |S_u x S_v| (none where |S_u x S_v| <= 1e-12 |S_u| |S_v|).
  [[nodiscard]] std::optional<Vector<T, 3>> normal(T u, T v) const
    requires(D == 3)
  {
    const auto c = curvature(u, v);
    if (!c) return std::nullopt;
    return c->normal;
  }
  /// The limit normal: the unit normal where it is defined, else, on a degenerate edge (a
  /// sphere's pole), the limit of the unit normals about the point where it exists (none
  /// at a cone's apex, where they turn about the axis). See detail::limit_normal.
  [[nodiscard]] std::optional<Vector<T, 3>> limit_normal(T u, T v) const
    requires(D == 3)
  {
    const auto n = detail::limit_normal(f_, u, v);
    if (!n) return std::nullopt;
    return Vector<T, 3>((*n)[0], (*n)[1], (*n)[2]);
  }
  /// Gaussian, mean and principal curvatures where the normal is defined.
  [[nodiscard]] std::optional<SurfaceCurvature<T>> curvature(T u, T v) const
    requires(D == 3)
  {
    const detail::SurfaceGeometry<T> g = detail::geometry(f_, u, v);
    if (!g.defined) return std::nullopt;
    return SurfaceCurvature<T>{Vector<T, 3>(g.normal[0], g.normal[1], g.normal[2]), g.gaussian, g.mean, g.k1, g.k2};
  }

  /// The halves at t in direction dir (B-spline kinds: t strictly inside the domain, both
  /// keep their parameter; Bézier kinds: t in (0, 1), both on [0, 1]).
  [[nodiscard]] std::pair<Surface, Surface> split(Direction dir, T t) const {
    auto [a, b] = detail::split(f_, dir, t);
    return {from_form(std::move(a)), from_form(std::move(b))};
  }
  [[nodiscard]] Surface elevate(Direction dir, int r = 1) const { return from_form(detail::elevate(f_, dir, r)); }
  [[nodiscard]] Surface insert_knot(Direction dir, T u, int times = 1) const
    requires(!is_bezier)
  {
    return from_form(detail::insert_knot(f_, dir, u, times));
  }
  /// The exact isocurve: v -> S(value, v) for dir u, u -> S(u, value) for dir v.
  [[nodiscard]] Curve isocurve(Direction dir, T value) const {
    const detail::CurveForm<T> c = detail::isocurve(f_, dir, value);
    std::vector<PointType> P(c.size());
    std::vector<T> w(c.size(), T(1));
    for (std::size_t i = 0; i < c.size(); ++i) {
      const T* x = c.P.data() + i * c.dim;
      if (is_rational) w[i] = x[D];
      for (int k = 0; k < D; ++k) P[i][k] = x[k];
    }
    if constexpr (K == SurfaceKind::bezier) return Curve(std::move(P));
    else if constexpr (K == SurfaceKind::rational_bezier) return Curve(std::move(P), std::move(w));
    else if constexpr (K == SurfaceKind::bspline) return Curve(c.p, c.U, std::move(P));
    else return Curve(c.p, c.U, std::move(P), std::move(w));
  }
  /// The image under an affine map: the control points mapped, the weights and knots kept
  /// (affine invariance; exact for the rational kinds too, whose points are Cartesian: the
  /// map commutes with their weighted averages). Error InvalidArgument("m") when a mapped
  /// point is not finite.
  [[nodiscard]] Surface transform(const Affine<T, D>& m) const {
    detail::SurfaceForm<T> f = f_;
    for (std::size_t i = 0; i < f.rows; ++i)
      for (std::size_t j = 0; j < f.cols; ++j) {
        T* x = f.at(i, j);
        PointType p;
        for (int k = 0; k < D; ++k) p[k] = x[k];
        const PointType q = m(p);
        for (int k = 0; k < D; ++k) {
          if (!std::isfinite(q[k]) || (is_rational && !std::isfinite(q[k] * x[D]))) {
            throw InvalidArgument("m", "the transformed surface is not representable: its control point [" + std::to_string(i) + "][" +
                                           std::to_string(j) + "] is not finite");
          }
          x[k] = q[k];
        }
      }
    return Surface(std::move(f));
  }
  /// The exact Bézier patches and their breaks.
  [[nodiscard]] PatchGrid<Patch> patches() const {
    const detail::SurfacePatches<T> sp = detail::patches(f_);
    PatchGrid<Patch> g{sp.ubreaks, sp.vbreaks, {}};
    for (const auto& row : sp.patches) {
      auto& out = g.patches.emplace_back();
      for (const auto& p : row) out.push_back(Patch::from_form(p));
    }
    return g;
  }

 private:
  template <class, int, SurfaceKind>
  friend class Surface;
  explicit Surface(detail::SurfaceForm<T> f) : f_(std::move(f)) {}

  static std::pair<int, std::vector<T>> bezier_knots(std::size_t count) {
    const int n = static_cast<int>(count) - 1;
    std::vector<T> knots(count, T(0));
    knots.insert(knots.end(), count, T(1));
    return {n, std::move(knots)};
  }

  static detail::SurfaceForm<T> make(std::pair<int, std::vector<T>> u, std::pair<int, std::vector<T>> v, const Grid& points,
                                     const Weights* weights) {
    if (points.empty() || points.front().empty()) throw InvalidArgument("points", "a surface needs at least one row of at least one point");
    const std::size_t rows = points.size(), cols = points.front().size();
    for (std::size_t i = 1; i < rows; ++i) {
      if (points[i].size() != cols) {
        throw InvalidArgument("points[" + std::to_string(i) + "]", "row " + std::to_string(i) + " has " + std::to_string(points[i].size()) +
                                                                      " points, row 0 has " + std::to_string(cols));
      }
    }
    if (weights) {
      if (weights->size() != rows) {
        throw InvalidArgument("weights", "has " + std::to_string(weights->size()) + " rows, points has " + std::to_string(rows));
      }
      for (std::size_t i = 0; i < rows; ++i) {
        if ((*weights)[i].size() != cols) {
          throw InvalidArgument("weights[" + std::to_string(i) + "]", "row " + std::to_string(i) + " has " +
                                                                          std::to_string((*weights)[i].size()) + " weights, points rows have " +
                                                                          std::to_string(cols));
        }
      }
    }
    detail::SurfaceForm<T> f;
    f.p = u.first;
    f.q = v.first;
    f.U = std::move(u.second);
    f.V = std::move(v.second);
    f.rows = rows;
    f.cols = cols;
    f.rational = is_rational;
    f.dim = static_cast<std::size_t>(D) + (is_rational ? 1 : 0);
    f.P.reserve(rows * cols * f.dim);
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t j = 0; j < cols; ++j) {
        const T w = weights ? (*weights)[i][j] : T(1);
        if (weights && !(w > 0 && std::isfinite(w))) {
          throw InvalidArgument("weights[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                                "weights must be finite and > 0, got " + detail::format_number(w));
        }
        for (int c = 0; c < D; ++c) {
          require_finite(points[i][j][c], "points[" + std::to_string(i) + "][" + std::to_string(j) + "][" + std::to_string(c) + "]");
          f.P.push_back(points[i][j][c]);
        }
        if (weights) f.P.push_back(w);
      }
    }
    detail::check_surface_form(f);
    return f;
  }

  detail::SurfaceForm<T> f_;
};

}  // namespace casteljau
