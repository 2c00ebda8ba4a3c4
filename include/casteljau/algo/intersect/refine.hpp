// Intersection engine, root polishing (algo/intersect.hpp): a seed refined into a common
// point (damped Newton on a(s) - b(t)), a touch polished as a simple root, and a point
// located on an arc (the roots of its coordinates' numerators, then foot-point steps).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/prepare.hpp"

namespace casteljau::detail::isect {

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

}  // namespace casteljau::detail::isect
