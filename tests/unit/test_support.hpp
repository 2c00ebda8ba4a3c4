// Helpers shared by the unit, property and reference tests: a seeded generator, random
// control points, independent geometric helpers and the check for InvalidArgument.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/casteljau.hpp"

namespace casteljau::test {
/// Machine epsilon of double, the unit of the tests' tolerances.
inline constexpr double eps = std::numeric_limits<double>::epsilon();

/// The largest distance between two curves at equal parameters, sampled at samples + 1
/// equally spaced parameters of [lo, hi].
template <class A, class B>
double max_distance(const A& a, const B& b, double lo, double hi, int samples = 200) {
  double d = 0;
  for (int i = 0; i <= samples; ++i) {
    const double u = lo + (hi - lo) * i / samples;
    d = std::max(d, distance(a(u), b(u)));
  }
  return d;
}

/// splitmix64 (Steele, Lea, Flood 2014): a tiny, fully specified generator, so the
/// reference data are the same on every platform and standard library.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::uint64_t s_;
};

/// n + 1 random points in the box [lo, hi]^D.
template <class T, int D>
std::vector<Point<T, D>> random_points(SplitMix64& rng, int n, double lo = 0, double hi = 1) {
  std::vector<Point<T, D>> P(static_cast<std::size_t>(n) + 1);
  for (auto& p : P)
    for (int d = 0; d < D; ++d) p[d] = static_cast<T>(rng.uniform(lo, hi));
  return P;
}

/// max_i |p_i| over the coordinates of a point set (the scale errors are relative to).
template <class T, int D>
T max_abs(const std::vector<Point<T, D>>& P) {
  T m = 0;
  for (const auto& p : P)
    for (int d = 0; d < D; ++d) m = std::max(m, std::abs(p[d]));
  return m;
}

/// Max-coordinate distance |a - b|_inf (used where a per-coordinate bound is the claim).
template <class T, int D>
T max_coord_diff(const Point<T, D>& a, const Point<T, D>& b) {
  T m = 0;
  for (int d = 0; d < D; ++d) m = std::max(m, std::abs(a[d] - b[d]));
  return m;
}
template <class T, int D>
T max_coord_diff(const Vector<T, D>& a, const Vector<T, D>& b) {
  T m = 0;
  for (int d = 0; d < D; ++d) m = std::max(m, std::abs(a[d] - b[d]));
  return m;
}

template <class T, int D>
bool all_finite(const Point<T, D>& p) {
  for (int d = 0; d < D; ++d)
    if (!std::isfinite(p[d])) return false;
  return true;
}
template <class T, int D>
bool all_finite(const Vector<T, D>& p) {
  for (int d = 0; d < D; ++d)
    if (!std::isfinite(p[d])) return false;
  return true;
}

/// Distance from p to the segment [a, b], written here independently of the library.
template <class T, int D>
T segment_distance(const Point<T, D>& p, const Point<T, D>& a, const Point<T, D>& b) {
  T ab2 = 0, apab = 0;
  for (int d = 0; d < D; ++d) {
    ab2 += (b[d] - a[d]) * (b[d] - a[d]);
    apab += (p[d] - a[d]) * (b[d] - a[d]);
  }
  T s = ab2 > 0 ? std::clamp(apab / ab2, T(0), T(1)) : T(0);
  T r2 = 0;
  for (int d = 0; d < D; ++d) {
    const T q = a[d] + s * (b[d] - a[d]) - p[d];
    r2 += q * q;
  }
  return std::sqrt(r2);
}

/// Distance from p to a polyline.
template <class T, int D>
T polyline_distance(const Point<T, D>& p, const std::vector<Point<T, D>>& poly) {
  if (poly.size() == 1) return segment_distance(p, poly[0], poly[0]);
  T best = std::numeric_limits<T>::infinity();
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) best = std::min(best, segment_distance(p, poly[i], poly[i + 1]));
  return best;
}

/// Distance from points that walk along a polyline (dense samples of the curve it
/// flattens, in parameter order) to it, decided against a bound: the segments near the
/// previous point's nearest are tried first, and every segment only when none of those is
/// within `bound`. The answer is polyline_distance's whenever that exceeds `bound`, and
/// otherwise the distance to one segment (an upper bound of it, itself within `bound`), so
/// `distance(p, bound) <= bound` holds exactly when `polyline_distance(p, poly) <= bound`,
/// at O(1) per point instead of O(segments).
template <class T, int D>
class PolylineWalk {
 public:
  explicit PolylineWalk(const std::vector<Point<T, D>>& poly) : poly_(poly) {}

  T distance(const Point<T, D>& p, T bound) {
    if (poly_.size() == 1) return segment_distance(p, poly_[0], poly_[0]);
    const std::size_t segments = poly_.size() - 1, window = 4;
    const std::size_t lo = last_ > window ? last_ - window : 0, hi = std::min(segments, last_ + window + 1);
    T best = std::numeric_limits<T>::infinity();
    std::size_t at = last_;
    const auto scan = [&](std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) {
        const T d = segment_distance(p, poly_[i], poly_[i + 1]);
        if (d < best) best = d, at = i;
      }
    };
    scan(lo, hi);
    if (!(best <= bound)) scan(0, segments);
    last_ = at;
    return best;
  }

 private:
  const std::vector<Point<T, D>>& poly_;
  std::size_t last_ = 0;
};

/// Central finite difference of c at t with step h: error O(h^2 |c'''|) + O(eps |c| / h).
template <class C>
auto central_difference(const C& c, typename C::Scalar t, typename C::Scalar h) {
  return (c(t + h) - c(t - h)) / (2 * h);
}

}  // namespace casteljau::test

/// Runs `statement`, which must throw casteljau::InvalidArgument (an std::invalid_argument)
/// whose where() is exactly `where_expected` and whose problem() contains `problem_part`.
#define EXPECT_INVALID_ARGUMENT(statement, where_expected, problem_part)                              \
  do {                                                                                               \
    bool caught_ = false;                                                                            \
    try {                                                                                            \
      (void)(statement);                                                                             \
    } catch (const casteljau::InvalidArgument& e_) {                                                 \
      caught_ = true;                                                                                \
      EXPECT_EQ(e_.where(), std::string(where_expected)) << e_.what();                               \
      EXPECT_NE(e_.problem().find(problem_part), std::string::npos)                                  \
          << "problem \"" << e_.problem() << "\" does not mention \"" << problem_part << "\"";       \
      EXPECT_EQ(std::string(e_.what()), e_.where() + ": " + e_.problem());                           \
    } catch (const std::exception& other_) {                                                         \
      ADD_FAILURE() << "threw a different exception: " << other_.what();                             \
      caught_ = true;                                                                                \
    }                                                                                                \
    EXPECT_TRUE(caught_) << #statement " did not throw";                                             \
  } while (0)
