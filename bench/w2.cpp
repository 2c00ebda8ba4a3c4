// W2 of docs/performance.md: accuracy at degrees 5, 10, 20, 40 against a
// 256-bit MPFR de Casteljau reference computed from the exact double inputs. Each entry
// W2/<library>/<method>/<n> times the method on the 10 curves x 1000 parameters and
// reports the counter max_error = max over curves, parameters and both coordinates of
// |value - reference|.
#include <benchmark/benchmark.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/algo/evaluate.hpp"
#include "casteljau/basis/binomial.hpp"
#include "casteljau/curves/bezier.hpp"
#include "common.hpp"

#if CASTELJAU_BENCH_HAVE_2GEOM
#include <2geom/bezier.h>
#endif
#if CASTELJAU_BENCH_HAVE_OCCT
#include <Geom2d_BezierCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Pnt2d.hxx>
#endif

namespace {

using P2 = casteljau::Point<double, 2>;
using Curve = casteljau::Bezier<double, 2>;
constexpr mpfr_prec_t precision = 256;

/// RAII for one mpfr_t.
class Mp {
 public:
  Mp() { mpfr_init2(v, precision); }
  ~Mp() { mpfr_clear(v); }
  Mp(const Mp&) = delete;
  Mp& operator=(const Mp&) = delete;
  mpfr_t v;
};

/// One degree's inputs with the reference values ref[(c * 1000 + j) * 2 + d].
struct Set {
  bench::W2Set in;
  std::vector<double> ref;
  std::vector<double> out;  // the method's values, same layout
};

std::vector<Set>& sets() {
  static std::vector<Set> s = [] {
    std::vector<Set> r;
    for (auto& in : bench::w2_data()) r.push_back({std::move(in), {}, {}});
    return r;
  }();
  return s;
}

/// de Casteljau in 256-bit arithmetic, w_i <- w_i + t (w_{i+1} - w_i): each step rounds
/// at 2^-256 relative, far below the double results compared against it.
void reference(Set& s) {
  const std::size_t m = s.in.P[0].size();
  std::vector<Mp> w(m);
  Mp t, d;
  s.ref.assign(s.in.P.size() * s.in.ts.size() * 2, 0.0);
  for (std::size_t c = 0; c < s.in.P.size(); ++c)
    for (std::size_t j = 0; j < s.in.ts.size(); ++j)
      for (int k = 0; k < 2; ++k) {
        mpfr_set_d(t.v, s.in.ts[j], MPFR_RNDN);
        for (std::size_t i = 0; i < m; ++i) mpfr_set_d(w[i].v, s.in.P[c][i][k], MPFR_RNDN);
        for (std::size_t r = 1; r < m; ++r)
          for (std::size_t i = 0; i + r < m; ++i) {
            mpfr_sub(d.v, w[i + 1].v, w[i].v, MPFR_RNDN);
            mpfr_mul(d.v, d.v, t.v, MPFR_RNDN);
            mpfr_add(w[i].v, w[i].v, d.v, MPFR_RNDN);
          }
        s.ref[(c * s.in.ts.size() + j) * 2 + static_cast<std::size_t>(k)] = mpfr_get_d(w[0].v, MPFR_RNDN);
      }
  s.out.assign(s.ref.size(), 0.0);
}

double max_error(const Set& s) {
  double e = 0;
  for (std::size_t k = 0; k < s.ref.size(); ++k) e = std::max(e, std::abs(s.out[k] - s.ref[k]));
  return e;
}

/// Power coefficients a_j = C(n,j) sum_i (-1)^(j-i) C(j,i) P_i (docs/performance.md, W2), [j][d];
/// in double, or exactly in MPFR and then rounded once.
std::vector<std::array<double, 2>> power_double(const std::vector<P2>& P) {
  const int n = static_cast<int>(P.size()) - 1;
  std::vector<std::array<double, 2>> a(P.size());
  for (int j = 0; j <= n; ++j)
    for (int d = 0; d < 2; ++d) {
      double s = 0;
      for (int i = 0; i <= j; ++i) {
        const double b = casteljau::binomial<double>(j, i);
        s += ((j - i) % 2 ? -b : b) * P[static_cast<std::size_t>(i)][d];
      }
      a[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)] = casteljau::binomial<double>(n, j) * s;
    }
  return a;
}

std::vector<std::array<double, 2>> power_mpfr(const std::vector<P2>& P) {
  const int n = static_cast<int>(P.size()) - 1;
  std::vector<std::array<double, 2>> a(P.size());
  Mp s, term;
  for (int j = 0; j <= n; ++j)
    for (int d = 0; d < 2; ++d) {
      mpfr_set_zero(s.v, 1);
      for (int i = 0; i <= j; ++i) {
        // C(j,i) and C(n,j) are exact in double for n <= 40 (below 2^53), products exact in 256 bits.
        mpfr_set_d(term.v, P[static_cast<std::size_t>(i)][d], MPFR_RNDN);
        mpfr_mul_d(term.v, term.v, casteljau::binomial<double>(j, i), MPFR_RNDN);
        if ((j - i) % 2) mpfr_neg(term.v, term.v, MPFR_RNDN);
        mpfr_add(s.v, s.v, term.v, MPFR_RNDN);
      }
      mpfr_mul_d(s.v, s.v, casteljau::binomial<double>(n, j), MPFR_RNDN);
      a[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)] = mpfr_get_d(s.v, MPFR_RNDN);
    }
  return a;
}

/// Runs `eval(curve index, out)` (which writes 1000 x 2 values) in the timed loop, then
/// reports the error of the last run.
void run(benchmark::State& state, Set& s, const std::function<void(std::size_t, double*)>& eval) {
  const std::size_t per_curve = s.in.ts.size() * 2;
  for (auto _ : state) {
    for (std::size_t c = 0; c < s.in.P.size(); ++c) eval(c, s.out.data() + c * per_curve);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.in.P.size() * s.in.ts.size()));
  state.counters["max_error"] = max_error(s);
  state.counters["degree"] = s.in.n;
}

void reg(const std::string& name, Set& s, std::function<void(std::size_t, double*)> eval) {
  benchmark::RegisterBenchmark(name.c_str(), [&s, eval](benchmark::State& st) { run(st, s, eval); })
      ->Unit(benchmark::kMicrosecond);
}

void register_all() {
  for (Set& s : sets()) {
    const std::string n = std::to_string(s.in.n);
    const std::vector<double>& ts = s.in.ts;
    auto curves = std::make_shared<std::vector<Curve>>();
    for (const auto& P : s.in.P) curves->emplace_back(P);

    reg("W2/casteljau/fast_path/" + n, s, [curves, &ts](std::size_t c, double* o) {
      // the batch API into SoA scratch, then interleaved for the common error check (the
      // interleave is timed too, as in every row: each writes 1000 x 2 values per curve)
      thread_local std::vector<double> x, y;
      x.resize(ts.size());
      y.resize(ts.size());
      casteljau::evaluate((*curves)[c], std::span<const double>(ts), std::array<std::span<double>, 2>{std::span(x), std::span(y)});
      for (std::size_t j = 0; j < ts.size(); ++j) {
        o[2 * j] = x[j];
        o[2 * j + 1] = y[j];
      }
    });
    // The same with the kernels of each other instruction set this CPU runs, forced (the
    // row above takes the best, chosen at run time).
    for (const auto isa : {casteljau::batch::Isa::baseline, casteljau::batch::Isa::avx2}) {
      if (!casteljau::batch::isa_available(isa) || isa == casteljau::batch::active_isa()) continue;
      reg(std::string("W2/casteljau/fast_path_") + casteljau::batch::isa_name(isa) + "/" + n, s, [curves, &ts, isa](std::size_t c, double* o) {
        thread_local std::vector<double> x, y;
        x.resize(ts.size());
        y.resize(ts.size());
        const casteljau::batch::Isa best = casteljau::batch::active_isa();
        casteljau::batch::select_isa(isa);
        casteljau::evaluate((*curves)[c], std::span<const double>(ts), std::array<std::span<double>, 2>{std::span(x), std::span(y)});
        casteljau::batch::select_isa(best);
        for (std::size_t j = 0; j < ts.size(); ++j) {
          o[2 * j] = x[j];
          o[2 * j + 1] = y[j];
        }
      });
    }
    reg("W2/casteljau/scalar_de_casteljau/" + n, s, [curves, &ts](std::size_t c, double* o) {
      for (std::size_t j = 0; j < ts.size(); ++j) {
        const P2 p = (*curves)[c](ts[j]);
        o[2 * j] = p[0];
        o[2 * j + 1] = p[1];
      }
    });
    reg("W2/plain/bernstein_sum/" + n, s, [&s, &ts](std::size_t c, double* o) {
      const auto& P = s.in.P[c];
      const int deg = s.in.n;
      for (std::size_t j = 0; j < ts.size(); ++j) {
        const double t = ts[j], u = 1 - t;
        double x = 0, y = 0;
        for (int k = 0; k <= deg; ++k) {
          double b = casteljau::binomial<double>(deg, k);
          for (int q = 0; q < k; ++q) b *= t;
          for (int q = 0; q < deg - k; ++q) b *= u;
          x += b * P[static_cast<std::size_t>(k)][0];
          y += b * P[static_cast<std::size_t>(k)][1];
        }
        o[2 * j] = x;
        o[2 * j + 1] = y;
      }
    });
    for (const bool exact : {false, true}) {
      auto a = std::make_shared<std::vector<std::vector<std::array<double, 2>>>>();
      for (const auto& P : s.in.P) a->push_back(exact ? power_mpfr(P) : power_double(P));
      reg(std::string("W2/plain/power_horner_") + (exact ? "mpfr" : "double") + "/" + n, s, [a, &ts](std::size_t c, double* o) {
        const auto& ac = (*a)[c];
        for (std::size_t j = 0; j < ts.size(); ++j) {
          double x = ac.back()[0], y = ac.back()[1];
          for (std::size_t k = ac.size() - 1; k-- > 0;) {
            x = x * ts[j] + ac[k][0];
            y = y * ts[j] + ac[k][1];
          }
          o[2 * j] = x;
          o[2 * j + 1] = y;
        }
      });
    }
#if CASTELJAU_BENCH_HAVE_2GEOM
    {
      auto b = std::make_shared<std::vector<std::array<Geom::Bezier, 2>>>();
      for (const auto& P : s.in.P) {
        std::vector<double> x, y;
        for (const auto& p : P) {
          x.push_back(p[0]);
          y.push_back(p[1]);
        }
        b->push_back({Geom::Bezier(x), Geom::Bezier(y)});
      }
      reg("W2/lib2geom/valueAt/" + n, s, [b, &ts](std::size_t c, double* o) {
        for (std::size_t j = 0; j < ts.size(); ++j) {
          o[2 * j] = (*b)[c][0].valueAt(ts[j]);
          o[2 * j + 1] = (*b)[c][1].valueAt(ts[j]);
        }
      });
    }
#endif
#if CASTELJAU_BENCH_HAVE_OCCT
    if (s.in.n <= Geom2d_BezierCurve::MaxDegree()) {
      auto b = std::make_shared<std::vector<Handle(Geom2d_BezierCurve)>>();
      for (const auto& P : s.in.P) {
        TColgp_Array1OfPnt2d poles(1, static_cast<int>(P.size()));
        for (std::size_t k = 0; k < P.size(); ++k) poles.SetValue(static_cast<int>(k) + 1, gp_Pnt2d(P[k][0], P[k][1]));
        b->push_back(new Geom2d_BezierCurve(poles));
      }
      reg("W2/occt/D0/" + n, s, [b, &ts](std::size_t c, double* o) {
        for (std::size_t j = 0; j < ts.size(); ++j) {
          gp_Pnt2d p;
          (*b)[c]->D0(ts[j], p);
          o[2 * j] = p.X();
          o[2 * j + 1] = p.Y();
        }
      });
    }
#endif
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (Set& s : sets()) reference(s);
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
