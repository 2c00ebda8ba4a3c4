// Flattening's tests of a chord against a curve piece (Bézier or rational Bézier): the
// convex-hull flatness test, a part of a piece, the exact chord deviation; and the piece's
// unit-scale copy that every method runs on.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "casteljau/algo/flatten/common.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/core/segment.hpp"
#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/bezier.hpp"
#include "casteljau/curves/rational_bezier.hpp"

namespace casteljau::detail {

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

/// The curve with control points (P_i - origin) 2^-e (weights unchanged), in the unit
/// frame (core/unit_frame.hpp): translation then an exact power-of-two scaling. Scaling a
/// curve by 2^k changes every value here by exactly 2^k (while all stay normal numbers),
/// so the copy does not depend on k.
template <class T, int D>
std::vector<Point<T, D>> normalised_points(const std::vector<Point<T, D>>& P, const Point<T, D>& origin, int e) {
  std::vector<Point<T, D>> Q(P.size());
  for (std::size_t i = 0; i < Q.size(); ++i) Q[i] = to_unit(P[i], origin, e);
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

}  // namespace casteljau::detail
