// The pieces, arcs, seeds and per-problem context shared by the general intersection
// engine (algo/intersect.hpp) and its band step (algo/intersect/band.hpp), with the
// tangent cone of a part that both use.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "casteljau/basis/roots.hpp"
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

/// A piece evaluated with its first two derivatives for foot-point steps: past degree 32
/// a polynomial piece through the Bernstein coefficients of its coordinates and their
/// differences in O(n) (bernstein_value_fast: about n eps of the coefficients, 5e-14 at
/// degree 500 in the unit frame, far below the near-miss distance), where de Casteljau
/// costs O(n^2) per value (most of the time of two coincident degree-500 curves); else the
/// piece's own evaluation (so low degrees are computed as before). `exact()`: the same
/// piece through its own evaluation at every degree (to finish a Newton iteration run on
/// the fast form: refine, polish_touch).
template <class T>
struct FootEval {
  const Piece<T>* c;
  bool fast = false;
  std::array<std::vector<T>, 2> p, d1, d2;  // coordinates, then n and n (n - 1) times their differences

  explicit FootEval(const Piece<T>& piece) : c(&piece) {
    const auto* z = std::get_if<Bezier<T, 2>>(&piece);
    if (!z || z->degree() <= 32) return;
    fast = true;
    const auto& P = z->points();
    const std::size_t n = P.size() - 1;
    for (int k = 0; k < 2; ++k) {
      p[k].resize(n + 1);
      for (std::size_t i = 0; i <= n; ++i) p[k][i] = P[i][k];
      d1[k].resize(n);
      for (std::size_t i = 0; i < n; ++i) d1[k][i] = p[k][i + 1] - p[k][i];
      d2[k].resize(n - 1);
      for (std::size_t i = 0; i + 1 < n; ++i) d2[k][i] = d1[k][i + 1] - d1[k][i];
      for (auto& x : d1[k]) x *= static_cast<T>(n);
      for (auto& x : d2[k]) x *= static_cast<T>(n) * static_cast<T>(n - 1);
    }
  }
  static Vector<T, 2> value(const std::array<std::vector<T>, 2>& v, T t) {
    return {bernstein_value_fast<T>(std::span<const T>(v[0]), t), bernstein_value_fast<T>(std::span<const T>(v[1]), t)};
  }
  Point<T, 2> at(T t) const {
    if (!fast) return isect::at(*c, t);
    const Vector<T, 2> v = value(p, t);
    return {v[0], v[1]};
  }
  Vector<T, 2> d(T t) const { return fast ? value(d1, t) : derivative(*c, t); }
  Vector<T, 2> dd(T t) const { return fast ? value(d2, t) : derivative(*c, t, 2); }
  FootEval exact() const { return FootEval(*c, false); }
  FootEval(const Piece<T>& piece, bool) : c(&piece) {}
};

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
  // The pieces' evaluators (FootEval: O(n) past degree 32), for band()'s projections.
  const FootEval<T>* fa = nullptr;
  const FootEval<T>* fb = nullptr;
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
