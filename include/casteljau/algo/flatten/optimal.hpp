// The near-optimal flattening of any piece (rational, higher degree, any dimension): a
// greedy walk along the near-optimal density, every step checked exactly.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "casteljau/algo/flatten/chord.hpp"

namespace casteljau::detail {

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
    // A sample where a derivative is not representable (weights 1, 1e200, 1: the second
    // derivative at an end is about 1e400) adds nothing: the density only guesses the
    // steps, which the exact checks correct.
    density = [&](T t) {
      try {
        return flatten_density(c.derivative_at(t, 1), c.derivative_at(t, 2));
      } catch (const InvalidArgument&) {
        return T(0);
      }
    };
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

}  // namespace casteljau::detail
