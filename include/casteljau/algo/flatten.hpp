// Flattening: a polyline within a distance tolerance of a curve, by recursive subdivision.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "casteljau/curves/path.hpp"

namespace casteljau {

namespace detail {

/// Distance from p to the segment [a, b].
template <class T, int D>
T distance_to_segment(const Point<T, D>& p, const Point<T, D>& a, const Point<T, D>& b) {
  const Vector<T, D> ab = b - a, ap = p - a;
  const T len2 = squared_norm(ab);
  if (!(len2 > 0)) return norm(ap);
  const T s = std::clamp(dot(ap, ab) / len2, T(0), T(1));
  return norm(ap - s * ab);
}

/// Flat when every control point is within tol of the chord segment: the curve lies in
/// the convex hull of its control points, and every point of that hull is within tol of
/// the (convex) segment, so the whole piece is too. A guaranteed bound.
template <class C>
bool is_flat(const C& c, typename C::Scalar tol) {
  const auto& P = c.points();
  for (std::size_t i = 1; i + 1 < P.size(); ++i) {
    if (distance_to_segment(P[i], P.front(), P.back()) > tol) return false;
  }
  return true;
}

template <class C>
void flatten_rec(const C& c, typename C::Scalar tol, int depth, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  if (is_flat(c, tol)) {
    out.push_back(c.points().back());
    return;
  }
  // 2^-52 of the parameter range: beyond this, subdivision is stuck on rounding (the
  // tolerance is below the coordinates' resolution).
  if (depth >= 52) throw NumericalError("flatten: tolerance " + format_number(tol) + " is below the resolution of the curve's coordinates");
  const auto halves = c.split(typename C::Scalar(0.5));
  flatten_rec(halves.left, tol, depth + 1, out);
  flatten_rec(halves.right, tol, depth + 1, out);
}

template <class T>
void require_tolerance(T tolerance) {
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(tolerance));
}

}  // namespace detail

/// A polyline from the curve's start to its end whose every point of the curve is within
/// `tolerance` (model units) of the polyline: recursive midpoint subdivision until each
/// piece's control points lie within tolerance of its chord segment (a guaranteed bound
/// for Bézier and positive-weight rational Bézier curves). The vertices lie on the curve.
/// Cost O(n^2) per subdivision; about 1.6x the near-optimal vertex count on cubics
/// (WORKLOADS.md, W3). Throws InvalidArgument for tolerance <= 0, NumericalError when
/// the tolerance is below the coordinates' floating point resolution.
template <class C>
  requires detail::is_bezier_piece<C>
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance) {
  detail::require_tolerance(tolerance);
  using T = typename C::Scalar;
  // Below a few ulps of the coordinates the flatness test cannot succeed reliably, and
  // the subdivision would branch 2^depth ways (up to 2^52) before the depth limit stops
  // a single path: report it at once. 16 eps of max |P| covers the rounding of the
  // flatness distances and of the split control points.
  T m = 0;
  for (const auto& p : c.points())
    for (int d = 0; d < C::dimension; ++d) m = std::max(m, std::abs(p[d]));
  if (tolerance < 16 * std::numeric_limits<T>::epsilon() * m) {
    throw NumericalError("flatten: tolerance " + detail::format_number(tolerance) +
                         " is below the resolution of the curve's coordinates (max |coordinate| " + detail::format_number(m) + ")");
  }
  std::vector<Point<typename C::Scalar, C::dimension>> out{c.points().front()};
  detail::flatten_rec(c, tolerance, 0, out);
  return out;
}

namespace detail {
/// |a - b| without overflow or underflow in the squares (inf only when a coordinate
/// difference itself overflows).
template <class T, int D>
T scaled_distance(const Point<T, D>& a, const Point<T, D>& b) {
  T m = 0;
  for (int d = 0; d < D; ++d) m = std::max(m, std::abs(a[d] - b[d]));
  if (!(m > 0) || !std::isfinite(m)) return m;
  T s = 0;
  for (int d = 0; d < D; ++d) {
    const T x = (a[d] - b[d]) / m;
    s += x * x;
  }
  return m * std::sqrt(s);
}
}  // namespace detail

/// Any other curve flattened piece by piece (pieces(c)), with the same guarantee: a
/// polyline from c(domain().lo) to c(domain().hi) within `tolerance` of the curve, each
/// piece's end vertex written once where the next piece starts at the same point. A
/// curve whose consecutive pieces are more than `tolerance` apart (a path whose segments
/// do not meet) is refused with InvalidArgument("curve", ...): the polyline would have
/// to bridge the gap farther than the tolerance from the curve. A gap up to the
/// tolerance is bridged (every point of the bridge is within the gap of the curve).
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance) {
  using T = typename C::Scalar;
  detail::require_tolerance(tolerance);
  const Pieces<T, C::dimension> p = pieces(c);
  std::vector<Point<T, C::dimension>> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto part = std::visit([&](const auto& s) { return flatten(s, tolerance); }, p.segments()[i]);
    std::size_t skip = 0;
    if (i > 0) {
      const T gap = detail::scaled_distance(out.back(), part.front());
      if (gap > tolerance) {
        throw InvalidArgument("curve", "the curve is not connected at t = " + detail::format_number(p.breaks()[i]) +
                                           ": its pieces are " + detail::format_number(gap) +
                                           " apart there, more than the tolerance " + detail::format_number(tolerance));
      }
      if (gap == 0) skip = 1;
    }
    out.insert(out.end(), part.begin() + static_cast<std::ptrdiff_t>(skip), part.end());
  }
  return out;
}

}  // namespace casteljau
