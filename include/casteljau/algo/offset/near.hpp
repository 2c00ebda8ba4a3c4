// The trim's distance test (phase of algo/offset.hpp): the curve in the unit frame as
// pieces with their control boxes, and whether a point comes nearer to it than a distance
// (Nearness::within: polynomial pieces by subdivision against their chords, rational ones
// and degrees above 15 by project(); a grid over the boxes for many pieces). Depends on
// common.hpp (length), algo/project.hpp and curves/piecewise.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/offset/common.hpp"
#include "casteljau/algo/project.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau::detail::offset {

/// The curve (in the unit frame) as the trim sees it: its pieces and the boxes of their
/// control points (a piece lies inside its box), to ask whether a point is nearer to the
/// curve than a distance.
template <class T>
struct Nearness {
  static constexpr std::size_t max_points = 16;  // polynomial pieces up to degree 15 by subdivision
  std::vector<BezierPiece<T, 2>> pieces;
  std::vector<Box<T, 2>> boxes;
  T leaf = 0;  ///< the box diagonal at which subdivision stops (a fraction of the tolerance)

  void add(const BezierPiece<T, 2>& piece) {
    pieces.push_back(piece);
    boxes.push_back(std::visit([](const auto& c) { return c.control_bounds(); }, piece));
  }
  /// Whether the polynomial piece with control points P[0..m) comes nearer to p than r.
  /// Its control points lie within e of its chord S (the segment between its ends), so the
  /// piece does (its hull is inside that band, and it runs from end to end of S): its
  /// distance from p is within e of S's. Decided when that settles it, else the piece is
  /// halved (de Casteljau), nearer half first, until e is below `leaf` (then S's distance
  /// decides: a point up to `leaf` farther than r may count as near).
  bool near_polynomial(const Point<T, 2>* P, std::size_t m, const Point<T, 2>& p, T r, int depth) const {
    const Point<T, 2>& a = P[0];
    const Vector<T, 2> ab = P[m - 1] - a;
    const T l2 = ab[0] * ab[0] + ab[1] * ab[1];
    const auto to_chord = [&](const Point<T, 2>& q) {
      const Vector<T, 2> aq = q - a;
      const T s = l2 > 0 ? std::clamp((aq[0] * ab[0] + aq[1] * ab[1]) / l2, T(0), T(1)) : T(0);
      const Vector<T, 2> e = aq - ab * s;
      return std::sqrt(e[0] * e[0] + e[1] * e[1]);
    };
    T e = 0;
    for (std::size_t j = 1; j + 1 < m; ++j) e = std::max(e, to_chord(P[j]));
    const T ds = to_chord(p);
    if (ds - e >= r) return false;
    if (ds + e < r) return true;
    if (e <= leaf || depth >= 60) return ds < r;
    std::array<Point<T, 2>, max_points> L, R, W;
    for (std::size_t j = 0; j < m; ++j) W[j] = P[j];
    for (std::size_t level = 0; level < m; ++level) {
      L[level] = W[0];
      R[m - 1 - level] = W[m - 1 - level];
      for (std::size_t j = 0; j + 1 < m - level; ++j) W[j] = W[j] + (W[j + 1] - W[j]) * T(0.5);
    }
    const T dl = length(L[m / 2] - p), dr = length(R[m / 2] - p);  // the nearer half first
    if (dl <= dr) return near_polynomial(L.data(), m, p, r, depth + 1) || near_polynomial(R.data(), m, p, r, depth + 1);
    return near_polynomial(R.data(), m, p, r, depth + 1) || near_polynomial(L.data(), m, p, r, depth + 1);
  }
  /// A grid over the pieces' boxes for the queries of radius at most `reach` (cells of at
  /// least that size, at most about 4 per piece): a query looks at the pieces listed in
  /// the 2 x 2 or more cells its disc's box meets, not at all the pieces.
  T cell = 0, reach = 0;
  Point<T, 2> grid_lo{};
  std::size_t nx = 0, ny = 0;
  std::vector<std::vector<std::uint32_t>> cells;
  mutable std::vector<std::size_t> seen;  // the query stamp that last looked at a piece
  mutable std::size_t stamp = 0;

  void build_grid(T r) {
    reach = r;
    Box<T, 2> all;
    for (const auto& b : boxes) all.add(b);
    const Point<T, 2> lo = all.lo, hi = all.hi;
    const T w = hi[0] - lo[0], h = hi[1] - lo[1];
    const T budget = T(4 * boxes.size() + 16);
    cell = std::max({r, std::sqrt(w * h / budget), std::max(w, h) / budget, std::numeric_limits<T>::min()});
    nx = static_cast<std::size_t>(w / cell) + 1, ny = static_cast<std::size_t>(h / cell) + 1;
    grid_lo = lo;
    cells.assign(nx * ny, {});
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto [x0, y0] = at(boxes[i].lo);
      const auto [x1, y1] = at(boxes[i].hi);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) cells[y * nx + x].push_back(static_cast<std::uint32_t>(i));
    }
    seen.assign(boxes.size(), 0);
  }
  std::pair<std::size_t, std::size_t> at(const Point<T, 2>& q) const {
    const auto idx = [&](T v, std::size_t n) {
      if (!(v > 0)) return std::size_t(0);
      return std::min(static_cast<std::size_t>(v / cell), n - 1);
    };
    return {idx(q[0] - grid_lo[0], nx), idx(q[1] - grid_lo[1], ny)};
  }
  bool near_piece(std::size_t i, const Point<T, 2>& p, T r) const {
    const T dx = std::max({boxes[i].lo[0] - p[0], T(0), p[0] - boxes[i].hi[0]});
    const T dy = std::max({boxes[i].lo[1] - p[1], T(0), p[1] - boxes[i].hi[1]});
    if (dx * dx + dy * dy >= r * r) return false;
    return std::visit(
        [&](const auto& c) {
          using C = std::decay_t<decltype(c)>;
          if constexpr (std::is_same_v<C, Bezier<T, 2>>) {
            if (c.points().size() <= max_points) return near_polynomial(c.points().data(), c.points().size(), p, r, 0);
          }
          return project(c, p).distance < r;
        },
        pieces[i]);
  }
  /// True when some point of the curve lies nearer to p than r (or up to `leaf` farther;
  /// see near_polynomial): the pieces whose box is nearer than r, polynomial ones by
  /// subdivision, rational ones (and degree above 15) projected on (project()).
  bool within(const Point<T, 2>& p, T r) const {
    if (!(r > 0)) return false;
    if (!cells.empty() && r <= reach) {
      ++stamp;
      const auto [x0, y0] = at(Point<T, 2>{p[0] - r, p[1] - r});
      const auto [x1, y1] = at(Point<T, 2>{p[0] + r, p[1] + r});
      for (std::size_t y = y0; y <= y1; ++y) {
        for (std::size_t x = x0; x <= x1; ++x) {
          for (const std::uint32_t i : cells[y * nx + x]) {
            if (seen[i] == stamp) continue;
            seen[i] = stamp;
            if (near_piece(i, p, r)) return true;
          }
        }
      }
      return false;
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (near_piece(i, p, r)) return true;
    }
    return false;
  }
};

}  // namespace casteljau::detail::offset
