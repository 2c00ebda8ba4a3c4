// The piecewise algebra of curves/piecewise.hpp (locate, lift, lift_roots, for_each_piece,
// portion) on closed-form pieces with a domain that is not [0, 1]: breaks [-3, 0.5, 7].
// Every expected value is exact in binary (breaks and fractions are dyadic), computed by
// hand from the affine map u = u_i + t (u_(i+1) - u_i).
#include <cmath>
#include <cstddef>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;
using I = Interval<double>;

/// Two straight pieces, (0, 0) -> (1, 0) on [-3, 0.5] (length 3.5) and (1, 0) -> (1, 2)
/// on [0.5, 7] (length 6.5).
Pieces<double, 2> two_lines() {
  return Pieces<double, 2>({B2{{0, 0}, {1, 0}}, B2{{1, 0}, {1, 2}}}, {-3.0, 0.5, 7.0});
}

/// One visit of for_each_piece: the piece's index and the clipped own range.
struct Visit {
  std::size_t index;
  I own;
  friend bool operator==(const Visit&, const Visit&) = default;
};
std::ostream& operator<<(std::ostream& os, const Visit& v) { return os << v.index << ' ' << v.own; }

std::vector<Visit> visits(const Pieces<double, 2>& p, I range) {
  std::vector<Visit> out;
  p.for_each_piece(range, [&](std::size_t i, const auto&, const I& own) { out.push_back({i, own}); });
  return out;
}

TEST(PiecewiseAlgebra, LocateAndLiftOnANonUnitDomain) {
  const auto p = two_lines();
  // -1.25 = -3 + 0.5 * 3.5; 3.75 = 0.5 + 0.5 * 6.5.
  EXPECT_EQ(p.lift(0, 0.5), -1.25);
  EXPECT_EQ(p.lift(1, 0.5), 3.75);
  // The ends lift exactly onto the breaks, from both sides of the joint.
  EXPECT_EQ(p.lift(0, 0.0), -3.0);
  EXPECT_EQ(p.lift(0, 1.0), 0.5);
  EXPECT_EQ(p.lift(1, 0.0), 0.5);
  EXPECT_EQ(p.lift(1, 1.0), 7.0);
  EXPECT_EQ(p.lift(1, I(0.25, 0.5)), I(2.125, 3.75));
  const auto at = p.locate(-1.25);
  EXPECT_EQ(at.index, 0u);
  EXPECT_EQ(at.t, 0.5);
  // An interior break belongs to the right piece (as evaluation), the domain's end to the last.
  EXPECT_EQ(p.locate(0.5).index, 1u);
  EXPECT_EQ(p.locate(0.5).t, 0.0);
  EXPECT_EQ(p.locate(7.0).index, 1u);
  EXPECT_EQ(p.locate(7.0).t, 1.0);
  EXPECT_EQ(p.locate(-3.0).index, 0u);
  EXPECT_EQ(p.locate(-3.0).t, 0.0);
  // The chain rule's factor: own length 1 over break lengths 3.5 and 6.5.
  EXPECT_EQ(p.parameter_scale(0), 1 / 3.5);
  EXPECT_EQ(p.parameter_scale(1), 1 / 6.5);
}

TEST(PiecewiseAlgebra, ForEachPieceClipsARangeThatStartsAndEndsInsidePieces) {
  const auto p = two_lines();
  EXPECT_EQ(visits(p, {-1.25, 3.75}), (std::vector<Visit>{{0, {0.5, 1}}, {1, {0, 0.5}}}));
  // Inside one piece: only that piece, both ends clipped (-2.125 = -3 + 0.25 * 3.5).
  EXPECT_EQ(visits(p, {-2.125, -1.25}), (std::vector<Visit>{{0, {0.25, 0.5}}}));
  // The whole domain: every piece whole.
  EXPECT_EQ(visits(p, {-3, 7}), (std::vector<Visit>{{0, {0, 1}}, {1, {0, 1}}}));
  std::vector<Visit> all;
  p.for_each_piece([&](std::size_t i, const auto&, const I& own) { all.push_back({i, own}); });
  EXPECT_EQ(all, visits(p, {-3, 7}));
}

TEST(PiecewiseAlgebra, ForEachPieceOnBreaksVisitsOnlyPiecesOfPositiveOverlap) {
  const auto p = two_lines();
  // From a break to a break: the piece between, not the one that touches at the break.
  EXPECT_EQ(visits(p, {0.5, 7}), (std::vector<Visit>{{1, {0, 1}}}));
  EXPECT_EQ(visits(p, {-3, 0.5}), (std::vector<Visit>{{0, {0, 1}}}));
  // A range ending on a break inside: the piece after it is not visited.
  EXPECT_EQ(visits(p, {-1.25, 0.5}), (std::vector<Visit>{{0, {0.5, 1}}}));
}

TEST(PiecewiseAlgebra, ForEachPieceOnADegenerateRangeVisitsThePieceHoldingIt) {
  const auto p = two_lines();
  EXPECT_EQ(visits(p, {0.5, 0.5}), (std::vector<Visit>{{1, {0, 0}}}));  // the right piece at a break
  EXPECT_EQ(visits(p, {7, 7}), (std::vector<Visit>{{1, {1, 1}}}));      // the last at the end
  EXPECT_EQ(visits(p, {-3, -3}), (std::vector<Visit>{{0, {0, 0}}}));
  EXPECT_EQ(visits(p, {-1.25, -1.25}), (std::vector<Visit>{{0, {0.5, 0.5}}}));
  // So a query over it sees the curve's point: the box of one point, a length of 0.
  const auto b = bounds(p, 0.5, 0.5);
  EXPECT_EQ(b.lo, (P2{1, 0}));
  EXPECT_EQ(b.hi, (P2{1, 0}));
  EXPECT_EQ(arc_length(p, 0.5, 0.5), 0.0);
}

TEST(PiecewiseAlgebra, ForEachPieceStopsWhenTheKernelSaysSo) {
  const auto p = two_lines();
  int calls = 0;
  p.for_each_piece(I(-3, 7), [&](std::size_t, const auto&, const I&) { return ++calls < 1; });
  EXPECT_EQ(calls, 1);
  calls = 0;
  p.for_each_piece([&](std::size_t, const auto&, const I&) { return ++calls < 1; });
  EXPECT_EQ(calls, 1);
}

TEST(PiecewiseAlgebra, QueriesOverAClippedRangeMatchClosedForms) {
  const auto p = two_lines();
  // From (0.5, 0) (a's half way) to (1, 1) (b's half way): straight pieces, so the box is
  // the ends' and the length the sum of the straight parts 0.5 + 1.
  const auto b = bounds(p, -1.25, 3.75);
  EXPECT_EQ(b.lo, (P2{0.5, 0}));
  EXPECT_EQ(b.hi, (P2{1, 1}));
  // 4 eps: the quadrature of a constant speed, rounded per piece.
  EXPECT_NEAR(arc_length(p, -1.25, 3.75), 1.5, 4 * test::eps);
}

TEST(PiecewiseAlgebra, LiftRootsKeepsAJointDuplicateOnce) {
  const auto p = two_lines();
  std::vector<double> out;
  // Piece 0 has a root at its end, piece 1 at its start: the same break 0.5, kept once.
  p.lift_roots(0, std::vector<double>{0.5, 1.0}, out);
  p.lift_roots(1, std::vector<double>{0.0, 0.5}, out);
  EXPECT_EQ(out, (std::vector<double>{-1.25, 0.5, 3.75}));
  // Only one side has it: kept.
  out.clear();
  p.lift_roots(0, std::vector<double>{0.5}, out);
  p.lift_roots(1, std::vector<double>{0.0}, out);
  EXPECT_EQ(out, (std::vector<double>{-1.25, 0.5}));
  out.clear();
  p.lift_roots(0, std::vector<double>{1.0}, out);
  p.lift_roots(1, std::vector<double>{0.5}, out);
  EXPECT_EQ(out, (std::vector<double>{0.5, 3.75}));
  // A root at the domain's start (piece 0, nothing before) and equal roots inside a
  // piece (a kernel's double root) are all kept.
  out.clear();
  p.lift_roots(0, std::vector<double>{0.0, 0.5, 0.5}, out);
  EXPECT_EQ(out, (std::vector<double>{-3.0, -1.25, -1.25}));
}

// At a jump the end of the piece before it lifts to the double below the break, where
// evaluation takes that piece: its point there is the left limit to rounding. Where the
// pieces meet (to rounding: 64 eps of their control coordinates) the break stays.
TEST(PiecewiseAlgebra, LiftAtAJumpStaysOnThePiece) {
  const Pieces<double, 2> p({B2{{0, 0}, {1, 0}}, B2{{1, 1}, {1, 2}}, B2{{1, 2 + 1e-15}, {3, 2}}}, {-3.0, 0.5, 7.0, 8.0});
  EXPECT_TRUE(p.jumps_after(0));
  EXPECT_FALSE(p.jumps_after(1));  // 1e-15 apart: rounding
  EXPECT_FALSE(p.jumps_after(2));  // the last piece
  const double below = std::nextafter(0.5, -1.0);
  EXPECT_EQ(p.end_parameter(0), below);
  EXPECT_EQ(p.end_parameter(1), 7.0);
  EXPECT_EQ(p.end_parameter(2), 8.0);
  EXPECT_EQ(p.lift(0, 1.0), below);
  EXPECT_EQ(p.lift(1, 0.0), 0.5);
  EXPECT_EQ(p.lift(1, 1.0), 7.0);
  EXPECT_EQ(p.locate(below).index, 0u);
  EXPECT_LE(distance(p(below), P2(1, 0)), 2 * test::eps);
  EXPECT_EQ(p(0.5), P2(1, 1));
  // Both limits are roots of their pieces: two points of the curve, both kept.
  std::vector<double> out;
  p.lift_roots(0, std::vector<double>{1.0}, out);
  p.lift_roots(1, std::vector<double>{0.0}, out);
  EXPECT_EQ(out, (std::vector<double>{below, 0.5}));
  // One-point pieces (degree 0): a jump where the points differ, none where they agree.
  const Pieces<double, 2> steps({B2{{0, 0}}, B2{{0, 0}}, B2{{1, 0}}}, {0.0, 1.0, 2.0, 3.0});
  EXPECT_FALSE(steps.jumps_after(0));
  EXPECT_TRUE(steps.jumps_after(1));
  EXPECT_EQ(steps.lift(1, I(0, 1)), I(1, std::nextafter(2.0, 0.0)));
}

TEST(PiecewiseAlgebra, PortionKeepsTheParametrisation) {
  const auto p = two_lines();
  const auto q = p.portion({-1.25, 3.75});
  EXPECT_EQ(q.breaks(), (std::vector<double>{-1.25, 0.5, 3.75}));
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(std::get<B2>(q.segments()[0]).points(), (std::vector<P2>{{0.5, 0}, {1, 0}}));
  EXPECT_EQ(std::get<B2>(q.segments()[1]).points(), (std::vector<P2>{{1, 0}, {1, 1}}));
  // Same points at the same parameters (straight pieces: linear in u, exact at dyadic u).
  for (double u : {-1.25, -0.375, 0.5, 2.125, 3.75}) EXPECT_EQ(q(u), p(u)) << u;
  // Inside one piece; a range from break to break copies the piece.
  const auto r = p.portion({-2.125, -1.25});
  EXPECT_EQ(r.breaks(), (std::vector<double>{-2.125, -1.25}));
  EXPECT_EQ(std::get<B2>(r.segments()[0]).points(), (std::vector<P2>{{0.25, 0}, {0.5, 0}}));
  EXPECT_EQ(p.portion({0.5, 7}).segments()[0], p.segments()[1]);
  EXPECT_EQ(p.portion({-3, 7}), p);
  // A degenerate or reversed range, or one outside the domain, has no portion.
  EXPECT_INVALID_ARGUMENT(p.portion({0.5, 0.5}), "range", "from < to");
  EXPECT_INVALID_ARGUMENT(p.portion({-4, 0}), "range", "within the domain");
}

}  // namespace
