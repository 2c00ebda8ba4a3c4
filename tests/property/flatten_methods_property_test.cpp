// The three flattening methods: each within its tolerance on random curves (cubics with
// cusps, loops and inflections included; rational ones too), scaling exactly by powers of
// two, and the segment counts compared with each other and with the greedy near-optimal
// count of W3 (docs/performance.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <vector>

#include "../unit/flatten_oracle.hpp"
#include "../unit/test_support.hpp"
#include "generators.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;

constexpr FlattenMethod methods[] = {FlattenMethod::uniform, FlattenMethod::subdivision, FlattenMethod::optimal};

template <class C>
void check_within(const C& c, double tol, FlattenMethod m) {
  const auto poly = flatten(c, tol, m);
  RC_ASSERT(poly.front() == c.points().front());
  RC_ASSERT(poly.back() == c.points().back());
  // Dense samples (2000, plus 16 per segment) of the curve are within tolerance.
  const int S = 2000 + 16 * static_cast<int>(poly.size());
  test::PolylineWalk walk(poly);
  for (int i = 0; i <= S; ++i) RC_ASSERT(walk.distance(c(static_cast<double>(i) / S), tol) <= tol);
}

// Random curves of degree 1..7 and random cubics through an affine image of the cusp cubic
// (0,0),(2,2),(0,2),(2,0) (cusp at t = 1/2; an affine map keeps it): every method keeps
// the tolerance, polynomial and rational.
RC_GTEST_PROP(FlattenMethods, WithinToleranceIncludingCusps, ()) {
  const double tol = std::pow(10.0, -*rc::gen::inRange(1, 5));
  const int n = *rc::gen::inRange(1, 8);
  const Bezier<double, 2> c(prop::control_points<2>(n));
  const auto A = prop::control_points<2>(2);  // columns and translation of an affine map
  std::vector<P2> cusp;
  for (const P2 q : {P2(0, 0), P2(2, 2), P2(0, 2), P2(2, 0)})
    cusp.push_back(P2(A[0][0] * q[0] + A[1][0] * q[1] + A[2][0], A[0][1] * q[0] + A[1][1] * q[1] + A[2][1]));
  const Bezier<double, 2> k(cusp);
  const RationalBezier<double, 2> r(c.points(), prop::weights(n));
  for (const FlattenMethod m : methods) {
    check_within(c, tol, m);
    check_within(k, tol, m);
    check_within(r, tol, m);
  }
}

// Scaling a curve and its tolerance by 2^k scales every method's polyline by exactly 2^k.
RC_GTEST_PROP(FlattenMethods, ScaleExactlyByPowersOfTwo, ()) {
  const int n = *rc::gen::inRange(2, 6);
  const auto P = prop::control_points<2>(n);
  const int k = *rc::gen::inRange(-900, 900);
  const double tol = std::pow(10.0, -*rc::gen::inRange(1, 4));
  std::vector<P2> Q(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) Q[i] = P2(std::ldexp(P[i][0], k), std::ldexp(P[i][1], k));
  for (const FlattenMethod m : methods) {
    const auto a = flatten(Bezier<double, 2>(P), tol, m), b = flatten(Bezier<double, 2>(Q), std::ldexp(tol, k), m);
    RC_ASSERT(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      RC_ASSERT(b[i][0] == std::ldexp(a[i][0], k));
      RC_ASSERT(b[i][1] == std::ldexp(a[i][1], k));
    }
  }
}

// --- counts -------------------------------------------------------------------------------

/// splitmix64 as docs/performance.md ("Workloads") defines it.
struct SplitMix {
  std::uint64_t state;
  double uniform(double a, double b) {
    state += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return a + (b - a) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

// 1000 cubics of W3 dataset A (points uniform in [0, 100]^2, splitmix64 seed 3) at
// tolerance 0.1: the optimal method within 5% of the near-optimal count, fewer segments
// than the other two, and its count estimate (told before emitting) within 3%. The
// numbers are printed for docs/accuracy.md.
TEST(FlattenMethods, CountsOnW3RandomCubics) {
  SplitMix rng{3};
  long uniform = 0, subdivision = 0, optimal = 0, near = 0;
  double estimate = 0;
  for (int i = 0; i < 1000; ++i) {
    std::vector<P2> P;
    for (int k = 0; k < 4; ++k) {
      const double x = rng.uniform(0, 100);
      P.emplace_back(x, rng.uniform(0, 100));
    }
    const Bezier<double, 2> c(P);
    uniform += static_cast<long>(flatten(c, 0.1, FlattenMethod::uniform).size()) - 1;
    subdivision += static_cast<long>(flatten(c, 0.1, FlattenMethod::subdivision).size()) - 1;
    optimal += static_cast<long>(flatten(c, 0.1, FlattenMethod::optimal).size()) - 1;
    estimate += flatten_count_estimate(c, 0.1);
    near += test::near_optimal_count(c, 0.1);
  }
  std::cout << "W3 random cubics (1000, tol 0.1): near-optimal " << near << ", optimal " << optimal << " ("
            << static_cast<double>(optimal) / static_cast<double>(near) << "x, estimate " << estimate << "), subdivision "
            << subdivision << " (" << static_cast<double>(subdivision) / static_cast<double>(near) << "x), uniform " << uniform
            << " (" << static_cast<double>(uniform) / static_cast<double>(near) << "x)\n";
  EXPECT_LE(static_cast<double>(optimal), 1.05 * static_cast<double>(near));
  EXPECT_LT(optimal, subdivision);
  EXPECT_LT(optimal, uniform);
  EXPECT_NEAR(estimate, static_cast<double>(optimal), 0.03 * static_cast<double>(optimal));
}

}  // namespace
