// The batch entry points of basis/batch.hpp: prepares a curve's coefficients for the
// method its degree takes, and calls the kernels of the instruction set chosen once at
// run time (__builtin_cpu_supports, which also checks that the OS saves the registers).
#include <atomic>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "casteljau/basis/batch.hpp"
#include "kernels.hpp"

#if CASTELJAU_KERNELS_X86
#include <immintrin.h>
#endif

namespace casteljau::batch {

namespace {

using kernels::Method;
using kernels::Plan;
using kernels::Table;

static_assert(block == 64, "kernels.inc assumes blocks of 64 parameters");

const Table* table_of(Isa isa) {
  switch (isa) {
    case Isa::baseline: return &kernels::baseline::table;
#if CASTELJAU_KERNELS_MULTI
    case Isa::avx2: return &kernels::avx2::table;
    case Isa::avx512: return &kernels::avx512::table;
#else
    default: return nullptr;
#endif
  }
  return nullptr;
}

bool supported(Isa isa) {
#if CASTELJAU_KERNELS_MULTI
  __builtin_cpu_init();  // idempotent; needed if called before libgcc's constructor ran
#endif
  switch (isa) {
    case Isa::baseline: return true;
#if CASTELJAU_KERNELS_MULTI
    case Isa::avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case Isa::avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") &&
             __builtin_cpu_supports("fma");
#else
    default: return false;
#endif
  }
  return false;
}

Isa best() {
#if CASTELJAU_KERNELS_MULTI
  if (supported(Isa::avx512)) return Isa::avx512;
  if (supported(Isa::avx2)) return Isa::avx2;
#endif
  return Isa::baseline;
}

std::atomic<Isa>& current() {
  static std::atomic<Isa> isa{best()};
  return isa;
}

template <class T>
const kernels::Ops<T>& ops() {
  const Table& t = *table_of(current().load(std::memory_order_relaxed));
  if constexpr (std::is_same_v<T, float>) {
    return t.f;
  } else if constexpr (std::is_same_v<T, double>) {
    return t.d;
  } else {
    return t.ld;
  }
}

/// C(n, j) for j = 0..n, exact in 64 bits for n <= 62 (C(n, j) (n - j) < 2^64 there).
void binomials(int n, std::uint64_t* out) {
  std::uint64_t b = 1;
  for (int j = 0; j <= n; ++j) {
    out[j] = b;
    b = b * static_cast<std::uint64_t>(n - j) / static_cast<std::uint64_t>(j + 1);
  }
}

/// Lays out the curve's coefficients for its method in buf (one per thread, reused).
template <class T>
Plan<T> prepare(const T* c, int n, int dims, std::vector<T>& buf) {
  static_assert(bernstein_horner_max_degree <= 62, "binomials() is exact up to degree 62");
  const std::size_t m = static_cast<std::size_t>(n) + 1, D = static_cast<std::size_t>(dims), nd = m * D;
  Method method = n <= horner_max_degree ? Method::power : n <= bernstein_horner_max_degree ? Method::bernstein : Method::de_casteljau;
  const std::size_t coef = method == Method::power ? nd : method == Method::bernstein ? 2 * nd : 0;
  buf.resize(nd + coef + m * block);
  T* points = buf.data();
  T* extra = points + nd;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t d = 0; d < D; ++d) points[d * m + i] = c[i * D + d];
  Plan<T> p{method, n, dims, points, nullptr, nullptr, nullptr, extra + coef};
  if (method == Method::power) {
    // a_j = sum_{i <= j} (-1)^(j-i) C(n, j) C(j, i) P_i, the same sum in the same order as
    // Bezier::to_power() (curves/bezier.hpp).
    constexpr int binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    for (std::size_t d = 0; d < D; ++d)
      for (int j = 0; j <= n; ++j) {
        T s{};
        for (int i = 0; i <= j; ++i) {
          const T v = static_cast<T>(binom[n][j]) * static_cast<T>(binom[j][i]);
          s += ((j - i) % 2 == 0 ? v : -v) * points[d * m + static_cast<std::size_t>(i)];
        }
        extra[d * m + static_cast<std::size_t>(j)] = s;
      }
    p.power = extra;
  } else if (method == Method::bernstein) {
    std::uint64_t C[bernstein_horner_max_degree + 1];
    binomials(n, C);
    T* fwd = extra;
    T* rev = extra + nd;
    bool finite = true;  // C(n, j) P_j overflows only for |P| near the top of the range
    for (std::size_t d = 0; d < D; ++d)
      for (std::size_t j = 0; j < m; ++j) {
        const T v = static_cast<T>(C[j]) * points[d * m + j];
        finite = finite && std::isfinite(v);
        fwd[d * m + j] = v;
        rev[d * m + (m - 1 - j)] = v;
      }
    if (finite) {
      p.fwd = fwd;
      p.rev = rev;
    } else {
      p.method = Method::de_casteljau;
    }
  }
  return p;
}

template <class T>
void soa(const T* c, int degree, int dims, const T* ts, std::size_t m, T* const* out, bool stream) {
  thread_local std::vector<T> buf;
  const Plan<T> p = prepare(c, degree, dims, buf);
  ops<T>().soa(p, ts, m, out, stream);
}

}  // namespace

void evaluate_soa(const float* c, int degree, int dims, const float* ts, std::size_t m, float* const* out, bool stream) {
  soa(c, degree, dims, ts, m, out, stream);
}
void evaluate_soa(const double* c, int degree, int dims, const double* ts, std::size_t m, double* const* out, bool stream) {
  soa(c, degree, dims, ts, m, out, stream);
}
void evaluate_soa(const long double* c, int degree, int dims, const long double* ts, std::size_t m, long double* const* out,
                  bool stream) {
  soa(c, degree, dims, ts, m, out, stream);
}
bool all_finite(const float* ts, std::size_t m) { return ops<float>().all_finite(ts, m); }
bool all_finite(const double* ts, std::size_t m) { return ops<double>().all_finite(ts, m); }
bool all_finite(const long double* ts, std::size_t m) { return ops<long double>().all_finite(ts, m); }

void store_fence() {
#if CASTELJAU_KERNELS_X86
  _mm_sfence();
#endif
}

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::baseline: return "baseline";
    case Isa::avx2: return "avx2";
    case Isa::avx512: return "avx512";
  }
  return "unknown";
}

bool isa_available(Isa isa) { return table_of(isa) != nullptr && supported(isa); }

Isa active_isa() { return current().load(std::memory_order_relaxed); }

bool select_isa(Isa isa) {
  if (!isa_available(isa)) return false;
  current().store(isa, std::memory_order_relaxed);
  return true;
}

}  // namespace casteljau::batch
