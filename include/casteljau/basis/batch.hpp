// Batch evaluation of a polynomial curve in Bernstein form at many parameters: the entry
// points of the compiled kernels (library casteljau::kernels, src/batch/), which are built
// for several x86-64 instruction sets and chosen once at run time for the CPU. No
// intrinsics here; algo/evaluate.hpp is the user-facing API on top.
#pragma once

#include <cstddef>

namespace casteljau::batch {

/// Parameters are processed in blocks of this many: 64 doubles = 512 bytes per buffer,
/// small enough for a block's buffers to stay in L1 (the de Casteljau work array, used
/// above bernstein_horner_max_degree, holds (n + 1) x 64 values).
inline constexpr std::size_t block = 64;

/// The method depends on the degree n (docs/decisions/0004-compiled-kernels.md):
/// - n <= horner_max_degree: Horner on the power form (conversion in the working
///   precision; its rounding is amplified by about 3^n, harmless at n <= 3);
/// - n <= bernstein_horner_max_degree, t in [0, 1]: Bernstein-Horner, i.e. Horner in
///   s = t/(1-t) (t < 1/2) or (1-t)/t on the coefficients C(n, j) P_j, times (1-t)^n or
///   t^n, with the roundings of 1 - t, of s and of the power corrected to second order:
///   O(n) per parameter (2n multiply-adds per coordinate), error measured at most
///   6.2e-16 on unit-box data at degrees 4..60 (tests/reference), below de Casteljau's.
///   The corrections use error-free products (Dekker 1971; a fused multiply-add where
///   the instruction set has one) and apply the rest of s through the derivative, as
///   compensated Horner schemes do (Graillat, Langlois, Louvet 2009);
/// - above that degree, and in blocks with a parameter outside [0, 1]: de Casteljau
///   across the parameters of a block, O(n^2) per parameter.
/// The binomials are exact in 64-bit integers up to degree 62, hence the limit.
inline constexpr int horner_max_degree = 3;
inline constexpr int bernstein_horner_max_degree = 60;

/// Evaluates the curve with control points c[i * dims + d] (i = 0..degree, d < dims) at
/// ts[0..m) into out[d][0..m) (dims arrays). With `stream`, non-temporal stores where the
/// instruction set has them (x86, float and double; the caller then calls store_fence()).
/// Preconditions (the caller checks them; algo/evaluate.hpp does): degree >= 0, dims >= 1,
/// every value finite, outputs not overlapping the inputs or each other. Thread-safe.
void evaluate_soa(const float* c, int degree, int dims, const float* ts, std::size_t m, float* const* out, bool stream);
void evaluate_soa(const double* c, int degree, int dims, const double* ts, std::size_t m, double* const* out, bool stream);
void evaluate_soa(const long double* c, int degree, int dims, const long double* ts, std::size_t m, long double* const* out,
                  bool stream);

/// Whether every ts[j], j < m, is finite (vectorised: the check runs on every batch call).
bool all_finite(const float* ts, std::size_t m);
bool all_finite(const double* ts, std::size_t m);
bool all_finite(const long double* ts, std::size_t m);

/// Orders the non-temporal stores of evaluate_soa before later stores (sfence on x86).
void store_fence();

/// The instruction sets the kernels are compiled for. On x86-64 with GCC or Clang:
/// baseline (the build's flags, SSE2 for a generic build), avx2 (AVX2 + FMA), avx512
/// (AVX-512 F, DQ, VL + FMA); elsewhere only baseline. Results agree to the accuracy above
/// but not bit for bit across instruction sets (FMA rounds once where SSE2 rounds twice).
enum class Isa { baseline, avx2, avx512 };

/// "baseline", "avx2" or "avx512".
const char* isa_name(Isa isa);
/// Compiled in and supported by this CPU (and its operating system).
bool isa_available(Isa isa);
/// The kernels in use: the best available, chosen at the first call.
Isa active_isa();
/// Switches every thread to `isa` if available (returns false otherwise, and changes
/// nothing). For tests and benchmarks; not meant to be called while other threads evaluate.
bool select_isa(Isa isa);

}  // namespace casteljau::batch
