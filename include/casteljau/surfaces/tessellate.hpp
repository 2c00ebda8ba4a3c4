// Tessellation of a tensor-product surface (the run-time form of surfaces/surface_form.hpp)
// into triangles to a tolerance, both ways: every point of every triangle lies within the
// tolerance of the surface, and every point of the surface within the tolerance of the mesh.
//
// The mesh. The surface is cut into its exact Bézier patches (detail::patches). Each patch
// gets its own counts n_u x n_v of equal parameter steps (a grid of cells). A patch side
// shared by two patches is split at the union of both patches' steps along it (computed
// once for both, as reduced fractions, so that both see the same nodes): the mesh has no
// cracks and no T-junctions; the counts of neighbouring patches along a shared side are
// made compatible (min / gcd <= 3, "Compatible counts" below) so that no two of its nodes
// are needlessly close (needles). A cell is cut along the diagonal its bound asks for (below:
// the sign of the mixed term), else along its shorter diagonal in space; a cell on a patch
// side that carries extra nodes of the neighbour is a convex polygon, each half of it cut
// into fans over those nodes (without a diagonal: a fan from a corner whose two sides carry
// none, else from a vertex added at the cell's middle). Every triangle lies inside its
// cell (inside its half when the bound asks for a diagonal), and the triangles are
// counter-clockwise in (u, v), so counter-clockwise seen from the side S_u x S_v points
// to. The counts adapt to each patch's curvature: a flat patch gets one step, a curved
// one as many as its cells' bounds ask.
//
// The bound (why the tolerance holds). Take a cell of a patch, reparametrised to the unit
// square (s, t), and one of its triangles, with barycentric coordinates lambda_i of its
// parameter vertices x_i. For a polynomial map F with |F_ss| <= A, |F_st| <= B, |F_tt| <= C
// on the cell (from the cell's Bézier net: |F_ss| <= p (p - 1) max |second difference in
// s|, |F_st| <= p q max |mixed difference|, |F_tt| <= q (q - 1) max |second difference in
// t|), Taylor's theorem about x with the integral remainder gives
//   |F(x) - sum lambda_i F(x_i)| <= 1/2 sum lambda_i Q(x_i - x),
//   Q(d) = A d_s^2 + 2 B |d_s d_t| + C d_t^2 <= (A + B) d_s^2 + (C + B) d_t^2,
// and for any triangle inside the unit cell sum lambda_i |x_i - x|^2 in that diagonal
// metric is at most the squared radius of the triangle's least enclosing circle, at most
// that of the cell (the half diagonal), so the error is at most e(F) = ((A + B) + (C + B))
// / 8. The pairing x -> sum lambda_i F(x_i) maps the parameter triangle onto the flat
// triangle, so the bound holds both ways. For a rational surface S = P / w (homogeneous
// patch (P, w), weights > 0) two bounds hold and the smaller is taken:
// (1) pick a centre c and r >= |S - c| on the cell (the radius of the cell's control
// points about c: the surface lies in their hull). The point
// T(x) = sum lambda_i P(x_i) / sum lambda_i w(x_i) is a point of the flat triangle (weights
// lambda_i w(x_i) / sum, >= 0), and x -> T(x) maps the parameter triangle onto the whole
// flat triangle; S(x) - T(x) = [(P - c w) - L(P - c w) - (S - c)(w - L w)] / L w, L the
// linear interpolant, L w >= min w >= the least control weight, so
//   |S(x) - T(x)| <= (e(P - c w) + r e(w)) / w_min;
// (2) the bound e(S) of S itself, with A, B, C bounds of its Cartesian second partials on
// the cell, the sharper form of cartesian_bound: the second partials as centre values plus
// variations, and the directions of the centre values taken into account (a mixed partial
// perpendicular to the others, as on a sphere near its pole, adds far less than its
// length; with the diagonal (0, 0)-(1, 1) every node of a half of the cell is comonotone
// with every other in (s, t), so M_st >= 0 for its triangles, with the other diagonal
// M_st <= 0: the cell takes the diagonal whose sign gives the smaller bound, the mixed term
// then working against the others). (1) sees the weights' variation 2 w' S' in the second
// differences of P - c w, (2) does not; (2) is tighter on most cells of a sphere. A
// polynomial patch is the case w = 1, and takes the smaller of (2) and the plain e(F) too.
//
// The counts. Each patch starts from the counts that its Cartesian net's bound asks (for a
// polynomial patch a valid bound: a cell's differences are the patch's scaled by the
// step squared), 0.6 of them (0.4 for a rational patch); at given counts every cell's own
// net (Bézier subdivision of the patch) gives its bound's parts (e_u, e_v), which scale
// about as the step squared: the next counts are those of least n_u n_v that the parts,
// so scaled, would allow, checked again cell by cell; the least n_u n_v that held is kept
// (should none hold in 64 rounds: a polynomial patch takes its patch bound's counts, a
// rational one is refused). A relative slack of 1e-13 of the surface's size covers the
// rounding of the evaluation.
//
// Degenerate edges. A patch edge whose control points coincide (a sphere's pole, the
// apex of a cone) is one point: its grid vertices are merged into one vertex, the cells
// along it lose the triangle that would have two corners there (no zero-area triangles),
// and the rest fan about the point. The normal there is the limit normal
// (surface_form.hpp, limit_normal: with S_v = 0 along u = u0, S_u x S_v ~ (u - u0) S_u x
// S_uv at a sphere's pole), null where it does not exist (a cone's apex). Bands (slivers): the
// steps along such an edge that the tolerance asks fall toward it (about as the square
// root of the distance on a sphere), so one count per patch leaves long thin cells and a
// fan of needles at the point. A patch row (column) with such an edge is cut into bands at
// 1/2, 1/4, ..., 2^-K of its interval from the edge (exact subdivision); each band's counts
// are searched as a patch's, then, from the outer band in, the count along the edge is
// nested (a divisor of the outer neighbour's, at most 4 times smaller, never below the
// band's own search: no union nodes close together) and the count across raised to cells
// at most 3 times as long across as along (control polygons); the new counts are checked
// cell by cell, a band whose check fails keeps its searched counts.
//
// Cost: the count is estimated from the patches' nets before any vertex is evaluated, and
// again at each round of the counts; beyond max_triangles the request is refused
// (InvalidArgument "tolerance"). The vertices are numbered in the order the triangles
// first use them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <numeric>
#include <string>
#include <vector>

#include "casteljau/basis/binomial.hpp"
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

/// A tensor-product Bézier polynomial of degrees (m, n) with `d` values per coefficient,
/// row-major; m < 0: the zero polynomial.
template <class T>
struct Poly {
  int m = -1, n = -1;
  std::size_t d = 0;
  std::vector<T> c;
  [[nodiscard]] bool zero() const { return m < 0 || n < 0; }
  [[nodiscard]] const T* at(int i, int j) const { return c.data() + (static_cast<std::size_t>(i) * static_cast<std::size_t>(n + 1) + static_cast<std::size_t>(j)) * d; }
  [[nodiscard]] T* at(int i, int j) { return c.data() + (static_cast<std::size_t>(i) * static_cast<std::size_t>(n + 1) + static_cast<std::size_t>(j)) * d; }
};

template <class T>
Poly<T> make_poly(int m, int n, std::size_t d) {
  if (m < 0 || n < 0) return Poly<T>{};
  return Poly<T>{m, n, d, std::vector<T>(static_cast<std::size_t>(m + 1) * static_cast<std::size_t>(n + 1) * d, T(0))};
}

/// The derivative along s (dir 0, the rows) or t (dir 1), in Bézier form.
template <class T>
Poly<T> derivative(const Poly<T>& a, int dir) {
  if (a.zero()) return a;
  Poly<T> r = make_poly<T>(dir == 0 ? a.m - 1 : a.m, dir == 0 ? a.n : a.n - 1, a.d);
  if (r.zero()) return r;
  const T k = T(dir == 0 ? a.m : a.n);
  for (int i = 0; i <= r.m; ++i)
    for (int j = 0; j <= r.n; ++j) {
      const T *x0 = a.at(i, j), *x1 = dir == 0 ? a.at(i + 1, j) : a.at(i, j + 1);
      T* y = r.at(i, j);
      for (std::size_t c = 0; c < a.d; ++c) y[c] = k * (x1[c] - x0[c]);
    }
  return r;
}

/// Row n of Pascal's triangle (cached per thread; a deque keeps the rows handed out in
/// place while it grows).
template <class T>
const std::vector<T>& binomials(int n) {
  thread_local std::deque<std::vector<T>> rows;
  while (rows.size() <= static_cast<std::size_t>(n)) rows.push_back(binomial_row<T>(static_cast<int>(rows.size())));
  return rows[static_cast<std::size_t>(n)];
}

/// The product of a scalar polynomial s (d = 1) and a polynomial b, in Bézier form (the
/// degrees add): through the scaled Bernstein coefficients, whose products convolve.
template <class T>
Poly<T> product(const Poly<T>& s, const Poly<T>& b) {
  if (s.zero() || b.zero()) return Poly<T>{};
  Poly<T> r = make_poly<T>(s.m + b.m, s.n + b.n, b.d);
  const std::vector<T>&sm = binomials<T>(s.m), &sn = binomials<T>(s.n), &bm = binomials<T>(b.m), &bn = binomials<T>(b.n),
                 &rm = binomials<T>(r.m), &rn = binomials<T>(r.n);
  const std::size_t d = b.d, bc = static_cast<std::size_t>(b.n + 1), rc = static_cast<std::size_t>(r.n + 1);
  std::vector<T> sb(b.c.size());
  for (std::size_t i = 0; i <= static_cast<std::size_t>(b.m); ++i)
    for (std::size_t j = 0; j < bc; ++j)
      for (std::size_t c = 0; c < d; ++c) sb[(i * bc + j) * d + c] = b.c[(i * bc + j) * d + c] * bm[i] * bn[j];
  for (std::size_t k = 0; k <= static_cast<std::size_t>(s.m); ++k)
    for (std::size_t l = 0; l <= static_cast<std::size_t>(s.n); ++l) {
      const T sk = s.c[k * static_cast<std::size_t>(s.n + 1) + l] * sm[k] * sn[l];
      if (sk == 0) continue;
      for (std::size_t i = 0; i <= static_cast<std::size_t>(b.m); ++i) {
        const T* x = sb.data() + i * bc * d;
        T* y = r.c.data() + ((k + i) * rc + l) * d;
        for (std::size_t jc = 0; jc < bc * d; ++jc) y[jc] += sk * x[jc];
      }
    }
  for (std::size_t i = 0; i <= static_cast<std::size_t>(r.m); ++i)
    for (std::size_t j = 0; j < rc; ++j) {
      const T f = 1 / (rm[i] * rn[j]);
      for (std::size_t c = 0; c < d; ++c) r.c[(i * rc + j) * d + c] *= f;
    }
  return r;
}

/// acc += k * a (a zero or of acc's degrees; a zero acc takes a's).
template <class T>
void accumulate(Poly<T>& acc, const Poly<T>& a, T k) {
  if (a.zero()) return;
  if (acc.zero()) acc = make_poly<T>(a.m, a.n, a.d);
  for (std::size_t i = 0; i < a.c.size(); ++i) acc.c[i] += k * a.c[i];
}

/// The largest Euclidean norm of a coefficient (a bound of the polynomial's norm on the
/// unit square: the convex hull property).
template <class T>
T max_norm(const Poly<T>& a) {
  if (a.zero()) return T(0);
  T best = 0;
  for (std::size_t i = 0; i < a.c.size(); i += a.d) {
    T s = 0;
    for (std::size_t c = 0; c < a.d; ++c) s += a.c[i + c] * a.c[i + c];
    best = std::max(best, s);
  }
  return std::sqrt(best);
}

/// The largest |p^2 a + q^2 c + 2 rho p q b| over p, q in [0, 1/2] and rho = +-1 (a, b, c
/// vectors of d values), from above: the expression is homogeneous of degree 2 in (p, q),
/// so the largest value lies on p = 1/2 or q = 1/2; each of those segments is sampled at
/// 33 points: between two samples h = 1/64 apart the vector (a quadratic in the free
/// variable, second derivative 2c on p = 1/2, 2a on q = 1/2) is within h^2 |c| / 4 (or
/// h^2 |a| / 4) of the chord between the samples' values, whose length is at most the
/// larger of theirs.
///
/// `sign` restricts rho (a rho between its values is never larger: the length is convex in
/// rho): 0, rho = +-1; +1, rho in {0, 1}; -1, rho in {0, -1}.
///
/// `du` (when given): the derivative of the largest value along x for the vectors
/// (x a, sqrt(x) b, c) at x = 1, at the largest sample (the envelope theorem):
/// v . (p^2 a + rho p q b) / |v|, clamped to [0, the largest value].
template <class T>
T largest_form(const T* a, const T* b, const T* c, std::size_t d, int sign, T* du = nullptr) {
  const auto norm = [d](const T* x) {
    T s = 0;
    for (std::size_t k = 0; k < d; ++k) s += x[k] * x[k];
    return std::sqrt(s);
  };
  const T na = norm(a), nc = norm(c);
  T best = 0, arg_p = 0, arg_q = 0, arg_len = 0;
  int arg_rho = 0;
  for (int side = 0; side < 2; ++side) {
    T top = 0;
    for (int rho = -1; rho <= 1; ++rho) {
      if (sign == 0 ? rho == 0 : rho == -sign) continue;
      for (int k = 0; k <= 32; ++k) {
        const T x = T(k) / 64, p = side == 0 ? T(0.5) : x, q = side == 0 ? x : T(0.5);
        T s = 0;
        for (std::size_t i = 0; i < d; ++i) {
          const T v = p * p * a[i] + q * q * c[i] + 2 * T(rho) * p * q * b[i];
          s += v * v;
        }
        if (s > top * top) {
          top = std::sqrt(s);
          if (top > arg_len) {
            arg_len = top;
            arg_p = p;
            arg_q = q;
            arg_rho = rho;
          }
        }
      }
    }
    best = std::max(best, top + (side == 0 ? nc : na) / (4 * 64 * 64));
  }
  if (du != nullptr) {
    T g = 0;
    if (arg_len > 0) {
      for (std::size_t i = 0; i < d; ++i) {
        const T v = arg_p * arg_p * a[i] + arg_q * arg_q * c[i] + 2 * T(arg_rho) * arg_p * arg_q * b[i];
        g += v * (arg_p * arg_p * a[i] + T(arg_rho) * arg_p * arg_q * b[i]);
      }
      g /= arg_len;
    }
    *du = std::clamp(g, T(0), best);
  }
  return best;
}

/// The Cartesian bound of a cell (homogeneous net when rational, weights > 0), by the
/// second partials of S itself on the cell, each written as a centre value plus a
/// variation: |S_ss - a| <= D_ss, |S_st - b| <= D_st, |S_tt - c| <= D_tt on the cell.
/// Taylor's theorem about x (header comment) gives S(x) - sum lambda_i S(x_i) = 1/2 (M_ss
/// a + 2 M_st b + M_tt c) + R with M = sum lambda_i (x_i - x)(x_i - x)^T, a positive
/// semidefinite matrix whose diagonal entries are variances of numbers in [0, 1] (so at
/// most 1/4, and M_st^2 <= M_ss M_tt) for any triangle inside the cell, and
/// |R| <= ((D_ss + D_st) + (D_tt + D_st)) / 8 as in the header comment; so the error is at
/// most largest_form(a, b, c) / 2 + that. The directions count: a mixed partial
/// perpendicular to the others (a sphere near its pole) adds far less than its length.
/// Polynomial cell: the second partials are polynomials (Bézier nets of the second
/// differences): centre = the middle of their coefficients' box, variation = the largest
/// distance of a coefficient from it. Rational cell: with X = P - c w (c the middle of the
/// box of the cell's Cartesian points), the second partials of S = c + X / w are N / w^3,
///   N_ss = w^2 X_ss - w w_ss X - 2 w w_s X_s + 2 w_s^2 X,
///   N_st = w^2 X_st - w w_t X_s - w w_s X_t - w w_st X + 2 w_s w_t X,
///   N_tt = w^2 X_tt - w w_tt X - 2 w w_t X_t + 2 w_t^2 X,
/// polynomials in Bézier form (products); with N's coefficients within R_N of a centre
/// N_c and w between its least and largest coefficients w0 <= w1, N / w^3 lies within
/// R_N / w0^3 + |N_c| (1 / w0^3 - 1 / w1^3) / 2 of N_c (1 / w0^3 + 1 / w1^3) / 2.
/// Returns the parts {e_u, e_v} (their sum the bound; the split only guides the counts).
template <class T>
struct CellBound {
  std::array<T, 2> e{};  ///< the parts {e_u, e_v}
  /// The diagonal the bound needs: +1 the cell's (0, 0)-(1, 1), -1 its (1, 0)-(0, 1), 0 any.
  int diagonal = 0;
  [[nodiscard]] T total() const { return e[0] + e[1]; }
};

template <class T>
CellBound<T> cartesian_bound(const Net<T>& n, bool rational) {
  const std::size_t cd = rational ? n.d - 1 : n.d;
  const int P = static_cast<int>(n.rows) - 1, Q = static_cast<int>(n.cols) - 1;
  Poly<T> Nss, Nst, Ntt;
  T w0 = 1, w1 = 1;
  if (!rational) {
    Poly<T> X = make_poly<T>(P, Q, cd);
    for (int i = 0; i <= P; ++i)
      for (int j = 0; j <= Q; ++j) {
        const T* x = n.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
        std::copy(x, x + cd, X.at(i, j));
      }
    const Poly<T> Xs = derivative(X, 0);
    Nss = derivative(Xs, 0);
    Nst = derivative(Xs, 1);
    Ntt = derivative(derivative(X, 1), 1);
  } else {
    std::vector<T> lo(cd, T(INFINITY)), hi(cd, T(-INFINITY));
    w0 = T(INFINITY);
    w1 = 0;
    for (std::size_t i = 0; i < n.rows; ++i)
      for (std::size_t j = 0; j < n.cols; ++j) {
        const T* x = n.at(i, j);
        w0 = std::min(w0, x[cd]);
        w1 = std::max(w1, x[cd]);
        for (std::size_t k = 0; k < cd; ++k) {
          lo[k] = std::min(lo[k], x[k] / x[cd]);
          hi[k] = std::max(hi[k], x[k] / x[cd]);
        }
      }
    Poly<T> w = make_poly<T>(P, Q, 1), X = make_poly<T>(P, Q, cd);
    for (int i = 0; i <= P; ++i)
      for (int j = 0; j <= Q; ++j) {
        const T* x = n.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
        w.at(i, j)[0] = x[cd];
        for (std::size_t k = 0; k < cd; ++k) X.at(i, j)[k] = x[k] - (lo[k] / 2 + hi[k] / 2) * x[cd];
      }
    const Poly<T> ws = derivative(w, 0), wt = derivative(w, 1), wss = derivative(ws, 0), wst = derivative(ws, 1), wtt = derivative(wt, 1);
    const Poly<T> Xs = derivative(X, 0), Xt = derivative(X, 1), Xss = derivative(Xs, 0), Xst = derivative(Xs, 1), Xtt = derivative(Xt, 1);
    const Poly<T> ww = product(w, w), wws = product(w, ws), wwt = product(w, wt);
    // The scalar factors of X gathered first: -w w_ss + 2 w_s^2 and so on.
    const auto factor = [&](const Poly<T>& w2, const Poly<T>& a, const Poly<T>& b) {
      Poly<T> g;
      accumulate(g, product(w, w2), T(-1));
      accumulate(g, product(a, b), T(2));
      return g;
    };
    accumulate(Nss, product(ww, Xss), T(1));
    accumulate(Nss, product(factor(wss, ws, ws), X), T(1));
    accumulate(Nss, product(wws, Xs), T(-2));
    accumulate(Nst, product(ww, Xst), T(1));
    accumulate(Nst, product(wwt, Xs), T(-1));
    accumulate(Nst, product(wws, Xt), T(-1));
    accumulate(Nst, product(factor(wst, ws, wt), X), T(1));
    accumulate(Ntt, product(ww, Xtt), T(1));
    accumulate(Ntt, product(factor(wtt, wt, wt), X), T(1));
    accumulate(Ntt, product(wwt, Xt), T(-2));
  }
  // Centre and variation of each second partial.
  const T i0 = 1 / (w0 * w0 * w0), i1 = 1 / (w1 * w1 * w1);
  const auto centre = [&](const Poly<T>& N, T* out) {
    std::fill(out, out + cd, T(0));
    if (N.zero()) return T(0);
    for (std::size_t k = 0; k < cd; ++k) {
      T l = T(INFINITY), h = T(-INFINITY);
      for (std::size_t i = k; i < N.c.size(); i += cd) {
        l = std::min(l, N.c[i]);
        h = std::max(h, N.c[i]);
      }
      out[k] = l / 2 + h / 2;
    }
    T r = 0, len = 0;
    for (std::size_t i = 0; i < N.c.size(); i += cd) {
      T s = 0;
      for (std::size_t k = 0; k < cd; ++k) s += (N.c[i + k] - out[k]) * (N.c[i + k] - out[k]);
      r = std::max(r, s);
    }
    for (std::size_t k = 0; k < cd; ++k) len += out[k] * out[k];
    const T D = std::sqrt(r) * i0 + std::sqrt(len) * (i0 - i1) / 2;
    for (std::size_t k = 0; k < cd; ++k) out[k] *= (i0 + i1) / 2;
    return D;
  };
  std::vector<T> abc(3 * cd);
  const T Dss = centre(Nss, abc.data()), Dst = centre(Nst, abc.data() + cd), Dtt = centre(Ntt, abc.data() + 2 * cd);
  // The split of the main term between u and v: its derivative along x of the main term
  // of counts scaled by 1 / sqrt(x) in u (a x, b sqrt(x), c): the term is homogeneous of
  // degree 1 in the two scales, so the two derivatives add up to it.
  const T rest_u = (Dss + Dst) / 8, rest_v = (Dtt + Dst) / 8;
  CellBound<T> out;
  for (const int sign : {1, -1}) {
    T du = 0;
    const T main = largest_form(abc.data(), abc.data() + cd, abc.data() + 2 * cd, cd, sign, &du) / 2;
    du /= 2;
    const CellBound<T> c{{du + rest_u, main - du + rest_v}, sign};
    if (sign == 1 || c.total() < out.total()) out = c;
  }
  return out;
}

/// The bound of a cell: the smaller of the bound of its net's differences (cell_bound:
/// for a rational cell the homogeneous one) and the Cartesian one (both hold).
/// `enough`: a first bound at most this is taken as it is (the Cartesian one, dearer, is
/// then not computed).
template <class T>
CellBound<T> bound(const Net<T>& n, bool rational, T enough) {
  const CellBound<T> h{cell_bound(n, rational), 0};
  if (h.total() <= enough) return h;
  const CellBound<T> c = cartesian_bound(n, rational);
  return c.total() < h.total() ? c : h;
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

/// A fraction num / den of a patch side, reduced (so that equal fractions give equal
/// parameters).
struct Fraction {
  std::size_t num = 0, den = 1;
};

inline Fraction reduced(std::size_t num, std::size_t den) {
  const std::size_t g = std::gcd(num, den);
  return g == 0 ? Fraction{0, 1} : Fraction{num / g, den / g};
}

/// The nodes strictly inside a patch side shared by patches with n1 and n2 steps along it
/// (n2 = 0: a side on the domain's boundary): the union of both sides' steps, sorted.
inline std::vector<Fraction> side_nodes(std::size_t n1, std::size_t n2) {
  std::vector<Fraction> out;
  std::size_t i = 1, k = 1;
  while (i < n1 || (n2 > 0 && k < n2)) {
    const bool has_i = i < n1, has_k = n2 > 0 && k < n2;
    // Compare i / n1 with k / n2.
    if (has_i && has_k && i * n2 == k * n1) {
      out.push_back(reduced(i, n1));
      ++i;
      ++k;
    } else if (has_i && (!has_k || i * n2 < k * n1)) {
      out.push_back(reduced(i, n1));
      ++i;
    } else {
      out.push_back(reduced(k, n2));
      ++k;
    }
  }
  return out;
}

/// The index in `nodes` of the fraction a / b (present).
inline std::size_t find_fraction(const std::vector<Fraction>& nodes, std::size_t a, std::size_t b) {
  const auto it = std::lower_bound(nodes.begin(), nodes.end(), a, [&](const Fraction& f, std::size_t) { return f.num * b < a * f.den; });
  return static_cast<std::size_t>(it - nodes.begin());
}

/// The parameter at the fraction f of [lo, hi].
template <class T>
T at_fraction(T lo, T hi, Fraction f) {
  return f.num == 0 ? lo : f.num == f.den ? hi : lo + (hi - lo) * T(f.num) / T(f.den);
}

}  // namespace tess

/// The tessellation of f (checked) within tol > 0 (InvalidArgument "tolerance" when not a
/// finite positive number, or when the answer would exceed max_triangles: estimated
/// before any vertex is evaluated; InvalidArgument "surface" for a degree 0 in u or v: the
/// surface is then constant along that direction, a curve or a point, and its triangles
/// would all have zero area). Throws InvalidArgument("surface", ...) for a surface
/// that is not continuous across a knot line (an interior knot of full multiplicity whose
/// two sides differ): its mesh would need two edges there.
template <class T>
SurfaceMesh<T> tessellate(const SurfaceForm<T>& f, T tol) {
  using tess::Fraction;
  using tess::Net;
  if (!(tol > 0) || !std::isfinite(tol)) throw InvalidArgument("tolerance", "must be a finite number > 0, got " + format_number(tol));
  if (f.p == 0 || f.q == 0) {
    throw InvalidArgument("surface", std::string("has degree 0 in ") + (f.p == 0 ? "u" : "v") +
                                         ": it is a curve (or a point), with no area to mesh into triangles");
  }
  const SurfacePatches<T> sp = patches(f);
  std::size_t A = sp.patches.size(), B = sp.patches.front().size();
  const std::size_t cd = f.cartesian();
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
  std::vector<T> ub = sp.ubreaks, vb = sp.vbreaks;
  // A degenerate patch edge: all its control points within 1e-12 of the size of the first.
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
  // The counts that a patch's Cartesian net asks, {along u, along v} (a valid bound for a
  // polynomial patch; a start for a rational one).
  const auto estimate = [&](const Net<T>& net) {
    Net<T> c = net;
    if (f.rational) {
      Net<T> cart{c.rows, c.cols, cd, std::vector<T>(c.rows * c.cols * cd)};
      for (std::size_t i = 0; i < c.rows; ++i)
        for (std::size_t j = 0; j < c.cols; ++j)
          for (std::size_t q = 0; q < cd; ++q) cart.at(i, j)[q] = c.at(i, j)[q] / c.at(i, j)[cd];
      c = std::move(cart);
    }
    const auto e = tess::cell_bound(c, false);
    return std::array<std::size_t, 2>{tess::steps_for(e[0], budget), tess::steps_for(e[1], budget)};
  };
  // Bands toward degenerate edges (a sphere's poles, a cone's apex). Along such an edge the
  // circles shrink to a point: the steps along the edge that the tolerance asks fall about
  // as the square root of the distance from it, and one count for the whole patch would
  // leave its cells near the edge long and thin (slivers). A patch row with a degenerate
  // edge (u fixed) is cut at the fractions 1/2, 1/4, ..., 2^-K of its u interval from the
  // edge, exactly (Bézier subdivision): K = 2 floor(log2(s / 4)) for s steps along it by
  // the Cartesian net, so that the band on the edge asks about 4; no bands below s = 16
  // (the sphere at 1e-2: the same 1472 triangles without them, 8 patches to search instead
  // of 24); each band takes its own counts, and after the search the counts along the edge
  // are nested from the outer band in (below). Columns likewise (the grid transposed).
  // `runs`: each edge's bands from the outer one to the one on the edge.
  struct Run {
    bool along_u = true;  ///< the bands are rows (u intervals); else columns
    std::vector<std::size_t> lines;
  };
  std::vector<Run> runs;
  const auto transpose_grid = [&] {
    std::vector<Net<T>> t(A * B);
    for (std::size_t a = 0; a < A; ++a)
      for (std::size_t b = 0; b < B; ++b) t[b * A + a] = tess::transpose(nets[a * B + b]);
    nets = std::move(t);
    std::swap(A, B);
    std::swap(ub, vb);
  };
  for (const bool along_u : {true, false}) {
    if (!along_u) transpose_grid();
    std::vector<Net<T>> out;
    std::vector<T> nb{ub.front()};
    for (std::size_t a = 0; a < A; ++a) {
      bool lo = false, hi = false;
      std::size_t most = 1;
      for (std::size_t b = 0; b < B; ++b) {
        const Net<T>& n = nets[a * B + b];
        lo = lo || point_edge(n, true, 0);
        hi = hi || point_edge(n, true, n.rows - 1);
        most = std::max(most, estimate(n)[1]);
      }
      const int K = (lo || hi) && most >= 16 ? std::min(16, 2 * static_cast<int>(std::floor(std::log2(T(most) / 4)))) : 0;
      std::vector<T> fr{T(0)};
      if (K > 0 && lo)
        for (int q = K; q >= 1; --q) fr.push_back(std::ldexp(T(1), -q));
      if (K > 0 && hi)
        for (int q = lo ? 2 : 1; q <= K; ++q) fr.push_back(1 - std::ldexp(T(1), -q));
      fr.push_back(T(1));
      const std::size_t first = nb.size() - 1, pieces = fr.size() - 1;
      for (std::size_t q = 0; q < pieces; ++q) {
        for (std::size_t b = 0; b < B; ++b)
          out.push_back(pieces == 1 ? nets[a * B + b] : tess::sub_u(nets[a * B + b], fr[q], fr[q + 1]));
        nb.push_back(q + 1 == pieces ? ub[a + 1] : ub[a] + (ub[a + 1] - ub[a]) * fr[q + 1]);
      }
      if (K == 0) continue;
      Run lower{along_u, {}}, upper{along_u, {}};
      for (std::size_t q = pieces; q-- > 0;)
        if (lo && (fr[q + 1] <= T(0.5) || !hi)) lower.lines.push_back(first + q);
      for (std::size_t q = 0; q < pieces; ++q)
        if (hi && (fr[q] >= T(0.5) || !lo)) upper.lines.push_back(first + q);
      if (lo) runs.push_back(std::move(lower));
      if (hi) runs.push_back(std::move(upper));
    }
    nets = std::move(out);
    ub = std::move(nb);
    A = ub.size() - 1;
    if (!along_u) transpose_grid();
  }
  // Start: the Cartesian net of each patch (valid for polynomial patches).
  std::vector<std::size_t> nu(A * B, 1), nv(A * B, 1);
  for (std::size_t k = 0; k < A * B; ++k) {
    const auto e = estimate(nets[k]);
    nu[k] = e[0];
    nv[k] = e[1];
  }
  T total = 0;
  for (std::size_t k = 0; k < A * B; ++k) total += 2 * T(nu[k]) * T(nv[k]);
  const auto refuse_if_too_many = [&] {
    if (total > max_triangles) {
      char about[32];
      std::snprintf(about, sizeof about, "%.2g", static_cast<double>(total));
      throw InvalidArgument("tolerance", "the tessellation would have about " + std::string(about) +
                                             " triangles, more than 10^7: ask for a larger tolerance (got " + format_number(tol) + ")");
    }
  };
  refuse_if_too_many();
  // Each patch's own counts (n, m). At given counts every cell's own net gives the parts
  // (e_u, e_v) of its bound; as they scale about as the step squared, counts (n', m')
  // would hold where e_u x + e_v y <= budget for every cell, x = (n / n')^2 and
  // y = (m / m')^2. The next counts maximise x y under those constraints (x y is
  // unimodal along x: golden sections), and are checked cell by cell again; the least
  // n m that held is kept.
  std::vector<std::array<T, 2>> parts;
  // The diagonal each cell's bound needs (CellBound::diagonal), per patch, cell (i, j) at
  // i * n_v + j.
  std::vector<std::vector<signed char>> diagonals(A * B);
  const auto propose = [&](std::size_t n, std::size_t m) {
    const T big = T(1e12);
    T xmax = big;
    for (const auto& e : parts)
      if (e[0] > 0) xmax = std::min(xmax, budget / e[0]);
    const auto y_of = [&](T x) {
      T y = big;
      for (const auto& e : parts) {
        if (e[1] > 0) y = std::min(y, (budget - e[0] * x) / e[1]);
        else if (e[0] * x > budget) y = 0;
      }
      return std::max(y, T(0));
    };
    T lo = 0, hi = xmax;
    const T g = T(0.6180339887498949);
    T x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = x1 * y_of(x1), f2 = x2 * y_of(x2);
    for (int it = 0; it < 80; ++it) {
      if (f1 < f2) {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = x2 * y_of(x2);
      } else {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = x1 * y_of(x1);
      }
    }
    const T x = (lo + hi) / 2, y = y_of(x);
    const auto count = [](std::size_t c, T r) {
      if (!(r > 0)) return c + 1;
      const T want = std::ceil(T(c) / std::sqrt(r) - T(1e-9));
      return want < 1 ? std::size_t(1) : want > T(1e9) ? std::size_t(1000000000) : static_cast<std::size_t>(want);
    };
    return std::pair<std::size_t, std::size_t>{count(n, x), count(m, y)};
  };
  for (std::size_t k = 0; k < A * B; ++k) {
    const Net<T>& net = nets[k];
    const std::size_t patch_nu = nu[k], patch_nv = nv[k];
    // For a polynomial patch the patch bound holds at the patch counts; a cell's own net
    // is usually well below it (the patch takes its most curved corner): start from 0.6
    // of them. For a rational patch (the counts of its Cartesian net, no bound) from 0.4.
    const double start = f.rational ? 0.4 : 0.6;
    std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(start * static_cast<double>(patch_nu))));
    std::size_t m = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(start * static_cast<double>(patch_nv))));
    total += 2 * (T(n) * T(m) - T(patch_nu) * T(patch_nv));
    std::size_t best_n = 0, best_m = 0;
    std::vector<std::pair<std::size_t, std::size_t>> tried;
    // Every cell's bound at counts (a, b) into `parts`; true when all hold.
    std::vector<signed char> cur_diagonal;
    std::vector<std::array<T, 2>> best_parts;
    const auto cell_bound_at = [&](std::size_t i, std::size_t j, std::size_t a, std::size_t b) {
      const Net<T> strip = tess::transpose(tess::sub_u(net, T(i) / T(a), T(i + 1) / T(a)));
      const Net<T> cell = tess::transpose(tess::sub_u(strip, T(j) / T(b), T(j + 1) / T(b)));
      return tess::bound(cell, f.rational, f.rational ? T(0.6) * budget : T(0));
    };
    // `early`: the counts are a guess near the best counts (bn, bm) held so far, whose cells'
    // parts are best_parts: the cells whose parts, scaled to (a, b), come nearest the budget
    // are checked first, and the first that fails ends the check (no parts then).
    const auto check = [&](std::size_t a, std::size_t b, bool early = false, std::size_t bn = 0, std::size_t bm = 0) {
      tried.emplace_back(a, b);
      if (early) {
        // Every cell, in the order of its predicted bound, largest first.
        const T x = T(bn) * T(bn) / (T(a) * T(a)), y = T(bm) * T(bm) / (T(b) * T(b));
        std::vector<std::pair<T, std::size_t>> order;
        order.reserve(a * b);
        for (std::size_t i = 0; i < a; ++i)
          for (std::size_t j = 0; j < b; ++j) {
            const std::size_t bi = std::min(bn - 1, static_cast<std::size_t>((T(i) + T(0.5)) * T(bn) / T(a)));
            const std::size_t bj = std::min(bm - 1, static_cast<std::size_t>((T(j) + T(0.5)) * T(bm) / T(b)));
            const auto& e = best_parts[bi * bm + bj];
            order.emplace_back(e[0] * x + e[1] * y, i * b + j);
          }
        std::sort(order.begin(), order.end(), [](const auto& l, const auto& r) { return l.first > r.first; });
        parts.assign(a * b, std::array<T, 2>{});
        cur_diagonal.assign(a * b, 0);
        for (const auto& [predicted, at] : order) {
          const auto e = cell_bound_at(at / b, at % b, a, b);
          if (e.total() > budget) return false;
          parts[at] = e.e;
          cur_diagonal[at] = static_cast<signed char>(e.diagonal);
        }
        return true;
      }
      parts.clear();
      cur_diagonal.clear();
      bool ok = true;
      for (std::size_t i = 0; i < a; ++i) {
        const Net<T> strip = tess::transpose(tess::sub_u(net, T(i) / T(a), T(i + 1) / T(a)));
        for (std::size_t j = 0; j < b; ++j) {
          const Net<T> cell = tess::transpose(tess::sub_u(strip, T(j) / T(b), T(j + 1) / T(b)));
          const auto e = tess::bound(cell, f.rational, f.rational ? T(0.6) * budget : T(0));
          if (e.total() > budget) {
            ok = false;
            if (early) return false;
          }
          parts.push_back(e.e);
          cur_diagonal.push_back(static_cast<signed char>(e.diagonal));
        }
      }
      return ok;
    };
    const auto seen = [&](std::size_t a, std::size_t b) { return std::find(tried.begin(), tried.end(), std::pair{a, b}) != tried.end(); };
    for (int round = 0; round < 64; ++round) {
      refuse_if_too_many();
      const bool ok = check(n, m);
      if (ok && (best_n == 0 || n * m < best_n * best_m)) {
        best_n = n;
        best_m = m;
        diagonals[k] = cur_diagonal;
        best_parts = parts;
      }
      auto [n2, m2] = propose(n, m);
      if (ok && n2 * m2 >= n * m) break;
      if (best_n != 0 && (seen(n2, m2) || n2 * m2 >= best_n * best_m)) break;
      while (seen(n2, m2)) {
        // Failed there before: more steps in both directions.
        n2 += 1 + n2 / 16;
        m2 += 1 + m2 / 16;
      }
      total += 2 * (T(n2) * T(m2) - T(n) * T(m));
      n = n2;
      m = m2;
    }
    // Counts near the best with fewer cells: the best counts' cell parts, scaled by the
    // step squared, predict for each n' near best_n the least m' that holds (the parts'
    // split between u and v only guides this); the predicted counts are tried by fewest
    // cells, each check ending at its first failing cell (the cells predicted worst
    // first), and the first that holds is taken; then once more from there.
    for (int tries = 0; best_n != 0 && tries < 2; ++tries) {
      const std::size_t bn = best_n, bm = best_m, span = 2 + bn / 8;
      std::vector<std::pair<std::size_t, std::size_t>> near;
      for (std::size_t a = bn > span ? bn - span : 1; a <= bn + span; ++a) {
        const T x = T(bn) * T(bn) / (T(a) * T(a));
        T y = T(1e12);
        for (const auto& e : best_parts) {
          if (e[1] > 0) y = std::min(y, (T(1.02) * budget - e[0] * x) / e[1]);
          else if (e[0] * x > T(1.02) * budget) y = 0;
        }
        if (!(y > 0)) continue;
        const T want = std::ceil(T(bm) / std::sqrt(y) - T(1e-9));
        const std::size_t b = want < 1 ? 1 : static_cast<std::size_t>(std::min(want, T(1e9)));
        if (a * b < bn * bm && !seen(a, b)) near.emplace_back(a, b);
      }
      // The next counts with one step fewer in u or in v as well (the prediction is not exact).
      for (const auto& [a, b] : {std::pair<std::size_t, std::size_t>{bn - 1, bm}, {bn, bm - 1}, {bn - 1, bm + 1}, {bn + 1, bm - 1}})
        if (a >= 1 && b >= 1 && a * b < bn * bm && !seen(a, b) && std::find(near.begin(), near.end(), std::pair{a, b}) == near.end())
          near.emplace_back(a, b);
      std::sort(near.begin(), near.end(), [](const auto& l, const auto& r) { return l.first * l.second < r.first * r.second; });
      bool better = false;
      for (std::size_t q = 0; q < near.size() && q < 6; ++q) {
        if (check(near[q].first, near[q].second, true, bn, bm)) {
          best_n = near[q].first;
          best_m = near[q].second;
          diagonals[k] = cur_diagonal;
          best_parts = parts;
          better = true;
          break;
        }
      }
      if (!better) break;
    }
    if (best_n == 0) {
      // Not settled in 64 rounds (not met in practice): a polynomial patch falls back on
      // the patch bound's counts, which hold; a rational one is refused rather than risked.
      if (f.rational) throw NumericalError("the tessellation's step counts did not settle (tolerance " + format_number(tol) + ")");
      best_n = patch_nu;
      best_m = patch_nv;
      diagonals[k].assign(best_n * best_m, 0);
    }
    total += 2 * (T(best_n) * T(best_m) - T(n) * T(m));
    nu[k] = best_n;
    nv[k] = best_m;
  }
  // The bands' counts (runs, above), from the outer band in: along the edge, the outer
  // band's count rounded up to 8..15 x a power of 2 (at most 1/8 more), then each band
  // takes its outer neighbour's count halved as often as its own search allows (nested: the
  // band's side has no extra nodes close to others); across, enough steps for cells at most
  // twice as long across as along (by the net's polygons), so that the cells near the edge
  // and the fans at it are not slivers. New counts are checked cell by cell as in the
  // search; where they fail the band keeps the searched ones.
  const auto verify = [&](std::size_t k, std::size_t a, std::size_t b) {
    std::vector<signed char> diag;
    diag.reserve(a * b);
    for (std::size_t i = 0; i < a; ++i) {
      const Net<T> strip = tess::transpose(tess::sub_u(nets[k], T(i) / T(a), T(i + 1) / T(a)));
      for (std::size_t j = 0; j < b; ++j) {
        const Net<T> cell = tess::transpose(tess::sub_u(strip, T(j) / T(b), T(j + 1) / T(b)));
        const auto e = tess::bound(cell, f.rational, f.rational ? T(0.6) * budget : T(0));
        if (e.total() > budget) return false;
        diag.push_back(static_cast<signed char>(e.diagonal));
      }
    }
    diagonals[k] = std::move(diag);
    return true;
  };
  // The longest polygon of a net's Cartesian points along u (dir 0) or v (dir 1).
  const auto polygon = [&](const Net<T>& n, int dir) {
    T best = 0;
    const std::size_t lines = dir == 0 ? n.cols : n.rows, len = dir == 0 ? n.rows : n.cols;
    for (std::size_t l = 0; l < lines; ++l) {
      T sum = 0;
      for (std::size_t q = 0; q + 1 < len; ++q) {
        const T *x = dir == 0 ? n.at(q, l) : n.at(l, q), *y = dir == 0 ? n.at(q + 1, l) : n.at(l, q + 1);
        T s2 = 0;
        for (std::size_t c = 0; c < cd; ++c) {
          const T e = f.rational ? y[c] / y[cd] - x[c] / x[cd] : y[c] - x[c];
          s2 += e * e;
        }
        sum += std::sqrt(s2);
      }
      best = std::max(best, sum);
    }
    return best;
  };
  for (const Run& r : runs) {
    std::vector<std::size_t>&along = r.along_u ? nv : nu, &across = r.along_u ? nu : nv;
    for (std::size_t c = 0; c < (r.along_u ? B : A); ++c) {
      const std::size_t L = r.lines.size();
      std::vector<std::size_t> ks(L);
      std::vector<T> la(L), lx(L);
      for (std::size_t t = 0; t < L; ++t) {
        ks[t] = r.along_u ? r.lines[t] * B + c : c * B + r.lines[t];
        la[t] = polygon(nets[ks[t]], r.along_u ? 1 : 0);
        lx[t] = polygon(nets[ks[t]], r.along_u ? 0 : 1);
      }
      // The counts of the bands for an outer count N (need0..2 need0): each band the least
      // divisor of its outer neighbour's count, at most 4 times smaller, that its search allows;
      // across, the searched count or enough for the shape. The N of fewest cells is taken.
      const auto chain = [&](std::size_t N, std::vector<std::array<std::size_t, 2>>* out) {
        T cells = 0;
        std::size_t prev = N;
        for (std::size_t t = 0; t < L; ++t) {
          const std::size_t need = along[ks[t]];
          std::size_t want = prev;
          for (std::size_t d = 2; d <= 4; ++d)
            if (prev % d == 0 && prev / d >= need) want = std::min(want, prev / d);
          if (want < need) want = need;  // not nested (not met on the bands' searches)
          std::size_t want_across = across[ks[t]];
          if (la[t] > 0) want_across = std::max(want_across, static_cast<std::size_t>(std::min(T(1e6), std::ceil(lx[t] * T(want) / (3 * la[t])))));
          cells += T(want) * T(want_across);
          if (out != nullptr) out->push_back({want_across, want});
          prev = want;
        }
        // The band on the edge: its count is the fan's at the point (the fan's angles there
        // are the edge's total turn over it): an N that leaves it above twice its search's
        // comes after every N that does not.
        return std::pair<bool, T>{prev > 2 * along[ks[L - 1]], cells};
      };
      const std::size_t need0 = along[ks[0]];
      std::size_t bestN = 0;
      std::pair<bool, T> best{};
      for (std::size_t N = need0; N <= 2 * need0; ++N) {
        const std::pair<bool, T> cost = chain(N, nullptr);
        if (bestN == 0 || cost < best) {
          bestN = N;
          best = cost;
        }
      }
      std::vector<std::array<std::size_t, 2>> plan;
      chain(bestN, &plan);
      for (std::size_t t = 0; t < L; ++t) {
        const std::size_t k = ks[t];
        const std::size_t a = r.along_u ? plan[t][0] : plan[t][1], b = r.along_u ? plan[t][1] : plan[t][0];
        if ((a != nu[k] || b != nv[k]) && T(2) * T(a) * T(b) <= max_triangles && verify(k, a, b)) {
          total += 2 * (T(a) * T(b) - T(nu[k]) * T(nv[k]));
          nu[k] = a;
          nv[k] = b;
        }
      }
    }
  }
  // Compatible counts across patch sides (needles). A side shared by patches with n1 and
  // n2 steps along it carries the union of both steps; its two nearest distinct nodes are
  // g / (n1 n2) apart (g = gcd(n1, n2)), 1 / r of the finer step with r = min(n1, n2) / g,
  // and a triangle on two such nodes is a needle when r is large (7 and 8 steps: 1/56 of
  // the side; the torus at 1e-4 had 0.52 degrees). Along each line of patches (a column,
  // for the counts along v; a row, for those along u) the counts are raised, each by at
  // most max(2, count / 2), so that every consecutive pair has r <= 3, at the least number
  // of added cells (dynamic programming along the line; a pair left beyond 3 only if no
  // raise within those limits reaches it). Raised counts are checked cell by cell as in
  // the search (a patch whose check fails keeps its count); patches in bands keep theirs
  // (nested already). The bicubic of W8 at 3e-3: 152 more triangles (43240 -> 43392).
  {
    constexpr std::size_t max_ratio = 3;
    std::vector<char> banded(A * B, 0);
    for (const Run& r : runs)
      for (std::size_t c = 0; c < (r.along_u ? B : A); ++c)
        for (const std::size_t l : r.lines) banded[r.along_u ? l * B + c : c * B + l] = 1;
    const auto ratio = [](std::size_t x, std::size_t y) { return std::min(x, y) / std::gcd(x, y); };
    // An incompatible pair costs more than any raise (counted in cells).
    const T penalty = T(1e9);
    for (const bool counts_v : {true, false}) {
      std::vector<std::size_t>& cnt = counts_v ? nv : nu;
      const std::vector<std::size_t>& other = counts_v ? nu : nv;
      const std::size_t lines = counts_v ? B : A, len = counts_v ? A : B;
      for (std::size_t c = 0; c < lines && len > 1; ++c) {
        std::vector<std::size_t> ks(len);
        bool any = false;
        for (std::size_t t = 0; t < len; ++t) {
          ks[t] = counts_v ? t * B + c : c * B + t;
          if (t > 0 && !banded[ks[t - 1]] && !banded[ks[t]] && ratio(cnt[ks[t - 1]], cnt[ks[t]]) > max_ratio) any = true;
        }
        if (!any) continue;
        // Each patch's candidates: its count raised by 0 .. max(2, count / 2) (a banded
        // patch: its count only). cost[t][d]: the least added cells of patches 0..t with
        // patch t raised by d, each pair beyond max_ratio costing `penalty` cells.
        std::vector<std::size_t> span(len);
        std::vector<std::vector<T>> cost(len);
        std::vector<std::vector<std::size_t>> from(len);
        for (std::size_t t = 0; t < len; ++t) {
          span[t] = banded[ks[t]] ? 0 : std::max<std::size_t>(2, cnt[ks[t]] / 2);
          cost[t].assign(span[t] + 1, T(0));
          from[t].assign(span[t] + 1, 0);
          for (std::size_t d = 0; d <= span[t]; ++d) {
            const T own = T(d) * T(other[ks[t]]);
            if (t == 0) {
              cost[t][d] = own;
              continue;
            }
            T best = T(INFINITY);
            for (std::size_t e = 0; e <= span[t - 1]; ++e) {
              const bool bad = ratio(cnt[ks[t - 1]] + e, cnt[ks[t]] + d) > max_ratio;
              const T x = cost[t - 1][e] + (bad ? penalty * T(other[ks[t]] + other[ks[t - 1]]) : T(0));
              if (x < best) {
                best = x;
                from[t][d] = e;
              }
            }
            cost[t][d] = best + own;
          }
        }
        std::size_t d = static_cast<std::size_t>(std::min_element(cost[len - 1].begin(), cost[len - 1].end()) - cost[len - 1].begin());
        for (std::size_t t = len; t-- > 0;) {
          const std::size_t k = ks[t], n = cnt[k] + d;
          const std::size_t prev_d = t > 0 ? from[t][d] : 0;
          if (d > 0) {
            const std::size_t a = counts_v ? nu[k] : n, b = counts_v ? n : nv[k];
            if (T(2) * T(a) * T(b) <= max_triangles && verify(k, a, b)) {
              total += 2 * (T(a) * T(b) - T(nu[k]) * T(nv[k]));
              nu[k] = a;
              nv[k] = b;
            }
          }
          d = prev_d;
        }
      }
    }
  }
  refuse_if_too_many();
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
          throw InvalidArgument("surface", "is not continuous across u = " + format_number(ub[a + 1]) +
                                               " (a knot of full multiplicity): a mesh without cracks cannot follow it");
        }
    }
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b + 1 < B; ++b) {
      const Net<T>&lo = nets[a * B + b], &hi = nets[a * B + b + 1];
      for (std::size_t i = 0; i < lo.rows; ++i)
        if (!close(lo.at(i, lo.cols - 1), hi.at(i, 0), lo.d, f.rational)) {
          throw InvalidArgument("surface", "is not continuous across v = " + format_number(vb[b + 1]) +
                                               " (a knot of full multiplicity): a mesh without cracks cannot follow it");
        }
    }

  // The nodes. Corners of the patches; the nodes inside each patch side, the union of the
  // steps of the two patches that share it (so a side is split the same way for both);
  // the inner nodes of each patch's grid.
  std::vector<T> node_u, node_v;
  const auto new_node = [&](T u, T v) {
    node_u.push_back(u);
    node_v.push_back(v);
    return static_cast<std::uint32_t>(node_u.size() - 1);
  };
  const auto corner = [&](std::size_t a, std::size_t b) { return static_cast<std::uint32_t>(a * (B + 1) + b); };
  for (std::size_t a = 0; a <= A; ++a)
    for (std::size_t b = 0; b <= B; ++b) new_node(ub[a], vb[b]);
  struct Side {
    std::vector<Fraction> at;
    std::uint32_t first = 0;  ///< the node id of at[0] (the others follow)
  };
  // Sides along u at v = vbreaks[b] over [ubreaks[a], ubreaks[a + 1]]: su[a * (B + 1) + b];
  // sides along v at u = ubreaks[a] over [vbreaks[b], vbreaks[b + 1]]: sv[a * B + b].
  std::vector<Side> su(A * (B + 1)), sv((A + 1) * B);
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b <= B; ++b) {
      Side& s = su[a * (B + 1) + b];
      s.at = tess::side_nodes(b < B ? nu[a * B + b] : nu[a * B + b - 1], b > 0 && b < B ? nu[a * B + b - 1] : 0);
      s.first = static_cast<std::uint32_t>(node_u.size());
      for (const Fraction x : s.at) new_node(tess::at_fraction(ub[a], ub[a + 1], x), vb[b]);
    }
  for (std::size_t a = 0; a <= A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      Side& s = sv[a * B + b];
      s.at = tess::side_nodes(a < A ? nv[a * B + b] : nv[(a - 1) * B + b], a > 0 && a < A ? nv[(a - 1) * B + b] : 0);
      s.first = static_cast<std::uint32_t>(node_u.size());
      for (const Fraction x : s.at) new_node(ub[a], tess::at_fraction(vb[b], vb[b + 1], x));
    }
  std::vector<std::uint32_t> inner_first(A * B);
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      const std::size_t k = a * B + b;
      inner_first[k] = static_cast<std::uint32_t>(node_u.size());
      for (std::size_t I = 1; I < nu[k]; ++I)
        for (std::size_t J = 1; J < nv[k]; ++J)
          new_node(tess::at_fraction(ub[a], ub[a + 1], tess::reduced(I, nu[k])),
                   tess::at_fraction(vb[b], vb[b + 1], tess::reduced(J, nv[k])));
    }
  // The node of patch (a, b) at grid index (I, J).
  const auto grid_node = [&](std::size_t a, std::size_t b, std::size_t I, std::size_t J) -> std::uint32_t {
    const std::size_t k = a * B + b, n = nu[k], m = nv[k];
    const bool u_end = I == 0 || I == n, v_end = J == 0 || J == m;
    if (u_end && v_end) return corner(I == 0 ? a : a + 1, J == 0 ? b : b + 1);
    if (u_end) {
      const Side& s = sv[(I == 0 ? a : a + 1) * B + b];
      return s.first + static_cast<std::uint32_t>(tess::find_fraction(s.at, J, m));
    }
    if (v_end) {
      const Side& s = su[a * (B + 1) + (J == 0 ? b : b + 1)];
      return s.first + static_cast<std::uint32_t>(tess::find_fraction(s.at, I, n));
    }
    return inner_first[k] + static_cast<std::uint32_t>((I - 1) * (m - 1) + (J - 1));
  };
  tess::Merge merge{std::vector<std::uint32_t>(node_u.size())};
  std::iota(merge.up.begin(), merge.up.end(), 0u);
  // Degenerate patch edges (point_edge, above): the side's nodes and its two corners
  // become one.
  const auto join_side = [&](const Side& s, std::uint32_t c0, std::uint32_t c1) {
    merge.join(c0, c1);
    for (std::size_t k = 0; k < s.at.size(); ++k) merge.join(c0, s.first + static_cast<std::uint32_t>(k));
  };
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      const Net<T>& n = nets[a * B + b];
      for (const std::size_t side : {std::size_t(0), std::size_t(1)}) {
        if (point_edge(n, true, side ? n.rows - 1 : 0)) {  // u fixed, along v
          const std::size_t aa = side ? a + 1 : a;
          join_side(sv[aa * B + b], corner(aa, b), corner(aa, b + 1));
        }
        if (point_edge(n, false, side ? n.cols - 1 : 0)) {  // v fixed, along u
          const std::size_t bb = side ? b + 1 : b;
          join_side(su[a * (B + 1) + bb], corner(a, bb), corner(a + 1, bb));
        }
      }
    }
  // Vertices: one per merged node, evaluated at its representative (the least node).
  SurfaceMesh<T> m;
  m.dim = cd;
  const bool normals = cd == 3;
  const auto add_vertex = [&](T u, T v) {
    const std::vector<T> d = partials(f, u, v, normals ? 2 : 0);
    m.vertices.insert(m.vertices.end(), d.begin(), d.begin() + static_cast<std::ptrdiff_t>(cd));
    m.uv.push_back(u);
    m.uv.push_back(v);
    if (!normals) return static_cast<std::uint32_t>(m.uv.size() / 2 - 1);
    const auto at = [&](std::size_t a, std::size_t b) { return d.data() + (a * 3 + b) * 3; };
    const SurfaceGeometry<T> g = geometry<T>(at(1, 0), at(0, 1), at(2, 0), at(1, 1), at(0, 2));
    T nrm[3] = {g.normal[0], g.normal[1], g.normal[2]};
    bool ok = g.defined;
    if (!ok) {
      // At a degenerate edge (a sphere's pole): the limit normal where it exists.
      if (const auto n = limit_normal(f, u, v)) {
        std::copy(n->begin(), n->end(), nrm);
        ok = true;
      }
    }
    m.normals.insert(m.normals.end(), nrm, nrm + 3);
    m.has_normal.push_back(ok ? 1 : 0);
    return static_cast<std::uint32_t>(m.uv.size() / 2 - 1);
  };
  std::vector<std::uint32_t> vid(node_u.size(), UINT32_MAX);
  for (std::uint32_t k = 0; k < node_u.size(); ++k) {
    const std::uint32_t r = merge.find(k);
    if (vid[r] == UINT32_MAX) vid[r] = add_vertex(node_u[r], node_v[r]);
    vid[k] = vid[r];
  }
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
  // The cells. A cell is a rectangle of its patch's grid; a cell along a patch side also
  // has the side's nodes from the neighbouring patch on that side. Every triangle lies in
  // its cell, so the cell's bound holds for it (the bound of the header comment holds for
  // any triangle inside the cell). Counter-clockwise in (u, v).
  std::vector<std::uint32_t> ring;
  for (std::size_t a = 0; a < A; ++a)
    for (std::size_t b = 0; b < B; ++b) {
      const std::size_t k = a * B + b, n = nu[k], mm = nv[k];
      for (std::size_t I = 0; I < n; ++I)
        for (std::size_t J = 0; J < mm; ++J) {
          const std::uint32_t c00 = grid_node(a, b, I, J), c10 = grid_node(a, b, I + 1, J), c11 = grid_node(a, b, I + 1, J + 1),
                              c01 = grid_node(a, b, I, J + 1);
          // The extra nodes of each side: bottom (v = v_J, u rising), right, top (u
          // falling), left (v falling); only on the patch's border.
          ring.clear();
          std::size_t extra[4] = {0, 0, 0, 0};
          const auto side_run = [&](const Side& s, std::size_t lo, std::size_t hi, std::size_t den, bool reverse, int which) {
            const std::size_t i0 = tess::find_fraction(s.at, lo, den) + (lo == 0 ? 0 : 1);
            const std::size_t i1 = hi == den ? s.at.size() : tess::find_fraction(s.at, hi, den);
            extra[which] = i1 > i0 ? i1 - i0 : 0;
            if (!reverse)
              for (std::size_t i = i0; i < i1; ++i) ring.push_back(s.first + static_cast<std::uint32_t>(i));
            else
              for (std::size_t i = i1; i-- > i0;) ring.push_back(s.first + static_cast<std::uint32_t>(i));
          };
          ring.push_back(c00);
          if (J == 0) side_run(su[a * (B + 1) + b], I, I + 1, n, false, 0);
          ring.push_back(c10);
          if (I + 1 == n) side_run(sv[(a + 1) * B + b], J, J + 1, mm, false, 1);
          ring.push_back(c11);
          if (J + 1 == mm) side_run(su[a * (B + 1) + b + 1], I, I + 1, n, true, 2);
          ring.push_back(c01);
          if (I == 0) side_run(sv[a * B + b], J, J + 1, mm, true, 3);
          const int diagonal = diagonals[k][I * mm + J];
          const std::size_t pos[4] = {0, 1 + extra[0], 2 + extra[0] + extra[1], 3 + extra[0] + extra[1] + extra[2]};
          const std::size_t R = ring.size();
          if (diagonal != 0) {
            // The cell's two halves on its diagonal, each a triangle P, Q, R of the ring's
            // corners (P -> Q and Q -> R sides of the cell, which may carry extra nodes):
            // a fan from R over the side P -> Q but its last piece, then a fan from the
            // last node before Q over the side Q -> R. Every node of a half is comonotone
            // (or countermonotone) in (s, t) with every other, as the bound asks.
            for (const std::size_t cp : diagonal > 0 ? std::array<std::size_t, 2>{0, 2} : std::array<std::size_t, 2>{3, 1}) {
              const std::size_t p = pos[cp], q = pos[(cp + 1) % 4], r = pos[(cp + 2) % 4];
              const std::size_t K = (q + R - p) % R, L = (r + R - q) % R;
              const auto node = [&](std::size_t from, std::size_t i) { return vid[ring[(from + i) % R]]; };
              for (std::size_t i = 0; i + 2 <= K; ++i) emit(node(p, i), node(p, i + 1), node(r, 0));
              const std::uint32_t last = node(p, K - 1);
              for (std::size_t j = 0; j < L; ++j) emit(last, node(q, j), node(q, j + 1));
            }
            continue;
          }
          if (ring.size() == 4) {
            const std::uint32_t p00 = vid[c00], p10 = vid[c10], p11 = vid[c11], p01 = vid[c01];
            if (dist2(p00, p11) <= dist2(p10, p01)) {
              emit(p00, p10, p11);
              emit(p00, p11, p01);
            } else {
              emit(p00, p10, p01);
              emit(p10, p11, p01);
            }
            continue;
          }
          // A fan from a corner whose two sides have no extra nodes (corner c of the ring
          // order: c00 between left and bottom, c10 bottom and right, ...); else from a
          // new vertex at the cell's middle.
          int apex = -1;
          for (int c = 0; c < 4 && apex < 0; ++c)
            if (extra[c] == 0 && extra[(c + 3) % 4] == 0) apex = c;
          if (apex >= 0) {
            const std::size_t s = pos[apex];
            for (std::size_t i = 1; i + 1 < R; ++i) emit(vid[ring[s]], vid[ring[(s + i) % R]], vid[ring[(s + i + 1) % R]]);
          } else {
            const T um = (node_u[c00] + node_u[c10]) / 2, vm = (node_v[c00] + node_v[c01]) / 2;
            const std::uint32_t mid = add_vertex(um, vm);
            for (std::size_t i = 0; i < R; ++i) emit(mid, vid[ring[i]], vid[ring[(i + 1) % R]]);
          }
        }
    }
  // The vertices numbered in the order the triangles first use them.
  const std::size_t V = m.size();
  std::vector<std::uint32_t> order(V, UINT32_MAX);
  std::vector<std::uint32_t> old_of;
  old_of.reserve(V);
  for (auto& t : m.triangles)
    for (auto& x : t) {
      if (order[x] == UINT32_MAX) {
        order[x] = static_cast<std::uint32_t>(old_of.size());
        old_of.push_back(x);
      }
      x = order[x];
    }
  SurfaceMesh<T> r;
  r.dim = m.dim;
  r.triangles = std::move(m.triangles);
  for (const std::uint32_t k : old_of) {
    r.vertices.insert(r.vertices.end(), m.vertices.begin() + static_cast<std::ptrdiff_t>(k * cd), m.vertices.begin() + static_cast<std::ptrdiff_t>((k + 1) * cd));
    r.uv.push_back(m.uv[2 * k]);
    r.uv.push_back(m.uv[2 * k + 1]);
    if (normals) {
      r.normals.insert(r.normals.end(), m.normals.begin() + static_cast<std::ptrdiff_t>(3 * k), m.normals.begin() + static_cast<std::ptrdiff_t>(3 * k + 3));
      r.has_normal.push_back(m.has_normal[k]);
    }
  }
  return r;
}

}  // namespace casteljau::detail
