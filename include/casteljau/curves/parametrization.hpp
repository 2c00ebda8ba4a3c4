// Parameters for interpolation from the data points alone: uniform, chord length and
// centripetal (shared by the interpolating curve types and fitting).
#pragma once

#include <cmath>
#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/point.hpp"

namespace casteljau {

/// How parameters grow from one data point to the next: by 1 (uniform), by |P_(i+1) - P_i|
/// (chord) or by its square root (centripetal) [Farin02, 9.4; Lee89].
enum class Parametrization { uniform, chord, centripetal };

/// The rules' names, in the enum's order (the JSON field `parametrization`).
inline constexpr std::string_view parametrization_names[] = {"uniform", "chord", "centripetal"};

/// The rule with the given name, or nothing.
inline std::optional<Parametrization> parametrization_named(std::string_view name) {
  const auto* at = std::find(std::begin(parametrization_names), std::end(parametrization_names), name);
  if (at == std::end(parametrization_names)) return std::nullopt;
  return static_cast<Parametrization>(at - std::begin(parametrization_names));
}

namespace detail {

/// One step of the rule from a to b: 1, |b - a| or its square root.
template <class T, int D>
T parameter_step(const Point<T, D>& b, const Point<T, D>& a, Parametrization rule) {
  if (rule == Parametrization::uniform) return T(1);
  const T d = distance(b, a);
  return rule == Parametrization::chord ? d : std::sqrt(d);
}

}  // namespace detail

/// The parameters u_0 = 0, u_(k+1) = u_k + step(P_k, P_(k+1)) of the points P for the
/// given rule (see Parametrization), unchecked: a zero step (equal points under chord or
/// centripetal) gives equal parameters, and sums beyond the largest double give inf. For
/// a closed polygon one more step, the closing one P_last -> P_0 (n + 1 parameters for n
/// points). Distances by distance() (no overflow for huge coordinates). Empty for no
/// points. Cost O(n).
template <class T, int D>
std::vector<T> parameter_sums(const std::vector<Point<T, D>>& P, Parametrization rule, bool closed = false) {
  if (P.empty()) return {};
  const std::size_t n = P.size(), steps = closed ? n : n - 1;
  std::vector<T> u(steps + 1);
  u[0] = 0;
  for (std::size_t k = 1; k <= steps; ++k) u[k] = u[k - 1] + detail::parameter_step(P[k % n], P[k - 1], rule);
  return u;
}

/// The parameters of parameter_sums (open, or closed with the closing step), checked.
/// Affine maps of the points leave uniform parameters unchanged; chord and centripetal
/// ones commute only with similarities (they scale with the distances). Throws
/// InvalidArgument naming "points" (fewer than 2 points, or lengths summing beyond the
/// largest double) or "points[i]" (for chord and centripetal: a point equal to the one
/// before it, points[0] for the closing step, or so close that the parameter does not
/// grow). Cost O(n).
template <class T, int D>
std::vector<T> parameters_from_points(const std::vector<Point<T, D>>& P, Parametrization rule, bool closed = false) {
  if (P.size() < 2) throw InvalidArgument("points", "needs at least 2 points, got " + std::to_string(P.size()));
  const std::size_t n = P.size(), steps = closed ? n : n - 1;
  std::vector<T> u(steps + 1);
  u[0] = 0;
  const char* name = rule == Parametrization::chord ? "chord" : "centripetal";
  for (std::size_t k = 1; k <= steps; ++k) {
    const std::size_t i = k % n;
    const auto at = [&] { return "points[" + std::to_string(i) + "]"; };
    const auto before = [&] { return "points[" + std::to_string(k - 1) + "]"; };
    const T step = detail::parameter_step(P[i], P[k - 1], rule);  // > 0 exactly when the distance is
    if (rule != Parametrization::uniform && !(step > 0)) {
      throw InvalidArgument(at(), "equals " + before() + ": " + name + " parameters need distinct consecutive points");
    }
    u[k] = u[k - 1] + step;
    if (!std::isfinite(u[k])) throw InvalidArgument("points", std::string("the ") + name + " lengths sum beyond the largest double");
    if (!(u[k] > u[k - 1])) {
      throw InvalidArgument(at(), "is too close to " + before() + " for " + name + " parameters: the parameter does not grow");
    }
  }
  return u;
}

/// Parameters divided by the last one, so that they run from 0 to 1 (the last set to 1
/// exactly). The last must be positive and finite.
template <class T>
void normalize_parameters(std::vector<T>& u) {
  const T total = u.back();
  for (T& x : u) x /= total;
  u.back() = 1;
}

/// parameters_from_points normalised to run from 0 to 1 (normalize_parameters); the same
/// errors.
template <class T, int D>
std::vector<T> unit_parameters(const std::vector<Point<T, D>>& P, Parametrization rule, bool closed = false) {
  std::vector<T> u = parameters_from_points(P, rule, closed);
  normalize_parameters(u);
  return u;
}

}  // namespace casteljau
