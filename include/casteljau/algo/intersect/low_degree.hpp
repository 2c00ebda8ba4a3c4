// The fast path of intersect() for two polynomial Bézier pieces of degree 1 to 3:
// allocation-free subdivision on fixed-size arrays, certified isolation by tangent cones,
// Newton's method on the curves, and a refusal (std::nullopt) whenever it cannot certify
// its answer, upon which intersect() runs the general engine.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "casteljau/core/point.hpp"
#include "casteljau/core/unit_frame.hpp"

namespace casteljau::detail::isect_fast {

/// Highest piece degree of the fast path (cubic x cubic is the common case; quadratics and
/// lines are handled at their own degree).
inline constexpr int max_degree = 3;

/// The common points found, as parameters (s, t) in [0, 1] of the two Bézier pieces, sorted
/// by s. Two curves of degrees m, n <= 3 that do not overlap meet at most m n <= 9 times
/// (Bézout); more room is kept for the duplicates found on both sides of a subdivision
/// boundary before they are merged.
template <class T>
struct Roots {
  static constexpr int capacity = 16;
  std::array<std::pair<T, T>, capacity> st{};
  int count = 0;
};

/// Thresholds of the fast path. Each exists so that it answers only where the general
/// engine would give the same answer; anything closer to a limit is refused.
template <class T>
struct Limits {
  /// Sine of the angle by which the tangent cones of two parts must be separated for the
  /// parts to count as meeting at most once: far above the rounding of a cone's directions
  /// (below 1e-7, see min_leg), so the certificate holds for the exact curves.
  static constexpr T cone_gap = T(1e-5);
  /// Smallest length (in the unit frame, coordinates below 1) of a non-zero control leg
  /// used for a cone. The control points of a part at subdivision depth d are off by about
  /// d eps; over legs of at least 1e-8 that tilts a direction by under 1e-7 for d <= 60.
  static constexpr T min_leg = T(1e-8);
  /// Parameter width below which a part is not halved again: the pair is refused (a
  /// near-tangency or an overlap; the general engine decides).
  static constexpr T min_width = T(1.0 / (1ull << 40));
  /// Pairs of parts visited per pair of pieces before refusing (W6's random cubic pairs take
  /// 12.5 on average; overlapping or nearly tangent curves many more).
  static constexpr int max_nodes = 600;
  /// Two distinct common points closer than this in both parameters: refused, as the
  /// general engine may merge them into one touch (it merges within 1e-3 of the pieces'
  /// parameter intervals when the curves stay within the near-miss distance between them).
  static constexpr T near_pair = T(1e-3);
  /// Points found twice (from both sides of a subdivision boundary) agree to a few eps;
  /// closer than this in both parameters they are one point.
  static constexpr T duplicate = T(1e-12);
  /// A Newton solution outside [0, 1]^2 by less than this is refused: the curves end
  /// within a hair of each other, where the general engine's near-miss rule decides.
  static constexpr T end_zone = T(1e-6);
};

/// The tangent cone of a part: unit vectors u (most clockwise) and v (most
/// counter-clockwise) of its control legs P_(i+1) - P_i, which contain every tangent
/// direction of the part (the derivative is a non-negative combination of the legs).
template <class T>
struct Cone {
  T ux = 0, uy = 0, vx = 0, vy = 0;
  bool ok = false;  ///< false: no usable cone (see tangent_cone)
};

/// One curve (or a part of it) of degree K in the unit frame: control point coordinates,
/// the parameter interval [lo, hi] of the whole piece that the part covers, and what the
/// pair tests need, computed once per part by finish(): the control box, the fat line
/// (unit normal n of the chord P_0 P_K and the band [f0, f1] of n . P_i; none when the
/// chord is a point) and the tangent cone, the latter two when first needed.
template <class T, int K>
struct Part {
  std::array<T, K + 1> x{}, y{};
  T lo = 0, hi = 1;
  T x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // control box
  T nx = 0, ny = 0, f0 = 0, f1 = 0;  // fat line
  bool fat = false;
  bool fat_done = false, cone_done = false;  // computed lazily: most pairs are rejected by their boxes
  Cone<T> cone;
};

/// The tangent cone of a part; not ok when every leg is zero, a non-zero leg is shorter
/// than Limits::min_leg (direction spoilt by rounding), or a leg is a right angle or more
/// away from the first non-zero one (the cone is then narrower than a half-turn).
template <class T, int K>
Cone<T> tangent_cone(const Part<T, K>& p) {
  bool any = false;
  T rx = 0, ry = 0, ux = 0, uy = 0, vx = 0, vy = 0;
  for (std::size_t i = 0; i < std::size_t(K); ++i) {
    const T dx = p.x[i + 1] - p.x[i], dy = p.y[i + 1] - p.y[i];
    if (dx == 0 && dy == 0) continue;
    if (std::abs(dx) + std::abs(dy) < Limits<T>::min_leg) return {};
    if (!any) {
      any = true;
      rx = ux = vx = dx;
      ry = uy = vy = dy;
      continue;
    }
    // Within a right angle of the first leg (an open half-plane), so that the cross
    // products below order the legs by angle.
    if (rx * dx + ry * dy <= 0) return {};
    if (ux * dy - uy * dx < 0) ux = dx, uy = dy;
    if (vx * dy - vy * dx > 0) vx = dx, vy = dy;
  }
  if (!any) return {};
  // Unit frame: coordinates below 1, no overflow in the squares.
  const T nu = std::sqrt(ux * ux + uy * uy), nv = std::sqrt(vx * vx + vy * vy);
  return {ux / nu, uy / nu, vx / nv, vy / nv, true};
}

/// Computes a part's control box from its control points (and marks the rest to do).
template <class T, int K>
void finish(Part<T, K>& p) {
  p.x0 = p.x1 = p.x[0];
  p.y0 = p.y1 = p.y[0];
  for (std::size_t i = 1; i <= std::size_t(K); ++i) {
    p.x0 = std::min(p.x0, p.x[i]);
    p.x1 = std::max(p.x1, p.x[i]);
    p.y0 = std::min(p.y0, p.y[i]);
    p.y1 = std::max(p.y1, p.y[i]);
  }
  p.fat_done = p.cone_done = false;
}

/// Computes a part's fat line, once.
template <class T, int K>
void make_fat_line(Part<T, K>& p) {
  if (p.fat_done) return;
  p.fat_done = true;
  const T cx = p.x[K] - p.x[0], cy = p.y[K] - p.y[0];
  const T len = std::sqrt(cx * cx + cy * cy);  // unit frame: no overflow
  p.fat = len > 0;
  if (!p.fat) return;
  p.nx = -cy / len;
  p.ny = cx / len;
  p.f0 = p.f1 = p.nx * p.x[0] + p.ny * p.y[0];
  for (std::size_t i = 1; i <= std::size_t(K); ++i) {
    const T f = p.nx * p.x[i] + p.ny * p.y[i];
    p.f0 = std::min(p.f0, f);
    p.f1 = std::max(p.f1, f);
  }
}

/// Computes a part's tangent cone, once.
template <class T, int K>
void make_cone(Part<T, K>& p) {
  if (p.cone_done) return;
  p.cone_done = true;
  p.cone = tangent_cone(p);
}

/// The two halves of a part (de Casteljau at 1/2: every operation a halving of a sum, so
/// the halves' control points are within (K + 1) ulp of the exact ones), finished.
template <class T, int K>
void halve(const Part<T, K>& p, Part<T, K>& l, Part<T, K>& r) {
  auto one = [](std::array<T, K + 1> w, std::array<T, K + 1>& L, std::array<T, K + 1>& R) {
    L[0] = w[0];
    R[K] = w[K];
    for (int j = 1; j <= K; ++j) {
      for (int i = 0; i + j <= K; ++i) w[std::size_t(i)] = (w[std::size_t(i)] + w[std::size_t(i + 1)]) * T(0.5);
      L[std::size_t(j)] = w[0];
      R[std::size_t(K - j)] = w[std::size_t(K - j)];
    }
  };
  one(p.x, l.x, r.x);
  one(p.y, l.y, r.y);
  const T m = (p.lo + p.hi) * T(0.5);
  l.lo = p.lo;
  l.hi = m;
  r.lo = m;
  r.hi = p.hi;
  finish(l);
  finish(r);
}

/// The point and first derivative of a whole curve at s (any real s: de Casteljau's
/// recurrence is the polynomial's identity beyond [0, 1] too).
template <class T, int K>
void value_and_derivative(const Part<T, K>& c, T s, T& px, T& py, T& dx, T& dy) {
  std::array<T, K + 1> wx = c.x, wy = c.y;
  const T u = 1 - s;
  for (int j = 1; j < K; ++j)
    for (int i = 0; i + j <= K; ++i) {
      wx[std::size_t(i)] = u * wx[std::size_t(i)] + s * wx[std::size_t(i + 1)];
      wy[std::size_t(i)] = u * wy[std::size_t(i)] + s * wy[std::size_t(i + 1)];
    }
  dx = T(K) * (wx[1] - wx[0]);
  dy = T(K) * (wy[1] - wy[0]);
  px = u * wx[0] + s * wx[1];
  py = u * wy[0] + s * wy[1];
}

/// Whether the control boxes of two parts are apart by more than `slack`.
template <class T, int K, int L>
bool boxes_apart(const Part<T, K>& a, const Part<T, L>& b, T slack) {
  return a.x0 > b.x1 + slack || b.x0 > a.x1 + slack || a.y0 > b.y1 + slack || b.y0 > a.y1 + slack;
}

/// Whether part q lies entirely on one side of part p's fat line (the band parallel to
/// p's chord that holds p's control points), widened by `slack` [SederbergNishita90]:
/// then the parts have no common point.
template <class T, int K, int L>
bool fat_line_rejects(Part<T, K>& p, const Part<T, L>& q, T slack) {
  make_fat_line(p);
  if (!p.fat) return false;
  const T lo = p.f0 - slack, hi = p.f1 + slack;
  bool below = true, above = true;
  for (std::size_t j = 0; j <= std::size_t(L); ++j) {
    const T f = p.nx * q.x[j] + p.ny * q.y[j];
    below = below && f < lo;
    above = above && f > hi;
  }
  return below || above;
}

/// Whether no line direction lies in both cones, with a margin of sine Limits::cone_gap:
/// then the parts meet at most once [SederbergMeyers88] (two common points would give a
/// chord whose direction is in both cones). For cones narrower than a half-turn (as arcs
/// of line directions, i.e. modulo a half-turn, shorter than the whole circle) this holds
/// when each extreme direction of either cone leaves the other cone's two extremes
/// strictly on one side: overlapping arcs would put an end of one inside the other.
template <class T>
bool cones_separated(const Cone<T>& a, const Cone<T>& b) {
  if (!a.ok || !b.ok) return false;
  constexpr T g = Limits<T>::cone_gap;
  auto clear_of = [](T px, T py, const Cone<T>& k) {
    const T c1 = px * k.uy - py * k.ux, c2 = px * k.vy - py * k.vx;
    return (c1 > g && c2 > g) || (c1 < -g && c2 < -g);
  };
  return clear_of(b.ux, b.uy, a) && clear_of(b.vx, b.vy, a) && clear_of(a.ux, a.uy, b) && clear_of(a.vx, a.vy, b);
}

/// Subdivision of two curves of degrees M and N in the unit frame. run() visits pairs of
/// parts; `refused` is set when it cannot certify the result.
template <class T, int M, int N>
class Solver {
 public:
  Solver(const Part<T, M>& a, const Part<T, N>& b, T tol) : A_(a), B_(b), tol_(tol), slack_(tol + 128 * std::numeric_limits<T>::epsilon()) {}

  /// The common points, or nothing when refused.
  std::optional<Roots<T>> solve() {
    Part<T, M> a = A_;
    Part<T, N> b = B_;
    run(a, b);
    if (refused_) return std::nullopt;
    auto* first = roots_.st.data();
    std::sort(first, first + roots_.count);
    Roots<T> out;
    for (int i = 0; i < roots_.count; ++i) {
      const auto [s, t] = roots_.st[std::size_t(i)];
      bool dup = false;
      for (int j = 0; j < out.count; ++j) {
        const T ds = std::abs(out.st[std::size_t(j)].first - s), dt = std::abs(out.st[std::size_t(j)].second - t);
        if (ds <= Limits<T>::duplicate && dt <= Limits<T>::duplicate) {
          dup = true;
          break;
        }
        if (ds < Limits<T>::near_pair && dt < Limits<T>::near_pair) return std::nullopt;
      }
      if (!dup) out.st[std::size_t(out.count++)] = {s, t};
    }
    if (out.count > M * N) return std::nullopt;
    return out;
  }

 private:
  Part<T, M> A_;
  Part<T, N> B_;
  T tol_, slack_;
  int nodes_ = 0;
  bool refused_ = false;
  Roots<T> roots_;

  void refuse() { refused_ = true; }

  void run(Part<T, M>& a, Part<T, N>& b) {
    if (refused_) return;
    if (++nodes_ > Limits<T>::max_nodes) return refuse();
    if (boxes_apart(a, b, slack_) || fat_line_rejects(a, b, slack_) || fat_line_rejects(b, a, slack_)) return;
    make_cone(a);
    make_cone(b);
    if (cones_separated(a.cone, b.cone)) {
      // At most one common point in this pair: Newton's method from the chords' closest
      // points. A solution inside the pair is that point, and the pair is done; otherwise
      // (no convergence, or a point of another pair) the pair is halved further, until
      // boxes or fat lines reject its parts or a part holds the point.
      T s, t;
      seed(a, b, s, t);
      if (newton(s, t)) {
        // Inside the pair: within 1e-10 of its widths (a point on the boundary of two
        // pairs, found from both, is merged later), and within rounding of [0, 1]^2.
        constexpr T e8 = 8 * std::numeric_limits<T>::epsilon();
        const T ma = T(1e-10) * (a.hi - a.lo) + e8, mb = T(1e-10) * (b.hi - b.lo) + e8;
        const bool in_pair = s >= a.lo - ma && s <= a.hi + ma && t >= b.lo - mb && t <= b.hi + mb;
        const bool in_domain = s >= -e8 && s <= 1 + e8 && t >= -e8 && t <= 1 + e8;
        if (in_pair && in_domain) return add(std::clamp(s, T(0), T(1)), std::clamp(t, T(0), T(1)));
        constexpr T z = Limits<T>::end_zone;
        if (!in_domain && s > -z && s < 1 + z && t > -z && t < 1 + z) return refuse();
      }
    }
    const T wa = a.hi - a.lo, wb = b.hi - b.lo;
    const bool can_a = wa > Limits<T>::min_width, can_b = wb > Limits<T>::min_width;
    if (!can_a && !can_b) return refuse();
    const T da = (a.x1 - a.x0) + (a.y1 - a.y0), db = (b.x1 - b.x0) + (b.y1 - b.y0);
    if (can_a && (!can_b || da >= db)) {
      Part<T, M> l, r;
      halve(a, l, r);
      run(l, b);
      run(r, b);
    } else {
      Part<T, N> l, r;
      halve(b, l, r);
      run(a, l);
      run(a, r);
    }
  }

  void add(T s, T t) {
    if (roots_.count == Roots<T>::capacity) return refuse();
    roots_.st[std::size_t(roots_.count++)] = {s, t};
  }

  /// Start of Newton's method: the closest points of the parts' chords (where the lines
  /// through them cross, clamped to the chords), lifted to the whole pieces' parameters.
  static void seed(const Part<T, M>& a, const Part<T, N>& b, T& s, T& t) {
    const T ex = a.x[M] - a.x[0], ey = a.y[M] - a.y[0], fx = b.x[N] - b.x[0], fy = b.y[N] - b.y[0];
    const T gx = b.x[0] - a.x[0], gy = b.y[0] - a.y[0];
    const T den = ex * fy - ey * fx;
    T u = T(0.5), v = T(0.5);
    if (den != 0) {
      u = std::clamp((gx * fy - gy * fx) / den, T(0), T(1));
      v = std::clamp((gx * ey - gy * ex) / den, T(0), T(1));
    }
    s = a.lo + u * (a.hi - a.lo);
    t = b.lo + v * (b.hi - b.lo);
  }

  /// Newton's method on F(s, t) = A(s) - B(t) = 0 over the whole curves, Jacobian
  /// [A'(s), -B'(t)]. True when a step below 1e-12 in both parameters was taken (the
  /// iterate after it is then accurate to rounding: quadratic convergence) at a point
  /// where the curves are within the near-miss distance; false when the Jacobian is
  /// singular, an iterate leaves [-1/2, 3/2]^2 or 24 steps do not converge.
  bool newton(T& s, T& t) const {
    for (int it = 0; it < 24; ++it) {
      T ax, ay, adx, ady, bx, by, bdx, bdy;
      value_and_derivative(A_, s, ax, ay, adx, ady);
      value_and_derivative(B_, t, bx, by, bdx, bdy);
      const T fx = ax - bx, fy = ay - by;
      const T det = adx * bdy - ady * bdx;
      if (!(std::abs(det) > 0)) return false;
      const T ds = -(fx * bdy - fy * bdx) / det, dt = (adx * fy - ady * fx) / det;
      if (!std::isfinite(ds) || !std::isfinite(dt)) return false;
      s += ds;
      t += dt;
      if (!(s > T(-0.5) && s < T(1.5) && t > T(-0.5) && t < T(1.5))) return false;
      // The residual before this last step (within rounding of the one after it: the
      // step moved the point by under 1e-12 of the curves' speed, about 1e-12).
      if (std::abs(ds) <= T(1e-12) && std::abs(dt) <= T(1e-12)) return std::sqrt(fx * fx + fy * fy) <= tol_;  // unit frame
    }
    return false;
  }
};

/// Copies control points into the unit frame: (P - origin) 2^-e.
template <class T, int K>
Part<T, K> unit_part(std::span<const Point<T, 2>> P, const Point<T, 2>& origin, T scale) {
  Part<T, K> p;
  for (std::size_t i = 0; i <= std::size_t(K); ++i) {
    p.x[i] = (P[i][0] - origin[0]) * scale;
    p.y[i] = (P[i][1] - origin[1]) * scale;
  }
  finish(p);
  return p;
}

/// The unit frame of one intersection problem, shared by every pair of pieces: points
/// map to (P - origin) scale, with scale = 2^-e the power of two that brings the largest
/// |P - origin| of both curves into [1/2, 1); tol is the near-miss distance in that frame.
template <class T>
struct Frame {
  Point<T, 2> origin;
  T scale;
  T tol;
};

/// The general engine's frame and near-miss distance (algo/intersect.hpp, solve()): origin
/// at a's first control point, tol = 1e-10 of the larger control-box diagonal of the two
/// curves (each curve given by its pieces' control points), at least 64 eps. Nothing when
/// both curves are one point or the scale would leave the range of T.
template <class T>
std::optional<Frame<T>> unit_frame(std::span<const std::span<const Point<T, 2>>> a, std::span<const std::span<const Point<T, 2>>> b) {
  if (a.empty() || b.empty() || a.front().empty()) return std::nullopt;
  const Point<T, 2> origin = a.front().front();
  T extent = 0;  // half the extent (core/unit_frame.hpp)
  for (const auto* c : {&a, &b})
    for (const auto& piece : *c) extent = std::max(extent, casteljau::detail::half_extent<T, 2>(piece, origin));
  if (!(extent > 0) || !std::isfinite(extent)) return std::nullopt;
  const int e = casteljau::detail::unit_exponent(extent);
  // 2^-e: multiplying by it is exact (as ldexp) unless a result is subnormal.
  const T scale = std::ldexp(T(1), -e);
  if (!std::isfinite(scale) || !(scale > 0)) return std::nullopt;
  T size = 0;
  for (const auto* c : {&a, &b}) {
    T x0 = std::numeric_limits<T>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& piece : *c)
      for (const auto& q : piece) {
        x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]);
        y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
      }
    const T w = (x1 - x0) * scale, h = (y1 - y0) * scale;  // below 2: no overflow
    size = std::max(size, std::sqrt(w * w + h * h));
  }
  return Frame<T>{origin, scale, std::max(T(1e-10) * size, 64 * std::numeric_limits<T>::epsilon())};
}

template <class T, int M, int N>
std::optional<Roots<T>> solve_degrees(std::span<const Point<T, 2>> a, std::span<const Point<T, 2>> b, const Frame<T>& f) {
  return Solver<T, M, N>(unit_part<T, M>(a, f.origin, f.scale), unit_part<T, N>(b, f.origin, f.scale), f.tol).solve();
}

template <class T, int M>
std::optional<Roots<T>> solve_second(std::span<const Point<T, 2>> a, std::span<const Point<T, 2>> b, const Frame<T>& f) {
  switch (b.size()) {
    case 2: return solve_degrees<T, M, 1>(a, b, f);
    case 3: return solve_degrees<T, M, 2>(a, b, f);
    case 4: return solve_degrees<T, M, 3>(a, b, f);
    default: return std::nullopt;
  }
}

/// The common points of two polynomial Bézier pieces given by their control points
/// (degrees 1 to 3) in frame f, as parameters in [0, 1] sorted by s, or nothing when the
/// fast path does not apply or cannot certify its answer (then the caller runs the general
/// engine).
///
/// Method: pairs of parts are halved (the one with the larger box) and rejected by
/// control boxes and by fat lines [SederbergNishita90], each widened by tol; a pair whose
/// tangent cones are separated meets at most once [SederbergMeyers88], and Newton's method
/// on the whole pieces from the chords' closest points finds that point, accepted when it
/// lies in the pair. Refused: more than Limits::max_nodes pairs of parts or parts narrower
/// than 2^-40 (near-tangency, overlap, degenerate curves), a solution just outside [0, 1]^2
/// (near-misses at the ends), two points within 1e-3 in both parameters (candidate
/// touches), more than m n points.
///
/// Accuracy: every reported point has |A(s) - B(t)| <= tol and was reached by a Newton
/// step below 1e-12, so s and t are accurate to a few eps / sin(angle); the angle is at
/// least about 1e-5 (cone separation), so every point is a crossing.
template <class T>
std::optional<Roots<T>> intersect_in_frame(std::span<const Point<T, 2>> a, std::span<const Point<T, 2>> b, const Frame<T>& f) {
  switch (a.size()) {
    case 2: return solve_second<T, 1>(a, b, f);
    case 3: return solve_second<T, 2>(a, b, f);
    case 4: return solve_second<T, 3>(a, b, f);
    default: return std::nullopt;
  }
}

/// intersect_in_frame() for two single Bézier curves, in their own frame.
template <class T>
std::optional<Roots<T>> intersect_low_degree(std::span<const Point<T, 2>> a, std::span<const Point<T, 2>> b) {
  const std::array<std::span<const Point<T, 2>>, 1> sa{a}, sb{b};
  const auto f = unit_frame<T>(sa, sb);
  if (!f) return std::nullopt;
  return intersect_in_frame(a, b, *f);
}

}  // namespace casteljau::detail::isect_fast
