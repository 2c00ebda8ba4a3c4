// The conformance suite (conformance.hpp) for the interpolating polynomial curves:
// Lagrange and Catmull-Rom.
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

using InterpPolyFamily = ::testing::Types<Lagrange<double, 2>>;
INSTANTIATE_TYPED_TEST_SUITE_P(InterpPolyFamily, Conformance, InterpPolyFamily);

}  // namespace casteljau::test
