// The intersections of a 3-D curve with a 3-D surface (issue 19), written once on the
// run-time forms (surfaces/surface_form.hpp): crossings and tangent touches, and the
// parameter intervals where the curve lies on the surface.
//
// Subdivision on the exact Bézier pieces of both (homogeneous control points, de Casteljau
// at the middle): a curve piece and a patch whose control boxes do not overlap cannot
// meet (weights > 0: each lies in the box of its Cartesian control points). Of an
// overlapping pair the larger is halved (a patch in both directions), until both are below
// 1e-4 of the size of the data; then damped Newton (Levenberg-Marquardt) on C(t) - S(u, v)
// = 0 from the pair's centre, inside both domains, accepts the points where the two meet to
// 1e-9 of the size. A curve piece between 1e-3 and 1e-2 of the size whose 9 sample points
// all lie on the surface (a local projection to within 1e-13 of the size, or the rounding
// of the coordinates) lies on it: an overlap (shorter ones are not seen as such);
// the overlaps' ends are refined by bisection. Points found twice (a piece boundary, a
// seam of a closed surface) are merged, and so are solutions between which the curve stays
// on the surface to 1e-9 of the size (a touch of high order: one tangent point); a point
// is tangent where the curve's unit tangent makes an angle below 1e-6 with the surface's
// tangent plane.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "casteljau/core/error.hpp"
#include "casteljau/surfaces/surface_form.hpp"
#include "casteljau/surfaces/surface_project.hpp"

namespace casteljau::detail {

/// One intersection: the curve's parameter t, the surface's (u, v), the curve's point.
template <class T>
struct CurveSurfaceHit {
  T t, u, v;
  std::array<T, 3> point;
  bool tangent;
};

template <class T>
struct CurveSurfaceIntersection {
  std::vector<CurveSurfaceHit<T>> hits;        ///< sorted by t, none inside an overlap
  std::vector<std::array<T, 2>> overlaps;      ///< [t0, t1] where the curve lies on the surface
};

/// The homogeneous Bernstein grid (w x, w) of a Bézier patch form (x Cartesian, w its
/// weight or 1) on the rectangle [u0, u1] x [v0, v1].
template <class T>
BernsteinGrid<T> homogeneous_grid(const SurfaceForm<T>& p, T u0, T u1, T v0, T v1) {
  const std::size_t cd = p.cartesian();
  BernsteinGrid<T> g{static_cast<int>(p.rows) - 1, static_cast<int>(p.cols) - 1, cd + 1, {}, u0, u1, v0, v1};
  g.c.reserve(p.rows * p.cols * (cd + 1));
  for (std::size_t i = 0; i < p.rows; ++i)
    for (std::size_t j = 0; j < p.cols; ++j) {
      const T* x = p.at(i, j);
      const T w = p.rational ? x[cd] : T(1);
      for (std::size_t c = 0; c < cd; ++c) g.c.push_back(w * x[c]);
      g.c.push_back(w);
    }
  return g;
}

/// The box of a homogeneous grid's Cartesian points (3-D) and its diagonal.
template <class T>
struct Box3 {
  std::array<T, 3> lo, hi;
  [[nodiscard]] T diagonal() const { return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]); }
  [[nodiscard]] bool meets(const Box3& o, T slack) const {
    for (int c = 0; c < 3; ++c)
      if (lo[c] > o.hi[c] + slack || o.lo[c] > hi[c] + slack) return false;
    return true;
  }
};

template <class T>
Box3<T> box_of(const BernsteinGrid<T>& g) {
  Box3<T> b;
  b.lo.fill(std::numeric_limits<T>::infinity());
  b.hi.fill(-std::numeric_limits<T>::infinity());
  for (std::size_t k = 0; k < g.c.size(); k += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      const T x = g.c[k + c] / g.c[k + 3];
      b.lo[c] = std::min(b.lo[c], x);
      b.hi[c] = std::max(b.hi[c], x);
    }
  return b;
}

/// The largest distance between neighbouring Cartesian control points of a homogeneous
/// grid along u and along v.
template <class T>
std::array<T, 2> net_spans(const BernsteinGrid<T>& g) {
  T su = 0, sv = 0;
  const auto dist = [](const T* a, const T* b) {
    return std::hypot(a[0] / a[3] - b[0] / b[3], a[1] / a[3] - b[1] / b[3], a[2] / a[3] - b[2] / b[3]);
  };
  for (int i = 0; i <= g.n; ++i)
    for (int j = 0; j <= g.m; ++j) {
      if (i > 0) su = std::max(su, dist(g.at(i, j), g.at(i - 1, j)));
      if (j > 0) sv = std::max(sv, dist(g.at(i, j), g.at(i, j - 1)));
    }
  return {su, sv};
}

/// The intersections of the curve c (a B-spline form seen as a surface of one column:
/// its parameter is u) with the surface f, both 3-D. Throws NumericalError past max_pairs
/// examined pairs.
template <class T>
CurveSurfaceIntersection<T> intersect_curve_surface(const SurfaceForm<T>& f, const SurfaceForm<T>& c, std::size_t max_pairs = 2'000'000) {
  const SurfacePatches<T> sp = patches(f), cp = patches(c);
  const T ua = f.U[static_cast<std::size_t>(f.p)], ub = f.U[f.rows], va = f.V[static_cast<std::size_t>(f.q)], vb = f.V[f.cols];
  const T ta = c.U[static_cast<std::size_t>(c.p)], tb = c.U[c.rows];
  std::vector<BernsteinGrid<T>> all_patches, pieces;
  for (std::size_t a = 0; a + 1 < sp.ubreaks.size(); ++a)
    for (std::size_t b = 0; b + 1 < sp.vbreaks.size(); ++b)
      all_patches.push_back(homogeneous_grid(sp.patches[a][b], sp.ubreaks[a], sp.ubreaks[a + 1], sp.vbreaks[b], sp.vbreaks[b + 1]));
  for (std::size_t a = 0; a + 1 < cp.ubreaks.size(); ++a)
    pieces.push_back(homogeneous_grid(cp.patches[a][0], cp.ubreaks[a], cp.ubreaks[a + 1], T(0), T(1)));
  // The size of the data: the diagonal of the box of every control point.
  Box3<T> all = box_of(all_patches.front());
  for (const auto* set : {&all_patches, &pieces})
    for (const auto& g : *set) {
      const Box3<T> b = box_of(g);
      for (int k = 0; k < 3; ++k) {
        all.lo[k] = std::min(all.lo[k], b.lo[k]);
        all.hi[k] = std::max(all.hi[k], b.hi[k]);
      }
    }
  const T eps = std::numeric_limits<T>::epsilon();
  T scale = all.diagonal();
  T mag = 0;
  for (int k = 0; k < 3; ++k) mag = std::max({mag, std::abs(all.lo[k]), std::abs(all.hi[k])});
  scale = std::max(scale, 64 * eps * mag);
  if (!(scale > 0)) scale = 1;  // everything at the origin
  // on_tol: a point on the surface to the rounding of the data (looser, a touch of high
  // order would pass for an overlap along its flat contact).
  const T slack = T(1e-10) * scale, leaf = T(1e-4) * scale, hit_tol = T(1e-9) * scale;
  const T on_tol = std::max(T(1e-13) * scale, 64 * eps * mag);

  const auto curve_at = [&](T t, int k) { return partials(c, t, T(0), k); };  // layout (k+1) x (k+1) x 3
  // The distance from C(t) to the surface near (u, v) (a local projection), and where.
  const auto local_distance = [&](T t, T& u, T& v) {
    const std::vector<T> x = point(c, t, T(0));
    const auto uv = polish_projection<T>(f, std::span<const T>(x.data(), 3), u, v, scale);
    u = uv[0];
    v = uv[1];
    const std::vector<T> y = point(f, u, v);
    return safe_distance(x.data(), y.data(), 3);
  };
  // Whether C(t) lies on the surface, trying the given starts; the (u, v) found.
  const auto on_surface = [&](T t, std::span<const std::array<T, 2>> starts, T& u, T& v) {
    for (const auto& s : starts) {
      T uu = s[0], vv = s[1];
      if (local_distance(t, uu, vv) <= on_tol) {
        u = uu;
        v = vv;
        return true;
      }
    }
    return false;
  };

  struct Raw {
    T t, u, v, residual;
  };
  std::vector<Raw> raw;
  std::vector<std::array<T, 2>> over;
  std::vector<std::array<T, 2>> over_uv;  // a surface point of each overlap's start (for the end refinement)

  // Damped Newton on F(t, u, v) = C(t) - S(u, v) inside both domains. A curve that runs
  // along the surface within the tolerances without lying on it makes a solve at every
  // leaf along it: past max_solves the search stops rather than running on for seconds.
  std::size_t solves = 0;
  const std::size_t max_solves = 5000;
  const auto solve = [&](T t, T u, T v) {
    if (++solves > max_solves) {
      throw NumericalError("the intersection did not settle: more than " + std::to_string(max_solves) +
                           " candidate points (the curve runs along the surface, within 1e-9 of the size, without lying on it)");
    }
    const auto residual = [&](T tt, T uu, T vv, std::array<T, 3>& F) {
      const std::vector<T> x = point(c, tt, T(0)), y = point(f, uu, vv);
      for (int k = 0; k < 3; ++k) F[static_cast<std::size_t>(k)] = x[static_cast<std::size_t>(k)] - y[static_cast<std::size_t>(k)];
      return std::hypot(F[0], F[1], F[2]);
    };
    std::array<T, 3> F;
    T r = residual(t, u, v, F);
    T lambda = 0;
    for (int it = 0; it < 100 && r > 0; ++it) {
      const std::vector<T> dc = curve_at(t, 1), ds = partials(f, u, v, 1);
      // Columns of J: C'(t), -S_u, -S_v (curve layout (1,0) at index 2*3, surface (1,0) at 2*3, (0,1) at 1*3).
      const T* Ct = dc.data() + 2 * 3;
      const T* Su = ds.data() + 2 * 3;
      const T* Sv = ds.data() + 1 * 3;
      T J[3][3];
      for (int k = 0; k < 3; ++k) {
        J[k][0] = Ct[k];
        J[k][1] = -Su[k];
        J[k][2] = -Sv[k];
      }
      T A[3][3] = {}, g[3] = {};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k) A[i][j] += J[k][i] * J[k][j];
        for (int k = 0; k < 3; ++k) g[i] -= J[k][i] * F[static_cast<std::size_t>(k)];
      }
      const T tr = A[0][0] + A[1][1] + A[2][2];
      if (!(tr > 0)) break;
      if (lambda == 0) lambda = T(1e-12) * tr;
      bool improved = false;
      for (int k = 0; k < 30 && !improved; ++k) {
        T B[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) B[i][j] = A[i][j] + (i == j ? lambda : T(0));
        const T det = B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) - B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0]) +
                      B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0]);
        if (!(det != 0) || !std::isfinite(det)) {
          lambda *= 16;
          continue;
        }
        T x[3];
        for (int col = 0; col < 3; ++col) {
          T M[3][3];
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) M[i][j] = j == col ? g[i] : B[i][j];
          x[col] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                    M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
                   det;
        }
        const T nt = std::clamp(t + x[0], ta, tb), nu = std::clamp(u + x[1], ua, ub), nv = std::clamp(v + x[2], va, vb);
        std::array<T, 3> G;
        const T nr = residual(nt, nu, nv, G);
        if (nr < r) {
          improved = true;
          const bool still = nt == t && nu == u && nv == v;
          t = nt;
          u = nu;
          v = nv;
          F = G;
          r = nr;
          lambda = std::max(lambda / 4, T(1e-15) * tr);
          if (still) break;
        } else {
          lambda *= 16;
        }
      }
      if (!improved) break;
    }
    if (r <= hit_tol) raw.push_back({t, u, v, r});
  };

  struct Work {
    BernsteinGrid<T> curve;
    std::vector<BernsteinGrid<T>> patches;
  };
  std::size_t pairs = 0;
  std::vector<Work> stack;
  for (auto& p : pieces) stack.push_back({std::move(p), all_patches});
  while (!stack.empty()) {
    Work w = std::move(stack.back());
    stack.pop_back();
    const Box3<T> bc = box_of(w.curve);
    std::vector<BernsteinGrid<T>> keep;
    T largest = 0;
    for (auto& p : w.patches) {
      const Box3<T> bp = box_of(p);
      if (!bc.meets(bp, slack)) continue;
      largest = std::max(largest, bp.diagonal());
      keep.push_back(std::move(p));
    }
    pairs += keep.size();
    if (pairs > max_pairs) {
      throw NumericalError("the intersection did not settle within " + std::to_string(max_pairs) +
                           " curve-patch pairs (the curve runs along the surface too closely for too long)");
    }
    if (keep.empty()) continue;
    const T size = bc.diagonal();
    const bool curve_splits = can_halve(w.curve, Direction::u);
    if (size <= T(1e-2) * scale && size >= T(1e-3) * scale) {
      // Does the whole piece lie on the surface?
      std::vector<std::array<T, 2>> starts;
      for (const auto& p : keep) starts.push_back({(p.u0 + p.u1) / 2, (p.v0 + p.v1) / 2});
      bool on = true;
      T u = 0, v = 0, u_first = 0, v_first = 0;
      for (int k = 0; k <= 8 && on; ++k) {
        const T t = k == 8 ? w.curve.u1 : w.curve.u0 + (w.curve.u1 - w.curve.u0) * static_cast<T>(k) / 8;
        if (k > 0) starts.insert(starts.begin(), {u, v});
        on = on_surface(t, starts, u, v);
        if (k > 0) starts.erase(starts.begin());
        if (k == 0) {
          u_first = u;
          v_first = v;
        }
      }
      if (on) {
        over.push_back({w.curve.u0, w.curve.u1});
        over_uv.push_back({u_first, v_first});
        continue;
      }
    }
    if ((size <= leaf && largest <= leaf) || (!curve_splits && std::none_of(keep.begin(), keep.end(), [](const auto& p) {
                                                return can_halve(p, Direction::u) || can_halve(p, Direction::v);
                                              }))) {
      for (const auto& p : keep) solve((w.curve.u0 + w.curve.u1) / 2, (p.u0 + p.u1) / 2, (p.v0 + p.v1) / 2);
      continue;
    }
    if (curve_splits && size >= largest) {
      auto [a, b] = halve(w.curve, Direction::u);
      stack.push_back({std::move(b), keep});
      stack.push_back({std::move(a), std::move(keep)});
      continue;
    }
    std::vector<BernsteinGrid<T>> next;
    for (auto& p : keep) {
      if (box_of(p).diagonal() <= std::max(size, leaf)) {
        next.push_back(std::move(p));
        continue;
      }
      // Halve across the direction in which the control net spans more (both when they
      // are within a factor 2): near a degenerate edge (a sphere's pole) the net spans
      // little along it, and halving along it too would multiply the patches there.
      const auto [su, sv] = net_spans(p);
      std::vector<Direction> dirs;
      if (su >= sv / 2) dirs.push_back(Direction::u);
      if (sv >= su / 2) dirs.push_back(Direction::v);
      std::vector<BernsteinGrid<T>> quarter{std::move(p)};
      for (const Direction d : dirs) {
        std::vector<BernsteinGrid<T>> halves;
        for (auto& q : quarter) {
          if (!can_halve(q, d)) {
            halves.push_back(std::move(q));
            continue;
          }
          auto [a, b] = halve(q, d);
          halves.push_back(std::move(a));
          halves.push_back(std::move(b));
        }
        quarter = std::move(halves);
      }
      for (auto& q : quarter) next.push_back(std::move(q));
    }
    stack.push_back({std::move(w.curve), std::move(next)});
  }

  CurveSurfaceIntersection<T> out;
  // Overlaps: adjacent pieces joined, each end refined by bisection between the last
  // parameter on the surface and one beyond it that is not.
  {
    std::vector<std::size_t> order(over.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return over[a][0] < over[b][0]; });
    const T tjoin = T(1e-12) * (tb - ta);
    std::vector<std::array<T, 2>> joined, joined_uv;
    for (const std::size_t i : order) {
      if (!joined.empty() && over[i][0] <= joined.back()[1] + tjoin) {
        joined.back()[1] = std::max(joined.back()[1], over[i][1]);
      } else {
        joined.push_back(over[i]);
        joined_uv.push_back(over_uv[i]);
      }
    }
    for (std::size_t k = 0; k < joined.size(); ++k) {
      auto& o = joined[k];
      for (const int side : {0, 1}) {
        T on = o[static_cast<std::size_t>(side)];
        if (on == (side == 0 ? ta : tb)) continue;
        T u = joined_uv[k][0], v = joined_uv[k][1];
        {
          T uu = u, vv = v;
          const std::array<T, 2> s0{u, v};
          if (on_surface(on, std::span<const std::array<T, 2>>(&s0, 1), uu, vv)) {
            u = uu;
            v = vv;
          }
        }
        // A parameter beyond the end that is off the surface.
        T step = std::max((o[1] - o[0]) / 8, T(1e-9) * (tb - ta));
        T off = on;
        bool found = false;
        for (int k2 = 0; k2 < 60; ++k2) {
          off = side == 0 ? std::max(ta, on - step) : std::min(tb, on + step);
          T uu = u, vv = v;
          const std::array<T, 2> s0{u, v};
          if (!on_surface(off, std::span<const std::array<T, 2>>(&s0, 1), uu, vv)) {
            found = true;
            break;
          }
          on = off;
          u = uu;
          v = vv;
          if (off == (side == 0 ? ta : tb)) break;
        }
        if (found) {
          for (int k2 = 0; k2 < 60; ++k2) {
            const T mid = (on + off) / 2;
            if (mid == on || mid == off) break;
            T uu = u, vv = v;
            const std::array<T, 2> s0{u, v};
            if (on_surface(mid, std::span<const std::array<T, 2>>(&s0, 1), uu, vv)) {
              on = mid;
              u = uu;
              v = vv;
            } else {
              off = mid;
            }
          }
        }
        o[static_cast<std::size_t>(side)] = on;
      }
    }
    // Refined ends may now meet.
    for (const auto& o : joined) {
      if (!out.overlaps.empty() && o[0] <= out.overlaps.back()[1] + tjoin) out.overlaps.back()[1] = std::max(out.overlaps.back()[1], o[1]);
      else out.overlaps.push_back(o);
    }
  }
  // Points: merged where found twice (the same point from two pairs), or where the curve
  // between two of them stays on the surface to hit_tol (a touch of high order gives a run
  // of solutions along its flat contact: one tangent point, the one that meets best).
  std::sort(raw.begin(), raw.end(), [](const Raw& a, const Raw& b) { return a.t < b.t; });
  const T tmerge = T(1e-6) * (tb - ta), dmerge = T(1e-6) * scale;
  struct Cluster {
    Raw best, last;
    T first_t;
  };
  std::vector<Cluster> merged;
  for (const auto& r : raw) {
    if (!merged.empty()) {
      Cluster& k = merged.back();
      const std::vector<T> x = point(c, r.t, T(0)), y = point(c, k.last.t, T(0));
      bool same = r.t - k.last.t <= tmerge && safe_distance(x.data(), y.data(), 3) <= dmerge;
      if (!same && r.t - k.last.t <= T(1e-2) * (tb - ta)) {
        same = true;
        for (int q = 1; q <= 3 && same; ++q) {
          const T tm = k.last.t + (r.t - k.last.t) * static_cast<T>(q) / 4;
          T u = k.last.u + (r.u - k.last.u) * static_cast<T>(q) / 4, v = k.last.v + (r.v - k.last.v) * static_cast<T>(q) / 4;
          same = local_distance(tm, u, v) <= hit_tol;
        }
      }
      if (same) {
        if (r.residual < k.best.residual) k.best = r;
        k.last = r;
        continue;
      }
    }
    merged.push_back({r, r, r.t});
  }
  const T tin = T(1e-9) * (tb - ta);
  for (const auto& k : merged) {
    const Raw& r = k.best;
    bool inside = false;
    for (const auto& o : out.overlaps) inside = inside || (r.t >= o[0] - tin && r.t <= o[1] + tin);
    if (inside) continue;
    const std::vector<T> x = point(c, r.t, T(0));
    CurveSurfaceHit<T> h{r.t, r.u, r.v, {x[0], x[1], x[2]}, false};
    // The surface's normal there (at a degenerate point, the limit normal: a point nudged
    // towards the domain's centre), the curve's tangent.
    std::vector<T> ds = partials(f, r.u, r.v, 1);
    const auto normal = [&](const std::vector<T>& d, std::array<T, 3>& nrm) {
      const T* Su = d.data() + 2 * 3;
      const T* Sv = d.data() + 1 * 3;
      nrm = {Su[1] * Sv[2] - Su[2] * Sv[1], Su[2] * Sv[0] - Su[0] * Sv[2], Su[0] * Sv[1] - Su[1] * Sv[0]};
      const T l = std::hypot(nrm[0], nrm[1], nrm[2]);
      const T lu = std::hypot(Su[0], Su[1], Su[2]), lv = std::hypot(Sv[0], Sv[1], Sv[2]);
      if (!(l > T(1e-12) * lu * lv)) return false;
      for (auto& x2 : nrm) x2 /= l;
      return true;
    };
    std::array<T, 3> nrm{};
    bool have = normal(ds, nrm);
    for (T nudge = T(1e-7); !have && nudge <= T(1e-3); nudge *= 10) {
      const T nu = r.u + nudge * ((ua + ub) / 2 - r.u), nv = r.v + nudge * ((va + vb) / 2 - r.v);
      have = normal(partials(f, nu, nv, 1), nrm);
    }
    const std::vector<T> dc = curve_at(r.t, 1);
    const T* Ct = dc.data() + 2 * 3;
    const T cl = std::hypot(Ct[0], Ct[1], Ct[2]);
    if (have && cl > 0) h.tangent = std::abs(Ct[0] * nrm[0] + Ct[1] * nrm[1] + Ct[2] * nrm[2]) / cl <= T(1e-6);
    // A run of solutions spread along the curve: a contact of high order.
    if (k.last.t - k.first_t > T(1e-9) * (tb - ta)) h.tangent = true;
    out.hits.push_back(h);
  }
  return out;
}

}  // namespace casteljau::detail
