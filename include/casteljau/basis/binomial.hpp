// Binomial coefficients C(n, k) as floating-point numbers.
#pragma once

#include <cstddef>
#include <vector>

#include "casteljau/core/error.hpp"

namespace casteljau {

/// Row n of Pascal's triangle, C(n, 0..n), built by additions [Farin02, 4.1]. Every entry
/// is exact in double while it is below 2^53, which holds for all k when n <= 56; past
/// that each entry carries a relative error of at most about n * epsilon. Cost O(n^2).
template <class T>
std::vector<T> binomial_row(int n) {
  if (n < 0) throw InvalidArgument("n", "binomial row index must be >= 0, got " + std::to_string(n));
  std::vector<T> row(static_cast<std::size_t>(n) + 1, T(0));
  row[0] = 1;
  for (int i = 1; i <= n; ++i) {
    for (int k = i; k > 0; --k) row[static_cast<std::size_t>(k)] += row[static_cast<std::size_t>(k - 1)];
  }
  return row;
}

/// C(n, k) for 0 <= k <= n (0 otherwise), by the multiplicative formula with exact
/// integer steps while they fit in 64 bits (n <= 62), else in floating point.
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
  for (int i = 1; i <= k; ++i) r = r * static_cast<T>(n - k + i) / static_cast<T>(i);
  return r;
}

}  // namespace casteljau
