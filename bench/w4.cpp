// W4 of docs/performance.md: a natural cubic spline through 10^6 points, built
// and evaluated at 10^6 random and 10^6 sorted queries, against GSL's gsl_spline (cspline)
// in the same run. Names W4/<library>/build, W4/<library>/eval_random, W4/<library>/eval_sorted;
// one iteration builds the whole spline or evaluates all 10^6 queries. Our eval_random is
// the batch call evaluate(q, out); W4/casteljau/eval_random_single is one s(q) per query. Eval rows report
// max_abs_diff: the largest difference from GSL's values (0 for GSL itself; -1 without GSL).
// scipy (optional in the workload) is not run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"

// Our spline comes from the interpolating-curves work (issue 6); without it only GSL runs.
#if __has_include("casteljau/curves/cubic_spline.hpp")
#include "casteljau/curves/cubic_spline.hpp"
#define CASTELJAU_BENCH_HAVE_CUBIC_SPLINE 1
#else
#define CASTELJAU_BENCH_HAVE_CUBIC_SPLINE 0
#endif

#if CASTELJAU_BENCH_HAVE_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_spline.h>
#endif

namespace {

/// The workload's inputs (seed 4, the workload's number): x_0 = 0, x_i = x_(i-1) + 0.5 +
/// uniform() for i = 1..n-1; then y_i = uniform() for i = 0..n-1; then 10^6 queries
/// q = x_0 + (x_(n-1) - x_0) uniform(). Sorted: the same queries in ascending order.
struct W4Data {
  static constexpr std::size_t n = 1'000'000;
  static constexpr std::size_t queries = 1'000'000;
  std::vector<double> x, y, random, sorted;
  std::vector<double> gsl_random, gsl_sorted;  // GSL's values, the check of the other rows

  W4Data() : x(n), y(n), random(queries) {
    bench::SplitMix64 rng(4);
    x[0] = 0;
    for (std::size_t i = 1; i < n; ++i) x[i] = x[i - 1] + 0.5 + rng.uniform();
    for (auto& v : y) v = rng.uniform();
    for (auto& q : random) q = x[0] + (x[n - 1] - x[0]) * rng.uniform();
    sorted = random;
    std::sort(sorted.begin(), sorted.end());
  }
  const std::vector<double>& params(bool is_sorted) const { return is_sorted ? sorted : random; }
};

W4Data& data() {
  static W4Data d;
  return d;
}

#if CASTELJAU_BENCH_HAVE_GSL
/// A natural cubic spline by GSL, kept for the evaluation rows and the reference values.
gsl_spline* gsl_built() {
  static gsl_spline* s = [] {
    const W4Data& d = data();
    gsl_spline* sp = gsl_spline_alloc(gsl_interp_cspline, W4Data::n);
    if (gsl_spline_init(sp, d.x.data(), d.y.data(), W4Data::n) != GSL_SUCCESS) throw std::runtime_error("gsl_spline_init failed");
    return sp;
  }();
  return s;
}

void gsl_eval(const std::vector<double>& q, std::vector<double>& out) {
  gsl_spline* s = gsl_built();
  gsl_interp_accel* acc = gsl_interp_accel_alloc();  // a fresh accelerator in every repetition
  for (std::size_t k = 0; k < q.size(); ++k) out[k] = gsl_spline_eval(s, q[k], acc);
  gsl_interp_accel_free(acc);
}

/// GSL's values at both query sets, computed once before any timing.
void gsl_reference() {
  W4Data& d = data();
  d.gsl_random.resize(W4Data::queries);
  d.gsl_sorted.resize(W4Data::queries);
  gsl_eval(d.random, d.gsl_random);
  gsl_eval(d.sorted, d.gsl_sorted);
}

void gsl_build(benchmark::State& state) {
  const W4Data& d = data();
  for (auto _ : state) {
    gsl_spline* s = gsl_spline_alloc(gsl_interp_cspline, W4Data::n);
    if (gsl_spline_init(s, d.x.data(), d.y.data(), W4Data::n) != GSL_SUCCESS) throw std::runtime_error("gsl_spline_init failed");
    benchmark::DoNotOptimize(s);
    gsl_spline_free(s);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * W4Data::n));
}
#endif

#if CASTELJAU_BENCH_HAVE_CUBIC_SPLINE
using Spline = casteljau::CubicSpline<double, 1>;
using P1 = casteljau::Point<double, 1>;

/// The data values as the 1-D points the spline takes, made once.
const std::vector<P1>& y_points() {
  static const std::vector<P1> P = [] {
    std::vector<P1> v(W4Data::n);
    for (std::size_t i = 0; i < W4Data::n; ++i) v[i][0] = data().y[i];
    return v;
  }();
  return P;
}

/// casteljau::CubicSpline with natural ends; the constructor takes its params and points by
/// value, so each build copies them (as gsl_spline_init copies x and y).
void casteljau_build(benchmark::State& state) {
  const W4Data& d = data();
  const auto& P = y_points();
  for (auto _ : state) {
    const Spline s(d.x, P, Spline::Boundary::natural());
    benchmark::DoNotOptimize(&s);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * W4Data::n));
}

const Spline& casteljau_built() {
  static const Spline s(data().x, y_points(), Spline::Boundary::natural());
  return s;
}

/// One call s(q) per query (binary search for the piece).
void casteljau_eval_random(const std::vector<double>& q, std::vector<double>& out) {
  const Spline& s = casteljau_built();
  for (std::size_t k = 0; k < q.size(); ++k) out[k] = s(q[k])[0];
}

/// The sorted batch: evaluate_sorted (a linear merge of the queries with the params) into
/// the caller's storage, as GSL's rows write into `out` (a 1-D point is one double).
void casteljau_eval_sorted(const std::vector<double>& q, std::vector<double>& out) {
  static_assert(sizeof(P1) == sizeof(double));
  static std::vector<P1> points(W4Data::queries);
  casteljau_built().evaluate_sorted(std::span<const double>(q), std::span<P1>(points));
  for (std::size_t k = 0; k < q.size(); ++k) out[k] = points[k][0];
}

/// The random batch: evaluate (groups of 16 queries searched side by side, their memory
/// waits overlapped) into the caller's storage.
void casteljau_eval_random_batch(const std::vector<double>& q, std::vector<double>& out) {
  static std::vector<P1> points(W4Data::queries);
  casteljau_built().evaluate(std::span<const double>(q), std::span<P1>(points));
  for (std::size_t k = 0; k < q.size(); ++k) out[k] = points[k][0];
}
#endif

/// Runs one evaluation method: eval(queries, out) fills out, then out is compared with GSL.
void run_eval(benchmark::State& state, bool is_sorted, const std::function<void(const std::vector<double>&, std::vector<double>&)>& eval) {
  const W4Data& d = data();
  const auto& q = d.params(is_sorted);
  std::vector<double> out(q.size());
  for (auto _ : state) {
    eval(q, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  const auto& ref = is_sorted ? d.gsl_sorted : d.gsl_random;
  double diff = ref.empty() ? -1 : 0;
  for (std::size_t k = 0; k < ref.size(); ++k) diff = std::max(diff, std::abs(out[k] - ref[k]));
  state.counters["max_abs_diff"] = diff;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * q.size()));
}

void reg_eval(const std::string& name, bool is_sorted, void (*eval)(const std::vector<double>&, std::vector<double>&)) {
  benchmark::RegisterBenchmark(name.c_str(), [is_sorted, eval](benchmark::State& st) { run_eval(st, is_sorted, eval); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

}  // namespace

int main(int argc, char** argv) {
#if CASTELJAU_BENCH_HAVE_CUBIC_SPLINE
  benchmark::RegisterBenchmark("W4/casteljau/build", casteljau_build)->Unit(benchmark::kMillisecond)->UseRealTime();
  reg_eval("W4/casteljau/eval_random", false, casteljau_eval_random_batch);
  reg_eval("W4/casteljau/eval_random_single", false, casteljau_eval_random);
  reg_eval("W4/casteljau/eval_sorted", true, casteljau_eval_sorted);
#endif
#if CASTELJAU_BENCH_HAVE_GSL
  benchmark::RegisterBenchmark("W4/gsl/build", gsl_build)->Unit(benchmark::kMillisecond)->UseRealTime();
  reg_eval("W4/gsl/eval_random", false, gsl_eval);
  reg_eval("W4/gsl/eval_sorted", true, gsl_eval);
#endif
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
#if CASTELJAU_BENCH_HAVE_GSL
  gsl_reference();
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
