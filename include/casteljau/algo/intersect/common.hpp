// The pieces, arcs, seeds and per-problem context shared by the general intersection
// engine (algo/intersect.hpp) and its band step (algo/intersect/band.hpp), with the
// tangent cone of a part that both use.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

#include "casteljau/curves/piecewise.hpp"

namespace casteljau::detail::isect {

template <class T>
using Piece = BezierPiece<T, 2>;

/// Part [lo, hi] of piece `piece` (its own parameters) on which both coordinates are
/// monotone: a graph over x and over y, so it cannot meet itself, and two such arcs that
/// coincide somewhere coincide on one interval whose ends are arc ends.
template <class T>
struct Arc {
  std::size_t piece;
  T lo, hi;
};

template <class T>
Point<T, 2> at(const Piece<T>& c, T t) {
  return std::visit([&](const auto& x) { return x(t); }, c);
}
template <class T>
Vector<T, 2> derivative(const Piece<T>& c, T t, int k = 1) {
  return std::visit([&](const auto& x) { return x.derivative_at(t, k); }, c);
}
template <class T>
const std::vector<Point<T, 2>>& points(const Piece<T>& c) {
  return std::visit([](const auto& x) -> const std::vector<Point<T, 2>>& { return x.points(); }, c);
}
template <class T>
int degree(const Piece<T>& c) {
  return static_cast<int>(points(c).size()) - 1;
}

/// A start for the refinement (piece parameters s of a, t of b). `edge` marks one placed
/// at an arc end by a band (see band()): it stands for its near region only when the
/// region has no other point (solve() decides).
template <class T>
struct Seed {
  T s, t;
  bool edge = false;
};

/// Tolerances of one intersection problem, in unit coordinates.
template <class T>
struct Context {
  T tol;    // near-miss distance: points closer than this are common points
  T flat;   // subdivision stops when both parts are within `flat` of their chords
  T slack;  // box rejection slack: tol plus rounding
  std::size_t nodes = 0;
  std::size_t node_limit = 0;
  bool exhausted = false;  // node_limit reached: the seeds are incomplete
  std::vector<Seed<T>> seeds;
  // The pieces and arcs being intersected (piece parameters): band() extends parts along them.
  const Piece<T>* a = nullptr;
  const Piece<T>* b = nullptr;
  const Arc<T>* ra = nullptr;
  const Arc<T>* rb = nullptr;
  bool near = false;  // a band lies within tol of the other curve all along: test for an overlap
  bool stop_on_near = false;  // stop the subdivision once near (the overlap test comes first)
};

/// The tangent cone of a Bézier or rational Bézier part: the directions of its control
/// polygon's legs P_(i+1) - P_i, which contain every tangent direction (for rational
/// pieces too: the derivative is a non-negative combination of the P_j - P_i [Floater92]),
/// as angles [lo, hi] relative to the first non-zero leg `ref`. False when every leg is
/// zero or the cone is wider than 0.5 rad (not worth testing).
template <class T>
struct Cone {
  Vector<T, 2> ref;
  T lo, hi;
};
template <class C>
std::optional<Cone<typename C::Scalar>> tangent_cone(const C& c) {
  using T = typename C::Scalar;
  const auto& P = c.points();
  std::optional<Cone<T>> k;
  for (std::size_t i = 0; i + 1 < P.size(); ++i) {
    const Vector<T, 2> v = P[i + 1] - P[i];
    if (v[0] == 0 && v[1] == 0) continue;
    if (!k) {
      k = Cone<T>{v, 0, 0};
      continue;
    }
    const T a = std::atan2(cross(k->ref, v), dot(k->ref, v));
    k->lo = std::min(k->lo, a);
    k->hi = std::max(k->hi, a);
    if (k->hi - k->lo > T(0.5)) return std::nullopt;
  }
  return k;
}

}  // namespace casteljau::detail::isect
