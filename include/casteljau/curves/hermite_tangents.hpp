// Tangent rules for Hermite interpolation: the derivatives at the data points from the
// data alone (finite differences, Catmull-Rom, cardinal, Kochanek-Bartels, monotone PCHIP,
// Akima), each returning one tangent per point with respect to the parameter.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/curves/hermite.hpp"

namespace casteljau {

namespace detail {

/// Checks params (n >= min_points, finite, strictly increasing) and one point per param;
/// the Hermite constructor repeats these checks, the rules need them first.
template <class T, int D>
void check_rule_data(const std::vector<T>& u, const std::vector<Point<T, D>>& P, std::size_t min_points, const char* rule) {
  if (P.size() < min_points) {
    throw InvalidArgument("points", std::string("the ") + rule + " tangent rule needs at least " + std::to_string(min_points) +
                                        " points, got " + std::to_string(P.size()));
  }
  if (u.size() != P.size()) {
    throw InvalidArgument("points", "needs one point per param: " + std::to_string(u.size()) + " params but " +
                                        std::to_string(P.size()) + " points");
  }
  // Messages (and their strings) only for the element that fails: O(n) without allocation.
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (std::isfinite(u[i]) && (i == 0 || u[i] > u[i - 1])) continue;
    const std::string where = "params[" + std::to_string(i) + "]";
    require_finite(u[i], where);
    throw InvalidArgument(where, "params must be strictly increasing (" + format_number(u[i]) + " after " + format_number(u[i - 1]) + ")");
  }
  if (!std::isfinite(u.back() - u.front())) {
    throw InvalidArgument("params", "the domain [" + format_number(u.front()) + ", " + format_number(u.back()) +
                                        "] is longer than the largest double");
  }
  for (std::size_t i = 0; i < P.size(); ++i)
    if (!all_coordinates_finite(P[i])) require_finite_point(P[i], "points[" + std::to_string(i) + "]");
  // Every chord's slope must be a double: not overflowing, and keeping at least 43 of its
  // 53 bits when the points differ (not below 2^-1032 = 2.2e-311: a subnormal slope 2^-k
  // below the normal range keeps 53 - k bits, and the curve's shape would carry that
  // error; params 1e200 apart with coordinates 1e-200 give slopes 1e-400, which round to
  // 0). The general solve and every rule run this check; the fused spline solve hands
  // any subnormal slope to them.
  for (std::size_t i = 0; i + 1 < P.size(); ++i) {
    const Vector<T, D> d = slope(P[i], P[i + 1], u[i + 1] - u[i]);
    T dmax = 0, pmax = 0;
    for (int k = 0; k < D; ++k) {
      dmax = std::max(dmax, std::abs(d[k]));
      pmax = std::max(pmax, std::abs(P[i + 1][k] - P[i][k]));
    }
    if (!std::isfinite(dmax)) {
      throw InvalidArgument("points", "the chord slope from points[" + std::to_string(i) + "] to points[" + std::to_string(i + 1) +
                                          "] overflows a double (coordinates too large for the param spacing)");
    }
    if (pmax > 0 && dmax < std::ldexp(std::numeric_limits<T>::min(), -10)) {
      throw InvalidArgument("points", "the chord slope from points[" + std::to_string(i) + "] to points[" + std::to_string(i + 1) + "] = " +
                                          format_number(dmax) + " underflows a double (coordinates too small for the param spacing)");
    }
  }
}

/// The chord slopes d_i = (P_(i+1) - P_i) / (u_(i+1) - u_i), i = 0..n-1 (slope: no overflow
/// in the differences).
template <class T, int D>
std::vector<Vector<T, D>> chord_slopes(const std::vector<T>& u, const std::vector<Point<T, D>>& P) {
  std::vector<Vector<T, D>> d(P.size() - 1);
  for (std::size_t i = 0; i + 1 < P.size(); ++i) d[i] = slope(P[i], P[i + 1], u[i + 1] - u[i]);
  return d;
}

/// Throws InvalidArgument("points", ...) when a computed tangent is not finite (data so
/// large for its param spacing that a slope overflows).
template <class T, int D>
void require_finite_tangents(const std::vector<Vector<T, D>>& m, const char* rule) {
  for (std::size_t i = 0; i < m.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      if (!std::isfinite(m[i][k])) {
        throw InvalidArgument("points", std::string("the ") + rule + " tangent at points[" + std::to_string(i) +
                                            "] overflows a double (coordinates too large for the param spacing)");
      }
    }
  }
}

/// One coordinate of every point, as a plain array.
template <class T, int D>
std::vector<T> coordinate(const std::vector<Point<T, D>>& P, int k) {
  std::vector<T> y(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) y[i] = P[i][k];
  return y;
}

/// (b - a) / h for scalars, as slope: at half scale when b - a overflows.
template <class T>
T scalar_slope(T a, T b, T h) {
  const T v = b - a;
  if (std::isfinite(v)) [[likely]]
    return v / h;
  return ((b / 2 - a / 2) / h) * 2;
}

/// A power of two that brings the largest spacing hmax > 0 into [1/2, 1) unless it already
/// lies in [2^-500, 2^500], where the products of spacings cannot overflow or underflow
/// (1 then: results bit for bit as without scaling). Rules homogeneous in the spacings use
/// it; the scaling is exact unless a spacing 2^600 times smaller than the largest becomes
/// subnormal.
template <class T>
T spacing_scale(T hmax) {
  if (hmax >= std::ldexp(T(1), -500) && hmax <= std::ldexp(T(1), 500)) return 1;
  int e = 0;
  std::frexp(hmax, &e);
  return std::ldexp(T(1), -e);
}

template <class T>
int sign(T v) {
  return (v > 0) - (v < 0);
}

/// PCHIP's one-sided three-point end slope with its shape-preserving corrections
/// (scipy 1.10 PchipInterpolator._edge_case, after Moler's pchiptx.m [Moler04, 3.6]):
/// d = ((2 h0 + h1) m0 - h0 m1) / (h0 + h1); 0 if sign(d) != sign(m0); else 3 m0 if
/// sign(m0) != sign(m1) and |d| > 3 |m0|.
template <class T>
T pchip_end_slope(T h0, T h1, T m0, T m1) {
  T d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
  if (!std::isfinite(d)) {  // h m overflowed (slopes near the largest double): the same with w = h0 / (h0 + h1)
    const T w = h0 / (h0 + h1);
    d = (1 + w) * m0 - w * m1;
  }
  if (sign(d) != sign(m0)) return 0;
  if (sign(m0) != sign(m1) && std::abs(d) > 3 * std::abs(m0)) return 3 * m0;
  return d;
}

/// PCHIP slopes of one coordinate (x strictly increasing, n >= 2), exactly as scipy 1.10
/// PchipInterpolator._find_derivatives [FritschButland84; Moler04, 3.6].
template <class T>
std::vector<T> pchip_slopes(const std::vector<T>& x, const std::vector<T>& y) {
  const std::size_t n = x.size();
  std::vector<T> h(n - 1), m(n - 1), d(n, T(0));
  T hmax = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const T hi = x[i + 1] - x[i];
    hmax = std::max(hmax, hi);
    m[i] = scalar_slope(y[i], y[i + 1], hi);
  }
  // The weights and the end rule are homogeneous in the spacings: scaled by a power of two
  // (exact) so that 2 h + h does not overflow near the largest double, nor h underflow.
  const T sigma = spacing_scale(hmax);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = (x[i + 1] - x[i]) * sigma;
  if (n == 2) return {m[0], m[0]};  // the straight line
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const T ml = m[k - 1], mr = m[k];
    if (sign(ml) != sign(mr) || ml == 0 || mr == 0) continue;  // a local extremum or flat: 0
    // Weighted harmonic mean: w1 = 2 h_k + h_(k-1) weighs the left slope.
    const T w1 = 2 * h[k] + h[k - 1], w2 = h[k] + 2 * h[k - 1];
    const T q = w1 / ml + w2 / mr;
    if (std::isfinite(q)) [[likely]] {
      d[k] = 1 / (q / (w1 + w2));
    } else {  // slopes below about 1e-308: the same mean of the slopes scaled to at most 1
      const T c = std::max(std::abs(ml), std::abs(mr));
      d[k] = c / (((w1 / (ml / c)) + (w2 / (mr / c))) / (w1 + w2));
    }
  }
  d[0] = pchip_end_slope(h[0], h[1], m[0], m[1]);
  d[n - 1] = pchip_end_slope(h[n - 2], h[n - 3], m[n - 2], m[n - 3]);  // n >= 3 here
  return d;
}

/// Akima slopes of one coordinate (x strictly increasing, n >= 3), exactly as scipy 1.10
/// Akima1DInterpolator [Akima70]: chord slopes m_2..m_n, two more at each end extrapolated
/// linearly (m_1 = 2 m_2 - m_3, m_0 = 2 m_1 - m_2, likewise at the right); then at point i
/// with f1 = |m_(i+3) - m_(i+2)|, f2 = |m_(i+1) - m_i|: t_i = (f1 m_(i+1) + f2 m_(i+2)) / (f1 +
/// f2) where f1 + f2 > 1e-9 max(f1 + f2) over the points, else (equal weights undefined)
/// t_i = (m_i + m_(i+3)) / 2. The threshold is scipy's; it is relative to the largest
/// f1 + f2 of this coordinate (scipy on a 2-D array takes the largest over all columns).
template <class T>
std::vector<T> akima_slopes(const std::vector<T>& x, const std::vector<T>& y) {
  const std::size_t n = x.size();
  std::vector<T> m(n + 3);
  for (std::size_t i = 0; i + 1 < n; ++i) m[i + 2] = scalar_slope(y[i], y[i + 1], x[i + 1] - x[i]);
  // The rule is homogeneous of degree 1 in the slopes (the weights are differences of
  // slopes): they are scaled by a power of two when tiny or huge, so that the products
  // f m neither underflow (slopes 1e-300: params 1e300 apart) nor overflow.
  T mmax = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) mmax = std::max(mmax, std::abs(m[i + 2]));
  const T sigma = mmax > 0 ? spacing_scale(mmax) : T(1);
  for (std::size_t i = 0; i + 1 < n; ++i) m[i + 2] *= sigma;
  m[1] = 2 * m[2] - m[3];
  m[0] = 2 * m[1] - m[2];
  m[n + 1] = 2 * m[n] - m[n - 1];
  m[n + 2] = 2 * m[n + 1] - m[n];
  std::vector<T> f1(n), f2(n), t(n);
  T fmax = -std::numeric_limits<T>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    f1[i] = std::abs(m[i + 3] - m[i + 2]);
    f2[i] = std::abs(m[i + 1] - m[i]);
    fmax = std::max(fmax, f1[i] + f2[i]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const T f12 = f1[i] + f2[i];
    t[i] = (f12 > T(1e-9) * fmax ? (f1[i] * m[i + 1] + f2[i] * m[i + 2]) / f12 : T(0.5) * (m[i + 3] + m[i])) / sigma;
  }
  return t;
}

/// Runs a scalar slope rule on each coordinate.
template <class T, int D, class Rule>
std::vector<Vector<T, D>> per_coordinate(const std::vector<T>& u, const std::vector<Point<T, D>>& P, Rule rule) {
  std::vector<Vector<T, D>> out(P.size());
  for (int k = 0; k < D; ++k) {
    const std::vector<T> s = rule(u, coordinate(P, k));
    for (std::size_t i = 0; i < P.size(); ++i) out[i][k] = s[i];
  }
  return out;
}

}  // namespace detail

/// Finite differences [Wikipedia "Cubic Hermite spline", finite difference; deBoor01, IV]:
/// the mean of the two chord slopes, m_i = (d_(i-1) + d_i) / 2 with d_i = (P_(i+1) - P_i) /
/// (u_(i+1) - u_i); one-sided at the ends (m_0 = d_0, m_n = d_(n-1)). Needs n + 1 >= 2
/// points. Throws InvalidArgument naming "points", "params[i]", "points[i][j]".
template <class T, int D>
std::vector<Vector<T, D>> finite_difference_tangents(const std::vector<T>& u, const std::vector<Point<T, D>>& P) {
  detail::check_rule_data(u, P, 2, "finite_difference");
  const auto d = detail::chord_slopes(u, P);
  std::vector<Vector<T, D>> m(P.size());
  m.front() = d.front();
  m.back() = d.back();
  for (std::size_t i = 1; i + 1 < P.size(); ++i) {
    m[i] = (d[i - 1] + d[i]) / T(2);
    if (!detail::all_coordinates_finite(m[i])) m[i] = d[i - 1] / T(2) + d[i] / T(2);  // the sum overflowed
  }
  detail::require_finite_tangents(m, "finite_difference");
  return m;
}

/// Cardinal tangents with tension c in [0, 1] [Wikipedia "Cubic Hermite spline",
/// cardinal spline]: m_i = (1 - c) (P_(i+1) - P_(i-1)) / (u_(i+1) - u_(i-1)); at the ends
/// (1 - c) times the end chord's slope (as if the end chord were repeated beyond the end).
/// c = 0 is Catmull-Rom (on uniform params, m_i = (P_(i+1) - P_(i-1)) / 2: the uniform
/// Catmull-Rom spline on the interior intervals), c = 1 gives zero tangents. Throws
/// InvalidArgument("tension", ...) for c outside [0, 1], and as finite_difference_tangents.
template <class T, int D>
std::vector<Vector<T, D>> cardinal_tangents(const std::vector<T>& u, const std::vector<Point<T, D>>& P, T tension) {
  require_finite(tension, "tension");
  if (!(tension >= 0 && tension <= 1)) {
    throw InvalidArgument("tension", "cardinal tension must be in [0, 1], got " + detail::format_number(tension));
  }
  detail::check_rule_data(u, P, 2, "cardinal");
  const std::size_t n = P.size() - 1;
  const T s = 1 - tension;
  std::vector<Vector<T, D>> m(n + 1);
  m[0] = s * detail::slope(P[0], P[1], u[1] - u[0]);
  m[n] = s * detail::slope(P[n - 1], P[n], u[n] - u[n - 1]);
  for (std::size_t i = 1; i < n; ++i) m[i] = s * detail::slope(P[i - 1], P[i + 1], u[i + 1] - u[i - 1]);
  detail::require_finite_tangents(m, "cardinal");
  return m;
}

/// Catmull-Rom tangents: cardinal with tension 0.
template <class T, int D>
std::vector<Vector<T, D>> catmull_rom_tangents(const std::vector<T>& u, const std::vector<Point<T, D>>& P) {
  return cardinal_tangents(u, P, T(0));
}

/// Kochanek-Bartels parameters, each in [-1, 1]; all zero gives finite-difference
/// tangents (Catmull-Rom on uniform params).
template <class T>
struct KochanekBartels {
  T tension = 0;
  T continuity = 0;
  T bias = 0;
};

/// One-sided tangents: `incoming[i]` ends piece i - 1, `outgoing[i]` starts piece i.
template <class T, int D>
struct OneSidedTangents {
  std::vector<Vector<T, D>> incoming;
  std::vector<Vector<T, D>> outgoing;
};

/// Kochanek-Bartels tangents [KB84, eq. 8-9] on chord slopes d_i (so that they are
/// derivatives with respect to the params): with a = (1 - t) / 2,
///   outgoing m_i  = a ((1 + b)(1 + c) d_(i-1) + (1 - b)(1 - c) d_i),
///   incoming m'_i = a ((1 + b)(1 - c) d_(i-1) + (1 - b)(1 + c) d_i);
/// at the ends the missing chord is the end chord repeated (d_(-1) = d_0, d_n = d_(n-1)).
/// Continuity c != 0 makes the two sides differ (a corner; c = -1 the polyline's
/// straight pieces); t = 1 gives zero tangents, b shifts the weight to the previous
/// (b > 0) or next chord. On uniform params with t = b = c = 0 this is Catmull-Rom.
/// Throws InvalidArgument("tension" / "continuity" / "bias", ...) for a value outside
/// [-1, 1], and as finite_difference_tangents.
template <class T, int D>
OneSidedTangents<T, D> kochanek_bartels_tangents(const std::vector<T>& u, const std::vector<Point<T, D>>& P, KochanekBartels<T> kb) {
  const auto check = [](T v, const char* name) {
    require_finite(v, name);
    if (!(v >= -1 && v <= 1)) {
      throw InvalidArgument(name, std::string("Kochanek-Bartels ") + name + " must be in [-1, 1], got " + detail::format_number(v));
    }
  };
  check(kb.tension, "tension");
  check(kb.continuity, "continuity");
  check(kb.bias, "bias");
  detail::check_rule_data(u, P, 2, "kochanek_bartels");
  const auto d = detail::chord_slopes(u, P);
  const std::size_t n = P.size() - 1;
  const T a = (1 - kb.tension) / 2, b = kb.bias, c = kb.continuity;
  OneSidedTangents<T, D> r{std::vector<Vector<T, D>>(n + 1), std::vector<Vector<T, D>>(n + 1)};
  for (std::size_t i = 0; i <= n; ++i) {
    const Vector<T, D>& prev = d[i == 0 ? 0 : i - 1];
    const Vector<T, D>& next = d[i == n ? n - 1 : i];
    r.outgoing[i] = a * ((1 + b) * (1 + c) * prev + (1 - b) * (1 - c) * next);
    r.incoming[i] = a * ((1 + b) * (1 - c) * prev + (1 - b) * (1 + c) * next);
  }
  detail::require_finite_tangents(r.outgoing, "kochanek_bartels");
  detail::require_finite_tangents(r.incoming, "kochanek_bartels");
  return r;
}

/// Monotone (shape-preserving) tangents, each coordinate on its own: exactly scipy 1.10's
/// PchipInterpolator [FritschButland84; Moler04, 3.6] (see detail::pchip_slopes): zero at
/// a local extremum or flat chord of that coordinate, else the weighted harmonic mean of
/// the chord slopes; the end slopes by the three-point rule with its corrections; with 2
/// points the straight line. Each coordinate is monotone wherever its data are.
template <class T, int D>
std::vector<Vector<T, D>> monotone_tangents(const std::vector<T>& u, const std::vector<Point<T, D>>& P) {
  detail::check_rule_data(u, P, 2, "monotone");
  auto m = detail::per_coordinate(u, P, [](const std::vector<T>& x, const std::vector<T>& y) { return detail::pchip_slopes(x, y); });
  detail::require_finite_tangents(m, "monotone");
  return m;
}

/// Akima tangents, each coordinate on its own: exactly scipy 1.10's Akima1DInterpolator
/// [Akima70] (see detail::akima_slopes), including its linear extrapolation of the chord
/// slopes beyond the ends and its fill value where both weights vanish. Needs at least 3
/// points (scipy 1.10 reads uninitialised memory with 2).
template <class T, int D>
std::vector<Vector<T, D>> akima_tangents(const std::vector<T>& u, const std::vector<Point<T, D>>& P) {
  detail::check_rule_data(u, P, 3, "akima");
  auto m = detail::per_coordinate(u, P, [](const std::vector<T>& x, const std::vector<T>& y) { return detail::akima_slopes(x, y); });
  detail::require_finite_tangents(m, "akima");
  return m;
}

}  // namespace casteljau
