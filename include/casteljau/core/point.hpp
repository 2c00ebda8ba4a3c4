// Points and vectors of fixed dimension D: distinct types, so that point - point is a
// vector, point + vector is a point, and point + point does not compile.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <type_traits>

#include "casteljau/core/error.hpp"

namespace casteljau {

template <class T, int D>
struct Vector {
  static_assert(D >= 1, "dimension must be at least 1");
  using Scalar = T;
  static constexpr int dimension = D;

  std::array<T, D> c{};  ///< coordinates

  constexpr Vector() = default;
  template <class... A>
    requires(sizeof...(A) == D && D > 0)
  constexpr explicit(sizeof...(A) == 1) Vector(A... a) : c{static_cast<T>(a)...} {}
  constexpr explicit Vector(const std::array<T, D>& a) : c(a) {}

  constexpr T& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  constexpr const T& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }

  constexpr Vector& operator+=(const Vector& o) {
    for (int i = 0; i < D; ++i) (*this)[i] += o[i];
    return *this;
  }
  constexpr Vector& operator-=(const Vector& o) {
    for (int i = 0; i < D; ++i) (*this)[i] -= o[i];
    return *this;
  }
  constexpr Vector& operator*=(T s) {
    for (int i = 0; i < D; ++i) (*this)[i] *= s;
    return *this;
  }
  constexpr Vector& operator/=(T s) {
    for (int i = 0; i < D; ++i) (*this)[i] /= s;
    return *this;
  }
  friend constexpr Vector operator+(Vector a, const Vector& b) { return a += b; }
  friend constexpr Vector operator-(Vector a, const Vector& b) { return a -= b; }
  friend constexpr Vector operator*(Vector a, T s) { return a *= s; }
  friend constexpr Vector operator*(T s, Vector a) { return a *= s; }
  friend constexpr Vector operator/(Vector a, T s) { return a /= s; }
  friend constexpr Vector operator-(Vector a) {
    for (int i = 0; i < D; ++i) a[i] = -a[i];
    return a;
  }
  friend constexpr bool operator==(const Vector&, const Vector&) = default;
};

template <class T, int D>
struct Point {
  static_assert(D >= 1, "dimension must be at least 1");
  using Scalar = T;
  static constexpr int dimension = D;

  std::array<T, D> c{};  ///< coordinates

  constexpr Point() = default;
  template <class... A>
    requires(sizeof...(A) == D && D > 0)
  constexpr explicit(sizeof...(A) == 1) Point(A... a) : c{static_cast<T>(a)...} {}
  constexpr explicit Point(const std::array<T, D>& a) : c(a) {}

  constexpr T& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  constexpr const T& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }

  /// The vector from the origin to this point.
  [[nodiscard]] constexpr Vector<T, D> to_vector() const { return Vector<T, D>(c); }
  /// The point at the tip of v placed at the origin.
  [[nodiscard]] static constexpr Point from_vector(const Vector<T, D>& v) { return Point(v.c); }

  constexpr Point& operator+=(const Vector<T, D>& v) {
    for (int i = 0; i < D; ++i) (*this)[i] += v[i];
    return *this;
  }
  constexpr Point& operator-=(const Vector<T, D>& v) {
    for (int i = 0; i < D; ++i) (*this)[i] -= v[i];
    return *this;
  }
  friend constexpr Point operator+(Point p, const Vector<T, D>& v) { return p += v; }
  friend constexpr Point operator-(Point p, const Vector<T, D>& v) { return p -= v; }
  friend constexpr Vector<T, D> operator-(const Point& a, const Point& b) {
    Vector<T, D> r;
    for (int i = 0; i < D; ++i) r[i] = a[i] - b[i];
    return r;
  }
  friend constexpr bool operator==(const Point&, const Point&) = default;
};

template <class T, int D>
constexpr T dot(const Vector<T, D>& a, const Vector<T, D>& b) {
  T s = 0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

template <class T, int D>
constexpr T squared_norm(const Vector<T, D>& v) {
  return dot(v, v);
}

/// Euclidean length, without overflow or underflow for huge or tiny coordinates.
template <class T, int D>
T norm(const Vector<T, D>& v) {
  T scale = 0;
  for (int i = 0; i < D; ++i) scale = std::max(scale, std::abs(v[i]));
  if (scale == 0 || !std::isfinite(scale)) return scale;
  T s = 0;
  for (int i = 0; i < D; ++i) {
    const T x = v[i] / scale;
    s += x * x;
  }
  return scale * std::sqrt(s);
}

template <class T, int D>
T distance(const Point<T, D>& a, const Point<T, D>& b) {
  return norm(a - b);
}

/// z-component of the cross product of two plane vectors.
template <class T>
constexpr T cross(const Vector<T, 2>& a, const Vector<T, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

/// (1 - t) a + t b, exact at t = 0 and t = 1 (the form de Casteljau's algorithm uses).
template <class T>
  requires std::is_floating_point_v<T>
constexpr T lerp(T a, T b, T t) {
  return (1 - t) * a + t * b;
}
template <class T, int D>
constexpr Point<T, D> lerp(const Point<T, D>& a, const Point<T, D>& b, T t) {
  Point<T, D> r;
  const T s = 1 - t;
  for (int i = 0; i < D; ++i) r[i] = s * a[i] + t * b[i];
  return r;
}
template <class T, int D>
constexpr Vector<T, D> lerp(const Vector<T, D>& a, const Vector<T, D>& b, T t) {
  Vector<T, D> r;
  const T s = 1 - t;
  for (int i = 0; i < D; ++i) r[i] = s * a[i] + t * b[i];
  return r;
}

namespace detail {
/// Writes "(x, y, ...)" with each coordinate in the shortest form that reads back as the
/// same value (as the CLI and error messages write numbers).
template <class T, std::size_t D>
std::ostream& write_coordinates(std::ostream& os, const std::array<T, D>& c) {
  os << '(';
  for (std::size_t i = 0; i < D; ++i) os << (i ? ", " : "") << format_number(c[i]);
  return os << ')';
}

/// Whether every coordinate of a point or vector is finite.
template <class V>
bool all_finite_point(const V& v) {
  for (int d = 0; d < V::dimension; ++d) {
    if (!std::isfinite(v[d])) return false;
  }
  return true;
}
}  // namespace detail

/// Prints "(2, 1.5)": shortest round-trip coordinates.
template <class T, int D>
std::ostream& operator<<(std::ostream& os, const Point<T, D>& p) {
  return detail::write_coordinates(os, p.c);
}
/// Prints "(0.5, -1)", as a point.
template <class T, int D>
std::ostream& operator<<(std::ostream& os, const Vector<T, D>& v) {
  return detail::write_coordinates(os, v.c);
}

/// Throws InvalidArgument naming `where[i]` unless every coordinate is finite.
template <class P>
void require_finite_point(const P& p, std::string_view where) {
  for (int i = 0; i < P::dimension; ++i) {
    if (!std::isfinite(p[i])) {
      throw InvalidArgument(std::string(where) + "[" + std::to_string(i) + "]",
                            "coordinate must be finite, got " + detail::format_number(p[i]));
    }
  }
}

/// Throws InvalidArgument naming `name[i][j]` for the first point i of `points` with a
/// non-finite coordinate j (require_finite_point's message); the name text is built only
/// then (the constructors check every point of every curve they make).
template <class Range>
void require_finite_points(const Range& points, std::string_view name) {
  std::size_t i = 0;
  for (const auto& p : points) {
    for (int k = 0; k < std::remove_cvref_t<decltype(p)>::dimension; ++k) {
      if (!std::isfinite(p[k])) require_finite_point(p, std::string(name) + "[" + std::to_string(i) + "]");
    }
    ++i;
  }
}

}  // namespace casteljau
