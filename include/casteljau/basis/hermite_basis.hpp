// The four cubic Hermite basis functions h00, h10, h01, h11 on [0, 1] and their
// derivatives: plain functions, callable without a curve object.
#pragma once

#include <array>
#include <string>

#include "casteljau/core/error.hpp"

namespace casteljau {

/// The values at t of the cubic Hermite basis functions, in the order of the data they
/// multiply in p(t) = h00 P0 + h10 m0 + h01 P1 + h11 m1 (m0, m1 the end derivatives with
/// respect to t on [0, 1]) [Farin02, 7.5; deBoor01, ch. IV]:
///   h00 = 2t^3 - 3t^2 + 1,  h10 = t^3 - 2t^2 + t,  h01 = -2t^3 + 3t^2,  h11 = t^3 - t^2.
/// h00(0) = h01(1) = 1, h10'(0) = h11'(1) = 1, every other value and slope at 0 and 1 is
/// 0: these hold exactly in floating point (each term is exact at t = 0 and t = 1).
/// h00 + h01 = 1. Any finite t (outside [0, 1] the same cubics). Cost O(1).
template <class T>
struct HermiteBasis {
  T h00{}, h10{}, h01{}, h11{};
};

/// The k-th derivatives (k >= 0) at t of h00, h10, h01, h11 with respect to t: k = 0 the
/// values above, k = 1: 6t^2 - 6t, 3t^2 - 4t + 1, 6t - 6t^2, 3t^2 - 2t; k = 2: 12t - 6,
/// 6t - 4, 6 - 12t, 6t - 2; k = 3: 12, 6, -12, 6; zero above (cubics). Horner forms, so
/// the values at t = 0 and t = 1 are exact. Throws InvalidArgument("k", ...) for k < 0.
template <class T>
HermiteBasis<T> hermite_basis(T t, int k = 0) {
  if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  switch (k) {
    case 0: {
      // h01 = t^2 (3 - 2t); h00 = 1 - h01 is exact at 0 and 1 but loses relative accuracy
      // where h00 is tiny, so it gets its own product form (1 - t)^2 (1 + 2t).
      const T s = 1 - t;
      return {s * s * (1 + 2 * t), t * s * s, t * t * (3 - 2 * t), t * t * (t - 1)};
    }
    case 1: {
      const T a = 6 * t * (t - 1);  // h00' = -h01'
      return {a, (3 * t - 1) * (t - 1), -a, t * (3 * t - 2)};
    }
    case 2: return {12 * t - 6, 6 * t - 4, 6 - 12 * t, 6 * t - 2};
    case 3: return {T(12), T(6), T(-12), T(6)};
    default: return {T(0), T(0), T(0), T(0)};
  }
}

}  // namespace casteljau
