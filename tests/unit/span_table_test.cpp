// SpanTable (algo/span_table.hpp): batch evaluation of piecewise polynomial curves against
// each curve's own evaluation (de Boor for B-splines, de Casteljau for Bézier segments),
// at random, sorted and reversed parameters, exactly at the breaks, outside the domain,
// and on break sequences built to defeat the bucket grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;

/// Uniform cubic-or-other-degree B-spline with n control points and the given interior
/// knots (clamped ends at lo and hi).
BSpline<double, 3> clamped(int p, const std::vector<double>& interior, double lo, double hi, test::SplitMix64& rng) {
  std::vector<double> knots(static_cast<std::size_t>(p) + 1, lo);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, hi);
  const int n = static_cast<int>(knots.size()) - p - 1;
  return BSpline<double, 3>(p, knots, test::random_points<double, 3>(rng, n - 1, -2, 3));  // n points
}

/// Parameters spread over [lo, hi], the breaks themselves, and a few outside.
std::vector<double> parameters(const std::vector<double>& breaks, test::SplitMix64& rng, int count) {
  const double lo = breaks.front(), hi = breaks.back();
  std::vector<double> ts;
  for (int i = 0; i < count; ++i) ts.push_back(lo + (hi - lo) * rng.uniform());
  ts.insert(ts.end(), breaks.begin(), breaks.end());
  for (const double b : breaks) {
    ts.push_back(std::nextafter(b, -INFINITY));
    ts.push_back(std::nextafter(b, INFINITY));
  }
  ts.push_back(lo - 0.5 * (hi - lo));
  ts.push_back(hi + 2.0 * (hi - lo));
  return ts;
}

/// Evaluates through the table in the given order and compares with c(t) point by point:
/// both are the same polynomial in different forms (Bernstein weights vs de Boor's or de
/// Casteljau's convex combinations), a few eps of the control points' size apart inside
/// the domain; outside it, relative to the point (a tiny end piece extrapolated far grows
/// like s^p).
template <class C>
void expect_matches(const C& c, std::vector<double> ts, double tol) {
  for (int order = 0; order < 3; ++order) {
    if (order == 1) std::sort(ts.begin(), ts.end());
    if (order == 2) std::reverse(ts.begin(), ts.end());
    std::vector<Point<double, C::dimension>> out(ts.size());
    evaluate_pieces(c, std::span<const double>(ts), std::span<Point<double, C::dimension>>(out));
    double worst = 0;
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const auto ref = c(ts[j]);
      worst = std::max(worst, test::max_coord_diff(out[j], ref) / std::max(1.0, norm(ref.to_vector())));
    }
    EXPECT_LE(worst, tol) << "order " << order;
  }
}

TEST(SpanTable, BSplinesOfEveryDegreeMatchDeBoor) {
  test::SplitMix64 rng(7);
  for (int p = 1; p <= 7; ++p) {
    std::vector<double> interior;
    for (int i = 1; i < 40; ++i) interior.push_back(i / 40.0);
    if (p >= 2) interior.insert(interior.begin() + 10, interior[9]);  // a double knot
    const auto c = clamped(p, interior, 0, 1, rng);
    const auto table = SpanTable<double, 3>::of(pieces(c));
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->degree(), p);
    EXPECT_EQ(table->size(), 40u);  // 41 distinct knots (one of them double)
    expect_matches(c, parameters(pieces(c).breaks(), rng, 2000), 1e-14 * 8);
  }
}

TEST(SpanTable, UnevenAndNearlyEqualBreaks) {
  test::SplitMix64 rng(11);
  // 200 breaks crowded into [0, 1e-9], then a few spread to 1: one bucket holds most of them.
  std::vector<double> interior;
  for (int i = 1; i <= 200; ++i) interior.push_back(i * 5e-12);
  interior.push_back(0.25);
  interior.push_back(0.75);
  const auto crowded = clamped(3, interior, 0, 1, rng);
  auto ts = parameters(pieces(crowded).breaks(), rng, 3000);
  for (int i = 0; i < 500; ++i) ts.push_back(1e-9 * rng.uniform());
  expect_matches(crowded, ts, 1e-13);
  // Breaks one ulp apart, on a domain far from zero.
  std::vector<double> ulps;
  double b = 1000.5;
  for (int i = 0; i < 20; ++i) ulps.push_back(b = std::nextafter(b, INFINITY));
  const auto tight = clamped(2, ulps, 1000, 1001, rng);
  expect_matches(tight, parameters(pieces(tight).breaks(), rng, 1000), 1e-12);
}

TEST(SpanTable, RightPieceAnswersAtABreak) {
  // Two lines with a gap at the break t = 1: the right one answers there, the last one
  // at the domain's end.
  const Path<double, 2> gap({Bezier<double, 2>{{0, 0}, {1, 0}}, Bezier<double, 2>{{5, 5}, {6, 5}}});
  const std::vector<double> ts{1.0, 2.0, 0.0, std::nextafter(1.0, 0.0)};
  std::vector<Point<double, 2>> out(ts.size());
  evaluate_pieces(gap, std::span<const double>(ts), std::span<Point<double, 2>>(out));
  EXPECT_EQ(out[0], (Point<double, 2>{5, 5}));
  EXPECT_EQ(out[1], (Point<double, 2>{6, 5}));
  EXPECT_EQ(out[2], (Point<double, 2>{0, 0}));
  EXPECT_NEAR(out[3][0], 1.0, 1e-15);
  EXPECT_EQ(out[3][1], 0.0);
}

TEST(SpanTable, PolylinesPathsAndFallbacks) {
  test::SplitMix64 rng(3);
  const Polyline<double, 2> poly{{0, 0}, {1, 2}, {1, 2}, {3, -1}, {4, 0.5}};
  ASSERT_TRUE((SpanTable<double, 2>::of(pieces(poly)).has_value()));
  expect_matches(poly, parameters(pieces(poly).breaks(), rng, 500), 1e-15 * 8);
  // Rational pieces and mixed degrees take the point-by-point path, with the same answers.
  const Path<double, 2> mixed({Bezier<double, 2>{{0, 0}, {1, 1}, {2, -1}, {3, 0}},
                               RationalBezier<double, 2>({{3, 0}, {4, 1}, {5, 0}}, {1, 3, 1})},
                              {-1.0, 0.5, 2.0});
  EXPECT_FALSE((SpanTable<double, 2>::of(pieces(mixed)).has_value()));
  expect_matches(mixed, parameters(pieces(mixed).breaks(), rng, 500), 0.0);
  const double h = std::sqrt(0.5);
  const Nurbs<double, 2> circle(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                                {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
                                {1, h, 1, h, 1, h, 1, h, 1});
  EXPECT_FALSE((SpanTable<double, 2>::of(pieces(circle)).has_value()));
  // Above the table's degree: de Casteljau point by point.
  const auto high = Bezier<double, 2>(test::random_points<double, 2>(rng, SpanTable<double, 2>::max_degree + 2));
  EXPECT_FALSE((SpanTable<double, 2>::of(pieces(high)).has_value()));
}

TEST(SpanTable, BadInput) {
  test::SplitMix64 rng(5);
  const auto c = clamped(3, {0.5}, 0, 1, rng);
  const std::vector<double> ts{0.5, std::nan(""), 0.25};
  std::vector<Point<double, 3>> out(ts.size());
  EXPECT_INVALID_ARGUMENT(evaluate_pieces(c, std::span<const double>(ts), std::span<Point<double, 3>>(out)), "t[1]",
                          "finite");
  const std::vector<double> inf{std::numeric_limits<double>::infinity()};
  std::vector<Point<double, 3>> one(1);
  EXPECT_INVALID_ARGUMENT(evaluate_pieces(c, std::span<const double>(inf), std::span<Point<double, 3>>(one)), "t[0]",
                          "finite");
  std::vector<Point<double, 3>> short_out(2);
  EXPECT_INVALID_ARGUMENT(evaluate_pieces(c, std::span<const double>(ts), std::span<Point<double, 3>>(short_out)), "out",
                          "one point per parameter");
  std::vector<Point<double, 3>> none;
  evaluate_pieces(c, std::span<const double>(), std::span<Point<double, 3>>(none));  // nothing to do, no error
}

}  // namespace
