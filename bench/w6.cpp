// W6 of docs/performance.md: intersections of 10,000 random pairs of plane
// cubics, against lib2geom (CubicBezier::intersect, find_intersections_bezier_clipping) and
// OCCT (Geom2dAPI_InterCurveCurve) in the same run, each checked against the workload's
// reference: recursive subdivision of both curves in long double. Names W6/<library>/<method>;
// one iteration intersects all pairs. Counters: intersections, pairs_missed, pairs_extra,
// max_distance (docs/performance.md, "Names and counters"); reported (hits before merging).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/curves/bezier.hpp"
#include "common.hpp"

// Our method comes from the intersection work (issue 8); without it only the peers and the
// reference run.
#if __has_include("casteljau/algo/intersect.hpp")
#include "casteljau/algo/intersect.hpp"
#define CASTELJAU_BENCH_HAVE_INTERSECT 1
#else
#define CASTELJAU_BENCH_HAVE_INTERSECT 0
#endif

#if CASTELJAU_BENCH_HAVE_2GEOM
#include <2geom/basic-intersection.h>
#include <2geom/bezier-curve.h>
#endif
#if CASTELJAU_BENCH_HAVE_OCCT_ALGO
#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2dInt_GInter.hxx>
#include <IntRes2d_IntersectionPoint.hxx>
#include <IntRes2d_IntersectionSegment.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Pnt2d.hxx>
#endif

namespace {

using P2 = casteljau::Point<double, 2>;
using Cubic = std::array<P2, 4>;
/// A reported or reference intersection: parameters (s on curve A, t on curve B).
using Hit = std::pair<double, double>;

constexpr std::size_t pair_count = 10'000;
/// Hits closer than this in both parameters are one intersection (docs/performance.md, W6).
constexpr double merge_distance = 1e-6;

// ---- the reference: long double subdivision -------------------------------------------

using LP = std::array<long double, 2>;
using LCubic = std::array<LP, 4>;

/// Halves of a cubic at t = 1/2 (de Casteljau).
std::pair<LCubic, LCubic> halves(const LCubic& c) {
  LCubic l, r;
  for (int k = 0; k < 2; ++k) {
    const long double p01 = (c[0][k] + c[1][k]) / 2, p12 = (c[1][k] + c[2][k]) / 2, p23 = (c[2][k] + c[3][k]) / 2;
    const long double p012 = (p01 + p12) / 2, p123 = (p12 + p23) / 2, mid = (p012 + p123) / 2;
    l[0][k] = c[0][k], l[1][k] = p01, l[2][k] = p012, l[3][k] = mid;
    r[0][k] = mid, r[1][k] = p123, r[2][k] = p23, r[3][k] = c[3][k];
  }
  return {l, r};
}

/// Control boxes meet (closed boxes: touching counts). The curve lies in the convex hull of
/// its control points, so disjoint boxes mean no common point.
bool boxes_meet(const LCubic& a, const LCubic& b) {
  for (int k = 0; k < 2; ++k) {
    long double alo = a[0][k], ahi = alo, blo = b[0][k], bhi = blo;
    for (int i = 1; i < 4; ++i) {
      alo = std::min(alo, a[i][k]), ahi = std::max(ahi, a[i][k]);
      blo = std::min(blo, b[i][k]), bhi = std::max(bhi, b[i][k]);
    }
    if (ahi < blo || bhi < alo) return false;
  }
  return true;
}

/// The workload's reference: both curves halved together, pairs of parts whose control boxes
/// meet kept, down to parameter width 2^-34; surviving leaves are hits at their midpoints.
/// Throws past 4 10^6 nodes per pair (docs/performance.md: never hit).
struct Reference {
  static constexpr int depth = 34;
  static constexpr std::size_t node_cap = 4'000'000;
  std::size_t nodes = 0;
  std::vector<Hit> leaves;

  void run(const LCubic& a, const LCubic& b, long double s0, long double t0, int level) {
    if (++nodes > node_cap) throw std::runtime_error("W6 reference: more than 4e6 subdivision nodes for one pair");
    if (!boxes_meet(a, b)) return;
    const long double w = std::ldexp(1.0L, -level);
    if (level == depth) {
      leaves.emplace_back(static_cast<double>(s0 + w / 2), static_cast<double>(t0 + w / 2));
      return;
    }
    const auto [al, ar] = halves(a);
    const auto [bl, br] = halves(b);
    const long double h = w / 2;
    run(al, bl, s0, t0, level + 1);
    run(al, br, s0, t0 + h, level + 1);
    run(ar, bl, s0 + h, t0, level + 1);
    run(ar, br, s0 + h, t0 + h, level + 1);
  }
};

/// Groups hits that chain together by |ds| < 1e-6 and |dt| < 1e-6 (single linkage) and
/// returns one hit per group (its first by s).
std::vector<Hit> merged(std::vector<Hit> hits) {
  std::sort(hits.begin(), hits.end());
  std::vector<std::size_t> parent(hits.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const std::function<std::size_t(std::size_t)> find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < hits.size(); ++i)
    for (std::size_t j = i + 1; j < hits.size() && hits[j].first - hits[i].first < merge_distance; ++j)
      if (std::abs(hits[j].second - hits[i].second) < merge_distance) parent[find(j)] = find(i);
  std::vector<Hit> out;
  for (std::size_t i = 0; i < hits.size(); ++i)
    if (find(i) == i) out.push_back(hits[i]);
  return out;
}

LCubic to_long(const Cubic& c) {
  LCubic l;
  for (int i = 0; i < 4; ++i) l[std::size_t(i)] = {c[std::size_t(i)][0], c[std::size_t(i)][1]};
  return l;
}

/// c(t) in long double (Bernstein form).
LP value(const Cubic& c, long double t) {
  const long double u = 1 - t;
  const long double b[4] = {u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t};
  LP p{0, 0};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 2; ++k) p[std::size_t(k)] += b[i] * c[std::size_t(i)][k];
  return p;
}

/// The workload's inputs (seed 6, the workload's number): per pair, curve A's P_k.x, P_k.y
/// for k = 0..3, then curve B's; and the reference intersections of every pair.
struct W6Data {
  std::vector<std::pair<Cubic, Cubic>> pairs;
  std::vector<std::vector<Hit>> reference;  // merged, per pair
  std::size_t reference_total = 0;

  W6Data() : pairs(pair_count), reference(pair_count) {
    bench::SplitMix64 rng(6);
    for (auto& [a, b] : pairs) {
      for (auto& p : a) p[0] = rng.uniform(), p[1] = rng.uniform();
      for (auto& p : b) p[0] = rng.uniform(), p[1] = rng.uniform();
    }
    std::size_t max_nodes = 0;
    for (std::size_t i = 0; i < pair_count; ++i) {
      Reference r;
      r.run(to_long(pairs[i].first), to_long(pairs[i].second), 0, 0, 0);
      max_nodes = std::max(max_nodes, r.nodes);
      reference[i] = merged(std::move(r.leaves));
      reference_total += reference[i].size();
    }
    std::fprintf(stderr, "W6 reference: %zu intersections in %zu pairs (at most %zu subdivision nodes for one pair)\n", reference_total,
                 pair_count, max_nodes);
  }
};

const W6Data& data() {
  static const W6Data d;
  return d;
}

/// Each method's merged counts per pair, for the lib2geom / OCCT disagreement list.
std::map<std::string, std::vector<std::size_t>>& counts_by_method() {
  static std::map<std::string, std::vector<std::size_t>> m;
  return m;
}

/// The hits of one run, pair by pair: hits[first[i] .. first[i + 1]) belong to pair i.
struct Hits {
  std::vector<Hit> hits;
  std::vector<std::size_t> first;
  void clear() {
    hits.clear();
    first.clear();
  }
  void end_pair() { first.push_back(hits.size()); }
};

/// Runs one method: intersect_all(out) appends the hits of every pair to out.hits and calls
/// out.end_pair() after each pair (out.first starts with 0).
void run(benchmark::State& state, const std::string& name, const std::function<void(Hits&)>& intersect_all) {
  const W6Data& d = data();
  Hits out;
  out.hits.reserve(4 * pair_count);
  out.first.reserve(pair_count + 1);
  for (auto _ : state) {
    out.clear();
    out.first.push_back(0);
    intersect_all(out);
    benchmark::DoNotOptimize(out.hits.data());
    benchmark::ClobberMemory();
  }
  if (out.first.size() != pair_count + 1) throw std::logic_error("W6: a method did not report every pair");
  std::size_t total = 0, missed = 0, extra = 0;
  double max_distance = 0;
  std::vector<std::size_t> counts(pair_count);
  for (std::size_t i = 0; i < pair_count; ++i) {
    const std::vector<Hit> pair_hits(out.hits.begin() + std::ptrdiff_t(out.first[i]), out.hits.begin() + std::ptrdiff_t(out.first[i + 1]));
    for (const auto& [s, t] : pair_hits) {
      const LP a = value(d.pairs[i].first, s), b = value(d.pairs[i].second, t);
      max_distance = std::max(max_distance, static_cast<double>(std::hypot(a[0] - b[0], a[1] - b[1])));
    }
    counts[i] = merged(pair_hits).size();
    total += counts[i];
    missed += counts[i] < d.reference[i].size();
    extra += counts[i] > d.reference[i].size();
  }
  counts_by_method()[name] = counts;
  state.counters["intersections"] = static_cast<double>(total);
  state.counters["pairs_missed"] = static_cast<double>(missed);
  state.counters["pairs_extra"] = static_cast<double>(extra);
  state.counters["max_distance"] = max_distance;
  state.counters["reported"] = static_cast<double>(out.hits.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pair_count));
}

/// The reference itself, timed (long double subdivision to 2^-34, then the merge).
void reference_all(Hits& out) {
  for (const auto& [a, b] : data().pairs) {
    Reference r;
    r.run(to_long(a), to_long(b), 0, 0, 0);
    const auto m = merged(std::move(r.leaves));
    out.hits.insert(out.hits.end(), m.begin(), m.end());
    out.end_pair();
  }
}

#if CASTELJAU_BENCH_HAVE_INTERSECT
/// casteljau::intersect on two Bezier<double, 2> built before timing; an overlap (none in
/// this data) would count as one hit at its start.
void casteljau_intersect(Hits& out) {
  static const auto curves = [] {
    std::vector<std::pair<casteljau::Bezier<double, 2>, casteljau::Bezier<double, 2>>> cs;
    for (const auto& [a, b] : data().pairs)
      cs.emplace_back(casteljau::Bezier<double, 2>(std::vector<P2>(a.begin(), a.end())),
                      casteljau::Bezier<double, 2>(std::vector<P2>(b.begin(), b.end())));
    return cs;
  }();
  for (const auto& [a, b] : curves) {
    const auto r = casteljau::intersect(a, b);
    for (const auto& p : r.points) out.hits.emplace_back(p.ta, p.tb);
    for (const auto& o : r.overlaps) out.hits.emplace_back(o.a.lo, o.b_start);
    out.end_pair();
  }
}
#endif

#if CASTELJAU_BENCH_HAVE_2GEOM
Geom::Point geom(const P2& p) { return Geom::Point(p[0], p[1]); }

void lib2geom_intersect(Hits& out) {
  static const auto curves = [] {
    std::vector<std::pair<Geom::CubicBezier, Geom::CubicBezier>> cs;
    for (const auto& [a, b] : data().pairs)
      cs.emplace_back(Geom::CubicBezier(geom(a[0]), geom(a[1]), geom(a[2]), geom(a[3])),
                      Geom::CubicBezier(geom(b[0]), geom(b[1]), geom(b[2]), geom(b[3])));
    return cs;
  }();
  for (const auto& [a, b] : curves) {
    for (const auto& x : a.intersect(b, 1e-6)) out.hits.emplace_back(x.first, x.second);
    out.end_pair();
  }
}

void lib2geom_bezier_clipping(Hits& out) {
  static const auto curves = [] {
    std::vector<std::pair<std::vector<Geom::Point>, std::vector<Geom::Point>>> cs;
    for (const auto& [a, b] : data().pairs)
      cs.emplace_back(std::vector<Geom::Point>{geom(a[0]), geom(a[1]), geom(a[2]), geom(a[3])},
                      std::vector<Geom::Point>{geom(b[0]), geom(b[1]), geom(b[2]), geom(b[3])});
    return cs;
  }();
  std::vector<std::pair<double, double>> xs;
  for (const auto& [a, b] : curves) {
    xs.clear();
    Geom::find_intersections_bezier_clipping(xs, a, b, 1e-6);
    out.hits.insert(out.hits.end(), xs.begin(), xs.end());
    out.end_pair();
  }
}
#endif

#if CASTELJAU_BENCH_HAVE_OCCT_ALGO
Handle(Geom2d_BezierCurve) occt_curve(const Cubic& c) {
  TColgp_Array1OfPnt2d poles(1, 4);
  for (int i = 0; i < 4; ++i) poles(i + 1) = gp_Pnt2d(c[std::size_t(i)][0], c[std::size_t(i)][1]);
  return new Geom2d_BezierCurve(poles);
}

/// Points, and each overlap segment as one hit at its first point (none in this data).
void occt_inter_curve_curve(Hits& out) {
  static const auto curves = [] {
    std::vector<std::pair<Handle(Geom2d_BezierCurve), Handle(Geom2d_BezierCurve)>> cs;
    for (const auto& [a, b] : data().pairs) cs.emplace_back(occt_curve(a), occt_curve(b));
    return cs;
  }();
  for (const auto& [a, b] : curves) {
    const Geom2dAPI_InterCurveCurve x(a, b, 1e-6);
    const Geom2dInt_GInter& g = x.Intersector();
    for (int i = 1; i <= g.NbPoints(); ++i) out.hits.emplace_back(g.Point(i).ParamOnFirst(), g.Point(i).ParamOnSecond());
    for (int i = 1; i <= g.NbSegments(); ++i) {
      const IntRes2d_IntersectionSegment& seg = g.Segment(i);
      if (seg.HasFirstPoint())
        out.hits.emplace_back(seg.FirstPoint().ParamOnFirst(), seg.FirstPoint().ParamOnSecond());
      else
        out.hits.emplace_back(0.0, 0.0);
    }
    out.end_pair();
  }
}
#endif

void reg(const std::string& name, void (*intersect_all)(Hits&)) {
  benchmark::RegisterBenchmark(name.c_str(), [name, intersect_all](benchmark::State& st) { run(st, name, intersect_all); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

/// The pairs where lib2geom's CubicBezier::intersect and OCCT disagree, and which of them
/// matches the reference (docs/performance.md, W6), on stderr.
void list_disagreements() {
  const auto& m = counts_by_method();
  const auto g = m.find("W6/lib2geom/intersect"), o = m.find("W6/occt/InterCurveCurve");
  if (g == m.end() || o == m.end()) return;
  const W6Data& d = data();
  std::size_t n = 0;
  for (std::size_t i = 0; i < pair_count; ++i) {
    const std::size_t gc = g->second[i], oc = o->second[i], rc = d.reference[i].size();
    if (gc == oc) continue;
    ++n;
    std::fprintf(stderr, "W6 pair %zu: reference %zu, lib2geom %zu, occt %zu: %s matches the reference\n", i, rc, gc, oc,
                 gc == rc ? "lib2geom" : oc == rc ? "occt" : "neither");
  }
  std::fprintf(stderr, "W6: lib2geom (intersect) and OCCT disagree on %zu pairs\n", n);
}

}  // namespace

int main(int argc, char** argv) {
  reg("W6/reference/long_double_subdivision", reference_all);
#if CASTELJAU_BENCH_HAVE_INTERSECT
  reg("W6/casteljau/intersect", casteljau_intersect);
#endif
#if CASTELJAU_BENCH_HAVE_2GEOM
  reg("W6/lib2geom/intersect", lib2geom_intersect);
  reg("W6/lib2geom/bezier_clipping", lib2geom_bezier_clipping);
#endif
#if CASTELJAU_BENCH_HAVE_OCCT_ALGO
  reg("W6/occt/InterCurveCurve", occt_inter_curve_curve);
#endif
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  data();  // the reference, before any timing
  benchmark::RunSpecifiedBenchmarks();
  list_disagreements();
  benchmark::Shutdown();
  return 0;
}
