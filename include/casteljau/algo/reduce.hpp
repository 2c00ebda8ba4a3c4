// Degree reduction of Bézier curves: the least-squares approximation of lower degree
// (kept out of curves/bezier.hpp so that evaluating a curve does not need Eigen's
// Cholesky module).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/basis/power.hpp"
#include "casteljau/curves/bezier.hpp"

namespace casteljau {

/// Result of reduce_degree: the lower-degree curve and how far it is from the original.
template <class T, int D>
struct Reduction {
  Bezier<T, D> curve;
  T max_error;    ///< max distance at 64 (n + 1) + 1 uniform parameters (an estimate, from below)
  T error_bound;  ///< guaranteed: max control point distance after elevating back to degree n
};

/// Whether degree reduction keeps the end points (and so C0 joins of a composite curve).
enum class Endpoints { keep, free };

namespace detail {
template <class T, int D, class M>
Vector<T, D> row_vector(const M& x, int row) {
  Vector<T, D> v;
  for (int d = 0; d < D; ++d) v[d] = x(row, d);
  return v;
}
}  // namespace detail

/// The least-squares degree-m approximation of c (0 <= m <= n) in the L2 norm over
/// [0, 1]: solves the Bernstein Gram system G_mm Q = G_mn P [Eck93; Farin02, 5.9] by LDLT,
/// with the end points fixed when `endpoints` is keep (then m >= 1). Exact when c is a
/// degree-elevated degree-m curve. The Gram matrix's condition number grows like 4^m, so
/// results are reliable for m up to about 25 in double. Reports the error (see
/// Reduction). Throws InvalidArgument("degree", ...) for m outside the range. Cost
/// O(m n + m^3 + n^2) plus the O(n^2) sampled error estimate at 64 (n + 1) + 1 points.
template <class T, int D>
Reduction<T, D> reduce_degree(const Bezier<T, D>& c, int m, Endpoints endpoints = Endpoints::keep) {
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  const auto& P = c.points();
  const int n = c.degree();
  if (m < 0 || m > n) {
    throw InvalidArgument("degree", "target degree must lie in [0, " + std::to_string(n) + "], got " + std::to_string(m));
  }
  if (endpoints == Endpoints::keep && m < 1) {
    throw InvalidArgument("degree", "keeping both end points needs target degree >= 1, got " + std::to_string(m));
  }
  // The Gram entries use binomial rows up to C(m + n, .), which overflow a double past
  // m + n = 1029; the least-squares solve is unreliable far earlier (see above).
  if (n > 1000) {
    throw InvalidArgument("curve", "degree reduction needs a curve of degree <= 1000, got degree " + std::to_string(n));
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
  // Reduced curves are built as offsets from P0 so that translations cancel exactly.
  const PointType origin = P.front();
  Eigen::Matrix<T, Eigen::Dynamic, D> rhs(m + 1, D);
  for (int j = 0; j <= m; ++j) {
    VectorType s{};
    for (int i = 0; i <= n; ++i) s += gmn(j, i) * (P[static_cast<std::size_t>(i)] - origin);
    for (int d = 0; d < D; ++d) rhs(j, d) = s[d];
  }
  std::vector<PointType> Q(static_cast<std::size_t>(m) + 1);
  if (endpoints == Endpoints::free) {
    Matrix<T> g(m + 1, m + 1);
    for (int j = 0; j <= m; ++j)
      for (int k = 0; k <= m; ++k) g(j, k) = gmm(j, k);
    const Eigen::Matrix<T, Eigen::Dynamic, D> x = g.ldlt().solve(rhs);
    for (int j = 0; j <= m; ++j) Q[static_cast<std::size_t>(j)] = origin + detail::row_vector<T, D>(x, j);
  } else {
    const VectorType qm = P.back() - origin;  // Q_0 = P0 (offset 0), Q_m = Pn
    Q.front() = P.front();
    Q.back() = P.back();
    const int u = m - 1;  // unknowns Q_1..Q_{m-1}
    if (u > 0) {
      Matrix<T> g(u, u);
      Eigen::Matrix<T, Eigen::Dynamic, D> r(u, D);
      for (int j = 1; j <= u; ++j) {
        for (int k = 1; k <= u; ++k) g(j - 1, k - 1) = gmm(j, k);
        for (int d = 0; d < D; ++d) r(j - 1, d) = rhs(j, d) - gmm(j, m) * qm[d];
      }
      const Eigen::Matrix<T, Eigen::Dynamic, D> x = g.ldlt().solve(r);
      for (int j = 1; j <= u; ++j) Q[static_cast<std::size_t>(j)] = origin + detail::row_vector<T, D>(x, j - 1);
    }
  }
  Bezier<T, D> reduced(std::move(Q));
  const Bezier<T, D> back = reduced.elevate(n - m);
  T bound = 0;
  for (int i = 0; i <= n; ++i) bound = std::max(bound, distance(back.points()[static_cast<std::size_t>(i)], P[static_cast<std::size_t>(i)]));
  T sampled = 0;
  const int samples = 64 * (n + 1);
  for (int s = 0; s <= samples; ++s) {
    const T t = static_cast<T>(s) / static_cast<T>(samples);
    sampled = std::max(sampled, distance(c(t), reduced(t)));
  }
  return {std::move(reduced), sampled, bound};
}

/// A curve whose degree can be lowered: a Bézier curve (reduce_degree above) or a type with
/// a reduce_degree(tolerance) member (BSpline, Nurbs). The command line's `reduce` takes
/// exactly these types (io::Capability::degree_reduction).
template <class C>
concept DegreeReducibleCurve = requires(const C& x) { reduce_degree(x, 1); } ||
                               requires(const C& x, typename C::Scalar tolerance) { x.reduce_degree(tolerance); };

}  // namespace casteljau
