// The offset's candidate cubics (phase of algo/offset.hpp): for a Source over [a, b], the
// cubics through its end points with its end tangent directions (Ends): the Hermite cubic
// (the source's own velocities) and the least-squares fit of the two handle lengths to
// the normal distances of 15 samples (fitted: Gauss-Newton on the shape). Depends on
// common.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "casteljau/algo/offset/common.hpp"

namespace casteljau::detail::offset {

/// The two candidate cubics for the source over [a, b] share its end points and end
/// tangent directions (Ends): the Hermite cubic (handles the source's velocity times
/// (b - a) / 3) and the least-squares fit of the two handle lengths to the normal
/// distances of 15 interior samples (fitted: Gauss-Newton, below; the fixed-tangent fit
/// of [Schneider90] made geometric), when its lengths are positive. The fit stops when a
/// step moves the cubic by less than 1e-2 of the tolerance `tol` (the handles' step times
/// the largest Bernstein weight 4/9, or twice the largest movement along the normals at
/// the samples, the smaller), or when the cubic cannot come within the tolerance (below).
template <class T>
struct Ends {
  Point<T, 2> P0, P3;
  Vector<T, 2> T0, T3;
  T ha, hb;
  Ends(const Source<T>& s, T a, T b) : P0(s.point(a)), P3(s.point(b)), T0(s.tangent(a)), T3(s.tangent(b)) {
    const T h = (b - a) / 3;
    ha = length(s.velocity(a)) * h, hb = length(s.velocity(b)) * h;
  }
  CubicForm<T> hermite() const { return CubicForm<T>(P0, P0 + T0 * ha, P3 - T3 * hb, P3); }
};

/// The least-squares candidate (above), or nothing where the fit finds no positive lengths.
template <class T>
std::optional<CubicForm<T>> fitted(const Source<T>& s, T a, T b, const Ends<T>& E, T tol) {
  const Point<T, 2> P0 = E.P0, P3 = E.P3;
  const Vector<T, 2> T0 = E.T0, T3 = E.T3;
  const T ha = E.ha, hb = E.hb;
  constexpr int m = 15;
  std::array<Point<T, 2>, m + 2> q;
  std::array<T, m + 2> u;
  for (int j = 0; j <= m + 1; ++j) q[j] = j == 0 ? P0 : j == m + 1 ? P3 : s.point(a + (b - a) * T(j) / (m + 1));
  u[0] = 0;
  for (int j = 1; j <= m + 1; ++j) u[j] = u[j - 1] + length(q[j] - q[j - 1]);
  if (!(u[m + 1] > 0)) return std::nullopt;
  for (int j = 1; j <= m + 1; ++j) u[j] /= u[m + 1];
  // Gauss-Newton on the handle lengths (alpha, beta) for the normal distances of the
  // samples to the cubic: each sample projected on the current cubic (Newton on
  // (B(u) - q) . B'(u), from its last foot), its residual e = n . (B(u) - q) with n the
  // cubic's unit normal there, whose derivatives are n . (b1(u) T0) and -n . (b2(u) T3)
  // (the foot moves along the cubic, which changes the distance only to second order).
  // Fitting the shape, not the parametrisation, converges in a few steps where the
  // alternation of linear least squares and reparametrisation [Schneider90] crawls.
  T alpha = ha > 0 ? ha : length(P3 - P0) / 3, beta = hb > 0 ? hb : length(P3 - P0) / 3;
  bool ok = false;
  for (int round = 0; round < 8; ++round) {
    const CubicForm<T> B(P0, P0 + T0 * alpha, P3 - T3 * beta, P3);
    T a11 = 0, a12 = 0, a22 = 0, r1 = 0, r2 = 0, emax = 0;
    std::array<T, m + 1> ja_at{}, jb_at{};
    for (int j = 1; j <= m; ++j) {
      for (int it = 0; it < 3; ++it) {
        const Vector<T, 2> e = B.at(u[j]) - q[j], d1 = B.d1(u[j]), d2 = B.d2(u[j]);
        const T den = dot(d1, d1) + dot(e, d2);
        if (den > 0) u[j] = std::clamp(u[j] - dot(e, d1) / den, T(0), T(1));
      }
      const T v = u[j], w = 1 - v;
      const T b1 = 3 * v * w * w, b2 = 3 * v * v * w;
      const Vector<T, 2> n = unit(left(B.d1(v)));
      const T e = dot(n, B.at(v) - q[j]), ja = dot(n, T0) * b1, jb = -dot(n, T3) * b2;
      a11 += ja * ja, a12 += ja * jb, a22 += jb * jb, r1 += ja * e, r2 += jb * e;
      emax = std::max(emax, std::abs(e)), ja_at[j] = ja, jb_at[j] = jb;
    }
    const T det = a11 * a22 - a12 * a12;
    if (!(std::abs(det) > std::numeric_limits<T>::epsilon() * 16 * (a11 * a22))) break;  // a straight stretch: any lengths
    const T al = alpha - (r1 * a22 - r2 * a12) / det, be = beta - (a11 * r2 - a12 * r1) / det;
    if (!(al > 0 && be > 0 && std::isfinite(al) && std::isfinite(be))) break;  // the last good lengths stay
    // The step's movement of the cubic: the handles' bound (4/9 of their steps) or twice
    // the largest normal movement at the samples (the linear model's), the smaller. Where
    // the two lengths trade against each other (near-circular arcs), the handles move
    // far and the cubic hardly: the bound alone kept a quarter of the glyph fits at the
    // 8-round cap.
    const T dal = al - alpha, dbe = be - beta;
    T normal_move = 0;
    for (int j = 1; j <= m; ++j) normal_move = std::max(normal_move, std::abs(ja_at[j] * dal + jb_at[j] * dbe));
    const T bound = (std::abs(dal) + std::abs(dbe)) * T(4) / 9;
    // Done when the cubic moves by less than 1e-2 of the tolerance, or when a sample stays
    // more than 1.5 tolerances off after four steps of the bound (a candidate the measure
    // rejects anyway; its error only steers the search's next end).
    const bool done = std::min(bound, 2 * normal_move) <= T(1e-2) * tol || (round >= 1 && emax - 4 * bound > T(1.5) * tol);
    alpha = al, beta = be, ok = true;
    if (done) break;
  }
  if (ok) return CubicForm<T>(P0, P0 + T0 * alpha, P3 - T3 * beta, P3);
  return std::nullopt;
}

}  // namespace casteljau::detail::offset
