// The conformance suite (conformance.hpp) for the interpolating cubics: Hermite curves and
// cubic splines.
#include "conformance.hpp"

namespace casteljau::test {

/// A Hermite curve on uneven params with tangents of mixed sizes.
template <>
struct Sample<Hermite<double, 2>> {
  static Hermite<double, 2> make() {
    return Hermite<double, 2>({-1, 0.5, 0.75, 2.5}, {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}},
                              {{1, 1}, {2, 0}, {0.5, -3}, {1, 1}});
  }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {3, -1}; }
};

/// Kochanek-Bartels one-sided tangents (continuity -0.5: a corner at every point).
template <>
struct Sample<Hermite<double, 3>> {
  static Hermite<double, 3> make() {
    const std::vector<double> u = {0, 1, 1.5, 3};
    const std::vector<Point<double, 3>> P = {{0, 0, 0}, {1, 2, 1}, {2.5, 1.5, -1}, {3, -1, 0}};
    auto m = kochanek_bartels_tangents(u, P, KochanekBartels<double>{0.25, -0.5, 0.5});
    return Hermite<double, 3>(u, P, m.incoming, m.outgoing);
  }
  static Point<double, 3> start() { return {0, 0, 0}; }
  static Point<double, 3> end() { return {3, -1, 0}; }
};

/// A natural spline on uneven params.
template <>
struct Sample<CubicSpline<double, 2>> {
  static CubicSpline<double, 2> make() {
    return CubicSpline<double, 2>({0, 0.5, 1.25, 2, 4}, {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}, {1, -2}});
  }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {1, -2}; }
};

/// A closed (periodic) spline.
template <>
struct Sample<CubicSpline<double, 3>> {
  static CubicSpline<double, 3> make() {
    return CubicSpline<double, 3>({0, 1, 1.5, 2.25, 3}, {{1, 0, 0}, {0, 1, 0.5}, {-1, 0, 1}, {0, -1, 0.5}, {1, 0, 0}},
                                  SplineBoundary<double, 3>::periodic());
  }
  static Point<double, 3> start() { return {1, 0, 0}; }
  static Point<double, 3> end() { return {1, 0, 0}; }
};

using InterpSplineFamily = ::testing::Types<Hermite<double, 2>, Hermite<double, 3>, CubicSpline<double, 2>, CubicSpline<double, 3>>;
INSTANTIATE_TYPED_TEST_SUITE_P(InterpSplineFamily, Conformance, InterpSplineFamily);

}  // namespace casteljau::test
