// The scalar Bernstein polynomials of a Bézier piece that the queries build on: its
// coordinates relative to an origin (homogeneous numerators and the weight function for
// a rational piece), scaled by one power of two so that every product stays in range,
// and the numerators of the coordinates' derivatives.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/basis/bernstein_poly.hpp"
#include "casteljau/basis/extrapolate.hpp"
#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau::detail {

/// A piece as scalar Bernstein forms on [0, 1]: coordinate k of the piece minus the
/// origin is x[k] / w, times 2^e. For a polynomial piece w is the constant 1 (degree 0)
/// and `rational` is false; for a rational piece x[k][i] = w_i (P_ik - origin_k) 2^-e
/// with the weights divided by the largest (which leaves the curve unchanged). The
/// coordinates are those of the unit frame about the origin (core/unit_frame.hpp: no
/// overflow in the differences, the largest |x| in [0.5, 1)): products of these forms
/// then neither overflow nor underflow for coordinates of any size.
template <class T, int D>
struct ScalarForms {
  std::vector<std::vector<T>> x;  // D forms of degree n
  std::vector<T> w;               // weight function (degree n), or {1}
  bool rational = false;
  int e = 0;                      // the scale: coordinates are x / w times 2^e
  int degree = 0;
};

template <class T, int D, class Piece>
ScalarForms<T, D> scalar_forms(const Piece& c, const Point<T, D>& origin) {
  ScalarForms<T, D> f;
  const auto& P = c.points();
  f.degree = static_cast<int>(P.size()) - 1;
  f.x.assign(D, std::vector<T>(P.size()));
  const T h = half_extent<T, D>(std::span<const Point<T, D>>(P), origin);  // the unit frame about origin
  f.e = h > 0 ? unit_exponent(h) : 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int k = 0; k < D; ++k) f.x[k][i] = to_unit(P[i][k], origin[k], f.e);  // largest |x| in [0.5, 1)
  if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) {
    f.rational = true;
    const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
    f.w = c.weights();
    for (T& v : f.w) v /= wmax;
    for (auto& xk : f.x)
      for (std::size_t i = 0; i < xk.size(); ++i) xk[i] *= f.w[i];
  } else {
    f.w = {T(1)};
  }
  return f;
}

/// The numerator of the derivative of coordinate k: x_k' for a polynomial piece (degree
/// n - 1), x_k' w - x_k w' for a rational one (degree 2n - 1; the derivative is this over
/// w^2). With `absolute`, the same expression on absolute values, which bounds the
/// rounding error of each coefficient (see bernstein_abs).
template <class T>
std::vector<T> abs_derivative_bound(const std::vector<T>& c) {
  const std::size_t n = c.size() - 1;
  if (n == 0) return {T(0)};
  std::vector<T> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<T>(n) * (std::abs(c[i]) + std::abs(c[i + 1]));
  return d;
}

template <class T, int D>
std::vector<T> derivative_numerator(const ScalarForms<T, D>& f, int k, bool absolute = false) {
  if (absolute) {
    // Bound of the rounding error of each coefficient: the same sums and products of
    // absolute values, with |a - b| bounded by |a| + |b|.
    const std::vector<T> dxa = abs_derivative_bound<T>(f.x[k]);
    if (!f.rational) return dxa;
    return bernstein_sum<T>(bernstein_product<T>(dxa, f.w),
                            bernstein_product<T>(bernstein_abs<T>(f.x[k]), abs_derivative_bound<T>(f.w)));
  }
  const std::vector<T> dx = bernstein_derivative_coefficients<T>(f.x[k]);
  if (!f.rational) return dx;
  return bernstein_difference<T>(bernstein_product<T>(dx, f.w),
                                 bernstein_product<T>(f.x[k], bernstein_derivative_coefficients<T>(f.w)));
}

/// The map from a part's parameter u on [0, 1] back to its piece's parameter t:
/// (tau1, tau0) = m (u, 1 - u) (a 2 x 2 matrix, row-major, entries >= 0) and
/// t = tau1 / (tau1 + tau0), a Möbius map of [0, 1] onto the part's parameter interval.
/// `identity`: t = u exactly (the part is the piece itself).
template <class T>
struct PartMap {
  std::array<T, 4> m{T(1), T(0), T(0), T(1)};
  bool identity = true;

  [[nodiscard]] T t_of(T u) const {
    if (identity) return u;
    const T a = m[0] * u + m[1] * (1 - u), b = m[2] * u + m[3] * (1 - u);
    return std::clamp(a / (a + b), T(0), T(1));
  }
};

/// A part of a Bézier piece that the queries can resolve, and its map back to the piece.
template <class Piece>
struct RegularPart {
  Piece piece;
  PartMap<typename Piece::Scalar> map;
};

/// Largest ratio of a rational piece's weights in standard form (end weights 1) under
/// which its parametrisation is left as it is: weights w_i c^i / w_0 with
/// c = (w_0 / w_n)^(1/n) give the same curve reparametrised by t = c u / (1 - u + c u)
/// [Farin02, 13.4], and with all of them within [1/R, R] the speed and the distance to a
/// point vary by bounded factors over [0, 1], which quadrature and root isolation
/// resolve. Ordinary rational curves (conics, circles: standard-form weights <= 1 or a
/// few) stay on the plain path.
template <class T>
inline constexpr T regular_weight_ratio = T(64);

namespace regular {

template <class T>
std::array<T, 4> compose(const std::array<T, 4>& a, const std::array<T, 4>& b) {
  std::array<T, 4> r{a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
  const T big = std::max({r[0], r[1], r[2], r[3]});
  int e = 0;
  (void)std::frexp(big, &e);
  for (T& x : r) x = std::ldexp(x, -e);  // the map is unchanged by a common factor
  return r;
}

template <class T, int D>
void parts_rec(const RationalBezier<T, D>& c, const std::array<T, 4>& m, int depth,
               std::vector<RegularPart<RationalBezier<T, D>>>& out) {
  const auto& w = c.weights();
  const std::size_t n = w.size() - 1;
  // Logarithms: weights may span the whole range of T.
  const T l0 = std::log(w.front()), ln = std::log(w.back());
  const T lc = (l0 - ln) / static_cast<T>(n);
  T rho = 0, low = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    const T li = std::log(w[i]) + static_cast<T>(i) * lc - l0;
    rho = std::max(rho, li);
    low = std::min(low, li);
  }
  const T lr = std::log(regular_weight_ratio<T>);
  const bool balanced = std::abs(lc) * static_cast<T>(n) <= lr;
  if ((rho <= lr && balanced) || depth >= 60 || out.size() >= 4096) {
    out.push_back({c, {m, false}});
    return;
  }
  const std::array<T, 4> left{T(0.5), T(0), T(0.5), T(1)}, right{T(1), T(0.5), T(0), T(0.5)};
  if (rho - low > T(600) || std::abs(lc) > T(600)) {
    // The standard form is not representable: halve in the present parameter first
    // (each half's weights span about the square root of the whole's).
    const auto h = c.split(T(0.5));
    parts_rec(h.left, compose(m, left), depth + 1, out);
    parts_rec(h.right, compose(m, right), depth + 1, out);
    return;
  }
  std::vector<T> ws(n + 1);
  for (std::size_t i = 0; i <= n; ++i) ws[i] = std::exp(std::log(w[i]) + static_cast<T>(i) * lc - l0);
  const T cc = std::exp(lc);
  const RationalBezier<T, D> s(c.points(), std::move(ws));
  const auto ms = compose(m, std::array<T, 4>{cc, T(0), T(0), T(1)});
  if (rho <= lr) {
    out.push_back({s, {ms, false}});
    return;
  }
  // A large interior weight: the curve hugs its control polygon and passes most of it in
  // a parameter interval of width about 1 / rho at each end. Halving in the standard
  // form's parameter takes the square root of rho (for a quadratic, rho -> sqrt((1 + rho)
  // / 2)): a few levels reach a tame parametrisation.
  const auto h = s.split(T(0.5));
  parts_rec(h.left, compose(ms, left), depth + 1, out);
  parts_rec(h.right, compose(ms, right), depth + 1, out);
}

}  // namespace regular

/// The piece as parts the queries can resolve: a polynomial piece, or a rational one whose
/// weights in standard form lie within regular_weight_ratio, is one identity part (the
/// piece itself); a rational piece with extreme weights (weights 1, 1e30, 1: the curve
/// hugs its control polygon and passes each leg within 1e-30 of a parameter end, where
/// quadrature and root isolation in t cannot resolve it) is reparametrised to its
/// standard form and halved there until every part is tame, each with its Möbius map
/// back to t. Exact up to the rounding of the splits (convex combinations). Parameters
/// reported through the map are rounded to the doubles in [0, 1], which may not
/// resolve a part (t within 1e-30 of 1); the parts' points and distances are exact.
template <class Piece>
std::vector<RegularPart<Piece>> regular_parts(const Piece& c) {
  using T = typename Piece::Scalar;
  std::vector<RegularPart<Piece>> out;
  if constexpr (requires { c.weights(); }) {
    if (c.points().size() > 1) {
      regular::parts_rec(c, std::array<T, 4>{T(1), T(0), T(0), T(1)}, 0, out);
      if (out.size() == 1 && out.front().map.m == std::array<T, 4>{T(1), T(0), T(0), T(1)}) out.front().map.identity = true;
      return out;
    }
  }
  out.push_back({c, {}});
  return out;
}

/// The work of a per-piece query (project, arc length, features) on a curve, in units of
/// (n + 1)^2 summed over its Bézier pieces of degree n: root isolation and de Casteljau
/// evaluation cost O(n^2) per step on each piece. On this project's machines 10^7 units
/// take one to three seconds (2950 pieces of degree 50: 7.7e6 units, 2 s for features).
template <class T, int D>
double query_work(const Pieces<T, D>& p) {
  double work = 0;
  for (const auto& s : p.segments()) {
    const double n = static_cast<double>(std::visit([](const auto& c) { return c.points().size(); }, s));
    work += n * n;
  }
  return work;
}

/// The limit of query_work that a request may ask for (see io/queries.hpp).
inline constexpr double max_query_work = 1e7;

/// Per-coefficient test that a form vanishes identically: |c_i| <= slack eps a_i for the
/// absolute-value form a of the same expression (its rounding error bound).
template <class T>
bool vanishes(const std::vector<T>& c, const std::vector<T>& a, T slack) {
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!(std::abs(c[i]) <= slack * std::numeric_limits<T>::epsilon() * a[i])) return false;
  return true;
}

}  // namespace casteljau::detail
