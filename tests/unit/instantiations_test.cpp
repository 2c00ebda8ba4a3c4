// Other scalar types and dimensions through the whole API (float, long double; one and
// four dimensions). In the unity group of scalar_types_test.cpp (CMakeLists.txt): the
// library's templates at float and long double are instantiated there anyway, so these
// checks cost about 1 s of compile there against about 10 s in the other group.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "test_support.hpp"

namespace instantiations {

using namespace casteljau;

// Other scalar types and dimensions compile and work through the whole API (accuracy
// against a high-precision oracle is in tests/reference). Tolerances are in units of
// each type's own epsilon.
template <class T>
void exercise_scalar_type() {
  const T e = std::numeric_limits<T>::epsilon();
  const Bezier<T, 3> c{{0, 0, 0}, {1, 2, 0.5}, {3, -1, 1}, {4, 1, 0}};
  EXPECT_EQ(c(T(0)), c.points().front());
  EXPECT_EQ(c(T(0.5))[0], T(2));  // (0 + 3 + 9 + 4) / 8, dyadic: exact
  const auto s = c.split(T(0.5));
  EXPECT_EQ(s.left.points().back(), c(T(0.5)));
  EXPECT_EQ(c.elevate(2).degree(), 5);
  const RationalBezier<T, 2> q({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(T(2)) / 2, 1});
  const auto p = q(T(0.3));
  EXPECT_NEAR(std::hypot(p[0], p[1]), T(1), 8 * e);
  EXPECT_NEAR(*curvature(q, T(0.3)), T(1), 64 * e);
  const auto b = bounds(q);
  EXPECT_NEAR(b.hi[0], T(1), 4 * e);
  const Path<T, 2> path({Bezier<T, 2>{{0, 0}, {1, 0}}, q});
  EXPECT_EQ(path(T(1)), (Point<T, 2>{1, 0}));
  const auto poly = flatten(path, T(1e-3));
  EXPECT_GE(poly.size(), 3u);
  std::vector<T> ts{T(0), T(0.25), T(1)};
  std::vector<Point<T, 3>> out(3);
  evaluate(c, std::span<const T>(ts), std::span<Point<T, 3>>(out));
  EXPECT_NEAR(out[1][1], c(T(0.25))[1], 64 * e);
}

TEST(Instantiations, FloatAndLongDouble) {
  exercise_scalar_type<float>();
  exercise_scalar_type<long double>();
}

TEST(Instantiations, OneAndFourDimensions) {
  const Bezier<double, 1> c1{Point<double, 1>(0.0), Point<double, 1>(2.0), Point<double, 1>(1.0)};
  EXPECT_EQ(c1(0.5)[0], 1.25);
  // x(t) = 4t - 3t^2 peaks at t = 2/3 (the root is found to a few eps; flat there).
  EXPECT_NEAR(bounds(c1).hi[0], 4.0 / 3, 4 * std::numeric_limits<double>::epsilon());
  const Bezier<double, 4> c4{{0, 0, 0, 0}, {1, 1, 1, 1}, {2, 0, 2, -2}};
  EXPECT_EQ(c4(0.5), (Point<double, 4>{1, 0.5, 1, 0}));
  EXPECT_EQ(c4.derivative_at(0.0), (Vector<double, 4>{2, 2, 2, 2}));
}

}  // namespace instantiations
