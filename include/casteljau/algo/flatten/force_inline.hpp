// The flattening kernels' inlining attributes, defined once. Their small helpers are
// called once or twice per vertex: GCC, left to itself, does not inline them into the step
// loop (about 30% slower on W3). Project-prefixed macros, left defined.
#pragma once

#if defined(__GNUC__)
#define CASTELJAU_FLATTEN_INLINE [[gnu::always_inline]] inline
#define CASTELJAU_FLATTEN_LAMBDA __attribute__((always_inline))
#else
#define CASTELJAU_FLATTEN_LAMBDA
#define CASTELJAU_FLATTEN_INLINE inline
#endif
