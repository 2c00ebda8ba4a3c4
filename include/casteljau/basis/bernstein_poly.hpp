// Scalar polynomials in Bernstein form on [0, 1]: the algebra the queries need (degree
// elevation, sum, difference, product, derivative, integral, value). Plain functions
// over coefficient spans; the product itself is bernstein_product (basis/roots.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <span>
#include <vector>

#include "casteljau/basis/de_casteljau.hpp"
#include "casteljau/basis/roots.hpp"

namespace casteljau {

/// The value at t of the Bernstein form c (de Casteljau: error a few (n + 1) eps of
/// max |c_i| on [0, 1] [Farin02, 3.1]). Throws InvalidArgument("c", ...) for no
/// coefficients.
template <class T>
T bernstein_value(std::span<const T> c, T t) {
  if (c.empty()) throw InvalidArgument("c", "needs at least one coefficient");
  return de_casteljau<T, T>(c, t);
}

/// The same polynomial at degree n + r (r >= 0): the product with the constant 1 written
/// at degree r, i.e. Forrest's elevation with binomial-free hypergeometric weights
/// [Forrest72; Farin02, 5.1]. Each coefficient is a convex combination of the c_i: error
/// a few (min(n, r) + 2) eps of max |c_i|. Throws InvalidArgument("r", ...) for r < 0.
template <class T>
std::vector<T> bernstein_elevate(std::span<const T> c, int r) {
  if (r < 0) throw InvalidArgument("r", "elevation count must be >= 0, got " + std::to_string(r));
  if (r == 0) return std::vector<T>(c.begin(), c.end());
  const std::vector<T> one(static_cast<std::size_t>(r) + 1, T(1));
  return bernstein_product<T>(c, one);
}

/// f + s g at degree max(m, n) (the lower one elevated first). Error: the elevation's
/// plus one rounding per coefficient.
template <class T>
std::vector<T> bernstein_sum(std::span<const T> f, std::span<const T> g, T s = T(1)) {
  if (f.empty()) throw InvalidArgument("f", "needs at least one coefficient");
  if (g.empty()) throw InvalidArgument("g", "needs at least one coefficient");
  const int m = static_cast<int>(f.size()) - 1, n = static_cast<int>(g.size()) - 1, k = std::max(m, n);
  std::vector<T> a = bernstein_elevate<T>(f, k - m);
  const std::vector<T> b = bernstein_elevate<T>(g, k - n);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += s * b[i];
  return a;
}

/// f - g at degree max(m, n).
template <class T>
std::vector<T> bernstein_difference(std::span<const T> f, std::span<const T> g) {
  return bernstein_sum<T>(f, g, T(-1));
}

/// The derivative on [0, 1]: degree n - 1 with coefficients n (c_{i+1} - c_i)
/// [Farin02, 5.3]; the zero polynomial of degree 0 for a constant. Error: one rounding
/// per difference (absolute about 2 n eps max |c_i|).
template <class T>
std::vector<T> bernstein_derivative_coefficients(std::span<const T> c) {
  if (c.empty()) throw InvalidArgument("c", "needs at least one coefficient");
  const std::size_t n = c.size() - 1;
  if (n == 0) return {T(0)};
  std::vector<T> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<T>(n) * (c[i + 1] - c[i]);
  return d;
}

/// The integral over [0, 1]: every B(i,n) integrates to 1 / (n + 1), so it is the mean
/// of the coefficients [Farin02, 5.4]. Exact up to the summation's rounding (n eps of
/// sum |c_i| / (n + 1)).
template <class T>
T bernstein_integral(std::span<const T> c) {
  if (c.empty()) throw InvalidArgument("c", "needs at least one coefficient");
  return std::accumulate(c.begin(), c.end(), T(0)) / static_cast<T>(c.size());
}

/// |c_i| for every coefficient: products and sums of these bound the rounding error of
/// the same expression on c (each result coefficient of a product is a sum of products
/// with positive weights), which is how the queries tell a polynomial that vanishes
/// identically from rounding noise.
template <class T>
std::vector<T> bernstein_abs(std::span<const T> c) {
  std::vector<T> a(c.begin(), c.end());
  for (T& x : a) x = std::abs(x);
  return a;
}

}  // namespace casteljau
