// RapidCheck generators for the property tests: degrees, parameters and control points on
// a grid of 2^-20 (so shrinking gives readable counterexamples and values are exact
// binary fractions), in the box [-1, 1]^D unless stated.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/casteljau.hpp"

namespace casteljau::prop {

/// Machine epsilon of double, the unit of the properties' tolerances.
inline constexpr double eps = std::numeric_limits<double>::epsilon();

/// A random degree in 1..30.
inline int degree() { return *rc::gen::inRange(1, 31); }

/// The largest coordinate difference between two points (or vectors) of one dimension.
template <class P>
double diff(const P& a, const P& b) {
  double m = 0;
  for (int d = 0; d < P::dimension; ++d) m = std::max(m, std::abs(a[d] - b[d]));
  return m;
}

/// A coordinate in [lo, hi] on a grid of (hi - lo) 2^-20.
inline rc::Gen<double> coordinate(double lo = -1, double hi = 1) {
  return rc::gen::map(rc::gen::inRange(0, (1 << 20) + 1),
                      [lo, hi](int k) { return lo + (hi - lo) * static_cast<double>(k) * 0x1.0p-20; });
}

/// A parameter in [0, 1].
inline rc::Gen<double> parameter() { return coordinate(0, 1); }

template <int D>
rc::Gen<Point<double, D>> point(double lo = -1, double hi = 1) {
  return rc::gen::map(rc::gen::container<std::vector<double>>(D, coordinate(lo, hi)), [](const std::vector<double>& v) {
    Point<double, D> p;
    for (int d = 0; d < D; ++d) p[d] = v[static_cast<std::size_t>(d)];
    return p;
  });
}

/// A random valid knot vector: degree 1..5, fewer than max_inner interior knots on the
/// grid k/16 of (0, 1) (each at most p times, so repeated knots are frequent), clamped at
/// 0 and 1 or with outer knots -k/16 and 1 + k/16 (the domain is [0, 1] either way).
inline KnotVector<double> knot_vector(int max_inner) {
  const int p = *rc::gen::inRange(1, 6);
  const int inner = *rc::gen::inRange(0, max_inner);
  std::vector<double> X;
  for (int i = 0; i < inner; ++i) X.push_back(*rc::gen::inRange(1, 16) / 16.0);
  std::sort(X.begin(), X.end());
  for (const double x : X) RC_PRE(std::count(X.begin(), X.end(), x) <= p);
  const bool clamped = *rc::gen::arbitrary<bool>();
  std::vector<double> U;
  for (int i = p; i >= 0; --i) U.push_back(clamped ? 0.0 : -i / 16.0);
  U.insert(U.end(), X.begin(), X.end());
  for (int i = 0; i <= p; ++i) U.push_back(clamped ? 1.0 : 1 + i / 16.0);
  return KnotVector<double>(p, std::move(U));
}

/// Control points of a curve of degree n.
template <int D>
std::vector<Point<double, D>> control_points(int n, double lo = -1, double hi = 1) {
  return *rc::gen::container<std::vector<Point<double, D>>>(static_cast<std::size_t>(n) + 1, point<D>(lo, hi));
}

/// Weights in [1/4, 4] (a log-uniform-ish spread: 2^[-2, 2]).
inline std::vector<double> weights(int n) {
  return *rc::gen::container<std::vector<double>>(
      static_cast<std::size_t>(n) + 1,
      rc::gen::map(rc::gen::inRange(-64, 65), [](int k) { return std::exp2(static_cast<double>(k) / 32); }));
}

/// Runs f.template operator()<D>() for a dimension D drawn from 1..4, so one property
/// covers every dimension the run-time interfaces support.
template <class F>
void with_random_dimension(F&& f) {
  switch (*rc::gen::inRange(1, 5)) {
    case 1: f.template operator()<1>(); break;
    case 2: f.template operator()<2>(); break;
    case 3: f.template operator()<3>(); break;
    default: f.template operator()<4>(); break;
  }
}

}  // namespace casteljau::prop
