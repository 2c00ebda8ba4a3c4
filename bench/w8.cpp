// W8 of docs/performance.md: tessellation to a tolerance, casteljau's tessellate against
// OCCT's BRepMesh_IncrementalMesh (linear deflection = tolerance, angular deflection 0.5,
// relative mode off) on the face of the same Geom_BSplineSurface. Surfaces: W7's bicubic
// B-spline with heights x 0.1, a NURBS torus (circle of radius 0.3 at distance 1 about z),
// a NURBS sphere of radius 1. Names W8/<library>/<method>/<surface>/<tolerance>; one
// iteration tessellates once. Counters (measured once, outside the timing, the same way
// for both): triangles; max_deviation, the larger of (a) each triangle at 15 barycentric
// points, the distance to the surface by Gauss-Newton from the interpolated (u, v), and
// (b) the surface on a 200 x 200 (u, v) grid against the triangles whose (u, v) boxes
// hold the point; over_tolerance (1 when max_deviation > 1.0001 x tolerance); cracks
// (edges used by one triangle whose ends are not both on the domain's boundary);
// min_angle_deg (the smallest angle of any triangle, in space).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/surfaces/tessellate.hpp"
#include "common.hpp"

#if CASTELJAU_BENCH_HAVE_OCCT_MESH
// Debian's OCCT 7.6 headers lack NCollection_AliasedArray.hxx, which Poly_Triangulation.hxx
// (and BRep_Tool.hxx) include: the triangulation is read back from BRepTools::Write's text
// (its "Triangulations" section) instead, outside the timing.
#include <sstream>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>
#endif

namespace {

using Form = casteljau::detail::SurfaceForm<double>;

/// A mesh as both libraries give it: 3-D vertices, their (u, v), triangles.
struct Mesh {
  std::vector<std::array<double, 3>> x;
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<int, 3>> t;
};

// ---- the surfaces ---------------------------------------------------------------------

Form bicubic() {
  // W7: seed 7, P_ij = (i / 49, j / 49, uniform()), heights x 0.1 here.
  bench::SplitMix64 rng(7);
  Form f{3, 3, {}, {}, 50, 50, 3, false, std::vector<double>(50 * 50 * 3)};
  for (std::size_t i = 0; i < 50; ++i)
    for (std::size_t j = 0; j < 50; ++j) {
      double* p = f.at(i, j);
      p[0] = static_cast<double>(i) / 49;
      p[1] = static_cast<double>(j) / 49;
      p[2] = 0.1 * rng.uniform();
    }
  std::vector<double> K(4, 0.0);
  for (int k = 1; k <= 46; ++k) K.push_back(k / 47.0);
  K.insert(K.end(), 4, 1.0);
  f.U = f.V = K;
  return f;
}

/// The surface of revolution about z of a profile in the xz plane (degree 2 rational, its
/// points (x, z) and weights): the profile times the 9-point NURBS circle ([PT97] A8.1).
Form revolve(const std::vector<std::array<double, 2>>& profile, const std::vector<double>& pw, const std::vector<double>& U) {
  const double h = std::sqrt(0.5);
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  const double cw[9] = {1, h, 1, h, 1, h, 1, h, 1};
  Form f{2, 2, U, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, profile.size(), 9, 4, true, {}};
  f.P.resize(f.rows * f.cols * 4);
  for (std::size_t i = 0; i < f.rows; ++i)
    for (std::size_t j = 0; j < 9; ++j) {
      double* p = f.at(i, j);
      p[0] = profile[i][0] * cx[j];
      p[1] = profile[i][0] * cy[j];
      p[2] = profile[i][1];
      p[3] = pw[i] * cw[j];
    }
  return f;
}

Form torus() {
  const double h = std::sqrt(0.5), R = 1, a = 0.3;
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  std::vector<std::array<double, 2>> prof;
  for (int k = 0; k < 9; ++k) prof.push_back({R + a * cx[k], a * cy[k]});
  return revolve(prof, {1, h, 1, h, 1, h, 1, h, 1}, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1});
}

Form sphere() {
  const double h = std::sqrt(0.5);
  return revolve({{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}}, {1, h, 1, h, 1}, {0, 0, 0, 0.5, 0.5, 1, 1, 1});
}

// ---- measurement ----------------------------------------------------------------------

std::array<double, 3> eval(const Form& f, double u, double v, std::array<double, 3>* du = nullptr, std::array<double, 3>* dv = nullptr) {
  const std::vector<double> d = casteljau::detail::partials(f, u, v, du ? 1 : 0);
  if (du) {
    *du = {d[6], d[7], d[8]};  // (1, 0): index (1 * 2 + 0) * 3
    *dv = {d[3], d[4], d[5]};  // (0, 1)
  }
  return {d[0], d[1], d[2]};
}

double dist(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// Distance from p to the triangle abc (Ericson 5.1.5).
double point_triangle(const std::array<double, 3>& p, const std::array<double, 3>& a, const std::array<double, 3>& b,
                      const std::array<double, 3>& c) {
  const auto sub = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
    return std::array<double, 3>{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
  };
  const auto dot = [](const std::array<double, 3>& x, const std::array<double, 3>& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const auto at = [&](const std::array<double, 3>& o, const std::array<double, 3>& e, double s) {
    return std::array<double, 3>{o[0] + s * e[0], o[1] + s * e[1], o[2] + s * e[2]};
  };
  const auto ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return dist(p, a);
  const auto bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dist(p, b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return dist(p, at(a, ab, d1 / (d1 - d3)));
  const auto cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dist(p, c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return dist(p, at(a, ac, d2 / (d2 - d6)));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return dist(p, at(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
  const double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
  return dist(p, {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w});
}

struct Measured {
  double max_deviation = 0;
  int cracks = 0;
};

/// The distance from p to S near (u, v): Gauss-Newton steps on |S - p|^2, clamped to the
/// domain; the least distance met (each one that of a surface point: an upper bound).
double newton(const Form& f, const std::array<double, 3>& p, double u, double v, double u0, double u1, double v0, double v1,
              int steps = 8) {
  double best = 1e300;
  for (int it = 0; it < steps; ++it) {
    std::array<double, 3> su, sv;
    const auto s = eval(f, u, v, &su, &sv);
    const std::array<double, 3> e{p[0] - s[0], p[1] - s[1], p[2] - s[2]};
    best = std::min(best, dist(p, s));
    const double a11 = su[0] * su[0] + su[1] * su[1] + su[2] * su[2], a12 = su[0] * sv[0] + su[1] * sv[1] + su[2] * sv[2],
                 a22 = sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2];
    const double b1 = su[0] * e[0] + su[1] * e[1] + su[2] * e[2], b2 = sv[0] * e[0] + sv[1] * e[1] + sv[2] * e[2];
    const double det = a11 * a22 - a12 * a12;
    if (!(std::abs(det) > 1e-300)) break;
    u = std::clamp(u + (a22 * b1 - a12 * b2) / det, u0, u1);
    v = std::clamp(v + (a11 * b2 - a12 * b1) / det, v0, v1);
  }
  return std::min(best, dist(p, eval(f, u, v)));
}

Measured measure(const Form& f, const Mesh& m, double tol_hint) {
  const double u0 = f.U[static_cast<std::size_t>(f.p)], u1 = f.U[f.rows], v0 = f.V[static_cast<std::size_t>(f.q)], v1 = f.V[f.cols];
  Measured r;
  // (a) mesh -> surface.
  for (const auto& t : m.t) {
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; i + j <= 4; ++j) {
        const double a = i / 4.0, b = j / 4.0, c = 1 - a - b;
        std::array<double, 3> p{};
        for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(k)] = a * m.x[t[0]][k] + b * m.x[t[1]][k] + c * m.x[t[2]][k];
        const double u = a * m.uv[t[0]][0] + b * m.uv[t[1]][0] + c * m.uv[t[2]][0];
        const double v = a * m.uv[t[0]][1] + b * m.uv[t[1]][1] + c * m.uv[t[2]][1];
        double best = newton(f, p, u, v, u0, u1, v0, v1, 4);
        // Global fallback: a start at the interpolated (u, v) can be far from the foot
        // point (a pole vertex carries one (u, v) of the whole degenerate edge): again
        // from each vertex's u or v combined with the interpolated other one.
        if (best > 0.5 * tol_hint) {
          for (int s = 0; s < 6; ++s) {
            const auto& q = m.uv[t[s % 3]];
            best = std::min(best, newton(f, p, s < 3 ? q[0] : u, s < 3 ? v : q[1], u0, u1, v0, v1));
          }
        }
        r.max_deviation = std::max(r.max_deviation, best);
      }
  }
  // (b) surface -> mesh: triangles bucketed by their (u, v) boxes.
  const int B = 64;
  std::vector<std::vector<int>> bucket(B * B);
  const auto cell = [&](double x, double lo, double hi) { return std::clamp(static_cast<int>((x - lo) / (hi - lo) * B), 0, B - 1); };
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    double ul = 1e300, uh = -1e300, vl = 1e300, vh = -1e300;
    for (const int i : m.t[k]) {
      ul = std::min(ul, m.uv[static_cast<std::size_t>(i)][0]);
      uh = std::max(uh, m.uv[static_cast<std::size_t>(i)][0]);
      vl = std::min(vl, m.uv[static_cast<std::size_t>(i)][1]);
      vh = std::max(vh, m.uv[static_cast<std::size_t>(i)][1]);
    }
    for (int a = cell(ul, u0, u1); a <= cell(uh, u0, u1); ++a)
      for (int b = cell(vl, v0, v1); b <= cell(vh, v0, v1); ++b) bucket[static_cast<std::size_t>(a * B + b)].push_back(static_cast<int>(k));
  }
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) {
      const double u = u0 + (u1 - u0) * i / 199, v = v0 + (v1 - v0) * j / 199;
      const auto p = eval(f, u, v);
      double best = 1e300;
      for (const int k : bucket[static_cast<std::size_t>(cell(u, u0, u1) * B + cell(v, v0, v1))]) {
        const auto& t = m.t[static_cast<std::size_t>(k)];
        best = std::min(best, point_triangle(p, m.x[t[0]], m.x[t[1]], m.x[t[2]]));
      }
      r.max_deviation = std::max(r.max_deviation, best);
    }
  // Cracks.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : m.t)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  const double eu = 1e-9 * (u1 - u0), ev = 1e-9 * (v1 - v0);
  const auto boundary = [&](int k) {
    const auto& q = m.uv[static_cast<std::size_t>(k)];
    return std::abs(q[0] - u0) <= eu || std::abs(q[0] - u1) <= eu || std::abs(q[1] - v0) <= ev || std::abs(q[1] - v1) <= ev;
  };
  for (const auto& [e, n] : edges)
    if (n == 1 && !(boundary(e.first) && boundary(e.second))) ++r.cracks;
  return r;
}

Mesh ours(const Form& f, double tol) {
  const auto m = casteljau::detail::tessellate(f, tol);
  Mesh r;
  for (std::size_t k = 0; k < m.size(); ++k) {
    r.x.push_back({m.vertices[3 * k], m.vertices[3 * k + 1], m.vertices[3 * k + 2]});
    r.uv.push_back({m.uv[2 * k], m.uv[2 * k + 1]});
  }
  for (const auto& t : m.triangles) r.t.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  return r;
}

#if CASTELJAU_BENCH_HAVE_OCCT_MESH
Handle(Geom_BSplineSurface) occt_surface(const Form& f) {
  TColgp_Array2OfPnt poles(1, static_cast<int>(f.rows), 1, static_cast<int>(f.cols));
  TColStd_Array2OfReal weights(1, static_cast<int>(f.rows), 1, static_cast<int>(f.cols));
  for (std::size_t i = 0; i < f.rows; ++i)
    for (std::size_t j = 0; j < f.cols; ++j) {
      const double* p = f.at(i, j);
      poles.SetValue(static_cast<int>(i) + 1, static_cast<int>(j) + 1, gp_Pnt(p[0], p[1], p[2]));
      weights.SetValue(static_cast<int>(i) + 1, static_cast<int>(j) + 1, f.rational ? p[3] : 1.0);
    }
  const auto knots = [](const std::vector<double>& K, TColStd_Array1OfReal*& k, TColStd_Array1OfInteger*& m) {
    std::vector<std::pair<double, int>> d;
    for (const double x : K) {
      if (!d.empty() && d.back().first == x) ++d.back().second;
      else d.push_back({x, 1});
    }
    k = new TColStd_Array1OfReal(1, static_cast<int>(d.size()));
    m = new TColStd_Array1OfInteger(1, static_cast<int>(d.size()));
    for (std::size_t i = 0; i < d.size(); ++i) {
      k->SetValue(static_cast<int>(i) + 1, d[i].first);
      m->SetValue(static_cast<int>(i) + 1, d[i].second);
    }
  };
  TColStd_Array1OfReal *uk, *vk;
  TColStd_Array1OfInteger *um, *vm;
  knots(f.U, uk, um);
  knots(f.V, vk, vm);
  Handle(Geom_BSplineSurface) s = f.rational ? new Geom_BSplineSurface(poles, weights, *uk, *vk, *um, *vm, f.p, f.q)
                                             : new Geom_BSplineSurface(poles, *uk, *vk, *um, *vm, f.p, f.q);
  delete uk;
  delete vk;
  delete um;
  delete vm;
  return s;
}

/// Meshes a new face of s (timed part); with `out`, reads the triangulation back.
void occt(const Handle(Geom_BSplineSurface) & s, double tol, Mesh* out) {
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(s, 1e-9);
  BRepMesh_IncrementalMesh mesher(face, tol, false, 0.5);
  if (out == nullptr) return;
  std::ostringstream text;
  BRepTools::Write(face, text);
  std::istringstream in(text.str());
  std::string line;
  while (std::getline(in, line) && line.rfind("Triangulations", 0) != 0) {
  }
  int count = 0;
  std::istringstream(line.substr(14)) >> count;
  if (count < 1) return;
  std::getline(in, line);  // nodes, triangles, has (u, v)[, has normals], deflection
  std::istringstream head(line);
  int nodes = 0, triangles = 0, has_uv = 0;
  head >> nodes >> triangles >> has_uv;
  out->x.resize(static_cast<std::size_t>(nodes));
  out->uv.resize(static_cast<std::size_t>(nodes));
  for (auto& p : out->x) in >> p[0] >> p[1] >> p[2];
  if (has_uv)
    for (auto& q : out->uv) in >> q[0] >> q[1];
  out->t.resize(static_cast<std::size_t>(triangles));
  for (auto& t : out->t) {
    in >> t[0] >> t[1] >> t[2];
    for (auto& k : t) --k;
  }
}
#endif

void set_counters(benchmark::State& state, const std::string& key, const Form& f, const Mesh& m, double tol) {
  // Measured once per benchmark (repetitions reuse it: the meshes do not change).
  static std::map<std::string, Measured> done;
  auto it = done.find(key);
  if (it == done.end()) it = done.emplace(key, measure(f, m, tol)).first;
  const Measured q = it->second;
  state.counters["triangles"] = static_cast<double>(m.t.size());
  state.counters["max_deviation"] = q.max_deviation;
  state.counters["over_tolerance"] = q.max_deviation > 1.0001 * tol ? 1 : 0;
  state.counters["cracks"] = q.cracks;
  // The smallest angle of a triangle (degrees): slivers (issue 19: none at a sphere's poles).
  double smallest = 180;
  for (const auto& t : m.t)
    for (int k = 0; k < 3; ++k) {
      const auto &a = m.x[static_cast<std::size_t>(t[k])], &b = m.x[static_cast<std::size_t>(t[(k + 1) % 3])],
                 &c = m.x[static_cast<std::size_t>(t[(k + 2) % 3])];
      const double ab = dist(a, b), ac = dist(a, c);
      const double cosine = ((b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]) + (b[2] - a[2]) * (c[2] - a[2])) / (ab * ac);
      smallest = std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / 3.141592653589793);
    }
  state.counters["min_angle_deg"] = smallest;
}

struct Case {
  const char* name;
  Form (*make)();
  std::vector<std::pair<double, const char*>> tolerances;
};

const Case cases[] = {
    {"bicubic", bicubic, {{1e-2, "1e-2"}, {3e-3, "3e-3"}, {1e-3, "1e-3"}}},
    {"torus", torus, {{1e-2, "1e-2"}, {1e-3, "1e-3"}, {1e-4, "1e-4"}}},
    {"sphere", sphere, {{1e-2, "1e-2"}, {1e-3, "1e-3"}, {1e-4, "1e-4"}}},
};

}  // namespace

int main(int argc, char** argv) {
  for (const auto& c : cases) {
    for (const auto& [tol, label] : c.tolerances) {
      const std::string suffix = std::string(c.name) + "/" + label;
      const Form f = c.make();
      benchmark::RegisterBenchmark(("W8/casteljau/tessellate/" + suffix).c_str(), [f, suffix, tol = tol](benchmark::State& state) {
        for (auto _ : state) {
          auto mesh = casteljau::detail::tessellate(f, tol);
          benchmark::DoNotOptimize(mesh.triangles.data());
        }
        set_counters(state, "casteljau/" + suffix, f, ours(f, tol), tol);
      })->Unit(benchmark::kMillisecond);
#if CASTELJAU_BENCH_HAVE_OCCT_MESH
      benchmark::RegisterBenchmark(("W8/occt/BRepMesh_IncrementalMesh/" + suffix).c_str(), [f, suffix, tol = tol](benchmark::State& state) {
        const Handle(Geom_BSplineSurface) s = occt_surface(f);
        for (auto _ : state) occt(s, tol, nullptr);
        Mesh m;
        occt(s, tol, &m);
        set_counters(state, "occt/" + suffix, f, m, tol);
      })->Unit(benchmark::kMillisecond);
#endif
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
