// The basis functions of the library's curve kinds as plain tables: their values and
// derivatives at parameters, and for the cubic kinds the matrix view of basis_matrix.hpp
// (P(t) = [1 t t^2 t^3] M G). In double, not templated: one small function per kind.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/barycentric.hpp"
#include "casteljau/basis/basis_matrix.hpp"
#include "casteljau/basis/bernstein.hpp"
#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/core/error.hpp"

namespace casteljau {

/// The kinds of basis (geometry G of the cubic kinds in brackets):
enum class BasisKind {
  bernstein,        ///< B(i, n), i = 0..n, on [0, 1] (degree n >= 0; n = 3: the Bézier points)
  bspline,          ///< N(i, p), i = 0..len(knots) - p - 2, on a knot vector
  lagrange,         ///< the Lagrange polynomials l_j of distinct params
  hermite,          ///< h00, h01, h10, h11 ([p0, p1, m0, m1])
  catmull_rom,      ///< uniform Catmull-Rom ([P(i-1), P(i), P(i+1), P(i+2)])
  cardinal,         ///< as catmull_rom with tangents (1 - s) times Catmull-Rom's
  uniform_bspline,  ///< one span of a uniform cubic B-spline (the four de Boor points)
};

/// A basis: its kind and the data the kind needs (the others empty).
struct BasisSpec {
  BasisKind kind = BasisKind::bernstein;
  int degree = 3;              ///< bernstein, bspline
  std::vector<double> knots;   ///< bspline
  std::vector<double> params;  ///< lagrange
  double tension = 0;          ///< cardinal, in [0, 1]
};

/// The table of a basis at parameters t: value[j][i][f] is the j-th derivative (j = 0..k)
/// of basis function f at t[i]; for the cubic kinds (and bernstein of degree 3) matrix M,
/// constraint C = M^-1 (std::nullopt when M is singular: cardinal of tension 1), row-major.
struct BasisTable {
  std::vector<std::vector<std::vector<double>>> value;
  std::optional<Eigen::Matrix4d> matrix;
  std::optional<Eigen::Matrix4d> constraint;
};

namespace detail {

inline Eigen::Matrix4d to_eigen(const RationalMatrix4& m) {
  Eigen::Matrix4d r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = m.at<double>(i, j);
  return r;
}

/// x + y as a double-double: x + y = hi + lo exactly (Knuth's TwoSum, any order).
struct DoubleDouble {
  double hi, lo;
};
inline DoubleDouble two_sum(double x, double y) {
  const double s = x + y, z = s - x;
  return {s, (x - (s - z)) + (y - z)};
}

/// x + y + z rounded once (to within a few 2^-106 relative before the final rounding),
/// for exact x, y and a small z: TwoSum of x and y, then the low parts added.
inline double sum3(double x, double y, double z) {
  const DoubleDouble a = two_sum(x, y);
  return a.hi + (a.lo + z);
}

/// The cardinal matrix M in closed form, c = (1 - s) / 2 (the tangents c (P2 - P0) and
/// c (P3 - P1) put into Hermite's M):
///   [ 0      1       0        0 ]
///   [ -c     0       c        0 ]
///   [ 2c     c - 3   3 - 2c  -c ]
///   [ -c     2 - c   c - 2    c ]
/// Each entry is the double nearest the exact value for the double s (up to the tie
/// cases of a 2^-106 relative error): 1 - s = d + e exactly (TwoSum), c = d / 2 is the
/// nearest double to (1 - s) / 2, and the sums take e into account before rounding.
inline Eigen::Matrix4d cardinal_matrix(double s) {
  const DoubleDouble d = two_sum(1.0, -s);
  const double c = d.hi / 2, e = d.lo / 2;  // (1 - s) / 2 = c + e exactly
  Eigen::Matrix4d m;
  m << 0, 1, 0, 0,                                                  //
      -c, 0, c, 0,                                                  //
      2 * c, sum3(c, -3, e), sum3(3, -2 * c, -2 * e), -c,           //
      -c, sum3(2, -c, -e), sum3(c, -2, e), c;
  return m;
}

/// The cardinal constraint matrix C = M^-1 in closed form, k = 1 / c = 2 / (1 - s) (rows:
/// P0 = P2 - a1 / c, P1 = a0, P2 = a0 + a1 + a2 + a3, P3 = P1 + (a1 + 2 a2 + 3 a3) / c,
/// from p(0) = P1, p(1) = P2, p'(0) = c (P2 - P0), p'(1) = c (P3 - P1)):
///   [ 1  1 - k  1   1  ]
///   [ 1  0      0   0  ]
///   [ 1  1      1   1  ]
///   [ 1  k      2k  3k ]
/// The factor 1 - s is divided out analytically, so C is as accurate at s = 1 - 2^-53
/// (k = 2^54) as at 0. k is carried as a double-double: 1 - s = d + e exactly (TwoSum),
/// q = 2 / d, its remainder 2 - q d exact by an fma, k = q + (2 - q d - q e) / d to about
/// 2^-104 relative; each entry is then rounded once (the nearest double up to ties of
/// that error). std::nullopt at s = 1, where M is singular (both tangents vanish).
inline std::optional<Eigen::Matrix4d> cardinal_constraint(double s) {
  if (s == 1) return std::nullopt;
  const DoubleDouble d = two_sum(1.0, -s);
  const double q = 2 / d.hi;
  const double kl = (std::fma(-q, d.hi, 2.0) - q * d.lo) / d.hi;  // k = q + kl
  const double k = q + kl;
  const double k3 = 3 * q, k3l = std::fma(3.0, q, -k3);  // 3 q = k3 + k3l exactly
  Eigen::Matrix4d m;
  m << 1, sum3(1, -q, -kl), 1, 1,  //
      1, 0, 0, 0,                  //
      1, 1, 1, 1,                  //
      1, k, 2 * k, k3 + (k3l + 3 * kl);
  return m;
}

/// Checks a degree-0 knot vector: finite, non-decreasing, at least two knots, a non-empty
/// domain (a degree-0 basis function is the indicator of its knot interval).
inline void check_knots_degree0(std::span<const double> U) {
  if (U.size() < 2) throw InvalidArgument("knots", "degree 0 needs at least 2 knots, got " + std::to_string(U.size()));
  for (std::size_t i = 0; i < U.size(); ++i) {
    const std::string where = "knots[" + std::to_string(i) + "]";
    require_finite(U[i], where);
    if (i > 0 && U[i] < U[i - 1]) {
      throw InvalidArgument(where, "knots must be non-decreasing (" + format_number(U[i]) + " after " + format_number(U[i - 1]) + ")");
    }
  }
  if (!(U.front() < U.back())) throw InvalidArgument("knots", "the domain is empty: every knot is " + format_number(U.front()));
}

}  // namespace detail

/// Checks a basis: degree >= 0 ("degree"), knots valid for the degree ("knots",
/// "knots[i]": check_knots), params distinct and finite ("params", "params[j]"), tension
/// in [0, 1] ("tension"). Throws InvalidArgument naming the field.
inline void check_basis(const BasisSpec& b) {
  switch (b.kind) {
    case BasisKind::bernstein:
      if (b.degree < 0) throw InvalidArgument("degree", "must be >= 0, got " + std::to_string(b.degree));
      break;
    case BasisKind::bspline:
      if (b.degree < 0) throw InvalidArgument("degree", "must be >= 0, got " + std::to_string(b.degree));
      if (b.degree == 0) {
        detail::check_knots_degree0(b.knots);
      } else {
        check_knots<double>(b.knots, b.degree);
      }
      break;
    case BasisKind::lagrange: (void)barycentric_weights<double>(b.params); break;
    case BasisKind::cardinal:
      if (!(b.tension >= 0 && b.tension <= 1)) {
        throw InvalidArgument("tension", "must be in [0, 1], got " + detail::format_number(b.tension));
      }
      break;
    default: break;
  }
}

/// How many basis functions the basis has (check_basis first).
inline std::size_t basis_count(const BasisSpec& b) {
  switch (b.kind) {
    case BasisKind::bernstein: return static_cast<std::size_t>(b.degree) + 1;
    case BasisKind::bspline: return b.knots.size() - static_cast<std::size_t>(b.degree) - 1;
    case BasisKind::lagrange: return b.params.size();
    default: return 4;
  }
}

/// M of a cubic kind (and bernstein of degree 3), else std::nullopt.
inline std::optional<Eigen::Matrix4d> cubic_matrix(const BasisSpec& b) {
  switch (b.kind) {
    case BasisKind::bernstein:
      if (b.degree != 3) return std::nullopt;
      return detail::to_eigen(basis_matrix(CubicForm::bezier));
    case BasisKind::hermite: return detail::to_eigen(basis_matrix(CubicForm::hermite));
    case BasisKind::catmull_rom: return detail::to_eigen(basis_matrix(CubicForm::catmull_rom));
    case BasisKind::uniform_bspline: return detail::to_eigen(basis_matrix(CubicForm::bspline));
    case BasisKind::cardinal: return detail::cardinal_matrix(b.tension);
    default: return std::nullopt;
  }
}

/// The table of basis b at the finite parameters t, derivatives 0..k (k >= 0): bernstein
/// by bernstein_all_derivatives, bspline by [PT97] A2.3 on the span of each t (outside
/// the domain the end spans continued, as curve evaluation), lagrange by the barycentric
/// Taylor coefficients of each l_j (O(n^2 (k + 1)) per t), the cubic kinds as
/// [1 t t^2 t^3]^(j) M. The constraint C is the exact inverse for the fixed kinds
/// (constraint_matrix) and the closed form of cardinal_constraint for cardinal (each entry
/// the double nearest the exact rational for the given tension; null at tension 1, where
/// two tangents vanish). Throws as check_basis, ("t[i]", ...) for a non-finite t,
/// ("derivatives", ...) for k < 0.
inline BasisTable basis_table(const BasisSpec& b, std::span<const double> t, int k) {
  check_basis(b);
  if (k < 0) throw InvalidArgument("derivatives", "must be >= 0, got " + std::to_string(k));
  require_finite_values(t, "t");
  const std::size_t n = basis_count(b), K = static_cast<std::size_t>(k);
  BasisTable r;
  r.value.assign(K + 1, std::vector<std::vector<double>>(t.size(), std::vector<double>(n, 0.0)));
  r.matrix = cubic_matrix(b);
  if (r.matrix) {
    switch (b.kind) {
      case BasisKind::bernstein: r.constraint = detail::to_eigen(constraint_matrix(CubicForm::bezier)); break;
      case BasisKind::hermite: r.constraint = detail::to_eigen(constraint_matrix(CubicForm::hermite)); break;
      case BasisKind::catmull_rom: r.constraint = detail::to_eigen(constraint_matrix(CubicForm::catmull_rom)); break;
      case BasisKind::uniform_bspline: r.constraint = detail::to_eigen(constraint_matrix(CubicForm::bspline)); break;
      default: r.constraint = detail::cardinal_constraint(b.tension);
    }
  }
  const std::vector<double> w = b.kind == BasisKind::lagrange ? barycentric_weights<double>(b.params) : std::vector<double>{};
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double u = t[i];
    switch (b.kind) {
      case BasisKind::bernstein:
        for (std::size_t j = 0; j <= K; ++j) bernstein_all_derivatives<double>(b.degree, static_cast<int>(j), u, r.value[j][i]);
        break;
      case BasisKind::bspline: {
        const std::size_t s = find_span<double>(b.knots, b.degree, u);
        const auto ders = basis_function_derivatives<double>(b.knots, b.degree, s, u, k);
        for (std::size_t j = 0; j <= K; ++j)
          for (std::size_t q = 0; q <= static_cast<std::size_t>(b.degree); ++q) r.value[j][i][s - static_cast<std::size_t>(b.degree) + q] = ders[j][q];
        break;
      }
      case BasisKind::lagrange: {
        std::vector<double> y(n, 0.0), c(K + 1);
        for (std::size_t f = 0; f < n; ++f) {
          y[f] = 1;
          barycentric_taylor<double, double, double>(b.params, w, y, u, k, c.data());
          y[f] = 0;
          double factorial = 1;
          for (std::size_t j = 0; j <= K; ++j) {
            if (j > 0) factorial *= static_cast<double>(j);
            r.value[j][i][f] = c[j] * factorial;
          }
        }
        break;
      }
      default: {
        // d^j/dt^j of [1 t t^2 t^3], times M.
        for (std::size_t j = 0; j <= K && j <= 3; ++j) {
          Eigen::RowVector4d pw = Eigen::RowVector4d::Zero();
          for (std::size_t e = j; e <= 3; ++e) {
            double c = 1;
            for (std::size_t q = 0; q < j; ++q) c *= static_cast<double>(e - q);
            pw(static_cast<Eigen::Index>(e)) = c * std::pow(u, static_cast<double>(e - j));
          }
          const Eigen::RowVector4d row = pw * *r.matrix;
          for (std::size_t f = 0; f < 4; ++f) r.value[j][i][f] = row(static_cast<Eigen::Index>(f));
        }
      }
    }
    // Far outside the data (a Lagrange basis at t = 1e300, a cubic at 1e110) the values
    // overflow: refused naming the parameter, never a table with inf or NaN in it.
    for (std::size_t j = 0; j <= K; ++j)
      for (const double v : r.value[j][i])
        if (!std::isfinite(v)) {
          throw InvalidArgument("t[" + std::to_string(i) + "]",
                                (j == 0 ? std::string("the basis values") : "the derivatives of order " + std::to_string(j) + " of the basis") +
                                    " at t = " + detail::format_number(u) + " are not representable (they overflow a double)");
        }
  }
  return r;
}

}  // namespace casteljau
