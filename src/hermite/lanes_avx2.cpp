// The Hermite evaluation's lane kernels for AVX2 (flags set on this file in
// src/batch/CMakeLists.txt; hermite.cpp chooses at run time).
#define CASTELJAU_KERNEL_NS avx2
#include "lanes.inc"
