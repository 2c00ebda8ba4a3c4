// The largest distance between two curves at equal parameters, by dense sampling and a
// local maximisation of every sampled peak.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/core/interval.hpp"

namespace casteljau {

/// max over u in the breaks' range of |a(u) - b(u)|, for curves a and b (callables giving
/// points) smooth between consecutive `breaks` (ascending: the pieces of both curves).
/// Method: `samples` + 1 equally spaced parameters per interval; around every sampled
/// local maximum at least half the largest sample, golden-section search on the
/// bracketing samples to a bracket of 1e-13 of the interval (the distance is smooth
/// there, and near a maximum it varies quadratically, so the value is found to far
/// better than 1e-9 relative). An estimate from below, exact up to rounding unless a
/// peak narrower than the sample spacing hides between two samples (for polynomials of
/// degree n, samples = 32 (n + 1) leaves no room for that in practice). Cost: about
/// (samples + 80 per peak) evaluations of both curves per interval.
template <class T, class A, class B>
T max_deviation(const A& a, const B& b, const std::vector<T>& breaks, int samples) {
  const auto dist = [&](T u) { return norm(a(u) - b(u)); };
  T best = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const T lo = breaks[i], hi = breaks[i + 1];
    std::vector<T> u(static_cast<std::size_t>(samples) + 1), f(u.size());
    for (std::size_t j = 0; j < u.size(); ++j) {
      u[j] = j + 1 == u.size() ? hi : lo + (hi - lo) * static_cast<T>(j) / static_cast<T>(samples);
      f[j] = dist(u[j]);
    }
    const T top = *std::max_element(f.begin(), f.end());
    best = std::max(best, top);
    for (std::size_t j = 0; j < u.size(); ++j) {
      const bool peak = (j == 0 || f[j] >= f[j - 1]) && (j + 1 == u.size() || f[j] >= f[j + 1]);
      if (!peak || f[j] < top / 2 || top == 0) continue;
      // Golden section on [u_(j-1), u_(j+1)] (clipped to the interval).
      T x0 = u[j == 0 ? 0 : j - 1], x3 = u[j + 1 == u.size() ? j : j + 1];
      constexpr T g = T(0.6180339887498949);
      T x1 = x3 - g * (x3 - x0), x2 = x0 + g * (x3 - x0);
      T f1 = dist(x1), f2 = dist(x2);
      const T stop = T(1e-13) * (hi - lo);
      for (int it = 0; it < 200 && x3 - x0 > stop; ++it) {
        if (f1 < f2) {
          x0 = x1;
          x1 = x2;
          f1 = f2;
          x2 = x0 + g * (x3 - x0);
          f2 = dist(x2);
        } else {
          x3 = x2;
          x2 = x1;
          f2 = f1;
          x1 = x3 - g * (x3 - x0);
          f1 = dist(x1);
        }
      }
      best = std::max({best, f1, f2});
    }
  }
  return best;
}

}  // namespace casteljau
