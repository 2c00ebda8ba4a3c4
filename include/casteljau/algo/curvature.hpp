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
  // With the unit tangent u = c'/|c'|, kappa = (u x c'') / |c'|^2, divided by the speed
  // one factor at a time: |c'|^3 itself would overflow or underflow for coordinates near
  // 1e+-100, although kappa (size 1/coordinates) is representable.
  const auto u = d1 / speed;
  if constexpr (C::dimension == 2) {
    return cross(u, d2) / speed / speed;
  } else {
    // |u x c''| = |c'' - (u . c'') u| (the component of c'' normal to the tangent).
    const auto normal = d2 - dot(u, d2) * u;
    return norm(normal) / speed / speed;
  }
}

}  // namespace casteljau
