// Affine maps x -> A x + b of D-space, applied to points (A x + b) and vectors (A x).
#pragma once

#include <vector>

#include <array>

#include "casteljau/core/point.hpp"

namespace casteljau {

template <class T, int D>
struct Affine {
  std::array<std::array<T, D>, D> linear{};  ///< A, row-major: linear[row][col]
  Vector<T, D> translation{};                ///< b

  static constexpr Affine identity() {
    Affine m;
    for (int i = 0; i < D; ++i) m.linear[i][i] = 1;
    return m;
  }
  static constexpr Affine translate(const Vector<T, D>& b) {
    Affine m = identity();
    m.translation = b;
    return m;
  }
  static constexpr Affine scale(T s) {
    Affine m;
    for (int i = 0; i < D; ++i) m.linear[i][i] = s;
    return m;
  }

  constexpr Vector<T, D> operator()(const Vector<T, D>& v) const {
    Vector<T, D> r;
    for (int i = 0; i < D; ++i) {
      T s = 0;
      for (int j = 0; j < D; ++j) s += linear[i][j] * v[j];
      r[i] = s;
    }
    return r;
  }
  constexpr Point<T, D> operator()(const Point<T, D>& p) const {
    return Point<T, D>::from_vector((*this)(p.to_vector()) + translation);
  }
  /// The map "this after other": x -> this(other(x)).
  friend constexpr Affine operator*(const Affine& a, const Affine& b) {
    Affine r;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) {
        T s = 0;
        for (int k = 0; k < D; ++k) s += a.linear[i][k] * b.linear[k][j];
        r.linear[i][j] = s;
      }
    r.translation = a(b.translation) + a.translation;
    return r;
  }
};

/// The points mapped by m: the control points of every curve type's transform() (affine
/// invariance).
template <class T, int D>
std::vector<Point<T, D>> mapped_points(const Affine<T, D>& m, const std::vector<Point<T, D>>& P) {
  std::vector<Point<T, D>> Q;
  Q.reserve(P.size());
  for (const auto& p : P) Q.push_back(m(p));
  return Q;
}

/// Rotation of the plane by `angle` radians counter-clockwise about the origin.
template <class T>
Affine<T, 2> rotation(T angle) {
  Affine<T, 2> m;
  const T c = std::cos(angle), s = std::sin(angle);
  m.linear = {{{c, -s}, {s, c}}};
  return m;
}

}  // namespace casteljau
