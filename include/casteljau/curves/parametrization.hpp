// Parameters for interpolation from the data points alone: uniform, chord length and
// centripetal (shared by the interpolating curve types and fitting).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "casteljau/core/point.hpp"

namespace casteljau {

/// How parameters grow from one data point to the next: by 1 (uniform), by |P_(i+1) - P_i|
/// (chord) or by its square root (centripetal) [Farin02, 9.4; Lee89].
enum class Parametrization { uniform, chord, centripetal };

/// The parameters u_0 = 0, u_(i+1) = u_i + step(P_i, P_(i+1)) of the points P for the
/// given rule (see Parametrization). Affine maps of the points leave uniform parameters
/// unchanged; chord and centripetal ones commute only with similarities (they scale with
/// the distances). Throws InvalidArgument naming "points" (fewer than 2 points, or
/// lengths summing beyond the largest double) or "points[i]" (for chord and centripetal:
/// a point equal to the one before it, or so close that the parameter does not grow).
/// Distances by norm() (no overflow for huge coordinates). Cost O(n).
template <class T, int D>
std::vector<T> parameters_from_points(const std::vector<Point<T, D>>& P, Parametrization rule) {
  if (P.size() < 2) throw InvalidArgument("points", "needs at least 2 points, got " + std::to_string(P.size()));
  std::vector<T> u(P.size());
  u[0] = 0;
  const char* name = rule == Parametrization::chord ? "chord" : "centripetal";
  for (std::size_t i = 1; i < P.size(); ++i) {
    T step = 1;
    if (rule != Parametrization::uniform) {
      const T d = distance(P[i], P[i - 1]);
      step = rule == Parametrization::chord ? d : std::sqrt(d);
      if (!(d > 0)) {
        throw InvalidArgument("points[" + std::to_string(i) + "]", "equals points[" + std::to_string(i - 1) +
                                                                        "]: " + name + " parameters need distinct consecutive points");
      }
    }
    u[i] = u[i - 1] + step;
    if (!std::isfinite(u[i])) throw InvalidArgument("points", std::string("the ") + name + " lengths sum beyond the largest double");
    if (!(u[i] > u[i - 1])) {
      throw InvalidArgument("points[" + std::to_string(i) + "]", "is too close to points[" + std::to_string(i - 1) + "] for " +
                                                                      name + " parameters: the parameter does not grow");
    }
  }
  return u;
}

}  // namespace casteljau
