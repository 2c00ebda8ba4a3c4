// Intersections of plane curves: curve with curve (a line segment or polyline is a curve)
// and the self-intersections of one curve, with tangential touches and overlaps. The
// general engine; its band step for near-coincident parts is in algo/intersect_band.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/algo/flatten.hpp"
#include "casteljau/algo/intersect_band.hpp"
#include "casteljau/algo/intersect_common.hpp"
#include "casteljau/algo/intersect_low_degree.hpp"
#include "casteljau/algo/intersect_tame.hpp"
#include "casteljau/basis/bernstein_poly.hpp"
#include "casteljau/core/segment.hpp"
#include "casteljau/core/unit_frame.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/curves/path.hpp"

namespace casteljau {

/// How two curves meet at an isolated common point.
enum class IntersectionKind {
  crossing,  ///< the tangents differ (sine of their angle above 1e-6)
  tangent,   ///< the tangents are parallel: a touch, or a crossing with parallel tangents
};

/// An isolated common point: a(ta) = b(tb) (for self-intersections ta < tb).
template <class T>
struct CurveIntersection {
  T ta{};
  T tb{};
  Point<T, 2> point;  ///< a(ta)
  IntersectionKind kind = IntersectionKind::crossing;
};

/// A stretch where the curves coincide: a over [a.lo, a.hi] (a.lo < a.hi) traces the same
/// points as b from b_start to b_end (b_start > b_end when b runs the other way).
template <class T>
struct CurveOverlap {
  Interval<T> a;
  T b_start{};
  T b_end{};
};

/// The result of intersect(): isolated points sorted by ta, and overlaps sorted by a.lo.
template <class T>
struct Intersections {
  std::vector<CurveIntersection<T>> points;
  std::vector<CurveOverlap<T>> overlaps;
};

namespace detail::isect {

/// The curve prepared for intersection: its pieces translated and scaled by a power of
/// two (shared by both curves, so that coordinates are O(1)), and its monotone arcs.
template <class T>
struct Prepared {
  const Pieces<T, 2>* curve;
  std::vector<Piece<T>> unit;
  std::vector<std::vector<T>> weights;  // normalised weights per piece (1 for polynomial)
  std::vector<Arc<T>> arcs;
  std::vector<Piece<T>> arc_parts;   // each arc as a curve of its own on [0, 1]
  std::vector<Box<T, 2>> arc_boxes;  // control box of each arc's part
  T size = 0;  // diagonal of the control box, in unit coordinates
};

/// Bernstein coefficients of the numerator of coordinate k minus X: w_i (P_ik - X)
/// (weights 1 for a polynomial piece). Its roots are where the piece meets the line
/// coordinate k = X; the sign is the side.
template <class T>
std::vector<T> coordinate_numerator(const Piece<T>& c, const std::vector<T>& w, int k, T X) {
  const auto& P = points(c);
  std::vector<T> a(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) a[i] = w[i] * (P[i][k] - X);
  return a;
}

/// Coefficients of a polynomial whose sign is that of d/dt coordinate k: the hodograph
/// n (P_(i+1) - P_i) for a polynomial piece; N' w - N w' (degree 2n - 1, quotient rule)
/// with N the numerator (P - P_0) w for a rational piece.
template <class T>
std::vector<T> derivative_numerator(const Piece<T>& c, const std::vector<T>& w, int k) {
  const auto& P = points(c);
  const std::size_t n = P.size() - 1;
  std::vector<T> d(n);
  if (std::holds_alternative<Bezier<T, 2>>(c)) {
    for (std::size_t i = 0; i < n; ++i) d[i] = P[i + 1][k] - P[i][k];
    return d;
  }
  const std::vector<T> N = coordinate_numerator(c, w, k, P[0][k]);
  std::vector<T> dw(n);
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = N[i + 1] - N[i];
    dw[i] = w[i + 1] - w[i];
  }
  const auto p1 = bernstein_product<T>(d, w), p2 = bernstein_product<T>(N, dw);
  std::vector<T> r(p1.size());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = p1[i] - p2[i];
  return r;
}

template <class T>
Box<T, 2> grown(Box<T, 2> b, T by) {
  for (int d = 0; d < 2; ++d) {
    b.lo[d] -= by;
    b.hi[d] += by;
  }
  return b;
}
template <class T>
bool boxes_meet(const Box<T, 2>& a, const Box<T, 2>& b, T slack) {
  for (int d = 0; d < 2; ++d) {
    if (a.lo[d] > b.hi[d] + slack || b.lo[d] > a.hi[d] + slack) return false;
  }
  return true;
}
template <class T>
T diagonal(const Box<T, 2>& b) {
  return norm(b.hi - b.lo);
}

/// The closest points of the chords [p0, p1] and [q0, q1] (core/segment.hpp): their
/// parameters (u, v) in [0, 1] and distance.
template <class T>
struct SegmentClosest {
  T u, v, distance;
};
template <class T>
SegmentClosest<T> chord_closest(const Point<T, 2>& p0, const Point<T, 2>& p1, const Point<T, 2>& q0, const Point<T, 2>& q1) {
  const auto [u, v] = casteljau::closest_on_segments(p0, p1, q0, q1);
  return {u, v, norm((p0 + u * (p1 - p0)) - (q0 + v * (q1 - q0)))};
}

/// Whether no tangent line of one part is parallel to a tangent line of the other: then
/// the parts meet at most once [SederbergMeyers88] and one refined seed finds the point.
template <class T>
bool cones_separated(const Cone<T>& a, const Cone<T>& b) {
  constexpr T pi = std::numbers::pi_v<T>;
  const T phi = std::atan2(cross(a.ref, b.ref), dot(a.ref, b.ref));
  // Angles of b's directions minus a's, and their range; no multiple of pi inside it.
  const T lo = b.lo + phi - a.hi, hi = b.hi + phi - a.lo;
  const T margin = T(1e-6);
  const T k = std::ceil((lo - margin) / pi);
  return k * pi > hi + margin;
}

/// Whether the control points of b all lie outside the fat line of a (the band along a's
/// chord holding a's control points, widened by slack) on one side: then the parts are
/// apart [SederbergNishita90]. Unlike control boxes, fat lines follow the parts' direction,
/// so two curves running side by side at a distance d (near-coincident curves) are told
/// apart once their parts bend by less than d, not only once the parts are shorter than d:
/// a few hundred parts instead of millions. Rational parts too (their points lie in the
/// convex hull of their control points, the weights being positive).
template <class CA, class CB>
bool fat_line_apart(const CA& a, const CB& b, typename CA::Scalar slack) {
  using T = typename CA::Scalar;
  const auto& P = a.points();
  const Vector<T, 2> chord = P.back() - P.front();
  const T len = norm(chord);
  if (!(len > 0)) return false;
  const Vector<T, 2> n{-chord[1] / len, chord[0] / len};
  T dmin = 0, dmax = 0;
  for (const auto& p : P) {
    const T d = dot(p - P.front(), n);
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
  }
  bool above = true, below = true;
  for (const auto& q : b.points()) {
    const T d = dot(q - P.front(), n);
    above = above && d > dmax + slack;
    below = below && d < dmin - slack;
    if (!above && !below) return false;
  }
  return true;
}

/// Largest number of subdivision steps one pair of arcs may take; a pair of transversal
/// arcs takes a few hundred. Hitting it means the curves run within the tolerance of each
/// other over a long stretch without coinciding: reported, not silently truncated.
inline constexpr std::size_t max_nodes = 2'000'000;
/// The most common points an answer may list: a random 3,000-point polyline meets itself
/// about 2.5 million times (a 114 MB answer). Past it the request is refused rather than
/// answered in hundreds of megabytes; the raw points found on the way (before merging,
/// about one per point for lines, a few for curves) are capped at twice this.
inline constexpr std::size_t max_points = 100'000;

/// The refusal past max_points.
[[noreturn]] inline void too_many_points(std::size_t found) {
  throw InvalidArgument("curves", "the curves meet in more than " + std::to_string(max_points) + " points (" + std::to_string(found) +
                                      " found before stopping): the answer is refused as too large");
}
/// Depth at which a part counts as flat whatever its shape (2^-50 of the piece: below the
/// resolution of the parameters of double).
inline constexpr int max_depth = 50;

/// Bounding-box subdivision of two arcs (Bezier or RationalBezier parts a on [alo, ahi],
/// b on [blo, bhi] of their pieces' parameters) down to parts flat within ctx.flat; each
/// pair of flat parts whose chords come within 2 flat + slack gives a seed (the chords'
/// closest points), later refined on the curves themselves.
template <class T, class CA, class CB>
void subdivide(const CA& a, T alo, T ahi, int da, const CB& b, T blo, T bhi, int db, Context<T>& ctx, bool bands = true) {
  if (ctx.exhausted || (ctx.near && ctx.stop_on_near)) return;
  if (++ctx.nodes > ctx.node_limit) {
    ctx.exhausted = true;
    return;
  }
  const Box<T, 2> ba = a.control_bounds(), bb = b.control_bounds();
  if (!boxes_meet(ba, bb, ctx.slack)) return;
  if (fat_line_apart(a, b, ctx.slack) || fat_line_apart(b, a, ctx.slack)) return;
  const bool fa = da >= max_depth || is_flat(a, ctx.flat), fb = db >= max_depth || is_flat(b, ctx.flat);
  if (fa && fb) {
    const auto& P = a.points();
    const auto& Q = b.points();
    const auto c = chord_closest(P.front(), P.back(), Q.front(), Q.back());
    if (c.distance <= 2 * ctx.flat + ctx.slack) ctx.seeds.push_back({alo + c.u * (ahi - alo), blo + c.v * (bhi - blo)});
    return;
  }
  // Parts whose tangent cones are separated meet at most once: one seed, at the closest
  // points of their chords, which the refinement takes to the crossing or, where the
  // parts do not meet, to their closest approach (then discarded as a near miss).
  if (const auto ka = tangent_cone(a)) {
    if (const auto kb = tangent_cone(b); kb && cones_separated(*ka, *kb)) {
      const auto& P = a.points();
      const auto& Q = b.points();
      const auto c = chord_closest(P.front(), P.back(), Q.front(), Q.back());
      ctx.seeds.push_back({alo + c.u * (ahi - alo), blo + c.v * (bhi - blo)});
      return;
    }
  }
  // Near-coincident parts (narrow tangent cones along one direction): decided at once on
  // the separation polynomial instead of subdivided down to the near-miss distance.
  bool split_longer = false;
  if (bands) {
    const BandResult r = band(a, alo, ahi, b, blo, bhi, ctx);
    if (r == BandResult::done) return;
    bands = r != BandResult::too_far;
    // A part much longer than the other (a line against a short stretch of a curve near
    // a touch) stretches the other's core out of the cone: the longer one is split, flat
    // or not, until bands apply (else two crossings in one pair of flat parts would give
    // one seed, and one of them would be missed).
    split_longer = r == BandResult::too_long;
  }
  const bool split_a = split_longer ? da < max_depth && (diagonal(ba) >= diagonal(bb) || db >= max_depth)
                                    : !fa && (fb || diagonal(ba) >= diagonal(bb));
  if (split_a) {
    const auto h = a.split(T(0.5));
    const T m = alo + (ahi - alo) / 2;
    subdivide(h.left, alo, m, da + 1, b, blo, bhi, db, ctx, bands);
    subdivide(h.right, m, ahi, da + 1, b, blo, bhi, db, ctx, bands);
  } else {
    const auto h = b.split(T(0.5));
    const T m = blo + (bhi - blo) / 2;
    subdivide(a, alo, ahi, da, h.left, blo, m, db + 1, ctx, bands);
    subdivide(a, alo, ahi, da, h.right, m, bhi, db + 1, ctx, bands);
  }
}

/// Refined common point (s, t) of pieces a and b within [a_lo, a_hi] x [b_lo, b_hi],
/// started at a seed, and its distance |a(s) - b(t)|.
template <class T>
struct Refined {
  T s, t, distance;
};

/// Newton's method on F(s, t) = a(s) - b(t) = 0 with the Jacobian [a'(s), -b'(t)]; where
/// that is near singular (tangent curves, a vanishing derivative) a Levenberg-Marquardt
/// step on |F|^2 instead, and steps halved until |F| decreases. Parameters stay in the
/// arcs. Quadratic convergence to about eps / sin(angle) at crossings, linear at touches
/// (which are located to about sqrt(eps) in the parameters, the conditioning of a double
/// root). At most 100 steps; returns the best point seen.
template <class T>
Refined<T> refine(const Piece<T>& a, const Arc<T>& aa, const Piece<T>& b, const Arc<T>& ab, T s, T t) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  auto clamp_s = [&](T x) { return std::clamp(x, aa.lo, aa.hi); };
  auto clamp_t = [&](T x) { return std::clamp(x, ab.lo, ab.hi); };
  s = clamp_s(s);
  t = clamp_t(t);
  Vector<T, 2> F = at(a, s) - at(b, t);
  T f = norm(F);
  for (int it = 0; it < 100 && f > 0; ++it) {
    const Vector<T, 2> Ja = derivative(a, s), Jb = derivative(b, t);
    const T det = cross(Ja, Jb), na = norm(Ja), nb = norm(Jb);
    T ds, dt;
    if (std::abs(det) > T(1e-8) * na * nb && na > 0 && nb > 0) {
      ds = -cross(F, Jb) / det;
      dt = cross(Ja, F) / det;
    } else {
      // (M^T M + mu I) d = -M^T F with M = [Ja, -Jb].
      const T aa2 = dot(Ja, Ja), bb2 = dot(Jb, Jb), ab2 = -dot(Ja, Jb);
      const T mu = T(1e-12) * (aa2 + bb2) + std::numeric_limits<T>::min();
      const T g0 = dot(Ja, F), g1 = -dot(Jb, F);
      const T m00 = aa2 + mu, m11 = bb2 + mu, dd = m00 * m11 - ab2 * ab2;
      if (!(dd > 0)) break;
      ds = -(m11 * g0 - ab2 * g1) / dd;
      dt = -(m00 * g1 - ab2 * g0) / dd;
    }
    if (!std::isfinite(ds) || !std::isfinite(dt)) break;
    // A step at the resolution of the parameters: converged. Taken if it helps, without
    // the halvings below (which would cost 30 evaluations of each curve for nothing).
    if (std::abs(ds) <= 4 * eps * std::max(T(1), std::abs(s)) && std::abs(dt) <= 4 * eps * std::max(T(1), std::abs(t))) {
      const T s2 = clamp_s(s + ds), t2 = clamp_t(t + dt);
      const Vector<T, 2> F2 = at(a, s2) - at(b, t2);
      if (norm(F2) < f) {
        s = s2;
        t = t2;
        f = norm(F2);
      }
      break;
    }
    bool improved = false;
    for (int half = 0; half < 30; ++half) {
      const T s2 = clamp_s(s + ds), t2 = clamp_t(t + dt);
      const Vector<T, 2> F2 = at(a, s2) - at(b, t2);
      const T f2 = norm(F2);
      if (f2 < f || (f2 == f && (s2 != s || t2 != t) && half == 0)) {
        const bool tiny = std::abs(s2 - s) <= 2 * eps * std::max(T(1), std::abs(s)) && std::abs(t2 - t) <= 2 * eps * std::max(T(1), std::abs(t));
        s = s2;
        t = t2;
        F = F2;
        improved = f2 < f;
        f = f2;
        if (tiny) improved = false;
        break;
      }
      ds /= 2;
      dt /= 2;
    }
    if (!improved) break;
  }
  return {s, t, f};
}

/// Polish of a touch (s, t) found by refine(): Newton's method on G(s, t) = ((a(s) -
/// b(t)) . b'(t), a'(s) x b'(t)) = 0 (a(s)'s foot on b is b(t), and the tangents are
/// parallel), whose root is simple at a touch of curves with different curvatures,
/// where F = a - b has a double root. Gives the touch to a few eps instead of sqrt(eps).
/// Returns the polished point if Newton converged (at most 16 steps) to a common point
/// (distance <= tol) within 1e-5 of the start, else nothing.
template <class T>
std::optional<Refined<T>> polish_touch(const Piece<T>& a, const Arc<T>& aa, const Piece<T>& b, const Arc<T>& ab, Refined<T> r,
                                       T tol) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  T s = r.s, t = r.t;
  for (int it = 0; it < 16; ++it) {
    const Vector<T, 2> F = at(a, s) - at(b, t), a1 = derivative(a, s), a2 = derivative(a, s, 2), b1 = derivative(b, t),
                       b2 = derivative(b, t, 2);
    const T g1 = dot(F, b1), g2 = cross(a1, b1);
    const T j11 = dot(a1, b1), j12 = dot(F, b2) - dot(b1, b1), j21 = cross(a2, b1), j22 = cross(a1, b2);
    const T det = j11 * j22 - j12 * j21;
    if (!(std::abs(det) > 0)) return std::nullopt;
    const T ds = -(g1 * j22 - j12 * g2) / det, dt = -(j11 * g2 - j21 * g1) / det;
    if (!std::isfinite(ds) || !std::isfinite(dt)) return std::nullopt;
    s = std::clamp(s + ds, aa.lo, aa.hi);
    t = std::clamp(t + dt, ab.lo, ab.hi);
    if (std::abs(s - r.s) > T(1e-5) || std::abs(t - r.t) > T(1e-5)) return std::nullopt;
    if (std::abs(ds) <= 4 * eps * std::max(T(1), std::abs(s)) && std::abs(dt) <= 4 * eps * std::max(T(1), std::abs(t))) {
      const T d = distance(at(a, s), at(b, t));
      if (d <= tol) return Refined<T>{s, t, d};
      return std::nullopt;
    }
  }
  return std::nullopt;
}

/// A direction of the curve at t: the first non-zero derivative (a cusp's direction comes
/// from the second).
template <class T>
Vector<T, 2> direction(const Piece<T>& c, T t) {
  for (int k = 1; k <= std::max(1, degree(c)); ++k) {
    const Vector<T, 2> v = derivative(c, t, k);
    const T n = norm(v);
    if (n > 0) return v / n;
  }
  return Vector<T, 2>{};
}

/// A piece evaluated with its first two derivatives for foot-point steps: past degree 32
/// a polynomial piece through the Bernstein coefficients of its coordinates and their
/// differences in O(n) (bernstein_value_fast: about n eps of the coefficients, 5e-14 at
/// degree 500 in the unit frame, far below the near-miss distance), where de Casteljau
/// costs O(n^2) per value (most of the time of two coincident degree-500 curves); else the
/// piece's own evaluation (so low degrees are computed as before).
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
};

/// Newton steps (at most 4) on (c(t) - q) . c'(t) from t within arc r of piece c, each
/// kept only if it brings c(t) closer to q: the foot of q near t.
template <class T>
T polish_foot(const FootEval<T>& c, const Arc<T>& r, const Point<T, 2>& q, T t) {
  for (int it = 0; it < 4; ++it) {
    const Vector<T, 2> e = c.at(t) - q, d1 = c.d(t), d2 = c.dd(t);
    const T den = dot(d1, d1) + dot(e, d2);
    if (!(den > 0)) break;
    const T t2 = std::clamp(t - dot(e, d1) / den, r.lo, r.hi);
    if (!(distance(c.at(t2), q) <= norm(e))) break;
    t = t2;
  }
  return t;
}

/// The weights of a piece's own control points (1 for a polynomial piece).
template <class T>
std::vector<T> own_weights(const Piece<T>& c) {
  if (const auto* r = std::get_if<RationalBezier<T, 2>>(&c)) return r->weights();
  return std::vector<T>(points(c).size(), T(1));
}

/// The parameter in arc `r` of piece c of the point q, if q lies within tol of the arc
/// (`part`: the arc as a curve of its own on [0, 1], A.arc_parts): the roots of each
/// coordinate's numerator minus q on the part (the arc is monotone in both, so at most one
/// lies in it unless that coordinate is constant; the part's roots only, not the whole
/// piece's: a random piece of degree 500 meets a line dozens of times, and isolating every
/// root took most of the time of two coincident curves) and the arc's ends, each polished
/// by Newton steps on (c(t) - q) . c'(t), the closest kept. Nothing at once when q lies
/// outside the part's control box grown by tol (the arc lies in it).
template <class T>
std::optional<T> locate(const FootEval<T>& c, const Piece<T>& part, const Box<T, 2>& part_box, const Arc<T>& r, const Point<T, 2>& q, T tol) {
  if (!part_box.contains(q, 2 * tol)) return std::nullopt;
  std::vector<T> cand{r.lo, r.hi};
  const std::vector<T> w = own_weights(part);
  for (int k = 0; k < 2; ++k) {
    const std::vector<T> num = coordinate_numerator(part, w, k, q[k]);
    for (T x : bernstein_roots<T>(num)) cand.push_back(std::clamp(r.lo + (r.hi - r.lo) * x, r.lo, r.hi));
  }
  std::optional<T> best;
  T best_d = std::numeric_limits<T>::infinity();
  for (T t : cand) {
    t = polish_foot(c, r, q, t);
    const T d = distance(c.at(t), q);
    if (d < best_d) {
      best_d = d;
      best = t;
    }
  }
  if (best_d <= tol) return best;
  return std::nullopt;
}

/// Overlap of arcs ra (of piece a) and rb (of piece b), as piece parameters: a on
/// [s0, s1] traces b from t0 to t1.
template <class T>
struct ArcOverlap {
  T s0, s1, t0, t1;
};

/// Whether arcs ia of A and ib of B coincide on an interval. Its ends are arc ends (see
/// Arc), so the candidates are the ends of each arc located on the other; the two extreme
/// ones bound the interval, which is then confirmed at m n + 1 interior points (m, n the
/// degrees, at least 3, at most 64): two distinct algebraic curves of degrees m and n
/// share at most m n points (Bézout), so curves that share more are the same curve there.
/// An interior point a(s) is first tried at b's parameter in the same proportion between
/// t0 and t1 (where a coinciding copy, re-parametrised by an affine map, has it), then by
/// Newton steps from there; located from scratch (locate) only where these miss it.
template <class T>
std::optional<ArcOverlap<T>> arc_overlap(const Prepared<T>& A, std::size_t ia, const Prepared<T>& B, std::size_t ib, T tol) {
  const Arc<T>& ra = A.arcs[ia];
  const Arc<T>& rb = B.arcs[ib];
  const Piece<T>& pa = A.unit[ra.piece];
  const Piece<T>& pb = B.unit[rb.piece];
  const FootEval<T> a(pa), b(pb);
  auto on_b = [&](const Point<T, 2>& q) { return locate(b, B.arc_parts[ib], B.arc_boxes[ib], rb, q, tol); };
  auto on_a = [&](const Point<T, 2>& q) { return locate(a, A.arc_parts[ia], A.arc_boxes[ia], ra, q, tol); };
  std::vector<std::pair<T, T>> ends;  // (s, t)
  for (T s : {ra.lo, ra.hi})
    if (auto t = on_b(a.at(s))) ends.emplace_back(s, *t);
  for (T t : {rb.lo, rb.hi})
    if (auto s = on_a(b.at(t))) ends.emplace_back(*s, t);
  if (ends.size() < 2) return std::nullopt;
  std::sort(ends.begin(), ends.end());
  const auto [s0, t0] = ends.front();
  const auto [s1, t1] = ends.back();
  if (!(s1 - s0 > T(1e-9) * (ra.hi - ra.lo)) || !(std::abs(t1 - t0) > T(1e-9) * (rb.hi - rb.lo))) return std::nullopt;
  const int k = std::clamp(degree(pa) * degree(pb) + 1, 3, 64);
  const T tlo = std::min(t0, t1), thi = std::max(t0, t1), tm = T(1e-9) * (rb.hi - rb.lo);
  for (int j = 1; j <= k; ++j) {
    const T f = static_cast<T>(j) / static_cast<T>(k + 1);
    const T s = s0 + (s1 - s0) * f;
    const Point<T, 2> q = a.at(s);
    T guess = std::clamp(t0 + (t1 - t0) * f, tlo, thi);
    if (distance(b.at(guess), q) <= tol) continue;
    guess = polish_foot(b, rb, q, guess);
    if (guess >= tlo - tm && guess <= thi + tm && distance(b.at(guess), q) <= tol) continue;
    const auto t = on_b(q);
    if (!t || *t < tlo - tm || *t > thi + tm) return std::nullopt;
  }
  return ArcOverlap<T>{s0, s1, t0, t1};
}

/// Splits every piece at the roots of its coordinates' derivatives (interior ones), so
/// that each arc is monotone in x and in y.
template <class T>
void make_arcs(Prepared<T>& p) {
  for (std::size_t i = 0; i < p.unit.size(); ++i) {
    std::vector<T> cuts{T(0), T(1)};
    if (degree(p.unit[i]) >= 2) {
      for (int k = 0; k < 2; ++k) {
        const auto num = derivative_numerator(p.unit[i], p.weights[i], k);
        for (T r : bernstein_roots<T>(num))
          if (r > 0 && r < 1) cuts.push_back(r);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
      if (cuts[j + 1] - cuts[j] > T(1e-12)) p.arcs.push_back({i, cuts[j], cuts[j + 1]});
      else if (j + 2 == cuts.size() && !p.arcs.empty() && p.arcs.back().piece == i) p.arcs.back().hi = cuts[j + 1];
    }
  }
}

/// Prepares a curve: unit-scale copies of its pieces (origin and e shared by both
/// curves: coordinates (P - origin) 2^-e) and its arcs.
template <class T>
Prepared<T> prepare(const Pieces<T, 2>& c, const Point<T, 2>& origin, int e) {
  Prepared<T> p{&c, {}, {}, {}, {}, {}, 0};
  Box<T, 2> box = Box<T, 2>::empty_box();
  for (const auto& s : c.segments()) {
    std::visit(
        [&](const auto& x) {
          auto u = normalised_copy(x, origin, e);
          box.add(u.control_bounds());
          std::vector<T> w(x.points().size(), T(1));
          if constexpr (requires { x.weights(); }) {
            const T wmax = *std::max_element(x.weights().begin(), x.weights().end());
            for (std::size_t i = 0; i < w.size(); ++i) w[i] = x.weights()[i] / wmax;
          }
          p.unit.emplace_back(std::move(u));
          p.weights.push_back(std::move(w));
        },
        s);
  }
  p.size = diagonal(box);
  make_arcs(p);
  for (const auto& r : p.arcs) {
    p.arc_parts.push_back(std::visit([&](const auto& x) { return Piece<T>(part(x, r.lo, r.hi)); }, p.unit[r.piece]));
    p.arc_boxes.push_back(std::visit([](const auto& x) { return x.control_bounds(); }, p.arc_parts.back()));
  }
  return p;
}

/// A common point in piece parameters before it is lifted to the curves' parameters.
template <class T>
struct Hit {
  T ta, tb;  // curve parameters
  std::size_t pa, pb;
  T sa, sb;  // piece parameters
  T distance;
  bool touch = false;  // two crossings merged into a touch
  bool edge = false;   // from an edge seed (see band())
};

/// Subdivision steps of the first pass over a pair of arcs, before the overlap test: a
/// few hundred suffice for transversal arcs; coinciding arcs take many more.
inline constexpr std::size_t lazy_nodes = 2000;

/// The common points of two arcs (subdivision, then refinement of each seed) appended to
/// hits. Returns false when the arcs may overlap: the node limit was reached (the seeds
/// are then incomplete), a point has parallel tangents (every point of an overlap does)
/// or a band lies within tol all along (with ctx.stop_on_near the pass stops there, and
/// its points are incomplete too).
template <class T>
bool intersect_arcs(const Prepared<T>& A, std::size_t ia, const Prepared<T>& B, std::size_t ib, Context<T>& ctx,
                    std::size_t node_limit, std::vector<Hit<T>>& hits) {
  const Arc<T>& ra = A.arcs[ia];
  const Arc<T>& rb = B.arcs[ib];
  const Piece<T>& a = A.unit[ra.piece];
  const Piece<T>& b = B.unit[rb.piece];
  ctx.seeds.clear();
  ctx.nodes = 0;
  ctx.node_limit = node_limit;
  ctx.exhausted = false;
  ctx.a = &a;
  ctx.b = &b;
  ctx.ra = &ra;
  ctx.rb = &rb;
  ctx.near = false;
  std::visit(
      [&](const auto& x, const auto& y) { subdivide(x, ra.lo, ra.hi, 0, y, rb.lo, rb.hi, 0, ctx); }, A.arc_parts[ia],
      B.arc_parts[ib]);
  if (ctx.exhausted || (ctx.near && ctx.stop_on_near)) return false;
  bool clean = true;
  // Refined points so far, by s: seeds from neighbouring parts refine to the same point
  // (thousands of them along near-coincident curves), found again in O(log) each.
  std::multimap<T, T> done;
  for (const auto& [s0, t0, edge] : ctx.seeds) {
    Refined<T> r = refine(a, ra, b, rb, s0, t0);
    if (!(r.distance <= ctx.tol)) continue;
    // A touch refined as a double root is located to about sqrt(eps / curvature) only,
    // where the tangents of a curve of high curvature (a Chebyshev polynomial of degree
    // 12 touching y = 1: curvature about 1e4 per unit parameter) already differ by more
    // than 1e-6: the polish (parallel tangents, a common point within 1e-5 in the
    // parameters) is tried up to 1e-4, and where it finds the touch the point is there.
    const T angle = std::abs(cross(direction(a, r.s), direction(b, r.t)));
    if (angle <= T(1e-6)) clean = false;
    if (angle <= T(1e-4)) {
      if (auto p = polish_touch(a, ra, b, rb, r, ctx.tol)) r = *p;
    }
    bool dup = false;
    for (auto it = done.lower_bound(r.s - T(1e-12)); !dup && it != done.end() && it->first <= r.s + T(1e-12); ++it)
      dup = std::abs(it->second - r.t) <= T(1e-12);
    if (dup) continue;
    done.emplace(r.s, r.t);
    hits.push_back({A.curve->lift(ra.piece, r.s), B.curve->lift(rb.piece, r.t), ra.piece, rb.piece, r.s,
                    r.t, r.distance, false, edge});
  }
  // Arc ends common to both arcs (within tol) where the arcs are tangent: a touch at the
  // end, where the curves part slowly (a conic leaving its control polygon's leg as t^2 /
  // W). A seed near it may refine to a point of the near region beyond the distance (the
  // leg first: 1.1e-10 from the conic [1, 1e3, 1] near its end (0, 1)) and lose the touch.
  // The arcs' ends are their parts' end control points (no evaluation: the general
  // engine's cost per pair of arcs stays).
  const auto& Pa = points(A.arc_parts[ia]);
  const auto& Pb = points(B.arc_parts[ib]);
  for (const bool ea : {false, true}) {
    for (const bool eb : {false, true}) {
      const Vector<T, 2> v = (ea ? Pa.back() : Pa.front()) - (eb ? Pb.back() : Pb.front());
      if (!(dot(v, v) <= ctx.tol * ctx.tol)) continue;
      const T d = norm(v);
      const T s = ea ? ra.hi : ra.lo, t = eb ? rb.hi : rb.lo;
      if (!(std::abs(cross(direction(a, s), direction(b, t))) <= T(1e-6))) continue;
      clean = false;
      bool dup = false;
      for (auto it = done.lower_bound(s - T(1e-12)); !dup && it != done.end() && it->first <= s + T(1e-12); ++it)
        dup = std::abs(it->second - t) <= T(1e-12);
      if (dup) continue;
      done.emplace(s, t);
      hits.push_back({A.curve->lift(ra.piece, s), B.curve->lift(rb.piece, t), ra.piece, rb.piece, s, t, d, false, false});
    }
  }
  return clean && !ctx.near;
}

/// Common points closer than this fraction of their pieces' parameter intervals (in
/// both parameters) are one point: touches are located to about sqrt(eps) ~ 1e-8, so a
/// touch found from several seeds or from two arcs meeting at it is reported once.
inline constexpr double merge_fraction = 1e-6;

/// The unit-frame point of a curve at its parameter g (pieces chosen as evaluation does).
template <class T>
Point<T, 2> unit_at(const Pieces<T, 2>& c, const Prepared<T>& P, T g) {
  const auto [p, t] = c.locate(g);
  return at(P.unit[p], t);
}

/// The foot of q on curve c near its parameter t (unit frame): Newton's method on
/// (c(t) - q) . c'(t) from t, over the pieces, within the domain; the parameter of the
/// least distance seen and that distance (an upper bound of the distance to the curve,
/// exact at a converged foot point).
template <class T>
struct Foot {
  T t, distance;
};
template <class T>
Foot<T> foot_near(const Pieces<T, 2>& c, const Prepared<T>& P, const Point<T, 2>& q, T t) {
  const Interval<T> dom = c.domain();
  Foot<T> best{t, std::numeric_limits<T>::infinity()};
  for (int it = 0; it < 12; ++it) {
    const auto [p, s] = c.locate(t);
    const T k = c.parameter_scale(p);
    const Point<T, 2> x = at(P.unit[p], s);
    const Vector<T, 2> e = x - q, d1 = k * derivative(P.unit[p], s), d2 = (k * k) * derivative(P.unit[p], s, 2);
    if (norm(e) < best.distance) best = {t, norm(e)};
    const T den = dot(d1, d1) + dot(e, d2);
    if (!(den > 0)) break;
    const T t2 = std::clamp(t - dot(e, d1) / den, dom.lo, dom.hi);
    if (t2 == t) break;
    t = t2;
  }
  return best;
}

/// The distance from q to curve c near its parameter t (see foot_near).
template <class T>
T distance_near(const Pieces<T, 2>& c, const Prepared<T>& P, const Point<T, 2>& q, T t) {
  return foot_near(c, P, q, t).distance;
}

/// The unit direction of curve c at its parameter g (pieces chosen as evaluation does).
template <class T>
Vector<T, 2> direction_at(const Pieces<T, 2>& c, const Prepared<T>& P, T g) {
  const auto [p, t] = c.locate(g);
  return direction(P.unit[p], t);
}

/// A curve's domain and whether the curve is closed (its ends within the near-miss
/// distance): on a closed curve the way between two parameters may pass its closing point.
template <class T>
struct Loop {
  Interval<T> dom;
  bool closed = false;
  /// The difference d of two parameters, the short way round a closed curve.
  T shortest(T d) const {
    const T L = dom.length();
    return closed && std::abs(d) > L / 2 ? d - std::copysign(L, d) : d;
  }
  /// A parameter up to one length beyond the domain of a closed curve, brought back in.
  T wrap(T t) const {
    if (!closed) return t;
    return t < dom.lo ? t + dom.length() : t > dom.hi ? t - dom.length() : t;
  }
};

/// The sine of the angle between unit tangents below which a common point counts as a
/// touch rather than a crossing when merging points of one near region: 64 eps, the
/// rounding of the cross product of two unit vectors computed from the curves (a few eps
/// each) with margin. Crossings of a touch region meet at angles of about sqrt(K tol)
/// (1e-6 or more at tol = 1e-10, K ~ 1), far above it.
template <class T>
inline constexpr T crossing_noise = 64 * std::numeric_limits<T>::epsilon();

/// The parameters of a touch region's ends: common points (ta0, tb0) and (ta1, tb1) of
/// curves a and b, ta0 <= ta1, between which the curves stay within the near-miss distance
/// (unwrapped round the closing point of a closed curve: ta1 may exceed its domain).
template <class T>
struct TouchSpan {
  T ta0, tb0, ta1, tb1;
};

/// The touch of curves a and b in a touch region (two crossings at a tiny angle, or points
/// near a touch): where the curves are closest, or farthest apart between two crossings,
/// i.e. the extremum of the signed separation of a(s) from b. Its derivative along a is
/// a'(s) . n_b at the foot of a(s) on b, so the touch is the root of g(s) = u_a(s) x u_b(t(s))
/// (unit tangents, t(s) the foot: tangents parallel). g changes sign between two crossings
/// (a passes b one way, then back), so the root is bracketed by the span's ends: regula
/// falsi with the Illinois modification [DowellJarratt71] to the resolution of the
/// parameters, at most 100 steps (a few tens). A simple root where the curvatures differ:
/// located to about eps over the difference of the curvatures (what polish_touch reaches).
/// Nothing when g does not change sign over the span or vanishes (to crossing_noise) at an
/// end, or when the touch is farther apart than tol.
template <class T>
std::optional<Hit<T>> touch_in(const Pieces<T, 2>& ca, const Prepared<T>& A, const Loop<T>& la, const Pieces<T, 2>& cb,
                               const Prepared<T>& B, const Loop<T>& lb, const TouchSpan<T>& span, T tol) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  auto foot = [&](T s) {
    // b's parameter interpolated along the span: the start of the foot's Newton steps.
    const T f = span.ta1 > span.ta0 ? (s - span.ta0) / (span.ta1 - span.ta0) : T(0.5);
    return foot_near(cb, B, unit_at(ca, A, la.wrap(s)), lb.wrap(span.tb0 + f * (span.tb1 - span.tb0)));
  };
  auto g = [&](T s) { return cross(direction_at(ca, A, la.wrap(s)), direction_at(cb, B, foot(s).t)); };
  T lo = span.ta0, hi = span.ta1, glo = g(lo), ghi = g(hi);
  T s = lo;
  // Ends where the tangents are parallel to rounding (a touch found as such, not a
  // crossing) bracket nothing.
  if (!(std::abs(glo) > crossing_noise<T>) || !(std::abs(ghi) > crossing_noise<T>) || (glo > 0) == (ghi > 0) || !(hi > lo)) {
    return std::nullopt;
  } else {
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 4 * eps * std::max(T(1), std::abs(lo)); ++it) {
      T m = (lo * ghi - hi * glo) / (ghi - glo);
      if (!(m > lo && m < hi)) m = lo + (hi - lo) / 2;
      const T gm = g(m);
      if (gm == 0) {
        lo = hi = m;
        break;
      }
      if ((gm > 0) == (ghi > 0)) {
        hi = m;
        ghi = gm;
        if (side == 1) glo /= 2;
        side = 1;
      } else {
        lo = m;
        glo = gm;
        if (side == -1) ghi /= 2;
        side = -1;
      }
    }
    s = std::abs(glo) <= std::abs(ghi) ? lo : hi;
  }
  const Foot<T> ft = foot(s);
  if (!(ft.distance <= tol)) return std::nullopt;
  s = la.wrap(s);
  const auto a = ca.locate(s), b = cb.locate(ft.t);
  return Hit<T>{s, ft.t, a.index, b.index, a.t, b.t, ft.distance, true};
}

/// Whether curves a and b, common at (ta, tb) (the end of an overlap), are still within
/// tol of each other beyond it: at a(ta + k da) against b near tb + k db (da, db the
/// overlap's extent, signed towards the outside; k = 1, or less where a domain ends
/// sooner). False when a curve ends within a quarter of the overlap's extent or turns
/// back there.
template <class T>
bool near_beyond(const Pieces<T, 2>& ca, const Prepared<T>& A, const Pieces<T, 2>& cb, const Prepared<T>& B, T ta, T tb, T da, T db,
                 T tol) {
  const Interval<T> dom_a = ca.domain(), dom_b = cb.domain();
  auto room = [](const Interval<T>& dom, T t, T d) {
    if (d == 0) return std::numeric_limits<T>::infinity();
    return (d > 0 ? dom.hi - t : t - dom.lo) / std::abs(d);
  };
  const T k = std::min({T(1), room(dom_a, ta, da), room(dom_b, tb, db)});
  if (!(k >= T(0.25))) return false;
  const T ta2 = std::clamp(ta + k * da, dom_a.lo, dom_a.hi), tb2 = std::clamp(tb + k * db, dom_b.lo, dom_b.hi);
  // A curve that turns back at the end (a fold: a curve running over itself along a line)
  // does not continue the overlap, whatever its points.
  if (dot(direction_at(ca, A, ta - da / 64), direction_at(ca, A, ta + k * da / 64)) < 0 ||
      dot(direction_at(cb, B, tb - db / 64), direction_at(cb, B, tb + k * db / 64)) < 0)
    return false;
  return distance_near(cb, B, unit_at(ca, A, ta2), tb2) <= tol;
}

// solve() runs the phases below in turn; each is a function of its inputs (the prepared
// curves, the near-miss distance) that a test can call alone.

/// The frame shared by both curves of solve() (core/unit_frame.hpp): origin at a's first
/// control point, e the exponent that brings the largest |P - origin| over the control
/// points of both curves into [0.5, 1) (0 when every point is the origin).
template <class T>
struct SharedFrame {
  Point<T, 2> origin;
  int e = 0;
};

/// Phase 1: the shared unit frame of curves a and b (b = a for self-intersections).
template <class T>
SharedFrame<T> shared_frame(const Pieces<T, 2>& ca, const Pieces<T, 2>& cb) {
  const Point<T, 2> origin = points(ca.segments().front()).front();
  T h = 0;
  for (const auto* c : {&ca, &cb})
    for (const auto& s : c->segments()) h = std::max(h, half_extent<T, 2>(points(s), origin));
  return {origin, h > 0 ? unit_exponent(h) : 0};
}

/// The near-miss distance of two prepared curves in their unit frame: 1e-10 of the larger
/// control-box diagonal (the contract's threshold), at least 64 eps of the unit
/// coordinates (|P| < 1: rounding when the curves are points or tiny far apart).
template <class T>
T near_miss(const Prepared<T>& A, const Prepared<T>& B) {
  return std::max(T(1e-10) * std::max(A.size, B.size), 64 * std::numeric_limits<T>::epsilon());
}

/// The intersection context of solve() for the near-miss distance tol.
template <class T>
Context<T> make_context(T tol) {
  return Context<T>{tol, tol, tol + 16 * std::numeric_limits<T>::epsilon(), 0, 0, false, {}, nullptr, nullptr, nullptr, nullptr, false};
}

/// An overlap found on one pair of arcs, in the curves' parameters, with the points that
/// pair gave (reported if the overlap turns out to lie inside a crossing or touch region:
/// confirm_overlaps) or, when the pair's first pass stopped early, the pair itself
/// (`deferred`), whose points are computed only if the overlap is rejected.
template <class T>
struct RawOverlap {
  CurveOverlap<T> o;
  std::vector<Hit<T>> found;
  std::vector<std::pair<std::size_t, std::size_t>> deferred;
  // The overlaps joined into this one (a.lo, a.hi, b_start, b_end); filled by join_overlaps.
  std::vector<std::array<T, 4>> parts = {};
};

/// All the common points of arc i of A and arc j of B (the engine's full pass: lazy_nodes
/// subdivision steps, then max_nodes). Throws NumericalError past max_nodes.
template <class T>
std::vector<Hit<T>> arc_points(const Prepared<T>& A, std::size_t i, const Prepared<T>& B, std::size_t j, Context<T>& ctx) {
  std::vector<Hit<T>> found;
  intersect_arcs(A, i, B, j, ctx, lazy_nodes, found);
  if (ctx.exhausted) {
    found.clear();
    intersect_arcs(A, i, B, j, ctx, max_nodes, found);
    if (ctx.exhausted) {
      throw NumericalError("intersect: more than " + std::to_string(max_nodes) +
                           " subdivision steps for one pair of arcs: the curves run within 1e-10 of their size of each "
                           "other without coinciding");
    }
  }
  return found;
}

/// What the pairs of arcs give: points, and overlaps arc by arc (in the order of the pairs).
template <class T>
struct ArcPairs {
  std::vector<Hit<T>> hits;
  std::vector<RawOverlap<T>> overlaps;
};

/// Phase 2: every pair of arcs (i of A, j of B; j > i when self, B being A) whose control
/// boxes meet within ctx.slack. Identical arcs give an overlap over the whole arc at once.
/// Otherwise a first pass stops at the first band along which the arcs stay within tol;
/// where that pass is not clean (a tangent point, the subdivision running long, a near
/// band) the overlap test (arc_overlap) runs, and an overlap keeps the pair's points (or
/// the pair, deferred); else the pair's points (arc_points where the pass stopped early).
/// Throws InvalidArgument past 2 max_points raw points.
template <class T>
ArcPairs<T> meet_arcs(const Prepared<T>& A, const Prepared<T>& B, bool self, Context<T>& ctx, bool tame = false) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  ArcPairs<T> out;
  // Two identical curves (the same pieces on the same domains, arc for arc): each arc is
  // an overlap with itself (below), and these join into one overlap over both domains,
  // inside which every common point lies. So the other pairs (i, j) need only the overlap
  // test, for a curve that runs over itself; their points are deferred to arc i's own
  // overlap (computed only if that is rejected). Subdividing them as any pair took most
  // of the time of a degree-500 curve and its copy (pairs of consecutive arcs touch at
  // their common end: the overlap test ran, then the points were found and dropped).
  const bool same = !self && !tame && A.arcs.size() == B.arcs.size() && ca.size() == cb.size() && [&] {
    for (std::size_t p = 0; p < ca.size(); ++p)
      if (!(ca.segment_domain(p) == cb.segment_domain(p)) || !(ca.own_domain(p) == cb.own_domain(p))) return false;
    for (std::size_t k = 0; k < A.arcs.size(); ++k)
      if (A.arcs[k].piece != B.arcs[k].piece || !(A.arc_parts[k] == B.arc_parts[k])) return false;
    return true;
  }();
  std::vector<std::size_t> own(same ? A.arcs.size() : 0);  // arc i's own overlap in out.overlaps
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> later(own.size());
  for (std::size_t i = 0; i < A.arcs.size(); ++i) {
    for (std::size_t j = self ? i + 1 : 0; j < B.arcs.size(); ++j) {
      const Arc<T>& ra = A.arcs[i];
      const Arc<T>& rb = B.arcs[j];
      if (!boxes_meet(A.arc_boxes[i], B.arc_boxes[j], ctx.slack)) continue;
      // The same arc on both sides (identical curves, or a curve that repeats a piece):
      // an overlap over the whole arc, without subdividing two coincident arcs down to
      // the near-miss distance all along (20 s for a degree-500 curve and its copy).
      if (A.arc_parts[i] == B.arc_parts[j]) {
        if (same && i == j) own[i] = out.overlaps.size();
        out.overlaps.push_back(
            RawOverlap<T>{{ca.lift(ra.piece, Interval<T>(ra.lo, ra.hi)), cb.lift(rb.piece, rb.lo), cb.lift(rb.piece, rb.hi)}, {}, {}});
        continue;
      }
      if (same) {
        if (auto o = arc_overlap(A, i, B, j, ctx.tol)) {
          out.overlaps.push_back(
              RawOverlap<T>{{ca.lift(ra.piece, Interval<T>(o->s0, o->s1)), cb.lift(rb.piece, o->t0), cb.lift(rb.piece, o->t1)}, {}, {{i, j}}});
        } else {
          later[i].emplace_back(i, j);
        }
        continue;
      }
      // The overlap test (a few root solves) only where the arcs may overlap: a tangent
      // point found, or the subdivision running long.
      // The first pass stops at the first band along which the arcs stay within tol (an
      // overlap is then likely; its points are computed only if the overlap test fails or
      // the overlap is later rejected).
      std::vector<Hit<T>> found;
      ctx.stop_on_near = true;
      const bool clean = intersect_arcs(A, i, B, j, ctx, lazy_nodes, found);
      ctx.stop_on_near = false;
      if (!clean) {
        const bool stopped = ctx.near && !ctx.exhausted;
        if (auto o = arc_overlap(A, i, B, j, ctx.tol)) {
          RawOverlap<T> raw{{ca.lift(ra.piece, Interval<T>(o->s0, o->s1)), cb.lift(rb.piece, o->t0), cb.lift(rb.piece, o->t1)}, {}, {}};
          if (stopped) {
            raw.deferred.emplace_back(i, j);
          } else {
            raw.found = std::move(found);
          }
          out.overlaps.push_back(std::move(raw));
          continue;
        }
        if (stopped || ctx.exhausted) found = arc_points(A, i, B, j, ctx);
      }
      out.hits.insert(out.hits.end(), found.begin(), found.end());
      if (out.hits.size() > 2 * max_points) too_many_points(out.hits.size());
    }
  }
  for (std::size_t i = 0; i < later.size(); ++i)
    for (const auto& p : later[i]) out.overlaps[own[i]].deferred.push_back(p);
  return out;
}

/// p extended by r, which continues it: p's end becomes r's, r's points join p's.
template <class T>
void absorb(RawOverlap<T>& p, RawOverlap<T>& r) {
  p.o.a.hi = r.o.a.hi;
  p.o.b_end = r.o.b_end;
  p.found.insert(p.found.end(), r.found.begin(), r.found.end());
  p.deferred.insert(p.deferred.end(), r.deferred.begin(), r.deferred.end());
  p.parts.insert(p.parts.end(), r.parts.begin(), r.parts.end());
}

/// Phase 3: the overlaps found arc by arc, sorted by their start on a, joined where one
/// continues the previous (its start within 1e-9 of la (a's domain length) of the
/// previous end on a, within 1e-9 lb on b, b running the same way); the points and
/// deferred pairs of joined ones go together. Stable for equal starts.
template <class T>
std::vector<RawOverlap<T>> join_overlaps(std::vector<RawOverlap<T>> overlaps, T la, T lb) {
  std::sort(overlaps.begin(), overlaps.end(), [](const auto& x, const auto& y) { return x.o.a.lo < y.o.a.lo; });
  const T ma = T(1e-9) * la, mb = T(1e-9) * lb;
  // Whether r lies inside p and runs as p does there: its a within p's, its b within the b
  // of a part of p whose a meets r's (a sliver that two consecutive arcs of a copy moved
  // along its tangent share with the wrong neighbour, 1e-10 long, inside the stretch that
  // the neighbours' own overlaps cover: it broke their join, and the copy was answered as
  // points). A stretch that a curve runs over twice is no such part: its b lies elsewhere.
  auto inside = [&](const RawOverlap<T>& p, const RawOverlap<T>& r) {
    const auto& o = r.o;
    if ((o.b_end > o.b_start) != (p.o.b_end > p.o.b_start)) return false;
    if (o.a.lo < p.o.a.lo - ma || o.a.hi > p.o.a.hi + ma) return false;
    const T blo = std::min(o.b_start, o.b_end), bhi = std::max(o.b_start, o.b_end);
    for (const auto& c : p.parts) {
      if (c[0] > o.a.hi + ma || c[1] < o.a.lo - ma) continue;
      if (std::min(c[2], c[3]) <= blo + mb && std::max(c[2], c[3]) >= bhi - mb) return true;
    }
    return false;
  };
  std::vector<RawOverlap<T>> joined;
  for (auto& r : overlaps) {
    const auto& o = r.o;
    if (r.parts.empty()) r.parts.push_back({o.a.lo, o.a.hi, o.b_start, o.b_end});
    if (!joined.empty()) {
      auto& p = joined.back();
      if (std::abs(o.a.lo - p.o.a.hi) <= ma && std::abs(o.b_start - p.o.b_end) <= mb &&
          ((o.b_end > o.b_start) == (p.o.b_end > p.o.b_start))) {
        absorb(p, r);
        continue;
      }
      if (inside(p, r)) {  // its points and pairs join p's; p's ends stay
        p.found.insert(p.found.end(), r.found.begin(), r.found.end());
        p.deferred.insert(p.deferred.end(), r.deferred.begin(), r.deferred.end());
        continue;
      }
    }
    joined.push_back(std::move(r));
  }
  return joined;
}

/// Whether curve X over [x0, x1] stays within tol of curve Y over [y0, y1], Y taken there
/// as the polyline through 17 points of each of its pieces in the range (its ends, and a
/// corner between pieces, among them), X checked at 17 points of each of its pieces in
/// the range (unit frame).
template <class T>
bool stays_near(const Prepared<T>& X, T x0, T x1, const Prepared<T>& Y, T y0, T y1, T tol) {
  auto samples = [](const Prepared<T>& C, T c0, T c1) {
    std::vector<Point<T, 2>> q;
    C.curve->for_each_piece(Interval<T>(std::min(c0, c1), std::max(c0, c1)), [&](std::size_t i, const auto&, const Interval<T>& own) {
      for (int j = 0; j <= 16; ++j) q.push_back(at(C.unit[i], own.lo + (own.hi - own.lo) * static_cast<T>(j) / 16));
    });
    if (q.empty()) q.push_back(unit_at(*C.curve, C, c0));
    return q;
  };
  const std::vector<Point<T, 2>> q = samples(Y, y0, y1);
  for (const auto& p : samples(X, x0, x1)) {
    T d = distance(p, q.front());
    for (std::size_t k = 1; k < q.size() && d > tol; ++k) d = std::min(d, distance_to_segment(p, q[k - 1], q[k]));
    if (!(d <= tol)) return false;
  }
  return true;
}

/// Phase 3, tame parts only (solve_extreme): consecutive joined overlaps also join across
/// a gap (b running on the same way) over which one curve stays within tol of the other
/// (stays_near, either way: the contract's overlap is a whole arc of one curve within the
/// distance of the other).
/// A curve hugging its control polygon turns the corner within rounding of it: the
/// conic on (1, 0), (1, 1), (0, 1) with weights 1, 1e16, 1 passes 5e-17 from (1, 1), and
/// the tame parts that turn it map to one point of the polygon, so the overlaps along the
/// two legs end and start there, several parts apart on the conic. Joined, they are the
/// one overlap the curves have (the whole conic within 5e-17 of its polygon, mpmath),
/// which the corner's parts alone would not be (no length on the polygon), leaving two
/// stretches that each continue near the other curve (confirm_overlaps: their points,
/// merged into one "crossing" at the corner). Either way suffices: the conic's corner is
/// within tol of the polygon from w = 1 / (2 tol) - 1 (3.54e9 at the size sqrt(2)), the
/// polygon's corner within tol of the conic only from twice that (it lies sqrt(2) times as
/// far: 1.41e-10 at w = 5e9), so for w from 3.54e9 to 7.07e9 the answer was one crossing.
template <class T>
void bridge_overlaps(const Prepared<T>& A, const Prepared<T>& B, std::vector<RawOverlap<T>>& overlaps, T tol) {
  const T la = A.curve->domain().length(), lb = B.curve->domain().length();
  std::vector<RawOverlap<T>> joined;
  for (auto& r : overlaps) {
    if (!joined.empty()) {
      auto& p = joined.back();
      const auto& o = r.o;
      const bool up = p.o.b_end > p.o.b_start;
      const T da = o.a.lo - p.o.a.hi, db = up ? o.b_start - p.o.b_end : p.o.b_end - o.b_start;
      const bool same_way = (o.b_end > o.b_start) == up;
      const bool bridged = same_way && da >= -T(1e-9) * la && db >= -T(1e-9) * lb &&
                           (stays_near(A, p.o.a.hi, o.a.lo, B, p.o.b_end, o.b_start, tol) ||
                            stays_near(B, p.o.b_end, o.b_start, A, p.o.a.hi, o.a.lo, tol));
      if (bridged) {
        absorb(p, r);
        continue;
      }
    }
    joined.push_back(std::move(r));
  }
  overlaps = std::move(joined);
}

/// Phase 4: the joined overlaps that are overlaps. An overlap is a stretch within the
/// near-miss distance that ends where the curves part or a curve ends. One that the curves
/// continue beyond, still within the near-miss distance as far again past one of its ends
/// (near_beyond), is a piece of a longer near region (a crossing or touch at a tiny angle,
/// seen between joints of pieces or arcs: two circles of radius 1 with centres d apart
/// meet at an angle d and stay within tol over 2 tol / d around each crossing): its
/// points are reported instead, as they are off the joints.
///
/// Nor is one that holds no whole monotone arc of either curve (its ends are joints or
/// arc ends of both, staggered) while a crosses b inside it: the signed separation at
/// its two ends of opposite signs, both beyond tol / 8 (coincident curves are apart by
/// rounding only, about 1e-16 of the size; an offset copy within the distance keeps one
/// side). That is a crossing at a small angle theta cut between joints closer than its
/// near region (2 tol / theta long): two NURBS unit circles with centres d = 1.4e-5 ..
/// 2.4e-5 apart along x, whose crossings lie between the joints of their quarters d
/// apart, are within d^2 / 2 there but 1.5 d^2 > tol as far again beyond.
///
/// The points of rejected ones (found, or computed now for deferred pairs) are appended
/// to hits; the confirmed overlaps are returned in order.
template <class T>
std::vector<CurveOverlap<T>> confirm_overlaps(const Prepared<T>& A, const Prepared<T>& B, std::vector<RawOverlap<T>>& candidates,
                                              Context<T>& ctx, std::vector<Hit<T>>& hits, const TameJoints<T>* tame = nullptr) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  const T tol = ctx.tol;
  auto signed_gap = [&](T ta, T tb) {
    const Point<T, 2> p = unit_at(ca, A, ta);
    const Foot<T> f = foot_near(cb, B, p, tb);
    return std::copysign(f.distance, cross(direction_at(cb, B, f.t), p - unit_at(cb, B, f.t)));
  };
  auto covers_arc = [](const Pieces<T, 2>& c, const Prepared<T>& P, T lo, T hi) {
    const T m = T(1e-9) * c.domain().length();
    for (const auto& r : P.arcs)
      if (c.lift(r.piece, r.lo) >= lo - m && c.lift(r.piece, r.hi) <= hi + m) return true;
    return false;
  };
  // Whether t is an arc end of c that is no joint of its tame parts (`joints`).
  auto arc_end = [](const Pieces<T, 2>& c, const Prepared<T>& P, const std::vector<T>& joints, T t) {
    const T m = T(1e-9) * c.domain().length();
    for (T j : joints)
      if (std::abs(t - j) <= m) return false;
    for (const auto& r : P.arcs)
      if (std::abs(c.lift(r.piece, r.lo) - t) <= m || std::abs(c.lift(r.piece, r.hi) - t) <= m) return true;
    return false;
  };
  std::vector<CurveOverlap<T>> joined;
  for (auto& [o, found, deferred, parts] : candidates) {
    bool continues = near_beyond(ca, A, cb, B, o.a.lo, o.b_start, -(o.a.hi - o.a.lo), o.b_start - o.b_end, tol) ||
                     near_beyond(ca, A, cb, B, o.a.hi, o.b_end, o.a.hi - o.a.lo, o.b_end - o.b_start, tol);
    // On tame parts (solve_extreme) each end must be an arc end of a curve as given: a
    // part is a whole arc of the tamed curve, not of the curve (the conic [1, 2e6, 1]'s
    // first part, t in [0, 5e-4], lies within the distance of its polygon's leg; the curves
    // part there, but no whole arc of either is within it: a touch at their common end).
    if (!continues && tame) {
      continues = !((arc_end(ca, A, tame->a, o.a.lo) || arc_end(cb, B, tame->b, o.b_start)) &&
                    (arc_end(ca, A, tame->a, o.a.hi) || arc_end(cb, B, tame->b, o.b_end)));
    }
    if (!continues && !covers_arc(ca, A, o.a.lo, o.a.hi) && !covers_arc(cb, B, std::min(o.b_start, o.b_end), std::max(o.b_start, o.b_end))) {
      const T g0 = signed_gap(o.a.lo, o.b_start), g1 = signed_gap(o.a.hi, o.b_end);
      continues = (g0 > 0) != (g1 > 0) && std::min(std::abs(g0), std::abs(g1)) > tol / 8;
    }
    if (continues) {
      hits.insert(hits.end(), found.begin(), found.end());
      for (const auto& [i, j] : deferred) {
        const auto more = arc_points(A, i, B, j, ctx);
        hits.insert(hits.end(), more.begin(), more.end());
      }
    } else {
      joined.push_back(o);
    }
  }
  return joined;
}

/// Phase 4, end: confirmed overlaps that continue one another (the end of one within 1e-9
/// of the domain lengths of the start of the next, on a and on b, b running the same way)
/// are one overlap. Two halves of a copy moved along x by 0.7 of the near-miss distance
/// (degree 20 to 80) were confirmed apart, their join broken by a sliver of a pair of
/// neighbouring arcs, and the sliver's points, between the halves in both parameters,
/// were listed as crossings.
template <class T>
std::vector<CurveOverlap<T>> join_confirmed(std::vector<CurveOverlap<T>> overlaps, T la, T lb) {
  std::vector<CurveOverlap<T>> out;
  for (const auto& o : overlaps) {
    if (!out.empty()) {
      auto& p = out.back();
      if (std::abs(o.a.lo - p.a.hi) <= T(1e-9) * la && std::abs(o.b_start - p.b_end) <= T(1e-9) * lb &&
          ((o.b_end > o.b_start) == (p.b_end > p.b_start))) {
        p.a = Interval<T>(p.a.lo, o.a.hi);
        p.b_end = o.b_end;
        continue;
      }
    }
    out.push_back(o);
  }
  return out;
}

/// The parameter length of piece i of c (the scale of the merge distances).
template <class T>
T break_length(const Pieces<T, 2>& c, std::size_t i) {
  return c.segment_domain(i).length();
}

/// Whether the point h lies inside (or at the end of, within 1e-7 of its pieces' parameter
/// lengths) one of the overlaps, of which it is then a part, not an isolated point; for a
/// self-intersection the overlap seen from the other side too.
template <class T>
bool in_overlap(const Hit<T>& h, const std::vector<CurveOverlap<T>>& overlaps, const Pieces<T, 2>& ca, const Pieces<T, 2>& cb,
                bool self) {
  bool inside = false;
  for (const auto& o : overlaps) {
    const T blo = std::min(o.b_start, o.b_end), bhi = std::max(o.b_start, o.b_end);
    const T ma = T(1e-7) * break_length(ca, h.pa), mb = T(1e-7) * break_length(cb, h.pb);
    inside = inside || (h.ta >= o.a.lo - ma && h.ta <= o.a.hi + ma && h.tb >= blo - mb && h.tb <= bhi + mb);
    if (self)  // the same stretch seen from the other side
      inside = inside || (h.tb >= o.a.lo - ma && h.tb <= o.a.hi + ma && h.ta >= blo - mb && h.ta <= bhi + mb);
  }
  return inside;
}

/// The curves' domains and whether each is closed (its ends within tol in the unit
/// frame): on a closed curve the way between two parameters may pass its closing point.
template <class T>
struct Loops {
  Loop<T> a, b;
};
template <class T>
Loops<T> loops(const Prepared<T>& A, const Prepared<T>& B, T tol) {
  const Interval<T> dom_a = A.curve->domain(), dom_b = B.curve->domain();
  const bool closed_a = distance(unit_at(*A.curve, A, dom_a.lo), unit_at(*A.curve, A, dom_a.hi)) <= tol;
  const bool closed_b = distance(unit_at(*B.curve, B, dom_b.lo), unit_at(*B.curve, B, dom_b.hi)) <= tol;
  return {{dom_a, closed_a}, {dom_b, closed_b}};
}

/// The points of solve() after merging: one per near region, sorted by ta, and the points
/// from edge seeds set aside (admit_edges decides which of them stand for a region).
template <class T>
struct MergedPoints {
  std::vector<Hit<T>> kept;
  std::vector<Hit<T>> edges;
};

/// Phase 5, step 1: the points in the order of ta; for a self-intersection each pair first
/// ordered ta <= tb (its pieces and piece parameters with it).
template <class T>
void order_hits(std::vector<Hit<T>>& hits, bool self) {
  if (self) {
    for (auto& h : hits) {
      if (h.ta > h.tb) {
        std::swap(h.ta, h.tb);
        std::swap(h.pa, h.pb);
        std::swap(h.sa, h.sb);
      }
    }
  }
  std::sort(hits.begin(), hits.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
}

/// Phase 5, step 2 (self-intersections): whether the point (ta <= tb) is the curve
/// meeting itself where consecutive arcs join, at its closing point, or at a cusp: none is
/// a self-intersection. A "loop" whose extent (the control boxes of the curve between ta
/// and tb) is below the near-miss distance times 100 is one of these at the resolution of
/// double.
template <class T>
bool trivial_self_contact(const Prepared<T>& A, const Hit<T>& h, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  if (h.tb - h.ta <= T(1e-12) * ca.domain().length()) return true;
  const Interval<T> dom = ca.domain();
  if (h.ta == dom.lo && h.tb == dom.hi) return true;
  Box<T, 2> loop = Box<T, 2>::empty_box();
  ca.for_each_piece({h.ta, h.tb}, [&](std::size_t p, const auto&, const Interval<T>& own) {
    if (own.hi > own.lo) loop.add(std::visit([&](const auto& x) { return part(x, own.lo, own.hi).control_bounds(); }, A.unit[p]));
    return loop.empty() || diagonal(loop) <= 100 * tol;  // beyond: a loop, no need to see the rest of it
  });
  return !loop.empty() && diagonal(loop) <= 100 * tol;
}

/// Phase 5, step 3: the points kept so far, one per near region, and how a new point
/// merges into one of them. Each kept point has its twins (points merged into it, all
/// common to rounding: the middle one in ta is kept at the end, middle_twins) and its
/// touch span (the extreme points of its touch region).
template <class T>
struct PointMerge {
  const Prepared<T>& A;
  const Prepared<T>& B;
  const Loops<T>& lp;
  T tol;
  std::vector<Hit<T>> kept{};
  std::vector<std::vector<Hit<T>>> twins{};
  std::vector<TouchSpan<T>> spans{};

  /// Common to rounding: within 1e-3 of the near-miss distance.
  [[nodiscard]] T exact() const { return T(1e-3) * tol; }

  /// A common point at which the curves cross (common to rounding, tangents apart by more
  /// than crossing_noise), not a touch.
  [[nodiscard]] bool crossing(const Hit<T>& x) const {
    return x.distance <= exact() &&
           std::abs(cross(direction(A.unit[x.pa], x.sa), direction(B.unit[x.pb], x.sb))) > crossing_noise<T>;
  }

  /// The touch span sp widened by h's parameters (taken next to the span's, round the
  /// closing point of a closed curve).
  [[nodiscard]] TouchSpan<T> widen(TouchSpan<T> sp, const Hit<T>& h) const {
    const T hta = sp.ta0 + lp.a.shortest(h.ta - sp.ta0), htb = sp.tb0 + lp.b.shortest(h.tb - sp.tb0);
    if (hta < sp.ta0) {
      sp.ta0 = hta;
      sp.tb0 = htb;
    }
    if (hta > sp.ta1) {
      sp.ta1 = hta;
      sp.tb1 = htb;
    }
    return sp;
  }

  /// Whether h is kept point ki seen again: within merge_fraction of their pieces'
  /// parameter lengths in both parameters and within 1e4 tol in the plane.
  [[nodiscard]] bool same_point(const Hit<T>& h, std::size_t ki) const {
    const Hit<T>& k = kept[ki];
    const T ma = T(merge_fraction) * break_length(*A.curve, h.pa), mb = T(merge_fraction) * break_length(*B.curve, h.pb);
    return std::abs(lp.a.shortest(h.ta - k.ta)) <= ma && std::abs(lp.b.shortest(h.tb - k.tb)) <= mb &&
           distance(at(A.unit[k.pa], k.sa), at(A.unit[h.pa], h.sa)) <= 1e4 * tol;
  }

  /// h merged into kept point ki, the same point: a touch is sought again over its span
  /// widened by h; two points common to rounding (a crossing at a tiny angle, seen from
  /// neighbouring parts with roots blurred by eps / angle) are twins; else the closer one.
  void merge_same(const Hit<T>& h, std::size_t ki) {
    Hit<T>& k = kept[ki];
    if (k.touch) {
      spans[ki] = widen(spans[ki], h);
      if (auto t = touch_in(*A.curve, A, lp.a, *B.curve, B, lp.b, spans[ki], tol)) k = *t;
    } else if (h.distance <= exact() && k.distance <= exact()) {
      twins[ki].push_back(h);
    } else if (h.distance < k.distance) {
      k = h;
      twins[ki].clear();
    }
  }

  /// Whether h and kept point ki are two points of one near region: within 1e3
  /// merge_fraction of their pieces in both parameters, the curves within the near-miss
  /// distance half way between them.
  [[nodiscard]] bool one_region(const Hit<T>& h, std::size_t ki) const {
    const Hit<T>& k = kept[ki];
    const T ma = T(merge_fraction) * break_length(*A.curve, h.pa), mb = T(merge_fraction) * break_length(*B.curve, h.pb);
    const T dta = lp.a.shortest(h.ta - k.ta), dtb = lp.b.shortest(h.tb - k.tb);
    if (!(std::abs(dta) <= T(1e3) * ma && std::abs(dtb) <= T(1e3) * mb)) return false;
    const T mta = lp.a.wrap(k.ta + dta / 2), mtb = lp.b.wrap(k.tb + dtb / 2);
    return distance_near(*B.curve, B, unit_at(*A.curve, A, mta), mtb) <= tol;
  }

  /// h merged into kept point ki of its near region: two crossings between which the
  /// curves stay within the near-miss distance (the separation peaks between them) are
  /// one touch at that resolution, reported once, as tangent, where the separation peaks
  /// (touch_in), or at the middle when that cannot be located; a touch region widened by
  /// h sought again; a crossing and a touch of one near region (the curves cross, then
  /// come within the distance again without crossing back) are one point, the crossing;
  /// two touches, the closer one.
  void merge_region(const Hit<T>& h, std::size_t ki) {
    Hit<T>& k = kept[ki];
    const bool pair = !k.touch && crossing(k) && crossing(h);
    if (k.touch || pair) {
      spans[ki] = widen(k.touch ? spans[ki] : TouchSpan<T>{k.ta, k.tb, k.ta, k.tb}, h);
      if (auto t = touch_in(*A.curve, A, lp.a, *B.curve, B, lp.b, spans[ki], tol)) {
        k = *t;
      } else if (pair) {  // not located (no sign change of g): at the middle
        const T mta = lp.a.wrap(k.ta + lp.a.shortest(h.ta - k.ta) / 2), mtb = lp.b.wrap(k.tb + lp.b.shortest(h.tb - k.tb) / 2);
        const auto a = A.curve->locate(mta), b = B.curve->locate(mtb);
        k = Hit<T>{mta, mtb, a.index, b.index, a.t, b.t, k.distance, true};
      }
    } else if (crossing(h) || (!crossing(k) && h.distance < k.distance)) {
      k = h;
    }
    twins[ki].clear();
  }

  /// h merged into kept point ki if it is the same point or of its near region.
  bool merge_into(const Hit<T>& h, std::size_t ki) {
    if (same_point(h, ki)) {
      merge_same(h, ki);
      return true;
    }
    if (one_region(h, ki)) {
      merge_region(h, ki);
      return true;
    }
    return false;
  }

  /// h as a new kept point.
  void keep(const Hit<T>& h) {
    kept.push_back(h);
    twins.emplace_back();
    spans.push_back({h.ta, h.tb, h.ta, h.tb});
  }

  /// Each kept point with twins replaced by the middle one in ta of it and its twins.
  void middle_twins() {
    for (std::size_t ki = 0; ki < kept.size(); ++ki) {
      if (twins[ki].empty()) continue;
      twins[ki].push_back(kept[ki]);
      std::sort(twins[ki].begin(), twins[ki].end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
      kept[ki] = twins[ki][(twins[ki].size() - 1) / 2];
    }
  }
};

/// Phase 5: the points of the arcs merged into one per near region. In the order of ta
/// (order_hits): points inside an overlap are dropped (in_overlap); for a
/// self-intersection, points where consecutive arcs join, the closing point and cusps
/// (trivial_self_contact); points from edge seeds are set aside; every other point merges
/// into a kept one of the same near region (PointMerge: the same point within
/// merge_fraction of the pieces; two crossings between which the curves stay within tol
/// are one touch, at the peak of the separation; a crossing and a touch of one region are
/// the crossing) or is kept. Linear in the number of points (each is compared with the
/// kept points of a window).
template <class T>
MergedPoints<T> merge_points(const Prepared<T>& A, const Prepared<T>& B, bool self, std::vector<Hit<T>> hits,
                             const std::vector<CurveOverlap<T>>& overlaps, const Loops<T>& lp, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  order_hits(hits, self);
  MergedPoints<T> out;
  PointMerge<T> m{A, B, lp, tol};
  // Hits merge only with kept points within 1e3 merge_fraction of the longest piece of a in
  // ta (see PointMerge::one_region); kept stays sorted by ta to within that window (a merge
  // moves a kept point towards the later hit), so each hit is compared with the kept points
  // from 4 windows back only: linear in the number of points, not quadratic (a polyline
  // crossing itself 10^5 times).
  T longest_a = 0;
  for (std::size_t p = 0; p < ca.size(); ++p) longest_a = std::max(longest_a, break_length(ca, p));
  const T window = T(1e3) * T(merge_fraction) * longest_a;
  for (const auto& h : hits) {
    // Inside (or at the end of) an overlap: part of it, not an isolated point.
    if (in_overlap(h, overlaps, ca, cb, self)) continue;
    if (self && trivial_self_contact(A, h, tol)) continue;
    if (h.edge) {
      out.edges.push_back(h);
      continue;
    }
    bool merged = false;
    std::size_t first = m.kept.size();
    while (first > 0 && m.kept[first - 1].ta >= h.ta - 4 * window) --first;
    for (std::size_t ki = first; ki < m.kept.size() && !merged; ++ki) merged = m.merge_into(h, ki);
    // On a closed curve a, the points at the start of its domain are next to h near its
    // end (the closing point: a point there is found at both ends of the domain).
    if (lp.a.closed && h.ta >= lp.a.dom.hi - 4 * window) {
      for (std::size_t ki = 0; ki < std::min<std::size_t>(first, 16) && !merged; ++ki)
        if (std::abs(lp.a.shortest(m.kept[ki].ta - h.ta)) <= 4 * window) merged = m.merge_into(h, ki);
    }
    if (!merged) m.keep(h);
  }
  m.middle_twins();
  out.kept = std::move(m.kept);
  // Sorted for the search below: merges move points within the window, and one at the
  // closing point of a closed curve may have moved to the other end of its domain.
  std::sort(out.kept.begin(), out.kept.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
  return out;
}

/// Phase 6: the points from edge seeds (arc ends inside a near region, see band()) added to
/// kept (sorted by ta) where they stand for a region of their own. One stands for its
/// region only if no other point does, i.e. if the curves part (beyond tol) between it
/// and each of its neighbours in ta among the points kept so far (the nearest 8 on each
/// side; on a closed curve a the first and last 8 too); the closest of several such
/// points of one region is kept. kept stays sorted by ta.
template <class T>
void admit_edges(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp, std::vector<Hit<T>>& kept, std::vector<Hit<T>> edges,
                 T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  const Loop<T>&loop_a = lp.a, &loop_b = lp.b;
  const bool closed_a = loop_a.closed;
  // Points from edge seeds (arc ends inside a near region, see band()): one stands for its
  // region only if no other point does, i.e. if the curves part (beyond tol) between it
  // and each of its neighbours in ta among the points kept so far (the nearest 8 on each
  // side); the closest of several such points of one region is kept.
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.distance < y.distance; });
  auto same_region = [&](const Hit<T>& x, const Hit<T>& y) {
    const T da = loop_a.shortest(y.ta - x.ta), db = loop_b.shortest(y.tb - x.tb);
    for (int j = 0; j <= 16; ++j) {
      const T f = static_cast<T>(j) / 16;
      const T ta = loop_a.wrap(x.ta + f * da), tb = loop_b.wrap(x.tb + f * db);
      if (!(distance_near(cb, B, unit_at(ca, A, ta), tb) <= tol)) return false;
    }
    return true;
  };
  for (const auto& h : edges) {
    const auto at_h = std::lower_bound(kept.begin(), kept.end(), h.ta, [](const auto& k, T ta) { return k.ta < ta; });
    const std::size_t mid = static_cast<std::size_t>(at_h - kept.begin());
    bool represented = false;
    for (std::size_t k = mid > 8 ? mid - 8 : 0; k < std::min(kept.size(), mid + 8) && !represented; ++k)
      represented = same_region(kept[k], h);
    if (closed_a) {  // the neighbours across the closing point
      for (std::size_t k = 0; k < std::min<std::size_t>(kept.size(), 8) && !represented; ++k) represented = same_region(kept[k], h);
      for (std::size_t k = kept.size() > 8 ? kept.size() - 8 : 0; k < kept.size() && !represented; ++k)
        represented = same_region(kept[k], h);
    }
    if (!represented) kept.insert(kept.begin() + static_cast<std::ptrdiff_t>(mid), h);
  }

}

/// Phase 7: the kept points as the answer's points, sorted by ta: each point's position
/// (piece a's value), and its kind. A point is tangent if it was merged into a touch or
/// its tangents are within 1e-6 (sine); a point whose tangents are within 1e-4 is
/// polished as a touch first (polish_touch: a touch located as a double root is off by up
/// to sqrt(eps / curvature)), and one that polishes onto a touch already listed is
/// dropped. A curve that is a point has no direction: its meeting with another is a
/// crossing.
template <class T>
std::vector<CurveIntersection<T>> classify(const Prepared<T>& A, const Prepared<T>& B, const std::vector<Hit<T>>& kept, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  std::vector<CurveIntersection<T>> points;
  for (auto h : kept) {
    Vector<T, 2> da = direction(A.unit[h.pa], h.sa), db = direction(B.unit[h.pb], h.sb);
    // A curve that is a point has no direction: its meeting with another is a crossing.
    bool tangent = h.touch || (norm(da) > 0 && norm(db) > 0 && std::abs(cross(da, db)) <= T(1e-6));
    // A touch located as a double root (to sqrt(eps / curvature): 1e-8 off on a Chebyshev
    // polynomial of degree 12, where its tangent already turned by 4e-6) or as a minimum of
    // a band's separation: polished where the tangents are parallel and the curves within
    // the near-miss distance (polish_touch, within 1e-5 in both parameters); then it is the
    // touch, and tangent. A second point polished onto the same touch is not listed again.
    if (!tangent && norm(da) > 0 && norm(db) > 0 && std::abs(cross(da, db)) <= T(1e-4)) {
      const Arc<T> aa{h.pa, T(0), T(1)}, ab{h.pb, T(0), T(1)};
      if (auto p = polish_touch(A.unit[h.pa], aa, B.unit[h.pb], ab, Refined<T>{h.sa, h.sb, h.distance}, tol)) {
        h.sa = p->s;
        h.sb = p->t;
        h.ta = ca.lift(h.pa, p->s);
        h.tb = cb.lift(h.pb, p->t);
        da = direction(A.unit[h.pa], h.sa);
        db = direction(B.unit[h.pb], h.sb);
        tangent = std::abs(cross(da, db)) <= T(1e-6);
        const T ma = T(merge_fraction) * break_length(ca, h.pa), mb = T(merge_fraction) * break_length(cb, h.pb);
        if (tangent && std::any_of(points.begin(), points.end(), [&](const CurveIntersection<T>& x) {
              return std::abs(x.ta - h.ta) <= ma && std::abs(x.tb - h.tb) <= mb;
            }))
          continue;
      }
    }
    points.push_back({h.ta, h.tb, std::visit([&](const auto& x) { return x(h.sa); }, ca.segments()[h.pa]),
                          tangent ? IntersectionKind::tangent : IntersectionKind::crossing});
  }
  std::sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.ta < y.ta; });
  return points;
}

/// Phase 8 (self-intersections of a closed curve): a closed curve crossing itself at its
/// closing point passes there three times in parameters (start, middle, end): the pairs
/// (start, middle) and (middle, end) are one self-intersection. Parameters at the end of
/// the domain count as its start (within merge_fraction of their piece); such a pair is
/// listed once, the first in ta. Other points are kept, in order.
template <class T>
std::vector<CurveIntersection<T>> once_at_closing_point(const Pieces<T, 2>& ca, const std::vector<CurveIntersection<T>>& points) {
  const Interval<T> dom_a = ca.domain();
  // A closed curve crossing itself at its closing point passes there three times in
  // parameters (start, middle, end): the pairs (start, middle) and (middle, end) are one
  // self-intersection. Parameters at the end of the domain count as its start (within
  // merge_fraction of their piece); such a pair is listed once, the first in ta.
  auto near_end = [&](T t) { return t >= dom_a.hi - T(merge_fraction) * break_length(ca, ca.segment_index(t)); };
  auto same_t = [&](T x, T y) {
    return std::abs(x - y) <= T(merge_fraction) * std::max(break_length(ca, ca.segment_index(x)), break_length(ca, ca.segment_index(y)));
  };
  auto canonical = [&](const CurveIntersection<T>& x) {
    T u = near_end(x.ta) ? dom_a.lo : x.ta, v = near_end(x.tb) ? dom_a.lo : x.tb;
    if (u > v) std::swap(u, v);
    return std::pair<T, T>{u, v};
  };
  std::vector<CurveIntersection<T>> once;
  std::vector<std::pair<T, T>> closing;  // canonical pairs of the kept points that touch the closing point
  for (const auto& x : points) {
    const bool touches = near_end(x.ta) || near_end(x.tb) || same_t(x.ta, dom_a.lo) || same_t(x.tb, dom_a.lo);
    if (touches) {
      const auto c = canonical(x);
      if (std::any_of(closing.begin(), closing.end(), [&](const auto& k) { return same_t(k.first, c.first) && same_t(k.second, c.second); }))
        continue;
      closing.push_back(c);
    }
    once.push_back(x);
  }
  return once;
}

/// Whether consecutive points x and y (in ta) are of one near region: one curve at 15
/// points between them (ta and tb interpolated, round the closing point of a closed curve)
/// within tol of the other, a of b or b of a (the foot of a point on a curve parametrised
/// very unevenly, the conic [1, 1e6, 1] seen from its polygon, is not always reached from
/// the interpolated parameter; the polygon from the conic's points is).
template <class T>
bool same_near_region(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp, const CurveIntersection<T>& x,
                      const CurveIntersection<T>& y, T tol) {
  const T da = lp.a.shortest(y.ta - x.ta), db = lp.b.shortest(y.tb - x.tb);
  auto near = [&](bool a_of_b) {
    for (int j = 1; j < 16; ++j) {
      const T f = static_cast<T>(j) / 16;
      const T ta = lp.a.wrap(x.ta + f * da), tb = lp.b.wrap(x.tb + f * db);
      const T d = a_of_b ? distance_near(*B.curve, B, unit_at(*A.curve, A, ta), tb) : distance_near(*A.curve, A, unit_at(*B.curve, B, tb), ta);
      if (!(d <= tol)) return false;
    }
    return true;
  };
  return near(true) || near(false);
}

/// Phase 9 (general engine): loose touches merged into their near region. Refinement may
/// stop inside a near region, at a point within tol that is neither a meeting to rounding
/// nor the closest approach, and PointMerge merges only points within 1e3 merge_fraction of
/// their pieces: where the curves part slowly (the conic [1, 5e4, 1] within the distance of
/// its control polygon's leg from t = 0 to 2e-5, leg parameters 0 to 0.68) such points were
/// listed as touches of their own (2.5e-11 and 4.6e-11 from the leg, the touch being at the
/// common end). A loose point is a `tangent` one farther apart than 1e-3 tol (a meeting to
/// rounding is within it: PointMerge::exact). Consecutive points (in ta) of one near region
/// (same_near_region) of which one is loose are one region: its points that are not loose
/// stand for it (as before), or, without one, its closest loose point. Points in order of ta.
template <class T>
std::vector<CurveIntersection<T>> absorb_touches(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp,
                                                 const std::vector<CurveIntersection<T>>& points, T tol) {
  auto separation = [&](const CurveIntersection<T>& x) { return distance(unit_at(*A.curve, A, x.ta), unit_at(*B.curve, B, x.tb)); };
  std::vector<char> loose(points.size());
  bool any = false;
  for (std::size_t k = 0; k < points.size(); ++k) {
    loose[k] = points[k].kind == IntersectionKind::tangent && separation(points[k]) > T(1e-3) * tol;
    any = any || loose[k];
  }
  if (points.size() < 2 || !any) return points;
  std::vector<CurveIntersection<T>> out;
  for (std::size_t i = 0; i < points.size();) {
    std::size_t j = i + 1;
    while (j < points.size() && (loose[j - 1] || loose[j]) && same_near_region(A, B, lp, points[j - 1], points[j], tol)) ++j;
    std::optional<std::size_t> pick;
    bool firm = false;
    for (std::size_t k = i; k < j; ++k) {
      if (!loose[k]) {
        firm = true;
        out.push_back(points[k]);
      } else if (!pick || separation(points[k]) < separation(points[*pick])) {
        pick = k;
      }
    }
    if (!firm) out.push_back(points[*pick]);
    i = j;
  }
  return out;
}

/// Phase 10 (curves taken through their tame parts only, see solve_extreme): consecutive
/// points (in ta) between which the curves stay within tol (at 15 points between them,
/// as admit_edges) are one near region and become one point: the middle one of its
/// crossings common to rounding (within 1e-3 tol), else (the curves do not cross there: a
/// touch) a point where both curves end and meet if it has one, else its closest point (before
/// session 15: its closest crossing, which took points within tol at an angle, 1e-12 to
/// 6e-11 from a leg, for crossings of the conic and its polygon). On the tame parts of a
/// curve hugging its control polygon the engine sees one near region from several
/// pieces, whose parameters (one unit per part) are far apart where the points are not:
/// a line through the corner meets the chord of the parts within 1e-30 of it and the
/// ends of the parts next to it, each within rounding. Points are in order of ta.
template <class T>
std::vector<CurveIntersection<T>> merge_regions(const Prepared<T>& A, const Prepared<T>& B, const Loops<T>& lp,
                                                const std::vector<CurveIntersection<T>>& points, T tol) {
  const Pieces<T, 2>& ca = *A.curve;
  const Pieces<T, 2>& cb = *B.curve;
  auto separation = [&](const CurveIntersection<T>& x) { return distance(unit_at(ca, A, x.ta), unit_at(cb, B, x.tb)); };
  // A point where both curves end, met to rounding (within 1e-3 tol): where the curves
  // meet, not merely come near.
  auto at_ends = [&](const CurveIntersection<T>& x) {
    return !lp.a.closed && !lp.b.closed && (x.ta == lp.a.dom.lo || x.ta == lp.a.dom.hi) &&
           (x.tb == lp.b.dom.lo || x.tb == lp.b.dom.hi) && separation(x) <= T(1e-3) * tol;
  };
  std::vector<CurveIntersection<T>> out;
  for (std::size_t i = 0; i < points.size();) {
    std::size_t j = i + 1;
    while (j < points.size() && same_near_region(A, B, lp, points[j - 1], points[j], tol)) ++j;
    // The crossings common to rounding (within 1e-3 tol, as PointMerge::exact): the middle
    // one. Without one the curves do not cross in the region (a point within tol at an
    // angle is no crossing), which is a touch: at a point where both curves end and meet
    // if the region holds one (the conic [1, w, 1] along its control polygon's leg from
    // their common end, within 1e-17 of it over parts near the end: the closest approach
    // to rounding, and the end exactly), else at its closest point.
    std::vector<std::size_t> exact;
    for (std::size_t k = i; k < j; ++k)
      if (points[k].kind == IntersectionKind::crossing && separation(points[k]) <= T(1e-3) * tol) exact.push_back(k);
    std::size_t pick = i;
    if (!exact.empty()) {
      pick = exact[(exact.size() - 1) / 2];
    } else {
      for (std::size_t k = i; k < j; ++k) {
        if (at_ends(points[pick])) break;
        if (at_ends(points[k]) || separation(points[k]) < separation(points[pick])) pick = k;
      }
    }
    out.push_back(points[pick]);
    i = j;
  }
  return out;
}

/// The common points and overlaps of curves a and b (b = nullptr: the self-intersections
/// of a): the phases above in turn (see intersect()). `tame` (not null): the curves are
/// tame parts (solve_extreme), overlaps end at arc ends of the curves before taming
/// (confirm_overlaps), and the points of one near region seen from several parts are
/// merged (merge_regions); else touches of one near region are (absorb_touches).
template <class T>
Intersections<T> solve(const Pieces<T, 2>& ca, const Pieces<T, 2>* cb, const TameJoints<T>* tame = nullptr) {
  const bool self = cb == nullptr;
  if (self) cb = &ca;
  const SharedFrame<T> frame = shared_frame(ca, *cb);
  const Prepared<T> A = prepare(ca, frame.origin, frame.e);
  const Prepared<T> B = self ? Prepared<T>{} : prepare(*cb, frame.origin, frame.e);
  const Prepared<T>& PB = self ? A : B;
  const T tol = near_miss(A, PB);
  Context<T> ctx = make_context(tol);
  ArcPairs<T> pairs = meet_arcs(A, PB, self, ctx, tame != nullptr);
  std::vector<RawOverlap<T>> candidates = join_overlaps(std::move(pairs.overlaps), ca.domain().length(), cb->domain().length());
  if (tame) bridge_overlaps(A, PB, candidates, tol);
  std::vector<CurveOverlap<T>> overlaps =
      join_confirmed(confirm_overlaps(A, PB, candidates, ctx, pairs.hits, tame), ca.domain().length(), cb->domain().length());
  const Loops<T> lp = loops(A, PB, tol);
  MergedPoints<T> merged = merge_points(A, PB, self, std::move(pairs.hits), overlaps, lp, tol);
  admit_edges(A, PB, lp, merged.kept, std::move(merged.edges), tol);
  Intersections<T> out;
  out.points = classify(A, PB, merged.kept, tol);
  if (self && lp.a.closed) out.points = once_at_closing_point(ca, out.points);
  out.points = tame ? merge_regions(A, PB, lp, out.points, tol) : absorb_touches(A, PB, lp, out.points, tol);
  out.overlaps = std::move(overlaps);
  if (out.points.size() + out.overlaps.size() > max_points) too_many_points(out.points.size() + out.overlaps.size());
  return out;
}

/// solve() for curves that may have pieces with extreme weights (has_extreme_weights):
/// such curves are taken through their tame parts (tame(), runs below 1e-3 of the
/// near-miss distance as chords), solved with merge_regions, and the answer mapped back to
/// the curves' own parameters. Parameters so mapped are rounded to the doubles of the
/// domain, which may not resolve a part (a crossing of the leg that the weights 1, 1e30, 1
/// pass within 1e-30 of t = 1 is at t = 1); the points are the parts' own, so they are
/// where the curves meet, not the curve at the rounded parameter. Other curves: solve().
template <class T>
Intersections<T> solve_extreme(const Pieces<T, 2>& ca, const Pieces<T, 2>* cb) {
  const bool self = cb == nullptr;
  if (!has_extreme_weights(ca) && (self || !has_extreme_weights(*cb))) return solve(ca, cb);
  T size = 0;
  for (const auto* c : {&ca, cb}) {
    if (!c) continue;
    Box<T, 2> box = Box<T, 2>::empty_box();
    for (const auto& s : c->segments()) box.add(std::visit([](const auto& x) { return x.control_bounds(); }, s));
    size = std::max(size, diagonal(box));
  }
  const T run = T(1e-13) * size;
  const Tamed<T> ta = tame(ca, run);
  const std::optional<Tamed<T>> tb = self ? std::nullopt : std::optional<Tamed<T>>(tame(*cb, run));
  const TameJoints<T> joints{ta.joints(), self ? ta.joints() : tb->joints()};
  Intersections<T> r = solve(ta.curve, self ? nullptr : &tb->curve, &joints);
  const Tamed<T>& mb = self ? ta : *tb;
  const Pieces<T, 2>& ob = self ? ca : *cb;
  if (!self) {
    for (auto& x : r.points) {
      // A crossing on a chord of one curve, the other taken as it is there: onto the run.
      const TamePart<T>& pa = ta.parts[ta.curve.locate(x.ta).index];
      const TamePart<T>& pb = mb.parts[mb.curve.locate(x.tb).index];
      if (x.kind != IntersectionKind::crossing || pa.chord == pb.chord) continue;
      if (pa.chord) {
        onto_run(pa, mb.curve, x.tb, x.point);
      } else {
        T t = x.ta;
        Point<T, 2> p = x.point;
        onto_run(pb, ta.curve, t, p);
        x.ta = t;
        x.point = p;
      }
    }
  }
  for (auto& x : r.points) {
    x.ta = ta.original(ca, x.ta);
    x.tb = mb.original(ob, x.tb);
  }
  for (auto& o : r.overlaps) {
    o.a = Interval<T>(ta.original(ca, o.a.lo), ta.original(ca, o.a.hi));
    o.b_start = mb.original(ob, o.b_start);
    o.b_end = mb.original(ob, o.b_end);
  }
  return r;
}

/// The fast path (algo/intersect_low_degree.hpp) for two polynomial Bézier curves of
/// degree 1 to 3; nothing when it does not apply or refuses. Its points are the general
/// engine's answer: isolated crossings, reported with the pieces' own values at their
/// parameters.
template <class T>
std::optional<Intersections<T>> low_degree(const Bezier<T, 2>& a, const Bezier<T, 2>& b) {
  const auto r = isect_fast::intersect_low_degree<T>(a.points(), b.points());
  if (!r) return std::nullopt;
  Intersections<T> out;
  out.points.reserve(static_cast<std::size_t>(r->count));
  for (int i = 0; i < r->count; ++i) {
    const auto [s, t] = r->st[static_cast<std::size_t>(i)];
    // A Bézier curve's own parameter is the curve's (one piece on its own domain [0, 1]).
    out.points.push_back({s, t, a(s), IntersectionKind::crossing});
  }
  return out;
}

/// The fast path for two curves whose pieces are all polynomial of degree 1 to 3: every
/// pair of pieces in one shared frame (the general engine's). Nothing when a piece does
/// not qualify, a pair is refused, a point lies within 1e-9 of a joint of pieces (the
/// general engine merges what both pieces see there), or two points of different pairs
/// are closer than 1e-3 of their pieces in both parameters (see Limits::near_pair).
template <class T>
std::optional<Intersections<T>> low_degree_pieces(const Pieces<T, 2>& pa, const Pieces<T, 2>& pb) {
  using Span = std::span<const Point<T, 2>>;
  std::vector<Span> sa, sb;
  auto collect = [](const Pieces<T, 2>& p, std::vector<Span>& out) {
    out.reserve(p.size());
    for (const auto& seg : p.segments()) {
      const auto* z = std::get_if<Bezier<T, 2>>(&seg);
      if (!z || z->degree() < 1 || z->degree() > isect_fast::max_degree) return false;
      out.emplace_back(z->points());
    }
    return true;
  };
  if (!collect(pa, sa) || !collect(pb, sb)) return std::nullopt;
  const auto frame = isect_fast::unit_frame<T>(sa, sb);
  if (!frame) return std::nullopt;
  // Control boxes of the pieces, so that pairs far apart cost one box test (as the general
  // engine's arcs): within twice the near-miss distance (in model units) they go on.
  auto boxes = [](const std::vector<Span>& pieces_points) {
    std::vector<Box<T, 2>> out;
    out.reserve(pieces_points.size());
    for (const auto& P : pieces_points) {
      Box<T, 2> b = Box<T, 2>::empty_box();
      for (const auto& q : P) b.add(q);
      out.push_back(b);
    }
    return out;
  };
  const std::vector<Box<T, 2>> ba = boxes(sa), bb = boxes(sb);
  const T slack = 2 * frame->tol / frame->scale;
  // b's pieces in runs of 16 consecutive ones with the box of the run: consecutive pieces
  // are neighbours in the plane, so a piece of a far from a run costs one test for all 16.
  constexpr std::size_t run = 16;
  std::vector<Box<T, 2>> runs((sb.size() + run - 1) / run, Box<T, 2>::empty_box());
  for (std::size_t j = 0; j < sb.size(); ++j) runs[j / run].add(bb[j]);
  constexpr T joint = T(1e-9);
  struct Found {
    T ta, tb, s;
    std::size_t i, j;
  };
  std::vector<Found> found;
  for (std::size_t i = 0; i < sa.size(); ++i) {
    for (std::size_t j = 0; j < sb.size(); ++j) {
      if (j % run == 0 && !boxes_meet(ba[i], runs[j / run], slack)) {
        j += run - 1;
        continue;
      }
      if (!boxes_meet(ba[i], bb[j], slack)) continue;
      const auto r = isect_fast::intersect_in_frame<T>(sa[i], sb[j], *frame);
      if (!r) return std::nullopt;
      for (int k = 0; k < r->count; ++k) {
        const auto [s, t] = r->st[static_cast<std::size_t>(k)];
        if ((i > 0 && s < joint) || (i + 1 < sa.size() && s > 1 - joint) || (j > 0 && t < joint) || (j + 1 < sb.size() && t > 1 - joint))
          return std::nullopt;
        found.push_back({pa.lift(i, s), pb.lift(j, t), s, i, j});
        if (found.size() > max_points) too_many_points(found.size());
      }
    }
  }
  std::sort(found.begin(), found.end(), [](const Found& x, const Found& y) { return x.ta < y.ta; });
  const T near = isect_fast::Limits<T>::near_pair;
  T longest = 0;  // the longest piece of a: no pair farther apart than near * longest in ta is near
  for (std::size_t i = 0; i < pa.size(); ++i) longest = std::max(longest, pa.segment_domain(i).length());
  for (std::size_t k = 0; k < found.size(); ++k) {
    for (std::size_t l = k + 1; l < found.size() && found[l].ta - found[k].ta < near * longest; ++l) {
      const Found &x = found[k], &y = found[l];
      const T la = std::max(pa.segment_domain(x.i).length(), pa.segment_domain(y.i).length());
      const T lb = std::max(pb.segment_domain(x.j).length(), pb.segment_domain(y.j).length());
      if (y.ta - x.ta < near * la && std::abs(y.tb - x.tb) < near * lb) return std::nullopt;
    }
  }
  Intersections<T> out;
  out.points.reserve(found.size());
  for (const auto& h : found) out.points.push_back({h.ta, h.tb, std::get<Bezier<T, 2>>(pa.segments()[h.i])(h.s), IntersectionKind::crossing});
  return out;
}

}  // namespace detail::isect

/// The common points and overlaps of two plane curves of any types (through their exact
/// Bézier pieces; a line segment is a degree-1 Bézier or a polyline).
///
/// Method: every piece is cut at the zeros of its coordinates' derivatives into arcs
/// monotone in x and y (for rational pieces the numerators of the quotient rule). For
/// each pair of arcs whose control boxes meet: first an overlap test (arc_overlap: the
/// arcs' ends located on each other, confirmed at m n + 1 points by Bézout's bound),
/// else recursive halving with control-box rejection down to parts flat within 1e-10 of
/// the curves' size, then Newton refinement of each candidate on the curves themselves
/// (Levenberg-Marquardt where the Jacobian is near singular) [SederbergNishita90 for the
/// subdivision family; Dennis-Schnabel96 for the damped Newton]. Near-coincident parts
/// (tangents within 0.1 rad of one direction, curves within about 1e-7 of each other)
/// are decided at once as bands (see band()): crossings at the roots of their separation
/// polynomial, touches at the minima of its modulus, nothing where it stays beyond the
/// near-miss distance.
///
/// Near regions (stretches where the curves stay within the near-miss distance): one
/// point per crossing (two crossings with the curves within the distance between them
/// are one touch, at the peak of the separation), one touch where they come within it
/// without crossing, a point at an arc end only when nothing else represents its region.
/// An overlap is reported where a monotone arc lies within the distance of the other
/// curve all along, unless the curves still do so as far again past one of its ends, or
/// it holds no whole arc and a crosses b inside it (then it is a piece of a crossing or
/// touch region, seen between joints, and that point is reported).
///
/// Guarantees and accuracy: a point is reported when the curves come within 1e-10 of
/// their size (the larger control-box diagonal) there, and only then: near-misses
/// farther apart are not reported. Transversal crossings are refined to full precision
/// (parameters to a few eps relative, eps / sin(angle) near tangency); touches at the
/// closest approach (or the peak of the separation between two crossings within the
/// distance) to a few eps over the difference of the curvatures (polish_touch,
/// touch_in), about sqrt(eps) where that is not found, and reported once with kind
/// `tangent` (tangent directions within 1e-6 radians). Points closer than 1e-6 of their
/// pieces' parameter intervals in both parameters are merged into one, round the closing
/// point of a closed curve too. Overlaps are reported as parameter
/// intervals (joined across arcs and pieces), never as points; a point inside an overlap
/// (or at its ends) is not reported separately.
///
/// Scale: computed on copies translated and scaled by a power of two, so huge and tiny
/// coordinates behave as unit ones. Cost: about a hundred subdivision steps and a few
/// Newton steps per crossing for cubics; a few bands per near region (a cubic and its copy
/// turned by 1e-9, or moved by 2e-10 of its size: under 1 ms); O(arcs_a x arcs_b) pairs. Throws NumericalError
/// when a pair of arcs needs more than 2 10^6 subdivision steps (curves within the
/// tolerance of each other along a stretch without coinciding).
template <class CA, class CB>
  requires PiecewiseBezierCurve<CA> && PiecewiseBezierCurve<CB> && (CA::dimension == 2) && (CB::dimension == 2) &&
           std::same_as<typename CA::Scalar, typename CB::Scalar>
Intersections<typename CA::Scalar> intersect(const CA& a, const CB& b) {
  using T = typename CA::Scalar;
  // Two Bézier curves of degree <= 3 (the common case, W6): the fast path, on their
  // control points directly, without building pieces.
  if constexpr (std::same_as<CA, Bezier<T, 2>> && std::same_as<CB, Bezier<T, 2>>) {
    if (auto r = detail::isect::low_degree(a, b)) return std::move(*r);
  }
  const auto& pa = pieces(a);
  const auto& pb = pieces(b);
  if constexpr (!(std::same_as<CA, Bezier<T, 2>> && std::same_as<CB, Bezier<T, 2>>)) {
    // Polynomial pieces of degree <= 3 on both sides (polylines, paths, cubic splines...).
    if (auto r = detail::isect::low_degree_pieces(pa, pb)) return std::move(*r);
  }
  return detail::isect::solve_extreme(pa, &pb);
}

/// The self-intersections of a plane curve: pairs ta < tb with c(ta) = c(tb), and the
/// stretches where the curve runs over itself (overlaps, a before b). Not reported: the
/// joints of consecutive pieces, the closing point of a closed curve (c at the start and
/// end of its domain), and cusps (a "loop" smaller than 1e-8 of the curve's size).
/// Method, accuracy and cost as intersect(), on the pairs of distinct arcs of one curve.
template <class C>
  requires PiecewiseBezierCurve<C> && (C::dimension == 2)
Intersections<typename C::Scalar> self_intersect(const C& c) {
  const auto& p = pieces(c);
  return detail::isect::solve_extreme(p, static_cast<decltype(&p)>(nullptr));
}

}  // namespace casteljau
