// Intersection engine, near regions (algo/intersect.hpp): a curve's point and direction
// at its parameter, the foot of a point on it, its domain and closing point, and whether
// two curves stay within the near-miss distance beyond a common point.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "casteljau/algo/intersect/refine.hpp"

namespace casteljau::detail::isect {

/// Common points closer than this fraction of their pieces' parameter intervals (in
/// both parameters) are one point: touches are located to about sqrt(eps) ~ 1e-8, so a
/// touch found from several seeds or from two arcs meeting at it is reported once.
inline constexpr double merge_fraction = 1e-6;

/// The unit-frame point of a curve at its parameter g (pieces chosen as evaluation does).
template <class T>
Point<T, 2> unit_at(const Pieces<T, 2>& c, const Prepared<T>& P, T g) {
  const auto [p, t] = c.locate(g);
  return at(P.unit[p], t);
}

/// The foot of q on curve c near its parameter t (unit frame): Newton's method on
/// (c(t) - q) . c'(t) from t, over the pieces, within the domain; the parameter of the
/// least distance seen and that distance (an upper bound of the distance to the curve,
/// exact at a converged foot point).
template <class T>
struct Foot {
  T t, distance;
};
template <class T>
Foot<T> foot_near(const Pieces<T, 2>& c, const Prepared<T>& P, const Point<T, 2>& q, T t) {
  const Interval<T> dom = c.domain();
  Foot<T> best{t, std::numeric_limits<T>::infinity()};
  for (int it = 0; it < 12; ++it) {
    const auto [p, s] = c.locate(t);
    const T k = c.parameter_scale(p);
    const Point<T, 2> x = at(P.unit[p], s);
    const Vector<T, 2> e = x - q, d1 = k * derivative(P.unit[p], s), d2 = (k * k) * derivative(P.unit[p], s, 2);
    if (norm(e) < best.distance) best = {t, norm(e)};
    const T den = dot(d1, d1) + dot(e, d2);
    if (!(den > 0)) break;
    const T t2 = std::clamp(t - dot(e, d1) / den, dom.lo, dom.hi);
    if (t2 == t) break;
    t = t2;
  }
  return best;
}

/// The distance from q to curve c near its parameter t (see foot_near).
template <class T>
T distance_near(const Pieces<T, 2>& c, const Prepared<T>& P, const Point<T, 2>& q, T t) {
  return foot_near(c, P, q, t).distance;
}

/// The unit direction of curve c at its parameter g (pieces chosen as evaluation does).
template <class T>
Vector<T, 2> direction_at(const Pieces<T, 2>& c, const Prepared<T>& P, T g) {
  const auto [p, t] = c.locate(g);
  return direction(P.unit[p], t);
}

/// A curve's domain and whether the curve is closed (its ends within the near-miss
/// distance): on a closed curve the way between two parameters may pass its closing point.
template <class T>
struct Loop {
  Interval<T> dom;
  bool closed = false;
  /// The difference d of two parameters, the short way round a closed curve.
  T shortest(T d) const {
    const T L = dom.length();
    return closed && std::abs(d) > L / 2 ? d - std::copysign(L, d) : d;
  }
  /// A parameter up to one length beyond the domain of a closed curve, brought back in.
  T wrap(T t) const {
    if (!closed) return t;
    return t < dom.lo ? t + dom.length() : t > dom.hi ? t - dom.length() : t;
  }
};

/// Whether curves a and b, common at (ta, tb) (the end of an overlap), are still within
/// tol of each other beyond it: at a(ta + k da) against b near tb + k db (da, db the
/// overlap's extent, signed towards the outside; k = 1, or less where a domain ends
/// sooner). False when a curve ends within a quarter of the overlap's extent or turns
/// back there.
template <class T>
bool near_beyond(const Pieces<T, 2>& ca, const Prepared<T>& A, const Pieces<T, 2>& cb, const Prepared<T>& B, T ta, T tb, T da, T db,
                 T tol) {
  const Interval<T> dom_a = ca.domain(), dom_b = cb.domain();
  auto room = [](const Interval<T>& dom, T t, T d) {
    if (d == 0) return std::numeric_limits<T>::infinity();
    return (d > 0 ? dom.hi - t : t - dom.lo) / std::abs(d);
  };
  const T k = std::min({T(1), room(dom_a, ta, da), room(dom_b, tb, db)});
  if (!(k >= T(0.25))) return false;
  const T ta2 = std::clamp(ta + k * da, dom_a.lo, dom_a.hi), tb2 = std::clamp(tb + k * db, dom_b.lo, dom_b.hi);
  // A curve that turns back at the end (a fold: a curve running over itself along a line)
  // does not continue the overlap, whatever its points.
  if (dot(direction_at(ca, A, ta - da / 64), direction_at(ca, A, ta + k * da / 64)) < 0 ||
      dot(direction_at(cb, B, tb - db / 64), direction_at(cb, B, tb + k * db / 64)) < 0)
    return false;
  return distance_near(cb, B, unit_at(ca, A, ta2), tb2) <= tol;
}

/// The parameter length of piece i of c (the scale of the merge distances).
template <class T>
T break_length(const Pieces<T, 2>& c, std::size_t i) {
  return c.segment_domain(i).length();
}

}  // namespace casteljau::detail::isect
