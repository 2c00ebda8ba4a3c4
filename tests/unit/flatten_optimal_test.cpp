// The optimal flattening's plane kernel for lines, quadratics and cubics (algo/flatten.hpp,
// detail::small_optimal: count planned from the density integral, vertices placed
// independently, every step checked): the tolerance against an independent dense sampling
// on cusps, inflections, loops, degenerate and extreme-scale curves; the parabola integral
// against a numerical integral computed here; counts against the greedy near-optimal count of W3
// (flatten_oracle.hpp).
#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "flatten_oracle.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;

/// Largest distance from the curve, sampled at 4000 + 16 n uniform parameters (n segments),
/// to the polyline, decided against `bound` (test::PolylineWalk: exact whenever a sample is
/// farther than `bound`, so the result is <= bound exactly when every sample is).
double sampled_deviation(const B2& c, const std::vector<P2>& poly, double bound) {
  const int S = 4000 + 16 * static_cast<int>(poly.size());
  test::PolylineWalk walk(poly);
  double worst = 0;
  for (int i = 0; i <= S; ++i) worst = std::max(worst, walk.distance(c(static_cast<double>(i) / S), bound));
  return worst;
}

/// The optimal polyline of c: its ends are the curve's, no vertex is NaN, it is within tol
/// of the densely sampled curve (1e-9 relative slack for the sampling's own rounding).
std::vector<P2> checked_optimal(const B2& c, double tol, const char* name) {
  const auto poly = flatten(c, tol, FlattenMethod::optimal);
  EXPECT_GE(poly.size(), 2u) << name;
  EXPECT_EQ(poly.front(), c.points().front()) << name;
  EXPECT_EQ(poly.back(), c.points().back()) << name;
  for (const auto& v : poly) EXPECT_TRUE(std::isfinite(v[0]) && std::isfinite(v[1])) << name;
  const double bound = tol * (1 + 1e-9);
  EXPECT_LE(sampled_deviation(c, poly, bound), bound) << name << " tol " << tol;
  return poly;
}

TEST(FlattenOptimal, ParabolaIntegralAgainstQuadrature) {
  // I(x) = integral_0^x (1 + 4 u^2)^(-1/4) du by the composite Simpson rule on 20000
  // intervals (error far below 1e-8 for this smooth integrand), against the closed form
  // (documented to about 1e-5 as the inverse of Levien's form, which is within 0.2% of the
  // true inverse: so within 0.3% of I), and the pair's consistency.
  for (const double x : {1e-6, 0.01, 0.3, 1.0, 2.5, 10.0, 100.0, 1e4}) {
    const int N = 20000;
    const double h = x / N;
    double s = 0;
    for (int i = 0; i <= N; ++i) {
      const double w = (i == 0 || i == N) ? 1 : (i % 2 ? 4 : 2);
      s += w * std::pow(1 + 4 * (i * h) * (i * h), -0.25);
    }
    const double exact = s * h / 3;
    const double I = detail::parabola_integral(x);
    EXPECT_NEAR(I / exact, 1, 3e-3) << x;
    EXPECT_NEAR(detail::parabola_integral(-x), -I, 0) << x;  // odd
    EXPECT_NEAR(detail::parabola_integral_inverse(I) / x, 1, 1e-4) << x;
  }
  EXPECT_EQ(detail::parabola_integral(0.0), 0.0);
  EXPECT_TRUE(std::isfinite(detail::parabola_integral(1e300)));
}

/// The distance from the sub-arc [t0, t1] of c to its chord segment by 1000 samples, and
/// whether every sample projects within the chord.
std::pair<double, bool> step_deviation(const B2& c, double t0, double t1) {
  const P2 a = c(t0), b = c(t1);
  const auto u = b - a;
  const double L2 = dot(u, u);
  double worst = 0;
  bool inside = true;
  for (int i = 0; i <= 1000; ++i) {
    const P2 p = c(t0 + (t1 - t0) * i / 1000.0);
    const double s = dot(p - a, u) / L2;
    inside = inside && s >= -1e-12 && s <= 1 + 1e-12;
    worst = std::max(worst, test::segment_distance(p, a, b));
  }
  return {worst, inside};
}

// The plan's roots without division or square root (fast_rsqrt, fast_rqrt4) against
// std::sqrt over the range they serve (1e-280 .. 1e290, log-spaced, 20001 points), their
// documented bounds 5e-6 and 2e-5; finite for 0 (a vanishing cross product or speed).
TEST(FlattenOptimal, FastRootsAgainstSqrt) {
  for (int i = 0; i <= 20000; ++i) {
    const double x = std::pow(10.0, -280.0 + 570.0 * i / 20000.0);
    EXPECT_LE(std::abs(detail::fast_rsqrt(x) * std::sqrt(x) - 1), 5e-6) << x;
    EXPECT_LE(std::abs(detail::fast_rqrt4(x) * std::sqrt(std::sqrt(x)) - 1), 2e-5) << x;
  }
  EXPECT_TRUE(std::isfinite(detail::fast_rsqrt(0.0)));
  EXPECT_EQ(0.0 * detail::fast_rsqrt(0.0), 0.0);
  EXPECT_EQ(0.0 * detail::fast_rsqrt(5e-324), 0.0);
}

TEST(FlattenOptimal, StepChecksAgainstSampling) {
  // The two O(1) step checks of the plane kernel on random steps of unit-scale pieces,
  // against the sampled distance of the sub-arc from its chord segment: sound (a step
  // accepted is within tol) and, for the parabola's closed form, tight (a step within
  // 0.9 tol whose arc projects inside its chord is accepted).
  test::SplitMix64 rng{8};
  const std::vector<std::vector<P2>> pieces = {
      {{0, 0}, {0.9, 0.1}, {0, 0.2}},                // sharp tip
      {{0, 0}, {1, 0.01}, {0, 0.02}},                // tip far narrower than tol: arcs overshoot their chords
      {{0, 0}, {0.5, 0.5}, {1, 0}},                  // arch
      {{0, 0}, {0.5, 1e-3}, {1, 0}},                 // nearly straight
      {{0, 0}, {1, 1}, {0, 1}, {1, 0}},              // cusp cubic
      {{0, 0}, {1, 0.6}, {-0.4, 0.6}, {0.6, 0}},     // loop
      {{0, 0}, {0.3, 0.5}, {0.6, -0.5}, {0.9, 0}},   // inflection
  };
  long closed_steps = 0, cheap_accepted = 0;
  for (const auto& Q : pieces) {
    const B2 c(Q);
    detail::SmallPiece<double, 2> s;
    s.m = static_cast<int>(Q.size());
    for (int i = 0; i < s.m; ++i) s.q[static_cast<std::size_t>(i)] = Q[static_cast<std::size_t>(i)];
    const auto d1 = c.derivative(1);
    for (const double tol : {1e-1, 1e-2, 3e-3, 1e-3}) {
      detail::SmallOptimalPlan<double> plan;
      detail::small_optimal_plan(s, tol, plan);
      EXPECT_EQ(plan.closed, Q.size() == 3);  // the quadratics here qualify, the cubics do not
      for (int k = 0; k < 120; ++k) {
        double t0 = rng.uniform(0, 1), t1 = rng.uniform(0, 1);
        if (t0 > t1) std::swap(t0, t1);
        if (k % 2) {
          t1 = t0 + (t1 - t0) * std::pow(rng.uniform(0, 1), 2);  // many short steps
        } else {
          t0 = rng.uniform(0.3, 0.5), t1 = rng.uniform(0.5, 0.7);  // across the tip, the cusp
        }
        if (!(t1 > t0)) continue;
        const auto [dev, inside] = step_deviation(c, t0, t1);
        if (plan.closed) {
          ++closed_steps;
          const bool ok = detail::parabola_step_within(plan, t0, t1);
          if (ok) {
            EXPECT_LE(dev, tol * (1 + 1e-6)) << t0 << " " << t1;
          }
          if (dev <= 0.9 * tol && inside) {
            EXPECT_TRUE(ok) << t0 << " " << t1;
          }
        }
        if (detail::small_cheap_check(t1 - t0, c(t0), d1(t0).to_vector(), c(t1), d1(t1).to_vector(), tol * tol)) {
          ++cheap_accepted;
          EXPECT_LE(dev, tol * (1 + 1e-6)) << t0 << " " << t1;
        }
      }
    }
  }
  EXPECT_GT(closed_steps, 500);
  EXPECT_GT(cheap_accepted, 200);
}

TEST(FlattenOptimal, CauchySchwarzStepBound) {
  // The cheap check's second bound of the offset D(u) = 3 u (1-u) ((1-u) d1 + u d2) of a
  // step's sub-arc from its chord: max |D|^2 <= 9/128 (3 d1^2 + 2 d1 d2 + 3 d2^2), against
  // D sampled at 20001 points; equal for d1 = d2 (a parabola's step), within 5% for d2 = 0.
  test::SplitMix64 rng{21};
  auto sampled = [](double d1, double d2) {
    double m = 0;
    for (int i = 0; i <= 20000; ++i) {
      const double u = i / 20000.0;
      m = std::max(m, std::abs(3 * u * (1 - u) * ((1 - u) * d1 + u * d2)));
    }
    return m;
  };
  auto bound = [](double d1, double d2) { return std::sqrt(9.0 / 128 * (3 * d1 * d1 + 2 * d1 * d2 + 3 * d2 * d2)); };
  for (int k = 0; k < 300; ++k) {
    const double d1 = rng.uniform(-1, 1), d2 = rng.uniform(-1, 1);
    EXPECT_LE(sampled(d1, d2), bound(d1, d2) * (1 + 1e-12)) << d1 << " " << d2;
  }
  EXPECT_NEAR(bound(0.7, 0.7), 0.75 * 0.7, 1e-15);
  EXPECT_LE(bound(1, 0), 1.05 * sampled(1, 0));  // 4/9 exactly; the bound sqrt(27/128) = 0.459
}

/// The instruction sets whose compiled kernels (src/flatten, chosen like the batch
/// evaluation kernels) this machine runs; a test runs over each and restores the choice.
std::vector<batch::Isa> available_isas() {
  std::vector<batch::Isa> v;
  for (batch::Isa isa : {batch::Isa::baseline, batch::Isa::avx2, batch::Isa::avx512})
    if (batch::isa_available(isa)) v.push_back(isa);
  return v;
}
struct IsaRestore {
  batch::Isa saved = batch::active_isa();
  ~IsaRestore() { batch::select_isa(saved); }
};

/// The first block of the batched walk of a sampled plan (small_optimal_batched): the
/// arrays and check bits as the walk computes them from the piece's start (the lane
/// kernel of the active instruction set, or the plain form).
struct FirstBlock {
  static constexpr int B = detail::optimal_block;
  double t[B + 1], x[B + 1], y[B + 1], dx[B + 1], dy[B + 1];
  unsigned ok = 0;
  int cnt = 0;    ///< vertices of the block that belong to the piece
  int fail = 0;   ///< the first failing step of the block (1 .. cnt), 0 when none fails
};
FirstBlock first_block(const detail::SmallOptimalPlan<double>& plan, double tol, bool lanes) {
  FirstBlock b;
  b.t[0] = 0, b.x[0] = plan.a0[0], b.y[0] = plan.a0[1], b.dx[0] = plan.a1[0], b.dy[0] = plan.a1[1];
  const double df = plan.F / plan.n;
  if (lanes) {
    b.ok = detail::optimal_block_lanes(plan, FirstBlock::B, 0.0, df, 1.0, tol * tol, b.t, b.x, b.y, b.dx, b.dy);
  } else {
    b.ok = detail::small_optimal_block_plain<double, FirstBlock::B>(plan, 0.0, df, 1.0, tol * tol, b.t, b.x, b.y, b.dx, b.dy);
  }
  b.cnt = std::min(FirstBlock::B, plan.n - 1);
  for (int k = 1; k <= b.cnt && !b.fail; ++k)
    if (!((b.ok >> k) & 1u)) b.fail = k;
  return b;
}

TEST(FlattenOptimal, BatchedBlocksAgainstSampling) {
  // Random unit-scale cubics (W3's kind) at tolerance 1e-3 with a sampled plan: the
  // placement of a block in vector lanes (fast_rsqrt) against the plain form (std::sqrt):
  // the same parameters within 1e-6 and the same points there; every step either form
  // accepts within tol by sampling its sub-arc; then the whole polyline against the
  // densely sampled curve and the greedy count, for pieces whose first block has its first
  // failing step first, last, in the middle, or none (each case met at least twice).
  const IsaRestore restore;
  for (batch::Isa isa : available_isas()) {
    ASSERT_TRUE(batch::select_isa(isa));
    SCOPED_TRACE(batch::isa_name(isa));
    test::SplitMix64 rng{33};
    const double tol = 1e-3;
    int first = 0, last = 0, middle = 0, none = 0, long_pieces = 0;
    for (int c = 0; c < 400 && (first < 2 || last < 2 || middle < 2 || none < 2); ++c) {
      detail::SmallPiece<double, 2> s;
      s.m = 4;
      std::vector<P2> Q(4);
      for (auto& q : Q) q = P2{rng.uniform(0, 0.8), rng.uniform(0, 0.8)};
      for (int i = 0; i < 4; ++i) s.q[static_cast<std::size_t>(i)] = Q[static_cast<std::size_t>(i)];
      detail::SmallOptimalPlan<double> plan;
      detail::small_optimal_plan(s, tol, plan);
      if (!plan.sampled || plan.n < 3) continue;
      const B2 curve(Q);
      const FirstBlock a = first_block(plan, tol, true), b = first_block(plan, tol, false);
      for (int k = 1; k <= a.cnt; ++k) {
        EXPECT_NEAR(a.t[k], b.t[k], 1e-6) << c << " " << k;
        EXPECT_NEAR(a.x[k], curve(a.t[k])[0], 1e-12);
        EXPECT_NEAR(a.y[k], curve(a.t[k])[1], 1e-12);
        for (const FirstBlock* f : {&a, &b}) {
          if ((f->ok >> k) & 1u) {
            EXPECT_LE(step_deviation(curve, f->t[k - 1], f->t[k]).first, tol * (1 + 1e-6)) << c << " " << k;
          }
        }
      }
      const bool full_block = plan.n - 1 > FirstBlock::B;
      long_pieces += full_block;
      int* which = a.fail == 0 ? &none : a.fail == 1 ? &first : a.fail == a.cnt ? &last : &middle;
      if (*which >= 2) continue;
      ++*which;
      const auto poly = checked_optimal(curve, tol, "random cubic");
      EXPECT_LE(static_cast<double>(poly.size() - 1), 1.05 * static_cast<double>(test::near_optimal_count(curve, tol)) + 1) << c;
    }
    EXPECT_EQ(first, 2);
    EXPECT_EQ(last, 2);
    EXPECT_EQ(middle, 2);
    EXPECT_EQ(none, 2);
    EXPECT_GT(long_pieces, 10);  // pieces of more than one block
  }
}

#if defined(__GNUC__)
TEST(FlattenOptimal, ParabolaBlocksAgainstScalarForms) {
  // The closed-form (one parabola) walk's block in vector lanes against the scalar forms it
  // stands for: each parameter within 1e-9 of parabola_integral_inverse's (std::sqrt), each
  // point the piece's, and each step's bit exactly parabola_step_within (itself tested
  // against sampling above) and t < 1, on random quadratics at several tolerances and
  // blocks; then their whole polylines against dense sampling.
  const IsaRestore restore;
  for (batch::Isa isa : available_isas()) {
    ASSERT_TRUE(batch::select_isa(isa));
    SCOPED_TRACE(batch::isa_name(isa));
    test::SplitMix64 rng{44};
    constexpr int B = detail::optimal_block;
    int steps = 0, refused = 0;
    for (int c = 0; c < 200; ++c) {
      std::vector<P2> Q(3);
      for (auto& q : Q) q = P2{rng.uniform(0, 0.8), rng.uniform(0, 0.8)};
      if (c % 4 == 0) Q[1] = P2{Q[0][0] + 30 * (Q[1][0] - Q[0][0]), Q[1][1]};  // sharp tips, long chords
      detail::SmallPiece<double, 2> s;
      s.m = 3;
      for (int i = 0; i < 3; ++i) s.q[static_cast<std::size_t>(i)] = Q[static_cast<std::size_t>(i)];
      const double tol = c % 3 == 0 ? 1e-2 : c % 3 == 1 ? 1e-3 : 1e-4;
      detail::SmallOptimalPlan<double> plan;
      detail::small_optimal_plan(s, tol, plan);
      if (!plan.closed || plan.n < 2) continue;
      const B2 curve(Q);
      const double df = 1.0 / plan.n, f_base = rng.uniform(0, 0.2) * df;  // (a base as after a repair)
      for (int first = 1; first < plan.n; first += B) {
        const double tp = first == 1 ? 0.0 : rng.uniform(0, 1) * 0.5;
        double bt[B], bx[B], by[B];
        const unsigned ok = detail::optimal_parabola_block_lanes(plan, f_base, df, first, tp, bt, bx, by);
        for (int k = 0; k < B && first + k < plan.n; ++k) {
          const double u = std::min(f_base + (first + k) * df, 1.0);
          const auto& p = plan.span;
          const double t =
              p.sx != 0 ? std::clamp((detail::parabola_integral_inverse(p.a0 + u * p.da) - p.x0) * p.sx, 0.0, 1.0) : u;
          EXPECT_NEAR(bt[k], t, 1e-9) << c << " " << k;
          EXPECT_NEAR(bx[k], curve(bt[k])[0], 1e-12);
          EXPECT_NEAR(by[k], curve(bt[k])[1], 1e-12);
          const double prev = k ? bt[k - 1] : tp;
          const bool want = detail::parabola_step_within(plan, prev, bt[k]) && bt[k] < 1;
          EXPECT_EQ(((ok >> k) & 1u) != 0, want) << c << " " << k;
          ++steps;
          refused += !want;
        }
      }
      checked_optimal(curve, tol, "random quadratic");
    }
    EXPECT_GT(steps, 2000);
    EXPECT_GT(refused, 20);  // both outcomes met
  }
}
#endif

TEST(FlattenOptimal, CompiledWalkSameInEveryInstructionSet) {
  // flatten() of double plane cubics and quadratics runs the walk compiled in src/flatten
  // with the lane kernels of the active instruction set: one rounding per operation in
  // every set (no FMA contraction), so the polylines are equal bit for bit across sets,
  // on random pieces (sampled and one-parabola plans, repairs included) at several
  // tolerances. The float walk stays in the header (PlainBlocks): its ends exact.
  const IsaRestore restore;
  const auto isas = available_isas();
  test::SplitMix64 rng{55};
  int compared = 0;
  for (int c = 0; c < 300; ++c) {
    std::vector<P2> Q(c % 2 == 0 ? 4 : 3);
    for (auto& q : Q) q = P2{rng.uniform(-50, 50), rng.uniform(-50, 50)};
    const double tol = c % 3 == 0 ? 1e-1 : c % 3 == 1 ? 1e-3 : 1e-5;
    const B2 curve(Q);
    ASSERT_TRUE(batch::select_isa(isas.front()));
    const auto ref = flatten(curve, tol, FlattenMethod::optimal);
    for (std::size_t i = 1; i < isas.size(); ++i) {
      ASSERT_TRUE(batch::select_isa(isas[i]));
      EXPECT_EQ(flatten(curve, tol, FlattenMethod::optimal), ref) << c << " " << batch::isa_name(isas[i]);
      ++compared;
    }
  }
  if (isas.size() > 1) {
    EXPECT_EQ(compared, 300 * static_cast<int>(isas.size() - 1));
  }
  std::vector<Point<float, 2>> Qf{{0, 0}, {1, 2}, {3, -1}, {4, 1}};
  const Bezier<float, 2> cf(Qf);
  const auto pf = flatten(cf, 1e-3f, FlattenMethod::optimal);
  EXPECT_EQ(pf.front(), Qf.front());
  EXPECT_EQ(pf.back(), Qf.back());
  EXPECT_GT(pf.size(), 10u);
}

TEST(FlattenOptimal, CuspInflectionLoopWithinTolerance) {
  // Cusp at t = 1/2 (B'(1/2) = 0), an S-curve (one inflection), a loop; tolerances from
  // far above to far below the curves' size 1.
  const B2 cusp{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  ASSERT_LT(norm(cusp.derivative(1)(0.5).to_vector()), 1e-15);
  const B2 inflection{{0, 0}, {1, 1}, {2, -1}, {3, 0}};
  const B2 loop{{0, 0}, {2, 1}, {-1, 1}, {1, 0}};
  for (const double tol : {10.0, 0.3, 1e-2, 1e-4, 1e-5}) {
    checked_optimal(cusp, tol, "cusp");
    checked_optimal(inflection, tol, "inflection");
    checked_optimal(loop, tol, "loop");
  }
  // A tolerance beyond the curve's extent: the chord.
  EXPECT_EQ(flatten(cusp, 10.0, FlattenMethod::optimal).size(), 2u);
}

TEST(FlattenOptimal, DegenerateCurves) {
  // Every control point equal: the point, written as its two ends.
  const B2 point{{3, 4}, {3, 4}, {3, 4}, {3, 4}};
  EXPECT_EQ(flatten(point, 0.1, FlattenMethod::optimal), (std::vector<P2>{{3, 4}, {3, 4}}));
  // Collinear, running past its end and back (zero density everywhere: only the checks'
  // overshoot term sees the reversal), and a quadratic folding back on itself.
  checked_optimal(B2{{0, 0}, {2, 0}, {-1, 0}, {1, 0}}, 1e-3, "collinear reversal");
  checked_optimal(B2{{0, 0}, {3, 3}, {1, 1}}, 1e-3, "collinear quadratic reversal");
  // Coincident inner points, a line as a cubic, a degree-1 piece.
  checked_optimal(B2{{0, 0}, {1, 2}, {1, 2}, {2, 0}}, 1e-3, "double inner point");
  EXPECT_EQ(flatten(B2{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, 1e-9, FlattenMethod::optimal).size(), 2u);
  EXPECT_EQ(flatten(B2{{0, 0}, {5, 1}}, 1e-9, FlattenMethod::optimal).size(), 2u);
}

TEST(FlattenOptimal, QuadraticsCheckedOnTheParabola) {
  // Quadratics (and cubics whose cubic term is below 1e-3 tol) have their steps checked on
  // the parabola in closed form: a sharp tip (the arc overshoots a long chord's ends), a
  // nearly straight arc (large parabola coordinates), a symmetric arch, each as a
  // quadratic and elevated (exactly) to a cubic, at tolerances around their size and far
  // below it.
  const std::vector<std::vector<P2>> quads = {
      {{0, 0}, {10, 1}, {0, 2}},      // sharp tip near t = 1/2
      {{0, 0}, {1, 1e-4}, {2, 0}},    // nearly straight
      {{0, 0}, {50, 100}, {100, 0}},  // arch
      {{0, 0}, {100, 0}, {0, 1e-3}},  // folded back on itself, not collinear
  };
  for (const auto& Q : quads) {
    const B2 quad(Q);
    const B2 elevated{Q[0], Q[0] + (2.0 / 3) * (Q[1] - Q[0]), Q[2] + (2.0 / 3) * (Q[1] - Q[2]), Q[2]};
    for (const double rel : {0.3, 1e-2, 1e-4}) {
      double extent = 0;
      for (const auto& q : Q) extent = std::max(extent, norm(q - Q[0]));
      checked_optimal(quad, rel * extent, "quadratic");
      checked_optimal(elevated, rel * extent, "elevated quadratic");
    }
  }
}

TEST(FlattenOptimal, HugeAndTinyCoordinates) {
  // Scaling the curve and tolerance by 2^k scales the polyline exactly (the unit-scale
  // copy), from 2^-1000 to 2^1000; and 1e150 / 1e-150 coordinates stay within tolerance.
  const B2 c{{0, 0}, {1, 1}, {0, 1}, {1, 0.25}};
  const auto base = flatten(c, 1e-3, FlattenMethod::optimal);
  for (const int k : {-1000, -300, 300, 1000}) {
    std::vector<P2> Q;
    for (const auto& p : c.points()) Q.emplace_back(std::ldexp(p[0], k), std::ldexp(p[1], k));
    const auto poly = flatten(B2(Q), std::ldexp(1e-3, k), FlattenMethod::optimal);
    ASSERT_EQ(poly.size(), base.size()) << k;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      EXPECT_EQ(poly[i][0], std::ldexp(base[i][0], k)) << k;
      EXPECT_EQ(poly[i][1], std::ldexp(base[i][1], k)) << k;
    }
  }
  for (const double s : {1e150, 1e-150}) {
    const B2 big{{s, -s}, {3 * s, 2 * s}, {-s, 2 * s}, {s, 0}};
    checked_optimal(big, 1e-3 * s, "extreme scale");
  }
}

TEST(FlattenOptimal, CountsNearTheGreedyCount) {
  // A quadratic (one parabola: the count in closed form), its exact elevation to a cubic
  // (same polyline), and cubics: within 1% (+1) and 5% (+1) of the greedy count, and the
  // count told before emitting (flatten_count_estimate, the plan) equal to the emitted one
  // unless a step needed its end moved (then within 2).
  const B2 quad{{0, 0}, {50, 100}, {100, 0}};
  const B2 elevated{{0, 0}, {100.0 / 3, 200.0 / 3}, {200.0 / 3, 200.0 / 3}, {100, 0}};
  const auto pq = checked_optimal(quad, 0.01, "quadratic");
  const auto pe = checked_optimal(elevated, 0.01, "elevated");
  EXPECT_EQ(pq.size(), pe.size());
  const long gq = test::near_optimal_count(quad, 0.01);
  EXPECT_LE(static_cast<double>(pq.size() - 1), 1.01 * static_cast<double>(gq) + 1);
  EXPECT_EQ(flatten_count_estimate(quad, 0.01), static_cast<double>(pq.size() - 1));
  for (const B2& c : {B2{{10, 20}, {90, 95}, {5, 80}, {70, 3}}, B2{{0, 0}, {100, 100}, {0, 100}, {100, 0}}}) {
    const auto p = checked_optimal(c, 0.1, "cubic");
    const double n = static_cast<double>(p.size() - 1);
    EXPECT_LE(n, 1.05 * static_cast<double>(test::near_optimal_count(c, 0.1)) + 1);
    EXPECT_NEAR(flatten_count_estimate(c, 0.1), n, 2);
  }
}

// Wang's count (detail::wang_count) stays finite where its plain form overflows: the
// second difference of a parabola with coordinates near the largest double, and a
// tolerance near the smallest normal number. Closed form: for P0, P1, P2 the count is
// ceil(sqrt(2 * 1 / 8 * |P0 - 2 P1 + P2| / tol)), here |P0 - 2 P1 + P2| = 4 * 2^1020 (y)
// and tol = 2^-1000, so sqrt(2^1020 / 2^-1000) = 2^1010, an exact power of two.
TEST(FlattenUniform, WangCountOverflowSafe) {
  const double big = std::ldexp(1.0, 1020);
  const std::vector<P2> P{P2{-big, 0}, P2{0, 2 * big}, P2{big, 0}};
  const double tol = std::ldexp(1.0, -1000);
  const double n = casteljau::detail::wang_count(std::span<const P2>(P), tol);
  EXPECT_EQ(n, std::ldexp(1.0, 1010));
  // The plain form where nothing overflows (unit coordinates): the same formula.
  const std::vector<P2> Q{P2{-1, 0}, P2{0, 2}, P2{1, 0}};
  EXPECT_EQ(casteljau::detail::wang_count(std::span<const P2>(Q), 1e-2), std::ceil(std::sqrt(0.25 * 4 / 1e-2)));
}

}  // namespace

