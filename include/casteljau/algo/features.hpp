// Inflections, cusps and per-axis extrema of curves, from the roots of Bernstein forms of
// their derivatives on every piece.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "casteljau/algo/scalar_forms.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

/// Parameters (ascending) of a curve's features: inflections (the signed curvature
/// changes sign; plane curves only), cusps (the velocity vanishes and the curve has a
/// point there that is not a stop on a straight piece, or the tangent reverses at a
/// break; plane curves only) and, per axis
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
/// a few eps gives about 1e-15; a near-cusp (a tight turn) above 1e-8 is not one. In
/// float, where a true cusp's rounding alone gives about 1e-7, 64 eps (7.6e-6).
template <class T>
inline constexpr T cusp_tolerance = std::max(T(1e-8), 64 * std::numeric_limits<T>::epsilon());

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

/// Whether the root t of c (near an end: within 1e-3) is the end's own root moved inside
/// by rounding: c is within `noise` of zero on the whole stretch from t to that end (its
/// Bernstein coefficients there, by one subdivision, all are). A natural spline's zero
/// curvature at its end, a clamped spline's zero slope, give such roots at 1 - 1e-15.
template <class T>
bool end_root_by_rounding(const std::vector<T>& c, T t, T noise) {
  if (t > T(1e-3) && t < 1 - T(1e-3)) return false;
  std::vector<T> left(c.size()), right(c.size());
  de_casteljau_split<T, T>(std::span<const T>(c), t, left, right);
  const auto& part = t < T(0.5) ? left : right;
  return std::all_of(part.begin(), part.end(), [&](T x) { return std::abs(x) <= noise; });
}

/// Roots in (0, 1) of odd multiplicity (a sign change) of c, unless c vanishes within
/// its rounding bound a; not those that are an end's root moved inside by rounding.
template <class T>
std::vector<T> sign_changes(const std::vector<T>& c, const std::vector<T>& a, T slack) {
  std::vector<T> out;
  if (c.size() < 2 || vanishes(c, a, slack)) return out;
  const T noise = noise_of(a, slack);
  for (const auto& r : bernstein_roots_with_multiplicity<T>(c, {T(0), T(1)}, noise))
    if (r.t > 0 && r.t < 1 && r.multiplicity % 2 == 1 && !end_root_by_rounding(c, r.t, noise)) out.push_back(r.t);
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

namespace detail {

/// The roots of the derivative numerator c with their multiplicities (the root engine
/// with the rounding bound a as its noise), or none when c vanishes within it.
template <class T>
std::vector<BernsteinRoot<T>> numerator_roots(const std::vector<T>& c, const std::vector<T>& a, T slack) {
  if (c.size() < 2 || vanishes(c, a, slack)) return {};
  return bernstein_roots_with_multiplicity<T>(c, {T(0), T(1)}, noise_of(a, slack));
}

/// The direction in which a Bézier piece leaves its start (at_end false) or enters its
/// end (at_end true): P_j - P_0 (P_n - P_(n-j)) for the first control point P_j that is
/// not the end point within 64 eps of the piece's size. A piece whose velocity vanishes
/// at the end still has this direction (the first non-zero derivative there is along
/// it, for rational pieces too); std::nullopt for a piece that is a single point.
template <class T, class Piece>
std::optional<Vector<T, 2>> end_direction(const Piece& c, bool at_end) {
  const auto& P = c.points();
  const std::size_t n = P.size() - 1;
  T size = 0;
  for (const auto& q : P) size = std::max({size, std::abs(q[0]), std::abs(q[1])});
  const T tol = 64 * std::numeric_limits<T>::epsilon() * size;
  for (std::size_t j = 1; j <= n; ++j) {
    const Vector<T, 2> d = at_end ? P[n] - P[n - j] : P[j] - P[0];
    if (std::max(std::abs(d[0]), std::abs(d[1])) > tol) return d / norm(d);
  }
  return std::nullopt;
}

}  // namespace detail

/// The features of a curve (see Features), written once on its Bézier pieces:
/// - extrema of coordinate k: the roots of odd multiplicity inside each piece of the
///   numerator of x_k' (its Bernstein form: x_k' for a polynomial piece, X_k' w - X_k w'
///   for a rational one), and the interior breaks where x_k' has opposite signs on the
///   two sides (read from the end coefficients);
/// - cusps (D = 2): the roots inside a piece of its largest derivative numerator at which
///   |c'| is below cusp_tolerance (1e-8) of the hodograph's size (a point piece or a
///   constant stretch has none); and the interior breaks where the tangent reverses: the
///   direction entering the break and the one leaving it (from the control points, so
///   also where the velocity vanishes at the break) are opposite within cusp_tolerance
///   (the sine of the angle between them). A polyline's vertex where it turns back is a
///   cusp; one where it turns by less than 180 degrees is a corner, not reported;
/// - inflections (D = 2): the roots of odd multiplicity inside a piece of the curvature
///   numerator det(H, H', H'') (x'y'' - y'x'' for a polynomial piece) that are not
///   cusps (within 1e-7): a straight piece (numerator zero within its rounding bound)
///   has none, a flat point (even multiplicity, y = x^4) is not one; and the interior
///   breaks that are not cusps where the signed curvature has opposite signs just before
///   and just after (from the end coefficients of the numerators, so whether or not the
///   curvature is continuous there: two arcs bending opposite ways, a cubic split at its
///   inflection). A straight piece has no sign, so a polyline has no inflections and an
///   arc-line-arc S has none at its breaks. A piece that is a single point is skipped:
///   the break after it is compared with the piece before it.
/// Roots by bernstein_roots_with_multiplicity, with the rounding bound of each form as
/// its noise; a root next to a piece's end where the form is zero within that noise all
/// the way to the end is the end's (detail::end_root_by_rounding), found at a break by
/// the rules above and not at all at the domain's ends. Parameters are accurate to a few eps of the piece's parameter range at
/// simple roots. Features at the domain's ends are not reported. Cost per piece: root
/// isolation on D forms of degree up to 2n - 1 and one of degree up to 3n - 3 (about
/// 0.3 s of CPU at degree 1000, 1 s rational; docs/accuracy.md).
template <class C>
  requires detail::is_pieces<C>
Features<typename C::Scalar, C::dimension> features(const C& c) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const auto& p = pieces(c);
  Features<T, D> out;
  std::array<int, D> previous_sign{};  // sign of x_k' at the end of the previous piece
  // Plane curves: the signed curvature's sign and the tangent direction entering the
  // previous break (the end of the last piece that is not a single point).
  int previous_bend = 0;
  std::optional<Vector<T, 2>> previous_direction;
  std::vector<T> odd;  // a piece's roots of odd multiplicity
  p.for_each_piece([&](std::size_t i, const auto& piece, const Interval<T>& own) {
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
    std::array<std::vector<BernsteinRoot<T>>, D> roots;
    for (int k = 0; k < D; ++k) {
      const int start_sign = detail::end_sign(num[k], bound[k], slack, false);
      if (i > 0 && previous_sign[k] * start_sign < 0) out.extrema[k].push_back(p.lift(i, own.lo));  // the break u_i
      const int end = detail::end_sign(num[k], bound[k], slack, true);
      if (end != 0 || start_sign != 0) previous_sign[k] = end;
      if (f.degree < 2) continue;
      roots[k] = detail::numerator_roots(num[k], bound[k], slack);
      const T noise = detail::noise_of(bound[k], slack);
      std::erase_if(roots[k], [&](const BernsteinRoot<T>& r) {
        return !(r.t > 0 && r.t < 1) || detail::end_root_by_rounding(num[k], r.t, noise);
      });
      odd.clear();
      for (const auto& r : roots[k])
        if (r.multiplicity % 2 == 1) odd.push_back(r.t);
      p.lift_roots(i, odd, out.extrema[k]);
    }
    if constexpr (D == 2) {
      std::vector<T> kn, ka;
      if (f.degree >= 2) {
        kn = detail::curvature_numerator<T>(f, false);
        ka = detail::curvature_numerator<T>(f, true);
      }
      const T kslack = 4 * slack;
      const auto leaving = detail::end_direction<T>(piece, false), entering = detail::end_direction<T>(piece, true);
      if (!leaving) return;  // a single point: nothing here, the next break compares across it
      const int bend_start = kn.empty() ? 0 : detail::end_sign(kn, ka, kslack, false);
      const int bend_end = kn.empty() ? 0 : detail::end_sign(kn, ka, kslack, true);
      if (i > 0 && previous_direction) {
        const Vector<T, 2>& a = *previous_direction;
        const Vector<T, 2>& b = *leaving;
        const T u = p.lift(i, own.lo);  // the break u_i
        if (dot(a, b) < 0 && std::abs(cross(a, b)) <= cusp_tolerance<T>) {
          out.cusps.push_back(u);
        } else if (previous_bend * bend_start < 0) {
          out.inflections.push_back(u);
        }
      }
      previous_direction = entering;
      previous_bend = bend_end;
      if (f.degree < 2 || hodograph_size == 0) return;
      std::vector<T> cusps;
      for (const auto& r : roots[biggest]) {
        Vector<T, D> v;
        for (int k = 0; k < D; ++k) v[k] = detail::bernstein_value_fast<T>(std::span<const T>(num[k]), r.t);
        if (norm(v) <= cusp_tolerance<T> * hodograph_size) cusps.push_back(r.t);
      }
      std::vector<T> inflections = detail::sign_changes(kn, ka, kslack);
      std::erase_if(inflections, [&](T t) {
        return std::any_of(cusps.begin(), cusps.end(), [&](T u) { return std::abs(u - t) <= T(1e-7); });
      });
      p.lift_roots(i, inflections, out.inflections);
      p.lift_roots(i, cusps, out.cusps);
    }
  });
  for (auto& e : out.extrema) std::sort(e.begin(), e.end());
  // A feature at a break may also be found, by rounding, just inside a piece next to it:
  // one report within 1e-9 of the domain's length.
  const T merge = T(1e-9) * p.domain().length();
  for (auto* list : {&out.inflections, &out.cusps}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end(), [&](T a, T b) { return b - a <= merge; }), list->end());
  }
  return out;
}

/// Every other curve type: the same, on its exact pieces (see detail::is_pieces).
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_pieces<C>)
Features<typename C::Scalar, C::dimension> features(const C& c) {
  return features(pieces(c));
}

}  // namespace casteljau
