// Intersection engine, phases 3 and 4 (algo/intersect.hpp): overlap detection on a pair
// of arcs (Bezout's bound), the overlaps joined across arcs and pieces, confirmed where
// the curves part at their ends, and whether a point lies inside one.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "casteljau/algo/intersect/near.hpp"
#include "casteljau/algo/intersect/subdivide.hpp"
#include "casteljau/algo/intersect/tame.hpp"

namespace casteljau::detail::isect {

/// Overlap of arcs ra (of piece a) and rb (of piece b), as piece parameters: a on
/// [s0, s1] traces b from t0 to t1.
template <class T>
struct ArcOverlap {
  T s0, s1, t0, t1;
};

/// Whether arcs ia of A and ib of B coincide on an interval. Its ends are arc ends (see
/// Arc), so the candidates are the ends of each arc located on the other; the two extreme
/// ones bound the interval, which is then confirmed at m n + 1 interior points (m, n the
/// degrees, at least 3, at most 64): two distinct algebraic curves of degrees m and n
/// share at most m n points (Bézout), so curves that share more are the same curve there.
/// An interior point a(s) is first tried at b's parameter in the same proportion between
/// t0 and t1 (where a coinciding copy, re-parametrised by an affine map, has it), then by
/// Newton steps from there; located from scratch (locate) only where these miss it.
template <class T>
std::optional<ArcOverlap<T>> arc_overlap(const Prepared<T>& A, std::size_t ia, const Prepared<T>& B, std::size_t ib, T tol) {
  const Arc<T>& ra = A.arcs[ia];
  const Arc<T>& rb = B.arcs[ib];
  const Piece<T>& pa = A.unit[ra.piece];
  const Piece<T>& pb = B.unit[rb.piece];
  const FootEval<T> a(pa), b(pb);
  auto on_b = [&](const Point<T, 2>& q) { return locate(b, B.arc_parts[ib], B.arc_boxes[ib], rb, q, tol); };
  auto on_a = [&](const Point<T, 2>& q) { return locate(a, A.arc_parts[ia], A.arc_boxes[ia], ra, q, tol); };
  std::vector<std::pair<T, T>> ends;  // (s, t)
  for (T s : {ra.lo, ra.hi})
    if (auto t = on_b(a.at(s))) ends.emplace_back(s, *t);
  for (T t : {rb.lo, rb.hi})
    if (auto s = on_a(b.at(t))) ends.emplace_back(*s, t);
  if (ends.size() < 2) return std::nullopt;
  std::sort(ends.begin(), ends.end());
  const auto [s0, t0] = ends.front();
  const auto [s1, t1] = ends.back();
  if (!(s1 - s0 > T(1e-9) * (ra.hi - ra.lo)) || !(std::abs(t1 - t0) > T(1e-9) * (rb.hi - rb.lo))) return std::nullopt;
  const int k = std::clamp(degree(pa) * degree(pb) + 1, 3, 64);
  const T tlo = std::min(t0, t1), thi = std::max(t0, t1), tm = T(1e-9) * (rb.hi - rb.lo);
  for (int j = 1; j <= k; ++j) {
    const T f = static_cast<T>(j) / static_cast<T>(k + 1);
    const T s = s0 + (s1 - s0) * f;
    const Point<T, 2> q = a.at(s);
    T guess = std::clamp(t0 + (t1 - t0) * f, tlo, thi);
    if (distance(b.at(guess), q) <= tol) continue;
    guess = polish_foot(b, rb, q, guess);
    if (guess >= tlo - tm && guess <= thi + tm && distance(b.at(guess), q) <= tol) continue;
    const auto t = on_b(q);
    if (!t || *t < tlo - tm || *t > thi + tm) return std::nullopt;
  }
  return ArcOverlap<T>{s0, s1, t0, t1};
}

/// An overlap found on one pair of arcs, in the curves' parameters, with the points that
/// pair gave (reported if the overlap turns out to lie inside a crossing or touch region:
/// confirm_overlaps) or, when the pair's first pass stopped early, the pair itself
/// (`deferred`), whose points are computed only if the overlap is rejected.
template <class T>
struct RawOverlap {
  CurveOverlap<T> o;
  std::vector<Hit<T>> found;
  std::vector<std::pair<std::size_t, std::size_t>> deferred;
  // The overlaps joined into this one (a.lo, a.hi, b_start, b_end); filled by join_overlaps.
  std::vector<std::array<T, 4>> parts = {};
};

/// p extended by r, which continues it: p's end becomes r's, r's points join p's.
template <class T>
void absorb(RawOverlap<T>& p, RawOverlap<T>& r) {
  p.o.a.hi = r.o.a.hi;
  p.o.b_end = r.o.b_end;
  p.found.insert(p.found.end(), r.found.begin(), r.found.end());
  p.deferred.insert(p.deferred.end(), r.deferred.begin(), r.deferred.end());
  p.parts.insert(p.parts.end(), r.parts.begin(), r.parts.end());
}

/// Phase 3: the overlaps found arc by arc, sorted by their start on a, joined where one
/// continues the previous (its start within 1e-9 of la (a's domain length) of the
/// previous end on a, within 1e-9 lb on b, b running the same way); the points and
/// deferred pairs of joined ones go together; a sliver inside p or at its end (see inside,
/// at_end) goes into p. Stable for equal starts.
template <class T>
std::vector<RawOverlap<T>> join_overlaps(std::vector<RawOverlap<T>> overlaps, T la, T lb) {
  std::sort(overlaps.begin(), overlaps.end(), [](const auto& x, const auto& y) { return x.o.a.lo < y.o.a.lo; });
  const T ma = T(1e-9) * la, mb = T(1e-9) * lb;
  // Whether r lies inside p and runs as p does there: its a within p's, its b within the b
  // of a part of p whose a meets r's (a sliver that two consecutive arcs of a copy moved
  // along its tangent share with the wrong neighbour, 1e-10 long, inside the stretch that
  // the neighbours' own overlaps cover: it broke their join, and the copy was answered as
  // points). A stretch that a curve runs over twice is no such part: its b lies elsewhere.
  auto inside = [&](const RawOverlap<T>& p, const RawOverlap<T>& r) {
    const auto& o = r.o;
    if ((o.b_end > o.b_start) != (p.o.b_end > p.o.b_start)) return false;
    if (o.a.lo < p.o.a.lo - ma || o.a.hi > p.o.a.hi + ma) return false;
    const T blo = std::min(o.b_start, o.b_end), bhi = std::max(o.b_start, o.b_end);
    for (const auto& c : p.parts) {
      if (c[0] > o.a.hi + ma || c[1] < o.a.lo - ma) continue;
      if (std::min(c[2], c[3]) <= blo + mb && std::max(c[2], c[3]) >= bhi - mb) return true;
    }
    return false;
  };
  // Whether r is a sliver at p's end: both its ends within 1e-7 of the domain lengths of
  // p's end, on a and on b (the margin of in_overlap, which takes a point there as p's),
  // b running the same way. Near a point where a curve's tangent is parallel to the
  // shift of a copy (an arc end), the copy's neighbouring arc is within the distance over
  // a stretch of a few 1e-9 with a lag: a degree-20 curve and its copy moved by 1e-9
  // along x (seed 7) gave a [0.825854426539, 0.825854428194] against b from
  // 0.825854424884 to 0.825854426539 there, between the overlaps of arcs 8 and 9,
  // which it kept apart; the middle stretch was then rejected as part of a longer near
  // region and answered as points.
  const T sa = T(1e-7) * la, sb = T(1e-7) * lb;
  auto at_end = [&](const RawOverlap<T>& p, const RawOverlap<T>& r) {
    const auto& o = r.o;
    if ((o.b_end > o.b_start) != (p.o.b_end > p.o.b_start)) return false;
    return std::abs(o.a.lo - p.o.a.hi) <= sa && std::abs(o.a.hi - p.o.a.hi) <= sa && std::abs(o.b_start - p.o.b_end) <= sb &&
           std::abs(o.b_end - p.o.b_end) <= sb;
  };
  std::vector<RawOverlap<T>> joined;
  for (auto& r : overlaps) {
    const auto& o = r.o;
    if (r.parts.empty()) r.parts.push_back({o.a.lo, o.a.hi, o.b_start, o.b_end});
    if (!joined.empty()) {
      auto& p = joined.back();
      if (std::abs(o.a.lo - p.o.a.hi) <= ma && std::abs(o.b_start - p.o.b_end) <= mb &&
          ((o.b_end > o.b_start) == (p.o.b_end > p.o.b_start))) {
        absorb(p, r);
        continue;
      }
      if (inside(p, r) || at_end(p, r)) {  // its points and pairs join p's; p's ends stay
        p.found.insert(p.found.end(), r.found.begin(), r.found.end());
        p.deferred.insert(p.deferred.end(), r.deferred.begin(), r.deferred.end());
        continue;
      }
    }
    joined.push_back(std::move(r));
  }
  return joined;
}

/// Whether curve X over [x0, x1] stays within tol of curve Y over [y0, y1], Y taken there
/// as the polyline through 17 points of each of its pieces in the range (its ends, and a
/// corner between pieces, among them), X checked at 17 points of each of its pieces in
/// the range (unit frame).
template <class T>
bool stays_near(const Prepared<T>& X, T x0, T x1, const Prepared<T>& Y, T y0, T y1, T tol) {
  auto samples = [](const Prepared<T>& C, T c0, T c1) {
    std::vector<Point<T, 2>> q;
    C.curve->for_each_piece(Interval<T>(std::min(c0, c1), std::max(c0, c1)), [&](std::size_t i, const auto&, const Interval<T>& own) {
      for (int j = 0; j <= 16; ++j) q.push_back(at(C.unit[i], own.lo + (own.hi - own.lo) * static_cast<T>(j) / 16));
    });
    if (q.empty()) q.push_back(unit_at(*C.curve, C, c0));
    return q;
  };
  const std::vector<Point<T, 2>> q = samples(Y, y0, y1);
  for (const auto& p : samples(X, x0, x1)) {
    T d = distance(p, q.front());
    for (std::size_t k = 1; k < q.size() && d > tol; ++k) d = std::min(d, distance_to_segment(p, q[k - 1], q[k]));
    if (!(d <= tol)) return false;
  }
  return true;
}

/// Phase 3, tame parts only (solve_extreme): consecutive joined overlaps also join across
/// a gap (b running on the same way) over which one curve stays within tol of the other
/// (stays_near, either way: the contract's overlap is a whole arc of one curve within the
/// distance of the other).
/// A curve hugging its control polygon turns the corner within rounding of it: the
/// conic on (1, 0), (1, 1), (0, 1) with weights 1, 1e16, 1 passes 5e-17 from (1, 1), and
/// the tame parts that turn it map to one point of the polygon, so the overlaps along the
/// two legs end and start there, several parts apart on the conic. Joined, they are the
/// one overlap the curves have (the whole conic within 5e-17 of its polygon, mpmath),
/// which the corner's parts alone would not be (no length on the polygon), leaving two
/// stretches that each continue near the other curve (confirm_overlaps: their points,
/// merged into one "crossing" at the corner). Either way suffices: the conic's corner is
/// within tol of the polygon from w = 1 / (2 tol) - 1 (3.54e9 at the size sqrt(2)), the
/// polygon's corner within tol of the conic only from twice that (it lies sqrt(2) times as
/// far: 1.41e-10 at w = 5e9), so for w from 3.54e9 to 7.07e9 the answer was one crossing.
template <class T>
void bridge_overlaps(const Prepared<T>& A, const Prepared<T>& B, std::vector<RawOverlap<T>>& overlaps, T tol) {
  const T la = A.curve->domain().length(), lb = B.curve->domain().length();
  std::vector<RawOverlap<T>> joined;
  for (auto& r : overlaps) {
    if (!joined.empty()) {
      auto& p = joined.back();
      const auto& o = r.o;
      const bool up = p.o.b_end > p.o.b_start;
      const T da = o.a.lo - p.o.a.hi, db = up ? o.b_start - p.o.b_end : p.o.b_end - o.b_start;
      const bool same_way = (o.b_end > o.b_start) == up;
      const bool bridged = same_way && da >= -T(1e-9) * la && db >= -T(1e-9) * lb &&
                           (stays_near(A, p.o.a.hi, o.a.lo, B, p.o.b_end, o.b_start, tol) ||
                            stays_near(B, p.o.b_end, o.b_start, A, p.o.a.hi, o.a.lo, tol));
      if (bridged) {
        absorb(p, r);
        continue;
      }
    }
    joined.push_back(std::move(r));
  }
  overlaps = std::move(joined);
}

/// Phase 4: the joined overlaps that are overlaps. An overlap is a stretch within the
/// near-miss distance that ends where the curves part or a curve ends. One that the curves
/// continue beyond, still within the near-miss distance as far again past one of its ends
/// (near_beyond), is a piece of a longer near region (a crossing or touch at a tiny angle,
/// seen between joints of pieces or arcs: two circles of radius 1 with centres d apart
/// meet at an angle d and stay within tol over 2 tol / d around each crossing): its
/// points are reported instead, as they are off the joints.
///
/// Nor is one that holds no whole monotone arc of either curve (its ends are joints or
/// arc ends of both, staggered) while a crosses b inside it: the signed separation at
/// its two ends of opposite signs, both beyond tol / 8 (coincident curves are apart by
/// rounding only, about 1e-16 of the size; an offset copy within the distance keeps one
/// side). That is a crossing at a small angle theta cut between joints closer than its
/// near region (2 tol / theta long): two NURBS unit circles with centres d = 1.4e-5 ..
/// 2.4e-5 apart along x, whose crossings lie between the joints of their quarters d
/// apart, are within d^2 / 2 there but 1.5 d^2 > tol as far again beyond.
///
/// The points of rejected ones (found, or computed now for deferred pairs) are appended
/// to hits; the confirmed overlaps are returned in order.
template <class T>
std::vector<CurveOverlap<T>> confirm_overlaps(const Prepared<T>& A, const Prepared<T>& B, std::vector<RawOverlap<T>>& candidates,
                                              Context<T>& ctx, std::vector<Hit<T>>& hits, const TameJoints<T>* tame = nullptr) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  const T tol = ctx.tol;
  auto signed_gap = [&](T ta, T tb) {
    const Point<T, 2> p = unit_at(ca, A, ta);
    const Foot<T> f = foot_near(cb, B, p, tb);
    return std::copysign(f.distance, cross(direction_at(cb, B, f.t), p - unit_at(cb, B, f.t)));
  };
  auto covers_arc = [](const Pieces<T, 2>& c, const Prepared<T>& P, T lo, T hi) {
    const T m = T(1e-9) * c.domain().length();
    for (const auto& r : P.arcs)
      if (c.lift(r.piece, r.lo) >= lo - m && c.lift(r.piece, r.hi) <= hi + m) return true;
    return false;
  };
  // Whether t is an arc end of c that is no joint of its tame parts (`joints`).
  auto arc_end = [](const Pieces<T, 2>& c, const Prepared<T>& P, const std::vector<T>& joints, T t) {
    const T m = T(1e-9) * c.domain().length();
    for (T j : joints)
      if (std::abs(t - j) <= m) return false;
    for (const auto& r : P.arcs)
      if (std::abs(c.lift(r.piece, r.lo) - t) <= m || std::abs(c.lift(r.piece, r.hi) - t) <= m) return true;
    return false;
  };
  std::vector<CurveOverlap<T>> joined;
  for (auto& [o, found, deferred, parts] : candidates) {
    bool continues = near_beyond(ca, A, cb, B, o.a.lo, o.b_start, -(o.a.hi - o.a.lo), o.b_start - o.b_end, tol) ||
                     near_beyond(ca, A, cb, B, o.a.hi, o.b_end, o.a.hi - o.a.lo, o.b_end - o.b_start, tol);
    // On tame parts (solve_extreme) each end must be an arc end of a curve as given: a
    // part is a whole arc of the tamed curve, not of the curve (the conic [1, 2e6, 1]'s
    // first part, t in [0, 5e-4], lies within the distance of its polygon's leg; the curves
    // part there, but no whole arc of either is within it: a touch at their common end).
    if (!continues && tame) {
      continues = !((arc_end(ca, A, tame->a, o.a.lo) || arc_end(cb, B, tame->b, o.b_start)) &&
                    (arc_end(ca, A, tame->a, o.a.hi) || arc_end(cb, B, tame->b, o.b_end)));
    }
    if (!continues && !covers_arc(ca, A, o.a.lo, o.a.hi) && !covers_arc(cb, B, std::min(o.b_start, o.b_end), std::max(o.b_start, o.b_end))) {
      const T g0 = signed_gap(o.a.lo, o.b_start), g1 = signed_gap(o.a.hi, o.b_end);
      continues = (g0 > 0) != (g1 > 0) && std::min(std::abs(g0), std::abs(g1)) > tol / 8;
    }
    if (continues) {
      hits.insert(hits.end(), found.begin(), found.end());
      for (const auto& [i, j] : deferred) {
        const auto more = arc_points(A, i, B, j, ctx);
        hits.insert(hits.end(), more.begin(), more.end());
      }
    } else {
      joined.push_back(o);
    }
  }
  return joined;
}

/// Phase 4, end: confirmed overlaps that continue one another (the end of one within 1e-9
/// of the domain lengths of the start of the next, on a and on b, b running the same way)
/// are one overlap. Two halves of a copy moved along x by 0.7 of the near-miss distance
/// (degree 20 to 80) were confirmed apart, their join broken by a sliver of a pair of
/// neighbouring arcs, and the sliver's points, between the halves in both parameters,
/// were listed as crossings.
template <class T>
std::vector<CurveOverlap<T>> join_confirmed(std::vector<CurveOverlap<T>> overlaps, T la, T lb) {
  std::vector<CurveOverlap<T>> out;
  for (const auto& o : overlaps) {
    if (!out.empty()) {
      auto& p = out.back();
      if (std::abs(o.a.lo - p.a.hi) <= T(1e-9) * la && std::abs(o.b_start - p.b_end) <= T(1e-9) * lb &&
          ((o.b_end > o.b_start) == (p.b_end > p.b_start))) {
        p.a = Interval<T>(p.a.lo, o.a.hi);
        p.b_end = o.b_end;
        continue;
      }
    }
    out.push_back(o);
  }
  return out;
}

/// Whether the point h lies inside (or at the end of, within 1e-7 of its pieces' parameter
/// lengths) one of the overlaps, of which it is then a part, not an isolated point; for a
/// self-intersection the overlap seen from the other side too.
template <class T>
bool in_overlap(const Hit<T>& h, const std::vector<CurveOverlap<T>>& overlaps, const Pieces<T, 2>& ca, const Pieces<T, 2>& cb,
                bool self) {
  bool inside = false;
  for (const auto& o : overlaps) {
    const T blo = std::min(o.b_start, o.b_end), bhi = std::max(o.b_start, o.b_end);
    const T ma = T(1e-7) * break_length(ca, h.pa), mb = T(1e-7) * break_length(cb, h.pb);
    inside = inside || (h.ta >= o.a.lo - ma && h.ta <= o.a.hi + ma && h.tb >= blo - mb && h.tb <= bhi + mb);
    if (self)  // the same stretch seen from the other side
      inside = inside || (h.tb >= o.a.lo - ma && h.tb <= o.a.hi + ma && h.ta >= blo - mb && h.ta <= bhi + mb);
  }
  return inside;
}

}  // namespace casteljau::detail::isect
