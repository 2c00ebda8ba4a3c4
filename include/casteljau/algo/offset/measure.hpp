// The offset's error measures by projection (phase of algo/offset.hpp): the distance
// between a candidate cubic and its Source over a parameter range, measured both ways on
// samples with every bump of the error refined (golden_min): hausdorff (projections of 33
// samples each way: the general fallback), parametric (the distance at equal parameters:
// across a cusp of the offset, a bound of the Hausdorff distance) and partner_distance
// (projections from partners: across a cusp, where parametric fails). The measure along
// the source's normal lines, used first elsewhere, is normal_scan.hpp. Depends on
// common.hpp (CubicForm, Source).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "casteljau/algo/offset/common.hpp"

namespace casteljau::detail::offset {

/// The minimum over [lo, hi] of f (unimodal there) by golden section in `steps` steps
/// (the bracket shrinks by 0.618 a step): the best parameter seen and its value, the
/// ends included.
template <class T, class F>
std::pair<T, T> golden_min(const F& f, T lo, T hi, int steps) {
  constexpr T r = T(0.6180339887498948482045868343656381L);
  T a = lo, b = hi;
  T x1 = b - r * (b - a), x2 = a + r * (b - a);
  T f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < steps; ++k) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - r * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + r * (b - a), f2 = f(x2);
    }
  }
  std::pair<T, T> best = f1 <= f2 ? std::pair<T, T>{x1, f1} : std::pair<T, T>{x2, f2};
  for (const T e : {lo, hi}) {
    const T v = f(e);
    if (v < best.second) best = {e, v};
  }
  return best;
}

/// A curve sampled at increasing parameters, to measure distances to it: f its point,
/// v its derivative.
template <class T>
struct Sampled {
  std::function<Point<T, 2>(T)> f;
  std::function<Vector<T, 2>(T)> v;
  std::vector<T> t;
  std::vector<Point<T, 2>> p;

  /// The distance from q to the curve: the nearest sample, then Gauss-Newton steps from it
  /// (done when they settle inside the two sample intervals about it; most points), else
  /// golden section on the squared
  /// distance over the two sample intervals about it (8 steps: 2% of their length), then
  /// five Gauss-Newton steps t -= (f - q) . v / |v|^2 (kept in the bracket), which
  /// converge at the rate distance x curvature (1e-5 and less for a point within the
  /// tolerance), so that a point on the curve (where the distance grows linearly, not
  /// quadratically) measures to rounding. The smallest distance seen.
  T distance(const Point<T, 2>& q) const {
    std::size_t k = 0;
    T best = std::numeric_limits<T>::infinity();
    for (std::size_t j = 0; j < p.size(); ++j) {
      const T s = squared_norm(p[j] - q);
      if (s < best) best = s, k = j;
    }
    const T lo = t[k > 0 ? k - 1 : 0], hi = t[std::min(k + 1, t.size() - 1)];
    // First Gauss-Newton from the nearest sample alone: when it settles (a step below
    // 1e-12 of the bracket) inside the bracket, that is the foot; otherwise (a step out of
    // the bracket, no convergence) the golden section below starts over.
    {
      T x = t[k];
      for (int it = 0; it < 6; ++it) {
        const Vector<T, 2> vel = v(x);
        const T vv = squared_norm(vel);
        if (!(vv > 0)) break;
        const T nx = x - dot(f(x) - q, vel) / vv;
        if (!(nx >= lo && nx <= hi)) break;
        const T dist = squared_norm(f(nx) - q);
        best = std::min(best, dist);
        if (std::abs(nx - x) <= T(1e-12) * (hi - lo)) return std::sqrt(best);
        x = nx;
      }
    }
    auto [u, m] = golden_min([&](T x) { return squared_norm(f(x) - q); }, lo, hi, 8);
    best = std::min(best, m);
    for (int it = 0; it < 5; ++it) {
      const Vector<T, 2> vel = v(u);
      const T vv = squared_norm(vel);
      if (!(vv > 0)) break;
      u = std::clamp(u - dot(f(u) - q, vel) / vv, lo, hi);
      best = std::min(best, squared_norm(f(u) - q));
    }
    return std::sqrt(best);
  }
};

/// The measured Hausdorff distance between the cubic B (on [0, 1]) and the source over
/// [a, b]: 33 samples each way, each sample's distance to the other curve computed by
/// projection (Sampled::distance), then each local maximum of the samples of either
/// direction that is at least 80% of the largest sample maximised locally over its two
/// sample intervals (golden section on the distance). The error of a cubic fit is a smooth
/// function of the parameter with a few bumps per segment (at most about four between its
/// interpolated ends), which 32 intervals resolve; the local maximisation finds a bump's
/// top, which can lie up to about 8% above its best sample (a bump 8 intervals wide,
/// sampled half an interval off its top: 1 - cos(pi / 8)), so every bump whose best sample
/// is within 20% of the largest is refined, not only the largest (the bump of the largest
/// sample is not always the highest: W11 of docs/performance.md found offsets 1.7% over
/// the tolerance that way). `stop_above`: when the samples of one direction
/// exceed it, that value is returned at once (a rejected candidate; the cheap direction,
/// the source's samples against the cubic, first).
template <class T>
T hausdorff(const CubicForm<T>& F, const Source<T>& s, T a, T b, T stop_above) {
  constexpr int m = 32;
  Sampled<T> exact{s.point, s.velocity, {}, {}}, cubic{[&](T u) { return F.at(u); }, [&](T u) { return F.d1(u); }, {}, {}};
  exact.t.resize(m + 1), exact.p.resize(m + 1), cubic.t.resize(m + 1), cubic.p.resize(m + 1);
  for (int j = 0; j <= m; ++j) {
    const T f = T(j) / m;
    exact.t[j] = j == m ? b : a + (b - a) * f;
    exact.p[j] = s.point(exact.t[j]);
    cubic.t[j] = f;
    cubic.p[j] = F.at(f);
  }
  std::array<T, m + 1> d1{}, d2{};
  T e1 = 0, e2 = 0;
  for (int j = 0; j <= m; ++j) {
    d1[j] = cubic.distance(exact.p[j]);
    e1 = std::max(e1, d1[j]);
    if (e1 > stop_above) return e1;
  }
  for (int j = 0; j <= m; ++j) {
    d2[j] = exact.distance(cubic.p[j]);
    e2 = std::max(e2, d2[j]);
    if (e2 > stop_above) return e2;
  }
  const auto peak = [&](const Sampled<T>& from, const Sampled<T>& to, int j) {
    const T lo = from.t[j > 0 ? j - 1 : 0], hi = from.t[std::min(j + 1, m)];
    // The top of a bump is flat: 12 steps (3e-3 of the two intervals, a 1/16 of the
    // segment: 2e-4 of the segment, a phase of 5e-3 rad on a bump a quarter of the segment
    // long) find its height to about 1e-5 relative.
    return std::sqrt(-golden_min(
                          [&](T u) {
                            const T dd = to.distance(from.f(u));
                            return -dd * dd;
                          },
                          lo, hi, 12)
                          .second);
  };
  T worst = std::max(e1, e2);
  const T floor = T(0.8) * worst;
  for (int j = 0; j <= m; ++j) {
    const bool top1 = d1[j] >= floor && (j == 0 || d1[j] >= d1[j - 1]) && (j == m || d1[j] >= d1[j + 1]);
    const bool top2 = d2[j] >= floor && (j == 0 || d2[j] >= d2[j - 1]) && (j == m || d2[j] >= d2[j + 1]);
    if (top1) worst = std::max(worst, peak(exact, cubic, j));
    if (top2) worst = std::max(worst, peak(cubic, exact, j));
    if (worst > stop_above) return worst;
  }
  return worst;
}

/// The parametric distance between the cubic F and the source over [a, b]: the largest
/// |F(u) - O(a + u (b - a))| over u in [0, 1], an upper bound of the Hausdorff (and the
/// Fréchet) distance (each point of either curve is that close to its partner on the
/// other). The natural measure of the Hermite cubic across a cusp of the offset, where the
/// normal scan's feet do not run in order: sampled at 33 parameters and the cusps, every
/// local maximum within 80% of the largest refined over its two intervals (golden section,
/// 12 steps; the error of a Hermite interpolant is a smooth function with a few bumps).
/// Stops above stop_above.
template <class T>
T parametric(const CubicForm<T>& F, const Source<T>& s, T a, T b, T stop_above) {
  constexpr int m = 32;
  const auto err = [&](T u) { return length(F.at(u) - s.point(a + (b - a) * u)); };
  std::array<T, m + 1> e{};
  T worst = 0;
  for (int j = 1; j < m; ++j) {
    e[j] = err(T(j) / m);
    worst = std::max(worst, e[j]);
    if (worst > stop_above) return worst;
  }
  for (const T c : s.cusps) {
    if (c > a && c < b) worst = std::max(worst, err((c - a) / (b - a)));
    if (worst > stop_above) return worst;
  }
  const T floor = T(0.8) * worst;
  for (int j = 1; j < m; ++j) {
    if (!(e[j] >= floor && e[j] >= e[j - 1] && e[j] >= e[j + 1])) continue;
    worst = std::max(worst, -golden_min([&](T u) { return -err(u); }, T(j - 1) / m, T(j + 1) / m, 12).second);
    if (worst > stop_above) return worst;
  }
  return worst;
}

/// The distance between the cubic F and the source over [a, b] measured both ways from
/// partners: the samples of each curve at 33 equal parameters, each projected on the other
/// curve from its partner at the same fraction of the parameter (Newton on the squared
/// distance for the cubic, Gauss-Newton for the source, 4 steps kept in the domain), the
/// nearest point seen kept, then every local maximum within 80% of the largest refined over
/// its two intervals (golden section, 10 steps). Each value is a distance to a point of the
/// other curve, never below the true distance: a projection that ends off the nearest
/// point overstates, so the measure errs to the safe side (a candidate refused), and no
/// sample searches all 33 of the other curve as in hausdorff. Used across the
/// cusps of the offset, where the normal scan's feet do not run in order; the source's
/// cusps are sampled too. Stops above stop_above.
template <class T>
T partner_distance(const CubicForm<T>& F, const Source<T>& s, T a, T b, T stop_above) {
  constexpr int m = 32;
  const auto to_cubic = [&](T f) {  // source point at fraction f to the cubic
    const Point<T, 2> q = s.point(a + (b - a) * f);
    T u = f, best = length(F.at(u) - q);
    for (int it = 0; it < 4; ++it) {
      const Vector<T, 2> e = F.at(u) - q, d1 = F.d1(u), d2 = F.d2(u);
      const T den = dot(d1, d1) + dot(e, d2);
      if (!(den > 0)) break;
      u = std::clamp(u - dot(e, d1) / den, T(0), T(1));
      best = std::min(best, length(F.at(u) - q));
    }
    return best;
  };
  const auto to_source = [&](T f) {  // cubic point at fraction f to the source
    const Point<T, 2> q = F.at(f);
    T t = a + (b - a) * f, best = length(s.point(t) - q);
    for (int it = 0; it < 4; ++it) {
      const Vector<T, 2> v = s.velocity(t);
      const T vv = dot(v, v);
      if (!(vv > 0)) break;
      t = std::clamp(t - dot(s.point(t) - q, v) / vv, a, b);
      best = std::min(best, length(s.point(t) - q));
    }
    return best;
  };
  std::array<T, m + 1> e1{}, e2{};
  T worst = 0;
  for (const T c : s.cusps) {
    if (c > a && c < b) worst = std::max(worst, to_cubic((c - a) / (b - a)));
    if (worst > stop_above) return worst;
  }
  for (int j = 1; j < m; ++j) {
    e1[j] = to_cubic(T(j) / m);
    worst = std::max(worst, e1[j]);
    if (worst > stop_above) return worst;
  }
  for (int j = 1; j < m; ++j) {
    e2[j] = to_source(T(j) / m);
    worst = std::max(worst, e2[j]);
    if (worst > stop_above) return worst;
  }
  const T floor = T(0.8) * worst;
  for (int j = 1; j < m; ++j) {
    const T lo = T(j - 1) / m, hi = T(j + 1) / m;
    if (e1[j] >= floor && e1[j] >= e1[j - 1] && e1[j] >= e1[j + 1]) worst = std::max(worst, -golden_min([&](T f) { return -to_cubic(f); }, lo, hi, 10).second);
    if (e2[j] >= floor && e2[j] >= e2[j - 1] && e2[j] >= e2[j + 1]) worst = std::max(worst, -golden_min([&](T f) { return -to_source(f); }, lo, hi, 10).second);
    if (worst > stop_above) return worst;
  }
  return worst;
}

}  // namespace casteljau::detail::offset
