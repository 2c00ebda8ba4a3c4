// The batch evaluation kernels compiled for the build's baseline instruction set (SSE2 on generic x86-64; whatever the flags say elsewhere);
// the flags are set on this file in src/batch/CMakeLists.txt, dispatch.cpp chooses at run time.
#define CASTELJAU_KERNEL_NS baseline
#include "kernels.inc"
