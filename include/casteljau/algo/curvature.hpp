// Curvature of differentiable curves.
#pragma once

#include <cmath>
#include <optional>

#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// Curvature from the first two derivatives d1 = c'(t), d2 = c''(t) [Farin02, 10.2]: in
/// the plane the signed (x'y'' - y'x'') / |c'|^3, positive where the curve turns left; in
/// other dimensions the non-negative |c' x c''| / |c'|^3 (0 for a curve in R^1, which
/// moves along a line). std::nullopt where the speed |c'| is zero (a cusp or a stop),
/// where curvature is undefined.
template <class T, int D>
std::optional<T> curvature_of(const Vector<T, D>& d1, const Vector<T, D>& d2) {
  const T speed = norm(d1);
  if (!(speed > 0)) return std::nullopt;
  if constexpr (D == 1) {
    return T(0);
  } else {
    // With the unit tangent u = c'/|c'|, kappa = (u x c'') / |c'|^2, divided by the speed
    // one factor at a time: |c'|^3 itself would overflow or underflow for coordinates near
    // 1e+-100, although kappa (size 1/coordinates) is representable.
    const auto u = d1 / speed;
    if constexpr (D == 2) {
      return cross(u, d2) / speed / speed;
    } else {
      // |u x c''| = |c'' - (u . c'') u| (the component of c'' normal to the tangent).
      const auto normal = d2 - dot(u, d2) * u;
      return norm(normal) / speed / speed;
    }
  }
}

namespace detail {
/// Curvature of a Bézier piece at t: a rational piece on [0, 1] (degree <= 24) from its
/// jet (rational_jet: the numerator R' ^ R'' as a sum over triples of control points with
/// positive coefficients, exact in sign and relative size where the curve hugs its chord
/// or its control polygon), every other from the first two derivatives.
template <class Piece>
std::optional<typename Piece::Scalar> piece_curvature(const Piece& s, typename Piece::Scalar t) {
  if constexpr (requires { s.jet(t, true); }) {
    if (t >= 0 && t <= 1 && s.degree() <= rational_jet_max_degree) return jet_curvature(s.jet(t, true));
  }
  return curvature_of(s.derivative_at(t, 1), s.derivative_at(t, 2));
}
}  // namespace detail

/// Curvature at t of a differentiable curve (see curvature_of): std::nullopt where the
/// speed is zero. The derivatives are taken in the curve's own parameter: for a domain
/// far from unit length use the overload on Pieces, which does not depend on its scale.
template <DifferentiableCurve C>
  requires(C::dimension >= 2)
std::optional<typename C::Scalar> curvature(const C& c, typename C::Scalar t) {
  return detail::piece_curvature(c, t);
}

/// Curvature at u of a curve given by its exact Bézier pieces (at an interior break the
/// right-hand piece answers, at the domain's end the last, as derivative_at). Curvature
/// is a geometric quantity, unchanged by an increasing affine change of parameter, so it
/// is computed from the derivatives of the piece in its own parameter on [0, 1], not in
/// the curve's: a domain of length 1e200 (or 1e-200) scales the k-th derivative by its
/// k-th power, which underflows (overflows) although the curvature is representable.
/// Throws InvalidArgument("t", ...) for a non-finite u.
template <class T, int D>
std::optional<T> curvature(const Pieces<T, D>& p, T u) {
  require_finite(u, "t");
  // (no structured binding: clang 14 cannot capture one in a lambda)
  const PieceParameter<T> at = p.locate(u);
  const T t = at.t;
  return std::visit([&](const auto& s) { return detail::piece_curvature(s, t); }, p.segments()[at.index]);
}

}  // namespace casteljau
