// The near-optimal flattening of plane lines, quadratics and cubics after Levien's
// analytic flattening [Levien19]: the count planned first, each vertex placed from it
// alone and checked in O(1), no allocation. The scalar walk for any scalar type; for
// double, flatten() calls the walk compiled in src/flatten with the lane kernels of the
// instruction set chosen at run time (docs/decisions/0004, 0006).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "casteljau/algo/flatten/common.hpp"
#include "casteljau/algo/flatten/plane_plan.hpp"
#include "casteljau/algo/flatten/small_piece.hpp"

namespace casteljau::detail {

/// Roots of c0 + c1 x + c2 x^2 in the open interval (0, 1), stable form (no
/// cancellation between -c1 and the square root); at most two, written to r.
template <class T>
inline int unit_quadratic_roots(T c0, T c1, T c2, T* r) {
  int n = 0;
  if (c2 == 0) {
    if (c1 != 0) {
      const T x = -c0 / c1;
      if (x > 0 && x < 1) r[n++] = x;
    }
    return n;
  }
  const T disc = c1 * c1 - 4 * c2 * c0;
  if (!(disc >= 0)) return 0;
  const T q = -(c1 + std::copysign(std::sqrt(disc), c1)) / 2;
  const T x = q / c2;
  if (x > 0 && x < 1) r[n++] = x;
  if (q != 0) {
    const T y = c0 / q;
    if (y > 0 && y < 1) r[n++] = y;
  }
  return n;
}

/// Result of small_chord_check: the squared deviation bound dev2 and the squared limit
/// lim, both times |chord|^2 (so no division or square root is needed to compare them).
template <class T>
struct SmallChordCheck {
  T dev2 = std::numeric_limits<T>::infinity();
  T lim = 0;
  bool ok = false;
};

/// The distance from the plane sub-arc of a polynomial piece of degree <= 3 over a
/// parameter step h to its chord segment, from its end points A, E and end derivatives
/// dA, dE alone: on the step the sub-arc is the cubic with Bézier points A, A + dA h/3,
/// E - dE h/3, E (exactly, in real arithmetic, for degree <= 3). With v = E - A, its
/// signed distance to the chord's line times |v| is D(u) = 3 d1 u (1-u)^2 + 3 d2 u^2 (1-u)
/// (d1, d2 the cross products of v with the inner points' offsets; zero at both ends),
/// and its projection on v is P(u) = 3 p1 u (1-u)^2 + 3 p2 u^2 (1-u) + |v|^2 u^3.
/// - When 0 <= p1, p2 <= |v|^2 the whole sub-arc projects inside the chord (convex hull)
///   and its distance to the segment is |D| / |v|; else the overshoot beyond the ends,
///   `over` = the largest of -P and P - |v|^2 at the roots of P' (closed form), bounds
///   the extra distance: distance <= sqrt(max D^2 + over^2) / |v| (exact when over = 0).
/// - Two cheap bounds of max |D|: 3/4 max(|d1|, |d2|) (u (1-u) <= 1/4), and, writing
///   (1-u) d1 + u d2 = m + (u - 1/2) (d2 - d1) with m the mean, 3/4 |m| + |d2 - d1| / (4
///   sqrt 3) (max of u (1-u) |u - 1/2| is 1 / (12 sqrt 3); 0.1444 rounds 0.14434 up). Both
///   are tight when d1 = d2 (a parabola's sub-arc), the second over by about |d2 - d1| / 7
///   otherwise. When the smaller does not pass, max |D| exactly from the roots of D' (a
///   quadratic, closed form).
/// A guaranteed check up to rounding of a few eps of the unit-scale coordinates. Fails
/// (ok = false, dev2 = inf) for a zero chord.
template <class T>
inline SmallChordCheck<T> small_chord_check(T h, const Point<T, 2>& A, const Vector<T, 2>& dA, const Point<T, 2>& E,
                                            const Vector<T, 2>& dE, T tol2) {
  SmallChordCheck<T> r;
  const Vector<T, 2> v = E - A;
  const T L2 = dot(v, v);
  if (!(L2 > 0)) return r;
  const T h3 = h / 3;
  const T d1 = cross(v, dA) * h3, d2 = -cross(v, dE) * h3;
  const T p1 = dot(v, dA) * h3, p2 = L2 - dot(v, dE) * h3;
  T over = 0;
  if (!(p1 >= 0 && p1 <= L2 && p2 >= 0 && p2 <= L2)) {
    // P(u) = c1 u + c2 u^2 + c3 u^3 (power form of the Bernstein form above).
    const T c1 = 3 * p1, c2 = 3 * p2 - 6 * p1, c3 = 3 * p1 - 3 * p2 + L2;
    T x[2];
    const int n = unit_quadratic_roots(c1, 2 * c2, 3 * c3, x);
    for (int i = 0; i < n; ++i) {
      const T p = ((c3 * x[i] + c2) * x[i] + c1) * x[i];
      over = std::max({over, -p, p - L2});
    }
  }
  r.lim = tol2 * L2;
  const T b = std::min(T(0.75) * std::max(std::abs(d1), std::abs(d2)), T(0.375) * std::abs(d1 + d2) + T(0.1444) * std::abs(d2 - d1));
  r.dev2 = b * b + over * over;
  if (!(r.dev2 <= r.lim)) {
    // D(u) = c1 u + c2 u^2 + c3 u^3, its extremes at the roots of D' in (0, 1).
    const T c1 = 3 * d1, c2 = 3 * (d2 - 2 * d1), c3 = 3 * (d1 - d2);
    T x[2];
    const int n = unit_quadratic_roots(c1, 2 * c2, 3 * c3, x);
    T maxD = 0;
    for (int i = 0; i < n; ++i) maxD = std::max(maxD, std::abs(((c3 * x[i] + c2) * x[i] + c1) * x[i]));
    r.dev2 = maxD * maxD + over * over;
  }
  r.ok = r.dev2 <= r.lim;
  return r;
}

/// (num / den)^(1/4), the factor that scales a step whose deviation is sqrt(den) to
/// sqrt(num) (a short chord's deviation grows as the square of its step), clamped to
/// [1/4, 4]. Near 1 (ratio within [1/2, 2]) by its Padé form (3 den + 5 num) / (5 den +
/// 3 num), exact to 0.6% there and free of square roots (the steps are only predictions:
/// every step is checked).
template <class T>
inline T step_factor(T num, T den) {
  if (num <= 2 * den && 2 * num >= den) return (3 * den + 5 * num) / (5 * den + 3 * num);
  const T f = std::sqrt(std::sqrt(num / den));
  if (!(f >= T(0.25))) return f > T(4) ? T(4) : T(0.25);  // NaN (0 / 0) shrinks
  return std::min(f, T(4));
}

/// The near-optimal count of a plane polynomial piece of degree <= 3 (on the unit-scale
/// copy) and its spans, told before any vertex is placed: F = integral of the density
/// sqrt(|B' x B''| / |B'|) dt / sqrt(8 tol) (flatten_density), n = ceil(s F) with the
/// safety factor s = 1 for one parabola and 1.02 for sampled cells (so that about 95%
/// of the steps pass their check as placed, with the count still about 1.04x the
/// near-optimal greedy count on random cubics; see docs/accuracy.md). Two forms:
/// - the cubic term negligible (|a3| <= tol: quadratics, font outlines' elevated
///   quadratics): one parabola, with B' and B'' of t = 1/2 (the piece itself for a
///   quadratic), mapped to y = x^2 [Levien19]: x = (B' . B'') / (2 B' x B'') is linear in t
///   and lengths scale by 2 (B' x B'')^2 / |B''|^3, so the count is sqrt(scale / tol) / 2
///   |I(x1) - I(x0)| in closed form (parabola_integral);
/// - else the density at two Gauss-Legendre nodes in each of optimal_cells equal cells
///   (exact for a density linear across the cell; the density is integrable at a cusp,
///   where the checks correct the placement).
/// Throws NumericalError past 2^26 segments.
template <class T>
void small_optimal_plan(const SmallPiece<T, 2>& s, T tol, SmallOptimalPlan<T>& plan) {
  using V = Vector<T, 2>;
  plan.a0 = s.q[0];
  plan.a1 = V{}, plan.a2 = V{}, plan.a3 = V{};
  if (s.m == 2) {
    plan.a1 = s.q[1] - s.q[0];
  } else if (s.m == 3) {
    plan.a1 = T(2) * (s.q[1] - s.q[0]);
    plan.a2 = (s.q[2] - s.q[1]) - (s.q[1] - s.q[0]);
  } else {
    plan.a1 = T(3) * (s.q[1] - s.q[0]);
    plan.a2 = T(3) * ((s.q[2] - s.q[1]) - (s.q[1] - s.q[0]));
    plan.a3 = (s.q[3] - s.q[0]) - T(3) * (s.q[2] - s.q[1]);
  }
  const V a1 = plan.a1, a2 = plan.a2, a3 = plan.a3;
  plan.sampled = s.m == 4 && !(dot(a3, a3) <= tol * tol);
  plan.closed = false;
  T F = 0;
  if (plan.sampled) {
    const T h = T(1) / static_cast<T>(optimal_cells);
    const T g = h * T(0.28867513459481287);  // the nodes at h (1/2 -+ 1 / (2 sqrt 3)) in each cell
    T rho[2 * optimal_cells];
    for (int j = 0; j < 2 * optimal_cells; ++j) {
      const T t = h * static_cast<T>(j >> 1) + h / 2 + ((j & 1) ? g : -g);
      const T ux = (3 * a3[0] * t + 2 * a2[0]) * t + a1[0], uy = (3 * a3[1] * t + 2 * a2[1]) * t + a1[1];
      const T wx = 6 * a3[0] * t + 2 * a2[0], wy = 6 * a3[1] * t + 2 * a2[1];
      const T c = std::abs(ux * wy - uy * wx), n2 = ux * ux + uy * uy;
      // |c|^(1/2) n2^(-1/4) with no division or square root (24 of each per cubic were
      // about a quarter of the method's time): fast_rsqrt and fast_rqrt4 (relative error
      // below 2e-5, which moves the count by as much, the checks keep the guarantee).
      // A vanishing or denormal speed (a cusp) gets density 0, as 0 / 0 did.
      rho[j] = n2 > T(1e-280) ? c * fast_rsqrt(c) * fast_rqrt4(n2) : T(0);
    }
    const T scale = h / 2 / std::sqrt(8 * tol), inv_scale = 1 / scale;
    T sum[optimal_cells];
    for (int i = 0; i < optimal_cells; ++i) {
      // density mean + slope (x - 1/2) across the cell: slope from the nodes 1 / sqrt 3
      // apart. Selections, not branches, and the divisions side by side (they vectorise).
      sum[i] = rho[2 * i] + rho[2 * i + 1];
      const bool some = sum[i] > 0;
      const T r = (some ? T(1) : T(0)) / (some ? sum[i] : T(1));
      plan.slope[i] = std::clamp(T(2 * 1.7320508075688772) * (rho[2 * i + 1] - rho[2 * i]) * r, T(-2), T(2));
      plan.inv[i] = r * inv_scale;  // 1 / (f1 - f0) up to rounding
    }
    for (int i = 0; i < optimal_cells; ++i) {
      plan.f0[i] = F;
      F += sum[i] * scale;
      plan.f1[i] = F;
    }
  } else {
    CountSpan<T>& p = plan.span;
    p.a0 = p.da = p.x0 = p.sx = 0;
    const V b2 = T(3) * a3 + T(2) * a2;                        // B''(1/2)
    const V d1 = (T(0.75) * a3 + a2) + a1 - T(0.5) * b2;      // B'(1/2) - B''(1/2) / 2: the parabola's B'(0)
    const T c = cross(d1, b2), w2 = dot(b2, b2), dd = dot(d1, b2);
    if (c != 0 && w2 > 0) {
      const T r = 1 / (2 * c);
      const T xa = dd * r, xb = (dd + w2) * r;
      const T ia = parabola_integral(xa), ib = parabola_integral(xb);
      const T w32 = std::sqrt(w2) * std::sqrt(std::sqrt(w2));  // |B''|^(3/2)
      F = std::abs(c) * std::abs(ib - ia) / (std::sqrt(T(2)) * w32 * std::sqrt(tol));
      p.a0 = ia;
      p.da = ib - ia;
      p.x0 = xa;
      p.sx = xb != xa ? 1 / (xb - xa) : T(0);
      const T a3n = std::abs(a3[0]) + std::abs(a3[1]);  // >= |a3|
      // (|xa| + |xb - xa| <= 1e4: the rounding of x in the checks stays below 1e-11 relative)
      if (a3n <= T(1e-3) * tol && p.sx != 0 && std::abs(xa) + std::abs(xb - xa) <= T(1e4)) {
        const T scale = 2 * c * c / (w2 * std::sqrt(w2));
        // B - (the parabola) = a3 (t - 1/2)^3: both the arc and its chord move by at most
        // |a3| / 8, so the parabola's chords are held to tol - |a3| / 4, less 1e-9 tol for
        // rounding in these few operations.
        const T lim = tol * (1 - T(1e-9)) - a3n / 4;
        plan.closed = true;
        plan.scale2 = scale * scale;
        plan.xa = xa;
        plan.xspan = xb - xa;
        plan.lim2 = lim * lim;
      }
    }
  }
  plan.F = F;
  const T want = std::ceil((plan.sampled ? T(1.02) : T(1)) * F - T(1e-9));
  if (!(want <= T(max_piece_segments))) throw NumericalError("flatten: more than 2^26 segments for one piece");
  plan.n = std::max(1, static_cast<int>(want));
}

/// Whether the step [tp, tn] (0 <= tp < tn <= 1) of a piece whose plan is `closed` (one
/// parabola within 1e-3 tol of the piece) is within tol of its chord segment, in closed
/// form: on the parabola y = x^2 scaled by `scale`, the chord from xp to xn deviates most
/// by the vertical gap ((xn - xp) / 2)^2 over sqrt(1 + slope^2), slope xp + xn, times the
/// scale (held to lim = tol - |a3| / 4, see SmallOptimalPlan); the arc projects within the
/// chord (so this is its distance to the segment) exactly when the tangent (1, 2 x) has a
/// non-negative component along (1, slope) at both ends (the component is linear in x).
/// x is affine in t, so dx and the slope come from the parameters without cancellation;
/// with |x0| + |x1 - x0| <= 1e4 (required of a closed plan) the rounding of x and of 1 +
/// slope^2 stays far below the 1e-9 tol slack of lim.
template <class T>
inline bool parabola_step_within(const SmallOptimalPlan<T>& plan, T tp, T tn) {
  const T xn = plan.xa + tn * plan.xspan, xp = plan.xa + tp * plan.xspan;
  const T dx = (tn - tp) * plan.xspan / 2, sl = 2 * plan.xa + (tp + tn) * plan.xspan;
  return (plan.scale2 * (dx * dx) * (dx * dx) <= plan.lim2 * (1 + sl * sl)) & (1 + 2 * xp * sl >= 0) & (1 + 2 * xn * sl >= 0) & (tn > tp);
}

/// The cheap form of small_chord_check: the inner points project inside the chord and the
/// smaller of two bounds of max |D| is within the limit: 3/8 |d1 + d2| + 0.1444 |d2 - d1|
/// (small_chord_check), and by Cauchy-Schwarz 3/4 sqrt(m^2 + e^2 / 2), m = (d1 + d2) / 2,
/// e = (d2 - d1) / 2: with w = 2u - 1, |D| = 3/4 (1 - w^2) |m + w e| <= 3/4 (1 - w^2)
/// sqrt(1 + 2 w^2) sqrt(m^2 + e^2 / 2) and (1 - w^2)^2 (1 + 2 w^2) <= 1 on [-1, 1]; its
/// square 9/128 (3 d1^2 + 2 d1 d2 + 3 d2^2) needs no root. Tight for a parabola (d1 = d2)
/// and within 4% for d2 = 0 (where the first is 17% over), so it refuses far fewer steps
/// that pass. Sufficient, not necessary (small_chord_check decides the rest). False for a
/// step that is not positive.
template <class T>
inline bool small_cheap_check(T h, const Point<T, 2>& A, const Vector<T, 2>& dA, const Point<T, 2>& E,
                              const Vector<T, 2>& dE, T tol2) {
  const Vector<T, 2> v = E - A;
  const T h3 = h * T(1.0 / 3);  // a multiplication (h / 3 is a division; the bound has slack for the ulp)
  const T L2 = dot(v, v);
  const T d1 = cross(v, dA) * h3, d2 = -cross(v, dE) * h3;
  const T p1 = dot(v, dA) * h3, p2 = L2 - dot(v, dE) * h3;
  const T b = T(0.375) * std::abs(d1 + d2) + T(0.1444) * std::abs(d2 - d1);
  const T c2 = T(0.0703125) * (T(3) * (d1 * d1 + d2 * d2) + T(2) * (d1 * d2));  // 9/128 (...): small_chord_check
  return (p1 >= 0) & (p1 <= L2) & (p2 >= 0) & (p2 <= L2) & (std::min(b * b, c2) <= tol2 * L2) & (h > 0);
}

/// A step [tp, tn] of small_optimal whose cheap check failed: checked exactly
/// (small_chord_check) and, while it fails, its end moved back to the target deviation
/// 0.97 tol (a short chord's deviation grows as the square of its step; half the step
/// when the chord has no length), until a step passes. An interior step's end is replaced
/// by the first end that passes (tn, E, dE updated, nothing written). The last step
/// (end = true) cannot move its end: the shortened steps' ends are written as vertices
/// until the rest passes. Throws NumericalError when a step stops shrinking (below the
/// parameter's resolution).
template <class T, class At, class D1, class Emit>
[[gnu::noinline]] void small_optimal_repair(T tp, Point<T, 2> A, Vector<T, 2> dA, T& tn, Point<T, 2>& E, Vector<T, 2>& dE, T tol2,
                                            bool end, const At& point_at, const D1& d1_at, Emit& emit) {
  const T target = T(0.97 * 0.97);  // of the squared limit
  SmallChordCheck<T> c = small_chord_check(tn - tp, A, dA, E, dE, tol2);
  while (!c.ok) {
    T f = c.lim > 0 ? std::min(T(0.97), step_factor(target * c.lim, c.dev2)) : T(0.5);
    T tm;
    Point<T, 2> M;
    Vector<T, 2> dM;
    for (;;) {
      tm = tp + (tn - tp) * f;
      if (!(tm > tp)) {
        throw NumericalError("flatten: the optimal method's step fell below the parameter's resolution at t = " + format_number(tp) +
                             ": the tolerance is below the resolution of the curve");
      }
      M = point_at(tm);
      dM = d1_at(tm);
      const SmallChordCheck<T> cm = small_chord_check(tm - tp, A, dA, M, dM, tol2);
      if (cm.ok) break;
      f *= cm.lim > 0 ? std::min(T(0.97), step_factor(target * cm.lim, cm.dev2)) : T(0.5);
    }
    if (!end) {
      tn = tm, E = M, dE = dM;
      return;
    }
    emit(M);
    tp = tm, A = M, dA = dM;
    c = small_chord_check(tn - tp, A, dA, E, dE, tol2);
  }
}

/// small_optimal_batched's block: the vertices j = first .. first + B - 1 past the count's
/// base (count f_base + j df) placed, their points and derivatives, and the cheap check
/// (small_cheap_check, and t < 1) of each step from the one before (the first from the
/// block's start, index 0 of the arrays), into bt .. bdy [1 .. B] and the bits 1 .. B of
/// the result. The plain form, for any scalar type and compiler.
template <class T, int B>
unsigned small_optimal_block_plain(const SmallOptimalPlan<T>& plan, T f_base, T df, T first, T tol2, T* bt, T* bx, T* by, T* bdx, T* bdy) {
  const T h = T(1) / static_cast<T>(optimal_cells);
  const T *f0s = plan.f0, *f1s = plan.f1, *inv = plan.inv, *sl = plan.slope;
  for (int k = 1; k <= B; ++k) {
    const T f = f_base + (first + static_cast<T>(k - 1)) * df;
    int qi = 0;
    for (int i = 0; i + 1 < optimal_cells; ++i) qi += f >= f1s[i] ? 1 : 0;
    const T s = sl[qi];
    const T u = std::clamp((f - f0s[qi]) * inv[qi], T(0), T(1));
    const T b = 1 - s / 2;
    const T x = 2 * u / (b + std::sqrt(b * b + 2 * s * u));
    const T t = (static_cast<T>(qi) + (x <= 1 ? x : T(1))) * h;
    bt[k] = t;
    bx[k] = plan.a0[0] + ((plan.a3[0] * t + plan.a2[0]) * t + plan.a1[0]) * t;
    by[k] = plan.a0[1] + ((plan.a3[1] * t + plan.a2[1]) * t + plan.a1[1]) * t;
    bdx[k] = (T(3) * plan.a3[0] * t + T(2) * plan.a2[0]) * t + plan.a1[0];
    bdy[k] = (T(3) * plan.a3[1] * t + T(2) * plan.a2[1]) * t + plan.a1[1];
  }
  unsigned ok = 0;
  for (int k = 1; k <= B; ++k) {
    const bool pass = small_cheap_check(bt[k] - bt[k - 1], Point<T, 2>{bx[k - 1], by[k - 1]}, Vector<T, 2>{bdx[k - 1], bdy[k - 1]},
                                        Point<T, 2>{bx[k], by[k]}, Vector<T, 2>{bdx[k], bdy[k]}, tol2) &
                      (bt[k] < 1);
    ok |= static_cast<unsigned>(pass) << k;
  }
  return ok;
}

/// The block kernels of small_optimal_batched in plain C++ for any scalar type (no
/// parabola blocks: a piece that is one parabola is walked vertex by vertex).
struct PlainBlocks {
  static constexpr bool parabola_blocks = false;
  template <class T>
  unsigned block(const SmallOptimalPlan<T>& plan, T f_base, T df, T first, T tol2, T* bt, T* bx, T* by, T* bdx, T* bdy, bool /*half*/) const {
    return small_optimal_block_plain<T, optimal_block>(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
  }
};


/// small_optimal's walk over a sampled plan, a block of optimal_block vertices at a time
/// (Kernels::block: small_optimal_block_plain, or the lane kernels of src/flatten): every vertex of the block placed from its share
/// of the count alone, then the block's points and derivatives, then the cheap check of
/// each of its steps, without branches or carried dependences (so that the vertices
/// overlap in the processor, and in vector lanes). The steps that pass are emitted in
/// order up to the first that fails, which is handled as in the sequential walk
/// (small_optimal): repaired, and when its vertex moved, the rest of the count spread
/// again and the next block placed from there; when it did not move, the block's later
/// checks still hold and the scan goes on. The same guarantee as the sequential walk
/// (every emitted step passed the cheap or the exact check). On return tp, A, dA are the
/// last emitted vertex's.
template <class T, class Kernels, class At, class D1, class Emit>
inline void small_optimal_batched(const SmallOptimalPlan<T>& plan, const Kernels& kernels, T tol2, const At& point_at,
                                  const D1& d1_at, Emit& emit, T& tp, Point<T, 2>& A, Vector<T, 2>& dA) {
  constexpr int B = optimal_block;
  const int n = plan.n;
  T f_base = 0, df = plan.F / static_cast<T>(n);
  int j_base = 0;
  // index 0: the block's start (the last emitted vertex); 1 .. B: the block's vertices
  T bt[B + 1], bx[B + 1], by[B + 1], bdx[B + 1], bdy[B + 1];
  int j = 1;
  while (j < n) {
    bt[0] = tp, bx[0] = A[0], by[0] = A[1], bdx[0] = dA[0], bdy[0] = dA[1];
    const T first = static_cast<T>(j - j_base);  // vertex j's index past the count's base
    // (half a block when the piece has no more than 4 vertices left: about half the
    // pieces' last blocks; only the lane kernels compute fewer)
    const unsigned ok = kernels.block(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy, n - j <= B / 2);
    const int cnt = std::min(B, n - j);
    int k = 1;
    bool replace = false;
    if constexpr (requires { emit.block(bx, by, cnt); }) {
      // every step of the block passed (the common case): its vertices written at once
      if (((ok >> 1) & ((1u << cnt) - 1)) == (1u << cnt) - 1) {
        emit.block(bx + 1, by + 1, cnt);
        k = cnt + 1;
      }
    }
    while (k <= cnt) {
      if ((ok >> k) & 1u) [[likely]] {
        emit(Point<T, 2>{bx[k], by[k]});
        ++k;
        continue;
      }
      // Step k failed: the state before it is vertex k - 1 of the block.
      tp = bt[k - 1], A = Point<T, 2>{bx[k - 1], by[k - 1]}, dA = Vector<T, 2>{bdx[k - 1], bdy[k - 1]};
      T tn = bt[k];
      Point<T, 2> E{bx[k], by[k]};
      Vector<T, 2> dE{bdx[k], bdy[k]};
      const int jj = j + k - 1;
      if (!(tn > tp && tn < 1)) {  // a rounding tie (or NaN): the vertex is left out
        j = jj + 1;
        replace = true;
        break;
      }
      const T planned = tn;
      small_optimal_repair(tp, A, dA, tn, E, dE, tol2, false, point_at, d1_at, emit);
      emit(E);
      if (tn != planned) {  // the count reached at the moved vertex, the rest spread again
        const int q = std::min(optimal_cells - 1, static_cast<int>(tn * optimal_cells));
        const T x = tn * optimal_cells - static_cast<T>(q);
        const T fn = plan.f0[q] + (plan.f1[q] - plan.f0[q]) * (x + plan.slope[q] / 2 * (x * x - x));
        df = (plan.F - fn) / static_cast<T>(n - jj);
        f_base = fn;
        j_base = jj;
        tp = tn, A = E, dA = dE;
        j = jj + 1;
        replace = true;
        break;
      }
      ++k;
    }
    if (!replace) {
      j += cnt;
      tp = bt[cnt], A = Point<T, 2>{bx[cnt], by[cnt]}, dA = Vector<T, 2>{bdx[cnt], bdy[cnt]};
    }
  }
}

/// small_optimal's walk over a piece that is one parabola (plan.closed), with the
/// kernels that have a parabola block (Kernels::parabola_blocks), as small_optimal_batched: a block of optimal_block vertices placed,
/// evaluated and checked on the parabola in closed form (Kernels::parabola_block);
/// the steps taken in order up to the first that fails, which is handled as in the
/// sequential walk (the cubic's cheap check, then small_optimal_repair). The closed-form check depends on the parameters alone, so after
/// a failing step whose vertex stays, the block's later checks still hold. On return tp
/// and A are the last emitted vertex's (dA is left to the caller).
template <class T, class Kernels, class At, class D1, class Emit>
inline void small_optimal_parabola_batched(const SmallOptimalPlan<T>& plan, const Kernels& kernels, T tol2,
                                           const At& point_at, const D1& d1_at, Emit& emit, T& tp, Point<T, 2>& A) {
  constexpr int B = optimal_block;
  const int n = plan.n;
  const CountSpan<T> p0 = plan.span;
  T f_base = 0, df = 1 / static_cast<T>(n);
  int j_base = 0;
  alignas(32) T bt[B], bx[B], by[B];
  int j = 1;
  while (j < n) {
    const T first = static_cast<T>(j - j_base);
    const unsigned ok = kernels.parabola_block(plan, f_base, df, first, tp, bt, bx, by);
    const int cnt = std::min(B, n - j);
    int k = 0;
    bool replace = false;
    if constexpr (requires { emit.block(bx, by, cnt); }) {
      if ((ok & ((1u << cnt) - 1)) == (1u << cnt) - 1) {  // every step passed: written at once
        emit.block(bx, by, cnt);
        k = cnt;
      }
    }
    while (k < cnt) {
      if ((ok >> k) & 1u) [[likely]] {
        emit(Point<T, 2>{bx[k], by[k]});
        ++k;
        continue;
      }
      // Step k failed on the parabola: the cubic's own check, from the vertex before it.
      if (k > 0) tp = bt[k - 1], A = Point<T, 2>{bx[k - 1], by[k - 1]};
      const Vector<T, 2> dA = d1_at(tp);
      T tn = bt[k];
      Point<T, 2> E{bx[k], by[k]};
      Vector<T, 2> dE = d1_at(tn);
      const int jj = j + k;
      if (!(small_cheap_check(tn - tp, A, dA, E, dE, tol2) && tn < 1)) {
        if (!(tn > tp && tn < 1)) {  // a rounding tie (or NaN): the vertex is left out
          j = jj + 1;
          replace = true;
          break;
        }
        const T planned = tn;
        small_optimal_repair(tp, A, dA, tn, E, dE, tol2, false, point_at, d1_at, emit);
        if (tn != planned) {  // the count reached at the moved vertex, the rest spread again
          const T fn = p0.fraction_at(tn);
          df = (1 - fn) / static_cast<T>(n - jj);
          f_base = fn;
          j_base = jj;
          emit(E);
          tp = tn, A = E;
          j = jj + 1;
          replace = true;
          break;
        }
      }
      emit(E);
      ++k;
    }
    if (!replace) {
      j += cnt;
      tp = bt[cnt - 1], A = Point<T, 2>{bx[cnt - 1], by[cnt - 1]};
    }
  }
}

/// The near-optimal method on a plane polynomial piece of degree <= 3 (the unit-scale
/// copy), after Levien's analytic flattening [Levien19]: the count n is planned first
/// (small_optimal_plan), then vertex j is placed where the count function reaches j F / n
/// (inverting the parabola integral, or the linear density of its cell), independently of
/// the other vertices, so successive vertices overlap in the processor (for sampled
/// cubics a block of optimal_block at a time, small_optimal_batched, through `kernels`:
/// PlainBlocks here, the lane kernels of src/flatten for double). Each step is
/// checked exactly against the tolerance: on the parabola in closed form when the piece
/// is one within 1e-3 tol (parabola_step_within: quadratics, font outlines), else by the
/// cheap bound of small_cheap_check; these accept most, small_optimal_repair handles the
/// rest (about 3% of the steps on W3's random cubics, one in eight of them passing the
/// exact check as placed; 0.07% on its font outlines), so the
/// tolerance is guaranteed whatever the count function's accuracy (cusps, inflections,
/// loops). After a vertex is moved back the rest of the count is spread evenly over the
/// remaining steps (so one short step does not lengthen the next). Interior vertices to
/// emit; the caller writes the ends.
template <class T, class Emit, class Kernels = PlainBlocks>
void small_optimal(const SmallPiece<T, 2>& s, T tol, Emit&& emit, const Kernels& kernels = {}) {
  using V = Vector<T, 2>;
  if (s.m == 2) return;  // a line is its chord
  SmallOptimalPlan<T> plan;
  small_optimal_plan(s, tol, plan);
  if constexpr (requires { emit.reserve(plan.n); }) emit.reserve(plan.n);
  const Point<T, 2> a0 = plan.a0;
  const V a1 = plan.a1, a2 = plan.a2, a3 = plan.a3;
  auto point_at = [&](T t) { return a0 + ((a3 * t + a2) * t + a1) * t; };
  auto d1_at = [&](T t) { return (T(3) * a3 * t + T(2) * a2) * t + a1; };
  const T tol2 = tol * tol;
  T tp = 0;
  Point<T, 2> A = a0;
  V dA = a1;
  // One parabola checked in closed form: in blocks where the kernels have them.
  auto batched_parabola = [&](T& tp_, Point<T, 2>& A_) {
    if constexpr (Kernels::parabola_blocks) {
      if (plan.closed) {
        small_optimal_parabola_batched(plan, kernels, tol2, point_at, d1_at, emit, tp_, A_);
        return true;
      }
    }
    (void)tp_, (void)A_;
    return false;
  };
  if (plan.sampled) {
    small_optimal_batched(plan, kernels, tol2, point_at, d1_at, emit, tp, A, dA);
  } else if (batched_parabola(tp, A)) {
  } else {
    // One parabola: its constants in locals (the plan's memory must be read again after
    // every vertex written). Vertex j is placed at the fraction f_base + (j - j_base) df
    // of the count: j / n until a step is repaired, then the rest of the count spread
    // evenly over the remaining steps from the repaired vertex.
    const int n = plan.n;
    const CountSpan<T> p0 = plan.span;
    T f_base = 0, df = 1 / static_cast<T>(n);
    // closed-form checks (one parabola): whether dA is current
    const bool closed = plan.closed;
    bool fresh = true;
    int j_base = 0;
    for (int j = 1; j < n; ++j) {
      const T u = std::min(f_base + static_cast<T>(j - j_base) * df, T(1));
      T tn = p0.sx != 0 ? std::clamp((parabola_integral_inverse(p0.a0 + u * p0.da) - p0.x0) * p0.sx, T(0), T(1)) : u;
      if (closed) {
        if (parabola_step_within(plan, tp, tn) && tn < 1) [[likely]] {
          const Point<T, 2> E = point_at(tn);
          emit(E);
          tp = tn;
          A = E;
          fresh = false;
          continue;
        }
        if (!fresh) dA = d1_at(tp);
        fresh = true;
      }
      Point<T, 2> E = point_at(tn);
      V dE = d1_at(tn);
      if (!(small_cheap_check(tn - tp, A, dA, E, dE, tol2) && tn < 1)) [[unlikely]] {
        if (!(tn > tp && tn < 1)) continue;  // a rounding tie (or NaN): the vertex is left out
        const T planned = tn;
        small_optimal_repair(tp, A, dA, tn, E, dE, tol2, false, point_at, d1_at, emit);
        if (tn != planned) {  // the count reached at the moved vertex, the rest spread again
          const T fn = p0.fraction_at(tn);
          df = (1 - fn) / static_cast<T>(n - j);
          f_base = fn;
          j_base = j;
        }
      }
      emit(E);
      tp = tn;
      A = E;
      dA = dE;
    }
  }
  if (plan.closed) dA = d1_at(tp);  // the walk may have left dA behind
  T tn = 1;
  Point<T, 2> E = s.q[static_cast<std::size_t>(s.m - 1)];
  V dE = d1_at(T(1));
  if (!small_cheap_check(1 - tp, A, dA, E, dE, tol2)) small_optimal_repair(tp, A, dA, tn, E, dE, tol2, true, point_at, d1_at, emit);
}

/// small_optimal's output appended to out: each vertex q of the unit-scale copy mapped
/// back (origin + q 2^e) and written through a pointer into room made for the planned
/// count (reserve), so the vertex loop calls no vector::push_back (a call, not inlined,
/// about 7% of the method's time on W3's random cubics); more room on demand (the last

template <class T>
struct SmallOptimalWriter {
  std::vector<Point<T, 2>>& out;
  Point<T, 2> origin;
  T up;
  Point<T, 2>* p = nullptr;    ///< the next vertex's place in out
  Point<T, 2>* end = nullptr;  ///< the end of the room
  /// Room for n more vertices after those written.
  void reserve(int n) {
    const std::size_t used = p ? static_cast<std::size_t>(p - out.data()) : out.size();
    out.resize(used + static_cast<std::size_t>(n));
    p = out.data() + used;
    end = out.data() + out.size();
  }
  void operator()(const Point<T, 2>& q) {
    if (p == end) [[unlikely]] reserve(8);
    (*p)[0] = origin[0] + q[0] * up;
    (*p)[1] = origin[1] + q[1] * up;
    ++p;
  }
  /// The vertices (x[i], y[i]), i < count, in order (a block of small_optimal_batched).
  void block(const T* x, const T* y, int count) {
    if (end - p < count) [[unlikely]] reserve(count);
    for (int i = 0; i < count; ++i) {
      p[i][0] = origin[0] + x[i] * up;
      p[i][1] = origin[1] + y[i] * up;
    }
    p += count;
  }
  void finish() {
    if (p) out.resize(static_cast<std::size_t>(p - out.data()));
  }
};

/// small_optimal for double with the lane kernels of the instruction set chosen at run
/// time (compiled in src/flatten, library casteljau::kernels): the interior vertices of the
/// unit-scale piece s (degree 1..3, s.m >= 2) mapped back by origin + q up and appended to
/// out. The same vertices as small_optimal(s, tol, SmallOptimalWriter<double>{out, origin,
/// up}) with PlainBlocks, bit for bit.
void small_optimal_compiled(const SmallPiece<double, 2>& s, double tol, std::vector<Point<double, 2>>& out, const Point<double, 2>& origin,
                            double up);

/// The lane kernels of the active instruction set (batch::active_isa), for tests: the
/// block of small_optimal_batched (block = 4 or 8 vertices; the same values and bits as
/// small_optimal_block_plain<double, block>) and the block of the parabola walk (8
/// vertices: placed, evaluated and checked in closed form as parabola_step_within, into
/// bt, bx, by [0 .. 8) and the bits 0 .. 7).
unsigned optimal_block_lanes(const SmallOptimalPlan<double>& plan, int block, double f_base, double df, double first, double tol2, double* bt,
                             double* bx, double* by, double* bdx, double* bdy);
unsigned optimal_parabola_block_lanes(const SmallOptimalPlan<double>& plan, double f_base, double df, double first, double tp, double* bt,
                                      double* bx, double* by);

}  // namespace casteljau::detail

