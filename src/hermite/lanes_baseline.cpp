// The Hermite evaluation's lane kernels for the baseline instruction set of the build
// (SSE2 on generic x86-64); hermite.cpp chooses a set at run time.
#define CASTELJAU_KERNEL_NS baseline
#include "lanes.inc"
