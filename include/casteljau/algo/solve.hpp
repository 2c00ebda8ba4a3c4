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
#include "casteljau/curves/piecewise.hpp"

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
/// numerator of a . C - value over the positive weight function). `bound` receives a
/// bound of each coefficient's rounding error: the same sums on absolute values times
/// the count of roundings.
template <class T, int D, class Piece>
std::vector<T> level_form(const Piece& c, const Vector<T, D>& a, T value, std::vector<T>& bound) {
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
  const T eps = std::numeric_limits<T>::epsilon();
  for (std::size_t i = 0; i < P.size(); ++i) {
    T s = -v, b = std::abs(v);
    for (int k = 0; k < D; ++k) {
      const T x = std::ldexp(P[i][k], -ep);  // |x| < 1, exact (or a harmless underflow)
      s += as[k] * x;
      b += std::abs(as[k] * x);
    }
    f[i] = s;
    bound[i] = 2 * (D + 1) * eps * b;  // D products and D sums, each one rounding
  }
  if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) {
    const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
    for (std::size_t i = 0; i < f.size(); ++i) {
      const T w = c.weights()[i] / wmax;
      f[i] *= w;
      bound[i] = bound[i] * w + 2 * eps * std::abs(f[i]);
    }
  }
  return f;
}

}  // namespace detail

/// Every parameter of the domain where a . C(t) = value (a coordinate k = value when a is
/// the unit vector e_k), written once on the curve's exact Bézier pieces. On each piece the
/// scalar polynomial a . P_i - value (rational pieces: w_i (a . P_i - value), the
/// numerator over the positive weight function) is formed exactly in Bernstein form:
/// - a piece on which it is zero within its rounding bound (every coefficient within
///   2 (D + 1) eps of the size of its terms, times 8 (n + 2) for the pieces' own
///   rounding) is an interval where it holds throughout (a straight piece on the line,
///   a constant coordinate); adjacent ones merge across breaks;
/// - otherwise its roots come from bernstein_roots_with_multiplicity with that bound as
///   the noise: sign changes by subdivision and, through the derivatives, the roots of
///   even multiplicity (a tangency, where the curve touches the level without crossing)
///   that rounded coefficients alone can miss; each is reported once.
/// An end of a piece where the form is zero within that bound is a root at the break
/// exactly (roots within 1e-10 of the piece's range from it are that one).
/// A root within 1e-10 of the domain's length of another (the same root seen from the two
/// pieces at a break, a multiple root's cluster) is reported once, and roots inside or at
/// the ends of an interval are dropped. A near-touch within the rounding bound counts as a
/// tangency. Accuracy: a simple root to a few eps of its piece's parameter range times
/// its conditioning; a multiple root as the simple root of a derivative.
/// Errors: InvalidArgument("direction", ...) for a zero or non-finite direction,
/// ("value", ...) for a non-finite value. Cost per piece of degree n: up to four root
/// isolations of degree <= n (O(n^2) each per root).
template <class C>
  requires PiecewiseBezierCurve<C>
LevelSet<typename C::Scalar> solve(const C& c, const Vector<typename C::Scalar, C::dimension>& a, typename C::Scalar value) {
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
  std::vector<T> roots;
  std::vector<Interval<T>> intervals;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Interval<T> span = p.segment_domain(i);
    std::visit(
        [&](const auto& piece) {
          std::vector<T> bound;
          const std::vector<T> f = detail::level_form<T, D>(piece, a, value, bound);
          const T slack = 8 * static_cast<T>(f.size() + 1);
          T noise = 0;
          for (T b : bound) noise = std::max(noise, slack * b);
          if (bernstein_negligible<T>(f, noise)) {
            if (!intervals.empty() && intervals.back().hi == span.lo) {
              intervals.back().hi = span.hi;
            } else {
              intervals.push_back(span);
            }
            return;
          }
          // An end where the form is zero within its noise is a root there, exactly: a
          // crossing at a break whose rounded values lie on one side in both pieces, or a
          // root the solver places a few eps inside, is snapped to the break.
          const bool at_start = std::abs(f.front()) <= noise, at_end = std::abs(f.back()) <= noise;
          if (at_start) roots.push_back(span.lo);
          if (at_end) roots.push_back(span.hi);
          for (const auto& r : bernstein_roots_with_multiplicity<T>(f, {T(0), T(1)}, noise)) {
            if ((at_start && r.t <= T(1e-10)) || (at_end && r.t >= 1 - T(1e-10))) continue;
            // The piece's ends map exactly onto its break (Pieces::lift).
            roots.push_back(p.lift(i, r.t));
          }
        },
        p.segments()[i]);
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

}  // namespace casteljau
