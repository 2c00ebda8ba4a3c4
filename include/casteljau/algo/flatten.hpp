// Flattening: a polyline within a distance tolerance of a curve, three ways: uniform steps
// (Wang's bound), recursive subdivision (the flatness test), near-optimal steps.
#pragma once

#include <algorithm>
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

}  // namespace detail

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
/// - `optimal`: near the fewest segments with vertices on the curve. The count is the
///   integral of sqrt(|B''_normal|) dt / sqrt(8 tolerance) (the asymptotically optimal
///   density, sqrt(curvature) per arc length, which Levien's flattening of quadratics
///   evaluates in closed form [Levien19]; here by the trapezoid rule on 8 p samples, so
///   for every degree and rational pieces alike): detail::optimal_count tells it before
///   emitting. Vertices divide the integral evenly; each step is checked exactly (the
///   largest distance of the part from its chord, from the roots of the derivative of the
///   squared distance, when the control points project inside the chord; else the hull
///   test) and shortened until it passes, so the tolerance holds at cusps and inflections
///   where the density is only an estimate. Cost: one O(p^3) part and one root solve per
///   vertex.
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
  detail::require_tolerance(tolerance);
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
    throw NumericalError("flatten: tolerance " + detail::format_number(tolerance) +
                         " is below the resolution of the curve's coordinates (max |coordinate| " + detail::format_number(m) + ")");
  }
  const Point<T, D> origin = P.front();
  std::vector<Point<T, D>> out{origin};
  if constexpr (requires { detail::normalised_copy(c, origin, 0); }) {
    // Extent of the control polygon about P_0, as a power of two. Differences of finite
    // coordinates may overflow (|P| near the largest double): halve first then.
    T extent = 0;
    for (const auto& p : P)
      for (int d = 0; d < D; ++d) extent = std::max(extent, std::abs(p[d] / 2 - origin[d] / 2));
    if (extent == 0) {  // every control point at P_0: the curve is that point
      out.push_back(P.back());
      return out;
    }
    int e = 0;
    (void)std::frexp(extent, &e);
    ++e;  // extent was halved
    const T tol = std::ldexp(tolerance, -e);
    if (!(tol < 1)) {  // tolerance >= 2^e > every |P_i - P_0|: the chord is within it
      out.push_back(P.back());
      return out;
    }
    if (!(tol >= std::numeric_limits<T>::min())) {
      throw NumericalError("flatten: tolerance " + detail::format_number(tolerance) + " is too small relative to the curve's extent " +
                           detail::format_number(extent * 2) + " (their ratio is below the smallest normal number)");
    }
    if (!(e < std::numeric_limits<T>::max_exponent)) {
      throw NumericalError("flatten: the curve's extent overflows the floating point range");
    }
    const auto unit = detail::normalised_copy(c, origin, e);
    std::vector<Point<T, D>> local{unit.points().front()};
    switch (method) {
      case FlattenMethod::uniform: detail::flatten_uniform(unit, tol, local); break;
      case FlattenMethod::optimal: detail::flatten_optimal(unit, tol, local); break;
      default: detail::flatten_subdivision(unit, tol, local); break;
    }
    for (std::size_t i = 1; i + 1 < local.size(); ++i) {
      Point<T, D> q;
      for (int d = 0; d < D; ++d) q[d] = origin[d] + std::ldexp(local[i][d], e);
      out.push_back(q);
    }
    out.push_back(P.back());
  } else {
    detail::flatten_rec(c, tolerance, 0, out);
  }
  return out;
}

/// The segment count of the optimal method told before emitting: ceil of the integral of
/// the near-optimal density (detail::flatten_cumulative) over each piece, summed over the
/// pieces; computed on the same unit-scale copy as flatten(). An estimate: the emitted
/// count, whose every step is checked, was within 1.1% of it on W3's random cubics (see
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
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_bezier_piece<C>)
std::vector<Point<typename C::Scalar, C::dimension>> flatten(const C& c, typename C::Scalar tolerance,
                                                             FlattenMethod method = FlattenMethod::subdivision) {
  using T = typename C::Scalar;
  detail::require_tolerance(tolerance);
  const Pieces<T, C::dimension>& p = pieces(c);  // a reference to c itself when c is Pieces
  std::vector<Point<T, C::dimension>> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto part = std::visit([&](const auto& s) { return flatten(s, tolerance, method); }, p.segments()[i]);
    std::size_t skip = 0;
    if (i > 0) {
      const T gap = detail::scaled_distance(out.back(), part.front());
      if (gap > tolerance) {
        throw InvalidArgument("curve", "the curve is not connected at t = " + detail::format_number(p.breaks()[i]) +
                                           ": its pieces are " + detail::format_number(gap) +
                                           " apart there, more than the tolerance " + detail::format_number(tolerance));
      }
      if (gap == 0) skip = 1;
    }
    out.insert(out.end(), part.begin() + static_cast<std::ptrdiff_t>(skip), part.end());
  }
  return out;
}

}  // namespace casteljau
