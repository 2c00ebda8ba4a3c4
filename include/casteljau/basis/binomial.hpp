// Binomial coefficients C(n, k) as floating-point numbers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "casteljau/core/error.hpp"

namespace casteljau {

/// C(n, k) for 0 <= k <= n (0 otherwise), by the multiplicative formula with exact
/// integer steps while they fit in 64 bits (n <= 62), else in floating point (relative
/// error about 2k eps). Throws InvalidArgument("n", ...) when C(n, k) overflows T, never
/// returns infinity.
template <class T>
T binomial(int n, int k) {
  if (k < 0 || k > n) return T(0);
  if (k > n - k) k = n - k;
  if (n <= 62) {
    // r = C(n-k+i, i) after step i, i.e. r * m / i with m = n-k+i, which is exact. It is
    // computed as (r / i) m + (r mod i) m / i: both terms are exact integers (r m and
    // (r / i) i m are multiples of i, so (r mod i) m is too) and nothing exceeds the result
    // (< 2^63 for n <= 62) or 62^2.
    unsigned long long r = 1;
    for (int i = 1; i <= k; ++i) {
      const auto m = static_cast<unsigned long long>(n - k + i), ii = static_cast<unsigned long long>(i);
      r = r / ii * m + r % ii * m / ii;
    }
    return static_cast<T>(r);
  }
  T r = 1;
  // r times the ratio (n-k+i)/i, not r (n-k+i) / i: the product alone would overflow
  // before the division for results near the largest double (C(1029, 514) ~ 1.4e308).
  for (int i = 1; i <= k; ++i) r *= static_cast<T>(n - k + i) / static_cast<T>(i);
  if (!std::isfinite(r)) {
    throw InvalidArgument("n", "binomial coefficient C(" + std::to_string(n) + ", " + std::to_string(k) +
                                   ") exceeds the floating point range");
  }
  return r;
}

/// Row n of Pascal's triangle, C(n, 0..n), built by additions [Farin02, 4.1]. Every entry
/// is exact in double while it is below 2^53, which holds for all k when n <= 56; past
/// that each entry carries a relative error of at most about n * epsilon. Throws
/// InvalidArgument("n", ...) for n < 0 and when the middle entry overflows T (n > 1029
/// in double): use detail::hypergeometric_row for ratios of binomials. Cost O(n^2).
template <class T>
std::vector<T> binomial_row(int n) {
  if (n < 0) throw InvalidArgument("n", "binomial row index must be >= 0, got " + std::to_string(n));
  (void)binomial<T>(n, n / 2);  // the largest entry: throws InvalidArgument("n", ...) if it overflows
  std::vector<T> row(static_cast<std::size_t>(n) + 1, T(0));
  row[0] = 1;
  for (int i = 1; i <= n; ++i) {
    for (int k = i; k > 0; --k) row[static_cast<std::size_t>(k)] += row[static_cast<std::size_t>(k - 1)];
  }
  return row;
}

namespace detail {

/// The hypergeometric weights h_j = C(K, j) C(N-K, m-j) / C(N, m) for j = lo..hi, lo =
/// max(0, m-(N-K)), hi = min(K, m), written to out[j - lo] (out.size() == hi - lo + 1).
/// They are the coefficients of Forrest's degree elevation (N = n + r, K = n, m = i) and
/// of the Bernstein product (N = m + n, K = m, m = k), and sum to 1 (Vandermonde).
/// Computed without binomials (which overflow a double past N = 1029): h_mode = 1 at the
/// mode, then the ratio h_{j+1} / h_j = (K-j)(m-j) / ((j+1)(N-K-m+j+1)) outward (the
/// weights decrease away from the mode, so nothing overflows; far tails may underflow to
/// 0, below 2^-1074 of the largest), and finally divided by their sum. Relative error
/// about 4 |j - mode| + 2 eps per weight. Cost O(hi - lo).
template <class T>
void hypergeometric_row(int N, int K, int m, std::span<T> out) {
  const int lo = std::max(0, m - (N - K)), hi = std::min(K, m);
  const auto at = [&](int j) -> T& { return out[static_cast<std::size_t>(j - lo)]; };
  // The mode of the hypergeometric distribution, floor((m+1)(K+1)/(N+2)), clamped.
  const long long mode_ll = (static_cast<long long>(m) + 1) * (static_cast<long long>(K) + 1) / (static_cast<long long>(N) + 2);
  const int mode = std::clamp(static_cast<int>(mode_ll), lo, hi);
  const auto ratio = [&](int j) {  // h_{j+1} / h_j
    return (static_cast<T>(K - j) * static_cast<T>(m - j)) / (static_cast<T>(j + 1) * static_cast<T>(N - K - m + j + 1));
  };
  at(mode) = 1;
  for (int j = mode; j < hi; ++j) at(j + 1) = at(j) * ratio(j);
  for (int j = mode; j > lo; --j) at(j - 1) = at(j) / ratio(j - 1);
  T sum = 0;
  for (int j = lo; j <= hi; ++j) sum += at(j);
  for (int j = lo; j <= hi; ++j) at(j) /= sum;
}

}  // namespace detail

}  // namespace casteljau
