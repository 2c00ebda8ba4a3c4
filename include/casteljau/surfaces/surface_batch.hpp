// Batch evaluation of surface points (issue 19, workload W7), on the run-time form
// (surfaces/surface_form.hpp):
// - evaluate_grid: S(u_k, v_l) on a tensor-product grid, u outer. Each v's span and basis
//   functions are computed once; for each u, its p + 1 rows are blended once into one
//   "column curve" (the isocurve's homogeneous points, the rows' span only), so that each
//   grid point costs q + 1 blends of that curve: O(q d) per point instead of O(p q d).
// - evaluate_points: S(u, v) at scattered pairs, without allocating per point.
// evaluate_points gives exactly the values of partials(f, u, v, 0) (the same operations in
// the same order: the basis by [PT97] A2.2, the row sums first, homogeneous weights
// applied as (N_i w) x), so callers may use it in place of it; evaluate_grid too (for a
// rational 3-D surface only when asked: by default it takes the quotient by one reciprocal,
// within an ulp).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/surfaces/surface_form.hpp"

namespace casteljau::detail {

/// The p + 1 basis functions of span s at u into N, by the same arithmetic as
/// basis_functions (left, right: scratch of p + 1).
template <class T>
inline void basis_into(const T* U, int p, std::size_t s, T u, T* N, T* left, T* right) {
  N[0] = 1;
  for (int j = 1; j <= p; ++j) {
    const std::size_t J = static_cast<std::size_t>(j);
    left[J] = u - U[s + 1 - J];
    right[J] = U[s + J] - u;
    T saved = 0;
    for (int r = 0; r < j; ++r) {
      const std::size_t R = static_cast<std::size_t>(r);
      const T temp = N[R] / (right[R + 1] + left[J - R]);
      N[R] = saved + right[R + 1] * temp;
      saved = left[J - R] * temp;
    }
    N[J] = saved;
  }
}

/// The error of a rational surface's pole at the k-th pair (the message of partials).
template <class T>
[[noreturn]] void surface_pole(std::size_t k, T u, T v, T w) {
  throw InvalidArgument("uv[" + std::to_string(k) + "]", "the rational surface has a pole at (" + format_number(u) + ", " + format_number(v) +
                                                             ") (its weight function is " + format_number(w) + " there, outside the domain)");
}

namespace batch {

/// out (cd values) from the homogeneous sums x (d values).
template <class T>
inline void finish_point(const SurfaceForm<T>& f, const T* x, T* out, std::size_t k, T u, T v) {
  const std::size_t cd = f.cartesian();
  if (!f.rational) {
    for (std::size_t c = 0; c < cd; ++c) out[c] = x[c];
    return;
  }
  const T w = x[cd];
  if (!(w > 0)) surface_pole(k, u, v, w);
  for (std::size_t c = 0; c < cd; ++c) out[c] = x[c] / w;
}

/// Columns j0 .. j0 + count - 1 of the u-blend of rows su - p .. su: C_j = sum_r (N_r w_rj)
/// x_rj (homogeneous, d values per column).
template <class T>
inline void blend_rows(const SurfaceForm<T>& f, std::size_t su, const T* Nu, std::size_t j0, std::size_t count, T* C) {
  const std::size_t d = f.dim, cd = f.cartesian(), P = static_cast<std::size_t>(f.p);
  std::fill(C, C + count * d, T(0));
  for (std::size_t j = 0; j < count; ++j) {
    T* out = C + j * d;
    for (std::size_t r = 0; r <= P; ++r) {
      const T n = Nu[r];
      const T* x = f.at(su - P + r, j0 + j);
      if (f.rational) {
        const T nw = n * x[cd];
        for (std::size_t c = 0; c < cd; ++c) out[c] += nw * x[c];
        out[cd] += n * x[cd];
      } else {
        for (std::size_t c = 0; c < d; ++c) out[c] += n * x[c];
      }
    }
  }
}

/// find_span for many parameters of one knot vector: the first and last non-empty spans
/// found once, then a branchless binary search (the last knot <= u in [U_p, U_last]):
/// random parameters make the branches of a plain binary search unpredictable. The same
/// span as find_span.
template <class T>
struct SpanFinder {
  const T* U;
  std::size_t lo, first, last;
  SpanFinder(const std::vector<T>& knots, int p) : U(knots.data()), lo(static_cast<std::size_t>(p)) {
    const std::size_t n = knots.size() - lo - 1;
    last = n - 1;
    while (last > lo && !(U[last] < U[last + 1])) --last;
    first = lo;
    while (first < last && !(U[first] < U[first + 1])) ++first;
  }
  [[nodiscard]] std::size_t operator()(T u) const {
    if (u >= U[last]) return last;
    if (!(u > U[lo])) return first;
    const T* base = U + lo;
    std::size_t len = last - lo + 1;
    while (len > 1) {
      const std::size_t half = len / 2;
      base = base[half] <= u ? base + half : base;
      len -= half;
    }
    return static_cast<std::size_t>(base - U);
  }
};

/// evaluate_points for 3-D surfaces of degrees (P, Q) known at compile time (R: rational):
/// the same operations as the general loop, unrolled, without scratch vectors.
template <class T, int P, int Q, bool R>
void points_3d(const SurfaceForm<T>& f, std::span<const std::array<T, 2>> uv, T* out) {
  constexpr std::size_t D = R ? 4 : 3;
  const std::size_t cols = f.cols;
  const T* base = f.P.data();
  const SpanFinder<T> span_u(f.U, P), span_v(f.V, Q);
  for (std::size_t k = 0; k < uv.size(); ++k) {
    const T u = uv[k][0], v = uv[k][1];
    const std::size_t su = span_u(u), sv = span_v(v);
    T Nu[P + 1], Nv[Q + 1], left[4], right[4];
    basis_into(f.U.data(), P, su, u, Nu, left, right);
    basis_into(f.V.data(), Q, sv, v, Nv, left, right);
    T x[D] = {};
    for (int s = 0; s <= Q; ++s) {
      T t[D] = {};
      for (int r = 0; r <= P; ++r) {
        const T* p = base + ((su - P + static_cast<std::size_t>(r)) * cols + sv - Q + static_cast<std::size_t>(s)) * D;
        const T n = Nu[r];
        if constexpr (R) {
          const T nw = n * p[3];
          t[0] += nw * p[0];
          t[1] += nw * p[1];
          t[2] += nw * p[2];
          t[3] += n * p[3];
        } else {
          t[0] += n * p[0];
          t[1] += n * p[1];
          t[2] += n * p[2];
        }
      }
      for (std::size_t c = 0; c < D; ++c) x[c] += Nv[s] * t[c];
    }
    if constexpr (R) {
      if (!(x[3] > 0)) surface_pole(k, u, v, x[3]);
      for (std::size_t c = 0; c < 3; ++c) out[3 * k + c] = x[c] / x[3];
    } else {
      for (std::size_t c = 0; c < 3; ++c) out[3 * k + c] = x[c];
    }
  }
}

/// One row of evaluate_grid for a 3-D surface of degree Q in v (R: rational): the blend of
/// the row's column curve C at each v, unrolled.
template <class T, int Q, bool R, bool Exact>
void grid_row_3d(const T* C, const T* Nv, const std::size_t* sv, std::size_t nv, T* row, std::size_t k, T u, std::span<const T> vs) {
  constexpr std::size_t D = R ? 4 : 3;
  for (std::size_t l = 0; l < nv; ++l) {
    const T* N = Nv + l * (Q + 1);
    const T* c0 = C + (sv[l] - Q) * D;
    T x[D] = {};
    for (int s = 0; s <= Q; ++s)
      for (std::size_t c = 0; c < D; ++c) x[c] += N[s] * c0[static_cast<std::size_t>(s) * D + c];
    if constexpr (R) {
      if (!(x[3] > 0)) surface_pole(k * nv + l, u, vs[l], x[3]);
      if constexpr (Exact) {
        for (std::size_t c = 0; c < 3; ++c) row[3 * l + c] = x[c] / x[3];
      } else {
        // One division per point (the quotient within an ulp of partials' x / w).
        const T iw = 1 / x[3];
        for (std::size_t c = 0; c < 3; ++c) row[3 * l + c] = x[c] * iw;
      }
    } else {
      for (std::size_t c = 0; c < 3; ++c) row[3 * l + c] = x[c];
    }
  }
}

/// points_3d for the degrees 1..3 in each direction; false for any other surface.
template <class T>
bool points_3d_dispatch(const SurfaceForm<T>& f, std::span<const std::array<T, 2>> uv, T* out) {
  if (f.cartesian() != 3 || f.p < 1 || f.p > 3 || f.q < 1 || f.q > 3) return false;
  const auto go = [&]<int P, int Q>() {
    if (f.rational) points_3d<T, P, Q, true>(f, uv, out);
    else points_3d<T, P, Q, false>(f, uv, out);
  };
  switch (f.p * 4 + f.q) {
    case 5: go.template operator()<1, 1>(); break;
    case 6: go.template operator()<1, 2>(); break;
    case 7: go.template operator()<1, 3>(); break;
    case 9: go.template operator()<2, 1>(); break;
    case 10: go.template operator()<2, 2>(); break;
    case 11: go.template operator()<2, 3>(); break;
    case 13: go.template operator()<3, 1>(); break;
    case 14: go.template operator()<3, 2>(); break;
    default: go.template operator()<3, 3>(); break;
  }
  return true;
}

}  // namespace batch

/// S at every (us[k], vs[l]), u outer: out[(k * vs.size() + l) * cd + c] (cd the Cartesian
/// dimension). Throws InvalidArgument("uv[k * vs.size() + l]") at a rational surface's pole.
/// exact: a rational 3-D surface's quotient by division (partials' values exactly), else
/// by one reciprocal per point (within an ulp of them).
template <class T>
void evaluate_grid(const SurfaceForm<T>& f, std::span<const T> us, std::span<const T> vs, T* out, bool exact = false) {
  const std::size_t d = f.dim, cd = f.cartesian(), P = static_cast<std::size_t>(f.p), Q = static_cast<std::size_t>(f.q);
  const std::size_t nv = vs.size();
  std::vector<std::size_t> sv(nv);
  std::vector<T> Nv(nv * (Q + 1)), left(std::max(P, Q) + 1), right(std::max(P, Q) + 1), Nu(P + 1), C(f.cols * d), x(d);
  for (std::size_t l = 0; l < nv; ++l) {
    sv[l] = find_span<T>(f.V, f.q, vs[l]);
    basis_into(f.V.data(), f.q, sv[l], vs[l], Nv.data() + l * (Q + 1), left.data(), right.data());
  }
  for (std::size_t k = 0; k < us.size(); ++k) {
    const std::size_t su = find_span<T>(f.U, f.p, us[k]);
    basis_into(f.U.data(), f.p, su, us[k], Nu.data(), left.data(), right.data());
    batch::blend_rows(f, su, Nu.data(), 0, f.cols, C.data());
    T* row = out + k * nv * cd;
    if (d == (f.rational ? 4u : 3u) && f.cartesian() == 3 && Q >= 1 && Q <= 3) {
      const auto go = [&]<int QQ>() {
        if (!f.rational) batch::grid_row_3d<T, QQ, false, true>(C.data(), Nv.data(), sv.data(), nv, row, k, us[k], vs);
        else if (exact) batch::grid_row_3d<T, QQ, true, true>(C.data(), Nv.data(), sv.data(), nv, row, k, us[k], vs);
        else batch::grid_row_3d<T, QQ, true, false>(C.data(), Nv.data(), sv.data(), nv, row, k, us[k], vs);
      };
      if (Q == 1) go.template operator()<1>();
      else if (Q == 2) go.template operator()<2>();
      else go.template operator()<3>();
      continue;
    }
    for (std::size_t l = 0; l < nv; ++l) {
      const T* N = Nv.data() + l * (Q + 1);
      const T* c0 = C.data() + (sv[l] - Q) * d;
      std::fill(x.begin(), x.end(), T(0));
      for (std::size_t s = 0; s <= Q; ++s)
        for (std::size_t c = 0; c < d; ++c) x[c] += N[s] * c0[s * d + c];
      batch::finish_point(f, x.data(), row + l * cd, k * nv + l, us[k], vs[l]);
    }
  }
}

/// S at each pair uv[k] (k = 0..n - 1, u then v): out[k * cd + c]. Throws
/// InvalidArgument("uv[k]") at a rational surface's pole.
template <class T>
void evaluate_points(const SurfaceForm<T>& f, std::span<const std::array<T, 2>> uv, T* out) {
  if (batch::points_3d_dispatch(f, uv, out)) return;
  const std::size_t d = f.dim, cd = f.cartesian(), P = static_cast<std::size_t>(f.p), Q = static_cast<std::size_t>(f.q);
  std::vector<T> left(std::max(P, Q) + 1), right(std::max(P, Q) + 1), Nu(P + 1), Nv(Q + 1), C((Q + 1) * d), x(d);
  const batch::SpanFinder<T> span_u(f.U, f.p), span_v(f.V, f.q);
  for (std::size_t k = 0; k < uv.size(); ++k) {
    const T u = uv[k][0], v = uv[k][1];
    const std::size_t su = span_u(u), sv = span_v(v);
    basis_into(f.U.data(), f.p, su, u, Nu.data(), left.data(), right.data());
    basis_into(f.V.data(), f.q, sv, v, Nv.data(), left.data(), right.data());
    batch::blend_rows(f, su, Nu.data(), sv - Q, Q + 1, C.data());
    std::fill(x.begin(), x.end(), T(0));
    for (std::size_t s = 0; s <= Q; ++s)
      for (std::size_t c = 0; c < d; ++c) x[c] += Nv[s] * C[s * d + c];
    batch::finish_point(f, x.data(), out + k * cd, k, u, v);
  }
}

}  // namespace casteljau::detail
