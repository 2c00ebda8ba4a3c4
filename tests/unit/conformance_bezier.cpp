// The conformance suite (conformance.hpp) for the Bézier family: Bezier, RationalBezier,
// Polyline, Path and Pieces; and the scalar types and dimensions beyond double 2-D/3-D.
#include <numbers>

#include "conformance.hpp"

namespace casteljau::test {

template <>
struct Sample<Bezier<double, 2>> {
  static Bezier<double, 2> make() { return {{0, 0}, {1, 2.5}, {2.5, -1}, {4, 1.5}, {3, 3}}; }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {3, 3}; }
};

template <>
struct Sample<Bezier<double, 3>> {
  static Bezier<double, 3> make() { return {{0, 0, 1}, {1, 2, -1}, {3, -1, 0.5}, {2, 2, 2}}; }
  static Point<double, 3> start() { return {0, 0, 1}; }
  static Point<double, 3> end() { return {2, 2, 2}; }
};

template <>
struct Sample<RationalBezier<double, 2>> {
  static RationalBezier<double, 2> make() { return {{{1, 0}, {1, 1}, {0.5, 2}, {0, 1}}, {1, 0.6, 2.5, 1.2}}; }
  static Point<double, 2> start() { return {1, 0}; }
  static Point<double, 2> end() { return {0, 1}; }
};

template <>
struct Sample<Path<double, 2>> {
  // A cubic on [-1, 0.5] and a rational quadratic on [0.5, 2], C0 at the joint.
  static Path<double, 2> make() {
    return Path<double, 2>({Bezier<double, 2>{{0, 0}, {1, 1}, {2, -1}, {3, 0}},
                            RationalBezier<double, 2>({{3, 0}, {4, 1}, {5, 0}}, {1, 3, 1})},
                           {-1.0, 0.5, 2.0});
  }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {5, 0}; }
};

template <>
struct Sample<Polyline<double, 2>> {
  static Polyline<double, 2> make() { return {{0, 0}, {1, 2}, {1, 2}, {3, -1}, {4, 0.5}}; }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {4, 0.5}; }
};

/// A path of every segment type, one of them a polyline whose own domain [0, 3] is mapped
/// onto [1, 1.5] (so its derivatives scale by 6).
template <>
struct Sample<Path<double, 3>> {
  static Path<double, 3> make() {
    return Path<double, 3>({Bezier<double, 3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}},
                            Polyline<double, 3>{{2, 0, 1}, {3, 1, 1}, {3, 2, 0}, {4, 2, 2}},
                            RationalBezier<double, 3>({{4, 2, 2}, {5, 3, 2}, {6, 2, 1}}, {1, 0.5, 2})},
                           {0.0, 1.0, 1.5, 4.0});
  }
  static Point<double, 3> start() { return {0, 0, 0}; }
  static Point<double, 3> end() { return {6, 2, 1}; }
};

template <>
struct Sample<Pieces<double, 2>> {
  static Pieces<double, 2> make() { return pieces(Sample<Path<double, 2>>::make()); }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {5, 0}; }
};

using BezierFamily = ::testing::Types<Bezier<double, 2>, RationalBezier<double, 2>, Path<double, 2>, Bezier<double, 3>,
                                     Polyline<double, 2>, Path<double, 3>, Pieces<double, 2>>;
INSTANTIATE_TYPED_TEST_SUITE_P(BezierFamily, Conformance, BezierFamily);

}  // namespace casteljau::test

namespace {

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

}  // namespace
