// W7 of docs/performance.md: a bicubic B-spline (and NURBS) surface of 50 x 50 control
// points evaluated on a 1000 x 1000 grid and at 10^6 random (u, v), against OCCT
// (Geom_BSplineSurface::D0, GeomAdaptor_Surface::D0: its span cache kept while u and v
// stay in one span) and SISL (s1421, the previous spans kept between calls) in the same
// run. Names W7/<library>/<method>/<bspline|nurbs>/<grid|random>; one iteration evaluates
// all 10^6 points. Counter max_abs_diff: the largest coordinate difference from the
// reference (de Boor in long double, written here).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "casteljau/surfaces/surface_batch.hpp"
#include "common.hpp"

#if CASTELJAU_BENCH_HAVE_OCCT
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pnt.hxx>
#endif
#if CASTELJAU_BENCH_HAVE_SISL
#include <sisl.h>
#endif

namespace {

constexpr int n = 50, degree = 3, side = 1000;
constexpr std::size_t count = std::size_t(side) * side;

/// The workload's inputs (seed 7): heights, then weights, then the random pairs.
struct W7Data {
  std::vector<std::array<double, 3>> P;  // P[i * n + j], i along u
  std::vector<double> w;
  std::vector<double> knots;  // 54: 0 x4, 1/47 .. 46/47, 1 x4 (both directions)
  std::vector<double> grid;   // k / 999
  std::vector<std::array<double, 2>> random;
  std::vector<double> reference[2][2];  // [rational][random]
  casteljau::detail::SurfaceForm<double> form[2];

  W7Data() : P(n * n), w(n * n), grid(side), random(count) {
    bench::SplitMix64 rng(7);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) P[std::size_t(i * n + j)] = {i / 49.0, j / 49.0, rng.uniform()};
    for (auto& x : w) x = 0.5 + rng.uniform();
    for (auto& uv : random) {
      uv[0] = rng.uniform();
      uv[1] = rng.uniform();
    }
    for (int k = 0; k < side; ++k) grid[std::size_t(k)] = k / 999.0;
    knots.assign(4, 0.0);
    for (int k = 1; k <= 46; ++k) knots.push_back(k / 47.0);
    knots.insert(knots.end(), 4, 1.0);
    for (const int r : {0, 1}) {
      auto& f = form[r];
      f.p = f.q = degree;
      f.U = f.V = knots;
      f.rows = f.cols = n;
      f.rational = r == 1;
      f.dim = r ? 4 : 3;
      for (std::size_t k = 0; k < P.size(); ++k) {
        f.P.insert(f.P.end(), P[k].begin(), P[k].end());
        if (r) f.P.push_back(w[k]);
      }
      for (const int rnd : {0, 1}) {
        auto& ref = reference[r][rnd];
        ref.resize(3 * count);
        for (std::size_t k = 0; k < count; ++k) {
          const double u = rnd ? random[k][0] : grid[k / side], v = rnd ? random[k][1] : grid[k % side];
          de_boor(u, v, r == 1, &ref[3 * k]);
        }
      }
    }
  }

  /// The span s (3 <= s <= 49) with U_s <= t < U_s+1 (the last at t = 1), and the four
  /// basis functions by the Cox-de Boor recursion, in long double.
  void basis(long double t, int& s, long double N[4]) const {
    s = 3;
    while (s < 49 && knots[std::size_t(s) + 1] <= t) ++s;
    long double left[4], right[4];
    N[0] = 1;
    for (int j = 1; j <= 3; ++j) {
      left[j] = t - knots[std::size_t(s + 1 - j)];
      right[j] = knots[std::size_t(s + j)] - t;
      long double saved = 0;
      for (int r = 0; r < j; ++r) {
        const long double temp = N[r] / (right[r + 1] + left[j - r]);
        N[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      N[j] = saved;
    }
  }

  void de_boor(double u, double v, bool rational, double* out) const {
    int su = 0, sv = 0;
    long double Nu[4], Nv[4];
    basis(u, su, Nu);
    basis(v, sv, Nv);
    long double x[4] = {0, 0, 0, 0};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const std::size_t k = std::size_t((su - 3 + a) * n + (sv - 3 + b));
        const long double c = Nu[a] * Nv[b] * (rational ? w[k] : 1.0L);
        for (int d = 0; d < 3; ++d) x[d] += c * P[k][std::size_t(d)];
        x[3] += c;
      }
    for (int d = 0; d < 3; ++d) out[d] = static_cast<double>(rational ? x[d] / x[3] : x[d]);
  }
};

const W7Data& data() {
  static const W7Data d;
  return d;
}

using Eval = std::function<void(bool rational, bool random, double* out)>;

void run(benchmark::State& state, bool rational, bool random, const Eval& eval) {
  const W7Data& d = data();
  bench::Buffer<double> out(3 * count);
  for (auto _ : state) {
    eval(rational, random, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  double diff = 0;
  const auto& ref = d.reference[rational][random];
  for (std::size_t k = 0; k < 3 * count; ++k) diff = std::max(diff, std::abs(out[k] - ref[k]));
  state.counters["max_abs_diff"] = diff;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * std::int64_t(count)));
}

/// Ours: evaluate_grid on the grid (each row's and column's basis once), evaluate_points
/// on the random pairs.
void casteljau_batch(bool rational, bool random, double* out) {
  const W7Data& d = data();
  if (random) casteljau::detail::evaluate_points<double>(d.form[rational], d.random, out);
  else casteljau::detail::evaluate_grid<double>(d.form[rational], d.grid, d.grid, out);
}

/// Ours, pair by pair (evaluate_points) on the grid as well: what a caller without the
/// grid's structure gets.
void casteljau_points(bool rational, bool random, double* out) {
  const W7Data& d = data();
  if (random) {
    casteljau::detail::evaluate_points<double>(d.form[rational], d.random, out);
    return;
  }
  static const std::vector<std::array<double, 2>> pairs = [&] {
    std::vector<std::array<double, 2>> p(count);
    for (std::size_t k = 0; k < count; ++k) p[k] = {d.grid[k / side], d.grid[k % side]};
    return p;
  }();
  casteljau::detail::evaluate_points<double>(d.form[rational], pairs, out);
}

#if CASTELJAU_BENCH_HAVE_OCCT
Handle(Geom_BSplineSurface) occt_surface(bool rational) {
  const W7Data& d = data();
  TColgp_Array2OfPnt poles(1, n, 1, n);
  TColStd_Array2OfReal weights(1, n, 1, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto& p = d.P[std::size_t(i * n + j)];
      poles(i + 1, j + 1) = gp_Pnt(p[0], p[1], p[2]);
      weights(i + 1, j + 1) = d.w[std::size_t(i * n + j)];
    }
  TColStd_Array1OfReal knots(1, 48);
  TColStd_Array1OfInteger mults(1, 48);
  for (int i = 0; i < 48; ++i) {
    knots(i + 1) = d.knots[std::size_t(i) + 3];
    mults(i + 1) = (i == 0 || i == 47) ? 4 : 1;
  }
  if (rational) return new Geom_BSplineSurface(poles, weights, knots, knots, mults, mults, degree, degree);
  return new Geom_BSplineSurface(poles, knots, knots, mults, mults, degree, degree);
}

template <class F>
void occt_loop(bool random, double* out, F&& d0) {
  const W7Data& d = data();
  gp_Pnt p;
  for (std::size_t k = 0; k < count; ++k) {
    const double u = random ? d.random[k][0] : d.grid[k / side], v = random ? d.random[k][1] : d.grid[k % side];
    d0(u, v, p);
    out[3 * k] = p.X();
    out[3 * k + 1] = p.Y();
    out[3 * k + 2] = p.Z();
  }
}

void occt_bspline_d0(bool rational, bool random, double* out) {
  static const Handle(Geom_BSplineSurface) s[2] = {occt_surface(false), occt_surface(true)};
  const Handle(Geom_BSplineSurface)& c = s[rational];
  occt_loop(random, out, [&](double u, double v, gp_Pnt& p) { c->D0(u, v, p); });
}

void occt_adaptor_d0(bool rational, bool random, double* out) {
  static const Handle(Geom_BSplineSurface) s[2] = {occt_surface(false), occt_surface(true)};
  const GeomAdaptor_Surface a(s[rational]);  // its span cache starts empty in every iteration
  occt_loop(random, out, [&](double u, double v, gp_Pnt& p) { a.D0(u, v, p); });
}
#endif

#if CASTELJAU_BENCH_HAVE_SISL
SISLSurf* sisl_surface(bool rational) {
  const W7Data& d = data();
  // SISL: vertices with the first parameter's index running fastest; rational ones in
  // homogeneous form (w x, w y, w z, w).
  static std::vector<double> knots = d.knots;
  std::vector<double> coef;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto& p = d.P[std::size_t(i * n + j)];
      const double w = rational ? d.w[std::size_t(i * n + j)] : 1.0;
      coef.insert(coef.end(), {w * p[0], w * p[1], w * p[2]});
      if (rational) coef.push_back(w);
    }
  return newSurf(n, n, degree + 1, degree + 1, knots.data(), knots.data(), coef.data(), rational ? 2 : 1, 3, 1);
}

void sisl_s1421(bool rational, bool random, double* out) {
  static SISLSurf* s[2] = {sisl_surface(false), sisl_surface(true)};
  const W7Data& d = data();
  int left1 = 0, left2 = 0, stat = 0;
  double normal[3];
  for (std::size_t k = 0; k < count; ++k) {
    double par[2] = {random ? d.random[k][0] : d.grid[k / side], random ? d.random[k][1] : d.grid[k % side]};
    s1421(s[rational], 0, par, &left1, &left2, out + 3 * k, normal, &stat);
    if (stat < 0) throw std::runtime_error("s1421 failed");
  }
}
#endif

void reg(const std::string& name, void (*eval)(bool, bool, double*)) {
  for (const bool rational : {false, true})
    for (const bool random : {false, true}) {
      benchmark::RegisterBenchmark((name + (rational ? "/nurbs" : "/bspline") + (random ? "/random" : "/grid")).c_str(),
                                   [rational, random, eval](benchmark::State& st) { run(st, rational, random, eval); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
}

}  // namespace

int main(int argc, char** argv) {
  reg("W7/casteljau/batch", casteljau_batch);
  reg("W7/casteljau/points", casteljau_points);
#if CASTELJAU_BENCH_HAVE_OCCT
  reg("W7/occt/Geom_BSplineSurface_D0", occt_bspline_d0);
  reg("W7/occt/GeomAdaptor_Surface_D0", occt_adaptor_d0);
#endif
#if CASTELJAU_BENCH_HAVE_SISL
  reg("W7/sisl/s1421", sisl_s1421);
#endif
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
