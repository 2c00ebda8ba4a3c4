// Hermite curves and cubic splines: the Hermite basis, textbook splines (Burden & Faires),
// reproduction of cubics, periodic closure, integrals, solutions of y = c, sorted batches,
// tangent rules and n = 10^6.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/json.hpp"
#include "random_interp_data.hpp"
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

// The shared parametrization's closed and normalised forms (fit and the surface grids use
// them): the 3-4-5 triangle's chord steps 3, 4, 5 over a perimeter of 12; a repeated
// closing point is named; parameter_sums keeps a zero step and sums without overflow at
// 1e200. The origin-0 frame's scaling at float: 2^200 is no float, 1e-30f 2^200 is.
TEST(Parametrization, ClosedNormalisedUncheckedAndTheOriginZeroFrame) {
  const std::vector<Point<double, 2>> tri = {{0, 0}, {3, 0}, {3, 4}};
  EXPECT_EQ((parameters_from_points(tri, Parametrization::chord, true)), (std::vector<double>{0, 3, 7, 12}));
  EXPECT_EQ((unit_parameters(tri, Parametrization::chord, true)), (std::vector<double>{0, 0.25, 7.0 / 12, 1}));
  EXPECT_EQ((unit_parameters(tri, Parametrization::uniform, false)), (std::vector<double>{0, 0.5, 1}));
  EXPECT_INVALID_ARGUMENT((parameters_from_points<double, 2>({{0, 0}, {1, 0}, {0, 0}}, Parametrization::chord, true)), "points[0]",
                          "equals points[2]");
  EXPECT_EQ((parameter_sums<double, 1>(ys({0, 1, 1, 3}), Parametrization::chord)), (std::vector<double>{0, 1, 1, 3}));
  const std::vector<double> big = parameter_sums<double, 2>({{0, 0}, {3e200, 4e200}}, Parametrization::chord);
  EXPECT_NEAR(big[1] / 5e200, 1.0, 1e-15);
  EXPECT_EQ(detail::times_pow2(1e-30f, 200), std::ldexp(1e-30f, 200));
  EXPECT_EQ(detail::times_pow2(3.0, -1074), std::ldexp(3.0, -1074));
  EXPECT_EQ(detail::abs_exponent(0.75), 0);
  EXPECT_EQ(detail::abs_exponent(0.0), 0);
}

// Curve JSON holds one tangent per point: the writer gives the ones the pieces use (the
// incoming tangent at the last point), and a curve with a corner becomes a path of
// two-point hermite segments; either way the curve read back is the same curve.
TEST(Hermite, JsonKeepsTheCurve) {
  const Hermite<double, 1> ends({0, 1, 2}, ys({0, 1, 0}), {V1(9.0), V1(1.0), V1(5.0)}, {V1(2.0), V1(1.0), V1(7.0)});
  const std::vector<double> u = {0, 1, 1.5, 3};
  const std::vector<Point<double, 2>> P = {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}};
  const auto kb = kochanek_bartels_tangents(u, P, KochanekBartels<double>{0.25, -0.5, 0.5});
  const Hermite<double, 2> corner(u, P, kb.incoming, kb.outgoing);
  ASSERT_FALSE(ends.one_sided());
  ASSERT_TRUE(corner.one_sided());
  const auto back_ends = io::curve_from_json(io::parse_json(io::to_json(io::AnyCurve(ends)).dump()));
  const auto back_corner = io::curve_from_json(io::parse_json(io::to_json(io::AnyCurve(corner)).dump()));
  EXPECT_EQ(io::type_name(back_ends), "hermite");
  EXPECT_EQ(io::type_name(back_corner), "path");
  for (double t : {-0.5, 0.0, 0.5, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 3.5}) {
    for (int k = 0; k <= 3; ++k) {
      const auto a = io::derivatives(back_ends, std::span<const double>(&t, 1), k);
      EXPECT_NEAR(a.coords[0], ends.derivative_at(t, k)[0], 1e-14 * (1 + std::abs(a.coords[0]))) << t << " " << k;
      const auto b = io::derivatives(back_corner, std::span<const double>(&t, 1), k);
      const auto c = corner.derivative_at(t, k);
      // The path maps each segment's own domain [u_i, u_(i+1)] onto the same break interval:
      // the same polynomials, up to the rounding of that identity map.
      for (int d = 0; d < 2; ++d) EXPECT_NEAR(b.coords[static_cast<std::size_t>(d)], c[d], 1e-13 * (1 + std::abs(c[d]))) << t << " " << k;
    }
  }
}

// The Hermite curve with the Catmull-Rom tangent rule on the uniform params u_i = i is the
// uniform (alpha 0) catmull_rom curve on the interior pieces. The rule gives m_i = (P_(i+1)
// - P_(i-1)) / (u_(i+1) - u_(i-1)) = (P_(i+1) - P_(i-1)) / 2 at i = 1..N-2, the Catmull-Rom
// tangent; but at the ends it takes the end chord (m_0 = P_1 - P_0), while the open
// catmull_rom curve drops P_0 and P_(N-1) (they only shape the end tangents) and starts at
// P_1 with parameter 0. So Hermite piece i (i = 1..N-3, on [i, i+1]) is catmull_rom segment
// i - 1 (on [i - 1, i]): H(u) = CR(u - 1) for u in [1, N - 2], derivatives alike (both
// with respect to unit-spaced params); the end pieces differ. Bound 1e-14 of the data's
// size (8 times that for derivatives): both sides are a few flops from the same data
// (Hermite form against de Casteljau on the Bézier form).
TEST(HermiteTangents, CatmullRomRuleOnUniformParamsIsTheUniformCatmullRomCurve) {
  const std::vector<Point<double, 2>> P = {{0, 0}, {1, 3}, {2.5, 2}, {3, -1}, {5, 0.5}, {6, 4}, {4, 6}};
  std::vector<double> u(P.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i);
  const Hermite<double, 2> h(u, P, catmull_rom_tangents(u, P));
  const CatmullRom<double, 2> cr(P, 0.0);
  const double n2 = static_cast<double>(P.size()) - 2;
  ASSERT_EQ(cr.domain().lo, 0.0);
  ASSERT_EQ(cr.domain().hi, n2 - 1);
  const double size = 6;  // max |coordinate| of the data
  for (int j = 0; j <= 400; ++j) {
    const double x = 1 + (n2 - 1) * j / 400;
    EXPECT_LE(test::max_coord_diff(h(x), cr(x - 1)), 1e-14 * size) << x;
    // At x = N - 2 the Hermite curve's right-hand piece (the end piece) answers but the
    // catmull_rom curve's last segment (its domain's end): their second and third
    // derivatives differ there by design; the first derivatives agree (C^1).
    for (int k = 1; k <= (j < 400 ? 3 : 1); ++k) {
      EXPECT_LE(test::max_coord_diff(h.derivative_at(x, k), cr.derivative_at(x - 1, k)), 8e-14 * size) << x << " " << k;
    }
  }
  // The end pieces differ: the rule's end tangent is the end chord (Catmull-Rom's curve
  // has no piece there).
  EXPECT_EQ(h.derivative_at(0.0, 1), P[1] - P[0]);
  EXPECT_EQ(h.derivative_at(6.0, 1), P[6] - P[5]);
}

// Derivatives of every interpolating type to any order: zero above the degree; at an
// interior param the right-hand piece answers, at the domain's end the last piece. The
// expected values are the Hermite basis's closed forms at a piece's start (t = 0) and end
// (t = 1), with h the piece's length and m its end tangents:
//   second derivative at the start  6 (P_(i+1) - P_i) / h^2 - (4 m_i + 2 m_(i+1)) / h,
//   second derivative at the end   -6 (P_(i+1) - P_i) / h^2 + (2 m_i + 4 m_(i+1)) / h,
//   third derivative               12 (P_i - P_(i+1)) / h^3 + 6 (m_i + m_(i+1)) / h^2.
// Bounds: a few eps of values up to ~100.
TEST(InterpolatingCurves, DerivativesOfAnyOrderAndTheRightHandPiece) {
  using V2 = Vector<double, 2>;
  using Pt = Point<double, 2>;
  const auto second_start = [](Pt a, Pt b, V2 ma, V2 mb, double h) { return 6 * (b - a) / (h * h) - (4 * ma + 2 * mb) / h; };
  const auto second_end = [](Pt a, Pt b, V2 ma, V2 mb, double h) { return -6 * (b - a) / (h * h) + (2 * ma + 4 * mb) / h; };
  const auto third = [](Pt a, Pt b, V2 ma, V2 mb, double h) { return 12 * (a - b) / (h * h * h) + 6 * (ma + mb) / (h * h); };
  const std::vector<double> u = {0, 0.5, 2, 3};
  const std::vector<Pt> P = {{0, 0}, {1, 2}, {2, -1}, {4, 1}};
  // Hermite with given tangents and the natural spline (with its slopes): the same checks.
  const std::vector<V2> m = {{1, 0}, {0, 3}, {2, -2}, {1, 1}};
  const Hermite<double, 2> hermite(u, P, m);
  const CubicSpline<double, 2> spline(u, P);
  for (int which = 0; which < 2; ++which) {
    const auto& t = which == 0 ? m : spline.slopes();
    const auto D = [&](double x, int k) { return which == 0 ? hermite.derivative_at(x, k) : spline.derivative_at(x, k); };
    for (std::size_t i = 1; i < 3; ++i) {  // the interior params: piece i answers
      const double h = u[i + 1] - u[i], hl = u[i] - u[i - 1];
      EXPECT_LE(test::max_coord_diff(D(u[i], 2), second_start(P[i], P[i + 1], t[i], t[i + 1], h)), 1e-13) << which << i;
      EXPECT_LE(test::max_coord_diff(D(u[i], 3), third(P[i], P[i + 1], t[i], t[i + 1], h)), 1e-12) << which << i;
      // ... and not the left piece (its third derivative differs on this data).
      EXPECT_GT(test::max_coord_diff(D(u[i], 3), third(P[i - 1], P[i], t[i - 1], t[i], hl)), 0.1) << which << i;
    }
    // At the domain's end the last piece answers.
    EXPECT_LE(test::max_coord_diff(D(3, 2), second_end(P[2], P[3], t[2], t[3], 1)), 1e-13) << which;
    for (int k = 4; k <= 6; ++k) {
      EXPECT_EQ(D(1.0, k), V2(0, 0)) << which << k;
      EXPECT_EQ(D(3.0, k), V2(0, 0)) << which << k;
    }
  }
  // Catmull-Rom, alpha 0 (unit knot intervals, tangents (P_(i+1) - P_(i-1)) / 2); its
  // segment j runs from P_(j+1) to P_(j+2) on [j, j + 1].
  const std::vector<Pt> Q = {{0, 0}, {1, 2}, {2, -1}, {4, 1}, {5, 3}};
  const CatmullRom<double, 2> cr(Q, 0.0);
  const auto tan = [&](std::size_t i) { return (Q[i + 1] - Q[i - 1]) / 2; };
  EXPECT_LE(test::max_coord_diff(cr.derivative_at(1.0, 2), second_start(Q[2], Q[3], tan(2), tan(3), 1)), 1e-13);
  EXPECT_GT(test::max_coord_diff(cr.derivative_at(1.0, 2), second_end(Q[1], Q[2], tan(1), tan(2), 1)), 0.1);
  EXPECT_LE(test::max_coord_diff(cr.derivative_at(2.0, 2), second_end(Q[2], Q[3], tan(2), tan(3), 1)), 1e-13);  // the end
  EXPECT_LE(test::max_coord_diff(cr.derivative_at(1.5, 3), third(Q[2], Q[3], tan(2), tan(3), 1)), 1e-12);
  for (int k = 4; k <= 6; ++k) EXPECT_EQ(cr.derivative_at(0.5, k), V2(0, 0)) << k;
  // Lagrange: one polynomial piece of degree n; the n-th derivative is constant, n! times
  // the leading coefficient: on y = x^3 through 4 nodes, y''' = 6, and zero above.
  const Lagrange<double, 1> lag({-1, 0, 0.5, 2}, {P1(-1.0), P1(0.0), P1(0.125), P1(8.0)});
  for (const double x : {-1.0, 0.3, 2.0}) {
    EXPECT_NEAR(lag.derivative_at(x, 3)[0], 6, 1e-12) << x;
    EXPECT_NEAR(lag.derivative_at(x, 2)[0], 6 * x, 1e-12) << x;
    for (int k = 4; k <= 6; ++k) EXPECT_EQ(lag.derivative_at(x, k)[0], 0.0) << x << k;
  }
}

// The fast paths against plain references: segment_index (a branch-free search over every
// 64th param, then over a block) against std::upper_bound at every param, between params
// and outside the domain, for sizes around the block length; the fused spline solve
// against cubic_spline_slopes (the unfused Thomas solve) for the non-periodic boundaries:
// the same diagonally dominant system solved with other roundings (spacing ratios up to
// 100 here), so 1e-13 of the largest slope; evaluate_sorted into caller storage, and its
// size check.
TEST(CubicSpline, FastPathsAgreeWithTheReferences) {
  std::mt19937_64 rng(6);
  for (const std::size_t n : {1, 2, 3, 4, 63, 64, 65, 66, 127, 128, 129, 1000}) {
    const auto [u, P] = test::random_interp_data(n, rng);
    const Hermite<double, 1> h(u, P, finite_difference_tangents(u, P));
    std::vector<double> q = {u[0] - 1, u[n] + 1};
    for (std::size_t i = 0; i <= n; ++i) q.push_back(u[i]);
    for (std::size_t i = 0; i < n; ++i) q.push_back((u[i] + u[i + 1]) / 2);
    for (const double x : q) {
      const auto expected = static_cast<std::size_t>(std::upper_bound(u.begin() + 1, u.end() - 1, x) - (u.begin() + 1));
      EXPECT_EQ(h.segment_index(x), expected) << n << " " << x;
    }
    std::sort(q.begin(), q.end());
    std::vector<P1> out(q.size());
    h.evaluate_sorted(std::span<const double>(q), std::span<P1>(out));
    for (std::size_t k = 0; k < q.size(); ++k) EXPECT_EQ(out[k], h(q[k])) << n << " " << q[k];
    using B = CubicSpline<double, 1>::Boundary;
    std::vector<B> boundaries = {B::natural(), B::clamped(V1(0.5), V1(-2.0)), B::general({1, V1(1.0)}, {2, V1(3.0)}),
                                 B::general({2, V1(-1.0)}, {1, V1(0.25)})};
    if (n >= 3) boundaries.push_back(B::not_a_knot());
    for (const B& b : boundaries) {
      const CubicSpline<double, 1> s(u, P, b);
      const auto ref = cubic_spline_slopes(u, P, b);
      double scale = 1, worst = 0;
      for (std::size_t i = 0; i <= n; ++i) {
        scale = std::max(scale, std::abs(ref[i][0]));
        worst = std::max(worst, std::abs(s.slopes()[i][0] - ref[i][0]));
      }
      EXPECT_LE(worst, 1e-13 * scale) << n << " " << static_cast<int>(b.kind);
    }
  }
  const CubicSpline<double, 1> s({0, 1, 2}, ys({0, 1, 0}));
  const std::vector<double> t = {0.5, 1.5};
  std::vector<P1> small(1);
  EXPECT_INVALID_ARGUMENT(s.evaluate_sorted(std::span<const double>(t), std::span<P1>(small)), "out", "one point per parameter");
}

// The random batch (groups of 16 queries searched side by side) against one call per query,
// bit for bit, in shuffled order: every param, midpoints and points outside the domain, for
// sizes around the block length and batch lengths that are not multiples of the group;
// the size check, and a NaN query refused (naming "t") as operator() refuses it.
TEST(CubicSpline, RandomBatchAgreesWithOneCallPerQuery) {
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const std::size_t n : {1, 2, 5, 63, 64, 65, 129, 1000}) {
    std::vector<double> u(n + 1);
    std::vector<P1> P(n + 1);
    u[0] = 2;
    P[0] = P1(U(rng));
    for (std::size_t i = 1; i <= n; ++i) {
      u[i] = u[i - 1] + 0.01 + U(rng);
      P[i] = P1(U(rng));
    }
    const CubicSpline<double, 1> s(u, P);
    std::vector<double> q = {u[0] - 1, u[n] + 1};
    for (std::size_t i = 0; i <= n; ++i) q.push_back(u[i]);
    for (std::size_t i = 0; i < n; ++i) q.push_back((u[i] + u[i + 1]) / 2);
    std::shuffle(q.begin(), q.end(), rng);
    for (const std::size_t len : {std::size_t{0}, std::size_t{1}, std::size_t{17}, q.size()}) {
      if (len > q.size()) continue;
      std::vector<P1> out(len);
      s.evaluate(std::span<const double>(q.data(), len), std::span<P1>(out));
      for (std::size_t k = 0; k < len; ++k) EXPECT_EQ(out[k], s(q[k])) << n << " " << q[k];
    }
  }
  const CubicSpline<double, 1> s({0, 1, 2}, ys({0, 1, 0}));
  const std::vector<double> t = {0.5, 1.5};
  std::vector<P1> small(1), two(2);
  EXPECT_INVALID_ARGUMENT(s.evaluate(std::span<const double>(t), std::span<P1>(small)), "out", "one point per parameter");
  const std::vector<double> bad = {0.5, std::nan("")};
  EXPECT_INVALID_ARGUMENT(s.evaluate(std::span<const double>(bad), std::span<P1>(two)), "t", "");
}

// ---------------------------------------------------------------------------------------
// Issue 15: params and coordinates from 1e-300 to 1e300 (and near the largest double).

// Burden & Faires' natural spline through (1, 2), (2, 3), (3, 5), S0 = 2 + 3/4 (x-1) +
// 1/4 (x-1)^3, with params scaled by a and coordinates by b: C(1.5 a) = 2.40625 b,
// C' = 0.9375 b / a, C'' = 0.75 b / a^2 (checked where that is a normal double). The
// system is homogeneous in the spacings, and was solved unscaled: 2 (h + h) overflowed
// from 4.5e307 and h0 h0 underflowed below 1e-154.
TEST(CubicSpline, BurdenFairesAtAnyScale) {
  const std::pair<double, double> scales[] = {{1, 1},       {1e300, 1e300}, {1e-300, 1e-300}, {1e300, 1}, {1e-300, 1},
                                              {1, 1e300},   {1, 1e-300},    {1e154, 1e154},   {5e307, 1}, {1e-160, 1e-160}};
  for (const auto& [a, b] : scales) {
    for (auto bc : {SplineBoundary<double, 1>::natural(),
                    SplineBoundary<double, 1>::general({2, V1(0.0)}, {2, V1(0.0)})}) {  // natural twice: the fused and the general path
      const CubicSpline<double, 1> c({a, 2 * a, 3 * a}, ys({2 * b, 3 * b, 5 * b}), bc);
      // Relative: a few eps of the data (the scaling by a power of two is exact).
      EXPECT_NEAR(c(1.5 * a)[0], 2.40625 * b, 4e-16 * 5 * b) << a << " " << b;
      EXPECT_NEAR(c.derivative_at(1.5 * a)[0], 0.9375 * b / a, 4e-15 * b / a) << a << " " << b;
      const double second = 0.75 * b / a / a;
      if (std::isnormal(second)) {
        EXPECT_NEAR(c.derivative_at(1.5 * a, 2)[0], second, 4e-14 * second) << a << " " << b;
      }
    }
  }
}

// Not-a-knot and clamped splines reproduce a cubic: f(x) = x^3 - 2x + 1 at x = 0, 1, 2.5, 4, 5,
// scaled as above (f' given at the ends for clamped): C(a x) = b f(x).
TEST(CubicSpline, CubicsReproducedAtAnyScale) {
  const auto f = [](double x) { return x * x * x - 2 * x + 1; };
  const auto df = [](double x) { return 3 * x * x - 2; };
  const std::vector<double> x{0, 1, 2.5, 4, 5};
  for (const auto& [a, b] : {std::pair{1.0, 1.0}, {1e300, 1e300}, {1e-300, 1e-300}, {1e150, 1e-150}, {1e-200, 1e100}, {2e307, 1.0}}) {
    std::vector<double> u;
    std::vector<P1> P;
    for (double xi : x) {
      u.push_back(a * xi);
      P.emplace_back(b * f(xi));
    }
    for (auto bc : {SplineBoundary<double, 1>::not_a_knot(), SplineBoundary<double, 1>::clamped(V1(b * df(0) / a), V1(b * df(5) / a))}) {
      const CubicSpline<double, 1> c(u, P, bc);
      for (double xi : {0.5, 3.3, 4.9}) {
        // A few eps of max |f| = 116 at the data, times the system's small condition number.
        EXPECT_NEAR(c(a * xi)[0], b * f(xi), 1e-14 * 116 * b) << a << " " << b << " x=" << xi;
      }
    }
  }
}

// Params across the whole double range: 0, 1e308, 1.7e308 (the domain is a double; the
// spacings' sum 2 (h0 + h1) is not). The natural spline through (0, 0), (1, 1), (1.7, 0),
// by hand: M1 = 3 (d1 - d0) / (h0 + h1) with d0 = 1, d1 = -1 / 0.7, and on [0, 1]
// S(x) = (1 - M1 / 6) x + M1 x^3 / 6.
TEST(CubicSpline, ParamsAcrossTheDoubleRange) {
  const CubicSpline<double, 1> c({0, 1e308, 1.7e308}, ys({0, 1, 0}));
  const double M1 = 3 * (-1 / 0.7 - 1) / 1.7;
  const double x = 0.5;
  EXPECT_NEAR(c(x * 1e308)[0], (1 - M1 / 6) * x + M1 * x * x * x / 6, 1e-15);
  // A domain longer than the largest double: refused naming params (was "internal:
  // solve_tridiagonal: zero pivot").
  EXPECT_INVALID_ARGUMENT((CubicSpline<double, 1>({-1e308, 0, 1e308, 1.5e308}, ys({0, 1, 0, 2}))), "params", "longer than the largest double");
  EXPECT_INVALID_ARGUMENT((CubicSpline<double, 1>({-1e308, 0, 1e308, 1.5e308}, ys({0, 1, 0, 2}), SplineBoundary<double, 1>::not_a_knot())),
                          "params", "longer than the largest double");
  // Slopes that overflow: named points, not the tangents the user did not give.
  EXPECT_INVALID_ARGUMENT((CubicSpline<double, 1>({0, 1e-300, 2e-300}, ys({0, 1e300, 0}))), "points", "overflow");
  // Slopes that underflow (1e-200 / 1e200): refused, not rounded to 0 (the curve would
  // lose its shape), on the fused path (natural) and the general one (not-a-knot, 3 points).
  EXPECT_INVALID_ARGUMENT((CubicSpline<double, 1>({0, 1e200, 2e200, 3e200}, ys({0, 1e-200, 0, 1e-200}))), "points", "underflows");
  EXPECT_INVALID_ARGUMENT((CubicSpline<double, 1>({0, 1e200, 2e200}, ys({0, 1e-200, 0}), SplineBoundary<double, 1>::not_a_knot())),
                          "points", "underflows");
}

// Coordinates +-1e308 whose differences overflow: natural spline through (0, -1), (1, 1),
// (2, -1), (3, 1) scaled by 1e308, params by 1e300. By hand (antisymmetric about 1.5:
// M1 = -8, M2 = 8): S(x) = -1 + (10/3) x - (4/3) x^3 on [0, 1], S(0.5) = 0.5, S(1.5) = 0.
TEST(CubicSpline, CoordinatesNearTheLargestDouble) {
  const CubicSpline<double, 1> c({0, 1e300, 2e300, 3e300}, ys({-1e308, 1e308, -1e308, 1e308}));
  EXPECT_NEAR(c(0.5e300)[0], 0.5e308, 1e-15 * 1e308);
  EXPECT_NEAR(c(1.5e300)[0], 0, 1e-15 * 1e308);
  std::vector<P1> out(2);
  const std::vector<double> at{0.5e300, 2.5e300};
  c.evaluate_sorted(std::span<const double>(at), std::span<P1>(out));
  EXPECT_NEAR(out[0][0], 0.5e308, 1e-15 * 1e308);
  EXPECT_NEAR(out[1][0], -0.5e308, 1e-15 * 1e308);
  // S'(0.5) = 10/3 - 4 (0.25) = 7/3, times 1e308 / 1e300.
  EXPECT_NEAR(c.derivative_at(0.5e300)[0], 7.0 / 3 * 1e8, 1e-14 * 1e8);
}

// Every tangent rule reproduces a straight line; here one from -1e308 to 1e308 (so that
// P_(i+1) - P_(i-1) overflows), params scaled by 1e10 (slopes 2e298) and by 1e300.
TEST(TangentRules, LinesNearTheLargestDouble) {
  for (double a : {1e10, 1e300}) {
    const std::vector<double> u{0, 0.5 * a, a};
    const std::vector<P1> P = ys({-1e308, 0, 1e308});
    const std::vector<std::vector<V1>> rules{finite_difference_tangents(u, P), catmull_rom_tangents(u, P), cardinal_tangents(u, P, 0.0),
                                             kochanek_bartels_tangents(u, P, KochanekBartels<double>{}).outgoing, monotone_tangents(u, P),
                                             akima_tangents(u, P)};
    for (const auto& m : rules) {
      const Hermite<double, 1> h(u, P, m);
      // The slope 2e308 / a to a few eps (written 2 (1e308 / a): the constant 2e308 is
      // beyond the largest double); the points to a few eps of 1e308.
      const double slope = 2 * (1e308 / a);
      for (const V1& mi : m) EXPECT_NEAR(mi[0], slope, 1e-15 * slope) << a;
      EXPECT_NEAR(h(0.25 * a)[0], -0.5e308, 1e-15 * 1e308) << a;
      EXPECT_NEAR(h(0.75 * a)[0], 0.5e308, 1e-15 * 1e308) << a;
    }
  }
  // Slopes 2e308 / 1e-10 overflow: refused naming points.
  EXPECT_INVALID_ARGUMENT(finite_difference_tangents(std::vector<double>{0, 1e-10}, ys({-1e308, 1e308})), "points", "overflows");
}

}  // namespace
