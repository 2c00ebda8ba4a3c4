// Flattening: a polyline within a distance tolerance of a curve, three ways: uniform steps
// (Wang's bound), recursive subdivision (the flatness test), near-optimal steps. The
// methods live in algo/flatten/ (one header each, and their shared parts); this header
// gives the public flatten() and flatten_count_estimate().
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/algo/flatten/chord.hpp"
#include "casteljau/algo/flatten/common.hpp"
#include "casteljau/algo/flatten/optimal.hpp"
#include "casteljau/algo/flatten/plane.hpp"
#include "casteljau/algo/flatten/subdivision.hpp"
#include "casteljau/algo/flatten/uniform.hpp"
#include "casteljau/algo/flatten_method.hpp"
#include "casteljau/curves/path.hpp"

/// flatten(c, tolerance, method, out) appends to out (defined for code, such as bench/,
/// that must also build against versions without that overload).
#define CASTELJAU_FLATTEN_APPENDS 1

namespace casteljau {

namespace detail {

/// flatten() of one piece, appended to out (see the public overloads).
template <class C>
void flatten_piece(const C& c, typename C::Scalar tolerance, FlattenMethod method, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  require_tolerance(tolerance);
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
    throw NumericalError("flatten: tolerance " + format_number(tolerance) +
                         " is below the resolution of the curve's coordinates (max |coordinate| " + format_number(m) + ")");
  }
  const Point<T, D> origin = P.front();
  out.push_back(origin);
  if constexpr (requires { normalised_copy(c, origin, 0); }) {
    // Extent of the control polygon about P_0, as a power of two. Differences of finite
    // coordinates may overflow (|P| near the largest double): halve first then.
    const T extent = half_extent(std::span<const Point<T, D>>(P), origin);
    if (extent == 0) {  // every control point at P_0: the curve is that point
      out.push_back(P.back());
      return;
    }
    const int e = unit_exponent(extent);
    // (tolerance 2^-e by one multiplication, correctly rounded as ldexp, when 2^-e is normal)
    const T tol = -e >= -1022 && -e <= 1023 ? tolerance * pow2<T>(-e) : std::ldexp(tolerance, -e);
    if (!(tol < 1)) {  // tolerance >= 2^e > every |P_i - P_0|: the chord is within it
      out.push_back(P.back());
      return;
    }
    if (!(tol >= std::numeric_limits<T>::min())) {
      throw NumericalError("flatten: tolerance " + format_number(tolerance) + " is too small relative to the curve's extent " +
                           format_number(extent * 2) + " (their ratio is below the smallest normal number)");
    }
    if (!(e < std::numeric_limits<T>::max_exponent)) {
      throw NumericalError("flatten: the curve's extent overflows the floating point range");
    }
    // 2^e is a normal or subnormal number here (e < max_exponent, and e > -1074 since
    // extent >= the smallest subnormal), so q 2^e rounds exactly as ldexp(q, e).
    const T up = pow2<T>(e);
    if constexpr (!requires { c.weights(); }) {
      // Lines, quadratics and cubics: the allocation-free kernels (same guarantees; the
      // uniform method gives the same vertices as the general code).
      if (P.size() <= 4 && (method == FlattenMethod::uniform || (D == 2 && method == FlattenMethod::optimal))) {
        const SmallPiece<T, D> s = small_piece(P, origin, e);
        auto emit = [&](const Point<T, D>& q) {
          Point<T, D> r;
          for (int d = 0; d < D; ++d) r[d] = origin[d] + q[d] * up;
          out.push_back(r);
        };
        if (method == FlattenMethod::uniform) {
          small_uniform(s, tol, emit);
        } else if constexpr (D == 2 && std::is_same_v<T, double>) {
          small_optimal_compiled(s, tol, out, origin, up);  // src/flatten: the lane kernels
        } else if constexpr (D == 2) {
          SmallOptimalWriter<T> writer{out, origin, up};
          small_optimal(s, tol, writer);
          writer.finish();
        }
        out.push_back(P.back());
        return;
      }
    }
    const auto unit = normalised_copy(c, origin, e);
    const std::size_t first = out.size();  // the unit-scale vertices after P_0, scaled back in place
    switch (method) {
      case FlattenMethod::uniform: flatten_uniform(unit, tol, out); break;
      case FlattenMethod::optimal: flatten_optimal(unit, tol, out); break;
      default: flatten_subdivision(unit, tol, out); break;
    }
    for (std::size_t i = first; i + 1 < out.size(); ++i)
      for (int d = 0; d < D; ++d) out[i][d] = origin[d] + out[i][d] * up;
    out.back() = P.back();
  } else {
    flatten_rec(c, tolerance, 0, out);
  }
}
}  // namespace detail

/// flatten() appending to out: the same polyline (its first vertex, the curve's start,
/// included) pushed onto the end of out, so that many curves can share one vector
/// without an allocation per curve. An out-parameter rather than a returned value (our
/// style's default) for that reason. When it throws, out is left as it was.
template <class C>
  requires detail::is_bezier_piece<C>
void flatten(const C& c, typename C::Scalar tolerance, FlattenMethod method, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  const std::size_t size0 = out.size();
  try {
    detail::flatten_piece(c, tolerance, method, out);
  } catch (...) {
    out.resize(size0);
    throw;
  }
}

/// A polyline from the curve's start to its end whose every point of the curve is within
/// `tolerance` (model units) of the polyline, its vertices on the curve (the first and
/// last exactly its end points), by one of three methods:
/// - `subdivision`: recursive midpoint
///   subdivision until each part's control points lie within tolerance of its chord
///   segment (the convex hull property makes it a guaranteed bound). About 1.6x the
///   near-optimal count on cubics (W3 of docs/performance.md). Cost O(p^2) per halving.
/// - `uniform`: n equal parameter steps, n from Wang's bound [Wang84; Filip86] (a proven
///   bound for polynomial pieces; for rational pieces Wang's formula on the Cartesian
///   points, doubled until every step passes the exact check below). Cheapest per vertex.
/// - `optimal` (the default, as on the command line): near the fewest segments with vertices on the curve, each step checked
///   exactly, so the tolerance holds at cusps, inflections and loops. Steps follow the
///   near-optimal density sqrt(|B''_normal|) (a chord over a short arc of curvature k
///   deviates by k s^2 / 8, so segments of deviation tol number the integral of sqrt(k) ds
///   / sqrt(8 tol); Levien's flattening of quadratics integrates it in closed form
///   [Levien19]). Two implementations:
///   - plane polynomial pieces of degree <= 3 (detail::small_optimal, Levien's analytic
///     flattening): the count n = ceil(s F) is planned first (F the density integral: one
///     parabola in closed form when the cubic term is negligible, else the density at two
///     Gauss-Legendre nodes in each of 12 cells; safety s = 1 and 1.02), then each vertex
///     is placed independently where the count function reaches j F / n; each step is
///     checked in O(1): in closed form on the parabola when the piece is one within 1e-3
///     tol (detail::parabola_step_within), else from its end points and end derivatives
///     (the signed distance to the chord's line is a cubic with zero ends whose extremes are
///     roots of a quadratic; the overshoot beyond the chord's ends bounded likewise, see
///     detail::small_chord_check),
///     and a failing step's end is moved back until it passes (the last step gains
///     vertices instead). About 95% of the steps pass as placed on random cubics, 99.9% on
///     font outlines; no allocation.
///   - every other piece (rational, higher degree, 3-D): a greedy walk whose steps start
///     from one unit of the cumulative density (trapezoid rule on 8 p samples) and are
///     corrected by the measured deviation into [0.9, 1] tolerance, each check on the part
///     split off (from the roots of the derivative of the squared distance when the part's
///     control points project inside the chord, else the hull test); one O(p^3) part and
///     one root solve per check.
///   The count can be told before emitting: flatten_count_estimate (for the plane kernel,
///   its planned n: 0.5% below the emitted count on W3's random cubics, equal on 99.9% of
///   font outlines).
///
/// Scale: every method runs on a copy translated to P_0 and scaled by the power of two
/// 2^-e that brings the largest |P_i - P_0| into [0.5, 1), with the tolerance scaled
/// alike; the vertices are scaled back. So huge and tiny coordinates behave as unit ones,
/// no distance over- or underflows, and scaling a curve and its tolerance by 2^k scales
/// the polyline by exactly 2^k (same vertex count) while every value stays a normal
/// number. A tolerance of at least the curve's extent gives the chord.
///
/// Throws InvalidArgument("tolerance", ...) for a tolerance that is not finite or <= 0,
/// NumericalError when the tolerance is below the coordinates' floating point resolution
/// (16 eps of max |P_i|), the scaled tolerance underflows, or a piece would need more
/// than 2^26 segments.
template <class C>
  requires detail::is_bezier_piece<C>
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance,
                                                             FlattenMethod method = FlattenMethod::optimal) {
  std::vector<Point<typename C::Scalar, C::dimension>> out;
  detail::flatten_piece(c, tolerance, method, out);
  return out;
}

/// The segment count of the optimal method told before emitting, summed over the pieces
/// and computed on the same unit-scale copy as flatten(): for plane polynomial pieces of
/// degree <= 3 the count the kernel plans (detail::small_optimal_plan: it emits exactly
/// that many segments unless a step's check moves its end, then a few more: 0.5% on W3's
/// random cubics); for other pieces ceil of the integral of the near-optimal density
/// (detail::flatten_cumulative; the emitted count was 2.3% above it on W3's random cubics
/// before the plane kernel). At least 1 per piece. Cost: about that of 24 derivative
/// evaluations per cubic, 8 p + 1 per general piece.
template <class C>
  requires detail::is_bezier_piece<C>
double flatten_count_estimate(const C& c, typename C::Scalar tolerance) {
  detail::require_tolerance(tolerance);
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const auto& P = c.points();
  const Point<T, D> origin = P.front();
  const T extent = detail::half_extent(std::span<const Point<T, D>>(P), origin);
  if (extent == 0) return 1;
  const int e = detail::unit_exponent(extent);
  const T tol = std::ldexp(tolerance, -e);
  if (!(tol < 1)) return 1;
  if (!(tol >= std::numeric_limits<T>::min())) return std::numeric_limits<double>::infinity();
  if constexpr (D == 2 && !requires { c.weights(); }) {
    if (P.size() <= 4) {  // the plan of the plane kernel (detail::small_optimal_plan)
      if (P.size() == 2) return 1;
      detail::SmallOptimalPlan<T> plan;
      detail::small_optimal_plan(detail::small_piece(P, origin, e), tol, plan);
      return plan.n;
    }
  }
  return detail::optimal_count(detail::normalised_copy(c, origin, e), tol);
}

template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
double flatten_count_estimate(const C& c, typename C::Scalar tolerance) {
  const auto& p = pieces(c);
  double n = 0;
  p.for_each_piece([&](std::size_t, const auto& piece, const auto&) { n += flatten_count_estimate(piece, tolerance); });
  return n;
}

/// Any other curve flattened piece by piece (pieces(c)), with the same guarantee: a
/// polyline from c(domain().lo) to c(domain().hi) within `tolerance` of the curve, each
/// piece's end vertex written once where the next piece starts at the same point, and
/// no vertex twice in a row (a curve that is one point gives it twice). A
/// curve whose consecutive pieces are more than `tolerance` apart (a path whose segments
/// do not meet) is refused with InvalidArgument("curve", ...): the polyline would have
/// to bridge the gap farther than the tolerance from the curve. A gap up to the
/// tolerance is bridged (every point of the bridge is within the gap of the curve).
/// This overload appends the polyline to out, as the one-piece one does (out unchanged
/// when it throws); the next returns it.
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
void flatten(const C& c, typename C::Scalar tolerance, FlattenMethod method, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  using T = typename C::Scalar;
  detail::require_tolerance(tolerance);
  const Pieces<T, C::dimension>& p = pieces(c);  // a reference to c itself when c is Pieces
  const std::size_t size0 = out.size();
  try {
    p.for_each_piece([&](std::size_t i, const auto& piece, const Interval<T>& own) {
      const std::size_t start = out.size();
      detail::flatten_piece(piece, tolerance, method, out);
      if (i == 0) return;
      const T gap = detail::scaled_distance(out[start - 1], out[start]);
      if (gap > tolerance) {
        throw InvalidArgument("curve", "the curve is not connected at t = " + detail::format_number(p.lift(i, own.lo)) +
                                           ": its pieces are " + detail::format_number(gap) +
                                           " apart there, more than the tolerance " + detail::format_number(tolerance));
      }
      if (gap == 0) out.erase(out.begin() + static_cast<std::ptrdiff_t>(start));
    });
    // A piece that is a single point (a zero-length segment of a path) adds nothing: no
    // vertex is written twice in a row, but a curve that is one point keeps its two.
    const auto first = out.begin() + static_cast<std::ptrdiff_t>(size0);
    out.erase(std::unique(first, out.end()), out.end());
    if (out.size() - size0 == 1) out.push_back(out.back());
  } catch (...) {
    out.resize(size0);
    throw;
  }
}

template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance,
                                                             FlattenMethod method = FlattenMethod::optimal) {
  std::vector<Point<typename C::Scalar, C::dimension>> out;
  flatten(c, tolerance, method, out);
  return out;
}

}  // namespace casteljau
