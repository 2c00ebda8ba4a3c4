// Tensor-product surfaces as plain data with the dimension known at run time, and the
// algorithms on them, written once per scalar: a surface is a curve of curves. Along u it
// is a B-spline curve whose control "points" are the rows of the grid (Row: the row's
// coordinates in one flat vector), so knot insertion, refinement, splitting, the Bézier
// pieces and degree elevation are the curve algorithms of basis/knot_ops.hpp and
// basis/knot_form.hpp applied to rows; along v the same on the transposed grid.
// Evaluation and partial derivatives follow [PT97] A3.6 (tensor product of the basis
// function derivatives) and A4.4 (the rational quotient rule). Rational surfaces are held
// in homogeneous coordinates (w P, w). The typed surfaces (surfaces/surface.hpp) wrap this
// form, so that every algorithm is compiled once per scalar, not once per type and
// dimension.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/knot_form.hpp"
#include "casteljau/basis/knot_ops.hpp"
#include "casteljau/core/error.hpp"

namespace casteljau {

/// The two parameter directions of a surface.
enum class Direction { u, v };

namespace detail {

/// A row of a surface's grid as one value of a vector space (the control "point" of the
/// surface seen as a curve in the other direction): its coordinates in one flat vector.
template <class T>
struct Row {
  std::vector<T> x;
};

template <class T>
Row<T> lerp(const Row<T>& a, const Row<T>& b, T t) {
  Row<T> r{std::vector<T>(a.x.size())};
  const T s = 1 - t;
  for (std::size_t i = 0; i < a.x.size(); ++i) r.x[i] = s * a.x[i] + t * b.x[i];
  return r;
}
template <class T>
Row<T> operator+(const Row<T>& a, const Row<T>& b) {
  Row<T> r = a;
  for (std::size_t i = 0; i < r.x.size(); ++i) r.x[i] += b.x[i];
  return r;
}
template <class T>
Row<T> operator-(const Row<T>& a, const Row<T>& b) {
  Row<T> r = a;
  for (std::size_t i = 0; i < r.x.size(); ++i) r.x[i] -= b.x[i];
  return r;
}
template <class T>
Row<T> operator*(T s, const Row<T>& a) {
  Row<T> r = a;
  for (auto& c : r.x) c *= s;
  return r;
}
template <class T>
Row<T>& operator+=(Row<T>& a, const Row<T>& b) {
  for (std::size_t i = 0; i < a.x.size(); ++i) a.x[i] += b.x[i];
  return a;
}
template <class T>
bool all_finite_point(const Row<T>& a) {
  return std::all_of(a.x.begin(), a.x.end(), [](T c) { return std::isfinite(c); });
}
template <class T>
Row<T> operator/(const Row<T>& a, T s) {
  Row<T> r = a;
  for (auto& c : r.x) c /= s;
  return r;
}

/// A B-spline curve with the dimension known at run time: degree p, knots U, n points of
/// `dim` coordinates each (when rational: the Cartesian point, then its weight).
template <class T>
struct CurveForm {
  int p = 0;
  std::vector<T> U;
  std::size_t dim = 0;
  bool rational = false;
  std::vector<T> P;  ///< n * dim
  [[nodiscard]] std::size_t size() const { return dim == 0 ? 0 : P.size() / dim; }
};

/// A tensor-product B-spline surface with the dimension known at run time: degrees p
/// (along u, the rows) and q (along v, the columns), knots U and V, a rows x cols grid of
/// points of `dim` coordinates (when rational: the Cartesian point, then its weight),
/// row-major.
/// No invariant is enforced here: check_surface_form states them; the typed surfaces
/// check them once.
template <class T>
struct SurfaceForm {
  int p = 0, q = 0;
  std::vector<T> U, V;
  std::size_t rows = 0, cols = 0;
  std::size_t dim = 0;  ///< stored coordinates per point (Cartesian dimension + 1 when rational)
  bool rational = false;
  std::vector<T> P;  ///< P[(i * cols + j) * dim + k]

  [[nodiscard]] const T* at(std::size_t i, std::size_t j) const { return P.data() + (i * cols + j) * dim; }
  [[nodiscard]] T* at(std::size_t i, std::size_t j) { return P.data() + (i * cols + j) * dim; }
  /// The Cartesian dimension.
  [[nodiscard]] std::size_t cartesian() const { return rational ? dim - 1 : dim; }
};

/// f with every rational point (P, w) taken to (w P, w) (forward) or back.
template <class T>
SurfaceForm<T> weighted(SurfaceForm<T> f, bool forward) {
  if (!f.rational) return f;
  const std::size_t cd = f.dim - 1;
  for (std::size_t i = 0; i < f.P.size(); i += f.dim) {
    const T w = f.P[i + cd];
    for (std::size_t c = 0; c < cd; ++c) f.P[i + c] = forward ? f.P[i + c] * w : f.P[i + c] / w;
  }
  return f;
}

/// f with u and v exchanged (p with q, U with V, the grid transposed).
template <class T>
SurfaceForm<T> transposed(const SurfaceForm<T>& f) {
  SurfaceForm<T> g{f.q, f.p, f.V, f.U, f.cols, f.rows, f.dim, f.rational, std::vector<T>(f.P.size())};
  for (std::size_t i = 0; i < f.rows; ++i)
    for (std::size_t j = 0; j < f.cols; ++j) std::copy(f.at(i, j), f.at(i, j) + f.dim, g.at(j, i));
  return g;
}

/// f as a curve along u whose points are its rows.
template <class T>
KnotForm<T, Row<T>> u_curve(const SurfaceForm<T>& f) {
  KnotForm<T, Row<T>> c{f.p, f.U, std::vector<Row<T>>(f.rows)};
  const std::size_t w = f.cols * f.dim;
  for (std::size_t i = 0; i < f.rows; ++i) c.P[i].x.assign(f.P.begin() + static_cast<std::ptrdiff_t>(i * w), f.P.begin() + static_cast<std::ptrdiff_t>((i + 1) * w));
  return c;
}

/// The surface whose rows are the points of c, with f's v data.
template <class T>
SurfaceForm<T> from_u_curve(const SurfaceForm<T>& f, const KnotForm<T, Row<T>>& c) {
  SurfaceForm<T> g{c.p, f.q, c.U, f.V, c.P.size(), f.cols, f.dim, f.rational, {}};
  g.P.reserve(g.rows * g.cols * g.dim);
  for (const auto& r : c.P) g.P.insert(g.P.end(), r.x.begin(), r.x.end());
  return g;
}

/// Applies op (a function of the u curve of rows giving another) in `dir`: directly along
/// u, on the transposed grid along v.
template <class T, class Op>
SurfaceForm<T> along_homogeneous(const SurfaceForm<T>& h, Direction dir, Op&& op) {
  if (dir == Direction::u) return from_u_curve(h, op(u_curve(h)));
  const SurfaceForm<T> t = transposed(h);
  return transposed(from_u_curve(t, op(u_curve(t))));
}
template <class T, class Op>
SurfaceForm<T> along(const SurfaceForm<T>& f, Direction dir, Op&& op) {
  return weighted(along_homogeneous(weighted(f, true), dir, op), false);
}

/// Checks the data of a surface (the typed surfaces' constructors call it): degrees >= 0
/// ("degree[0]", "degree[1]"), at least p + 1 rows and q + 1 columns ("points"), the knot
/// rules of check_knots in each direction ("knots[0][i]", "knots[1][j]"), finite points
/// ("points[i][j][k]"), weights > 0 ("weights[i][j]").
template <class T>
void check_surface_form(const SurfaceForm<T>& f) {
  const auto check_direction = [](int deg, const std::vector<T>& K, std::size_t count, int d) {
    const std::string which = "[" + std::to_string(d) + "]";
    const char* noun = d == 0 ? "rows of points" : "columns of points";
    if (deg < 0) throw InvalidArgument("degree" + which, "a surface needs degrees >= 0, got " + std::to_string(deg));
    if (count < static_cast<std::size_t>(deg) + 1) {
      throw InvalidArgument("points", "degree " + std::to_string(deg) + " in " + (d == 0 ? "u" : "v") + " needs at least " +
                                          std::to_string(deg + 1) + " " + noun + ", got " + std::to_string(count));
    }
    if (K.size() != count + static_cast<std::size_t>(deg) + 1) {
      throw InvalidArgument("knots" + which, std::string("needs ") + (d == 0 ? "rows" : "columns") + " + degree + 1 = " +
                                                 std::to_string(count + static_cast<std::size_t>(deg) + 1) + " knots, got " +
                                                 std::to_string(K.size()));
    }
    try {
      check_knots<T>(K, deg);
    } catch (const InvalidArgument& e) {
      std::string w = e.where();
      if (w.rfind("knots", 0) == 0) w = "knots" + which + w.substr(5);
      else if (w == "degree") w = "degree" + which;
      throw InvalidArgument(w, e.problem());
    }
  };
  check_direction(f.p, f.U, f.rows, 0);
  check_direction(f.q, f.V, f.cols, 1);
  for (std::size_t i = 0; i < f.rows; ++i) {
    for (std::size_t j = 0; j < f.cols; ++j) {
      const T* x = f.at(i, j);
      const std::string ij = "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      if (f.rational && !(x[f.dim - 1] > 0 && std::isfinite(x[f.dim - 1]))) {
        throw InvalidArgument("weights" + ij, "weights must be finite and > 0, got " + format_number(x[f.dim - 1]));
      }
      for (std::size_t k = 0; k < f.dim; ++k) {
        if (!std::isfinite(x[k])) {
          throw InvalidArgument("points" + ij + "[" + std::to_string(k) + "]", "value must be finite");
        }
        if (f.rational && k + 1 < f.dim && !std::isfinite(x[k] * x[f.dim - 1])) {
          throw InvalidArgument("points" + ij + "[" + std::to_string(k) + "]", "the coordinate times its weight is not finite");
        }
      }
    }
  }
}

/// f with u inserted `times` times in direction dir (the curve rules: errors "knot",
/// "times").
template <class T>
SurfaceForm<T> insert_knot(const SurfaceForm<T>& f, Direction dir, T u, int times) {
  return along(f, dir, [&](const KnotForm<T, Row<T>>& c) { return insert_knot<T, Row<T>>(c, u, times); });
}

/// f with the sorted knots X inserted in direction dir (errors "knots[j]").
template <class T>
SurfaceForm<T> refine(const SurfaceForm<T>& f, Direction dir, std::span<const T> X) {
  return along(f, dir, [&](const KnotForm<T, Row<T>>& c) { return refine<T, Row<T>>(c, X); });
}

/// f elevated r >= 1 times in direction dir.
template <class T>
SurfaceForm<T> elevate(const SurfaceForm<T>& f, Direction dir, int r) {
  if (r < 1) throw InvalidArgument("times", "elevation count must be >= 1, got " + std::to_string(r));
  return along(f, dir, [&](const KnotForm<T, Row<T>>& c) { return elevate(c, r); });
}

/// The halves of f at t strictly inside the domain of direction dir (error "t"); both keep
/// their parameter.
template <class T>
std::pair<SurfaceForm<T>, SurfaceForm<T>> split(const SurfaceForm<T>& f, Direction dir, T t) {
  std::optional<KnotForm<T, Row<T>>> second;
  const SurfaceForm<T> h = weighted(f, true);
  SurfaceForm<T> first = along_homogeneous(h, dir, [&](const KnotForm<T, Row<T>>& c) {
    auto halves = split<T, Row<T>>(c, t);
    second = std::move(halves.second);
    return std::move(halves.first);
  });
  SurfaceForm<T> other = from_u_curve(dir == Direction::u ? h : transposed(h), *second);
  if (dir == Direction::v) other = transposed(other);
  return {weighted(std::move(first), false), weighted(std::move(other), false)};
}

/// The exact polynomial (or rational) pieces of f: breaks in u and in v (the domain's ends
/// and the distinct knots between), and patches[a][b] on [ubreaks[a], ubreaks[a+1]] x
/// [vbreaks[b], vbreaks[b+1]], each a Bézier patch (degrees p, q; its knots the patch's
/// interval, each end p + 1 resp. q + 1 times), by blossoming [Ramshaw87].
template <class T>
struct SurfacePatches {
  std::vector<T> ubreaks, vbreaks;
  std::vector<std::vector<SurfaceForm<T>>> patches;
};

template <class T>
std::vector<SurfaceForm<T>> u_pieces(const SurfaceForm<T>& f, std::vector<T>& breaks) {
  const KnotForm<T, Row<T>> c = u_curve(f);
  const std::span<const T> U(c.U);
  std::vector<SurfaceForm<T>> out;
  breaks.clear();
  for (const std::size_t s : nonempty_spans(U, c.p)) {
    KnotForm<T, Row<T>> b{c.p, std::vector<T>(static_cast<std::size_t>(c.p) + 1, U[s]), span_bezier_points<Row<T>, T>(U, c.p, s, c.P)};
    b.U.insert(b.U.end(), static_cast<std::size_t>(c.p) + 1, U[s + 1]);
    if (breaks.empty()) breaks.push_back(U[s]);
    breaks.push_back(U[s + 1]);
    out.push_back(from_u_curve(f, b));
  }
  return out;
}

template <class T>
SurfacePatches<T> patches(const SurfaceForm<T>& f) {
  SurfacePatches<T> r;
  for (const auto& strip : u_pieces(weighted(f, true), r.ubreaks)) {
    std::vector<SurfaceForm<T>> row;
    for (auto& piece : u_pieces(transposed(strip), r.vbreaks)) row.push_back(weighted(transposed(piece), false));
    r.patches.push_back(std::move(row));
  }
  return r;
}

/// The partial derivatives of f at (u, v) up to total order k, Cartesian: out[(a * (k + 1)
/// + b) * cd + c] = coordinate c of d^(a+b) S / du^a dv^b for a + b <= k (cd the Cartesian
/// dimension; entries with a + b > k are zero). [PT97] A3.6 on the (homogeneous) points,
/// then A4.4 for a rational surface. At a knot the right limit answers, at the domain's
/// end the last span, outside the domain the end patches extrapolate (find_span).
template <class T>
std::vector<T> partials(const SurfaceForm<T>& f, T u, T v, int k) {
  const std::size_t K = static_cast<std::size_t>(k) + 1, d = f.dim, cd = f.cartesian();
  const std::size_t su = find_span<T>(f.U, f.p, u), sv = find_span<T>(f.V, f.q, v);
  const auto Nu = basis_function_derivatives<T>(f.U, f.p, su, u, k);
  const auto Nv = basis_function_derivatives<T>(f.V, f.q, sv, v, k);
  const std::size_t P = static_cast<std::size_t>(f.p), Q = static_cast<std::size_t>(f.q);
  // A[a][b]: the homogeneous partials. temp[s]: the u-derivative of order a of column s.
  std::vector<T> A(K * K * d, T(0)), temp((Q + 1) * d);
  const std::size_t cw = f.rational ? cd : d;  // index of the weight (none: d)
  for (std::size_t a = 0; a < K; ++a) {
    if (a > P) break;  // higher u-derivatives of a degree-p polynomial vanish
    std::fill(temp.begin(), temp.end(), T(0));
    for (std::size_t s = 0; s <= Q; ++s)
      for (std::size_t r = 0; r <= P; ++r) {
        const T n = Nu[a][r];
        const T* x = f.at(su - P + r, sv - Q + s);
        const T nw = cw < d ? n * x[cw] : n;  // (w P, w) on the fly
        for (std::size_t c = 0; c < d; ++c) temp[s * d + c] += (c == cw ? n : nw) * x[c];
      }
    for (std::size_t b = 0; a + b < K; ++b) {
      if (b > Q) break;
      T* out = A.data() + (a * K + b) * d;
      for (std::size_t s = 0; s <= Q; ++s)
        for (std::size_t c = 0; c < d; ++c) out[c] += Nv[b][s] * temp[s * d + c];
    }
  }
  if (!f.rational) return A;
  if (!(A[cd] > 0)) {
    throw InvalidArgument("uv", "the rational surface has a pole at (" + format_number(u) + ", " + format_number(v) +
                                    ") (its weight function is " + format_number(A[cd]) + " there, outside the domain)");
  }
  // A4.4: S^(a,b) = (A^(a,b) - sum_(i,j) != (0,0), i <= a, j <= b  C(a,i) C(b,j) w^(i,j) S^(a-i,b-j)) / w.
  std::vector<T> S(K * K * cd, T(0));
  const auto w = [&](std::size_t a, std::size_t b) { return A[(a * K + b) * d + cd]; };
  for (std::size_t a = 0; a < K; ++a) {
    for (std::size_t b = 0; a + b < K; ++b) {
      T* s = S.data() + (a * K + b) * cd;
      const T* x = A.data() + (a * K + b) * d;
      for (std::size_t c = 0; c < cd; ++c) s[c] = x[c];
      for (std::size_t i = 0; i <= a; ++i) {
        const T ci = binomial<T>(static_cast<int>(a), static_cast<int>(i));
        for (std::size_t j = 0; j <= b; ++j) {
          if (i == 0 && j == 0) continue;
          const T c2 = ci * binomial<T>(static_cast<int>(b), static_cast<int>(j)) * w(i, j);
          if (c2 == 0) continue;
          const T* y = S.data() + ((a - i) * K + (b - j)) * cd;
          for (std::size_t c = 0; c < cd; ++c) s[c] -= c2 * y[c];
        }
      }
      const T w0 = w(0, 0);
      for (std::size_t c = 0; c < cd; ++c) s[c] /= w0;
    }
  }
  return S;
}

/// The point of f at (u, v), Cartesian (cd coordinates).
template <class T>
std::vector<T> point(const SurfaceForm<T>& f, T u, T v) {
  std::vector<T> x = partials(f, u, v, 0);
  x.resize(f.cartesian());
  return x;
}

/// Unit normal and curvatures at one point of a 3-D surface, from S_u, S_v, S_uu, S_uv,
/// S_vv: n = S_u x S_v / |S_u x S_v|, none where |S_u x S_v| <= 1e-12 |S_u| |S_v| or where
/// one of |S_u|, |S_v| is below 1e-12 of the other (rounding noise of a zero); with E,
/// F, G and L = S_uu . n, M = S_uv . n, N = S_vv . n: K = (LN - M^2) / (EG - F^2), H =
/// (EN - 2FM + GL) / (2 (EG - F^2)), k1,2 = H +- sqrt(H^2 - K) (H^2 - K < 0 only by
/// rounding: read as 0).
template <class T>
struct SurfaceGeometry {
  bool defined = false;
  T normal[3] = {0, 0, 0};
  T gaussian = 0, mean = 0, k1 = 0, k2 = 0;
};

template <class T>
SurfaceGeometry<T> geometry(const T* Su, const T* Sv, const T* Suu, const T* Suv, const T* Svv) {
  SurfaceGeometry<T> g;
  const T n[3] = {Su[1] * Sv[2] - Su[2] * Sv[1], Su[2] * Sv[0] - Su[0] * Sv[2], Su[0] * Sv[1] - Su[1] * Sv[0]};
  const auto dot = [](const T* a, const T* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const T len = std::sqrt(dot(n, n));
  const T E = dot(Su, Su), F = dot(Su, Sv), G = dot(Sv, Sv);
  if (!(len > T(1e-12) * std::sqrt(E) * std::sqrt(G))) return g;
  // A partial derivative below 1e-12 of the other is rounding noise of a zero one (a
  // rational surface's pole row: S_v = (A_v - w_v S) / w cancels to a few eps, not to
  // 0), so the normal is undefined there too.
  if (!(std::min(E, G) > T(1e-24) * std::max(E, G))) return g;
  g.defined = true;
  for (int c = 0; c < 3; ++c) g.normal[c] = n[c] / len;
  const T L = dot(Suu, g.normal), M = dot(Suv, g.normal), N = dot(Svv, g.normal);
  const T den = E * G - F * F;
  g.gaussian = (L * N - M * M) / den;
  g.mean = (E * N - 2 * F * M + G * L) / (2 * den);
  const T disc = std::sqrt(std::max(T(0), g.mean * g.mean - g.gaussian));
  g.k1 = g.mean + disc;
  g.k2 = g.mean - disc;
  return g;
}

/// The geometry of a 3-D surface at (u, v) (partials up to order 2).
template <class T>
SurfaceGeometry<T> geometry(const SurfaceForm<T>& f, T u, T v) {
  const std::vector<T> d = partials(f, u, v, 2);
  const auto at = [&](std::size_t a, std::size_t b) { return d.data() + (a * 3 + b) * 3; };
  return geometry<T>(at(1, 0), at(0, 1), at(2, 0), at(1, 1), at(0, 2));
}

/// The isocurve of f at `value` in direction dir: for u, the curve v -> S(value, v) (knots
/// V, degree q, points sum_i N_i(value) (w P)_ij in homogeneous form, written back as
/// point and weight); for v, u -> S(u, value).
/// Exact: the tensor product evaluated in one direction.
template <class T>
CurveForm<T> isocurve(const SurfaceForm<T>& f, Direction dir, T value) {
  const SurfaceForm<T> g = weighted(dir == Direction::u ? f : transposed(f), true);
  const std::size_t s = find_span<T>(g.U, g.p, value);
  std::vector<T> N(static_cast<std::size_t>(g.p) + 1);
  basis_functions<T>(g.U, g.p, s, value, N);
  CurveForm<T> c{g.q, g.V, g.dim, g.rational, std::vector<T>(g.cols * g.dim, T(0))};
  for (std::size_t r = 0; r <= static_cast<std::size_t>(g.p); ++r) {
    const T* row = g.at(s - static_cast<std::size_t>(g.p) + r, 0);
    for (std::size_t x = 0; x < g.cols * g.dim; ++x) c.P[x] += N[r] * row[x];
  }
  if (c.rational) {
    for (std::size_t i = 0; i < c.P.size(); i += c.dim)
      for (std::size_t k = 0; k + 1 < c.dim; ++k) c.P[i + k] /= c.P[i + c.dim - 1];
  }
  return c;
}

/// The limit normal of a 3-D surface at (u, v): the unit normal where it is defined (the
/// test of geometry()), else the limit of the unit normals of the nearby surface where
/// (u, v) lies on a degenerate edge and that limit exists; none otherwise.
///
/// A degenerate edge: the isocurve u = u0 (or v = v0) is one point over the knot spans
/// about (u, v) (every control point of those spans within 1e-12 of the net's size of the
/// first), as at a sphere's pole or a cone's apex. Along u = u0, S_v vanishes, and S_u x
/// S_v expands in t = u - u0 as sum_k t^k N_k(v) with N_k = (1/k!) d^k/du^k (S_u x S_v) =
/// (1/k!) sum_i C(k, i) S_(u^(i+1)) x S_(u^(k-i) v) (Leibniz; the i = k term has S_v = 0).
/// The first N_k not lost to cancellation (|N_k| > 1e-10 x the sum of the terms'
/// magnitudes; k <= 4) gives the direction sign(t)^k N_k / |N_k| as (u, v') is approached
/// from inside the domain (t > 0 at the domain's start, t < 0 at its end; at an interior
/// line both sides, which agree only for even k). On a sphere's pole k = 1: S_u x S_uv.
/// The normal of the surface has a limit at that point only if this direction is the same
/// for every v' along the degenerate edge: it is compared with the direction at v at
/// points of every span of the edge, more than the degree of N_k x n in v' (a polynomial
/// surface: 2q + 1 points per span, degree <= 2q - 1; a rational one: 8q + 1, the
/// numerator's degree <= (k + 4) q - 1), so that agreement within 1e-8 at those points
/// means the directions agree along the edge up to rounding. A cone's apex: the direction
/// turns with v', no limit. Likewise for v = v0 (S_u x S_v = -(S_v x S_u), the roles
/// exchanged); on a corner where both edges are degenerate, both limits must agree.
/// Accuracy: the direction comes from exact derivatives (A3.6, A4.4): a few eps divided
/// by the sine between the factors of N_k, as for the ordinary normal.
/// Elsewhere where S_u x S_v vanishes (an isolated singular point): none.
template <class T>
std::optional<std::array<T, 3>> limit_normal(const SurfaceForm<T>& f, T u, T v) {
  if (f.cartesian() != 3) throw InvalidArgument("normal", "normals need a 3-D surface, got " + std::to_string(f.cartesian()) + "-D");
  {
    const std::vector<T> d = partials(f, u, v, 1);
    const T *Su = d.data() + 2 * 3, *Sv = d.data() + 3;
    const SurfaceGeometry<T> g = geometry<T>(Su, Sv, Su, Su, Su);
    if (g.defined) return std::array<T, 3>{g.normal[0], g.normal[1], g.normal[2]};
  }
  T size = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    T lo = 0, hi = 0;
    for (std::size_t i = 0; i < f.rows * f.cols; ++i) {
      const T x = f.P[i * f.dim + c];
      lo = i == 0 ? x : std::min(lo, x);
      hi = i == 0 ? x : std::max(hi, x);
    }
    size = std::max({size, hi - lo, std::abs(lo), std::abs(hi)});
  }
  constexpr int kmax = 4;
  // The limit along the isocurve u = s of g (flip: g is f transposed): nullopt when (s, t)
  // is not on a degenerate edge, {false, ...} when it is and the limit does not exist.
  struct Edge {
    bool exists;
    std::array<T, 3> n;
  };
  const auto edge = [&](const SurfaceForm<T>& g, T s, T t, bool flip) -> std::optional<Edge> {
    const CurveForm<T> c = isocurve(g, Direction::u, s);
    const std::size_t q = static_cast<std::size_t>(g.q);
    const auto point_span = [&](std::size_t j) {
      const T* x0 = c.P.data() + (j - q) * c.dim;
      for (std::size_t i = j - q + 1; i <= j; ++i) {
        const T* x = c.P.data() + i * c.dim;
        const T e = std::hypot(x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]);
        if (!(e <= T(1e-12) * size)) return false;
      }
      return true;
    };
    const std::size_t sp = find_span<T>(c.U, g.q, t);
    if (!point_span(sp)) return std::nullopt;
    std::size_t lo = sp, hi = sp;
    while (lo > q && point_span(lo - 1)) --lo;
    while (hi + 1 < g.cols && point_span(hi + 1)) ++hi;
    const T s0 = g.U[static_cast<std::size_t>(g.p)], s1 = g.U[g.rows];
    const int side = s <= s0 ? 1 : s >= s1 ? -1 : 0;
    const std::size_t K = kmax + 2;
    const auto leading = [&](T tt) -> std::optional<std::array<T, 3>> {
      const std::vector<T> d = partials(g, s, tt, kmax + 1);
      const auto at = [&](std::size_t a, std::size_t b) { return d.data() + (a * K + b) * 3; };
      const auto norm = [](const T* x) { return std::hypot(x[0], x[1], x[2]); };
      for (std::size_t k = 1; k <= kmax; ++k) {
        T N[3] = {0, 0, 0}, mag = 0;
        for (std::size_t i = 0; i < k; ++i) {
          const T b = binomial<T>(static_cast<int>(k), static_cast<int>(i));
          const T *x = at(i + 1, 0), *y = at(k - i, 1);
          N[0] += b * (x[1] * y[2] - x[2] * y[1]);
          N[1] += b * (x[2] * y[0] - x[0] * y[2]);
          N[2] += b * (x[0] * y[1] - x[1] * y[0]);
          mag += b * norm(x) * norm(y);
        }
        const T len = norm(N);
        if (!(len > T(1e-10) * mag)) continue;
        if (side == 0 && k % 2 == 1) return std::nullopt;  // the two sides opposite
        const T sign = (side < 0 && k % 2 == 1) != flip ? T(-1) : T(1);
        return std::array<T, 3>{sign * N[0] / len, sign * N[1] / len, sign * N[2] / len};
      }
      return std::nullopt;
    };
    const auto ref = leading(t);
    if (!ref) return Edge{false, {}};
    const std::size_t m = f.rational ? 8 * q + 1 : 2 * q + 1;
    const T pi = std::acos(T(-1));
    for (std::size_t j = lo; j <= hi; ++j) {
      const T a = c.U[j], b = c.U[j + 1];
      if (!(a < b)) continue;
      for (std::size_t i = 0; i < m; ++i) {
        const T tt = a + (b - a) * (1 - std::cos(pi * (T(i) + T(0.5)) / T(m))) / 2;
        const auto n = leading(tt);
        if (!n || std::hypot((*n)[0] - (*ref)[0], (*n)[1] - (*ref)[1], (*n)[2] - (*ref)[2]) > T(1e-8)) return Edge{false, {}};
      }
    }
    return Edge{true, *ref};
  };
  std::optional<std::array<T, 3>> out;
  bool any = false;
  for (const bool along_u : {false, true}) {
    const auto e = along_u ? edge(transposed(f), v, u, true) : edge(f, u, v, false);
    if (!e) continue;
    if (!e->exists) return std::nullopt;
    if (any && std::hypot(e->n[0] - (*out)[0], e->n[1] - (*out)[1], e->n[2] - (*out)[2]) > T(1e-8)) return std::nullopt;
    any = true;
    out = e->n;
  }
  return out;
}

}  // namespace detail
}  // namespace casteljau
