// Intersection engine, the driver (algo/intersect.hpp): solve() runs the phases in turn;
// solve_extreme() takes curves with extreme weights through their tame parts; the fast
// paths for polynomial pieces of degree 1 to 3.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/low_degree.hpp"
#include "casteljau/algo/intersect/merge.hpp"
#include "casteljau/algo/intersect/pairs.hpp"
#include "casteljau/algo/intersect/tame.hpp"

namespace casteljau::detail::isect {

/// The common points and overlaps of curves a and b (b = nullptr: the self-intersections
/// of a): the phases above in turn (see intersect()). `tame` (not null): the curves are
/// tame parts (solve_extreme), overlaps end at arc ends of the curves before taming
/// (confirm_overlaps), and the points of one near region seen from several parts are
/// merged (merge_regions); else touches of one near region are (absorb_touches).
template <class T>
Intersections<T> solve(const Pieces<T, 2>& ca, const Pieces<T, 2>* cb, const TameJoints<T>* tame = nullptr) {
  const bool self = cb == nullptr;
  if (self) cb = &ca;
  const SharedFrame<T> frame = shared_frame(ca, *cb);
  const Prepared<T> A = prepare(ca, frame.origin, frame.e);
  const Prepared<T> B = self ? Prepared<T>{} : prepare(*cb, frame.origin, frame.e);
  const Prepared<T>& PB = self ? A : B;
  const T tol = near_miss(A, PB);
  Context<T> ctx = make_context(tol);
  ArcPairs<T> pairs = meet_arcs(A, PB, self, ctx, tame != nullptr);
  std::vector<RawOverlap<T>> candidates = join_overlaps(std::move(pairs.overlaps), ca.domain().length(), cb->domain().length());
  if (tame) bridge_overlaps(A, PB, candidates, tol);
  std::vector<CurveOverlap<T>> overlaps =
      join_confirmed(confirm_overlaps(A, PB, candidates, ctx, pairs.hits, tame), ca.domain().length(), cb->domain().length());
  const Loops<T> lp = loops(A, PB, tol);
  MergedPoints<T> merged = merge_points(A, PB, self, std::move(pairs.hits), overlaps, lp, tol);
  admit_edges(A, PB, lp, merged.kept, std::move(merged.edges), tol);
  Intersections<T> out;
  out.points = classify(A, PB, merged.kept, tol);
  if (self && lp.a.closed) out.points = once_at_closing_point(ca, out.points);
  out.points = tame ? merge_regions(A, PB, lp, out.points, tol) : absorb_touches(A, PB, lp, out.points, tol);
  out.overlaps = std::move(overlaps);
  if (out.points.size() + out.overlaps.size() > max_points) too_many_points(out.points.size() + out.overlaps.size());
  return out;
}

/// solve() for curves that may have pieces with extreme weights (has_extreme_weights):
/// such curves are taken through their tame parts (tame(), runs below 1e-3 of the
/// near-miss distance as chords), solved with merge_regions, and the answer mapped back to
/// the curves' own parameters. Parameters so mapped are rounded to the doubles of the
/// domain, which may not resolve a part (a crossing of the leg that the weights 1, 1e30, 1
/// pass within 1e-30 of t = 1 is at t = 1); the points are the parts' own, so they are
/// where the curves meet, not the curve at the rounded parameter. Other curves: solve().
template <class T>
Intersections<T> solve_extreme(const Pieces<T, 2>& ca, const Pieces<T, 2>* cb) {
  const bool self = cb == nullptr;
  if (!has_extreme_weights(ca) && (self || !has_extreme_weights(*cb))) return solve(ca, cb);
  T size = 0;
  for (const auto* c : {&ca, cb}) {
    if (!c) continue;
    Box<T, 2> box = Box<T, 2>::empty_box();
    for (const auto& s : c->segments()) box.add(std::visit([](const auto& x) { return x.control_bounds(); }, s));
    size = std::max(size, diagonal(box));
  }
  const T run = T(1e-13) * size;
  const Tamed<T> ta = tame(ca, run);
  const std::optional<Tamed<T>> tb = self ? std::nullopt : std::optional<Tamed<T>>(tame(*cb, run));
  const TameJoints<T> joints{ta.joints(), self ? ta.joints() : tb->joints()};
  Intersections<T> r = solve(ta.curve, self ? nullptr : &tb->curve, &joints);
  const Tamed<T>& mb = self ? ta : *tb;
  const Pieces<T, 2>& ob = self ? ca : *cb;
  if (!self) {
    for (auto& x : r.points) {
      // A crossing on a chord of one curve, the other taken as it is there: onto the run.
      const TamePart<T>& pa = ta.parts[ta.curve.locate(x.ta).index];
      const TamePart<T>& pb = mb.parts[mb.curve.locate(x.tb).index];
      if (x.kind != IntersectionKind::crossing || pa.chord == pb.chord) continue;
      if (pa.chord) {
        onto_run(pa, mb.curve, x.tb, x.point);
      } else {
        T t = x.ta;
        Point<T, 2> p = x.point;
        onto_run(pb, ta.curve, t, p);
        x.ta = t;
        x.point = p;
      }
    }
  }
  for (auto& x : r.points) {
    x.ta = ta.original(ca, x.ta);
    x.tb = mb.original(ob, x.tb);
  }
  for (auto& o : r.overlaps) {
    o.a = Interval<T>(ta.original(ca, o.a.lo), ta.original(ca, o.a.hi));
    o.b_start = mb.original(ob, o.b_start);
    o.b_end = mb.original(ob, o.b_end);
  }
  return r;
}

/// The stretches where a curve stands still: runs of consecutive constant pieces (every
/// control point the same: a degree-0 B-spline's steps, a point segment) at one point, as
/// [first parameter, last parameter] (the last by Pieces::end_parameter: the double below
/// a break where the curve jumps off the point) and the point.
template <class T>
std::vector<std::pair<Interval<T>, Point<T, 2>>> resting_runs(const Pieces<T, 2>& c) {
  std::vector<std::pair<Interval<T>, Point<T, 2>>> out;
  std::size_t last = 0;  // the piece that ended the last run
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto& P = std::visit([](const auto& s) -> const std::vector<Point<T, 2>>& { return s.points(); }, c.segments()[i]);
    if (!std::all_of(P.begin(), P.end(), [&](const Point<T, 2>& q) { return q == P.front(); })) continue;
    if (!out.empty() && last + 1 == i && out.back().second == P.front()) {
      out.back().first.hi = c.end_parameter(i);
    } else {
      out.push_back({Interval<T>(c.segment_domain(i).lo, c.end_parameter(i)), P.front()});
    }
    last = i;
  }
  return out;
}

/// One contact per stretch where a curve stands still (resting_runs): the engine sees such
/// a stretch at its ends, and any of its parameters is the same point. Each point whose ta
/// (or tb) lies in a run of a (of b) is moved to the run's first parameter, with the run's
/// point; then points that agree in both parameters (within 1e-9 of the domains) are one,
/// the first kept. For self-intersections (cb = nullptr) both parameters are a's, and a
/// pair whose two parameters fall in one run is the curve resting, not meeting itself.
template <class T>
void once_per_rest(const Pieces<T, 2>& ca, const Pieces<T, 2>* cb, Intersections<T>& r) {
  const bool self = cb == nullptr;
  const auto ra = resting_runs(ca);
  const auto rb_own = self ? decltype(ra){} : resting_runs(*cb);
  const auto& rb = self ? ra : rb_own;
  if (ra.empty() && rb.empty()) return;
  const auto snap = [](const std::vector<std::pair<Interval<T>, Point<T, 2>>>& runs, T& t, Point<T, 2>& at) {
    for (const auto& [iv, q] : runs) {
      if (t >= iv.lo && t <= iv.hi) {
        t = iv.lo;
        at = q;
        return true;
      }
    }
    return false;
  };
  std::vector<CurveIntersection<T>> out;
  const T ma = T(1e-9) * ca.domain().length(), mb = T(1e-9) * (self ? ca : *cb).domain().length();
  bool moved = false;
  for (auto x : r.points) {
    const bool sa = snap(ra, x.ta, x.point), sb = snap(rb, x.tb, x.point);
    moved = moved || sa || sb;
    if (self && x.tb <= x.ta) continue;  // both in one run
    const bool seen = std::any_of(out.begin(), out.end(), [&](const CurveIntersection<T>& y) {
      return std::abs(y.ta - x.ta) <= ma && std::abs(y.tb - x.tb) <= mb;
    });
    if (!seen) out.push_back(x);
  }
  if (!moved) return;
  std::stable_sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
  r.points = std::move(out);
}

/// The fast path (algo/intersect/low_degree.hpp) for two polynomial Bézier curves of
/// degree 1 to 3; nothing when it does not apply or refuses. Its points are the general
/// engine's answer: isolated crossings, reported with the pieces' own values at their
/// parameters.
template <class T>
std::optional<Intersections<T>> low_degree(const Bezier<T, 2>& a, const Bezier<T, 2>& b) {
  const auto r = isect_fast::intersect_low_degree<T>(a.points(), b.points());
  if (!r) return std::nullopt;
  Intersections<T> out;
  out.points.reserve(static_cast<std::size_t>(r->count));
  for (int i = 0; i < r->count; ++i) {
    const auto [s, t] = r->st[static_cast<std::size_t>(i)];
    // A Bézier curve's own parameter is the curve's (one piece on its own domain [0, 1]).
    out.points.push_back({s, t, a(s), IntersectionKind::crossing});
  }
  return out;
}

/// The fast path for two curves whose pieces are all polynomial of degree 1 to 3: every
/// pair of pieces in one shared frame (the general engine's). Nothing when a piece does
/// not qualify, a pair is refused, a point lies within 1e-9 of a joint of pieces (the
/// general engine merges what both pieces see there), or two points of different pairs
/// are closer than 1e-3 of their pieces in both parameters (see Limits::near_pair).
template <class T>
std::optional<Intersections<T>> low_degree_pieces(const Pieces<T, 2>& pa, const Pieces<T, 2>& pb) {
  using Span = std::span<const Point<T, 2>>;
  std::vector<Span> sa, sb;
  auto collect = [](const Pieces<T, 2>& p, std::vector<Span>& out) {
    out.reserve(p.size());
    for (const auto& seg : p.segments()) {
      const auto* z = std::get_if<Bezier<T, 2>>(&seg);
      if (!z || z->degree() < 1 || z->degree() > isect_fast::max_degree) return false;
      out.emplace_back(z->points());
    }
    return true;
  };
  if (!collect(pa, sa) || !collect(pb, sb)) return std::nullopt;
  const auto frame = isect_fast::unit_frame<T>(sa, sb);
  if (!frame) return std::nullopt;
  // Control boxes of the pieces, so that pairs far apart cost one box test (as the general
  // engine's arcs): within twice the near-miss distance (in model units) they go on.
  auto boxes = [](const std::vector<Span>& pieces_points) {
    std::vector<Box<T, 2>> out;
    out.reserve(pieces_points.size());
    for (const auto& P : pieces_points) {
      Box<T, 2> b = Box<T, 2>::empty_box();
      for (const auto& q : P) b.add(q);
      out.push_back(b);
    }
    return out;
  };
  const std::vector<Box<T, 2>> ba = boxes(sa), bb = boxes(sb);
  const T slack = 2 * frame->tol / frame->scale;
  // b's pieces in runs of 16 consecutive ones with the box of the run: consecutive pieces
  // are neighbours in the plane, so a piece of a far from a run costs one test for all 16.
  constexpr std::size_t run = 16;
  std::vector<Box<T, 2>> runs((sb.size() + run - 1) / run, Box<T, 2>::empty_box());
  for (std::size_t j = 0; j < sb.size(); ++j) runs[j / run].add(bb[j]);
  constexpr T joint = T(1e-9);
  struct Found {
    T ta, tb, s;
    std::size_t i, j;
  };
  std::vector<Found> found;
  for (std::size_t i = 0; i < sa.size(); ++i) {
    for (std::size_t j = 0; j < sb.size(); ++j) {
      if (j % run == 0 && !boxes_meet(ba[i], runs[j / run], slack)) {
        j += run - 1;
        continue;
      }
      if (!boxes_meet(ba[i], bb[j], slack)) continue;
      const auto r = isect_fast::intersect_in_frame<T>(sa[i], sb[j], *frame);
      if (!r) return std::nullopt;
      for (int k = 0; k < r->count; ++k) {
        const auto [s, t] = r->st[static_cast<std::size_t>(k)];
        if ((i > 0 && s < joint) || (i + 1 < sa.size() && s > 1 - joint) || (j > 0 && t < joint) || (j + 1 < sb.size() && t > 1 - joint))
          return std::nullopt;
        found.push_back({pa.lift(i, s), pb.lift(j, t), s, i, j});
        if (found.size() > max_points) too_many_points(found.size());
      }
    }
  }
  std::sort(found.begin(), found.end(), [](const Found& x, const Found& y) { return x.ta < y.ta; });
  const T near = isect_fast::Limits<T>::near_pair;
  T longest = 0;  // the longest piece of a: no pair farther apart than near * longest in ta is near
  for (std::size_t i = 0; i < pa.size(); ++i) longest = std::max(longest, pa.segment_domain(i).length());
  for (std::size_t k = 0; k < found.size(); ++k) {
    for (std::size_t l = k + 1; l < found.size() && found[l].ta - found[k].ta < near * longest; ++l) {
      const Found &x = found[k], &y = found[l];
      const T la = std::max(pa.segment_domain(x.i).length(), pa.segment_domain(y.i).length());
      const T lb = std::max(pb.segment_domain(x.j).length(), pb.segment_domain(y.j).length());
      if (y.ta - x.ta < near * la && std::abs(y.tb - x.tb) < near * lb) return std::nullopt;
    }
  }
  Intersections<T> out;
  out.points.reserve(found.size());
  for (const auto& h : found) out.points.push_back({h.ta, h.tb, std::get<Bezier<T, 2>>(pa.segments()[h.i])(h.s), IntersectionKind::crossing});
  return out;
}

}  // namespace casteljau::detail::isect
