// Intersection engine, phases 5, 6 and 8 to 10 (algo/intersect.hpp): de-duplication.
// The points merged into one per near region (joints, closing points and cusps of a
// self-intersection dropped), edge points admitted where nothing else stands for their
// region, a crossing at a closing point listed once, loose touches and the points of
// tame parts merged into their region.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/classify.hpp"
#include "casteljau/algo/intersect/overlap.hpp"
#include "casteljau/core/segment.hpp"

namespace casteljau::detail::isect {

/// The curves' domains and whether each is closed (its ends within tol in the unit
/// frame): on a closed curve the way between two parameters may pass its closing point.
template <class T>
struct Loops {
  Loop<T> a, b;
};
template <class T>
Loops<T> loops(const Prepared<T>& A, const Prepared<T>& B, T tol) {
  const Interval<T> dom_a = A.curve->domain(), dom_b = B.curve->domain();
  const bool closed_a = distance(unit_at(*A.curve, A, dom_a.lo), unit_at(*A.curve, A, dom_a.hi)) <= tol;
  const bool closed_b = distance(unit_at(*B.curve, B, dom_b.lo), unit_at(*B.curve, B, dom_b.hi)) <= tol;
  return {{dom_a, closed_a}, {dom_b, closed_b}};
}

/// The points of solve() after merging: one per near region, sorted by ta, and the points
/// from edge seeds set aside (admit_edges decides which of them stand for a region).
template <class T>
struct MergedPoints {
  std::vector<Hit<T>> kept;
  std::vector<Hit<T>> edges;
};

/// Phase 5, step 1: the points in the order of ta; for a self-intersection each pair first
/// ordered ta <= tb (its pieces and piece parameters with it).
template <class T>
void order_hits(std::vector<Hit<T>>& hits, bool self) {
  if (self) {
    for (auto& h : hits) {
      if (h.ta > h.tb) {
        std::swap(h.ta, h.tb);
        std::swap(h.pa, h.pb);
        std::swap(h.sa, h.sb);
      }
    }
  }
  std::sort(hits.begin(), hits.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
}

/// Whether the curve between ta and tb (a short stretch) is a hairpin: out to a tip and
/// back along itself, every point within 2 tol of the other branch, as at a cusp where a
/// path reverses at a joint and its two branches leave the tip with one tangent, parting
/// slowly (a raw offset's cusp: curvatures 0.43 and 0.47, within the near-miss distance
/// for about 4e-5 of their length). Judged on 65 samples at equal parameter steps (the
/// stretch is at most 1e-6 of the curve's size: its chords are exact to far below tol):
/// the tip is the sample farthest from c(ta); each branch's samples within 2 tol of the
/// other branch's polyline.
template <class T>
bool hairpin(const Prepared<T>& A, T ta, T tb, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  constexpr int n = 64;
  std::array<Point<T, 2>, n + 1> P;
  for (int k = 0; k <= n; ++k) {
    const T u = k == n ? tb : ta + (tb - ta) * static_cast<T>(k) / n;
    const auto at = ca.locate(u);
    P[static_cast<std::size_t>(k)] = std::visit([&](const auto& x) { return x(at.t); }, A.unit[at.index]);
  }
  std::size_t tip = 0;
  for (std::size_t k = 1; k <= n; ++k)
    if (squared_norm(P[k] - P[0]) > squared_norm(P[tip] - P[0])) tip = k;
  if (tip == 0 || tip == n) return false;
  const auto near_other = [&](std::size_t lo, std::size_t hi, std::size_t olo, std::size_t ohi) {
    for (std::size_t k = lo; k <= hi; ++k) {
      T d = std::numeric_limits<T>::infinity();
      for (std::size_t j = olo; j < ohi && d > 2 * tol; ++j) d = std::min(d, distance_to_segment(P[k], P[j], P[j + 1]));
      if (!(d <= 2 * tol)) return false;
    }
    return true;
  };
  return near_other(0, tip, tip, n) && near_other(tip, n, 0, tip);
}

/// Phase 5, step 2 (self-intersections): whether the point (ta <= tb) is the curve
/// meeting itself where consecutive arcs join, at its closing point, or at a cusp: none is
/// a self-intersection. A "loop" whose extent (the control boxes of the curve between ta
/// and tb) is below the near-miss distance times 100 is one of these at the resolution of
/// double; so is a hairpin (above) whose extent is below 1e-6 of the curve's size.
template <class T>
bool trivial_self_contact(const Prepared<T>& A, const Hit<T>& h, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  if (h.tb - h.ta <= T(1e-12) * ca.domain().length()) return true;
  const Interval<T> dom = ca.domain();
  if (h.ta == dom.lo && h.tb == dom.hi) return true;
  const T small = std::max(100 * tol, T(1e-6) * A.size);
  Box<T, 2> loop = Box<T, 2>::empty_box();
  ca.for_each_piece({h.ta, h.tb}, [&](std::size_t p, const auto&, const Interval<T>& own) {
    if (own.hi > own.lo) loop.add(std::visit([&](const auto& x) { return part(x, own.lo, own.hi).control_bounds(); }, A.unit[p]));
    return loop.empty() || diagonal(loop) <= small;  // beyond: a loop, no need to see the rest of it
  });
  if (loop.empty()) return false;
  return diagonal(loop) <= 100 * tol || (diagonal(loop) <= small && hairpin(A, h.ta, h.tb, tol));
}

/// Phase 5, step 3: the points kept so far, one per near region, and how a new point
/// merges into one of them. Each kept point has its twins (points merged into it, all
/// common to rounding: the middle one in ta is kept at the end, middle_twins) and its
/// touch span (the extreme points of its touch region).
template <class T>
struct PointMerge {
  const Prepared<T>& A;
  const Prepared<T>& B;
  const Loops<T>& lp;
  T tol;
  std::vector<Hit<T>> kept{};
  std::vector<std::vector<Hit<T>>> twins{};
  std::vector<TouchSpan<T>> spans{};

  /// Common to rounding: within 1e-3 of the near-miss distance.
  [[nodiscard]] T exact() const { return T(1e-3) * tol; }

  /// A common point at which the curves cross (common to rounding, tangents apart by more
  /// than crossing_noise), not a touch.
  [[nodiscard]] bool crossing(const Hit<T>& x) const {
    return x.distance <= exact() &&
           std::abs(cross(direction(A.unit[x.pa], x.sa), direction(B.unit[x.pb], x.sb))) > crossing_noise<T>;
  }

  /// The touch span sp widened by h's parameters (taken next to the span's, round the
  /// closing point of a closed curve).
  [[nodiscard]] TouchSpan<T> widen(TouchSpan<T> sp, const Hit<T>& h) const {
    const T hta = sp.ta0 + lp.a.shortest(h.ta - sp.ta0), htb = sp.tb0 + lp.b.shortest(h.tb - sp.tb0);
    if (hta < sp.ta0) {
      sp.ta0 = hta;
      sp.tb0 = htb;
    }
    if (hta > sp.ta1) {
      sp.ta1 = hta;
      sp.tb1 = htb;
    }
    return sp;
  }

  /// Whether h is kept point ki seen again: within merge_fraction of their pieces'
  /// parameter lengths in both parameters and within 1e4 tol in the plane.
  [[nodiscard]] bool same_point(const Hit<T>& h, std::size_t ki) const {
    const Hit<T>& k = kept[ki];
    const T ma = T(merge_fraction) * break_length(*A.curve, h.pa), mb = T(merge_fraction) * break_length(*B.curve, h.pb);
    return std::abs(lp.a.shortest(h.ta - k.ta)) <= ma && std::abs(lp.b.shortest(h.tb - k.tb)) <= mb &&
           distance(at(A.unit[k.pa], k.sa), at(A.unit[h.pa], h.sa)) <= 1e4 * tol;
  }

  /// h merged into kept point ki, the same point: a touch is sought again over its span
  /// widened by h; two points common to rounding (a crossing at a tiny angle, seen from
  /// neighbouring parts with roots blurred by eps / angle) are twins; else the closer one.
  void merge_same(const Hit<T>& h, std::size_t ki) {
    Hit<T>& k = kept[ki];
    if (k.touch) {
      spans[ki] = widen(spans[ki], h);
      if (auto t = touch_in(*A.curve, A, lp.a, *B.curve, B, lp.b, spans[ki], tol)) k = *t;
    } else if (h.distance <= exact() && k.distance <= exact()) {
      twins[ki].push_back(h);
    } else if (h.distance < k.distance) {
      k = h;
      twins[ki].clear();
    }
  }

  /// Whether h and kept point ki are two points of one near region: within 1e3
  /// merge_fraction of their pieces in both parameters, the curves within the near-miss
  /// distance half way between them.
  [[nodiscard]] bool one_region(const Hit<T>& h, std::size_t ki) const {
    const Hit<T>& k = kept[ki];
    const T ma = T(merge_fraction) * break_length(*A.curve, h.pa), mb = T(merge_fraction) * break_length(*B.curve, h.pb);
    const T dta = lp.a.shortest(h.ta - k.ta), dtb = lp.b.shortest(h.tb - k.tb);
    if (!(std::abs(dta) <= T(1e3) * ma && std::abs(dtb) <= T(1e3) * mb)) return false;
    const T mta = lp.a.wrap(k.ta + dta / 2), mtb = lp.b.wrap(k.tb + dtb / 2);
    return distance_near(*B.curve, B, unit_at(*A.curve, A, mta), mtb) <= tol;
  }

  /// h merged into kept point ki of its near region: two crossings between which the
  /// curves stay within the near-miss distance (the separation peaks between them) are
  /// one touch at that resolution, reported once, as tangent, where the separation peaks
  /// (touch_in), or at the middle when that cannot be located; a touch region widened by
  /// h sought again; a crossing and a touch of one near region (the curves cross, then
  /// come within the distance again without crossing back) are one point, the crossing;
  /// two touches, the closer one.
  void merge_region(const Hit<T>& h, std::size_t ki) {
    Hit<T>& k = kept[ki];
    const bool pair = !k.touch && crossing(k) && crossing(h);
    if (k.touch || pair) {
      spans[ki] = widen(k.touch ? spans[ki] : TouchSpan<T>{k.ta, k.tb, k.ta, k.tb}, h);
      if (auto t = touch_in(*A.curve, A, lp.a, *B.curve, B, lp.b, spans[ki], tol)) {
        k = *t;
      } else if (pair) {  // not located (no sign change of g): at the middle
        const T mta = lp.a.wrap(k.ta + lp.a.shortest(h.ta - k.ta) / 2), mtb = lp.b.wrap(k.tb + lp.b.shortest(h.tb - k.tb) / 2);
        const auto a = A.curve->locate(mta), b = B.curve->locate(mtb);
        k = Hit<T>{mta, mtb, a.index, b.index, a.t, b.t, k.distance, true};
      }
    } else if (crossing(h) || (!crossing(k) && h.distance < k.distance)) {
      k = h;
    }
    twins[ki].clear();
  }

  /// h merged into kept point ki if it is the same point or of its near region.
  bool merge_into(const Hit<T>& h, std::size_t ki) {
    if (same_point(h, ki)) {
      merge_same(h, ki);
      return true;
    }
    if (one_region(h, ki)) {
      merge_region(h, ki);
      return true;
    }
    return false;
  }

  /// h as a new kept point.
  void keep(const Hit<T>& h) {
    kept.push_back(h);
    twins.emplace_back();
    spans.push_back({h.ta, h.tb, h.ta, h.tb});
  }

  /// Each kept point with twins replaced by the middle one in ta of it and its twins.
  void middle_twins() {
    for (std::size_t ki = 0; ki < kept.size(); ++ki) {
      if (twins[ki].empty()) continue;
      twins[ki].push_back(kept[ki]);
      std::sort(twins[ki].begin(), twins[ki].end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
      kept[ki] = twins[ki][(twins[ki].size() - 1) / 2];
    }
  }
};

/// Phase 5: the points of the arcs merged into one per near region. In the order of ta
/// (order_hits): points inside an overlap are dropped (in_overlap); for a
/// self-intersection, points where consecutive arcs join, the closing point and cusps
/// (trivial_self_contact); points from edge seeds are set aside; every other point merges
/// into a kept one of the same near region (PointMerge: the same point within
/// merge_fraction of the pieces; two crossings between which the curves stay within tol
/// are one touch, at the peak of the separation; a crossing and a touch of one region are
/// the crossing) or is kept. Linear in the number of points (each is compared with the
/// kept points of a window).
template <class T>
MergedPoints<T> merge_points(const Prepared<T>& A, const Prepared<T>& B, bool self, std::vector<Hit<T>> hits,
                             const std::vector<CurveOverlap<T>>& overlaps, const Loops<T>& lp, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  order_hits(hits, self);
  MergedPoints<T> out;
  PointMerge<T> m{A, B, lp, tol};
  // Hits merge only with kept points within 1e3 merge_fraction of the longest piece of a in
  // ta (see PointMerge::one_region); kept stays sorted by ta to within that window (a merge
  // moves a kept point towards the later hit), so each hit is compared with the kept points
  // from 4 windows back only: linear in the number of points, not quadratic (a polyline
  // crossing itself 10^5 times).
  T longest_a = 0;
  for (std::size_t p = 0; p < ca.size(); ++p) longest_a = std::max(longest_a, break_length(ca, p));
  const T window = T(1e3) * T(merge_fraction) * longest_a;
  for (const auto& h : hits) {
    // Inside (or at the end of) an overlap: part of it, not an isolated point.
    if (in_overlap(h, overlaps, ca, cb, self)) continue;
    if (self && trivial_self_contact(A, h, tol)) continue;
    if (h.edge) {
      out.edges.push_back(h);
      continue;
    }
    bool merged = false;
    std::size_t first = m.kept.size();
    while (first > 0 && m.kept[first - 1].ta >= h.ta - 4 * window) --first;
    for (std::size_t ki = first; ki < m.kept.size() && !merged; ++ki) merged = m.merge_into(h, ki);
    // On a closed curve a, the points at the start of its domain are next to h near its
    // end (the closing point: a point there is found at both ends of the domain).
    if (lp.a.closed && h.ta >= lp.a.dom.hi - 4 * window) {
      for (std::size_t ki = 0; ki < std::min<std::size_t>(first, 16) && !merged; ++ki)
        if (std::abs(lp.a.shortest(m.kept[ki].ta - h.ta)) <= 4 * window) merged = m.merge_into(h, ki);
    }
    if (!merged) m.keep(h);
  }
  m.middle_twins();
  out.kept = std::move(m.kept);
  // Sorted for the search below: merges move points within the window, and one at the
  // closing point of a closed curve may have moved to the other end of its domain.
  std::sort(out.kept.begin(), out.kept.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
  return out;
}

/// Phase 6: the points from edge seeds (arc ends inside a near region, see band()) added to
/// kept (sorted by ta) where they stand for a region of their own. One stands for its
/// region only if no other point does, i.e. if the curves part (beyond tol) between it
/// and each of its neighbours in ta among the points kept so far (the nearest 8 on each
/// side; on a closed curve a the first and last 8 too); the closest of several such
/// points of one region is kept. kept stays sorted by ta.
template <class T>
void admit_edges(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp, std::vector<Hit<T>>& kept, std::vector<Hit<T>> edges,
                 T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  const Loop<T>&loop_a = lp.a, &loop_b = lp.b;
  const bool closed_a = loop_a.closed;
  // Points from edge seeds (arc ends inside a near region, see band()): one stands for its
  // region only if no other point does, i.e. if the curves part (beyond tol) between it
  // and each of its neighbours in ta among the points kept so far (the nearest 8 on each
  // side); the closest of several such points of one region is kept.
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.distance < y.distance; });
  auto same_region = [&](const Hit<T>& x, const Hit<T>& y) {
    const T da = loop_a.shortest(y.ta - x.ta), db = loop_b.shortest(y.tb - x.tb);
    for (int j = 0; j <= 16; ++j) {
      const T f = static_cast<T>(j) / 16;
      const T ta = loop_a.wrap(x.ta + f * da), tb = loop_b.wrap(x.tb + f * db);
      if (!(distance_near(cb, B, unit_at(ca, A, ta), tb) <= tol)) return false;
    }
    return true;
  };
  for (const auto& h : edges) {
    const auto at_h = std::lower_bound(kept.begin(), kept.end(), h.ta, [](const auto& k, T ta) { return k.ta < ta; });
    const std::size_t mid = static_cast<std::size_t>(at_h - kept.begin());
    bool represented = false;
    for (std::size_t k = mid > 8 ? mid - 8 : 0; k < std::min(kept.size(), mid + 8) && !represented; ++k)
      represented = same_region(kept[k], h);
    if (closed_a) {  // the neighbours across the closing point
      for (std::size_t k = 0; k < std::min<std::size_t>(kept.size(), 8) && !represented; ++k) represented = same_region(kept[k], h);
      for (std::size_t k = kept.size() > 8 ? kept.size() - 8 : 0; k < kept.size() && !represented; ++k)
        represented = same_region(kept[k], h);
    }
    if (!represented) kept.insert(kept.begin() + static_cast<std::ptrdiff_t>(mid), h);
  }

}

/// Phase 8 (self-intersections of a closed curve): a closed curve crossing itself at its
/// closing point passes there three times in parameters (start, middle, end): the pairs
/// (start, middle) and (middle, end) are one self-intersection. Parameters at the end of
/// the domain count as its start (within merge_fraction of their piece); such a pair is
/// listed once, the first in ta. Other points are kept, in order.
template <class T>
std::vector<CurveIntersection<T>> once_at_closing_point(const Pieces<T, 2>& ca, const std::vector<CurveIntersection<T>>& points) {
  const Interval<T> dom_a = ca.domain();
  // A closed curve crossing itself at its closing point passes there three times in
  // parameters (start, middle, end): the pairs (start, middle) and (middle, end) are one
  // self-intersection. Parameters at the end of the domain count as its start (within
  // merge_fraction of their piece); such a pair is listed once, the first in ta.
  auto near_end = [&](T t) { return t >= dom_a.hi - T(merge_fraction) * break_length(ca, ca.segment_index(t)); };
  auto same_t = [&](T x, T y) {
    return std::abs(x - y) <= T(merge_fraction) * std::max(break_length(ca, ca.segment_index(x)), break_length(ca, ca.segment_index(y)));
  };
  auto canonical = [&](const CurveIntersection<T>& x) {
    T u = near_end(x.ta) ? dom_a.lo : x.ta, v = near_end(x.tb) ? dom_a.lo : x.tb;
    if (u > v) std::swap(u, v);
    return std::pair<T, T>{u, v};
  };
  std::vector<CurveIntersection<T>> once;
  std::vector<std::pair<T, T>> closing;  // canonical pairs of the kept points that touch the closing point
  for (const auto& x : points) {
    const bool touches = near_end(x.ta) || near_end(x.tb) || same_t(x.ta, dom_a.lo) || same_t(x.tb, dom_a.lo);
    if (touches) {
      const auto c = canonical(x);
      if (std::any_of(closing.begin(), closing.end(), [&](const auto& k) { return same_t(k.first, c.first) && same_t(k.second, c.second); }))
        continue;
      closing.push_back(c);
    }
    once.push_back(x);
  }
  return once;
}

/// Whether consecutive points x and y (in ta) are of one near region: one curve at 15
/// points between them (ta and tb interpolated, round the closing point of a closed curve)
/// within tol of the other, a of b or b of a (the foot of a point on a curve parametrised
/// very unevenly, the conic [1, 1e6, 1] seen from its polygon, is not always reached from
/// the interpolated parameter; the polygon from the conic's points is).
template <class T>
bool same_near_region(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp, const CurveIntersection<T>& x,
                      const CurveIntersection<T>& y, T tol) {
  const T da = lp.a.shortest(y.ta - x.ta), db = lp.b.shortest(y.tb - x.tb);
  auto near = [&](bool a_of_b) {
    for (int j = 1; j < 16; ++j) {
      const T f = static_cast<T>(j) / 16;
      const T ta = lp.a.wrap(x.ta + f * da), tb = lp.b.wrap(x.tb + f * db);
      const T d = a_of_b ? distance_near(*B.curve, B, unit_at(*A.curve, A, ta), tb) : distance_near(*A.curve, A, unit_at(*B.curve, B, tb), ta);
      if (!(d <= tol)) return false;
    }
    return true;
  };
  return near(true) || near(false);
}

/// Phase 9 (general engine): loose touches merged into their near region. Refinement may
/// stop inside a near region, at a point within tol that is neither a meeting to rounding
/// nor the closest approach, and PointMerge merges only points within 1e3 merge_fraction of
/// their pieces: where the curves part slowly (the conic [1, 5e4, 1] within the distance of
/// its control polygon's leg from t = 0 to 2e-5, leg parameters 0 to 0.68) such points were
/// listed as touches of their own (2.5e-11 and 4.6e-11 from the leg, the touch being at the
/// common end). A loose point is a `tangent` one farther apart than 1e-3 tol (a meeting to
/// rounding is within it: PointMerge::exact). Consecutive points (in ta) of one near region
/// (same_near_region) of which one is loose are one region: its points that are not loose
/// stand for it (as before), or, without one, its closest loose point. Points in order of ta.
template <class T>
std::vector<CurveIntersection<T>> absorb_touches(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp,
                                                 const std::vector<CurveIntersection<T>>& points, T tol) {
  auto separation = [&](const CurveIntersection<T>& x) { return distance(unit_at(*A.curve, A, x.ta), unit_at(*B.curve, B, x.tb)); };
  std::vector<char> loose(points.size());
  bool any = false;
  for (std::size_t k = 0; k < points.size(); ++k) {
    loose[k] = points[k].kind == IntersectionKind::tangent && separation(points[k]) > T(1e-3) * tol;
    any = any || loose[k];
  }
  if (points.size() < 2 || !any) return points;
  std::vector<CurveIntersection<T>> out;
  for (std::size_t i = 0; i < points.size();) {
    std::size_t j = i + 1;
    while (j < points.size() && (loose[j - 1] || loose[j]) && same_near_region(A, B, lp, points[j - 1], points[j], tol)) ++j;
    std::optional<std::size_t> pick;
    bool firm = false;
    for (std::size_t k = i; k < j; ++k) {
      if (!loose[k]) {
        firm = true;
        out.push_back(points[k]);
      } else if (!pick || separation(points[k]) < separation(points[*pick])) {
        pick = k;
      }
    }
    if (!firm) out.push_back(points[*pick]);
    i = j;
  }
  return out;
}

/// Phase 10 (curves taken through their tame parts only, see solve_extreme): consecutive
/// points (in ta) between which the curves stay within tol (at 15 points between them,
/// as admit_edges) are one near region and become one point: the middle one of its
/// crossings common to rounding (within 1e-3 tol), else (the curves do not cross there: a
/// touch) a point where both curves end and meet if it has one, else its closest point (before
/// session 15: its closest crossing, which took points within tol at an angle, 1e-12 to
/// 6e-11 from a leg, for crossings of the conic and its polygon). On the tame parts of a
/// curve hugging its control polygon the engine sees one near region from several
/// pieces, whose parameters (one unit per part) are far apart where the points are not:
/// a line through the corner meets the chord of the parts within 1e-30 of it and the
/// ends of the parts next to it, each within rounding. Points are in order of ta.
template <class T>
std::vector<CurveIntersection<T>> merge_regions(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp,
                                                const std::vector<CurveIntersection<T>>& points, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  auto separation = [&](const CurveIntersection<T>& x) { return distance(unit_at(ca, A, x.ta), unit_at(cb, B, x.tb)); };
  // A point where both curves end, met to rounding (within 1e-3 tol): where the curves
  // meet, not merely come near.
  auto at_ends = [&](const CurveIntersection<T>& x) {
    return !lp.a.closed && !lp.b.closed && (x.ta == lp.a.dom.lo || x.ta == lp.a.dom.hi) &&
           (x.tb == lp.b.dom.lo || x.tb == lp.b.dom.hi) && separation(x) <= T(1e-3) * tol;
  };
  std::vector<CurveIntersection<T>> out;
  for (std::size_t i = 0; i < points.size();) {
    std::size_t j = i + 1;
    while (j < points.size() && same_near_region(A, B, lp, points[j - 1], points[j], tol)) ++j;
    // The crossings common to rounding (within 1e-3 tol, as PointMerge::exact): the middle
    // one. Without one the curves do not cross in the region (a point within tol at an
    // angle is no crossing), which is a touch: at a point where both curves end and meet
    // if the region holds one (the conic [1, w, 1] along its control polygon's leg from
    // their common end, within 1e-17 of it over parts near the end: the closest approach
    // to rounding, and the end exactly), else at its closest point.
    std::vector<std::size_t> exact;
    for (std::size_t k = i; k < j; ++k)
      if (points[k].kind == IntersectionKind::crossing && separation(points[k]) <= T(1e-3) * tol) exact.push_back(k);
    std::size_t pick = i;
    if (!exact.empty()) {
      pick = exact[(exact.size() - 1) / 2];
    } else {
      for (std::size_t k = i; k < j; ++k) {
        if (at_ends(points[pick])) break;
        if (at_ends(points[k]) || separation(points[k]) < separation(points[pick])) pick = k;
      }
    }
    out.push_back(points[pick]);
    i = j;
  }
  return out;
}

}  // namespace casteljau::detail::isect
