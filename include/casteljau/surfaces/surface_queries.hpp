// Queries on surfaces, written once on the run-time form (surfaces/surface_form.hpp):
// bounds (a containing box, each side within a relative tolerance of the true extent, by
// branch and bound on the Bézier patches) and area (nested adaptive Gauss-Kronrod over each
// patch's rectangle).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

#include "casteljau/basis/quadrature.hpp"
#include "casteljau/surfaces/surface_form.hpp"

namespace casteljau::detail {

/// A box in the surface's dimension.
template <class T>
struct SurfaceBox {
  std::vector<T> lo, hi;
};

/// A box containing S over its domain whose sides lie within rel x (the diagonal of the
/// box of the points found on S) of the true extent: per coordinate and side, branch and
/// bound over the Bézier patches. A patch lies in the box of its (Cartesian) control points
/// (weights > 0: convex combinations); the corners of a patch and the centre of each
/// patch examined are points of S, so the best of them bounds the extent from the
/// inside. A patch whose control extent is not beyond the best point by more than the
/// tolerance is settled; the others are halved (across the longer side of their control
/// net) and examined again. The answer is the outermost control extent of the settled
/// patches: it contains S and lies within the tolerance of a point of S. Patches deeper
/// than max_depth halvings are settled as they are (the box still contains S; only a
/// surface with control points near 1e300 gets there), and so is every patch left after
/// max_splits halvings for one side: an extent attained along a curve inside the patches
/// (a torus's top circle between knots) needs patches of the tolerance's square root all
/// along it; the box then still contains S but may miss the tolerance (issue 19: left).
template <class T>
SurfaceBox<T> bounds(const SurfaceForm<T>& f, T rel) {
  const std::size_t cd = f.cartesian();
  const SurfacePatches<T> sp = patches(f);
  std::vector<SurfaceForm<T>> all;
  for (const auto& row : sp.patches) all.insert(all.end(), row.begin(), row.end());
  // Points of S: every patch's corners (a Bézier patch interpolates its corner points).
  SurfaceBox<T> found{std::vector<T>(cd, std::numeric_limits<T>::infinity()), std::vector<T>(cd, -std::numeric_limits<T>::infinity())};
  const auto see = [&](const T* x) {
    for (std::size_t c = 0; c < cd; ++c) {
      found.lo[c] = std::min(found.lo[c], x[c]);
      found.hi[c] = std::max(found.hi[c], x[c]);
    }
  };
  for (const auto& p : all)
    for (const std::size_t i : {std::size_t(0), p.rows - 1})
      for (const std::size_t j : {std::size_t(0), p.cols - 1}) see(p.at(i, j));
  T diag = 0;
  for (std::size_t c = 0; c < cd; ++c) diag += (found.hi[c] - found.lo[c]) * (found.hi[c] - found.lo[c]);
  const T tol = rel * std::sqrt(diag);
  SurfaceBox<T> out{found.lo, found.hi};
  constexpr int max_depth = 80;
  constexpr std::size_t max_splits = 50000;  // per side; about 0.3 s
  struct Item {
    SurfaceForm<T> patch;
    int depth;
    T e;  ///< the patch's control extent
  };
  for (std::size_t c = 0; c < cd; ++c) {
    for (const T side : {T(1), T(-1)}) {
      // extent(p): the control extent of coordinate c on this side, as the smallest of
      // side x (side 1: the lower side; side -1: the upper one, negated).
      const auto extent = [&](const SurfaceForm<T>& p) {
        T e = std::numeric_limits<T>::infinity();
        for (std::size_t i = 0; i < p.rows; ++i)
          for (std::size_t j = 0; j < p.cols; ++j) e = std::min(e, side * p.at(i, j)[c]);
        return e;
      };
      T best = side > 0 ? found.lo[c] : -found.hi[c];  // the best point of S so far (in side's sign)
      T settled = best;
      // Best first: the patch reaching farthest is examined first, so that the best point
      // approaches the extent quickly and the other patches settle at once.
      std::size_t splits = 0;
      const auto later = [](const Item& a, const Item& b) { return a.e > b.e; };
      std::priority_queue<Item, std::vector<Item>, decltype(later)> queue(later);
      for (const auto& p : all) queue.push({p, 0, extent(p)});
      while (!queue.empty()) {
        Item it = queue.top();
        queue.pop();
        const T e = it.e;
        if (e >= best - tol) {
          // Settled, and so is every patch left (they reach no farther).
          settled = std::min(settled, e);
          break;
        }
        if (it.depth >= max_depth || ++splits > max_splits) {
          settled = std::min(settled, e);
          continue;
        }
        // A point of S: the patch's centre.
        const T um = (it.patch.U.front() + it.patch.U.back()) / 2, vm = (it.patch.V.front() + it.patch.V.back()) / 2;
        const std::vector<T> x = point(it.patch, um, vm);
        best = std::min(best, side * x[c]);
        // Halve across the side whose control net varies more in this coordinate.
        T du = 0, dv = 0;
        for (std::size_t i = 0; i < it.patch.rows; ++i)
          for (std::size_t j = 0; j < it.patch.cols; ++j) {
            if (i > 0) du = std::max(du, std::abs(it.patch.at(i, j)[c] - it.patch.at(i - 1, j)[c]));
            if (j > 0) dv = std::max(dv, std::abs(it.patch.at(i, j)[c] - it.patch.at(i, j - 1)[c]));
          }
        const Direction dir = du >= dv ? Direction::u : Direction::v;
        auto halves = split(it.patch, dir, dir == Direction::u ? um : vm);
        for (auto* h : {&halves.first, &halves.second}) {
          const T eh = extent(*h);
          queue.push({std::move(*h), it.depth + 1, eh});
        }
      }
      // Every settled patch lies beyond `settled`; the found points were settled too.
      if (side > 0) out.lo[c] = std::min(settled, best);
      else out.hi[c] = -std::min(settled, best);
    }
  }
  return out;
}

/// The area of S over its domain, integral of sqrt(EG - F^2) (|S_u x S_v| in 3-D; the Gram
/// determinant in any dimension), patch by patch: along v by adaptive Gauss-Kronrod inside
/// an adaptive Gauss-Kronrod along u, each to rel (relative) of its own value, the inner
/// one tighter so that its error is no noise to the outer one. Throws NumericalError when
/// an integral does not converge (integrate_adaptive).
template <class T>
T area(const SurfaceForm<T>& f, T rel) {
  const std::size_t cd = f.cartesian();
  const SurfacePatches<T> sp = patches(f);
  T total = 0;
  for (std::size_t a = 0; a + 1 < sp.ubreaks.size(); ++a) {
    for (std::size_t b = 0; b + 1 < sp.vbreaks.size(); ++b) {
      const T v0 = sp.vbreaks[b], v1 = sp.vbreaks[b + 1];
      const T u0 = sp.ubreaks[a], u1 = sp.ubreaks[a + 1];
      // Evaluate on the patch (exactly the surface there; no span search at its edges).
      const SurfaceForm<T>& p = sp.patches[a][b];
      // An absolute floor for integrals that vanish (a patch degenerate to a curve): far
      // below the patch's own scale, the square of its control box's diagonal.
      T lo2 = 0;
      {
        std::vector<T> lo(cd, std::numeric_limits<T>::infinity()), hi(cd, -std::numeric_limits<T>::infinity());
        for (std::size_t i = 0; i < p.rows; ++i)
          for (std::size_t j = 0; j < p.cols; ++j)
            for (std::size_t c = 0; c < cd; ++c) {
              lo[c] = std::min(lo[c], p.at(i, j)[c]);
              hi[c] = std::max(hi[c], p.at(i, j)[c]);
            }
        for (std::size_t c = 0; c < cd; ++c) lo2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
      }
      const T floor = std::max(rel * T(1e-3) * lo2, std::numeric_limits<T>::min());
      const auto density = [&](T u, T v) {
        const std::vector<T> d = partials(p, u, v, 1);
        const T* Su = d.data() + 2 * cd;  // (1, 0) in the 2 x 2 layout
        const T* Sv = d.data() + cd;      // (0, 1)
        T E = 0, F = 0, G = 0;
        for (std::size_t c = 0; c < cd; ++c) {
          E += Su[c] * Su[c];
          F += Su[c] * Sv[c];
          G += Sv[c] * Sv[c];
        }
        return std::sqrt(std::max(T(0), E * G - F * F));
      };
      const auto inner = [&](T u) {
        return integrate_adaptive([&](T v) { return density(u, v); }, v0, v1, rel / 16, floor / (u1 - u0)).value;
      };
      total += integrate_adaptive(inner, u0, u1, rel, floor).value;
    }
  }
  return total;
}

}  // namespace casteljau::detail
