// Interpolating cubic splines (C^2 through the data) with natural, clamped, not-a-knot,
// periodic and general end conditions, built in O(n) and stored as Hermite curves; their
// integrals, antiderivatives and, for d = 1, the solutions of y(x) = c.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/hermite_tangents.hpp"

namespace casteljau {

/// One end condition of the general form: the first (order 1) or second (order 2)
/// derivative with respect to the parameter at that end.
template <class T, int D>
struct SplineEnd {
  int order = 2;
  Vector<T, D> value{};
  friend bool operator==(const SplineEnd&, const SplineEnd&) = default;
};

/// The end conditions of a cubic spline. natural: second derivatives 0 at both ends;
/// clamped: given first derivatives; not_a_knot: the third derivative continuous at the
/// second and the second-to-last params (the first two and last two pieces are one cubic
/// each); periodic: first and second derivatives equal at both ends (the first and last
/// points must be equal); general: `start` and `end` each give a first or second
/// derivative. natural and clamped are kept apart from general only to write them back as
/// given; `start` and `end` hold their values.
template <class T, int D>
struct SplineBoundary {
  enum class Kind { natural, clamped, not_a_knot, periodic, general };
  Kind kind = Kind::natural;
  SplineEnd<T, D> start{};
  SplineEnd<T, D> end{};

  static SplineBoundary natural() { return {}; }
  static SplineBoundary clamped(const Vector<T, D>& a, const Vector<T, D>& b) { return {Kind::clamped, {1, a}, {1, b}}; }
  static SplineBoundary not_a_knot() { return {Kind::not_a_knot, {}, {}}; }
  static SplineBoundary periodic() { return {Kind::periodic, {}, {}}; }
  static SplineBoundary general(const SplineEnd<T, D>& a, const SplineEnd<T, D>& b) { return {Kind::general, a, b}; }
  friend bool operator==(const SplineBoundary&, const SplineBoundary&) = default;
};

namespace detail {

/// Solves the tridiagonal system a_i x_(i-1) + b_i x_i + c_i x_(i+1) = r_i (a_0 and
/// c_(m-1) unused) by Thomas' algorithm (Gaussian elimination without pivoting)
/// [GolubVanLoan13, 4.3.6], in place on r (the solution) and b (overwritten), O(m). Stable for the spline systems: their
/// interior rows are strictly diagonally dominant (2 (h_(i-1) + h_i) > h_(i-1) + h_i), and
/// the pivots stay >= the row's off-diagonal sum. Throws NumericalError for a zero or
/// non-finite pivot (not reached by the spline systems).
inline constexpr const char* tridiagonal_pivot_message =
    "the spline's linear system has a zero or non-finite pivot (parameters too close together or too far apart)";

template <class T, class V>
void solve_tridiagonal(const std::vector<T>& a, std::vector<T>& b, const std::vector<T>& c, std::vector<V>& r) {
  const std::size_t m = b.size();
  for (std::size_t i = 1; i < m; ++i) {
    if (!(b[i - 1] != 0) || !std::isfinite(b[i - 1])) throw NumericalError(tridiagonal_pivot_message);
    const T w = a[i] / b[i - 1];
    b[i] -= w * c[i - 1];
    r[i] -= w * r[i - 1];
  }
  if (!(b[m - 1] != 0) || !std::isfinite(b[m - 1])) throw NumericalError(tridiagonal_pivot_message);
  r[m - 1] /= b[m - 1];
  for (std::size_t i = m - 1; i-- > 0;) r[i] = (r[i] - c[i] * r[i + 1]) / b[i];
}

/// Solves the cyclic tridiagonal system (row 0 also has a_0 x_(m-1), row m-1 also c_(m-1)
/// x_0; m >= 3) by the Sherman-Morrison formula on two tridiagonal solves [NR07, 2.7.2]:
/// the corner entries move into a rank-one update, the modified diagonal (b_0 - g,
/// b_(m-1) - c_(m-1) a_0 / g with g = -b_0) stays dominant. O(m).
template <class T, class V>
void solve_cyclic(const std::vector<T>& a, std::vector<T> b, const std::vector<T>& c, std::vector<V>& r) {
  const std::size_t m = b.size();
  const T alpha = c[m - 1], beta = a[0], gamma = -b[0];
  b[0] -= gamma;
  b[m - 1] -= alpha * beta / gamma;
  std::vector<T> z(m, T(0));
  z[0] = gamma;
  z[m - 1] = alpha;
  std::vector<T> b2 = b;  // both solves need the modified diagonal
  solve_tridiagonal(a, b, c, r);
  solve_tridiagonal(a, b2, c, z);
  const V fact = (r[0] + (beta / gamma) * r[m - 1]) / (1 + z[0] + beta * z[m - 1] / gamma);
  for (std::size_t i = 0; i < m; ++i) r[i] -= z[i] * fact;
}

/// Throws InvalidArgument("points", ...) when a solved slope s_i, or a Bézier control point
/// P_i + h_i s_i / 3, P_(i+1) - h_i s_(i+1) / 3 of the spline is not finite (data so large
/// for its param spacing that the spline's derivative or its bulge overflows), rather
/// than leaving the Hermite constructor to name "tangents", which the user did not give.
template <class T, int D>
void require_representable_spline(const std::vector<T>& u, const std::vector<Point<T, D>>& P, const std::vector<Vector<T, D>>& s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!all_coordinates_finite(s[i])) {
      throw InvalidArgument("points", "the spline's slope at points[" + std::to_string(i) +
                                          "] overflows a double (coordinates too large for the param spacing)");
    }
  }
  for (std::size_t i = 0; i + 1 < P.size(); ++i) {
    const T h3 = (u[i + 1] - u[i]) / 3;
    if (!all_coordinates_finite(P[i] + h3 * s[i]) || !all_coordinates_finite(P[i + 1] - h3 * s[i + 1])) {
      throw InvalidArgument("points", "the spline between points[" + std::to_string(i) + "] and points[" + std::to_string(i + 1) +
                                          "] leaves the range of a double (its Bézier control points overflow)");
    }
  }
}

}  // namespace detail

/// The slopes s_0..s_n at the params of the C^2 cubic spline through (u_i, P_i) with the
/// given end conditions: the tridiagonal system of the C^2 conditions [deBoor01, IV (4.4)]
///   h_i s_(i-1) + 2 (h_(i-1) + h_i) s_i + h_(i-1) s_(i+1) = 3 (h_i d_(i-1) + h_(i-1) d_i)
/// (h_i = u_(i+1) - u_i, d_i the chord slopes), with the end rows of scipy 1.10's
/// CubicSpline: first derivative s_0 = v; second derivative 2 s_0 + s_1 = 3 d_0 - v h_0 / 2;
/// not-a-knot h_1 s_0 + (h_0 + h_1) s_1 = ((h_0 + 2 (h_0 + h_1)) h_1 d_0 + h_0^2 d_1) / (h_0 +
/// h_1); likewise at the end; periodic: a cyclic system in s_0..s_(n-1) (s_n = s_0).
/// Small n as scipy: with 2 points not-a-knot and periodic ends become s = d_0 (the line;
/// periodic: the constant); 3 points with not-a-knot at both ends give the parabola, 3
/// periodic points the common slope (h_1 d_0 + h_0 d_1) / (h_0 + h_1). Cost O(n).
/// Throws InvalidArgument naming "points" (fewer than 2), "params[i]" and "points[i]"
/// as Hermite, "points[n]" when periodic ends differ, "boundary.start.order" /
/// "boundary.end.order" for an order other than 1 or 2.
template <class T, int D>
std::vector<Vector<T, D>> cubic_spline_slopes(const std::vector<T>& u, const std::vector<Point<T, D>>& P,
                                               const SplineBoundary<T, D>& bc) {
  using V = Vector<T, D>;
  using Kind = typename SplineBoundary<T, D>::Kind;
  if (P.size() < 2) throw InvalidArgument("points", "a cubic spline needs at least 2 points, got " + std::to_string(P.size()));
  detail::check_rule_data(u, P, 2, "cubic spline");
  const std::size_t n = P.size() - 1;  // pieces
  if (bc.kind == Kind::periodic && !(P[n] == P[0])) {
    throw InvalidArgument("points[" + std::to_string(n) + "]", "must equal points[0] for a periodic boundary");
  }
  for (const auto* e : {&bc.start, &bc.end}) {
    if (e->order != 1 && e->order != 2) {
      throw InvalidArgument(e == &bc.start ? "boundary.start.order" : "boundary.end.order",
                            "the derivative order must be 1 or 2, got " + std::to_string(e->order));
    }
    require_finite_point(e->value, e == &bc.start ? "boundary.start.value" : "boundary.end.value");
  }
  // The C^2, not-a-knot and periodic rows are homogeneous in the spacings: they use h_i
  // scaled by one power of two (exact), so that sums and products of spacings near the
  // largest double (or below 1e-154) neither overflow nor underflow; the rows of a given
  // second derivative use the true spacing hu_i.
  std::vector<T> h(n), hu(n);
  T hmax = 0;
  for (std::size_t i = 0; i < n; ++i) hmax = std::max(hmax, hu[i] = u[i + 1] - u[i]);
  const T sigma = detail::spacing_scale(hmax);
  for (std::size_t i = 0; i < n; ++i) h[i] = hu[i] * sigma;
  const std::vector<V> d = detail::chord_slopes(u, P);
  for (std::size_t i = 0; i < n; ++i) {
    if (!detail::all_coordinates_finite(d[i])) {
      throw InvalidArgument("points", "the chord slope from points[" + std::to_string(i) + "] to points[" + std::to_string(i + 1) +
                                          "] overflows a double (coordinates too large for the param spacing)");
    }
  }

  // The end conditions, with scipy's small-n replacements.
  enum class End { first, second, not_a_knot };
  struct Cond {
    End type;
    V value;
  };
  const auto cond = [&](const SplineEnd<T, D>& e) -> Cond {
    switch (bc.kind) {
      case Kind::not_a_knot: return {End::not_a_knot, V{}};
      case Kind::periodic: return {End::not_a_knot, V{}};  // not used: periodic is solved apart
      default: return {e.order == 1 ? End::first : End::second, e.value};
    }
  };
  Cond cs = cond(bc.start), ce = cond(bc.end);
  if (n == 1) {
    if (bc.kind == Kind::periodic || bc.kind == Kind::not_a_knot) return {d[0], d[0]};
  }
  if (bc.kind == Kind::periodic) {
    if (n == 2) {
      const V s = (h[1] * d[0] + h[0] * d[1]) / (h[0] + h[1]);
      return {s, s, s};
    }
    // Unknowns s_0..s_(n-1); row i couples s_(i-1), s_i, s_(i+1) cyclically.
    std::vector<T> a(n), b(n), c(n);
    std::vector<V> r(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t p = i == 0 ? n - 1 : i - 1;
      a[i] = h[i];
      b[i] = 2 * (h[p] + h[i]);
      c[i] = h[p];
      r[i] = T(3) * (h[i] * d[p] + h[p] * d[i]);
    }
    detail::solve_cyclic(a, b, c, r);
    r.push_back(r[0]);
    detail::require_representable_spline(u, P, r);
    return r;
  }
  if (n == 2 && cs.type == End::not_a_knot && ce.type == End::not_a_knot) {
    // The parabola through the three points: p'(u) = d_0 + q (2u - u_0 - u_1) with q =
    // (d_1 - d_0) / (u_2 - u_0).
    const V q = (d[1] - d[0]) / (h[0] + h[1]);  // with the scaled h: h_i q is the true product
    return {d[0] - h[0] * q, d[0] + h[0] * q, d[0] + (h[0] + 2 * h[1]) * q};
  }
  const std::size_t m = n + 1;
  std::vector<T> a(m, T(0)), b(m, T(0)), c(m, T(0));
  std::vector<V> r(m);
  for (std::size_t i = 1; i < n; ++i) {
    a[i] = h[i];
    b[i] = 2 * (h[i - 1] + h[i]);
    c[i] = h[i - 1];
    r[i] = T(3) * (h[i] * d[i - 1] + h[i - 1] * d[i]);
  }
  switch (cs.type) {
    case End::first: b[0] = 1; c[0] = 0; r[0] = cs.value; break;
    case End::second: b[0] = 2; c[0] = 1; r[0] = T(3) * d[0] - (hu[0] / 2) * cs.value; break;
    case End::not_a_knot: {
      const T s = h[0] + h[1];
      b[0] = h[1];
      c[0] = s;
      r[0] = ((h[0] + 2 * s) * h[1] * d[0] + (h[0] * h[0]) * d[1]) / s;
      break;
    }
  }
  switch (ce.type) {
    case End::first: b[n] = 1; a[n] = 0; r[n] = ce.value; break;
    case End::second: b[n] = 2; a[n] = 1; r[n] = T(3) * d[n - 1] + (hu[n - 1] / 2) * ce.value; break;
    case End::not_a_knot: {
      const T s = h[n - 1] + h[n - 2];
      b[n] = h[n - 2];
      a[n] = s;
      r[n] = ((h[n - 1] * h[n - 1]) * d[n - 2] + (2 * s + h[n - 1]) * h[n - 2] * d[n - 1]) / s;
      break;
    }
  }
  detail::solve_tridiagonal(a, b, c, r);
  detail::require_representable_spline(u, P, r);
  return r;
}

namespace detail {

/// The slopes of a non-periodic cubic spline, as cubic_spline_slopes computes them, in
/// two sweeps over the data and one scratch array: the elimination sweep builds each row
/// of the system from the data as it goes (no arrays of h_i, d_i or of the three
/// diagonals) and eliminates it at once (Thomas' algorithm [GolubVanLoan13, 4.3.6],
/// keeping only the multipliers that substitution needs, one reciprocal per row; from 5
/// rows on from both ends towards the middle row, see below); the substitution sweep
/// checks that the Hermite curve's Bézier control points
/// P_i + h_i s_i / 3 and P_(i+1) - h_i s_(i+1) / 3 are finite. The checks of the data are
/// folded into the sweeps without branches: every h_i in (0, inf) (params finite and
/// strictly increasing), every control point finite (points finite, no overflow; a
/// non-finite point or slope makes some control point non-finite). Returns false, leaving
/// s unspecified, for a case it does not take (periodic; not-a-knot below 4 points, whose
/// small-n forms cubic_spline_slopes gives; an order or end value that is not valid) and
/// for data failing a check: the caller then runs cubic_spline_slopes and the checking
/// Hermite constructor, which name the faulty field. The same spline as
/// cubic_spline_slopes, the same values up to rounding (the order of elimination, the
/// pivot's reciprocal; not-a-knot ends from 6 points on are eliminated as the end cubics'
/// join rows, below, more accurately than cubic_spline_slopes' textbook rows). O(n).
template <class T, int D>
bool cubic_spline_slopes_fused(const std::vector<T>& u, const std::vector<Point<T, D>>& P, const SplineBoundary<T, D>& bc,
                               std::vector<Vector<T, D>>& s) {
  using V = Vector<T, D>;
  using Kind = typename SplineBoundary<T, D>::Kind;
  if (P.size() < 2 || u.size() != P.size() || bc.kind == Kind::periodic) return false;
  const std::size_t n = P.size() - 1;
  const bool nak = bc.kind == Kind::not_a_knot;
  if (nak && n < 3) return false;
  for (const auto* e : {&bc.start, &bc.end}) {
    if (e->order != 1 && e->order != 2) return false;
    if (!all_coordinates_finite(e->value)) return false;
  }
  if (!std::isfinite(u[n] - u[0])) return false;  // also catches a non-finite end param
  const auto hh = [&](std::size_t i) { return u[i + 1] - u[i]; };
  const auto dd = [&](std::size_t i) { return (P[i + 1] - P[i]) / hh(i); };

  // The system solved here is rows f..l in s_f..s_l: row f is b0 s_f + c0 s_(f+1) = r0,
  // row l is an s_(l-1) + bn s_l = rn, the rows between are the C^2 rows. Natural and
  // clamped ends, and not-a-knot below 6 points: f = 0, l = n, the end rows of
  // cubic_spline_slopes. Not-a-knot from 6 points on: f = 2, l = n - 2. scipy's not-a-knot
  // row h_1 s_0 + (h_0 + h_1) s_1 = ... is not diagonally dominant, and eliminating it
  // loses digits when h_0 and h_1 differ much (one-way and twisted elimination alike, and
  // LAPACK's partial pivoting, which ties on its first column): hundreds of ulps in the end
  // slopes at a ratio of 10^3, which the power form's cubic coefficient of an end piece
  // amplifies far outside the domain. Here the first two pieces are taken as the one cubic
  // on [u_0, u_2] that not-a-knot makes them: through P_0, P_1, P_2 with slope s_2 at u_2
  // (Newton's form on the nodes u_2, u_2, u_1, u_0), whose C^2 join with piece 2, times
  // h_1 h_2 / 2, is the row
  //   (h_2 (1 + rho) + 2 h_1) s_2 + h_1 s_3 = h_2 ((1 + rho) d_1 + rho^2 (d_1 - d_0)) + 3 h_1 d_2,
  // rho = h_1 / (h_0 + h_1), strictly diagonally dominant as every C^2 row; after the solve
  // s_0 and s_1 are that cubic's slopes (end_slopes below); likewise at the end, mirrored.
  // The same spline (the C^2 row at u_1 holds within the one cubic); end slopes within a
  // few ulps of the exact solve's where the textbook rows were tens to hundreds off
  // (measured against the solve in rational arithmetic, docs/python.md).
  const bool reduced = nak && n >= 5;
  const std::size_t f = reduced ? 2 : 0, l = reduced ? n - 2 : n;
  const T big = std::ldexp(T(1), 500), tiny = std::ldexp(T(1), -500);
  bool ok = true;
  // A slope below the normal range (a coordinate that moves by less than 2.2e-308 h) goes
  // to the checked path too, which refuses a chord whose whole slope underflows.
  constexpr T smallest = std::numeric_limits<T>::min();
  const auto slope_ok = [&](const V& d, std::size_t i) {
    bool good = true;
    for (int k = 0; k < D; ++k) good = good && (std::abs(d[k]) >= smallest || P[i + 1][k] == P[i][k]);
    return good;
  };
  // Spacing i and its chord slope, checked (see below).
  const auto interval = [&](std::size_t i, T& h, V& d) {
    h = u[i + 1] - u[i];
    ok &= (h >= tiny) & (h <= big);
    d = (P[i + 1] - P[i]) / h;
    ok &= slope_ok(d, i);
  };
  T b0, c0, an, bn;
  V r0, rn;
  // not-a-knot from 6 points: the spacings and chord slopes of the two end cubics, a =
  // (h_0, h_1, h_2) and (d_0, d_1, d_2) at the start, b the mirrored ones at the end.
  T ha[3] = {}, hb[3] = {};
  V da[3] = {}, db[3] = {};
  if (reduced) {
    for (std::size_t j = 0; j < 3; ++j) {
      interval(j, ha[j], da[j]);
      interval(n - 1 - j, hb[j], db[j]);
    }
    // The join row at u_2 (above) and, mirrored, at u_(n-2): the mirror negates the slopes
    // on both sides, so the row keeps its form with h_(n-1-j), d_(n-1-j) for h_j, d_j.
    const auto join = [](const T* h, const V* d, T& diag, T& off, V& rhs) {
      const T rho = h[1] / (h[0] + h[1]);
      diag = h[2] * (1 + rho) + 2 * h[1];
      off = h[1];
      rhs = h[2] * ((1 + rho) * d[1] + (rho * rho) * (d[1] - d[0])) + T(3) * h[1] * d[2];
    };
    join(ha, da, b0, c0, r0);
    join(hb, db, bn, an, rn);
  } else if (nak) {
    const T h0 = hh(0), h1 = hh(1), s0 = h0 + h1;
    b0 = h1;
    c0 = s0;
    r0 = ((h0 + 2 * s0) * h1 * dd(0) + (h0 * h0) * dd(1)) / s0;
    const T g0 = hh(n - 1), g1 = hh(n - 2), s1 = g0 + g1;
    bn = g1;
    an = s1;
    rn = ((g0 * g0) * dd(n - 2) + (2 * s1 + g0) * g1 * dd(n - 1)) / s1;
  } else {
    if (bc.start.order == 1) {
      b0 = 1, c0 = 0, r0 = bc.start.value;
    } else {
      b0 = 2, c0 = 1, r0 = T(3) * dd(0) - (hh(0) / 2) * bc.start.value;
    }
    if (bc.end.order == 1) {
      bn = 1, an = 0, rn = bc.end.value;
    } else {
      bn = 2, an = 1, rn = T(3) * dd(n - 1) + (hh(n - 1) / 2) * bc.end.value;
    }
  }

  s.resize(n + 1);
  const auto w = std::make_unique_for_overwrite<T[]>(n + 1);  // the multipliers, not zeroed first
  // Spacings outside [2^-500, 2^500] go to cubic_spline_slopes, which scales them: here
  // their sums and products (2 (h + h), h0 h0 in the not-a-knot rows) would overflow or
  // underflow.
  // The Bézier control points' finiteness accumulates in acc (x * 0 is 0 for finite x, NaN
  // otherwise); piece i is checked once s_i and s_(i+1) are final.
  T acc = 0;
  const auto check_piece = [&](std::size_t i) {
    const T h3 = (u[i + 1] - u[i]) / 3;
    const Point<T, D> a = P[i] + h3 * s[i], b = P[i + 1] - h3 * s[i + 1];
    for (int k = 0; k < D; ++k) acc += a[k] * 0 + b[k] * 0;
  };
  // The slopes of an end cubic (not-a-knot from 6 points) from the solved slope at its far
  // end, the join's: on [u_0, u_2] with tau = h_0 / (h_0 + h_1), rho = h_1 / (h_0 + h_1),
  //   s_1 = d_1 - tau (s_2 - d_1) - rho^2 (d_1 - d_0),
  //   s_0 = d_0 - 2 tau (d_1 - d_0) + (h_0 / h_1) (s_2 - d_1)
  // (the derivatives of Newton's form at u_1 and u_0); at the end mirrored (the slopes'
  // signs cancel). Then its two pieces are checked.
  const auto end_slopes = [&](const T* h, const V* d, const V& joint, V& inner, V& outer) {
    const T sum = h[0] + h[1], tau = h[0] / sum, rho = h[1] / sum;
    const V e = joint - d[1], dd01 = d[1] - d[0];
    inner = d[1] - tau * e - (rho * rho) * dd01;
    outer = d[0] - (2 * tau) * dd01 + (h[0] / h[1]) * e;
  };
  // Row i (0 < i < n): h_i s_(i-1) + 2 (h_(i-1) + h_i) s_i + h_(i-1) s_(i+1) = 3 (h_i d_(i-1) + h_(i-1) d_i).
  T inv = 1 / b0;
  w[f] = c0 * inv;
  s[f] = r0 * inv;
  T hl;  // the downward sweep's h_(i-1), d_(i-1)
  V dl;
  interval(f, hl, dl);
  const auto down = [&](std::size_t i) {  // eliminates x_(i-1) from row i: x_i + w_i x_(i+1) = s_i
    T h;
    V d;
    interval(i, h, d);
    const T r = 1 / (2 * (hl + h) - h * w[i - 1]);
    w[i] = hl * r;
    s[i] = (T(3) * (h * dl + hl * d) - h * s[i - 1]) * r;
    hl = h;
    dl = d;
  };
  const auto finish = [&] {
    if (reduced) {
      end_slopes(ha, da, s[2], s[1], s[0]);
      end_slopes(hb, db, s[n - 2], s[n - 1], s[n]);
      for (const std::size_t i : {std::size_t(0), std::size_t(1), n - 2, n - 1}) check_piece(i);
    }
    return ok && acc == 0;
  };
  if (l - f < 4) {
    for (std::size_t i = f + 1; i < l; ++i) down(i);
    const T pivot = bn - an * w[l - 1];
    ok &= std::isfinite(pivot) & (pivot != 0);
    s[l] = (rn - an * s[l - 1]) / pivot;
    for (std::size_t i = l; i-- > f;) {
      s[i] -= w[i] * s[i + 1];
      check_piece(i);
    }
    return finish();
  }
  // A twisted factorization [ParlettDhillon97]: downward from row f to row k - 1 and upward
  // from row l to row k + 1 in the same loop, two independent chains (each step waits for
  // the division of the one before it), met at row k; then substitution outward from x_k,
  // again two chains. Each sweep meets the same diagonally dominant rows as one-way
  // elimination does, the end row first (as the downward sweep meets row f).
  const std::size_t k = (f + l) / 2;
  inv = 1 / bn;
  w[l] = an * inv;
  s[l] = rn * inv;
  T hr;  // the upward sweep's h_i, d_i
  V dr;
  interval(l - 1, hr, dr);
  const auto up = [&](std::size_t i) {  // eliminates x_(i+1) from row i: x_i + w_i x_(i-1) = s_i
    T g;
    V e;
    interval(i - 1, g, e);
    const T r = 1 / (2 * (g + hr) - g * w[i + 1]);
    w[i] = hr * r;
    s[i] = (T(3) * (hr * e + g * dr) - g * s[i + 1]) * r;
    hr = g;
    dr = e;
  };
  std::size_t top = f + 1, bottom = l - 1;
  for (; top < k && bottom > k; ++top, --bottom) {
    down(top);
    up(bottom);
  }
  for (; top < k; ++top) down(top);
  for (; bottom > k; --bottom) up(bottom);
  // Row k with x_(k-1) = s_(k-1) - w_(k-1) x_k and x_(k+1) = s_(k+1) - w_(k+1) x_k; here
  // hl, dl = h_(k-1), d_(k-1) and hr, dr = h_k, d_k.
  const T pivot = 2 * (hl + hr) - hr * w[k - 1] - hl * w[k + 1];
  ok &= std::isfinite(pivot) & (pivot != 0);
  s[k] = (T(3) * (hr * dl + hl * dr) - hr * s[k - 1] - hl * s[k + 1]) / pivot;
  std::size_t i = k, j = k;
  for (; i > f && j < l; --i, ++j) {
    s[i - 1] -= w[i - 1] * s[i];
    check_piece(i - 1);
    s[j + 1] -= w[j + 1] * s[j];
    check_piece(j);
  }
  for (; i > f; --i) {
    s[i - 1] -= w[i - 1] * s[i];
    check_piece(i - 1);
  }
  for (; j < l; ++j) {
    s[j + 1] -= w[j + 1] * s[j];
    check_piece(j);
  }
  return finish();
}

}  // namespace detail

/// The interpolating C^2 cubic spline through (u_i, P_i), i = 0..n (n >= 1), with the end
/// conditions of SplineBoundary (default natural); d = 1 is the classic y(x) spline, d >= 2
/// a parametric curve (periodic: closed). Stored as the Hermite curve of its values and
/// slopes (cubic_spline_slopes), which it shares for evaluation (binary search, or a
/// linear merge for sorted batches), derivatives (orders 1..3, zero above; the right piece
/// answers at a param, the last one at u_n), extrapolation and the exact Bézier pieces.
/// reverse() and transform() act on that Hermite form (no new solve): reversing swaps
/// the end conditions (first derivatives negated), an affine map maps the derivative
/// values by its linear part; either way the result is the spline of the mapped data.
template <class T, int D>
class CubicSpline {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using Boundary = SplineBoundary<T, D>;
  static constexpr int dimension = D;

  /// Throws as cubic_spline_slopes.
  CubicSpline(std::vector<T> params, std::vector<PointType> points, Boundary boundary = Boundary::natural())
      : bc_(boundary), h_(make(std::move(params), std::move(points), boundary)) {}

  [[nodiscard]] const Boundary& boundary() const { return bc_; }
  /// The spline as a Hermite curve (its values and slopes at the params).
  [[nodiscard]] const Hermite<T, D>& hermite() const { return h_; }
  [[nodiscard]] const std::vector<T>& params() const { return h_.params(); }
  [[nodiscard]] const std::vector<PointType>& points() const { return h_.points(); }
  /// The first derivatives at the params.
  [[nodiscard]] const std::vector<VectorType>& slopes() const { return h_.tangents(); }
  [[nodiscard]] std::size_t size() const { return h_.size(); }
  [[nodiscard]] Interval<T> domain() const { return h_.domain(); }

  [[nodiscard]] PointType operator()(T u) const { return h_(u); }
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const { return h_.derivative_at(u, k); }
  [[nodiscard]] std::vector<PointType> evaluate_sorted(std::span<const T> u) const { return h_.evaluate_sorted(u); }
  void evaluate_sorted(std::span<const T> u, std::span<PointType> out) const { h_.evaluate_sorted(u, out); }
  /// Random (unsorted) batches: Hermite::evaluate.
  void evaluate(std::span<const T> u, std::span<PointType> out) const { h_.evaluate(u, out); }

  [[nodiscard]] CubicSpline reverse() const {
    Boundary b = bc_;
    std::swap(b.start, b.end);
    if (b.start.order == 1) b.start.value = -b.start.value;
    if (b.end.order == 1) b.end.value = -b.end.value;
    return CubicSpline(b, h_.reverse());
  }

  [[nodiscard]] CubicSpline transform(const Affine<T, D>& m) const {
    Boundary b = bc_;
    b.start.value = m(b.start.value);
    b.end.value = m(b.end.value);
    return CubicSpline(b, h_.transform(m));
  }

  [[nodiscard]] Box<T, D> control_bounds() const { return h_.control_bounds(); }

  friend bool operator==(const CubicSpline&, const CubicSpline&) = default;

 private:
  CubicSpline(const Boundary& b, Hermite<T, D> h) : bc_(b), h_(std::move(h)) {}

  /// The fused solve (checks included) when it takes the case, else cubic_spline_slopes and
  /// the checking Hermite constructor, which throw naming the field.
  static Hermite<T, D> make(std::vector<T> u, std::vector<PointType> P, const Boundary& b) {
    std::vector<VectorType> s;
    if (detail::cubic_spline_slopes_fused(u, P, b, s)) return Hermite<T, D>(detail::Unchecked{}, std::move(u), std::move(P), std::move(s));
    s = cubic_spline_slopes(u, P, b);
    detail::require_representable_spline(u, P, s);  // also the small-n forms
    return Hermite<T, D>(std::move(u), std::move(P), std::move(s));
  }

  Boundary bc_;
  Hermite<T, D> h_;
};

template <class T, int D>
Pieces<T, D> pieces(const CubicSpline<T, D>& c) {
  return pieces(c.hermite());
}

static_assert(DifferentiableCurve<CubicSpline<double, 2>>);
static_assert(Curve<CubicSpline<double, 1>>);
static_assert(PiecewiseBezierCurve<CubicSpline<double, 2>>);

/// The antiderivative F(u) = integral from u_0 to u of C, as exact quartic Bézier pieces
/// on the same breaks (a "curve" whose points are the integral vectors): on a piece with
/// control points Q_0..Q_3 and length h, F's control points are F(u_i) + (h / 4) (Q_0 +
/// ... + Q_(j-1)), j = 0..4 [Farin02, 5.3 integral of a Bernstein polynomial]. Outside
/// the domain the end pieces extend (the integral of the extrapolated cubics). Cost O(n).
template <class T, int D>
Pieces<T, D> antiderivative(const Hermite<T, D>& c) {
  std::vector<BezierPiece<T, D>> segs;
  segs.reserve(c.size());
  Point<T, D> F{};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const T h4 = (c.params()[i + 1] - c.params()[i]) / 4;
    const Bezier<T, D> piece = c.piece(i);  // bound to a local: points() refers into it
    const auto& Q = piece.points();
    std::vector<Point<T, D>> R(5);
    R[0] = F;
    for (std::size_t j = 0; j < 4; ++j) R[j + 1] = R[j] + h4 * Q[j].to_vector();
    F = R[4];
    segs.emplace_back(Bezier<T, D>(std::move(R)));
  }
  return Pieces<T, D>(std::move(segs), c.params());
}
template <class T, int D>
Pieces<T, D> antiderivative(const CubicSpline<T, D>& c) {
  return antiderivative(c.hermite());
}

/// The integral of C from a to b (any finite a, b; b < a gives the negative), as
/// F(b) - F(a) on the antiderivative. Error a few eps of the integral of |C| over the
/// span of [u_0, a, b]. Throws InvalidArgument("a" / "b", ...) for non-finite bounds.
template <class T, int D>
Vector<T, D> integral(const Hermite<T, D>& c, T a, T b) {
  require_finite(a, "a");
  require_finite(b, "b");
  const Pieces<T, D> F = antiderivative(c);
  return F(b) - F(a);
}
template <class T, int D>
Vector<T, D> integral(const CubicSpline<T, D>& c, T a, T b) {
  return integral(c.hermite(), a, b);
}

/// The solutions of y(u) = value over the domain of a 1-D Hermite curve or spline.
struct Solutions {
  std::vector<double> t;                   ///< isolated solutions, ascending
  std::vector<Interval<double>> intervals; ///< pieces on which y is identically the value
};

/// Every u in the domain with y(u) = value, as scipy's PPoly.solve (with extrapolate off):
/// on each piece the roots of the Bézier form Q_j - value by basis/roots.hpp
/// (bernstein_roots: subdivision and a bracketed solve, a few eps of the piece's
/// parameter), lifted to the params; a root at a shared param is reported once; a piece
/// on which y equals the value throughout is reported in `intervals` (scipy gives NaN
/// there). Accuracy and the multiple-root caveats are bernstein_roots'. Throws
/// InvalidArgument("value", ...) for a non-finite value.
template <class T>
Solutions solve(const Hermite<T, 1>& c, T value) {
  require_finite(value, "value");
  Solutions s;
  const auto& u = c.params();
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Bezier<T, 1> piece = c.piece(i);  // bound to a local: points() refers into it
    const auto& Q = piece.points();
    std::vector<T> coef(4);
    for (std::size_t j = 0; j < 4; ++j) coef[j] = Q[j][0] - value;
    if (coef[0] == 0 && coef[1] == 0 && coef[2] == 0 && coef[3] == 0) {
      s.intervals.push_back({static_cast<double>(u[i]), static_cast<double>(u[i + 1])});
      continue;
    }
    for (const T t : bernstein_roots<T>(coef)) {
      const T x = t == 0 ? u[i] : t == 1 ? u[i + 1] : u[i] + t * (u[i + 1] - u[i]);
      if (!s.t.empty() && static_cast<double>(x) <= s.t.back()) continue;  // the shared param, once
      s.t.push_back(static_cast<double>(x));
    }
  }
  return s;
}
template <class T>
Solutions solve(const CubicSpline<T, 1>& c, T value) {
  return solve(c.hermite(), value);
}

}  // namespace casteljau
