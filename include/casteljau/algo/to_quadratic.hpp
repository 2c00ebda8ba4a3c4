// Quadratic approximation: any curve as a chain of quadratic Bézier segments within a
// tolerance (Hausdorff), tangent-continuous wherever the curve is, with near the fewest
// segments. Written once on the exact pieces (Pieces<T, D>).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// A chain of quadratic Bézier segments approximating a curve: segment i replaces the
/// curve over [breaks[i], breaks[i + 1]] (the curve's own parameter, so the chain has the
/// curve's domain). max_error is the largest of the segments' error bounds, each an upper
/// bound of the segment's Hausdorff distance to its part, within the tolerance and not
/// tight (see to_quadratic; the one exception, a straight segment over 1e-9 of a span
/// where no quadratic through the tangent lines fits, is measured, whatever its bound).
template <class T, int D>
struct QuadraticChain {
  std::vector<Bezier<T, D>> segments;
  std::vector<T> breaks;
  T max_error = 0;
};

namespace detail::quadratic {


/// Sample intervals per part in the error bound at its finest (to_quadratic): the margin
/// between samples falls as 1 / N^2.
inline constexpr int bound_samples = 32;

/// Input joints whose tangent directions differ by less than this angle (radians) are
/// treated as tangent-continuous: both sides get one shared direction, so the output is
/// exactly G1 there.
template <class T>
inline constexpr T snap_angle = T(1e-6);

/// |v| as the square root of the sum of squares where that neither overflows nor loses
/// precision to underflow, norm() (which scales by the largest coordinate: two divisions
/// more) beyond.
template <class T, int D>
[[gnu::noinline]] T scaled_norm(const Vector<T, D>& v) {
  return norm(v);
}
template <class T, int D>
inline T fast_norm(const Vector<T, D>& v) {
  const T s = squared_norm(v);
  constexpr T lo = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
  constexpr T hi = std::numeric_limits<T>::max() * std::numeric_limits<T>::epsilon();
  if (s >= lo && s <= hi) [[likely]]
    return std::sqrt(s);
  return scaled_norm(v);
}

template <class T, int D>
Vector<T, D> unit(const Vector<T, D>& v) {
  const T n = fast_norm(v);
  return n > 0 ? v / n : Vector<T, D>{};
}

/// The unit tangent direction of a Bézier form (polynomial, or the Cartesian points of
/// a rational one with positive weights) at its start (at_start) or end, as the curve is
/// travelled: the first control point that stands out from the end point (|P_k - P_0| >
/// 1e-7 of the polygon's size; lower-order derivatives that vanish are skipped, which is
/// the limit direction at a cusp or a zero-length handle). Zero for a polygon that is
/// one point.
template <class T, int D>
Vector<T, D> end_direction(const std::vector<Point<T, D>>& C, bool at_start) {
  const std::size_t n = C.size() - 1;
  if (n == 3) {  // a cubic: the same test on squared lengths (one square root)
    const Point<T, D>& e = at_start ? C[0] : C[3];
    T size2 = 0;
    for (const auto& p : C) size2 = std::max(size2, squared_norm(p - e));
    constexpr T lo = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
    constexpr T hi = std::numeric_limits<T>::max() * std::numeric_limits<T>::epsilon();
    if (size2 >= lo && size2 <= hi) [[likely]] {
      const T small2 = T(1e-14) * size2;
      for (std::size_t k = 1; k <= 3; ++k) {
        const Vector<T, D> d = at_start ? C[k] - C[0] : C[3] - C[3 - k];
        const T d2 = squared_norm(d);
        if (d2 > small2) return d / std::sqrt(d2);
      }
      return {};
    }
  }
  const Point<T, D>& e = at_start ? C[0] : C[n];
  T size = 0;
  for (const auto& p : C) size = std::max(size, fast_norm(p - e));
  if (!(size > 0)) return {};
  const T small = T(1e-7) * size;
  for (std::size_t k = 1; k <= n; ++k) {
    const Vector<T, D> d = at_start ? C[k] - C[0] : C[n] - C[n - k];
    if (fast_norm(d) > small) return unit(d);
  }
  return {};
}

/// One quadratic, or two joined (tangent_chain), on the stack.
template <class T, int D>
struct Chain {
  using Quad = std::array<Point<T, D>, 3>;
  std::array<Quad, 2> q;
  int size;
  explicit Chain(const Quad& a) : q{a, a}, size(1) {}
  Chain(const Quad& a, const Quad& b) : q{a, b}, size(2) {}
  const Quad& front() const { return q[0]; }
  const Quad& back() const { return q[static_cast<std::size_t>(size - 1)]; }
};

/// The quadratics from p0 (direction t0) to p2 (direction t1) whose end tangents are t0
/// and t1: one quadratic whose middle point is where the tangent lines meet, ahead of p0
/// and behind p2 (alpha, beta > 0 in p0 + alpha t0 = p2 - beta t1). When the lines are
/// skew (a space curve, beyond 1e-12 of the chord or 64 ulps of it), two quadratics (p0, a, m), (m, b, p2)
/// with a = p0 + (v0 / 4) t0, b = p2 - (v1 / 4) t1 and m their midpoint, v0 and v1 the
/// part's speeds at its ends: each half matches the part's end point and end derivative
/// (as cu2qu's two-piece spline), and the halves are tangent-continuous at m (a, m, b on
/// one line) with equal speeds. Parallel directions: the chord's midpoint when the chord
/// runs along them (a straight part). None otherwise (lines meeting behind; parallel
/// lines apart). The intersection is computed in the orthonormal frame u1 = t0,
/// u2 = (t1 - (t0 . t1) t0) normalised, which stays accurate for nearly parallel lines; in
/// the plane by Cramer's rule on alpha t0 + beta t1 = p2 - p0, the sine of the angle the
/// cross product t0 x t1 (the same |t1 - (t0 . t1) t0| for unit directions, and the same
/// thresholds).
template <class T, int D>
std::optional<Chain<T, D>> tangent_chain(const Point<T, D>& p0, const Vector<T, D>& t0, const Point<T, D>& p2, const Vector<T, D>& t1, T v0,
                                         T v1) {
  using C = Chain<T, D>;
  const Vector<T, D> d = p2 - p0;
  const T chord = fast_norm(d);
  if (!(chord > 0)) return C({p0, p0, p2});  // a part that is one point (or closed: measured)
  if constexpr (D == 2) {
    // The plane: sin of the angle between the directions as their cross product (the same
    // as |t1 - (t0 . t1) t0| for unit directions), alpha and beta by Cramer's rule.
    const T s = t0[0] * t1[1] - t0[1] * t1[0];
    if (!(std::abs(s) > T(1e-8))) {
      const T a = dot(d, t0), b = dot(d, t1);
      if (a > 0 && b > 0 && fast_norm(d - a * t0) <= T(1e-9) * chord && fast_norm(d - b * t1) <= T(1e-9) * chord) return C({p0, p0 + T(0.5) * d, p2});
      if (!(std::abs(s) > T(16) * std::numeric_limits<T>::epsilon())) return std::nullopt;
    }
    const T alpha = (d[0] * t1[1] - d[1] * t1[0]) / s, beta = (t0[0] * d[1] - t0[1] * d[0]) / s;
    if (!(alpha > 0 && beta > 0) || !std::isfinite(alpha) || !std::isfinite(beta)) return std::nullopt;
    return C({p0, p0 + alpha * t0, p2});
  }
  const T c = dot(t0, t1);
  const Vector<T, D> w = t1 - c * t0;
  const T s = fast_norm(w);
  // A straight part: the chord along both directions (to 1e-9 of it; then they differ by
  // at most about 2e-9 radians), whose lines' crossing is lost in rounding (a line of a
  // glyph split into 20 segments): the chord's midpoint.
  if (!(s > T(1e-8))) {
    const T a = dot(d, t0), b = dot(d, t1);
    if (a > 0 && b > 0 && fast_norm(d - a * t0) <= T(1e-9) * chord && fast_norm(d - b * t1) <= T(1e-9) * chord) return C({p0, p0 + T(0.5) * d, p2});
    if (!(s > T(16) * std::numeric_limits<T>::epsilon())) return std::nullopt;
  }
  const Vector<T, D> u2 = w / s;
  const T d1 = dot(d, t0), d2 = dot(d, u2);
  const Vector<T, D> off = d - d1 * t0 - d2 * u2;  // the part of the chord out of the lines' plane
  // Skew: beyond 1e-12 of the chord, or 64 ulps where that is finer than the type (float:
  // the rounding of a plane curve's own frame, which made an exact quadratic two). Plane
  // curves' lines always meet.
  constexpr T skew = std::max(T(1e-12), T(64) * std::numeric_limits<T>::epsilon());
  if (D > 2 && fast_norm(off) > skew * chord) {
    if (!(v0 > 0 && v1 > 0)) return std::nullopt;
    const Point<T, D> a = p0 + (v0 / T(4)) * t0, b = p2 - (v1 / T(4)) * t1;
    const Point<T, D> m = a + T(0.5) * (b - a);
    return C({p0, a, m}, {m, b, p2});
  }
  // alpha t0 + beta t1 = (d1, d2) in the frame: t1 = (c, s).
  const T beta = d2 / s, alpha = d1 - beta * c;
  if (!(alpha > 0 && beta > 0) || !std::isfinite(alpha) || !std::isfinite(beta)) return std::nullopt;
  return C({p0, p0 + alpha * t0, p2});
}

/// The point of the quadratic q at s and its first two derivatives.
template <class T, int D>
struct QuadraticForm {
  Point<T, D> p0;
  Vector<T, D> b, a;  // q(s) = p0 + 2 s b + s^2 a
  explicit QuadraticForm(const std::array<Point<T, D>, 3>& q) : p0(q[0]), b(q[1] - q[0]), a((q[0] - q[1]) + (q[2] - q[1])) {}
  Point<T, D> at(T s) const { return p0 + (T(2) * s) * b + (s * s) * a; }
  Vector<T, D> d1(T s) const { return T(2) * b + (T(2) * s) * a; }
};

/// The foot of p on the quadratic qf from the guess x (its own parameter): Newton's method
/// on (q(x) - p) . q'(x) = 0, clamped to [0, 1], at most `iterations` steps, stopped after
/// a step of at most `stop`. Where the derivative of the equation is not positive (the
/// distance concave there), a step along |q'|^2 alone when `concave_step`, else stopped.
template <class T, int D>
T quadratic_foot(const QuadraticForm<T, D>& qf, const Point<T, D>& p, T x, T stop, int iterations, bool concave_step) {
  for (int it = 0; it < iterations; ++it) {
    // r = q(x) - p, d = q'(x); g = r . d, g' = d . d + r . q''
    T g = 0, dd = 0, ra = 0;
    for (int k = 0; k < D; ++k) {
      const T bk = qf.b[k], ak = qf.a[k];
      const T r = qf.p0[k] + x * (T(2) * bk + x * ak) - p[k], d = T(2) * (bk + x * ak);
      g += r * d;
      dd += d * d;
      ra += r * ak;
    }
    T gp = dd + T(2) * ra;
    if (!(gp > 0) && concave_step) gp = dd;
    if (!(gp > 0)) break;
    const T nx = std::clamp(x - g / gp, T(0), T(1));
    const bool close = std::abs(nx - x) <= stop;
    x = nx;
    if (close) break;
  }
  return x;
}
/// |q(x) - p|^2 for the quadratic qf.
template <class T, int D>
T quadratic_distance2(const QuadraticForm<T, D>& qf, const Point<T, D>& p, T x) {
  T s2 = 0;
  for (int k = 0; k < D; ++k) {
    const T r = qf.p0[k] + x * (T(2) * qf.b[k] + x * qf.a[k]) - p[k];
    s2 += r * r;
  }
  return s2;
}

/// The distance between a part c of the curve on [0, 1] and a chain q of one or two
/// quadratics (joined with equal speeds, as tangent_chain makes them) with the same end
/// points, on the chain's parameter sigma in [0, m] (quadratic i on [i, i + 1]), from
/// samples of c at s_j = j / N (N = bound_samples) taken coarse to fine: 1/2 first, then
/// the quarters, the eighths, ... Each sample's nearest point on each quadratic is found
/// by Newton's method on (q(x) - c(s)) . q'(x) = 0 from the neighbours' feet, clamped to
/// the quadratic, and the nearer kept; the ends are pinned to the ends (sigma_0 = 0,
/// sigma_N = m). The samples taken stay: bound() after estimate() continues from them.
template <class T, int D>
class ChainDistance {
 public:
  static constexpr int N = bound_samples;

  explicit ChainDistance(const Chain<T, D>& q) : q_(q), form_{QuadraticForm<T, D>(q.q[0]), QuadraticForm<T, D>(q.back())} {}

  /// The largest distance from the ends and the samples at spacing 1 / intervals (a power
  /// of two up to N) to the chain: a lower estimate of the distance (each sample's
  /// distance is at most the Hausdorff distance, up to the feet's accuracy), exact to
  /// within the sampling. Stops early, returning a value above `stop`, once one exceeds it.
  template <class Eval>
  T estimate(const Eval& c, int intervals, T stop) {
    if (step_ == 0) {
      sigma_[0] = 0;
      sigma_[N] = T(q_.size);
      f_[0] = fast_norm(c(T(0)) - q_.front()[0]);
      f_[N] = fast_norm(c(T(1)) - q_.back()[2]);
      largest_ = std::max(f_[0], f_[N]);
      step_ = N;
      if (largest_ > stop) return largest_;
    }
    while (N / step_ < intervals) {
      const int half = step_ / 2;
      for (int j = half; j < N; j += step_) {
        const T d = foot(c, j, T(0.5) * (sigma_[static_cast<std::size_t>(j - half)] + sigma_[static_cast<std::size_t>(j + half)]));
        largest_ = std::max(largest_, d);
        if (d > stop) {  // the level is incomplete: sampled again from its start next time
          return d;
        }
      }
      step_ = half;
    }
    return largest_;
  }

  /// An upper bound of the Hausdorff (indeed the Fréchet) distance. The piecewise linear
  /// map sigma(s) through the samples' feet is continuous and onto [0, m], so every point
  /// of either curve is within max_s |c(s) - q(sigma(s))| of the other. Between samples,
  /// f = c - q o sigma (C^1: the chain is C^1 in sigma) differs from its linear
  /// interpolant by at most h^2 / 8 max |c'' - q'' sigma'^2| (h the spacing, sigma' the
  /// slope there, c'' within the convex hull of the caller's `hull` vectors, so the max is
  /// taken over them), which is added to the larger end value. From 4 intervals on, the
  /// bound of each level (the margin falls as 1 / N^2, so a loose tolerance is met with a
  /// few samples); returns the first at most `sure`, or at most `stop` with samples
  /// reaching `enough`, else the finest. Stops early (returning a value above `stop`) once
  /// a sample exceeds it, or from 16 intervals on when the samples exceed 95% of `stop`
  /// and the bound exceeds `stop`. Levels whose samples exceed `sure` (below `enough`) are
  /// not bounded (the bound is at least the samples).
  template <class Eval>
  T bound(const Eval& c, const std::vector<Vector<T, D>>& hull, T stop, T sure, T enough = std::numeric_limits<T>::infinity()) {
    constexpr int coarsest = 4;  // intervals of the first bound: the samples 1/4, 1/2, 3/4
    T b = 0;
    for (int intervals = coarsest; intervals <= N; intervals *= 2) {
      const T e = estimate(c, intervals, stop);
      if (e > stop) return e;
      if (e > sure && e < enough && intervals < N) continue;  // the bound (at least e) is refined anyway
      b = margin_bound(hull);
      if (b <= sure || (e >= enough && b <= stop)) return b;
      // Samples above 95% of `stop` and a bound above it from 16 intervals on: a part at
      // the tolerance, rejected without the finest level (a few segments more, 0.15%).
      if (intervals >= 16 && e > T(0.95) * stop && b > stop) return b;
    }
    return b;
  }

 private:
  // The foot of p on quadratic qf from the guess x, stopped after a step of at most 1e-3
  // (the bound holds for any foot; the distance at the foot is only overestimated, by about
  // the square of that).
  static T foot_on(const QuadraticForm<T, D>& qf, const Point<T, D>& p, T x) { return quadratic_foot(qf, p, x, T(1e-3), 12, true); }
  static T distance_at(const QuadraticForm<T, D>& qf, const Point<T, D>& p, T x) {
    return std::sqrt(quadratic_distance2(qf, p, x));  // points near the curve: no overflow
  }
  template <class Eval>
  T foot(const Eval& c, int j, T guess) {
    const Point<T, D> p = c(T(j) / T(N));
    T best = std::numeric_limits<T>::infinity(), at = 0;
    for (int i = 0; i < q_.size; ++i) {
      const auto& qf = form_[static_cast<std::size_t>(i)];
      const T x = foot_on(qf, p, std::clamp(guess - T(i), T(0), T(1)));
      const T dist = distance_at(qf, p, x);
      if (dist < best) {
        best = dist;
        at = T(i) + x;
      }
    }
    sigma_[static_cast<std::size_t>(j)] = at;
    f_[static_cast<std::size_t>(j)] = best;
    return best;
  }
  // The bound on the intervals of the samples taken (spacing step_).
  T margin_bound(const std::vector<Vector<T, D>>& hull) const {
    const int m = q_.size;
    const T h = T(step_) / T(N);
    T b = 0;
    if (m == 1 && hull.size() == 2) {
      // The common case (a cubic part, one quadratic) as below, with c'' at each sample
      // parameter computed once (the same operations).
      const Vector<T, D> dh = hull[1] - hull[0];
      const Vector<T, D>& a = form_[0].a;
      const T hh = h * h / T(8);
      Vector<T, D> c0 = hull[0] + (T(0) / T(N)) * dh;
      for (int j = 0; j < N; j += step_) {
        const std::size_t j0 = static_cast<std::size_t>(j), j1 = static_cast<std::size_t>(j + step_);
        const T slope = (sigma_[j1] - sigma_[j0]) / h;
        const Vector<T, D> w = (T(2) * slope * slope) * a;
        const Vector<T, D> c1 = hull[0] + (T(j + step_) / T(N)) * dh;
        const T f2 = std::max(std::max(T(0), squared_norm(c0 - w)), squared_norm(c1 - w));
        b = std::max(b, std::max(f_[j0], f_[j1]) + hh * std::sqrt(f2));
        c0 = c1;
      }
      return b;
    }
    for (int j = 0; j < N; j += step_) {
      const std::size_t j0 = static_cast<std::size_t>(j), j1 = static_cast<std::size_t>(j + step_);
      const T slope = (sigma_[j1] - sigma_[j0]) / h;
      // f'' = c'' - q'' slope^2 on the interval (q'' of the quadratic the interval's feet
      // lie on; an interval across the pair's joint takes the larger of the two).
      const std::size_t i0 = std::min<std::size_t>(static_cast<std::size_t>(sigma_[j0]), static_cast<std::size_t>(m - 1));
      const std::size_t i1 = std::min<std::size_t>(static_cast<std::size_t>(sigma_[j1]), static_cast<std::size_t>(m - 1));
      T f2 = 0;  // squared
      for (std::size_t i = std::min(i0, i1); i <= std::max(i0, i1); ++i) {
        const Vector<T, D> w = (T(2) * slope * slope) * form_[i].a;
        if (hull.size() == 2) {
          // Two vectors: a cubic part's c'' at s = 0 and 1, linear between, so on this
          // interval c'' lies between its values at the interval's ends.
          const T s0 = T(j) / T(N), s1 = T(j + step_) / T(N);
          f2 = std::max(f2, squared_norm(hull[0] + s0 * (hull[1] - hull[0]) - w));
          f2 = std::max(f2, squared_norm(hull[0] + s1 * (hull[1] - hull[0]) - w));
        } else {
          for (const auto& v : hull) f2 = std::max(f2, squared_norm(v - w));
        }
      }
      b = std::max(b, std::max(f_[j0], f_[j1]) + h * h / T(8) * std::sqrt(f2));
    }
    return b;
  }

  Chain<T, D> q_;
  std::array<QuadraticForm<T, D>, 2> form_;
  std::array<T, N + 1> sigma_{}, f_{};
  int step_ = 0;  // the spacing (in 1 / N) of the samples taken; 0: none yet
  T largest_ = 0;
};

/// The point at s of the Bézier form with control points P (de Casteljau, on the stack
/// up to degree 15).
template <class T, int D>
Point<T, D> bezier_point(const std::vector<Point<T, D>>& P, T s) {
  const std::size_t n = P.size();
  if (n == 4) {  // the common cubic, unrolled on the coordinates
    Point<T, D> out;
    for (int k = 0; k < D; ++k) {
      const T a = P[0][k] + s * (P[1][k] - P[0][k]), b = P[1][k] + s * (P[2][k] - P[1][k]), c = P[2][k] + s * (P[3][k] - P[2][k]);
      const T d = a + s * (b - a), e = b + s * (c - b);
      out[k] = d + s * (e - d);
    }
    return out;
  }
  if (n == 3) {  // a cubic's hodograph
    Point<T, D> out;
    for (int k = 0; k < D; ++k) {
      const T a = P[0][k] + s * (P[1][k] - P[0][k]), b = P[1][k] + s * (P[2][k] - P[1][k]);
      out[k] = a + s * (b - a);
    }
    return out;
  }
  std::vector<Point<T, D>> large;
  std::array<Point<T, D>, 16> small;
  Point<T, D>* w = small.data();
  if (n > small.size()) {
    large = P;
    w = large.data();
  } else {
    std::copy(P.begin(), P.end(), small.begin());
  }
  for (std::size_t k = 1; k < n; ++k)
    for (std::size_t i = 0; i + k < n; ++i) w[i] = w[i] + s * (w[i + 1] - w[i]);
  return w[0];
}

/// The control points of the polynomial piece P over [a, b] of [0, 1], into out (reused):
/// the left part at b, then the right part of that at a / b (de Casteljau in place).
template <class T, int D>
void polynomial_portion(const std::vector<Point<T, D>>& P, T a, T b, std::vector<Point<T, D>>& out) {
  out = P;
  const std::size_t n = out.size() - 1;
  if (b < T(1)) {
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t i = n; i >= k; --i) out[i] = out[i - 1] + b * (out[i] - out[i - 1]);
  }
  if (a > T(0)) {
    const T t = a / b;
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t i = 0; i + k <= n; ++i) out[i] = out[i] + t * (out[i + 1] - out[i]);
  }
}

/// polynomial_portion for a cubic, unrolled into out[0..3] (the same operations).
template <class T, int D>
void cubic_portion(const Point<T, D>* P, T a, T b, Point<T, D>* out) {
  Point<T, D> p0 = P[0], p1 = P[1], p2 = P[2], p3 = P[3];
  if (b < T(1)) {
    p3 = p2 + b * (p3 - p2);
    p2 = p1 + b * (p2 - p1);
    p1 = p0 + b * (p1 - p0);
    p3 = p2 + b * (p3 - p2);
    p2 = p1 + b * (p2 - p1);
    p3 = p2 + b * (p3 - p2);
  }
  if (a > T(0)) {
    const T t = a / b;
    p0 = p0 + t * (p1 - p0);
    p1 = p1 + t * (p2 - p1);
    p2 = p2 + t * (p3 - p2);
    p0 = p0 + t * (p1 - p0);
    p1 = p1 + t * (p2 - p1);
    p0 = p0 + t * (p1 - p0);
  }
  out[0] = p0;
  out[1] = p1;
  out[2] = p2;
  out[3] = p3;
}

/// A part of a piece (its own parameter [a, b] mapped onto [0, 1]): its control points,
/// evaluation and a bound on its second derivative.
template <class Piece>
struct Part {
  using T = typename Piece::Scalar;
  static constexpr int D = Piece::dimension;
  static constexpr bool polynomial = std::is_same_v<Piece, Bezier<T, D>>;
  std::vector<Point<T, D>> points;  // polynomial parts
  std::optional<Piece> form;        // rational parts

  std::array<Vector<T, D>, 4> power{};  // a cubic part: c(s) = P_0 + s (power[1] + s (power[2] + s power[3]))

  void make(const Piece& piece, T a, T b) {
    if constexpr (polynomial) {
      if (piece.points().size() == 4) {
        points.resize(4);
        cubic_portion(piece.points().data(), a, b, points.data());
      } else {
        polynomial_portion(piece.points(), a, b, points);
      }
      if (points.size() == 4) {
        const auto& P = points;
        power[1] = T(3) * (P[1] - P[0]);
        power[2] = T(3) * ((P[2] - P[1]) - (P[1] - P[0]));
        power[3] = (P[3] - P[0]) - T(3) * (P[2] - P[1]);
      }
    } else {
      form.emplace(piece.portion(a, b));
      points = form->points();
    }
  }
  Point<T, D> operator()(T s) const {
    if constexpr (polynomial) {
      if (points.size() == 4) return points[0] + s * (power[1] + s * (power[2] + s * power[3]));  // Horner
      return bezier_point(points, s);
    } else {
      return (*form)(s);
    }
  }

  /// |c'| at the start or the end (the limit along the first differing control point
  /// where the derivative vanishes: n |P_k - P_0| / k, a stand-in for the speed).
  T end_speed(bool at_start) const {
    const std::size_t n = points.size() - 1;
    for (std::size_t k = 1; k <= n; ++k) {
      const T d = at_start ? fast_norm(points[k] - points[0]) : fast_norm(points[n] - points[n - k]);
      if (d > 0) {
        T v = T(n) * d / T(k);
        if constexpr (!polynomial) v *= at_start ? form->weights()[1] / form->weights()[0] : form->weights()[n - 1] / form->weights()[n];
        return v;
      }
    }
    return 0;
  }

  /// An upper bound of the Fréchet (so the Hausdorff) distance between a polynomial part
  /// and a single quadratic q, from the parametrisations alone: q degree-elevated to the
  /// part's degree n, Q_k = sum_i C(2, i) C(n - 2, k - i) / C(n, k) q_i, and c(s) - Q(s) =
  /// sum_k B_k(s) (c_k - Q_k), at most max_k |c_k - Q_k| (the Bernstein weights sum to 1).
  /// For a cubic part, the polygon of c - Q is halved (de Casteljau at 1/2) up to `levels`
  /// times where its largest coefficient is above `limit` (polygon_bound_n): the bound
  /// tends to the parametric distance itself. Infinite for a rational part, a chain of two
  /// quadratics or degree above 15. Costs a few operations per control point: cu2qu's
  /// test, against our G1 quadratic.
  T elevated_bound(const Chain<T, D>& q, T limit = 0, int levels = 0) const {
    const std::size_t n = points.size() - 1;
    if (!polynomial || q.size != 1 || n < 2 || n > 15) return std::numeric_limits<T>::infinity();
    const auto& a = q.front();
    if (n == 3) {
      // A cubic: the weights below as constants (the same values), the loops unrolled.
      static constexpr std::array<std::array<T, 3>, 4> w = [] {
        std::array<std::array<T, 3>, 4> r{};
        for (std::size_t k = 0; k <= 3; ++k) {
          const T kk = T(k), m = T(3 - k);
          r[k] = {m * (m - 1) / T(6), T(2) * kk * m / T(6), kk * (kk - 1) / T(6)};
        }
        return r;
      }();
      std::array<std::array<T, D>, 4> f;
      for (std::size_t k = 0; k <= 3; ++k)
        for (int c = 0; c < D; ++c) f[k][static_cast<std::size_t>(c)] = points[k][c] - (w[k][0] * a[0][c] + w[k][1] * a[1][c] + w[k][2] * a[2][c]);
      if (levels > 0) {
        // The difference's value at 1/2, (f0 + 3 f1 + 3 f2 + f3) / 8: above the limit, no
        // halving brings the bound under it (the first halving's end value).
        T m2 = 0;
        for (std::size_t c = 0; c < static_cast<std::size_t>(D); ++c) {
          const T v = (f[0][c] + T(3) * (f[1][c] + f[2][c]) + f[3][c]) / T(8);
          m2 += v * v;
        }
        if (m2 > limit * limit) levels = 0;
      }
      return polygon_bound_n(f, limit, levels);
    }
    const T N = T(n * (n - 1));
    T worst = 0;
    for (std::size_t k = 0; k <= n; ++k) {
      // The weights C(2, i) C(n - 2, k - i) / C(n, k): (n-k)(n-k-1), 2k(n-k), k(k-1) over n(n-1).
      const T kk = T(k), r = T(n - k);
      const T w0 = r * (r - 1) / N, w1 = T(2) * kk * r / N, w2 = kk * (kk - 1) / N;
      T d2 = 0;
      for (int c = 0; c < D; ++c) {
        const T d = points[k][c] - (w0 * a[0][c] + w1 * a[1][c] + w2 * a[2][c]);
        d2 += d * d;
      }
      worst = std::max(worst, d2);
    }
    return std::sqrt(worst);  // parts near the curve: no overflow
  }

  /// The distance from c(1/2) to its foot on the single quadratic q of a cubic part (the
  /// foot's parameter into x): Newton's method on (q(x) - c(1/2)) . q'(x) = 0, clamped to
  /// [0, 1], from the parameter that the affine map of q's control triangle gives c(1/2),
  /// stopped after a step of at most 1e-2 (the error left is about the square of that
  /// step, and the distance's is second order in it). The search's measure of a part's
  /// error (to_quadratic), not a bound: on 8,700 parts of random cubics, where the part's
  /// distance to q (dense samples) is within 1e-3 of its chord, that distance is 1.001,
  /// 1.011 and 1.12 times the measure at the median, 90th and 99th percentiles; from 1e-3
  /// to 1e-2 of the chord 1.017, 1.10 and 1.47 times. From the guess, Newton can end at a
  /// farther foot than the nearest (1.5% of those parts; mostly quadratics far longer than
  /// their part, a hairpin through a far crossing of the tangent lines): when the distance
  /// found exceeds `recheck` and that foot lies within `recheck` of the part's control box,
  /// Newton again from the nearest of q's ends and middle, the nearer foot kept, and the
  /// first foot's parameter written to *first (the caller measures that point of q against
  /// the part: distance_from). Infinite for other parts
  /// (rational, degree other than 3, a chain of two) and a quadratic with a handle of
  /// zero length.
  T middle_foot(const Chain<T, D>& q, T& x, T recheck = std::numeric_limits<T>::infinity(), T* first = nullptr) const {
    if (!polynomial || q.size != 1 || points.size() != 4) return std::numeric_limits<T>::infinity();
    const auto& Q = q.front();
    const Vector<T, D> b = Q[1] - Q[0];
    if (!(squared_norm(b) > 0 && squared_norm(Q[2] - Q[1]) > 0)) return std::numeric_limits<T>::infinity();
    const Point<T, D> m = (*this)(T(0.5));
    {
      // The affine map of the quadratic's control triangle that sends Q0, Q1, Q2 to 0, 1/2, 1
      // (exact on q: q(u) has barycentric coordinates (1-u)^2, 2u(1-u), u^2, so u = tau1 / 2
      // + tau2), at m's projection on the triangle's plane: first order in m's distance.
      const Vector<T, D> e2 = Q[2] - Q[0], w = m - Q[0];
      const T g11 = dot(b, b), g12 = dot(b, e2), g22 = dot(e2, e2), w1 = dot(w, b), w2 = dot(w, e2);
      const T det = g11 * g22 - g12 * g12;
      if (det > T(1e-6) * g11 * g22) {
        const T t1 = (w1 * g22 - w2 * g12) / det, t2 = (w2 * g11 - w1 * g12) / det;
        x = std::clamp(T(0.5) * t1 + t2, T(0), T(1));
      } else {
        x = g22 > 0 ? std::clamp(w2 / g22, T(0), T(1)) : T(0.5);  // nearly straight: along the chord
      }
    }
    const QuadraticForm<T, D> qf(Q);
    const auto squared_distance = [&](T u) { return quadratic_distance2(qf, m, u); };
    const auto newton = [&](T& u) {
      u = quadratic_foot(qf, m, u, T(1e-2), 8, false);
      return squared_distance(u);
    };
    T d2 = newton(x);
    // Beyond `recheck`, unless the foot itself is farther than that from the part's control
    // box (so from the part: the Hausdorff distance is beyond it too, and the part is
    // rejected on the measure rightly): Newton again from the nearest of q's ends and
    // middle, the nearer foot kept (from the guess, Newton can end at another branch's
    // foot where the guess's first-order model fails: c(1/2) far from q for its size, a
    // hairpin).
    const auto outside_box = [&](T u) {
      const Box<T, D> box = box_of<T, D>(points);
      T o2 = 0;
      for (int k = 0; k < D; ++k) {
        const T v = qf.p0[k] + u * (T(2) * qf.b[k] + u * qf.a[k]);
        const T o = std::max(T(0), std::max(box.lo[k] - v, v - box.hi[k]));
        o2 += o * o;
      }
      return o2;
    };
    if (d2 > recheck * recheck && !(outside_box(x) > recheck * recheck)) {
      T u = 0, best = squared_distance(T(0));
      for (const T v : {T(0.5), T(1)}) {
        const T dv = squared_distance(v);
        if (dv < best) best = dv, u = v;
      }
      if (best < d2) {
        const T d2u = newton(u);
        if (d2u < d2) {
          if (first) *first = x;
          d2 = d2u, x = u;
        }
      }
    }
    return std::sqrt(d2);  // points near the curve: no overflow
  }

  /// The distance from p to a cubic part: Newton's method on (c(s) - p) . c'(s) = 0 from s,
  /// clamped to [0, 1], stopped after a step of at most 1e-2, and the part's ends and middle
  /// (the nearest kept). A distance to a point of the part: at least the true distance.
  T distance_from(const Point<T, D>& p, T s) const {
    const auto at = [&](T u) { return (*this)(u); };
    for (int it = 0; it < 8; ++it) {
      const Vector<T, D> r = at(s) - p, d1 = power[1] + s * (T(2) * power[2] + T(3) * s * power[3]),
                         d2 = T(2) * power[2] + T(6) * s * power[3];
      T gp = dot(d1, d1) + dot(r, d2);
      if (!(gp > 0)) gp = dot(d1, d1);
      if (!(gp > 0)) break;
      const T ns = std::clamp(s - dot(r, d1) / gp, T(0), T(1));
      const bool close = std::abs(ns - s) <= T(1e-2);
      s = ns;
      if (close) break;
    }
    T best = squared_norm(at(s) - p);
    for (const T v : {T(0), T(0.5), T(1)}) best = std::min(best, squared_norm(at(v) - p));
    return std::sqrt(best);
  }

  /// An upper bound of the Hausdorff distance between a cubic part c and a single
  /// quadratic q with the same end points and end directions, after a change of q's
  /// parameter: sigma(s) the quartic with sigma(0) = 0, sigma(1) = 1 and the end slopes
  /// |c'| / |q'| (Bernstein coefficients 0, sigma'(0) / 4, s2, 1 - sigma'(1) / 4, 1), so
  /// that q(sigma(s)) matches c's points and first derivatives at both ends and f(s) =
  /// c(s) - q(sigma(s)), a polynomial of degree 8, has a double zero at each end; s2 is
  /// chosen so that sigma(1/2) = x, the foot of c(1/2) on q (middle_foot's), which removes
  /// most of the tangential part of f; any x in [0, 1] gives a bound, the foot a tight one (a cubic sigma's bound is 1.4 to 20 times the distance on
  /// parts whose speeds vary). f's Bernstein coefficients (c raised to degree 8, sigma
  /// raised and sigma^2 as a product) bound |f|; the polygon is halved (de Casteljau at
  /// 1/2) up to `levels` times where its largest coefficient is above `limit`. When
  /// sigma's coefficients lie in [0, 1], sigma maps [0, 1] into [0, 1] (c(s) is within
  /// |f(s)| of the point q(sigma(s)) of q) and onto it (every q(u) is some q(sigma(s)),
  /// within |f(s)| of c(s)). Infinite for other parts (rational, degree other than 3, a
  /// chain of two quadratics) and a sigma leaving [0, 1]. No projections: about 300
  /// operations, unrolled.
  T reparametrised_bound4_at(const Chain<T, D>& q, T x, T limit, int levels) const {
    if (!polynomial || q.size != 1 || points.size() != 4) return std::numeric_limits<T>::infinity();
    const auto& Q = q.front();
    const Vector<T, D> b = Q[1] - Q[0], a = (Q[0] - Q[1]) + (Q[2] - Q[1]);
    const T q0 = fast_norm(b), q1 = fast_norm(Q[2] - Q[1]);
    if (!(q0 > 0 && q1 > 0)) return std::numeric_limits<T>::infinity();
    const T c0 = fast_norm(points[1] - points[0]), c1 = fast_norm(points[3] - points[2]);
    const T s1 = T(3) * c0 / (T(8) * q0), s3 = T(1) - T(3) * c1 / (T(8) * q1);
    const T s2 = (T(16) * x - T(4) * s1 - T(4) * s3 - T(1)) / T(6);
    if (!(s1 >= 0 && s1 <= 1 && s2 >= 0 && s2 <= 1 && s3 >= 0 && s3 <= 1)) {
      return std::numeric_limits<T>::infinity();
    }
    const std::array<T, 5> sg{T(0), s1, s2, s3, T(1)};
    // The products' weights C(4, i) C(4, k - i) / C(8, k) (sigma and sigma^2 raised to
    // degree 8; the partner index k - i, 0 where the weight is 0) and C(3, i) C(5, k - i) /
    // C(8, k) (c raised by 5), once at compile time; the loops below have constant bounds.
    struct Weights {
      std::array<std::array<T, 5>, 9> w44{};
      std::array<std::array<std::size_t, 5>, 9> partner{};
      std::array<std::array<T, 4>, 9> w35{};
    };
    static constexpr Weights W = [] {
      constexpr std::array<T, 4> c3{1, 3, 3, 1};
      constexpr std::array<T, 5> c4{1, 4, 6, 4, 1};
      constexpr std::array<T, 6> c5{1, 5, 10, 10, 5, 1};
      constexpr std::array<T, 9> c8{1, 8, 28, 56, 70, 56, 28, 8, 1};
      Weights r;
      for (std::size_t k = 0; k <= 8; ++k) {
        for (std::size_t i = 0; i <= 4 && i <= k; ++i)
          if (k - i <= 4) {
            r.w44[k][i] = c4[i] * c4[k - i] / c8[k];
            r.partner[k][i] = k - i;
          }
        for (std::size_t i = 0; i <= 3 && i <= k; ++i)
          if (k - i <= 5) r.w35[k][i] = c3[i] * c5[k - i] / c8[k];
      }
      return r;
    }();
    std::array<std::array<T, D>, 4> cq;
    for (std::size_t i = 0; i < 4; ++i)
      for (int c = 0; c < D; ++c) cq[i][static_cast<std::size_t>(c)] = points[i][c] - Q[0][c];
    std::array<std::array<T, D>, 9> f;
    // Unrolled at compile time (the weights as constants, the terms of zero weight left
    // out: they add zeros).
    const auto row = [&]<std::size_t k>(std::integral_constant<std::size_t, k>) {
      T sig = 0, sig2 = 0;
      const auto term = [&]<std::size_t i>(std::integral_constant<std::size_t, i>) {
        if constexpr (W.w44[k][i] != T(0)) {
          const T w = W.w44[k][i] * sg[i];
          sig += w;
          sig2 += w * sg[W.partner[k][i]];
        }
      };
      [&]<std::size_t... i>(std::index_sequence<i...>) { (term(std::integral_constant<std::size_t, i>{}), ...); }(std::make_index_sequence<5>{});
      for (int c = 0; c < D; ++c) {
        const std::size_t cc = static_cast<std::size_t>(c);
        T v = 0;
        [&]<std::size_t... i>(std::index_sequence<i...>) {
          ((W.w35[k][i] != T(0) ? void(v += W.w35[k][i] * cq[i][cc]) : void()), ...);
        }(std::make_index_sequence<4>{});
        f[k][cc] = v - (T(2) * sig) * b[c] - sig2 * a[c];
      }
    };
    [&]<std::size_t... k>(std::index_sequence<k...>) { (row(std::integral_constant<std::size_t, k>{}), ...); }(std::make_index_sequence<9>{});
    return polygon_bound_n(f, limit, levels);
  }

  /// The largest coefficient of the Bernstein polygon f (vectors as arrays), halved up to
  /// `levels` times where it exceeds `limit` (not where an end value, a value of f, does:
  /// no halving can bring the bound under `limit` then): an upper bound of max |f| on
  /// [0, 1].
  template <std::size_t M>
  static T polygon_bound_n(const std::array<std::array<T, D>, M>& f, T limit, int levels) {
    return std::sqrt(polygon_bound2(f, limit * limit, levels));  // the largest root is the root of the largest square
  }
  /// polygon_bound_n squared (limit2 = limit^2). The halving leaves the right half in w
  /// (de Casteljau's right edge is never overwritten), the left half gathered level by level.
  template <std::size_t M>
  static T polygon_bound2(const std::array<std::array<T, D>, M>& f, T limit2, int levels) {
    std::array<T, M> q;
    T worst = 0;
    for (std::size_t k = 0; k < M; ++k) {
      T s = 0;
      for (const T x : f[k]) s += x * x;
      q[k] = s;
      worst = std::max(worst, s);
    }
    if (worst <= limit2 || levels == 0 || q[0] > limit2 || q[M - 1] > limit2) return worst;
    std::array<std::array<T, D>, M> l, w = f;
    for (std::size_t lvl = 0; lvl < M; ++lvl) {
      l[lvl] = w[0];
      for (std::size_t i = 0; i + lvl + 1 < M; ++i)
        for (std::size_t c = 0; c < static_cast<std::size_t>(D); ++c) w[i][c] = T(0.5) * (w[i][c] + w[i + 1][c]);
    }
    const T left = polygon_bound2(l, limit2, levels - 1);
    return std::max(left, polygon_bound2(w, limit2, levels - 1));
  }

  /// Vectors whose convex hull holds c'' on [0, 1], into out (the margin of
  /// ChainDistance::bound takes max |v - w| over them for |c'' - w|): n (n - 1) times the
  /// second differences for a polynomial (the second hodograph's control points: a bound;
  /// for a cubic, c''(0) and c''(1), between which c'' is linear); for a rational piece
  /// c'' at the N + 1 sample parameters (an estimate, not a bound).
  void second_derivative_hull(std::vector<Vector<T, D>>& out) const {
    out.clear();
    const auto& C = points;
    const int n = static_cast<int>(C.size()) - 1;
    if (n < 2) {
      out.push_back(Vector<T, D>{});
      return;
    }
    if constexpr (polynomial) {
      for (std::size_t k = 0; k + 2 < C.size(); ++k) out.push_back(T(n) * T(n - 1) * ((C[k] - C[k + 1]) + (C[k + 2] - C[k + 1])));
    } else {
      for (int j = 0; j <= bound_samples; ++j) out.push_back(form->derivative_at(T(j) / T(bound_samples), 2));
    }
  }
};

/// The directions of a piece at its own parameter t, from the left and from the right
/// (the limit directions where the derivative vanishes).
template <class Piece, class T>
std::pair<Vector<T, Piece::dimension>, Vector<T, Piece::dimension>> directions_at(const Piece& piece, T t) {
  const Interval<T> own = piece.domain();
  Vector<T, Piece::dimension> left{}, right{};
  if (t > own.lo) left = end_direction(piece.portion(own.lo, t).points(), false);
  if (t < own.hi) right = end_direction(piece.portion(t, own.hi).points(), true);
  return {left, right};
}

/// The cusps of a cubic polynomial piece with hodograph control points H (c' = H0 B0 +
/// H1 B1 + H2 B2), in closed form: the local minima of |c'|^2 in (0, 1) are roots of the
/// cubic g = c' . c'' (where g turns from negative to positive), found by bisection on the
/// intervals where g is monotone (between the roots of g'), stopped as soon as the speed
/// in the bracket is sure to stay above 1e-9 of the largest |H_k| (at least the largest
/// speed); a minimum below that where the direction turns back is a cusp. No allocation
/// unless a cusp is found.
template <class Piece, class T, int D>
std::vector<T> cubic_cusps(const Piece& piece, const std::array<Point<T, D>, 3>& H) {
  std::vector<T> out;
  const Vector<T, D> C = H[0].to_vector(), B = T(2) * (H[1] - H[0]), A = (H[0] - H[1]) + (H[2] - H[1]);  // c'(t) = A t^2 + B t + C
  // g(t) = c'(t) . c''(t) = g3 t^3 + g2 t^2 + g1 t + g0.
  const T g3 = T(2) * dot(A, A), g2 = T(3) * dot(A, B), g1 = dot(B, B) + T(2) * dot(A, C), g0 = dot(B, C);
  const auto g = [&](T t) { return ((g3 * t + g2) * t + g1) * t + g0; };
  const auto speed2 = [&](T t) { return squared_norm((A * t + B) * t + C); };
  // The ends of the monotone intervals of g: 0, the roots of g' = 3 g3 t^2 + 2 g2 t + g1 in (0, 1), 1.
  std::array<T, 4> cut{T(0), T(1), T(1), T(1)};
  int m = 1;
  {
    const T a = T(3) * g3, b = T(2) * g2, c = g1;
    std::array<T, 2> r{};
    int nr = 0;
    if (a != 0) {
      const T disc = b * b - T(4) * a * c;
      if (disc >= 0) {
        const T sq = std::sqrt(disc);
        const T qq = -T(0.5) * (b + (b >= 0 ? sq : -sq));  // the stable quadratic formula
        r[0] = qq / a;
        r[1] = qq != 0 ? c / qq : r[0];
        nr = 2;
      }
    } else if (b != 0) {
      r[0] = -c / b;
      nr = 1;
    }
    if (nr == 2 && r[1] < r[0]) std::swap(r[0], r[1]);
    for (int i = 0; i < nr; ++i)
      if (r[static_cast<std::size_t>(i)] > cut[static_cast<std::size_t>(m - 1)] && r[static_cast<std::size_t>(i)] < T(1)) cut[static_cast<std::size_t>(m++)] = r[static_cast<std::size_t>(i)];
    cut[static_cast<std::size_t>(m)] = T(1);
  }
  T big2 = 0;  // the largest |H_k|^2: at least the largest |c'|^2
  for (const auto& h : H) big2 = std::max(big2, squared_norm(h.to_vector()));
  std::array<T, 3> minima{};
  int nmin = 0;
  const T level = T(1e-9) * std::sqrt(big2);  // a cusp's speed at most: 1e-9 of the largest
  const T W = T(2) * fast_norm(A) + fast_norm(B);  // |c''| <= W on [0, 1]
  for (int i = 0; i < m; ++i) {
    T lo = cut[static_cast<std::size_t>(i)], hi = cut[static_cast<std::size_t>(i + 1)];
    T glo = g(lo);
    const T ghi = g(hi);
    if (!(glo < 0 && ghi > 0)) continue;  // no minimum of |c'|^2 inside
    // Bisection, stopped once the speed in the bracket stays above the level (|c'| >=
    // |c'(lo)| - W (hi - lo) there).
    bool low = true;
    for (int it = 0; it < 200; ++it) {
      if (std::sqrt(speed2(lo)) - W * (hi - lo) > level) {
        low = false;
        break;
      }
      const T mid = lo + T(0.5) * (hi - lo);
      if (!(mid > lo && mid < hi)) break;
      const T gm = g(mid);
      if ((gm < 0) == (glo < 0)) {
        lo = mid;
        glo = gm;
      } else {
        hi = mid;
      }
    }
    if (low) minima[static_cast<std::size_t>(nmin++)] = speed2(lo) <= speed2(hi) ? lo : hi;
  }
  const T top2 = big2;
  if (!(top2 > 0)) return out;
  for (int i = 0; i < nmin; ++i) {
    const T tc = minima[static_cast<std::size_t>(i)];
    if (speed2(tc) > T(1e-18) * top2 || tc <= T(0) || tc >= T(1)) continue;
    const auto [left, right] = directions_at(piece, tc);
    if (dot(left, right) < 0 && (out.empty() || tc > out.back())) out.push_back(tc);
  }
  return out;
}

/// True when a plane cubic with hodograph control points H (c' = A t^2 + B t + C) has
/// speed above 1e-6 of the largest |H_k| (1024 ulps for float) on all of [0, 1], so no cusp
/// (a cusp's speed is at most 1e-9 of it; the gap covers the rounding of the few
/// operations below): where
/// |c'(t)| <= eps, the cross product A x c'(t) = (A x B) t + (A x C), linear in t, is at
/// most |A| eps in size; when it stays beyond that on [0, 1], or |c'| stays above eps on
/// the short interval where it does not (|c'| changes by at most (2 |A| + |B|) per unit
/// of t), there is no such t. About 40 operations: most cubics leave cusps() here. False
/// (not decided) otherwise, and when A is 0 (a raised quadratic).
template <class T>
bool plane_cubic_without_cusp(const std::array<Point<T, 2>, 3>& H) {
  const Vector<T, 2> C = H[0].to_vector(), B = T(2) * (H[1] - H[0]), A = (H[0] - H[1]) + (H[2] - H[1]);
  T big2 = 0;
  for (const auto& h : H) big2 = std::max(big2, squared_norm(h.to_vector()));
  // The margin: 1e-6, or 1024 ulps where that is coarser (float), far above a cusp's 1e-9.
  constexpr T margin = std::max(T(1e-6), T(1024) * std::numeric_limits<T>::epsilon());
  const T eps = margin * std::sqrt(big2), nA = std::sqrt(squared_norm(A));
  const T e = eps * nA;
  const T a = A[0] * B[1] - A[1] * B[0], b = A[0] * C[1] - A[1] * C[0];  // cross(A, c'(t)) = a t + b
  if (!(e > 0) || !std::isfinite(e)) return false;
  if ((b > e && a + b > e) || (b < -e && a + b < -e)) return true;
  if (a == 0) return false;
  // |a t + b| <= e on [t* - delta, t* + delta], t* = -b / a; its part in [0, 1].
  const T ts = -b / a, delta = e / std::abs(a);
  const T lo = std::max(T(0), ts - delta), hi = std::min(T(1), ts + delta);
  if (!(lo <= hi)) return true;
  const T tm = T(0.5) * (lo + hi), r = T(0.5) * (hi - lo);
  const T W = T(2) * nA + std::sqrt(squared_norm(B));  // |c''| on [0, 1] at most
  const T speed = std::sqrt(squared_norm((A * tm + B) * tm + C));
  return speed - W * r > eps;
}

/// The cusps of a piece inside its own domain: parameters where the derivative vanishes
/// (|c'| <= 1e-9 of its largest value on the piece, found by sampling 16 (n + 1) points
/// and refining each low local minimum of |c'| by golden section) and the direction turns
/// back (the one-sided directions opposed). Sorted.
template <class Piece>
std::vector<typename Piece::Scalar> cusps(const Piece& piece) {
  using T = typename Piece::Scalar;
  std::vector<T> out;
  const int n = piece.degree();
  if (n < 2) return out;
  const int M = 16 * (n + 1);
  // The speed |c'|: for a polynomial piece from its hodograph's control points, computed
  // once (de Casteljau on the stack, no allocation); a rational piece through derivative_at.
  constexpr int D = Piece::dimension;
  std::vector<Point<T, D>> hodograph;
  if constexpr (std::is_same_v<Piece, Bezier<T, D>>) {
    const auto& P = piece.points();
    std::array<Point<T, D>, 3> cubic_hodograph;
    if (n == 3) {
      cubic_hodograph = {Point<T, D>::from_vector(T(3) * (P[1] - P[0])), Point<T, D>::from_vector(T(3) * (P[2] - P[1])),
                         Point<T, D>::from_vector(T(3) * (P[3] - P[2]))};
    } else {
      hodograph.reserve(P.size() - 1);
      for (std::size_t k = 0; k + 1 < P.size(); ++k) hodograph.push_back(Point<T, D>::from_vector(T(n) * (P[k + 1] - P[k])));
    }
    if constexpr (D == 2) {
      if (n == 3 && plane_cubic_without_cusp(cubic_hodograph)) return out;
    }
    const Point<T, D>* H = n == 3 ? cubic_hodograph.data() : hodograph.data();
    const std::size_t nh = static_cast<std::size_t>(n);
    // No cusp when the hodograph's control polygon keeps away from the origin: its convex
    // hull (which holds c' on [0, 1]) lies beyond a line at distance `low` from the origin,
    // for the normal u of the line the mean of the control points or the nearest point of
    // the chord H_0 H_n-1 to the origin; then |c'| >= low everywhere and the largest speed
    // is at most the largest |H_k|, so when low > 0.06 max |H_k| no sampled minimum below
    // would reach 0.05 of the largest sample (the margin covers rounding).
    T big = 0;
    for (std::size_t i = 0; i < nh; ++i) big = std::max(big, fast_norm(H[i].to_vector()));
    // The test on a control polygon H[0..k): true when it keeps away from the origin.
    const auto clear = [&](const Point<T, D>* H, std::size_t k) {
      const Vector<T, D> chord = H[k - 1] - H[0];
      const T cc = squared_norm(chord);
      Vector<T, D> mean{};
      for (std::size_t i = 0; i < k; ++i) mean = mean + H[i].to_vector();
      const T lam = cc > 0 ? std::clamp(-dot(H[0].to_vector(), chord) / cc, T(0), T(1)) : T(0);
      for (const Vector<T, D>& dir : {mean, H[0].to_vector() + lam * chord}) {
        const Vector<T, D> u = unit(dir);
        if (squared_norm(u) == 0) continue;
        T low = std::numeric_limits<T>::infinity();
        for (std::size_t i = 0; i < k; ++i) low = std::min(low, dot(H[i].to_vector(), u));
        if (low > T(0.06) * big) return true;
      }
      return false;
    };
    if (clear(H, nh)) return out;
    if (n == 3) return cubic_cusps(piece, cubic_hodograph);
    // Else the same test on the hodograph's halves and quarters (de Casteljau at their
    // middles): a hodograph that turns about the origin without nearing it passes on the
    // parts, each holding its part of c' in its hull, with the same margin to `big`.
    const std::size_t k = hodograph.size();
    if (k <= 16) {
      std::array<std::array<Point<T, D>, 16>, 4> part{};
      std::copy(hodograph.begin(), hodograph.end(), part[0].begin());
      const auto split = [&](std::array<Point<T, D>, 16>& left, std::array<Point<T, D>, 16>& right) {
        // left holds the polygon; afterwards its first half, right its second.
        std::array<Point<T, D>, 16> w = left;
        for (std::size_t lvl = 0; lvl < k; ++lvl) {
          left[lvl] = w[0];
          right[k - 1 - lvl] = w[k - 1 - lvl];
          for (std::size_t i = 0; i + lvl + 1 < k; ++i) w[i] = w[i] + T(0.5) * (w[i + 1] - w[i]);
        }
      };
      split(part[0], part[2]);  // halves in 0 and 2
      split(part[0], part[1]);  // quarters 0, 1 of the first half
      split(part[2], part[3]);  // quarters 2, 3
      bool all = true;
      for (const auto& h : part) all = all && clear(h.data(), k);
      if (all) return out;
    }
  }
  const auto sp = [&](T x) {
    if constexpr (std::is_same_v<Piece, Bezier<T, D>>) {
      return fast_norm(bezier_point(hodograph, x).to_vector());
    } else {
      return fast_norm(piece.derivative_at(x, 1));
    }
  };
  std::array<T, 16 * 16 + 1> small_speed;  // up to degree 15 on the stack
  std::vector<T> large_speed;
  if (static_cast<std::size_t>(M) + 1 > small_speed.size()) large_speed.resize(static_cast<std::size_t>(M) + 1);
  T* speed = large_speed.empty() ? small_speed.data() : large_speed.data();
  T top = 0;
  for (int j = 0; j <= M; ++j) {
    speed[static_cast<std::size_t>(j)] = sp(T(j) / T(M));
    top = std::max(top, speed[static_cast<std::size_t>(j)]);
  }
  if (!(top > 0)) return out;
  for (int j = 1; j < M; ++j) {
    const T v = speed[static_cast<std::size_t>(j)];
    if (!(v <= speed[static_cast<std::size_t>(j - 1)] && v <= speed[static_cast<std::size_t>(j + 1)]) || v > T(0.05) * top) continue;
    T x0 = T(j - 1) / T(M), x3 = T(j + 1) / T(M);
    constexpr T g = T(0.6180339887498949L);
    T x1 = x3 - g * (x3 - x0), x2 = x0 + g * (x3 - x0);
    T f1 = sp(x1), f2 = sp(x2);
    for (int it = 0; it < 200 && x3 - x0 > T(4) * std::numeric_limits<T>::epsilon(); ++it) {
      if (f1 < f2) {
        x3 = x2;
        x2 = x1;
        f2 = f1;
        x1 = x3 - g * (x3 - x0);
        f1 = sp(x1);
      } else {
        x0 = x1;
        x1 = x2;
        f1 = f2;
        x2 = x0 + g * (x3 - x0);
        f2 = sp(x2);
      }
    }
    const T tc = f1 < f2 ? x1 : x2;
    if (std::min(f1, f2) > T(1e-9) * top || tc <= T(0) || tc >= T(1)) continue;
    const auto [left, right] = directions_at(piece, tc);
    if (dot(left, right) < 0 && (out.empty() || tc > out.back())) out.push_back(tc);
  }
  return out;
}

/// The inflections of a plane cubic piece inside (s0, s1), into out (sorted; returns how
/// many): the roots of c' x c'' = a2 t^2 + a1 t + a0 (c' = A t^2 + B t + C: a2 = -A x B,
/// a1 = 2 C x A, a0 = C x B) where it changes sign. Used only to choose where to try a
/// segment's end, so its accuracy does not bear on the result's.
template <class Piece, class T>
int cubic_inflections(const Piece& piece, T s0, T s1, std::array<T, 2>& out) {
  const auto& P = piece.points();
  if (P.size() != 4) return 0;
  const Vector<T, 2> C = T(3) * (P[1] - P[0]), B = T(6) * ((P[2] - P[1]) - (P[1] - P[0])),
                     A = T(3) * ((P[3] - P[0]) - T(3) * (P[2] - P[1]));
  const auto cross = [](const Vector<T, 2>& u, const Vector<T, 2>& v) { return u[0] * v[1] - u[1] * v[0]; };
  const T a2 = -cross(A, B), a1 = T(2) * cross(C, A), a0 = cross(C, B);
  int n = 0;
  const auto keep = [&](T t) {
    if (t > s0 && t < s1 && std::isfinite(t)) out[static_cast<std::size_t>(n++)] = t;
  };
  if (a2 != 0) {
    const T disc = a1 * a1 - T(4) * a2 * a0;
    if (!(disc > 0)) return 0;  // no sign change (a double root at most)
    const T sq = std::sqrt(disc);
    const T qq = -T(0.5) * (a1 + (a1 >= 0 ? sq : -sq));
    T r0 = qq / a2, r1 = qq != 0 ? a0 / qq : r0;
    if (r1 < r0) std::swap(r0, r1);
    keep(r0);
    if (r1 != r0) keep(r1);
  } else if (a1 != 0) {
    keep(-a0 / a1);
  }
  return n;
}

/// The chain of one span [s0, s1] of a piece (no cusp inside), from direction t_start at
/// its start to t_end at its end: greedy, each segment reaching as far as it can (the
/// largest end found to 4% of its step by a model of the measure, galloping and
/// bisection; the span's end first when the model's step nearly reaches it; an inflection
/// inside, else the midpoint, first after the span fails as one segment within 16 times
/// the tolerance) with the quadratic whose middle point is where the end tangents meet;
/// consecutive segments share the point and the direction at their joint. Appends
/// segments and own parameters of their ends; throws when more than max_segments would be
/// made.
template <class Piece, class Sink, class T = typename Piece::Scalar, int D = Piece::dimension>
void approximate_span(const Piece& piece, T s0, T s1, const Point<T, D>& p_start, const Point<T, D>& p_end, Vector<T, D> t_start,
                      const Vector<T, D>& t_end, T tolerance, std::size_t max_segments, Sink& out, T& max_error) {
  T t0 = s0;
  Point<T, D> p0 = p_start;
  Vector<T, D> dir0 = t_start;
  T step = s1 - s0;
  const T min_step = T(1e-9) * (s1 - s0);
  // The search aims each end at a measure of aim x tolerance, and takes an end whose
  // measure is at least take x tolerance.
  constexpr T aim = T(0.9), take = T(0.8);
  struct Try {
    Chain<T, D> q;
    Vector<T, D> dir1;
    T error;  // infinite when the tangent lines do not meet ahead
    bool ok;  // within the tolerance
    T aim = -1;  // when not negative: the search's measure (the distance from c(1/2) to q), else `error`
    bool measured() const { return aim >= 0; }
    T search_error() const { return aim >= 0 ? aim : error; }
  };
  // The quadratic over [t0, t1] and its error bound, or none when the tangent lines do
  // not meet ahead or the bound exceeds the tolerance.
  Part<Piece> part;
  std::vector<Vector<T, D>> hull;
  const auto attempt = [&](T t1) -> Try {
    part.make(piece, t0, t1);
    const bool last = t1 == s1;
    const Point<T, D> p2 = last ? p_end : part.points.back();
    const Vector<T, D> dir1 = last ? t_end : end_direction(part.points, false);
    Vector<T, D> d0 = dir0;
    if (squared_norm(d0) == 0) d0 = end_direction(part.points, true);
    // The end speeds serve skew tangent lines only (a space curve): not computed in the plane.
    const T v0 = D > 2 ? part.end_speed(true) : T(0), v1 = D > 2 ? part.end_speed(false) : T(0);
    const auto q = tangent_chain(p0, d0, p2, dir1, v0, v1);
    if (!q) return Try{Chain<T, D>({p0, p0, p2}), dir1, std::numeric_limits<T>::infinity(), false};
    // A part is taken on the first of its bounds found within the tolerance, cheapest
    // first: any bound will do, since the search aims from the measure below, not from the
    // bound. The span's last part: the cheap bound (the part's control points against the
    // raised quadratic, a bound of the parametric distance, its polygon halved where above
    // the tolerance: cu2qu's test, on our quadratic); taken on it without the measure (the
    // span ends there).
    const T p = last ? part.elevated_bound(*q, tolerance, 4) : part.elevated_bound(*q);
    if (last && p <= tolerance) return Try{*q, dir1, p, true};
    // The search's measure: the distance from c(1/2) to its foot on the chain, near the
    // Hausdorff distance on parts near a small tolerance (see middle_foot) and consistent
    // from one end to the next (the search's model of the error holds on it); a part whose
    // c(1/2) is farther than the tolerance is rejected on it. A cubic part against one quadratic
    // (middle_foot), else the sample at 1/2 of the sampled bound, which continues from it.
    T foot = 0;
    T spike = -1;
    T mid = part.middle_foot(*q, foot, tolerance, &spike);
    if (spike >= 0 && mid <= tolerance) {
      // The first foot, farther than the tolerance from c(1/2), is a point of q: its distance
      // to the part (a measure, like the foot's: a distance to some point of the part) is
      // the search's measure when above the tolerance, and the part is rejected on it.
      const auto& Q = q->front();
      const T u = spike, w = T(1) - u;
      Point<T, D> at;
      for (int k = 0; k < D; ++k) at[k] = w * w * Q[0][k] + T(2) * w * u * Q[1][k] + u * u * Q[2][k];
      const T far = part.distance_from(at, u);
      if (far > tolerance) return Try{*q, dir1, far, false};
    }
    std::optional<ChainDistance<T, D>> dist;
    if (!std::isfinite(mid)) {
      dist.emplace(*q);
      mid = dist->estimate(part, 2, tolerance);
    }
    if (mid > tolerance) return Try{*q, dir1, mid, false, mid};
    if (p <= tolerance) return Try{*q, dir1, p, true, mid};
    if (!dist) {
      // A cubic part: the bound after the quartic change of the quadratic's parameter
      // through the foot, then the cheap bound halved.
      const T rb = part.reparametrised_bound4_at(*q, foot, tolerance, 3);
      if (rb <= tolerance) return Try{*q, dir1, rb, true, mid};
      if (!last) {
        const T ps = part.elevated_bound(*q, tolerance, 4);
        if (ps <= tolerance) return Try{*q, dir1, ps, true, mid};
      }
      dist.emplace(*q);
    }
    // The sampled bound, coarse to fine, up to the first level within the tolerance.
    part.second_derivative_hull(hull);
    const T e = dist->bound(part, hull, tolerance, tolerance);
    return Try{*q, dir1, e, e <= tolerance, e <= tolerance ? mid : T(-1)};
  };
  const auto accept = [&](const Try& r, T t1) {
    if (out.size() + static_cast<std::size_t>(r.q.size) > max_segments) {
      throw InvalidArgument("tolerance", "the approximation needs more than " + std::to_string(max_segments) +
                                             " quadratic segments: use a larger tolerance");
    }
    if (r.q.size == 2) {
      out.push(r.q.q[0], t0 + T(0.5) * (t1 - t0));
      out.push(r.q.q[1], t1);
    } else {
      out.push(r.q.q[0], t1);
    }
    max_error = std::max(max_error, r.error);
    step = t1 - t0;
    {
      // The next segment's first end by the model of the search below from this one's
      // error (at most 1.5 times its step).
      const T e = r.search_error();
      if (std::isfinite(e) && e > 0) step *= std::min(T(1.5), std::sqrt(std::sqrt(aim * tolerance / e)));
    }
    t0 = t1;
    p0 = r.q.back()[2];
    dir0 = r.dir1;
  };
  // The span's inflections (a plane cubic piece): where the tangent lines of a part
  // across one stop meeting ahead, so the first end tried after the span fails as one
  // segment (two convex parts).
  std::array<T, 2> inflection{};
  int inflections = -1;  // not computed yet
  while (t0 < s1) {
    // The farthest end: a model of the error (growing as a power of the step on smooth
    // parts, the exponent 4 or fitted from the last two ends) proposes each next end from
    // the last measure, aiming at 90% of the tolerance; a bracket [lo, hi] (feasible,
    // infeasible) keeps the search safe where the model fails (bisection). Accepted once an
    // end is feasible with a measure of at least 80% of the tolerance, or the bracket is
    // within 4% of the step.
    T lo = t0, hi = s1;
    bool hi_tested = false;
    std::optional<Try> best;
    bool done = false, probe = false;
    int rest_tries = 0;
    T model_guess = std::numeric_limits<T>::quiet_NaN();  // where a probe without a chain sends the search (NaN: bisection)
    T prev_x = t0, prev_e = 0;
    // The span's end first when the model's step nearly reaches it (a failure there gives
    // the model its measure as well as the step would).
    T x = s1 - t0 <= T(1.5) * step ? s1 : t0 + step;
    for (int it = 0; it < 200; ++it) {
      Try r = attempt(x);
      const T e = r.search_error();  // the measure, or a bound above the tolerance, or infinite
      const bool was_probe = probe;
      probe = false;
      T g = std::numeric_limits<T>::quiet_NaN();
      if (r.ok) {
        lo = x;
        const bool enough = x == s1 || (e >= take * tolerance && !was_probe);
        if (!enough && hi == s1 && hi_tested && rest_tries < 2 && (was_probe || s1 - x <= x - t0)) {
          // The span's rest failed as one segment, so two is the fewest: when the rest
          // from x fits one, the two are taken; else the rest's error places the next
          // end (the rest's start that its model lets fit), tried with its rest in turn.
          ++rest_tries;
          const T t0_was = t0;
          const Point<T, D> p0_was = p0;
          const Vector<T, D> dir0_was = dir0;
          t0 = x, p0 = r.q.back()[2], dir0 = r.dir1;
          Try rest = attempt(s1);
          t0 = t0_was, p0 = p0_was, dir0 = dir0_was;
          if (rest.ok) {
            accept(r, x);
            accept(rest, s1);
            done = true;
            break;
          }
          const T er = rest.search_error();
          if (std::isfinite(er) && er > 0 && rest_tries < 2) {
            const T start = s1 - (s1 - x) * std::sqrt(std::sqrt(aim * tolerance / er));
            if (start > x && start < hi) {
              g = start + T(0.1) * (hi - start);
              probe = true;
              model_guess = std::numeric_limits<T>::quiet_NaN();  // a failure there: bisection
            }
          }
        }
        best = std::move(r);
        if (enough) break;
      } else if (!(was_probe && !std::isfinite(e))) {
        hi = x;
        hi_tested = true;
      }
      if (best && hi_tested && hi - lo <= T(0.04) * (lo - t0)) break;
      if (!best && hi - t0 <= min_step) break;
      if (probe) {
        // g: the rest's start by the rest's model, set above
      } else if (was_probe && !r.ok && !std::isfinite(e)) {
        g = model_guess;
      } else if (std::isfinite(e) && e > 0) {
        // The model: e grows as (x - t0)^k, k = 4 (G1 Hermite interpolation) unless the
        // last two ends from t0 measured another exponent (within [2, 10]).
        T k = T(4);
        if (r.measured() && prev_x > t0 && std::isfinite(prev_e) && prev_e > 0) {
          const T lr = std::log((x - t0) / (prev_x - t0));
          if (std::abs(lr) > T(0.02)) k = std::clamp(std::log(e / prev_e) / lr, T(2), T(10));
        }
        g = t0 + (x - t0) * (k == T(4) ? std::sqrt(std::sqrt(aim * tolerance / e)) : std::pow(aim * tolerance / e, T(1) / k));
        if (r.measured()) prev_x = x, prev_e = e;
      }
      // The span's rest failed as one segment within 16 times the tolerance (the error falls
      // as the fourth power of the step: halves near a sixteenth of it; a rest whose tangent
      // lines do not meet ahead goes on with the model): an inflection inside is the next end
      // (the two convex parts; measured: trying it after such failures too saved nothing),
      // else the midpoint (cu2qu's two equal parts); with either, the rest from there as the
      // second segment (taken whatever the first's error). Where the tangent lines do not meet
      // ahead at that end (feasibility is not monotone there: S-shaped spans fit past it),
      // the search resumes from the model's end and keeps its bracket.
      if (it == 0 && x == s1 && !r.ok) {
        T at = -1;
        if (inflections < 0) {
          inflections = 0;
          if constexpr (D == 2 && std::is_same_v<Piece, Bezier<T, D>>) inflections = cubic_inflections(piece, s0, s1, inflection);
        }
        for (int i = 0; i < (e <= T(16) * tolerance ? inflections : 0); ++i) {
          const T ti = inflection[static_cast<std::size_t>(i)];
          if (ti > t0 + T(0.02) * (s1 - t0) && ti < s1 - T(0.02) * (s1 - t0)) {
            at = ti;
            break;
          }
        }
        if (at < 0 && e <= T(16) * tolerance) at = t0 + T(0.5) * (s1 - t0);
        if (at >= 0) {
          model_guess = g;
          g = at;
          probe = true;
        }
      }
      if (!(g > lo)) g = lo + T(0.5) * (hi - lo);
      if (g >= hi) g = hi_tested ? lo + T(0.5) * (hi - lo) : s1;
      if (g == x) break;
      x = g;
    }
    if (done) break;
    if (!best) {
      // No quadratic through the tangent lines fits even over the smallest step (not
      // expected between cusps): the part over min_step as a straight quadratic, measured.
      const T t1 = std::min(s1, t0 + min_step);
      part.make(piece, t0, t1);
      const Point<T, D> p2 = t1 == s1 ? p_end : part.points.back();
      const Chain<T, D> q({p0, p0 + T(0.5) * (p2 - p0), p2});
      part.second_derivative_hull(hull);
      ChainDistance<T, D> dist(q);
      const T e = dist.bound(part, hull, std::numeric_limits<T>::max(), T(0));
      accept(Try{q, t1 == s1 ? t_end : end_direction(part.points, false), e, true}, t1);
      continue;
    }
    accept(*best, lo);
  }
}

/// Appends the chain of one piece s to r: its segments, and their ends' parameters lifted
/// to the curve's by lift (the piece's last end is piece_end, exactly). start_dir and
/// end_dir: the directions at the piece's ends (shared with the neighbours' at smooth
/// joints). Throws when r would hold more than max_segments segments.
template <class S, class T, int D, class Lift>
void approximate_piece(const S& s, const Vector<T, D>& start_dir, const Vector<T, D>& end_dir, T tolerance, std::size_t max_segments,
                       QuadraticChain<T, D>& r, T piece_end, const Lift& lift) {
  struct Sink {
    QuadraticChain<T, D>& r;
    T piece_end;
    const Lift& lift;
    std::size_t size() const { return r.segments.size(); }
    void push(const std::array<Point<T, D>, 3>& q, T own_end) {
      r.segments.push_back(Bezier<T, D>({q[0], q[1], q[2]}));
      r.breaks.push_back(own_end == T(1) ? piece_end : lift(own_end));
    }
  } sink{r, piece_end, lift};
  const auto& P = s.points();
  const int n = s.degree();
  bool equal_weights = true;
  if constexpr (!std::is_same_v<S, Bezier<T, D>>) {
    for (const T w : s.weights()) equal_weights = equal_weights && w == s.weights().front();
  }
  if (n <= 1 || (n == 2 && equal_weights)) {
    const Point<T, D> mid = n == 2 ? P[1] : P.front() + T(0.5) * (P.back() - P.front());
    if (r.segments.size() + 1 > max_segments) {
      throw InvalidArgument("tolerance", "the approximation needs more than " + std::to_string(max_segments) +
                                             " quadratic segments: use a larger tolerance");
    }
    sink.push({P.front(), mid, P.back()}, T(1));
    return;
  }
  const std::vector<T> inner = cusps(s);
  if (inner.empty()) {
    approximate_span(s, T(0), T(1), P.front(), P.back(), start_dir, end_dir, tolerance, max_segments, sink, r.max_error);
    return;
  }
  std::vector<T> cut;
  cut.reserve(inner.size() + 2);
  cut.push_back(T(0));
  cut.insert(cut.end(), inner.begin(), inner.end());
  cut.push_back(T(1));
  std::vector<Point<T, D>> span_points;  // the span's control points (Cartesian)
  for (std::size_t j = 0; j + 1 < cut.size(); ++j) {
    const T a = cut[j], b = cut[j + 1];
    if constexpr (std::is_same_v<S, Bezier<T, D>>) {
      polynomial_portion(P, a, b, span_points);
    } else {
      span_points = s.portion(a, b).points();
    }
    const Point<T, D> pa = j == 0 ? P.front() : span_points.front();
    const Point<T, D> pb = j + 2 == cut.size() ? P.back() : span_points.back();
    const Vector<T, D> da = j == 0 ? start_dir : end_direction(span_points, true);
    const Vector<T, D> db = j + 2 == cut.size() ? end_dir : end_direction(span_points, false);
    approximate_span(s, a, b, pa, pb, da, db, tolerance, max_segments, sink, r.max_error);
  }
}


/// The frame of to_quadratic: the exponent e that brings the largest |coordinate| of the
/// control points into [0.5, 1) (0 when every coordinate is 0). When |e| is beyond a
/// sixteenth of the type's exponent range (double: 2^64, where squared and fourth powers
/// of lengths and tolerances begin to leave the normal range), the approximation runs on
/// the curve scaled by 2^-e and the tolerance with it, then scales the chain back by 2^e:
/// exact (powers of two), so that tiny or huge curves give the unit curve's segments
/// times their scale. Within that range the arithmetic is the same at every power of two
/// (no absolute threshold; measured: the same counts from 1e-155 to 1e150 before the
/// frame), and the curve is used as it is (no copy). A curve of exact pieces (degree
/// <= 2, see approximate_piece) is never scaled: it comes back as itself.
template <class T>
bool needs_frame(int e) {
  constexpr int range = std::numeric_limits<T>::max_exponent / 16;
  return e < -range || e > range;
}
template <class S>
bool exact_piece(const S& s) {
  using T = typename S::Scalar;
  const int n = s.degree();
  if (n <= 1) return true;
  if (n > 2) return false;
  if constexpr (requires { s.weights(); }) {
    for (const T w : s.weights())
      if (w != s.weights().front()) return false;
  }
  return true;
}
template <class T, int D>
std::vector<Point<T, D>> scale_points(const std::vector<Point<T, D>>& P, int k) {
  std::vector<Point<T, D>> Q(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) Q[i] = times_pow2(P[i], k);
  return Q;
}
template <class T, int D>
Bezier<T, D> scale_piece(const Bezier<T, D>& c, int k) {
  return Bezier<T, D>(scale_points(c.points(), k));
}
template <class T, int D>
RationalBezier<T, D> scale_piece(const RationalBezier<T, D>& c, int k) {
  return RationalBezier<T, D>(scale_points(c.points(), k), c.weights());
}
/// The tolerance in the frame: capped at 2^512 (the curve there is within 1 of the
/// origin, so a larger tolerance admits nothing more) so that it stays finite.
template <class T>
T frame_tolerance(T tolerance, int e) {
  return std::min(times_pow2(tolerance, -e), pow2<T>(512));
}
/// The chain computed in the frame, back in the curve's coordinates.
template <class T, int D>
void unframe(QuadraticChain<T, D>& r, int e) {
  for (auto& s : r.segments) s = Bezier<T, D>(scale_points(s.points(), e));
  r.max_error = times_pow2(r.max_error, e);
}

}  // namespace detail::quadratic

/// The curve as a chain of quadratic Bézier segments within `tolerance` (> 0) of it.
///
/// Each exact piece is handled on its own: a polynomial of degree <= 2 is exact (a point
/// or a line as a quadratic with its middle point at the chord's midpoint, a quadratic as
/// itself; so is a rational piece of degree <= 1, or of degree 2 with equal weights). Any
/// other piece is cut at its cusps, and each span between them is covered greedily: from
/// its start, the segment reaching farthest (to 4% of its step) whose middle control point
/// is where the curve's tangent lines at the segment's two ends meet, within the
/// tolerance. The segment therefore starts and ends on the curve with the curve's
/// tangent directions (G1 Hermite interpolation, error falling as the fourth power of
/// the step on smooth parts), and consecutive segments share one direction at their
/// joint. A part whose tangent lines do not meet ahead (an inflection in the middle, skew
/// lines of a space curve) is made shorter. Piece joints where the curve's directions
/// agree to snap_angle get one shared direction; corners (G0 joints, cusps) stay
/// corners.
///
/// The search for each segment's end steers by a measure, not a bound: the distance from
/// the part's middle point c(1/2) to its foot on the quadratic (Part::middle_foot; within
/// a few percent of the Hausdorff distance on parts near a small tolerance), with a model
/// of the error growing as a power of the step (4, or fitted from the last two ends),
/// aiming at 90% of the tolerance and taking an end whose measure reaches 80% (or whose
/// bracket is within 4% of the step). A part whose measure exceeds the tolerance is
/// rejected on it. A part is taken only on an upper bound of its Hausdorff distance
/// within the tolerance, the first found of, cheapest first: the control points of the
/// part minus the quadratic raised to its degree (Part::elevated_bound, a bound of the
/// parametric distance; for a cubic part its Bernstein polygon halved up to four times
/// where above the tolerance), the distance after a quartic change of the quadratic's
/// parameter through the foot (Part::reparametrised_bound4_at, cubic parts), then samples
/// with their nearest points on the quadratic and a second-derivative margin between samples
/// (detail::quadratic::ChainDistance::bound, 5 to 33 samples, up to the first level within
/// the tolerance; a bound for polynomial pieces, for rational pieces with an estimated
/// margin). max_error is the largest of the bounds taken: within the tolerance, not
/// tight (except where no quadratic through the tangent lines fits even over 1e-9 of a
/// span, not expected between cusps: that part becomes a straight segment, its bound
/// measured and reported whatever it is). Cusps and inflections of a plane cubic are found in closed form
/// (plane_cubic_without_cusp, cubic_cusps, cubic_inflections). Once the rest of a span has
/// failed as one segment within 16 times the tolerance, the first end tried is an
/// inflection inside (two convex parts), else its midpoint (cu2qu's two equal parts); once
/// it has failed, an end found within the tolerance is tried with the rest as a second
/// segment (two is then the fewest); when the rest fails, its measure places the next end
/// tried so. Errors:
/// InvalidArgument "tolerance" (not finite and > 0; more than max_segments segments
/// needed).
template <class C>
  requires detail::is_pieces<C>
QuadraticChain<typename C::Scalar, C::dimension> to_quadratic(const C& p, typename C::Scalar tolerance,
                                                               std::size_t max_segments = std::numeric_limits<std::size_t>::max()) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  using namespace detail::quadratic;
  if (!std::isfinite(tolerance) || !(tolerance > 0)) {
    throw InvalidArgument("tolerance", "must be a finite number > 0, got " + detail::format_number(tolerance));
  }
  {  // the frame (abs_exponent): the scaled pieces have e = 0
    T m = 0;
    bool exact = true;
    for (const auto& seg : p.segments()) {
      std::visit(
          [&](const auto& s) {
            detail::max_abs<T, D>(std::span<const Point<T, D>>(s.points()), m);
            exact = exact && exact_piece(s);
          },
          seg);
    }
    if (const int e = detail::abs_exponent(m); !exact && needs_frame<T>(e)) {
      std::vector<BezierPiece<T, D>> scaled;
      scaled.reserve(p.size());
      for (const auto& seg : p.segments()) std::visit([&](const auto& s) { scaled.emplace_back(scale_piece(s, -e)); }, seg);
      QuadraticChain<T, D> r = to_quadratic(C(std::move(scaled), p.breaks()), frame_tolerance(tolerance, e), max_segments);
      unframe(r, e);
      return r;
    }
  }
  QuadraticChain<T, D> r;
  r.breaks.reserve(p.size() + 1);
  r.segments.reserve(p.size());
  r.breaks.push_back(p.domain().lo);
  const std::size_t k = p.size();
  // Each piece's end directions, with the shared direction at tangent-continuous joints.
  std::vector<Vector<T, D>> start_dir(k), end_dir(k);
  for (std::size_t i = 0; i < k; ++i) {
    std::visit(
        [&](const auto& s) {
          start_dir[i] = end_direction(s.points(), true);
          end_dir[i] = end_direction(s.points(), false);
        },
        p.segments()[i]);
  }
  for (std::size_t i = 0; i + 1 < k; ++i) {
    const Vector<T, D> a = end_dir[i], b = start_dir[i + 1];
    const Point<T, D> pa = std::visit([](const auto& s) { return s.points().back(); }, p.segments()[i]);
    const Point<T, D> pb = std::visit([](const auto& s) { return s.points().front(); }, p.segments()[i + 1]);
    if (squared_norm(a) == 0 || squared_norm(b) == 0 || !(pa == pb)) continue;
    const T angle = std::atan2(fast_norm(a - dot(a, b) * b), dot(a, b));
    if (angle < snap_angle<T>) end_dir[i] = start_dir[i + 1] = unit(a + b);
  }
  for (std::size_t i = 0; i < k; ++i) {
    std::visit([&](const auto& s) { approximate_piece(s, start_dir[i], end_dir[i], tolerance, max_segments, r, p.breaks()[i + 1], [&](T t) { return p.lift(i, t); }); },
               p.segments()[i]);
  }
  return r;
}

/// A Bézier or rational Bézier curve: itself the one piece (as on pieces(c), without
/// building them).
template <class C>
  requires detail::is_bezier_piece<C>
QuadraticChain<typename C::Scalar, C::dimension> to_quadratic(const C& c, typename C::Scalar tolerance,
                                                               std::size_t max_segments = std::numeric_limits<std::size_t>::max()) {
  using T = typename C::Scalar;
  using namespace detail::quadratic;
  if (!std::isfinite(tolerance) || !(tolerance > 0)) {
    throw InvalidArgument("tolerance", "must be a finite number > 0, got " + detail::format_number(tolerance));
  }
  {  // the frame (abs_exponent): the scaled curve has e = 0
    T m = 0;
    detail::max_abs<T, C::dimension>(std::span<const Point<T, C::dimension>>(c.points()), m);
    if (const int e = detail::abs_exponent(m); needs_frame<T>(e) && !exact_piece(c)) {
      QuadraticChain<T, C::dimension> r = to_quadratic(scale_piece(c, -e), frame_tolerance(tolerance, e), max_segments);
      unframe(r, e);
      return r;
    }
  }
  QuadraticChain<T, C::dimension> r;
  r.breaks.reserve(4);
  r.segments.reserve(3);
  r.breaks.push_back(T(0));
  approximate_piece(c, end_direction(c.points(), true), end_direction(c.points(), false), tolerance, max_segments, r, T(1),
                    [](T t) { return t; });
  return r;
}

/// Any other curve type: on its exact pieces (pieces(c)).
template <class C>
  requires(!detail::is_pieces<C>) && (!detail::is_bezier_piece<C>) && PiecewiseBezierCurve<C>
auto to_quadratic(const C& c, typename C::Scalar tolerance, std::size_t max_segments = std::numeric_limits<std::size_t>::max()) {
  return to_quadratic(pieces(c), tolerance, max_segments);
}

}  // namespace casteljau
