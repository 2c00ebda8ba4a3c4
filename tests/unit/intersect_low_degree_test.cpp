// The fast path of intersect() for Bézier pieces of degree <= 3
// (algo/intersect/low_degree.hpp): closed-form crossings, the cases it must refuse
// (touches, near-misses at the ends, close pairs, overlaps) and the answers intersect()
// then gives, and agreement with the general engine on random pairs.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "casteljau/algo/intersect.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;

std::optional<detail::isect_fast::Roots<double>> fast(const B2& a, const B2& b) {
  return detail::isect_fast::intersect_low_degree<double>(a.points(), b.points());
}

/// The general engine alone (no fast path).
Intersections<double> general(const B2& a, const B2& b) {
  const auto pa = pieces(a);
  const auto pb = pieces(b);
  return detail::isect::solve(pa, &pb);
}

TEST(IntersectLowDegree, CubicCrossesLineAtKnownRoots) {
  // y(s) = 12.5 (s - 0.2)(s - 0.5)(s - 0.8), x(s) = 3s: Bernstein coefficients of y from
  // its power form -1 + 8.25 s - 18.75 s^2 + 12.5 s^3 (all exact in binary). The line
  // y = 0 from x = -1 to 4 is met at s = 0.2, 0.5, 0.8 with t = (3s + 1) / 5; s = 0.5 lies
  // on the first subdivision boundary (a point found from both halves, reported once).
  const B2 c{{0, -1}, {1, 1.75}, {2, -1.75}, {3, 1}};
  const B2 line{{-1, 0}, {4, 0}};
  const auto f = fast(c, line);
  ASSERT_TRUE(f.has_value());
  ASSERT_EQ(f->count, 3);
  const auto r = intersect(c, line);
  ASSERT_EQ(r.points.size(), 3u);
  const double want[] = {0.2, 0.5, 0.8};
  for (int i = 0; i < 3; ++i) {
    const auto& h = r.points[std::size_t(i)];
    EXPECT_NEAR(h.ta, want[i], 2e-16);  // about 1 ulp: well-conditioned simple roots
    EXPECT_NEAR(h.tb, (3 * want[i] + 1) / 5, 4e-16);
    EXPECT_EQ(h.kind, IntersectionKind::crossing);
    EXPECT_EQ(h.point, c(h.ta));
  }
}

TEST(IntersectLowDegree, SegmentsCrossAtKnownPoint) {
  // (0,0)-(4,2) and (0,2)-(4,0) cross at (2, 1), t = 1/2 on both; and a segment ending
  // exactly on the other, at its parameter 1/4.
  const auto r = intersect(B2{{0, 0}, {4, 2}}, B2{{0, 2}, {4, 0}});
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_EQ(r.points[0].ta, 0.5);
  EXPECT_EQ(r.points[0].tb, 0.5);
  const B2 a{{0, 0}, {4, 0}}, b{{1, 3}, {1, 0}};
  ASSERT_TRUE(fast(a, b).has_value());
  const auto e = intersect(a, b);
  ASSERT_EQ(e.points.size(), 1u);
  EXPECT_EQ(e.points[0].ta, 0.25);
  EXPECT_EQ(e.points[0].tb, 1.0);
}

TEST(IntersectLowDegree, NineCrossings) {
  // y = T3(x) = 4x^3 - 3x on [-1, 1] and its mirror x = T3(y): with x = cos(theta), T3(T3(x))
  // = T9(x) = x at theta = pi k / 4 (k = 0..4) and pi k / 5 (k = 0..5), nine points (two at
  // the curves' ends), all transversal; the parameters are (cos theta + 1) / 2 and
  // (cos 3 theta + 1) / 2.
  const B2 a{{-1, -1}, {-1.0 / 3, 5}, {1.0 / 3, -5}, {1, 1}};
  const B2 b{{-1, -1}, {5, -1.0 / 3}, {-5, 1.0 / 3}, {1, 1}};
  const auto f = fast(a, b);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->count, 9);
  std::vector<std::pair<double, double>> want;
  const double pi = std::numbers::pi;
  for (double th : {0.0, pi / 5, pi / 4, 2 * pi / 5, pi / 2, 3 * pi / 5, 3 * pi / 4, 4 * pi / 5, pi})
    want.emplace_back((std::cos(th) + 1) / 2, (std::cos(3 * th) + 1) / 2);
  std::sort(want.begin(), want.end());
  const auto r = intersect(a, b);
  ASSERT_EQ(r.points.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) {
    // A few eps: 1/3 is rounded in the control points, the cosines carry about 1 ulp.
    EXPECT_NEAR(r.points[i].ta, want[i].first, 1e-15);
    EXPECT_NEAR(r.points[i].tb, want[i].second, 1e-15);
    EXPECT_EQ(r.points[i].kind, IntersectionKind::crossing);
  }
}

TEST(IntersectLowDegree, TouchIsRefusedAndReportedOnceAsTangent) {
  // y(t) = (2t - 1)^2 touches y = 0 at t = 1/2 (a double root): no separated cones there.
  const B2 parabola{{0, 1}, {1, -1}, {2, 1}};
  const B2 line{{0, 0}, {2, 0}};
  EXPECT_FALSE(fast(parabola, line).has_value());
  const auto r = intersect(parabola, line);
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_EQ(r.points[0].kind, IntersectionKind::tangent);
  EXPECT_NEAR(r.points[0].ta, 0.5, 1e-7);  // a double root: about sqrt(eps)
}

TEST(IntersectLowDegree, NearMissesAroundTheContractDistance) {
  // The parabola lifted by g over y = 0 (size: control-box diagonal sqrt(8), the line's is
  // 2). Apart by 1e-9 of the size: not a common point; by 1e-11 of it: within the
  // contract's near-miss distance (1e-10 of the size), one touch.
  const double size = std::sqrt(8.0);
  for (const double g : {1e-9, 1e-11}) {
    const B2 parabola{{0, 1 + g * size}, {1, -1 + g * size}, {2, 1 + g * size}};
    const auto r = intersect(parabola, B2{{0, 0}, {2, 0}});
    if (g > 1e-10) {
      EXPECT_TRUE(r.points.empty());
    } else {
      ASSERT_EQ(r.points.size(), 1u);
      EXPECT_EQ(r.points[0].kind, IntersectionKind::tangent);
    }
  }
  // A segment ending short of another by d (transversal): within the near-miss distance
  // the fast path leaves the end to the general engine, which reports the point (at the
  // end, s = 1); farther, the boxes or fat lines are apart and there is no point.
  for (const double d : {1e-13, 1e-8}) {
    const B2 a{{0, 0}, {1, 0}}, b{{1 + d, -1}, {1 + d, 1}};
    if (d < 1e-10) {
      EXPECT_FALSE(fast(a, b).has_value());
    }
    const auto r = intersect(a, b);
    ASSERT_EQ(r.points.size(), d < 1e-10 ? 1u : 0u) << d;
    if (d < 1e-10) {
      EXPECT_EQ(r.points[0].ta, 1.0);
    }
  }
}

TEST(IntersectLowDegree, ClosePairOfCrossingsIsRefused) {
  // y(t) = (2t - 1)^2 - 1e-8 crosses y = 0 at t = 1/2 +- 5e-5: two points closer than
  // 1e-3, which the general engine handles (here, two crossings).
  const B2 parabola{{0, 1 - 1e-8}, {1, -1 - 1e-8}, {2, 1 - 1e-8}};
  const B2 line{{0, 0}, {2, 0}};
  EXPECT_FALSE(fast(parabola, line).has_value());
  const auto r = intersect(parabola, line);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_NEAR(r.points[0].ta, 0.5 - 0.5e-4, 1e-12);
  EXPECT_NEAR(r.points[1].ta, 0.5 + 0.5e-4, 1e-12);
}

TEST(IntersectLowDegree, OverlapIsRefusedAndReportedAsInterval) {
  // A cubic and its own right half [0.25, 1] (de Casteljau split): overlap, never points.
  const B2 c{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  const B2 right = c.split(0.25).right;
  EXPECT_FALSE(fast(c, right).has_value());
  const auto r = intersect(c, right);
  EXPECT_TRUE(r.points.empty());
  ASSERT_EQ(r.overlaps.size(), 1u);
  EXPECT_NEAR(r.overlaps[0].a.lo, 0.25, 1e-12);
  EXPECT_NEAR(r.overlaps[0].a.hi, 1.0, 1e-12);
  // Degenerate: a curve that is a point has no tangent cone; on the other curve it is
  // refused (the general engine reports it, as a crossing), away from it answered (none).
  const B2 on{c(0.5), c(0.5), c(0.5)}, off{{1, 1}, {1, 1}, {1, 1}};
  EXPECT_FALSE(fast(on, c).has_value());
  const auto p = intersect(on, c);
  ASSERT_EQ(p.points.size(), 1u);
  EXPECT_NEAR(p.points[0].tb, 0.5, 1e-12);
  const auto q = fast(off, c);
  ASSERT_TRUE(q.has_value());
  EXPECT_EQ(q->count, 0);
  EXPECT_TRUE(intersect(off, c).points.empty());
}

TEST(IntersectLowDegree, AgreesWithGeneralEngineOnRandomPairs) {
  // Random pairs of degrees 1..3 in the unit square: wherever the fast path answers, the
  // general engine (arcs, subdivision to flatness, damped Newton: a separate
  // implementation) finds the same points, to a few eps / sin(angle) in the parameters.
  test::SplitMix64 rng(8);
  int answered = 0, points = 0;
  const int pairs = 600;
  for (int i = 0; i < pairs; ++i) {
    const int m = 1 + int(rng.uniform() * 3), n = 1 + int(rng.uniform() * 3);
    const B2 a(test::random_points<double, 2>(rng, m)), b(test::random_points<double, 2>(rng, n));
    const auto f = fast(a, b);
    const auto g = general(a, b);
    if (!f) continue;
    ++answered;
    ASSERT_EQ(f->count, static_cast<int>(g.points.size())) << i;
    ASSERT_TRUE(g.overlaps.empty());
    for (int k = 0; k < f->count; ++k) {
      const auto [s, t] = f->st[std::size_t(k)];
      const auto& h = g.points[std::size_t(k)];
      const auto da = a.derivative_at(s), db = b.derivative_at(t);
      const double sine = std::abs(cross(da, db)) / (norm(da) * norm(db));
      EXPECT_NEAR(s, h.ta, 1e-14 / sine) << i;
      EXPECT_NEAR(t, h.tb, 1e-14 / sine) << i;
      EXPECT_EQ(h.kind, IntersectionKind::crossing);
      ++points;
    }
  }
  // Refusals are the rare cases (near-tangency, close pairs, end zones): for random pairs
  // well under 2%.
  EXPECT_GT(answered, pairs * 98 / 100);
  EXPECT_GT(points, pairs / 3);  // the sample does exercise crossings
}

TEST(IntersectLowDegree, ShallowCrossingsRefusedOrAgree) {
  // A random cubic and its copy turned by a small angle about one of its points: a
  // crossing there at that angle, the curves within about angle x size of each other
  // everywhere (farther than the near-miss distance). Wherever the fast path answers, the
  // general engine finds the same points; the crossing itself is always found.
  test::SplitMix64 rng(10);
  int answered = 0;
  // (Smaller angles keep the general engine subdividing for long: curves within 1e-6 of
  // their size everywhere take it about 0.5 s.)
  for (int i = 0; i < 20; ++i) {
    const B2 a(test::random_points<double, 2>(rng, 3));
    const double t0 = rng.uniform(0.1, 0.9);
    const P2 c = a(t0);
    for (const double angle : {1e-2, 1e-3}) {
      const double co = std::cos(angle), si = std::sin(angle);
      std::vector<P2> Q;
      for (const auto& p : a.points()) {
        const auto v = p - c;
        Q.push_back(c + Vector<double, 2>{co * v[0] - si * v[1], si * v[0] + co * v[1]});
      }
      const B2 b(Q);
      const auto f = fast(a, b);
      const auto g = general(a, b);
      const auto r = intersect(a, b);
      // The crossing at t0 (on b at t0 too), to eps / angle in the parameters.
      bool found = false;
      for (const auto& h : r.points) found = found || (std::abs(h.ta - t0) < 1e-13 / angle && std::abs(h.tb - t0) < 1e-13 / angle);
      EXPECT_TRUE(found) << i << " " << angle;
      if (!f) continue;
      ++answered;
      ASSERT_EQ(f->count, static_cast<int>(g.points.size())) << i << " " << angle;
      for (int k = 0; k < f->count; ++k) {
        EXPECT_NEAR(f->st[std::size_t(k)].first, g.points[std::size_t(k)].ta, 1e-13 / angle);
        EXPECT_NEAR(f->st[std::size_t(k)].second, g.points[std::size_t(k)].tb, 1e-13 / angle);
      }
    }
  }
  EXPECT_GE(answered, 20);  // at 1e-2 at least
}

TEST(IntersectLowDegree, PiecewiseCurvesAgreeWithGeneralEngine) {
  // A random polyline of 6 segments and a random cubic B-spline of 3 pieces against a
  // random cubic: every pair of pieces in one frame, points lifted to the curves'
  // parameters; the same points as the general engine wherever the fast path answers.
  test::SplitMix64 rng(9);
  int answered = 0, points = 0;
  const int trials = 150;
  for (int i = 0; i < trials; ++i) {
    const Polyline<double, 2> poly(test::random_points<double, 2>(rng, 6));
    const BSpline<double, 2> spline(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, test::random_points<double, 2>(rng, 5));
    const B2 c(test::random_points<double, 2>(rng, 3));
    const auto pc = pieces(c);
    for (const auto& other : {pieces(poly), pieces(spline)}) {
      const auto f = detail::isect::low_degree_pieces(other, pc);
      const auto g = detail::isect::solve(other, &pc);
      if (!f) continue;
      ++answered;
      ASSERT_EQ(f->points.size(), g.points.size()) << i;
      for (std::size_t k = 0; k < g.points.size(); ++k) {
        const auto& x = f->points[k];
        const auto& y = g.points[k];
        const auto da = other.derivative_at(x.ta), db = c.derivative_at(x.tb);
        const double sine = std::abs(cross(da, db)) / (norm(da) * norm(db));
        EXPECT_NEAR(x.ta, y.ta, 3e-14 / sine) << i;  // the spline's parameters reach 3
        EXPECT_NEAR(x.tb, y.tb, 1e-14 / sine) << i;
        EXPECT_LE(distance(x.point, other(x.ta)), 1e-15) << i;
        ++points;
      }
    }
  }
  EXPECT_GT(answered, 2 * trials * 95 / 100);
  EXPECT_GT(points, trials);
}

}  // namespace
