// The matrix view of cubic segments [Foley90, 11.2; Farin02, 5.8]: a segment is
// p(t) = [1 t t^2 t^3] B G on [0, 1], with G the four geometry values of its form (Bézier
// points, Hermite ends and tangents, Catmull-Rom or uniform B-spline points), B the basis
// matrix and C = B^-1 the constraint matrix (G = C a for the power coefficients a). The
// matrices are exact rationals, so B C = I holds exactly, and conversions between forms
// are the products C_to B_from.
#pragma once

#include <array>
#include <cstdlib>
#include <numeric>

#include "casteljau/basis/power.hpp"
#include "casteljau/core/error.hpp"

namespace casteljau {

/// The cubic segment forms with a matrix view. Geometry G, in order:
enum class CubicForm {
  bezier,       ///< P_0, P_1, P_2, P_3: the Bézier control points
  hermite,      ///< p(0), p(1), p'(0), p'(1): end points and end tangents
  catmull_rom,  ///< P_0, P_1, P_2, P_3 with p(0) = P_1, p(1) = P_2, p'(0) = (P_2 - P_0) / 2, p'(1) = (P_3 - P_1) / 2
  bspline,      ///< P_0, P_1, P_2, P_3: de Boor points of one span of a uniform cubic B-spline
};

/// A 4 x 4 matrix of rationals num / den with one common denominator den > 0, kept
/// reduced (the gcd of den and every entry is 1).
struct RationalMatrix4 {
  std::array<std::array<long long, 4>, 4> num{};
  long long den = 1;

  /// Entry (i, j) as a T (one rounding).
  template <class T>
  [[nodiscard]] T at(int i, int j) const {
    return static_cast<T>(num[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]) / static_cast<T>(den);
  }
  template <class T>
  [[nodiscard]] Matrix<T> to_matrix() const {
    Matrix<T> m(4, 4);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) m(i, j) = at<T>(i, j);
    return m;
  }
  [[nodiscard]] static RationalMatrix4 identity() {
    RationalMatrix4 m;
    for (std::size_t i = 0; i < 4; ++i) m.num[i][i] = 1;
    return m;
  }

  /// The exact product (entries stay small: these matrices have denominators <= 6).
  friend RationalMatrix4 operator*(const RationalMatrix4& a, const RationalMatrix4& b) {
    RationalMatrix4 r;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 4; ++j) {
        long long s = 0;
        for (std::size_t k = 0; k < 4; ++k) s += a.num[i][k] * b.num[k][j];
        r.num[i][j] = s;
      }
    r.den = a.den * b.den;
    r.reduce();
    return r;
  }
  friend bool operator==(const RationalMatrix4&, const RationalMatrix4&) = default;

  void reduce() {
    long long g = den;
    for (const auto& row : num)
      for (long long v : row) g = std::gcd(g, std::llabs(v));
    if (g > 1) {
      den /= g;
      for (auto& row : num)
        for (long long& v : row) v /= g;
    }
  }
};

/// B of a form: the power coefficients a = B G (p(t) = sum_k a_k t^k). Rows for the
/// Catmull-Rom form: 0 1 0 0 / -1/2 0 1/2 0 / 1 -5/2 2 -1/2 / -1/2 3/2 -3/2 1/2
/// [CatmullRom74]; Bézier: the Bernstein-to-power matrix (bernstein_to_power_matrix(3));
/// Hermite: 1 0 0 0 / 0 0 1 0 / -3 3 -2 -1 / 2 -2 1 1; uniform B-spline:
/// (1 4 1 0 / -3 0 3 0 / 3 -6 3 0 / -1 3 -3 1) / 6 [Foley90, 11.2].
inline RationalMatrix4 basis_matrix(CubicForm form) {
  switch (form) {
    case CubicForm::bezier: return {{{{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}}}, 1};
    case CubicForm::hermite: return {{{{1, 0, 0, 0}, {0, 0, 1, 0}, {-3, 3, -2, -1}, {2, -2, 1, 1}}}, 1};
    case CubicForm::catmull_rom: return {{{{0, 2, 0, 0}, {-1, 0, 1, 0}, {2, -5, 4, -1}, {-1, 3, -3, 1}}}, 2};
    case CubicForm::bspline: return {{{{1, 4, 1, 0}, {-3, 0, 3, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}}}, 6};
  }
  throw InvalidArgument("form", "unknown cubic form");
}

/// C = B^-1 of a form: the geometry G = C a of the cubic with power coefficients a, i.e.
/// the constraints each geometry value puts on the polynomial. Bézier: power-to-Bernstein
/// (i, j) = C(i, j) / C(3, j); Hermite: rows p(0), p(1), p'(0), p'(1); Catmull-Rom:
/// P_0 = p(1) - 2 p'(0), P_1 = p(0), P_2 = p(1), P_3 = p(0) + 2 p'(1); uniform B-spline:
/// P_0 = a_0 - a_1 + 2/3 a_2, P_1 = a_0 - a_2 / 3, P_2 = a_0 + a_1 + 2/3 a_2,
/// P_3 = a_0 + 2 a_1 + 11/3 a_2 + 6 a_3 (solved from p(0), p'(0), p''(0), p''').
inline RationalMatrix4 constraint_matrix(CubicForm form) {
  switch (form) {
    case CubicForm::bezier: return {{{{3, 0, 0, 0}, {3, 1, 0, 0}, {3, 2, 1, 0}, {3, 3, 3, 3}}}, 3};
    case CubicForm::hermite: return {{{{1, 0, 0, 0}, {1, 1, 1, 1}, {0, 1, 0, 0}, {0, 1, 2, 3}}}, 1};
    case CubicForm::catmull_rom: return {{{{1, -1, 1, 1}, {1, 0, 0, 0}, {1, 1, 1, 1}, {1, 2, 4, 6}}}, 1};
    case CubicForm::bspline: return {{{{3, -3, 2, 0}, {3, 0, -1, 0}, {3, 3, 2, 0}, {3, 6, 11, 18}}}, 3};
  }
  throw InvalidArgument("form", "unknown cubic form");
}

/// The matrix taking the geometry of one form to that of another for the same cubic:
/// C_to B_from (exact). Catmull-Rom to Bézier, for example, gives the Bézier points
/// P_1, P_1 + (P_2 - P_0) / 6, P_2 - (P_3 - P_1) / 6, P_2.
inline RationalMatrix4 conversion_matrix(CubicForm from, CubicForm to) { return constraint_matrix(to) * basis_matrix(from); }

/// The geometry in form `to` of the cubic with geometry g in form `from`: four values of
/// any vector type (Vector<T, D> or a scalar; points as vectors from the origin), each
/// a combination of g with the rational entries rounded once. Cost 16 multiply-adds.
template <class T, class V>
std::array<V, 4> convert_geometry(CubicForm from, CubicForm to, const std::array<V, 4>& g) {
  const RationalMatrix4 m = conversion_matrix(from, to);
  std::array<V, 4> r{};
  for (int i = 0; i < 4; ++i) {
    V s{};
    for (int j = 0; j < 4; ++j)
      if (m.num[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] != 0) s += m.at<T>(i, j) * g[static_cast<std::size_t>(j)];
    r[static_cast<std::size_t>(i)] = s;
  }
  return r;
}

}  // namespace casteljau
