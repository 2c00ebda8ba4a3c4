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
/// root). At most 100 steps; returns the best point seen. (refine_steps: the iteration on
/// evaluators a and b, FootEval, at most `steps` steps of at most `halvings` halvings.)
template <class T, class E>
Refined<T> refine_steps(const E& a, const Arc<T>& aa, const E& b, const Arc<T>& ab, T s, T t, int steps, int halvings) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  auto clamp_s = [&](T x) { return std::clamp(x, aa.lo, aa.hi); };
  auto clamp_t = [&](T x) { return std::clamp(x, ab.lo, ab.hi); };
  s = clamp_s(s);
  t = clamp_t(t);
  Vector<T, 2> F = a.at(s) - b.at(t);
  T f = norm(F);
  for (int it = 0; it < steps && f > 0; ++it) {
    const Vector<T, 2> Ja = a.d(s), Jb = b.d(t);
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
      const Vector<T, 2> F2 = a.at(s2) - b.at(t2);
      if (norm(F2) < f) {
        s = s2;
        t = t2;
        f = norm(F2);
      }
      break;
    }
    bool improved = false;
    for (int half = 0; half < halvings; ++half) {
      const T s2 = clamp_s(s + ds), t2 = clamp_t(t + dt);
      const Vector<T, 2> F2 = a.at(s2) - b.at(t2);
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

/// refine() on the pieces' evaluators: as refine_steps() where both are evaluated exactly
/// (degree <= 32), else refine_steps() on the O(n) forms (the iteration costs O(n) per
/// step instead of O(n^2): hundreds of seeds along a degree-500 curve and its copy, each
/// up to 100 steps of up to 30 halvings at touches), then at most 8 steps of 8 halvings
/// on the pieces' own evaluation from there (about n eps of the fast form is far inside
/// Newton's basin), so that the point and its distance are the exact evaluation's.
template <class T>
Refined<T> refine(const FootEval<T>& a, const Arc<T>& aa, const FootEval<T>& b, const Arc<T>& ab, T s, T t) {
  if (!a.fast && !b.fast) return refine_steps(a, aa, b, ab, s, t, 100, 30);
  const Refined<T> r = refine_steps(a, aa, b, ab, s, t, 100, 30);
  return refine_steps(a.exact(), aa, b.exact(), ab, r.s, r.t, 8, 8);
}
template <class T>
Refined<T> refine(const Piece<T>& a, const Arc<T>& aa, const Piece<T>& b, const Arc<T>& ab, T s, T t) {
  return refine(FootEval<T>(a), aa, FootEval<T>(b), ab, s, t);
}

/// Polish of a touch (s, t) found by refine(): Newton's method on G(s, t) = ((a(s) -
/// b(t)) . b'(t), a'(s) x b'(t)) = 0 (a(s)'s foot on b is b(t), and the tangents are
/// parallel), whose root is simple at a touch of curves with different curvatures,
/// where F = a - b has a double root. Gives the touch to a few eps instead of sqrt(eps).
/// Returns the polished point if Newton converged (at most 16 steps) to a common point
/// (distance <= tol) within 1e-5 of the start, else nothing.
template <class T, class E>
std::optional<Refined<T>> polish_steps(const E& a, const Arc<T>& aa, const E& b, const Arc<T>& ab, Refined<T> r, Refined<T> from,
                                       T tol, T converged) {
  T s = from.s, t = from.t;
  for (int it = 0; it < 16; ++it) {
    const Vector<T, 2> F = a.at(s) - b.at(t), a1 = a.d(s), a2 = a.dd(s), b1 = b.d(t), b2 = b.dd(t);
    const T g1 = dot(F, b1), g2 = cross(a1, b1);
    const T j11 = dot(a1, b1), j12 = dot(F, b2) - dot(b1, b1), j21 = cross(a2, b1), j22 = cross(a1, b2);
    const T det = j11 * j22 - j12 * j21;
    if (!(std::abs(det) > 0)) return std::nullopt;
    const T ds = -(g1 * j22 - j12 * g2) / det, dt = -(j11 * g2 - j21 * g1) / det;
    if (!std::isfinite(ds) || !std::isfinite(dt)) return std::nullopt;
    s = std::clamp(s + ds, aa.lo, aa.hi);
    t = std::clamp(t + dt, ab.lo, ab.hi);
    if (std::abs(s - r.s) > T(1e-5) || std::abs(t - r.t) > T(1e-5)) return std::nullopt;
    if (std::abs(ds) <= converged * std::max(T(1), std::abs(s)) && std::abs(dt) <= converged * std::max(T(1), std::abs(t))) {
      const T d = distance(a.at(s), b.at(t));
      if (d <= tol) return Refined<T>{s, t, d};
      return std::nullopt;
    }
  }
  return std::nullopt;
}
/// (polish_steps: the iteration on evaluators a and b from `from`, converged when a step
/// is below `converged` relative.) Past degree 32 (FootEval::fast) Newton runs on the O(n)
/// forms to 1e-9 first, then on the pieces' own evaluation from there (one or two steps);
/// nothing where the fast pass fails.
template <class T>
std::optional<Refined<T>> polish_touch(const FootEval<T>& a, const Arc<T>& aa, const FootEval<T>& b, const Arc<T>& ab, Refined<T> r,
                                       T tol) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  if (!a.fast && !b.fast) return polish_steps(a, aa, b, ab, r, r, tol, 4 * eps);
  const auto x = polish_steps(a, aa, b, ab, r, r, T(1e6) * tol + 1, T(1e-9));
  if (!x) return std::nullopt;  // Newton left the start's neighbourhood or met a singular step
  return polish_steps(a.exact(), aa, b.exact(), ab, r, *x, tol, 4 * eps);
}
template <class T>
std::optional<Refined<T>> polish_touch(const Piece<T>& a, const Arc<T>& aa, const Piece<T>& b, const Arc<T>& ab, Refined<T> r,
                                       T tol) {
  return polish_touch(FootEval<T>(a), aa, FootEval<T>(b), ab, r, tol);
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

/// direction() through the piece's evaluator (O(n) past degree 32: the angle tests of
/// intersect_arcs are at 1e-6 and 1e-4, far above n eps).
template <class T>
Vector<T, 2> direction(const FootEval<T>& c, T t) {
  if (!c.fast) return direction(*c.c, t);
  for (const Vector<T, 2> v : {c.d(t), c.dd(t)}) {
    const T n = norm(v);
    if (n > 0) return v / n;
  }
  return direction(*c.c, t);
}

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
