// Closest and farthest point of a curve to a point: the global extremum of the distance
// over the domain, from the roots of its derivative on every Bézier piece.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include "casteljau/algo/scalar_forms.hpp"
#include "casteljau/basis/roots.hpp"
#include "casteljau/core/affine.hpp"
#include "casteljau/curves/concepts.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The result of project(): the first parameter t where the distance is extreme, the
/// curve's point there and the distance. `all_t` lists every isolated parameter that ties
/// (distance equal to the extreme within 1e-12 relative; empty when t is the only one),
/// `intervals` the parameter intervals on which the distance is constant and extreme (a
/// circular arc about the point, a curve that is a single point).
template <class T, int D>
struct Projection {
  T t;
  Point<T, D> point;
  T distance;
  std::vector<T> all_t;
  std::vector<Interval<T>> intervals;
};

/// Relative tolerance under which two distances tie (shared/spec/cli.md, `project`).
template <class T>
inline constexpr T projection_tie = T(1e-12);

namespace detail {

/// |a - b| without overflow for any finite coordinates (computed on halves).
template <class T, int D>
T safe_distance(const Point<T, D>& a, const Point<T, D>& b) {
  Vector<T, D> v;
  for (int k = 0; k < D; ++k) v[k] = a[k] / 2 - b[k] / 2;
  return 2 * norm(v);
}

/// The map x -> (x - o) / 2: moves o to the origin and halves, exactly but for one
/// rounding of the difference, and never overflows for finite coordinates.
template <class T, int D>
Affine<T, D> halved_about(const Point<T, D>& o) {
  Affine<T, D> m = Affine<T, D>::scale(T(0.5));
  for (int k = 0; k < D; ++k) m.translation[k] = -(o[k] / 2);
  return m;
}

/// Candidates of one piece: its ends and every root in (0, 1) of the derivative of the
/// squared distance to q, and whether that derivative vanishes identically (the distance
/// is constant on the piece). (c(t) - q) . c'(t) is sum_k x_k x_k' for a polynomial piece
/// (degree 2n - 1); for a rational piece c = X / w its numerator is
/// sum_k X_k (X_k' w - X_k w') (degree 3n - 1; the derivative is this over w^3).
template <class T, int D, class Piece>
void projection_candidates(const Piece& c, const Point<T, D>& q, std::vector<T>& ts, bool& constant) {
  ts = {T(0), T(1)};
  constant = false;
  const ScalarForms<T, D> f = scalar_forms<T, D>(c, q);
  if (f.degree == 0) {
    constant = true;
    return;
  }
  std::vector<T> g, a;
  for (int k = 0; k < D; ++k) {
    const auto gk = bernstein_product<T>(f.x[k], derivative_numerator(f, k));
    const auto ak = bernstein_product<T>(bernstein_abs<T>(f.x[k]), derivative_numerator(f, k, true));
    g = g.empty() ? gk : bernstein_sum<T>(g, gk);
    a = a.empty() ? ak : bernstein_sum<T>(a, ak);
  }
  // Each coefficient is a sum of O(n) products of O(n)-term convex combinations: its
  // rounding error is below about 8 (deg + 2) eps of its absolute-value bound.
  const T slack = 8 * static_cast<T>(g.size() + 2);
  if (vanishes(g, a, slack)) {
    constant = true;
    return;
  }
  // An interior extremum of the distance is a sign change of g (or g vanishes on the whole
  // piece, handled above): the sign-change roots of the root engine's first stage are all
  // the candidates needed; a root of even multiplicity is a stationary inflection of the
  // distance, never its extremum, so the engine's multiplicity stages (three more root
  // isolations) are skipped here.
  for (T r : bernstein_roots<T>(g))
    if (r > 0 && r < 1) ts.push_back(r);
}

}  // namespace detail

/// The point of the curve nearest to q over its whole domain (the farthest with
/// `farthest`), guaranteed global: on every Bézier piece the extremum is at an end of the
/// piece (the domain's ends and the breaks) or at a sign change of the derivative of the
/// squared distance, and every sign change is found (bernstein_roots: Bernstein
/// subdivision isolates them all, odd multiplicities included); every candidate is
/// evaluated and the best kept. Ties (distances equal within 1e-12
/// relative, plus 64 eps of the curve's extent from q for distances near 0) are all
/// reported; a piece on which the distance is constant (the derivative vanishes within
/// its rounding bound: a circular arc about q, a piece that is a point) gives an
/// interval. A curve that is a single point answers its domain's start, with the whole
/// domain as an interval.
///
/// Accuracy: the distance to a few eps of the curve's extent; a parameter at a simple
/// root to a few eps over |d^2/dt^2 distance| (a flat minimum, e.g. at the centre of
/// curvature, is located less well, but its distance is as accurate). Cost per piece of
/// degree n: the root isolation of a degree 2n - 1 (3n - 1 rational) Bernstein form plus
/// one evaluation per candidate. Throws NumericalError if a root solve does not
/// converge, InvalidArgument("point", ...) for a non-finite q.
template <class C>
  requires PiecewiseBezierCurve<C>
Projection<typename C::Scalar, C::dimension> project(const C& c, const Point<typename C::Scalar, C::dimension>& q,
                                                      bool farthest = false) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  require_finite_point(q, "point");
  const auto& p = pieces(c);  // a reference when c is Pieces; else the local owns them
  struct Candidate {
    T t;
    T d;
  };
  // Distances are measured on the curve moved so that q is the origin, and halved (so
  // that nothing overflows): their rounding is then a few eps of |c(t) - q|, not of the
  // coordinates (a unit curve at 1e12 from the origin keeps its digits).
  const auto rel = p.transform(detail::halved_about(q));
  const auto distance_at = [&](const auto& rel_piece, T t) { return 2 * norm(rel_piece(t).to_vector()); };
  std::vector<Candidate> cand;
  std::vector<std::pair<Interval<T>, T>> flat;  // constant-distance pieces and their distance
  T reach = 0;
  std::vector<T> ts;
  for (std::size_t i = 0; i < p.size(); ++i) {
    bool constant = false;
    std::visit(
        [&](const auto& piece) {
          const auto& rp = std::get<std::decay_t<decltype(piece)>>(rel.segments()[i]);
          for (const auto& P : piece.points()) reach = std::max(reach, detail::safe_distance(P, q));
          detail::projection_candidates<T, D>(piece, q, ts, constant);
          for (T t : ts) cand.push_back({p.global_parameter(i, t), distance_at(rp, t)});
          if (constant) flat.push_back({p.segment_domain(i), distance_at(rp, T(0))});
        },
        p.segments()[i]);
  }
  auto better = [&](T a, T b) { return farthest ? a > b : a < b; };
  T best = cand.front().d;
  for (const auto& x : cand)
    if (better(x.d, best)) best = x.d;
  const T tol = projection_tie<T> * best + 64 * std::numeric_limits<T>::epsilon() * reach;
  auto ties = [&](T d) { return std::abs(d - best) <= tol; };

  Projection<T, D> r{};
  r.distance = best;
  for (const auto& [iv, d] : flat) {
    if (!ties(d)) continue;
    if (!r.intervals.empty() && r.intervals.back().hi == iv.lo)
      r.intervals.back().hi = iv.hi;  // adjacent pieces: one interval
    else
      r.intervals.push_back(iv);
  }
  std::sort(cand.begin(), cand.end(), [](const Candidate& a, const Candidate& b) { return a.t < b.t; });
  const Interval<T> dom = p.domain();
  const T merge = T(1e-9) * dom.length();  // one minimiser seen from two pieces, or twice
  for (const auto& x : cand) {
    if (!ties(x.d)) continue;
    const bool inside = std::any_of(r.intervals.begin(), r.intervals.end(),
                                    [&](const Interval<T>& iv) { return x.t >= iv.lo && x.t <= iv.hi; });
    if (inside) continue;
    if (!r.all_t.empty() && x.t - r.all_t.back() <= merge) continue;
    r.all_t.push_back(x.t);
  }
  r.t = r.all_t.empty() ? r.intervals.front().lo : r.all_t.front();
  if (!r.intervals.empty()) r.t = std::min(r.t, r.intervals.front().lo);
  if (r.all_t.size() == 1 && r.intervals.empty()) r.all_t.clear();
  r.point = p(r.t);
  // The distance reported is the one at the reported parameter (equal to best within tol).
  r.distance = distance_at(rel, r.t);
  return r;
}

}  // namespace casteljau
