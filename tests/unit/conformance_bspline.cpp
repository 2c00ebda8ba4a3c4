// The conformance suite (conformance.hpp) for B-splines and NURBS.
#include "conformance.hpp"

namespace casteljau::test {

/// A non-uniform, unclamped cubic B-spline with a double interior knot.
template <>
struct Sample<BSpline<double, 2>> {
  static BSpline<double, 2> make() {
    return BSpline<double, 2>(3, {-1, -0.5, 0, 0.5, 1.5, 1.5, 2.5, 3, 4, 4.5},
                              {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}, {4, 0.5}, {5, 2}});
  }
  // The domain [0.5, 2.5]; the points there are (5/6, 23/18) and (187/45, 11/15), as
  // scipy.interpolate.BSpline 1.10 rounds them (its own de Boor, bit for bit ours).
  static Point<double, 2> start() { return {0.8333333333333334, 1.277777777777778}; }
  static Point<double, 2> end() { return {4.155555555555556, 0.7333333333333334}; }
};

/// The full NURBS circle of radius 2 about (1, -1): nine points, weights 1 and sqrt(2)/2,
/// double knots at the quarters [PT97, Ex. 7.2].
template <>
struct Sample<Nurbs<double, 2>> {
  static Nurbs<double, 2> make() {
    const double h = std::sqrt(0.5);
    return Nurbs<double, 2>(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                            {{3, -1}, {3, 1}, {1, 1}, {-1, 1}, {-1, -1}, {-1, -3}, {1, -3}, {3, -3}, {3, -1}},
                            {1, h, 1, h, 1, h, 1, h, 1});
  }
  static Point<double, 2> start() { return {3, -1}; }
  static Point<double, 2> end() { return {3, -1}; }
};

using BSplineFamily = ::testing::Types<BSpline<double, 2>, Nurbs<double, 2>>;
INSTANTIATE_TYPED_TEST_SUITE_P(BSplineFamily, Conformance, BSplineFamily);

}  // namespace casteljau::test
