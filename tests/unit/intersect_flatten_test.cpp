// Intersections (algo/intersect.hpp) through the library API and the three flattening
// methods on the shared degenerate fixtures and on NURBS. The closed-form and oracle cases
// of intersect are in tests/cli/test_intersect.py; these check the C++ entry points, the
// degenerate fixtures and the curve types the CLI tests do not reach the same way.
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "casteljau/algo/intersect.hpp"
#include "degenerate_fixtures.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;

constexpr FlattenMethod all_methods[] = {FlattenMethod::uniform, FlattenMethod::subdivision, FlattenMethod::optimal};

/// The unit circle as a NURBS of four rational quadratic quarters (weights sqrt(2)/2 at the
/// corners) [PT97, 7.5].
Nurbs<double, 2> circle() {
  const double w = std::sqrt(2.0) / 2;
  return Nurbs<double, 2>(2, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4},
                          {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
                          {1, w, 1, w, 1, w, 1, w, 1});
}

TEST(FlattenMethods, DegenerateFixturesEveryMethod) {
  for (const auto& f : test::degenerate_fixtures()) {
    const double tol = 1e-3 * f.scale;
    for (const FlattenMethod m : all_methods) {
      const auto poly = flatten(f.curve, tol, m);
      ASSERT_GE(poly.size(), 2u) << f.name;
      EXPECT_EQ(poly.front(), f.curve.points().front()) << f.name;
      EXPECT_EQ(poly.back(), f.curve.points().back()) << f.name;
      for (int i = 0; i <= 2000; ++i)
        EXPECT_LE(test::polyline_distance(f.curve(i / 2000.0), poly), tol * (1 + 1e-12)) << f.name << " " << static_cast<int>(m);
    }
  }
}

TEST(FlattenMethods, NurbsCircleEveryMethod) {
  // Every vertex on the circle (radius 1 to rounding), every chord's midpoint inside it by
  // at most the tolerance: the exact geometry of a circle's polyline.
  const auto c = circle();
  for (const FlattenMethod m : all_methods) {
    const auto poly = flatten(c, 1e-3, m);
    for (const auto& v : poly) EXPECT_NEAR(norm(v.to_vector()), 1.0, 1e-15);
    for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
      const double r = norm((poly[i].to_vector() + poly[i + 1].to_vector()) / 2.0);
      EXPECT_GE(r, 1 - 1e-3);
    }
  }
  // The fewest chords of a circle within tolerance h: each spans at most 2 acos(1 - h)
  // radians, so at least 2 pi / (2 acos(1 - h)) = 70.2 -> 71 at h = 1e-3. Optimal is
  // within 5% of it (vertices per quarter: the pieces start at the quarter points).
  const double fewest = std::ceil(std::numbers::pi / std::acos(1 - 1e-3));
  const auto opt = flatten(c, 1e-3, FlattenMethod::optimal);
  EXPECT_GE(static_cast<double>(opt.size() - 1), fewest);
  EXPECT_LE(static_cast<double>(opt.size() - 1), 1.06 * fewest);
  EXPECT_NEAR(flatten_count_estimate(c, 1e-3), static_cast<double>(opt.size() - 1), 3);
}

// Lines, quadratics and cubics take allocation-free kernels (uniform and, in the plane,
// optimal). Uniform: n from Wang's bound computed here (n = ceil(sqrt(p (p-1) / 8 max|second
// difference| / tol))) and vertices c(i / n). Curve of W3 size (0..100), tolerance 0.1.
TEST(FlattenMethods, SmallUniformIsWangsSteps) {
  const B2 c{{10, 20}, {90, 95}, {5, 80}, {70, 3}};
  const auto P = c.points();
  double second = 0;
  for (int i = 0; i < 2; ++i) second = std::max(second, norm((P[i + 2] - P[i + 1]) - (P[i + 1] - P[i])));
  const int n = static_cast<int>(std::ceil(std::sqrt(6.0 / 8.0 * second / 0.1)));
  const auto poly = flatten(c, 0.1, FlattenMethod::uniform);
  ASSERT_EQ(poly.size(), static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) EXPECT_LE(norm(poly[static_cast<std::size_t>(i)] - c(static_cast<double>(i) / n)), 1e-12);
}

// A cubic on a line that runs past its end and back: every point lies on the line
// through any chord, so only the distance to the chord *segment* (the part beyond its
// ends) can fail a step. Every method within tolerance.
TEST(FlattenMethods, CollinearCurveDoublingBack) {
  // Control points 0, 3, -2, 1 on the x axis: x(t) = 9 t - 24 t^2 + 16 t^3, extremes at
  // t = 1/4 (x = 1) and t = 3/4 (x = 0); x(1) = 1. Also B'(0) = 0 at a collinear start
  // (0, 0, 3, 1), which stalled an early version of the optimal kernel.
  for (const B2& c : {B2{{0, 0}, {3, 0}, {-2, 0}, {1, 0}}, B2{{0, 0}, {0, 0}, {3, 0}, {1, 0}}}) {
    for (const FlattenMethod m : all_methods) {
      const auto poly = flatten(c, 0.1, m);
      for (int i = 0; i <= 4000; ++i) EXPECT_LE(test::polyline_distance(c(i / 4000.0), poly), 0.1) << static_cast<int>(m);
    }
  }
}

// The appending overload: the same polyline as the returning one, after what out held;
// out unchanged when it throws (tolerance below the coordinates' resolution; a path whose
// pieces do not meet).
TEST(FlattenMethods, AppendingOverload) {
  const B2 cubic{{0, 0}, {1, 2}, {2, -1}, {3, 1}};
  const B2 quintic{{0, 0}, {1, 2}, {2, -1}, {3, 1}, {4, 0}, {5, 2}};
  const RationalBezier<double, 2> conic({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1});
  const P2 marker(-7, -7);
  for (const FlattenMethod m : all_methods) {
    auto check = [&](const auto& c) {
      std::vector<P2> out{marker};
      flatten(c, 1e-3, m, out);
      const auto alone = flatten(c, 1e-3, m);
      ASSERT_EQ(out.size(), alone.size() + 1);
      EXPECT_EQ(out[0], marker);
      for (std::size_t i = 0; i < alone.size(); ++i) EXPECT_EQ(out[i + 1], alone[i]);
    };
    check(cubic);
    check(quintic);
    check(conic);
    check(circle());
    std::vector<P2> out{marker};
    EXPECT_THROW(flatten(B2{{1e10, 0}, {1e10, 1}, {1e10 + 1, 1}}, 1e-9, m, out), NumericalError);
    const Path<double, 2> broken({cubic, B2{{3.5, 1}, {4, 2}, {5, 0}}});
    EXPECT_THROW(flatten(broken, 0.1, m, out), InvalidArgument);
    EXPECT_EQ(out, std::vector<P2>{marker});
  }
}

TEST(Intersect, LibraryEntryPointsAcrossTypes) {
  // Cubic against a polyline: x(t) = 3t, y(t) = (1-t)^3 (-1) + ... crosses y = 0 three times.
  const B2 c{{0, -1}, {1, 3}, {2, -3}, {3, 1}};
  const Polyline<double, 2> line{{-1, 0}, {1.5, 0}, {4, 0}};
  const auto r = intersect(c, line);
  ASSERT_EQ(r.points.size(), 3u);
  EXPECT_TRUE(r.overlaps.empty());
  for (const auto& h : r.points) {
    EXPECT_NEAR(c(h.ta)[1], 0, 1e-15);
    EXPECT_NEAR(line(h.tb)[0], c(h.ta)[0], 1e-14);
    EXPECT_EQ(h.kind, IntersectionKind::crossing);
  }
  EXPECT_DOUBLE_EQ(r.points[1].ta, 0.5);  // the middle root by symmetry: x = 1.5, tb = 1
  EXPECT_DOUBLE_EQ(r.points[1].tb, 1.0);
  // The circle and the line x = 0.6 meet at (0.6, +-0.8), on pieces 0 and 1 ...; the
  // line y = 1 touches it at (0, 1) where two pieces join (t = 1): once, tangent.
  const auto cc = circle();
  const auto vert = intersect(cc, B2{{0.6, -2}, {0.6, 2}});
  ASSERT_EQ(vert.points.size(), 2u);
  for (const auto& h : vert.points) {
    EXPECT_NEAR(std::abs(h.point[1]), 0.8, 1e-15);
    EXPECT_NEAR(h.point[0], 0.6, 1e-15);
  }
  const auto top = intersect(cc, B2{{-2, 1}, {2, 1}});
  ASSERT_EQ(top.points.size(), 1u);
  EXPECT_EQ(top.points[0].kind, IntersectionKind::tangent);
  EXPECT_NEAR(top.points[0].ta, 1.0, 1e-7);
  EXPECT_NEAR(top.points[0].tb, 0.5, 1e-7);
  // The circle with itself: one overlap over its whole domain; no self-intersection (its
  // closing point is not one).
  const auto same = intersect(cc, cc);
  EXPECT_TRUE(same.points.empty());
  ASSERT_EQ(same.overlaps.size(), 1u);
  EXPECT_EQ(same.overlaps[0].a, (Interval<double>{0, 4}));
  const auto self = self_intersect(cc);
  EXPECT_TRUE(self.points.empty());
  EXPECT_TRUE(self.overlaps.empty());
}

TEST(Intersect, DegenerateFixturesGiveCommonPointsOnly) {
  // Each fixture against itself and a crossing line, and alone: no throw, no NaN, and every
  // reported point on both curves (1e-9 of the size; the near-miss rule is 1e-10).
  for (const auto& f : test::degenerate_fixtures()) {
    const auto& c = f.curve;
    const auto box = c.control_bounds();
    const B2 diag{box.lo, box.hi};
    for (const auto& r : {intersect(c, c), intersect(c, diag), self_intersect(c)}) {
      for (const auto& h : r.points) {
        ASSERT_TRUE(std::isfinite(h.ta) && std::isfinite(h.tb)) << f.name;
        EXPECT_GE(h.ta, 0);
        EXPECT_LE(h.tb, 1);
        EXPECT_LE(distance(c(h.ta), h.point), 1e-9 * f.scale) << f.name;
      }
      for (const auto& o : r.overlaps) EXPECT_LT(o.a.lo, o.a.hi) << f.name;
    }
    // A curve with extent overlaps itself over its whole domain.
    if (box.lo != box.hi && f.curve.degree() >= 1) {
      const auto r = intersect(c, c);
      ASSERT_FALSE(r.overlaps.empty()) << f.name;
      EXPECT_EQ(r.overlaps.front().a.lo, 0.0) << f.name;
      EXPECT_EQ(r.overlaps.back().a.hi, 1.0) << f.name;
      EXPECT_TRUE(r.points.empty()) << f.name;
    }
  }
}

/// c turned by angle a about o (rounded coordinates: the copy is exact to a few eps).
B2 turned(const B2& c, const P2& o, double a) {
  std::vector<P2> q;
  for (const auto& p : c.points()) {
    const auto v = p - o;
    q.push_back(P2{o[0] + std::cos(a) * v[0] - std::sin(a) * v[1], o[1] + std::sin(a) * v[0] + std::cos(a) * v[1]});
  }
  return B2(q);
}

TEST(Intersect, NearCoincidentCurves) {
  // The general engine (detail::isect::solve: the fast path refuses these pairs). A cubic
  // and its copy turned by 1e-6 about c(0.5) cross there once, at an angle of 1e-6
  // (parameters to about eps / 1e-6); turned about its start they meet there.
  using PC = Pieces<double, 2>;
  auto general = [](const B2& a, const B2& b) {
    const PC pa(std::vector<BezierPiece<double, 2>>{a}), pb(std::vector<BezierPiece<double, 2>>{b});
    return detail::isect::solve(pa, &pb);
  };
  const B2 c{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  const auto mid = general(c, turned(c, c(0.5), 1e-6));
  ASSERT_EQ(mid.points.size(), 1u);
  EXPECT_TRUE(mid.overlaps.empty());
  EXPECT_NEAR(mid.points[0].ta, 0.5, 1e-8);
  EXPECT_NEAR(mid.points[0].tb, 0.5, 1e-8);
  const auto start = general(c, turned(c, c(0.0), 1e-6));
  ASSERT_EQ(start.points.size(), 1u);
  EXPECT_TRUE(start.overlaps.empty());
  EXPECT_NEAR(start.points[0].ta, 0.0, 1e-8);
  EXPECT_NEAR(start.points[0].tb, 0.0, 1e-8);
  // Translated copies: apart by 1e-9 of the size (the control-box diagonal, 5): a near
  // miss, nothing; by 1e-11 of it, within the near-miss distance everywhere: one overlap.
  const double size = 5;
  for (double d : {1e-9, 1e-8}) {
    const B2 up{{0, d * size}, {1, 2 + d * size}, {3, -1 + d * size}, {4, 1 + d * size}};
    const auto r = general(c, up);
    EXPECT_TRUE(r.points.empty()) << d;
    EXPECT_TRUE(r.overlaps.empty()) << d;
  }
  const B2 close{{0, 1e-11 * size}, {1, 2 + 1e-11 * size}, {3, -1 + 1e-11 * size}, {4, 1 + 1e-11 * size}};
  const auto ov = general(c, close);
  EXPECT_TRUE(ov.points.empty());
  ASSERT_EQ(ov.overlaps.size(), 1u);
  EXPECT_EQ(ov.overlaps[0].a, (Interval<double>{0, 1}));
  EXPECT_EQ(ov.overlaps[0].b_start, 0.0);
  EXPECT_EQ(ov.overlaps[0].b_end, 1.0);
}

TEST(Intersect, CopiesTurnedByTinyAnglesCrossOnceAtTheCentre) {
  // A cubic and its copy turned by a about c(t0) cross there only, at the angle a: one
  // point, tangent (a < 1e-6), at t0 to the conditioning of a crossing at angle a (a few
  // eps / a in the parameters; the copy's rounded control points move the exact crossing
  // by about that much). The general engine decides these on bands (no subdivision down
  // to the near-miss distance). Before bands: t = 0.607 about c(0.5) at 1e-9, three
  // points at 1e-8 on the joint and in the loop.
  using PC = Pieces<double, 2>;
  const B2 c{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  for (const double a : {1e-7, 1e-8, 1e-9}) {
    for (const double t0 : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const B2 b = turned(c, c(t0), a);
      const PC pa(std::vector<BezierPiece<double, 2>>{c}), pb(std::vector<BezierPiece<double, 2>>{b});
      const auto r = detail::isect::solve(pa, &pb);
      ASSERT_EQ(r.points.size(), 1u) << a << " " << t0;
      EXPECT_TRUE(r.overlaps.empty());
      EXPECT_EQ(r.points[0].kind, IntersectionKind::tangent);
      const double accuracy = 1e3 * std::numeric_limits<double>::epsilon() / a;
      EXPECT_NEAR(r.points[0].ta, t0, accuracy) << a;
      EXPECT_NEAR(r.points[0].tb, t0, accuracy) << a;
      EXPECT_LE(distance(c(r.points[0].ta), b(r.points[0].tb)), 1e-14);
    }
    // The same crossing on the joint of two pieces (c's halves, on [0, 2]), and as the
    // self-intersection of the loop c, then the copy turned about c(0.5) run backwards.
    const auto h = c.split(0.5);
    const PC halves(std::vector<BezierPiece<double, 2>>{h.left, h.right});
    const PC turned_copy(std::vector<BezierPiece<double, 2>>{turned(c, c(0.5), a)});
    const auto joint = detail::isect::solve(halves, &turned_copy);
    ASSERT_EQ(joint.points.size(), 1u) << a;
    EXPECT_TRUE(joint.overlaps.empty());
    EXPECT_NEAR(joint.points[0].ta, 1, 2e3 * std::numeric_limits<double>::epsilon() / a);
    EXPECT_NEAR(joint.points[0].tb, 0.5, 1e3 * std::numeric_limits<double>::epsilon() / a);
    const PC loop(std::vector<BezierPiece<double, 2>>{c, turned(c, c(0.5), a).reverse()});
    const auto self = detail::isect::solve(loop, static_cast<const PC*>(nullptr));
    ASSERT_EQ(self.points.size(), 1u) << a;
    EXPECT_TRUE(self.overlaps.empty());
    EXPECT_NEAR(self.points[0].ta, 0.5, 1e3 * std::numeric_limits<double>::epsilon() / a);
    EXPECT_NEAR(self.points[0].tb, 1.5, 1e3 * std::numeric_limits<double>::epsilon() / a);
  }
}

TEST(Intersect, RandomCopiesTurnedByTinyAnglesProperty) {
  // Seeded property: a random cubic (points in the unit square) and its copy turned by a
  // in [1e-9, 1e-7] about c(t0) meet at (t0, t0): exactly one reported point there (to
  // 1e3 eps / a, the conditioning of a crossing at angle a), tangent; every reported point
  // (loops of the cubic may add crossings elsewhere) within the near-miss distance on
  // both curves. The curves stay within it of each other over at most 1e-10 / a <= 0.1 of
  // the size around t0: no overlap.
  using PC = Pieces<double, 2>;
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 60; ++k) {
    std::vector<P2> p;
    for (int i = 0; i < 4; ++i) p.push_back(P2{u(rng), u(rng)});
    const B2 c(p);
    const double t0 = u(rng), a = std::pow(10.0, -9 + 2 * u(rng));
    const B2 b = turned(c, c(t0), a);
    const PC pa(std::vector<BezierPiece<double, 2>>{c}), pb(std::vector<BezierPiece<double, 2>>{b});
    const auto r = detail::isect::solve(pa, &pb);
    EXPECT_TRUE(r.overlaps.empty()) << k;
    const auto bc = c.control_bounds(), bb = b.control_bounds();
    const double size = std::max(norm(bc.hi - bc.lo), norm(bb.hi - bb.lo));
    const double accuracy = 1e3 * std::numeric_limits<double>::epsilon() / a;
    int at_t0 = 0;
    for (const auto& h : r.points) {
      EXPECT_LE(distance(c(h.ta), b(h.tb)), 1e-10 * size) << k;
      if (std::abs(h.ta - t0) <= accuracy && std::abs(h.tb - t0) <= accuracy) {
        ++at_t0;
        EXPECT_EQ(h.kind, IntersectionKind::tangent) << k;
      }
    }
    EXPECT_EQ(at_t0, 1) << k << " t0 " << t0 << " a " << a;
  }
}

/// The unit circle about (cx, cy) as circle() builds it.
Nurbs<double, 2> circle_at(double cx, double cy) {
  const auto c = circle();
  std::vector<P2> q;
  for (const auto& p : c.points()) q.push_back(P2{p[0] + cx, p[1] + cy});
  return Nurbs<double, 2>(2, c.knots(), q, c.weights());
}

TEST(Intersect, CirclesWithCloseCentresCrossTwice) {
  // Unit circles with centres d apart (size 2 sqrt 2, near-miss distance 2.8e-10) cross at
  // c / 2 +- n sqrt(1 - d^2 / 4) at an angle d: two points, never an overlap, whether the
  // crossings fall on the joints of the quarters (offset along x) or inside them; tangent
  // below an angle of 1e-6. Positions to 4 eps / d, the conditioning of the crossing.
  // 1.4e-5 and 2e-5 along x gave a 1e-5 overlap at each crossing (between the joints of
  // the two circles' quarters, d apart) before overlaps crossed inside were rejected.
  for (const double d : {3e-10, 1e-9, 1e-8, 1e-7, 1e-5, 1.4e-5, 2e-5, 1e-4}) {
    for (const bool diagonal : {false, true}) {
      const P2 u = diagonal ? P2{std::sqrt(0.5), std::sqrt(0.5)} : P2{1, 0};
      const P2 c{d * u[0], d * u[1]};
      const auto r = intersect(circle(), circle_at(c[0], c[1]));
      EXPECT_TRUE(r.overlaps.empty()) << d << " " << diagonal;
      ASSERT_EQ(r.points.size(), 2u) << d << " " << diagonal;
      const double h = std::sqrt(1 - d * d / 4);
      const P2 e0{c[0] / 2 - u[1] * h, c[1] / 2 + u[0] * h}, e1{c[0] / 2 + u[1] * h, c[1] / 2 - u[0] * h};
      const double accuracy = 4 * std::numeric_limits<double>::epsilon() / d;
      const auto& p = r.points;
      const bool first_is_e0 = distance(p[0].point, e0) < distance(p[1].point, e0);
      EXPECT_LE(distance(p[first_is_e0 ? 0 : 1].point, e0), accuracy) << d << " " << diagonal;
      EXPECT_LE(distance(p[first_is_e0 ? 1 : 0].point, e1), accuracy) << d << " " << diagonal;
      for (const auto& x : p) EXPECT_EQ(x.kind, d < 1e-6 ? IntersectionKind::tangent : IntersectionKind::crossing) << d;
    }
  }
}

TEST(Intersect, CopiesApartByOneToThreeNearMissDistances) {
  // Translated by k 1e-10 of the size (5) along the chord's normal: apart by k (0.65 .. 1)
  // 1e-10 of the size (the cosine of the tangent's angle to the chord, 0.65 at the ends).
  // k = 2, 3: farther than the near-miss distance everywhere, nothing; k = 0.5: within it
  // everywhere, one overlap.
  const B2 c{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  const P2 n{-1 / std::sqrt(17.0), 4 / std::sqrt(17.0)};
  for (const double k : {2.0, 3.0, 0.5}) {
    std::vector<P2> q;
    for (const auto& p : c.points()) q.push_back(P2{p[0] + k * 5e-10 * n[0], p[1] + k * 5e-10 * n[1]});
    const auto r = intersect(c, B2(q));
    EXPECT_TRUE(r.points.empty()) << k;
    ASSERT_EQ(r.overlaps.size(), k < 1 ? 1u : 0u) << k;
    if (k < 1) {
      EXPECT_EQ(r.overlaps[0].a, (Interval<double>{0, 1}));
    }
  }
}

TEST(Intersect, MergedTouchAtTheClosestApproach) {
  // Two crossings closer than the near-miss distance, or a near miss within it, are one
  // touch reported where the separation of the curves peaks (the tangents parallel), not
  // at the middle of the points merged. The parabola y = 4 t (1 - t) (apex (1, 1) at
  // t = 1/2) against y = 1 + d from x = -1 to 3 (tb = 1/2 below the apex): crossings
  // 2 sqrt(-d) apart for d < 0 (at d = -1e-11 the merge used to give t = 0.5000008), a
  // near miss for d > 0. Closed form: (0.5, 0.5), to 1e-14 (g = u_a x u_b has slope 4
  // there and is rounded to a few eps).
  const B2 parabola{{0, 0}, {1, 2}, {2, 0}};
  for (const double d : {-1e-11, 1e-11, -1e-10, -3e-10}) {
    const auto r = intersect(parabola, B2{{-1, 1 + d}, {3, 1 + d}});
    ASSERT_EQ(r.points.size(), 1u) << d;
    EXPECT_TRUE(r.overlaps.empty());
    EXPECT_EQ(r.points[0].kind, IntersectionKind::tangent) << d;
    EXPECT_NEAR(r.points[0].ta, 0.5, 1e-14) << d;
    EXPECT_NEAR(r.points[0].tb, 0.5, 1e-14) << d;
  }
  // The same on a joint of pieces: the parabola's halves on [0, 2] (apex at t = 1), and
  // the NURBS unit circle against y = 1 + d (its top (0, 1) is the joint u = 1 of the
  // quarters).
  using PC = Pieces<double, 2>;
  const auto h = parabola.split(0.5);
  const PC halves(std::vector<BezierPiece<double, 2>>{h.left, h.right});
  for (const double d : {-1e-11, 1e-11}) {
    const PC line(std::vector<BezierPiece<double, 2>>{B2{{-1, 1 + d}, {3, 1 + d}}});
    const auto r = detail::isect::solve(halves, &line);
    ASSERT_EQ(r.points.size(), 1u) << d;
    EXPECT_EQ(r.points[0].kind, IntersectionKind::tangent) << d;
    EXPECT_NEAR(r.points[0].ta, 1, 1e-14) << d;
    EXPECT_NEAR(r.points[0].tb, 0.5, 1e-14) << d;
    const auto c = intersect(circle(), B2{{-2, 1 + d}, {2, 1 + d}});
    ASSERT_EQ(c.points.size(), 1u) << d;
    EXPECT_EQ(c.points[0].kind, IntersectionKind::tangent) << d;
    EXPECT_NEAR(c.points[0].ta, 1, 1e-14) << d;
    EXPECT_NEAR(c.points[0].tb, 0.5, 1e-14) << d;
  }
  // Unit circles touching from outside, centres 2 + d apart along the direction 0.5 rad:
  // at (cos 0.5, sin 0.5) on the first, inside its first quarter.
  for (const double d : {-1e-11, 1e-11}) {
    const auto r = intersect(circle(), circle_at((2 + d) * std::cos(0.5), (2 + d) * std::sin(0.5)));
    ASSERT_EQ(r.points.size(), 1u) << d;
    EXPECT_EQ(r.points[0].kind, IntersectionKind::tangent) << d;
    EXPECT_LE(distance(r.points[0].point, P2{std::cos(0.5), std::sin(0.5)}), 1e-14) << d;
    // Along x the touch is at (1, 0), the closing point of the first circle (u = 0 and
    // u = 4): one point, not one at each end of its domain.
    const auto x = intersect(circle(), circle_at(2 + d, 0));
    ASSERT_EQ(x.points.size(), 1u) << d;
    EXPECT_EQ(x.points[0].kind, IntersectionKind::tangent) << d;
    EXPECT_LE(std::min(x.points[0].ta, 4 - x.points[0].ta), 1e-14) << d;
    EXPECT_NEAR(x.points[0].tb, 2, 1e-14) << d;
  }
}

TEST(Intersect, ReparametrisedAndSubIntervalOverlaps) {
  // The halves of a cubic split at 0.3 (a path on [0, 2]) against the whole: one overlap,
  // joined across the joint, both ways round.
  using PC = Pieces<double, 2>;
  const B2 c{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  const auto h = c.split(0.3);
  const PC halves(std::vector<BezierPiece<double, 2>>{h.left, h.right});
  const PC whole(std::vector<BezierPiece<double, 2>>{c});
  for (const bool swap : {false, true}) {
    const auto r = swap ? detail::isect::solve(whole, &halves) : detail::isect::solve(halves, &whole);
    EXPECT_TRUE(r.points.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].a.lo, 0, 1e-12);
    EXPECT_NEAR(r.overlaps[0].a.hi, swap ? 1 : 2, 1e-12);
    EXPECT_NEAR(r.overlaps[0].b_start, 0, 1e-12);
    EXPECT_NEAR(r.overlaps[0].b_end, swap ? 2 : 1, 1e-12);
  }
  // A degree-12 curve (points on a wave: no loops) cut into its parts on [0, 0.6] and
  // [0.4, 1]: they share c on [0.4, 0.6], which is [2/3, 1] of the first and [0, 1/3] of
  // the second.
  std::vector<P2> q;
  for (int i = 0; i <= 12; ++i) q.push_back(P2{i / 12.0, std::sin(i * 0.7)});
  const B2 w(q);
  const auto r = intersect(detail::part(w, 0.0, 0.6), detail::part(w, 0.4, 1.0));
  EXPECT_TRUE(r.points.empty());
  ASSERT_EQ(r.overlaps.size(), 1u);
  EXPECT_NEAR(r.overlaps[0].a.lo, 2.0 / 3, 1e-9);
  EXPECT_NEAR(r.overlaps[0].a.hi, 1, 1e-12);
  EXPECT_NEAR(r.overlaps[0].b_start, 0, 1e-12);
  EXPECT_NEAR(r.overlaps[0].b_end, 1.0 / 3, 1e-9);
}

TEST(Intersect, SerpentineCrossesItselfAtEveryGridPoint) {
  // A polyline sweeping the rows y = 0..k (x from 0.5 to k + 0.5, back and forth), then the
  // columns x = 1..k (y from k + 1 or k + 0.5 down to -0.5 and back): every row crosses
  // every column once, at (j, i), and the connectors cross nothing: k (k + 1) crossings,
  // each found once (the merge of points compares neighbours in ta only).
  const int k = 40;
  std::vector<P2> v;
  for (int i = 0; i <= k; ++i) {
    const bool even = i % 2 == 0;
    v.push_back(P2{even ? 0.5 : k + 0.5, double(i)});
    v.push_back(P2{even ? k + 0.5 : 0.5, double(i)});
  }
  v.push_back(P2{k + 0.5, k + 1.0});  // k even: the last row ends at x = k + 0.5
  for (int j = 1; j <= k; ++j) {
    const bool down = j % 2 == 1;
    v.push_back(P2{double(j), down ? (j == 1 ? k + 1.0 : k + 0.5) : -0.5});
    v.push_back(P2{double(j), down ? -0.5 : k + 0.5});
  }
  const Polyline<double, 2> serpentine(v);
  const auto r = self_intersect(serpentine);
  EXPECT_TRUE(r.overlaps.empty());
  ASSERT_EQ(r.points.size(), static_cast<std::size_t>(k * (k + 1)));
  std::vector<int> seen(static_cast<std::size_t>(k * (k + 1)), 0);
  for (const auto& h : r.points) {
    EXPECT_LT(h.ta, h.tb);
    EXPECT_EQ(h.kind, IntersectionKind::crossing);
    const double j = std::round(h.point[0]), i = std::round(h.point[1]);
    EXPECT_NEAR(h.point[0], j, 1e-14);
    EXPECT_NEAR(h.point[1], i, 1e-14);
    ASSERT_TRUE(j >= 1 && j <= k && i >= 0 && i <= k) << h.point[0] << " " << h.point[1];
    ++seen[static_cast<std::size_t>((j - 1) * (k + 1) + i)];
  }
  for (int c : seen) EXPECT_EQ(c, 1);
}

}  // namespace
