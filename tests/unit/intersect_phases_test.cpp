// The phases of the general intersection engine (algo/intersect.hpp, solve()) called one
// at a time on inputs whose answers are known in closed form: the shared frame, the pairs
// of arcs, the joining and confirming of overlaps, the merging of points, edge points,
// classification and the closing point of a closed curve; and, below them, the steps
// for one pair of arcs (arc_points, arc_overlap, refine, polish_touch) on textbook inputs.
#include <array>
#include <cmath>
#include <vector>

#include "casteljau/algo/intersect.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using namespace casteljau::detail::isect;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;
using Pc = Pieces<double, 2>;

/// Both curves prepared in their shared frame, with the context solve() makes.
struct Both {
  Pc a, b;
  Prepared<double> A, B;
  double tol;
  Context<double> ctx;
  Both(Pc a_, Pc b_) : a(std::move(a_)), b(std::move(b_)) {
    const auto f = shared_frame(a, b);
    A = prepare(a, f.origin, f.e);
    B = prepare(b, f.origin, f.e);
    tol = near_miss(A, B);
    ctx = make_context(tol);
  }
};

TEST(IntersectPhases, SharedFrameIsOriginAtAsFirstPointAndAPowerOfTwo) {
  // Largest |P - origin| over both curves: 3 (x of (4, 1), y of (1, -2)); 3 2^-2 = 0.75
  // lies in [0.5, 1), so e = 2.
  const Pc a = pieces(B2{{1, 1}, {4, 1}});
  const Pc b = pieces(B2{{1, -2}, {2, 0}});
  const auto f = shared_frame(a, b);
  EXPECT_EQ(f.origin, (P2{1, 1}));
  EXPECT_EQ(f.e, 2);
  // Scaled by 2^10: the same frame, 10 more in the exponent.
  const auto g = shared_frame(pieces(B2{{1024, 1024}, {4096, 1024}}), pieces(B2{{1024, -2048}, {2048, 0}}));
  EXPECT_EQ(g.e, 12);
  // Every point the origin: no scale.
  EXPECT_EQ(shared_frame(pieces(B2{{5, 5}, {5, 5}}), pieces(B2{{5, 5}, {5, 5}})).e, 0);
}

TEST(IntersectPhases, NearMissIsATenBillionthOfTheLargerDiagonal) {
  // Unit frame e = 1 (largest |P| = 1): a spans (0, 0)..(0.5, 0), b (0, 0)..(0.25, 0.25);
  // the larger control-box diagonal is 0.5.
  const Both s(pieces(B2{{0, 0}, {1, 0}}), pieces(B2{{0, 0}, {0.5, 0.5}}));
  EXPECT_DOUBLE_EQ(s.tol, 0.5e-10);
}

TEST(IntersectPhases, MeetArcsFindsTheCrossingOfTwoLines) {
  // The diagonals of the square [0, 2]^2 cross at (1, 1), both at parameter 1/2.
  Both s(pieces(B2{{0, 0}, {2, 2}}), pieces(B2{{0, 2}, {2, 0}}));
  const auto pairs = meet_arcs(s.A, s.B, false, s.ctx);
  EXPECT_TRUE(pairs.overlaps.empty());
  ASSERT_GE(pairs.hits.size(), 1u);
  for (const auto& h : pairs.hits) {
    // Newton on a linear system: exact to a few eps.
    EXPECT_NEAR(h.ta, 0.5, 4 * test::eps);
    EXPECT_NEAR(h.tb, 0.5, 4 * test::eps);
  }
}

TEST(IntersectPhases, MeetArcsTakesIdenticalArcsAsOneOverlap) {
  // A quadratic and its copy: one arc each (monotone in x and y), the same arc.
  const B2 q{{0, 0}, {1, 2}, {2, 3}};
  Both s(pieces(q), pieces(q));
  const auto pairs = meet_arcs(s.A, s.B, false, s.ctx);
  EXPECT_TRUE(pairs.hits.empty());
  ASSERT_EQ(pairs.overlaps.size(), 1u);
  EXPECT_EQ(pairs.overlaps[0].o.a, Interval<double>(0, 1));
  EXPECT_EQ(pairs.overlaps[0].o.b_start, 0.0);
  EXPECT_EQ(pairs.overlaps[0].o.b_end, 1.0);
}

TEST(IntersectPhases, JoinOverlapsJoinsOnlyContinuations) {
  using R = RawOverlap<double>;
  std::vector<R> raw;
  raw.push_back(R{{{0.5, 1}, 0.5, 1}, {}, {{1, 1}}});
  raw.push_back(R{{{0, 0.5}, 0, 0.5}, {}, {{0, 0}}});
  raw.push_back(R{{{1, 1.5}, 1.5, 1}, {}, {}});  // continues on a, but b runs back: apart
  raw.push_back(R{{{2, 3}, 2, 3}, {}, {}});        // a gap on a: apart
  const auto joined = join_overlaps(std::move(raw), 4.0, 4.0);
  ASSERT_EQ(joined.size(), 3u);
  EXPECT_EQ(joined[0].o.a, Interval<double>(0, 1));
  EXPECT_EQ(joined[0].o.b_start, 0.0);
  EXPECT_EQ(joined[0].o.b_end, 1.0);
  EXPECT_EQ(joined[0].deferred.size(), 2u);  // the pairs of both parts go together
  EXPECT_EQ(joined[1].o.a, Interval<double>(1, 1.5));
  EXPECT_EQ(joined[2].o.a, Interval<double>(2, 3));
}

TEST(IntersectPhases, ConfirmOverlapsKeepsTheCommonStretchOfCollinearSegments) {
  // a = (0, 0) -> (2, 0) and b = (1, 0) -> (3, 0) share x in [1, 2]: a over [0.5, 1]
  // traces b from 0 to 0.5; beyond its ends the curves part (a ends, b leaves a's line
  // nowhere: a ends at 1, b starts at 0).
  Both s(pieces(B2{{0, 0}, {2, 0}}), pieces(B2{{1, 0}, {3, 0}}));
  auto pairs = meet_arcs(s.A, s.B, false, s.ctx);
  auto candidates = join_overlaps(std::move(pairs.overlaps), 1.0, 1.0);
  const auto overlaps = confirm_overlaps(s.A, s.B, candidates, s.ctx, pairs.hits);
  ASSERT_EQ(overlaps.size(), 1u);
  // The ends are located by root solves on the other arc: a few eps.
  EXPECT_NEAR(overlaps[0].a.lo, 0.5, 4 * test::eps);
  EXPECT_NEAR(overlaps[0].a.hi, 1.0, 4 * test::eps);
  EXPECT_NEAR(overlaps[0].b_start, 0.0, 4 * test::eps);
  EXPECT_NEAR(overlaps[0].b_end, 0.5, 4 * test::eps);
}

TEST(IntersectPhases, ArcPointsFindsTheRootsOfALineOnAParabola) {
  // The parabola x = 2t, y = (1 - 2t)^2 (control points (0, 1), (1, -1), (2, 1)) meets
  // the line y = 1/4 from (0, 1/4) to (2, 1/4) where 1 - 2t = +-1/2: t = 1/4 and 3/4, at
  // x = 1/2 and 3/2, the line's parameters x / 2 = 1/4 and 3/4. y turns at t = 1/2, so the
  // parabola has two monotone arcs, one root each.
  Both s(pieces(B2{{0, 1}, {1, -1}, {2, 1}}), pieces(B2{{0, 0.25}, {2, 0.25}}));
  ASSERT_EQ(s.A.arcs.size(), 2u);
  EXPECT_EQ(s.A.arcs[0].hi, 0.5);
  ASSERT_EQ(s.B.arcs.size(), 1u);
  const double want[2] = {0.25, 0.75};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto hits = arc_points(s.A, i, s.B, 0, s.ctx);
    ASSERT_GE(hits.size(), 1u) << "arc " << i;
    for (const auto& h : hits) {
      // Newton at a transversal crossing: to a few eps.
      EXPECT_NEAR(h.ta, want[i], 8 * test::eps);
      EXPECT_NEAR(h.tb, want[i], 8 * test::eps);
    }
  }
}

TEST(IntersectPhases, ArcOverlapOfCoincidentSegmentsIsTheirCommonRange) {
  // a = (0, 0) -> (4, 0) and b = (3, 0) -> (1, 0): a over [1/4, 3/4] traces b from 1 to 0
  // (b runs the other way).
  Both s(pieces(B2{{0, 0}, {4, 0}}), pieces(B2{{3, 0}, {1, 0}}));
  const auto o = arc_overlap(s.A, 0, s.B, 0, s.tol);
  ASSERT_TRUE(o.has_value());
  EXPECT_NEAR(o->s0, 0.25, 4 * test::eps);
  EXPECT_NEAR(o->s1, 0.75, 4 * test::eps);
  EXPECT_NEAR(o->t0, 1.0, 4 * test::eps);
  EXPECT_NEAR(o->t1, 0.0, 4 * test::eps);
  // Parallel segments 1e-3 apart (far beyond the near-miss distance): no overlap.
  Both t(pieces(B2{{0, 0}, {4, 0}}), pieces(B2{{3, 1e-3}, {1, 1e-3}}));
  EXPECT_FALSE(arc_overlap(t.A, 0, t.B, 0, t.tol).has_value());
}

TEST(IntersectPhases, RefineThenPolishLocatesATouchAndClassifyCallsItTangent) {
  // y = (1 - 2t)^2, x = 2t touches the x axis (0, 0) -> (2, 0) at t = 1/2, x = 1 (line
  // parameter 1/2): a double root, which refine() locates to about sqrt(eps) and
  // polish_touch() to a few eps.
  Both s(pieces(B2{{0, 1}, {1, -1}, {2, 1}}), pieces(B2{{0, 0}, {2, 0}}));
  const Arc<double> whole{0, 0.0, 1.0};
  const auto r = refine(s.A.unit[0], whole, s.B.unit[0], whole, 0.4, 0.45);
  EXPECT_NEAR(r.s, 0.5, 1e-7);
  EXPECT_NEAR(r.t, 0.5, 1e-7);
  EXPECT_LE(r.distance, s.tol);
  const auto p = polish_touch(s.A.unit[0], whole, s.B.unit[0], whole, r, s.tol);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->s, 0.5, 8 * test::eps);
  EXPECT_NEAR(p->t, 0.5, 8 * test::eps);
  // The whole pipeline's middle: the pairs' points merged into one, classified tangent.
  auto pairs = meet_arcs(s.A, s.B, false, s.ctx);
  EXPECT_TRUE(pairs.overlaps.empty());
  const auto lp = loops(s.A, s.B, s.tol);
  const auto merged = merge_points(s.A, s.B, false, std::move(pairs.hits), {}, lp, s.tol);
  const auto pts = classify(s.A, s.B, merged.kept, s.tol);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0].kind, IntersectionKind::tangent);
  EXPECT_NEAR(pts[0].ta, 0.5, 8 * test::eps);
  EXPECT_NEAR(pts[0].tb, 0.5, 8 * test::eps);
}

/// A hit of the diagonals' crossing (pieces 0, parameters 1/2), at distance 0.
Hit<double> crossing_hit() { return Hit<double>{0.5, 0.5, 0, 0, 0.5, 0.5, 0.0, false, false}; }

TEST(IntersectPhases, InOverlapUsesBothParametersWithARelativeMargin) {
  const Pc a = pieces(B2{{0, 0}, {2, 2}});
  const std::vector<CurveOverlap<double>> overlaps{{{0.25, 0.5}, 0.75, 0.5}};  // b runs backwards
  EXPECT_TRUE(in_overlap(crossing_hit(), overlaps, a, a, false));  // at its end (0.5, 0.5)
  Hit<double> h = crossing_hit();
  h.tb = 0.25;  // a inside, b outside
  EXPECT_FALSE(in_overlap(h, overlaps, a, a, false));
  // (0.6, 0.3) is outside a [0.25, 0.5] x b [0.55, 0.65]; swapped, (0.3, 0.6) is inside:
  // for a self-intersection the same stretch seen from the other side.
  h = crossing_hit();
  h.ta = 0.6;
  h.tb = 0.3;
  const std::vector<CurveOverlap<double>> o2{{{0.25, 0.5}, 0.55, 0.65}};
  EXPECT_FALSE(in_overlap(h, o2, a, a, false));
  EXPECT_TRUE(in_overlap(h, o2, a, a, true));
}

TEST(IntersectPhases, MergePointsKeepsOnePointPerCrossing) {
  Both s(pieces(B2{{0, 0}, {2, 2}}), pieces(B2{{0, 2}, {2, 0}}));
  const auto lp = loops(s.A, s.B, s.tol);
  EXPECT_FALSE(lp.a.closed);
  EXPECT_FALSE(lp.b.closed);
  // The same crossing found twice (from two pairs of arcs): one point.
  const auto merged = merge_points(s.A, s.B, false, {crossing_hit(), crossing_hit()}, {}, lp, s.tol);
  ASSERT_EQ(merged.kept.size(), 1u);
  EXPECT_EQ(merged.kept[0].ta, 0.5);
  EXPECT_TRUE(merged.edges.empty());
  // An edge point is set aside, not merged.
  Hit<double> e = crossing_hit();
  e.edge = true;
  const auto m2 = merge_points(s.A, s.B, false, {e}, {}, lp, s.tol);
  EXPECT_TRUE(m2.kept.empty());
  EXPECT_EQ(m2.edges.size(), 1u);
}

TEST(IntersectPhases, OrderHitsPutsTaFirstForSelfIntersections) {
  // (ta, tb) = (0.7, 0.2) on pieces (1, 0) and (0.1, 0.9): ordered by ta; for a
  // self-intersection the first pair is swapped, its pieces and piece parameters with it.
  const Hit<double> x{0.7, 0.2, 1, 0, 0.4, 0.2, 0.0}, y{0.1, 0.9, 0, 1, 0.1, 0.8, 0.0};
  std::vector<Hit<double>> hits{x, y};
  order_hits(hits, false);
  EXPECT_EQ(hits[0].ta, 0.1);
  EXPECT_EQ(hits[1].ta, 0.7);
  hits = {x, y};
  order_hits(hits, true);
  EXPECT_EQ(hits[0].ta, 0.1);
  EXPECT_EQ((std::array<double, 4>{hits[1].ta, hits[1].tb, hits[1].sa, hits[1].sb}), (std::array<double, 4>{0.2, 0.7, 0.2, 0.4}));
  EXPECT_EQ((std::array<std::size_t, 2>{hits[1].pa, hits[1].pb}), (std::array<std::size_t, 2>{0, 1}));
}

TEST(IntersectPhases, TrivialSelfContactsAreJointsClosingPointsAndTinyLoops) {
  // The segment (0, 0)..(1, 0): in the unit frame (e = 1) it runs to (0.5, 0), tol =
  // 0.5e-10, and the curve "between" ta and tb is (tb - ta) / 2 long (100 tol: 5e-9).
  const Both s(pieces(B2{{0, 0}, {1, 0}}), pieces(B2{{0, 0}, {1, 0}}));
  ASSERT_DOUBLE_EQ(s.tol, 0.5e-10);
  auto hit = [](double ta, double tb) { return Hit<double>{ta, tb, 0, 0, ta, tb, 0.0}; };
  EXPECT_TRUE(trivial_self_contact(s.A, hit(0.3, 0.3), s.tol));           // a joint: tb - ta <= 1e-12
  EXPECT_TRUE(trivial_self_contact(s.A, hit(0, 1), s.tol));               // the closing point
  EXPECT_TRUE(trivial_self_contact(s.A, hit(0.3, 0.3 + 5e-9), s.tol));    // a "loop" 2.5e-9 long: below 100 tol
  EXPECT_FALSE(trivial_self_contact(s.A, hit(0.3, 0.3 + 2e-8), s.tol));   // 1e-8 long: a loop
  EXPECT_FALSE(trivial_self_contact(s.A, hit(0.25, 0.75), s.tol));
}

/// The parabola y = x^2 - 1e-10 (x = 2t - 1: control points (-1, 1 - d), (0, -1 - d),
/// (1, 1 - d)) and the line y = 0 from (-1, 0) to (1, 0): they cross at x = -+1e-5
/// (t = 1/2 -+ 5e-6 on both) and stay within 1e-10 of each other between the crossings,
/// below the near-miss distance (1e-10 of the box diagonal 2 sqrt(2) in model units).
struct NearRegion : Both {
  NearRegion() : Both(pieces(B2{{-1, 1 - 1e-10}, {0, -1 - 1e-10}, {1, 1 - 1e-10}}), pieces(B2{{-1, 0}, {1, 0}})) {}
  static Hit<double> at(double t) { return Hit<double>{t, t, 0, 0, t, t, 0.0}; }
};

TEST(IntersectPhases, PointMergeTellsTheSamePointFromOneRegion) {
  NearRegion s;
  const auto lp = loops(s.A, s.B, s.tol);
  PointMerge<double> m{s.A, s.B, lp, s.tol};
  m.keep(NearRegion::at(0.5 - 5e-6));
  // 1e-7 apart: within merge_fraction (1e-6 of the pieces' length 1) in both parameters.
  EXPECT_TRUE(m.same_point(NearRegion::at(0.5 - 5e-6 + 1e-7), 0));
  // The other crossing, 1e-5 apart: not the same point, but of the same near region (the
  // curves 1e-10 apart half way); 1e-2 away, beyond 1e3 merge_fraction: neither.
  EXPECT_FALSE(m.same_point(NearRegion::at(0.5 + 5e-6), 0));
  EXPECT_TRUE(m.one_region(NearRegion::at(0.5 + 5e-6), 0));
  EXPECT_FALSE(m.one_region(NearRegion::at(0.51), 0));
  // Both crossings (tangents 2e-5 apart, beyond crossing_noise; distance 0): crossings.
  EXPECT_TRUE(m.crossing(m.kept[0]));
}

TEST(IntersectPhases, PointMergeMakesTwoCrossingsOfOneRegionOneTouchAtThePeak) {
  NearRegion s;
  const auto lp = loops(s.A, s.B, s.tol);
  PointMerge<double> m{s.A, s.B, lp, s.tol};
  m.keep(NearRegion::at(0.5 - 5e-6));
  EXPECT_TRUE(m.merge_into(NearRegion::at(0.5 + 5e-6), 0));
  ASSERT_EQ(m.kept.size(), 1u);
  // One touch where the separation peaks: x = 0, t = 1/2 on both (touch_in: regula falsi
  // on the tangents' cross product, to the resolution of the parameters about 1e-12 here).
  EXPECT_TRUE(m.kept[0].touch);
  EXPECT_NEAR(m.kept[0].ta, 0.5, 1e-9);
  EXPECT_NEAR(m.kept[0].tb, 0.5, 1e-9);
  // Its span: from one crossing to the other.
  EXPECT_EQ(m.spans[0].ta0, 0.5 - 5e-6);
  EXPECT_EQ(m.spans[0].ta1, 0.5 + 5e-6);
}

TEST(IntersectPhases, PointMergeKeepsTheMiddleOfTwinsAndTheCloserOfTwo) {
  // The diagonals' crossing seen three times, each common to rounding (distance 0): twins,
  // the middle one in ta kept.
  Both s(pieces(B2{{0, 0}, {2, 2}}), pieces(B2{{0, 2}, {2, 0}}));
  const auto lp = loops(s.A, s.B, s.tol);
  PointMerge<double> m{s.A, s.B, lp, s.tol};
  auto hit = [](double ta, double distance) { return Hit<double>{ta, 0.5, 0, 0, ta, 0.5, distance}; };
  m.keep(hit(0.5, 0));
  m.merge_same(hit(0.5 + 2e-16, 0), 0);
  m.merge_same(hit(0.5 - 2e-16, 0), 0);
  EXPECT_EQ(m.twins[0].size(), 2u);
  m.middle_twins();
  EXPECT_EQ(m.kept[0].ta, 0.5);
  // Not common to rounding (distance above 1e-3 tol): the closer one is kept, no twins.
  PointMerge<double> n{s.A, s.B, lp, s.tol};
  n.keep(hit(0.5, s.tol / 2));
  n.merge_same(hit(0.5 + 1e-12, s.tol / 4), 0);
  n.merge_same(hit(0.5 - 1e-12, s.tol / 3), 0);
  EXPECT_EQ(n.kept[0].ta, 0.5 + 1e-12);
  EXPECT_TRUE(n.twins[0].empty());
}

TEST(IntersectPhases, AdmitEdgesAddsAnEdgePointOnlyWhereNothingStandsForItsRegion) {
  Both s(pieces(B2{{0, 0}, {2, 2}}), pieces(B2{{0, 2}, {2, 0}}));
  const auto lp = loops(s.A, s.B, s.tol);
  Hit<double> e = crossing_hit();
  e.edge = true;
  std::vector<Hit<double>> kept{crossing_hit()};
  admit_edges(s.A, s.B, lp, kept, {e}, s.tol);
  EXPECT_EQ(kept.size(), 1u);  // the crossing already stands for it
  kept.clear();
  admit_edges(s.A, s.B, lp, kept, {e}, s.tol);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept[0].edge);
}

TEST(IntersectPhases, ClassifyTellsCrossingsFromTouches) {
  {
    Both s(pieces(B2{{0, 0}, {2, 2}}), pieces(B2{{0, 2}, {2, 0}}));
    const auto pts = classify(s.A, s.B, {crossing_hit()}, s.tol);
    ASSERT_EQ(pts.size(), 1u);
    EXPECT_EQ(pts[0].kind, IntersectionKind::crossing);
    EXPECT_EQ(pts[0].point, (P2{1, 1}));
  }
  {
    // y = (1 - 2t)^2 (control points (0, 1), (1, -1), (2, 1)) touches y = 0 at t = 1/2,
    // x = 1: parallel tangents there.
    Both s(pieces(B2{{0, 1}, {1, -1}, {2, 1}}), pieces(B2{{0, 0}, {2, 0}}));
    const auto pts = classify(s.A, s.B, {crossing_hit()}, s.tol);
    ASSERT_EQ(pts.size(), 1u);
    EXPECT_EQ(pts[0].kind, IntersectionKind::tangent);
    EXPECT_EQ(pts[0].point, (P2{1, 0}));
  }
}

TEST(IntersectPhases, OnceAtClosingPointListsAClosingCrossingOnce) {
  // A curve on [0, 2] in two pieces: the closing point is at 0 and at 2. The pairs (0, 1)
  // and (1, 2) are one self-intersection at the closing point; (0.5, 1.5) is another.
  const Pc c({B2{{0, 0}, {1, 0}}, B2{{1, 0}, {0, 0}}}, {0.0, 1.0, 2.0});
  const std::vector<CurveIntersection<double>> pts{
      {0, 1, {0, 0}, IntersectionKind::crossing}, {0.5, 1.5, {0, 0}, IntersectionKind::crossing}, {1, 2, {0, 0}, IntersectionKind::crossing}};
  const auto once = once_at_closing_point(c, pts);
  ASSERT_EQ(once.size(), 2u);
  EXPECT_EQ(once[0].ta, 0.0);
  EXPECT_EQ(once[1].ta, 0.5);
}

}  // namespace
