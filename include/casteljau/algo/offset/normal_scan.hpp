// The offset's normal-line measure (phase of algo/offset.hpp): a candidate cubic's error
// along the source's normal lines [Tiller-Hanson84; Elber-Lee-Kim97], which bounds the
// distance both ways when the lines meet the cubic in order (NormalScan: why, and how it
// samples). normal_foot (one foot), normal_scan (the samples: the screening estimate of a
// candidate), normal_peaks (the tops of its bumps: the measure) and measured (the scan,
// or the projections of measure.hpp where it fails). Depends on common.hpp and
// measure.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "casteljau/algo/offset/common.hpp"
#include "casteljau/algo/offset/measure.hpp"

namespace casteljau::detail::offset {

/// The error of the cubic B against the source over [a, b] measured along the source's
/// normal lines [Tiller-Hanson84; Elber-Lee-Kim97]: for a source parameter t, the foot u(t)
/// where the normal line at O(t) meets the cubic ((B(u) - O(t)) . T(t) = 0, T the unit
/// tangent, by Newton), and the error e(t) = |B(u(t)) - O(t)|. The normal lines of an
/// offset are the curve's own (O(t) = C(t) + d N(t) moves along T(t), also at its cusps),
/// and a join arc's are its radii.
///
/// Why it measures the distance both ways: when the feet run from u = 0 at t = a to u = 1
/// at t = b, increasing and continuous, every point O(t) of the source is within e(t) of
/// the cubic (of B(u(t))) and every point B(u) of the cubic is B(u(t)) for some t (the
/// feet cover [0, 1]), within e(t) of the source: the Hausdorff distance (and the Fréchet
/// distance) is at most max_t e(t). So one scan along the source bounds both directions,
/// where two sets of projections (the nearest point of one curve for samples of the other)
/// were needed, and each foot costs a few Newton steps on the cubic from the last foot
/// (no search over samples). e(t) exceeds the nearest-point distance by a factor
/// 1 / cos(angle between the curves), 1 + 5e-5 for an angle of 1e-2 (a cubic within 1e-3
/// of a unit curve).
///
/// Sampling: m = 20 equal parts of [a, b], and every part whose feet are more than 1.5 / m
/// apart on the cubic halved (three times at most; a part still that long fails the scan:
/// the feet jump, over an excursion of the cubic that no normal line meets first), so that both curves are sampled at
/// least as densely as 20 parts of either parameter (where the offset runs fast, near a
/// sharp turn of the curve on its convex side, equal parts of t are long on it). The
/// error of a fit is a smooth function with a few bumps (at most about four between the
/// interpolated ends: each 5 parts wide or more), which these parts resolve; the top of
/// every local maximum of the samples within 80% of the largest is then found over its two
/// parts by successive parabolas through the largest sample and its neighbours (at most
/// four more feet; the last parabola's own top counted too; golden section, 12 steps, where
/// three samples make no cap; a bump 5 parts wide sampled half a part off its top is up to
/// 1 - cos(pi / 10) = 4.9% low, one 4 parts wide 7.6%, so a lower sample can sit on a
/// higher bump, within the 20% margin). Session 14 scanned 33 parts: the bench's
/// independent measure (W11, docs/performance.md) finds the same 0 over the tolerance with
/// 20, and the W11 counts within 0.1%.
///
/// A foot that Newton does not find inside (0, 1) (the normal line misses the cubic, or
/// the cubic runs across it), or feet out of order, make the scan fail (ok = false): the
/// caller measures by projections instead (hausdorff).
template <class T>
struct NormalScan {
  static constexpr int parts = 20;
  static constexpr int capacity = 8 * parts + 1;
  std::array<T, capacity> t, u, e;  // source parameter, foot on the cubic, error (the first n set)
  int n = 0;
  T worst = 0;     ///< the largest sampled error (the scan stops at the first above stop_above)
  T estimate = 0;  ///< worst with the parabola through the largest sample and its neighbours
  bool ok = true;
};

/// The foot on the cubic F of the source's normal line at t inside (ul, ur): Newton on
/// g(u) = (F(u) - O) . T = 0 from `guess`; where a step leaves (ul, ur) or meets a place
/// where the cubic does not run forward along T, the first sign change of g on 16 equal
/// parts of (ul, ur), narrowed by Newton steps kept inside a bisection bracket. The foot
/// and the distance |F(u) - O|; false when there is no such foot (g does not change sign
/// from negative to positive, or the cubic runs across or against the normal line there).
template <class T>
bool normal_foot(const CubicForm<T>& F, const Source<T>& s, T t, T guess, T ul, T ur, T& u, T& err) {
  const std::pair<Point<T, 2>, Vector<T, 2>> frame = s.frame(t);
  const Point<T, 2> O = frame.first;
  const Vector<T, 2> Tt = frame.second;
  const auto g = [&](T x) { return dot(F.at(x) - O, Tt); };
  const auto accept = [&](T x) {
    if (!(x > ul && x < ur) || !(dot(F.d1(x), Tt) > 0)) return false;
    u = x, err = length(F.at(x) - O);
    return true;
  };
  constexpr T settled = T(1e-7);  // a Newton step this small leaves an error of about its square (1e-14)
  T x = std::clamp(guess, ul, ur);
  for (int it = 0; it < 8; ++it) {
    const T gp = dot(F.d1(x), Tt);
    if (!(gp > 0)) break;
    const T nx = x - g(x) / gp;
    if (!(nx > ul && nx < ur)) break;
    if (std::abs(nx - x) <= settled) return accept(nx);
    x = nx;
  }
  T xl = ul, xr = ur;
  if (!(g(ul) < 0)) return false;
  bool found = false;
  for (int k = 1; k <= 16 && !found; ++k) {
    const T y = k == 16 ? ur : ul + (ur - ul) * T(k) / 16;
    if (g(y) >= 0) xr = y, found = true;
    else xl = y;
  }
  if (!found) return false;
  x = (xl + xr) / 2;
  for (int it = 0; it < 100; ++it) {
    const T gx = g(x), gp = dot(F.d1(x), Tt);
    if (gx < 0) xl = x;
    else xr = x;
    T nx = x - gx / gp;
    if (!(gp > 0) || !(nx > xl && nx < xr)) nx = (xl + xr) / 2;
    if (std::abs(nx - x) <= settled || xr - xl <= std::numeric_limits<T>::epsilon() * 4) return accept(nx);
    x = nx;
  }
  return false;
}

/// The scan of NormalScan (its samples, their errors, stopping above stop_above).
template <class T>
void normal_scan(const CubicForm<T>& F, const Source<T>& s, T a, T b, T stop_above, NormalScan<T>& r) {
  constexpr int m = NormalScan<T>::parts;
  r.n = 0, r.worst = 0, r.estimate = 0, r.ok = true;
  // The equal parts first (feet from the last foot, extrapolated).
  std::array<T, m + 1> t0{}, u0{}, e0{};
  t0[0] = a, u0[0] = 0, t0[m] = b, u0[m] = 1;
  T du = T(1) / m;
  int at = 0;
  for (int i = 1; i < m; ++i) {
    t0[i] = a + (b - a) * T(i) / m;
    if (!normal_foot(F, s, t0[i], u0[i - 1] + du, u0[i - 1], T(1), u0[i], e0[i])) {
      r.ok = false;
      return;
    }
    if (e0[i] > r.worst) r.worst = e0[i], at = i;
    if (r.worst > stop_above) {
      r.estimate = r.worst;
      return;
    }
    du = u0[i] - u0[i - 1];
  }
  if (!(u0[m] > u0[m - 1])) {
    r.ok = false;
    return;
  }
  r.estimate = r.worst;
  if (at > 1 && at < m - 1) {  // the parabola through the largest sample and its neighbours
    const T y0 = e0[at - 1], y1 = e0[at], y2 = e0[at + 1];
    const T den = y0 - 2 * y1 + y2;
    if (den < 0) r.estimate = std::max(r.estimate, y1 - (y2 - y0) * (y2 - y0) / (8 * den));
  }
  // Parts long on the cubic halved.
  const T gap = T(1.5) / m;
  const auto push = [&](T t, T u, T e) { r.t[r.n] = t, r.u[r.n] = u, r.e[r.n] = e, ++r.n; };
  push(t0[0], u0[0], e0[0]);
  for (int i = 0; i < m && r.ok; ++i) {
    const auto fill = [&](const auto& self, T tl, T ul, T tr, T ur, int depth) -> void {
      if (!r.ok) return;
      if (ur - ul > gap && depth < 3) {
        const T tm = (tl + tr) / 2;
        T um = 0, em = 0;
        if (!normal_foot(F, s, tm, (ul + ur) / 2, ul, ur, um, em)) {
          r.ok = false;
          return;
        }
        r.worst = std::max(r.worst, em), r.estimate = std::max(r.estimate, em);
        self(self, tl, ul, tm, um, depth + 1);
        push(tm, um, em);
        self(self, tm, um, tr, ur, depth + 1);
      } else if (ur - ul > gap) {
        // Still long on the cubic after three halvings: the feet jump (the cubic makes an
        // excursion that no normal line meets first, as a fit with a runaway handle can).
        r.ok = false;
      }
    };
    fill(fill, t0[i], u0[i], t0[i + 1], u0[i + 1], 0);
    push(t0[i + 1], u0[i + 1], e0[i + 1]);
  }
  // A cubic whose control polygon is more than 2.5 times the length through its feet
  // (a smooth cubic's is at most about 1.5 times its length: a half circle) may hide an
  // excursion between two feet: measured by projections instead.
  if (r.ok) {
    T through = 0;
    for (int k = 1; k < r.n; ++k) through += length(F.at(r.u[k]) - F.at(r.u[k - 1]));
    const T polygon = length(F.P[1] - F.P[0]) + length(F.P[2] - F.P[1]) + length(F.P[3] - F.P[2]);
    if (polygon > T(2.5) * through) r.ok = false;
  }
  return;
}

/// The measured error of a scan that is within stop_above: the top of every local maximum
/// of its samples within 80% of the largest (see NormalScan). Clears r.ok when a foot is
/// not found.
template <class T>
T normal_peaks(const CubicForm<T>& F, const Source<T>& s, NormalScan<T>& r, T stop_above) {
  T worst = r.worst;
  const T floor = T(0.8) * r.worst;
  for (int j = 1; j + 1 < r.n && r.ok; ++j) {
    if (!(r.e[j] >= floor && r.e[j] >= r.e[j - 1] && r.e[j] >= r.e[j + 1])) continue;
    const T tl = r.t[j - 1], tm = r.t[j], tr = r.t[j + 1], ul = r.u[j - 1], um = r.u[j], ur = r.u[j + 1];
    const auto minus_error = [&](T t) {
      if (t == tm) return -r.e[j];
      if (t <= tl) return -r.e[j - 1];
      if (t >= tr) return -r.e[j + 1];
      const T guess = t < tm ? ul + (um - ul) * (t - tl) / (tm - tl) : um + (ur - um) * (t - tm) / (tr - tm);
      T u = 0, e = 0;
      if (!normal_foot(F, s, t, guess, ul, ur, u, e)) r.ok = false;
      return -e;
    };
    // The top by successive parabolas through the largest sample and its two neighbours
    // (a smooth bump's top is a parabola's to third order: a few feet), the parabola's
    // own top counted too; golden section where the three samples do not make a cap.
    std::array<T, 3> pt{tl, tm, tr}, pe{r.e[j - 1], r.e[j], r.e[j + 1]};
    bool capped = true;
    T top = r.e[j];
    for (int it = 0; it < 4 && capped; ++it) {
      const T s0 = (pe[1] - pe[0]) / (pt[1] - pt[0]), s1 = (pe[2] - pe[1]) / (pt[2] - pt[1]);
      const T curv = (s1 - s0) / (pt[2] - pt[0]);  // p(t) = pe[0] + s0 (t - pt[0]) + curv (t - pt[0]) (t - pt[1])
      if (!(curv < 0)) {
        capped = false;
        break;
      }
      const T tvx = std::clamp((pt[0] + pt[1]) / 2 - s0 / (2 * curv), pt[0], pt[2]);
      top = std::max(top, pe[0] + s0 * (tvx - pt[0]) + curv * (tvx - pt[0]) * (tvx - pt[1]));
      if (std::abs(tvx - pt[1]) <= T(1e-4) * (tr - tl)) break;
      const T ev = -minus_error(tvx);
      if (!r.ok) break;
      top = std::max(top, ev);
      if (ev >= pe[1]) {
        if (tvx < pt[1]) pt = {pt[0], tvx, pt[1]}, pe = {pe[0], ev, pe[1]};
        else pt = {pt[1], tvx, pt[2]}, pe = {pe[1], ev, pe[2]};
      } else {
        if (tvx < pt[1]) pt[0] = tvx, pe[0] = ev;
        else pt[2] = tvx, pe[2] = ev;
      }
    }
    if (!r.ok) break;
    if (!capped) top = std::max(top, -golden_min(minus_error, tl, tr, 12).second);
    worst = std::max(worst, top);
    if (worst > stop_above) return worst;
  }
  return worst;
}

/// The measured distance between the cubic B and the source over [a, b] (both ways): the
/// normal scan and its peaks (NormalScan), or where the scan fails the projections both
/// ways (hausdorff). Stops above stop_above (a rejected cubic).
template <class T>
T measured(const CubicForm<T>& F, const Source<T>& s, T a, T b, T stop_above) {
  NormalScan<T> r;
  normal_scan(F, s, a, b, stop_above, r);
  if (r.ok && r.worst > stop_above) return r.worst;
  if (r.ok) {
    const T e = normal_peaks(F, s, r, stop_above);
    if (r.ok) return e;
  }
  return hausdorff(F, s, a, b, stop_above);
}

}  // namespace casteljau::detail::offset
