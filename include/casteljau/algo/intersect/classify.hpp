// Intersection engine, touch and tangent classification (algo/intersect.hpp): the touch
// of a near region (the peak of the separation between two crossings), and the kind of
// each kept point (crossing or tangent, touches polished).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/near.hpp"

namespace casteljau::detail::isect {

/// The sine of the angle between unit tangents below which a common point counts as a
/// touch rather than a crossing when merging points of one near region: 64 eps, the
/// rounding of the cross product of two unit vectors computed from the curves (a few eps
/// each) with margin. Crossings of a touch region meet at angles of about sqrt(K tol)
/// (1e-6 or more at tol = 1e-10, K ~ 1), far above it.
template <class T>
inline constexpr T crossing_noise = 64 * std::numeric_limits<T>::epsilon();

/// The parameters of a touch region's ends: common points (ta0, tb0) and (ta1, tb1) of
/// curves a and b, ta0 <= ta1, between which the curves stay within the near-miss distance
/// (unwrapped round the closing point of a closed curve: ta1 may exceed its domain).
template <class T>
struct TouchSpan {
  T ta0, tb0, ta1, tb1;
};

/// The touch of curves a and b in a touch region (two crossings at a tiny angle, or points
/// near a touch): where the curves are closest, or farthest apart between two crossings,
/// i.e. the extremum of the signed separation of a(s) from b. Its derivative along a is
/// a'(s) . n_b at the foot of a(s) on b, so the touch is the root of g(s) = u_a(s) x u_b(t(s))
/// (unit tangents, t(s) the foot: tangents parallel). g changes sign between two crossings
/// (a passes b one way, then back), so the root is bracketed by the span's ends: regula
/// falsi with the Illinois modification [DowellJarratt71] to the resolution of the
/// parameters, at most 100 steps (a few tens). A simple root where the curvatures differ:
/// located to about eps over the difference of the curvatures (what polish_touch reaches).
/// Nothing when g does not change sign over the span or vanishes (to crossing_noise) at an
/// end, or when the touch is farther apart than tol.
template <class T>
std::optional<Hit<T>> touch_in(const Pieces<T, 2>& ca, const Prepared<T>& A, const Loop<T>& la, const Pieces<T, 2>& cb,
                               const Prepared<T>& B, const Loop<T>& lb, const TouchSpan<T>& span, T tol) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  auto foot = [&](T s) {
    // b's parameter interpolated along the span: the start of the foot's Newton steps.
    const T f = span.ta1 > span.ta0 ? (s - span.ta0) / (span.ta1 - span.ta0) : T(0.5);
    return foot_near(cb, B, unit_at(ca, A, la.wrap(s)), lb.wrap(span.tb0 + f * (span.tb1 - span.tb0)));
  };
  auto g = [&](T s) { return cross(direction_at(ca, A, la.wrap(s)), direction_at(cb, B, foot(s).t)); };
  T lo = span.ta0, hi = span.ta1, glo = g(lo), ghi = g(hi);
  T s = lo;
  // Ends where the tangents are parallel to rounding (a touch found as such, not a
  // crossing) bracket nothing.
  if (!(std::abs(glo) > crossing_noise<T>) || !(std::abs(ghi) > crossing_noise<T>) || (glo > 0) == (ghi > 0) || !(hi > lo)) {
    return std::nullopt;
  } else {
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 4 * eps * std::max(T(1), std::abs(lo)); ++it) {
      T m = (lo * ghi - hi * glo) / (ghi - glo);
      if (!(m > lo && m < hi)) m = lo + (hi - lo) / 2;
      const T gm = g(m);
      if (gm == 0) {
        lo = hi = m;
        break;
      }
      if ((gm > 0) == (ghi > 0)) {
        hi = m;
        ghi = gm;
        if (side == 1) glo /= 2;
        side = 1;
      } else {
        lo = m;
        glo = gm;
        if (side == -1) ghi /= 2;
        side = -1;
      }
    }
    s = std::abs(glo) <= std::abs(ghi) ? lo : hi;
  }
  const Foot<T> ft = foot(s);
  if (!(ft.distance <= tol)) return std::nullopt;
  s = la.wrap(s);
  const auto a = ca.locate(s), b = cb.locate(ft.t);
  return Hit<T>{s, ft.t, a.index, b.index, a.t, b.t, ft.distance, true};
}

/// Phase 7: the kept points as the answer's points, sorted by ta: each point's position
/// (piece a's value), and its kind. A point is tangent if it was merged into a touch or
/// its tangents are within 1e-6 (sine); a point whose tangents are within 1e-4 is
/// polished as a touch first (polish_touch: a touch located as a double root is off by up
/// to sqrt(eps / curvature)), and one that polishes onto a touch already listed is
/// dropped. A curve that is a point has no direction: its meeting with another is a
/// crossing.
template <class T>
std::vector<CurveIntersection<T>> classify(const Prepared<T>& A, const Prepared<T>& B, const std::vector<Hit<T>>& kept, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  std::vector<CurveIntersection<T>> points;
  for (auto h : kept) {
    Vector<T, 2> da = direction(A.unit[h.pa], h.sa), db = direction(B.unit[h.pb], h.sb);
    // A curve that is a point has no direction: its meeting with another is a crossing.
    bool tangent = h.touch || (norm(da) > 0 && norm(db) > 0 && std::abs(cross(da, db)) <= T(1e-6));
    // A touch located as a double root (to sqrt(eps / curvature): 1e-8 off on a Chebyshev
    // polynomial of degree 12, where its tangent already turned by 4e-6) or as a minimum of
    // a band's separation: polished where the tangents are parallel and the curves within
    // the near-miss distance (polish_touch, within 1e-5 in both parameters); then it is the
    // touch, and tangent. A second point polished onto the same touch is not listed again.
    if (!tangent && norm(da) > 0 && norm(db) > 0 && std::abs(cross(da, db)) <= T(1e-4)) {
      const Arc<T> aa{h.pa, T(0), T(1)}, ab{h.pb, T(0), T(1)};
      if (auto p = polish_touch(A.unit[h.pa], aa, B.unit[h.pb], ab, Refined<T>{h.sa, h.sb, h.distance}, tol)) {
        h.sa = p->s;
        h.sb = p->t;
        h.ta = ca.lift(h.pa, p->s);
        h.tb = cb.lift(h.pb, p->t);
        da = direction(A.unit[h.pa], h.sa);
        db = direction(B.unit[h.pb], h.sb);
        tangent = std::abs(cross(da, db)) <= T(1e-6);
        const T ma = T(merge_fraction) * break_length(ca, h.pa), mb = T(merge_fraction) * break_length(cb, h.pb);
        if (tangent && std::any_of(points.begin(), points.end(), [&](const CurveIntersection<T>& x) {
              return std::abs(x.ta - h.ta) <= ma && std::abs(x.tb - h.tb) <= mb;
            }))
          continue;
      }
    }
    points.push_back({h.ta, h.tb, std::visit([&](const auto& x) { return x(h.sa); }, ca.segments()[h.pa]),
                          tangent ? IntersectionKind::tangent : IntersectionKind::crossing});
  }
  std::sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
  return points;
}

}  // namespace casteljau::detail::isect
