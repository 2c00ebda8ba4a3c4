// Lines, quadratics and cubics by value on the unit-scale copy: the allocation-free
// flattening kernels' input (uniform and the plane near-optimal method).
#pragma once

#include <array>
#include <vector>

#include "casteljau/core/unit_frame.hpp"
#include "casteljau/basis/de_casteljau.hpp"

namespace casteljau::detail {

// ---- Allocation-free kernels for polynomial pieces of degree <= 3 -----------------------
// Lines, quadratics and cubics are most curves in practice (fonts, SVG paths): they are
// flattened from fixed-size arrays on the unit-scale copy, each vertex handed to an
// emit callback (no vector per piece, no heap-allocated sub-curves). The methods and
// their guarantees are those of the general code above; uniform gives the same vertices.

/// A polynomial piece of degree 1..3 on the unit-scale copy (see flatten()), by value.
template <class T, int D>
struct SmallPiece {
  int m = 0;                         ///< number of control points, 2..4
  std::array<Point<T, D>, 4> q{};    ///< control points q[0 .. m)
  /// q(t) by de Casteljau: the same lerps in the same order as de_casteljau() (so the
  /// same values as Bezier::operator() on [0, 1]).
  Point<T, D> at(T t) const {
    switch (m) {
      case 2: return lerp(q[0], q[1], t);
      case 3: return lerp(lerp(q[0], q[1], t), lerp(q[1], q[2], t), t);
      default: {
        const Point<T, D> a = lerp(q[0], q[1], t), b = lerp(q[1], q[2], t), d = lerp(q[2], q[3], t);
        return lerp(lerp(a, b, t), lerp(b, d, t), t);
      }
    }
  }
};

/// The unit-scale copy of a polynomial piece of degree <= 3 as a SmallPiece: (P_i - origin)
/// 2^-e (to_unit, the same values as normalised_points).
template <class T, int D>
SmallPiece<T, D> small_piece(const std::vector<Point<T, D>>& P, const Point<T, D>& origin, int e) {
  SmallPiece<T, D> s;
  s.m = static_cast<int>(P.size());
  for (int i = 0; i < s.m; ++i) s.q[static_cast<std::size_t>(i)] = to_unit(P[static_cast<std::size_t>(i)], origin, e);
  return s;
}

}  // namespace casteljau::detail
