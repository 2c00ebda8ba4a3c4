// Intersections of curves with extreme weights: a rational piece whose weights in standard
// form spread beyond tame_trigger (weights 1, 1e16, 1: the curve hugs its control polygon
// and passes each leg within 1e-16 of a parameter end, where subdivision and Newton's
// method in t resolve nothing) is intersected through its tame parts (the Möbius
// reparametrisations and splits of detail::regular_parts), the parameters mapped back.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/common.hpp"
#include "casteljau/algo/scalar_forms.hpp"

namespace casteljau::detail::isect {

/// The spread of a rational piece's weights in standard form (end weights equal, the
/// reparametrisation w_i -> w_i c^i of detail::regular_parts) as the natural logarithm of
/// the largest ratio of a weight to the end weights, either way: 0 for a polynomial
/// piece, ln(1e16) for the weights 1, 1e16, 1.
template <class T>
T standard_weight_spread(const Piece<T>& c) {
  const auto* r = std::get_if<RationalBezier<T, 2>>(&c);
  if (!r || r->degree() < 1) return 0;
  const auto& w = r->weights();
  const std::size_t n = w.size() - 1;
  const T l0 = std::log(w.front()), lc = (l0 - std::log(w.back())) / static_cast<T>(n);
  T spread = 0;
  for (std::size_t i = 0; i <= n; ++i) spread = std::max(spread, std::abs(std::log(w[i]) + static_cast<T>(i) * lc - l0));
  return spread;
}

/// The spread (as standard_weight_spread) above which a piece is intersected through its
/// tame parts: 2^20. Below it the engine works on the piece itself, as it always did (a
/// NURBS circle's weights spread by sqrt(2)); above it, subdivision in t stops resolving
/// the legs that the curve passes within about 1 / spread of the parameter's ends.
template <class T>
inline constexpr T tame_trigger = T(20) * T(0.6931471805599453);

/// A piece of the tamed curve and the way back to the curve's own parameters: part of
/// piece `piece` through its map (a Möbius map, or the identity for a piece taken as it
/// is), or a run of consecutive parts smaller than the run size replaced by its chord,
/// whose parameter maps linearly onto the piece parameters [lo, hi] of the run's ends
/// (any point of such a run is the same point at the engine's resolution).
template <class T>
struct TamePart {
  std::size_t piece = 0;
  PartMap<T> map{};
  bool chord = false;
  T lo = 0, hi = 1;
  std::vector<Point<T, 2>> run;  ///< a chord's run: the ends of its parts, in order

  [[nodiscard]] T piece_parameter(T u) const {
    if (!chord) return map.t_of(u);
    if (u <= 0) return lo;
    if (u >= 1) return hi;
    return lo + u * (hi - lo);
  }
};

/// A curve as tame pieces (on the breaks 0, 1, ..., k) and the way back.
template <class T>
struct Tamed {
  Pieces<T, 2> curve;
  std::vector<TamePart<T>> parts;

  /// The tamed curve's breaks between two parts of one piece (not ends of the curve's
  /// own arcs).
  [[nodiscard]] std::vector<T> joints() const {
    std::vector<T> out;
    for (std::size_t k = 1; k < parts.size(); ++k)
      if (parts[k].piece == parts[k - 1].piece) out.push_back(curve.segment_domain(k).lo);
    return out;
  }

  /// The original curve's parameter of the tamed curve's parameter g.
  [[nodiscard]] T original(const Pieces<T, 2>& c, T g) const {
    const auto [k, u] = curve.locate(g);
    return c.lift(parts[k].piece, parts[k].piece_parameter(u));
  }
};

/// The joints of the tame parts of both curves of solve() (Tamed::joints), b's = a's for
/// self-intersections.
template <class T>
struct TameJoints {
  std::vector<T> a, b;
};

/// Whether some piece of c has weights spread beyond tame_trigger.
template <class T>
bool has_extreme_weights(const Pieces<T, 2>& c) {
  return std::any_of(c.segments().begin(), c.segments().end(), [](const Piece<T>& s) { return standard_weight_spread(s) > tame_trigger<T>; });
}

/// c with every piece of extreme weights replaced by its tame parts (detail::regular_parts:
/// exact up to the rounding of the splits), and each run of consecutive parts whose
/// control points lie within a box of diagonal `run` (model units) by the chord of the run
/// (the parts within 1e-30 of a corner of the control polygon, whose control points round
/// to the corner: points, which would each meet a curve through the corner). Other pieces
/// are kept as they are.
template <class T>
Tamed<T> tame(const Pieces<T, 2>& c, T run) {
  std::vector<Piece<T>> segs;
  std::vector<TamePart<T>> parts;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Piece<T>& s = c.segments()[i];
    if (!(standard_weight_spread(s) > tame_trigger<T>)) {
      segs.push_back(s);
      parts.push_back({i, PartMap<T>{}, false, 0, 1, {}});
      continue;
    }
    const auto rp = regular_parts(std::get<RationalBezier<T, 2>>(s));
    for (std::size_t k = 0; k < rp.size();) {
      Box<T, 2> box = rp[k].piece.control_bounds();
      std::size_t j = k + 1;
      if (norm(box.hi - box.lo) <= run) {
        for (; j < rp.size(); ++j) {
          Box<T, 2> more = box;
          more.add(rp[j].piece.control_bounds());
          if (!(norm(more.hi - more.lo) <= run)) break;
          box = more;
        }
        segs.push_back(Bezier<T, 2>({rp[k].piece.points().front(), rp[j - 1].piece.points().back()}));
        std::vector<Point<T, 2>> ends{rp[k].piece.points().front()};
        for (std::size_t m = k; m < j; ++m) ends.push_back(rp[m].piece.points().back());
        parts.push_back({i, PartMap<T>{}, true, rp[k].map.t_of(T(0)), rp[j - 1].map.t_of(T(1)), std::move(ends)});
      } else {
        segs.push_back(rp[k].piece);
        parts.push_back({i, rp[k].map, false, 0, 1, {}});
      }
      k = j;
    }
  }
  return {Pieces<T, 2>(std::move(segs)), std::move(parts)};
}

/// A crossing found on a chord (a run of parts within the run size, see tame) moved onto
/// the run itself: the chord cuts a corner of the run by up to the run size (1e-13 of the
/// size; a line through the corner of a NURBS square with weights 1e20 met it 1.0e-13 from
/// the corner, where the curve passes 5e-21 from it). The other curve, a line at this
/// scale (its tangent at tb, in its tamed parameter), is intersected with the polyline
/// through the run's part ends (points of the curve); the point moves there and tb with
/// it. Nothing changes where the line misses the polyline. ta stays (any parameter of
/// the run is the same point at the engine's resolution).
template <class T>
void onto_run(const TamePart<T>& part, const Pieces<T, 2>& other, T& tb, Point<T, 2>& point) {
  if (part.run.size() < 2) return;
  const Vector<T, 2> d = other.derivative_at(tb, 1);
  const T dd = dot(d, d);
  if (!(dd > 0)) return;
  const Point<T, 2> q = other(tb);
  const Vector<T, 2> n{-d[1], d[0]};
  std::optional<Point<T, 2>> best;
  for (std::size_t m = 1; m < part.run.size(); ++m) {
    const Point<T, 2>& p0 = part.run[m - 1];
    const Point<T, 2>& p1 = part.run[m];
    const T s0 = dot(n, p0 - q), s1 = dot(n, p1 - q);  // signed sides of the line
    if ((s0 > 0 && s1 > 0) || (s0 < 0 && s1 < 0)) continue;
    const Point<T, 2> x = s0 == s1 ? p0 : lerp(p0, p1, s0 / (s0 - s1));
    if (!best || distance(x, point) < distance(*best, point)) best = x;
  }
  if (!best) return;
  tb += dot(*best - q, d) / dd;
  point = *best;
}

}  // namespace casteljau::detail::isect
