// The basis tables of the `basis` command (basis/basis_kinds.hpp) and rotation-minimizing
// frames by double reflection (algo/rmf.hpp), on closed forms: the cubic forms' matrices
// as the course notes write them ([1 t t^2 t^3] M G), Bernstein, B-spline and Lagrange
// values written out, and the helix's exact rotation-minimizing frame.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/algo/rmf.hpp"
#include "casteljau/basis/basis_kinds.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using V3r = Vector<double, 3>;

/// M of [1 t t^2 t^3] M G, rows the powers, as printed in the course notes.
Eigen::Matrix4d rows(std::initializer_list<double> v, double scale = 1) {
  Eigen::Matrix4d m;
  auto it = v.begin();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m(i, j) = *it++ * scale;
  return m;
}

BasisSpec kind(BasisKind k) {
  BasisSpec b;
  b.kind = k;
  return b;
}

TEST(BasisKinds, CubicMatricesAreTheTextbookOnes) {
  // Hermite [p0, p1, m0, m1]: h00 = 1 - 3t^2 + 2t^3, h01 = 3t^2 - 2t^3, h10 = t - 2t^2 + t^3,
  // h11 = t^3 - t^2. Catmull-Rom: (1/2) [[0 2 0 0] [-1 0 1 0] [2 -5 4 -1] [-1 3 -3 1]].
  // Uniform B-spline: (1/6) [[1 4 1 0] [-3 0 3 0] [3 -6 3 0] [-1 3 -3 1]]. Bezier: the
  // binomial rows. Small integers and halves / sixths: equal to the last bit (1/6 once
  // rounded), so the comparison is at 1 ulp.
  const std::pair<BasisSpec, Eigen::Matrix4d> cases[] = {
      {kind(BasisKind::hermite), rows({1, 0, 0, 0, 0, 0, 1, 0, -3, 3, -2, -1, 2, -2, 1, 1})},
      {kind(BasisKind::catmull_rom), rows({0, 2, 0, 0, -1, 0, 1, 0, 2, -5, 4, -1, -1, 3, -3, 1}, 0.5)},
      {kind(BasisKind::uniform_bspline), rows({1, 4, 1, 0, -3, 0, 3, 0, 3, -6, 3, 0, -1, 3, -3, 1}, 1.0 / 6)},
      {kind(BasisKind::bernstein), rows({1, 0, 0, 0, -3, 3, 0, 0, 3, -6, 3, 0, -1, 3, -3, 1})},
  };
  const std::vector<double> t{0, 0.25, 1};
  for (const auto& [spec, want] : cases) {
    const BasisTable r = basis_table(spec, t, 3);
    ASSERT_TRUE(r.matrix && r.constraint);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR((*r.matrix)(i, j), want(i, j), 1e-16 * (1 + std::abs(want(i, j))));
    // C = M^-1 (exact rationals, rounded once each): M C = I to a few ulps.
    EXPECT_LE(((*r.matrix) * (*r.constraint) - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
    // The values and derivatives are [1 t t^2 t^3]^(j) M: at t = 1/4 (dyadic, exact powers).
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double u = t[i];
      const Eigen::RowVector4d p[4] = {{1, u, u * u, u * u * u}, {0, 1, 2 * u, 3 * u * u}, {0, 0, 2, 6 * u}, {0, 0, 0, 6}};
      for (int j = 0; j <= 3; ++j) {
        const Eigen::RowVector4d v = p[j] * want;
        for (int f = 0; f < 4; ++f) EXPECT_NEAR(r.value[static_cast<std::size_t>(j)][i][static_cast<std::size_t>(f)], v(f), 1e-15);
      }
    }
  }
  // Cardinal at tension 0 is Catmull-Rom; at 1 its tangents vanish: M is singular, no C.
  BasisSpec c = kind(BasisKind::cardinal);
  const std::vector<double> t0{0.5};
  const BasisTable cr = basis_table(kind(BasisKind::catmull_rom), t0, 0), c0 = basis_table(c, t0, 0);
  EXPECT_LE((*cr.matrix - *c0.matrix).cwiseAbs().maxCoeff(), 1e-16);
  EXPECT_TRUE(*cr.constraint == *c0.constraint);  // the closed form: exact at s = 0
  // Just below 1, M is invertible: C exists, with k = 2 / (1 - s) = 2^53 (exact).
  c.tension = 1 - 0x1p-52;
  const BasisTable near = basis_table(c, t0, 0);
  ASSERT_TRUE(near.constraint.has_value());
  EXPECT_EQ((*near.constraint)(3, 1), 0x1p53);
  EXPECT_EQ((*near.constraint)(3, 3), 3 * 0x1p53);
  c.tension = 1;
  const BasisTable c1 = basis_table(c, t0, 0);
  EXPECT_FALSE(c1.constraint.has_value());
  // Tension 1: P(t) = h00 P1 + h01 P2 (no tangents).
  EXPECT_EQ(c1.value[0][0], (std::vector<double>{0, 0.5, 0.5, 0}));
}

TEST(BasisKinds, BsplineLagrangeBernsteinValues) {
  // Hats of degree 1 on [0, 0, 1, 2, 2] at t = 1/2 and 3/2 (exact halves).
  BasisSpec b = kind(BasisKind::bspline);
  b.degree = 1;
  b.knots = {0, 0, 1, 2, 2};
  const std::vector<double> t{0.5, 1.5};
  const BasisTable hb = basis_table(b, t, 1);
  EXPECT_EQ(hb.value[0][0], (std::vector<double>{0.5, 0.5, 0}));
  EXPECT_EQ(hb.value[0][1], (std::vector<double>{0, 0.5, 0.5}));
  EXPECT_EQ(hb.value[1][0], (std::vector<double>{-1, 1, 0}));
  EXPECT_FALSE(hb.matrix.has_value());
  // Lagrange on 0, 1, 2 at 1/2: l0 = (t-1)(t-2)/2 = 3/8, l1 = t(2-t) = 3/4, l2 = t(t-1)/2 =
  // -1/8; derivatives l0' = t - 3/2, l1' = 2 - 2t, l2' = t - 1/2, l'' = 1, -2, 1. The
  // barycentric Taylor recurrence divides differences by t - x_j once per order: values and
  // first derivatives to a few ulps, second derivatives measured 5.5 eps off; 1e-14 (45
  // eps) allows both.
  BasisSpec l = kind(BasisKind::lagrange);
  l.params = {0, 1, 2};
  const std::vector<double> h{0.5};
  const BasisTable lb = basis_table(l, h, 2);
  const double want[3][3] = {{0.375, 0.75, -0.125}, {-1, 1, 0}, {1, -2, 1}};
  for (std::size_t j = 0; j < 3; ++j)
    for (std::size_t f = 0; f < 3; ++f) EXPECT_NEAR(lb.value[j][0][f], want[j][f], 1e-14) << j << " " << f;
  // Bernstein of degree 2 at 1/4: (9/16, 6/16, 1/16), exact.
  BasisSpec z = kind(BasisKind::bernstein);
  z.degree = 2;
  const std::vector<double> q{0.25};
  EXPECT_EQ(basis_table(z, q, 0).value[0][0], (std::vector<double>{0.5625, 0.375, 0.0625}));
}

TEST(BasisKinds, ErrorsNameTheField) {
  const std::vector<double> t{0.5};
  BasisSpec c = kind(BasisKind::cardinal);
  c.tension = 1.5;
  EXPECT_INVALID_ARGUMENT(basis_table(c, t, 0), "tension", "[0, 1]");
  BasisSpec l = kind(BasisKind::lagrange);
  l.params = {0, 1, 1};
  EXPECT_INVALID_ARGUMENT(basis_table(l, t, 0), "params[2]", "");
  BasisSpec b = kind(BasisKind::bspline);
  b.degree = 2;
  b.knots = {0, 1, 0.5, 2, 3, 4};
  EXPECT_INVALID_ARGUMENT(basis_table(b, t, 0), "knots[2]", "");
  EXPECT_INVALID_ARGUMENT(basis_table(kind(BasisKind::hermite), t, -1), "derivatives", ">= 0");
  const std::vector<double> bad{0.5, std::nan("")};
  EXPECT_INVALID_ARGUMENT(basis_table(kind(BasisKind::hermite), bad, 0), "t[1]", "");
}

/// The helix (cos s, sin s, s): its rotation-minimizing normal turns against the principal
/// normal N = -(cos s, sin s, 0) by -tau times the arc length (r' has no normal part:
/// phi' = -tau per unit length), tau = 1/2, speed sqrt(2): phi = -s / sqrt(2), with the
/// binormal B = (sin s, -cos s, 1) / sqrt(2).
V3r helix_rmf(double s) {
  const double phi = -s / std::sqrt(2.0);
  const V3r N(-std::cos(s), -std::sin(s), 0), B(std::sin(s) / std::sqrt(2.0), -std::cos(s) / std::sqrt(2.0), 1 / std::sqrt(2.0));
  return std::cos(phi) * N + std::sin(phi) * B;
}

double helix_rmf_error(int n) {
  std::vector<V3r> x, tangent;
  for (int i = 0; i <= n; ++i) {
    const double s = 2 * std::numbers::pi * i / n;
    x.emplace_back(std::cos(s), std::sin(s), s);
    tangent.push_back(V3r(-std::sin(s), std::cos(s), 1) / std::sqrt(2.0));
  }
  const auto r = rotation_minimizing_normals(x, tangent, helix_rmf(0));
  double err = 0;
  for (int i = 0; i <= n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    // Unit and normal to the tangent to rounding (each step projected and normalised).
    EXPECT_NEAR(norm(r[k]), 1, 1e-15);
    EXPECT_NEAR(dot(r[k], tangent[k]), 0, 1e-15);
    err = std::max(err, norm(r[k] - helix_rmf(2 * std::numbers::pi * i / n)));
  }
  return err;
}

TEST(Rmf, HelixExactFrameAtFourthOrder) {
  // One turn in 64 and 128 steps: the global error is O(h^4) [WangJuttlerZhengLiu08], so
  // halving the step divides it by about 16 (between 12 and 20: the next terms; measured
  // 1.43e-7 and 8.96e-9, a ratio of 16.0); at 128 steps (h = 0.049) below 2e-8.
  const double e64 = helix_rmf_error(64), e128 = helix_rmf_error(128);
  EXPECT_LT(e128, 2e-8);
  EXPECT_GT(e64 / e128, 12);
  EXPECT_LT(e64 / e128, 20);
}

TEST(Rmf, StraightLineKeepsItsNormalAndSizesAreChecked) {
  // Along a straight line every frame is rotation-minimizing: r stays r0 exactly (both
  // reflections are skipped or cancel: v2 = 0).
  const std::vector<V3r> x{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}, t(3, V3r(1, 1, 0) / std::sqrt(2.0));
  const V3r r0(0, 0, 1);
  for (const auto& r : rotation_minimizing_normals(x, t, r0)) EXPECT_EQ(r, r0);
  const std::vector<V3r> fewer(t.begin(), t.begin() + 2);
  EXPECT_INVALID_ARGUMENT(rotation_minimizing_normals(x, fewer, r0), "tangents", "one tangent per point");
  EXPECT_TRUE(rotation_minimizing_normals({}, {}, r0).empty());
}

}  // namespace
