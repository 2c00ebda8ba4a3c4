// Inflections, cusps and per-axis extrema of curves, from the roots of Bernstein forms of
// their derivatives on every piece.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/algo/scalar_forms.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

/// Parameters (ascending) of a curve's features: inflections (the signed curvature
/// changes sign; plane curves only), cusps (the velocity vanishes and the curve has a
/// point there that is not a stop on a straight piece; plane curves only) and, per axis
/// k, the parameters inside the domain where coordinate k has a local extremum (its
/// derivative changes sign; at a break too, e.g. a polyline's corner).
template <class T, int D>
struct Features {
  std::vector<T> inflections;
  std::vector<T> cusps;
  std::array<std::vector<T>, D> extrema;
};

/// Relative size below which the velocity counts as zero at a candidate cusp: |c'| at
/// most this fraction of the hodograph's control polygon size. A true cusp located to
/// a few eps gives about 1e-15; a near-cusp (a tight turn) above 1e-8 is not one.
template <class T>
inline constexpr T cusp_tolerance = T(1e-8);

namespace detail {

/// Sign of a Bernstein form just inside its end (at_end) or its start: the sign of its
/// last (first) coefficient above the noise; 0 if all are within it.
template <class T>
int end_sign(const std::vector<T>& c, const std::vector<T>& a, T slack, bool at_end) {
  const T eps = std::numeric_limits<T>::epsilon();
  for (std::size_t j = 0; j < c.size(); ++j) {
    const std::size_t i = at_end ? c.size() - 1 - j : j;
    if (std::abs(c[i]) > slack * eps * a[i]) return c[i] > 0 ? 1 : -1;
  }
  return 0;
}

template <class T>
T noise_of(const std::vector<T>& a, T slack) {
  return slack * std::numeric_limits<T>::epsilon() * max_abs<T>(std::span<const T>(a));
}

/// Roots in (0, 1) of odd multiplicity (a sign change) of c, unless c vanishes within
/// its rounding bound a.
template <class T>
std::vector<T> sign_changes(const std::vector<T>& c, const std::vector<T>& a, T slack) {
  std::vector<T> out;
  if (c.size() < 2 || vanishes(c, a, slack)) return out;
  for (const auto& r : bernstein_roots_with_multiplicity<T>(c, {T(0), T(1)}, noise_of(a, slack)))
    if (r.t > 0 && r.t < 1 && r.multiplicity % 2 == 1) out.push_back(r.t);
  return out;
}

/// det(H, H', H'') for the homogeneous plane piece H = (X, Y, w), the numerator of its
/// signed curvature (kappa = det / (w^3 |c'|^3), up to the positive scale); for a
/// polynomial piece (w = 1) it is x'y'' - y'x''. With `absolute`, the bound of its
/// rounding error (the same sums of products of absolute values).
template <class T>
std::vector<T> curvature_numerator(const ScalarForms<T, 2>& f, bool absolute) {
  auto d = [&](const std::vector<T>& c) {
    return absolute ? abs_derivative_bound<T>(c) : bernstein_derivative_coefficients<T>(c);
  };
  auto v = [&](const std::vector<T>& c) { return absolute ? bernstein_abs<T>(c) : c; };
  auto mul = [](const std::vector<T>& a, const std::vector<T>& b) { return bernstein_product<T>(a, b); };
  auto sub = [&](const std::vector<T>& a, const std::vector<T>& b) {
    return absolute ? bernstein_sum<T>(a, b) : bernstein_difference<T>(a, b);
  };
  const auto X1 = d(f.x[0]), Y1 = d(f.x[1]);
  const auto X2 = d(X1), Y2 = d(Y1);
  const auto XY = sub(mul(X1, Y2), mul(Y1, X2));
  if (!f.rational) return XY;
  const auto W1 = d(f.w), W2 = d(W1);
  const auto a = mul(v(f.x[0]), sub(mul(Y1, W2), mul(W1, Y2)));
  const auto b = mul(v(f.x[1]), sub(mul(X1, W2), mul(W1, X2)));
  const auto c = mul(v(f.w), XY);
  return absolute ? bernstein_sum<T>(bernstein_sum<T>(a, b), c) : bernstein_sum<T>(bernstein_difference<T>(a, b), c);
}

}  // namespace detail

/// The features of a curve (see Features), written once on its Bézier pieces:
/// - extrema of coordinate k: the roots of odd multiplicity inside each piece of the
///   numerator of x_k' (its Bernstein form: x_k' for a polynomial piece, X_k' w - X_k w'
///   for a rational one), and the interior breaks where x_k' has opposite signs on the
///   two sides (read from the end coefficients);
/// - cusps (D = 2): the roots inside a piece of its largest derivative numerator at which
///   |c'| is below cusp_tolerance (1e-8) of the hodograph's size (a point piece or a
///   constant stretch has none);
/// - inflections (D = 2): the roots of odd multiplicity inside a piece of the curvature
///   numerator det(H, H', H'') (x'y'' - y'x'' for a polynomial piece) that are not
///   cusps (within 1e-7): a straight piece (numerator zero within its rounding bound)
///   has none, a flat point (even multiplicity, y = x^4) is not one.
/// Roots by bernstein_roots_with_multiplicity, with the rounding bound of each form as
/// its noise; parameters are accurate to a few eps of the piece's parameter range at
/// simple roots. Features at the domain's ends are not reported. Cost per piece: root
/// isolation on D forms of degree up to 2n - 1 and one of degree up to 3n - 3.
template <class C>
  requires PiecewiseBezierCurve<C>
Features<typename C::Scalar, C::dimension> features(const C& c) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const auto& p = pieces(c);
  Features<T, D> out;
  std::array<int, D> previous_sign{};  // sign of x_k' at the end of the previous piece
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::visit(
        [&](const auto& piece) {
          const auto f = detail::scalar_forms<T, D>(piece, piece.points().front());
          std::array<std::vector<T>, D> num, bound;
          T hodograph_size = 0;
          int biggest = 0;
          for (int k = 0; k < D; ++k) {
            num[k] = detail::derivative_numerator(f, k);
            bound[k] = detail::derivative_numerator(f, k, true);
            const T m = detail::max_abs<T>(std::span<const T>(num[k]));
            if (m > hodograph_size) {
              hodograph_size = m;
              biggest = k;
            }
          }
          const T slack = 8 * static_cast<T>(f.degree + 2) * (f.rational ? 4 : 1);
          for (int k = 0; k < D; ++k) {
            const int start_sign = detail::end_sign(num[k], bound[k], slack, false);
            if (i > 0 && previous_sign[k] * start_sign < 0) out.extrema[k].push_back(p.segment_domain(i).lo);
            const int end = detail::end_sign(num[k], bound[k], slack, true);
            if (end != 0 || start_sign != 0) previous_sign[k] = end;
            if (f.degree < 2) continue;
            for (T t : detail::sign_changes(num[k], bound[k], slack)) out.extrema[k].push_back(p.global_parameter(i, t));
          }
          if constexpr (D == 2) {
            if (f.degree < 2 || hodograph_size == 0) return;
            std::vector<T> cusps;
            const auto& cand = num[biggest];
            if (!detail::vanishes(cand, bound[biggest], slack)) {
              for (const auto& r : bernstein_roots_with_multiplicity<T>(cand, {T(0), T(1)}, detail::noise_of(bound[biggest], slack))) {
                if (!(r.t > 0 && r.t < 1)) continue;
                Vector<T, D> v;
                for (int k = 0; k < D; ++k) v[k] = de_casteljau<T, T>(std::span<const T>(num[k]), r.t);
                if (norm(v) <= cusp_tolerance<T> * hodograph_size) cusps.push_back(r.t);
              }
            }
            const auto kn = detail::curvature_numerator<T>(f, false), ka = detail::curvature_numerator<T>(f, true);
            for (T t : detail::sign_changes(kn, ka, 4 * slack)) {
              const bool at_cusp = std::any_of(cusps.begin(), cusps.end(), [&](T u) { return std::abs(u - t) <= T(1e-7); });
              if (!at_cusp) out.inflections.push_back(p.global_parameter(i, t));
            }
            for (T t : cusps) out.cusps.push_back(p.global_parameter(i, t));
          }
        },
        p.segments()[i]);
  }
  for (auto& e : out.extrema) std::sort(e.begin(), e.end());
  return out;
}

}  // namespace casteljau
