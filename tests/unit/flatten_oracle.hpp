// The near-optimal segment count of W3 (docs/performance.md, "Workloads"), written apart from the library's
// flattening: the oracle of the flattening tests in the unit and property executables.
#pragma once

#include <algorithm>
#include <cmath>

#include <casteljau/casteljau.hpp>

namespace casteljau::test {

/// The largest distance of the plane Bézier curve c of degree <= 3 on [t0, t1] from the
/// line through c(t0), c(t1) (W3's measure of a step). The part as a cubic (a quadratic
/// or a line elevated by hand) has control points offset (0, d1, d2, 0) from that line, so
/// the offset is 3 t (1-t)^2 d1 + 3 t^2 (1-t) d2, extreme where its derivative (a
/// quadratic) vanishes. A part whose ends coincide: the farthest control point.
inline double line_deviation(const Bezier<double, 2>& c, double t0, double t1) {
  auto P = c.portion(t0, t1).points();
  if (P.size() == 2) P = {P[0], P[0] + (P[1] - P[0]) / 3, P[0] + 2 * (P[1] - P[0]) / 3, P[1]};
  if (P.size() == 3) P = {P[0], P[0] + 2 * (P[1] - P[0]) / 3, P[2] + 2 * (P[1] - P[2]) / 3, P[2]};
  const auto ch = P[3] - P[0];
  const double L = norm(ch);
  if (L == 0) return std::max(norm(P[1] - P[0]), norm(P[2] - P[0]));
  const double d1 = cross(ch, P[1] - P[0]) / L, d2 = cross(ch, P[2] - P[0]) / L;
  // d'(t) / 3 = (1-t)^2 d1 + 2 t (1-t) (d2 - d1) - t^2 d2 = a t^2 + b t + d1.
  const double a = d1 - 2 * (d2 - d1) - d2, b = 2 * (d2 - d1) - 2 * d1;
  auto off = [&](double t) { return std::abs(3 * t * (1 - t) * (1 - t) * d1 + 3 * t * t * (1 - t) * d2); };
  double m = 0;
  if (a == 0) {
    if (b != 0 && -d1 / b > 0 && -d1 / b < 1) m = off(-d1 / b);
  } else if (const double disc = b * b - 4 * a * d1; disc >= 0) {
    for (const double t : {(-b + std::sqrt(disc)) / (2 * a), (-b - std::sqrt(disc)) / (2 * a)})
      if (t > 0 && t < 1) m = std::max(m, off(t));
  }
  return m;
}

/// W3's near-optimal count: from t0, the largest t1 (bisection to 1e-13) whose arc stays
/// within tol of the line through its ends, until the rest of the curve does.
inline long near_optimal_count(const Bezier<double, 2>& c, double tol) {
  double t = 0;
  long n = 0;
  while (t < 1) {
    ++n;
    if (line_deviation(c, t, 1) <= tol) break;
    double lo = t, hi = 1;
    while (hi - lo > 1e-13) {
      const double mid = (lo + hi) / 2;
      (line_deviation(c, t, mid) <= tol ? lo : hi) = mid;
    }
    t = lo;
  }
  return n;
}

}  // namespace casteljau::test
