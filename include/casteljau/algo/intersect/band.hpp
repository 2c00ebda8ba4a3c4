// The band step of the general intersection engine (algo/intersect.hpp): a pair of
// near-coincident parts (tangents within band_angle of one direction, curves within
// about 1e-7 of each other) decided at once from the polynomial of their separation
// instead of subdivided down to the near-miss distance. See band() and docs/accuracy.md
// ("Near-coincident curves (bands)").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "casteljau/algo/flatten.hpp"
#include "casteljau/algo/intersect/common.hpp"
#include "casteljau/basis/bernstein_poly.hpp"
#include "casteljau/basis/roots.hpp"

namespace casteljau::detail::isect {

/// Bernstein coefficients on [0, 1] of a part c(u) = (X(u), Y(u)) / W(u): W = {1} for a
/// polynomial part, the weights scaled to at most 1 for a rational one.
template <class T>
struct Homogeneous {
  std::vector<T> x, y, w;
};
template <class T>
Homogeneous<T> homogeneous(const Bezier<T, 2>& c) {
  Homogeneous<T> h;
  for (const auto& p : c.points()) {
    h.x.push_back(p[0]);
    h.y.push_back(p[1]);
  }
  h.w = {T(1)};
  return h;
}
template <class T>
Homogeneous<T> homogeneous(const RationalBezier<T, 2>& c) {
  Homogeneous<T> h;
  const auto& P = c.points();
  const auto& w = c.weights();
  const T wmax = *std::max_element(w.begin(), w.end());
  for (std::size_t i = 0; i < P.size(); ++i) {
    const T wi = w[i] / wmax;
    h.x.push_back(wi * P[i][0]);
    h.y.push_back(wi * P[i][1]);
    h.w.push_back(wi);
  }
  return h;
}

/// The numerator Q = X' W - X W' of the derivative c' = Q / W^2 (X' for a polynomial).
template <class T>
std::array<std::vector<T>, 2> hodograph_numerator(const Homogeneous<T>& h) {
  if (h.w.size() == 1) return {bernstein_derivative_coefficients<T>(h.x), bernstein_derivative_coefficients<T>(h.y)};
  const std::vector<T> dw = bernstein_derivative_coefficients<T>(h.w);
  auto one = [&](const std::vector<T>& x) {
    return bernstein_difference<T>(bernstein_product<T>(bernstein_derivative_coefficients<T>(x), h.w), bernstein_product<T>(x, dw));
  };
  return {one(h.x), one(h.y)};
}

/// Largest angle (radians) between a band's direction e and a tangent of either part.
/// Within it, e . c(u) is monotone along both parts, and along a stretch of arc length L
/// the curves advance by at least cos(2 band_angle) L = 0.98 L along any tangent of theirs.
inline constexpr double band_angle = 0.1;
/// Highest degree a band takes (its separation polynomial has degree 2 n - 1, about 4 n
/// for rational pieces): above it, plain subdivision. Above the command line's limit
/// (500): bands cost O(n^2) per node, and near-coincident curves of degree 30 / 80 turned
/// by 1e-9 take 9 / 88 ms with them, 6.6 / 33 s without; random pairs of degree 200 to
/// 500 cost the same either way (bands seldom apply to them).
inline constexpr int band_max_degree = 512;

/// Bounds of a part h whose tangents lie within band_angle of e: a bound of its curvature
/// (|c''| / |c'|^2, from the convex hulls of Q, Q', W and W'), and min e . Q, max |Q|.
/// Nothing when a tangent may leave the cone.
template <class T>
struct PartBounds {
  T curvature, q_along, q_max;
};
template <class T>
std::optional<PartBounds<T>> part_bounds(const Homogeneous<T>& h, const Vector<T, 2>& e) {
  const auto q = hodograph_numerator(h);
  const T slope = std::tan(T(band_angle));
  T q_along = std::numeric_limits<T>::infinity(), q_max = 0;
  for (std::size_t i = 0; i < q[0].size(); ++i) {
    const Vector<T, 2> v{q[0][i], q[1][i]};
    const T along = dot(e, v);
    if (!(along > 0) || !(std::abs(cross(e, v)) <= slope * along)) return std::nullopt;
    q_along = std::min(q_along, along);
    q_max = std::max(q_max, norm(v));
  }
  T q2_max = 0;
  if (q[0].size() > 1) {
    const auto dx = bernstein_derivative_coefficients<T>(q[0]), dy = bernstein_derivative_coefficients<T>(q[1]);
    for (std::size_t i = 0; i < dx.size(); ++i) q2_max = std::max(q2_max, norm(Vector<T, 2>{dx[i], dy[i]}));
  }
  const T w_min = *std::min_element(h.w.begin(), h.w.end()), w_max = *std::max_element(h.w.begin(), h.w.end());
  const T w1_max = h.w.size() > 1 ? casteljau::detail::max_abs<T>(std::span<const T>(bernstein_derivative_coefficients<T>(h.w))) : T(0);
  // c' = Q / W^2 and c'' = (Q' W - 2 Q W') / W^3.
  const T speed = q_along / (w_max * w_max), accel = (q2_max * w_max + 2 * q_max * w1_max) / (w_min * w_min * w_min);
  if (!(speed > 0) || !(w_min > 0)) return std::nullopt;
  return PartBounds<T>{accel / (speed * speed), q_along, q_max};
}

/// The parameter in [lo, hi] of piece c where e . c = X, when e . c is monotone there
/// (either way): Newton's method kept inside the bracket (bisection when it leaves it);
/// the nearer end when X is outside the range.
template <class T>
T solve_projection(const FootEval<T>& c, const Vector<T, 2>& e, T X, T lo, T hi) {
  auto f = [&](T u) { return dot(e, c.at(u).to_vector()) - X; };
  T flo = f(lo), fhi = f(hi);
  if (flo == 0) return lo;
  if (fhi == 0) return hi;
  if ((flo > 0) == (fhi > 0)) return std::abs(flo) <= std::abs(fhi) ? lo : hi;
  T u = lo - flo * (hi - lo) / (fhi - flo);  // the secant's first guess
  for (int it = 0; it < 200 && hi - lo > 4 * std::numeric_limits<T>::epsilon() * std::max(T(1), std::abs(hi)); ++it) {
    const T m = u > lo && u < hi ? u : lo + (hi - lo) / 2;
    const T fm = f(m);
    if (fm == 0) return m;
    const T slope = dot(e, c.d(m));
    u = slope != 0 ? m - fm / slope : m;
    if (std::abs(u - m) <= 2 * std::numeric_limits<T>::epsilon() * std::max(T(1), std::abs(m))) return m;
    if ((fm > 0) == (flo > 0)) {
      lo = m;
      flo = fm;
    } else {
      hi = m;
      fhi = fm;
    }
  }
  return std::abs(flo) <= std::abs(fhi) ? lo : hi;
}

/// The part of piece c on [lo, hi] as a piece of its own on [0, 1], reversed if asked.
template <class T>
Piece<T> piece_part(const Piece<T>& c, T lo, T hi, bool reversed) {
  return std::visit(
      [&](const auto& x) -> Piece<T> {
        auto p = part(x, lo, hi);
        if (reversed) return p.reverse();
        return p;
      },
      c);
}

/// What band() made of a pair of parts.
enum class BandResult {
  done,     ///< the pair is decided (seeds emitted, or none)
  no,       ///< not a band here; smaller parts may be
  too_far,  ///< the curves are too far apart for the bound (E > 0.05 tol): plain subdivision below
  too_long, ///< a core, extended over the other part's range, leaves the cone: split the longer part
};

/// Near-coincident parts a on [alo, ahi] and b on [blo, bhi] (piece parameters) of the
/// arcs in ctx, decided at once (done) instead of subdivided down to the near-miss
/// distance; otherwise plain subdivision goes on (trying bands again below unless the
/// curves are too far apart for the bound: their matched difference D hardly shrinks
/// with the parts, and a failed attempt costs about as much as 20 subdivision steps;
/// halving the longer part first when a core, extended over the other part's range,
/// leaves the cone: too_long).
///
/// Applies when every tangent of both parts lies within band_angle of one direction e (b
/// possibly running the other way) and the curves are close: both parts are extended
/// along their arcs to a common range [X0, X1] of x = e . p (cores A(u), B(u), u in [0, 1],
/// matched at the ends), and the separation of A(u) from the curve b is the signed
/// distance beta(u) of A(u) from the tangent of b at B(u), up to E = 4.5 K |D|^2 (K a
/// curvature bound of b there, D = A - B: the foot of A(u) on b lies within 3 |D| of B(u)
/// along b, where b stays within K (3 |D|)^2 / 2 of its tangent; farther points advance
/// by more than 0.98 of their arc length). With A = (X, Y) / W, B' = Q / W_B^2:
///   beta(u) = h(u) / (W_A W_B |Q|)(u),  h = Q x (X_A W_B - X_B W_A),
/// a polynomial h in Bernstein form. Decisions, all from h:
///  - sign changes of h (its roots): crossings; local minima of |h| where |beta| may be
///    within tol: touches (the refinement then finds the closest approach); an arc end
///    where |beta| may be within 2.5 tol (a part beyond the other arc's end may come
///    within tol of it only there): an edge seed (the curves may meet at the arc end,
///    or the near region continue into the next arc: solve() decides which);
///  - h within tol everywhere: the parts may overlap (ctx.near: the overlap test runs).
/// Seeds are kept only where both parameters lie in the parts, to the rounding of the
/// roots (neighbouring pairs of parts see the rest). Requires E <= 0.05 tol (curves within
/// about 1e-7 of each other) and degrees up to band_max_degree. Cost: a few products and
/// two root solves of polynomials of degree 2 n - 1 (4 n - 1 for rational parts),
/// independent of how close the curves run: a cubic and its copy 2e-10 of its size away
/// take a few band nodes where subdivision took 10^5 parts. [SederbergNishita90 for the
/// fat-line form of the separation; the bound is ours.]
template <class T, class CA, class CB>
BandResult band(const CA& a, T alo, T ahi, const CB& b, T blo, T bhi, Context<T>& ctx) {
  if (!ctx.a || !ctx.b || !ctx.fa || !ctx.fb) return BandResult::no;
  const int na = static_cast<int>(a.points().size()) - 1, nb = static_cast<int>(b.points().size()) - 1;
  if (na > band_max_degree || nb > band_max_degree) return BandResult::no;
  const auto ka = tangent_cone(a), kb = tangent_cone(b);
  if (!ka || !kb || ka->hi - ka->lo > T(band_angle) || kb->hi - kb->lo > T(band_angle)) return BandResult::no;
  const T mid = (ka->lo + ka->hi) / 2;
  const Vector<T, 2> r = ka->ref / norm(ka->ref);
  const Vector<T, 2> e{std::cos(mid) * r[0] - std::sin(mid) * r[1], std::sin(mid) * r[0] + std::cos(mid) * r[1]};
  const bool reversed = dot(e, kb->ref) < 0;
  const Piece<T>& pa = *ctx.a;
  const Piece<T>& pb = *ctx.b;
  const Arc<T>& ra = *ctx.ra;
  const Arc<T>& rb = *ctx.rb;
  // Projections on e through the pieces' evaluators (O(n) past degree 32: about n eps of
  // the unit coordinates, far below the near-miss distance the decisions below rest on).
  const FootEval<T>& fa = *ctx.fa;
  const FootEval<T>& fb = *ctx.fb;
  auto xa = [&](T u) { return dot(e, fa.at(u).to_vector()); };
  auto xb = [&](T v) { return dot(e, fb.at(v).to_vector()); };
  const T xa0 = xa(alo), xa1 = xa(ahi);
  // b's parameters at its low and high x end.
  const T b_low = reversed ? bhi : blo, b_high = reversed ? blo : bhi;
  const T b_arc_low = reversed ? rb.hi : rb.lo, b_arc_high = reversed ? rb.lo : rb.hi;
  const T xb0 = xb(b_low), xb1 = xb(b_high);
  if (!(xa0 < xa1) || !(xb0 < xb1)) return BandResult::no;
  // The arcs' own x ranges bound the common range below (when x is monotone along them;
  // when not, the cores' cone test below fails anyway): nothing to extend to when they
  // barely overlap, as for consecutive arcs of one curve meeting end to end.
  const T width = std::max(xa1 - xa0, xb1 - xb0);
  if (!(std::min(xa(ra.hi), xb(b_arc_high)) - std::max(xa(ra.lo), xb(b_arc_low)) > T(1e-10) * width)) return BandResult::no;
  // Both parts extended along their arcs over the union of their x ranges, then the
  // common range of the extensions.
  const T U0 = std::min(xa0, xb0), U1 = std::max(xa1, xb1);
  const T ea0 = U0 < xa0 ? solve_projection(fa, e, U0, ra.lo, alo) : alo;
  const T ea1 = U1 > xa1 ? solve_projection(fa, e, U1, ahi, ra.hi) : ahi;
  const T eb0 = U0 < xb0 ? solve_projection(fb, e, U0, std::min(b_arc_low, b_low), std::max(b_arc_low, b_low)) : b_low;
  const T eb1 = U1 > xb1 ? solve_projection(fb, e, U1, std::min(b_arc_high, b_high), std::max(b_arc_high, b_high)) : b_high;
  const T X0 = std::max(xa(ea0), xb(eb0)), X1 = std::min(xa(ea1), xb(eb1));
  // A common range at the rounding of the parts' extent: parts that only touch end to end
  // (consecutive arcs of one curve), left to subdivision.
  if (!(X1 - X0 > T(1e-10) * width)) return BandResult::no;
  const T ca0 = xa(ea0) >= X0 ? ea0 : solve_projection(fa, e, X0, ea0, ea1);
  const T ca1 = xa(ea1) <= X1 ? ea1 : solve_projection(fa, e, X1, ea0, ea1);
  const T cb0 = xb(eb0) >= X0 ? eb0 : solve_projection(fb, e, X0, std::min(eb0, eb1), std::max(eb0, eb1));
  const T cb1 = xb(eb1) <= X1 ? eb1 : solve_projection(fb, e, X1, std::min(eb0, eb1), std::max(eb0, eb1));
  if (!(ca0 < ca1) || !(reversed ? cb1 < cb0 : cb0 < cb1)) return BandResult::no;
  // Cores (B oriented along e) and the span of b the bound must cover (core and part).
  const Piece<T> A = piece_part(pa, ca0, ca1, false);
  const Piece<T> B = piece_part(pb, std::min(cb0, cb1), std::max(cb0, cb1), reversed);
  const T sb0 = std::min({cb0, cb1, blo}), sb1 = std::max({cb0, cb1, bhi});
  const Homogeneous<T> HA = std::visit([](const auto& x) { return homogeneous(x); }, A);
  const Homogeneous<T> HB = std::visit([](const auto& x) { return homogeneous(x); }, B);
  const auto qb = part_bounds(HB, e);
  if (!qb || !part_bounds(HA, e)) return BandResult::too_long;
  const bool span_is_core = sb0 == std::min(cb0, cb1) && sb1 == std::max(cb0, cb1);
  const auto span_b =
      span_is_core ? qb : part_bounds(std::visit([](const auto& x) { return homogeneous(x); }, piece_part(pb, sb0, sb1, reversed)), e);
  if (!span_b) return BandResult::too_long;
  // D = R / (W_A W_B), R = X_A W_B - X_B W_A; h = Q x R.
  const auto rx = bernstein_difference<T>(bernstein_product<T>(HA.x, HB.w), bernstein_product<T>(HB.x, HA.w));
  const auto ry = bernstein_difference<T>(bernstein_product<T>(HA.y, HB.w), bernstein_product<T>(HB.y, HA.w));
  const auto q = hodograph_numerator(HB);
  const auto h = bernstein_difference<T>(bernstein_product<T>(q[0], ry), bernstein_product<T>(q[1], rx));
  const T wa_min = *std::min_element(HA.w.begin(), HA.w.end()), wa_max = *std::max_element(HA.w.begin(), HA.w.end());
  const T wb_min = *std::min_element(HB.w.begin(), HB.w.end()), wb_max = *std::max_element(HB.w.begin(), HB.w.end());
  T d_max = 0;
  for (std::size_t i = 0; i < rx.size(); ++i) d_max = std::max(d_max, norm(Vector<T, 2>{rx[i], ry[i]}));
  d_max /= wa_min * wb_min;
  const T E = T(4.5) * span_b->curvature * d_max * d_max;
  if (!(E <= T(0.05) * ctx.tol)) return BandResult::too_far;
  // |beta| >= |h| / den_hi everywhere; |beta| <= |h| / den_lo.
  const T den_hi = wa_max * wb_max * qb->q_max, den_lo = wa_min * wb_min * qb->q_along;
  const T near_hi = (ctx.tol + E) * den_hi;
  const T h_max = casteljau::detail::max_abs<T>(std::span<const T>(h));
  if (std::all_of(h.begin(), h.end(), [&](T c) { return c > T(2.5) * near_hi; }) ||
      std::all_of(h.begin(), h.end(), [&](T c) { return c < T(-2.5) * near_hi; }))
    return BandResult::done;  // apart by more than 2 tol all along: nothing (arc ends included)
  if (h_max <= (ctx.tol - E) * den_lo) ctx.near = true;
  // A first pass that stops on a near band (ctx.stop_on_near) drops its seeds: no roots.
  if (ctx.near && ctx.stop_on_near) return BandResult::done;
  // Membership of a seed in the parts, with a slack above the roots' accuracy: h is
  // rounded to about 32 eps max|Q| max|coordinate| (the cores' de Casteljau steps and the
  // products), so a root moves by that over |h'| (eps over the crossing angle: 1e-8 at an
  // angle of 1e-8), and neighbouring parts computing it differently must not both drop
  // it. The duplicates let through merge later (merge_fraction, or as one touch).
  T coordinate_max = 0;
  for (const auto* c : {&HA.x, &HA.y, &HB.x, &HB.y}) coordinate_max = std::max(coordinate_max, casteljau::detail::max_abs<T>(std::span<const T>(*c)));
  const T h_noise = 32 * std::numeric_limits<T>::epsilon() * coordinate_max * qb->q_max;
  const auto dh = bernstein_derivative_coefficients<T>(h);
  // Values of h and its derivatives at their roots: O(n) past degree 32 of the pieces (h has
  // degree 2 n - 1; its coefficients are |Q| |D| small, so n eps of them is far below
  // h_noise), de Casteljau below.
  const bool fast = fa.fast || fb.fast;
  auto value = [&](const std::vector<T>& c, T u) { return fast ? bernstein_value_fast<T>(std::span<const T>(c), u) : bernstein_value<T>(c, u); };
  auto emit = [&](T u, bool edge) {
    const T slope = std::abs(value(dh, u));
    const T du = slope > 0 ? std::min(T(1e-2), 2 * h_noise / slope) : T(1e-2);
    const T slack_a = std::max(T(1e-7), du * (ca1 - ca0)), slack_b = std::max(T(1e-7), du * std::abs(cb1 - cb0));
    // b's parameter where e . b = e . a(s) (b is monotone along e): within |beta| tan
    // band_angle of the foot of a(s) on b, while B(u) lags it by up to |D| (the cores are
    // matched at their ends only; D is not small against a line, whose curvature is 0).
    const T s = ca0 + u * (ca1 - ca0), t = solve_projection(fb, e, xa(s), std::min(cb0, cb1), std::max(cb0, cb1));
    if (s < alo - slack_a || s > ahi + slack_a || t < blo - slack_b || t > bhi + slack_b) return;
    ctx.seeds.push_back({std::clamp(s, ra.lo, ra.hi), std::clamp(t, rb.lo, rb.hi), edge});
  };
  // Roots of h closer than 1e-6 (of the core) are one crossing blurred by rounding (h
  // crosses zero at a slope of the crossing angle: at 1e-9 its rounding noise spans about
  // 1e-8 in u): the middle root of each cluster stands for it.
  const std::vector<T> roots = bernstein_roots<T>(h);
  constexpr T cluster = T(1e-6);
  for (std::size_t i = 0; i < roots.size();) {
    std::size_t j = i + 1;
    while (j < roots.size() && roots[j] - roots[j - 1] <= cluster) ++j;
    emit(roots[i + (j - i - 1) / 2], false);
    i = j;
  }
  auto near_root = [&](T u) {
    const auto it = std::lower_bound(roots.begin(), roots.end(), u);
    return (it != roots.end() && *it - u <= cluster) || (it != roots.begin() && u - *(it - 1) <= cluster);
  };
  if (h.size() > 2) {
    const auto d2h = bernstein_derivative_coefficients<T>(dh);
    for (T u : bernstein_roots<T>(dh)) {
      const T hu = value(h, u);
      // A local minimum of |h| (h'' of the sign of h) where the curves may be within tol,
      // deeper than the rounding of h below both ends of the core (a flat h, in a core
      // shorter than the curves' offset or along an overlap, has minima of noise only).
      const T depth = std::min(std::abs(h.front()), std::abs(h.back())) - std::abs(hu);
      if (std::abs(hu) <= near_hi && hu * value(d2h, u) >= 0 && !near_root(u) && depth > 4 * h_noise) emit(u, false);
    }
  }
  if ((ca0 == ra.lo || cb0 == b_arc_low) && std::abs(h.front()) <= T(2.5) * near_hi) emit(T(0), true);
  if ((ca1 == ra.hi || cb1 == b_arc_high) && std::abs(h.back()) <= T(2.5) * near_hi) emit(T(1), true);
  return BandResult::done;
}

}  // namespace casteljau::detail::isect
