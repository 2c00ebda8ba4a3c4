// W3 and the quadratic half of W11 of docs/performance.md.
// W3: flattening at tolerance 0.1 of 10,000 random cubics
// (dataset `random`) and of DejaVuSans's quadratics elevated to cubics (`glyphs`), against
// cairo (cairo_copy_path_flat) and OCCT (GCPnts_TangentialDeflection, GCPnts_QuasiUniformDeflection)
// in the same run, with the workload's near-optimal count. Names W3/<library>/<method>/<dataset>;
// one iteration flattens every curve of the dataset. Counters (docs/performance.md, "Names and
// counters"): curves, segments, over_tolerance, max_deviation, measured after timing by
// dense sampling of every curve against its own polyline.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <tuple>
#include <functional>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/algo/flatten.hpp"
#include "casteljau/algo/offset.hpp"
#include "casteljau/algo/to_quadratic.hpp"
#include "casteljau/curves/bezier.hpp"
#include "common.hpp"

// The three methods of issue 8 (uniform, subdivision, optimal); before them, flatten() is
// the subdivision alone.
#if __has_include("casteljau/algo/flatten_method.hpp")
#include "casteljau/algo/flatten_method.hpp"
#define CASTELJAU_BENCH_HAVE_FLATTEN_METHODS 1
#else
#define CASTELJAU_BENCH_HAVE_FLATTEN_METHODS 0
#endif

#if CASTELJAU_BENCH_HAVE_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#endif
#if CASTELJAU_BENCH_HAVE_CAIRO
#include <cairo.h>
#endif
#if CASTELJAU_BENCH_HAVE_2GEOM
#include <2geom/bezier-curve.h>
#include <2geom/exception.h>
#include <2geom/path.h>
#include <2geom/piecewise.h>
#include <2geom/sbasis-geometric.h>
#include <2geom/sbasis-to-bezier.h>
#endif
#if CASTELJAU_BENCH_HAVE_OCCT_ALGO
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#endif

namespace {

using P2 = casteljau::Point<double, 2>;
using Cubic = std::array<P2, 4>;

constexpr double tolerance = 0.1;
constexpr const char* font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// ---- inputs ----------------------------------------------------------------------------

/// Dataset A (seed 3, the workload's number): for each of 10,000 cubics, for k = 0..3,
/// P_k.x = uniform(0, 100) then P_k.y = uniform(0, 100).
std::vector<Cubic> random_cubics() {
  bench::SplitMix64 rng(3);
  std::vector<Cubic> cs(10'000);
  for (auto& c : cs)
    for (auto& p : c) {
      p[0] = rng.uniform(0, 100);
      p[1] = rng.uniform(0, 100);
    }
  return cs;
}

#if CASTELJAU_BENCH_HAVE_FREETYPE
/// Dataset B2: every conic_to of every glyph of DejaVuSans in glyph-index and
/// FT_Outline_Decompose order, in font units, elevated to the exact cubic
/// (C1 = P0 + 2/3 (P1 - P0), C2 = P2 + 2/3 (P1 - P2)). Line segments are left out.
struct GlyphCollector {
  P2 current{};
  std::vector<Cubic> cubics;
  static P2 point(const FT_Vector* v) { return P2{static_cast<double>(v->x), static_cast<double>(v->y)}; }
  static int move_to(const FT_Vector* to, void* user) {
    static_cast<GlyphCollector*>(user)->current = point(to);
    return 0;
  }
  static int line_to(const FT_Vector* to, void* user) { return move_to(to, user); }
  static int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto* g = static_cast<GlyphCollector*>(user);
    const P2 p0 = g->current, p1 = point(control), p2 = point(to);
    Cubic c{p0, p0, p2, p2};
    for (int k = 0; k < 2; ++k) {
      c[1][k] = p0[k] + 2.0 / 3.0 * (p1[k] - p0[k]);
      c[2][k] = p2[k] + 2.0 / 3.0 * (p1[k] - p2[k]);
    }
    g->cubics.push_back(c);
    g->current = p2;
    return 0;
  }
  static int cubic_to(const FT_Vector*, const FT_Vector*, const FT_Vector* to, void* user) { return move_to(to, user); }
};

/// Empty (with a message) when the font or FreeType fails.
std::vector<Cubic> glyph_cubics() {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  if (FT_Init_FreeType(&lib) != 0 || FT_New_Face(lib, font_path, 0, &face) != 0) {
    std::fprintf(stderr, "W3: cannot open %s (fonts-dejavu-core): skipping the glyphs dataset\n", font_path);
    if (lib) FT_Done_FreeType(lib);
    return {};
  }
  GlyphCollector g;
  FT_Outline_Funcs funcs{};
  funcs.move_to = &GlyphCollector::move_to;
  funcs.line_to = &GlyphCollector::line_to;
  funcs.conic_to = &GlyphCollector::conic_to;
  funcs.cubic_to = &GlyphCollector::cubic_to;
  long glyphs = 0;
  for (FT_Long gi = 0; gi < face->num_glyphs; ++gi) {
    if (FT_Load_Glyph(face, static_cast<FT_UInt>(gi), FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0) continue;
    if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) continue;
    ++glyphs;
    FT_Outline_Decompose(&face->glyph->outline, &funcs, &g);
  }
  std::fprintf(stderr, "W3 glyphs: %ld glyphs, units_per_EM %d, %zu quadratics\n", glyphs, face->units_per_EM, g.cubics.size());
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
  return std::move(g.cubics);
}
#endif

const std::vector<Cubic>& dataset(const std::string& name) {
  static std::map<std::string, std::vector<Cubic>> sets;
  auto it = sets.find(name);
  if (it != sets.end()) return it->second;
  std::vector<Cubic> cs;
  if (name == "random") cs = random_cubics();
#if CASTELJAU_BENCH_HAVE_FREETYPE
  if (name == "glyphs") cs = glyph_cubics();
#endif
  return sets.emplace(name, std::move(cs)).first->second;
}

// ---- polylines and their measurement ---------------------------------------------------

/// The polylines of a dataset: curve i's vertices are points[first[i] .. first[i + 1]).
struct Polylines {
  std::vector<P2> points;
  std::vector<std::size_t> first;
  void clear() {
    points.clear();
    first.assign(1, 0);
  }
  void end_curve() { first.push_back(points.size()); }
  std::size_t curves() const { return first.size() - 1; }
  std::size_t segments() const {
    std::size_t s = 0;
    for (std::size_t i = 0; i < curves(); ++i) s += first[i + 1] - first[i] - (first[i + 1] > first[i] ? 1 : 0);
    return s;
  }
};

/// B(t) of a cubic (de Casteljau).
P2 value(const Cubic& c, double t) {
  P2 p{};
  for (int k = 0; k < 2; ++k) {
    const double a = c[0][k] + t * (c[1][k] - c[0][k]), b = c[1][k] + t * (c[2][k] - c[1][k]), d = c[2][k] + t * (c[3][k] - c[2][k]);
    const double ab = a + t * (b - a), bd = b + t * (d - b);
    p[k] = ab + t * (bd - ab);
  }
  return p;
}

/// Squared distance from p to the segment [a, b].
double distance2_to_segment(const P2& p, const P2& a, const P2& b) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = p[0] - a[0], vy = p[1] - a[1];
  const double len2 = ux * ux + uy * uy;
  double s = len2 > 0 ? (ux * vx + uy * vy) / len2 : 0;
  s = std::clamp(s, 0.0, 1.0);
  const double dx = vx - s * ux, dy = vy - s * uy;
  return dx * dx + dy * dy;
}

/// docs/performance.md, W3: the curve sampled at S = 64 + 16 segments uniform parameters
/// t_j = j / (S - 1); the largest distance from a sample to the nearest segment of the polyline.
/// Exhaustive over the segments (a segment whose box is already farther than the best
/// distance is skipped without changing the result).
double deviation(const Cubic& c, const P2* v, std::size_t n) {
  if (n == 0) return INFINITY;
  const std::size_t segs = n - 1;
  const std::size_t S = 64 + 16 * segs;
  double worst2 = 0;
  std::size_t guess = 0;
  for (std::size_t j = 0; j < S; ++j) {
    const P2 p = value(c, static_cast<double>(j) / static_cast<double>(S - 1));
    if (segs == 0) {
      worst2 = std::max(worst2, (p[0] - v[0][0]) * (p[0] - v[0][0]) + (p[1] - v[0][1]) * (p[1] - v[0][1]));
      continue;
    }
    double best2 = distance2_to_segment(p, v[guess], v[guess + 1]);
    for (std::size_t k = 0; k < segs && best2 > 0; ++k) {
      const P2 &a = v[k], &b = v[k + 1];
      const double gx = std::max({0.0, std::min(a[0], b[0]) - p[0], p[0] - std::max(a[0], b[0])});
      const double gy = std::max({0.0, std::min(a[1], b[1]) - p[1], p[1] - std::max(a[1], b[1])});
      if (gx * gx + gy * gy >= best2) continue;
      const double d2 = distance2_to_segment(p, a, b);
      if (d2 < best2) best2 = d2, guess = k;
    }
    worst2 = std::max(worst2, best2);
  }
  return std::sqrt(worst2);
}

struct Measured {
  std::size_t curves = 0, segments = 0, over = 0;
  double max_deviation = 0;
};

Measured measure(const std::vector<Cubic>& cs, const Polylines& out) {
  if (out.curves() != cs.size()) throw std::logic_error("W3: a flattener did not report every curve");
  Measured m;
  m.curves = cs.size();
  m.segments = out.segments();
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const double d = deviation(cs[i], out.points.data() + out.first[i], out.first[i + 1] - out.first[i]);
    m.max_deviation = std::max(m.max_deviation, d);
    m.over += !(d <= 1.0001 * tolerance);
  }
  return m;
}

/// The counters of one benchmark. The measurement (a few seconds for some methods) is made
/// once per benchmark name and reused by the later repetitions: it does not change.
void report(benchmark::State& state, const std::string& name, const std::vector<Cubic>& cs, const Polylines& out) {
  static std::map<std::string, Measured> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, measure(cs, out)).first;
  const Measured& m = it->second;
  state.counters["curves"] = static_cast<double>(m.curves);
  state.counters["segments"] = static_cast<double>(m.segments);
  state.counters["over_tolerance"] = static_cast<double>(m.over);
  state.counters["max_deviation"] = m.max_deviation;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

/// Runs one flattener: flatten_all(curves, out) writes every curve's polyline (out cleared
/// before, one end_curve() per curve).
void run(benchmark::State& state, const std::string& name, const std::string& set,
         const std::function<void(const std::vector<Cubic>&, Polylines&)>& flatten_all) {
  const auto& cs = dataset(set);
  Polylines out;
  for (auto _ : state) {
    out.clear();
    flatten_all(cs, out);
    benchmark::DoNotOptimize(out.points.data());
    benchmark::ClobberMemory();
  }
  report(state, name, cs, out);
}

// ---- the near-optimal count -----------------------------------------------------------

/// W3's exact check (docs/performance.md): the sub-arc [t0, t1] of c lies within tol of the line
/// through c(t0) and c(t1). The signed distance d(t) = cross(u, c(t) - c(t0)) with u the
/// line's unit direction is a cubic in t (power basis of c); |d| is largest at the ends
/// (where it is 0) or at the real roots of d' inside (t0, t1).
struct Arc {
  std::array<P2, 4> a;  // c(t) = a0 + a1 t + a2 t^2 + a3 t^3
  explicit Arc(const Cubic& c) {
    for (int k = 0; k < 2; ++k) {
      a[0][k] = c[0][k];
      a[1][k] = 3 * (c[1][k] - c[0][k]);
      a[2][k] = 3 * (c[2][k] - 2 * c[1][k] + c[0][k]);
      a[3][k] = c[3][k] - 3 * c[2][k] + 3 * c[1][k] - c[0][k];
    }
  }
  bool within(const Cubic& c, double t0, double t1) const {
    const P2 A = value(c, t0), B = value(c, t1);
    const double lx = B[0] - A[0], ly = B[1] - A[1], len = std::hypot(lx, ly);
    if (!(len > 0)) return t1 == t0;
    const double ux = lx / len, uy = ly / len;
    const auto cross = [&](double x, double y) { return ux * y - uy * x; };
    const double c0 = cross(a[0][0] - A[0], a[0][1] - A[1]), c1 = cross(a[1][0], a[1][1]), c2 = cross(a[2][0], a[2][1]),
                 c3 = cross(a[3][0], a[3][1]);
    const auto d = [&](double t) { return ((c3 * t + c2) * t + c1) * t + c0; };
    // Roots of d'(t) = 3 c3 t^2 + 2 c2 t + c1 (numerically stable quadratic formula).
    const double qa = 3 * c3, qb = 2 * c2, qc = c1;
    double roots[2];
    int n = 0;
    if (qa == 0) {
      if (qb != 0) roots[n++] = -qc / qb;
    } else {
      const double disc = qb * qb - 4 * qa * qc;
      if (disc >= 0) {
        const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
        roots[n++] = q / qa;
        if (q != 0) roots[n++] = qc / q;
      }
    }
    for (int i = 0; i < n; ++i)
      if (roots[i] > t0 && roots[i] < t1 && !(std::abs(d(roots[i])) <= tolerance)) return false;
    return true;
  }
};

/// The greedy walk: from t0, the largest t1 (bisection to 1e-13) whose sub-arc passes the
/// check; vertices c(t_i).
void near_optimal(const std::vector<Cubic>& cs, Polylines& out) {
  for (const Cubic& c : cs) {
    const Arc arc(c);
    out.points.push_back(c[0]);
    double t0 = 0;
    while (t0 < 1) {
      double t1 = 1;
      if (!arc.within(c, t0, 1)) {
        double lo = t0, hi = 1;
        while (hi - lo > 1e-13) {
          const double mid = lo + (hi - lo) / 2;
          (arc.within(c, t0, mid) ? lo : hi) = mid;
        }
        t1 = std::max(lo, t0 + 1e-13);
      }
      out.points.push_back(t1 == 1 ? c[3] : value(c, t1));
      t0 = t1;
    }
    out.end_curve();
  }
}

// ---- own simple code and the library ---------------------------------------------------

/// Uniform steps, the count from Wang's bound n = ceil(sqrt(d (d - 1) / 8 max|P_i - 2 P_(i+1)
/// + P_(i+2)| / tol)) with d = 3, vertices c(i / n) (simple code written for the comparison).
void wang_uniform(const std::vector<Cubic>& cs, Polylines& out) {
  for (const Cubic& c : cs) {
    double m = 0;
    for (int i = 0; i < 2; ++i)
      m = std::max(m, std::hypot(c[std::size_t(i)][0] - 2 * c[std::size_t(i) + 1][0] + c[std::size_t(i) + 2][0],
                                 c[std::size_t(i)][1] - 2 * c[std::size_t(i) + 1][1] + c[std::size_t(i) + 2][1]));
    const int n = std::max(1, static_cast<int>(std::ceil(std::sqrt(0.75 * m / tolerance))));
    out.points.push_back(c[0]);
    for (int i = 1; i < n; ++i) out.points.push_back(value(c, static_cast<double>(i) / n));
    out.points.push_back(c[3]);
    out.end_curve();
  }
}

/// casteljau::flatten on Bezier<double, 2> curves built before timing (per dataset).
const std::vector<casteljau::Bezier<double, 2>>& casteljau_curves(const std::vector<Cubic>& cs) {
  static std::map<const std::vector<Cubic>*, std::vector<casteljau::Bezier<double, 2>>> built;
  auto& curves = built[&cs];
  if (curves.empty())
    for (const Cubic& c : cs) curves.emplace_back(std::vector<P2>(c.begin(), c.end()));
  return curves;
}

#if CASTELJAU_BENCH_HAVE_FLATTEN_METHODS
/// Every polyline appended to the one output vector (flatten's appending overload, where
/// the library has it: no allocation per curve).
template <casteljau::FlattenMethod M>
void casteljau_flatten(const std::vector<Cubic>& cs, Polylines& out) {
  for (const auto& c : casteljau_curves(cs)) {
#ifdef CASTELJAU_FLATTEN_APPENDS
    casteljau::flatten(c, tolerance, M, out.points);
#else
    const auto v = casteljau::flatten(c, tolerance, M);
    out.points.insert(out.points.end(), v.begin(), v.end());
#endif
    out.end_curve();
  }
}
#else
/// flatten(): the recursive subdivision (control points within tol of the chord segment).
void casteljau_subdivision(const std::vector<Cubic>& cs, Polylines& out) {
  for (const auto& c : casteljau_curves(cs)) {
    const auto v = casteljau::flatten(c, tolerance);
    out.points.insert(out.points.end(), v.begin(), v.end());
    out.end_curve();
  }
}
#endif

// ---- peers -----------------------------------------------------------------------------

#if CASTELJAU_BENCH_HAVE_CAIRO
/// cairo: one open subpath per curve (move_to, curve_to), cairo_copy_path_flat at tolerance
/// 0.1 with the identity CTM on a 1x1 A8 image surface; the path is parsed after timing.
/// cairo keeps coordinates in 24.8 fixed point (steps of 1/256 unit).
void cairo_run(benchmark::State& state, const std::string& name, const std::string& set) {
  const auto& cs = dataset(set);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(surface);
  cairo_set_tolerance(cr, tolerance);
  cairo_path_t* path = nullptr;
  for (auto _ : state) {
    if (path) cairo_path_destroy(path);
    cairo_new_path(cr);
    for (const Cubic& c : cs) {
      cairo_move_to(cr, c[0][0], c[0][1]);
      cairo_curve_to(cr, c[1][0], c[1][1], c[2][0], c[2][1], c[3][0], c[3][1]);
    }
    path = cairo_copy_path_flat(cr);
    benchmark::DoNotOptimize(path);
  }
  if (path->status != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cairo_copy_path_flat failed");
  // Every MOVE_TO starts the next curve's polyline.
  Polylines out;
  out.first.clear();
  for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
    const cairo_path_data_t& d = path->data[i];
    if (d.header.type == CAIRO_PATH_MOVE_TO) out.first.push_back(out.points.size());
    if (d.header.type == CAIRO_PATH_MOVE_TO || d.header.type == CAIRO_PATH_LINE_TO) out.points.push_back(P2{path->data[i + 1].point.x, path->data[i + 1].point.y});
  }
  out.first.push_back(out.points.size());
  cairo_path_destroy(path);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (out.curves() != cs.size())
    throw std::runtime_error("W3 cairo: " + std::to_string(out.curves()) + " subpaths for " + std::to_string(cs.size()) + " curves");
  report(state, name, cs, out);
}
#endif

#if CASTELJAU_BENCH_HAVE_OCCT_ALGO
/// Geom2d_BezierCurve objects, built before timing (per dataset).
const std::vector<Handle(Geom2d_BezierCurve)>& occt_curves(const std::vector<Cubic>& cs) {
  static std::map<const std::vector<Cubic>*, std::vector<Handle(Geom2d_BezierCurve)>> built;
  auto& v = built[&cs];
  if (v.empty())
    for (const Cubic& c : cs) {
      TColgp_Array1OfPnt2d poles(1, 4);
      for (int i = 0; i < 4; ++i) poles(i + 1) = gp_Pnt2d(c[std::size_t(i)][0], c[std::size_t(i)][1]);
      v.push_back(new Geom2d_BezierCurve(poles));
    }
  return v;
}

/// GCPnts_TangentialDeflection(adaptor, angular deflection, curvature deflection 0.1);
/// adaptor and algorithm constructed in the timed loop.
template <int AngularMilliradians>
void occt_tangential(const std::vector<Cubic>& cs, Polylines& out) {
  constexpr double angular = AngularMilliradians < 0 ? std::numbers::pi / 2 : AngularMilliradians / 1000.0;
  for (const auto& c : occt_curves(cs)) {
    const Geom2dAdaptor_Curve a(c);
    const GCPnts_TangentialDeflection f(a, angular, tolerance);
    for (int i = 1; i <= f.NbPoints(); ++i) {
      const gp_Pnt p = f.Value(i);
      out.points.push_back(P2{p.X(), p.Y()});
    }
    out.end_curve();
  }
}

/// GCPnts_QuasiUniformDeflection(adaptor, 0.1, C1).
void occt_quasi_uniform(const std::vector<Cubic>& cs, Polylines& out) {
  for (const auto& c : occt_curves(cs)) {
    const Geom2dAdaptor_Curve a(c);
    const GCPnts_QuasiUniformDeflection f(a, tolerance, GeomAbs_C1);
    if (!f.IsDone()) throw std::runtime_error("GCPnts_QuasiUniformDeflection failed");
    for (int i = 1; i <= f.NbPoints(); ++i) {
      const gp_Pnt p = f.Value(i);
      out.points.push_back(P2{p.X(), p.Y()});
    }
    out.end_curve();
  }
}
#endif

// ---- W11, quadratic approximation ------------------------------------------------------
// W3's datasets at tolerance 1e-3 and 1e-1 of the unit (random: the box, 100; glyphs: the
// em, 2048). Names W11/casteljau/quadratic/<dataset>/<1e-3|1e-1>; counters segments,
// over_tolerance (curves whose measured deviation exceeds 1.0001 x tol), max_deviation.
// The same measure is written in bench/w11_cu2qu.py for fonttools' cu2qu.

using Quad = std::array<P2, 3>;

P2 quad_point(const Quad& q, double s) {
  const double u = 1 - s;
  return P2{u * u * q[0][0] + 2 * u * s * q[1][0] + s * s * q[2][0], u * u * q[0][1] + 2 * u * s * q[1][1] + s * s * q[2][1]};
}

/// Newton on (x(s) - p) . x'(s) = 0 from s, kept in [lo, hi], for x = f (point, first and
/// second derivative at s); returns the smaller of the distances at the start and at the
/// end (both points of the curve, so never below the true distance: an iteration that
/// strays to a farther stationary point cannot inflate it).
template <class F>
double refine_distance(const F& f, const P2& p, double s, double lo, double hi) {
  const auto dist = [&](double u) {
    const P2 x = std::get<0>(f(u));
    return std::hypot(x[0] - p[0], x[1] - p[1]);
  };
  const double d0 = dist(s);
  for (int it = 0; it < 8; ++it) {
    const auto [x, d1, d2] = f(s);
    const double rx = x[0] - p[0], ry = x[1] - p[1];
    const double g = rx * d1[0] + ry * d1[1];
    double gp = d1[0] * d1[0] + d1[1] * d1[1] + rx * d2[0] + ry * d2[1];
    if (!(gp > 0)) gp = d1[0] * d1[0] + d1[1] * d1[1];
    if (!(gp > 0)) break;
    s = std::clamp(s - g / gp, lo, hi);
  }
  return std::min(d0, dist(s));
}

/// The distance from p to the curve f sampled at the n points x_j = f(j / (n - 1)): every
/// local minimum of the sampled distance (along the samples, the ends included) refined by
/// Newton's method within its neighbouring samples, the smallest kept. Not only the nearest
/// sample: where the curve passes close to itself, or moves fast (samples far apart), the
/// nearest sample can lie on another branch than the nearest point.
template <class F>
double distance_to(const F& f, const P2* x, std::size_t n, const P2& p) {
  const auto d2 = [&](std::size_t j) { return (x[j][0] - p[0]) * (x[j][0] - p[0]) + (x[j][1] - p[1]) * (x[j][1] - p[1]); };
  const double h = 1.0 / static_cast<double>(n - 1);
  double best = INFINITY;
  double prev = INFINITY, cur = d2(0);
  for (std::size_t j = 0; j < n; ++j) {
    const double next = j + 1 < n ? d2(j + 1) : INFINITY;
    if (cur <= prev && cur <= next) {
      const double s = static_cast<double>(j) * h;
      best = std::min(best, refine_distance(f, p, s, j > 0 ? s - h : 0.0, j + 1 < n ? s + h : 1.0));
    }
    prev = cur;
    cur = next;
  }
  return best;
}

/// The two-sided distance between a cubic and its chain of quadratics: the cubic at
/// S = 64 + 16 k parameters (k segments) to the chain, each quadratic at 65 parameters to
/// the cubic; each distance as in distance_to (the quadratics sampled at 33 parameters,
/// the cubic at its S). The same measure as bench/w11_cu2qu.py's.
double quad_deviation(const Cubic& c, const Quad* q, std::size_t k) {
  const std::size_t S = 64 + 16 * k;
  const auto qf = [](const Quad& a) {
    return [&a](double s) {
      const P2 x = quad_point(a, s);
      const P2 d1{2 * ((1 - s) * (a[1][0] - a[0][0]) + s * (a[2][0] - a[1][0])), 2 * ((1 - s) * (a[1][1] - a[0][1]) + s * (a[2][1] - a[1][1]))};
      const P2 d2{2 * (a[0][0] - 2 * a[1][0] + a[2][0]), 2 * (a[0][1] - 2 * a[1][1] + a[2][1])};
      return std::tuple{x, d1, d2};
    };
  };
  const auto cf = [&c](double s) {
    const double u = 1 - s;
    const P2 x = value(c, s);
    P2 d1, d2;
    for (int i = 0; i < 2; ++i) {
      d1[i] = 3 * (u * u * (c[1][i] - c[0][i]) + 2 * u * s * (c[2][i] - c[1][i]) + s * s * (c[3][i] - c[2][i]));
      d2[i] = 6 * (u * (c[2][i] - 2 * c[1][i] + c[0][i]) + s * (c[3][i] - 2 * c[2][i] + c[1][i]));
    }
    return std::tuple{x, d1, d2};
  };
  double worst = 0;
  std::vector<P2> cs(S);
  for (std::size_t j = 0; j < S; ++j) cs[j] = value(c, static_cast<double>(j) / static_cast<double>(S - 1));
  std::vector<std::array<P2, 33>> qs(k);
  for (std::size_t i = 0; i < k; ++i)
    for (int j = 0; j <= 32; ++j) qs[i][static_cast<std::size_t>(j)] = quad_point(q[i], j / 32.0);
  for (const P2& p : cs) {
    double best = INFINITY;
    for (std::size_t i = 0; i < k; ++i) best = std::min(best, distance_to(qf(q[i]), qs[i].data(), 33, p));
    worst = std::max(worst, best);
  }
  for (std::size_t i = 0; i < k; ++i)
    for (int j = 0; j <= 64; ++j) worst = std::max(worst, distance_to(cf, cs.data(), S, quad_point(q[i], j / 64.0)));
  return worst;
}

/// The unit of a dataset (W11): the random cubics' box, the glyphs' em.
double w11_unit(const std::string& set) { return set == "glyphs" ? 2048.0 : 100.0; }

void w11_casteljau(benchmark::State& state, const std::string& set, double rel, const std::string& name) {
  const auto& cs = dataset(set);
  const double tol = rel * w11_unit(set);
  std::vector<Quad> out;
  std::vector<std::size_t> first;
  for (auto _ : state) {
    out.clear();
    first.clear();
    for (const Cubic& c : cs) {
      first.push_back(out.size());
      const casteljau::Bezier<double, 2> b({c[0], c[1], c[2], c[3]});
      const auto r = casteljau::to_quadratic(b, tol);
      for (const auto& q : r.segments) out.push_back(Quad{q.points()[0], q.points()[1], q.points()[2]});
    }
    first.push_back(out.size());
    benchmark::DoNotOptimize(out.data());
  }
  static std::map<std::string, Measured> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    Measured m;
    m.curves = cs.size();
    m.segments = out.size();
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const double d = quad_deviation(cs[i], out.data() + first[i], first[i + 1] - first[i]);
      m.max_deviation = std::max(m.max_deviation, d);
      m.over += !(d <= 1.0001 * tol);
    }
    it = cache.emplace(name, m).first;
  }
  state.counters["curves"] = static_cast<double>(it->second.curves);
  state.counters["segments"] = static_cast<double>(it->second.segments);
  state.counters["over_tolerance"] = static_cast<double>(it->second.over);
  state.counters["max_deviation"] = it->second.max_deviation;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

// ---- W11, offsets ---------------------------------------------------------------------
// W3's datasets offset by d = 1e-2 and 1e-1 of the unit (random: the box, 100; glyphs: the
// em, 2048), each curve on its own, at tolerance 1e-3 of the unit. Names
// W11/<casteljau|lib2geom>/offset/<dataset>/<d>, d written 1e-2 or 1e-1; counters segments
// (cubics), over_tolerance (curves whose measured deviation exceeds 1.0001 x tol),
// max_deviation: the two-sided distance between the output and the exact offset
// C(t) + d N(t) (N the left unit normal), measured after timing (offset_deviation).

/// The exact offset of a cubic: C(t) + d N(t), N = C' / |C'| turned left. Where C' vanishes
/// (an end with a zero-length handle: 2,771 of the glyphs' elevated quadratics, whose
/// control point is their start), N is its limit: C' taken 1e-9 inside the parameter range.
P2 exact_offset(const Cubic& c, double d, double t) {
  const auto velocity = [&c](double s, double* v) {
    const double u = 1 - s;
    for (int i = 0; i < 2; ++i) v[i] = 3 * (u * u * (c[1][i] - c[0][i]) + 2 * u * s * (c[2][i] - c[1][i]) + s * s * (c[3][i] - c[2][i]));
    return std::hypot(v[0], v[1]);
  };
  double v[2];
  double n = velocity(t, v);
  if (!(n > 0)) n = velocity(t < 0.5 ? t + 1e-9 : t - 1e-9, v);
  const P2 x = value(c, t);
  if (!(n > 0)) return x;  // a cubic that is one point
  return P2{x[0] - d * v[1] / n, x[1] + d * v[0] / n};
}

/// The two-sided distance between the exact offset of c and the cubics out[0..k): the exact
/// offset sampled at S = 64 + 16 k uniform parameters, then every interval whose chord is
/// longer than 1/256 of the sampled length split in two (to 2^-20 of the parameter), so
/// that the fast turns of the offset near high curvature are sampled as densely as the
/// rest; each cubic at 65 parameters. Offset samples to the cubics: distance_to (every local
/// minimum over the cubic's 65 samples refined by Newton). Cubic samples to the exact
/// offset: every local minimum over the offset's samples refined by golden section on the
/// squared distance within its neighbouring samples (40 steps: 1e-8 of the bracket), the
/// smallest kept (never below the true distance: each is the distance to a point of the
/// offset).
double offset_deviation(const Cubic& c, double d, const Cubic* out, std::size_t k) {
  if (k == 0) return INFINITY;
  const std::size_t S = 64 + 16 * k;
  std::vector<double> ts(S);
  std::vector<P2> os(S);
  for (std::size_t j = 0; j < S; ++j) {
    ts[j] = static_cast<double>(j) / static_cast<double>(S - 1);
    os[j] = exact_offset(c, d, ts[j]);
  }
  double length = 0;
  for (std::size_t j = 1; j < S; ++j) length += std::hypot(os[j][0] - os[j - 1][0], os[j][1] - os[j - 1][1]);
  const double step = length / 256;
  {
    std::vector<double> t2{ts[0]};
    std::vector<P2> o2{os[0]};
    std::vector<std::pair<double, P2>> stack;  // the right ends still to reach
    for (std::size_t j = 1; j < S; ++j) {
      stack.emplace_back(ts[j], os[j]);
      while (!stack.empty()) {
        const auto [tr, pr] = stack.back();
        const double tl = t2.back();
        const P2 pl = o2.back();
        if (std::hypot(pr[0] - pl[0], pr[1] - pl[1]) > step && tr - tl > 0x1p-20) {
          const double tm = 0.5 * (tl + tr);
          stack.emplace_back(tm, exact_offset(c, d, tm));
        } else {
          t2.push_back(tr);
          o2.push_back(pr);
          stack.pop_back();
        }
      }
    }
    ts = std::move(t2);
    os = std::move(o2);
  }
  const std::size_t n = ts.size();
  // The cubics' forms and samples.
  const auto cubic_f = [](const Cubic& a) {
    return [&a](double s) {
      const double u = 1 - s;
      P2 d1, d2;
      for (int i = 0; i < 2; ++i) {
        d1[i] = 3 * (u * u * (a[1][i] - a[0][i]) + 2 * u * s * (a[2][i] - a[1][i]) + s * s * (a[3][i] - a[2][i]));
        d2[i] = 6 * (u * (a[2][i] - 2 * a[1][i] + a[0][i]) + s * (a[3][i] - 2 * a[2][i] + a[1][i]));
      }
      return std::tuple{value(a, s), d1, d2};
    };
  };
  std::vector<std::array<P2, 65>> cs(k);
  for (std::size_t i = 0; i < k; ++i)
    for (int j = 0; j <= 64; ++j) cs[i][static_cast<std::size_t>(j)] = value(out[i], j / 64.0);
  double worst = 0;
  for (const P2& p : os) {
    double best = INFINITY;
    for (std::size_t i = 0; i < k; ++i) best = std::min(best, distance_to(cubic_f(out[i]), cs[i].data(), 65, p));
    worst = std::max(worst, best);
  }
  std::vector<double> dist(n);
  for (std::size_t i = 0; i < k; ++i) {
    for (const P2& p : cs[i]) {
      for (std::size_t j = 0; j < n; ++j) dist[j] = std::hypot(os[j][0] - p[0], os[j][1] - p[1]);
      double best = INFINITY;
      for (std::size_t j = 0; j < n; ++j) {
        if ((j > 0 && dist[j] > dist[j - 1]) || (j + 1 < n && dist[j] > dist[j + 1])) continue;
        best = std::min(best, dist[j]);
        constexpr double r = 0.6180339887498949;
        double a = ts[j > 0 ? j - 1 : 0], b = ts[std::min(j + 1, n - 1)];
        const auto f = [&](double t) {
          const P2 x = exact_offset(c, d, t);
          return std::hypot(x[0] - p[0], x[1] - p[1]);
        };
        double x1 = b - r * (b - a), x2 = a + r * (b - a), f1 = f(x1), f2 = f(x2);
        for (int it = 0; it < 40; ++it) {
          if (f1 <= f2) {
            b = x2, x2 = x1, f2 = f1, x1 = b - r * (b - a), f1 = f(x1);
          } else {
            a = x1, x1 = x2, f1 = f2, x2 = a + r * (b - a), f2 = f(x2);
          }
        }
        best = std::min({best, f1, f2});
      }
      worst = std::max(worst, best);
    }
  }
  return worst;
}

/// Runs one offsetter: offset_all(curve, d, tol, out) appends the curve's offset cubics.
void w11_offset(benchmark::State& state, const std::string& name, const std::string& set, double rel_d,
                const std::function<void(const Cubic&, double, double, std::vector<Cubic>&)>& offset_all) {
  const auto& cs = dataset(set);
  const double d = rel_d * w11_unit(set), tol = 1e-3 * w11_unit(set);
  std::vector<Cubic> out;
  std::vector<std::size_t> first;
  for (auto _ : state) {
    out.clear();
    first.clear();
    for (const Cubic& c : cs) {
      first.push_back(out.size());
      offset_all(c, d, tol, out);
    }
    first.push_back(out.size());
    benchmark::DoNotOptimize(out.data());
  }
  static std::map<std::string, Measured> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    Measured m;
    m.curves = cs.size();
    m.segments = out.size();
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const double e = offset_deviation(cs[i], d, out.data() + first[i], first[i + 1] - first[i]);
      m.max_deviation = std::max(m.max_deviation, e);
      m.over += !(e <= 1.0001 * tol);
    }
    it = cache.emplace(name, m).first;
  }
  state.counters["curves"] = static_cast<double>(it->second.curves);
  state.counters["segments"] = static_cast<double>(it->second.segments);
  state.counters["over_tolerance"] = static_cast<double>(it->second.over);
  state.counters["max_deviation"] = it->second.max_deviation;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

/// casteljau::offset of the cubic, untrimmed (trim = false: the raw offset, the same curve
/// as the exact offset the measure compares with, and as lib2geom's; the trim cuts loops
/// away, which a two-sided distance to the untrimmed offset would count as missing).
void casteljau_offset(const Cubic& c, double d, double tol, std::vector<Cubic>& out) {
  const casteljau::Bezier<double, 2> b({c[0], c[1], c[2], c[3]});
  casteljau::OffsetOptions<double> o;
  o.distance = d;
  o.tolerance = tol;
  o.trim = false;
  for (const auto& s : casteljau::offset(b, o).segments) {
    const auto& P = s.points();
    out.push_back(Cubic{P[0], P[1], P[2], P[3]});
  }
}

#if CASTELJAU_BENCH_HAVE_2GEOM
/// lib2geom 1.2.2's offset (the Debian package has no half_outline, which is Inkscape's
/// helper): the curve as an s-power basis piecewise, its unit tangent approximated by
/// unitVector (to tol / |d|, order 3, so that d N is within tol), turned left (rot90),
/// C + d N, back to cubics with path_from_piecewise (only cubic Béziers).
void lib2geom_offset(const Cubic& c, double d, double tol, std::vector<Cubic>& out) {
  Geom::Path path(Geom::Point(c[0][0], c[0][1]));
  path.appendNew<Geom::CubicBezier>(Geom::Point(c[1][0], c[1][1]), Geom::Point(c[2][0], c[2][1]), Geom::Point(c[3][0], c[3][1]));
  const Geom::Piecewise<Geom::D2<Geom::SBasis>> pw = path.toPwSb();
  Geom::PathVector pv;
  try {
    const Geom::Piecewise<Geom::D2<Geom::SBasis>> n = Geom::rot90(Geom::unitVector(Geom::derivative(pw), tol / std::abs(d), 3));
    pv = Geom::path_from_piecewise(pw + n * d, tol, true);
  } catch (const Geom::Exception&) {
    // A curve whose derivative vanishes at an end (a zero-length handle) gets a unit
    // tangent that is not finite, and path_from_piecewise refuses it: no output for the
    // curve, which the measure counts as over the tolerance.
    return;
  }
  for (const Geom::Path& p : pv) {
    for (std::size_t i = 0; i < p.size_open(); ++i) {
      const auto* b = dynamic_cast<const Geom::BezierCurve*>(&p[i]);
      if (!b) throw std::runtime_error("W11 lib2geom: path_from_piecewise made a curve that is not a Bézier");
      const std::vector<Geom::Point> P = b->controlPoints();
      Cubic q;
      if (P.size() == 4) {
        for (int j = 0; j < 4; ++j) q[static_cast<std::size_t>(j)] = P2{P[static_cast<std::size_t>(j)][0], P[static_cast<std::size_t>(j)][1]};
      } else if (P.size() == 2) {  // a line, as the cubic at its thirds
        for (int j = 0; j < 4; ++j) q[static_cast<std::size_t>(j)] = P2{P[0][0] + j / 3.0 * (P[1][0] - P[0][0]), P[0][1] + j / 3.0 * (P[1][1] - P[0][1])};
      } else {
        throw std::runtime_error("W11 lib2geom: a Bézier of order " + std::to_string(P.size() - 1));
      }
      out.push_back(q);
    }
  }
}
#endif

/// With CASTELJAU_W11_DUMP=DIR, each dataset is written to DIR/w11_<set>.f64 (raw
/// little-endian doubles, x0 y0 ... x3 y3 per cubic) for bench/w11_cu2qu.py.
void w11_dump(const std::string& set) {
  const char* dir = std::getenv("CASTELJAU_W11_DUMP");
  if (!dir) return;
  const auto& cs = dataset(set);
  const std::string path = std::string(dir) + "/w11_" + set + ".f64";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("W11: cannot write " + path);
  for (const Cubic& c : cs)
    for (const P2& p : c) std::fwrite(&p[0], sizeof(double), 2, f);
  std::fclose(f);
}

void reg(const std::string& library_method, const std::string& set, void (*flatten_all)(const std::vector<Cubic>&, Polylines&)) {
  const std::string name = "W3/" + library_method + "/" + set;
  benchmark::RegisterBenchmark(name.c_str(), [name, set, flatten_all](benchmark::State& st) { run(st, name, set, flatten_all); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> sets{"random"};
#if CASTELJAU_BENCH_HAVE_FREETYPE
  sets.push_back("glyphs");
#else
  std::fprintf(stderr, "W3: built without FreeType (libfreetype-dev): no glyphs dataset\n");
#endif
  for (const std::string& set : sets) {
    for (const auto& [rel, label] : {std::pair{1e-3, "1e-3"}, std::pair{1e-1, "1e-1"}}) {
      const std::string name = std::string("W11/casteljau/quadratic/") + set + "/" + label;
      benchmark::RegisterBenchmark(name.c_str(), [name, set, rel = rel](benchmark::State& st) { w11_casteljau(st, set, rel, name); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
    for (const auto& [rel, label] : {std::pair{1e-2, "1e-2"}, std::pair{1e-1, "1e-1"}}) {
      std::vector<std::pair<std::string, void (*)(const Cubic&, double, double, std::vector<Cubic>&)>> libs{{"casteljau", casteljau_offset}};
#if CASTELJAU_BENCH_HAVE_2GEOM
      libs.emplace_back("lib2geom", lib2geom_offset);
#endif
      for (const auto& [lib, fn] : libs) {
        const std::string name = "W11/" + lib + "/offset/" + set + "/" + label;
        benchmark::RegisterBenchmark(name.c_str(), [name, set, rel = rel, fn = fn](benchmark::State& st) { w11_offset(st, name, set, rel, fn); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
    }
    reg("near_optimal/greedy", set, near_optimal);
    reg("plain/wang_uniform", set, wang_uniform);
#if CASTELJAU_BENCH_HAVE_FLATTEN_METHODS
    reg("casteljau/uniform", set, casteljau_flatten<casteljau::FlattenMethod::uniform>);
    reg("casteljau/subdivision", set, casteljau_flatten<casteljau::FlattenMethod::subdivision>);
    reg("casteljau/optimal", set, casteljau_flatten<casteljau::FlattenMethod::optimal>);
#else
    reg("casteljau/subdivision", set, casteljau_subdivision);
#endif
#if CASTELJAU_BENCH_HAVE_CAIRO
    {
      const std::string name = "W3/cairo/copy_path_flat/" + set;
      benchmark::RegisterBenchmark(name.c_str(), [name, set](benchmark::State& st) { cairo_run(st, name, set); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
#endif
#if CASTELJAU_BENCH_HAVE_OCCT_ALGO
    reg("occt/TangentialDeflection_pi_2", set, occt_tangential<-1>);
    reg("occt/TangentialDeflection_0.1rad", set, occt_tangential<100>);
    reg("occt/QuasiUniformDeflection", set, occt_quasi_uniform);
#endif
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const std::string& set : sets) {
    dataset(set);  // inputs read before any timing
    w11_dump(set);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
