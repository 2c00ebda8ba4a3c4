// Signed area enclosed by a closed plane curve, by Green's theorem on its Bézier pieces.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/algo/project.hpp"
#include "casteljau/algo/scalar_forms.hpp"
#include "casteljau/basis/quadrature.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

/// Relative closure tolerance of area(): the end may differ from the start (and a piece's
/// start from the previous piece's end) by this fraction of the curve's extent (the
/// largest coordinate difference between control points), which covers control points
/// written with a rounded closing coordinate and no more.
template <class T>
inline constexpr T area_closure_tolerance = T(1e-9);

/// The signed area enclosed by a closed plane curve (positive when it runs
/// counter-clockwise; a figure eight gives the difference of its lobes), by Green's
/// theorem A = 1/2 sum over pieces of the integral over [0, 1] of x y' - y x', with
/// coordinates relative to the curve's start point (which makes the formula
/// translation-invariant in floating point). A polynomial piece's integrand is the
/// Bernstein product x y' - y x' (degree 2n - 1), whose integral is the mean of its
/// coefficients [Farin02, 5.4]: exact up to rounding (a few n eps of the curve's extent
/// squared). A rational piece's integrand is (X Y' - Y X') / w^2 (the w' terms cancel),
/// integrated by adaptive Gauss-Kronrod to 1e-13 of the integral of its absolute value
/// (for double; the same units in the last place at other scalars, detail::target_at).
/// Gaps within the closure tolerance (end to start, piece to piece) are closed by their
/// chords, whose area terms are included. Throws InvalidArgument("curve", ...) when the
/// curve is not closed (naming the gap), NumericalError if a quadrature fails.
template <class C>
  requires detail::is_pieces<C> && (C::dimension == 2)
typename C::Scalar area(const C& c) {
  using T = typename C::Scalar;
  const auto& p = pieces(c);
  const Point<T, 2> origin = p(p.domain().lo);
  // The extent: largest coordinate difference from the start among the control points.
  T extent = 0;
  for (const auto& s : p.segments())
    std::visit([&](const auto& piece) {
      for (const auto& P : piece.points()) extent = std::max(extent, detail::safe_distance(P, origin));
    }, s);
  const T gap_tol = area_closure_tolerance<T> * extent;
  T twice = 0;  // twice the area, in units 2^(2 e) of each piece
  auto chord = [&](const Point<T, 2>& a, const Point<T, 2>& b, const std::string& what) {
    const T g = detail::safe_distance(a, b);
    if (g > gap_tol) {
      throw InvalidArgument("curve", "must be closed for its area: " + what + " are " + detail::format_number(g) +
                                         " apart, more than " + detail::format_number(gap_tol) + " (1e-9 of its extent)");
    }
    // (a - o) x (b - o): the chord's term of the sum.
    twice += (a[0] - origin[0]) * (b[1] - origin[1]) - (a[1] - origin[1]) * (b[0] - origin[0]);
  };
  {
    // Closed at all, before any integration (which may fail on an open curve first).
    const T g = detail::safe_distance(p(p.domain().hi), origin);
    if (g > gap_tol) {
      throw InvalidArgument("curve", "must be closed for its area: the end and the start are " + detail::format_number(g) +
                                         " apart, more than " + detail::format_number(gap_tol) + " (1e-9 of its extent)");
    }
  }
  Point<T, 2> previous_end = origin;
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::visit(
        [&](const auto& piece) {
          const Point<T, 2> start = piece(T(0));
          if (i > 0) chord(previous_end, start, "the end of piece " + std::to_string(i - 1) + " and the start of piece " + std::to_string(i));
          previous_end = piece(T(1));
          // The integral is the same in any parametrisation: a rational piece with extreme
          // weights (1, 1e200, 1, where the quadrature cannot resolve the ends) is summed
          // over its tame reparametrised parts (detail::regular_parts; ordinary pieces are
          // one part, themselves).
          auto add = [&](const auto& part) {
            const auto f = detail::scalar_forms<T, 2>(part, origin);
            if (f.degree == 0) return;
            const auto dx = bernstein_derivative_coefficients<T>(f.x[0]), dy = bernstein_derivative_coefficients<T>(f.x[1]);
            const auto num = bernstein_difference<T>(bernstein_product<T>(f.x[0], dy), bernstein_product<T>(f.x[1], dx));
            T value;
            if (!f.rational) {
              value = bernstein_integral<T>(num);
            } else {
              auto integrand = [&](T t) {
                const T w = de_casteljau<T, T>(std::span<const T>(f.w), t);
                return de_casteljau<T, T>(std::span<const T>(num), t) / w / w;
              };
              const auto a = bernstein_sum<T>(bernstein_product<T>(bernstein_abs<T>(f.x[0]), bernstein_abs<T>(dy)),
                                              bernstein_product<T>(bernstein_abs<T>(f.x[1]), bernstein_abs<T>(dx)));
              auto bound = [&](T t) {
                const T w = de_casteljau<T, T>(std::span<const T>(f.w), t);
                return de_casteljau<T, T>(std::span<const T>(a), t) / w / w;
              };
              const T scale = gauss_kronrod_15<T>(bound, T(0), T(1)).value;
              try {
                value = integrate_adaptive<T>(integrand, T(0), T(1), T(0), detail::target_at<T>(1e-13) * scale).value;
              } catch (const NumericalError& e) {
                // In the request's terms: which piece, and the quadrature's figures.
                throw NumericalError("the area of piece " + std::to_string(i) + " (a rational piece) cannot be computed: " + e.what());
              }
            }
            twice += std::ldexp(value, 2 * f.e);
          };
          if constexpr (requires { piece.weights(); }) {
            for (const auto& rp : detail::regular_parts(piece)) add(rp.piece);
          } else {
            add(piece);
          }
        },
        p.segments()[i]);
  }
  chord(previous_end, origin, "the end and the start");
  return twice / 2;
}

/// Every other curve type: the same, on its exact pieces (see detail::is_pieces).
template <class C>
  requires PiecewiseBezierCurve<C> && (C::dimension == 2) && (!detail::is_pieces<C>)
typename C::Scalar area(const C& c) {
  return area(pieces(c));
}

}  // namespace casteljau
