// Seeded random 1-D interpolation data shared by the Hermite and cubic spline tests.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

#include "casteljau/core/point.hpp"

namespace casteljau::test {

struct InterpData {
  std::vector<double> u;             ///< params
  std::vector<Point<double, 1>> P;   ///< values
};

/// n + 1 params from -3 with uneven steps in [0.01, 1.01) and values in [0, 1): n pieces.
/// Draws u_i then P_i for i = 1..n after P_0, in that order.
inline InterpData random_interp_data(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  InterpData d{std::vector<double>(n + 1), std::vector<Point<double, 1>>(n + 1)};
  d.u[0] = -3;
  d.P[0] = Point<double, 1>(U(rng));
  for (std::size_t i = 1; i <= n; ++i) {
    d.u[i] = d.u[i - 1] + 0.01 + U(rng);
    d.P[i] = Point<double, 1>(U(rng));
  }
  return d;
}

}  // namespace casteljau::test
