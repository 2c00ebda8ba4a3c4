// Offset curves of plane curves: C(t) + d N(t) approximated by cubic Béziers within a
// measured tolerance, with joins at the corners of the input, and trimmed to the points at
// least |d| from the curve. The phases are in algo/offset/, one header each
// (docs/architecture.md): common (vector helpers, cubic forms, the Source and the raw
// offset), stretches (cusps of the piece and of the offset, the offset's Source), measure
// and normal_scan (the error measures), fit (the candidate cubics), place (greedy or
// uniform placement along a Source), joins (round, miter, bevel, inner corners), near (the
// trim's distance test) and trim (crossings, caps, judged parts); options.hpp holds
// OffsetOptions, which the phases read. This header gives offset() and its estimate.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/offset/common.hpp"
#include "casteljau/algo/offset/joins.hpp"
#include "casteljau/algo/offset/near.hpp"
#include "casteljau/algo/offset/options.hpp"
#include "casteljau/algo/offset/place.hpp"
#include "casteljau/algo/offset/stretches.hpp"
#include "casteljau/algo/offset/trim.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The result of offset(): the cubics in order (a path, continuous except between the
/// parts the trim leaves, see offset()), the largest measured distance of a cubic of the
/// raw offset from its exact source (offset stretch or join), and the number of runs of
/// the raw offset the trim cut away.
template <class T>
struct OffsetCurve {
  std::vector<Bezier<T, 2>> segments;
  T max_error = 0;
  std::size_t loops_cut = 0;
  std::size_t raw_segments = 0;  ///< cubics before trimming
};

/// An estimate of the number of cubics offset() makes, before any work: per piece at least
/// one, plus its turning measured on 32 (n + 1) samples, each angle dtheta counted as
/// dtheta / phi_max, phi_max = (tolerance / (c r))^(1/6) the largest arc of the offset's
/// radius r = |1 - d kappa| / |kappa| that one cubic approximates within the tolerance
/// (a cubic's error on a circular arc of angle phi is about c r phi^6, c = 1.8e-5: the
/// classic quarter circle with handles 0.5523 r is 2.7e-4 r off); plus two per piece for
/// its cusps and joins. Cost: O(pieces n^2).
template <class T>
double offset_segments_estimate(const Pieces<T, 2>& curve, T distance, T tolerance) {
  double total = 0;
  for (const auto& seg : curve.segments()) {
    std::visit(
        [&](const auto& c) {
          const int m = 32 * (c.degree() + 1);
          double sum = 0;
          for (int j = 0; j < m; ++j) {
            const T t = (T(j) + T(0.5)) / T(m);
            const Vector<T, 2> d1 = c.derivative_at(t, 1), d2 = c.derivative_at(t, 2);
            const double sp = static_cast<double>(norm(d1));
            if (!(sp > 0)) continue;
            const double k = static_cast<double>(cross(d1, d2)) / (sp * sp * sp);
            const double dtheta = std::abs(k) * sp / m;
            if (!(dtheta > 1e-15) || !std::isfinite(dtheta)) continue;
            const double r = std::abs(1 - static_cast<double>(distance) * k) / std::abs(k);
            sum += dtheta * std::pow(1.8e-5 * r / static_cast<double>(tolerance), 1.0 / 6);
          }
          total += 2 + std::ceil(std::isfinite(sum) ? sum : 0);
        },
        seg);
  }
  return total;
}

/// The offset of a plane curve at signed distance d (positive to the left of the
/// direction of travel), C(t) + d N(t) with N the unit normal turned +90 degrees from the
/// tangent, as cubic Bézier segments within `tolerance` of it.
///
/// Method. The curve is taken in its unit frame (origin at its first control point, a
/// power-of-two scale: huge and tiny coordinates behave as unit ones). Each exact piece
/// (Bézier or rational Bézier) is cut at its cusps (interior zeros of the speed, found as
/// minima below 1e-6 of the piece's largest speed on a grid of max(64, 16 (n + 1)) points)
/// and at the offset's cusps, where 1 - d kappa(t) changes sign (kappa the signed curvature, > 0 where the curve turns left;
/// bisection to full precision) or touches zero (|d| equals a radius of curvature: minima
/// of |1 - d kappa| below 1e-9) [Farouki90]. On each stretch the offset is smooth and runs with the
/// curve (1 - d kappa > 0) or against it; its tangent is +-T(t), the curve's (its limit
/// where the speed vanishes). Each stretch is approximated greedily: the longest cubic
/// from the current parameter that is within the tolerance, the cubic interpolating the
/// offset's end points and tangent directions, with the handle lengths of a least-squares
/// fit to 15 samples or of the Hermite cubic, whichever is closer. Each candidate is
/// measured along the offset's normal lines (Tiller-Hanson's measure; see
/// detail::offset::NormalScan): where those lines meet the cubic in order from end to end,
/// the largest distance along them bounds the distance both ways, so one scan of 20 or more
/// feet, the tops of its bumps refined (successive parabolas), measures the cubic (the
/// projections both ways, detail::offset::hausdorff, where the lines do not meet it in
/// order). The end is chosen from the scans' estimates with a model of the error's growth
/// and a bracket (detail::offset::approximate); the cubic kept is the one whose measure is
/// within the tolerance. The measure is sampled: an estimate of the Hausdorff distance
/// from above between samples that resolve the error's bumps, not a proven bound.
///
/// Joins. At each G0 corner of the input (a joint of pieces, or a cusp inside one, where
/// the tangents differ by more than 1e-9 rad; at the closing point of a closed curve too)
/// the outer side gets `join`: a round arc of radius |d| (approximated as above), a miter
/// (the offset lines extended to their meeting point, while 1 / cos(theta / 2) <=
/// miter_limit for a turn theta; a bevel beyond, as SVG's stroke-miterlimit) or a bevel
/// line; a reversal (a turn of pi) is always closed by a round arc or a bevel. The inner
/// side gets a straight line from one offset end to the other, traversed backwards.
///
/// Trim. Kept: the points of the raw offset at least |d| - tolerance from the curve (the
/// offset as stroking and tool paths need it: swallowtails, the lines at inner corners,
/// the offsets of parts of the curve nearer than 2 |d| to each other, a circle offset past
/// its centre all go). The raw offset is cut at the crossings of its cubics
/// (detail::offset::raw_crossings), its cusps and join ends, and for an open curve where
/// it crosses the circles of radius |d| about the curve's ends; each part between cuts is
/// judged by the distance of samples to the curve, a change between samples found by
/// bisection (detail::offset::trimmed_intervals). What is kept stays in order; parts that
/// do not meet follow each other with a gap (a closed curve's part through the closing
/// point is one part).
///
/// Untrimmed (trim = false), parts that the tolerance covers are left out: a stretch
/// between two cusps of the offset whose points are all within tolerance / 4 of its start
/// (sampled at 33 points), the next cubic fitted within the tolerance less the stretch's
/// chord (its start moves by that to the last end), and for an open curve of one piece a
/// first or last stretch cut off by a cusp, within 0.9 tolerance of the cusp.
///
/// Result: the cubics in order, each starting where the previous ends except between the
/// parts the trim leaves (a gap: a new part). d = 0 gives the
/// curve itself as cubics (exact for polynomial pieces of degree <= 3). Pieces that are
/// single points are skipped. Errors: InvalidArgument "distance", "tolerance" (not > 0 and
/// finite; below 1e-11 of the curve's size plus |d|; more than max_segments cubics),
/// "curve" (a single point), "distance" when the trim leaves nothing.
template <class T>
OffsetCurve<T> offset(const Pieces<T, 2>& curve, const OffsetOptions<T>& o) {
  using namespace detail::offset;
  if (!std::isfinite(o.distance)) throw InvalidArgument("distance", "must be a finite number");
  if (!(o.tolerance > 0) || !std::isfinite(o.tolerance)) throw InvalidArgument("tolerance", "must be a finite number > 0");
  if (!(o.miter_limit >= 1) || !std::isfinite(o.miter_limit)) throw InvalidArgument("miter_limit", "must be a finite number >= 1");
  // The unit frame of every control point.
  std::vector<Point<T, 2>> all;
  for (const auto& s : curve.segments()) std::visit([&](const auto& c) { all.insert(all.end(), c.points().begin(), c.points().end()); }, s);
  const Point<T, 2> origin = all.front();
  const T half = detail::half_extent<T, 2>(all, origin);
  if (!(half > 0)) throw InvalidArgument("curve", "is a single point: its offset is undefined");
  const int e = detail::unit_exponent(half);
  const T scale = detail::pow2<T>(-e);
  const T d = o.distance * scale, tol = o.tolerance * scale;
  if (tol < T(1e-11) * (1 + std::abs(d))) {
    throw InvalidArgument("tolerance", "is below 1e-11 of the curve's size plus |distance|: cubics in floating point cannot be "
                                       "measured that close");
  }
  const auto to_frame = [&](const auto& c) {
    using C = std::decay_t<decltype(c)>;
    std::vector<Point<T, 2>> P;
    for (const auto& p : c.points()) P.push_back(detail::to_unit(p, origin, e));
    if constexpr (std::is_same_v<C, Bezier<T, 2>>) {
      return BezierPiece<T, 2>(Bezier<T, 2>(std::move(P)));
    } else {
      return BezierPiece<T, 2>(RationalBezier<T, 2>(std::move(P), c.weights()));
    }
  };
  const T tiny = 64 * std::numeric_limits<T>::epsilon();  // a derivative this small (in the unit frame) counts as zero
  Raw<T> raw;
  raw.tolerance = tol;
  raw.max_segments = o.max_segments;
  std::optional<Vector<T, 2>> prev;  // the curve's tangent at the end of the last stretch
  std::optional<Vector<T, 2>> first;
  Point<T, 2> first_at{}, last_at{};
  bool any = false;
  bool single_open = false;  // one piece whose ends differ (no closing join)
  if (curve.segments().size() == 1) {
    std::visit([&](const auto& c) { single_open = norm(c.points().back() - c.points().front()) * scale > T(1e-10); },
               curve.segments().front());
  }
  Nearness<T> near;  // the curve, for the trim's distance tests
  near.leaf = tol / 64;
  std::optional<Point<T, 2>> piece_end;  // the end of the last piece, a single point too
  for (const auto& seg : curve.segments()) {
    const BezierPiece<T, 2> piece = std::visit(to_frame, seg);
    if (o.trim && d != 0) near.add(piece);
    std::visit(
        [&](const auto& c) {
          const auto& P = c.points();
          // Pieces that do not meet (a B-spline of degree 0 with jumps: single points too).
          if (piece_end && norm(P.front() - *piece_end) > tol) {
            throw InvalidArgument("curve", "has a gap of " + std::to_string(norm(P.front() - *piece_end) / scale) +
                                               " between two pieces, more than the tolerance: its offset would not be connected");
          }
          piece_end = P.back();
          if (std::all_of(P.begin(), P.end(), [&](const auto& p) { return norm(p - P.front()) <= tiny; })) return;  // a point
          bool piece_start = true;
          const std::vector<Stretch<T>> ss = stretches<T>(c, d, tiny);
          // The start of a stretch: the first tangent, the gap between pieces, the join.
          const auto begin = [&](const Stretch<T>& s) {
            if (!any) first = s.t_lo, first_at = c(s.lo), any = true;
            if (piece_start && prev && norm(c(s.lo) - last_at) > tol) {
              throw InvalidArgument("curve", "has a gap of " + std::to_string(norm(c(s.lo) - last_at) / scale) +
                                                 " between two pieces, more than the tolerance: its offset would not be connected");
            }
            piece_start = false;
            if (prev && d != 0) join(Corner<T>{c(s.lo), *prev, s.t_lo}, o, d, raw);
          };
          // One stretch on its own (`begun`: its start already made).
          const auto one = [&](std::size_t k, bool begun) {
            const Stretch<T>& s = ss[k];
            // Untrimmed, a stretch between two cusps of the offset (a swallowtail's middle)
            // whose every point is within a quarter of the tolerance of its start (sampled
            // at 33 points; so short that its curvature cannot hide more) is left out: the
            // last cubic's end is that close to all of it, and the next cubic, whose start
            // moves there by the stretch's chord, is fitted within the tolerance less that.
            if (!o.trim && d != 0 && o.fit == OffsetFit::greedy && k > 0 && k + 1 < ss.size() && !raw.cubics.empty() && raw.start_shift == 0 &&
                std::abs(turn(ss[k - 1].t_hi, s.t_lo)) <= T(1e-9) && std::abs(turn(s.t_hi, ss[k + 1].t_lo)) <= T(1e-9)) {
              const Source<T> src = stretch_source<T>(c, s, d);
              const Point<T, 2> start = src.point(s.lo);
              T extent = 0;
              for (int j = 1; j <= 32; ++j) extent = std::max(extent, length(src.point(s.lo + (s.hi - s.lo) * T(j) / 32) - start));
              if (extent <= T(0.25) * tol) {
                raw.max_error = std::max(raw.max_error, extent);
                raw.start_shift = length(src.point(s.hi) - start);
                prev = s.t_hi;
                last_at = c(s.hi);
                return;
              }
            }
            // Untrimmed, an open curve of one piece: a first or last stretch cut off by a
            // cusp of the offset whose every point is within 90% of the tolerance of the
            // end it shares with its neighbour is left out (nothing moves: the path starts
            // or ends at that cusp).
            if (!o.trim && d != 0 && o.fit == OffsetFit::greedy && single_open && ss.size() > 1 && (k == 0 || (k + 1 == ss.size() && !raw.cubics.empty())) &&
                std::abs(turn(k == 0 ? s.t_hi : ss[k - 1].t_hi, k == 0 ? ss[1].t_lo : s.t_lo)) <= T(1e-9)) {
              const Source<T> src = stretch_source<T>(c, s, d);
              const Point<T, 2> shared = src.point(k == 0 ? s.hi : s.lo);
              T extent = 0;
              for (int j = 0; j <= 32; ++j) extent = std::max(extent, length(src.point(s.lo + (s.hi - s.lo) * T(j) / 32) - shared));
              if (extent <= T(0.9) * tol) {
                if (!any) first = s.t_lo, first_at = c(s.lo), any = true;
                raw.max_error = std::max(raw.max_error, extent);
                prev = s.t_hi;
                last_at = c(s.hi);
                return;
              }
            }
            if (!begun) begin(s);
            approximate(stretch_source<T>(c, s, d), o.fit, raw);
            prev = s.t_hi;
            last_at = c(s.hi);
          };
          for (std::size_t k = 0; k < ss.size(); ++k) {
            // Untrimmed, a run of stretches k..k1 between cusps of the offset (the curve's
            // tangent continuous between them).
            std::size_t k1 = k;
            if (!o.trim && d != 0 && o.fit == OffsetFit::greedy) {
              while (k1 + 1 < ss.size() && std::abs(turn(ss[k1].t_hi, ss[k1 + 1].t_lo)) <= T(1e-9)) ++k1;
            }
            if (k1 == k) {
              one(k, false);
              continue;
            }
            begin(ss[k]);
            // First one cubic across them all (offset_source; lib2geom's route follows the
            // offset through its cusps the same way, docs/performance.md W11, session 16),
            // else the stretches' cubics one by one.
            if (raw.start_shift == 0) {
              const Source<T> src = offset_source<T>(c, &ss[k], &ss[k1], d);
              std::array<Screened<T>, 2> work;
              Screened<T>& g = best_screened(src, src.lo, src.hi, tol, true, work);
              const T e = g.error <= tol ? certify(g, src, src.lo, src.hi, tol) : g.error;
              if (e <= tol) {
                raw.max_error = std::max(raw.max_error, e);
                raw.push(g.cubic.P, ss[k].reversed);
                prev = ss[k1].t_hi;
                last_at = c(ss[k1].hi);
                k = k1;
                continue;
              }
            }
            for (std::size_t j = k; j <= k1; ++j) one(j, j == k);
            k = k1;
          }
        },
        piece);
  }
  if (!any) throw InvalidArgument("curve", "is a single point: its offset is undefined");
  const bool closed = norm(last_at - first_at) <= T(1e-10);
  if (closed && d != 0) join(Corner<T>{first_at, *prev, *first}, o, d, raw);
  if (closed && !raw.cubics.empty()) {  // the last end exactly on the first start
    const Point<T, 2> start = raw.cubics.front()[0];
    if (norm(raw.cubics.back()[3] - start) <= tol) raw.cubics.back()[3] = start;
  }
  if (raw.cubics.empty()) {
    throw InvalidArgument("distance", "the offset is a single point (|distance| equals the radius of curvature all along)");
  }
  OffsetCurve<T> out;
  out.raw_segments = raw.cubics.size();
  out.max_error = raw.max_error / scale;
  std::vector<Quad<T>> kept;
  if (o.trim && d != 0) {
    kept = trimmed_cubics(raw, near, d, tol, closed, first_at, last_at, tiny, out.loops_cut);
  } else {
    kept = std::move(raw.cubics);
  }
  // Back from the unit frame.
  const T back = detail::pow2<T>(e);
  out.segments.reserve(kept.size());
  for (const auto& Q : kept) {
    std::vector<Point<T, 2>> P(4);
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 2; ++k) P[static_cast<std::size_t>(j)][k] = Q[static_cast<std::size_t>(j)][k] * back + origin[k];
    out.segments.push_back(Bezier<T, 2>(std::move(P)));
  }
  return out;
}

/// The offset of any plane curve through its exact pieces.
template <class C>
  requires PiecewiseBezierCurve<C> && (C::dimension == 2) && (!detail::is_pieces<C>)
OffsetCurve<typename C::Scalar> offset(const C& c, const OffsetOptions<typename C::Scalar>& o) {
  return offset(pieces(c), o);
}

}  // namespace casteljau
