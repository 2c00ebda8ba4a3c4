// Robustness at the edges of floating point (issue 5, sections 3 and 5): extrapolation
// far outside the domain, derivative order 0, rational curves with extreme weights,
// high-degree bounds, flattening of huge and tiny curves, numerical honesty of the basis
// kernels, closed operations and printing.

// Evaluating a curve must not need Eigen's Cholesky module (degree reduction moved to
// algo/reduce.hpp): the curve headers alone must not pull it in.
#include "casteljau/curves/rational_bezier.hpp"
#ifdef EIGEN_CHOLESKY_MODULE_H
#error "curves/bezier.hpp or curves/rational_bezier.hpp includes <Eigen/Cholesky>"
#endif

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <numbers>
#include <sstream>
#include <vector>

#include "test_support.hpp"

// Allocation counting for the no-allocation claim of rational evaluation: the global
// operator new is replaced for this executable (every non-aligned form, so that memory
// from any of them, e.g. std::stable_sort's nothrow buffer, meets the matching delete:
// ASan checks the pairing); it counts only while `counting` is set.
// g++ 12 inlines the replacement pair and then misreports free() of operator new's
// memory as a mismatch; it is malloc/free on both sides.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace
void* operator new(std::size_t n) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace casteljau {
namespace {

using P1 = Point<double, 1>;
using P2 = Point<double, 2>;
using B1 = Bezier<double, 1>;
using B2 = Bezier<double, 2>;
using R1 = RationalBezier<double, 1>;
using R2 = RationalBezier<double, 2>;
constexpr double eps = std::numeric_limits<double>::epsilon();

#define EXPECT_INVALID_ARGUMENT_AT(expr, where_, fragment)                                   \
  do {                                                                                       \
    try {                                                                                    \
      (void)(expr);                                                                          \
      ADD_FAILURE() << #expr " did not throw";                                               \
    } catch (const InvalidArgument& e) {                                                     \
      EXPECT_EQ(e.where(), where_) << e.what();                                              \
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();        \
    }                                                                                        \
  } while (0)

// --- 1. extrapolation far outside [0, 1] -----------------------------------------------

// The cubic with 1-D points 0, 1, 2, 3 is the line 3t (its Bernstein coefficients are
// those of an elevated line). Its value is exactly representable at every t below; de
// Casteljau's lerps gave 0 at 1e103 and NaN at 1e200.
TEST(Extrapolation, ElevatedLineIsExactFarAway) {
  const B1 c{P1(0.0), P1(1.0), P1(2.0), P1(3.0)};
  for (double t : {1e103, 1e200, -1e200, 1e300, -7.5, 12345.0}) {
    EXPECT_EQ(c(t)[0], 3 * t) << t;
    EXPECT_EQ(c.derivative_at(t, 1)[0], 3.0) << t;
    EXPECT_EQ(c.derivative_at(t, 2)[0], 0.0) << t;
  }
}

// A value that overflows is bad input naming t, never inf or NaN.
TEST(Extrapolation, NotRepresentableThrowsNamingT) {
  const B1 cube{P1(0.0), P1(0.0), P1(0.0), P1(1.0)};  // t^3
  EXPECT_NEAR(cube(1e100)[0], 1e300, 4 * eps * 1e300);  // two roundings of the Horner steps
  EXPECT_INVALID_ARGUMENT_AT(cube(1e103), "t", "not representable");
  EXPECT_INVALID_ARGUMENT_AT(cube(-1e200), "t", "not representable");
  EXPECT_INVALID_ARGUMENT_AT(cube.derivative_at(1e200, 1), "t", "not representable");
  const R1 r({P1(0.0), P1(0.0), P1(1e300)}, {1, 1, 1});  // 1e300 t^2 / 1
  EXPECT_INVALID_ARGUMENT_AT(r(1e10), "t", "not representable");
}

// Independent oracle: de Casteljau in long double (64-bit significand, 2^-11 of double's
// eps) on the same double inputs. Its own error is eps_ld max|P| (1 + 2 d)^n, 2048 times
// below the bound asserted, so it resolves the double error. Measured worst case over
// these curves: 0.85 eps max|P| (1 + 2d)^n (docs/accuracy.md); 4 eps leaves rounding
// slack across compilers.
long double de_casteljau_ld(std::vector<long double> w, long double t) {
  for (std::size_t r = 1; r < w.size(); ++r)
    for (std::size_t i = 0; i + r < w.size(); ++i) w[i] = (1 - t) * w[i] + t * w[i + 1];
  return w[0];
}

TEST(Extrapolation, ErrorGrowthAgainstLongDoubleOracle) {
  test::SplitMix64 rng(2026);
  for (int n : {3, 5, 10, 20}) {
    for (double d : {0.1, 1.0, 10.0, 100.0, 1e4, 1e8}) {
      for (int trial = 0; trial < 5; ++trial) {
        const auto P = test::random_points<double, 1>(rng, n);
        std::vector<long double> L(P.size());
        for (std::size_t i = 0; i < P.size(); ++i) L[i] = P[i][0];
        const B1 c(P);
        for (int k = 0; k < 40; ++k) {
          const double s = d * rng.uniform();
          const double t = k % 2 ? 1 + s : -s;
          const long double ref = de_casteljau_ld(L, t);
          const double bound = 4 * eps * std::pow(1 + 2 * std::abs(k % 2 ? t - 1 : t), n);
          EXPECT_LE(std::abs(static_cast<long double>(c(t)[0]) - ref), bound) << n << " " << t;
        }
      }
    }
  }
}

// Rational curves far outside: the exact quarter circle extends to the whole unit circle
// (minus one point), so |R(t)| = 1 at every t; R(t) = 3t / (1 + 2t) (points 0, 1,
// weights 1, 3) tends to 3/2, and R'(t) = 3 / (1 + 2t)^2.
TEST(Extrapolation, RationalFarOutside) {
  const auto arc = R2::circular_arc(P2(0, 0), 1.0, 0.0, std::numbers::pi / 2);
  for (double t : {1e200, -1e200, 1e10, -3.0, 7.0, 1e300}) {
    const auto p = arc(t);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 4 * eps) << t;
  }
  const R1 q({P1(0.0), P1(1.0)}, {1, 3});
  for (double t : {1e100, -1e100, 1e200, 1e15, -1e15}) {
    EXPECT_NEAR(q(t)[0], 3 * t / (1 + 2 * t), 4 * eps) << t;
  }
  for (double t : {1e100, -1e50, 1e10, 3.0}) {
    const double expected = 3 / ((1 + 2 * t) * (1 + 2 * t));
    EXPECT_NEAR(q.derivative_at(t, 1)[0], expected, 8 * eps * expected) << t;
  }
  // The pole at t = -1/2 is still reported.
  EXPECT_INVALID_ARGUMENT_AT(q(-0.5), "t", "pole");
}

// --- 2. derivative order 0 is the point --------------------------------------------------

TEST(DerivativeOrderZero, IsThePointAsAVector) {
  const B2 c{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const R2 r({{0, 0}, {1, 2}, {3, 2}}, {1, 2, 1});
  for (double t : {0.0, 0.3, 1.0, -2.0, 5.0}) {
    EXPECT_EQ(c.derivative_at(t, 0), c(t).to_vector()) << t;
    EXPECT_EQ(r.derivative_at(t, 0), r(t).to_vector()) << t;
  }
  EXPECT_EQ(c.derivative(0), c);
  EXPECT_INVALID_ARGUMENT_AT(c.derivative_at(0.5, -1), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT_AT(r.derivative_at(0.5, -1), "k", ">= 0");
}

// --- 3. rational curves --------------------------------------------------------------------

// (a) Evaluation up to degree 15 uses stack buffers only.
TEST(Rational, EvaluationDoesNotAllocate) {
  test::SplitMix64 rng(5);
  const auto P = test::random_points<double, 3>(rng, 15);
  std::vector<double> w(P.size());
  for (auto& x : w) x = rng.uniform(0.5, 2);
  const RationalBezier<double, 3> r(P, w);
  double sink = 0;
  allocations = 0;
  counting = true;
  for (int k = 0; k <= 100; ++k) sink += r(k / 100.0)[0];
  counting = false;
  EXPECT_EQ(allocations.load(), 0);
  EXPECT_TRUE(std::isfinite(sink));
}

// (b) Equal weights give the polynomial curve, even when they are subnormal (5e-324 is
// the smallest positive double): no false pole, same points as the Bézier curve.
TEST(Rational, EqualSubnormalWeightsAreThePolynomialCurve) {
  const std::vector<P2> P{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const B2 c(P);
  const R2 r(P, {5e-324, 5e-324, 5e-324, 5e-324});
  for (double t : {0.0, 0.25, 0.5, 0.9, 1.0, -1.0, 3.0}) {
    // The rational de Casteljau steps with equal weights are the same lerps (ratio
    // b / (a + b) = t up to one rounding): a few eps of max |P| = 4; outside [0, 1] the
    // error bound of docs/accuracy.md at distance 2, degree 3.
    const double tol = (t >= 0 && t <= 1) ? 8 * 4 * eps : 4 * eps * 4 * 125;
    EXPECT_LE(test::max_coord_diff(r(t), c(t)), tol) << t;
    EXPECT_LE(test::max_coord_diff(P2::from_vector(r.derivative_at(t, 1)), P2::from_vector(c.derivative_at(t, 1))), 64 * tol) << t;
  }
  const auto br = bounds(r), bc = bounds(c);
  EXPECT_LE(test::max_coord_diff(br.lo, bc.lo), 64 * 4 * eps);
  EXPECT_LE(test::max_coord_diff(br.hi, bc.hi), 64 * 4 * eps);
}

// (c) Weights 1..1e300 with finite points: w P would overflow (1e300 * 1e10); the
// operations work with normalised weights and give finite results on the same curve.
TEST(Rational, HugeWeightRangeSplitsAndElevates) {
  const R2 r({{0, 0}, {1e10, 1e10}, {2e10, 0}, {3e10, 5e9}}, {1, 1e300, 1e150, 1});
  const auto s = r.split(0.5);
  const auto e = r.elevate(3);
  const auto p = r.portion(0.25, 0.75);
  for (double t : {0.0, 0.1, 0.5, 0.9, 1.0}) {
    const double scale = 3e10;
    // Convex steps: a few eps of the coordinates, 64 eps leaves room for the weight ratios.
    EXPECT_LE(test::max_coord_diff(s.left(t), r(t / 2)), 64 * eps * scale) << t;
    EXPECT_LE(test::max_coord_diff(s.right(t), r(0.5 + t / 2)), 64 * eps * scale) << t;
    EXPECT_LE(test::max_coord_diff(e(t), r(t)), 64 * eps * scale) << t;
    EXPECT_LE(test::max_coord_diff(p(t), r(0.25 + t / 2)), 64 * eps * scale) << t;
  }
  // Weights spanning more than the floating point range cannot be normalised: reported.
  EXPECT_INVALID_ARGUMENT_AT(R2({{0, 0}, {1, 1}}, {1e300, 1e-300}), "weights[1]", "range");
}

// (d) Elevation by r at once equals r single elevations (both the unique degree-(n+r)
// representation), with weights spanning 1e-8..1e8. Each single step is a convex
// combination with error ~eps, so r steps drift by ~r eps (2.7e-15 measured); the
// direct formula must match to 1e-14 of the curve's size (was 2.4e-10).
TEST(Rational, ElevationByManyAtOnceIsAccurate) {
  const R2 r({{0, 0}, {1, 3}, {2, -1}, {4, 2}, {5, 0}}, {1e-8, 1e8, 1, 1e4, 1e-3});
  const auto once = r.elevate(300);
  auto steps = r;
  for (int i = 0; i < 300; ++i) steps = steps.elevate(1);
  ASSERT_EQ(once.degree(), 304);
  double worst = 0;
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    worst = std::max(worst, test::max_coord_diff(once(t), steps(t)));
    worst = std::max(worst, test::max_coord_diff(once(t), r(t)));
  }
  EXPECT_LE(worst, 1e-14 * 5);  // curve size 5
}

// (e) bounds of high-degree rational curves: the Bernstein product's binomials used to
// overflow at degree ~518 ("c[341]: value must be finite, got -nan"). The quarter
// circle's box is [0, 1]^2 at every degree.
TEST(Rational, BoundsAtDegreeOneThousand) {
  const auto arc = R2::circular_arc(P2(0, 0), 1.0, 0.0, std::numbers::pi / 2);
  for (int r : {600, 998}) {
    const auto e = arc.elevate(r);
    const auto b = bounds(e);
    for (int d = 0; d < 2; ++d) {
      // End points exact up to the elevation's rounding (a few hundred eps at worst).
      EXPECT_NEAR(b.lo[d], 0.0, 1e-12) << r;
      EXPECT_NEAR(b.hi[d], 1.0, 1e-12) << r;
    }
  }
}

// The Bernstein product beyond degree 1029 (where C(m+n, k) overflows): the product of
// 1 (all coefficients 1) with itself is 1.
TEST(Rational, BernsteinProductHighDegree) {
  const std::vector<double> ones(700, 1.0);
  const auto h = bernstein_product<double>(ones, ones);
  ASSERT_EQ(h.size(), 1399u);
  for (double x : h) EXPECT_NEAR(x, 1.0, 1e-13);
}

// --- 5. flatten with huge and tiny coordinates --------------------------------------------

// Distance from p to the polyline, computed on coordinates divided by `scale` (an
// independent, scale-safe helper).
double scaled_polyline_distance(const P2& p, const std::vector<P2>& poly, double scale) {
  std::vector<P2> q(poly.size());
  for (std::size_t i = 0; i < poly.size(); ++i) q[i] = P2(poly[i][0] / scale, poly[i][1] / scale);
  return test::polyline_distance(P2(p[0] / scale, p[1] / scale), q);
}

TEST(Flatten, HugeCoordinatesStayWithinTolerance) {
  const double s = 1e155;
  const B2 parabola{{1 * s, 0}, {1.5 * s, 1 * s}, {2 * s, 0}};
  const double tol = 1e150;
  const auto poly = flatten(parabola, tol);
  EXPECT_GT(poly.size(), 2u);  // was a single chord 5e4 tolerances away
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    // 1e-12 relative: the distance helper's own rounding on unit-scaled data.
    EXPECT_LE(scaled_polyline_distance(parabola(t), poly, s), tol / s * (1 + 1e-12)) << t;
  }
  const auto arc = R2::circular_arc(P2(0, 0), 1e200, 0.0, std::numbers::pi / 2);
  const auto apoly = flatten(arc, 1e195);
  EXPECT_GT(apoly.size(), 2u);
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    EXPECT_LE(scaled_polyline_distance(arc(t), apoly, 1e200), 1e-5 * (1 + 1e-12)) << t;
  }
}

// Scaling a curve and its tolerance by 2^k scales the polyline by exactly 2^k (same
// vertex count), for k from tiny (1e-300) to huge (1e300) coordinates.
TEST(Flatten, PowerOfTwoScalingIsExact) {
  const std::vector<P2> P{{1, 0}, {1.5, 1}, {2, 0.25}, {3, -1}};
  const B2 unit(P);
  const auto arc = R2::circular_arc(P2(0.5, 0.25), 1.0, 0.0, std::numbers::pi / 2);
  const double tol = 1e-7;
  const auto ref = flatten(unit, tol);
  const auto aref = flatten(arc, tol);
  for (int k : {-1000, -997, -531, -100, 1, 100, 500, 990}) {
    std::vector<P2> Q(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) Q[i] = P2(std::ldexp(P[i][0], k), std::ldexp(P[i][1], k));
    const auto poly = flatten(B2(Q), std::ldexp(tol, k));
    ASSERT_EQ(poly.size(), ref.size()) << k;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      EXPECT_EQ(poly[i][0], std::ldexp(ref[i][0], k)) << k << " " << i;
      EXPECT_EQ(poly[i][1], std::ldexp(ref[i][1], k)) << k << " " << i;
    }
    const auto sarc = arc.transform(Affine<double, 2>::scale(std::ldexp(1.0, k)));
    EXPECT_EQ(flatten(sarc, std::ldexp(tol, k)).size(), aref.size()) << k;
  }
}

// Tiny curves: 1e-300 with tolerance 1e-307 took 11 s and ~1e7 vertices, 1e-160 died
// of bad_alloc; they flatten as the unit curve does (4,097 vertices at 1e-7).
TEST(Flatten, TinyCoordinatesBehaveAsUnitOnes) {
  const B2 unit{{1, 0}, {1.5, 1}, {2, 0}};
  const auto n_unit = flatten(unit, 1e-7).size();
  for (double s : {1e-160, 1e-300}) {
    const B2 tiny{{1 * s, 0}, {1.5 * s, 1 * s}, {2 * s, 0}};
    EXPECT_NEAR(static_cast<double>(flatten(tiny, 1e-7 * s).size()), static_cast<double>(n_unit), 2.0) << s;
  }
  // A tolerance whose ratio to the extent is below the normal range is reported.
  const B2 c{{0, 0}, {1e300, 1e300}, {2e300, 0}};
  EXPECT_THROW((void)flatten(c, 1e-10), NumericalError);
}

// --- 6. numerical honesty of the basis ------------------------------------------------------

TEST(Honesty, IntervalAndBoxInvariants) {
  EXPECT_INVALID_ARGUMENT_AT((Interval<double>(2, 1)), "interval", "lo <= hi");
  EXPECT_INVALID_ARGUMENT_AT((Interval<double>(std::nan(""), 1)), "interval.lo", "finite");
  EXPECT_INVALID_ARGUMENT_AT((Box<double, 2>(P2(0, 1), P2(1, 0))), "box", "lo <= hi");
  EXPECT_TRUE((Box<double, 2>().empty()));
  const Box<double, 2> unit_box(P2(0, 0), P2(1, 1));
  EXPECT_FALSE(unit_box.empty());
}

TEST(Honesty, BasisKernelsCheckPreconditions) {
  const std::vector<double> none;
  const std::vector<double> c{1, 2, 3};
  std::vector<double> l(3), r(2);
  EXPECT_INVALID_ARGUMENT_AT((de_casteljau<double, double>(none, 0.5)), "c", "at least one");
  EXPECT_INVALID_ARGUMENT_AT((de_casteljau<double, double>(c, std::nan(""))), "t", "finite");
  EXPECT_INVALID_ARGUMENT_AT((de_casteljau_split<double, double>(c, 0.5, l, r)), "right", "3 entries");
  const std::vector<double> u{0.5};
  EXPECT_INVALID_ARGUMENT_AT((blossom<double, double>(c, u)), "u", "2 parameters");
}

// Binomials that do not fit a double are reported, never returned as infinity (C(1029,
// 514) ~ 1.4e308 is the last middle entry that fits).
TEST(Honesty, BinomialOverflowIsReported) {
  EXPECT_TRUE(std::isfinite(binomial<double>(1029, 514)));
  EXPECT_INVALID_ARGUMENT_AT(binomial<double>(2000, 1000), "n", "exceeds the floating point range");
  EXPECT_INVALID_ARGUMENT_AT(binomial_row<double>(1100), "n", "C(1100, 550) exceeds the floating point range");
}

// bernstein_all is O(n) without overflow at any degree: the values at degree 2000 sum to
// 1 (partition of unity; relative error ~4n eps per value).
TEST(Honesty, BernsteinAllHighDegree) {
  for (int n : {3, 100, 2000}) {
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
      const auto b = bernstein_all(n, t);
      double s = 0;
      for (double x : b) {
        EXPECT_TRUE(std::isfinite(x));
        s += x;
      }
      EXPECT_NEAR(s, 1.0, 8 * n * eps) << n << " " << t;
    }
  }
  // Against the textbook values at degree 3.
  const auto b = bernstein_all(3, 0.25);
  EXPECT_NEAR(b[0], 27.0 / 64, 4 * eps);
  EXPECT_NEAR(b[1], 27.0 / 64, 4 * eps);
  EXPECT_NEAR(b[2], 9.0 / 64, 4 * eps);
  EXPECT_NEAR(b[3], 1.0 / 64, 4 * eps);
}

// --- 7. closed operations -------------------------------------------------------------------

TEST(ClosedOperations, OverflowIsReportedNamingTheArgument) {
  const B2 c{{0, 0}, {1e308, 1e308}, {1.5e308, 0}};
  EXPECT_INVALID_ARGUMENT_AT(c.transform(Affine<double, 2>::scale(4.0)), "m", "not representable");
  EXPECT_INVALID_ARGUMENT_AT(c.portion(0, 1e10), "b", "not representable");
  const R2 r({{0, 0}, {1e308, 1e308}, {1.5e308, 0}}, {1, 2, 1});
  EXPECT_INVALID_ARGUMENT_AT(r.transform(Affine<double, 2>::scale(4.0)), "m", "not representable");
  // Operations that only take convex combinations stay finite.
  const auto s = c.split(0.3);
  EXPECT_TRUE(test::all_finite(s.left(0.5)));
  EXPECT_EQ(c.reverse().reverse(), c);
  EXPECT_EQ(c.elevate(5).degree(), 7);
}

// --- 8. printing ----------------------------------------------------------------------------

TEST(Printing, ShortestRoundTrip) {
  const B2 c{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  std::ostringstream os;
  os << c(0.5) << ' ' << Vector<double, 2>(0.1, -1) << ' ' << bounds(c) << ' ' << Interval<double>(0, 1) << ' '
     << Box<double, 2>();
  EXPECT_EQ(os.str(), "(2, 1.5) (0.1, -1) [(0, 0), (4, 1.5)] [0, 1] [empty]");
}

}  // namespace
// Batch evaluation agrees with c(t) outside [0, 1] too: the kernels' plain de Casteljau
// would overflow there (3t at t = 1e200 gave NaN); such parameters go through c(t),
// which is exact for this curve (3t: all Taylor terms beyond the first vanish) or
// throws naming t[j].
TEST(BatchExtrapolation, FarOutsideTheDomainMatchesScalarEvaluation) {
  const Bezier<double, 1> c({Point<double, 1>(0.0), Point<double, 1>(1.0), Point<double, 1>(2.0), Point<double, 1>(3.0)});
  const std::vector<double> ts{0.5, 1e103, -1e200, 2.0, 1e300};
  std::vector<double> x(ts.size());
  evaluate(c, std::span<const double>(ts), std::array<std::span<double>, 1>{std::span<double>(x)});
  EXPECT_EQ(x, (std::vector<double>{1.5, 3e103, -3e200, 6.0, 3e300}));
  std::vector<Point<double, 1>> aos(ts.size());
  evaluate(c, std::span<const double>(ts), std::span<Point<double, 1>>(aos));
  for (std::size_t j = 0; j < ts.size(); ++j) EXPECT_EQ(aos[j][0], x[j]);
  const std::vector<double> over{0.25, 1e308};
  std::vector<double> y(2);
  EXPECT_INVALID_ARGUMENT(evaluate(c, std::span<const double>(over), std::array<std::span<double>, 1>{std::span<double>(y)}), "t[1]",
                          "not representable");
}

}  // namespace casteljau
