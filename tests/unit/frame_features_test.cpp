// Bounds over a parameter range, the Frenet frame and the features at breaks (issue 8),
// on closed forms (the helix, the twisted cubic, circles as rational arcs, hand-solved
// boxes), and the shared degenerate fixtures through the new queries.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "degenerate_fixtures.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using P3 = Point<double, 3>;
using V2 = Vector<double, 2>;
using V3 = Vector<double, 3>;
using B2 = Bezier<double, 2>;
using B3 = Bezier<double, 3>;
using R2 = RationalBezier<double, 2>;
using R3 = RationalBezier<double, 3>;
using casteljau::test::eps;
constexpr double pi = std::numbers::pi;

/// A full circle of radius r about c, counter-clockwise, as four rational quarter arcs on
/// [0, 4] [PT97, 7.3].
Pieces<double, 2> circle(double r, P2 c) {
  std::vector<BezierPiece<double, 2>> segs;
  for (int i = 0; i < 4; ++i) segs.emplace_back(R2::circular_arc(c, r, i * pi / 2, (i + 1) * pi / 2));
  return Pieces<double, 2>(std::move(segs));
}

template <int D>
void expect_vector_near(const Vector<double, D>& got, const Vector<double, D>& want, double tol) {
  for (int k = 0; k < D; ++k) EXPECT_NEAR(got[k], want[k], tol) << "component " << k;
}

// --- bounds over a range ------------------------------------------------------------------------

TEST(BoundsRange, HandSolvedBoxes) {
  // x = 2t, y = 4t(1 - t): on [0, 1/4] both increase; on [1/4, 3/4] y peaks at 1 (t = 1/2).
  const B2 c{{0, 0}, {1, 2}, {2, 0}};
  auto b = bounds(c, 0.0, 0.25);
  EXPECT_EQ(b.lo, P2(0, 0));
  EXPECT_EQ(b.hi, P2(0.5, 0.75));
  b = bounds(c, 0.25, 0.75);
  EXPECT_EQ(b.lo, P2(0.5, 0.75));
  EXPECT_EQ(b.hi, P2(1.5, 1));
  b = bounds(c, 0.5, 0.5);  // one point
  EXPECT_EQ(b.lo, b.hi);
  EXPECT_EQ(b.lo, P2(1, 1));
  // The circle of radius 2 about (1, -1) from 45 to 135 degrees (parameters 0.5 to 1.5,
  // across the break at 1): x within +-sqrt(2), y from sqrt(2) to the top, 2, at 90 degrees.
  const auto circ = circle(2, P2(1, -1));
  b = bounds(circ, 0.5, 1.5);
  // (1e-14: the arcs' control points come from cos and sin of multiples of pi / 2.)
  const double s = std::sqrt(2.0);
  EXPECT_NEAR(b.lo[0], 1 - s, 1e-14);
  EXPECT_NEAR(b.hi[0], 1 + s, 1e-14);
  EXPECT_NEAR(b.lo[1], -1 + s, 1e-14);
  EXPECT_NEAR(b.hi[1], 1, 1e-14);
  // The whole range is the whole box; a polyline goes through its pieces.
  EXPECT_EQ(bounds(circ, 0.0, 4.0).hi, bounds(circ).hi);
  const Polyline<double, 2> zig({{0, 0}, {2, 3}, {4, -1}, {5, 5}});
  b = bounds(zig, 0.5, 2.5);  // (1, 1.5) .. (2, 3) .. (4, -1) .. (4.5, 2)
  EXPECT_EQ(b.lo, P2(1, -1));
  EXPECT_EQ(b.hi, P2(4.5, 3));
}

TEST(BoundsRange, RationalInsideAndErrors) {
  // Quarter circle of radius 1 as one rational quadratic: on [0, t] the box runs from
  // (cos a, 0) to (1, sin a) with the angle a at t (read from the curve's own point, which
  // lies on the circle: only the box's composition from the ends is tested here).
  const R2 q({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1});
  const auto p = q(0.3);
  const auto b = bounds(q, 0.0, 0.3);
  EXPECT_EQ(b.lo, P2(p[0], 0));
  EXPECT_EQ(b.hi, P2(1, p[1]));
  EXPECT_INVALID_ARGUMENT(bounds(q, 0.5, 0.25), "to", ">= from");
  EXPECT_INVALID_ARGUMENT(bounds(q, -0.5, 0.25), "from", "domain");
  EXPECT_INVALID_ARGUMENT(bounds(circle(1, P2(0, 0)), 1.0, 4.5), "to", "domain [0, 4]");
  EXPECT_INVALID_ARGUMENT(bounds(q, 0.0, std::nan("")), "to", "finite");
}

// --- the Frenet frame -------------------------------------------------------------------------

// The circular helix (r cos u, r sin u, h u) [doCarmo76, 1-5]: curvature r / (r^2 + h^2),
// torsion h / (r^2 + h^2), T = (-r sin u, r cos u, h) / sqrt(r^2 + h^2), N = (-cos u,
// -sin u, 0), B = (h sin u, -h cos u, r) / sqrt(r^2 + h^2). The kernel gets its exact
// derivatives (a helix is not a rational curve).
TEST(Frame, HelixClosedForms) {
  const double r = 2, h = 0.5, a = std::sqrt(r * r + h * h);
  for (double u : {0.0, 0.4, 2.0, -3.0}) {
    SCOPED_TRACE(u);
    const V3 d1(-r * std::sin(u), r * std::cos(u), h), d2(-r * std::cos(u), -r * std::sin(u), 0), d3(r * std::sin(u), -r * std::cos(u), 0);
    const auto f = frame_of<double, 3>(d1, d2, d3);
    ASSERT_TRUE(f && f->normal && f->binormal && f->torsion);
    expect_vector_near<3>(f->tangent, V3(-r * std::sin(u), r * std::cos(u), h) / a, 4 * eps);
    expect_vector_near<3>(*f->normal, V3(-std::cos(u), -std::sin(u), 0), 4 * eps);
    expect_vector_near<3>(*f->binormal, V3(h * std::sin(u), -h * std::cos(u), r) / a, 4 * eps);
    EXPECT_NEAR(f->curvature, r / (a * a), 4 * eps);
    EXPECT_NEAR(*f->torsion, h / (a * a), 4 * eps);
  }
}

// The twisted cubic (t, t^2, t^3) as a Bézier curve (control points (0,0,0), (1/3,0,0),
// (2/3,1/3,0), (1,1,1)): kappa = 2 sqrt(1 + 9t^2 + 9t^4) / (1 + 4t^2 + 9t^4)^(3/2),
// torsion = 3 / (1 + 9t^2 + 9t^4) (from c' = (1, 2t, 3t^2), c'' = (0, 2, 6t), c''' = (0, 0, 6)).
TEST(Frame, TwistedCubic) {
  const B3 c{{0, 0, 0}, {1.0 / 3, 0, 0}, {2.0 / 3, 1.0 / 3, 0}, {1, 1, 1}};
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    SCOPED_TRACE(t);
    const auto f = frame(c, t);
    ASSERT_TRUE(f && f->normal && f->torsion);
    const double q = 1 + 9 * t * t + 9 * t * t * t * t, s = 1 + 4 * t * t + 9 * t * t * t * t;
    EXPECT_NEAR(f->curvature, 2 * std::sqrt(q) / std::pow(s, 1.5), 1e-14);
    EXPECT_NEAR(*f->torsion, 3 / q, 1e-14);
    expect_vector_near<3>(f->tangent, V3(1, 2 * t, 3 * t * t) / std::sqrt(s), 1e-15);
    // B is along c' x c'' = (6t^2, -6t, 2).
    const V3 b(6 * t * t, -6 * t, 2);
    expect_vector_near<3>(*f->binormal, b / norm(b), 1e-15);
  }
}

// Circles as rational arcs: T perpendicular to the radius, N towards the centre, kappa
// 1/r; in 3-D in a tilted plane, torsion 0 and B the plane's normal.
TEST(Frame, CirclesAsRationalArcs) {
  const double r = 3;
  const auto circ = circle(r, P2(1, -2));
  for (double u : {0.0, 0.3, 1.0, 2.5, 4.0}) {
    SCOPED_TRACE(u);
    const auto f = frame(circ, u);
    ASSERT_TRUE(f && f->normal);
    const auto radial = (circ(u) - P2(1, -2)) / r;
    expect_vector_near<2>(f->tangent, V2(-radial[1], radial[0]), 1e-15);
    expect_vector_near<2>(*f->normal, -radial, 1e-15);
    EXPECT_NEAR(f->curvature, 1 / r, 1e-15);
  }
  // The quarter arc centre + r (e1 cos a + e2 sin a), a in [0, 90 degrees], with e1 =
  // (1, 0, 0), e2 = (0, 1, 1) / sqrt 2: B = e1 x e2 = (0, -1, 1) / sqrt 2.
  const double s = std::sqrt(0.5);
  const P3 o(1, 2, 3);
  const R3 arc({o + V3(r, 0, 0), o + V3(r, r * s, r * s), o + V3(0, r * s, r * s)}, {1, s, 1});
  for (double t : {0.0, 0.5, 0.9}) {
    const auto f = frame(arc, t);
    ASSERT_TRUE(f && f->normal && f->binormal && f->torsion);
    EXPECT_NEAR(f->curvature, 1 / r, 1e-15);
    EXPECT_NEAR(*f->torsion, 0, 1e-15);
    expect_vector_near<3>(*f->binormal, V3(0, -s, s), 1e-15);
    expect_vector_near<3>(*f->normal, (o - arc(t)) / r, 1e-15);
  }
}

TEST(Frame, UndefinedWhereTheDataSaySo) {
  // A straight cubic in space, A + s D with s = 0, 1, -1/2, 2 (uneven speed, running back
  // and forth; the points collinear up to the rounding of their decimal coordinates): a
  // tangent along D (s' = 0.255 > 0 at t = 0.3), no normal.
  const B3 line{{0.1, 0.2, 0.3}, {0.4, 0.7, 1.0}, {-0.05, -0.05, -0.05}, {0.7, 1.2, 1.7}};
  for (double t : {0.0, 0.3, 0.8}) {
    const auto f = frame(line, t);
    ASSERT_TRUE(f);
    EXPECT_FALSE(f->normal);
    EXPECT_FALSE(f->torsion);
  }
  expect_vector_near<3>(frame(line, 0.3)->tangent, V3(0.3, 0.5, 0.7) / norm(V3(0.3, 0.5, 0.7)), 1e-14);
  // In the plane the left normal exists on a line (curvature 0).
  const auto g = frame(B2{{0, 0}, {1, 1}, {3, 3}}, 0.5);
  ASSERT_TRUE(g && g->normal);
  expect_vector_near<2>(*g->normal, V2(-1, 1) / std::sqrt(2.0), 1e-15);
  EXPECT_EQ(g->curvature, 0);
  // The cusp of (0,0), (1,1), (0,1), (1,0) at 1/2 and a stop (coincident points).
  EXPECT_FALSE(frame(B2{{0, 0}, {1, 1}, {0, 1}, {1, 0}}, 0.5));
  EXPECT_FALSE(frame(B2{{0, 0}, {0, 0}, {1, 2}}, 0.0));
  EXPECT_INVALID_ARGUMENT(frame(line, std::nan("")), "t", "finite");
}

TEST(Frame, BreaksTakeTheRightPieceAndTheEndTheLeft) {
  const Polyline<double, 2> p({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_EQ(frame(p, 0.0)->tangent, V2(1, 0));
  EXPECT_EQ(frame(p, 1.0)->tangent, V2(0, 1));
  EXPECT_EQ(frame(p, 3.0)->tangent, V2(-1, 0));
}

// --- features at breaks -------------------------------------------------------------------------

TEST(FeaturesAtBreaks, OppositeArcsInflectAtTheBreak) {
  // Counter-clockwise quarter of the unit circle, then a clockwise quarter about (0, 2):
  // tangent continuous at (0, 1), curvature +1 then -1.
  const double s = std::sqrt(0.5);
  const Pieces<double, 2> path({BezierPiece<double, 2>(R2({{1, 0}, {1, 1}, {0, 1}}, {1, s, 1})),
                                BezierPiece<double, 2>(R2({{0, 1}, {-1, 1}, {-1, 2}}, {1, s, 1}))});
  const auto f = features(path);
  EXPECT_EQ(f.inflections, std::vector<double>{1.0});
  EXPECT_TRUE(f.cusps.empty());
  // The S cubic (0,0), (1,1), (2,-1), (3,0) split at its inflection t = 1/2 (halves by hand):
  // the curvature is continuous and zero at the break; found once, at the break.
  const Pieces<double, 2> halves({BezierPiece<double, 2>(B2{{0, 0}, {0.5, 0.5}, {1, 0.25}, {1.5, 0}}),
                                  BezierPiece<double, 2>(B2{{1.5, 0}, {2, -0.25}, {2.5, -0.5}, {3, 0}})});
  const auto h = features(halves);
  EXPECT_EQ(h.inflections, std::vector<double>{1.0});
  // The same arcs bending the same way (a G1 join, both counter-clockwise): none.
  const Pieces<double, 2> same({BezierPiece<double, 2>(R2({{1, 0}, {1, 1}, {0, 1}}, {1, s, 1})),
                                BezierPiece<double, 2>(R2({{0, 1}, {-1, 1}, {-1, 0}}, {1, s, 1}))});
  EXPECT_TRUE(features(same).inflections.empty());
}

TEST(FeaturesAtBreaks, PolylineCornersAndReversals) {
  // A zig-zag turns at every vertex but is straight in between: no inflections, no cusps.
  const auto z = features(Polyline<double, 2>({{0, 0}, {1, 1}, {2, 0}, {3, 1}}));
  EXPECT_TRUE(z.inflections.empty());
  EXPECT_TRUE(z.cusps.empty());
  // Turning back along itself at vertex 1 is a cusp; the turn at vertex 2 is a corner.
  const auto r = features(Polyline<double, 2>({{0, 0}, {2, 1}, {1, 0.5}, {3, 0}}));
  EXPECT_EQ(r.cusps, std::vector<double>{1.0});
  EXPECT_TRUE(r.inflections.empty());
  // Two cubics meeting with zero velocity and opposite directions at the break.
  const Pieces<double, 2> stop({BezierPiece<double, 2>(B2{{0, 0}, {1, 1}, {2, 1}, {2, 1}}),
                                BezierPiece<double, 2>(B2{{2, 1}, {2, 1}, {1, 1}, {0, 2}})});
  EXPECT_EQ(features(stop).cusps, std::vector<double>{1.0});
}

// --- the degenerate fixtures through the new queries ---------------------------------------------

TEST(FrameFeaturesDegenerate, FixturesGiveFiniteAnswers) {
  for (const auto& f : test::degenerate_fixtures()) {
    SCOPED_TRACE(f.name);
    const auto& c = f.curve;
    const auto whole = bounds(c), part = bounds(c, 0.25, 0.75);
    for (int k = 0; k < 2; ++k) {
      ASSERT_TRUE(std::isfinite(part.lo[k]) && std::isfinite(part.hi[k]));
      EXPECT_GE(part.lo[k], whole.lo[k]);
      EXPECT_LE(part.hi[k], whole.hi[k]);
    }
    for (double t : {0.25, 0.4, 0.5, 0.75}) {
      const auto q = c(t);
      for (int k = 0; k < 2; ++k) {
        // A sample lies in the box up to the evaluation's rounding (a few eps of the scale).
        EXPECT_GE(q[k], part.lo[k] - 16 * eps * f.scale) << t;
        EXPECT_LE(q[k], part.hi[k] + 16 * eps * f.scale) << t;
      }
    }
    // The 3-D lift (x, y, x y / scale) has a frame with unit vectors, or none, everywhere.
    std::vector<P3> lifted;
    for (const auto& p : c.points()) lifted.emplace_back(p[0], p[1], p[0] / f.scale * p[1]);
    const B3 c3(lifted);
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
      SCOPED_TRACE(t);
      if (const auto f2 = frame(c, t)) {
        EXPECT_NEAR(norm(f2->tangent), 1, 4 * eps);
        EXPECT_TRUE(std::isfinite(f2->curvature));
      }
      const auto fr = frame(c3, t);
      if (!fr) continue;
      EXPECT_NEAR(norm(fr->tangent), 1, 4 * eps);
      EXPECT_TRUE(std::isfinite(fr->curvature));
      if (fr->normal) {
        EXPECT_NEAR(norm(*fr->normal), 1, 4 * eps);
        EXPECT_NEAR(dot(*fr->normal, fr->tangent), 0, 8 * eps);
        EXPECT_TRUE(std::isfinite(*fr->torsion));
      }
    }
    const auto ft = features(c);
    for (double t : ft.cusps) EXPECT_TRUE(t > 0 && t < 1);
  }
}

}  // namespace
