// Nurbs::from_pieces: rational (and mixed polynomial / rational) Bézier pieces back to a
// NURBS, against the curves the pieces came from (exact decompositions, so the round trip
// is the same curve up to rounding), the NURBS circle against the unit circle, knot
// removal restoring the original knots, weight chains beyond the range of double, and
// the input rules.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using casteljau::test::max_distance;
using P2 = Point<double, 2>;
using N2 = Nurbs<double, 2>;

/// max |a(u) - b(u)| at 2001 parameters of [lo, hi].
void expect_positive_weights(const N2& c) {
  for (const double w : c.weights()) EXPECT_GT(w, 0);
}

/// A seeded NURBS of degree p: n points in [-1, 1]^2, weights in [0.2, 5], clamped knots
/// on [0, 1] with the interior ones simple or, every third, repeated up to p - 1 times.
N2 random_nurbs(int p, int n, std::uint64_t seed) {
  test::SplitMix64 rng(seed);
  std::vector<P2> P(static_cast<std::size_t>(n));
  std::vector<double> w(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    P[i] = P2{{rng.uniform(-1, 1), rng.uniform(-1, 1)}};
    w[i] = std::exp(rng.uniform(std::log(0.2), std::log(5.0)));
  }
  std::vector<double> U(static_cast<std::size_t>(p) + 1, 0.0);
  double u = 0;
  int k = 0;
  while (U.size() < static_cast<std::size_t>(n)) {
    u += rng.uniform(0.2, 1.0);
    const int m = (++k % 3 == 0) ? std::min(p - 1, n - static_cast<int>(U.size())) : 1;
    for (int j = 0; j < std::max(m, 1); ++j) U.push_back(u);
  }
  u += rng.uniform(0.2, 1.0);
  for (auto& x : U) x /= u;
  U.insert(U.end(), static_cast<std::size_t>(p) + 1, 1.0);
  return N2(p, U, P, w);
}

// The nine-point circle [PT97, Ex. 7.2] through its pieces and back: the same curve to
// 1e-14 at 2001 parameters, still at radius 1 to 1e-14, weights positive.
TEST(NurbsFromPieces, CircleRoundTrip) {
  const N2 c = nurbs_circle(P2{{0.0, 0.0}}, 1.0);
  const N2 d = N2::from_pieces(pieces(c));
  EXPECT_EQ(d.degree(), 2);
  EXPECT_LE(max_distance(c, d, 0, 1, 2000), 1e-14);
  for (int i = 0; i <= 2000; ++i) {
    const P2 q = d(i / 2000.0);
    EXPECT_NEAR(std::hypot(q[0], q[1]), 1.0, 1e-14) << i;
  }
  expect_positive_weights(d);
  // The circle's knots are already double at the quarters (C^0 joins in the homogeneous
  // sense as well): joining its 4 pieces gives the same knots back.
  EXPECT_EQ(d.knots(), c.knots());
}

// Random NURBS of degree 1..5 with repeated knots, through pieces and back: the same curve
// to 1e-14 (coordinates of size 1; each side is a few convex combinations).
TEST(NurbsFromPieces, RandomRoundTrip) {
  for (int p = 1; p <= 5; ++p) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const N2 c = random_nurbs(p, 9 + p, 1000 * static_cast<std::uint64_t>(p) + seed);
      const Pieces<double, 2> pc = pieces(c);
      const N2 d = N2::from_pieces(pc);
      EXPECT_LE(max_distance(c, d, 0, 1, 2000), 1e-14) << "p=" << p << " seed=" << seed;
      // Also the derivative, which sees the weights' joins (homogeneous continuity).
      for (const double u : {0.1, 0.37, 0.5, 0.93}) {
        const auto a = c.derivative_at(u), b = d.derivative_at(u);
        EXPECT_LE(norm(a - b), 1e-11 * std::max(1.0, norm(a))) << "p=" << p << " u=" << u;
      }
      expect_positive_weights(d);
      // C^0 form: every interior break p times.
      for (std::size_t i = 1; i + 1 < pc.breaks().size(); ++i) EXPECT_EQ(knot_multiplicity<double>(d.knots(), pc.breaks()[i]), static_cast<std::size_t>(p));
    }
  }
}

// With a removal tolerance the interior breaks are removed as far as the curve allows: a
// NURBS with simple knots comes back with its own knots (its pieces are C^(p-1) at every
// break in the homogeneous form), the same curve to 1e-12.
TEST(NurbsFromPieces, KnotRemovalRestoresContinuity) {
  for (int p = 2; p <= 4; ++p) {
    test::SplitMix64 rng(77 + static_cast<std::uint64_t>(p));
    std::vector<P2> P(8);
    std::vector<double> w(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
      P[i] = P2{{rng.uniform(-1, 1), rng.uniform(-1, 1)}};
      w[i] = rng.uniform(0.5, 2.0);
    }
    std::vector<double> U(static_cast<std::size_t>(p) + 1, 0.0);
    for (std::size_t j = 1; U.size() < P.size(); ++j) U.push_back(static_cast<double>(j) / static_cast<double>(P.size() - p));
    U.insert(U.end(), static_cast<std::size_t>(p) + 1, 1.0);
    const N2 c(p, U, P, w);
    const N2 joined = N2::from_pieces(pieces(c));
    EXPECT_GT(joined.points().size(), c.points().size());
    const N2 d = N2::from_pieces(pieces(c), 1e-12);
    ASSERT_EQ(d.knots().size(), c.knots().size()) << "p=" << p;
    for (std::size_t i = 0; i < U.size(); ++i) EXPECT_NEAR(d.knots()[i], U[i], 1e-15);
    EXPECT_LE(max_distance(c, d, 0, 1, 2000), 1e-12) << "p=" << p;
    // The weights come back up to one common factor (a NURBS does not change when all its
    // weights are scaled).
    const double f = d.weights()[0] / w[0];
    for (std::size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(d.weights()[i] / f, w[i], 1e-12 * w[i]) << i;
  }
  // A real corner (two arcs meeting at an angle) keeps its knot: nothing to remove.
  const std::vector<BezierPiece<double, 2>> corner{RationalBezier<double, 2>::circular_arc(P2{{0.0, 0.0}}, 1.0, 0.0, 1.0),
                                                   Bezier<double, 2>({P2{{std::cos(1.0), std::sin(1.0)}}, P2{{0.0, 2.0}}})};
  const N2 k = N2::from_pieces(corner, {0.0, 1.0, 2.0}, 1e-9);
  EXPECT_EQ(knot_multiplicity<double>(k.knots(), 1.0), 2U);
}

// A path of a line, a circular arc and a cubic: polynomial pieces get weight 1, elevated
// to the highest degree (3), and the NURBS traces the path.
TEST(NurbsFromPieces, MixedPieces) {
  const P2 a{{1.0, 0.0}};
  const auto arc = RationalBezier<double, 2>::circular_arc(P2{{0.0, 0.0}}, 1.0, 0.0, 1.2);
  const P2 e = arc.points().back();
  const std::vector<BezierPiece<double, 2>> segs{
      Bezier<double, 2>({P2{{1.0, -1.0}}, a}),
      arc,
      Bezier<double, 2>({e, P2{{e[0] - 0.5, e[1] + 0.2}}, P2{{-1.0, 1.5}}, P2{{-1.5, 0.5}}}),
  };
  const Pieces<double, 2> pc(segs, {0.0, 0.5, 2.0, 2.5});
  const N2 d = N2::from_pieces(pc);
  EXPECT_EQ(d.degree(), 3);
  EXPECT_EQ(d.domain().lo, 0.0);
  EXPECT_EQ(d.domain().hi, 2.5);
  EXPECT_LE(max_distance(pc, d, 0, 2.5, 2000), 1e-14);
  // The arc's points stay on the unit circle.
  for (int i = 0; i <= 100; ++i) {
    const P2 q = d(0.5 + 1.5 * i / 100.0);
    EXPECT_NEAR(std::hypot(q[0], q[1]), 1.0, 1e-14) << i;
  }
  expect_positive_weights(d);
}

// Each piece scales the next one's weights by 4 (weights 1, 2, 4 on every piece): after
// 400 pieces the chained factor is 4^400 = 2^800, within the range of double once the
// weights are normalised; after 600 the weights would span 2^1200 and are refused, not
// turned into zeros or infinities.
TEST(NurbsFromPieces, WeightChainsBeyondTheRange) {
  const auto chain = [](int count) {
    std::vector<RationalBezier<double, 2>> segs;
    std::vector<double> breaks{0.0};
    for (int i = 0; i < count; ++i) {
      const double x = i;
      segs.emplace_back(std::vector<P2>{P2{{x, 0.0}}, P2{{x + 0.5, 1.0}}, P2{{x + 1, 0.0}}}, std::vector<double>{1.0, 2.0, 4.0});
      breaks.push_back(i + 1.0);
    }
    return std::pair{segs, breaks};
  };
  {
    const auto [segs, breaks] = chain(400);
    const N2 d = N2::from_pieces(segs, breaks);
    expect_positive_weights(d);
    double worst = 0;
    for (std::size_t i = 0; i < segs.size(); i += 7) {
      for (const double t : {0.0, 0.3, 0.8}) worst = std::max(worst, distance(d(breaks[i] + t), segs[i](t)));
    }
    // Coordinates up to 400: a few eps relative (measured 1.7e-13).
    EXPECT_LE(worst, 1e-15 * 400);
  }
  const auto [segs, breaks] = chain(600);
  try {
    (void)N2::from_pieces(segs, breaks);
    ADD_FAILURE() << "weights spanning 2^1200 were accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.where(), "pieces");
  }
}

TEST(NurbsFromPieces, BadInput) {
  const auto arc = RationalBezier<double, 2>::circular_arc(P2{{0.0, 0.0}}, 1.0, 0.0, 1.0);
  const auto where = [](auto&& f) {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return e.where();
    }
    return std::string("no error");
  };
  EXPECT_EQ(where([&] { (void)N2::from_pieces(std::vector<RationalBezier<double, 2>>{}, {0.0}); }), "pieces");
  EXPECT_EQ(where([&] { (void)N2::from_pieces(std::vector{arc}, {0.0}); }), "breaks");
  EXPECT_EQ(where([&] { (void)N2::from_pieces(std::vector{arc, arc}, {0.0, 1.0, 1.0}); }), "breaks[2]");
  EXPECT_EQ(where([&] { (void)N2::from_pieces(std::vector{arc}, {NAN, 1.0}); }), "breaks[0]");
  EXPECT_EQ(where([&] { (void)N2::from_pieces(std::vector{arc}, {0.0, INFINITY}); }), "breaks[1]");
  EXPECT_EQ(where([&] { (void)N2::from_pieces(std::vector{arc, arc}, {0.0, 1.0, 2.0}, 0.0); }), "tolerance");
}

}  // namespace
