// The batch evaluation kernels compiled for AVX2 with FMA (x86-64-v3 class CPUs: Haswell, Zen 1 and later);
// the flags are set on this file in src/batch/CMakeLists.txt, dispatch.cpp chooses at run time.
#define CASTELJAU_KERNEL_NS avx2
#include "kernels.inc"
