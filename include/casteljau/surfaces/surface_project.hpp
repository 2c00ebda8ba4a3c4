// The guaranteed global closest point of a surface to a point (issue 19), written once on
// the run-time form (surfaces/surface_form.hpp).
//
// On each Bézier patch the squared distance f = |S - q|^2 is a ratio N / W of two
// tensor-product polynomials of degrees (2n, 2m) (N = |w (S - q)|^2, W = w^2), whose
// Bernstein coefficients are products of the patch's own [Farin, §5.10; PT97 §5.2]. Since
// W > 0, f >= min N_ij / W_ij on the patch (the coefficient ratios bound the ratio), and at
// the patch's corners f is exactly the corner ratio. Branch and bound, best first: the
// patch with the lowest bound is halved (de Casteljau at the middle, across the direction
// whose coefficient ratios vary more), its corners improve the best value found; a patch
// whose bound lies above the best value by more than the tie tolerance is discarded, and
// one whose ratios vary by less than the tolerance is settled (f is constant there to
// within it). The bound converges quadratically with the patch size, so around an
// isolated minimiser only a bounded number of patches survive each level. The settled
// patches, grouped where they touch, are the places the minimum is attained: each group
// is polished by a projected Newton iteration on the true surface (never increasing the
// distance), and a group spread over more than 1e-2 of the domain in u or v is a curve
// (or region) of minimisers (a sphere's centre, a point on the axis of a surface of
// revolution).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <queue>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/surfaces/surface_form.hpp"

namespace casteljau::detail {

/// A tensor-product Bernstein grid on the parameter rectangle [u0, u1] x [v0, v1]: (n + 1)
/// x (m + 1) coefficients of d values each (a curve: m = 0).
template <class T>
struct BernsteinGrid {
  int n = 0, m = 0;
  std::size_t d = 0;
  std::vector<T> c;
  T u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  [[nodiscard]] T* at(int i, int j) { return c.data() + (static_cast<std::size_t>(i) * static_cast<std::size_t>(m + 1) + static_cast<std::size_t>(j)) * d; }
  [[nodiscard]] const T* at(int i, int j) const {
    return c.data() + (static_cast<std::size_t>(i) * static_cast<std::size_t>(m + 1) + static_cast<std::size_t>(j)) * d;
  }
};

/// The halves of g at the middle of direction dir (de Casteljau at 1/2 along every line).
template <class T>
std::pair<BernsteinGrid<T>, BernsteinGrid<T>> halve(const BernsteinGrid<T>& g, Direction dir) {
  BernsteinGrid<T> a = g, b = g;
  const bool along_u = dir == Direction::u;
  const int len = along_u ? g.n : g.m, lines = along_u ? g.m + 1 : g.n + 1;
  const std::size_t d = g.d;
  std::vector<T> w(static_cast<std::size_t>(len + 1) * d);
  for (int l = 0; l < lines; ++l) {
    for (int k = 0; k <= len; ++k) std::copy_n(along_u ? g.at(k, l) : g.at(l, k), d, w.data() + static_cast<std::size_t>(k) * d);
    for (int r = 0; r <= len; ++r) {
      std::copy_n(w.data(), d, along_u ? a.at(r, l) : a.at(l, r));
      std::copy_n(w.data() + static_cast<std::size_t>(len - r) * d, d, along_u ? b.at(len - r, l) : b.at(l, len - r));
      for (std::size_t k = 0; k < static_cast<std::size_t>(len - r) * d; ++k) w[k] = (w[k] + w[k + d]) / 2;
    }
  }
  if (along_u) {
    const T mid = (g.u0 + g.u1) / 2;
    a.u1 = b.u0 = mid;
  } else {
    const T mid = (g.v0 + g.v1) / 2;
    a.v1 = b.v0 = mid;
  }
  return {std::move(a), std::move(b)};
}

/// Whether halving g across dir still gives a new parameter (the middle differs from
/// both ends).
template <class T>
bool can_halve(const BernsteinGrid<T>& g, Direction dir) {
  const T a = dir == Direction::u ? g.u0 : g.v0, b = dir == Direction::u ? g.u1 : g.v1;
  const T mid = (a + b) / 2;
  return mid > a && mid < b;
}

/// The Bernstein coefficients of the product of two scalar tensor-product polynomials of
/// degrees (n, m) (row-major (n + 1) x (m + 1)): degrees (2n, 2m),
/// c_IJ = sum a_ij b_(I-i)(J-j) C(n, i) C(n, I - i) / C(2n, I) x C(m, j) C(m, J - j) / C(2m, J).
template <class T>
std::vector<T> bernstein_tensor_product(const std::vector<T>& a, const std::vector<T>& b, int n, int m) {
  // On the scaled coefficients a_ij C(n, i) C(m, j) the product is a plain convolution.
  const std::vector<T> bn = binomial_row<T>(n), bm = binomial_row<T>(m), b2n = binomial_row<T>(2 * n), b2m = binomial_row<T>(2 * m);
  const std::size_t r = static_cast<std::size_t>(n) + 1, s = static_cast<std::size_t>(m) + 1, R = 2 * r - 1, S = 2 * s - 1;
  std::vector<T> x(r * s), y(r * s), c(R * S, T(0));
  for (std::size_t i = 0; i < r; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      x[i * s + j] = a[i * s + j] * bn[i] * bm[j];
      y[i * s + j] = b[i * s + j] * bn[i] * bm[j];
    }
  for (std::size_t i = 0; i < r; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const T xi = x[i * s + j];
      for (std::size_t k = 0; k < r; ++k) {
        T* out = c.data() + (i + k) * S + j;
        const T* yk = y.data() + k * s;
        for (std::size_t l = 0; l < s; ++l) out[l] += xi * yk[l];
      }
    }
  for (std::size_t I = 0; I < R; ++I)
    for (std::size_t J = 0; J < S; ++J) c[I * S + J] /= b2n[I] * b2m[J];
  return c;
}

/// The result of project_surface: the minimiser (u, v) (the smallest u, then v, among tied
/// isolated minimisers), the surface's point there and the distance; all_uv lists every
/// tied isolated minimiser (sorted by u, then v) when there are several; on_curve tells
/// that the minimum is attained along a curve (or a region) of the domain, (u, v) one of
/// its points and all_uv empty.
template <class T>
struct SurfaceProjection {
  T u = 0, v = 0;
  std::vector<T> point;
  T distance = 0;
  std::vector<std::array<T, 2>> all_uv;
  bool on_curve = false;
};

/// |a - b| over cd coordinates without overflow for finite coordinates.
template <class T>
T safe_distance(const T* a, const T* b, std::size_t cd) {
  T s = 0;
  for (std::size_t c = 0; c < cd; ++c) s = std::max(s, std::abs(a[c] / 2 - b[c] / 2));
  if (s == 0) return 0;
  T sum = 0;
  for (std::size_t c = 0; c < cd; ++c) {
    const T x = (a[c] / 2 - b[c] / 2) / s;
    sum += x * x;
  }
  return 2 * s * std::sqrt(sum);
}

/// A local minimum of |S - q| from (u, v) by projected Newton on |S - q|^2 / s^2 inside the
/// domain: a coordinate on the domain's edge whose gradient points outward is held there;
/// each step is halved until the distance does not grow. Returns the point reached (never
/// farther than the start).
template <class T>
std::array<T, 2> polish_projection(const SurfaceForm<T>& f, std::span<const T> q, T u, T v, T s) {
  const std::size_t cd = f.cartesian();
  const T ua = f.U[static_cast<std::size_t>(f.p)], ub = f.U[f.rows], va = f.V[static_cast<std::size_t>(f.q)], vb = f.V[f.cols];
  const auto value = [&](T x, T y) {
    const std::vector<T> S = point(f, x, y);
    T r = 0;
    for (std::size_t c = 0; c < cd; ++c) {
      const T e = (S[c] - q[c]) / s;
      r += e * e;
    }
    return r;
  };
  T fu = value(u, v);
  for (int it = 0; it < 60; ++it) {
    const std::vector<T> d = partials(f, u, v, 2);
    const auto at = [&](std::size_t a, std::size_t b) { return d.data() + (a * 3 + b) * cd; };
    T g[2] = {0, 0}, H[2][2] = {{0, 0}, {0, 0}};
    for (std::size_t c = 0; c < cd; ++c) {
      const T r = (at(0, 0)[c] - q[c]) / s, su = at(1, 0)[c] / s, sv = at(0, 1)[c] / s;
      g[0] += r * su;
      g[1] += r * sv;
      H[0][0] += su * su + r * at(2, 0)[c] / s;
      H[0][1] += su * sv + r * at(1, 1)[c] / s;
      H[1][1] += sv * sv + r * at(0, 2)[c] / s;
    }
    const bool free_u = !((u <= ua && g[0] > 0) || (u >= ub && g[0] < 0));
    const bool free_v = !((v <= va && g[1] > 0) || (v >= vb && g[1] < 0));
    T du = 0, dv = 0;
    if (free_u && free_v) {
      const T det = H[0][0] * H[1][1] - H[0][1] * H[0][1];
      if (!(H[0][0] > 0 && det > 0)) break;
      du = -(H[1][1] * g[0] - H[0][1] * g[1]) / det;
      dv = -(H[0][0] * g[1] - H[0][1] * g[0]) / det;
    } else if (free_u) {
      if (!(H[0][0] > 0)) break;
      du = -g[0] / H[0][0];
    } else if (free_v) {
      if (!(H[1][1] > 0)) break;
      dv = -g[1] / H[1][1];
    } else {
      break;
    }
    bool moved = false;
    T step = 1;
    for (int k = 0; k < 40; ++k, step /= 2) {
      const T nu = std::clamp(u + step * du, ua, ub), nv = std::clamp(v + step * dv, va, vb);
      const T fn = value(nu, nv);
      if (fn <= fu) {
        moved = nu != u || nv != v;
        u = nu;
        v = nv;
        fu = fn;
        break;
      }
    }
    if (!moved) break;
  }
  return {u, v};
}

/// The guaranteed global minimum of |S(u, v) - q| over the domain (q: cd coordinates).
/// Distances within 1e-12 relative (plus the coordinates' rounding) tie. Throws
/// NumericalError when more than max_splits halvings would be needed.
template <class T>
SurfaceProjection<T> project_surface(const SurfaceForm<T>& f, std::span<const T> q, std::size_t max_splits = 200000) {
  const std::size_t cd = f.cartesian();
  const SurfacePatches<T> sp = patches(f);
  const T ua = f.U[static_cast<std::size_t>(f.p)], ub = f.U[f.rows], va = f.V[static_cast<std::size_t>(f.q)], vb = f.V[f.cols];
  const T eps = std::numeric_limits<T>::epsilon();
  // Scales: s the largest coordinate of a control point minus q (f is computed on (S - q)
  // / s, at most 1 per coordinate on the control net), mag the largest coordinate.
  T s = 0, mag = 0, wmax = 0, wmin = std::numeric_limits<T>::infinity();
  for (std::size_t i = 0; i < f.rows; ++i)
    for (std::size_t j = 0; j < f.cols; ++j) {
      const T* x = f.at(i, j);
      for (std::size_t c = 0; c < cd; ++c) {
        s = std::max(s, std::abs(x[c] / 2 - q[c] / 2));
        mag = std::max({mag, std::abs(x[c]), std::abs(q[c])});
      }
      const T w = f.rational ? x[cd] : T(1);
      wmax = std::max(wmax, w);
      wmin = std::min(wmin, w);
    }
  s *= 2;
  SurfaceProjection<T> out;
  const auto finish_at = [&](T u, T v) {
    out.u = u;
    out.v = v;
    out.point = point(f, u, v);
    out.distance = safe_distance(out.point.data(), q.data(), cd);
  };
  if (s == 0) {  // every control point is q: the surface is the point q
    out.on_curve = true;
    finish_at(ua, va);
    return out;
  }
  const int n = f.p, m = f.q;
  // The rounding of the coefficient ratios (sums of O(n + m) products of numbers <= 1 per
  // coordinate, divided by W_ij >= (wmin / wmax)^2), and of the coordinates' translation
  // by q (relative eps of mag / s on each distance).
  const T rnd_f = 8 * static_cast<T>(n + m + 2) * static_cast<T>(cd) * eps * (wmax / wmin) * (wmax / wmin);
  const T floor_d = 8 * eps * (1 + mag / s);
  const auto tie_f = [&](T best) {
    const T d = std::sqrt(std::max(best, T(0)));
    const T delta = T(1e-12) * d + floor_d;
    return 2 * d * delta + delta * delta + rnd_f;
  };
  struct Item {
    BernsteinGrid<T> g;  ///< d = 2: (N, W)
    T lb;
  };
  std::vector<Item> items;
  T best = std::numeric_limits<T>::infinity();
  T best_u = ua, best_v = va;
  const auto ratio = [](const T* x) { return x[0] / x[1]; };
  // Bound, corners and coefficient spread of a grid.
  const auto examine = [&](BernsteinGrid<T>&& g) {
    T lb = std::numeric_limits<T>::infinity();
    for (std::size_t k = 0; k < g.c.size(); k += 2) lb = std::min(lb, g.c[k] / g.c[k + 1]);
    for (const int i : {0, g.n})
      for (const int j : {0, g.m}) {
        const T val = ratio(g.at(i, j));
        if (val < best) {
          best = val;
          best_u = i == 0 ? g.u0 : g.u1;
          best_v = j == 0 ? g.v0 : g.v1;
        }
      }
    items.push_back({std::move(g), lb});
    return items.size() - 1;
  };
  using Entry = std::pair<T, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t a = 0; a + 1 < sp.ubreaks.size(); ++a) {
    for (std::size_t b = 0; b + 1 < sp.vbreaks.size(); ++b) {
      const SurfaceForm<T>& p = sp.patches[a][b];
      const std::size_t cells = static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(m + 1);
      std::vector<T> W(cells);
      std::vector<std::vector<T>> Y(cd, std::vector<T>(cells));
      for (std::size_t i = 0; i < p.rows; ++i)
        for (std::size_t j = 0; j < p.cols; ++j) {
          const T* x = p.at(i, j);
          const T w = (p.rational ? x[cd] : T(1)) / wmax;
          W[i * p.cols + j] = w;
          for (std::size_t c = 0; c < cd; ++c) Y[c][i * p.cols + j] = w * ((x[c] - q[c]) / s);
        }
      BernsteinGrid<T> g{2 * n, 2 * m, 2, {}, sp.ubreaks[a], sp.ubreaks[a + 1], sp.vbreaks[b], sp.vbreaks[b + 1]};
      std::vector<T> N;
      for (std::size_t c = 0; c < cd; ++c) {
        const std::vector<T> yy = bernstein_tensor_product(Y[c], Y[c], n, m);
        if (N.empty()) N = yy;
        else
          for (std::size_t k = 0; k < N.size(); ++k) N[k] += yy[k];
      }
      const std::vector<T> WW = bernstein_tensor_product(W, W, n, m);
      g.c.resize(2 * N.size());
      for (std::size_t k = 0; k < N.size(); ++k) {
        g.c[2 * k] = N[k];
        g.c[2 * k + 1] = WW[k];
      }
      const std::size_t id = examine(std::move(g));
      queue.push({items[id].lb, id});
    }
  }
  struct Settled {
    T u0, u1, v0, v1;
    T lb;
  };
  std::vector<Settled> settled;
  std::size_t splits = 0;
  while (!queue.empty()) {
    const auto [lb, id] = queue.top();
    queue.pop();
    if (lb > best + tie_f(best)) break;  // this one and every one left lie farther
    BernsteinGrid<T> g = std::move(items[id].g);
    // The spread of the coefficient ratios along u and along v.
    T lo = std::numeric_limits<T>::infinity(), hi = -lo, du = 0, dv = 0;
    for (int i = 0; i <= g.n; ++i)
      for (int j = 0; j <= g.m; ++j) {
        const T r = ratio(g.at(i, j));
        lo = std::min(lo, r);
        hi = std::max(hi, r);
        if (i > 0) du = std::max(du, std::abs(r - ratio(g.at(i - 1, j))));
        if (j > 0) dv = std::max(dv, std::abs(r - ratio(g.at(i, j - 1))));
      }
    Direction dir = du >= dv ? Direction::u : Direction::v;
    if (!can_halve(g, dir)) dir = dir == Direction::u ? Direction::v : Direction::u;
    if (hi - lo <= tie_f(best) || !can_halve(g, dir)) {
      settled.push_back({g.u0, g.u1, g.v0, g.v1, lb});
      continue;
    }
    if (++splits > max_splits) {
      throw NumericalError("the closest point did not settle within " + std::to_string(max_splits) +
                           " patch subdivisions (a surface with many near-equal local minima)");
    }
    auto [a, b] = halve(g, dir);
    for (auto* h : {&a, &b}) {
      const std::size_t k = examine(std::move(*h));
      queue.push({items[k].lb, k});
    }
  }
  // The groups of settled patches that can hold the minimum (touching rectangles).
  const T tie = tie_f(best);
  std::vector<Settled> keep;
  for (const auto& x : settled)
    if (x.lb <= best + tie) keep.push_back(x);
  std::vector<std::size_t> parent(keep.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < keep.size(); ++i)
    for (std::size_t j = i + 1; j < keep.size(); ++j) {
      const Settled &a = keep[i], &b = keep[j];
      if (a.u0 <= b.u1 && b.u0 <= a.u1 && a.v0 <= b.v1 && b.v0 <= a.v1) parent[root(i)] = root(j);
    }
  struct Group {
    T u0, u1, v0, v1;
    T su, sv;  ///< the start: the centre of the group's lowest patch
    T lb;
  };
  std::vector<Group> groups;
  std::vector<std::size_t> group_of(keep.size(), std::size_t(-1));
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const std::size_t r = root(i);
    if (group_of[r] == std::size_t(-1)) {
      group_of[r] = groups.size();
      groups.push_back({keep[i].u0, keep[i].u1, keep[i].v0, keep[i].v1, (keep[i].u0 + keep[i].u1) / 2, (keep[i].v0 + keep[i].v1) / 2, keep[i].lb});
    }
    Group& g = groups[group_of[r]];
    g.u0 = std::min(g.u0, keep[i].u0);
    g.u1 = std::max(g.u1, keep[i].u1);
    g.v0 = std::min(g.v0, keep[i].v0);
    g.v1 = std::max(g.v1, keep[i].v1);
    if (keep[i].lb < g.lb) {
      g.lb = keep[i].lb;
      g.su = (keep[i].u0 + keep[i].u1) / 2;
      g.sv = (keep[i].v0 + keep[i].v1) / 2;
    }
  }
  const T lu = ub - ua, lv = vb - va;
  for (const auto& g : groups) {
    if ((lu > 0 && g.u1 - g.u0 > T(1e-2) * lu) || (lv > 0 && g.v1 - g.v0 > T(1e-2) * lv)) out.on_curve = true;
  }
  // Polish each group's start, and the best corner found (never worse than the bound).
  struct Candidate {
    T u, v, d;
  };
  std::vector<Candidate> cands;
  const auto candidate = [&](T u, T v) {
    const auto [pu, pv] = polish_projection(f, q, u, v, s);
    const std::vector<T> x = point(f, pu, pv);
    return Candidate{pu, pv, safe_distance(x.data(), q.data(), cd)};
  };
  const Candidate corner = candidate(best_u, best_v);
  if (out.on_curve || groups.empty()) {
    Candidate c = corner;
    for (const auto& g : groups) {
      const Candidate x = candidate(g.su, g.sv);
      if (x.d < c.d) c = x;
    }
    finish_at(c.u, c.v);
    return out;
  }
  for (const auto& g : groups) {
    Candidate x = candidate(g.su, g.sv);
    // The best corner, when it lies in this group, may be the better start.
    if (best_u >= g.u0 && best_u <= g.u1 && best_v >= g.v0 && best_v <= g.v1 && corner.d < x.d) x = corner;
    cands.push_back(x);
  }
  T dmin = corner.d;
  for (const auto& c : cands) dmin = std::min(dmin, c.d);
  const T dtie = T(1e-12) * dmin + 16 * eps * std::max(mag, s);
  std::vector<Candidate> tied;
  for (const auto& c : cands)
    if (c.d <= dmin + dtie) tied.push_back(c);
  if (tied.empty()) tied.push_back(corner);
  std::sort(tied.begin(), tied.end(), [](const Candidate& a, const Candidate& b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
  finish_at(tied.front().u, tied.front().v);
  if (tied.size() > 1)
    for (const auto& c : tied) out.all_uv.push_back({c.u, c.v});
  return out;
}

}  // namespace casteljau::detail
