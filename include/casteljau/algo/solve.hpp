// Level sets of a linear functional along a curve: every parameter where a . C(t) equals
// a value (a coordinate when a is a unit axis), from the exact Bernstein form of each piece.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/piecewise.hpp"
#include "casteljau/curves/polyline.hpp"

namespace casteljau {

/// Where a . C(t) = value along a curve (see solve): the isolated parameters, ascending,
/// each once, and the intervals [t0, t1] (t0 < t1) on which it holds throughout, ascending
/// and disjoint (adjacent ones merged). No parameter of `t` lies in an interval.
template <class T>
struct LevelSet {
  std::vector<T> t;
  std::vector<Interval<T>> intervals;
};

namespace detail {

/// The Bernstein coefficients on [0, 1] of a . C(t) - value for one piece, times 2^-e
/// (one power of two chosen so that nothing overflows): a . P_i - value for a polynomial
/// piece, w_i (a . P_i - value) for a rational one (weights divided by the largest; the
/// numerator of a . C - value over the positive weight function).
///
/// Each a . P_i - value is a compensated dot product (Dot2 [OgitaRumpOishi05]: the
/// products split exactly by fma, the sums by TwoSum, the errors summed apart): its
/// error is at most eps |result| + gamma_(d+1)^2 (|value| + sum |a_k P_ik|), so it is
/// relative to the difference itself, not to the coordinates (a coordinate at 1e13 minus a
/// value at 1e13 is exact, as a single subtraction is). `bound` receives that error per
/// coefficient (times 2, with the underflow of the scalings: a few of the smallest
/// subnormal), and `size` the sum of the magnitudes of its terms, |value| + sum |a_k P_ik|
/// (the scale of the pieces' own rounding, see solve). Rational pieces: times w_i, whose
/// roundings are relative to the coefficient (2 eps of it).
template <class T, int D, class Piece>
std::vector<T> level_form(const Piece& c, const Vector<T, D>& a, T value, std::vector<T>& bound, std::vector<T>& size) {
  const auto& P = c.points();
  T pm = std::abs(value), am = 0;
  for (const auto& q : P)
    for (int k = 0; k < D; ++k) pm = std::max(pm, std::abs(q[k]));
  for (int k = 0; k < D; ++k) am = std::max(am, std::abs(a[k]));
  int ep = 0, ea = 0;
  if (pm > 0) (void)std::frexp(pm, &ep);
  if (am > 0) (void)std::frexp(am, &ea);
  Vector<T, D> as;
  for (int k = 0; k < D; ++k) as[k] = std::ldexp(a[k], -ea);  // |as_k| < 1, exact
  const T v = std::ldexp(value, -ep - ea);  // (a . P - value) 2^-(ea + ep), exact scalings
  std::vector<T> f(P.size());
  bound.assign(P.size(), T(0));
  size.assign(P.size(), T(0));
  const T eps = std::numeric_limits<T>::epsilon();
  // gamma_n = n u / (1 - n u) for n = D + 1 terms, u = eps / 2: below (D + 1) eps.
  const T gamma = static_cast<T>(D + 1) * eps;
  // The scalings by 2^-ep may round a coordinate far below the largest into the
  // subnormals (half the smallest subnormal each), and so may the products' split.
  const T tiny = static_cast<T>(4 * (D + 1)) * std::numeric_limits<T>::denorm_min();
  for (std::size_t i = 0; i < P.size(); ++i) {
    T s = -v, err = 0, b = std::abs(v);
    for (int k = 0; k < D; ++k) {
      const T x = std::ldexp(P[i][k], -ep);  // |x| < 1, exact (or a harmless underflow)
      const T prod = as[k] * x;
      const T prod_err = std::fma(as[k], x, -prod);  // exact: as_k x = prod + prod_err
      const T sum = s + prod;                        // TwoSum: s + prod = sum + sum_err exactly
      const T z = sum - s;
      const T sum_err = (s - (sum - z)) + (prod - z);
      s = sum;
      err += sum_err + prod_err;
      b += std::abs(prod);
    }
    f[i] = s + err;
    size[i] = b;
    bound[i] = 2 * (eps * std::abs(f[i]) + gamma * gamma * b) + tiny;
  }
  if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) {
    const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
    for (std::size_t i = 0; i < f.size(); ++i) {
      const T w = c.weights()[i] / wmax;
      f[i] *= w;
      bound[i] = bound[i] * w + 2 * eps * std::abs(f[i]);
      size[i] *= w;
    }
  }
  return f;
}

/// How the exact pieces of a curve (pieces(c)) were obtained, which bounds their own
/// rounding (see solve): `given`, they are its control points (Bézier and rational Bézier
/// curves, polylines, Pieces themselves); `blossomed`, a polynomial B-spline's pieces by
/// blossoming (convex combinations, p levels: within 4 (n + 1) eps of the size of their
/// coordinates); `computed`, any other conversion (a NURBS's Cartesian points, the
/// interpolating types: 16 (n + 2) (D + 1) eps, the bound solve used for every type
/// before). A path takes its worst segment's.
enum class PieceRounding { given, blossomed, computed };

template <class C>
PieceRounding piece_rounding(const C& c) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  if constexpr (is_bezier_piece<C> || is_pieces<C> || std::is_same_v<C, Polyline<T, D>>) {
    return PieceRounding::given;
  } else if constexpr (requires { c.segments(); }) {
    PieceRounding r = PieceRounding::given;
    for (const auto& seg : c.segments()) r = std::max(r, std::visit([](const auto& x) { return piece_rounding(x); }, seg));
    return r;
  } else if constexpr (std::is_same_v<C, BSpline<T, D>>) {
    return PieceRounding::blossomed;
  } else {
    return PieceRounding::computed;
  }
}

}  // namespace detail

/// Every parameter of the domain where a . C(t) = value (a coordinate k = value when a is
/// the unit vector e_k), written once on the curve's exact Bézier pieces. On each piece the
/// scalar polynomial a . P_i - value (rational pieces: w_i (a . P_i - value), the
/// numerator over the positive weight function) is formed in Bernstein form with a known
/// error per coefficient (detail::level_form: compensated, relative to the coefficient
/// itself), plus, when the pieces are computed rather than given (`rounding`, see
/// detail::PieceRounding), their own rounding: 4 (n + 1) eps of the size of the
/// coefficient's terms for a B-spline's blossoms, 16 (n + 2) (D + 1) eps for other
/// conversions (a NURBS's Cartesian points, the interpolating types). That sum is the
/// noise:
/// - a piece on which every coefficient is within its noise of zero is an interval where
///   it holds throughout (a straight piece on the line, a constant coordinate); adjacent
///   ones merge across breaks;
/// - otherwise its roots come from bernstein_roots_with_multiplicity with that noise:
///   sign changes by subdivision and, through the derivatives, the roots of even
///   multiplicity (a tangency, where the curve touches the level without crossing) that
///   rounded coefficients alone can miss; each is reported once.
/// An end of a piece where the form is zero within that noise is a root at the break
/// exactly (roots within 1e-10 of the piece's range from it are that one).
/// Where the curve may jump (the form of piece i + 1 does not start within its noise of
/// zero while piece i ends there), the value is only piece i's left limit at the break,
/// which evaluation does not give: that end is no root, and an interval of piece i ends at
/// the double below the break (Pieces::end_parameter's rule).
/// A root within 1e-10 of the domain's length of another (the same root seen from the two
/// pieces at a break, a multiple root's cluster) is reported once, and roots inside or at
/// the ends of an interval are dropped. A near-touch within the noise counts as a
/// tangency. Accuracy: a simple root to a few eps of its piece's parameter range times
/// its conditioning; a multiple root as the simple root of a derivative.
/// Errors: InvalidArgument("direction", ...) for a zero or non-finite direction,
/// ("value", ...) for a non-finite value. Cost per piece of degree n: up to four root
/// isolations of degree <= n (O(n^2) each per root).
template <class C>
  requires PiecewiseBezierCurve<C>
LevelSet<typename C::Scalar> solve(const C& c, const Vector<typename C::Scalar, C::dimension>& a, typename C::Scalar value,
                                   detail::PieceRounding rounding) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  bool nonzero = false;
  for (int k = 0; k < D; ++k) {
    require_finite(a[k], "direction[" + std::to_string(k) + "]");
    nonzero = nonzero || a[k] != 0;
  }
  if (!nonzero) throw InvalidArgument("direction", "must not be the zero vector");
  require_finite(value, "value");
  const auto& p = pieces(c);
  const Interval<T> dom = p.domain();
  const T merge = T(1e-10) * (dom.hi - dom.lo);
  const T eps = std::numeric_limits<T>::epsilon();
  // Each piece's form and noise first: an end's root depends on the next piece's start.
  struct Form {
    std::vector<T> f;
    T noise = 0;
    bool zero = false;
  };
  std::vector<Form> forms(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::visit(
        [&](const auto& piece) {
          std::vector<T> bound, size;
          Form& g = forms[i];
          g.f = detail::level_form<T, D>(piece, a, value, bound, size);
          const T n = static_cast<T>(g.f.size()) - 1;
          const T slack = rounding == detail::PieceRounding::given       ? T(0)
                          : rounding == detail::PieceRounding::blossomed ? 4 * (n + 1) * eps
                                                                         : 16 * (n + 2) * (D + 1) * eps;
          for (std::size_t j = 0; j < bound.size(); ++j) g.noise = std::max(g.noise, bound[j] + slack * size[j]);
          g.zero = bernstein_negligible<T>(g.f, g.noise);
        },
        p.segments()[i]);
  }
  // Whether the level is attained at the end of piece i as the curve's value there: at the
  // domain's end, or where piece i + 1 starts on it too (else the curve jumps off it).
  const auto end_attained = [&](std::size_t i) {
    return i + 1 == p.size() || forms[i + 1].zero || std::abs(forms[i + 1].f.front()) <= forms[i + 1].noise;
  };
  std::vector<T> roots;
  std::vector<Interval<T>> intervals;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Interval<T> span = p.segment_domain(i);
    const Form& g = forms[i];
    if (g.zero) {
      const T hi = end_attained(i) ? span.hi : Pieces<T, D>::below_break(span.hi, span.lo);
      if (!intervals.empty() && intervals.back().hi == span.lo) {
        intervals.back().hi = hi;
      } else {
        intervals.push_back({span.lo, hi});
      }
      continue;
    }
    // An end where the form is zero within its noise is a root there, exactly: a
    // crossing at a break whose rounded values lie on one side in both pieces, or a
    // root the solver places a few eps inside, is snapped to the break (and dropped with
    // its cluster where only the left limit takes the value).
    const bool at_start = std::abs(g.f.front()) <= g.noise, at_end = std::abs(g.f.back()) <= g.noise;
    if (at_start) roots.push_back(span.lo);
    if (at_end && end_attained(i)) roots.push_back(span.hi);
    for (const auto& r : bernstein_roots_with_multiplicity<T>(g.f, {T(0), T(1)}, g.noise)) {
      if ((at_start && r.t <= T(1e-10)) || (at_end && r.t >= 1 - T(1e-10))) continue;
      roots.push_back(p.lift(i, r.t));
    }
  }
  std::sort(roots.begin(), roots.end());
  LevelSet<T> out;
  out.intervals = std::move(intervals);
  std::size_t j = 0;  // the first interval that may still contain a root
  for (T r : roots) {
    while (j < out.intervals.size() && out.intervals[j].hi + merge < r) ++j;
    if (j < out.intervals.size() && r >= out.intervals[j].lo - merge) continue;  // inside an interval
    if (!out.t.empty() && r - out.t.back() <= merge) continue;                   // the same root again
    out.t.push_back(std::clamp(r, dom.lo, dom.hi));
  }
  return out;
}

/// The same, with the pieces' rounding from the curve's type (detail::piece_rounding).
template <class C>
  requires PiecewiseBezierCurve<C>
LevelSet<typename C::Scalar> solve(const C& c, const Vector<typename C::Scalar, C::dimension>& a, typename C::Scalar value) {
  return solve(c, a, value, detail::piece_rounding(c));
}

}  // namespace casteljau
