// Intersection engine, phase 2 (algo/intersect.hpp): the candidate pairs of arcs whose
// boxes meet, each decided as points (subdivision) or an overlap.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "casteljau/algo/intersect/overlap.hpp"

namespace casteljau::detail::isect {

/// What the pairs of arcs give: points, and overlaps arc by arc (in the order of the pairs).
template <class T>
struct ArcPairs {
  std::vector<Hit<T>> hits;
  std::vector<RawOverlap<T>> overlaps;
};

/// Phase 2: every pair of arcs (i of A, j of B; j > i when self, B being A) whose control
/// boxes meet within ctx.slack. Identical arcs give an overlap over the whole arc at once.
/// Otherwise a first pass stops at the first band along which the arcs stay within tol;
/// where that pass is not clean (a tangent point, the subdivision running long, a near
/// band) the overlap test (arc_overlap) runs, and an overlap keeps the pair's points (or
/// the pair, deferred); else the pair's points (arc_points where the pass stopped early).
/// Throws InvalidArgument past 2 max_points raw points.
template <class T>
ArcPairs<T> meet_arcs(const Prepared<T>& A, const Prepared<T>& B, bool self, Context<T>& ctx, bool tame = false) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  ArcPairs<T> out;
  // Two identical curves (the same pieces on the same domains, arc for arc): each arc is
  // an overlap with itself (below), and these join into one overlap over both domains,
  // inside which every common point lies. So the other pairs (i, j) need only the overlap
  // test, for a curve that runs over itself; their points are deferred to arc i's own
  // overlap (computed only if that is rejected). Subdividing them as any pair took most
  // of the time of a degree-500 curve and its copy (pairs of consecutive arcs touch at
  // their common end: the overlap test ran, then the points were found and dropped).
  const bool same = !self && !tame && A.arcs.size() == B.arcs.size() && ca.size() == cb.size() && [&] {
    for (std::size_t p = 0; p < ca.size(); ++p)
      if (!(ca.segment_domain(p) == cb.segment_domain(p)) || !(ca.own_domain(p) == cb.own_domain(p))) return false;
    for (std::size_t k = 0; k < A.arcs.size(); ++k)
      if (A.arcs[k].piece != B.arcs[k].piece || !(A.arc_parts[k] == B.arc_parts[k])) return false;
    return true;
  }();
  std::vector<std::size_t> own(same ? A.arcs.size() : 0);  // arc i's own overlap in out.overlaps
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> later(own.size());
  for (std::size_t i = 0; i < A.arcs.size(); ++i) {
    for (std::size_t j = self ? i + 1 : 0; j < B.arcs.size(); ++j) {
      const Arc<T>& ra = A.arcs[i];
      const Arc<T>& rb = B.arcs[j];
      if (!boxes_meet(A.arc_boxes[i], B.arc_boxes[j], ctx.slack)) continue;
      // The same arc on both sides (identical curves, or a curve that repeats a piece):
      // an overlap over the whole arc, without subdividing two coincident arcs down to
      // the near-miss distance all along (20 s for a degree-500 curve and its copy).
      if (A.arc_parts[i] == B.arc_parts[j]) {
        if (same && i == j) own[i] = out.overlaps.size();
        out.overlaps.push_back(
            RawOverlap<T>{{ca.lift(ra.piece, Interval<T>(ra.lo, ra.hi)), cb.lift(rb.piece, rb.lo), cb.lift(rb.piece, rb.hi)}, {}, {}});
        continue;
      }
      if (same) {
        if (auto o = arc_overlap(A, i, B, j, ctx.tol)) {
          out.overlaps.push_back(
              RawOverlap<T>{{ca.lift(ra.piece, Interval<T>(o->s0, o->s1)), cb.lift(rb.piece, o->t0), cb.lift(rb.piece, o->t1)}, {}, {{i, j}}});
        } else {
          later[i].emplace_back(i, j);
        }
        continue;
      }
      // The overlap test (a few root solves) only where the arcs may overlap: a tangent
      // point found, or the subdivision running long.
      // The first pass stops at the first band along which the arcs stay within tol (an
      // overlap is then likely; its points are computed only if the overlap test fails or
      // the overlap is later rejected).
      std::vector<Hit<T>> found;
      ctx.stop_on_near = true;
      const bool clean = intersect_arcs(A, i, B, j, ctx, lazy_nodes, found);
      ctx.stop_on_near = false;
      if (!clean) {
        const bool stopped = ctx.near && !ctx.exhausted;
        if (auto o = arc_overlap(A, i, B, j, ctx.tol)) {
          RawOverlap<T> raw{{ca.lift(ra.piece, Interval<T>(o->s0, o->s1)), cb.lift(rb.piece, o->t0), cb.lift(rb.piece, o->t1)}, {}, {}};
          if (stopped) {
            raw.deferred.emplace_back(i, j);
          } else {
            raw.found = std::move(found);
          }
          out.overlaps.push_back(std::move(raw));
          continue;
        }
        if (stopped || ctx.exhausted) found = arc_points(A, i, B, j, ctx);
      }
      out.hits.insert(out.hits.end(), found.begin(), found.end());
      if (out.hits.size() > 2 * max_points) too_many_points(out.hits.size());
    }
  }
  for (std::size_t i = 0; i < later.size(); ++i)
    for (const auto& p : later[i]) out.overlaps[own[i]].deferred.push_back(p);
  return out;
}

}  // namespace casteljau::detail::isect
