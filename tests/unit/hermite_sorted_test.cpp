// The sorted batch evaluate_sorted of Hermite curves (and so of cubic splines) against one
// call operator() per query, bit for bit, at its edge cases: queries before the first and
// after the last param, exactly at params, runs of equal queries, steps of many pieces
// between queries (the counting merge's fallback loop), batches shorter than its four runs
// and lengths that are not multiples of its chunks, one-sided tangents, unsorted input;
// and its errors: a non-finite query anywhere, an overflowing point; other scalar types.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "casteljau/basis/batch.hpp"
#include "random_interp_data.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P1 = Point<double, 1>;
using P2 = Point<double, 2>;
using V1 = Vector<double, 1>;
using V2 = Vector<double, 2>;

/// Finite-difference tangents through test::random_interp_data: n pieces.
Hermite<double, 1> random_curve(std::size_t n, std::mt19937_64& rng) {
  const auto [u, P] = test::random_interp_data(n, rng);
  return Hermite<double, 1>(u, P, finite_difference_tangents(u, P));
}

/// evaluate_sorted(q) into caller storage equals h(q[k]) at every k, bit for bit.
template <class H>
void expect_batch_equals_pointwise(const H& h, const std::vector<double>& q, const char* what) {
  std::vector<typename H::PointType> out(q.size());
  h.evaluate_sorted(std::span<const double>(q), std::span<typename H::PointType>(out));
  for (std::size_t k = 0; k < q.size(); ++k) ASSERT_EQ(out[k], h(q[k])) << what << ": query " << k << " of " << q.size() << " at " << q[k];
}

TEST(HermiteSorted, EdgeCasesEqualOneCallPerQuery) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const std::size_t n : {1, 2, 3, 4, 5, 7, 8, 9, 63, 64, 65, 300}) {
    const Hermite<double, 1> h = random_curve(n, rng);
    const auto& u = h.params();
    const double a = u.front(), b = u.back();
    // Outside the domain, every param exactly, a run of 9 equal queries at a param and
    // inside a piece, four queries in most pieces.
    std::vector<double> q = {a - 5, a - 1, std::nextafter(a, -1e9), b + 1, b + 100, std::nextafter(b, 1e9)};
    for (const double x : u) q.push_back(x);
    for (int r = 0; r < 9; ++r) q.push_back(u[n / 2]);
    for (int r = 0; r < 9; ++r) q.push_back((u[0] + u[1]) / 2);
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 4; ++r) q.push_back(u[i] + (u[i + 1] - u[i]) * U(rng));
    std::sort(q.begin(), q.end());
    // Every length up to 13 (fewer queries than runs, and tails), and longer ones around
    // four runs of 64 (the chunk) plus a tail.
    for (std::size_t len = 0; len <= std::min<std::size_t>(13, q.size()); ++len)
      expect_batch_equals_pointwise(h, std::vector<double>(q.begin(), q.begin() + static_cast<std::ptrdiff_t>(len)), "prefix");
    for (const std::size_t len : {255, 256, 257, 259, 263, 513, 1000})
      if (len <= q.size()) expect_batch_equals_pointwise(h, std::vector<double>(q.end() - static_cast<std::ptrdiff_t>(len), q.end()), "suffix");
    expect_batch_equals_pointwise(h, q, "all");
    // Sparse queries: steps of 1 to 11 pieces between neighbours (the merge counts up to
    // 4 at once and then loops), at params and just before them.
    std::vector<double> sparse;
    for (std::size_t i = 0, step = 1; i <= n; i += step, step = step % 11 + 1) {
      sparse.push_back(std::nextafter(u[i], -1e9));
      sparse.push_back(u[i]);
    }
    expect_batch_equals_pointwise(h, sparse, "sparse");
    // Unsorted queries are still answered (by a binary search where one goes backwards).
    std::vector<double> shuffled = q;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    expect_batch_equals_pointwise(h, shuffled, "shuffled");
  }
}

// The points at the params are the given points, exactly (h00, h01 are exactly 0 and 1
// there): an oracle that does not go through operator().
TEST(HermiteSorted, ExactAtTheParams) {
  std::mt19937_64 rng(45);
  const Hermite<double, 1> h = random_curve(1000, rng);
  const std::vector<P1> at = h.evaluate_sorted(std::span<const double>(h.params()));
  for (std::size_t i = 0; i < at.size(); ++i) EXPECT_EQ(at[i], h.points()[i]) << i;
}

// One-sided tangents (the incoming ones differ) in the plane.
TEST(HermiteSorted, OneSidedTangentsInThePlane) {
  std::vector<double> u;
  std::vector<P2> P;
  std::vector<V2> in, out;
  for (int i = 0; i <= 40; ++i) {
    u.push_back(i * 0.75 + (i % 3) * 0.2);
    P.emplace_back(std::cos(i), std::sin(2.0 * i));
    in.emplace_back(1.0 + i, -0.5 * i);
    out.emplace_back(-1.0 + 0.25 * i, 2.0);
  }
  const Hermite<double, 2> h(u, P, in, out);
  ASSERT_TRUE(h.one_sided());
  std::vector<double> q;
  for (int k = -20; k <= 700; ++k) q.push_back(k * 0.05);
  expect_batch_equals_pointwise(h, q, "one-sided");
}

// A non-finite query is refused naming "t" wherever it is: the first query, inside each of
// the four runs, in the tail after them; in short and long batches.
TEST(HermiteSorted, NonFiniteQueryRefused) {
  std::mt19937_64 rng(46);
  const Hermite<double, 1> h = random_curve(50, rng);
  for (const std::size_t len : {1, 3, 4, 7, 300, 1003}) {
    std::vector<double> q(len);
    for (std::size_t k = 0; k < len; ++k) q[k] = -3 + 40.0 * static_cast<double>(k) / static_cast<double>(len);
    std::vector<P1> out(len);
    for (const std::size_t at : {std::size_t{0}, len / 4, std::min(len / 2 + 1, len - 1), 3 * len / 4, len - 1}) {
      for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
        std::vector<double> b = q;
        b[at] = bad;
        EXPECT_INVALID_ARGUMENT(h.evaluate_sorted(std::span<const double>(b), std::span<P1>(out)), "t", "finite");
      }
    }
  }
}

// A point that overflows (extrapolation far outside the domain of huge data) is refused as
// operator() refuses it, naming "t".
TEST(HermiteSorted, OverflowRefused) {
  const Hermite<double, 1> h({0, 1, 2}, {P1(1e300), P1(-1e300), P1(1e300)}, {V1(1e300), V1(0.0), V1(1e300)});
  const double far = 1e10;
  EXPECT_INVALID_ARGUMENT((void)h(far), "t", "overflows");
  std::vector<double> q = {0.5, 1.5, far};
  std::vector<P1> out(q.size());
  EXPECT_INVALID_ARGUMENT(h.evaluate_sorted(std::span<const double>(q), std::span<P1>(out)), "t", "overflows");
  q = {-far, 0.5, 1, 1.5, 2};
  out.resize(q.size());
  EXPECT_INVALID_ARGUMENT(h.evaluate_sorted(std::span<const double>(q), std::span<P1>(out)), "t", "overflows");
}

// float and long double take the header's portable kernel (src/hermite compiles double
// only): both compile, and the batch equals operator() and the points at the params.
template <class T>
void expect_scalar_type_works() {
  const std::vector<T> u = {0, 1, 2.5, 3, 4.25, 6};
  std::vector<Point<T, 2>> P;
  std::vector<Vector<T, 2>> m;
  for (int i = 0; i < 6; ++i) {
    P.emplace_back(T(i % 3), T(i * i) / 7);
    m.emplace_back(T(1), T(-i));
  }
  const Hermite<T, 2> h(u, P, m);
  std::vector<T> q;
  for (int k = -10; k <= 70; ++k) q.push_back(T(k) / 10);
  std::vector<Point<T, 2>> out(q.size());
  h.evaluate_sorted(std::span<const T>(q), std::span<Point<T, 2>>(out));
  for (std::size_t k = 0; k < q.size(); ++k) EXPECT_EQ(out[k], h(q[k])) << k;
  for (std::size_t i = 0; i < u.size(); ++i) EXPECT_EQ(h(u[i]), P[i]) << i;
}

TEST(HermiteSorted, FloatAndLongDouble) {
  expect_scalar_type_works<float>();
  expect_scalar_type_works<long double>();
}

/// A Hermite<T, D> through n + 1 points with one-sided tangents (a corner at every
/// third param), from one seed: the same values at double and long double.
template <class T, int D>
Hermite<T, D> random_one_sided(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<T> u(n + 1);
  std::vector<Point<T, D>> P(n + 1);
  std::vector<Vector<T, D>> in(n + 1), out(n + 1);
  double x = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    u[i] = T(x);
    x += 0.25 + (U(rng) + 1);
    for (int d = 0; d < D; ++d) {
      P[i][d] = T(U(rng));
      out[i][d] = T(2 * U(rng));
      in[i][d] = i % 3 == 0 ? T(2 * U(rng)) : out[i][d];
    }
  }
  return Hermite<T, D>(u, P, in, out);
}

struct HermiteIsaRestore {
  batch::Isa saved = batch::active_isa();
  ~HermiteIsaRestore() { batch::select_isa(saved); }
};

/// For double at dimension D (src/hermite's compiled kernels): in every instruction set
/// this machine runs, operator(), evaluate and evaluate_sorted give the same bits, and
/// the same as in the first set; the values are those of the header's portable kernel at
/// long double within 1e-13 (an evaluation that shares no code with the compiled one).
template <int D>
void expect_compiled_kernels_agree() {
  const Hermite<double, D> h = random_one_sided<double, D>(700, 50 + D);
  const Hermite<long double, D> hl = random_one_sided<long double, D>(700, 50 + D);
  ASSERT_TRUE(h.one_sided());
  std::mt19937_64 rng(60 + D);
  const double a = h.params().front(), b = h.params().back();
  std::uniform_real_distribution<double> U(a - 2, b + 2);
  std::vector<double> q(2003);
  for (double& x : q) x = U(rng);
  for (std::size_t i = 0; i < h.params().size(); i += 7) q.push_back(h.params()[i]);
  std::vector<double> sorted = q;
  std::sort(sorted.begin(), sorted.end());
  HermiteIsaRestore restore;
  std::vector<Point<double, D>> first;
  for (const batch::Isa isa : {batch::Isa::baseline, batch::Isa::avx2, batch::Isa::avx512}) {
    if (!batch::isa_available(isa)) continue;
    ASSERT_TRUE(batch::select_isa(isa));
    std::vector<Point<double, D>> one(q.size()), random(q.size()), in_order(q.size());
    for (std::size_t k = 0; k < q.size(); ++k) one[k] = h(q[k]);
    h.evaluate(std::span<const double>(q), std::span<Point<double, D>>(random));
    h.evaluate_sorted(std::span<const double>(sorted), std::span<Point<double, D>>(in_order));
    ASSERT_EQ(random, one) << batch::isa_name(isa) << " D " << D;
    for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(in_order[k], h(sorted[k])) << batch::isa_name(isa) << " D " << D << " " << k;
    if (first.empty()) first = one;
    ASSERT_EQ(one, first) << batch::isa_name(isa) << " D " << D;
  }
  for (std::size_t k = 0; k < q.size(); ++k) {
    const Point<long double, D> r = hl(static_cast<long double>(q[k]));
    for (int d = 0; d < D; ++d) EXPECT_NEAR(first[k][d], static_cast<double>(r[d]), 1e-13 * (1 + std::abs(static_cast<double>(r[d])))) << k;
  }
}

TEST(HermiteSorted, CompiledKernelsAgreeInEveryInstructionSet) {
  expect_compiled_kernels_agree<1>();
  expect_compiled_kernels_agree<2>();
  expect_compiled_kernels_agree<3>();
  expect_compiled_kernels_agree<4>();
}

// Dimension 5 is past the compiled kernels (1..4): the portable kernel, batch and
// pointwise still equal.
TEST(HermiteSorted, PortableKernelAtDimensionFive) {
  const Hermite<double, 5> h = random_one_sided<double, 5>(100, 70);
  std::vector<double> q;
  for (int k = -20; k <= 2000; ++k) q.push_back(k * 0.1);
  expect_batch_equals_pointwise(h, q, "D 5");
  std::vector<Point<double, 5>> random(q.size());
  std::shuffle(q.begin(), q.end(), std::mt19937_64(71));
  h.evaluate(std::span<const double>(q), std::span<Point<double, 5>>(random));
  for (std::size_t k = 0; k < q.size(); ++k) ASSERT_EQ(random[k], h(q[k])) << k;
}

}  // namespace
