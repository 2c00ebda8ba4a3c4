// Hermite curves and cubic splines: the Hermite basis, textbook splines (Burden & Faires),
// reproduction of cubics, periodic closure, integrals, solutions of y = c, sorted batches,
// tangent rules and n = 10^6.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "test_support.hpp"

namespace {

using namespace casteljau;
using P1 = Point<double, 1>;
using V1 = Vector<double, 1>;

std::vector<P1> ys(std::initializer_list<double> v) {
  std::vector<P1> P;
  for (double y : v) P.emplace_back(y);
  return P;
}

TEST(HermiteBasis, ValuesAndDerivatives) {
  // At t = 1/2: h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8 (exact in binary).
  const auto b = hermite_basis(0.5);
  EXPECT_EQ(b.h00, 0.5);
  EXPECT_EQ(b.h01, 0.5);
  EXPECT_EQ(b.h10, 0.125);
  EXPECT_EQ(b.h11, -0.125);
  // The interpolation conditions, exactly: values and slopes at 0 and 1.
  const auto b0 = hermite_basis(0.0), b1 = hermite_basis(1.0);
  EXPECT_EQ(b0.h00, 1); EXPECT_EQ(b0.h10, 0); EXPECT_EQ(b0.h01, 0); EXPECT_EQ(b0.h11, 0);
  EXPECT_EQ(b1.h00, 0); EXPECT_EQ(b1.h10, 0); EXPECT_EQ(b1.h01, 1); EXPECT_EQ(b1.h11, 0);
  const auto d0 = hermite_basis(0.0, 1), d1 = hermite_basis(1.0, 1);
  EXPECT_EQ(d0.h00, 0); EXPECT_EQ(d0.h10, 1); EXPECT_EQ(d0.h01, 0); EXPECT_EQ(d0.h11, 0);
  EXPECT_EQ(d1.h00, 0); EXPECT_EQ(d1.h10, 0); EXPECT_EQ(d1.h01, 0); EXPECT_EQ(d1.h11, 1);
  // Third derivatives are the leading coefficients times 6: 12, 6, -12, 6; fourth zero.
  const auto d3 = hermite_basis(0.3, 3), d4 = hermite_basis(0.3, 4);
  EXPECT_EQ(d3.h00, 12); EXPECT_EQ(d3.h10, 6); EXPECT_EQ(d3.h01, -12); EXPECT_EQ(d3.h11, 6);
  EXPECT_EQ(d4.h00, 0);
  // Derivatives against central differences of the values, and partition of unity.
  for (double t : {-0.5, 0.1, 0.37, 0.9, 1.7}) {
    const auto v = hermite_basis(t);
    EXPECT_NEAR(v.h00 + v.h01, 1, 1e-15);
    for (int k = 1; k <= 2; ++k) {
      const double h = 1e-6;
      const auto p = hermite_basis(t + h, k - 1), m = hermite_basis(t - h, k - 1), d = hermite_basis(t, k);
      EXPECT_NEAR((p.h00 - m.h00) / (2 * h), d.h00, 1e-8);
      EXPECT_NEAR((p.h10 - m.h10) / (2 * h), d.h10, 1e-8);
      EXPECT_NEAR((p.h01 - m.h01) / (2 * h), d.h01, 1e-8);
      EXPECT_NEAR((p.h11 - m.h11) / (2 * h), d.h11, 1e-8);
    }
  }
  EXPECT_INVALID_ARGUMENT((hermite_basis(0.5, -1)), "k", ">= 0");
}

// Burden & Faires, Numerical Analysis (9th ed.), 3.5 Examples 1 and 2: the natural and
// the clamped (f'(1) = 2, f'(3) = 1) splines through (1, 2), (2, 3), (3, 5):
//   natural: S0 = 2 + 3/4 (x-1) + 1/4 (x-1)^3, S1 = 3 + 3/2 (x-2) + 3/4 (x-2)^2 - 1/4 (x-2)^3
//   clamped: S0 = 2 + 2 (x-1) - 5/2 (x-1)^2 + 3/2 (x-1)^3, S1 = 3 + 3/2 (x-2) + 2 (x-2)^2 - 3/2 (x-2)^3
TEST(CubicSpline, BurdenFairesNaturalAndClamped) {
  const CubicSpline<double, 1> nat({1, 2, 3}, ys({2, 3, 5}));
  const CubicSpline<double, 1> cl({1, 2, 3}, ys({2, 3, 5}), SplineBoundary<double, 1>::clamped(V1(2.0), V1(1.0)));
  const auto S = [](double x, bool clamped) {
    if (x < 2) {
      const double s = x - 1;
      return clamped ? 2 + 2 * s - 2.5 * s * s + 1.5 * s * s * s : 2 + 0.75 * s + 0.25 * s * s * s;
    }
    const double s = x - 2;
    return clamped ? 3 + 1.5 * s + 2 * s * s - 1.5 * s * s * s : 3 + 1.5 * s + 0.75 * s * s - 0.25 * s * s * s;
  };
  for (double x = 0.5; x <= 3.5; x += 0.125) {
    // A few ulps of the values (<= 6).
    EXPECT_NEAR(nat(x)[0], S(x, false), 4e-15) << x;
    EXPECT_NEAR(cl(x)[0], S(x, true), 4e-15) << x;
  }
  EXPECT_NEAR(nat.slopes()[0][0], 0.75, 1e-15);
  EXPECT_NEAR(nat.slopes()[1][0], 1.5, 1e-15);
  EXPECT_NEAR(nat.derivative_at(1, 2)[0], 0, 1e-14);
  EXPECT_NEAR(nat.derivative_at(3, 2)[0], 0, 1e-14);
  EXPECT_NEAR(cl.derivative_at(2, 2)[0], 4, 1e-14);  // 2 c1
  EXPECT_NEAR(cl.derivative_at(2.5, 3)[0], -9, 1e-13);  // 6 d1
}

// A cubic is its own not-a-knot spline and its own clamped spline with its end
// derivatives (the spline is unique and the cubic satisfies every condition).
TEST(CubicSpline, ReproducesCubics) {
  const auto f = [](double x) { return 0.5 * x * x * x - 2 * x * x + x - 3; };
  const auto df = [](double x) { return 1.5 * x * x - 4 * x + 1; };
  const std::vector<double> x = {-1, -0.3, 0.4, 0.5, 2, 3.5};
  std::vector<P1> P;
  for (double v : x) P.emplace_back(f(v));
  const CubicSpline<double, 1> nak(x, P, SplineBoundary<double, 1>::not_a_knot());
  const CubicSpline<double, 1> cl(x, P, SplineBoundary<double, 1>::clamped(V1(df(-1)), V1(df(3.5))));
  const CubicSpline<double, 1> gen(x, P, SplineBoundary<double, 1>::general({2, V1(3 * -1 - 4)}, {1, V1(df(3.5))}));
  for (double t = -2; t <= 4.5; t += 0.1) {
    // Values up to ~30 here; the systems are well conditioned: 1e-12 absolute.
    EXPECT_NEAR(nak(t)[0], f(t), 1e-12) << t;
    EXPECT_NEAR(cl(t)[0], f(t), 1e-12) << t;
    EXPECT_NEAR(gen(t)[0], f(t), 1e-12) << t;
    EXPECT_NEAR(nak.derivative_at(t, 3)[0], 3, 1e-10) << t;
  }
  // Integral of f over [-1, 3]: F(x) = x^4/8 - 2x^3/3 + x^2/2 - 3x.
  const auto F = [](double s) { return s * s * s * s / 8 - 2 * s * s * s / 3 + s * s / 2 - 3 * s; };
  EXPECT_NEAR(integral(nak, -1.0, 3.0)[0], F(3) - F(-1), 1e-12);
  EXPECT_NEAR(integral(nak, 0.45, -2.0)[0], F(-2) - F(0.45), 1e-12);  // reversed, extrapolated
  const auto A = antiderivative(nak);
  EXPECT_EQ(A(-1.0)[0], 0);
  EXPECT_NEAR(A(2.0)[0], F(2) - F(-1), 1e-12);
}

TEST(CubicSpline, SolveFindsEveryRoot) {
  // (x - 1)(x - 2)(x - 3) = x^3 - 6x^2 + 11x - 6, reproduced by not-a-knot; y = 0 at 1, 2, 3
  // (2 is a param: reported once), y = 6 at x = 4 is outside the domain [0, 3.5].
  const auto f = [](double x) { return (x - 1) * (x - 2) * (x - 3); };
  const std::vector<double> x = {0, 0.7, 2, 3.5};
  std::vector<P1> P;
  for (double v : x) P.emplace_back(f(v));
  const CubicSpline<double, 1> s(x, P, SplineBoundary<double, 1>::not_a_knot());
  const Solutions r = solve(s, 0.0);
  ASSERT_EQ(r.t.size(), 3u);
  EXPECT_NEAR(r.t[0], 1, 1e-12);
  EXPECT_NEAR(r.t[1], 2, 1e-12);
  EXPECT_NEAR(r.t[2], 3, 1e-12);
  EXPECT_TRUE(r.intervals.empty());
  EXPECT_TRUE(solve(s, 6.0).t.empty() || solve(s, 6.0).t.front() < 3.5);
  // A flat piece is reported as an interval.
  const Hermite<double, 1> flat({0, 1, 2}, ys({1, 1, 0}), {V1(0.0), V1(0.0), V1(0.0)});
  const Solutions fr = solve(flat, 1.0);
  ASSERT_EQ(fr.intervals.size(), 1u);
  EXPECT_EQ(fr.intervals[0], Interval<double>(0, 1));
}

TEST(CubicSpline, PeriodicClosedCurve) {
  // Points on the unit circle at uneven angles, closed: C^2 where the ends meet.
  std::vector<double> u = {0, 0.9, 2.0, 3.1, 4.4, 5.2, 2 * M_PI};
  std::vector<Point<double, 2>> P;
  for (double a : u) P.emplace_back(std::cos(a), std::sin(a));
  P.back() = P.front();
  const CubicSpline<double, 2> s(u, P, SplineBoundary<double, 2>::periodic());
  for (int k = 1; k <= 2; ++k) {
    EXPECT_LE(test::max_coord_diff(s.derivative_at(u.front(), k), s.hermite().piece(s.size() - 1).derivative_at(1.0, k) *
                                                                       std::pow(1 / (u.back() - u[u.size() - 2]), k)),
              1e-12)
        << k;
  }
  // Close to the circle (interpolation error O(h^4)).
  for (double a = 0; a < 2 * M_PI; a += 0.05) EXPECT_NEAR(norm(s(a).to_vector()), 1, 0.02) << a;
  EXPECT_INVALID_ARGUMENT((CubicSpline<double, 1>({0, 1, 2}, ys({0, 1, 0.5}), SplineBoundary<double, 1>::periodic())), "points[2]",
                          "equal points[0]");
}

TEST(CubicSpline, SortedBatchEqualsPointwise) {
  const CubicSpline<double, 2> s({0, 0.5, 1.25, 2, 4}, {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}, {1, -2}});
  std::vector<double> t;
  for (int i = -10; i <= 50; ++i) t.push_back(i / 10.0);
  t.push_back(0.5);  // out of order: falls back to the binary search
  t.push_back(-3);
  const auto batch = s.evaluate_sorted(t);
  for (std::size_t j = 0; j < t.size(); ++j) EXPECT_EQ(batch[j], s(t[j])) << t[j];
}

// n = 10^6 points of a cubic on random spacing (ratios up to 100): the clamped spline is
// the cubic, so any error is the solve's; built in O(n).
TEST(CubicSpline, MillionPoints) {
  const std::size_t n = 1000000;
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> step(0.01, 1.0);
  std::vector<double> x(n);
  x[0] = 0;
  for (std::size_t i = 1; i < n; ++i) x[i] = x[i - 1] + step(rng) * 1e-6;
  const auto f = [](double v) { return v * v * v - v; };
  std::vector<P1> P(n);
  for (std::size_t i = 0; i < n; ++i) P[i] = P1(f(x[i]));
  const auto t0 = std::chrono::steady_clock::now();
  const CubicSpline<double, 1> s(x, P, SplineBoundary<double, 1>::clamped(V1(-1.0), V1(3 * x.back() * x.back() - 1)));
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // O(n): about 0.1 s here in Release on a loaded 2-core machine; a generous bound that
  // an O(n^2) build (hours) could not meet, even under the sanitizers.
  EXPECT_LT(secs, 60.0);
  double worst = 0;
  for (std::size_t i = 0; i + 1 < n; i += 997) worst = std::max(worst, std::abs(s.slopes()[i][0] - (3 * x[i] * x[i] - 1)));
  // Slopes from differences of values ~0.5 over steps ~5e-7: eps * 0.5 / 5e-7 ~ 2e-10 per
  // chord slope, and the solve does not amplify it (diagonally dominant).
  EXPECT_LT(worst, 1e-8);
}

TEST(HermiteTangents, MonotoneDataGiveMonotoneCurves) {
  const std::vector<double> x = {0, 1, 1.5, 4, 4.2, 6};
  const auto P = ys({0, 0.1, 3, 3.1, 8, 8});
  const Hermite<double, 1> h(x, P, monotone_tangents(x, P));
  double last = h(0.0)[0];
  for (double t = 0; t <= 6; t += 0.01) {
    const double v = h(t)[0];
    EXPECT_GE(v, last - 1e-15) << t;
    last = v;
  }
  // The natural spline through the same data overshoots (the gallery shows it).
  const CubicSpline<double, 1> s(x, P);
  double hi = 0;
  for (double t = 0; t <= 6; t += 0.01) hi = std::max(hi, s(t)[0]);
  EXPECT_GT(hi, 8.0);
}

TEST(HermiteTangents, AkimaReproducesLines) {
  const std::vector<double> x = {0, 0.3, 1, 2.5, 2.6};
  std::vector<P1> P;
  for (double v : x) P.emplace_back(2 * v - 1);
  for (const auto& m : akima_tangents(x, P)) EXPECT_NEAR(m[0], 2, 1e-14);
  EXPECT_INVALID_ARGUMENT((akima_tangents<double, 1>({0, 1}, ys({0, 1}))), "points", "at least 3");
}

TEST(HermiteTangents, KochanekBartelsCornersAndReverse) {
  const std::vector<double> u = {0, 1, 2};
  const std::vector<Point<double, 2>> P = {{0, 0}, {1, 1}, {2, 0}};
  const auto m = kochanek_bartels_tangents(u, P, KochanekBartels<double>{0, -1, 0});
  // continuity -1: each piece's tangents are its own chord: straight pieces.
  EXPECT_EQ(m.outgoing[1], (Vector<double, 2>{1, -1}));
  EXPECT_EQ(m.incoming[1], (Vector<double, 2>{1, 1}));
  const Hermite<double, 2> h(u, P, m.incoming, m.outgoing);
  EXPECT_TRUE(h.one_sided());
  EXPECT_EQ(h(0.5), (Point<double, 2>{0.5, 0.5}));
  EXPECT_EQ(h.derivative_at(1, 1), (Vector<double, 2>{1, -1}));  // the right piece at a param
  EXPECT_EQ(h.reverse().reverse(), h);
  EXPECT_EQ(h.reverse()(0.5), h(1.5));
  EXPECT_INVALID_ARGUMENT((kochanek_bartels_tangents(u, P, KochanekBartels<double>{0, 0, 1.5})), "bias", "[-1, 1]");
}

TEST(Hermite, ConstructionErrors) {
  EXPECT_INVALID_ARGUMENT((Hermite<double, 1>({0}, ys({0}), {V1(0.0)})), "params", "at least 2");
  EXPECT_INVALID_ARGUMENT((Hermite<double, 1>({0, 0}, ys({0, 1}), {V1(0.0), V1(0.0)})), "params[1]", "strictly increasing");
  EXPECT_INVALID_ARGUMENT((Hermite<double, 1>({0, 1}, ys({0, 1}), {V1(0.0)})), "tangents", "one tangent per param");
  EXPECT_INVALID_ARGUMENT((Hermite<double, 1>({0, 1}, ys({0, NAN}), {V1(0.0), V1(0.0)})), "points[1][0]", "finite");
  EXPECT_INVALID_ARGUMENT((Hermite<double, 1>({0, 1e300}, ys({0, 1}), {V1(1e300), V1(0.0)})), "tangents[0]", "overflows");
  EXPECT_INVALID_ARGUMENT((parameters_from_points<double, 1>(ys({0, 1, 1}), Parametrization::chord)), "points[2]", "distinct");
  const std::vector<double> centripetal = parameters_from_points<double, 2>({{0, 0}, {3, 4}, {3, 0}}, Parametrization::centripetal);
  EXPECT_EQ(centripetal, (std::vector<double>{0, std::sqrt(5.0), std::sqrt(5.0) + 2}));
}

}  // namespace
