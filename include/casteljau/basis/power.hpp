// The matrix form of Bézier curves: the Bernstein-to-power change of basis M of degree n
// and its inverse, so that B(t) = [1 t ... t^n] M [P_0 ... P_n]^T [Farin02, 5.8].
#pragma once

#include <Eigen/Core>

#include "casteljau/basis/binomial.hpp"

namespace casteljau {

template <class T>
using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// M with M(j, i) = (-1)^(j-i) C(n, j) C(j, i) for i <= j, else 0: power coefficient a_j =
/// sum_i M(j, i) P_i. Lower triangular. Entries are exact integers in double for n <= 50
/// (they reach C(n, n/2) 2^(n/2)-ish magnitudes); the conversion amplifies rounding by
/// about max_j sum_i |M(j, i)| ~ 3^n, which is why the power form is used only at low degree.
template <class T>
Matrix<T> bernstein_to_power_matrix(int n) {
  if (n < 0) throw InvalidArgument("n", "degree must be >= 0, got " + std::to_string(n));
  Matrix<T> m = Matrix<T>::Zero(n + 1, n + 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= j; ++i) {
      const T v = binomial<T>(n, j) * binomial<T>(j, i);
      m(j, i) = ((j - i) % 2 == 0) ? v : -v;
    }
  return m;
}

/// M^-1 with M^-1(i, j) = C(i, j) / C(n, j) for j <= i: P_i = sum_j M^-1(i, j) a_j. All
/// entries lie in [0, 1], so power-to-Bernstein is well conditioned.
template <class T>
Matrix<T> power_to_bernstein_matrix(int n) {
  if (n < 0) throw InvalidArgument("n", "degree must be >= 0, got " + std::to_string(n));
  Matrix<T> m = Matrix<T>::Zero(n + 1, n + 1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= i; ++j) m(i, j) = binomial<T>(i, j) / binomial<T>(n, j);
  return m;
}

}  // namespace casteljau
