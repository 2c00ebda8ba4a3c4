// Offset curves of plane curves: C(t) + d N(t) approximated by cubic Béziers within a
// measured tolerance, with joins at the corners of the input, and trimmed to the points at
// least |d| from the curve.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect.hpp"
#include "casteljau/algo/project.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// How the outer side of a corner of the input (a G0 joint) is closed.
enum class OffsetJoin {
  round,  ///< a circular arc of radius |d| about the corner (as cubics within the tolerance)
  miter,  ///< the two offset tangent lines extended to their meeting point (bevel past miter_limit)
  bevel,  ///< one straight line between the two offset end points
};

/// How the cubics are placed along each smooth stretch of the offset.
enum class OffsetFit {
  greedy,   ///< each cubic as long as the tolerance allows (near the fewest); the default
  uniform,  ///< the reference: n equal parameter parts, Hermite cubics, n = 1, 2, ... until within the tolerance
};

template <class T>
struct OffsetOptions {
  T distance = 0;   ///< d: positive to the left of the direction of travel
  T tolerance = 0;  ///< the largest distance allowed between the cubics and the exact offset (both ways)
  bool trim = true;
  OffsetJoin join = OffsetJoin::round;
  T miter_limit = 4;  ///< miter length over |d| (SVG's stroke-miterlimit), >= 1
  OffsetFit fit = OffsetFit::greedy;
  std::size_t max_segments = 20000;  ///< the work limit: more cubics than this are refused
};

/// The result of offset(): the cubics in order (a path, continuous except between the
/// parts the trim leaves, see offset()), the largest measured distance of a cubic of the
/// raw offset from its exact source (offset stretch or join), and the number of runs of
/// the raw offset the trim cut away.
template <class T>
struct OffsetCurve {
  std::vector<Bezier<T, 2>> segments;
  T max_error = 0;
  std::size_t loops_cut = 0;
  std::size_t raw_segments = 0;  ///< cubics before trimming
};

namespace detail::offset {

template <class T>
Vector<T, 2> left(const Vector<T, 2>& v) {
  return Vector<T, 2>{-v[1], v[0]};
}

/// |v| by the square root of the sum of squares where that neither overflows nor loses
/// precision to underflow (every vector of the unit frame's inner loops), norm() beyond:
/// norm's scaling (two divisions) was a quarter of the offset's time.
template <class T>
T length(const Vector<T, 2>& v) {
  const T s = v[0] * v[0] + v[1] * v[1];
  constexpr T lo = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
  constexpr T hi = std::numeric_limits<T>::max() * std::numeric_limits<T>::epsilon();
  return s >= lo && s <= hi ? std::sqrt(s) : norm(v);
}

template <class T>
Vector<T, 2> unit(const Vector<T, 2>& v) {
  const T n = length(v);
  return n > 0 ? v / n : Vector<T, 2>{};
}

/// The point at t of the Bézier form with control points P (de Casteljau on the stack up
/// to degree 15, on the heap beyond): no allocation in the inner loops of the fit.
template <class T>
Point<T, 2> form_point(const std::vector<Point<T, 2>>& P, T t) {
  const std::size_t n = P.size();
  if (n == 0) return Point<T, 2>{};
  if (n <= 4) {  // cubics and their hodographs, unrolled
    Point<T, 2> out;
    for (int k = 0; k < 2; ++k) {
      if (n == 1) {
        out[k] = P[0][k];
      } else if (n == 2) {
        out[k] = P[0][k] + t * (P[1][k] - P[0][k]);
      } else if (n == 3) {
        const T a = P[0][k] + t * (P[1][k] - P[0][k]), b = P[1][k] + t * (P[2][k] - P[1][k]);
        out[k] = a + t * (b - a);
      } else {
        const T a = P[0][k] + t * (P[1][k] - P[0][k]), b = P[1][k] + t * (P[2][k] - P[1][k]), c = P[2][k] + t * (P[3][k] - P[2][k]);
        const T d = a + t * (b - a), e = b + t * (c - b);
        out[k] = d + t * (e - d);
      }
    }
    return out;
  }
  std::array<T, 32> small;
  std::vector<T> large;
  T* w = small.data();
  if (n > 16) large.resize(2 * n), w = large.data();
  for (std::size_t i = 0; i < n; ++i) w[2 * i] = P[i][0], w[2 * i + 1] = P[i][1];
  for (std::size_t k = 1; k < n; ++k)
    for (std::size_t i = 0; i + k < n; ++i) {
      w[2 * i] += t * (w[2 * i + 2] - w[2 * i]);
      w[2 * i + 1] += t * (w[2 * i + 3] - w[2 * i + 1]);
    }
  return Point<T, 2>{w[0], w[1]};
}

/// The power-basis coefficients c0 + c1 u + c2 u^2 + c3 u^3 of the cubic Bézier form with
/// control points P0..P3 (fewer points: the form of lower degree). In the unit frame (every
/// coordinate about 1 or less) the power basis on [0, 1] loses a few ulps, no more; Horner's
/// point and derivatives cost a third of three de Casteljau passes.
template <class T>
std::array<Vector<T, 2>, 4> power_cubic(const Point<T, 2>* P, std::size_t n) {
  std::array<Vector<T, 2>, 4> c{};
  for (int k = 0; k < 2; ++k) {
    const T p0 = P[0][k];
    if (n == 1) {
      c[0][k] = p0;
    } else if (n == 2) {
      c[0][k] = p0, c[1][k] = P[1][k] - p0;
    } else if (n == 3) {
      c[0][k] = p0, c[1][k] = 2 * (P[1][k] - p0), c[2][k] = P[2][k] - 2 * P[1][k] + p0;
    } else {
      c[0][k] = p0, c[1][k] = 3 * (P[1][k] - p0), c[2][k] = 3 * (P[2][k] - 2 * P[1][k] + p0);
      c[3][k] = P[3][k] - p0 + 3 * (P[1][k] - P[2][k]);
    }
  }
  return c;
}

/// A cubic Bézier's point and first two derivatives, from its control points (the
/// candidates' inner loops), by Horner in the power basis.
template <class T>
struct CubicForm {
  std::array<Point<T, 2>, 4> P;
  std::array<Vector<T, 2>, 4> c;
  CubicForm() = default;
  Bezier<T, 2> bezier() const { return Bezier<T, 2>({P[0], P[1], P[2], P[3]}); }
  explicit CubicForm(const Bezier<T, 2>& B) : P{B.points()[0], B.points()[1], B.points()[2], B.points()[3]}, c(power_cubic(P.data(), 4)) {}
  CubicForm(const Point<T, 2>& p0, const Point<T, 2>& p1, const Point<T, 2>& p2, const Point<T, 2>& p3)
      : P{p0, p1, p2, p3}, c(power_cubic(P.data(), 4)) {}
  Point<T, 2> at(T u) const {
    Point<T, 2> out;
    for (int k = 0; k < 2; ++k) out[k] = c[0][k] + u * (c[1][k] + u * (c[2][k] + u * c[3][k]));
    return out;
  }
  Vector<T, 2> d1(T u) const {
    Vector<T, 2> v;
    for (int k = 0; k < 2; ++k) v[k] = c[1][k] + u * (2 * c[2][k] + 3 * u * c[3][k]);
    return v;
  }
  Vector<T, 2> d2(T u) const {
    Vector<T, 2> v;
    for (int k = 0; k < 2; ++k) v[k] = 2 * c[2][k] + 6 * u * c[3][k];
    return v;
  }
};

/// A piece's point and first two derivatives: for a polynomial piece from its control
/// points and its first two hodographs, computed once (form_point, no allocation); for a
/// rational piece through the curve's own evaluation.
template <class T, class Piece>
struct PieceForm {
  static constexpr bool polynomial = std::is_same_v<Piece, Bezier<T, 2>>;
  std::conditional_t<polynomial, std::monostate, std::optional<Piece>> c;  ///< a rational piece itself
  std::vector<Point<T, 2>> P, H1, H2;  ///< a polynomial piece above degree 3: its points and hodographs
  bool cubic = false;                  ///< degree <= 3: Horner in the power basis (CubicForm's), no vectors
  std::array<Vector<T, 2>, 4> pc{};
  explicit PieceForm(const Piece& piece) {
    if constexpr (polynomial) {
      const auto& Q = piece.points();
      if (Q.size() <= 4) {
        cubic = true, pc = power_cubic(Q.data(), Q.size());
        return;
      }
      P = Q;
      const std::size_t n = P.size() - 1;
      for (std::size_t k = 0; k < n; ++k) H1.push_back(Point<T, 2>::from_vector(T(n) * (P[k + 1] - P[k])));
      for (std::size_t k = 0; k + 1 < n; ++k) H2.push_back(Point<T, 2>::from_vector(T(n - 1) * (H1[k + 1] - H1[k])));
    } else {
      c = piece;
    }
  }
  /// An upper bound of |C''| on [0, 1] (polynomial pieces: the second hodograph's control
  /// points, its convex hull; for degree <= 3 the line 2 c2 + 6 c3 t at its ends).
  T second_bound() const {
    T b = 0;
    if (cubic) return std::max(length(pc[2] * T(2)), length(pc[2] * T(2) + pc[3] * T(6)));
    for (const auto& q : H2) b = std::max(b, length(q.to_vector()));
    return b;
  }
  Point<T, 2> at(T t) const {
    if constexpr (polynomial) {
      if (cubic) {
        Point<T, 2> out;
        for (int k = 0; k < 2; ++k) out[k] = pc[0][k] + t * (pc[1][k] + t * (pc[2][k] + t * pc[3][k]));
        return out;
      }
      return form_point(P, t);
    } else {
      return (*c)(t);
    }
  }
  Vector<T, 2> d1(T t) const {
    if constexpr (polynomial) {
      if (cubic) {
        Vector<T, 2> v;
        for (int k = 0; k < 2; ++k) v[k] = pc[1][k] + t * (2 * pc[2][k] + 3 * t * pc[3][k]);
        return v;
      }
      return form_point(H1, t).to_vector();
    } else {
      return c->derivative_at(t, 1);
    }
  }
  Vector<T, 2> d2(T t) const {
    if constexpr (polynomial) {
      if (cubic) {
        Vector<T, 2> v;
        for (int k = 0; k < 2; ++k) v[k] = 2 * pc[2][k] + 6 * t * pc[3][k];
        return v;
      }
      return H2.empty() ? Vector<T, 2>{} : form_point(H2, t).to_vector();
    } else {
      return c->derivative_at(t, 2);
    }
  }
};

/// One smooth source of the offset, parametrised on [lo, hi]: a stretch of the exact
/// offset of one piece (between the piece's cusps and the offset's cusps) or a join arc.
/// point(t), velocity(t) (its derivative) and tangent(t) (the unit direction of travel,
/// its limit at an end where the velocity vanishes).
template <class T>
struct Source {
  std::function<Point<T, 2>(T)> point;
  std::function<Vector<T, 2>(T)> velocity;
  std::function<Vector<T, 2>(T)> tangent;
  std::function<std::pair<Point<T, 2>, Vector<T, 2>>(T)> frame;  ///< point and tangent at once
  T lo = 0, hi = 1;
  bool reversed = false;  ///< runs against the curve (1 - d kappa < 0), or an inner corner's line
  /// The offset's cusps inside (lo, hi) (a run of stretches approximated across them, see
  /// offset()): a candidate over a part that contains one is measured by its parametric
  /// distance or from partners (parametric, partner_distance), never by the normal scan.
  std::vector<T> cusps;
  bool spans_cusp(T a, T b) const {
    return std::any_of(cusps.begin(), cusps.end(), [&](T c) { return c > a && c < b; });
  }
};

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

/// A cubic's four control points (the raw offset's cubics: no allocation per cubic).
template <class T>
using Quad = std::array<Point<T, 2>, 4>;

/// What a cubic of the raw offset follows (the trim's tests differ): the offset of a
/// stretch of the curve, the outer join at a corner (round arc, miter or bevel) or the
/// line at an inner corner.
enum class RawKind : unsigned char { stretch, outer_join, inner_join };

/// The fitter's state: the raw offset's cubics, a reversed flag per cubic, and what each
/// follows (with the corner of a join).
template <class T>
struct Raw {
  std::vector<Quad<T>> cubics;
  std::vector<bool> reversed;
  std::vector<RawKind> kind;
  std::vector<Point<T, 2>> corner;  ///< the corner of a join's cubic (unused for a stretch)
  RawKind kind_now = RawKind::stretch;
  Point<T, 2> corner_now{};
  T max_error = 0;
  T tolerance = 0;
  std::size_t max_segments = 0;
  /// How far the next cubic's start will be moved to the last end (a short stretch of an
  /// untrimmed swallowtail left out, see offset()): its fit gets that much less tolerance.
  T start_shift = 0;

  void push(Quad<T> Q, bool rev) {
    const T tiny = 64 * std::numeric_limits<T>::epsilon();  // in the unit frame
    if (std::all_of(Q.begin(), Q.end(), [&](const auto& p) { return norm(p - Q.front()) <= tiny; })) return;  // a point
    if (cubics.size() >= max_segments) {
      throw InvalidArgument("tolerance", "the offset needs more than " + std::to_string(max_segments) +
                                             " cubic segments at this tolerance (the limit): use a larger tolerance");
    }
    if (!cubics.empty()) Q[0] = cubics.back()[3];  // continuous: the previous end (equal up to rounding at G1 joints)
    cubics.push_back(Q);
    reversed.push_back(rev);
    kind.push_back(kind_now);
    corner.push_back(corner_now);
  }
};

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

/// A candidate cubic over [a, b] with its scan.
template <class T>
struct Screened {
  CubicForm<T> cubic;
  NormalScan<T> scan;
  T error;  ///< the scan's estimate (the choice of the end), or the measure where the scan failed
  bool measured = false;  ///< error is the measure itself (projections: a failed scan, or a part across a cusp)
};

/// A candidate over [a, b] and its scan's estimate (a failed scan measured by
/// projections): the first whose estimate is within stop_above, else the one with the
/// smaller estimate. `hermite_first`: the Hermite cubic is screened first, and the fit is
/// made only where it fails (for the last part of a stretch, which is often a whole glyph
/// piece that the Hermite cubic already follows: a third of the glyphs' time went to fits
/// whose cubic was not needed); otherwise the fit first (the longer reach in the middle of
/// the search, where the Hermite cubic is rarely within the tolerance).
template <class T>
Screened<T>& best_screened(const Source<T>& s, T a, T b, T stop_above, bool hermite_first, std::array<Screened<T>, 2>& work) {
  const Ends<T> E(s, a, b);
  Screened<T>* best = nullptr;  // the scans (a few kB each) stay where they were made
  const bool across = s.spans_cusp(a, b);
  if (across) hermite_first = true;  // the Hermite cubic follows the offset's parametrisation, across cusps too
  const auto screen = [&](const CubicForm<T>& c) {
    Screened<T>& g = best == &work[0] ? work[1] : work[0];
    const T limit = best ? std::min(stop_above, best->error) : stop_above;
    g.cubic = c;
    if (across) {
      // No normal scan (its feet do not run in order about a cusp): the parametric bound
      // (cheap, and met by most Hermite cubics that are within the tolerance), else the
      // projections from partners.
      g.scan.ok = false, g.measured = true;
      g.error = parametric(c, s, a, b, limit);
      if (g.error > limit) g.error = partner_distance(c, s, a, b, limit);
    } else {
      normal_scan(c, s, a, b, limit, g.scan);
      g.measured = !g.scan.ok;
      g.error = g.scan.ok ? g.scan.estimate : hausdorff(c, s, a, b, limit);
    }
    if (!best || g.error < best->error) best = &g;
    return best->error <= stop_above;
  };
  if (hermite_first) {
    if (screen(E.hermite())) return *best;
    // Across a cusp, no fit where the Hermite cubic is more than 8 tolerances off (its
    // first sample over the limit): on W11's glyphs at d = 204.8 such fits saved 2 cubics
    // of 83,463, for 0.7% of the instructions (2.4% on the random cubics, which they never
    // saved one).
    if (across && best->error > 8 * stop_above) return *best;
    if (const auto f = fitted(s, a, b, E, stop_above)) screen(*f);
  } else {
    if (const auto f = fitted(s, a, b, E, stop_above)) {
      if (screen(*f)) return *best;
    }
    screen(E.hermite());
  }
  return *best;
}

/// The measured error of a screened candidate within stop_above: its scan's peaks (or the
/// projections where the scan failed or a peak's foot is not found).
template <class T>
T certify(Screened<T>& g, const Source<T>& s, T a, T b, T stop_above) {
  if (g.measured) return g.error;  // within stop_above: the projections ran to the end
  if (g.scan.ok) {
    const T e = normal_peaks(g.cubic, s, g.scan, stop_above);
    if (g.scan.ok) return e;
  }
  return hausdorff(g.cubic, s, a, b, stop_above);
}

/// The best candidate over [a, b] and its measured error (stop_above as measured's).
template <class T>
std::pair<Quad<T>, T> best_fit(const Source<T>& s, T a, T b, T stop_above, bool hermite_only) {
  const Ends<T> E(s, a, b);
  std::optional<CubicForm<T>> best;
  T err = std::numeric_limits<T>::infinity();
  if (!hermite_only) {
    if (const auto f = fitted(s, a, b, E, stop_above)) err = measured(*f, s, a, b, stop_above), best = *f;
  }
  const CubicForm<T> h = E.hermite();
  const T e = measured(h, s, a, b, std::min(stop_above, err));
  if (!(e >= err)) err = e, best = h;
  if (!best) best = h, err = std::numeric_limits<T>::infinity();
  return {best->P, err};
}

/// Approximates the whole source by cubics within the tolerance into raw.
template <class T>
void approximate(const Source<T>& s, OffsetFit fit, Raw<T>& raw) {
  const T tol = raw.tolerance;
  const T min_step = (s.hi - s.lo) * T(1e-9);
  if (fit == OffsetFit::uniform) {
    for (std::size_t n = 1;; ++n) {
      if (n > raw.max_segments) {
        throw InvalidArgument("tolerance", "the reference subdivision needs more than " + std::to_string(raw.max_segments) + " cubics");
      }
      std::vector<Quad<T>> parts;
      T worst = 0;
      bool ok = true;
      for (std::size_t i = 0; i < n && ok; ++i) {
        const T a = s.lo + (s.hi - s.lo) * T(i) / T(n), b = i + 1 == n ? s.hi : s.lo + (s.hi - s.lo) * T(i + 1) / T(n);
        auto [B, e] = best_fit(s, a, b, tol, true);
        ok = e <= tol;
        worst = std::max(worst, e);
        parts.push_back(std::move(B));
      }
      if (ok) {
        raw.max_error = std::max(raw.max_error, worst);
        for (const auto& B : parts) raw.push(B, s.reversed);
        return;
      }
    }
  }
  // Greedy: the farthest end b whose best candidate is measured within the tolerance,
  // found from a model of the error (growing as about the fifth power of the step on
  // smooth parts: each next end proposed from the last error, the first from the last
  // step) inside a bracket [lo, hi] (within, over; bisection where the model fails), until
  // an end is measured at 70% of the tolerance or more, or the bracket is within 1/16 of
  // the step (90% and 1/64 made 0.7% fewer cubics on W11's random cubics for 1.25 times
  // the instructions: the band [0.9, 1] of the error is 2% of the step). Each end's candidates are compared by their normal scans' estimates (the
  // largest sample and a parabola at its top); the best, when estimated within the
  // tolerance, is measured (its scan's peaks: see NormalScan), so the cubic kept needs no
  // further check.
  T a = s.lo;
  T last_step = s.hi - s.lo;
  const T full_tol = tol;
  while (a < s.hi) {
    const T shift = raw.start_shift;
    const T tol = full_tol - shift;  // the first cubic after a stretch left out: less
    T lo = a, hi = s.hi;
    bool hi_tested = false;
    std::optional<std::pair<CubicForm<T>, T>> B;  // the longest cubic within the tolerance, its error
    std::array<Screened<T>, 2> work;
    T x = std::min(s.hi, a + last_step);
    for (int it = 0; it < 200; ++it) {
      if (x - a < min_step) {
        throw InvalidArgument("tolerance", "cannot be met by cubics near the offset's parameter " + std::to_string(a) +
                                               " of a piece (below the rounding of the computation): use a larger tolerance");
      }
      Screened<T>& g = best_screened(s, a, x, tol, x == s.hi, work);
      T e = g.error;
      if (e <= tol) e = certify(g, s, a, x, tol);
      if (e <= tol) {
        lo = x, B = std::pair{g.cubic, e};
        if (x == s.hi || e >= T(0.7) * tol) break;
      } else {
        hi = x, hi_tested = true;
      }
      if (B && hi_tested && hi - lo <= (lo - a) / 16) break;
      T next = std::numeric_limits<T>::quiet_NaN();
      if (std::isfinite(e) && e > 0) next = a + (x - a) * std::pow(T(0.95) * tol / e, T(0.2));
      if (!(next > lo)) next = lo + (hi - lo) / 2;
      if (next >= hi) next = hi_tested ? lo + (hi - lo) / 2 : s.hi;
      if (!B && next > a + (x - a) / 2 && !(e <= tol)) next = std::min(next, a + (x - a) / 2 + (x - a) / 4);  // failing: shrink surely
      if (next == x) break;
      x = next;
    }
    if (!B) {
      throw InvalidArgument("tolerance", "cannot be met by cubics near the offset's parameter " + std::to_string(a) +
                                             " of a piece (below the rounding of the computation): use a larger tolerance");
    }
    raw.max_error = std::max(raw.max_error, B->second + shift);
    raw.push(B->first.P, s.reversed);
    raw.start_shift = 0;
    last_step = lo - a;
    a = lo;
  }
}

/// The unit tangent of a piece at its own parameter t, the limit from inside [lo, hi]
/// where the first derivative vanishes: the first non-zero derivative of order k (up to
/// 6), signed (-1)^(k-1) at the right end of the stretch (C'(t) ~ C^(k)(t0) (t - t0)^(k-1)
/// / (k-1)!). `tiny`: the size below which a derivative counts as zero.
template <class T, class Piece>
Vector<T, 2> limit_tangent(const Piece& c, T t, bool from_left, T tiny) {
  for (int k = 1; k <= 6; ++k) {
    const Vector<T, 2> v = c.derivative_at(t, k);
    if (length(v) > tiny) return unit(v) * ((from_left && k % 2 == 0) ? T(-1) : T(1));
  }
  return {};
}

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

/// The offset's stretches of one piece (own parameter [0, 1]) split at the piece's cusps
/// (zero speed) and the offset's cusps (1 - d kappa = 0, or a touch of it), each with the
/// curve's tangents at its ends.
template <class T>
struct Stretch {
  T lo, hi;
  bool reversed;
  Vector<T, 2> t_lo, t_hi;  // the curve's unit tangents (limits) at the ends
};

/// n values on the stack up to N, on the heap beyond (the grids of stretches()).
template <class T, std::size_t N>
struct Scratch {
  std::array<T, N> small;
  std::vector<T> large;
  T* p = nullptr;
  explicit Scratch(std::size_t n) {
    if (n > N) large.resize(n), p = large.data();
    else p = small.data();
  }
  T& operator[](int i) { return p[i]; }
  const T& operator[](int i) const { return p[i]; }
};

template <class T, class Piece>
std::vector<Stretch<T>> stretches(const Piece& c, T d, T tiny) {
  const int n = c.degree();
  const int M = std::max(64, 16 * (n + 1));
  const PieceForm<T, Piece> form(c);
  const auto speed = [&](T t) { return length(form.d1(t)); };
  const auto g = [&](T t) {  // 1 - d kappa
    const Vector<T, 2> d1 = form.d1(t), d2 = form.d2(t);
    const T s = length(d1);
    return 1 - d * cross(d1, d2) / (s * s * s);
  };
  Scratch<T, 129> grid(static_cast<std::size_t>(M) + 1), sp(static_cast<std::size_t>(M) + 1);
  T top = 0;
  for (int j = 0; j <= M; ++j) grid[j] = T(j) / M, sp[j] = speed(grid[j]), top = std::max(top, sp[j]);
  // A zero of the speed within one grid step of t makes |C'(t)| at most the step times
  // max |C''|, which the second hodograph's control points bound (convex hull): a local
  // minimum of the sampled speed above that is no cusp and is not refined (polynomial
  // pieces; a rational piece's every minimum is refined).
  T near_zero = std::numeric_limits<T>::infinity();
  if constexpr (PieceForm<T, Piece>::polynomial) {
    const T b2 = form.second_bound();
    near_zero = (b2 / T(M)) * (1 + T(1e-6)) + tiny;
  }
  // The piece's interior cusps: local minima of the speed below 1e-6 of its largest.
  std::vector<T> cusps{T(0)};
  for (int j = 1; j < M; ++j) {
    if (sp[j] <= sp[j - 1] && sp[j] <= sp[j + 1] && sp[j] <= near_zero) {
      T lo = grid[j - 1], hi = grid[j + 1];
      const T rr = T(0.6180339887498948482045868343656381L);
      for (int k = 0; k < 60; ++k) {
        const T x1 = hi - rr * (hi - lo), x2 = lo + rr * (hi - lo);
        if (speed(x1) <= speed(x2)) hi = x2; else lo = x1;
      }
      const T t = (lo + hi) / 2;
      if (speed(t) <= T(1e-6) * top && t > grid[1] / 4 && t < 1 - grid[1] / 4) cusps.push_back(t);
    }
  }
  cusps.push_back(T(1));
  // A cubic piece (or one of lower degree) whose 1 - d kappa is surely positive has no
  // cusp of the offset, and its grid of 1 - d kappa is not needed (most pieces: on the
  // convex side of the curve d kappa <= 0; elsewhere, mostly, |d| is well under the
  // radius of curvature). d kappa = d cross(C', C'') / |C'|^3, whose numerator is the
  // quadratic 2 cross(c1, c2) + 6 cross(c1, c3) t + 6 cross(c2, c3) t^2 in the power basis
  // (its largest value on [0, 1] exactly: the ends and the vertex), whose denominator is
  // at least the cube of a lower bound of the speed: the grid's smallest speed less half a
  // step times max |C''| (the speed is Lipschitz with that constant).
  bool positive = false;
  if constexpr (PieceForm<T, Piece>::polynomial) {
    if (form.cubic && d != 0) {
      const auto& pc = form.pc;
      const T k0 = 2 * cross(pc[1], pc[2]), k1 = 6 * cross(pc[1], pc[3]), k2 = 6 * cross(pc[2], pc[3]);
      const auto num = [&](T t) { return d * (k0 + t * (k1 + t * k2)); };
      T top_num = std::max(num(0), num(1));
      if (k2 != 0) {
        const T tv = -k1 / (2 * k2);
        if (tv > 0 && tv < 1) top_num = std::max(top_num, num(tv));
      }
      T low = std::numeric_limits<T>::infinity();
      for (int j = 0; j <= M; ++j) low = std::min(low, sp[j]);
      low -= form.second_bound() / (2 * T(M));
      positive = top_num <= 0 || (low > 0 && top_num < T(0.5) * low * low * low);
    }
  }
  std::vector<Stretch<T>> out;
  for (std::size_t i = 0; i + 1 < cusps.size(); ++i) {
    const T a = cusps[i], b = cusps[i + 1];
    // The offset's cusps on (a, b): sign changes of g on a grid, and near-zero minima of |g|.
    std::vector<T> cuts{a};
    if (d != 0 && !positive) {
      const int K = M;
      const T h = (b - a) / K;
      Scratch<T, 129> gv(static_cast<std::size_t>(K) + 1);
      for (int j = 0; j <= K; ++j) {
        const T t = a + h * T(j) + (j == 0 ? h / 1024 : j == K ? -h / 1024 : T(0));  // off the cusps, where g is undefined
        gv[j] = g(t);
      }
      for (int j = 0; j < K; ++j) {
        const T t0 = a + h * T(j), t1 = j + 1 == K ? b : a + h * T(j + 1);
        if ((gv[j] < 0) != (gv[j + 1] < 0) && std::isfinite(gv[j]) && std::isfinite(gv[j + 1])) {
          T lo = std::max(t0, a + h / 1024), hi = std::min(t1, b - h / 1024);
          const bool neg_lo = g(lo) < 0;
          for (int k = 0; k < 80 && lo < hi; ++k) {
            const T mid = (lo + hi) / 2;
            if (!(mid > lo && mid < hi)) break;  // adjacent doubles: done
            if ((g(mid) < 0) == neg_lo) lo = mid; else hi = mid;
          }
          cuts.push_back((lo + hi) / 2);
        } else if (j > 0 && std::abs(gv[j]) <= std::abs(gv[j - 1]) && std::abs(gv[j]) <= std::abs(gv[j + 1]) &&
                   std::abs(gv[j]) <= 2 * std::max(std::abs(gv[j - 1] - gv[j]), std::abs(gv[j + 1] - gv[j])) + T(1e-9)) {
          // A touch of zero (a double root t* within half a step of the sample: g about
          // c (t - t*)^2) leaves |g| at the sample at most a quarter of its rise to either
          // neighbour; minima far above that (most minima of |1 - d kappa|) are not refined.
          T lo = a + h * T(j - 1), hi = a + h * T(j + 1);
          const T rr = T(0.6180339887498948482045868343656381L);
          for (int k = 0; k < 60; ++k) {
            const T x1 = hi - rr * (hi - lo), x2 = lo + rr * (hi - lo);
            if (std::abs(g(x1)) <= std::abs(g(x2))) hi = x2; else lo = x1;
          }
          const T t = (lo + hi) / 2;
          if (std::abs(g(t)) <= T(1e-9)) cuts.push_back(t);  // |d| touches the radius of curvature
        }
      }
      std::sort(cuts.begin(), cuts.end());
    }
    cuts.push_back(b);
    // One cusp found twice (a sign change and a touch of 1 - d kappa a rounding apart):
    // cuts within 64 ulps of 1 merged (a stretch of no length, which only the projections
    // of the fallback measure could measure, at length).
    {
      std::vector<T> merged{cuts.front()};
      for (std::size_t k = 1; k < cuts.size(); ++k) {
        if (cuts[k] - merged.back() > tiny) merged.push_back(cuts[k]);
        else if (k + 1 == cuts.size()) merged.back() = cuts[k];
      }
      if (merged.size() == 1) merged.push_back(b);
      cuts = std::move(merged);
    }
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const T lo = cuts[k], hi = cuts[k + 1];
      if (!(hi > lo)) continue;
      const T mid = (lo + hi) / 2;
      // At a cusp of the piece the speed is zero only to the accuracy of its minimisation:
      // derivatives below 1e-5 of the largest speed count as zero there.
      const T zero_lo = (k == 0 && i > 0) ? T(1e-5) * top : tiny;
      const T zero_hi = (k + 2 == cuts.size() && i + 2 < cusps.size()) ? T(1e-5) * top : tiny;
      // The tangent from the first derivative where it is not zero (the piece's form, no
      // allocation), else its limit from the higher derivatives.
      const auto tangent_at = [&](T t, bool from_left, T zero) {
        const Vector<T, 2> v = form.d1(t);
        return length(v) > zero ? unit(v) : limit_tangent<T>(c, t, from_left, zero);
      };
      Stretch<T> s{lo, hi, d != 0 && g(mid) < 0, tangent_at(lo, false, zero_lo), tangent_at(hi, true, zero_hi)};
      out.push_back(s);
    }
  }
  return out;
}

/// The Source of the offset of piece c over the stretches first..last (one, or a run of
/// them) as one smooth curve across the offset's cusps between them (where 1 - d kappa
/// changes sign or touches zero): O(t) = C(t) + d N(t) is as smooth in t as C there (its
/// velocity (1 - d kappa) C' only passes through zero), so a cubic can follow it across a
/// cusp (near one it is a semicubical cusp, (t^2, t^3) to leading order, which a cubic
/// represents). The direction of travel is sign(1 - d kappa) T (constant over one
/// stretch); the cusps are the stretches' ends between them (Source::cusps: parts across
/// them are measured by parametric and partner_distance).
template <class T, class Piece>
Source<T> offset_source(const Piece& c, const Stretch<T>* first, const Stretch<T>* last, T d) {
  // One shared state, so that each std::function holds a pointer only (no allocation of
  // its own: the small-object buffer).
  struct State {
    PieceForm<T, Piece> form;
    T lo, hi, d;
    Vector<T, 2> t_lo, t_hi;
    T sign_lo, sign_hi;
    bool varying;  // a run across cusps: the sign of 1 - d kappa at each t
    Vector<T, 2> tan(T t) const {
      if (t == lo) return t_lo;
      if (t == hi) return t_hi;
      const Vector<T, 2> v = unit(form.d1(t));
      return length(v) > 0 ? v : (t - lo < hi - t ? t_lo : t_hi);
    }
    T sign(T t) const {
      if (!varying || t == lo) return sign_lo;
      if (t == hi) return sign_hi;
      const Vector<T, 2> d1 = form.d1(t), d2 = form.d2(t);
      const T sp = length(d1);
      return sp > 0 && 1 - d * cross(d1, d2) / (sp * sp * sp) < 0 ? T(-1) : T(1);
    }
  };
  const auto st = std::make_shared<const State>(State{PieceForm<T, Piece>(c), first->lo, last->hi, d, first->t_lo, last->t_hi,
                                                      first->reversed ? T(-1) : T(1), last->reversed ? T(-1) : T(1), first != last});
  Source<T> src;
  src.point = [st](T t) { return st->form.at(t) + left(st->tan(t)) * st->d; };
  src.velocity = [st](T t) {
    const Vector<T, 2> d1 = st->form.d1(t), d2 = st->form.d2(t);
    const T sp = length(d1);
    if (!(sp > 0)) return Vector<T, 2>{};
    return d1 * (1 - st->d * cross(d1, d2) / (sp * sp * sp));
  };
  src.tangent = [st](T t) { return st->tan(t) * st->sign(t); };
  src.frame = [st](T t) {
    const Vector<T, 2> u = st->tan(t);
    return std::pair{st->form.at(t) + left(u) * st->d, u * st->sign(t)};
  };
  src.lo = st->lo, src.hi = st->hi;
  src.reversed = first->reversed;
  for (const Stretch<T>* k = first; k != last; ++k) src.cusps.push_back(k->hi);
  return src;
}

/// The Source of the offset of piece c over one stretch.
template <class T, class Piece>
Source<T> stretch_source(const Piece& c, const Stretch<T>& s, T d) {
  return offset_source<T>(c, &s, &s, d);
}

/// The curve (in the unit frame) as the trim sees it: its pieces and the boxes of their
/// control points (a piece lies inside its box), to ask whether a point is nearer to the
/// curve than a distance.
template <class T>
struct Nearness {
  static constexpr std::size_t max_points = 16;  // polynomial pieces up to degree 15 by subdivision
  std::vector<BezierPiece<T, 2>> pieces;
  std::vector<std::array<Point<T, 2>, 2>> boxes;
  T leaf = 0;  ///< the box diagonal at which subdivision stops (a fraction of the tolerance)

  void add(const BezierPiece<T, 2>& piece) {
    std::array<Point<T, 2>, 2> box{};
    std::visit(
        [&](const auto& c) {
          box = {c.points().front(), c.points().front()};
          for (const auto& p : c.points()) {
            for (int k = 0; k < 2; ++k) box[0][k] = std::min(box[0][k], p[k]), box[1][k] = std::max(box[1][k], p[k]);
          }
        },
        piece);
    pieces.push_back(piece);
    boxes.push_back(box);
  }
  /// Whether the polynomial piece with control points P[0..m) comes nearer to p than r.
  /// Its control points lie within e of its chord S (the segment between its ends), so the
  /// piece does (its hull is inside that band, and it runs from end to end of S): its
  /// distance from p is within e of S's. Decided when that settles it, else the piece is
  /// halved (de Casteljau), nearer half first, until e is below `leaf` (then S's distance
  /// decides: a point up to `leaf` farther than r may count as near).
  bool near_polynomial(const Point<T, 2>* P, std::size_t m, const Point<T, 2>& p, T r, int depth) const {
    const Point<T, 2>& a = P[0];
    const Vector<T, 2> ab = P[m - 1] - a;
    const T l2 = ab[0] * ab[0] + ab[1] * ab[1];
    const auto to_chord = [&](const Point<T, 2>& q) {
      const Vector<T, 2> aq = q - a;
      const T s = l2 > 0 ? std::clamp((aq[0] * ab[0] + aq[1] * ab[1]) / l2, T(0), T(1)) : T(0);
      const Vector<T, 2> e = aq - ab * s;
      return std::sqrt(e[0] * e[0] + e[1] * e[1]);
    };
    T e = 0;
    for (std::size_t j = 1; j + 1 < m; ++j) e = std::max(e, to_chord(P[j]));
    const T ds = to_chord(p);
    if (ds - e >= r) return false;
    if (ds + e < r) return true;
    if (e <= leaf || depth >= 60) return ds < r;
    std::array<Point<T, 2>, max_points> L, R, W;
    for (std::size_t j = 0; j < m; ++j) W[j] = P[j];
    for (std::size_t level = 0; level < m; ++level) {
      L[level] = W[0];
      R[m - 1 - level] = W[m - 1 - level];
      for (std::size_t j = 0; j + 1 < m - level; ++j) W[j] = W[j] + (W[j + 1] - W[j]) * T(0.5);
    }
    const T dl = length(L[m / 2] - p), dr = length(R[m / 2] - p);  // the nearer half first
    if (dl <= dr) return near_polynomial(L.data(), m, p, r, depth + 1) || near_polynomial(R.data(), m, p, r, depth + 1);
    return near_polynomial(R.data(), m, p, r, depth + 1) || near_polynomial(L.data(), m, p, r, depth + 1);
  }
  /// A grid over the pieces' boxes for the queries of radius at most `reach` (cells of at
  /// least that size, at most about 4 per piece): a query looks at the pieces listed in
  /// the 2 x 2 or more cells its disc's box meets, not at all the pieces.
  T cell = 0, reach = 0;
  Point<T, 2> grid_lo{};
  std::size_t nx = 0, ny = 0;
  std::vector<std::vector<std::uint32_t>> cells;
  mutable std::vector<std::size_t> seen;  // the query stamp that last looked at a piece
  mutable std::size_t stamp = 0;

  void build_grid(T r) {
    reach = r;
    Point<T, 2> lo = boxes.front()[0], hi = boxes.front()[1];
    for (const auto& b : boxes) {
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], b[0][k]), hi[k] = std::max(hi[k], b[1][k]);
    }
    const T w = hi[0] - lo[0], h = hi[1] - lo[1];
    const T budget = T(4 * boxes.size() + 16);
    cell = std::max({r, std::sqrt(w * h / budget), std::max(w, h) / budget, std::numeric_limits<T>::min()});
    nx = static_cast<std::size_t>(w / cell) + 1, ny = static_cast<std::size_t>(h / cell) + 1;
    grid_lo = lo;
    cells.assign(nx * ny, {});
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto [x0, y0] = at(boxes[i][0]);
      const auto [x1, y1] = at(boxes[i][1]);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) cells[y * nx + x].push_back(static_cast<std::uint32_t>(i));
    }
    seen.assign(boxes.size(), 0);
  }
  std::pair<std::size_t, std::size_t> at(const Point<T, 2>& q) const {
    const auto idx = [&](T v, std::size_t n) {
      if (!(v > 0)) return std::size_t(0);
      return std::min(static_cast<std::size_t>(v / cell), n - 1);
    };
    return {idx(q[0] - grid_lo[0], nx), idx(q[1] - grid_lo[1], ny)};
  }
  bool near_piece(std::size_t i, const Point<T, 2>& p, T r) const {
    const T dx = std::max({boxes[i][0][0] - p[0], T(0), p[0] - boxes[i][1][0]});
    const T dy = std::max({boxes[i][0][1] - p[1], T(0), p[1] - boxes[i][1][1]});
    if (dx * dx + dy * dy >= r * r) return false;
    return std::visit(
        [&](const auto& c) {
          using C = std::decay_t<decltype(c)>;
          if constexpr (std::is_same_v<C, Bezier<T, 2>>) {
            if (c.points().size() <= max_points) return near_polynomial(c.points().data(), c.points().size(), p, r, 0);
          }
          return project(c, p).distance < r;
        },
        pieces[i]);
  }
  /// True when some point of the curve lies nearer to p than r (or up to `leaf` farther;
  /// see near_polynomial): the pieces whose box is nearer than r, polynomial ones by
  /// subdivision, rational ones (and degree above 15) projected on (project()).
  bool within(const Point<T, 2>& p, T r) const {
    if (!(r > 0)) return false;
    if (!cells.empty() && r <= reach) {
      ++stamp;
      const auto [x0, y0] = at(Point<T, 2>{p[0] - r, p[1] - r});
      const auto [x1, y1] = at(Point<T, 2>{p[0] + r, p[1] + r});
      for (std::size_t y = y0; y <= y1; ++y) {
        for (std::size_t x = x0; x <= x1; ++x) {
          for (const std::uint32_t i : cells[y * nx + x]) {
            if (seen[i] == stamp) continue;
            seen[i] = stamp;
            if (near_piece(i, p, r)) return true;
          }
        }
      }
      return false;
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (near_piece(i, p, r)) return true;
    }
    return false;
  }
};

/// Where the raw cubic Q crosses the circle of radius r about e (an end of an open curve:
/// its round cap, which the raw offset does not hold): sign changes of |Q(u) - e| - r on 32
/// equal parts (values within eps of zero skipped: the offset starts on the circle), each
/// narrowed by bisection. Appends the raw parameters i + u.
template <class T>
void cap_crossings(const Quad<T>& Q, std::size_t i, const Point<T, 2>& e, T r, T eps, std::vector<T>& out) {
  T lo[2], hi[2];
  for (int k = 0; k < 2; ++k) {
    lo[k] = hi[k] = Q[0][k];
    for (const auto& p : Q) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  const T dx = std::max({lo[0] - e[0], T(0), e[0] - hi[0]}), dy = std::max({lo[1] - e[1], T(0), e[1] - hi[1]});
  if (std::sqrt(dx * dx + dy * dy) > r + eps) return;  // the box outside the circle
  const T fx = std::max(std::abs(lo[0] - e[0]), std::abs(hi[0] - e[0])), fy = std::max(std::abs(lo[1] - e[1]), std::abs(hi[1] - e[1]));
  if (std::sqrt(fx * fx + fy * fy) < r - eps) return;  // inside it
  const CubicForm<T> F(Q[0], Q[1], Q[2], Q[3]);
  const auto f = [&](T u) { return length(F.at(u) - e) - r; };
  T last_u = 0;
  int last_sign = 0;
  for (int j = 0; j <= 32; ++j) {
    const T u = T(j) / 32, v = f(u);
    const int sign = v > eps ? 1 : (v < -eps ? -1 : 0);
    if (sign == 0) continue;
    if (last_sign != 0 && sign != last_sign) {
      T a = last_u, b = u;
      for (int k = 0; k < 60 && b - a > T(1e-15); ++k) {
        const T m = (a + b) / 2;
        ((f(m) > 0) == (last_sign > 0) ? a : b) = m;
      }
      out.push_back(static_cast<T>(i) + (a + b) / 2);
    }
    last_u = u, last_sign = sign;
  }
}

/// The crossings of the raw offset's cubics with each other (consecutive ones too: a join
/// arc meets the stretch before it away from their shared end), appended to `out` as raw
/// parameters (cubic i on [i, i + 1]), both parameters of each, and the ends of overlaps.
/// Pairs whose control boxes meet, found by a sweep over the boxes sorted by their left
/// side (sweep and prune: the pairs of a path without interference are its neighbours'),
/// each intersected as two cubics (intersect(), its fast path for degree <= 3). A point
/// at the shared end of neighbours comes too; an extra cut only splits a part whose
/// pieces are judged alike.
template <class T>
void raw_crossings(const Raw<T>& raw, std::vector<T>& out) {
  const std::size_t n = raw.cubics.size();
  std::vector<std::array<T, 4>> box(n);  // x lo, x hi, y lo, y hi
  for (std::size_t i = 0; i < n; ++i) {
    const Quad<T>& Q = raw.cubics[i];
    box[i] = {Q[0][0], Q[0][0], Q[0][1], Q[0][1]};
    for (const auto& p : Q) {
      box[i][0] = std::min(box[i][0], p[0]), box[i][1] = std::max(box[i][1], p[0]);
      box[i][2] = std::min(box[i][2], p[1]), box[i][3] = std::max(box[i][3], p[1]);
    }
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return box[a][0] < box[b][0]; });
  const T slack = 64 * std::numeric_limits<T>::epsilon();  // in the unit frame
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t i = order[a];
    for (std::size_t b = a + 1; b < n && box[order[b]][0] <= box[i][1] + slack; ++b) {
      const std::size_t j = order[b];
      if (box[j][2] > box[i][3] + slack || box[i][2] > box[j][3] + slack) continue;
      const Quad<T>& P = raw.cubics[i];
      const Quad<T>& Q = raw.cubics[j];
      // Neighbours that lie on either side of a line through their shared end (every other
      // control point strictly) meet only there: the common case of a smooth stretch.
      if (j == i + 1 || i == j + 1) {
        const Quad<T>& A = j == i + 1 ? P : Q;  // the first of the two
        const Quad<T>& B = j == i + 1 ? Q : P;
        const auto apart = [&](const Vector<T, 2>& v) {
          for (int k = 0; k < 3; ++k) {
            if (!(dot(A[static_cast<std::size_t>(k)] - A[3], v) < 0)) return false;
          }
          for (int k = 1; k < 4; ++k) {
            if (!(dot(B[static_cast<std::size_t>(k)] - B[0], v) > 0)) return false;
          }
          return true;
        };
        if (apart(B[3] - A[0]) || apart(B[1] - B[0]) || apart(A[3] - A[2])) continue;
      }
      const Intersections<T> x = intersect(Bezier<T, 2>({P[0], P[1], P[2], P[3]}), Bezier<T, 2>({Q[0], Q[1], Q[2], Q[3]}));
      for (const auto& p : x.points) {
        // Not the shared end of neighbours (found there as a touch or a crossing).
        if (j == i + 1 && length(p.point - P[3]) <= T(1e-9)) continue;
        if (i == j + 1 && length(p.point - P[0]) <= T(1e-9)) continue;
        out.push_back(static_cast<T>(i) + p.ta), out.push_back(static_cast<T>(j) + p.tb);
      }
      for (const auto& v : x.overlaps) {
        out.insert(out.end(), {static_cast<T>(i) + v.a.lo, static_cast<T>(i) + v.a.hi, static_cast<T>(j) + v.b_start, static_cast<T>(j) + v.b_end});
      }
    }
  }
}

/// The trim (see offset()): the raw path (cubic i on [i, i + 1]) cut at its
/// self-intersections, at the ends of its reversed runs and joins (the cusps of the offset,
/// the corners) and, for an open curve, where it crosses the round caps of the curve's
/// ends; each part between cuts judged on samples in its share of each raw cubic (8 to 32
/// parts, at most |d| apart): kept
/// where they are at least |d| - tol from the curve (for an outer join, the point moved
/// radially onto the arc of radius |d| about the corner, so that a miter or bevel is
/// judged as the round join it replaces); where the samples disagree (the offset of the
/// other side of the curve passes there, which is not in the raw path) the change is found
/// by bisection. Returns the
/// kept parameter intervals in order; `dropped` counts the runs cut away.
template <class T>
std::vector<Interval<T>> trimmed_intervals(const Pieces<T, 2>& path, const Raw<T>& raw, const Nearness<T>& near, T d, T tol,
                                           const std::optional<std::array<Point<T, 2>, 2>>& open_ends, std::size_t& dropped) {
  const std::size_t n = raw.cubics.size();
  const T r = std::abs(d);
  std::vector<T> cut{T(0), static_cast<T>(n)};
  for (std::size_t i = 1; i < n; ++i) {
    if (raw.reversed[i] != raw.reversed[i - 1] || raw.kind[i] != raw.kind[i - 1]) cut.push_back(static_cast<T>(i));
  }
  std::sort(cut.begin(), cut.end());
  const std::vector<T> structural = cut;  // not crossings: their points are judged too
  raw_crossings(raw, cut);
  if (open_ends) {
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& e : *open_ends) cap_crossings(raw.cubics[i], i, e, r, T(1e-3) * tol, cut);
    }
  }
  // A crossing at a joint that is a cut already (the shared end of neighbours, rounded):
  // that joint, so that no sliver part lies between them.
  for (std::size_t k = structural.size(); k < cut.size(); ++k) {
    const T j = std::round(cut[k]);
    if (std::abs(cut[k] - j) <= T(1e-9) && std::binary_search(structural.begin(), structural.end(), j)) cut[k] = j;
  }
  std::sort(cut.begin(), cut.end());
  cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
  // The point of the raw offset at parameter t as judged (an outer join's moved onto the arc).
  const auto judged = [&](T t) {
    const std::size_t i = std::min(static_cast<std::size_t>(t), n - 1);
    const Quad<T>& Q = raw.cubics[i];
    Point<T, 2> p = CubicForm<T>(Q[0], Q[1], Q[2], Q[3]).at(t - static_cast<T>(i));
    if (raw.kind[i] == RawKind::outer_join) {  // a miter or bevel (a round arc's cubic is itself judged)
      const Vector<T, 2> v = p - raw.corner[i];
      const T lv = length(v);
      if (lv > 0 && std::abs(lv - r) > tol) p = raw.corner[i] + v * (r / lv);
    }
    return p;
  };
  // A point is judged on |d| - tol (a point of the offset is that far, the fit's error
  // allowing); a change between two samples is placed where the distance passes it.
  const auto valid = [&](T t) { return !near.within(judged(t), r - tol); };
  std::vector<Interval<T>> kept;
  const auto keep = [&](T lo, T hi, bool ok, bool& last_ok) {
    if (!ok) {
      if (last_ok) ++dropped;
    } else if (!kept.empty() && kept.back().hi == lo) {
      kept.back().hi = hi;
    } else {
      kept.push_back({lo, hi});
    }
    last_ok = ok;
  };
  bool last_ok = true;
  std::vector<std::pair<T, bool>> samples;
  struct Run {
    Interval<T> iv;
    bool ok;
    bool deep;
  };
  std::vector<Run> all;
  for (std::size_t k = 0; k + 1 < cut.size(); ++k) {
    const T a = std::max(cut[k], T(0)), b = std::min(cut[k + 1], static_cast<T>(n));
    if (!(b - a > T(1e-12))) continue;
    // Samples inside the part: 7 or more in its share of each raw cubic, the joints between, and
    // its ends where they are not crossings (at a crossing the point is |d| from the curve
    // on both sides: judging it would keep a sliver of the part cut away).
    samples.clear();
    const auto is_structural = [&](T t) { return std::binary_search(structural.begin(), structural.end(), t); };
    if (is_structural(a)) samples.emplace_back(a, valid(a));
    for (std::size_t i = std::min(static_cast<std::size_t>(a), n - 1); i < n && static_cast<T>(i) < b; ++i) {
      const T lo = std::max(a, static_cast<T>(i)), hi = std::min(b, static_cast<T>(i + 1));
      if (!(hi > lo)) continue;
      // At most |d| apart along the cubic (its control polygon's length): the stretch of an
      // offset within |d| of a part of the curve that crosses it is at least 2 |d| long.
      // 8 to 32 parts.
      const Quad<T>& Q = raw.cubics[i];
      const T poly = length(Q[1] - Q[0]) + length(Q[2] - Q[1]) + length(Q[3] - Q[2]);
      const T want = std::ceil(poly * (hi - lo) / r);
      const int m = want > 32 ? 32 : (want < 8 ? 8 : static_cast<int>(want));
      for (int j = lo > a ? 0 : 1; j < m; ++j) {
        const T t = lo + (hi - lo) * T(j) / T(m);
        samples.emplace_back(t, valid(t));
      }
    }
    if (is_structural(b)) samples.emplace_back(b, valid(b));
    // Where the samples disagree, the change (the offset of another part of the curve, a
    // cap, passes there without crossing this side's offset) narrowed by bisection.
    std::vector<std::pair<Interval<T>, bool>> runs;
    T at = a;
    for (std::size_t j = 1; j < samples.size(); ++j) {
      if (samples[j].second == samples[j - 1].second) continue;
      T lo = samples[j - 1].first, hi = samples[j].first;
      for (int it = 0; it < 48 && hi - lo > T(1e-13) && length(path(hi) - path(lo)) > tol / 16; ++it) {
        const T m = (lo + hi) / 2;
        (valid(m) == samples[j - 1].second ? lo : hi) = m;
      }
      const T c = samples[j - 1].second ? lo : hi;  // the end on the kept side
      if (c > at) runs.push_back({{at, c}, samples[j - 1].second});
      at = std::max(at, c);
    }
    if (b > at) runs.push_back({{at, b}, samples.empty() || samples.back().second});
    // A kept run between a crossing and a change is the spur of a part cut away there when
    // it is short, all within 8 tol of the crossing (the raw offset is up to tol off the
    // exact one, so the distance passes |d| - tol a little past the crossing, farther
    // where the two offsets cross at a small angle, as near a cusp of the offset): cut
    // away with it.
    if (runs.size() > 1) {
      const auto spur = [&](const Interval<T>& iv, T end) {
        const Point<T, 2> x = path(end);
        for (int j = 0; j <= 8; ++j) {
          if (length(path(iv.lo + (iv.hi - iv.lo) * T(j) / 8) - x) > 8 * tol) return false;
        }
        return true;
      };
      if (runs.front().second && !is_structural(a) && spur(runs.front().first, a)) runs.front().second = false;
      if (runs.back().second && !is_structural(b) && spur(runs.back().first, b)) runs.back().second = false;
    }
    for (const auto& [iv, ok] : runs) {
      bool deep = false;  // some sample of a run cut away nearer than |d| - 2 tol
      for (const auto& q : samples) {
        if (!ok && !q.second && q.first >= iv.lo && q.first <= iv.hi && near.within(judged(q.first), r - 2 * tol)) {
          deep = true;
          break;
        }
      }
      all.push_back({iv, ok, deep});
    }
  }
  // A stretch of consecutive runs to cut away is cut only where it goes deeper than 2 tol
  // somewhere: shallower, it is the raw offset's own error (a measured error of the fit a
  // little over the tolerance, the line at a corner that turns by very little), kept whole
  // (judged as one, so that the parts on either side still meet).
  for (std::size_t k = 0; k < all.size();) {
    if (all[k].ok) {
      ++k;
      continue;
    }
    std::size_t e = k;
    bool deep = all[k].deep;
    while (e + 1 < all.size() && !all[e + 1].ok && all[e + 1].iv.lo == all[e].iv.hi) {
      ++e;
      deep = deep || all[e].deep;
    }
    if (!deep) {
      for (std::size_t j = k; j <= e; ++j) all[j].ok = true;
    }
    k = e + 1;
  }
  for (const auto& x : all) keep(x.iv.lo, x.iv.hi, x.ok, last_ok);
  return kept;
}

}  // namespace detail::offset

/// An estimate of the number of cubics offset() makes, before any work: per piece at least
/// one, plus its turning measured on 32 (n + 1) samples, each angle dtheta counted as
/// dtheta / phi_max, phi_max = (tolerance / (c r))^(1/6) the largest arc of the offset's
/// radius r = |1 - d kappa| / |kappa| that one cubic approximates within the tolerance
/// (a cubic's error on a circular arc of angle phi is about c r phi^6, c = 1.8e-5: the
/// classic quarter circle with handles 0.5523 r is 2.7e-4 r off); plus two per piece for
/// its cusps and joins. Cost: O(pieces n^2).
template <class T>
double offset_segments_estimate(const Pieces<T, 2>& curve, T distance, T tolerance) {
  double total = 0;
  for (const auto& seg : curve.segments()) {
    std::visit(
        [&](const auto& c) {
          const int m = 32 * (c.degree() + 1);
          double sum = 0;
          for (int j = 0; j < m; ++j) {
            const T t = (T(j) + T(0.5)) / T(m);
            const Vector<T, 2> d1 = c.derivative_at(t, 1), d2 = c.derivative_at(t, 2);
            const double sp = static_cast<double>(norm(d1));
            if (!(sp > 0)) continue;
            const double k = static_cast<double>(cross(d1, d2)) / (sp * sp * sp);
            const double dtheta = std::abs(k) * sp / m;
            if (!(dtheta > 1e-15) || !std::isfinite(dtheta)) continue;
            const double r = std::abs(1 - static_cast<double>(distance) * k) / std::abs(k);
            sum += dtheta * std::pow(1.8e-5 * r / static_cast<double>(tolerance), 1.0 / 6);
          }
          total += 2 + std::ceil(std::isfinite(sum) ? sum : 0);
        },
        seg);
  }
  return total;
}

/// The offset of a plane curve at signed distance d (positive to the left of the
/// direction of travel), C(t) + d N(t) with N the unit normal turned +90 degrees from the
/// tangent, as cubic Bézier segments within `tolerance` of it.
///
/// Method. The curve is taken in its unit frame (origin at its first control point, a
/// power-of-two scale: huge and tiny coordinates behave as unit ones). Each exact piece
/// (Bézier or rational Bézier) is cut at its cusps (interior zeros of the speed, found as
/// minima below 1e-6 of the piece's largest speed on a grid of max(64, 16 (n + 1)) points)
/// and at the offset's cusps, where 1 - d kappa(t) changes sign (kappa the signed curvature, > 0 where the curve turns left;
/// bisection to full precision) or touches zero (|d| equals a radius of curvature: minima
/// of |1 - d kappa| below 1e-9) [Farouki90]. On each stretch the offset is smooth and runs with the
/// curve (1 - d kappa > 0) or against it; its tangent is +-T(t), the curve's (its limit
/// where the speed vanishes). Each stretch is approximated greedily: the longest cubic
/// from the current parameter that is within the tolerance, the cubic interpolating the
/// offset's end points and tangent directions, with the handle lengths of a least-squares
/// fit to 15 samples or of the Hermite cubic, whichever is closer. Each candidate is
/// measured along the offset's normal lines (Tiller-Hanson's measure; see
/// detail::offset::NormalScan): where those lines meet the cubic in order from end to end,
/// the largest distance along them bounds the distance both ways, so one scan of 20 or more
/// feet, the tops of its bumps refined (successive parabolas), measures the cubic (the
/// projections both ways, detail::offset::hausdorff, where the lines do not meet it in
/// order). The end is chosen from the scans' estimates with a model of the error's growth
/// and a bracket (detail::offset::approximate); the cubic kept is the one whose measure is
/// within the tolerance. The measure is sampled: an estimate of the Hausdorff distance
/// from above between samples that resolve the error's bumps, not a proven bound.
///
/// Joins. At each G0 corner of the input (a joint of pieces, or a cusp inside one, where
/// the tangents differ by more than 1e-9 rad; at the closing point of a closed curve too)
/// the outer side gets `join`: a round arc of radius |d| (approximated as above), a miter
/// (the offset lines extended to their meeting point, while 1 / cos(theta / 2) <=
/// miter_limit for a turn theta; a bevel beyond, as SVG's stroke-miterlimit) or a bevel
/// line; a reversal (a turn of pi) is always closed by a round arc or a bevel. The inner
/// side gets a straight line from one offset end to the other, traversed backwards.
///
/// Trim. Kept: the points of the raw offset at least |d| - tolerance from the curve (the
/// offset as stroking and tool paths need it: swallowtails, the lines at inner corners,
/// the offsets of parts of the curve nearer than 2 |d| to each other, a circle offset past
/// its centre all go). The raw offset is cut at the crossings of its cubics
/// (detail::offset::raw_crossings), its cusps and join ends, and for an open curve where
/// it crosses the circles of radius |d| about the curve's ends; each part between cuts is
/// judged by the distance of samples to the curve, a change between samples found by
/// bisection (detail::offset::trimmed_intervals). What is kept stays in order; parts that
/// do not meet follow each other with a gap (a closed curve's part through the closing
/// point is one part).
///
/// Untrimmed (trim = false), parts that the tolerance covers are left out: a stretch
/// between two cusps of the offset whose points are all within tolerance / 4 of its start
/// (sampled at 33 points), the next cubic fitted within the tolerance less the stretch's
/// chord (its start moves by that to the last end), and for an open curve of one piece a
/// first or last stretch cut off by a cusp, within 0.9 tolerance of the cusp.
///
/// Result: the cubics in order, each starting where the previous ends except between the
/// parts the trim leaves (a gap: a new part). d = 0 gives the
/// curve itself as cubics (exact for polynomial pieces of degree <= 3). Pieces that are
/// single points are skipped. Errors: InvalidArgument "distance", "tolerance" (not > 0 and
/// finite; below 1e-11 of the curve's size plus |d|; more than max_segments cubics),
/// "curve" (a single point), "distance" when the trim leaves nothing.
template <class T>
OffsetCurve<T> offset(const Pieces<T, 2>& curve, const OffsetOptions<T>& o) {
  using namespace detail::offset;
  if (!std::isfinite(o.distance)) throw InvalidArgument("distance", "must be a finite number");
  if (!(o.tolerance > 0) || !std::isfinite(o.tolerance)) throw InvalidArgument("tolerance", "must be a finite number > 0");
  if (!(o.miter_limit >= 1) || !std::isfinite(o.miter_limit)) throw InvalidArgument("miter_limit", "must be a finite number >= 1");
  // The unit frame of every control point.
  std::vector<Point<T, 2>> all;
  for (const auto& s : curve.segments()) std::visit([&](const auto& c) { all.insert(all.end(), c.points().begin(), c.points().end()); }, s);
  const Point<T, 2> origin = all.front();
  const T half = detail::half_extent<T, 2>(all, origin);
  if (!(half > 0)) throw InvalidArgument("curve", "is a single point: its offset is undefined");
  const int e = detail::unit_exponent(half);
  const T scale = detail::pow2<T>(-e);
  const T d = o.distance * scale, tol = o.tolerance * scale;
  if (tol < T(1e-11) * (1 + std::abs(d))) {
    throw InvalidArgument("tolerance", "is below 1e-11 of the curve's size plus |distance|: cubics in floating point cannot be "
                                       "measured that close");
  }
  const auto to_frame = [&](const auto& c) {
    using C = std::decay_t<decltype(c)>;
    std::vector<Point<T, 2>> P;
    for (const auto& p : c.points()) P.push_back(detail::to_unit(p, origin, e));
    if constexpr (std::is_same_v<C, Bezier<T, 2>>) {
      return BezierPiece<T, 2>(Bezier<T, 2>(std::move(P)));
    } else {
      return BezierPiece<T, 2>(RationalBezier<T, 2>(std::move(P), c.weights()));
    }
  };
  const T tiny = 64 * std::numeric_limits<T>::epsilon();  // a derivative this small (in the unit frame) counts as zero
  Raw<T> raw;
  raw.tolerance = tol;
  raw.max_segments = o.max_segments;
  std::optional<Vector<T, 2>> prev;  // the curve's tangent at the end of the last stretch
  std::optional<Vector<T, 2>> first;
  Point<T, 2> first_at{}, last_at{};
  bool any = false;
  bool single_open = false;  // one piece whose ends differ (no closing join)
  if (curve.segments().size() == 1) {
    std::visit([&](const auto& c) { single_open = norm(c.points().back() - c.points().front()) * scale > T(1e-10); },
               curve.segments().front());
  }
  Nearness<T> near;  // the curve, for the trim's distance tests
  near.leaf = tol / 64;
  std::optional<Point<T, 2>> piece_end;  // the end of the last piece, a single point too
  for (const auto& seg : curve.segments()) {
    const BezierPiece<T, 2> piece = std::visit(to_frame, seg);
    if (o.trim && d != 0) near.add(piece);
    std::visit(
        [&](const auto& c) {
          const auto& P = c.points();
          // Pieces that do not meet (a B-spline of degree 0 with jumps: single points too).
          if (piece_end && norm(P.front() - *piece_end) > tol) {
            throw InvalidArgument("curve", "has a gap of " + std::to_string(norm(P.front() - *piece_end) / scale) +
                                               " between two pieces, more than the tolerance: its offset would not be connected");
          }
          piece_end = P.back();
          if (std::all_of(P.begin(), P.end(), [&](const auto& p) { return norm(p - P.front()) <= tiny; })) return;  // a point
          bool piece_start = true;
          const std::vector<Stretch<T>> ss = stretches<T>(c, d, tiny);
          // The start of a stretch: the first tangent, the gap between pieces, the join.
          const auto begin = [&](const Stretch<T>& s) {
            if (!any) first = s.t_lo, first_at = c(s.lo), any = true;
            if (piece_start && prev && norm(c(s.lo) - last_at) > tol) {
              throw InvalidArgument("curve", "has a gap of " + std::to_string(norm(c(s.lo) - last_at) / scale) +
                                                 " between two pieces, more than the tolerance: its offset would not be connected");
            }
            piece_start = false;
            if (prev && d != 0) join(Corner<T>{c(s.lo), *prev, s.t_lo}, o, d, raw);
          };
          // One stretch on its own (`begun`: its start already made).
          const auto one = [&](std::size_t k, bool begun) {
            const Stretch<T>& s = ss[k];
            // Untrimmed, a stretch between two cusps of the offset (a swallowtail's middle)
            // whose every point is within a quarter of the tolerance of its start (sampled
            // at 33 points; so short that its curvature cannot hide more) is left out: the
            // last cubic's end is that close to all of it, and the next cubic, whose start
            // moves there by the stretch's chord, is fitted within the tolerance less that.
            if (!o.trim && d != 0 && o.fit == OffsetFit::greedy && k > 0 && k + 1 < ss.size() && !raw.cubics.empty() && raw.start_shift == 0 &&
                std::abs(turn(ss[k - 1].t_hi, s.t_lo)) <= T(1e-9) && std::abs(turn(s.t_hi, ss[k + 1].t_lo)) <= T(1e-9)) {
              const Source<T> src = stretch_source<T>(c, s, d);
              const Point<T, 2> start = src.point(s.lo);
              T extent = 0;
              for (int j = 1; j <= 32; ++j) extent = std::max(extent, length(src.point(s.lo + (s.hi - s.lo) * T(j) / 32) - start));
              if (extent <= T(0.25) * tol) {
                raw.max_error = std::max(raw.max_error, extent);
                raw.start_shift = length(src.point(s.hi) - start);
                prev = s.t_hi;
                last_at = c(s.hi);
                return;
              }
            }
            // Untrimmed, an open curve of one piece: a first or last stretch cut off by a
            // cusp of the offset whose every point is within 90% of the tolerance of the
            // end it shares with its neighbour is left out (nothing moves: the path starts
            // or ends at that cusp).
            if (!o.trim && d != 0 && o.fit == OffsetFit::greedy && single_open && ss.size() > 1 && (k == 0 || (k + 1 == ss.size() && !raw.cubics.empty())) &&
                std::abs(turn(k == 0 ? s.t_hi : ss[k - 1].t_hi, k == 0 ? ss[1].t_lo : s.t_lo)) <= T(1e-9)) {
              const Source<T> src = stretch_source<T>(c, s, d);
              const Point<T, 2> shared = src.point(k == 0 ? s.hi : s.lo);
              T extent = 0;
              for (int j = 0; j <= 32; ++j) extent = std::max(extent, length(src.point(s.lo + (s.hi - s.lo) * T(j) / 32) - shared));
              if (extent <= T(0.9) * tol) {
                if (!any) first = s.t_lo, first_at = c(s.lo), any = true;
                raw.max_error = std::max(raw.max_error, extent);
                prev = s.t_hi;
                last_at = c(s.hi);
                return;
              }
            }
            if (!begun) begin(s);
            approximate(stretch_source<T>(c, s, d), o.fit, raw);
            prev = s.t_hi;
            last_at = c(s.hi);
          };
          for (std::size_t k = 0; k < ss.size(); ++k) {
            // Untrimmed, a run of stretches k..k1 between cusps of the offset (the curve's
            // tangent continuous between them).
            std::size_t k1 = k;
            if (!o.trim && d != 0 && o.fit == OffsetFit::greedy) {
              while (k1 + 1 < ss.size() && std::abs(turn(ss[k1].t_hi, ss[k1 + 1].t_lo)) <= T(1e-9)) ++k1;
            }
            if (k1 == k) {
              one(k, false);
              continue;
            }
            begin(ss[k]);
            // First one cubic across them all (offset_source; lib2geom's route follows the
            // offset through its cusps the same way, docs/performance.md W11, session 16),
            // else the stretches' cubics one by one.
            if (raw.start_shift == 0) {
              const Source<T> src = offset_source<T>(c, &ss[k], &ss[k1], d);
              std::array<Screened<T>, 2> work;
              Screened<T>& g = best_screened(src, src.lo, src.hi, tol, true, work);
              const T e = g.error <= tol ? certify(g, src, src.lo, src.hi, tol) : g.error;
              if (e <= tol) {
                raw.max_error = std::max(raw.max_error, e);
                raw.push(g.cubic.P, ss[k].reversed);
                prev = ss[k1].t_hi;
                last_at = c(ss[k1].hi);
                k = k1;
                continue;
              }
            }
            for (std::size_t j = k; j <= k1; ++j) one(j, j == k);
            k = k1;
          }
        },
        piece);
  }
  if (!any) throw InvalidArgument("curve", "is a single point: its offset is undefined");
  const bool closed = norm(last_at - first_at) <= T(1e-10);
  if (closed && d != 0) join(Corner<T>{first_at, *prev, *first}, o, d, raw);
  if (closed && !raw.cubics.empty()) {  // the last end exactly on the first start
    const Point<T, 2> start = raw.cubics.front()[0];
    if (norm(raw.cubics.back()[3] - start) <= tol) raw.cubics.back()[3] = start;
  }
  if (raw.cubics.empty()) {
    throw InvalidArgument("distance", "the offset is a single point (|distance| equals the radius of curvature all along)");
  }
  OffsetCurve<T> out;
  out.raw_segments = raw.cubics.size();
  out.max_error = raw.max_error / scale;
  std::vector<Quad<T>> kept;
  if (o.trim && d != 0) {
    std::vector<BezierPiece<T, 2>> segs;
    segs.reserve(raw.cubics.size());
    for (const auto& Q : raw.cubics) segs.emplace_back(Bezier<T, 2>({Q[0], Q[1], Q[2], Q[3]}));
    const Pieces<T, 2> path(std::move(segs));
    std::optional<std::array<Point<T, 2>, 2>> open_ends;
    if (!closed) open_ends = std::array<Point<T, 2>, 2>{first_at, last_at};
    if (near.pieces.size() > 8) near.build_grid(std::abs(d));
    const auto keep = trimmed_intervals(path, raw, near, d, tol, open_ends, out.loops_cut);
    // The kept parts in order, each a run of cubics; consecutive intervals whose ends meet
    // (the two parameters of one crossing) within the tolerance continue one part.
    std::vector<std::vector<Quad<T>>> parts;
    for (const auto& iv : keep) {
      std::vector<Quad<T>> cubics;
      const Pieces<T, 2> portion = path.portion(iv);
      for (const auto& seg : portion.segments()) {
        const auto& P = std::get<Bezier<T, 2>>(seg).points();  // a portion of a cubic: a cubic
        if (std::all_of(P.begin(), P.end(), [&](const auto& p) { return norm(p - P.front()) <= tiny; })) continue;
        cubics.push_back(Quad<T>{P[0], P[1], P[2], P[3]});
      }
      if (cubics.empty()) continue;
      if (!parts.empty() && norm(cubics.front()[0] - parts.back().back()[3]) <= tol) {
        cubics.front()[0] = parts.back().back()[3];
        parts.back().insert(parts.back().end(), cubics.begin(), cubics.end());
      } else {
        parts.push_back(std::move(cubics));
      }
    }
    if (parts.empty()) throw InvalidArgument("distance", "the trimmed offset is empty: every point of the offset is nearer than |distance| to the curve");
    // A closed curve: the last part continues into the first across the closing point (or
    // a crossing) when its end meets the first's start; it is then put before it.
    if (closed && parts.size() > 1 && norm(parts.back().back()[3] - parts.front().front()[0]) <= tol) {
      parts.front().front()[0] = parts.back().back()[3];
      parts.back().insert(parts.back().end(), parts.front().begin(), parts.front().end());
      parts.erase(parts.begin());
    }
    for (auto& part : parts) kept.insert(kept.end(), part.begin(), part.end());
  } else {
    kept = std::move(raw.cubics);
  }
  // Back from the unit frame.
  const T back = detail::pow2<T>(e);
  out.segments.reserve(kept.size());
  for (const auto& Q : kept) {
    std::vector<Point<T, 2>> P(4);
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 2; ++k) P[static_cast<std::size_t>(j)][k] = Q[static_cast<std::size_t>(j)][k] * back + origin[k];
    out.segments.push_back(Bezier<T, 2>(std::move(P)));
  }
  return out;
}

/// The offset of any plane curve through its exact pieces.
template <class C>
  requires PiecewiseBezierCurve<C> && (C::dimension == 2) && (!detail::is_pieces<C>)
OffsetCurve<typename C::Scalar> offset(const C& c, const OffsetOptions<typename C::Scalar>& o) {
  return offset(pieces(c), o);
}

}  // namespace casteljau
