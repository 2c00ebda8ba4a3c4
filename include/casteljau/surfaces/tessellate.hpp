// Tessellation of a tensor-product surface (the run-time form of surfaces/surface_form.hpp)
// into triangles to a tolerance, both ways: every point of every triangle lies within the
// tolerance of the surface, and every point of the surface within the tolerance of the mesh.
//
// The mesh. The surface is cut into its exact Bézier patches (detail::patches). Each u
// interval between breaks (a strip of patches) gets one count n_u of equal steps, each v
// interval one count n_v, so the parameter lines form one tensor grid over the whole
// domain: an edge shared by two patches (a knot line) is split by the same parameters on
// both sides and its vertices are shared, so there are no cracks and no T-junctions.
// Each grid cell is cut into two triangles along its shorter diagonal in space; the
// triangles are counter-clockwise in (u, v), so counter-clockwise seen from the side S_u x
// S_v points to. The counts adapt to each strip's curvature: a flat strip gets one step,
// a curved one as many as its bound asks (the strip takes the largest need of its
// patches).
//
// The bound (why the tolerance holds). Take a cell of a patch, reparametrised to the unit
// square (s, t), and one of its triangles, with barycentric coordinates lambda_i of its
// parameter vertices x_i. For a polynomial map F with |F_ss| <= A, |F_st| <= B, |F_tt| <= C
// on the cell (from the cell's Bézier net: |F_ss| <= p (p - 1) max |second difference in
// s|, |F_st| <= p q max |mixed difference|, |F_tt| <= q (q - 1) max |second difference in
// t|), Taylor's theorem about x with the integral remainder gives
//   |F(x) - sum lambda_i F(x_i)| <= 1/2 sum lambda_i Q(x_i - x),
//   Q(d) = A d_s^2 + 2 B |d_s d_t| + C d_t^2 <= (A + B) d_s^2 + (C + B) d_t^2,
// and for the right triangles of a unit cell sum lambda_i |x_i - x|^2 in that diagonal
// metric is at most the squared circumradius (the hypotenuse's half), so the error is at
// most e(F) = ((A + B) + (C + B)) / 8. For a rational surface S = P / w (homogeneous
// patch (P, w), weights > 0), pick a centre c and r >= |S - c| on the cell (the radius of
// the cell's control points about c: the surface lies in their hull). The point
// T(x) = sum lambda_i P(x_i) / sum lambda_i w(x_i) is a point of the flat triangle (weights
// lambda_i w(x_i) / sum, >= 0), and x -> T(x) maps the parameter triangle onto the whole
// flat triangle; S(x) - T(x) = [(P - c w) - L(P - c w) - (S - c)(w - L w)] / L w, L the
// linear interpolant, L w >= min w >= the least control weight, so
//   |S(x) - T(x)| <= (e(P - c w) + r e(w)) / w_min.
// That one bound covers both directions (each surface point S(x) has T(x) on the mesh
// within it, each mesh point T(x) has S(x)); a polynomial patch is the case w = 1. The
// counts start from the patch's Cartesian net (for a polynomial patch a valid bound: a
// cell's differences are the patch's scaled by the step squared; it starts from 0.6 of
// those counts, which the cells raise where they need; should they not settle, the patch
// counts are used), and
// every cell's own net (Bézier subdivision of the patch) is checked against the bound
// above and the strip's count raised until all hold. A relative slack
// of 1e-13 of the surface's size covers the rounding of the evaluation.
//
// Degenerate edges. A patch edge whose control points coincide (a sphere's pole, the
// apex of a cone) is one point: its grid vertices are merged into one vertex, the cells
// along it lose the triangle that would have two corners there (no zero-area triangles),
// and the rest fan about the point. The normal there is the limit normal: with S_v = 0
// along u = u0, S_u x S_v ~ (u - u0) S_u x S_uv, so n = +-(S_u x S_uv) / |...| (the sign
// from the side the domain lies on); null when that vanishes too.
//
// Cost: the count is estimated from the patches' nets before any vertex is evaluated;
// beyond max_triangles the request is refused (InvalidArgument "tolerance").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "casteljau/core/error.hpp"
#include "casteljau/surfaces/surface_form.hpp"

namespace casteljau::detail {

/// A triangle mesh of a surface: `dim` coordinates per vertex, its (u, v), a unit normal
/// per vertex for 3-D surfaces (has_normal false where it is undefined), triangles as
/// vertex index triples, counter-clockwise about the normal.
template <class T>
struct SurfaceMesh {
  std::size_t dim = 0;
  std::vector<T> vertices;  ///< vertex k: vertices[k * dim + c]
  std::vector<T> uv;        ///< vertex k: uv[2 k], uv[2 k + 1]
  std::vector<T> normals;   ///< 3-D only: vertex k: normals[3 k + c]
  std::vector<unsigned char> has_normal;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// The parameter lines of the grid (diagnostics, tests).
  std::vector<T> us, vs;
  [[nodiscard]] std::size_t size() const { return dim == 0 ? 0 : vertices.size() / dim; }
};

/// The most triangles a tessellation may have (the contract's refusal threshold).
inline constexpr double max_triangles = 1e7;

namespace tess {

/// A Bézier grid in homogeneous form: (rows x cols) points of `d` values (the last the
/// weight when rational), row-major.
template <class T>
struct Net {
  std::size_t rows = 0, cols = 0, d = 0;
  std::vector<T> x;
  [[nodiscard]] const T* at(std::size_t i, std::size_t j) const { return x.data() + (i * cols + j) * d; }
  [[nodiscard]] T* at(std::size_t i, std::size_t j) { return x.data() + (i * cols + j) * d; }
};

/// The part of the Bézier net over [s0, s1] in u (the rows are the curve's points), by
/// two de Casteljau splits.
template <class T>
Net<T> sub_u(const Net<T>& n, T s0, T s1) {
  const std::size_t w = n.cols * n.d, m = n.rows;
  std::vector<T> a = n.x;
  // Left part at s1: after step k, row k holds the first point of level k.
  for (std::size_t k = 1; k < m; ++k)
    for (std::size_t i = m - 1; i >= k; --i) {
      T* r = a.data() + i * w;
      const T* q = a.data() + (i - 1) * w;
      for (std::size_t c = 0; c < w; ++c) r[c] = q[c] + s1 * (r[c] - q[c]);
    }
  // a now: row i = point i of the left part (on [0, s1]). Right part of it at s0 / s1.
  const T t = s1 > 0 ? s0 / s1 : T(0);
  for (std::size_t k = 1; k < m; ++k)
    for (std::size_t i = 0; i + k < m; ++i) {
      T* r = a.data() + i * w;
      const T* q = a.data() + (i + 1) * w;
      for (std::size_t c = 0; c < w; ++c) r[c] = r[c] + t * (q[c] - r[c]);
    }
  return Net<T>{n.rows, n.cols, n.d, std::move(a)};
}

template <class T>
Net<T> transpose(const Net<T>& n) {
  Net<T> t{n.cols, n.rows, n.d, std::vector<T>(n.x.size())};
  for (std::size_t i = 0; i < n.rows; ++i)
    for (std::size_t j = 0; j < n.cols; ++j) std::copy(n.at(i, j), n.at(i, j) + n.d, t.at(j, i));
  return t;
}

/// The bound of the header comment for one Bézier net on the unit square: {e_u, e_v},
/// the parts of the error bound from the u and v second differences (each with half the
/// mixed term), e = e_u + e_v. `rational`: the last value of each point is the weight.
template <class T>
std::array<T, 2> cell_bound(const Net<T>& n, bool rational) {
  const std::size_t cd = rational ? n.d - 1 : n.d, P = n.rows - 1, Q = n.cols - 1;
  T wmin = 1;
  std::vector<T> c(cd, T(0));
  T r = 0;
  if (rational) {
    // Centre: the middle of the Cartesian points' box.
    std::vector<T> lo(cd, T(INFINITY)), hi(cd, T(-INFINITY));
    wmin = T(INFINITY);
    for (std::size_t i = 0; i <= P; ++i)
      for (std::size_t j = 0; j <= Q; ++j) {
        const T* x = n.at(i, j);
        wmin = std::min(wmin, x[cd]);
        for (std::size_t k = 0; k < cd; ++k) {
          lo[k] = std::min(lo[k], x[k] / x[cd]);
          hi[k] = std::max(hi[k], x[k] / x[cd]);
        }
      }
    for (std::size_t k = 0; k < cd; ++k) c[k] = lo[k] / 2 + hi[k] / 2;
    for (std::size_t i = 0; i <= P; ++i)
      for (std::size_t j = 0; j <= Q; ++j) {
        const T* x = n.at(i, j);
        T s = 0;
        for (std::size_t k = 0; k < cd; ++k) {
          const T e = x[k] / x[cd] - c[k];
          s += e * e;
        }
        r = std::max(r, std::sqrt(s));
      }
  }
  // The value of F = P - c w (coordinates 0..cd-1) or w (coordinate cd) at point (i, j).
  const auto F = [&](std::size_t i, std::size_t j, std::size_t k) {
    const T* x = n.at(i, j);
    return k < cd ? (rational ? x[k] - c[k] * x[cd] : x[k]) : x[cd];
  };
  // Maxima of the norms of the second differences of F (Cartesian part) and of w.
  T duu[2] = {0, 0}, duv[2] = {0, 0}, dvv[2] = {0, 0};
  const std::size_t parts = rational ? 2 : 1;
  for (std::size_t part = 0; part < parts; ++part) {
    const std::size_t k0 = part == 0 ? 0 : cd, k1 = part == 0 ? cd : cd + 1;
    for (std::size_t i = 0; i <= P; ++i)
      for (std::size_t j = 0; j <= Q; ++j) {
        T a = 0, b = 0, e = 0;
        for (std::size_t k = k0; k < k1; ++k) {
          if (i + 2 <= P) {
            const T v = F(i + 2, j, k) - 2 * F(i + 1, j, k) + F(i, j, k);
            a += v * v;
          }
          if (i + 1 <= P && j + 1 <= Q) {
            const T v = F(i + 1, j + 1, k) - F(i + 1, j, k) - F(i, j + 1, k) + F(i, j, k);
            b += v * v;
          }
          if (j + 2 <= Q) {
            const T v = F(i, j + 2, k) - 2 * F(i, j + 1, k) + F(i, j, k);
            e += v * v;
          }
        }
        duu[part] = std::max(duu[part], std::sqrt(a));
        duv[part] = std::max(duv[part], std::sqrt(b));
        dvv[part] = std::max(dvv[part], std::sqrt(e));
      }
  }
  const T pp = T(P) * T(P > 0 ? P - 1 : 0), qq = T(Q) * T(Q > 0 ? Q - 1 : 0), pq = T(P) * T(Q);
  std::array<T, 2> out{};
  for (std::size_t part = 0; part < parts; ++part) {
    const T scale = part == 0 ? T(1) : r;
    out[0] += scale * (pp * duu[part] + pq * duv[part]) / 8;
    out[1] += scale * (qq * dvv[part] + pq * duv[part]) / 8;
  }
  out[0] /= wmin;
  out[1] /= wmin;
  return out;
}

/// A patch as a homogeneous Bézier net.
template <class T>
Net<T> net_of(const SurfaceForm<T>& patch) {
  const SurfaceForm<T> h = weighted(patch, true);
  return Net<T>{h.rows, h.cols, h.dim, h.P};
}

/// Union-find over grid nodes.
struct Merge {
  std::vector<std::uint32_t> up;
  std::uint32_t find(std::uint32_t a) {
    while (up[a] != a) a = up[a] = up[up[a]];
    return a;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) up[std::max(a, b)] = std::min(a, b);
  }
};

template <class T>
std::size_t steps_for(T part, T tol) {
  // part / n^2 <= tol / 2 (half the tolerance for each direction).
  const T n = std::ceil(std::sqrt(std::max(part, T(0)) / (tol / 2)));
  return n < 1 ? 1 : n > T(1e9) ? std::size_t(1000000000) : static_cast<std::size_t>(n);
}

}  // namespace tess

/// The tessellation of f (checked) within tol > 0 (InvalidArgument "tolerance" when not a
/// finite positive number, or when the answer would exceed max_triangles: estimated
/// before any vertex is evaluated). Throws InvalidArgument("surface", ...) for a surface
/// that is not continuous across a knot line (an interior knot of full multiplicity whose
/// two sides differ): its mesh would need two edges there.
template <class T>
SurfaceMesh<T> tessellate(const SurfaceForm<T>& f, T tol) {
  using tess::Net;
  if (!(tol > 0) || !std::isfinite(tol)) throw InvalidArgument("tolerance", "must be a finite number > 0, got " + format_number(tol));
  const SurfacePatches<T> sp = patches(f);
  const std::size_t A = sp.patches.size(), B = sp.patches.front().size(), cd = f.cartesian();
  // The size of the surface (the box of its control points), for the rounding slack and
  // the coincidence tests.
  T size = 0;
  {
    for (std::size_t k = 0; k < cd; ++k) {
      T lo = T(INFINITY), hi = T(-INFINITY);
      for (std::size_t i = 0; i < f.P.size(); i += f.dim) {
        lo = std::min(lo, f.P[i + k]);
        hi = std::max(hi, f.P[i + k]);
      }
      size = std::max({size, hi - lo, std::abs(lo), std::abs(hi)});
    }
  }
  const T slack = T(1e-13) * size;
  if (!(tol > 4 * slack)) {
    throw InvalidArgument("tolerance", "must be more than 4e-13 x the surface's size (" + format_number(size) +
                                           ") to be met in double precision, got " + format_number(tol));
  }
  const T budget = tol - slack;
  std::vector<Net<T>> nets;
  nets.reserve(A * B);
  for (const auto& row : sp.patches)
    for (const auto& patch : row) nets.push_back(tess::net_of(patch));
  // Start: the Cartesian net of each patch (valid for polynomial patches).
  std::vector<std::size_t> nu(A, 1), nv(B, 1);
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      Net<T> c = nets[a * B + b];
      if (f.rational) {
        Net<T> cart{c.rows, c.cols, cd, std::vector<T>(c.rows * c.cols * cd)};
        for (std::size_t i = 0; i < c.rows; ++i)
          for (std::size_t j = 0; j < c.cols; ++j)
            for (std::size_t k = 0; k < cd; ++k) cart.at(i, j)[k] = c.at(i, j)[k] / c.at(i, j)[cd];
        c = std::move(cart);
      }
      const auto e = tess::cell_bound(c, false);
      nu[a] = std::max(nu[a], tess::steps_for(e[0], budget));
      nv[b] = std::max(nv[b], tess::steps_for(e[1], budget));
    }
  const auto count = [&] {
    const T su = std::accumulate(nu.begin(), nu.end(), T(0)), sv = std::accumulate(nv.begin(), nv.end(), T(0));
    return 2 * su * sv;
  };
  const auto refuse_if_too_many = [&] {
    const T n = count();
    if (n > max_triangles) {
      char about[32];
      std::snprintf(about, sizeof about, "%.2g", static_cast<double>(n));
      throw InvalidArgument("tolerance", "the tessellation would have about " + std::string(about) +
                                             " triangles, more than 10^7: ask for a larger tolerance (got " + format_number(tol) + ")");
    }
  };
  refuse_if_too_many();
  std::vector<std::size_t> patch_nu, patch_nv;
  bool verified = false;
  if (!f.rational) {
    // The patch bound holds at these counts; a cell's own net is usually well below it
    // (the strip takes its most curved patch, the patch its most curved corner): start
    // from 0.6 of the counts and let the cells raise them back where they need to.
    patch_nu = nu;
    patch_nv = nv;
    for (auto& n : nu) n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(0.6 * static_cast<double>(n))));
    for (auto& n : nv) n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(0.6 * static_cast<double>(n))));
  }
  {
    // Every cell's own net against the bound; raise the strip counts until all hold.
    for (int round = 0; round < 64; ++round) {
      std::vector<std::size_t> want_u = nu, want_v = nv;
      bool ok = true;
      for (std::size_t a = 0; a < A; ++a) {
        for (std::size_t b = 0; b < B; ++b) {
          const Net<T>& n = nets[a * B + b];
          for (std::size_t i = 0; i < nu[a]; ++i) {
            const Net<T> strip = tess::transpose(tess::sub_u(n, T(i) / T(nu[a]), T(i + 1) / T(nu[a])));
            for (std::size_t j = 0; j < nv[b]; ++j) {
              const Net<T> cell = tess::transpose(tess::sub_u(strip, T(j) / T(nv[b]), T(j + 1) / T(nv[b])));
              const auto e = tess::cell_bound(cell, f.rational);
              if (e[0] + e[1] <= budget) continue;
              ok = false;
              // Each part's share is half the budget; raise the parts over it (as the
              // bound scales with the step squared), at least by one step.
              const bool raise_u = e[0] > budget / 2 || e[0] >= e[1], raise_v = e[1] > budget / 2 || e[1] >= e[0];
              if (raise_u) {
                const T k = std::sqrt(std::max(e[0], budget / 4) / (budget / 2)) * T(1.05);
                want_u[a] = std::max(want_u[a], std::max(nu[a] + 1, static_cast<std::size_t>(std::ceil(T(nu[a]) * k))));
              }
              if (raise_v) {
                const T k = std::sqrt(std::max(e[1], budget / 4) / (budget / 2)) * T(1.05);
                want_v[b] = std::max(want_v[b], std::max(nv[b] + 1, static_cast<std::size_t>(std::ceil(T(nv[b]) * k))));
              }
            }
          }
        }
      }
      if (ok) {
        verified = true;
        break;
      }
      nu = want_u;
      nv = want_v;
      refuse_if_too_many();
    }
  }
  if (!verified) {
    // Not settled in 64 rounds (not met in practice): a polynomial surface falls back on
    // the patch bound's counts, which hold; a rational one is refused rather than risked.
    if (f.rational) throw NumericalError("the tessellation's step counts did not settle (tolerance " + format_number(tol) + ")");
    nu = patch_nu;
    nv = patch_nv;
  }
  // Continuity across each interior break (the shared edge nets agree).
  const auto close = [&](const T* x, const T* y, std::size_t d, bool rational) {
    T s = 0;
    for (std::size_t k = 0; k + (rational ? 1 : 0) < d; ++k) {
      const T e = rational ? x[k] / x[d - 1] - y[k] / y[d - 1] : x[k] - y[k];
      s += e * e;
    }
    return std::sqrt(s) <= T(1e-9) * size;
  };
  for (std::size_t a = 0; a + 1 < A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      const Net<T>&lo = nets[a * B + b], &hi = nets[(a + 1) * B + b];
      for (std::size_t j = 0; j < lo.cols; ++j)
        if (!close(lo.at(lo.rows - 1, j), hi.at(0, j), lo.d, f.rational)) {
          throw InvalidArgument("surface", "is not continuous across u = " + format_number(sp.ubreaks[a + 1]) +
                                               " (a knot of full multiplicity): a mesh without cracks cannot follow it");
        }
    }
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b + 1 < B; ++b) {
      const Net<T>&lo = nets[a * B + b], &hi = nets[a * B + b + 1];
      for (std::size_t i = 0; i < lo.rows; ++i)
        if (!close(lo.at(i, lo.cols - 1), hi.at(i, 0), lo.d, f.rational)) {
          throw InvalidArgument("surface", "is not continuous across v = " + format_number(sp.vbreaks[b + 1]) +
                                               " (a knot of full multiplicity): a mesh without cracks cannot follow it");
        }
    }

  SurfaceMesh<T> m;
  m.dim = cd;
  // The grid lines, with index ranges per strip.
  std::vector<std::size_t> I0(A + 1, 0), J0(B + 1, 0);
  for (std::size_t a = 0; a < A; ++a) {
    const T u0 = sp.ubreaks[a], u1 = sp.ubreaks[a + 1];
    for (std::size_t k = 0; k < nu[a]; ++k) m.us.push_back(u0 + (u1 - u0) * T(k) / T(nu[a]));
    I0[a + 1] = I0[a] + nu[a];
  }
  m.us.push_back(sp.ubreaks.back());
  for (std::size_t b = 0; b < B; ++b) {
    const T v0 = sp.vbreaks[b], v1 = sp.vbreaks[b + 1];
    for (std::size_t k = 0; k < nv[b]; ++k) m.vs.push_back(v0 + (v1 - v0) * T(k) / T(nv[b]));
    J0[b + 1] = J0[b] + nv[b];
  }
  m.vs.push_back(sp.vbreaks.back());
  const std::size_t NU = m.us.size(), NV = m.vs.size();
  const auto node = [&](std::size_t I, std::size_t J) { return static_cast<std::uint32_t>(I * NV + J); };
  tess::Merge merge{std::vector<std::uint32_t>(NU * NV)};
  std::iota(merge.up.begin(), merge.up.end(), 0u);
  // Degenerate patch edges: all control points of the edge within 1e-12 of the size.
  const auto point_edge = [&](const Net<T>& n, bool along_v, std::size_t fixed) {
    const std::size_t count_pts = along_v ? n.cols : n.rows;
    const T* x0 = along_v ? n.at(fixed, 0) : n.at(0, fixed);
    for (std::size_t k = 1; k < count_pts; ++k) {
      const T* x = along_v ? n.at(fixed, k) : n.at(k, fixed);
      T s = 0;
      for (std::size_t c = 0; c < cd; ++c) {
        const T e = f.rational ? x[c] / x[cd] - x0[c] / x0[cd] : x[c] - x0[c];
        s += e * e;
      }
      if (!(std::sqrt(s) <= T(1e-12) * size)) return false;
    }
    return true;
  };
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      const Net<T>& n = nets[a * B + b];
      for (const std::size_t side : {std::size_t(0), std::size_t(1)}) {
        if (point_edge(n, true, side ? n.rows - 1 : 0)) {  // u fixed, along v
          const std::size_t I = side ? I0[a + 1] : I0[a];
          for (std::size_t J = J0[b]; J < J0[b + 1]; ++J) merge.join(node(I, J), node(I, J + 1));
        }
        if (point_edge(n, false, side ? n.cols - 1 : 0)) {  // v fixed, along u
          const std::size_t J = side ? J0[b + 1] : J0[b];
          for (std::size_t I = I0[a]; I < I0[a + 1]; ++I) merge.join(node(I, J), node(I + 1, J));
        }
      }
    }
  // Vertices: one per merged node, evaluated at its representative (the first node).
  std::vector<std::uint32_t> vid(NU * NV, UINT32_MAX);
  const bool normals = cd == 3;
  const T umin = sp.ubreaks.front(), umax = sp.ubreaks.back(), vmin = sp.vbreaks.front(), vmax = sp.vbreaks.back();
  const auto add_vertex = [&](std::size_t I, std::size_t J) {
    const T u = m.us[I], v = m.vs[J];
    const std::vector<T> d = partials(f, u, v, normals ? 2 : 0);
    m.vertices.insert(m.vertices.end(), d.begin(), d.begin() + static_cast<std::ptrdiff_t>(cd));
    m.uv.push_back(u);
    m.uv.push_back(v);
    if (!normals) return;
    const auto at = [&](std::size_t a, std::size_t b) { return d.data() + (a * 3 + b) * 3; };
    const SurfaceGeometry<T> g = geometry<T>(at(1, 0), at(0, 1), at(2, 0), at(1, 1), at(0, 2));
    T n[3] = {g.normal[0], g.normal[1], g.normal[2]};
    bool ok = g.defined;
    if (!ok) {
      // The limit normal at a degenerate edge: S_v = 0 along u = u0 gives S_u x S_v ~
      // (u - u0) S_u x S_uv; S_u = 0 along v = v0 gives (v - v0) S_uv x S_v.
      const T *Su = at(1, 0), *Sv = at(0, 1), *Suv = at(1, 1);
      const auto norm2 = [](const T* x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2]; };
      const bool v_vanishes = norm2(Sv) < norm2(Su);
      const T *a = v_vanishes ? Su : Suv, *b = v_vanishes ? Suv : Sv;
      T c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      // The side of the domain: at the end of u (or v) the factor u - u0 is negative.
      const T sign = v_vanishes ? (u == umax && u != umin ? T(-1) : T(1)) : (v == vmax && v != vmin ? T(-1) : T(1));
      const T len = std::sqrt(norm2(c));
      if (len > T(1e-12) * std::sqrt(norm2(a)) * std::sqrt(norm2(b)) && len > 0) {
        for (int k = 0; k < 3; ++k) n[k] = sign * c[k] / len;
        ok = true;
      }
    }
    m.normals.insert(m.normals.end(), n, n + 3);
    m.has_normal.push_back(ok ? 1 : 0);
  };
  const auto vertex = [&](std::size_t I, std::size_t J) {
    const std::uint32_t r = merge.find(node(I, J));
    if (vid[r] == UINT32_MAX) {
      vid[r] = static_cast<std::uint32_t>(m.uv.size() / 2);
      add_vertex(r / NV, r % NV);
    }
    return vid[r];
  };
  m.triangles.reserve(2 * (NU - 1) * (NV - 1));
  const auto dist2 = [&](std::uint32_t a, std::uint32_t b) {
    T s = 0;
    for (std::size_t c = 0; c < cd; ++c) {
      const T e = m.vertices[a * cd + c] - m.vertices[b * cd + c];
      s += e * e;
    }
    return s;
  };
  const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c) return;  // two corners on a degenerate edge
    m.triangles.push_back({a, b, c});
  };
  for (std::size_t I = 0; I + 1 < NU; ++I)
    for (std::size_t J = 0; J + 1 < NV; ++J) {
      const std::uint32_t p00 = vertex(I, J), p10 = vertex(I + 1, J), p11 = vertex(I + 1, J + 1), p01 = vertex(I, J + 1);
      if (dist2(p00, p11) <= dist2(p10, p01)) {
        emit(p00, p10, p11);
        emit(p00, p11, p01);
      } else {
        emit(p00, p10, p01);
        emit(p10, p11, p01);
      }
    }
  return m;
}

}  // namespace casteljau::detail
