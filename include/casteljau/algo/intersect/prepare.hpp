// Intersection engine, phase 1 (algo/intersect.hpp): the curves prepared for it. Their
// pieces in a unit frame shared by both curves, cut into monotone arcs; the near-miss
// distance and the context of solve(); the box tests and the limits on work and answer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/intersect/band.hpp"
#include "casteljau/algo/intersect/common.hpp"
#include "casteljau/algo/intersect/result.hpp"
#include "casteljau/basis/bernstein_poly.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/path.hpp"

namespace casteljau::detail::isect {

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

}  // namespace casteljau::detail::isect
