// Flattening by recursive midpoint subdivision until each part's control polygon is within
// the tolerance of its chord (the convex hull bound).
#pragma once

#include <vector>

#include "casteljau/algo/flatten/chord.hpp"

namespace casteljau::detail {

template <class C>
void flatten_rec(const C& c, typename C::Scalar tol, int depth, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  if (is_flat(c, tol)) {
    out.push_back(c.points().back());
    return;
  }
  // 2^-52 of the parameter range: beyond this, subdivision is stuck on rounding (the
  // tolerance is below the coordinates' resolution).
  if (depth >= 52) {
    throw NumericalError("flatten: subdivision reached depth 52 (pieces of 2^-52 of the parameter range): the tolerance is below "
                         "the resolution of the curve's coordinates");
  }
  const auto halves = c.split(typename C::Scalar(0.5));
  flatten_rec(halves.left, tol, depth + 1, out);
  flatten_rec(halves.right, tol, depth + 1, out);
}

/// The subdivision method on a unit-scale piece (see flatten()): vertices after out's
/// first.
template <class C>
void flatten_subdivision(const C& c, typename C::Scalar tol, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  flatten_rec(c, tol, 0, out);
}

}  // namespace casteljau::detail
