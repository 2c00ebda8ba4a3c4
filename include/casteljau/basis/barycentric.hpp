// Polynomial interpolation through n distinct nodes: barycentric weights (any nodes in
// O(n^2), Chebyshev nodes of both kinds in O(n)), node generators, evaluation and
// derivatives of any order by the barycentric formulas in O(n k), and Neville's scheme
// [BerrutTrefethen04; Higham04; SchneiderWerner86].
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "casteljau/core/interval.hpp"

namespace casteljau {

/// The node families with closed-form barycentric weights.
enum class Nodes {
  equispaced,  ///< x_j = a + j (b - a) / (n - 1), j = 0..n-1 (n >= 2)
  chebyshev1,  ///< roots of T_n mapped to [a, b]: a + (b - a)(1 - cos((2j+1) pi / 2n)) / 2 (n >= 1), ends not included
  chebyshev2,  ///< extrema of T_(n-1) mapped to [a, b]: a + (b - a)(1 - cos(j pi / (n-1))) / 2 (n >= 2), ends included
};

namespace detail {

/// A value as an element of a vector space: points become vectors from the origin,
/// vectors and scalars stay as they are (the barycentric sums need differences of data).
template <class V>
const V& as_vector(const V& v) {
  return v;
}
template <class T, int D>
Vector<T, D> as_vector(const Point<T, D>& p) {
  return p.to_vector();
}

/// x = m 2^e with m kept in [0.5, 1): products of many factors without overflow or
/// underflow (the exponent is an int).
template <class T>
struct ScaledProduct {
  T m = 1;
  long e = 0;
  void times(T f) {
    int k = 0;
    m = std::frexp(m * f, &k);
    e += k;
  }
};

/// Throws unless the n nodes are finite and pairwise distinct; names `where`[j] for the
/// later of two equal nodes (O(n log n)).
template <class T>
void check_distinct_nodes(std::span<const T> x, const std::string& where) {
  for (std::size_t j = 0; j < x.size(); ++j) require_finite(x[j], where + "[" + std::to_string(j) + "]");
  std::vector<std::size_t> order(x.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  for (std::size_t r = 1; r < order.size(); ++r) {
    if (x[order[r]] == x[order[r - 1]]) {
      const std::size_t first = std::min(order[r], order[r - 1]), second = std::max(order[r], order[r - 1]);
      throw InvalidArgument(where + "[" + std::to_string(second) + "]",
                            "interpolation nodes must be distinct: " + format_number(x[second]) + " repeats " + where + "[" +
                                std::to_string(first) + "]");
    }
  }
}

}  // namespace detail

/// The barycentric weights w_j = s / prod_{k != j} (x_j - x_k) of n >= 1 distinct finite
/// nodes (any order), scaled by one positive power of two s so that max |w_j| lies
/// in (0.5, 1]: the barycentric formulas are invariant under a common factor. Each product
/// is accumulated as mantissa and exponent, so nothing overflows or underflows whatever
/// n and the spread of the nodes (the capacity scaling of [BerrutTrefethen04, sec. 7]
/// solves the same problem for moderate n; this is exact in the exponent). Throws
/// InvalidArgument("params[j]", ...) for a non-finite or repeated node, ("params", ...)
/// when the ratio of the largest to the smallest weight exceeds the double range (the
/// smallest would round to 0: about 1000 equispaced nodes). Cost O(n^2); each weight
/// has a relative error of at most about 2 n eps.
template <class T>
std::vector<T> barycentric_weights(std::span<const T> x) {
  if (x.empty()) throw InvalidArgument("params", "interpolation needs at least one node");
  detail::check_distinct_nodes(x, "params");
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  if (!std::isfinite(*hi - *lo)) throw InvalidArgument("params", "the nodes span more than the largest double");
  const std::size_t n = x.size();
  std::vector<detail::ScaledProduct<T>> prod(n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < n; ++k)
      if (k != j) prod[j].times(x[j] - x[k]);
  long emax = -prod[0].e;
  for (const auto& p : prod) emax = std::max(emax, -p.e);
  // 1 / (m 2^e) = (1/m) 2^-e with 1/m in (1, 2]; scaled by 2^-(emax + 1), the largest
  // lies in (0.5, 1].
  std::vector<T> w(n);
  for (std::size_t j = 0; j < n; ++j) {
    const long shift = std::max<long>(-prod[j].e - emax - 1, -100000);  // ldexp gives 0 far below the range
    w[j] = std::ldexp(1 / prod[j].m, static_cast<int>(shift));
    if (w[j] == 0) {
      throw InvalidArgument("params", "the nodes are too unevenly placed for double precision: the barycentric weight of node " +
                                          std::to_string(j) + " underflows next to the largest");
    }
  }
  return w;
}

/// The closed-form barycentric weights of n nodes of a family, in increasing order of
/// the nodes, for any interval (an increasing affine map scales all weights alike) in
/// O(n) [BerrutTrefethen04, eq. (5.1)-(5.3)]: equispaced (-1)^(n-1-j) C(n-1, j) (only up
/// to n = 1030 in double: computed by the O(n^2) products instead, see barycentric_weights),
/// Chebyshev first kind (-1)^(n-1-j) sin((2j+1) pi / 2n), second kind (-1)^(n-1-j) delta_j
/// with delta_j = 1/2 at the two ends and 1 elsewhere. The signs make them equal to
/// barycentric_weights(nodes) up to one positive factor.
template <class T>
std::vector<T> chebyshev_weights(Nodes kind, std::size_t n) {
  if (kind == Nodes::equispaced) throw InvalidArgument("kind", "equispaced nodes have no O(n) weights here: use barycentric_weights");
  const std::size_t min_n = kind == Nodes::chebyshev1 ? 1 : 2;
  if (n < min_n) throw InvalidArgument("n", "needs at least " + std::to_string(min_n) + " nodes, got " + std::to_string(n));
  std::vector<T> w(n);
  for (std::size_t j = 0; j < n; ++j) {
    const T sign = (n - 1 - j) % 2 == 0 ? T(1) : T(-1);
    if (kind == Nodes::chebyshev1) {
      // sin((2j+1) pi / 2n) as cos of the symmetric angle: equal for j and n-1-j exactly.
      const T theta = std::numbers::pi_v<T> * (static_cast<T>(2 * j + 1) - static_cast<T>(n)) / static_cast<T>(2 * n);
      w[j] = sign * std::cos(theta);
    } else {
      w[j] = sign * (j == 0 || j == n - 1 ? T(0.5) : T(1));
    }
  }
  return w;
}

/// n nodes of a family on [a, b] (a < b), in increasing order. Chebyshev nodes are
/// computed as a + (b - a)(1 + sin(phi_j)) / 2 with the symmetric angle phi_j (phi_(n-1-j)
/// = -phi_j), so they are symmetric about the middle to rounding; the second kind and the
/// equispaced nodes include a and b exactly. Throws InvalidArgument("n", ...) below the
/// family's minimum count, ("interval", ...) unless a < b are finite.
template <class T>
std::vector<T> interpolation_nodes(Nodes kind, std::size_t n, T a, T b) {
  require_finite(a, "interval.lo");
  require_finite(b, "interval.hi");
  if (!(a < b) || !std::isfinite(b - a)) {
    throw InvalidArgument("interval", "needs a < b with a finite length, got [" + detail::format_number(a) + ", " + detail::format_number(b) + "]");
  }
  const std::size_t min_n = kind == Nodes::chebyshev1 ? 1 : 2;
  if (n < min_n) throw InvalidArgument("n", "needs at least " + std::to_string(min_n) + " nodes, got " + std::to_string(n));
  const Interval<T> ab(a, b);
  std::vector<T> x(n);
  for (std::size_t j = 0; j < n; ++j) {
    T s;  // the fraction of [a, b]
    if (kind == Nodes::equispaced) {
      s = static_cast<T>(j) / static_cast<T>(n - 1);
    } else {
      const T num = kind == Nodes::chebyshev1 ? static_cast<T>(2 * j + 1) - static_cast<T>(n) : static_cast<T>(2 * j) - static_cast<T>(n - 1);
      const T den = kind == Nodes::chebyshev1 ? static_cast<T>(2 * n) : static_cast<T>(2 * (n - 1));
      s = (1 + std::sin(std::numbers::pi_v<T> * num / den)) / 2;
    }
    x[j] = ab.at(s);
  }
  if (kind != Nodes::chebyshev1) {
    x.front() = a;
    x.back() = b;
  }
  return x;
}

/// The Taylor coefficients c_m = p^(m)(t) / m!, m = 0..k, of the interpolating polynomial
/// p of degree <= n - 1 through (x_j, y_j) with barycentric weights w (any common scale),
/// written to c[0..k]; c_m = 0 for m >= n. y may hold points, vectors or scalars (c holds
/// vectors or scalars). Any finite t.
///
/// Method: the divided differences q_m(x_j) = p[x_j, t, ..., t] (t repeated m times)
/// satisfy q_0 = y, q_(m+1)(x_j) = (q_m(x_j) - c_m) / (x_j - t), and c_m = q_m(t) is the
/// barycentric interpolant of the values q_m(x_j) (a polynomial of degree n - 1 - m)
/// [SchneiderWerner86]. Each level is written relative to the node x_i nearest t, with
/// h = t - x_i: c_m = q_m(x_i) + h T_m / S' and q_(m+1)(x_i) = T_m / S', where
/// T_m = sum_(j != i) w_j (q_m(x_j) - q_m(x_i)) / (t - x_j) and S' = h sum_j w_j / (t - x_j).
/// So the node term drops out exactly: at a node (h = 0) c_0 = y_i exactly and the
/// derivatives are the differentiation-matrix formulas; near a node nothing cancels
/// (the plain formula divides y_i - p(t) by h and loses eps |y| / h).
/// This is done inside [min x, max x], where S' = w_i + h sum_(j != i) w_j / (t - x_j): the
/// second (true) barycentric formula, forward stable for well-placed nodes [Higham04].
/// Outside it that sum cancels (sum_j w_j x_j^r = 0 for r < n - 1) and so does the
/// recursion, so the first formula p = y_i + l(t) sum_j w_j (y_j - y_i) / (t - x_j) is
/// differentiated by Leibniz's rule instead, with l(t) as a product (mantissa and
/// exponent: no overflow) and its derivatives from elementary symmetric sums of same-sign
/// terms (see the code). Cost O(n (k + 1) + k^2); one array of n values.
///
/// Accuracy: at order 0, a few eps times the Lebesgue function at t times max |y|; each
/// derivative order multiplies by about n^2 / (max x - min x) (the differentiation matrix
/// norm). Non-finite results (overflow far outside the nodes) are left to the caller.
template <class V, class T, class Y>
void barycentric_taylor(std::span<const T> x, std::span<const T> w, std::span<const Y> y, T t, int k, V* c) {
  const std::size_t n = x.size();
  std::size_t i = 0;
  T lo = x[0], hi = x[0];
  for (std::size_t j = 1; j < n; ++j) {
    if (std::abs(t - x[j]) < std::abs(t - x[i])) i = j;
    lo = std::min(lo, x[j]);
    hi = std::max(hi, x[j]);
  }
  const T h = t - x[i];
  const int top = std::min<int>(k, static_cast<int>(n) - 1);
  if (lo <= t && t <= hi) {
    T s = 0;
    if (h != 0)
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) s += w[j] / (t - x[j]);
    const T inv_den = 1 / (w[i] + h * s);  // 1 / S'
    std::vector<V> q(n);
    for (std::size_t j = 0; j < n; ++j) q[j] = detail::as_vector(y[j]);
    for (int m = 0; m <= top; ++m) {
      V T_m{};
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) T_m += (w[j] / (t - x[j])) * (q[j] - q[i]);
      const V next_i = T_m * inv_den;
      c[m] = h == 0 ? q[i] : q[i] + h * next_i;
      if (m == top) break;
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) q[j] = (q[j] - c[m]) / (x[j] - t);
      q[i] = next_i;
    }
  } else {
    // First form, differentiated: p(t) = y_i + l(t) r(t) with r(t) = sum_j w_j (y_j - y_i)
    // a_j, a_j = 1 / (t - x_j) (all of one sign out here), and l = 1 / sum_j w_j a_j formed
    // as the product h / S' (no cancellation). Leibniz: c_m = l sum_(r=0..m) e_r
    // (-1)^(m-r) R_(m-r), with l^(r) / (r! l) = e_r(a), the elementary symmetric
    // polynomials of the a_j (sums of same-sign products), and R_s = sum_j w_j (y_j - y_i)
    // a_j^(s+1). The recursion above would divide huge c_m by t - x_j and lose
    // |t|^(n-m) / (n-m)! digits.
    detail::ScaledProduct<T> r;
    r.times(w[i]);
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) r.times((x[i] - x[j]) / (t - x[j]));
    // l = h / S' = h / (r.m 2^r.e), as mantissa and exponent.
    const T l = std::ldexp(h / r.m, static_cast<int>(std::clamp<long>(-r.e, -100000, 100000)));
    std::vector<T> e(static_cast<std::size_t>(top) + 1, T(0));
    std::vector<V> R(static_cast<std::size_t>(top) + 1, V{});
    e[0] = 1;
    const V yi = detail::as_vector(y[i]);
    for (std::size_t j = 0; j < n; ++j) {
      const T a = 1 / (t - x[j]);
      for (int m = top; m >= 1; --m) e[m] += a * e[m - 1];
      if (j == i) continue;
      const V z = detail::as_vector(y[j]) - yi;
      T pw = w[j] * a;
      for (int m = 0; m <= top; ++m, pw *= a) R[m] += pw * z;
    }
    for (int m = 0; m <= top; ++m) {
      V acc{};
      for (int q = 0; q <= m; ++q) acc += ((m - q) % 2 == 0 ? e[q] : -e[q]) * R[m - q];
      c[m] = acc * l;
    }
    c[0] += yi;
  }
  for (int m = top + 1; m <= k; ++m) c[m] = V{};
}

/// p(t) by Neville's scheme [Neville34]: P_(j,j) = y_j, P_(j,l) = ((t - x_l) P_(j,l-1) -
/// (t - x_j) P_(j+1,l)) / (x_j - x_l); the answer is P_(0,n-1). Independent of the
/// barycentric weights (a check on them, and the classic one-point method).
/// Cost O(n^2), one array of n values.
template <class V, class T, class Y>
V neville(std::span<const T> x, std::span<const Y> y, T t) {
  const std::size_t n = x.size();
  if (n == 0 || y.size() != n) throw InvalidArgument("points", "Neville's scheme needs as many values as nodes, at least one");
  std::vector<V> P(n);
  for (std::size_t j = 0; j < n; ++j) P[j] = detail::as_vector(y[j]);
  for (std::size_t l = 1; l < n; ++l)
    for (std::size_t j = 0; j + l < n; ++j) P[j] = ((t - x[j + l]) * P[j] - (t - x[j]) * P[j + 1]) / (x[j] - x[j + l]);
  return P[0];
}

}  // namespace casteljau
