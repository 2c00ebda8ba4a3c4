// Batch evaluation (algo/evaluate.hpp) equals the scalar c(t) for every API: one curve
// into structure-of-arrays or array-of-points, many curves curve-major, cached or
// streaming stores, and from two threads writing disjoint outputs.
//
// Tolerance: degree <= 3 takes the power form with Horner's rule, whose coefficients reach
// 2^n max|P| (<= 8 here), so it differs from de Casteljau by a few eps of 8: 64 eps is
// the fast-path tolerance (docs/decisions/0003-batch-fast-path.md); above degree 3 the
// kernel does de Casteljau's arithmetic, within the same bound.
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

#include "../unit/test_support.hpp"
#include "generators.hpp"

namespace {

using namespace casteljau;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double fast_path_tol = 64 * eps;


std::vector<double> params() {
  // 0..300 parameters: crosses the 64-parameter block boundary several times.
  return *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(*rc::gen::inRange(0, 301)), prop::parameter());
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
