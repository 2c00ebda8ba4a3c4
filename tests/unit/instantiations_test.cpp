// Other scalar types and dimensions through the whole API (float, long double; one and
// four dimensions). In the unity group of scalar_types_test.cpp (CMakeLists.txt): the
// library's templates at float and long double are instantiated there anyway, so these
// checks cost about 1 s of compile there against about 10 s in the other group.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
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

// The queries added after the scalar-types suite (scalar_types_test.cpp), each on a
// textbook case with a known answer, at float and long double. Tolerances are stated per
// check, in units of the type's epsilon e unless a method error is named.
template <class T>
void exercise_newer_queries() {
  const T e = std::numeric_limits<T>::epsilon();
  using P2 = Point<T, 2>;
  // solve: the cubic (t, t^3) (Bernstein y coefficients 0, 0, 0, 1) meets y = 1/8 at
  // t = 1/2 only, and the line x = 4t meets x = 1 at t = 1/4 (simple roots: 64 e).
  const Bezier<T, 2> cubic{{0, 0}, {T(1) / 3, 0}, {T(2) / 3, 0}, {1, 1}};
  const LevelSet<T> at_eighth = solve(cubic, Vector<T, 2>{0, 1}, T(0.125));
  ASSERT_EQ(at_eighth.t.size(), 1u);
  EXPECT_TRUE(at_eighth.intervals.empty());
  EXPECT_NEAR(at_eighth.t[0], T(0.5), 64 * e);
  const LevelSet<T> on_line = solve(Bezier<T, 2>{{0, 0}, {4, 2}}, Vector<T, 2>{1, 0}, T(1));
  ASSERT_EQ(on_line.t.size(), 1u);
  EXPECT_NEAR(on_line.t[0], T(0.25), 64 * e);

  // to_bspline: the two halves of a cubic as a path on [0, 2] are one polynomial, so the
  // B-spline traces the cubic at u / 2 (the cubic evaluated by de Casteljau; 64 e times
  // its size 4).
  const Bezier<T, 2> c{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  const auto halves = c.split(T(0.5));
  const Path<T, 2> joined({halves.left, halves.right});
  const auto spline = to_bspline(joined);
  ASSERT_TRUE((std::holds_alternative<BSpline<T, 2>>(spline)));
  const BSpline<T, 2>& b = std::get<BSpline<T, 2>>(spline);
  EXPECT_EQ(b.degree(), 3);
  for (const T u : {T(0), T(0.3), T(1), T(1.7), T(2)}) {
    const P2 want = c(u / 2), got = b(u);
    EXPECT_NEAR(got[0], want[0], 256 * e) << u;
    EXPECT_NEAR(got[1], want[1], 256 * e) << u;
  }

  // refine_knots: the quadratic (2t, 4t (1 - t)) as a B-spline, knots 1/4 and 1/2
  // inserted: five points, the same curve (closed form; 16 e). The quarter circle as a
  // NURBS keeps |C| = 1 (16 e).
  const BSpline<T, 2> arch(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 2}, {2, 0}});
  const std::vector<T> X{T(0.25), T(0.5)};
  const BSpline<T, 2> refined = arch.refine_knots(std::span<const T>(X));
  EXPECT_EQ(refined.points().size(), 5u);
  for (const T t : {T(0.1), T(0.3), T(0.7)}) {
    EXPECT_NEAR(refined(t)[0], 2 * t, 16 * e) << t;
    EXPECT_NEAR(refined(t)[1], 4 * t * (1 - t), 16 * e) << t;
  }
  const Nurbs<T, 2> quarter(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(T(2)) / 2, 1});
  const std::vector<T> mid{T(0.5)};
  const Nurbs<T, 2> quarter2 = quarter.refine_knots(std::span<const T>(mid));
  for (const T t : {T(0.2), T(0.5), T(0.9)}) {
    const P2 q = quarter2(t);
    EXPECT_NEAR(std::hypot(q[0], q[1]), T(1), 16 * e) << t;
  }

  // reduce_spline: the quarter circle (a NURBS) to degree 1 is its chord, 1 - sqrt(2) / 2
  // off at t = 1/2 (64 e: the measure's golden section finds the quadratic peak to
  // rounding); the parabola (2t, 4t (1 - t)) as a cubic B-spline (its Bezier form
  // elevated by hand) comes back to degree 2 exactly (error 64 e times its size 2).
  const auto chord = reduce_spline(quarter, 1);
  EXPECT_EQ(chord.curve.degree(), 1);
  EXPECT_NEAR(chord.max_error, 1 - std::sqrt(T(2)) / 2, 64 * e);
  const BSpline<T, 2> elevated(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {T(2) / 3, T(4) / 3}, {T(4) / 3, T(4) / 3}, {2, 0}});
  const auto back = reduce_spline(elevated, 1);
  EXPECT_EQ(back.curve.degree(), 2);
  EXPECT_LE(back.max_error, 128 * e);

  // to_quadratic: a quadratic (2t, 4t (1 - t)) elevated to a cubic is the parabola
  // y = x (2 - x). Every segment's points at five parameters are on it within the
  // tolerance times sqrt(5) (the vertical distance for a Euclidean one where |slope| <= 2)
  // plus 64 e, and the chain runs from (0, 0) to (2, 0). The cubic is the quadratic (at
  // float up to the rounding of the elevation's 2/3 and 4/3): one segment, equal to it
  // (64 e).
  const Bezier<T, 2> quad{{0, 0}, {1, 2}, {2, 0}};
  const T qtol = T(1e-3);
  const auto chain = to_quadratic(quad.elevate(1), qtol);
  ASSERT_EQ(chain.segments.size(), 1u);
  EXPECT_LE(chain.max_error, qtol);
  for (const auto& seg : chain.segments) {
    for (const T t : {T(0), T(0.25), T(0.5), T(0.75), T(1)}) {
      const P2 q = seg(t);
      EXPECT_NEAR(q[1], q[0] * (2 - q[0]), std::sqrt(T(5)) * qtol + 64 * e) << t;
    }
  }
  EXPECT_EQ(chain.segments.front().points().front(), (P2{0, 0}));
  EXPECT_NEAR(chain.segments.back().points().back()[0], T(2), 64 * e);
  EXPECT_NEAR(chain.segments.back().points().back()[1], T(0), 64 * e);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(chain.segments[0].points()[i][0], quad.points()[i][0], 64 * e) << i;
    EXPECT_NEAR(chain.segments[0].points()[i][1], quad.points()[i][1], 64 * e) << i;
  }

  // offset: the unit quarter circle (counter-clockwise) offset by d = 1/4 to its left
  // (towards the centre) is the arc of radius 3/4: every cubic's points at five parameters
  // within the tolerance (1e-3 at float, 1e-9 at long double) plus 64 e of it.
  const RationalBezier<T, 2> arc({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(T(2)) / 2, 1});
  OffsetOptions<T> o;
  o.distance = T(0.25);
  o.tolerance = std::is_same_v<T, float> ? T(1e-3) : T(1e-9);
  const OffsetCurve<T> off = offset(arc, o);
  ASSERT_FALSE(off.segments.empty());
  EXPECT_LE(off.max_error, o.tolerance);
  for (const auto& seg : off.segments) {
    for (const T t : {T(0), T(0.25), T(0.5), T(0.75), T(1)}) {
      const P2 q = seg(t);
      EXPECT_NEAR(std::hypot(q[0], q[1]), T(0.75), o.tolerance + 64 * e) << t;
    }
  }
  EXPECT_NEAR(off.segments.front()(T(0))[0], T(0.75), 64 * e);
  EXPECT_NEAR(off.segments.back()(T(1))[1], T(0.75), 64 * e);

  // smoothing_spline: points on the line (t, 2t + 1) are the line for any lambda (zero
  // residual, zero second derivative: the minimum); 256 e times the size 7.
  std::vector<P2> on;
  std::vector<T> ts;
  for (int k = 0; k <= 3; ++k) {
    ts.push_back(T(k));
    on.push_back(P2{T(k), 2 * T(k) + 1});
  }
  const auto smooth = smoothing_spline(on, ts, std::optional<T>(T(1)));
  for (const T t : {T(0), T(0.5), T(1.25), T(3)}) {
    EXPECT_NEAR(smooth.curve(t)[0], t, 7 * 256 * e) << t;
    EXPECT_NEAR(smooth.curve(t)[1], 2 * t + 1, 7 * 256 * e) << t;
  }

  // rotation_minimizing_normals: on the helix (cos s, sin s, s), 64 steps of one turn, the
  // exact rotation-minimizing normal turns against the principal normal by -s / sqrt(2)
  // (basis_rmf_test.cpp); the method's error there is 1.43e-7 at double: bound 2e-7 plus
  // 256 e of rounding over the steps.
  using V3 = Vector<T, 3>;
  const T pi = std::numbers::pi_v<T>, r2 = std::sqrt(T(2));
  auto exact = [&](T s) {
    const T phi = -s / r2;
    const V3 N{-std::cos(s), -std::sin(s), 0}, B{std::sin(s) / r2, -std::cos(s) / r2, 1 / r2};
    return std::cos(phi) * N + std::sin(phi) * B;
  };
  const int n = 64;
  std::vector<V3> x, tangent;
  for (int i = 0; i <= n; ++i) {
    const T s = 2 * pi * T(i) / T(n);
    x.push_back(V3{std::cos(s), std::sin(s), s});
    tangent.push_back(V3{-std::sin(s), std::cos(s), 1} / r2);
  }
  const auto normals = rotation_minimizing_normals(x, tangent, exact(T(0)));
  ASSERT_EQ(normals.size(), x.size());
  for (int i = 0; i <= n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_NEAR(norm(normals[k] - exact(2 * pi * T(i) / T(n))), T(0), T(2e-7) + 256 * e) << i;
  }
}

TEST(Instantiations, NewerQueriesAtFloatAndLongDouble) {
  exercise_newer_queries<float>();
  exercise_newer_queries<long double>();
}

TEST(Instantiations, FloatAndLongDouble) {
  exercise_scalar_type<float>();
  exercise_scalar_type<long double>();
}

// Errors that reach the command line (re-rooted under the request's curve) say what
// failed, not which internal function: the adaptive quadrature (area's rational pieces,
// reduce's mean) and the spline's tridiagonal solve.
TEST(Instantiations, NumericalErrorsNameNoInternalFunction) {
  std::string what;
  try {
    (void)integrate_adaptive<double>([](double t) { return 1 / std::sqrt(t + 1e-300); }, 0.0, 1.0, 1e-15, 0.0, 50);
  } catch (const NumericalError& e) {
    what = e.what();
  }
  EXPECT_EQ(what.rfind("the integral cannot be computed to its accuracy target", 0), 0u) << what;
  std::vector<double> a{0, 1}, b{0, 1}, c{1, 0};
  std::vector<double> r{1, 1};
  what.clear();
  try {
    detail::solve_tridiagonal(a, b, c, r);
  } catch (const NumericalError& e) {
    what = e.what();
  }
  EXPECT_EQ(what.rfind("the spline's linear system has a zero or non-finite pivot", 0), 0u) << what;
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
