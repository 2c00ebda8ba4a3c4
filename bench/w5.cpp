// W5 of docs/performance.md: a clamped uniform cubic B-spline in 3-D with 1000
// control points evaluated at 10^6 sorted and 10^6 random parameters, against OCCT
// (Geom_BSplineCurve::D0, GeomAdaptor_Curve::D0), SISL (s1221) and GSL (bspline basis +
// dot product) in the same run. Names W5/<library>/<method>/<sorted|random>; one iteration
// evaluates all 10^6 parameters. Counter max_abs_diff: the largest coordinate difference
// from the reference (our binary search + de Boor, BSpline::operator()).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/algo/span_table.hpp"
#include "casteljau/curves/bspline.hpp"
#include "common.hpp"

#if CASTELJAU_BENCH_HAVE_OCCT
#include <Geom_BSplineCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Pnt.hxx>
#endif
#if CASTELJAU_BENCH_HAVE_SISL
#include <sisl.h>
#endif
#if CASTELJAU_BENCH_HAVE_GSL
#include <gsl/gsl_bspline.h>
#include <gsl/gsl_vector.h>
#endif

namespace {

using P3 = casteljau::Point<double, 3>;
// Our methods write points straight into the workload's interleaved xyz output.
static_assert(sizeof(P3) == 3 * sizeof(double) && std::is_standard_layout_v<P3>);

/// The workload's inputs (seed 5, the workload's number, as for W1 and W2).
struct W5Data {
  static constexpr int n = 1000;
  static constexpr int degree = 3;
  static constexpr std::size_t count = 1'000'000;
  std::vector<P3> P;
  std::vector<double> knots;  // 1004: 0 x4, 1/997 .. 996/997, 1 x4
  std::vector<double> random, sorted;
  std::vector<P3> reference_random, reference_sorted;

  W5Data() : P(n), random(count), sorted(count) {
    bench::SplitMix64 rng(5);
    for (auto& p : P)
      for (int d = 0; d < 3; ++d) p[d] = rng.uniform();
    for (auto& u : random) u = rng.uniform();
    for (std::size_t k = 0; k < count; ++k) sorted[k] = static_cast<double>(k) / static_cast<double>(count - 1);
    knots.assign(4, 0.0);
    for (int i = 1; i <= 996; ++i) knots.push_back(i / 997.0);
    knots.insert(knots.end(), 4, 1.0);
    const casteljau::BSpline<double, 3> c(degree, knots, P);
    for (const double u : random) reference_random.push_back(c(u));
    for (const double u : sorted) reference_sorted.push_back(c(u));
  }
  const std::vector<double>& params(bool is_sorted) const { return is_sorted ? sorted : random; }
  const std::vector<P3>& reference(bool is_sorted) const { return is_sorted ? reference_sorted : reference_random; }
};

const W5Data& data() {
  static const W5Data d;
  return d;
}

/// Runs one method: eval(params, out) fills out (xyz interleaved, 3 doubles per point).
void run(benchmark::State& state, bool is_sorted, const std::function<void(std::span<const double>, double*)>& eval) {
  const W5Data& d = data();
  const auto& u = d.params(is_sorted);
  bench::Buffer<double> out(3 * u.size());
  for (auto _ : state) {
    eval(u, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  double diff = 0;
  const auto& ref = d.reference(is_sorted);
  for (std::size_t j = 0; j < u.size(); ++j)
    for (int k = 0; k < 3; ++k) diff = std::max(diff, std::abs(out[3 * j + std::size_t(k)] - ref[j][k]));
  state.counters["max_abs_diff"] = diff;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * u.size()));
}

void casteljau_span_table(std::span<const double> u, double* out) {
  // The table is built in every iteration (about 1000 pieces), as a caller evaluating a
  // fresh curve pays it.
  const W5Data& d = data();
  const casteljau::BSpline<double, 3> c(W5Data::degree, d.knots, d.P);
  casteljau::evaluate_pieces(c, u, std::span<P3>(reinterpret_cast<P3*>(out), u.size()));
}

void casteljau_de_boor(std::span<const double> u, double* out) {
  const W5Data& d = data();
  const casteljau::BSpline<double, 3> c(W5Data::degree, d.knots, d.P);
  for (std::size_t j = 0; j < u.size(); ++j) {
    const P3 p = c(u[j]);
    for (int k = 0; k < 3; ++k) out[3 * j + std::size_t(k)] = p[k];
  }
}

#if CASTELJAU_BENCH_HAVE_OCCT
Handle(Geom_BSplineCurve) occt_curve() {
  const W5Data& d = data();
  TColgp_Array1OfPnt poles(1, W5Data::n);
  for (int i = 0; i < W5Data::n; ++i) poles(i + 1) = gp_Pnt(d.P[std::size_t(i)][0], d.P[std::size_t(i)][1], d.P[std::size_t(i)][2]);
  TColStd_Array1OfReal knots(1, 998);
  TColStd_Array1OfInteger mults(1, 998);
  for (int i = 0; i < 998; ++i) {
    knots(i + 1) = d.knots[std::size_t(i) + 3];
    mults(i + 1) = (i == 0 || i == 997) ? 4 : 1;
  }
  return new Geom_BSplineCurve(poles, knots, mults, W5Data::degree);
}

void occt_bspline_d0(std::span<const double> u, double* out) {
  static const Handle(Geom_BSplineCurve) c = occt_curve();
  gp_Pnt p;
  for (std::size_t j = 0; j < u.size(); ++j) {
    c->D0(u[j], p);
    out[3 * j] = p.X();
    out[3 * j + 1] = p.Y();
    out[3 * j + 2] = p.Z();
  }
}

void occt_adaptor_d0(std::span<const double> u, double* out) {
  static const Handle(Geom_BSplineCurve) c = occt_curve();
  const GeomAdaptor_Curve a(c);  // its per-span cache starts empty in every iteration
  gp_Pnt p;
  for (std::size_t j = 0; j < u.size(); ++j) {
    a.D0(u[j], p);
    out[3 * j] = p.X();
    out[3 * j + 1] = p.Y();
    out[3 * j + 2] = p.Z();
  }
}
#endif

#if CASTELJAU_BENCH_HAVE_SISL
void sisl_s1221(std::span<const double> u, double* out) {
  const W5Data& d = data();
  static std::vector<double> knots = d.knots, coef = [&] {
    std::vector<double> c;
    for (const auto& p : d.P) c.insert(c.end(), {p[0], p[1], p[2]});
    return c;
  }();
  static SISLCurve* curve = newCurve(W5Data::n, W5Data::degree + 1, knots.data(), coef.data(), 1, 3, 1);
  int left = 0, stat = 0;
  for (std::size_t j = 0; j < u.size(); ++j) {
    s1221(curve, 0, u[j], &left, out + 3 * j, &stat);
    if (stat < 0) throw std::runtime_error("s1221 failed");
  }
}
#endif

#if CASTELJAU_BENCH_HAVE_GSL
void gsl_bspline(std::span<const double> u, double* out) {
  const W5Data& d = data();
  static gsl_bspline_workspace* w = [] {
    gsl_bspline_workspace* ws = gsl_bspline_alloc(4, 998);
    gsl_vector* breaks = gsl_vector_alloc(998);
    for (std::size_t i = 0; i < 998; ++i) gsl_vector_set(breaks, i, data().knots[i + 3]);
    gsl_bspline_knots(breaks, ws);
    gsl_vector_free(breaks);
    return ws;
  }();
  static gsl_vector* B = gsl_vector_alloc(4);
  for (std::size_t j = 0; j < u.size(); ++j) {
    std::size_t first = 0, last = 0;
    gsl_bspline_eval_nonzero(u[j], B, &first, &last, w);
    double x = 0, y = 0, z = 0;
    for (std::size_t i = first; i <= last; ++i) {
      const double b = gsl_vector_get(B, i - first);
      x += b * d.P[i][0];
      y += b * d.P[i][1];
      z += b * d.P[i][2];
    }
    out[3 * j] = x;
    out[3 * j + 1] = y;
    out[3 * j + 2] = z;
  }
}
#endif

void reg(const std::string& name, void (*eval)(std::span<const double>, double*)) {
  for (const bool is_sorted : {true, false}) {
    benchmark::RegisterBenchmark((name + (is_sorted ? "/sorted" : "/random")).c_str(),
                                 [is_sorted, eval](benchmark::State& st) { run(st, is_sorted, eval); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

}  // namespace

int main(int argc, char** argv) {
  reg("W5/casteljau/span_table", casteljau_span_table);
  reg("W5/casteljau/de_boor", casteljau_de_boor);
#if CASTELJAU_BENCH_HAVE_OCCT
  reg("W5/occt/Geom_BSplineCurve_D0", occt_bspline_d0);
  reg("W5/occt/GeomAdaptor_Curve_D0", occt_adaptor_d0);
#endif
#if CASTELJAU_BENCH_HAVE_SISL
  reg("W5/sisl/s1221", sisl_s1221);
#endif
#if CASTELJAU_BENCH_HAVE_GSL
  reg("W5/gsl/bspline_eval_nonzero", gsl_bspline);
#endif
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
