// Batch evaluation (algo/evaluate.hpp) equals the scalar c(t) for every API: one curve
// into structure-of-arrays or array-of-points, many curves curve-major, cached or
// streaming stores, and from two threads writing disjoint outputs.
//
// The kernels are compiled once per instruction set (src/batch) and chosen at run time;
// KernelsProperty forces each one this machine can run through batch::select_isa and
// compares it with the scalar de Casteljau.
//
// Tolerance: degree <= 3 takes the power form with Horner's rule, whose coefficients reach
// 2^n max|P| (<= 8 here), so it differs from de Casteljau by a few eps of 8: 64 eps is
// the fast-path tolerance (docs/decisions/0003-batch-fast-path.md); above degree 3 the
// kernels take Bernstein-Horner (error a few eps of max|P|, tests/reference) or de
// Casteljau, within the same bound at these degrees (<= 30).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <thread>
#include <vector>

#include "../unit/test_support.hpp"
#include "generators.hpp"

namespace {

using namespace casteljau;
using casteljau::prop::eps;
constexpr double fast_path_tol = 64 * eps;


std::vector<double> params() {
  // 0..300 parameters: crosses the 64-parameter block boundary several times.
  return *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(*rc::gen::inRange(0, 301)), prop::parameter());
}

/// A parameter in [0, 1) with all 53 bits used, so that 1 - t is not exact for t < 1/2
/// (the grid parameters of prop::parameter() are multiples of 2^-20, where it is): a
/// 53-bit fraction times 0.7, rounded.
rc::Gen<double> full_parameter() {
  return rc::gen::map(rc::gen::arbitrary<std::uint64_t>(),
                      [](std::uint64_t x) { return static_cast<double>(x >> 11) * 0x1.0p-53 * 0.7; });
}

/// Selects an instruction set for the kernels for one scope, then restores the previous one.
class IsaScope {
 public:
  explicit IsaScope(batch::Isa isa) : previous_(batch::active_isa()), ok_(batch::select_isa(isa)) {}
  ~IsaScope() { batch::select_isa(previous_); }
  IsaScope(const IsaScope&) = delete;
  IsaScope& operator=(const IsaScope&) = delete;
  [[nodiscard]] bool ok() const { return ok_; }

 private:
  batch::Isa previous_;
  bool ok_;
};

constexpr batch::Isa all_isas[] = {batch::Isa::baseline, batch::Isa::avx2, batch::Isa::avx512};

/// The a-priori bound on |kernel - scalar de Casteljau| at parameter t, degree n: each is
/// within gamma_(3n) of sum_i |B_i(t)| |P_i| (de Casteljau: 2n roundings per path [Farin02];
/// Bernstein-Horner: n steps of a multiply-add plus the scaling, second-order corrected),
/// and sum_i |B_i(t)| = (|1 - t| + |t|)^n (1 in [0, 1], up to 3^n for extrapolation to
/// [-1, 2]). The power form at n <= 3 has coefficients up to 2^n max|P| instead: 64 eps
/// covers it. Doubling for the two errors: (8n + 64) eps (|1 - t| + |t|)^n max|P|.
double kernel_tolerance(int n, double t, double max_p) {
  return (8.0 * n + 64.0) * eps * std::pow(std::abs(1 - t) + std::abs(t), n) * max_p;
}

// Every instruction set's kernels, every method (power form n <= 3, Bernstein-Horner
// n <= bernstein_horner_max_degree, de Casteljau above and for t outside [0, 1]) against
// c(t); in the SoA overload (both stores) and the AoS one.
RC_GTEST_PROP(KernelsProperty, EveryInstructionSetEqualsScalar, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = *rc::gen::inRange(0, batch::bernstein_horner_max_degree + 12);
    const auto P = prop::control_points<D>(n);
    const Bezier<double, D> c(P);
    const double max_p = test::max_abs(P);
    // Grid parameters in [0, 1], full-precision ones, and for a third of the cases some in
    // [-1, 2] (the block containing them falls back to de Casteljau).
    auto ts = params();
    const auto full = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(*rc::gen::inRange(0, 150)), full_parameter());
    ts.insert(ts.end(), full.begin(), full.end());
    if (*rc::gen::inRange(0, 3) == 0) ts.push_back(*prop::coordinate(-1, 2));
    std::vector<Point<double, D>> expected(ts.size());
    for (std::size_t j = 0; j < ts.size(); ++j) expected[j] = c(ts[j]);
    for (const batch::Isa isa : all_isas) {
      const IsaScope scope(isa);
      if (!scope.ok()) continue;  // not compiled in or not supported by this CPU
      std::array<std::vector<double>, D> out;
      std::array<std::span<double>, D> spans;
      for (int d = 0; d < D; ++d) {
        out[d].assign(ts.size(), std::nan(""));
        spans[d] = out[d];
      }
      const Store store = *rc::gen::element(Store::cached, Store::streaming);
      evaluate(c, std::span<const double>(ts), spans, store);
      std::vector<Point<double, D>> aos(ts.size());
      evaluate(c, std::span<const double>(ts), std::span<Point<double, D>>(aos));
      for (std::size_t j = 0; j < ts.size(); ++j) {
        const double tol = kernel_tolerance(n, ts[j], max_p);
        for (int d = 0; d < D; ++d) {
          RC_ASSERT(std::abs(out[d][j] - expected[j][d]) <= tol);
          RC_ASSERT(std::abs(aos[j][d] - expected[j][d]) <= tol);
        }
      }
    }
  });
}

// The end points are exact (c(0) = P_0, c(1) = P_n) in every method and instruction set:
// de Casteljau's combinations reduce to copies there, and Bernstein-Horner computes
// s = 0, scale 1 and the first or last coefficient times C(n, 0) = 1.
RC_GTEST_PROP(KernelsProperty, EndPointsExact, ()) {
  const int n = *rc::gen::inRange(0, batch::bernstein_horner_max_degree + 12);
  const auto P = prop::control_points<2>(n);
  const Bezier<double, 2> c(P);
  const std::vector<double> ts{0.0, 1.0};
  for (const batch::Isa isa : all_isas) {
    const IsaScope scope(isa);
    if (!scope.ok()) continue;
    std::vector<double> x(2), y(2);
    evaluate(c, std::span<const double>(ts), {std::span<double>(x), std::span<double>(y)});
    RC_ASSERT(x[0] == P.front()[0]);
    RC_ASSERT(y[0] == P.front()[1]);
    RC_ASSERT(x[1] == P.back()[0]);
    RC_ASSERT(y[1] == P.back()[1]);
  }
}

TEST(KernelsDispatch, SelectsOnlyAvailableInstructionSets) {
  EXPECT_TRUE(batch::isa_available(batch::Isa::baseline));
  const batch::Isa best = batch::active_isa();
  EXPECT_TRUE(batch::isa_available(best));
  for (const batch::Isa isa : all_isas) {
    std::printf("kernels %s: %s\n", batch::isa_name(isa), batch::isa_available(isa) ? "available" : "not available");
    EXPECT_EQ(batch::select_isa(isa), batch::isa_available(isa));
    EXPECT_EQ(batch::active_isa(), batch::isa_available(isa) ? isa : batch::Isa::baseline);
    batch::select_isa(batch::Isa::baseline);
  }
  batch::select_isa(best);
  // The best available is chosen by default (checked against the CPU independently).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl")) {
    EXPECT_EQ(best, batch::Isa::avx512);
  } else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    EXPECT_EQ(best, batch::Isa::avx2);
  }
#endif
}

RC_GTEST_PROP(BatchProperty, SoAEqualsScalar, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = *rc::gen::inRange(0, 31);
    const Bezier<double, D> c(prop::control_points<D>(n));
    const auto ts = params();
    std::array<std::vector<double>, D> out;
    std::array<std::span<double>, D> spans;
    for (int d = 0; d < D; ++d) {
      out[d].assign(ts.size(), std::nan(""));
      spans[d] = out[d];
    }
    const Store store = *rc::gen::element(Store::automatic, Store::cached, Store::streaming);
    evaluate(c, std::span<const double>(ts), spans, store);
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const auto p = c(ts[j]);
      for (int d = 0; d < D; ++d) RC_ASSERT(std::abs(out[d][j] - p[d]) <= fast_path_tol);
    }
  });
}

RC_GTEST_PROP(BatchProperty, AoSEqualsScalar, ()) {
  prop::with_random_dimension([]<int D>() {
    const int n = *rc::gen::inRange(0, 31);
    const Bezier<double, D> c(prop::control_points<D>(n));
    const auto ts = params();
    std::vector<Point<double, D>> out(ts.size());
    evaluate(c, std::span<const double>(ts), std::span<Point<double, D>>(out));
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const auto p = c(ts[j]);
      for (int d = 0; d < D; ++d) RC_ASSERT(std::abs(out[j][d] - p[d]) <= fast_path_tol);
    }
  });
}

RC_GTEST_PROP(BatchProperty, ManyCurvesEqualScalar, ()) {
  prop::with_random_dimension([]<int D>() {
    const int k = *rc::gen::inRange(0, 6);
    std::vector<Bezier<double, D>> curves;
    for (int i = 0; i < k; ++i) curves.emplace_back(prop::control_points<D>(*rc::gen::inRange(0, 31)));
    const auto ts = params();
    std::array<std::vector<double>, D> out;
    std::array<std::span<double>, D> spans;
    for (int d = 0; d < D; ++d) {
      out[d].assign(curves.size() * ts.size(), std::nan(""));
      spans[d] = out[d];
    }
    const Store store = *rc::gen::element(Store::automatic, Store::cached, Store::streaming);
    evaluate(std::span<const Bezier<double, D>>(curves), std::span<const double>(ts), spans, store);
    for (std::size_t i = 0; i < curves.size(); ++i)
      for (std::size_t j = 0; j < ts.size(); ++j) {
        const auto p = curves[i](ts[j]);
        for (int d = 0; d < D; ++d) RC_ASSERT(std::abs(out[d][i * ts.size() + j] - p[d]) <= fast_path_tol);
      }
  });
}

// Extrapolation: parameters in [-1, 2] at degree <= 3 (Horner) agree with de Casteljau
// to the power form's conditioning there: |t|^j <= 8 times coefficients <= 8, so 64 * 8
// eps per term times 4 terms.
RC_GTEST_PROP(BatchProperty, ExtrapolationAtLowDegree, ()) {
  const int n = *rc::gen::inRange(0, 4);
  const Bezier<double, 2> c(prop::control_points<2>(n));
  const auto ts = *rc::gen::container<std::vector<double>>(70, prop::coordinate(-1, 2));
  std::vector<Point<double, 2>> out(ts.size());
  evaluate(c, std::span<const double>(ts), std::span<Point<double, 2>>(out));
  for (std::size_t j = 0; j < ts.size(); ++j) RC_ASSERT(test::max_coord_diff(out[j], c(ts[j])) <= 4 * 64 * 8 * eps);
}

// Two threads evaluate into disjoint halves of the same output arrays (the documented
// contract: pure functions over the caller's buffers). Fixed data, so a plain test.
TEST(BatchThreads, TwoThreadsDisjointOutputs) {
  test::SplitMix64 rng(7);
  std::vector<Bezier<double, 2>> curves;
  for (int i = 0; i < 40; ++i) curves.emplace_back(test::random_points<double, 2>(rng, 1 + i % 12, -1, 1));
  std::vector<double> ts(257);
  for (std::size_t j = 0; j < ts.size(); ++j) ts[j] = static_cast<double>(j) / 256;
  const std::size_t half = curves.size() / 2, per = ts.size();
  std::vector<double> x(curves.size() * per), y(curves.size() * per);
  std::vector<Point<double, 2>> aos(curves.size() * per);
  auto work = [&](std::size_t first, std::size_t count) {
    const std::span<const Bezier<double, 2>> mine(curves.data() + first, count);
    for (int rep = 0; rep < 5; ++rep) {
      evaluate(mine, std::span<const double>(ts),
               {std::span<double>(x.data() + first * per, count * per), std::span<double>(y.data() + first * per, count * per)});
      for (std::size_t i = 0; i < count; ++i)
        evaluate(curves[first + i], std::span<const double>(ts), std::span<Point<double, 2>>(aos.data() + (first + i) * per, per));
    }
  };
  std::thread a(work, 0, half), b(work, half, curves.size() - half);
  a.join();
  b.join();
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t j = 0; j < per; ++j) {
      const auto p = curves[i](ts[j]);
      ASSERT_LE(std::abs(x[i * per + j] - p[0]), fast_path_tol);
      ASSERT_LE(std::abs(y[i * per + j] - p[1]), fast_path_tol);
      ASSERT_LE(test::max_coord_diff(aos[i * per + j], p), fast_path_tol);
    }
}

// The generic fallback for any curve type is exactly c(t).
TEST(BatchThreads, GenericFallbackIsScalar) {
  const RationalBezier<double, 2> q({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1});
  std::vector<double> ts{0, 0.1, 0.5, 0.9, 1};
  std::vector<Point<double, 2>> out(ts.size());
  evaluate(q, std::span<const double>(ts), std::span<Point<double, 2>>(out));
  for (std::size_t j = 0; j < ts.size(); ++j) EXPECT_EQ(out[j], q(ts[j]));
}

}  // namespace
