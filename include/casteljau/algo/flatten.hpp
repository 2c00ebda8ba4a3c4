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

/// Distance from p to the segment [a, b], without overflow or underflow (norm() scales
/// by the largest coordinate) and with NaN propagated, never turned into a pass.
template <class T, int D>
T distance_to_segment(const Point<T, D>& p, const Point<T, D>& a, const Point<T, D>& b) {
  const Vector<T, D> ab = b - a, ap = p - a;
  const T len = norm(ab);
  if (len == 0) return norm(ap);
  // Projection parameter s = (ap . ab) / |ab|^2, computed on unit-length ab so that
  // neither the dot product nor the squared length over- or underflows.
  const Vector<T, D> u = ab / len;
  const T s = dot(ap, u) / len;
  if (!(s > 0)) return s == s ? norm(ap) : s;  // NaN stays NaN
  if (s >= 1) return norm(p - b);
  return norm(ap - (s * len) * u);
}

/// Flat when every control point is within tol of the chord segment: the curve lies in
/// the convex hull of its control points, and every point of that hull is within tol of
/// the (convex) segment, so the whole piece is too. A guaranteed bound. Written so that
/// a NaN distance fails the test.
template <class C>
bool is_flat(const C& c, typename C::Scalar tol) {
  const auto& P = c.points();
  for (std::size_t i = 1; i + 1 < P.size(); ++i) {
    if (!(distance_to_segment(P[i], P.front(), P.back()) <= tol)) return false;
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
  if (depth >= 52) {
    throw NumericalError("flatten: subdivision reached depth 52 (pieces of 2^-52 of the parameter range): the tolerance is below "
                         "the resolution of the curve's coordinates");
  }
  const auto halves = c.split(typename C::Scalar(0.5));
  flatten_rec(halves.left, tol, depth + 1, out);
  flatten_rec(halves.right, tol, depth + 1, out);
}

template <class T>
void require_tolerance(T tolerance) {
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(tolerance));
}

/// The curve with control points (P_i - origin) 2^-e (weights unchanged): translation
/// then an exact power-of-two scaling. Scaling a curve by 2^k changes every value here
/// by exactly 2^k (while all stay normal numbers), so the copy does not depend on k.
template <class T, int D>
std::vector<Point<T, D>> normalised_points(const std::vector<Point<T, D>>& P, const Point<T, D>& origin, int e) {
  std::vector<Point<T, D>> Q(P.size());
  for (std::size_t i = 0; i < Q.size(); ++i)
    for (int d = 0; d < D; ++d) {
      const T q = P[i][d] - origin[d];
      // The difference of two finite coordinates may overflow: then halve them first
      // (exact for normal numbers) and scale by one power of two less.
      Q[i][d] = std::isfinite(q) ? std::ldexp(q, -e) : std::ldexp(P[i][d] / 2 - origin[d] / 2, 1 - e);
    }
  return Q;
}
template <class T, int D>
Bezier<T, D> normalised_copy(const Bezier<T, D>& c, const Point<T, D>& origin, int e) {
  return Bezier<T, D>(normalised_points(c.points(), origin, e));
}
template <class T, int D>
RationalBezier<T, D> normalised_copy(const RationalBezier<T, D>& c, const Point<T, D>& origin, int e) {
  return RationalBezier<T, D>(normalised_points(c.points(), origin, e), c.weights());
}

}  // namespace detail

/// A polyline from the curve's start to its end whose every point of the curve is within
/// `tolerance` (model units) of the polyline: recursive midpoint subdivision until each
/// piece's control points lie within tolerance of its chord segment (a guaranteed bound
/// for Bézier and positive-weight rational Bézier curves). The vertices lie on the curve
/// (the first and last are exactly its end points).
///
/// Scale: the subdivision runs on a copy translated to P_0 and scaled by the power of
/// two 2^-e that brings the largest |P_i - P_0| into [0.5, 1), with the tolerance scaled
/// alike; the vertices are scaled back. So huge and tiny coordinates behave as unit ones,
/// no distance over- or underflows, and scaling a curve and its tolerance by 2^k scales
/// the polyline by exactly 2^k (same vertex count) while every value stays a normal
/// number. A tolerance of at least the curve's extent gives the chord.
///
/// Cost O(n^2) per subdivision; about 1.6x the near-optimal vertex count on cubics
/// (WORKLOADS.md, W3). Throws InvalidArgument("tolerance", ...) for a tolerance that is
/// not finite or <= 0, NumericalError when the tolerance is below the coordinates'
/// floating point resolution (16 eps of max |P_i|) or the scaled tolerance underflows.
template <class C>
  requires detail::is_bezier_piece<C>
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance) {
  detail::require_tolerance(tolerance);
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  // Below a few ulps of the coordinates the flatness test cannot succeed reliably, and
  // the subdivision would branch 2^depth ways (up to 2^52) before the depth limit stops
  // a single path: report it at once. 16 eps of max |P| covers the rounding of the
  // flatness distances, of the split control points and of the translation to P_0.
  const auto& P = c.points();
  T m = 0;
  for (const auto& p : P)
    for (int d = 0; d < D; ++d) m = std::max(m, std::abs(p[d]));
  if (tolerance < 16 * std::numeric_limits<T>::epsilon() * m) {
    throw NumericalError("flatten: tolerance " + detail::format_number(tolerance) +
                         " is below the resolution of the curve's coordinates (max |coordinate| " + detail::format_number(m) + ")");
  }
  const Point<T, D> origin = P.front();
  std::vector<Point<T, D>> out{origin};
  if constexpr (requires { detail::normalised_copy(c, origin, 0); }) {
    // Extent of the control polygon about P_0, as a power of two. Differences of finite
    // coordinates may overflow (|P| near the largest double): halve first then.
    T extent = 0;
    for (const auto& p : P)
      for (int d = 0; d < D; ++d) extent = std::max(extent, std::abs(p[d] / 2 - origin[d] / 2));
    if (extent == 0) {  // every control point at P_0: the curve is that point
      out.push_back(P.back());
      return out;
    }
    int e = 0;
    (void)std::frexp(extent, &e);
    ++e;  // extent was halved
    const T tol = std::ldexp(tolerance, -e);
    if (!(tol < 1)) {  // tolerance >= 2^e > every |P_i - P_0|: the chord is within it
      out.push_back(P.back());
      return out;
    }
    if (!(tol >= std::numeric_limits<T>::min())) {
      throw NumericalError("flatten: tolerance " + detail::format_number(tolerance) + " is too small relative to the curve's extent " +
                           detail::format_number(extent * 2) + " (their ratio is below the smallest normal number)");
    }
    if (!(e < std::numeric_limits<T>::max_exponent)) {
      throw NumericalError("flatten: the curve's extent overflows the floating point range");
    }
    const auto unit = detail::normalised_copy(c, origin, e);
    std::vector<Point<T, D>> local{unit.points().front()};
    detail::flatten_rec(unit, tol, 0, local);
    for (std::size_t i = 1; i + 1 < local.size(); ++i) {
      Point<T, D> q;
      for (int d = 0; d < D; ++d) q[d] = origin[d] + std::ldexp(local[i][d], e);
      out.push_back(q);
    }
    out.push_back(P.back());
  } else {
    detail::flatten_rec(c, tolerance, 0, out);
  }
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
  const Pieces<T, C::dimension>& p = pieces(c);  // a reference to c itself when c is Pieces
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
