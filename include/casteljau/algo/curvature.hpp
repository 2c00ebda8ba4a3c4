// Curvature of differentiable curves.
#pragma once

#include <cmath>
#include <optional>

#include "casteljau/curves/concepts.hpp"

namespace casteljau {

/// Curvature at t from the first two derivatives [Farin02, 10.2]: for plane curves the
/// signed curvature (x'y'' - y'x'') / |c'|^3, positive where the curve turns left; in
/// higher dimensions the non-negative sqrt(|c'|^2 |c''|^2 - (c'.c'')^2) / |c'|^3.
/// std::nullopt where the speed |c'| is zero (a cusp or a degenerate segment), where
/// curvature is undefined.
template <DifferentiableCurve C>
  requires(C::dimension >= 2)
std::optional<typename C::Scalar> curvature(const C& c, typename C::Scalar t) {
  using T = typename C::Scalar;
  const auto d1 = c.derivative_at(t, 1), d2 = c.derivative_at(t, 2);
  const T speed = norm(d1);
  if (!(speed > 0)) return std::nullopt;
  if constexpr (C::dimension == 2) {
    return cross(d1, d2) / (speed * speed * speed);
  } else {
    const T a = squared_norm(d1) * squared_norm(d2) - dot(d1, d2) * dot(d1, d2);
    return std::sqrt(std::max(a, T(0))) / (speed * speed * speed);
  }
}

}  // namespace casteljau
