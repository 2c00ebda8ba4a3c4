// The offset's joins at the corners of the input (phase of algo/offset.hpp): at an outer
// corner a round arc of radius |d| (a Source approximated by place.hpp), a miter or a
// bevel; at an inner corner the line between the two offset ends, marked reversed for the
// trim. Depends on common.hpp, place.hpp and options.hpp (OffsetJoin, the miter limit).
#pragma once

#include <cmath>
#include <numbers>
#include <utility>

#include "casteljau/algo/offset/common.hpp"
#include "casteljau/algo/offset/options.hpp"
#include "casteljau/algo/offset/place.hpp"

namespace casteljau::detail::offset {

/// A corner of the input: the curve's point and its unit tangents before and after.
template <class T>
struct Corner {
  Point<T, 2> at;
  Vector<T, 2> before, after;
};

/// The angle turned from u to v (unit vectors), in (-pi, pi].
template <class T>
T turn(const Vector<T, 2>& u, const Vector<T, 2>& v) {
  return std::atan2(cross(u, v), dot(u, v));
}

/// Cubics of a straight line a -> b (control points at thirds).
template <class T>
Quad<T> line(const Point<T, 2>& a, const Point<T, 2>& b) {
  const Vector<T, 2> v = b - a;
  return Quad<T>{a, a + v / T(3), a + v * (T(2) / 3), b};
}

/// The join at a corner (d != 0) into raw: nothing where the tangents agree within 1e-9
/// rad; at an outer corner (the side of the offset away from the turn, or both sides of a
/// reversal) a round arc about the corner (rotating against the sign of d), a miter or a
/// bevel; at an inner corner the straight line between the two offset end points, marked
/// reversed (the trim cuts it away with the overlapping ends of the offsets).
template <class T>
void join(const Corner<T>& c, const OffsetOptions<T>& o, T d, Raw<T>& raw) {
  const T theta = turn(c.before, c.after);
  const Point<T, 2> P = c.at + left(c.before) * d, Q = c.at + left(c.after) * d;
  if (std::abs(theta) <= T(1e-9)) return;
  const bool reversal = std::abs(theta) >= std::numbers::pi_v<T> * (1 - T(1e-12));
  const bool outer = reversal || theta * d < 0;
  raw.kind_now = outer ? RawKind::outer_join : RawKind::inner_join;
  raw.corner_now = c.at;
  struct Restore {  // the cubics after the join follow a stretch again
    Raw<T>& r;
    ~Restore() { r.kind_now = RawKind::stretch; }
  } restore{raw};
  if (!outer) {
    raw.push(line(P, Q), true);
    return;
  }
  const T sweep = std::abs(theta);  // rotating by -sign(d)
  if (o.join == OffsetJoin::miter && !reversal && 1 / std::cos(sweep / 2) <= o.miter_limit) {
    const Point<T, 2> M = c.at + unit(left(c.before) + left(c.after)) * (d / std::cos(sweep / 2));
    raw.push(line(P, M), false);
    raw.push(line(M, Q), false);
    return;
  }
  if (o.join != OffsetJoin::round) {
    raw.push(line(P, Q), false);
    return;
  }
  const T r = std::abs(d), dir = d > 0 ? T(-1) : T(1);
  const Vector<T, 2> e0 = left(c.before) * (d > 0 ? T(1) : T(-1));  // start direction from the centre
  const Point<T, 2> centre = c.at;
  const T phi0 = std::atan2(e0[1], e0[0]);
  Source<T> arc;
  arc.point = [=](T s) { return centre + Vector<T, 2>{std::cos(phi0 + dir * s), std::sin(phi0 + dir * s)} * r; };
  arc.velocity = [=](T s) { return Vector<T, 2>{-std::sin(phi0 + dir * s), std::cos(phi0 + dir * s)} * (r * dir); };
  arc.tangent = [=](T s) { return Vector<T, 2>{-std::sin(phi0 + dir * s), std::cos(phi0 + dir * s)} * dir; };
  arc.frame = [=](T s) {
    const T c = std::cos(phi0 + dir * s), n = std::sin(phi0 + dir * s);
    return std::pair{centre + Vector<T, 2>{c, n} * r, Vector<T, 2>{-n, c} * dir};
  };
  arc.lo = 0, arc.hi = sweep;
  // Exact end points (the arc's own ends differ from P and Q by rounding).
  approximate(arc, OffsetFit::greedy, raw);
}

}  // namespace casteljau::detail::offset
