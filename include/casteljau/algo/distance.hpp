// Minimum distance between two curves: branch and bound over their Bézier pieces with
// convex-hull lower bounds, exact end-point projections, and a final Newton refinement.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

#include "casteljau/algo/project.hpp"
#include "casteljau/core/segment.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

/// The result of distance(): the minimum distance between curves a and b, attained at
/// a(t[0]) = points[0] and b(t[1]) = points[1].
template <class T, int D>
struct CurveDistance {
  T distance;
  std::array<T, 2> t;
  std::array<Point<T, D>, 2> points;
};

/// The relative gap to the minimum that distance() guarantees before its refinement. It
/// sets the search's depth where the distance is nearly constant (concentric arcs need
/// parts of angle about sqrt(8 x 1e-7)): 1e-7 keeps that case to milliseconds.
template <class T>
inline constexpr T distance_tolerance = T(1e-7);

namespace detail {

/// A part [t0, t1] of piece `index` of a curve, with what the bounds need in coordinates
/// scaled by 2^-e: its box, the chord between its end points and the largest distance
/// of a control point from that chord (the part lies within that distance of the chord:
/// convex hull property, also for rational parts with positive weights).
template <class T, int D>
struct DistancePart {
  BezierPiece<T, D> piece;
  std::size_t index;
  T t0, t1;
  Box<T, D> box;
  Point<T, D> p0, p1;
  T flat;
};

template <class T, int D>
T box_distance(const Box<T, D>& x, const Box<T, D>& y) {
  Vector<T, D> v;
  for (int k = 0; k < D; ++k) v[k] = std::max({T(0), x.lo[k] - y.hi[k], y.lo[k] - x.hi[k]});
  return norm(v);
}

template <class T, int D>
DistancePart<T, D> make_part(BezierPiece<T, D> piece, std::size_t index, T t0, T t1, int e) {
  DistancePart<T, D> part{std::move(piece), index, t0, t1, Box<T, D>::empty_box(), {}, {}, T(0)};
  std::visit(
      [&](const auto& c) {
        const auto& P = c.points();
        for (const auto& q : P) part.box.add(scaled(q, -e));
        part.p0 = scaled(P.front(), -e);
        part.p1 = scaled(P.back(), -e);
        for (const auto& q : P) part.flat = std::max(part.flat, distance_to_segment(scaled(q, -e), part.p0, part.p1));
      },
      part.piece);
  return part;
}

template <class T, int D>
std::array<DistancePart<T, D>, 2> halve(const DistancePart<T, D>& x, int e) {
  const T mid = x.t0 + (x.t1 - x.t0) / 2;
  return std::visit(
      [&](const auto& c) {
        auto h = c.split(T(0.5));
        return std::array<DistancePart<T, D>, 2>{make_part<T, D>(BezierPiece<T, D>(std::move(h.left)), x.index, x.t0, mid, e),
                                                 make_part<T, D>(BezierPiece<T, D>(std::move(h.right)), x.index, mid, x.t1, e)};
      },
      x.piece);
}

template <class T, int D>
T lower_bound(const DistancePart<T, D>& x, const DistancePart<T, D>& y) {
  const auto st = closest_on_segments(x.p0, x.p1, y.p0, y.p1);
  const T chord = norm((x.p0 + st[0] * (x.p1 - x.p0)) - (y.p0 + st[1] * (y.p1 - y.p0)));
  return std::max(box_distance(x.box, y.box), chord - x.flat - y.flat);
}

}  // namespace detail

/// The minimum distance between curves a and b over both domains, with parameters where
/// it is attained. Guarantee: the result is within distance_tolerance (1e-7) relative
/// (plus 1e-13 of the curves' extent, for distances near 0) of the global minimum, by
/// branch and bound on parts of the Bézier pieces, best lower bound first. Lower bound
/// of a pair of parts: the larger of their control boxes' distance and their chords'
/// distance minus each part's flatness (every control point within `flat` of its chord,
/// so the part is: convex hull property [Farin02, 4.2]); this bound is within O(h^2) of
/// the true distance for parts of size h, which keeps the search small even for curves
/// at a constant distance (concentric arcs). Upper bounds: the curves' points at the
/// chords' closest parameters, and the exact projections of each curve's end points on
/// the other (project(), global). The best candidate is then refined by Newton's method
/// on the gradient of |a(s) - b(t)|^2 (kept only if it improves), which gives full
/// precision at a transversal or interior minimum. Curves that cross or overlap give 0.
/// Cost: O(number of part pairs whose bound is below the minimum); NumericalError past
/// 2,000,000 pair evaluations (never observed). Throws as project() does.
template <class CA, class CB>
  requires detail::is_pieces<CA> && detail::is_pieces<CB> && (CA::dimension == CB::dimension)
CurveDistance<typename CA::Scalar, CA::dimension> distance(const CA& a, const CB& b) {
  using T = typename CA::Scalar;
  constexpr int D = CA::dimension;
  const auto& pa0 = pieces(a);
  const auto& pb0 = pieces(b);
  // The search runs on both curves moved so that the centre of a's control box is the
  // origin, and halved (nothing overflows): rounding is then a few eps of the curves'
  // extent about that centre, not of their coordinates (unit curves at 1e12 from the
  // origin keep their digits). The distance is doubled back, the points evaluated on the
  // curves as given.
  const auto box_a = pa0.control_bounds();
  Point<T, D> centre;
  for (int k = 0; k < D; ++k) centre[k] = box_a.lo[k] / 2 + box_a.hi[k] / 2;
  const auto pa = pa0.transform(detail::halved_about(centre));
  const auto pb = pb0.transform(detail::halved_about(centre));
  // One power-of-two scale for both curves' bounds (no overflow in dot products).
  T m = 0;
  for (const auto* p : {&pa, &pb}) {
    const auto box = p->control_bounds();
    for (int k = 0; k < D; ++k) m = std::max({m, std::abs(box.lo[k]), std::abs(box.hi[k])});
  }
  int e = 0;
  if (m > 0) (void)std::frexp(m, &e);
  CurveDistance<T, D> best{std::numeric_limits<T>::infinity(), {}, {}};
  // The end of a piece before a jump (a path's gap, a B-spline's knot of multiplicity
  // p + 1) lifts to the double below the break (Pieces::lift), where evaluation gives that
  // piece's point: candidates are evaluated at their curve parameters.
  auto offer = [&](T ta, T tb) {
    const auto qa = pa(ta), qb = pb(tb);
    const T d = detail::safe_distance(qa, qb);
    if (d < best.distance) best = {d, {ta, tb}, {qa, qb}};
  };
  // Exact global candidates at the ends.
  for (T ta : {pa.domain().lo, pa.domain().hi}) offer(ta, project(pb, pa(ta)).t);
  for (T tb : {pb.domain().lo, pb.domain().hi}) offer(project(pa, pb(tb)).t, tb);

  // Parts live in one arena; the heap holds pairs of indices (no copies of control points).
  using Part = detail::DistancePart<T, D>;
  std::vector<Part> arena;
  struct Pair {
    T lb;
    std::size_t x, y;
  };
  auto worse = [](const Pair& u, const Pair& v) { return u.lb > v.lb; };
  std::priority_queue<Pair, std::vector<Pair>, decltype(worse)> heap(worse);
  // Scaled coordinates are below 1 in magnitude: 1e-13 of them is the absolute floor.
  auto tol = [&] { return std::max(distance_tolerance<T> * std::ldexp(best.distance, -e), T(1e-13)); };
  auto push = [&](std::size_t x, std::size_t y) {
    const T lb = detail::lower_bound(arena[x], arena[y]);
    if (lb < std::ldexp(best.distance, -e) - tol()) heap.push({lb, x, y});
  };
  std::vector<std::size_t> xa, xb;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    xa.push_back(arena.size());
    arena.push_back(detail::make_part<T, D>(pa.segments()[i], i, T(0), T(1), e));
  }
  for (std::size_t j = 0; j < pb.size(); ++j) {
    xb.push_back(arena.size());
    arena.push_back(detail::make_part<T, D>(pb.segments()[j], j, T(0), T(1), e));
  }
  for (std::size_t x : xa)
    for (std::size_t y : xb) push(x, y);
  std::size_t work = 0;
  // Children of a part, made once however many pairs it is in.
  std::vector<std::array<std::size_t, 2>> children(arena.size(), {0, 0});
  auto split_part = [&](std::size_t x) {
    if (children[x][0] == 0) {
      auto h = detail::halve(arena[x], e);
      arena.push_back(std::move(h[0]));
      arena.push_back(std::move(h[1]));
      children.push_back({0, 0});
      children.push_back({0, 0});
      children[x] = {arena.size() - 2, arena.size() - 1};
    }
    return children[x];
  };
  while (!heap.empty()) {
    const Pair top = heap.top();
    heap.pop();
    if (!(top.lb < std::ldexp(best.distance, -e) - tol())) break;  // nothing left can improve enough
    if (++work > 2'000'000) throw NumericalError("distance: the search exceeded 2,000,000 pairs of parts");
    const Part& x = arena[top.x];
    const Part& y = arena[top.y];
    // Upper bound from the chords' closest parameters, evaluated on the curves.
    const auto st = closest_on_segments(x.p0, x.p1, y.p0, y.p1);
    const PieceParameter<T> la{x.index, x.t0 + st[0] * (x.t1 - x.t0)}, lb{y.index, y.t0 + st[1] * (y.t1 - y.t0)};
    const T ta = pa.lift(la.index, la.t), tb = pb.lift(lb.index, lb.t);
    offer(ta, tb);
    const T sx = norm(x.box.hi - x.box.lo), sy = norm(y.box.hi - y.box.lo);
    const bool can_x = x.t1 - x.t0 > T(1e-15), can_y = y.t1 - y.t0 > T(1e-15);
    if (!can_x && !can_y) continue;  // at the resolution of the parameter: the offer stands
    const std::size_t ix = top.x, iy = top.y;
    if (can_x && (sx >= sy || !can_y)) {
      for (std::size_t h : split_part(ix)) push(h, iy);
    } else {
      for (std::size_t h : split_part(iy)) push(ix, h);
    }
  }
  // Newton on g(s, t) = (a(s) - b(t)) . (a'(s), -b'(t)) = 0 from the best candidate. A
  // derivative that is not representable (coordinates near the largest double) ends the
  // refinement: the candidate found by the search stands.
  try {
    T s = best.t[0], t = best.t[1];
    const auto da = pa.domain(), db = pb.domain();
    for (int it = 0; it < 32; ++it) {
      const auto r = pa(s) - pb(t);
      const auto a1 = pa.derivative_at(s, 1), a2 = pa.derivative_at(s, 2);
      const auto b1 = pb.derivative_at(t, 1), b2 = pb.derivative_at(t, 2);
      const T g0 = dot(r, a1), g1 = -dot(r, b1);
      const T h00 = dot(a1, a1) + dot(r, a2), h01 = -dot(a1, b1), h11 = dot(b1, b1) - dot(r, b2);
      const T det = h00 * h11 - h01 * h01;
      if (!(det > 0) || !std::isfinite(det)) break;
      const T ds = -(h11 * g0 - h01 * g1) / det, dt = -(h00 * g1 - h01 * g0) / det;
      const T ns = std::clamp(s + ds, da.lo, da.hi), nt = std::clamp(t + dt, db.lo, db.hi);
      if (!std::isfinite(ns) || !std::isfinite(nt)) break;
      const bool done = ns == s && nt == t;
      s = ns;
      t = nt;
      offer(s, t);
      if (done) break;
    }
  } catch (const InvalidArgument&) {
  }
  best.distance *= 2;
  best.points = {pa0(best.t[0]), pb0(best.t[1])};
  return best;
}

/// Any other pair of curve types: the same, on their exact pieces (see detail::is_pieces).
template <class CA, class CB>
  requires PiecewiseBezierCurve<CA> && PiecewiseBezierCurve<CB> && (CA::dimension == CB::dimension) &&
           (!(detail::is_pieces<CA> && detail::is_pieces<CB>))
CurveDistance<typename CA::Scalar, CA::dimension> distance(const CA& a, const CB& b) {
  return distance(pieces(a), pieces(b));
}

}  // namespace casteljau
