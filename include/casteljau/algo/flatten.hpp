// Flattening: a polyline within a distance tolerance of a curve, three ways: uniform steps
// (Wang's bound), recursive subdivision (the flatness test), near-optimal steps.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
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

/// The near-optimal method on a plane polynomial piece of degree <= 3: the greedy walk of
/// flatten_optimal (each step as long as the tolerance allows: its deviation within
/// [0.9, 1] tolerance, or the rest of the piece; the longest passing step after 8
/// corrections, else steps shortened by 0.7 until one passes), each step checked by
/// small_chord_check (O(1), no allocation). Steps are predicted without the density
/// integral: the previous step times step_factor of (target / measured deviation) times
/// the curvature trend (|B' x B''|^2 / |B'|^2 at the next step's middle against the last
/// one's: the deviation of a short chord is h^2 / 8 |B''| normal to B'); the first from
/// that density near t = 0. Interior vertices to emit, the caller writes the ends.
template <class T, class Emit>
void small_optimal(const SmallPiece<T, 2>& s, T tol, Emit&& emit) {
  using V = Vector<T, 2>;
  // Power form B(t) = a0 + a1 t + a2 t^2 + a3 t^3 (a3 = 0 below degree 3).
  V a1{}, a2{}, a3{};
  const Point<T, 2> a0 = s.q[0];
  if (s.m == 2) {
    a1 = s.q[1] - s.q[0];
  } else if (s.m == 3) {
    a1 = T(2) * (s.q[1] - s.q[0]);
    a2 = (s.q[2] - s.q[1]) - (s.q[1] - s.q[0]);
  } else {
    a1 = T(3) * (s.q[1] - s.q[0]);
    a2 = T(3) * ((s.q[2] - s.q[1]) - (s.q[1] - s.q[0]));
    a3 = (s.q[3] - s.q[0]) - T(3) * (s.q[2] - s.q[1]);
  }
  auto point_at = [&](T t) CASTELJAU_FLATTEN_LAMBDA { return a0 + ((a3 * t + a2) * t + a1) * t; };
  auto d1_at = [&](T t) CASTELJAU_FLATTEN_LAMBDA { return (T(3) * a3 * t + T(2) * a2) * t + a1; };
  // |B' x B''|^2 and |B'|^2 at t (their ratio is the squared normal part of B'').
  auto bend = [&](T t, T& c2, T& n2) CASTELJAU_FLATTEN_LAMBDA {
    const V d1 = d1_at(t), d2 = T(6) * a3 * t + T(2) * a2;
    const T c = cross(d1, d2);
    c2 = c * c;
    n2 = dot(d1, d1);
  };
  // Target deviation 0.97 tol (a step predicted to land exactly at tol would fail half
  // the time); accepted band [0.9, 1] tol.
  // (Both as fractions of the squared limit.)
  const T tol2 = tol * tol, target = T(0.97 * 0.97), band = T(0.81);
  T c_prev = 0, n_prev = 0;
  // First step: h^2 / 8 |B''_normal| = 0.97 tol at a point a little inside the piece.
  T h = 1;
  {
    T c2, n2;
    bend(std::sqrt(tol) / 2, c2, n2);
    const T k = c2 > 0 ? std::sqrt(c2 / n2) : T(0);
    const T g = std::sqrt(8 * T(0.97) * tol / k);
    if (g > T(1e-6) && g < 1) h = g;
    bend(std::min(T(1), h / 2), c_prev, n_prev);
  }
  T t = 0;
  Point<T, 2> A = a0;
  V dA = a1;
  std::size_t steps = 0;
  while (t < 1) {
    T t1 = t + h;
    if (!(t1 < 1)) t1 = 1;
    T best = 0;
    Point<T, 2> bE{};
    V bdE{};
    SmallChordCheck<T> bc;
    for (int it = 0; it < 8; ++it) {
      const T step = t1 - t;
      const Point<T, 2> E = t1 == 1 ? s.q[static_cast<std::size_t>(s.m - 1)] : point_at(t1);
      const V dE = d1_at(t1);
      const SmallChordCheck<T> k = small_chord_check(step, A, dA, E, dE, tol2);
      if (k.ok) {
        if (t1 > best) best = t1, bE = E, bdE = dE, bc = k;
        if (t1 == 1 || k.dev2 >= band * k.lim) break;
      }
      const T f = k.lim > 0 ? step_factor(target * k.lim, k.dev2) : T(0.5);
      const T next = std::min(T(1), t + step * f);
      if (next <= best) break;
      t1 = next;
    }
    while (!(best > t)) {
      t1 = t + (t1 - t) * T(0.7);
      if (!(t1 - t > T(1e-15))) {
        throw NumericalError("flatten: the optimal method's step fell below 1e-15 of the parameter at t = " + format_number(t) +
                             ": the tolerance is below the resolution of the curve");
      }
      const Point<T, 2> E = point_at(t1);
      const V dE = d1_at(t1);
      const SmallChordCheck<T> k = small_chord_check(t1 - t, A, dA, E, dE, tol2);
      if (k.ok) best = t1, bE = E, bdE = dE, bc = k;
    }
    if (++steps > max_piece_segments) throw NumericalError("flatten: more than 2^26 segments for one piece");
    const T step = best - t;
    if (best < 1) {
      emit(bE);
      // Next step: this one scaled to the target deviation and by the curvature trend
      // (the deviation is about h^2 / 8 sqrt(c2 / n2) at the step's middle).
      T c_next, n_next;
      bend(std::min(T(1), best + step / 2), c_next, n_next);
      // A zero curvature at either middle (a line, an inflection) leaves the trend out.
      T num = target * bc.lim, den = bc.dev2;
      if (c_prev > 0 && c_next > 0 && n_prev > 0 && n_next > 0) num *= c_prev * n_next, den *= n_prev * c_next;
      h = step * step_factor(num, den);
      c_prev = c_next;
      n_prev = n_next;
    }
    t = best;
    A = bE;
    dA = bdE;
  }
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
    int e = 0;
    (void)std::frexp(extent, &e);
    ++e;  // extent was halved
    const T tol = std::ldexp(tolerance, -e);
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
    const T up = std::ldexp(T(1), e);
    if constexpr (!requires { c.weights(); }) {
      // Lines, quadratics and cubics: the allocation-free kernels (same guarantees; the
      // uniform method gives the same vertices as the general code).
      if (P.size() <= 4 && (method == FlattenMethod::uniform || (D == 2 && method == FlattenMethod::optimal))) {
        SmallPiece<T, D> s;
        s.m = static_cast<int>(P.size());
        // q 2^-e as normalised_points computes it; by one multiplication (correctly
        // rounded, so equal to ldexp) while 2^-e is representable (e >= -1023).
        const bool multiply = e >= -1023;
        const T down = multiply ? std::ldexp(T(1), -e) : T(0);
        for (int i = 0; i < s.m; ++i)
          for (int d = 0; d < D; ++d) {
            const T q = P[static_cast<std::size_t>(i)][d] - origin[d];
            s.q[static_cast<std::size_t>(i)][d] = !std::isfinite(q) ? std::ldexp(P[static_cast<std::size_t>(i)][d] / 2 - origin[d] / 2, 1 - e)
                                                  : multiply         ? q * down
                                                                     : std::ldexp(q, -e);
          }
        auto emit = [&](const Point<T, D>& q) {
          Point<T, D> r;
          for (int d = 0; d < D; ++d) r[d] = origin[d] + q[d] * up;
          out.push_back(r);
        };
        if (method == FlattenMethod::uniform) {
          small_uniform(s, tol, emit);
        } else if constexpr (D == 2) {
          small_optimal(s, tol, emit);
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
/// - `optimal`: near the fewest segments with vertices on the curve: a greedy walk whose
///   every step is as long as the tolerance allows (its largest distance from its chord
///   segment within [0.9, 1] tolerance, or the rest of the piece), each step checked
///   exactly, so the tolerance holds at cusps, inflections and loops. Step lengths are
///   predicted from the near-optimal density sqrt(|B''_normal|) (a chord over a short arc
///   of curvature k deviates by k s^2 / 8; Levien's flattening of quadratics integrates it
///   in closed form [Levien19]) and corrected by the measured deviation (a short chord's
///   deviation grows as the square of its step). Two implementations:
///   - plane polynomial pieces of degree <= 3 (detail::small_optimal): the check of a step
///     is O(1) from its end points and end derivatives (the sub-arc's Bézier points; the
///     signed distance to the chord's line is a cubic with zero ends whose extremes are
///     roots of a quadratic; the overshoot beyond the chord's ends bounded likewise, see
///     detail::small_chord_check), and the next step is predicted from the last one's
///     deviation and the curvature trend. About 1.4 checks per vertex on random cubics, 1.0
///     on font outlines; no allocation.
///   - every other piece (rational, higher degree, 3-D): the steps start from one unit of
///     the cumulative density (trapezoid rule on 8 p samples), each check on the part split
///     off (from the roots of the derivative of the squared distance when the part's control
///     points project inside the chord, else the hull test); one O(p^3) part and one root
///     solve per check.
///   The count can be told before emitting: flatten_count_estimate, the integral of the
///   density / sqrt(8 tolerance) (2.3% below the emitted count on 1000 of W3's cubics).
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

/// The segment count of the optimal method told before emitting: ceil of the integral of
/// the near-optimal density (detail::flatten_cumulative) over each piece, summed over the
/// pieces; computed on the same unit-scale copy as flatten(). An estimate: the emitted
/// count, whose every step is checked, was 2.3% above it on 1000 of W3's random cubics (see
/// docs/accuracy.md). At least 1 per piece. Cost: 8 p + 1 derivative pairs per piece.
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
/// piece's end vertex written once where the next piece starts at the same point. A
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
