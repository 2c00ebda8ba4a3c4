// The batch evaluation kernels compiled for AVX-512 F/DQ/VL with FMA (Skylake-SP, Ice Lake, Sapphire Rapids, Zen 4 and later);
// the flags are set on this file in src/batch/CMakeLists.txt, dispatch.cpp chooses at run time.
#define CASTELJAU_KERNEL_NS avx512
#include "kernels.inc"
