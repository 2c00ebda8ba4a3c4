// Tensor-product surfaces (surfaces/surface.hpp): validation naming the grid, closed forms
// (linear precision, the hyperbolic paraboloid's curvatures, a rational quarter cylinder),
// and the operations that must leave the surface unchanged (knot insertion, elevation,
// splitting, the Bézier patches, isocurves). The command line's surfaces are checked
// against independent evaluation in tests/cli/test_surfaces.py.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/surfaces/surface.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P3 = Point<double, 3>;
using Grid3 = std::vector<std::vector<P3>>;

// A bicubic-by-quadratic NURBS surface with an interior knot in each direction and
// uneven weights: the subject of the invariance checks.
NurbsSurface<double, 3> sample_nurbs() {
  Grid3 P;
  std::vector<std::vector<double>> W;
  test::SplitMix64 rng(19);
  for (int i = 0; i < 5; ++i) {
    auto& row = P.emplace_back();
    auto& w = W.emplace_back();
    for (int j = 0; j < 4; ++j) {
      row.emplace_back(i + rng.uniform(-0.3, 0.3), j + rng.uniform(-0.3, 0.3), rng.uniform(-1, 1));
      w.push_back(rng.uniform(0.5, 2));
    }
  }
  return NurbsSurface<double, 3>(3, 2, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, {0, 0, 0, 0.6, 1, 1, 1}, P, W);
}

template <class S1, class S2>
double max_gap(const S1& a, const S2& b) {
  double d = 0;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) d = std::max(d, distance(a(i / 10.0, j / 10.0), b(i / 10.0, j / 10.0)));
  return d;
}

TEST(Surfaces, ErrorsNameTheGrid) {
  const Grid3 ragged{{P3(0, 0, 0), P3(1, 0, 0), P3(2, 0, 0), P3(3, 0, 0)}, {P3(0, 1, 0), P3(1, 1, 0), P3(2, 1, 0), P3(3, 1, 0)},
                     {P3(0, 2, 0), P3(1, 2, 0), P3(2, 2, 0)}};
  EXPECT_INVALID_ARGUMENT((BezierSurface<double, 3>{ragged}), "points[2]", "row 2 has 3 points, row 0 has 4");
  const Grid3 square{{P3(0, 0, 0), P3(0, 1, 0)}, {P3(1, 0, 0), P3(1, 1, 0)}};
  EXPECT_INVALID_ARGUMENT((BSplineSurface<double, 3>(1, 1, {0, 0, 1, 1}, {0, 0.7, 0.5, 1}, square)), "knots[1][2]",
                          "knots must be non-decreasing (0.5 after 0.7)");
  EXPECT_INVALID_ARGUMENT((BSplineSurface<double, 3>(1, 1, {0, 0, 1, 1, 1}, {0, 0, 1, 1}, square)), "knots[0]",
                          "rows + degree + 1 = 4 knots, got 5");
  EXPECT_INVALID_ARGUMENT((RationalBezierSurface<double, 3>(square, {{1, 1}, {1, 0}})), "weights[1][1]", "> 0");
  EXPECT_INVALID_ARGUMENT((RationalBezierSurface<double, 3>(square, {{1, 1}})), "weights", "has 1 rows, points has 2");
}

// Linear precision: control points at the Greville abscissae reproduce (u, v) exactly up
// to rounding, whatever the knots; and their partial derivatives are (1, 0), (0, 1).
TEST(Surfaces, LinearPrecision) {
  const std::vector<double> U{0, 0, 0, 0.3, 0.5, 1, 1, 1}, V{0, 0, 0.25, 1, 1};
  std::vector<std::vector<Point<double, 2>>> P(5);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 3; ++j) P[i].emplace_back((U[i + 1] + U[i + 2]) / 2, V[j + 1]);
  const BSplineSurface<double, 2> s(2, 1, U, V, P);
  for (double u : {0.0, 0.1, 0.3, 0.77, 1.0})
    for (double v : {0.0, 0.25, 0.6, 1.0}) {
      // A few roundings of the basis functions (each within a few eps of the sum).
      EXPECT_NEAR(s(u, v)[0], u, 8 * test::eps);
      EXPECT_NEAR(s(u, v)[1], v, 8 * test::eps);
      EXPECT_NEAR(s.derivative(u, v, 1, 0)[0], 1, 1e-13);
      EXPECT_NEAR(s.derivative(u, v, 0, 1)[1], 1, 1e-13);
      EXPECT_NEAR(s.derivative(u, v, 1, 1)[0], 0, 1e-13);
    }
}

// z = xy as the bilinear patch (u, v, uv): n ~ (-v, -u, 1), EG - F^2 = 1 + u^2 + v^2,
// K = -1 / (1 + u^2 + v^2)^2, H = -uv / (1 + u^2 + v^2)^(3/2).
TEST(Surfaces, HyperbolicParaboloidCurvature) {
  const BezierSurface<double, 3> s(Grid3{{P3(0, 0, 0), P3(0, 1, 0)}, {P3(1, 0, 0), P3(1, 1, 1)}});
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 0.9}) {
      const auto c = s.curvature(u, v);
      ASSERT_TRUE(c);
      const double r = 1 + u * u + v * v;
      // Closed forms against a few roundings in the fundamental forms.
      EXPECT_NEAR(c->gaussian, -1 / (r * r), 1e-14);
      EXPECT_NEAR(c->mean, -u * v / std::pow(r, 1.5), 1e-14);
      EXPECT_NEAR(c->k1 + c->k2, 2 * c->mean, 1e-14);
      EXPECT_NEAR(c->k1 * c->k2, c->gaussian, 1e-14);
      EXPECT_NEAR(c->normal[2], 1 / std::sqrt(r), 1e-15);
    }
}

// The quarter cylinder of radius 2 as a rational Bézier (the quarter circle in u, a line
// in v): every point at distance 2 from the z axis, the normal radial (outward: S_u x S_v
// with u turning counter-clockwise about +z and v along +z points away from the axis), so
// H = -1/4 by the contract's sign (+1/r when the normal points to the centre), K = 0,
// principal curvatures 0 and -1/2.
TEST(Surfaces, RationalCylinder) {
  const double h = std::sqrt(0.5);
  const RationalBezierSurface<double, 3> s(Grid3{{P3(2, 0, 0), P3(2, 0, 3)}, {P3(2, 2, 0), P3(2, 2, 3)}, {P3(0, 2, 0), P3(0, 2, 3)}},
                                           {{1, 1}, {h, h}, {1, 1}});
  for (double u : {0.0, 0.2, 0.5, 1.0})
    for (double v : {0.0, 0.5}) {
      const P3 x = s(u, v);
      EXPECT_NEAR(std::hypot(x[0], x[1]), 2, 4 * test::eps);  // rounding of the rational form
      const auto c = s.curvature(u, v);
      ASSERT_TRUE(c);
      EXPECT_NEAR(c->normal[0], x[0] / 2, 1e-14);
      EXPECT_NEAR(c->normal[1], x[1] / 2, 1e-14);
      EXPECT_NEAR(c->mean, -0.25, 1e-13);  // second derivatives of the rational form: a few eps relative
      EXPECT_NEAR(c->gaussian, 0, 1e-13);
      EXPECT_NEAR(c->k1, 0, 1e-13);
      EXPECT_NEAR(c->k2, -0.5, 1e-13);
    }
}

// A degenerate corner (both rows of a bilinear patch meet at one point along v = 0):
// S_v = 0 there and the normal is undefined, not NaN.
TEST(Surfaces, NormalUndefinedAtDegenerateEdge) {
  const BezierSurface<double, 3> s(Grid3{{P3(0, 0, 0), P3(0, 0, 0)}, {P3(1, 0, 0), P3(1, 1, 0)}});
  EXPECT_FALSE(s.normal(0.0, 0.5));
  EXPECT_TRUE(s.normal(0.5, 0.5));
}

// Knot insertion, elevation (both directions), splitting and the Bézier patches leave
// the surface unchanged up to rounding (convex combinations of the data; a few eps of
// the size, the coordinates are below 5).
TEST(Surfaces, OperationsKeepTheSurface) {
  const auto s = sample_nurbs();
  const double tol = 1e-13;
  EXPECT_LT(max_gap(s, s.insert_knot(Direction::u, 0.4, 2)), tol);
  EXPECT_LT(max_gap(s, s.insert_knot(Direction::v, 0.33)), tol);
  const auto e = s.elevate(Direction::u, 2).elevate(Direction::v, 1);
  EXPECT_EQ(e.degree_u(), 5);
  EXPECT_EQ(e.degree_v(), 3);
  EXPECT_LT(max_gap(s, e), tol);
  const auto [a, b] = s.split(Direction::v, 0.45);
  for (double u : {0.0, 0.3, 0.9})
    for (double v : {0.1, 0.45, 0.8}) EXPECT_LT(distance(s(u, v), v <= 0.45 ? a(u, v) : b(u, v)), tol);
  const auto g = s.patches();
  EXPECT_EQ(g.ubreaks, (std::vector<double>{0, 0.4, 1}));
  EXPECT_EQ(g.vbreaks, (std::vector<double>{0, 0.6, 1}));
  const auto& patch = g.patches[1][0];  // [0.4, 1] x [0, 0.6]
  EXPECT_LT(distance(patch(0.5, 0.5), s(0.7, 0.3)), tol);
  const auto iso = s.isocurve(Direction::u, 0.7);
  EXPECT_LT(distance(iso(0.3), s(0.7, 0.3)), tol);
  const auto iso_v = s.isocurve(Direction::v, 0.3);
  EXPECT_LT(distance(iso_v(0.7), s(0.7, 0.3)), tol);
  // Partition of unity: all points equal gives that point everywhere, derivatives 0.
  const BSplineSurface<double, 3> flat(3, 2, s.knots_u(), s.knots_v(), Grid3(5, std::vector<P3>(4, P3(1, 2, 3))));
  EXPECT_LT(distance(flat(0.37, 0.71), P3(1, 2, 3)), 4 * test::eps);
  EXPECT_LT(norm(flat.derivative(0.37, 0.71, 1, 1)), 1e-13);
}

// Affine maps (transform): the quarter cylinder of radius 2 (RationalCylinder) scaled by 3
// in x and 1/2 in y and moved by (1, -2, 5) is a quarter of the elliptic cylinder
// ((x - 1) / 3)^2 + ((y + 2) / (1/2))^2 = 4, z in [5, 8] (an affine image of a circle is
// an ellipse, exactly, with the same weights); a rotation by 90 degrees about z turns
// its start (2, 0, z) to (0, 2, z). A general affine map of the sample NURBS surface
// commutes with evaluation (affine invariance) and keeps knots and weights; a map to
// infinity is refused.
TEST(Surfaces, TransformIsExact) {
  const double h = std::sqrt(0.5);
  const RationalBezierSurface<double, 3> s(Grid3{{P3(2, 0, 0), P3(2, 0, 3)}, {P3(2, 2, 0), P3(2, 2, 3)}, {P3(0, 2, 0), P3(0, 2, 3)}},
                                           {{1, 1}, {h, h}, {1, 1}});
  Affine<double, 3> m;
  m.linear = {{{3, 0, 0}, {0, 0.5, 0}, {0, 0, 1}}};
  m.translation = Vector<double, 3>(1, -2, 5);
  const auto e = s.transform(m);
  for (double u : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0})
    for (double v : {0.0, 0.25, 1.0}) {
      const P3 x = e(u, v);
      EXPECT_NEAR(std::hypot((x[0] - 1) / 3, (x[1] + 2) / 0.5), 2, 8 * test::eps);
      EXPECT_NEAR(x[2], 5 + 3 * v, 8 * test::eps);
    }
  EXPECT_EQ(e.weight(1, 0), h);
  Affine<double, 3> r;
  r.linear = {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
  const P3 start = s.transform(r)(0.0, 0.5);
  EXPECT_NEAR(start[0], 0, 1e-15);
  EXPECT_NEAR(start[1], 2, 1e-15);
  EXPECT_NEAR(start[2], 1.5, 1e-15);
  const auto n = sample_nurbs();
  Affine<double, 3> g;
  g.linear = {{{1.5, -0.3, 0.2}, {0.4, 0.9, -1.1}, {0.0, 0.7, 2.0}}};
  g.translation = Vector<double, 3>(-3, 0.5, 7);
  const auto t = n.transform(g);
  EXPECT_EQ(t.knots_u(), n.knots_u());
  EXPECT_EQ(t.knots_v(), n.knots_v());
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) EXPECT_LT(distance(t(i / 6.0, j / 6.0), g(n(i / 6.0, j / 6.0))), 1e-13);
  EXPECT_THROW((void)n.transform(Affine<double, 3>::scale(1e308)), InvalidArgument);
}

// float and long double: the rational quarter cylinder evaluated, split, elevated and its
// curvature, each within a few eps of the scalar (the curve version of this is
// scalar_types_test.cpp).
template <class T>
void cylinder_at_scalar() {
  using PT = Point<T, 3>;
  const T h = std::sqrt(T(0.5)), eps = std::numeric_limits<T>::epsilon();
  const RationalBezierSurface<T, 3> s(std::vector<std::vector<PT>>{{PT(2, 0, 0), PT(2, 0, 3)}, {PT(2, 2, 0), PT(2, 2, 3)}, {PT(0, 2, 0), PT(0, 2, 3)}},
                                      {{1, 1}, {h, h}, {1, 1}});
  const auto [a, b] = s.split(Direction::u, T(0.3));
  const auto e = s.elevate(Direction::u, 2);
  for (const T u : {T(0), T(0.2), T(0.5), T(1)}) {
    const PT x = s(u, T(0.5));
    EXPECT_NEAR(std::hypot(x[0], x[1]), T(2), 8 * eps);
    EXPECT_NEAR(x[2], T(1.5), 8 * eps);
    EXPECT_LT(distance(e(u, T(0.5)), x), 32 * eps);
    const PT y = u <= T(0.3) ? a(u / T(0.3), T(0.5)) : b((u - T(0.3)) / (1 - T(0.3)), T(0.5));
    EXPECT_LT(distance(y, x), 32 * eps);
    const auto c = s.curvature(u, T(0.5));
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->mean, T(-0.25), 1024 * eps);
    EXPECT_NEAR(c->k2, T(-0.5), 1024 * eps);
  }
}

TEST(Surfaces, FloatAndLongDouble) {
  cylinder_at_scalar<float>();
  cylinder_at_scalar<long double>();
}

// float works (the algorithms are templated on the scalar): a bilinear patch at float
// precision.
TEST(Surfaces, FloatScalar) {
  using PF = Point<float, 2>;
  const BezierSurface<float, 2> s(std::vector<std::vector<PF>>{{PF(0, 0), PF(0, 1)}, {PF(1, 0), PF(1, 1)}});
  EXPECT_NEAR(s(0.25f, 0.75f)[0], 0.25f, 4 * std::numeric_limits<float>::epsilon());
  EXPECT_NEAR(s(0.25f, 0.75f)[1], 0.75f, 4 * std::numeric_limits<float>::epsilon());
}

}  // namespace
