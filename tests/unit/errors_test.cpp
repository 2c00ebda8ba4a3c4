// Bad input at every constructor and public entry: casteljau::InvalidArgument (an
// std::invalid_argument) whose where() names the argument and whose problem() names the
// rule (docs/errors.md).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;
using R2 = RationalBezier<double, 2>;
using Path2 = Path<double, 2>;
const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

static_assert(std::is_base_of_v<std::invalid_argument, InvalidArgument>);

TEST(Errors, InvalidArgumentIsAnInvalidArgument) {
  try {
    (void)B2(std::vector<P2>{});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "points: a Bézier curve needs at least one control point");
  }
  const InvalidArgument e("points[1]", "coordinate must be finite");
  EXPECT_EQ(e.within("curve").where(), "curve.points[1]");
  EXPECT_EQ(InvalidArgument("[3]", "x").within("segments").where(), "segments[3]");
  EXPECT_EQ(InvalidArgument("", "x").within("curve").where(), "curve");
  EXPECT_EQ(std::string(InvalidArgument("", "only the problem").what()), "only the problem");
}

TEST(Errors, BezierConstruction) {
  EXPECT_INVALID_ARGUMENT(B2(std::vector<P2>{}), "points", "at least one control point");
  EXPECT_INVALID_ARGUMENT((B2{{0, 0}, {nan, 1}}), "points[1][0]", "finite");
  EXPECT_INVALID_ARGUMENT((B2{{0, 0}, {1, 1}, {2, inf}}), "points[2][1]", "finite");
  EXPECT_INVALID_ARGUMENT((B2{{-inf, 0}}), "points[0][0]", "finite");
  EXPECT_INVALID_ARGUMENT((Bezier<double, 3>{{0, 0, 0}, {1, 1, nan}}), "points[1][2]", "finite");
  const std::vector<Vector<double, 2>> none;
  EXPECT_INVALID_ARGUMENT(B2::from_power(none), "coefficients", "at least one");
  const std::vector<Vector<double, 2>> bad{{0, 0}, {nan, 1}};
  EXPECT_INVALID_ARGUMENT(B2::from_power(bad), "coefficients[1][0]", "finite");
}

TEST(Errors, BezierEntries) {
  const B2 c{{0, 0}, {1, 2}, {3, 1}};
  EXPECT_INVALID_ARGUMENT(c(nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(c(inf), "t", "finite");
  EXPECT_INVALID_ARGUMENT(c.derivative_at(nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(c.derivative_at(0.5, -1), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(c.derivative(-1), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(c.split(1.5), "t", "[0, 1]");
  EXPECT_INVALID_ARGUMENT(c.split(-1e-300), "t", "[0, 1]");
  EXPECT_INVALID_ARGUMENT(c.split(nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(c.portion(nan, 1), "a", "finite");
  EXPECT_INVALID_ARGUMENT(c.portion(0, -inf), "b", "finite");
  EXPECT_INVALID_ARGUMENT(c.elevate(-1), "r", ">= 0");
  EXPECT_INVALID_ARGUMENT(reduce_degree(c, 3), "degree", "[0, 2]");
  EXPECT_INVALID_ARGUMENT(reduce_degree(c, -1, Endpoints::free), "degree", "[0, 2]");
  EXPECT_INVALID_ARGUMENT(reduce_degree(c, 0, Endpoints::keep), "degree", ">= 1");
}

TEST(Errors, RationalConstruction) {
  const std::vector<P2> P{{1, 0}, {1, 1}, {0, 1}};
  EXPECT_INVALID_ARGUMENT(R2({}, {}), "points", "at least one control point");
  EXPECT_INVALID_ARGUMENT(R2(P, {1, 1}), "weights", "one weight per control point");
  EXPECT_INVALID_ARGUMENT(R2(P, {1, 1, 1, 1}), "weights", "one weight per control point");
  EXPECT_INVALID_ARGUMENT(R2(P, {1, 1, 0}), "weights[2]", "> 0");
  EXPECT_INVALID_ARGUMENT(R2(P, {1, -0.5, 1}), "weights[1]", "> 0");
  EXPECT_INVALID_ARGUMENT(R2(P, {1, nan, 1}), "weights[1]", "finite");
  EXPECT_INVALID_ARGUMENT(R2(P, {inf, 1, 1}), "weights[0]", "finite");
  EXPECT_INVALID_ARGUMENT(R2({{1, 0}, {1, nan}, {0, 1}}, {1, 1, 1}), "points[1][1]", "finite");
  // A homogeneous point with weight 0 or less is reported at its weight.
  const Bezier<double, 3> h{{1, 0, 1}, {0, 0, 0}, {0, 1, 1}};
  EXPECT_INVALID_ARGUMENT(R2::from_homogeneous(h), "weights[1]", "> 0");
  const Bezier<double, 3> hn{{1, 0, 1}, {1, 1, -2}, {0, 1, 1}};
  EXPECT_INVALID_ARGUMENT(R2::from_homogeneous(hn), "weights[1]", "> 0");
  EXPECT_INVALID_ARGUMENT(R2::circular_arc({0, 0}, 0.0, 0, 1), "radius", "> 0");
  EXPECT_INVALID_ARGUMENT(R2::circular_arc({0, 0}, nan, 0, 1), "radius", "finite");
  EXPECT_INVALID_ARGUMENT(R2::circular_arc({0, 0}, 1, nan, 1), "start_angle", "finite");
  EXPECT_INVALID_ARGUMENT(R2::circular_arc({0, 0}, 1, 0, inf), "end_angle", "finite");
  EXPECT_INVALID_ARGUMENT(R2::circular_arc({0, 0}, 1, 0, 4), "end_angle", "pi");
}

TEST(Errors, RationalEntries) {
  const R2 q({{1, 0}, {1, 1}, {0, 1}}, {1, 0.5, 1});
  EXPECT_INVALID_ARGUMENT(q(nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(q.derivative_at(inf), "t", "finite");
  EXPECT_INVALID_ARGUMENT(q.derivative_at(0.5, -1), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(q.split(2.0), "t", "[0, 1]");
  EXPECT_INVALID_ARGUMENT(q.split(nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(q.portion(0, nan), "b", "finite");
  EXPECT_INVALID_ARGUMENT(q.elevate(-2), "r", ">= 0");
  // The extension of a rational curve past a pole has a non-positive weight.
  const R2 r({{0, 0}, {1, 1}, {2, 0}}, {1, 4, 1});  // w(t) = 1 + 6t - 6t^2 vanishes near -0.16
  EXPECT_INVALID_ARGUMENT(r.portion(-1, 1), "weights[0]", "> 0");
}

TEST(Errors, PathConstruction) {
  const B2 a{{0, 0}, {1, 1}}, b{{1, 1}, {2, 0}};
  EXPECT_INVALID_ARGUMENT(Path2(std::vector<Path2::SegmentType>{}), "segments", "at least one segment");
  EXPECT_INVALID_ARGUMENT(Path2({a, b}, {0.0, 1.0}), "breaks", "one more break than segments");
  EXPECT_INVALID_ARGUMENT(Path2({a, b}, {0.0, 1.0, 2.0, 3.0}), "breaks", "one more break than segments");
  EXPECT_INVALID_ARGUMENT(Path2({a, b}, {0.0, 0.0, 2.0}), "breaks[1]", "strictly increasing");
  EXPECT_INVALID_ARGUMENT(Path2({a, b}, {0.0, 3.0, 2.0}), "breaks[2]", "strictly increasing");
  EXPECT_INVALID_ARGUMENT(Path2({a, b}, {nan, 1.0, 2.0}), "breaks[0]", "finite");
  EXPECT_INVALID_ARGUMENT(Path2({a, b}, {0.0, 1.0, inf}), "breaks[2]", "finite");
}

TEST(Errors, PathEntries) {
  const Path2 p({B2{{0, 0}, {1, 1}}, B2{{1, 1}, {2, 0}}});
  EXPECT_INVALID_ARGUMENT(p(nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(p.derivative_at(-inf), "t", "finite");
  EXPECT_INVALID_ARGUMENT(p.derivative_at(0.5, -1), "k", ">= 0");
  EXPECT_EQ(p.derivative_at(0.5, 0), (Vector<double, 2>{0.5, 0.5}));  // order 0: the point
  EXPECT_INVALID_ARGUMENT(p.one_sided_derivative(2, 0.5, 1), "segment", "0..1");
  EXPECT_INVALID_ARGUMENT(p.one_sided_derivative(0, nan, 1), "t", "finite");
  EXPECT_INVALID_ARGUMENT(end_tangent(p, 5, true), "segment", "0..1");
}

TEST(Errors, BasisFunctions) {
  EXPECT_INVALID_ARGUMENT(bernstein(0, -1, 0.5), "n", ">= 0");
  EXPECT_INVALID_ARGUMENT(bernstein(0, 3, nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(bernstein(0, 3, 0.5, Interval<double>{1, 1}), "interval", "lo < hi");
  EXPECT_INVALID_ARGUMENT(bernstein(0, 3, 0.5, Interval<double>{2, 1}), "interval", "lo <= hi");  // the Interval itself refuses
  EXPECT_INVALID_ARGUMENT(bernstein(0, 3, 0.5, Interval<double>{nan, 1}), "interval.lo", "finite");
  EXPECT_INVALID_ARGUMENT(bernstein(0, 3, 0.5, Interval<double>{0, inf}), "interval.hi", "finite");
  std::vector<double> out(3);
  EXPECT_INVALID_ARGUMENT(bernstein_all(3, 0.5, std::span<double>(out)), "out", "n + 1 = 4");
  EXPECT_INVALID_ARGUMENT(bernstein_all(-2, 0.5, std::span<double>(out)), "n", ">= 0");
  EXPECT_INVALID_ARGUMENT(bernstein_all(2, inf, std::span<double>(out)), "t", "finite");
  EXPECT_INVALID_ARGUMENT(bernstein_derivative(0, 3, -1, 0.5), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(bernstein_derivative(0, 3, 1, nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(bernstein_derivative(0, 3, 5, nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(bernstein_all_derivatives(2, 1, 0.5, std::span<double>(out.data(), 2)), "out", "n + 1 = 3");
  EXPECT_INVALID_ARGUMENT(bernstein_all_derivatives(2, -1, 0.5, std::span<double>(out)), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(bernstein_all_derivatives(2, 3, nan, std::span<double>(out)), "t", "finite");
  EXPECT_INVALID_ARGUMENT(binomial_row<double>(-1), "n", ">= 0");
  EXPECT_INVALID_ARGUMENT(bernstein_to_power_matrix<double>(-1), "n", ">= 0");
  EXPECT_INVALID_ARGUMENT(power_to_bernstein_matrix<double>(-3), "n", ">= 0");
  const std::vector<double> c{1, nan, -1}, e{}, one{1, 2};
  EXPECT_INVALID_ARGUMENT(bernstein_roots<double>(c), "c[1]", "finite");
  EXPECT_INVALID_ARGUMENT(bernstein_product<double>(e, one), "f", "at least one");
  EXPECT_INVALID_ARGUMENT(bernstein_product<double>(one, e), "g", "at least one");
}

TEST(Errors, Algorithms) {
  const B2 a{{0, 0}, {1, 1}, {2, 1}}, b{{2, 1}, {3, 1}, {4, 0}};
  const Path2 p({a, b});
  EXPECT_INVALID_ARGUMENT(is_cr(p, 1, 1, -1e-9), "tolerance", ">= 0");
  EXPECT_INVALID_ARGUMENT(is_cr(p, 1, 1, nan), "tolerance", "finite");
  EXPECT_INVALID_ARGUMENT(is_cr(p, 0, 1, 1e-9), "joint", "interior break");
  EXPECT_INVALID_ARGUMENT(is_cr(p, 2, 1, 1e-9), "joint", "interior break");
  EXPECT_INVALID_ARGUMENT(is_cr(p, 1, -1, 1e-9), "r", ">= 0");
  EXPECT_INVALID_ARGUMENT(joint_derivatives(p, 1, -1), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(is_g1(p, 1, -1.0, 1e-9), "tolerance", ">= 0");
  EXPECT_INVALID_ARGUMENT(is_g1(p, 1, 1e-9, -1.0), "angle_tolerance", ">= 0");
  EXPECT_INVALID_ARGUMENT(is_g1(p, 1, 1e-9, nan), "angle_tolerance", "finite");
  // Even when the positions already differ, a bad angle tolerance is reported.
  const Path2 gap({a, B2{{5, 5}, {6, 6}}});
  EXPECT_INVALID_ARGUMENT(is_g1(gap, 1, 1e-9, nan), "angle_tolerance", "finite");
  EXPECT_INVALID_ARGUMENT(parametric_continuity(p, 1, 2, -1.0), "tolerance", ">= 0");
  EXPECT_INVALID_ARGUMENT(parametric_continuity(p, 1, -2, 1e-9), "max_order", ">= 0");
  EXPECT_INVALID_ARGUMENT(cr_join_points(a, 0.0, 3, 1.0, 1), "previous_length", "> 0");
  EXPECT_INVALID_ARGUMENT(cr_join_points(a, nan, 3, 1.0, 1), "previous_length", "finite");
  EXPECT_INVALID_ARGUMENT(cr_join_points(a, 1.0, 3, -1.0, 1), "next_length", "> 0");
  EXPECT_INVALID_ARGUMENT(cr_join_points(a, 1.0, 3, 1.0, 4), "r", "[0, degree = 3]");
  EXPECT_INVALID_ARGUMENT(cr_join_points(a, 1.0, 3, 1.0, -1), "r", "[0, degree = 3]");
  EXPECT_INVALID_ARGUMENT(curvature(a, nan), "t", "finite");
  EXPECT_INVALID_ARGUMENT(flatten(a, 0.0), "tolerance", "> 0");
  EXPECT_INVALID_ARGUMENT(flatten(R2({{0, 0}, {1, 1}}, {1, 2}), -1.0), "tolerance", "> 0");
}

TEST(Errors, BatchEvaluate) {
  const B2 c{{0, 0}, {1, 2}, {3, 1}};
  const std::vector<double> ts{0, 0.5, 1}, bad_ts{0, 0.5, nan};
  std::vector<double> x(3), y(2), big(6), big2(5);
  EXPECT_INVALID_ARGUMENT(evaluate(c, std::span<const double>(ts), {std::span<double>(x), std::span<double>(y)}), "out[1]",
                          "one value per parameter");
  EXPECT_INVALID_ARGUMENT(evaluate(c, std::span<const double>(bad_ts), {std::span<double>(x), std::span<double>(x)}), "t[2]",
                          "finite");
  std::vector<P2> pts(2);
  EXPECT_INVALID_ARGUMENT(evaluate(c, std::span<const double>(ts), std::span<P2>(pts)), "out", "one point per parameter");
  const std::vector<B2> many{c, c};
  EXPECT_INVALID_ARGUMENT(
      evaluate(std::span<const B2>(many), std::span<const double>(ts), {std::span<double>(big2), std::span<double>(big)}),
      "out[0]", "curves x parameters = 6");
  EXPECT_INVALID_ARGUMENT(
      evaluate(std::span<const B2>(many), std::span<const double>(ts), {std::span<double>(big), std::span<double>(big2)}),
      "out[1]", "curves x parameters = 6");
  // The generic fallback (any Curve) checks its output too.
  const R2 q({{1, 0}, {1, 1}, {0, 1}}, {1, 0.5, 1});
  EXPECT_INVALID_ARGUMENT(evaluate(q, std::span<const double>(ts), std::span<P2>(pts)), "out", "one point per parameter");
}

// Messages quote numbers in their shortest round-trip form, so a user sees the value they
// wrote (1.1), not its 17-digit expansion (1.1000000000000001).
TEST(Errors, MessagesQuoteNumbersAsWritten) {
  const B2 c{{0, 0}, {1, 1}};
  EXPECT_INVALID_ARGUMENT(c.split(1.1), "t", "got 1.1");
  try {
    (void)c.split(1.1);
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.problem(), "split parameter must lie in [0, 1], got 1.1");
  }
}

// A rational curve with weights 1 and 3 has the weight function W(t) = 1 + 2t, which
// vanishes at t = -1/2 (exactly representable): evaluating there is bad input naming t,
// not a silent infinity.
TEST(Errors, RationalPoleOutsideTheDomain) {
  const R2 q({{0, 0}, {1, 0}}, {1, 3});
  EXPECT_INVALID_ARGUMENT(q(-0.5), "t", "pole");
  EXPECT_INVALID_ARGUMENT(q.derivative_at(-0.5, 1), "t", "pole");
  // Next to the pole the curve is finite: R(t) = 3t / (1 + 2t).
  EXPECT_DOUBLE_EQ(q(-0.25)[0], 3 * -0.25 / (1 + 2 * -0.25));
}

}  // namespace
