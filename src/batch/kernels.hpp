// Private interface between the dispatcher (dispatch.cpp) and the evaluation kernels,
// which kernels.inc defines once per instruction set (kernels_<isa>.cpp). Plain data and
// function pointers only: no inline code, so that the per-ISA translation units share no
// function the linker could merge across instruction sets.
#pragma once

#include <cstddef>

namespace casteljau::batch::kernels {

/// How one curve is evaluated (chosen per curve by the dispatcher, see batch.hpp).
enum class Method { power, bernstein, de_casteljau };

/// One curve prepared for the kernels; every array is coordinate-major, [d * (n + 1) + i].
template <class T>
struct Plan {
  Method method;
  int n;         // degree
  int dims;      // coordinates
  const T* points;  // control point coordinates (every method: de Casteljau fallback)
  const T* power;   // power: Horner coefficients a_j
  const T* fwd;     // bernstein: C(n, j) P_j
  const T* rev;     // bernstein: C(n, j) P_(n-j), the same reversed
  T* work;          // (n + 1) * block values for de Casteljau
};

template <class T>
struct Ops {
  /// out[d][0..m) = coordinate d at ts[0..m); non-temporal stores when `stream` and the
  /// kernel can (x86, float and double; the caller fences).
  void (*soa)(const Plan<T>& p, const T* ts, std::size_t m, T* const* out, bool stream);
  /// Whether every ts[j], j < m, is finite.
  bool (*all_finite)(const T* ts, std::size_t m);
};

struct Table {
  const char* name;
  Ops<float> f;
  Ops<double> d;
  Ops<long double> ld;
};

namespace baseline { extern const Table table; }
#if CASTELJAU_KERNELS_MULTI
namespace avx2 { extern const Table table; }
namespace avx512 { extern const Table table; }
#endif

}  // namespace casteljau::batch::kernels
