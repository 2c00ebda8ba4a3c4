// The offset's shared pieces (algo/offset.hpp and its phases in algo/offset/): plane vector
// helpers (left normal, length, unit), the evaluation of Bézier forms without allocation
// (form_point, power_cubic, CubicForm: a cubic's point and derivatives by Horner), the
// Source (one smooth curve to approximate: a stretch of the exact offset or a join arc,
// as functions of its parameter) and the raw offset (Quad, RawKind, Raw: the cubics made so
// far, what each follows, the error and the work limit). Depends on core/ and curves/
// (Point, Vector, Bezier) only.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/core/error.hpp"
#include "casteljau/core/point.hpp"
#include "casteljau/curves/bezier.hpp"

namespace casteljau::detail::offset {

template <class T>
Vector<T, 2> left(const Vector<T, 2>& v) {
  return Vector<T, 2>{-v[1], v[0]};
}

/// |v| by the square root of the sum of squares where that neither overflows nor loses
/// precision to underflow (every vector of the unit frame's inner loops), norm() beyond:
/// norm's scaling (two divisions) was a quarter of the offset's time.
template <class T>
T length(const Vector<T, 2>& v) {
  const T s = v[0] * v[0] + v[1] * v[1];
  constexpr T lo = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
  constexpr T hi = std::numeric_limits<T>::max() * std::numeric_limits<T>::epsilon();
  return s >= lo && s <= hi ? std::sqrt(s) : norm(v);
}

template <class T>
Vector<T, 2> unit(const Vector<T, 2>& v) {
  const T n = length(v);
  return n > 0 ? v / n : Vector<T, 2>{};
}

/// The point at t of the Bézier form with control points P (de Casteljau on the stack up
/// to degree 15, on the heap beyond): no allocation in the inner loops of the fit.
template <class T>
Point<T, 2> form_point(const std::vector<Point<T, 2>>& P, T t) {
  const std::size_t n = P.size();
  if (n == 0) return Point<T, 2>{};
  if (n <= 4) {  // cubics and their hodographs, unrolled
    Point<T, 2> out;
    for (int k = 0; k < 2; ++k) {
      if (n == 1) {
        out[k] = P[0][k];
      } else if (n == 2) {
        out[k] = P[0][k] + t * (P[1][k] - P[0][k]);
      } else if (n == 3) {
        const T a = P[0][k] + t * (P[1][k] - P[0][k]), b = P[1][k] + t * (P[2][k] - P[1][k]);
        out[k] = a + t * (b - a);
      } else {
        const T a = P[0][k] + t * (P[1][k] - P[0][k]), b = P[1][k] + t * (P[2][k] - P[1][k]), c = P[2][k] + t * (P[3][k] - P[2][k]);
        const T d = a + t * (b - a), e = b + t * (c - b);
        out[k] = d + t * (e - d);
      }
    }
    return out;
  }
  std::array<T, 32> small;
  std::vector<T> large;
  T* w = small.data();
  if (n > 16) large.resize(2 * n), w = large.data();
  for (std::size_t i = 0; i < n; ++i) w[2 * i] = P[i][0], w[2 * i + 1] = P[i][1];
  for (std::size_t k = 1; k < n; ++k)
    for (std::size_t i = 0; i + k < n; ++i) {
      w[2 * i] += t * (w[2 * i + 2] - w[2 * i]);
      w[2 * i + 1] += t * (w[2 * i + 3] - w[2 * i + 1]);
    }
  return Point<T, 2>{w[0], w[1]};
}

/// The power-basis coefficients c0 + c1 u + c2 u^2 + c3 u^3 of the cubic Bézier form with
/// control points P0..P3 (fewer points: the form of lower degree). In the unit frame (every
/// coordinate about 1 or less) the power basis on [0, 1] loses a few ulps, no more; Horner's
/// point and derivatives cost a third of three de Casteljau passes.
template <class T>
std::array<Vector<T, 2>, 4> power_cubic(const Point<T, 2>* P, std::size_t n) {
  std::array<Vector<T, 2>, 4> c{};
  for (int k = 0; k < 2; ++k) {
    const T p0 = P[0][k];
    if (n == 1) {
      c[0][k] = p0;
    } else if (n == 2) {
      c[0][k] = p0, c[1][k] = P[1][k] - p0;
    } else if (n == 3) {
      c[0][k] = p0, c[1][k] = 2 * (P[1][k] - p0), c[2][k] = P[2][k] - 2 * P[1][k] + p0;
    } else {
      c[0][k] = p0, c[1][k] = 3 * (P[1][k] - p0), c[2][k] = 3 * (P[2][k] - 2 * P[1][k] + p0);
      c[3][k] = P[3][k] - p0 + 3 * (P[1][k] - P[2][k]);
    }
  }
  return c;
}

/// A cubic Bézier's point and first two derivatives, from its control points (the
/// candidates' inner loops), by Horner in the power basis.
template <class T>
struct CubicForm {
  std::array<Point<T, 2>, 4> P;
  std::array<Vector<T, 2>, 4> c;
  CubicForm() = default;
  Bezier<T, 2> bezier() const { return Bezier<T, 2>({P[0], P[1], P[2], P[3]}); }
  explicit CubicForm(const Bezier<T, 2>& B) : P{B.points()[0], B.points()[1], B.points()[2], B.points()[3]}, c(power_cubic(P.data(), 4)) {}
  CubicForm(const Point<T, 2>& p0, const Point<T, 2>& p1, const Point<T, 2>& p2, const Point<T, 2>& p3)
      : P{p0, p1, p2, p3}, c(power_cubic(P.data(), 4)) {}
  Point<T, 2> at(T u) const {
    Point<T, 2> out;
    for (int k = 0; k < 2; ++k) out[k] = c[0][k] + u * (c[1][k] + u * (c[2][k] + u * c[3][k]));
    return out;
  }
  Vector<T, 2> d1(T u) const {
    Vector<T, 2> v;
    for (int k = 0; k < 2; ++k) v[k] = c[1][k] + u * (2 * c[2][k] + 3 * u * c[3][k]);
    return v;
  }
  Vector<T, 2> d2(T u) const {
    Vector<T, 2> v;
    for (int k = 0; k < 2; ++k) v[k] = 2 * c[2][k] + 6 * u * c[3][k];
    return v;
  }
};

/// One smooth source of the offset, parametrised on [lo, hi]: a stretch of the exact
/// offset of one piece (between the piece's cusps and the offset's cusps) or a join arc.
/// point(t), velocity(t) (its derivative) and tangent(t) (the unit direction of travel,
/// its limit at an end where the velocity vanishes).
template <class T>
struct Source {
  std::function<Point<T, 2>(T)> point;
  std::function<Vector<T, 2>(T)> velocity;
  std::function<Vector<T, 2>(T)> tangent;
  std::function<std::pair<Point<T, 2>, Vector<T, 2>>(T)> frame;  ///< point and tangent at once
  T lo = 0, hi = 1;
  bool reversed = false;  ///< runs against the curve (1 - d kappa < 0), or an inner corner's line
  /// The offset's cusps inside (lo, hi) (a run of stretches approximated across them, see
  /// offset()): a candidate over a part that contains one is measured by its parametric
  /// distance or from partners (parametric, partner_distance), never by the normal scan.
  std::vector<T> cusps;
  bool spans_cusp(T a, T b) const {
    return std::any_of(cusps.begin(), cusps.end(), [&](T c) { return c > a && c < b; });
  }
};

/// A cubic's four control points (the raw offset's cubics: no allocation per cubic).
template <class T>
using Quad = std::array<Point<T, 2>, 4>;

/// What a cubic of the raw offset follows (the trim's tests differ): the offset of a
/// stretch of the curve, the outer join at a corner (round arc, miter or bevel) or the
/// line at an inner corner.
enum class RawKind : unsigned char { stretch, outer_join, inner_join };

/// The fitter's state: the raw offset's cubics, a reversed flag per cubic, and what each
/// follows (with the corner of a join).
template <class T>
struct Raw {
  std::vector<Quad<T>> cubics;
  std::vector<bool> reversed;
  std::vector<RawKind> kind;
  std::vector<Point<T, 2>> corner;  ///< the corner of a join's cubic (unused for a stretch)
  RawKind kind_now = RawKind::stretch;
  Point<T, 2> corner_now{};
  T max_error = 0;
  T tolerance = 0;
  std::size_t max_segments = 0;
  /// How far the next cubic's start will be moved to the last end (a short stretch of an
  /// untrimmed swallowtail left out, see offset()): its fit gets that much less tolerance.
  T start_shift = 0;

  void push(Quad<T> Q, bool rev) {
    const T tiny = 64 * std::numeric_limits<T>::epsilon();  // in the unit frame
    if (std::all_of(Q.begin(), Q.end(), [&](const auto& p) { return norm(p - Q.front()) <= tiny; })) return;  // a point
    if (cubics.size() >= max_segments) {
      throw InvalidArgument("tolerance", "the offset needs more than " + std::to_string(max_segments) +
                                             " cubic segments at this tolerance (the limit): use a larger tolerance");
    }
    if (!cubics.empty()) Q[0] = cubics.back()[3];  // continuous: the previous end (equal up to rounding at G1 joints)
    cubics.push_back(Q);
    reversed.push_back(rev);
    kind.push_back(kind_now);
    corner.push_back(corner_now);
  }
};

}  // namespace casteljau::detail::offset
