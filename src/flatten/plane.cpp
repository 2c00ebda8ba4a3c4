// The plane near-optimal flattening for double (algo/flatten/plane.hpp's small_optimal),
// compiled once, with the lane kernels of the instruction set chosen at run time (the
// one the batch evaluation kernels use: batch::active_isa, src/batch/dispatch.cpp).
#include "casteljau/algo/flatten/plane.hpp"

#include "casteljau/basis/batch.hpp"
#include "lanes.hpp"

namespace casteljau::detail {

namespace {

#if defined(__GNUC__)
const flatten_lanes::Table& lanes() {
  switch (batch::active_isa()) {
#if CASTELJAU_KERNELS_MULTI
    case batch::Isa::avx512: return flatten_lanes::avx512::table;
    case batch::Isa::avx2: return flatten_lanes::avx2::table;
#endif
    default: return flatten_lanes::baseline::table;
  }
}

/// The plan's power form as plain doubles (flatten_lanes::Block).
struct Coefficients {
  double a[8];
  explicit Coefficients(const SmallOptimalPlan<double>& p)
      : a{p.a0[0], p.a0[1], p.a1[0], p.a1[1], p.a2[0], p.a2[1], p.a3[0], p.a3[1]} {}
};

/// small_optimal's block kernels from a lane table (see PlainBlocks).
struct LaneBlocks {
  static constexpr bool parabola_blocks = true;
  const flatten_lanes::Table* t;
  unsigned block(const SmallOptimalPlan<double>& plan, double f_base, double df, double first, double tol2, double* bt, double* bx, double* by,
                 double* bdx, double* bdy, bool half) const {
    const Coefficients c(plan);
    return (half ? t->block4 : t->block8)(plan, c.a, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
  }
  unsigned parabola_block(const SmallOptimalPlan<double>& plan, double f_base, double df, double first, double tp, double* bt, double* bx,
                          double* by) const {
    const Coefficients c(plan);
    return t->parabola(plan, c.a, f_base, df, first, tp, bt, bx, by);
  }
};
#endif

}  // namespace

// The walk's helpers (the step checks, the writer, the lambdas of small_optimal) are
// plain inline functions of the public header; GCC at -O2 leaves some of them out of line
// in this loop (small_cheap_check, small_chord_check: about 1% more instructions on
// elevated quadratics). `flatten` inlines every call of this function's body into it,
// here only, instead of always_inline attributes in the header that every user's
// translation unit would see (docs/performance.md, "Inlining of the plane walk").
#if defined(__GNUC__)
[[gnu::flatten]]
#endif
void small_optimal_compiled(const SmallPiece<double, 2>& s, double tol, std::vector<Point<double, 2>>& out, const Point<double, 2>& origin,
                            double up) {
  SmallOptimalWriter<double> writer{out, origin, up};
#if defined(__GNUC__)
  small_optimal(s, tol, writer, LaneBlocks{&lanes()});
#else
  small_optimal(s, tol, writer);
#endif
  writer.finish();
}

unsigned optimal_block_lanes(const SmallOptimalPlan<double>& plan, int block, double f_base, double df, double first, double tol2, double* bt,
                             double* bx, double* by, double* bdx, double* bdy) {
  if (block != optimal_block && block != optimal_block / 2) {
    throw InvalidArgument("block", "must be " + std::to_string(optimal_block) + " or " + std::to_string(optimal_block / 2));
  }
#if defined(__GNUC__)
  const Coefficients c(plan);
  return (block == optimal_block ? lanes().block8 : lanes().block4)(plan, c.a, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
#else
  if (block == optimal_block) return small_optimal_block_plain<double, optimal_block>(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
  return small_optimal_block_plain<double, optimal_block / 2>(plan, f_base, df, first, tol2, bt, bx, by, bdx, bdy);
#endif
}

unsigned optimal_parabola_block_lanes(const SmallOptimalPlan<double>& plan, double f_base, double df, double first, double tp, double* bt,
                                      double* bx, double* by) {
#if defined(__GNUC__)
  const Coefficients c(plan);
  return lanes().parabola(plan, c.a, f_base, df, first, tp, bt, bx, by);
#else
  (void)plan, (void)f_base, (void)df, (void)first, (void)tp, (void)bt, (void)bx, (void)by;
  throw NumericalError("flatten: the parabola lane kernel needs GCC or Clang");
#endif
}

}  // namespace casteljau::detail
