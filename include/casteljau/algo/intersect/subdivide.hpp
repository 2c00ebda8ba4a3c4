// Intersection engine, phase 2 for one pair of arcs (algo/intersect.hpp): subdivision
// with control-box and fat-line clipping down to flat parts, each seed refined; the
// bands of near-coincident parts are algo/intersect/band.hpp's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/refine.hpp"
#include "casteljau/core/segment.hpp"

namespace casteljau::detail::isect {

/// The closest points of the chords [p0, p1] and [q0, q1] (core/segment.hpp): their
/// parameters (u, v) in [0, 1] and distance.
template <class T>
struct SegmentClosest {
  T u, v, distance;
};
template <class T>
SegmentClosest<T> chord_closest(const Point<T, 2>& p0, const Point<T, 2>& p1, const Point<T, 2>& q0, const Point<T, 2>& q1) {
  const auto [u, v] = casteljau::closest_on_segments(p0, p1, q0, q1);
  return {u, v, norm((p0 + u * (p1 - p0)) - (q0 + v * (q1 - q0)))};
}

/// Whether no tangent line of one part is parallel to a tangent line of the other: then
/// the parts meet at most once [SederbergMeyers88] and one refined seed finds the point.
template <class T>
bool cones_separated(const Cone<T>& a, const Cone<T>& b) {
  constexpr T pi = std::numbers::pi_v<T>;
  const T phi = std::atan2(cross(a.ref, b.ref), dot(a.ref, b.ref));
  // Angles of b's directions minus a's, and their range; no multiple of pi inside it.
  const T lo = b.lo + phi - a.hi, hi = b.hi + phi - a.lo;
  const T margin = T(1e-6);
  const T k = std::ceil((lo - margin) / pi);
  return k * pi > hi + margin;
}

/// Whether the control points of b all lie outside the fat line of a (the band along a's
/// chord holding a's control points, widened by slack) on one side: then the parts are
/// apart [SederbergNishita90]. Unlike control boxes, fat lines follow the parts' direction,
/// so two curves running side by side at a distance d (near-coincident curves) are told
/// apart once their parts bend by less than d, not only once the parts are shorter than d:
/// a few hundred parts instead of millions. Rational parts too (their points lie in the
/// convex hull of their control points, the weights being positive).
template <class CA, class CB>
bool fat_line_apart(const CA& a, const CB& b, typename CA::Scalar slack) {
  using T = typename CA::Scalar;
  const auto& P = a.points();
  const Vector<T, 2> chord = P.back() - P.front();
  const T len = norm(chord);
  if (!(len > 0)) return false;
  const Vector<T, 2> n{-chord[1] / len, chord[0] / len};
  T dmin = 0, dmax = 0;
  for (const auto& p : P) {
    const T d = dot(p - P.front(), n);
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
  }
  bool above = true, below = true;
  for (const auto& q : b.points()) {
    const T d = dot(q - P.front(), n);
    above = above && d > dmax + slack;
    below = below && d < dmin - slack;
    if (!above && !below) return false;
  }
  return true;
}

/// Bounding-box subdivision of two arcs (Bezier or RationalBezier parts a on [alo, ahi],
/// b on [blo, bhi] of their pieces' parameters) down to parts flat within ctx.flat; each
/// pair of flat parts whose chords come within 2 flat + slack gives a seed (the chords'
/// closest points), later refined on the curves themselves.
template <class T, class CA, class CB>
void subdivide(const CA& a, T alo, T ahi, int da, const CB& b, T blo, T bhi, int db, Context<T>& ctx, bool bands = true) {
  if (ctx.exhausted || (ctx.near && ctx.stop_on_near)) return;
  if (++ctx.nodes > ctx.node_limit) {
    ctx.exhausted = true;
    return;
  }
  const Box<T, 2> ba = a.control_bounds(), bb = b.control_bounds();
  if (!boxes_meet(ba, bb, ctx.slack)) return;
  if (fat_line_apart(a, b, ctx.slack) || fat_line_apart(b, a, ctx.slack)) return;
  const bool fa = da >= max_depth || is_flat(a, ctx.flat), fb = db >= max_depth || is_flat(b, ctx.flat);
  if (fa && fb) {
    const auto& P = a.points();
    const auto& Q = b.points();
    const auto c = chord_closest(P.front(), P.back(), Q.front(), Q.back());
    if (c.distance <= 2 * ctx.flat + ctx.slack) ctx.seeds.push_back({alo + c.u * (ahi - alo), blo + c.v * (bhi - blo)});
    return;
  }
  // Parts whose tangent cones are separated meet at most once: one seed, at the closest
  // points of their chords, which the refinement takes to the crossing or, where the
  // parts do not meet, to their closest approach (then discarded as a near miss). The
  // seed is refined here: where the refinement does not reach a common point, the parts
  // are split further as any others (the crossing, if any, is then seeded from a smaller
  // part). Newton cannot leave a seed at a stationary end of a part, where the velocity
  // is zero (an offset's cusp ends its cubic with a zero handle): from there a crossing
  // elsewhere in the part was lost. A seed that refines to a common point of these two
  // parts (not of other parts of the arcs, whose own crossing this pair would then miss)
  // is kept at its refined point.
  if (const auto ka = tangent_cone(a)) {
    if (const auto kb = tangent_cone(b); kb && cones_separated(*ka, *kb)) {
      const auto& P = a.points();
      const auto& Q = b.points();
      const auto c = chord_closest(P.front(), P.back(), Q.front(), Q.back());
      const T s = alo + c.u * (ahi - alo), t = blo + c.v * (bhi - blo);
      if (!ctx.fa || !ctx.fb) {
        ctx.seeds.push_back({s, t});
        return;
      }
      const Refined<T> r = refine(*ctx.fa, *ctx.ra, *ctx.fb, *ctx.rb, s, t);
      const T ma = T(1e-6) * (ahi - alo), mb = T(1e-6) * (bhi - blo);
      if (r.distance <= ctx.tol && r.s >= alo - ma && r.s <= ahi + ma && r.t >= blo - mb && r.t <= bhi + mb) {
        ctx.seeds.push_back({r.s, r.t});
        return;
      }
    }
  }
  // Near-coincident parts (narrow tangent cones along one direction): decided at once on
  // the separation polynomial instead of subdivided down to the near-miss distance.
  bool split_longer = false;
  if (bands) {
    const BandResult r = band(a, alo, ahi, b, blo, bhi, ctx);
    if (r == BandResult::done) return;
    bands = r != BandResult::too_far;
    // A part much longer than the other (a line against a short stretch of a curve near
    // a touch) stretches the other's core out of the cone: the longer one is split, flat
    // or not, until bands apply (else two crossings in one pair of flat parts would give
    // one seed, and one of them would be missed).
    split_longer = r == BandResult::too_long;
  }
  const bool split_a = split_longer ? da < max_depth && (diagonal(ba) >= diagonal(bb) || db >= max_depth)
                                    : !fa && (fb || diagonal(ba) >= diagonal(bb));
  if (split_a) {
    const auto h = a.split(T(0.5));
    const T m = alo + (ahi - alo) / 2;
    subdivide(h.left, alo, m, da + 1, b, blo, bhi, db, ctx, bands);
    subdivide(h.right, m, ahi, da + 1, b, blo, bhi, db, ctx, bands);
  } else {
    const auto h = b.split(T(0.5));
    const T m = blo + (bhi - blo) / 2;
    subdivide(a, alo, ahi, da, h.left, blo, m, db + 1, ctx, bands);
    subdivide(a, alo, ahi, da, h.right, m, bhi, db + 1, ctx, bands);
  }
}

/// Subdivision steps of the first pass over a pair of arcs, before the overlap test: a
/// few hundred suffice for transversal arcs; coinciding arcs take many more.
inline constexpr std::size_t lazy_nodes = 2000;

/// The common points of two arcs (subdivision, then refinement of each seed) appended to
/// hits. Returns false when the arcs may overlap: the node limit was reached (the seeds
/// are then incomplete), a point has parallel tangents (every point of an overlap does)
/// or a band lies within tol all along (with ctx.stop_on_near the pass stops there, and
/// its points are incomplete too).
template <class T>
bool intersect_arcs(const Prepared<T>& A, std::size_t ia, const Prepared<T>& B, std::size_t ib, Context<T>& ctx,
                    std::size_t node_limit, std::vector<Hit<T>>& hits) {
  const Arc<T>& ra = A.arcs[ia];
  const Arc<T>& rb = B.arcs[ib];
  const Piece<T>& a = A.unit[ra.piece];
  const Piece<T>& b = B.unit[rb.piece];
  ctx.seeds.clear();
  ctx.nodes = 0;
  ctx.node_limit = node_limit;
  ctx.exhausted = false;
  const FootEval<T> fa(a), fb(b);
  ctx.a = &a;
  ctx.b = &b;
  ctx.fa = &fa;
  ctx.fb = &fb;
  ctx.ra = &ra;
  ctx.rb = &rb;
  ctx.near = false;
  std::visit(
      [&](const auto& x, const auto& y) { subdivide(x, ra.lo, ra.hi, 0, y, rb.lo, rb.hi, 0, ctx); }, A.arc_parts[ia],
      B.arc_parts[ib]);
  ctx.fa = ctx.fb = nullptr;  // they end with this call
  if (ctx.exhausted || (ctx.near && ctx.stop_on_near)) return false;
  bool clean = true;
  // Refined points so far, by s: seeds from neighbouring parts refine to the same point
  // (thousands of them along near-coincident curves), found again in O(log) each.
  std::multimap<T, T> done;
  for (const auto& [s0, t0, edge] : ctx.seeds) {
    Refined<T> r = refine(fa, ra, fb, rb, s0, t0);
    if (!(r.distance <= ctx.tol)) continue;
    // A touch refined as a double root is located to about sqrt(eps / curvature) only,
    // where the tangents of a curve of high curvature (a Chebyshev polynomial of degree
    // 12 touching y = 1: curvature about 1e4 per unit parameter) already differ by more
    // than 1e-6: the polish (parallel tangents, a common point within 1e-5 in the
    // parameters) is tried up to 1e-4, and where it finds the touch the point is there.
    const T angle = std::abs(cross(direction(fa, r.s), direction(fb, r.t)));
    if (angle <= T(1e-6)) clean = false;
    if (angle <= T(1e-4)) {
      if (auto p = polish_touch(fa, ra, fb, rb, r, ctx.tol)) r = *p;
    }
    bool dup = false;
    for (auto it = done.lower_bound(r.s - T(1e-12)); !dup && it != done.end() && it->first <= r.s + T(1e-12); ++it)
      dup = std::abs(it->second - r.t) <= T(1e-12);
    if (dup) continue;
    done.emplace(r.s, r.t);
    hits.push_back({A.curve->lift(ra.piece, r.s), B.curve->lift(rb.piece, r.t), ra.piece, rb.piece, r.s,
                    r.t, r.distance, false, edge});
  }
  // Arc ends common to both arcs (within tol) where the arcs are tangent: a touch at the
  // end, where the curves part slowly (a conic leaving its control polygon's leg as t^2 /
  // W). A seed near it may refine to a point of the near region beyond the distance (the
  // leg first: 1.1e-10 from the conic [1, 1e3, 1] near its end (0, 1)) and lose the touch.
  // The arcs' ends are their parts' end control points (no evaluation: the general
  // engine's cost per pair of arcs stays).
  const auto& Pa = points(A.arc_parts[ia]);
  const auto& Pb = points(B.arc_parts[ib]);
  for (const bool ea : {false, true}) {
    for (const bool eb : {false, true}) {
      const Vector<T, 2> v = (ea ? Pa.back() : Pa.front()) - (eb ? Pb.back() : Pb.front());
      if (!(dot(v, v) <= ctx.tol * ctx.tol)) continue;
      const T d = norm(v);
      const T s = ea ? ra.hi : ra.lo, t = eb ? rb.hi : rb.lo;
      if (!(std::abs(cross(direction(fa, s), direction(fb, t))) <= T(1e-6))) continue;
      clean = false;
      bool dup = false;
      for (auto it = done.lower_bound(s - T(1e-12)); !dup && it != done.end() && it->first <= s + T(1e-12); ++it)
        dup = std::abs(it->second - t) <= T(1e-12);
      if (dup) continue;
      done.emplace(s, t);
      hits.push_back({A.curve->lift(ra.piece, s), B.curve->lift(rb.piece, t), ra.piece, rb.piece, s, t, d, false, false});
    }
  }
  return clean && !ctx.near;
}

/// All the common points of arc i of A and arc j of B (the engine's full pass: lazy_nodes
/// subdivision steps, then max_nodes). Throws NumericalError past max_nodes.
template <class T>
std::vector<Hit<T>> arc_points(const Prepared<T>& A, std::size_t i, const Prepared<T>& B, std::size_t j, Context<T>& ctx) {
  std::vector<Hit<T>> found;
  intersect_arcs(A, i, B, j, ctx, lazy_nodes, found);
  if (ctx.exhausted) {
    found.clear();
    intersect_arcs(A, i, B, j, ctx, max_nodes, found);
    if (ctx.exhausted) {
      throw NumericalError("intersect: more than " + std::to_string(max_nodes) +
                           " subdivision steps for one pair of arcs: the curves run within 1e-10 of their size of each "
                           "other without coinciding");
    }
  }
  return found;
}

}  // namespace casteljau::detail::isect
