// KnotVector (basis/knot_vector.hpp): every validation error, the generators against
// hand-computed vectors [PT97], span search, and degree reduction of B-splines and NURBS
// (BSpline::reduce_degree, Nurbs::reduce_degree [PT97, A5.11]) against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using KV = KnotVector<double>;
using P2 = Point<double, 2>;
using P3 = Point<double, 3>;
using Knots = std::vector<double>;

// -- Validation: the contract's knot rules, with the field and the rule in the message.

TEST(KnotVector, EveryRuleHasItsMessage) {
  EXPECT_INVALID_ARGUMENT(KV(-1, Knots{0, 1}), "degree", "degree >= 0");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, 0, 1, 1}), "knots", "needs at least 6 knots");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, 0, 1, 0.5, 2, 2, 2}), "knots[4]", "non-decreasing");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, 0, 1, 1, 1, 1, 2, 2, 2}), "knots[6]", "an interior knot may be repeated at most 3 times");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, 0, 0, 1, 2, 2, 2}), "knots[3]", "an end knot may be repeated at most 3 times");
  // Degree 0: "at most once", not "at most 1 times" (issue 15).
  EXPECT_INVALID_ARGUMENT(KV(0, Knots{0, 0.5, 0.5, 1}), "knots[2]", "an interior knot may be repeated at most once (p + 1) for degree 0");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, std::nan(""), 1, 1, 1}), "knots[2]", "finite");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, std::numeric_limits<double>::infinity(), 1, 1, 1}), "knots[2]", "finite");
  // U_2 = U_3 = 1: a knot vector whose every multiplicity is allowed but whose domain is empty.
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{-1, 0, 1, 1, 2, 3}), "knots", "is empty");
  EXPECT_INVALID_ARGUMENT(KV(1, Knots{-1e308, -1e308, 1e308, 1e308}), "knots", "longer than the largest double");
  // With a point count: the count rules first, as the curve constructors check them.
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, 0, 1, 1, 1}, 2), "points", "at least 3 control points");
  EXPECT_INVALID_ARGUMENT(KV(2, Knots{0, 0, 0, 1, 1, 1}, 4), "knots", "len(points) + degree + 1 = 7");
  EXPECT_NO_THROW(KV(2, Knots{0, 0, 0, 1, 1, 1}, 3));
}

// The curve constructors report the same messages (one place: check_knot_count, check_knots).
TEST(KnotVector, CurvesReportTheSameErrors) {
  const std::vector<P2> P(4);
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(2, Knots{0, 0, 0, 1, 1, 1}, P)), "knots", "len(points) + degree + 1 = 7");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(KV(2, Knots{0, 0, 0, 1, 1, 1}), P)), "knots", "len(points) + degree + 1 = 7");
  EXPECT_INVALID_ARGUMENT((BSpline<double, 2>(3, Knots{0, 0, 0, 0, 1, 1, 1, 1}, std::vector<P2>(2))), "points", "at least 4");
  EXPECT_INVALID_ARGUMENT((Nurbs<double, 2>(KV(3, Knots{0, 0, 0, 0, 1, 1, 1, 1}), P, {1, 1, -1, 1})), "weights[2]", "> 0");
}

// -- Accessors.

TEST(KnotVector, DomainDistinctKnotsAndMultiplicities) {
  // [PT97, Ex. 2.3]'s knots.
  const KV U(2, Knots{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5});
  EXPECT_EQ(U.degree(), 2);
  EXPECT_EQ(U.points(), 8u);
  EXPECT_EQ(U.domain(), (Interval<double>{0, 5}));
  EXPECT_TRUE(U.is_clamped());
  EXPECT_EQ(U.distinct(), (std::vector<KnotRun<double>>{{0, 3}, {1, 1}, {2, 1}, {3, 1}, {4, 2}, {5, 3}}));
  EXPECT_EQ(U.multiplicity(4), 2u);
  EXPECT_EQ(U.multiplicity(5), 3u);
  EXPECT_EQ(U.multiplicity(2.5), 0u);
  EXPECT_EQ(U.first_span(), 2u);
  EXPECT_EQ(U.last_span(), 7u);
  EXPECT_FALSE(KV(2, Knots{-2, -1, 0, 1, 2, 3}).is_clamped());
}

// -- Generators, against vectors computed by hand.

TEST(KnotVector, UniformAndClampedUniform) {
  // n = 5, p = 2 on [0, 3]: spacing 3 / (5 - 2) = 1, U_j = j - 2.
  EXPECT_EQ(KV::uniform(5, 2, 0, 3).knots(), (Knots{-2, -1, 0, 1, 2, 3, 4, 5}));
  // n = 4, p = 3 on [0, 1]: one span, spacing 1; the domain ends exact.
  EXPECT_EQ(KV::uniform(4, 3).knots(), (Knots{-3, -2, -1, 0, 1, 2, 3, 4}));
  // n = 7, p = 2 on [0, 5]: ends thrice, interior 1..4.
  EXPECT_EQ(KV::clamped_uniform(7, 2, 0, 5).knots(), (Knots{0, 0, 0, 1, 2, 3, 4, 5, 5, 5}));
  // n = 6, p = 3 on [0, 1]: interior 1/3, 2/3 (the doubles nearest them).
  EXPECT_EQ(KV::clamped_uniform(6, 3).knots(), (Knots{0, 0, 0, 0, 1.0 / 3, 2.0 / 3, 1, 1, 1, 1}));
  // n = p + 1: the Bézier knots.
  EXPECT_EQ(KV::clamped_uniform(3, 2, -1, 2).knots(), (Knots{-1, -1, -1, 2, 2, 2}));
  EXPECT_INVALID_ARGUMENT(KV::uniform(2, 2), "points", "at least 3 control points");
  EXPECT_INVALID_ARGUMENT(KV::clamped_uniform(4, -1), "degree", "degree >= 0");
  EXPECT_EQ(KV::clamped_uniform(4, 0).knots(), (Knots{0, 0.25, 0.5, 0.75, 1}));  // degree 0: every knot once
  EXPECT_INVALID_ARGUMENT(KV::clamped_uniform(4, 2, 1, 1), "domain", "a < b");
  EXPECT_INVALID_ARGUMENT(KV::uniform(4, 2, 0, std::nan("")), "domain.hi", "finite");
}

TEST(KnotVector, Periodic) {
  // L = 4 equally spaced breaks, p = 3: U_j = (j - 3) / 4, j = 0..10, domain [0, 1].
  const KV u = KV::periodic_uniform(4, 3);
  EXPECT_EQ(u.knots(), (Knots{-0.75, -0.5, -0.25, 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75}));
  EXPECT_EQ(u.points(), 7u);
  EXPECT_EQ(u.domain(), (Interval<double>{0, 1}));
  // The subdivision limit's convention: breaks p .. p + L - 1 give the integers 0..L + 2p.
  EXPECT_EQ(KV::periodic_uniform(5, 2, 2, 7).knots(), (Knots{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  // Uneven breaks {0, 0.1, 0.5}, period 1, p = 2: U_j = breaks[(j - 2) mod 3] + floor((j - 2) / 3).
  const Knots b{0, 0.1, 0.5};
  const KV v = KV::periodic(2, b, 1.0);
  const Knots expected{-0.9, -0.5, 0, 0.1, 0.5, 1, 1.1, 1.5};
  ASSERT_EQ(v.size(), expected.size());
  for (std::size_t j = 0; j < expected.size(); ++j) EXPECT_DOUBLE_EQ(v[j], expected[j]) << j;  // x + 1, x - 1 round
  EXPECT_INVALID_ARGUMENT(KV::periodic(2, Knots{0}, 1.0), "breaks", "at least 2");
  EXPECT_INVALID_ARGUMENT(KV::periodic(2, Knots{0, 0.5, 0.5}, 1.0), "breaks[2]", "strictly increasing");
  EXPECT_INVALID_ARGUMENT(KV::periodic(2, Knots{0, 0.5, 1}, 1.0), "period", "within one period");
}

// The curve on periodic knots with its points wrapped closes with C^(p-1): the
// derivatives of orders 0..p-1 agree at the two ends of the domain.
TEST(KnotVector, PeriodicCurvesClose) {
  test::SplitMix64 rng(7);
  for (int p = 1; p <= 5; ++p) {
    const Knots b{0, 0.07, 0.3, 0.34, 0.6, 0.9};
    const KV U = KV::periodic(p, b, 1.0);
    const auto P = test::random_points<double, 3>(rng, static_cast<int>(b.size()) - 1);
    std::vector<P3> Q;
    for (std::size_t i = 0; i < U.points(); ++i) Q.push_back(P[i % P.size()]);
    const BSpline<double, 3> c(U, Q);
    EXPECT_LT(distance(c(0), c(1)), 1e-14);
    for (int k = 1; k < p; ++k) {
      // Derivatives grow like 1 / (shortest span)^k: relative tolerance.
      const auto d0 = c.derivative_at(0, k), d1 = c.derivative_at(1, k);
      EXPECT_LT(norm(d0 - d1), 1e-11 * (1 + norm(d0))) << "p = " << p << ", k = " << k;
    }
  }
}

// [PT97, Ex. 9.1]: parameters {0, 5/17, 9/17, 14/17, 1} (chord length), p = 3: one interior
// knot (5 + 9 + 14) / (17 * 3) = 28/51. For p = 2 the averages of pairs: 7/17 and 23/34.
TEST(KnotVector, AveragingNurbsBookExample9_1) {
  const Knots t{0, 5.0 / 17, 9.0 / 17, 14.0 / 17, 1};
  const KV U3 = KV::averaging(3, t);
  ASSERT_EQ(U3.size(), 9u);
  for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(U3[j], 0);
  EXPECT_NEAR(U3[4], 28.0 / 51, 4e-16);  // rounded terms, sum and quotient: a few ulps of 0.55
  for (std::size_t j = 5; j < 9; ++j) EXPECT_EQ(U3[j], 1);
  const KV U2 = KV::averaging(2, t);
  ASSERT_EQ(U2.size(), 8u);
  EXPECT_NEAR(U2[3], 7.0 / 17, 4e-16);
  EXPECT_NEAR(U2[4], 23.0 / 34, 4e-16);
  // An end value repeated (an end derivative, [PT97, §9.2.2]): one more control point.
  EXPECT_EQ(KV::averaging(2, Knots{0, 0, 0.5, 1}).knots(), (Knots{0, 0, 0, 0.25, 1, 1, 1}));
  EXPECT_INVALID_ARGUMENT(KV::averaging(3, Knots{0, 0.5, 1}), "parameters", "at least 4");
  EXPECT_INVALID_ARGUMENT(KV::averaging(1, Knots{0, 0.5, 0.2, 1}), "parameters[2]", "non-decreasing");
  EXPECT_INVALID_ARGUMENT(KV::averaging(1, Knots{1, 1}), "parameters", "all be equal");
}

// -- Span search.

// At every knot, between knots and outside the domain, with repeated knots and unclamped
// ends: the binary search of KnotVector agrees with find_span, and every hint gives the
// same answer.
TEST(KnotVector, SpanSearchAndHints) {
  const std::vector<KV> cases{KV(2, Knots{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}), KV(3, Knots{-3, -2, -1, 0, 0, 0, 1, 2, 2, 3, 4, 5}),
                              KV(2, Knots{0, 1, 1, 2, 3, 3, 4, 5}), KV::clamped_uniform(40, 3)};
  for (const KV& U : cases) {
    Knots us{-10, 1e9};
    for (std::size_t i = 0; i < U.size(); ++i) {
      us.push_back(U[i]);
      us.push_back(std::nextafter(U[i], -1e300));
      us.push_back(std::nextafter(U[i], 1e300));
      if (i + 1 < U.size()) us.push_back(U[i] / 2 + U[i + 1] / 2);
    }
    for (const double u : us) {
      const std::size_t s = U.find_span(u);
      EXPECT_EQ(s, find_span(U.span(), U.degree(), u)) << u;
      for (std::size_t hint = 0; hint < U.size() + 3; ++hint) EXPECT_EQ(U.find_span(u, hint), s) << u << " from " << hint;
    }
  }
  // The rule itself on [PT97, Ex. 2.3]'s knots: the right limit at 4 (a double knot), the
  // last non-empty span at the end 5.
  const KV U = cases[0];
  EXPECT_EQ(U.find_span(4.0), 7u);
  EXPECT_EQ(U.find_span(5.0), 7u);
  EXPECT_EQ(U.find_span(3.999), 5u);
  EXPECT_EQ(U.find_span(0.0), 2u);
}

// -- Curves on knot vectors.

TEST(KnotVector, CurvesKeepTheirKnotVector) {
  const KV U = KV::clamped_uniform(5, 2);
  const std::vector<P2> P{{0, 0}, {1, 2}, {2, 0}, {3, 2}, {4, 0}};
  const BSpline<double, 2> a(U, P), b(2, U.knots(), P);
  EXPECT_EQ(a, b);
  EXPECT_EQ(&a.knot_vector().knots(), &a.knots());  // a reference to the stored knots: no copy
  EXPECT_EQ(a.knot_vector(), U);
  const Nurbs<double, 2> n(U, P, {1, 2, 1, 2, 1});
  EXPECT_EQ(n.knot_vector(), U);
  EXPECT_EQ(n, (Nurbs<double, 2>(2, U.knots(), P, {1, 2, 1, 2, 1})));
}

// Batch evaluation with hinted spans gives c(u) bit for bit, sorted or not, inside the
// domain, at its knots and outside it; evaluate_pieces uses it for NURBS.
TEST(KnotVector, BatchEvaluationMatchesPointwise) {
  test::SplitMix64 rng(3);
  const Knots U{-0.2, -0.1, 0, 0.25, 0.25, 0.5, 0.6, 0.9, 1, 1.2, 1.3};  // p = 3, unclamped
  const auto P = test::random_points<double, 2>(rng, 6);
  const BSpline<double, 2> c(3, U, P);
  std::vector<double> w;
  for (int i = 0; i < 7; ++i) w.push_back(rng.uniform(0.5, 2));
  const Nurbs<double, 2> n(3, U, P, w);
  Knots ts(U);
  for (int i = 0; i < 500; ++i) ts.push_back(rng.uniform(-0.5, 1.5));
  for (const bool sorted : {false, true}) {
    if (sorted) std::sort(ts.begin(), ts.end());
    std::vector<P2> a(ts.size()), b(ts.size());
    c.evaluate(ts, a);
    for (std::size_t j = 0; j < ts.size(); ++j) EXPECT_EQ(a[j], c(ts[j])) << ts[j];
    // The NURBS inside its domain (beyond it the weight function may vanish).
    Knots inside;
    for (const double u : ts)
      if (n.domain().contains(u)) inside.push_back(u);
    n.evaluate(inside, std::span<P2>(b.data(), inside.size()));
    for (std::size_t j = 0; j < inside.size(); ++j) EXPECT_EQ(b[j], n(inside[j])) << inside[j];
    std::vector<P2> e(inside.size());
    evaluate_pieces(n, std::span<const double>(inside), std::span<P2>(e));
    EXPECT_TRUE(std::equal(e.begin(), e.end(), b.begin()));
  }
  std::vector<P2> small(2);
  EXPECT_INVALID_ARGUMENT(c.evaluate(ts, small), "out", "one point per parameter");
  const Knots bad{0.5, std::nan("")};
  EXPECT_INVALID_ARGUMENT(c.evaluate(bad, small), "t[1]", "finite");
  EXPECT_INVALID_ARGUMENT(n.evaluate(bad, small), "t[1]", "finite");
}

// -- Degree reduction.

// One cubic Bézier piece (0,0), (1,2), (3,2), (4,0) [PT97, eq. 5.41-5.44 by hand]: Q_0 =
// P_0, Q_2 = P_3, Q_1 = the mean of P_1 + (P_1 - P_0) / 2 = (1.5, 3) and P_2 + (P_2 -
// P_3) / 2 = (2.5, 3), so (2, 3). Elevated back: (0,0), (4/3, 2), (8/3, 2), (4,0): the
// bound is 1/3. The true difference is x = t (1 - t)(2t - 1), y = 0, whose largest
// magnitude is sqrt(3) / 18 at t = (3 -+ sqrt 3) / 6: the bound is 2 sqrt 3 = 3.46 times it.
TEST(DegreeReduction, OneCubicPieceByHand) {
  const std::vector<P2> P{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const BSpline<double, 2> c(3, {0, 0, 0, 0, 1, 1, 1, 1}, P);
  const auto r = c.reduce_degree(1.0);
  EXPECT_EQ(r.curve.degree(), 2);
  EXPECT_EQ(r.curve.knots(), (Knots{0, 0, 0, 1, 1, 1}));
  const std::vector<P2> expected{{0, 0}, {2, 3}, {4, 0}};
  ASSERT_EQ(r.curve.points().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_LT(distance(r.curve.points()[i], expected[i]), 1e-15);  // 1/3, 2/3 rounded
  EXPECT_NEAR(r.error_bound, 1.0 / 3, 1e-15);
  EXPECT_EQ(r.kept_knots, 0);
  double worst = 0;
  for (int i = 0; i <= 100000; ++i) worst = std::max(worst, distance(c(i / 1e5), r.curve(i / 1e5)));
  EXPECT_NEAR(worst, std::sqrt(3.0) / 18, 1e-9);  // sampling 1e-5 from the maximum: error O(1e-10)
  EXPECT_LE(worst, r.error_bound);
  // A tolerance below the bound is refused, naming the tolerance.
  EXPECT_INVALID_ARGUMENT(c.reduce_degree(0.3), "tolerance", "moves the curve by up to");
}

// An elevated curve comes back: the same degree, knots and points (to 1e-12), error ~ 0.
TEST(DegreeReduction, ElevatedCurvesComeBack) {
  test::SplitMix64 rng(11);
  const Knots U{0, 0, 0, 0, 0.3, 0.5, 0.5, 0.8, 1, 1, 1, 1};  // p = 3, a double knot
  const auto P = test::random_points<double, 3>(rng, 7);
  const BSpline<double, 3> c(3, U, P);
  for (int r = 1; r <= 2; ++r) {
    BSpline<double, 3> e = c.elevate(r);
    for (int k = 0; k < r; ++k) {
      const auto red = e.reduce_degree(1e-9);
      EXPECT_LT(red.error_bound, 1e-12);
      EXPECT_EQ(red.kept_knots, 0);
      e = red.curve;
    }
    EXPECT_EQ(e.knots(), U);
    ASSERT_EQ(e.points().size(), P.size());
    for (std::size_t i = 0; i < P.size(); ++i) EXPECT_LT(distance(e.points()[i], P[i]), 1e-12) << "r = " << r << ", i = " << i;
  }
  // NURBS, through the homogeneous form: the same curve back, weights up to one factor.
  const std::vector<double> w{1, 0.5, 2, 1, 3, 0.7, 1, 1.5};
  const Nurbs<double, 3> n(3, U, P, w);
  const auto red = n.elevate(1).reduce_degree(1e-9);
  EXPECT_LT(red.error_bound, 1e-12);
  EXPECT_EQ(red.curve.degree(), 3);
  EXPECT_EQ(red.curve.knots(), U);
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_LT(distance(red.curve.points()[i], P[i]), 1e-12);
    EXPECT_NEAR(red.curve.weights()[i] / red.curve.weights()[0], w[i] / w[0], 1e-12);
  }
}

// A true cubic B-spline (random points, uneven knots, a double knot) reduced to degree 2:
// the reported bound is at least the largest deviation found by dense sampling, and not
// absurdly larger; the ends stay where they were; a smaller tolerance is refused.
TEST(DegreeReduction, CubicToQuadraticBoundHolds) {
  test::SplitMix64 rng(5);
  const Knots U{0, 0, 0, 0, 0.2, 0.45, 0.5, 0.5, 0.9, 1, 1, 1, 1};
  const auto P = test::random_points<double, 2>(rng, 8);
  const BSpline<double, 2> c(3, U, P);
  const auto r = c.reduce_degree(10.0);
  EXPECT_EQ(r.curve.degree(), 2);
  EXPECT_TRUE(r.curve.knot_vector().is_clamped());
  EXPECT_EQ(r.curve.domain(), c.domain());
  // Interior knots: simple ones stay simple, the double one drops to 1 (C^1 kept).
  EXPECT_EQ(r.curve.knots(), (Knots{0, 0, 0, 0.2, 0.45, 0.5, 0.9, 1, 1, 1}));
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) worst = std::max(worst, distance(c(i / 2e5), r.curve(i / 2e5)));
  EXPECT_LE(worst, r.error_bound * (1 + 1e-12));
  EXPECT_LE(r.error_bound, 10 * worst);  // the ratio seen is recorded in docs/accuracy.md
  RecordProperty("bound_over_measured", std::to_string(r.error_bound / worst));
  EXPECT_LT(distance(r.curve(0.0), c(0.0)), 1e-15);
  EXPECT_LT(distance(r.curve(1.0), c(1.0)), 1e-15);
  EXPECT_INVALID_ARGUMENT(c.reduce_degree(r.error_bound / 100), "tolerance", "more than the tolerance");
}

// A true rational cubic reduced to degree 2: the Cartesian bound (homogeneous bound times
// sqrt(1 + R^2) / w_min) holds against dense sampling; below it the reduction is refused.
TEST(DegreeReduction, NurbsBoundHolds) {
  test::SplitMix64 rng(9);
  const Knots U{0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1};
  const auto P = test::random_points<double, 2>(rng, 5);
  const Nurbs<double, 2> c(3, U, P, {1, 2, 0.5, 1.5, 1, 3});
  const auto r = c.reduce_degree(100.0);
  EXPECT_EQ(r.curve.degree(), 2);
  double worst = 0;
  for (int i = 0; i <= 100000; ++i) worst = std::max(worst, distance(c(i / 1e5), r.curve(i / 1e5)));
  EXPECT_LE(worst, r.error_bound);
  RecordProperty("nurbs_bound_over_measured", std::to_string(r.error_bound / worst));
  EXPECT_LT(distance(r.curve(0.0), c(0.0)), 1e-15);
  EXPECT_LT(distance(r.curve(1.0), c(1.0)), 1e-15);
  // Far below: the first reduced piece already exceeds it.
  EXPECT_INVALID_ARGUMENT(c.reduce_degree(worst / 1000), "tolerance", "more than the tolerance");
}

TEST(DegreeReduction, BadInput) {
  const BSpline<double, 2> line(1, {0, 0, 1, 1}, std::vector<P2>{{0, 0}, {1, 1}});
  EXPECT_INVALID_ARGUMENT(line.reduce_degree(1.0), "degree", "degree >= 2");
  const BSpline<double, 2> q(2, {0, 0, 0, 1, 1, 1}, std::vector<P2>{{0, 0}, {1, 1}, {2, 0}});
  EXPECT_INVALID_ARGUMENT(q.reduce_degree(0.0), "tolerance", "> 0");
  EXPECT_INVALID_ARGUMENT(q.reduce_degree(std::nan("")), "tolerance", "finite");
  // A quadratic to a line: bound |P_1 - (P_0 + P_2) / 2| = 1, refused below it.
  EXPECT_NEAR(q.reduce_degree(2.0).error_bound, 1.0, 1e-15);
  EXPECT_INVALID_ARGUMENT(q.reduce_degree(0.5), "tolerance", "moves the curve by up to 1");
}

}  // namespace
