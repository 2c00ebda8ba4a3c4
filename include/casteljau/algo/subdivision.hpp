// Subdivision curves on control polygons of any dimension: Chaikin's corner cutting, the
// Lane-Riesenfeld schemes of any degree (whose limits are uniform B-splines) and the
// interpolating 4-point scheme of Dyn, Levin and Gregory, on open and closed polygons.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/curves/bspline.hpp"

namespace casteljau {

/// The most points a subdivision result may have: each step doubles the count, so a
/// request for many iterations is refused (InvalidArgument "iterations") instead of
/// exhausting memory.
inline constexpr std::size_t max_subdivision_points = 1'000'000;

/// The largest tension for which the 4-point scheme converges to a C^1 curve:
/// (sqrt 5 - 1) / 8 [DLG87].
inline constexpr double four_point_max_tension = 0.1545084971874737;

namespace detail {

template <class T, int D>
void check_polygon(const std::vector<Point<T, D>>& P, std::size_t at_least, bool closed, const std::string& why) {
  if (P.size() < at_least) {
    throw InvalidArgument("points", std::string(closed ? "a closed" : "an open") + " polygon needs at least " +
                                        std::to_string(at_least) + " points" + why + ", got " + std::to_string(P.size()));
  }
  require_finite_points(P, "points");
}

inline void check_iterations(std::size_t points, int k) {
  if (k < 0) throw InvalidArgument("iterations", "iteration count must be >= 0, got " + std::to_string(k));
  double count = static_cast<double>(points);
  for (int j = 0; j < k; ++j) {
    count *= 2;
    if (count > static_cast<double>(max_subdivision_points)) {
      throw InvalidArgument("iterations", std::to_string(k) + " iterations would give more than " +
                                              std::to_string(max_subdivision_points) + " points");
    }
  }
}

}  // namespace detail

/// The limit of the Lane-Riesenfeld scheme of degree p on the polygon P: for an open
/// polygon the clamped uniform B-spline (KnotVector::clamped_uniform on [0, n - p]: knots
/// 0 (p + 1 times), 1, .., n - p - 1, n - p (p + 1 times)); for a closed one the periodic
/// uniform B-spline with points P_0..P_{n-1}, P_0..P_{p-1} and knots 0, 1, .., n + 2p
/// (KnotVector::periodic_uniform on [p, n + p], closed with C^(p-1)).
/// Chaikin is p = 2. Errors as lane_riesenfeld.
template <class T, int D>
BSpline<T, D> lane_riesenfeld_limit(const std::vector<Point<T, D>>& P, int p, bool closed) {
  if (p < 1) throw InvalidArgument("degree", "Lane-Riesenfeld needs degree >= 1, got " + std::to_string(p));
  detail::check_polygon(P, closed ? 3 : static_cast<std::size_t>(p) + 1, closed, closed ? "" : " (degree + 1)");
  const std::size_t n = P.size(), pp = static_cast<std::size_t>(p);
  if (!closed) return BSpline<T, D>(KnotVector<T>::clamped_uniform(n, p, T(0), static_cast<T>(n - pp)), P);
  std::vector<Point<T, D>> Q(P);
  for (std::size_t i = 0; i < pp; ++i) Q.push_back(P[i % n]);
  return BSpline<T, D>(KnotVector<T>::periodic_uniform(n, p, static_cast<T>(pp), static_cast<T>(n + pp)), std::move(Q));
}

/// k steps of the Lane-Riesenfeld scheme of degree p >= 1 [LR80]. Closed: each step
/// doubles every point and averages neighbours p times (cyclically); p = 1 inserts edge
/// midpoints, p = 2 is Chaikin's corner cutting [Chaikin74]: 3/4 P_i + 1/4 P_{i+1},
/// 1/4 P_i + 3/4 P_{i+1}. Open: each step is knot insertion at every span midpoint of the
/// clamped uniform B-spline of lane_riesenfeld_limit ([PT97, A5.4]): the same masks away
/// from the ends (more than p spans in), the end points kept. After k steps the points are
/// the control points of the limit B-spline with its knot spacing halved k times, so they
/// converge to it: the distance shrinks by about 4 per step (O(h^2)). Errors: "degree"
/// < 1, "points" (fewer than 3 closed, p + 1 open; non-finite), "iterations" (< 0, or more
/// than max_subdivision_points). Cost O(2^k n p).
template <class T, int D>
std::vector<Point<T, D>> lane_riesenfeld(const std::vector<Point<T, D>>& P, int p, int k, bool closed) {
  using V = Point<T, D>;
  const BSpline<T, D> limit = lane_riesenfeld_limit(P, p, closed);  // validates
  detail::check_iterations(P.size(), k);
  if (!closed) {
    KnotForm<T, V> f = limit.form();
    for (int step = 0; step < k; ++step) {
      std::vector<T> X;
      for (std::size_t i = 0; i + 1 < f.U.size(); ++i) {
        if (f.U[i] < f.U[i + 1]) X.push_back(f.U[i] / 2 + f.U[i + 1] / 2);
      }
      f = refine_knots<T, V>(f, X);
    }
    return f.P;
  }
  std::vector<V> Q(P);
  for (int step = 0; step < k; ++step) {
    std::vector<V> R(2 * Q.size());
    for (std::size_t i = 0; i < Q.size(); ++i) R[2 * i] = R[2 * i + 1] = Q[i];
    for (int a = 0; a < p; ++a) {
      const V first = R[0];
      for (std::size_t i = 0; i + 1 < R.size(); ++i) R[i] = lerp(R[i], R[i + 1], T(0.5));
      R.back() = lerp(R.back(), first, T(0.5));
    }
    Q = std::move(R);
  }
  return Q;
}

/// k steps of Chaikin's corner cutting: lane_riesenfeld with p = 2.
template <class T, int D>
std::vector<Point<T, D>> chaikin(const std::vector<Point<T, D>>& P, int k, bool closed) {
  return lane_riesenfeld(P, 2, k, closed);
}

/// k steps of the interpolating 4-point scheme [DLG87]: every point is kept and each edge
/// gets Q = (1/2 + w)(P_i + P_{i+1}) - w (P_{i-1} + P_{i+2}), tension w in
/// [0, four_point_max_tension) (default 1/16: cubic precision). Closed polygons wrap;
/// open ones use the reflected points P_{-1} = 2 P_0 - P_1 and P_n = 2 P_{n-1} - P_{n-2}
/// at the two end edges, so the end points are kept. The limit is C^1 for 0 < w < (sqrt 5
/// - 1) / 8 and is not a B-spline. Errors: "tension", "points" (fewer than 3 closed, 2
/// open), "iterations". Cost O(2^k n).
template <class T, int D>
std::vector<Point<T, D>> four_point(const std::vector<Point<T, D>>& P, int k, bool closed, T w = T(1) / 16) {
  using V = Point<T, D>;
  require_finite(w, "tension");
  if (!(w >= 0 && w < T(four_point_max_tension))) {
    throw InvalidArgument("tension", "the 4-point scheme converges for tension in [0, (sqrt 5 - 1) / 8) = [0, 0.1545...), got " +
                                         detail::format_number(w));
  }
  detail::check_polygon(P, closed ? 3 : 2, closed, "");
  detail::check_iterations(P.size(), k);
  std::vector<V> Q(P);
  for (int step = 0; step < k; ++step) {
    const std::size_t n = Q.size();
    const auto at = [&](std::ptrdiff_t i) -> V {
      if (closed) return Q[static_cast<std::size_t>((i % static_cast<std::ptrdiff_t>(n) + static_cast<std::ptrdiff_t>(n)) % static_cast<std::ptrdiff_t>(n))];
      if (i < 0) return Q[0] + (Q[0] - Q[1]);
      if (i >= static_cast<std::ptrdiff_t>(n)) return Q[n - 1] + (Q[n - 1] - Q[n - 2]);
      return Q[static_cast<std::size_t>(i)];
    };
    const std::size_t edges = closed ? n : n - 1;
    std::vector<V> R;
    R.reserve(n + edges);
    for (std::size_t i = 0; i < edges; ++i) {
      const auto j = static_cast<std::ptrdiff_t>(i);
      const V a = at(j), b = at(j + 1), before = at(j - 1), after = at(j + 2);
      // Midpoint plus w times the difference of the second differences: the mask in a
      // form that is exact for a straight polygon.
      const V mid = lerp(a, b, T(0.5));
      R.push_back(Q[i]);
      R.push_back(mid + w * ((a - before) + (b - after)));
    }
    if (!closed) R.push_back(Q[n - 1]);
    Q = std::move(R);
  }
  return Q;
}

}  // namespace casteljau
