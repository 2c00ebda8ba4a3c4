// The conformance suite (conformance.hpp) for the interpolating polynomial curves:
// Lagrange and Catmull-Rom (open centripetal, closed chordal).
#include "conformance.hpp"

namespace casteljau::test {

/// A cubic Lagrange curve through four points at uneven params given out of order; the
/// params are dyadic, so that reversing twice gives them back exactly.
template <>
struct Sample<Lagrange<double, 2>> {
  static Lagrange<double, 2> make() {
    return Lagrange<double, 2>({0.75, -0.5, 2, 0.25}, {{1, 2}, {0, 0}, {3, -1}, {0.5, 1.5}});
  }
  // The domain's ends are the params -0.5 and 2: the points there, exactly.
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {3, -1}; }
};

/// A centripetal open Catmull-Rom curve whose distances are perfect squares (16, 9, 25, 4,
/// 1: intervals 4, 3, 5, 2, 1 exactly), so that its knots and the reversed curve's are
/// exact sums. Segments from P_1 to P_4; domain [0, 3 + 5 + 2] = [0, 10].
template <>
struct Sample<CatmullRom<double, 2>> {
  static CatmullRom<double, 2> make() {
    return CatmullRom<double, 2>({{0, 0}, {16, 0}, {16, 9}, {-9, 9}, {-9, 5}, {-8, 5}}, 0.5);
  }
  static Point<double, 2> start() { return {16, 0}; }
  static Point<double, 2> end() { return {-9, 5}; }
};

/// A closed chordal triangle with integer side lengths 3, 4, 3 (exact knot sums): the
/// curve starts and ends at P_0.
template <>
struct Sample<CatmullRom<double, 3>> {
  static CatmullRom<double, 3> make() { return CatmullRom<double, 3>({{0, 0, 0}, {2, 1, 2}, {2, 1, -2}}, 1.0, true); }
  static Point<double, 3> start() { return {0, 0, 0}; }
  static Point<double, 3> end() { return {0, 0, 0}; }
};

using InterpPolyFamily = ::testing::Types<Lagrange<double, 2>, CatmullRom<double, 2>, CatmullRom<double, 3>>;
INSTANTIATE_TYPED_TEST_SUITE_P(InterpPolyFamily, Conformance, InterpPolyFamily);

}  // namespace casteljau::test
