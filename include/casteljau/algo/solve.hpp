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

#include <Eigen/LU>

#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/path.hpp"

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

/// How far the control points of one of a curve's pieces (pieces(c)) may lie from the
/// curve's exact Bézier form (see piece_errors): |computed - exact| of coordinate k of
/// every control point is at most coordinate[k] + relative |that coordinate|; for a
/// rational piece these are the homogeneous coordinates w_j P_jk, and each weight is
/// within `weight` of its exact value (the piece's own weight units, weights() as held).
/// All zero for pieces that are the curve's definition.
template <class T, int D>
struct PieceError {
  Vector<T, D> coordinate{};
  T weight = 0;
  T relative = 0;
};

/// The Bernstein coefficients on [0, 1] of a . C(t) - value for one piece, times 2^-e
/// (one power of two chosen so that nothing overflows): a . P_i - value for a polynomial
/// piece, w_i (a . P_i - value) for a rational one (weights divided by the largest; the
/// numerator of a . C - value over the positive weight function).
///
/// Each a . P_i - value is a compensated dot product (Dot2 [OgitaRumpOishi05]: the
/// products split exactly by fma, the sums by TwoSum, the errors summed apart): its
/// error is at most eps |result| + gamma_(d+1)^2 (|value| + sum |a_k P_ik|), so it is
/// relative to the difference itself, not to the coordinates (a coordinate at 1e13 minus a
/// value at 1e13 is exact, as a single subtraction is). Rational pieces: times w_i, whose
/// roundings are relative to the coefficient (2 eps of it). `bound` receives per
/// coefficient that error (times 2, with the underflow of the scalings: a few of the
/// smallest subnormal) plus what the pieces' own rounding `err` moves it by:
/// sum_k |a_k| coordinate_k + |value| weight + relative w_i sum_k |a_k P_ik| (the level
/// coefficient is linear in the homogeneous coordinates: a . (w P)_i - value w_i), in the
/// same scaled units, times 1 + 8 eps for the rounding of the bound's own arithmetic.
template <class T, int D, class Piece>
std::vector<T> level_form(const Piece& c, const Vector<T, D>& a, T value, const PieceError<T, D>& err, std::vector<T>& bound) {
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
  std::vector<T> f(P.size()), terms(P.size());
  bound.assign(P.size(), T(0));
  const T eps = std::numeric_limits<T>::epsilon();
  // gamma_n = n u / (1 - n u) for n = D + 1 terms, u = eps / 2: below (D + 1) eps.
  const T gamma = static_cast<T>(D + 1) * eps;
  // The scalings by 2^-ep may round a coordinate far below the largest into the
  // subnormals (half the smallest subnormal each), and so may the products' split.
  const T tiny = static_cast<T>(4 * (D + 1)) * std::numeric_limits<T>::denorm_min();
  // The pieces' own rounding on the homogeneous coordinates, scaled as the coefficients.
  T moved = 0;
  for (int k = 0; k < D; ++k) moved += std::abs(as[k]) * std::ldexp(err.coordinate[k], -ep);
  for (std::size_t i = 0; i < P.size(); ++i) {
    T s = -v, e = 0, b = std::abs(v), t = 0;
    for (int k = 0; k < D; ++k) {
      const T x = std::ldexp(P[i][k], -ep);  // |x| < 1, exact (or a harmless underflow)
      const T prod = as[k] * x;
      const T prod_err = std::fma(as[k], x, -prod);  // exact: as_k x = prod + prod_err
      const T sum = s + prod;                        // TwoSum: s + prod = sum + sum_err exactly
      const T z = sum - s;
      const T sum_err = (s - (sum - z)) + (prod - z);
      s = sum;
      e += sum_err + prod_err;
      t += std::abs(prod);
    }
    b += t;
    f[i] = s + e;
    terms[i] = t;
    bound[i] = 2 * (eps * std::abs(f[i]) + gamma * gamma * b) + tiny;
  }
  const T grow = 1 + 8 * eps;
  if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) {
    const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
    const T homogeneous = (moved + std::abs(v) * err.weight) / wmax;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const T w = c.weights()[i] / wmax;
      f[i] *= w;
      bound[i] = bound[i] * w + 2 * eps * std::abs(f[i]) + grow * (homogeneous + err.relative * w * terms[i]);
    }
  } else {
    for (std::size_t i = 0; i < f.size(); ++i) bound[i] += grow * (moved + err.relative * terms[i]);
  }
  return f;
}

/// The rounding of the Bézier points of each span of the B-spline (degree p, knots U,
/// points P of dimension E) as detail::span_bezier_points computes them: per coordinate k,
/// (4 p + 1) eps times the largest |P_jk| of the span's p + 1 control points. Derivation:
/// every step is q = (1 - alpha) x + alpha y with alpha = (c - U_i) / (U_j - U_i) in [0, 1]
/// (computed with relative error 3u, u = eps / 2: two differences and a quotient; then
/// 1 - alpha with |error| <= 3u alpha + u (1 - alpha)); the two products and the sum round
/// by u each, so one step adds at most u M (3 + 5 alpha) <= 4 eps M, M the largest
/// |input|, which is at most the span's largest |P_jk| (convex combinations); errors
/// already present pass through with weights summing to 1 + O(u). Each Bézier point is at
/// most p steps deep (g_0 after the p levels of de Boor at a; g_m, m >= 1, after p - m
/// levels of it and m - 1 of de Boor at b), hence 4 p eps M, and the + 1 covers the
/// second-order terms (p^2 eps^2). Measured: see docs/cli.md.
template <class T, int E>
std::vector<Vector<T, E>> span_rounding(std::span<const T> U, int p, std::span<const Point<T, E>> P) {
  const T eps = std::numeric_limits<T>::epsilon();
  std::vector<Vector<T, E>> out;
  for (const std::size_t s : nonempty_spans(U, p)) {
    Vector<T, E> m{};
    for (std::size_t j = s - static_cast<std::size_t>(p); j <= s; ++j)
      for (int k = 0; k < E; ++k) m[k] = std::max(m[k], std::abs(P[j][k]));
    out.push_back(static_cast<T>(4 * p + 1) * eps * m);
  }
  return out;
}

/// The pieces' own rounding (PieceError) of a curve for solve, one per piece that c
/// contributes to p from p.segments()[first] on (p = pieces(c) and first = 0 for a curve by
/// itself; a path's segments in turn), relative to the curve `eval` evaluates; empty where
/// every piece is the curve's definition (Bézier and rational Bézier curves, polylines,
/// Pieces, Catmull-Rom curves: eval evaluates the Bézier pieces they hold). The others,
/// each derived in its branch below:
/// - bspline: blossoms of the control points (span_rounding);
/// - nurbs (and circle, ellipse, arc, which are NURBS): blossoms of the homogeneous points
///   H_j = w_j P_j 2^-e, each a product rounded once (u = eps / 2 of |H_jk|; eval starts
///   from these H_j, so this much is relative to the control points as given); the weights
///   are exact. The pieces hold P = H / w (relative = u, the division);
/// - hermite and cubic_spline (whose eval is its Hermite form): P_i + (h / 3) m_i and
///   P_(i+1) - (h / 3) m'_(i+1), h = u_(i+1) - u_i;
/// - lagrange (eval by the barycentric formula; the piece by collocation): a bound from the
///   collocation's residual, computed here (lagrange_rounding).
/// A path: its segments' in turn. Only a Lagrange piece is read from p (the others'
/// bounds come from the curve's own data), so that no piece is computed twice.
template <class C>
std::vector<PieceError<typename C::Scalar, C::dimension>> piece_errors(const C& c, const Pieces<typename C::Scalar, C::dimension>& p,
                                                                       std::size_t first = 0);


/// The Lagrange curve's one piece (its Bézier form by collocation, b) against the exact
/// interpolant p of its points: the error e = q - p of the computed polynomial q is a
/// polynomial of the same degree n whose Bernstein coefficients are A^-1 r, A_jk =
/// B_(k,n)(s_j) at the nodes mapped to [0, 1] and r_j = q(s_j) - P_j its values there, so
/// each is at most ||A^-1||_inf max_j |r_j|. The residual is computed about c = b_0 (the
/// curve's point at the domain's start, exact): r_j = (q - c)(s_j) - (P_j - c), so that
/// its rounding is relative to the variation V_k = max_i |b_ik - c_k|, not to the
/// coordinates: b_i - c and P_j - c round by u V (u = eps / 2), de Casteljau on them by
/// n levels of 3 u V (the rounded 1 - s, two products, a sum), the node s_j (two
/// differences and a quotient, 3 u) moves q by at most |q'| 3 u <= 2 n V 3 u, and the
/// last difference rounds by u |r|: in all |r_j| <= |computed r_j| (1 + 2 eps) +
/// (2 + 4.5 n) eps V. ||A^-1|| is computed (Eigen's full-pivoting LU) and doubled for its own
/// rounding, a safety factor that is not a proof (measured: docs/cli.md). O(n^3), n <= 15.
template <class T, int D>
PieceError<T, D> lagrange_rounding(const Lagrange<T, D>& c, const Bezier<T, D>& q) {
  const auto& b = q.points();
  const std::size_t n1 = b.size();
  PieceError<T, D> out;
  if (n1 <= 1) return out;
  const int n = static_cast<int>(n1) - 1;
  const T eps = std::numeric_limits<T>::epsilon();
  const Interval<T> dom = c.domain();
  const auto& u = c.params();
  const auto& P = c.points();
  const Point<T, D>& c0 = b.front();
  std::vector<Vector<T, D>> d(n1);
  Vector<T, D> V{};
  for (std::size_t i = 0; i < n1; ++i) {
    d[i] = b[i] - c0;
    for (int k = 0; k < D; ++k) V[k] = std::max(V[k], std::abs(d[i][k]));
  }
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> A(static_cast<Eigen::Index>(n1), static_cast<Eigen::Index>(n1));
  std::vector<T> row(n1);
  Vector<T, D> r{};
  for (std::size_t j = 0; j < n1; ++j) {
    const T sj = (u[j] - dom.lo) / (dom.hi - dom.lo);
    bernstein_all<T>(n, sj, std::span<T>(row));
    for (std::size_t k = 0; k < n1; ++k) A(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) = row[k];
    std::vector<Vector<T, D>> w(d);  // de Casteljau on the differences
    for (std::size_t level = 1; level < n1; ++level)
      for (std::size_t i = 0; i + level < n1; ++i) w[i] = lerp(w[i], w[i + 1], sj);
    const Vector<T, D> rj = w[0] - (P[j] - c0);
    for (int k = 0; k < D; ++k) r[k] = std::max(r[k], std::abs(rj[k]));
  }
  // ||A^-1||_inf, the largest row sum of |A^-1| (LU with full pivoting; infinite where A
  // is singular to rounding).
  const Eigen::FullPivLU<Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>> lu(A);
  const T norm = lu.isInvertible() ? lu.inverse().cwiseAbs().rowwise().sum().maxCoeff() : std::numeric_limits<T>::infinity();
  for (int k = 0; k < D; ++k) out.coordinate[k] = 2 * norm * (r[k] * (1 + 2 * eps) + (2 + T(4.5) * n) * eps * V[k]);
  return out;
}

/// How many pieces pieces(c) has, without computing them (a path's segment in piece_errors).
template <class C>
std::size_t piece_count(const C& c) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  if constexpr (std::is_same_v<C, BSpline<T, D>> || std::is_same_v<C, Nurbs<T, D>>) {
    return nonempty_spans(std::span<const T>(c.knots()), c.degree()).size();
  } else if constexpr (std::is_same_v<C, Hermite<T, D>> || std::is_same_v<C, Polyline<T, D>>) {
    return c.size();
  } else if constexpr (std::is_same_v<C, CubicSpline<T, D>>) {
    return c.hermite().size();
  } else if constexpr (std::is_same_v<C, CatmullRom<T, D>>) {
    return c.bezier_pieces().size();
  } else {
    static_assert(is_bezier_piece<C> || std::is_same_v<C, Lagrange<T, D>>, "a segment type with one piece");
    return 1;
  }
}

template <class C>
std::vector<PieceError<typename C::Scalar, C::dimension>> piece_errors(const C& c, const Pieces<typename C::Scalar, C::dimension>& p,
                                                                       std::size_t first) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const T eps = std::numeric_limits<T>::epsilon();
  std::vector<PieceError<T, D>> out;
  if constexpr (std::is_same_v<C, BSpline<T, D>>) {
    for (const auto& e : span_rounding<T, D>(std::span<const T>(c.knots()), c.degree(), std::span<const Point<T, D>>(c.points())))
      out.push_back({e, T(0), T(0)});
  } else if constexpr (std::is_same_v<C, Nurbs<T, D>>) {
    // The homogeneous B-spline's blossoms, plus u |H_jk| for H_j = w_j P_j (rounded once;
    // convex combinations carry it to the pieces unchanged): 4 p + 1.5 eps on the
    // coordinates, 4 p + 1 on the weights (given exactly, scaled by a power of two).
    const auto& h = c.homogeneous();
    for (const auto& e : span_rounding<T, D + 1>(std::span<const T>(h.knots()), h.degree(), std::span<const Point<T, D + 1>>(h.points()))) {
      PieceError<T, D> x;
      const T grow = (4 * static_cast<T>(h.degree()) + T(1.5)) / (4 * static_cast<T>(h.degree()) + 1);
      for (int k = 0; k < D; ++k) x.coordinate[k] = e[k] * grow;
      x.weight = e[D];
      x.relative = eps / 2;  // P = H / w, one division
      out.push_back(x);
    }
  } else if constexpr (std::is_same_v<C, Hermite<T, D>>) {
    // t = fl(fl(fl(u_(i+1) - u_i) / 3) m) is within 3u (1 + 4u) |t| of h m / 3, and the
    // sum P + t rounds by u of itself: relative u on each point, 3u |t| absolute.
    const auto& u = c.params();
    const auto& in = c.incoming_tangents();
    for (std::size_t i = 0; i < c.size(); ++i) {
      const T h3 = (u[i + 1] - u[i]) / 3;
      PieceError<T, D> x;
      for (int k = 0; k < D; ++k)
        x.coordinate[k] = T(1.5) * eps * (1 + 4 * eps) * std::max(std::abs(h3 * c.tangents()[i][k]), std::abs(h3 * in[i + 1][k]));
      x.relative = eps / 2;
      out.push_back(x);
    }
  } else if constexpr (std::is_same_v<C, CubicSpline<T, D>>) {
    return piece_errors(c.hermite(), p, first);
  } else if constexpr (std::is_same_v<C, Lagrange<T, D>>) {
    out.push_back(lagrange_rounding(c, std::get<Bezier<T, D>>(p.segments()[first])));
  } else if constexpr (requires { c.segments(); } && !is_pieces<C>) {
    std::size_t at = first;
    for (const auto& seg : c.segments()) {
      std::visit(
          [&](const auto& x) {
            const std::size_t count = piece_count(x);
            auto e = piece_errors(x, p, at);
            e.resize(count);  // zeros for a segment whose pieces are its definition
            out.insert(out.end(), e.begin(), e.end());
            at += count;
          },
          seg);
    }
    if (std::all_of(out.begin(), out.end(), [](const PieceError<T, D>& e) { return e.weight == 0 && e.relative == 0 && e.coordinate == Vector<T, D>{}; }))
      out.clear();
  }
  return out;
}

}  // namespace detail

/// Every parameter of the domain where a . C(t) = value (a coordinate k = value when a is
/// the unit vector e_k), written once on the curve's exact Bézier pieces. On each piece the
/// scalar polynomial a . P_i - value (rational pieces: w_i (a . P_i - value), the
/// numerator over the positive weight function) is formed in Bernstein form with a known
/// error per coefficient (detail::level_form: compensated, relative to the coefficient
/// itself), plus what the pieces' own rounding `errors` (one detail::PieceError per piece,
/// or none: pieces that are the curve's definition) may move it by. That sum is the noise:
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
                                   std::span<const detail::PieceError<typename C::Scalar, C::dimension>> errors) {
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
  // Each piece's form and noise first: an end's root depends on the next piece's start.
  struct Form {
    std::vector<T> f;
    T noise = 0;
    bool zero = false;
  };
  std::vector<Form> forms(p.size());
  const detail::PieceError<T, D> exact{};
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::visit(
        [&](const auto& piece) {
          std::vector<T> bound;
          Form& g = forms[i];
          g.f = detail::level_form<T, D>(piece, a, value, i < errors.size() ? errors[i] : exact, bound);
          for (const T b : bound) g.noise = std::max(g.noise, b);
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

/// The same, with the pieces' rounding of the curve's type (detail::piece_errors).
template <class C>
  requires PiecewiseBezierCurve<C>
LevelSet<typename C::Scalar> solve(const C& c, const Vector<typename C::Scalar, C::dimension>& a, typename C::Scalar value) {
  const auto& p = pieces(c);
  const auto errors = detail::piece_errors(c, p);
  return solve(p, a, value, std::span<const detail::PieceError<typename C::Scalar, C::dimension>>(errors));
}

}  // namespace casteljau
