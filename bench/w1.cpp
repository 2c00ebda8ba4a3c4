// W1 of docs/performance.md: 1000 cubics x 10^4 parameters (10^7 points),
// curve-major, against memset of the same output size and against the peers.
// Names: W1/<library>/<variant>; counters: max_abs_diff (vs own scalar de Casteljau),
// items_per_second (points/s). Built twice: -O3 -march=native and -O2 generic.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

// The ceiling kernels are compiled in both builds, with function-level target attributes
// (the generic build's x86-64 baseline has neither AVX2 nor AVX-512), and run where the CPU
// has the instructions.
#if defined(__x86_64__) || defined(__i386__)
#define CASTELJAU_BENCH_W1_X86 1
#include <immintrin.h>
#else
#define CASTELJAU_BENCH_W1_X86 0
#endif

#include "casteljau/algo/evaluate.hpp"
#include "casteljau/curves/bezier.hpp"
#include "common.hpp"

#if CASTELJAU_BENCH_HAVE_2GEOM
#include <2geom/bezier-curve.h>
#include <2geom/bezier.h>
#endif
#if CASTELJAU_BENCH_HAVE_OCCT
#include <BSplCLib.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <PLib.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Pnt2d.hxx>
#endif

namespace {

using P2 = casteljau::Point<double, 2>;
using Curve = casteljau::Bezier<double, 2>;
constexpr std::size_t N = bench::W1Data::points;
constexpr std::size_t M = bench::W1Data::params;

/// Inputs, curve objects and the three output arrays (AoS, SoA x, SoA y), all allocated
/// and pre-faulted once; ref is the own scalar de Casteljau result (AoS).
struct W1 {
  bench::W1Data data;
  std::vector<Curve> curves;
  bench::Buffer<double> aos{2 * N}, x{N}, y{N}, ref{2 * N};

  W1() {
    curves.reserve(data.curves);
    for (const auto& c : data.P) curves.emplace_back(std::vector<P2>(c.begin(), c.end()));
    for (std::size_t i = 0; i < data.curves; ++i)
      for (std::size_t j = 0; j < M; ++j) {
        const P2 p = curves[i](data.ts[j]);
        ref[2 * (i * M + j)] = p[0];
        ref[2 * (i * M + j) + 1] = p[1];
      }
  }
  static W1& get() {
    static W1 w;
    return w;
  }
  double diff_aos() const {
    double e = 0;
    for (std::size_t k = 0; k < 2 * N; ++k) e = std::max(e, std::abs(aos[k] - ref[k]));
    return e;
  }
  double diff_soa() const {
    double e = 0;
    for (std::size_t k = 0; k < N; ++k) e = std::max({e, std::abs(x[k] - ref[2 * k]), std::abs(y[k] - ref[2 * k + 1])});
    return e;
  }
};

void finish(benchmark::State& state, double diff) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * N));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * N * 2 * sizeof(double)));
  state.counters["max_abs_diff"] = diff;
}

// ---- the machine's write bandwidth ----

void memset_output(benchmark::State& state) {
  W1& w = W1::get();
  int v = 0;
  for (auto _ : state) {
    std::memset(w.aos.data(), ++v & 0xff, 2 * N * sizeof(double));
    benchmark::ClobberMemory();
  }
  finish(state, 0);
}

void memcpy_output(benchmark::State& state) {
  W1& w = W1::get();
  for (auto _ : state) {
    std::memcpy(w.aos.data(), w.ref.data(), 2 * N * sizeof(double));
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

/// A plain loop of regular stores (the compiler vectorises it).
void store_loop(benchmark::State& state) {
  W1& w = W1::get();
  double v = 0;
  for (auto _ : state) {
    v += 1;
    double* __restrict o = w.aos.data();
    for (std::size_t k = 0; k < 2 * N; ++k) o[k] = v;
    benchmark::ClobberMemory();
  }
  finish(state, 0);
}

// ---- casteljau ----

/// The one-curve SoA overload called once per curve: with Store::automatic each call
/// (160 KB) stays below the streaming threshold, so this shows what the threshold costs a
/// caller who loops over curves himself.
void casteljau_per_curve_soa(benchmark::State& state, casteljau::Store store) {
  W1& w = W1::get();
  const std::span<const double> ts(w.data.ts);
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.curves.size(); ++i)
      casteljau::evaluate(w.curves[i], ts, std::array<std::span<double>, 2>{std::span(w.x.data() + i * M, M), std::span(w.y.data() + i * M, M)},
                          store);
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_soa());
}

void casteljau_batch_soa(benchmark::State& state, casteljau::Store store) {
  W1& w = W1::get();
  const std::span<const Curve> curves(w.curves);
  const std::span<const double> ts(w.data.ts);
  for (auto _ : state) {
    casteljau::evaluate(curves, ts, std::array<std::span<double>, 2>{std::span(w.x.data(), N), std::span(w.y.data(), N)}, store);
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_soa());
}

/// batch_soa with the kernels of one instruction set forced (the generic build chooses the
/// best at run time; these rows show what each would give), then the choice restored.
void casteljau_batch_soa_isa(benchmark::State& state, casteljau::batch::Isa isa) {
  const casteljau::batch::Isa best = casteljau::batch::active_isa();
  if (!casteljau::batch::select_isa(isa)) {
    state.SkipWithError("instruction set not available");
    return;
  }
  casteljau_batch_soa(state, casteljau::Store::automatic);
  casteljau::batch::select_isa(best);
}

void casteljau_batch_aos(benchmark::State& state) {
  W1& w = W1::get();
  const std::span<const double> ts(w.data.ts);
  P2* out = reinterpret_cast<P2*>(w.aos.data());
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.curves.size(); ++i) casteljau::evaluate(w.curves[i], ts, std::span<P2>(out + i * M, M));
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

void casteljau_scalar(benchmark::State& state) {
  W1& w = W1::get();
  double* out = w.aos.data();
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.curves.size(); ++i) {
      const Curve& c = w.curves[i];
      for (std::size_t j = 0; j < M; ++j) {
        const P2 p = c(w.data.ts[j]);
        out[2 * (i * M + j)] = p[0];
        out[2 * (i * M + j) + 1] = p[1];
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

// ---- simple own code: Horner on power coefficients, converted per curve in the loop ----

struct Power3 {
  double a[4][2];
  explicit Power3(const std::array<P2, 4>& P) {
    for (int d = 0; d < 2; ++d) {
      a[0][d] = P[0][d];
      a[1][d] = 3 * (P[1][d] - P[0][d]);
      a[2][d] = 3 * (P[0][d] - 2 * P[1][d] + P[2][d]);
      a[3][d] = P[3][d] - P[0][d] + 3 * (P[1][d] - P[2][d]);
    }
  }
};

void plain_horner_soa(benchmark::State& state) {
  W1& w = W1::get();
  const double* ts = w.data.ts.data();
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.data.curves; ++i) {
      const Power3 p(w.data.P[i]);
      double* __restrict x = w.x.data() + i * M;
      double* __restrict y = w.y.data() + i * M;
      for (std::size_t j = 0; j < M; ++j) {
        const double t = ts[j];
        x[j] = ((p.a[3][0] * t + p.a[2][0]) * t + p.a[1][0]) * t + p.a[0][0];
        y[j] = ((p.a[3][1] * t + p.a[2][1]) * t + p.a[1][1]) * t + p.a[0][1];
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_soa());
}

void plain_horner_aos(benchmark::State& state) {
  W1& w = W1::get();
  const double* ts = w.data.ts.data();
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.data.curves; ++i) {
      const Power3 p(w.data.P[i]);
      double* __restrict o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) {
        const double t = ts[j];
        o[2 * j] = ((p.a[3][0] * t + p.a[2][0]) * t + p.a[1][0]) * t + p.a[0][0];
        o[2 * j + 1] = ((p.a[3][1] * t + p.a[2][1]) * t + p.a[1][1]) * t + p.a[0][1];
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

// ---- ceilings: hand-written FMA Horner ----
// The AVX-512 pass is compiled in both builds (target attribute) for the paired row; the
// ceiling rows of their own stay in the build whose flags enable their instruction set.

/// Whether this CPU (and the OS, which must save the registers: __builtin_cpu_supports
/// checks both) runs the AVX-512 ceiling.
bool cpu_has_avx512() {
#if CASTELJAU_BENCH_W1_X86
  return __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}

#if CASTELJAU_BENCH_W1_X86
/// window: write every curve into the same 1000-point L1-resident window (compute limit;
/// the output is not kept, so no correctness figure). Call only where cpu_has_avx512().
template <bool Stream, bool Window>
__attribute__((target("avx512f"))) void ceiling_avx512_pass(W1& w) {
  const double* ts = w.data.ts.data();
  constexpr std::size_t window = 1000;  // 16 KB of x and y together, well inside L1
  for (std::size_t i = 0; i < w.data.curves; ++i) {
    const Power3 p(w.data.P[i]);
    __m512d ax[4], ay[4];
    for (int k = 0; k < 4; ++k) {
      ax[k] = _mm512_set1_pd(p.a[k][0]);
      ay[k] = _mm512_set1_pd(p.a[k][1]);
    }
    for (std::size_t j = 0; j < M; j += 8) {  // M is a multiple of 8, rows 64-byte aligned
      const __m512d t = _mm512_loadu_pd(ts + j);
      const __m512d vx = _mm512_fmadd_pd(_mm512_fmadd_pd(_mm512_fmadd_pd(ax[3], t, ax[2]), t, ax[1]), t, ax[0]);
      const __m512d vy = _mm512_fmadd_pd(_mm512_fmadd_pd(_mm512_fmadd_pd(ay[3], t, ay[2]), t, ay[1]), t, ay[0]);
      const std::size_t k = Window ? (j % window) : i * M + j;
      if constexpr (Stream) {
        _mm512_stream_pd(w.x.data() + k, vx);
        _mm512_stream_pd(w.y.data() + k, vy);
      } else {
        _mm512_storeu_pd(w.x.data() + k, vx);
        _mm512_storeu_pd(w.y.data() + k, vy);
      }
    }
  }
  if constexpr (Stream) _mm_sfence();
}
#endif

#if defined(__AVX512F__)
template <bool Stream, bool Window>
void ceiling_avx512(benchmark::State& state) {
  W1& w = W1::get();
  for (auto _ : state) {
    ceiling_avx512_pass<Stream, Window>(w);
    benchmark::ClobberMemory();
  }
  finish(state, Window ? 0.0 : w.diff_soa());
}
#endif

#if defined(__AVX2__) && defined(__FMA__)
void ceiling_avx2(benchmark::State& state) {
  W1& w = W1::get();
  const double* ts = w.data.ts.data();
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.data.curves; ++i) {
      const Power3 p(w.data.P[i]);
      __m256d ax[4], ay[4];
      for (int k = 0; k < 4; ++k) {
        ax[k] = _mm256_set1_pd(p.a[k][0]);
        ay[k] = _mm256_set1_pd(p.a[k][1]);
      }
      for (std::size_t j = 0; j < M; j += 4) {
        const __m256d t = _mm256_loadu_pd(ts + j);
        _mm256_storeu_pd(w.x.data() + i * M + j, _mm256_fmadd_pd(_mm256_fmadd_pd(_mm256_fmadd_pd(ax[3], t, ax[2]), t, ax[1]), t, ax[0]));
        _mm256_storeu_pd(w.y.data() + i * M + j, _mm256_fmadd_pd(_mm256_fmadd_pd(_mm256_fmadd_pd(ay[3], t, ay[2]), t, ay[1]), t, ay[0]));
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_soa());
}
#endif

// ---- lib2geom 1.2.2 ----

#if CASTELJAU_BENCH_HAVE_2GEOM
std::vector<Geom::CubicBezier> geom_curves(const W1& w) {
  std::vector<Geom::CubicBezier> v;
  v.reserve(w.data.curves);
  for (const auto& P : w.data.P)
    v.emplace_back(Geom::Point(P[0][0], P[0][1]), Geom::Point(P[1][0], P[1][1]), Geom::Point(P[2][0], P[2][1]), Geom::Point(P[3][0], P[3][1]));
  return v;
}

void geom_point_at(benchmark::State& state) {
  W1& w = W1::get();
  const auto cs = geom_curves(w);
  for (auto _ : state) {
    for (std::size_t i = 0; i < cs.size(); ++i) {
      double* o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) {
        const Geom::Point p = cs[i].Geom::CubicBezier::pointAt(w.data.ts[j]);  // qualified: no virtual call
        o[2 * j] = p[Geom::X];
        o[2 * j + 1] = p[Geom::Y];
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

void geom_curve_point_at(benchmark::State& state) {
  W1& w = W1::get();
  const auto cs = geom_curves(w);
  std::vector<const Geom::Curve*> ptr;
  for (const auto& c : cs) ptr.push_back(&c);
  benchmark::DoNotOptimize(ptr.data());
  for (auto _ : state) {
    for (std::size_t i = 0; i < ptr.size(); ++i) {
      double* o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) {
        const Geom::Point p = ptr[i]->pointAt(w.data.ts[j]);
        o[2 * j] = p[Geom::X];
        o[2 * j + 1] = p[Geom::Y];
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

void geom_value_at(benchmark::State& state) {
  W1& w = W1::get();
  std::vector<Geom::Bezier> bx, by;
  for (const auto& P : w.data.P) {
    bx.emplace_back(P[0][0], P[1][0], P[2][0], P[3][0]);
    by.emplace_back(P[0][1], P[1][1], P[2][1], P[3][1]);
  }
  for (auto _ : state) {
    for (std::size_t i = 0; i < bx.size(); ++i) {
      double* o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) {
        o[2 * j] = bx[i].valueAt(w.data.ts[j]);
        o[2 * j + 1] = by[i].valueAt(w.data.ts[j]);
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}
#endif

// ---- OpenCASCADE 7.6 ----

#if CASTELJAU_BENCH_HAVE_OCCT
TColgp_Array1OfPnt2d occt_poles(const std::array<P2, 4>& P) {
  TColgp_Array1OfPnt2d poles(1, 4);
  for (int k = 0; k < 4; ++k) poles.SetValue(k + 1, gp_Pnt2d(P[static_cast<std::size_t>(k)][0], P[static_cast<std::size_t>(k)][1]));
  return poles;
}

void occt_d0(benchmark::State& state) {
  W1& w = W1::get();
  std::vector<Handle(Geom2d_BezierCurve)> cs;
  for (const auto& P : w.data.P) cs.push_back(new Geom2d_BezierCurve(occt_poles(P)));
  for (auto _ : state) {
    for (std::size_t i = 0; i < cs.size(); ++i) {
      double* o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) {
        gp_Pnt2d p;
        cs[i]->D0(w.data.ts[j], p);
        o[2 * j] = p.X();
        o[2 * j + 1] = p.Y();
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

void occt_bsplclib_d0(benchmark::State& state) {
  W1& w = W1::get();
  std::vector<TColgp_Array1OfPnt2d> poles;
  for (const auto& P : w.data.P) poles.push_back(occt_poles(P));
  for (auto _ : state) {
    for (std::size_t i = 0; i < poles.size(); ++i) {
      double* o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) {
        gp_Pnt2d p;
        BSplCLib::D0(w.data.ts[j], poles[i], nullptr, p);
        o[2 * j] = p.X();
        o[2 * j + 1] = p.Y();
      }
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}

void occt_plib_polynomial(benchmark::State& state) {
  W1& w = W1::get();
  for (auto _ : state) {
    for (std::size_t i = 0; i < w.data.curves; ++i) {
      const Power3 p(w.data.P[i]);  // conversion inside the timed loop, as for own Horner
      double coef[8];
      for (int k = 0; k < 4; ++k) {
        coef[2 * k] = p.a[k][0];
        coef[2 * k + 1] = p.a[k][1];
      }
      double* o = w.aos.data() + 2 * i * M;
      for (std::size_t j = 0; j < M; ++j) PLib::NoDerivativeEvalPolynomial(w.data.ts[j], 3, 2, 6, coef[0], o[2 * j]);
    }
    benchmark::ClobberMemory();
  }
  finish(state, w.diff_aos());
}
#endif

// ---- paired rounds: batch_soa against its reference, pass by pass ----

/// Each iteration times one pass of batch_soa (Store::automatic) and one of the
/// reference, back to back, their order alternating, and the counters give the median of
/// the rounds' ratios (batch_soa over reference) with their quartiles, in wall time and in
/// the thread's CPU time, and the median of each pass's times (ms). This host's write bandwidth moves by up to 1.7x between runs a
/// minute apart (and within a run): separate rows, even interleaved, compare passes that
/// saw different bandwidth; two passes 10 ms apart see the same. The row's own time is
/// that of both passes. Reference: the non-temporal AVX-512 ceiling (both builds; the row
/// is skipped with an error on a CPU without AVX-512F), or memset of the output's 160 MB.
template <bool Ceiling>
void paired(benchmark::State& state) {
  if (Ceiling && !cpu_has_avx512()) {
    state.SkipWithError("this CPU has no AVX-512F: no non-temporal AVX-512 ceiling to pair with");
    return;
  }
  W1& w = W1::get();
  const std::span<const Curve> curves(w.curves);
  const std::span<const double> ts(w.data.ts);
  auto batch = [&] {
    casteljau::evaluate(curves, ts, std::array<std::span<double>, 2>{std::span(w.x.data(), N), std::span(w.y.data(), N)},
                        casteljau::Store::automatic);
  };
  int v = 0;
  auto reference = [&] {
#if CASTELJAU_BENCH_W1_X86
    if constexpr (Ceiling) {
      ceiling_avx512_pass<true, false>(w);
      return;
    }
#endif
    std::memset(w.aos.data(), ++v & 0xff, 2 * N * sizeof(double));
  };
  // Wall time, and this thread's CPU time (clock_gettime): on a loaded machine a pass
  // preempted by other processes gains wall time but not CPU time, while the stalls of
  // a memory-bound pass count in both.
  struct Times {
    double wall, cpu;
  };
  auto cpu_now = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
  };
  auto timed = [&](auto&& f) {
    const double c0 = cpu_now();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    benchmark::ClobberMemory();
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return Times{wall, cpu_now() - c0};
  };
  std::vector<double> ratio, ratio_cpu, tb, tr, cb, cr;
  bool first = true;
  for (auto _ : state) {
    Times b{}, r{};
    if (first) {
      b = timed(batch);
      r = timed(reference);
    } else {
      r = timed(reference);
      b = timed(batch);
    }
    first = !first;
    ratio.push_back(b.wall / r.wall);
    ratio_cpu.push_back(b.cpu / r.cpu);
    tb.push_back(b.wall);
    tr.push_back(r.wall);
    cb.push_back(b.cpu);
    cr.push_back(r.cpu);
  }
  auto quantile = [](std::vector<double> x, double q) {
    if (x.empty()) return 0.0;
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(x.size() - 1) + 0.5);
    std::nth_element(x.begin(), x.begin() + k, x.end());
    return x[static_cast<std::size_t>(k)];
  };
  state.counters["ratio"] = quantile(ratio, 0.5);
  state.counters["ratio_q1"] = quantile(ratio, 0.25);
  state.counters["ratio_q3"] = quantile(ratio, 0.75);
  state.counters["ratio_cpu"] = quantile(ratio_cpu, 0.5);
  state.counters["ratio_cpu_q1"] = quantile(ratio_cpu, 0.25);
  state.counters["ratio_cpu_q3"] = quantile(ratio_cpu, 0.75);
  state.counters["batch_ms"] = quantile(tb, 0.5);
  state.counters["reference_ms"] = quantile(tr, 0.5);
  state.counters["batch_cpu_ms"] = quantile(cb, 0.5);
  state.counters["reference_cpu_ms"] = quantile(cr, 0.5);
  state.counters["rounds"] = static_cast<double>(ratio.size());
  finish(state, w.diff_soa());
}

void reg(const char* name, void (*f)(benchmark::State&)) {
  benchmark::RegisterBenchmark(name, f)->Unit(benchmark::kMillisecond)->UseRealTime();
}

int register_all() {
  reg("W1/memset/output", memset_output);
  reg("W1/memcpy/output", memcpy_output);
  reg("W1/plain/store_loop", store_loop);
  benchmark::RegisterBenchmark("W1/casteljau/batch_soa", casteljau_batch_soa, casteljau::Store::automatic)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("W1/casteljau/batch_soa_cached", casteljau_batch_soa, casteljau::Store::cached)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("W1/casteljau/per_curve_soa", casteljau_per_curve_soa, casteljau::Store::automatic)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("W1/casteljau/per_curve_soa_streaming", casteljau_per_curve_soa, casteljau::Store::streaming)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  // In the generic build (several kernel sets): each set the CPU runs, forced.
  for (const auto isa : {casteljau::batch::Isa::baseline, casteljau::batch::Isa::avx2, casteljau::batch::Isa::avx512}) {
    if (casteljau::batch::isa_available(isa) && casteljau::batch::isa_available(casteljau::batch::Isa::avx2)) {
      benchmark::RegisterBenchmark((std::string("W1/casteljau/batch_soa_") + casteljau::batch::isa_name(isa)).c_str(),
                                   casteljau_batch_soa_isa, isa)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
  reg("W1/casteljau/batch_aos", casteljau_batch_aos);
  reg("W1/casteljau/scalar_de_casteljau", casteljau_scalar);
  reg("W1/plain/horner_soa", plain_horner_soa);
  reg("W1/plain/horner_aos", plain_horner_aos);
#if defined(__AVX2__) && defined(__FMA__)
  reg("W1/ceiling/avx2_fma_soa", ceiling_avx2);
#endif
#if defined(__AVX512F__)
  reg("W1/ceiling/avx512_fma_soa", ceiling_avx512<false, false>);
  reg("W1/ceiling/avx512_fma_soa_nt", ceiling_avx512<true, false>);
  reg("W1/ceiling/avx512_fma_l1_window", ceiling_avx512<false, true>);
#endif
  reg("W1/paired/batch_soa_over_memset", paired<false>);
  reg("W1/paired/batch_soa_over_ceiling_nt", paired<true>);
#if CASTELJAU_BENCH_HAVE_2GEOM
  reg("W1/lib2geom/pointAt", geom_point_at);
  reg("W1/lib2geom/curve_pointAt", geom_curve_point_at);
  reg("W1/lib2geom/valueAt", geom_value_at);
#endif
#if CASTELJAU_BENCH_HAVE_OCCT
  reg("W1/occt/D0", occt_d0);
  reg("W1/occt/BSplCLib_D0", occt_bsplclib_d0);
  reg("W1/occt/PLib_polynomial", occt_plib_polynomial);
#endif
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  W1::get();  // inputs, curves, pre-faulted outputs and the reference, before any timing
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
