// Flattening: a polyline within a distance tolerance of a curve, three ways: uniform steps
// (Wang's bound), recursive subdivision (the flatness test), near-optimal steps.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "casteljau/core/segment.hpp"
#include "casteljau/algo/flatten_method.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/path.hpp"

/// flatten(c, tolerance, method, out) appends to out (defined for code, such as bench/,
/// that must also build against versions without that overload).
#define CASTELJAU_FLATTEN_APPENDS 1

// The small kernels' helpers are called once or twice per vertex: GCC, left to itself,
// does not inline them into the step loop (about 30% slower on W3).
#if defined(__GNUC__)
#define CASTELJAU_FLATTEN_INLINE [[gnu::always_inline]] inline
#define CASTELJAU_FLATTEN_LAMBDA __attribute__((always_inline))
#else
#define CASTELJAU_FLATTEN_LAMBDA
#define CASTELJAU_FLATTEN_INLINE inline
#endif

namespace casteljau {

namespace detail {

/// Flat when every control point is within tol of the chord segment: the curve lies in
/// the convex hull of its control points, and every point of that hull is within tol of
/// the (convex) segment, so the whole piece is too. A guaranteed bound. Written so that
/// a NaN distance fails the test.
template <class C>
bool is_flat(const C& c, typename C::Scalar tol) {
  const auto& P = c.points();
  for (std::size_t i = 1; i + 1 < P.size(); ++i) {
    if (!(distance_to_segment(P[i], P.front(), P.back()) <= tol)) return false;
  }
  return true;
}

template <class C>
void flatten_rec(const C& c, typename C::Scalar tol, int depth, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  if (is_flat(c, tol)) {
    out.push_back(c.points().back());
    return;
  }
  // 2^-52 of the parameter range: beyond this, subdivision is stuck on rounding (the
  // tolerance is below the coordinates' resolution).
  if (depth >= 52) {
    throw NumericalError("flatten: subdivision reached depth 52 (pieces of 2^-52 of the parameter range): the tolerance is below "
                         "the resolution of the curve's coordinates");
  }
  const auto halves = c.split(typename C::Scalar(0.5));
  flatten_rec(halves.left, tol, depth + 1, out);
  flatten_rec(halves.right, tol, depth + 1, out);
}

/// The subdivision method on a unit-scale piece (see flatten()): vertices after out's
/// first.
template <class C>
void flatten_subdivision(const C& c, typename C::Scalar tol, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  flatten_rec(c, tol, 0, out);
}

/// Wang's count for a polynomial piece [Wang84; Filip86]: with n = ceil(sqrt(p (p - 1) / 8
/// max_i |P_i - 2 P_(i+1) + P_(i+2)| / tol)) uniform steps, the chord of each step is
/// within tol of the curve (|B(t) - chord(t)| <= h^2 / 8 max |B''| and |B''| <= p (p - 1)
/// max |second differences|). For a rational piece the same formula on its Cartesian
/// points is an estimate only (flatten_uniform checks it).
template <class C>
double wang_count(const C& c, typename C::Scalar tol) {
  const auto& P = c.points();
  const int p = static_cast<int>(P.size()) - 1;
  if (p < 2) return 1;
  double second = 0;
  for (std::size_t i = 0; i + 2 < P.size(); ++i) second = std::max(second, static_cast<double>(norm((P[i + 2] - P[i + 1]) - (P[i + 1] - P[i]))));
  return std::max(1.0, std::ceil(std::sqrt(p * (p - 1) / 8.0 * second / static_cast<double>(tol))));
}

/// Most segments one piece may be flattened into (2^26: far beyond any polyline worth
/// drawing; the CLI refuses responses over 10^6 vertices long before). A request past it
/// is reported, never silently truncated.
inline constexpr double max_piece_segments = 67108864.0;

template <class C>
Point<typename C::Scalar, C::dimension> end_point(const C& c, bool last) {
  return last ? c.points().back() : c.points().front();
}

/// The piece c on [t0, t1] (0 <= t0 < t1 <= 1) reparametrised to [0, 1], by two de
/// Casteljau splits (O(p^2), against O(p^3) for the blossom of portion()); the ends are
/// c(t0) and c(t1) up to rounding of the rescaled split parameter.
template <class C>
C part(const C& c, typename C::Scalar t0, typename C::Scalar t1) {
  using T = typename C::Scalar;
  if (t1 < 1) {
    if (t0 <= 0) return c.split(t1).left;
    return c.split(t1).left.split(std::clamp(t0 / t1, T(0), T(1))).right;
  }
  return t0 <= 0 ? c : c.split(t0).right;
}

/// Highest degree whose steps the exact deviation checks: above it a root solve per step
/// costs more than the vertices it saves (degree 200: 7 s against 0.1 s), and the hull
/// test (conservative) decides alone.
inline constexpr int exact_check_degree = 12;

/// The largest distance from the piece c on [t0, t1] to the chord segment c(t0) c(t1), when
/// it can be computed exactly: the sub-piece's control points must project inside the
/// chord (then by the convex hull property the whole sub-piece does, and its distance to
/// the segment is its distance to the line). The distance to the line of a polynomial
/// piece is |sum_i B_i(t) d_i| with d_i the control points' offsets from the line: its
/// maximum is at a root of the derivative (bernstein_roots) or an end; for a rational
/// piece the offsets are weighted and divided by the weight function (quotient rule on
/// the numerator of |d|^2). Returns nullopt when a control point projects outside the
/// chord (the caller takes a shorter step). Cost O(p^3) for the sub-piece plus one root
/// solve of degree 2p - 1 (3p - 1 rational).
template <class C>
std::optional<typename C::Scalar> chord_deviation(const C& c, typename C::Scalar t0, typename C::Scalar t1) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const C sub = part(c, t0, t1);
  const auto& P = sub.points();
  const std::size_t m = P.size();
  const Vector<T, D> chord = P.back() - P.front();
  const T L = norm(chord);
  if (!(L > 0)) return std::nullopt;
  const Vector<T, D> u = chord / L;
  // Offsets from the line, per coordinate, with the projections checked.
  std::vector<std::vector<T>> off(D, std::vector<T>(m));
  for (std::size_t i = 0; i < m; ++i) {
    const Vector<T, D> v = P[i] - P.front();
    const T e = dot(v, u);
    // The end points are the chord's ends (their projections 0 and L up to rounding).
    if (i > 0 && i + 1 < m && (e < 0 || e > L)) return std::nullopt;
    const Vector<T, D> d = v - e * u;
    for (int k = 0; k < D; ++k) off[k][i] = d[k];
  }
  std::vector<T> w(m, T(1));
  bool rational = false;
  if constexpr (requires { sub.weights(); }) {
    const T wmax = *std::max_element(sub.weights().begin(), sub.weights().end());
    for (std::size_t i = 0; i < m; ++i) w[i] = sub.weights()[i] / wmax;
    rational = true;
  }
  if constexpr (D == 2) {
    // In the plane the offset is a signed scalar: its extremes are at the roots of its
    // derivative (numerator N' w - N w' for a rational piece), degree p - 1 (2p - 2).
    std::vector<T> N(m), dN(m - 1), dw(m - 1);
    for (std::size_t i = 0; i < m; ++i) N[i] = w[i] * cross(u, P[i] - P.front());
    for (std::size_t i = 0; i + 1 < m; ++i) {
      dN[i] = N[i + 1] - N[i];
      dw[i] = w[i + 1] - w[i];
    }
    std::vector<T> g = dN;
    if (rational) {
      const auto a = bernstein_product<T>(dN, w), b = bernstein_product<T>(N, dw);
      g.resize(a.size());
      for (std::size_t i = 0; i < g.size(); ++i) g[i] = a[i] - b[i];
    }
    T worst = 0;
    auto offset_at = [&](T r) { worst = std::max(worst, std::abs(cross(u, sub(r) - P.front()))); };
    if (!rational && g.size() <= 3) {
      // Degree <= 3: the derivative is linear or quadratic, solved in closed form (the
      // common case, kept free of the general root finder's allocations).
      if (g.size() == 2) {
        if (g[0] != g[1]) {
          const T r = g[0] / (g[0] - g[1]);
          if (r > 0 && r < 1) offset_at(r);
        }
      } else if (g.size() == 3) {
        // g0 (1-t)^2 + 2 g1 t (1-t) + g2 t^2 = A t^2 + B t + g0.
        const T A = g[0] - 2 * g[1] + g[2], B = 2 * (g[1] - g[0]);
        if (A == 0) {
          if (B != 0 && -g[0] / B > 0 && -g[0] / B < 1) offset_at(-g[0] / B);
        } else if (const T disc = B * B - 4 * A * g[0]; disc >= 0) {
          // The stable pair of roots: q = -(B + sign(B) sqrt(disc)) / 2, roots q / A, g0 / q.
          const T q = -(B + std::copysign(std::sqrt(disc), B)) / 2;
          const T r1 = q / A;
          if (r1 > 0 && r1 < 1) offset_at(r1);
          if (q != 0) {
            const T r2 = g[0] / q;
            if (r2 > 0 && r2 < 1) offset_at(r2);
          }
        }
      }
      return worst;
    }
    for (T r : bernstein_roots<T>(g)) offset_at(r);
    return worst;
  }
  // Numerators N_k = sum w_i B_i d_ik; g = sum_k N_k (N_k' w - N_k w') has the sign of
  // d/dt |d|^2 (for a polynomial piece w = 1 and g = sum_k N_k N_k').
  std::vector<T> g;
  for (int k = 0; k < D; ++k) {
    std::vector<T> N(m), dN(m - 1), dw(m - 1);
    for (std::size_t i = 0; i < m; ++i) N[i] = w[i] * off[k][i];
    for (std::size_t i = 0; i + 1 < m; ++i) {
      dN[i] = N[i + 1] - N[i];
      dw[i] = w[i + 1] - w[i];
    }
    std::vector<T> term;
    if (rational) {
      const auto a = bernstein_product<T>(dN, w), b = bernstein_product<T>(N, dw);
      std::vector<T> q(a.size());
      for (std::size_t i = 0; i < q.size(); ++i) q[i] = a[i] - b[i];
      term = bernstein_product<T>(N, q);
    } else {
      term = bernstein_product<T>(N, dN);
    }
    if (g.empty()) g.assign(term.size(), T(0));
    for (std::size_t i = 0; i < g.size(); ++i) g[i] += term[i];
  }
  T worst = 0;
  for (T r : bernstein_roots<T>(g)) {
    const Point<T, D> q = sub(r);
    const Vector<T, D> v = q - P.front();
    worst = std::max(worst, norm(v - dot(v, u) * u));
  }
  return worst;
}

/// Whether the chord of c over [t0, t1] is within tol of that part of the curve: the
/// convex hull test (guaranteed, conservative) or the exact deviation (chord_deviation).
template <class C>
bool chord_within(const C& c, typename C::Scalar t0, typename C::Scalar t1, typename C::Scalar tol) {
  if (c.degree() <= exact_check_degree) {
    if (auto d = chord_deviation(c, t0, t1)) return *d <= tol;
  }
  return is_flat(part(c, t0, t1), tol);
}

/// Uniform steps: Wang's count for a polynomial piece (a proven bound); for a rational
/// piece Wang's formula on the Cartesian points as a start, doubled until every step
/// passes chord_within (uniform steps with a verified count).
template <class C>
void flatten_uniform(const C& c, typename C::Scalar tol, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  using T = typename C::Scalar;
  double n = wang_count(c, tol);
  constexpr bool rational = requires { c.weights(); };
  for (;;) {
    if (n > max_piece_segments) {
      throw NumericalError("flatten: the uniform method would need more than 2^26 segments for one piece at tolerance " +
                           format_number(tol) + " (relative to the piece's extent)");
    }
    bool ok = true;
    if constexpr (rational) {
      for (double i = 0; i < n && ok; ++i) ok = chord_within(c, static_cast<T>(i / n), static_cast<T>((i + 1) / n), tol);
    }
    if (ok) break;
    n *= 2;
  }
  constexpr int D = C::dimension;
  const auto& P = c.points();
  const std::size_t m = P.size();
  // Past degree 32 de Casteljau's O(p^2) per vertex dominates (degree 1000 at 1e5 vertices:
  // a minute): the Bernstein-Horner form (O(p), error about p eps of the unit-scale
  // coordinates) when the tolerance is 1000 times that error, else de Casteljau.
  const bool horner = m > 33 && tol > T(1000) * static_cast<T>(m) * std::numeric_limits<T>::epsilon();
  std::vector<std::vector<T>> coef;
  std::vector<T> wts;
  if (horner) {
    wts.assign(m, T(1));
    if constexpr (rational) {
      const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
      for (std::size_t i = 0; i < m; ++i) wts[i] = c.weights()[i] / wmax;
    }
    coef.assign(D, std::vector<T>(m));
    for (int d = 0; d < D; ++d)
      for (std::size_t i = 0; i < m; ++i) coef[d][i] = wts[i] * P[i][d];
  }
  for (double i = 1; i < n; ++i) {
    const T t = static_cast<T>(i / n);
    if (horner) {
      const T w = rational ? bernstein_value_fast<T>(wts, t) : T(1);
      Point<T, D> q;
      for (int d = 0; d < D; ++d) q[d] = bernstein_value_fast<T>(coef[d], t) / w;
      out.push_back(q);
    } else {
      out.push_back(c(t));
    }
  }
  out.push_back(P.back());
}

/// The density of the near-optimal flattening at t: sqrt(|B' x B''| / |B'|), with |B' x
/// B''| = sqrt(|B'|^2 |B''|^2 - (B'.B'')^2) in any dimension. A chord over a short arc of
/// curvature k deviates by k s^2 / 8, so segments of deviation tol have arc length
/// sqrt(8 tol / k): their number is the integral of sqrt(k) ds / sqrt(8 tol) = integral of
/// this density dt / sqrt(8 tol) ([Levien19], the integral his parabola form evaluates in
/// closed form for quadratics). Zero where B' = 0.
template <class T, int D>
T flatten_density(const Vector<T, D>& d1, const Vector<T, D>& d2) {
  const T n1 = norm(d1);
  if (!(n1 > 0)) return 0;
  // |B' x B''| / |B'| is the norm of B'' normal to B'.
  const T along = dot(d2, d1 / n1);
  return std::sqrt(std::sqrt(std::max(T(0), squared_norm(d2) - along * along)));
}

/// Samples of the near-optimal density per degree (trapezoid rule on 8 p intervals, p <= 16).
inline constexpr int density_samples_per_degree = 8;

/// Cumulative near-optimal segment count F(t_j) at t_j = j / m (F(0) = 0), trapezoid rule.
template <class C>
std::vector<typename C::Scalar> flatten_cumulative(const C& c, typename C::Scalar tol) {
  using T = typename C::Scalar;
  const int p = static_cast<int>(c.points().size()) - 1;
  // Capped at degree 16 (128 samples): above it each sample costs O(p^2) and the density
  // only guesses the first step length, which the checks correct.
  const int m = density_samples_per_degree * std::clamp(p, 1, 16);
  std::vector<T> F(static_cast<std::size_t>(m) + 1, T(0));
  if (p < 2) return F;
  const T scale = 1 / std::sqrt(8 * tol);
  // A polynomial piece's derivatives from its hodographs (built once); a rational
  // piece's by the quotient rule.
  std::function<T(T)> density;
  if constexpr (requires { c.weights(); }) {
    density = [&](T t) { return flatten_density(c.derivative_at(t, 1), c.derivative_at(t, 2)); };
  } else {
    density = [h1 = c.derivative(1), h2 = c.derivative(2)](T t) { return flatten_density(h1(t).to_vector(), h2(t).to_vector()); };
  }
  T prev = density(T(0));
  for (int j = 1; j <= m; ++j) {
    const T cur = density(static_cast<T>(j) / static_cast<T>(m));
    F[static_cast<std::size_t>(j)] = F[static_cast<std::size_t>(j) - 1] + (prev + cur) / 2 / static_cast<T>(m) * scale;
    prev = cur;
  }
  return F;
}

/// The analytic segment count of the optimal method: ceil of the density integral.
template <class C>
double optimal_count(const C& c, typename C::Scalar tol) {
  const auto F = flatten_cumulative(c, tol);
  return std::max(1.0, std::ceil(static_cast<double>(F.back()) - 1e-9));
}

/// Near-optimal steps: a greedy walk whose every step is as long as the tolerance allows
/// (the largest deviation within [0.9, 1] tolerance, or the rest of the piece), found by a
/// few secant-like corrections t1 <- t + (t1 - t) sqrt(0.97 tol / deviation) (the
/// deviation of a short step grows as its square) started from one unit of the
/// cumulative density (flatten_cumulative): usually 1 to 3 exact checks per vertex. When
/// 8 corrections do not land in the band, the longest step that passed is taken (or the
/// step is shortened by 0.7 until one passes), so the tolerance is guaranteed whatever
/// the density's accuracy (cusps, where it vanishes). Steps below 1e-15 of the parameter
/// throw NumericalError.
template <class C>
void flatten_optimal(const C& c, typename C::Scalar tol, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  using T = typename C::Scalar;
  const auto F = flatten_cumulative(c, tol);
  const std::size_t m = F.size() - 1;
  auto F_at = [&](T t) {
    const T x = t * static_cast<T>(m);
    const std::size_t j = std::min(m - 1, static_cast<std::size_t>(x));
    return F[j] + (F[j + 1] - F[j]) * (x - static_cast<T>(j));
  };
  auto t_at = [&](T f) {  // inverse of F_at (F is non-decreasing)
    const auto it = std::lower_bound(F.begin(), F.end(), f);
    if (it == F.begin()) return T(0);
    if (it == F.end()) return T(1);
    const std::size_t j = static_cast<std::size_t>(it - F.begin()) - 1;
    const T span = F[j + 1] - F[j];
    const T frac = span > 0 ? (f - F[j]) / span : T(0);
    return (static_cast<T>(j) + std::clamp(frac, T(0), T(1))) / static_cast<T>(m);
  };
  auto deviation = [&](T t0, T t1) -> T {  // infinity when only the hull test could decide and it fails
    if (c.degree() <= exact_check_degree) {
      if (auto d = chord_deviation(c, t0, t1)) return *d;
    }
    return is_flat(part(c, t0, t1), tol) ? T(0) : std::numeric_limits<T>::infinity();
  };
  T t = 0;
  std::size_t steps = 0;
  while (t < 1) {
    T t1 = std::min(T(1), std::max(t_at(F_at(t) + 1), t + (1 - t) / 1024));
    T best = 0;  // longest step end that passed
    for (int it = 0; it < 8; ++it) {
      const T d = deviation(t, t1);
      if (d <= tol) {
        best = std::max(best, t1);
        if (t1 == 1 || d >= T(0.9) * tol) break;
      }
      const T grow = d > 0 && std::isfinite(d) ? std::sqrt(T(0.97) * tol / d) : (d == 0 ? T(4) : T(0.5));
      T next = std::min(T(1), t + (t1 - t) * std::clamp(grow, T(0.25), T(4)));
      if (next <= best) break;
      t1 = next;
    }
    if (best > t) {
      t1 = best;
    } else {
      while (!chord_within(c, t, t1, tol)) {
        t1 = t + (t1 - t) * T(0.7);
        if (!(t1 - t > T(1e-15))) {
          throw NumericalError("flatten: the optimal method's step fell below 1e-15 of the parameter at t = " + format_number(t) +
                               ": the tolerance is below the resolution of the curve");
        }
      }
    }
    if (++steps > max_piece_segments) throw NumericalError("flatten: more than 2^26 segments for one piece");
    out.push_back(t1 == 1 ? c.points().back() : c(t1));
    t = t1;
  }
}

// ---- Allocation-free kernels for polynomial pieces of degree <= 3 -----------------------
// Lines, quadratics and cubics are most curves in practice (fonts, SVG paths): they are
// flattened from fixed-size arrays on the unit-scale copy, each vertex handed to an
// emit callback (no vector per piece, no heap-allocated sub-curves). The methods and
// their guarantees are those of the general code above; uniform gives the same vertices.

/// A polynomial piece of degree 1..3 on the unit-scale copy (see flatten()), by value.
template <class T, int D>
struct SmallPiece {
  int m = 0;                         ///< number of control points, 2..4
  std::array<Point<T, D>, 4> q{};    ///< control points q[0 .. m)
  /// q(t) by de Casteljau: the same lerps in the same order as de_casteljau() (so the
  /// same values as Bezier::operator() on [0, 1]).
  Point<T, D> at(T t) const {
    switch (m) {
      case 2: return lerp(q[0], q[1], t);
      case 3: return lerp(lerp(q[0], q[1], t), lerp(q[1], q[2], t), t);
      default: {
        const Point<T, D> a = lerp(q[0], q[1], t), b = lerp(q[1], q[2], t), d = lerp(q[2], q[3], t);
        return lerp(lerp(a, b, t), lerp(b, d, t), t);
      }
    }
  }
};

/// Wang's count (wang_count) of a small piece, the same expression.
template <class T, int D>
double small_wang_count(const SmallPiece<T, D>& s, T tol) {
  const int p = s.m - 1;
  if (p < 2) return 1;
  double second = 0;
  for (int i = 0; i + 2 < s.m; ++i)
    second = std::max(second, static_cast<double>(norm((s.q[i + 2] - s.q[i + 1]) - (s.q[i + 1] - s.q[i]))));
  return std::max(1.0, std::ceil(std::sqrt(p * (p - 1) / 8.0 * second / static_cast<double>(tol))));
}

/// Uniform steps on a small piece: the interior vertices q(i / n), i = 1 .. n - 1, with
/// n = Wang's count (a proven bound for polynomial pieces), to emit; the caller writes
/// the end points. Same vertices as flatten_uniform.
template <class T, int D, class Emit>
void small_uniform(const SmallPiece<T, D>& s, T tol, Emit&& emit) {
  const double n = small_wang_count(s, tol);
  if (n > max_piece_segments) {
    throw NumericalError("flatten: the uniform method would need more than 2^26 segments for one piece at tolerance " +
                         format_number(tol) + " (relative to the piece's extent)");
  }
  for (double i = 1; i < n; ++i) emit(s.at(static_cast<T>(i / n)));
}

/// Roots of c0 + c1 x + c2 x^2 in the open interval (0, 1), stable form (no
/// cancellation between -c1 and the square root); at most two, written to r.
template <class T>
CASTELJAU_FLATTEN_INLINE int unit_quadratic_roots(T c0, T c1, T c2, T* r) {
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
CASTELJAU_FLATTEN_INLINE SmallChordCheck<T> small_chord_check(T h, const Point<T, 2>& A, const Vector<T, 2>& dA, const Point<T, 2>& E,
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
CASTELJAU_FLATTEN_INLINE T step_factor(T num, T den) {
  if (num <= 2 * den && 2 * num >= den) return (3 * den + 5 * num) / (5 * den + 3 * num);
  const T f = std::sqrt(std::sqrt(num / den));
  if (!(f >= T(0.25))) return f > T(4) ? T(4) : T(0.25);  // NaN (0 / 0) shrinks
  return std::min(f, T(4));
}

/// The approximate inverse of the parabola integral I(x) = integral_0^x (1 + 4 u^2)^(-1/4)
/// du, after [Levien19]: a (1 - B + sqrt(B^2 + a^2 / 4)), B = 0.39 (slope 1 at 0 and the
/// asymptote a^2 / 2 + 0.61 a of the true inverse (a + 0.599)^2 / 2); within 0.2% of the
/// true inverse for all a (checked against scipy's hyp2f1 form of I). Odd in a.
template <class T>
CASTELJAU_FLATTEN_INLINE T parabola_integral_inverse(T a) {
  constexpr T B = T(0.39);
  return a * (1 - B + std::sqrt(B * B + T(0.25) * a * a));
}

/// The parabola integral I(x) as the exact inverse of parabola_integral_inverse (so that
/// the counts and the vertices placed from them agree), to about 1e-5 relative: a start
/// x / (A + ((1 - A)^4 + C x^2 / (1 + x^2) + x^2 / 4)^(1/4)) (A = 0.34136, C = 0.16191,
/// fitted for this code: within 0.45% of the true I, where Levien's one-parameter form is
/// within 3.3%, which put the counts 2% high) and one Newton step on
/// parabola_integral_inverse(a) = x. |x| is capped at 2^250 (x^2 stays finite; the caller's
/// count vanishes as 1 / |x| there). Odd in x.
template <class T>
CASTELJAU_FLATTEN_INLINE T parabola_integral(T x) {
  constexpr T A = T(0.34136), A4 = (1 - A) * (1 - A) * (1 - A) * (1 - A), C = T(0.16191), B = T(0.39), cap = T(0x1p250);
  x = std::clamp(x, -cap, cap);
  const T x2 = x * x;
  T a = x / (A + std::sqrt(std::sqrt(A4 + C * x2 / (1 + x2) + T(0.25) * x2)));
  const T S = std::sqrt(B * B + T(0.25) * a * a);
  a -= (a * (1 - B + S) - x) / (1 - B + S + T(0.25) * a * a / S);
  return a;
}

/// Approximately x^(-1/2) for a double x >= 0 (finite for 0 and denormals, accurate for
/// normal x): a guess from the bits of x (the exponent halved and negated) and two
/// Newton steps y (3 - x y^2) / 2, multiplications only (so loops of it vectorise):
/// relative error below 5e-6 (checked over 1e-290 .. 1e290). Only for estimates.
CASTELJAU_FLATTEN_INLINE double fast_rsqrt(double x) {
  double y = std::bit_cast<double>(std::uint64_t{0x5FE6EB50C7B537A9} - (std::bit_cast<std::uint64_t>(x) >> 1));
  y = y * (1.5 - 0.5 * x * y * y);
  y = y * (1.5 - 0.5 * x * y * y);
  return y;
}

/// Approximately x^(-1/4) for a double x > 1e-280, as fast_rsqrt: the exponent quartered
/// and negated, two Newton steps z (5 - x z^4) / 4; relative error below 2e-5 (checked
/// over 1e-280 .. 1e290 against numpy). Only for estimates.
CASTELJAU_FLATTEN_INLINE double fast_rqrt4(double x) {
  double z = std::bit_cast<double>(std::uint64_t{0x4FEB000000000000} - (std::bit_cast<std::uint64_t>(x) >> 2));
  for (int k = 0; k < 2; ++k) {
    const double z2 = z * z;
    z = z * (1.25 - 0.25 * x * (z2 * z2));
  }
  return z;
}

/// Cells of the sampled density of a cubic in small_optimal (two Gauss-Legendre nodes each).
inline constexpr int optimal_cells = 12;

/// The count function of a piece that is one parabola in small_optimal: the count's
/// fraction u maps to the parameter t = (I^-1(a0 + u da) - x0) sx (sx != 0; else t = u).
template <class T>
struct CountSpan {
  T a0, da, x0, sx;  ///< I(x0), I(x1) - I(x0), x0, 1 / (x1 - x0)

  /// The count's fraction reached at the parameter t (the inverse of the map above): where
  /// a repaired vertex moved, the rest of the count is spread again from it.
  T fraction_at(T t) const { return sx != 0 && da != 0 ? (parabola_integral(x0 + t / sx) - a0) / da : t; }
};

/// small_optimal's plan of a plane polynomial piece of degree 1..3: its power form, its
/// count function and the planned segment count n (see small_optimal).
template <class T>
struct SmallOptimalPlan {
  Point<T, 2> a0;
  Vector<T, 2> a1, a2, a3;
  CountSpan<T> span{};  ///< one parabola (not sampled)
  /// Sampled: cell i = [i, i + 1] / optimal_cells, over which the count grows from f0[i]
  /// to f1[i] (inv[i] = 1 / (f1[i] - f0[i]), 0 for an empty cell) with a density linear
  /// across the cell (slope[i], relative to the mean, in [-2, 2]). Arrays, so that the
  /// placement loads them without a stride.
  T f0[optimal_cells], f1[optimal_cells], inv[optimal_cells], slope[optimal_cells];
  bool sampled = false;
  T F = 0;  ///< the count function's total
  int n = 1;
  /// One parabola standing for the piece within 1e-3 tol (|a3| / 8 <= 1e-3 tol / 4): each
  /// step may be checked on the parabola in closed form (small_optimal): its scale
  /// squared, its x over [0, 1] (xa + t xspan) and the limit of its deviation squared.
  bool closed = false;
  T scale2 = 0, xa = 0, xspan = 0, lim2 = 0;
};

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
CASTELJAU_FLATTEN_INLINE bool parabola_step_within(const SmallOptimalPlan<T>& plan, T tp, T tn) {
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
CASTELJAU_FLATTEN_INLINE bool small_cheap_check(T h, const Point<T, 2>& A, const Vector<T, 2>& dA, const Point<T, 2>& E,
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

/// Vertices placed and checked together by small_optimal_batched (one block).
inline constexpr int optimal_block = 8;

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

#if defined(__GNUC__)
/// Four doubles (and four 64-bit integers) in a GCC/Clang vector register.
typedef double Lanes4 __attribute__((vector_size(32)));
typedef std::int64_t Ints4 __attribute__((vector_size(32)));

/// Each lane's previous lane across two vectors: lane 3 of a, then lanes 0..2 of b (the
/// shuffle in GCC's and Clang's spellings). Always inlined, so GCC's note that a 32-byte
/// vector is passed differently with and without AVX (-Wpsabi) does not apply.
#if !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
CASTELJAU_FLATTEN_INLINE Lanes4 previous_lanes(Lanes4 a, Lanes4 b) {
#if defined(__clang__)
  return __builtin_shufflevector(a, b, 3, 4, 5, 6);
#else
  return __builtin_shuffle(a, b, Ints4{3, 4, 5, 6});
#endif
}
#if !defined(__clang__)
#pragma GCC diagnostic pop
#endif

/// small_optimal_block_plain for double in GCC/Clang vector extensions, four vertices per
/// vector, kept in registers from the placement to the checks (the previous vertex of
/// each lane by a shuffle, not through memory): the cell by counting the cells' ends
/// passed, the square root as D fast_rsqrt(D) (multiplications only: the library sqrt
/// keeps errno and is not vectorised), the check small_cheap_check's expressions lane by
/// lane. The arrays are written at the end for the scan.
template <int B>
unsigned small_optimal_block_lanes(const SmallOptimalPlan<double>& plan, double f_base, double df, double first, double tol2, double* bt,
                                   double* bx, double* by, double* bdx, double* bdy) {
  using Lanes = Lanes4;
  using Ints = Ints4;
  constexpr int NV = B / 4;
  static_assert(B % 4 == 0);
  const double h = 1.0 / optimal_cells;
  const double *f0s = plan.f0, *f1s = plan.f1, *inv = plan.inv, *sl = plan.slope;
  const double a0x = plan.a0[0], a0y = plan.a0[1], a1x = plan.a1[0], a1y = plan.a1[1], a2x = plan.a2[0], a2y = plan.a2[1];
  const double a3x = plan.a3[0], a3y = plan.a3[1];
  Lanes T[NV], X[NV], Y[NV], DX[NV], DY[NV];
  for (int v = 0; v < NV; ++v) {
    const Lanes f = f_base + (Lanes{0, 1, 2, 3} + (first + 4 * v)) * df;
    Ints qi = {0, 0, 0, 0};
    for (int i = 0; i + 1 < optimal_cells; ++i) qi -= f >= f1s[i];
    const Lanes s = {sl[qi[0]], sl[qi[1]], sl[qi[2]], sl[qi[3]]};
    const Lanes f0 = {f0s[qi[0]], f0s[qi[1]], f0s[qi[2]], f0s[qi[3]]};
    const Lanes iv = {inv[qi[0]], inv[qi[1]], inv[qi[2]], inv[qi[3]]};
    Lanes u = (f - f0) * iv;
    u = u > 0 ? u : 0;
    u = u < 1 ? u : 1;
    const Lanes b = 1 - s * 0.5;
    Lanes D = b * b + 2 * s * u;  // >= (1 - |s| / 2)^2 >= 0 for |s| <= 2, 0 <= u <= 1, up to rounding
    D = D > 0 ? D : 0;            // (the bit guess needs the sign bit clear)
    Lanes y = (Lanes)(std::int64_t{0x5FE6EB50C7B537A9} - ((Ints)D >> 1));  // fast_rsqrt's
    y = y * (1.5 - 0.5 * D * y * y);
    y = y * (1.5 - 0.5 * D * y * y);
    Lanes x = 2 * u / (b + D * y);
    x = x <= 1 ? x : 1;  // (and 0 / 0)
    const Lanes t = (__builtin_convertvector(qi, Lanes) + x) * h;
    T[v] = t;
    X[v] = a0x + ((a3x * t + a2x) * t + a1x) * t;
    Y[v] = a0y + ((a3y * t + a2y) * t + a1y) * t;
    DX[v] = (3 * a3x * t + 2 * a2x) * t + a1x;
    DY[v] = (3 * a3y * t + 2 * a2y) * t + a1y;
  }
  unsigned ok = 0;
  for (int v = 0; v < NV; ++v) {
    // the previous vertex of each lane: the last lane of the vector before (or the start)
    const Lanes pT = previous_lanes(v ? T[v - 1] : Lanes{} + bt[0], T[v]);
    const Lanes pX = previous_lanes(v ? X[v - 1] : Lanes{} + bx[0], X[v]);
    const Lanes pY = previous_lanes(v ? Y[v - 1] : Lanes{} + by[0], Y[v]);
    const Lanes pDX = previous_lanes(v ? DX[v - 1] : Lanes{} + bdx[0], DX[v]);
    const Lanes pDY = previous_lanes(v ? DY[v - 1] : Lanes{} + bdy[0], DY[v]);
    const Lanes vx = X[v] - pX, vy = Y[v] - pY;
    const Lanes hh = T[v] - pT, h3 = hh * (1.0 / 3);
    const Lanes L2 = vx * vx + vy * vy;
    const Lanes d1 = (vx * pDY - vy * pDX) * h3, d2 = -(vx * DY[v] - vy * DX[v]) * h3;
    const Lanes p1 = (vx * pDX + vy * pDY) * h3, p2 = L2 - (vx * DX[v] + vy * DY[v]) * h3;
    const Lanes sum = d1 + d2, dif = d2 - d1;
    const Lanes bl = 0.375 * (sum < 0 ? -sum : sum) + 0.1444 * (dif < 0 ? -dif : dif);
    const Lanes b2 = bl * bl, c2 = 0.0703125 * (3 * (d1 * d1 + d2 * d2) + 2 * (d1 * d2));
    const Ints pass = (p1 >= 0) & (p1 <= L2) & (p2 >= 0) & (p2 <= L2) & ((b2 < c2 ? b2 : c2) <= tol2 * L2) & (hh > 0) & (T[v] < 1);
    for (int l = 0; l < 4; ++l) ok |= static_cast<unsigned>(pass[l] & 1) << (4 * v + l + 1);
  }
  for (int v = 0; v < NV; ++v) {
    std::memcpy(bt + 1 + 4 * v, &T[v], sizeof(Lanes));
    std::memcpy(bx + 1 + 4 * v, &X[v], sizeof(Lanes));
    std::memcpy(by + 1 + 4 * v, &Y[v], sizeof(Lanes));
    std::memcpy(bdx + 1 + 4 * v, &DX[v], sizeof(Lanes));
    std::memcpy(bdy + 1 + 4 * v, &DY[v], sizeof(Lanes));
  }
  return ok;
}
#endif

/// small_optimal's walk over a sampled plan, a block of optimal_block vertices at a time
/// (small_optimal_block_plain / _lanes): every vertex of the block placed from its share
/// of the count alone, then the block's points and derivatives, then the cheap check of
/// each of its steps, without branches or carried dependences (so that the vertices
/// overlap in the processor, and in vector lanes). The steps that pass are emitted in
/// order up to the first that fails, which is handled as in the sequential walk
/// (small_optimal): repaired, and when its vertex moved, the rest of the count spread
/// again and the next block placed from there; when it did not move, the block's later
/// checks still hold and the scan goes on. The same guarantee as the sequential walk
/// (every emitted step passed the cheap or the exact check). On return tp, A, dA are the
/// last emitted vertex's.
template <class T, class At, class D1, class Emit>
CASTELJAU_FLATTEN_INLINE void small_optimal_batched(const SmallOptimalPlan<T>& plan, T tol2, const At& point_at, const D1& d1_at, Emit& emit,
                                                    T& tp, Point<T, 2>& A, Vector<T, 2>& dA) {
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
    unsigned ok;
#if defined(__GNUC__)
    if constexpr (std::is_same_v<T, double>) {
      // (half a block when the piece has no more than 4 vertices left: about half the
      // pieces' last blocks)
      ok = n - j <= B / 2 ? small_optimal_block_lanes<B / 2>(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy)
                          : small_optimal_block_lanes<B>(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
    } else
#endif
    {
      ok = small_optimal_block_plain<T, B>(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
    }
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

#if defined(__GNUC__)
/// small_optimal_parabola_batched's block: the vertices first .. first + optimal_block - 1
/// past the count's base (fraction f_base + j df of the count) placed on a piece that is
/// one parabola (plan.closed), their points, and the closed-form check of each step from
/// the one before (the first from tp) with t < 1, lane by lane as parabola_step_within,
/// into bt, bx, by [0 .. optimal_block) and the bits 0 .. optimal_block - 1 of the result.
/// The inverse parabola integral's square root from fast_rsqrt's bit guess and three
/// Newton steps (relative error about 1e-11).
inline unsigned small_optimal_parabola_block(const SmallOptimalPlan<double>& plan, double f_base, double df, double first, double tp,
                                             double* bt, double* bx, double* by) {
  using Lanes = Lanes4;
  using Ints = Ints4;
  constexpr int NV = optimal_block / 4;
  const CountSpan<double> p0 = plan.span;
  const double a0x = plan.a0[0], a0y = plan.a0[1], a1x = plan.a1[0], a1y = plan.a1[1], a2x = plan.a2[0], a2y = plan.a2[1];
  const double a3x = plan.a3[0], a3y = plan.a3[1];
  const double xa = plan.xa, xspan = plan.xspan, scale2 = plan.scale2, lim2 = plan.lim2;
  unsigned ok = 0;
  Lanes prev = Lanes{} + tp;
  for (int v = 0; v < NV; ++v) {
    Lanes u = f_base + (Lanes{0, 1, 2, 3} + (first + 4 * v)) * df;
    u = u < 1 ? u : 1;
    Lanes t = u;
    if (p0.sx != 0) {
      // parabola_integral_inverse(a) = a (1 - B + sqrt(B^2 + a^2 / 4)), B = 0.39
      const Lanes a = p0.a0 + u * p0.da;
      const Lanes S = 0.39 * 0.39 + 0.25 * a * a;  // >= 0.152
      Lanes y = (Lanes)(std::int64_t{0x5FE6EB50C7B537A9} - ((Ints)S >> 1));
      for (int it = 0; it < 3; ++it) y = y * (1.5 - 0.5 * S * y * y);  // relative error about 1e-11
      t = (a * (1 - 0.39 + S * y) - p0.x0) * p0.sx;
      t = t > 0 ? t : 0;
      t = t < 1 ? t : 1;
    }
    const Lanes tq = previous_lanes(prev, t);  // each lane's previous parameter
    const Lanes xn = xa + t * xspan, xp = xa + tq * xspan;
    const Lanes dx = (t - tq) * xspan / 2, sl = 2 * xa + (tq + t) * xspan;
    const Ints pass = (scale2 * (dx * dx) * (dx * dx) <= lim2 * (1 + sl * sl)) & (1 + 2 * xp * sl >= 0) & (1 + 2 * xn * sl >= 0) &
                      (t > tq) & (t < 1);
    for (int l = 0; l < 4; ++l) ok |= static_cast<unsigned>(pass[l] & 1) << (4 * v + l);
    const Lanes X = a0x + ((a3x * t + a2x) * t + a1x) * t, Y = a0y + ((a3y * t + a2y) * t + a1y) * t;
    std::memcpy(bt + 4 * v, &t, sizeof(Lanes));
    std::memcpy(bx + 4 * v, &X, sizeof(Lanes));
    std::memcpy(by + 4 * v, &Y, sizeof(Lanes));
    prev = t;
  }
  return ok;
}

/// small_optimal's walk over a piece that is one parabola (plan.closed), for double with
/// GCC/Clang, as small_optimal_batched: a block of optimal_block vertices placed,
/// evaluated and checked on the parabola in closed form (small_optimal_parabola_block);
/// the steps taken in order up to the first that fails, which is handled as in the
/// sequential walk (the cubic's cheap check, then small_optimal_repair). The closed-form check depends on the parameters alone, so after
/// a failing step whose vertex stays, the block's later checks still hold. On return tp
/// and A are the last emitted vertex's (dA is left to the caller).
template <class At, class D1, class Emit>
CASTELJAU_FLATTEN_INLINE void small_optimal_parabola_batched(const SmallOptimalPlan<double>& plan, double tol2, const At& point_at,
                                                             const D1& d1_at, Emit& emit, double& tp, Point<double, 2>& A) {
  constexpr int B = optimal_block;
  const int n = plan.n;
  const CountSpan<double> p0 = plan.span;
  double f_base = 0, df = 1 / static_cast<double>(n);
  int j_base = 0;
  alignas(32) double bt[B], bx[B], by[B];
  int j = 1;
  while (j < n) {
    const double first = static_cast<double>(j - j_base);
    const unsigned ok = small_optimal_parabola_block(plan, f_base, df, first, tp, bt, bx, by);
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
        emit(Point<double, 2>{bx[k], by[k]});
        ++k;
        continue;
      }
      // Step k failed on the parabola: the cubic's own check, from the vertex before it.
      if (k > 0) tp = bt[k - 1], A = Point<double, 2>{bx[k - 1], by[k - 1]};
      const Vector<double, 2> dA = d1_at(tp);
      double tn = bt[k];
      Point<double, 2> E{bx[k], by[k]};
      Vector<double, 2> dE = d1_at(tn);
      const int jj = j + k;
      if (!(small_cheap_check(tn - tp, A, dA, E, dE, tol2) && tn < 1)) {
        if (!(tn > tp && tn < 1)) {  // a rounding tie (or NaN): the vertex is left out
          j = jj + 1;
          replace = true;
          break;
        }
        const double planned = tn;
        small_optimal_repair(tp, A, dA, tn, E, dE, tol2, false, point_at, d1_at, emit);
        if (tn != planned) {  // the count reached at the moved vertex, the rest spread again
          const double fn = p0.fraction_at(tn);
          df = (1 - fn) / static_cast<double>(n - jj);
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
      tp = bt[cnt - 1], A = Point<double, 2>{bx[cnt - 1], by[cnt - 1]};
    }
  }
}
#endif

/// The near-optimal method on a plane polynomial piece of degree <= 3 (the unit-scale
/// copy), after Levien's analytic flattening [Levien19]: the count n is planned first
/// (small_optimal_plan), then vertex j is placed where the count function reaches j F / n
/// (inverting the parabola integral, or the linear density of its cell), independently of
/// the other vertices, so successive vertices overlap in the processor (for sampled
/// cubics a block of optimal_block at a time, small_optimal_batched). Each step is
/// checked exactly against the tolerance: on the parabola in closed form when the piece
/// is one within 1e-3 tol (parabola_step_within: quadratics, font outlines), else by the
/// cheap bound of small_cheap_check; these accept most, small_optimal_repair handles the
/// rest (about 3% of the steps on W3's random cubics, one in eight of them passing the
/// exact check as placed; 0.07% on its font outlines), so the
/// tolerance is guaranteed whatever the count function's accuracy (cusps, inflections,
/// loops). After a vertex is moved back the rest of the count is spread evenly over the
/// remaining steps (so one short step does not lengthen the next). Interior vertices to
/// emit; the caller writes the ends.
template <class T, class Emit>
void small_optimal(const SmallPiece<T, 2>& s, T tol, Emit&& emit) {
  using V = Vector<T, 2>;
  if (s.m == 2) return;  // a line is its chord
  SmallOptimalPlan<T> plan;
  small_optimal_plan(s, tol, plan);
  if constexpr (requires { emit.reserve(plan.n); }) emit.reserve(plan.n);
  const Point<T, 2> a0 = plan.a0;
  const V a1 = plan.a1, a2 = plan.a2, a3 = plan.a3;
  auto point_at = [&](T t) CASTELJAU_FLATTEN_LAMBDA { return a0 + ((a3 * t + a2) * t + a1) * t; };
  auto d1_at = [&](T t) CASTELJAU_FLATTEN_LAMBDA { return (T(3) * a3 * t + T(2) * a2) * t + a1; };
  const T tol2 = tol * tol;
  T tp = 0;
  Point<T, 2> A = a0;
  V dA = a1;
  // One parabola checked in closed form: in blocks where vector extensions serve.
  auto batched_parabola = [&](T& tp_, Point<T, 2>& A_) CASTELJAU_FLATTEN_LAMBDA {
#if defined(__GNUC__)
    if constexpr (std::is_same_v<T, double>) {
      if (plan.closed) {
        small_optimal_parabola_batched(plan, tol2, point_at, d1_at, emit, tp_, A_);
        return true;
      }
    }
#endif
    (void)tp_, (void)A_;
    return false;
  };
  if (plan.sampled) {
    small_optimal_batched(plan, tol2, point_at, d1_at, emit, tp, A, dA);
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
/// step's repair may add vertices). finish() trims out to the vertices written.
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
  CASTELJAU_FLATTEN_INLINE void operator()(const Point<T, 2>& q) {
    if (p == end) [[unlikely]] reserve(8);
    (*p)[0] = origin[0] + q[0] * up;
    (*p)[1] = origin[1] + q[1] * up;
    ++p;
  }
  /// The vertices (x[i], y[i]), i < count, in order (a block of small_optimal_batched).
  CASTELJAU_FLATTEN_INLINE void block(const T* x, const T* y, int count) {
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

/// 2^k exactly, for double from its bits when 2^k is a normal number (std::ldexp is a
/// library call; with frexp about 3% of the optimal method's time on W3's cubics).
template <class T>
CASTELJAU_FLATTEN_INLINE T pow2(int k) {
  if constexpr (std::is_same_v<T, double>) {
    if (k >= -1022 && k <= 1023) return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
  }
  return std::ldexp(T(1), k);
}

/// The exponent e of x > 0 with x = m 2^e, m in [0.5, 1) (std::frexp's), for a normal
/// double from its bits.
template <class T>
CASTELJAU_FLATTEN_INLINE int frexp_exponent(T x) {
  if constexpr (std::is_same_v<T, double>) {
    if (x >= std::numeric_limits<double>::min()) return static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7FF) - 1022;
  }
  int e = 0;
  (void)std::frexp(x, &e);
  return e;
}

template <class T>
void require_tolerance(T tolerance) {
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(tolerance));
}

/// The curve with control points (P_i - origin) 2^-e (weights unchanged): translation
/// then an exact power-of-two scaling. Scaling a curve by 2^k changes every value here
/// by exactly 2^k (while all stay normal numbers), so the copy does not depend on k.
template <class T, int D>
std::vector<Point<T, D>> normalised_points(const std::vector<Point<T, D>>& P, const Point<T, D>& origin, int e) {
  std::vector<Point<T, D>> Q(P.size());
  for (std::size_t i = 0; i < Q.size(); ++i)
    for (int d = 0; d < D; ++d) {
      const T q = P[i][d] - origin[d];
      // The difference of two finite coordinates may overflow: then halve them first
      // (exact for normal numbers) and scale by one power of two less.
      Q[i][d] = std::isfinite(q) ? std::ldexp(q, -e) : std::ldexp(P[i][d] / 2 - origin[d] / 2, 1 - e);
    }
  return Q;
}
template <class T, int D>
Bezier<T, D> normalised_copy(const Bezier<T, D>& c, const Point<T, D>& origin, int e) {
  return Bezier<T, D>(normalised_points(c.points(), origin, e));
}
template <class T, int D>
RationalBezier<T, D> normalised_copy(const RationalBezier<T, D>& c, const Point<T, D>& origin, int e) {
  return RationalBezier<T, D>(normalised_points(c.points(), origin, e), c.weights());
}

/// The unit-scale copy of a polynomial piece of degree <= 3 as a SmallPiece: (P_i - origin)
/// 2^-e, the same values as normalised_points.
template <class T, int D>
SmallPiece<T, D> small_piece(const std::vector<Point<T, D>>& P, const Point<T, D>& origin, int e) {
  SmallPiece<T, D> s;
  s.m = static_cast<int>(P.size());
  // q 2^-e as normalised_points computes it; by one multiplication (correctly rounded, so
  // equal to ldexp) while 2^-e is representable (e >= -1023).
  const bool multiply = e >= -1023;
  const T down = multiply ? pow2<T>(-e) : T(0);
  for (int i = 0; i < s.m; ++i)
    for (int d = 0; d < D; ++d) {
      const T q = P[static_cast<std::size_t>(i)][d] - origin[d];
      s.q[static_cast<std::size_t>(i)][d] = !std::isfinite(q) ? std::ldexp(P[static_cast<std::size_t>(i)][d] / 2 - origin[d] / 2, 1 - e)
                                            : multiply         ? q * down
                                                               : std::ldexp(q, -e);
    }
  return s;
}

/// flatten() of one piece, appended to out (see the public overloads).
template <class C>
void flatten_piece(const C& c, typename C::Scalar tolerance, FlattenMethod method, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  require_tolerance(tolerance);
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  // Below a few ulps of the coordinates the flatness test cannot succeed reliably, and
  // the subdivision would branch 2^depth ways (up to 2^52) before the depth limit stops
  // a single path: report it at once. 16 eps of max |P| covers the rounding of the
  // flatness distances, of the split control points and of the translation to P_0.
  const auto& P = c.points();
  T m = 0;
  for (const auto& p : P)
    for (int d = 0; d < D; ++d) m = std::max(m, std::abs(p[d]));
  if (tolerance < 16 * std::numeric_limits<T>::epsilon() * m) {
    throw NumericalError("flatten: tolerance " + format_number(tolerance) +
                         " is below the resolution of the curve's coordinates (max |coordinate| " + format_number(m) + ")");
  }
  const Point<T, D> origin = P.front();
  out.push_back(origin);
  if constexpr (requires { normalised_copy(c, origin, 0); }) {
    // Extent of the control polygon about P_0, as a power of two. Differences of finite
    // coordinates may overflow (|P| near the largest double): halve first then.
    T extent = 0;
    for (const auto& p : P)
      for (int d = 0; d < D; ++d) extent = std::max(extent, std::abs(p[d] / 2 - origin[d] / 2));
    if (extent == 0) {  // every control point at P_0: the curve is that point
      out.push_back(P.back());
      return;
    }
    int e = frexp_exponent(extent);
    ++e;  // extent was halved
    // (tolerance 2^-e by one multiplication, correctly rounded as ldexp, when 2^-e is normal)
    const T tol = -e >= -1022 && -e <= 1023 ? tolerance * pow2<T>(-e) : std::ldexp(tolerance, -e);
    if (!(tol < 1)) {  // tolerance >= 2^e > every |P_i - P_0|: the chord is within it
      out.push_back(P.back());
      return;
    }
    if (!(tol >= std::numeric_limits<T>::min())) {
      throw NumericalError("flatten: tolerance " + format_number(tolerance) + " is too small relative to the curve's extent " +
                           format_number(extent * 2) + " (their ratio is below the smallest normal number)");
    }
    if (!(e < std::numeric_limits<T>::max_exponent)) {
      throw NumericalError("flatten: the curve's extent overflows the floating point range");
    }
    // 2^e is a normal or subnormal number here (e < max_exponent, and e > -1074 since
    // extent >= the smallest subnormal), so q 2^e rounds exactly as ldexp(q, e).
    const T up = pow2<T>(e);
    if constexpr (!requires { c.weights(); }) {
      // Lines, quadratics and cubics: the allocation-free kernels (same guarantees; the
      // uniform method gives the same vertices as the general code).
      if (P.size() <= 4 && (method == FlattenMethod::uniform || (D == 2 && method == FlattenMethod::optimal))) {
        const SmallPiece<T, D> s = small_piece(P, origin, e);
        auto emit = [&](const Point<T, D>& q) {
          Point<T, D> r;
          for (int d = 0; d < D; ++d) r[d] = origin[d] + q[d] * up;
          out.push_back(r);
        };
        if (method == FlattenMethod::uniform) {
          small_uniform(s, tol, emit);
        } else if constexpr (D == 2) {
          SmallOptimalWriter<T> writer{out, origin, up};
          small_optimal(s, tol, writer);
          writer.finish();
        }
        out.push_back(P.back());
        return;
      }
    }
    const auto unit = normalised_copy(c, origin, e);
    const std::size_t first = out.size();  // the unit-scale vertices after P_0, scaled back in place
    switch (method) {
      case FlattenMethod::uniform: flatten_uniform(unit, tol, out); break;
      case FlattenMethod::optimal: flatten_optimal(unit, tol, out); break;
      default: flatten_subdivision(unit, tol, out); break;
    }
    for (std::size_t i = first; i + 1 < out.size(); ++i)
      for (int d = 0; d < D; ++d) out[i][d] = origin[d] + out[i][d] * up;
    out.back() = P.back();
  } else {
    flatten_rec(c, tolerance, 0, out);
  }
}
}  // namespace detail

/// flatten() appending to out: the same polyline (its first vertex, the curve's start,
/// included) pushed onto the end of out, so that many curves can share one vector
/// without an allocation per curve. An out-parameter rather than a returned value (our
/// style's default) for that reason. When it throws, out is left as it was.
template <class C>
  requires detail::is_bezier_piece<C>
void flatten(const C& c, typename C::Scalar tolerance, FlattenMethod method, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  const std::size_t size0 = out.size();
  try {
    detail::flatten_piece(c, tolerance, method, out);
  } catch (...) {
    out.resize(size0);
    throw;
  }
}

/// A polyline from the curve's start to its end whose every point of the curve is within
/// `tolerance` (model units) of the polyline, its vertices on the curve (the first and
/// last exactly its end points), by one of three methods:
/// - `subdivision` (the default here; the CLI's default is `optimal`): recursive midpoint
///   subdivision until each part's control points lie within tolerance of its chord
///   segment (the convex hull property makes it a guaranteed bound). About 1.6x the
///   near-optimal count on cubics (WORKLOADS.md, W3). Cost O(p^2) per halving.
/// - `uniform`: n equal parameter steps, n from Wang's bound [Wang84; Filip86] (a proven
///   bound for polynomial pieces; for rational pieces Wang's formula on the Cartesian
///   points, doubled until every step passes the exact check below). Cheapest per vertex.
/// - `optimal`: near the fewest segments with vertices on the curve, each step checked
///   exactly, so the tolerance holds at cusps, inflections and loops. Steps follow the
///   near-optimal density sqrt(|B''_normal|) (a chord over a short arc of curvature k
///   deviates by k s^2 / 8, so segments of deviation tol number the integral of sqrt(k) ds
///   / sqrt(8 tol); Levien's flattening of quadratics integrates it in closed form
///   [Levien19]). Two implementations:
///   - plane polynomial pieces of degree <= 3 (detail::small_optimal, Levien's analytic
///     flattening): the count n = ceil(s F) is planned first (F the density integral: one
///     parabola in closed form when the cubic term is negligible, else the density at two
///     Gauss-Legendre nodes in each of 12 cells; safety s = 1 and 1.02), then each vertex
///     is placed independently where the count function reaches j F / n; each step is
///     checked in O(1): in closed form on the parabola when the piece is one within 1e-3
///     tol (detail::parabola_step_within), else from its end points and end derivatives
///     (the signed distance to the chord's line is a cubic with zero ends whose extremes are
///     roots of a quadratic; the overshoot beyond the chord's ends bounded likewise, see
///     detail::small_chord_check),
///     and a failing step's end is moved back until it passes (the last step gains
///     vertices instead). About 95% of the steps pass as placed on random cubics, 99.9% on
///     font outlines; no allocation.
///   - every other piece (rational, higher degree, 3-D): a greedy walk whose steps start
///     from one unit of the cumulative density (trapezoid rule on 8 p samples) and are
///     corrected by the measured deviation into [0.9, 1] tolerance, each check on the part
///     split off (from the roots of the derivative of the squared distance when the part's
///     control points project inside the chord, else the hull test); one O(p^3) part and
///     one root solve per check.
///   The count can be told before emitting: flatten_count_estimate (for the plane kernel,
///   its planned n: 0.5% below the emitted count on W3's random cubics, equal on 99.9% of
///   font outlines).
///
/// Scale: every method runs on a copy translated to P_0 and scaled by the power of two
/// 2^-e that brings the largest |P_i - P_0| into [0.5, 1), with the tolerance scaled
/// alike; the vertices are scaled back. So huge and tiny coordinates behave as unit ones,
/// no distance over- or underflows, and scaling a curve and its tolerance by 2^k scales
/// the polyline by exactly 2^k (same vertex count) while every value stays a normal
/// number. A tolerance of at least the curve's extent gives the chord.
///
/// Throws InvalidArgument("tolerance", ...) for a tolerance that is not finite or <= 0,
/// NumericalError when the tolerance is below the coordinates' floating point resolution
/// (16 eps of max |P_i|), the scaled tolerance underflows, or a piece would need more
/// than 2^26 segments.
template <class C>
  requires detail::is_bezier_piece<C>
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance,
                                                             FlattenMethod method = FlattenMethod::subdivision) {
  std::vector<Point<typename C::Scalar, C::dimension>> out;
  detail::flatten_piece(c, tolerance, method, out);
  return out;
}

/// The segment count of the optimal method told before emitting, summed over the pieces
/// and computed on the same unit-scale copy as flatten(): for plane polynomial pieces of
/// degree <= 3 the count the kernel plans (detail::small_optimal_plan: it emits exactly
/// that many segments unless a step's check moves its end, then a few more: 0.5% on W3's
/// random cubics); for other pieces ceil of the integral of the near-optimal density
/// (detail::flatten_cumulative; the emitted count was 2.3% above it on W3's random cubics
/// before the plane kernel). At least 1 per piece. Cost: about that of 24 derivative
/// evaluations per cubic, 8 p + 1 per general piece.
template <class C>
  requires detail::is_bezier_piece<C>
double flatten_count_estimate(const C& c, typename C::Scalar tolerance) {
  detail::require_tolerance(tolerance);
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const auto& P = c.points();
  const Point<T, D> origin = P.front();
  T extent = 0;
  for (const auto& p : P)
    for (int d = 0; d < D; ++d) extent = std::max(extent, std::abs(p[d] / 2 - origin[d] / 2));
  if (extent == 0) return 1;
  int e = 0;
  (void)std::frexp(extent, &e);
  ++e;
  const T tol = std::ldexp(tolerance, -e);
  if (!(tol < 1)) return 1;
  if (!(tol >= std::numeric_limits<T>::min())) return std::numeric_limits<double>::infinity();
  if constexpr (D == 2 && !requires { c.weights(); }) {
    if (P.size() <= 4) {  // the plan of the plane kernel (detail::small_optimal_plan)
      if (P.size() == 2) return 1;
      detail::SmallOptimalPlan<T> plan;
      detail::small_optimal_plan(detail::small_piece(P, origin, e), tol, plan);
      return plan.n;
    }
  }
  return detail::optimal_count(detail::normalised_copy(c, origin, e), tol);
}

template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
double flatten_count_estimate(const C& c, typename C::Scalar tolerance) {
  const auto& p = pieces(c);
  double n = 0;
  for (const auto& s : p.segments()) n += std::visit([&](const auto& x) { return flatten_count_estimate(x, tolerance); }, s);
  return n;
}

namespace detail {
/// |a - b| without overflow or underflow in the squares (inf only when a coordinate
/// difference itself overflows).
template <class T, int D>
T scaled_distance(const Point<T, D>& a, const Point<T, D>& b) {
  T m = 0;
  for (int d = 0; d < D; ++d) m = std::max(m, std::abs(a[d] - b[d]));
  if (!(m > 0) || !std::isfinite(m)) return m;
  T s = 0;
  for (int d = 0; d < D; ++d) {
    const T x = (a[d] - b[d]) / m;
    s += x * x;
  }
  return m * std::sqrt(s);
}
}  // namespace detail

/// Any other curve flattened piece by piece (pieces(c)), with the same guarantee: a
/// polyline from c(domain().lo) to c(domain().hi) within `tolerance` of the curve, each
/// piece's end vertex written once where the next piece starts at the same point, and
/// no vertex twice in a row (a curve that is one point gives it twice). A
/// curve whose consecutive pieces are more than `tolerance` apart (a path whose segments
/// do not meet) is refused with InvalidArgument("curve", ...): the polyline would have
/// to bridge the gap farther than the tolerance from the curve. A gap up to the
/// tolerance is bridged (every point of the bridge is within the gap of the curve).
/// This overload appends the polyline to out, as the one-piece one does (out unchanged
/// when it throws); the next returns it.
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
void flatten(const C& c, typename C::Scalar tolerance, FlattenMethod method, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  using T = typename C::Scalar;
  detail::require_tolerance(tolerance);
  const Pieces<T, C::dimension>& p = pieces(c);  // a reference to c itself when c is Pieces
  const std::size_t size0 = out.size();
  try {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t start = out.size();
      std::visit([&](const auto& s) { detail::flatten_piece(s, tolerance, method, out); }, p.segments()[i]);
      if (i == 0) continue;
      const T gap = detail::scaled_distance(out[start - 1], out[start]);
      if (gap > tolerance) {
        throw InvalidArgument("curve", "the curve is not connected at t = " + detail::format_number(p.breaks()[i]) +
                                           ": its pieces are " + detail::format_number(gap) +
                                           " apart there, more than the tolerance " + detail::format_number(tolerance));
      }
      if (gap == 0) out.erase(out.begin() + static_cast<std::ptrdiff_t>(start));
    }
    // A piece that is a single point (a zero-length segment of a path) adds nothing: no
    // vertex is written twice in a row, but a curve that is one point keeps its two.
    const auto first = out.begin() + static_cast<std::ptrdiff_t>(size0);
    out.erase(std::unique(first, out.end()), out.end());
    if (out.size() - size0 == 1) out.push_back(out.back());
  } catch (...) {
    out.resize(size0);
    throw;
  }
}

template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance,
                                                             FlattenMethod method = FlattenMethod::subdivision) {
  std::vector<Point<typename C::Scalar, C::dimension>> out;
  flatten(c, tolerance, method, out);
  return out;
}

}  // namespace casteljau
