// B-spline basis functions, knot vectors, B-spline and NURBS curves: textbook values
// [PT97], closed forms, and every knot and weight error of the contract.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;

// [PT97, Ex. 2.3]: U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2, u = 5/2 lies in span 4 and the
// non-zero functions are N_{2,2} = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8. Their derivatives
// from the closed forms on [2, 3] (N_{2,2} = (3-u)^2/2, N_{4,2} = (u-2)^2/2, and the
// middle one 1 minus both): -1/2, 0, 1/2; second derivatives 1, -2, 1. All dyadic: exact.
TEST(BSplineBasis, NurbsBookExample2_3) {
  const std::vector<double> U{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
  const std::span<const double> u(U);
  EXPECT_EQ(find_span(u, 2, 2.5), 4u);
  std::vector<double> N(3);
  basis_functions(u, 2, 4, 2.5, std::span<double>(N));
  EXPECT_EQ(N, (std::vector<double>{0.125, 0.75, 0.125}));
  const auto ders = basis_function_derivatives(u, 2, 4, 2.5, 3);
  EXPECT_EQ(ders[0], (std::vector<double>{0.125, 0.75, 0.125}));
  EXPECT_EQ(ders[1], (std::vector<double>{-0.5, 0, 0.5}));
  EXPECT_EQ(ders[2], (std::vector<double>{1, -2, 1}));
  EXPECT_EQ(ders[3], (std::vector<double>{0, 0, 0}));  // above the degree
}

// Span rule: right limits at interior knots (also a double knot), the last non-empty span
// at the domain's end, the end spans outside the domain.
TEST(BSplineBasis, FindSpan) {
  const std::vector<double> U{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
  const std::span<const double> u(U);
  EXPECT_EQ(find_span(u, 2, 0.0), 2u);
  EXPECT_EQ(find_span(u, 2, 0.999), 2u);
  EXPECT_EQ(find_span(u, 2, 1.0), 3u);
  EXPECT_EQ(find_span(u, 2, 4.0), 7u);  // after the double knot 4 (U_6 = U_7 = 4)
  EXPECT_EQ(find_span(u, 2, 5.0), 7u);  // the end: the left limit
  EXPECT_EQ(find_span(u, 2, 9.0), 7u);
  EXPECT_EQ(find_span(u, 2, -3.0), 2u);
  EXPECT_EQ(knot_multiplicity(u, 4.0), 2u);
  EXPECT_EQ(knot_multiplicity(u, 0.0), 3u);
  EXPECT_EQ(knot_multiplicity(u, 2.5), 0u);
}

TEST(BSplineBasis, KnotErrors) {
  auto check = [](std::vector<double> U, int p) { check_knots<double>(U, p); };
  EXPECT_INVALID_ARGUMENT(check({0, 1}, -1), "degree", ">= 0");
  EXPECT_INVALID_ARGUMENT(check({0, 0, 1}, 0), "knots[1]", "may be repeated at most once (p + 1) for degree 0");
  EXPECT_INVALID_ARGUMENT(check({0, 0, 1}, 1), "knots", "at least 4 knots");
  EXPECT_INVALID_ARGUMENT(check({0, 0, 2, 1, 3, 3}, 1), "knots[3]", "non-decreasing (1 after 2)");
  EXPECT_INVALID_ARGUMENT(check({0, 0, 0, 0, 1, 1, 1}, 2), "knots[3]", "end knot may be repeated at most 3 times");
  // p + 1 = 3 copies of an interior knot: a break where the curve may jump (allowed); 4 are not.
  check({0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, 2);
  EXPECT_INVALID_ARGUMENT(check({0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 2), "knots[6]", "interior knot may be repeated at most 3");
  EXPECT_INVALID_ARGUMENT(check({0, 0, NAN, 1}, 1), "knots[2]", "finite");
  EXPECT_INVALID_ARGUMENT(check({0, 1, 1, 1, 1, 2}, 2), "knots[4]", "repeated 4 times");  // the first knot past p + 1
}

TEST(BSpline, ConstructionErrors) {
  const std::vector<P2> P{{0, 0}, {1, 1}, {2, 0}};
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(-1, {0, 1, 2}, P)), "degree", ">= 0");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(0, {0, 1, 2}, P)), "knots", "len(points) + degree + 1 = 4");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(3, {0, 0, 0, 0, 1, 1, 1}, P)), "points", "at least 4 control points");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(2, {0, 0, 0, 1, 1}, P)), "knots", "len(points) + degree + 1 = 6");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(1, {0, 1, 0.5, 2, 3}, P)), "knots[2]", "non-decreasing");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(2, {0, 0, 1, 1, 2, 2}, P)), "knots", "empty");  // U_2 = U_3: empty domain
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(1, {0, 0, 1, 2, 2}, {{0, 0}, {1, NAN}, {2, 0}})), "points[1][1]", "finite");
  EXPECT_INVALID_ARGUMENT((Nurbs<double, 2>(1, {0, 0, 1, 2, 2}, P, {1, 0, 1})), "weights[1]", "> 0");
  EXPECT_INVALID_ARGUMENT((Nurbs<double, 2>(1, {0, 0, 1, 2, 2}, P, {1, 1})), "weights", "one weight per control point");
  EXPECT_INVALID_ARGUMENT((Nurbs<double, 2>(1, {0, 0, 1, 2, 2}, P, {1, -1, 1})), "weights[1]", "> 0");
  EXPECT_INVALID_ARGUMENT((Nurbs<double, 2>(1, {0, 0, 1, 2, 2}, P, {1e300, 1e-300, 1})), "weights[1]", "too small");
}

// A clamped B-spline with one span is its Bézier curve: same points, same derivatives.
TEST(BSpline, SingleSpanIsBezier) {
  const std::vector<P2> P{{0, 0}, {1, 3}, {3, 3}, {4, 0}};
  const BSpline<double, 2> b(3, {0, 0, 0, 0, 1, 1, 1, 1}, P);
  const Bezier<double, 2> z(P);
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    EXPECT_EQ(b(t), z(t)) << t;  // dyadic parameters and integer points: both exact
    EXPECT_LE(test::max_coord_diff(b.derivative_at(t, 1), z.derivative_at(t, 1)), 1e-14);
    EXPECT_LE(test::max_coord_diff(b.derivative_at(t, 2), z.derivative_at(t, 2)), 1e-13);
  }
  EXPECT_EQ(b.derivative_at(0.5, 4), V2(0, 0));
  const auto p = pieces(b);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ((std::get<Bezier<double, 2>>(p.segments()[0]).points()), P);
}

// Degree 0 is a step function: C(t) = P_i on [U_i, U_(i+1)), the last value at the
// domain's end, the end values continued outside; every derivative is zero; each piece is a
// one-point Bézier curve.
TEST(BSpline, DegreeZeroIsAStepFunction) {
  using P1 = Point<double, 1>;
  const BSpline<double, 1> c(0, {0, 1, 2, 3}, {P1(4), P1(5), P1(7)});
  const std::vector<std::pair<double, double>> want{{-0.5, 4}, {0, 4}, {0.5, 4}, {1, 5}, {1.999, 5}, {2, 7}, {3, 7}, {3.5, 7}};
  for (const auto& [t, v] : want) {
    EXPECT_EQ(c(t), P1(v)) << t;
    EXPECT_EQ(c.derivative_at(t, 1), (Vector<double, 1>(0))) << t;
    EXPECT_EQ(c.derivative_at(t, 3), (Vector<double, 1>(0))) << t;
  }
  std::vector<double> ts;
  for (const auto& [t, v] : want) ts.push_back(t);
  std::vector<P1> out(ts.size());
  c.evaluate(ts, out);
  for (std::size_t j = 0; j < ts.size(); ++j) EXPECT_EQ(out[j], P1(want[j].second)) << ts[j];
  const auto p = pieces(c);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.breaks(), (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ((std::get<Bezier<double, 1>>(p.segments()[1]).points()), (std::vector<P1>{P1(5)}));
}

// A sawtooth of degree 1 with jumps (every interior knot twice, p + 1):
// C(t) = (t, t - floor(t)) on [0, 3), the right limit 0 at the teeth, the left limit 1 at
// the end; velocity (1, 1) everywhere, also at a jump (the right piece's).
TEST(BSpline, SawtoothJumpsToTheRightLimit) {
  const BSpline<double, 2> c(1, {0, 0, 1, 1, 2, 2, 3, 3}, {P2(0, 0), P2(1, 1), P2(1, 0), P2(2, 1), P2(2, 0), P2(3, 1)});
  for (const double t : {0.0, 0.25, 0.5, 1.0, 1.75, 2.0, 2.5}) {
    EXPECT_EQ(c(t), P2(t, t - std::floor(t))) << t;  // dyadic: exact
    EXPECT_EQ(c.derivative_at(t, 1), V2(1, 1)) << t;
  }
  EXPECT_EQ(c(3.0), P2(3, 1));
  EXPECT_EQ(c.derivative_at(1.0, 2), V2(0, 0));
  const auto p = pieces(c);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.breaks(), (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ((std::get<Bezier<double, 2>>(p.segments()[1]).points()), (std::vector<P2>{P2(1, 0), P2(2, 1)}));
  // A quadratic jump: two Bézier pieces 0, 1, 0 on [0, 1] and 5, 6, 9 on [1, 2]. At 1 the
  // right piece answers: 5 and slope 2 (6 - 5) (the left limits are 0 and 2 (0 - 1)).
  using P1 = Point<double, 1>;
  const BSpline<double, 1> q(2, {0, 0, 0, 1, 1, 1, 2, 2, 2}, {P1(0), P1(1), P1(0), P1(5), P1(6), P1(9)});
  EXPECT_EQ(q(1.0), P1(5));
  EXPECT_EQ(q.derivative_at(1.0, 1), (Vector<double, 1>(2)));
  EXPECT_EQ(q(0.5), P1(0.5));
  EXPECT_EQ(q(2.0), P1(9));
  // NURBS: the same rule on the homogeneous points.
  const Nurbs<double, 2> n(1, {0, 0, 1, 1, 2, 2}, {P2(0, 0), P2(1, 1), P2(4, 0), P2(4, 2)}, {1, 2, 1, 1});
  EXPECT_EQ(n(1.0), P2(4, 0));
  EXPECT_EQ(n(2.0), P2(4, 2));
  EXPECT_LT(norm(n(0.5) - P2(2.0 / 3, 2.0 / 3)), 1e-15);  // (0.5 (0, 0) + 1 (1, 1)) / 1.5
}

// The uniform cubic B-spline segment on [0, 1] with knots -3..4 has Bézier points
// ((P0 + 4 P1 + P2) / 6, (2 P1 + P2) / 3, (P1 + 2 P2) / 3, (P1 + 4 P2 + P3) / 6) [Farin02, 7.5].
TEST(BSpline, UniformCubicBezierPieces) {
  const std::vector<P2> P{{0, 0}, {6, 6}, {12, 0}, {18, 6}};
  const BSpline<double, 2> b(3, {-3, -2, -1, 0, 1, 2, 3, 4}, P);
  EXPECT_EQ(b.domain(), (Interval<double>{0, 1}));
  const auto p = pieces(b);
  ASSERT_EQ(p.size(), 1u);
  const auto& Q = std::get<Bezier<double, 2>>(p.segments()[0]).points();
  const std::vector<P2> want{{6, 4}, {8, 4}, {10, 2}, {12, 2}};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LE(test::max_coord_diff(Q[i], want[i]), 1e-14) << i;
}

// The NURBS circle: every point at distance exactly r from the centre, to rounding (a few
// eps of r), also for tiny and huge radii.
TEST(Nurbs, FullCircleAtEveryScale) {
  const double h = std::sqrt(0.5);
  for (double r : {1.0, 1e-14, 1e-300, 1e300}) {
    std::vector<P2> P;
    for (const auto& q : std::vector<P2>{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}})
      P.push_back(P2(r * q[0], r * q[1]));
    const Nurbs<double, 2> c(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, P, {1, h, 1, h, 1, h, 1, h, 1});
    for (int k = 0; k <= 400; ++k) {
      const P2 q = c(k / 400.0);
      EXPECT_NEAR(std::hypot(q[0], q[1]) / r, 1.0, 4e-16 * 4) << "r=" << r << " k=" << k;  // a few eps
    }
    // Pieces: four rational quadratics, each an exact quarter arc.
    const auto p = pieces(c);
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p.breaks(), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  }
}

// Extrapolation past a sign change of the weight function is not a pole: the line
// x(t) = 3t / (1 + 2t) of weights 1, 3 (w(t) = 1 + 2t) is 3 at t = -1 (w = -1) and 9/5 at
// t = -3 (w = -5), as the same data as a RationalBezier gives; only w = 0 (t = -1/2) is
// a pole.
TEST(Nurbs, ExtrapolationPastAWeightSignChange) {
  using P1 = Point<double, 1>;
  const Nurbs<double, 1> c(1, {0, 0, 1, 1}, {P1(0.0), P1(1.0)}, {1, 3});
  EXPECT_NEAR(c(-1.0)[0], 3.0, 4e-16 * 3);
  EXPECT_NEAR(c(-3.0)[0], 1.8, 4e-16 * 2);
  EXPECT_NEAR(c(-0.4)[0], -6.0, 4e-16 * 6 * 8);
  // x'(t) = 3 / (1 + 2t)^2: 3 at t = -1.
  EXPECT_NEAR(c.derivative_at(-1.0, 1)[0], 3.0, 1e-14);
  EXPECT_THROW((void)c(-0.5), InvalidArgument);
  const RationalBezier<double, 1> r({P1(0.0), P1(1.0)}, {1, 3});
  EXPECT_NEAR(c(-1.0)[0], r(-1.0)[0], 1e-15);
}

}  // namespace
