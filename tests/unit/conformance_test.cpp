// The shared curve contract, checked for every curve type (a typed test suite): domain
// end points, finite values, derivative_at against finite differences, reverse,
// transform, and rejection of non-finite parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;

/// A non-trivial sample of each curve type, with its expected start and end points.
template <class C>
struct Sample;

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

template <class C>
class Conformance : public ::testing::Test {};

using CurveTypes = ::testing::Types<Bezier<double, 2>, RationalBezier<double, 2>, Path<double, 2>, Bezier<double, 3>,
                                    Polyline<double, 2>, Path<double, 3>, Pieces<double, 2>, BSpline<double, 2>,
                                    Nurbs<double, 2>>;
TYPED_TEST_SUITE(Conformance, CurveTypes);

/// n + 1 parameters spread over the domain, including both ends.
template <class C>
std::vector<double> params(const C& c, int n = 64) {
  std::vector<double> ts;
  const auto dom = c.domain();
  for (int i = 0; i <= n; ++i) ts.push_back(dom.at(static_cast<double>(i) / n));
  ts.back() = dom.hi;
  return ts;
}

TYPED_TEST(Conformance, ModelsTheConcepts) {
  static_assert(Curve<TypeParam>);
  static_assert(DifferentiableCurve<TypeParam>);
  static_assert(PiecewiseBezierCurve<TypeParam>);
}

// The exact Bézier form traces the same curve with the same parametrisation, so queries
// on the pieces never disagree with evaluation: points and derivatives (orders 1..3) at
// parameters across the domain and beyond it (extrapolation of the first and last
// piece). Both sides evaluate the same polynomials after one affine parameter map:
// a few ulps of the coordinates (<= 6) times the derivative's size (<= ~50 for k <= 3
// here, with the polyline's factor 6 per order): 1e-11.
TYPED_TEST(Conformance, PiecesTraceTheCurve) {
  const auto c = Sample<TypeParam>::make();
  const auto p = pieces(c);
  const auto dom = c.domain();
  EXPECT_EQ(p.domain(), dom);
  std::vector<double> ts = params(c, 97);
  ts.push_back(dom.lo - 0.1 * dom.length());
  ts.push_back(dom.hi + 0.1 * dom.length());
  if constexpr (requires { c.breaks(); }) ts.insert(ts.end(), c.breaks().begin(), c.breaks().end());
  for (double t : ts) {
    EXPECT_EQ(test::max_coord_diff(p(t), c(t)) <= 1e-13 * (1 + norm(c(t).to_vector())), true) << "t=" << t;
    for (int k = 1; k <= 3; ++k) {
      const auto a = p.derivative_at(t, k), b = c.derivative_at(t, k);
      EXPECT_LE(test::max_coord_diff(a, b), 1e-11 * (1 + norm(b))) << "t=" << t << " k=" << k;
    }
  }
  // Every piece's parameter lifts back to the curve's: the piece's ends are the breaks.
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.global_parameter(i, 0.0), p.breaks()[i]);
    EXPECT_EQ(p.global_parameter(i, 1.0), p.breaks()[i + 1]);
  }
}

// The domain's ends map to the first and last control points. Bézier forms interpolate
// exactly; a path maps its ends through Interval::fraction, exact at the break values.
TYPED_TEST(Conformance, DomainEndPoints) {
  const auto c = Sample<TypeParam>::make();
  const auto dom = c.domain();
  EXPECT_LT(dom.lo, dom.hi);
  EXPECT_EQ(c(dom.lo), Sample<TypeParam>::start());
  EXPECT_EQ(c(dom.hi), Sample<TypeParam>::end());
}

// Finite values everywhere in the domain, and inside the control box (convex hull).
TYPED_TEST(Conformance, FiniteAndInsideControlBounds) {
  const auto c = Sample<TypeParam>::make();
  const auto box = c.control_bounds();
  for (double t : params(c, 200)) {
    const auto p = c(t);
    EXPECT_TRUE(test::all_finite(p));
    EXPECT_TRUE(box.contains(p, 1e-14)) << "t=" << t;
    EXPECT_TRUE(test::all_finite(c.derivative_at(t, 1)));
    EXPECT_TRUE(test::all_finite(c.derivative_at(t, 2)));
  }
}

// derivative_at against central differences (c(t+h) - c(t-h)) / 2h: truncation error
// h^2 |c'''| / 6 and rounding eps |c| / h; with h = 1e-5 and |c'''|, |c| <= ~1e3 for these
// samples both are <= 1e-7, so 1e-6 is a safe bound. Second derivatives from differences
// of first derivatives, same step: error h^2 |c''''| / 6 + eps |c'| / h.
TYPED_TEST(Conformance, DerivativesMatchFiniteDifferences) {
  const auto c = Sample<TypeParam>::make();
  const auto dom = c.domain();
  const double h = 1e-5 * dom.length();
  const std::vector<double> joints = pieces(c).breaks();
  for (double t : params(c, 40)) {
    // Stay inside one segment of a path (breaks are at multiples of 1/40 of the domain
    // only for the Path sample's 0.5 = -1 + 1.5 * 40/40; avoid them and the domain ends).
    if (t - h <= dom.lo || t + h >= dom.hi) continue;
    // Nor straddle a joint of the pieces (a polyline's vertex, a path's break), where
    // derivatives jump.
    bool near_break = false;
    for (double b : joints) near_break = near_break || std::abs(t - b) <= 2 * h;
    if (near_break) continue;
    const auto fd = test::central_difference(c, t, h);
    EXPECT_LE(test::max_coord_diff(fd, c.derivative_at(t, 1)), 1e-6 * (1 + norm(fd))) << "t=" << t;
    const auto fd2 = (c.derivative_at(t + h, 1) - c.derivative_at(t - h, 1)) / (2 * h);
    EXPECT_LE(test::max_coord_diff(fd2, c.derivative_at(t, 2)), 1e-5 * (1 + norm(fd2))) << "t=" << t;
  }
}

// Reversing swaps the ends and traverses backwards: r(lo + hi - t) = c(t), and derivatives
// change sign. Reverse twice is the identity exactly (the same numbers, reordered twice).
TYPED_TEST(Conformance, Reverse) {
  const auto c = Sample<TypeParam>::make();
  const auto r = c.reverse();
  const auto dom = c.domain();
  EXPECT_EQ(r.domain(), dom);
  EXPECT_EQ(r.reverse(), c);
  for (double t : params(c, 50)) {
    const double u = dom.lo + dom.hi - t;
    // Both sides are evaluations at parameters related by one rounding: a few ulps of the
    // coordinates (<= 5) times |c'| (<= ~20).
    EXPECT_LE(test::max_coord_diff(r(u), c(t)), 1e-13) << "t=" << t;
  }
  // Away from breaks, derivatives flip sign.
  const double t = dom.at(0.3);
  EXPECT_LE(test::max_coord_diff(r.derivative_at(dom.lo + dom.hi - t), -c.derivative_at(t)), 1e-12);
}

// Affine invariance: the transformed curve is the transformed curve's image, to rounding
// of the map (entries <= 2, coordinates <= 5: 1e-13 absolute).
TYPED_TEST(Conformance, Transform) {
  const auto c = Sample<TypeParam>::make();
  constexpr int D = TypeParam::dimension;
  Affine<double, D> m = Affine<double, D>::identity();
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) m.linear[i][j] = (i == j ? 1.5 : 0.0) + 0.25 * (i - j);
  for (int i = 0; i < D; ++i) m.translation[i] = 0.5 * (i + 1);
  const auto tc = c.transform(m);
  for (double t : params(c, 50)) EXPECT_LE(test::max_coord_diff(tc(t), m(c(t))), 1e-13) << "t=" << t;
  // The identity map changes nothing.
  EXPECT_EQ(c.transform(Affine<double, D>::identity()), c);
  // Derivatives are mapped by the linear part only.
  const double t = c.domain().at(0.4);
  EXPECT_LE(test::max_coord_diff(tc.derivative_at(t), m(c.derivative_at(t))), 1e-12);
}

// Non-finite parameters throw InvalidArgument naming "t"; extrapolation outside the domain
// is finite.
TYPED_TEST(Conformance, NonFiniteParameterThrows) {
  const auto c = Sample<TypeParam>::make();
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    EXPECT_INVALID_ARGUMENT(c(bad), "t", "finite");
    EXPECT_INVALID_ARGUMENT(c.derivative_at(bad, 1), "t", "finite");
  }
  const auto dom = c.domain();
  EXPECT_TRUE(test::all_finite(c(dom.lo - 0.25)));
  EXPECT_TRUE(test::all_finite(c(dom.hi + 0.25)));
}

// Tight bounds of each type contain every sample and lie inside the control box.
TYPED_TEST(Conformance, TightBounds) {
  const auto c = Sample<TypeParam>::make();
  const auto b = bounds(c), cb = c.control_bounds();
  for (double t : params(c, 500)) EXPECT_TRUE(b.contains(c(t), 1e-14)) << "t=" << t;
  for (int d = 0; d < TypeParam::dimension; ++d) {
    EXPECT_GE(b.lo[d], cb.lo[d]);
    EXPECT_LE(b.hi[d], cb.hi[d]);
  }
}

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
