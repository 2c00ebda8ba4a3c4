// Closest and farthest point of a curve to a point: the global extremum of the distance
// over the domain, from the roots of its derivative on every Bézier piece.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
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

/// Relative tolerance under which two distances tie (docs/cli.md, `project`).
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
  // the candidates needed where they are simple; a root of even multiplicity is a
  // stationary inflection of the distance, never its extremum.
  const std::vector<T> simple = bernstein_roots<T>(g);
  // A flat extremum (the point at a centre of curvature: g has a triple root there, the
  // distance is flat to fourth order) is a root of odd multiplicity m >= 3 of g: rounding
  // splits it into a cluster of sign changes within about eps^(1/m) of it, one answer
  // seen several times, each located poorly. It shows as roots closer than the engine's
  // largest cluster radius (1e-3) or as a root where g' is within its rounding noise of
  // zero; then the multiplicity stages (up to three more isolations, on g's derivatives)
  // merge the cluster into one root located as the simple root of g^(m-1). Simple roots
  // keep the cheap path.
  const T noise = slack * std::numeric_limits<T>::epsilon() * detail::max_abs<T>(std::span<const T>(a));
  bool multiple = false;
  for (std::size_t i = 0; i + 1 < simple.size() && !multiple; ++i) multiple = simple[i + 1] - simple[i] <= T(1e-3);
  if (!multiple && !simple.empty() && g.size() > 2) {
    const std::vector<T> dg = bernstein_derivative_coefficients<T>(g);
    // g'(r) is below this bound only if r is a multiple root as far as the data tell: a
    // simple root with |g'(r)| this small moves by noise / |g'| >= 1e-4 under rounding.
    const T small = std::max(T(1e4) * noise, std::sqrt(noise * detail::max_abs<T>(std::span<const T>(dg))));
    for (T r : simple) multiple = multiple || std::abs(bernstein_value_fast<T>(std::span<const T>(dg), r)) <= small;
  }
  if (!multiple) {
    for (T r : simple)
      if (r > 0 && r < 1) ts.push_back(r);
    return;
  }
  for (const auto& r : bernstein_roots_with_multiplicity<T>(g, {T(0), T(1)}, noise))
    if (r.t > 0 && r.t < 1) ts.push_back(r.t);
}

/// The sign of the slope of the distance to q of a rational piece with extreme weights at
/// its own parameter s in [0, 1], found on the piece itself rather than on its regular
/// parts: a part that passes within 1e-16 of a corner of the control polygon has its
/// control points rounded to the corner, so that the distance is constant on it to
/// rounding and its candidates are its ends, which tie, while the extremum is well
/// defined by the direction of the curve there (weights 1, 1e30, 1 and the point
/// (1.5, 1.2): the closest point is at t = 0.387, where the curve is within 1e-30 of the
/// corner (1, 1) and its tangent is normal to the way to q). `rel` is the piece moved so
/// that q is the origin (and halved); the sign is that of g(s) = rel(s) . R'(s), R'
/// without cancellation (RationalBezier::jet, its direction only). Cost O(n^2).
template <class T, int D>
int distance_slope(const RationalBezier<T, D>& rel, T s) {
  const auto j = rel.jet(s, false);
  const T g = dot(rel(s).to_vector(), j.r);
  return g > 0 ? 1 : (g < 0 ? -1 : 0);
}

/// The sign change of distance_slope between lo < hi, where it is `before` at lo and
/// -before at hi, bisected: in s, and geometrically while the bracket spans more than a
/// factor of two (s ~ 1e-300 .. 1e-30 is resolved in about 70 steps). Returns the two
/// neighbouring parameters about it (equal where the slope's sign is 0). At most 256
/// steps.
template <class T, int D>
std::pair<T, T> bisect_slope(const RationalBezier<T, D>& rel, T lo, T hi, int before) {
  for (int step = 0; step < 256; ++step) {
    T m = lo + (hi - lo) / 2;
    if (hi > 2 * lo) m = std::sqrt(std::max(lo, std::numeric_limits<T>::denorm_min())) * std::sqrt(hi);
    if (!(m > lo && m < hi)) break;
    const int g = distance_slope(rel, m);
    if (g == 0) return {m, m};
    (g == before ? lo : hi) = m;
  }
  return {lo, hi};
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
  requires detail::is_pieces<C>
Projection<typename C::Scalar, C::dimension> project(const C& c, const Point<typename C::Scalar, C::dimension>& q,
                                                      bool farthest = false) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  require_finite_point(q, "point");
  const auto& p = pieces(c);  // a reference when c is Pieces; else the local owns them
  struct Candidate {
    T t;
    T d;
    bool exact;             // t is the candidate's parameter exactly (not a rounded image)
    Point<T, D> point{};    // the curve's point there when not exact
    std::size_t piece = 0;  // the piece it comes from, and its own parameter there
    T own = 0;
  };
  // Distances are measured on the curve moved so that q is the origin, and halved (so
  // that nothing overflows): their rounding is then a few eps of |c(t) - q|, not of the
  // coordinates (a unit curve at 1e12 from the origin keeps its digits).
  // Each piece is moved when first needed (a pruned piece never is: moving them all was a
  // copy of the whole curve per query).
  const Affine<T, D> to_rel = detail::halved_about(q);
  using Segment = typename std::decay_t<decltype(p)>::SegmentType;
  std::vector<std::optional<Segment>> moved(p.size());
  const auto rel_segment = [&](std::size_t i) -> const Segment& {
    if (!moved[i]) moved[i] = std::visit([&](const auto& c) { return Segment(c.transform(to_rel)); }, p.segments()[i]);
    return *moved[i];
  };
  const auto distance_at = [&](const auto& rel_piece, T t) { return 2 * norm(rel_piece(t).to_vector()); };
  std::vector<Candidate> cand;
  std::vector<std::pair<Interval<T>, T>> flat;  // constant-distance pieces and their distance
  T reach = 0;
  std::vector<T> ts;
  // Pruning (bounding boxes), for curves of many pieces: the box of a piece's control
  // points contains the piece (convex hull: Bézier pieces, rational ones with positive
  // weights), so its distance from q bounds the piece's distances below (nearest; its
  // farthest corner bounds them above, farthest). The pieces go in the order of that bound,
  // the best distance so far starting from the pieces' end points; once a piece's bound is
  // worse than the best so far by more than the tie tolerance and the rounding, it and
  // every piece after it hold no candidate that can win or tie, and their root isolation
  // is skipped (a 1000-piece cubic B-spline: tens of pieces isolated, not 1000). A run of
  // skipped pieces (in the curve's order) leaves one candidate, its first piece's start:
  // it does not tie, so tied candidates on either side stay in separate runs below.
  for (const auto& seg : p.segments())
    std::visit([&](const auto& piece) { for (const auto& P : piece.points()) reach = std::max(reach, detail::safe_distance(P, q)); }, seg);
  const auto better_d = [&](T a, T b) { return farthest ? a > b : a < b; };
  T so_far = farthest ? T(0) : std::numeric_limits<T>::infinity();
  const std::size_t n_pieces = p.size();
  std::vector<T> bound(n_pieces);
  std::vector<char> prunable(n_pieces, 0);
  for (std::size_t i = 0; i < n_pieces; ++i) {
    std::visit(
        [&](const auto& piece) {
          for (const auto* P : {&piece.points().front(), &piece.points().back()}) {
            const T d = 2 * norm(to_rel(*P).to_vector());
            if (better_d(d, so_far)) so_far = d;
          }
          if constexpr (requires { piece.weights(); }) {
            for (const T w : piece.weights())
              if (!(w > 0)) return;
          }
          // The box of the moved (halved) control points: its nearest and farthest
          // distance from the origin, doubled.
          Vector<T, D> nearv, farv;
          for (int k = 0; k < D; ++k) {
            T lo = std::numeric_limits<T>::infinity(), hi = -lo;
            for (const auto& P : piece.points()) {
              const T x = to_rel(P)[k];
              lo = std::min(lo, x);
              hi = std::max(hi, x);
            }
            nearv[k] = std::max({T(0), lo, -hi});
            farv[k] = std::max(std::abs(lo), std::abs(hi));
          }
          bound[i] = 2 * norm(farthest ? farv : nearv);
          prunable[i] = n_pieces > 1;
        },
        p.segments()[i]);
  }
  const T eps = std::numeric_limits<T>::epsilon();
  // More than the final tie tolerance (projection_tie best + 64 eps reach; best <= reach).
  const T margin = 4 * projection_tie<T> * reach + 256 * eps * reach;
  // Unprunable pieces first, then by their bound, best first; a piece whose bound is
  // already worse than the end points' best is never visited (the best only improves).
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < n_pieces; ++i)
    if (!prunable[i] || (farthest ? bound[i] >= so_far - margin : bound[i] <= so_far + margin)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (prunable[a] != prunable[b]) return prunable[a] < prunable[b];
    return better_d(bound[a], bound[b]) || (bound[a] == bound[b] && a < b);
  });
  std::vector<char> visited(n_pieces, 0);
  // Candidates at a break come from both pieces (the end of one, the start of the next):
  // both kept, as they carry each piece's own distance (a path may have a gap there).
  const auto process = [&](std::size_t i, const auto& piece, const Interval<T>& own) {
    bool constant = false;
    const auto& rp = std::get<std::decay_t<decltype(piece)>>(rel_segment(i));
    const auto parts = detail::regular_parts(piece);
    if (parts.front().map.identity) {
      detail::projection_candidates<T, D>(piece, q, ts, constant);
      for (T t : ts) cand.push_back({p.lift(i, t), distance_at(rp, t), true, {}, i, t});
      if (constant) flat.push_back({p.lift(i, own), distance_at(rp, T(0))});
      return;
    }
    // Extreme weights: candidates on parts with tame parametrisations (the same
    // splits on the moved curve: same weights), their points and distances taken
    // on the parts, the parameters mapped back (rounded).
    const auto rparts = detail::regular_parts(rp);
    bool all_constant = true;
    for (std::size_t j = 0; j < parts.size(); ++j) {
      detail::projection_candidates<T, D>(parts[j].piece, q, ts, constant);
      std::sort(ts.begin(), ts.end());  // in the curve's order: parameters mapped back may round together
      all_constant = all_constant && constant;
      for (T u : ts) {
        const T own = parts[j].map.t_of(u);
        cand.push_back({p.lift(i, own), distance_at(rparts[j].piece, u), false, parts[j].piece(u), i, own});
      }
    }
    if (all_constant) flat.push_back({p.lift(i, own), distance_at(rp, T(0))});
  };
  for (const std::size_t i : order) {
    if (prunable[i] && (farthest ? bound[i] < so_far - margin : bound[i] > so_far + margin)) break;
    const std::size_t first = cand.size();
    std::visit([&](const auto& piece) { process(i, piece, p.own_domain(i)); }, p.segments()[i]);
    for (std::size_t c = first; c < cand.size(); ++c)
      if (better_d(cand[c].d, so_far)) so_far = cand[c].d;
    visited[i] = 1;
  }
  for (std::size_t i = 0; i < n_pieces; ++i) {
    if (visited[i] || (i > 0 && !visited[i - 1])) continue;
    std::visit([&](const auto& piece) { cand.push_back({p.lift(i, T(0)), 2 * norm(to_rel(piece.points().front()).to_vector()), true, {}, i, T(0)}); },
               p.segments()[i]);
  }
  std::sort(flat.begin(), flat.end(), [](const auto& a, const auto& b) { return a.first.lo < b.first.lo; });
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
  // By parameter, then piece, stable: within a piece the candidates were made in its order
  // (parts, sorted parameters), which equal parameters (a part's rounded image) keep for
  // the runs below.
  std::stable_sort(cand.begin(), cand.end(),
                   [](const Candidate& a, const Candidate& b) { return a.t < b.t || (a.t == b.t && a.piece < b.piece); });
  const Interval<T> dom = p.domain();
  const T merge = T(1e-9) * dom.length();  // one minimiser seen from two pieces, or twice
  // Every stationary point of the distance is a candidate, so between consecutive
  // candidates (in t) the distance is monotone: a run of consecutive tied candidates
  // bounds the distance within the tie on its whole stretch. Such a run is one extremum
  // at the resolution of the tie (a flat minimum, whose rounded derivative changes sign
  // several times; a curve hugging its control polygon at an extreme weight), reported
  // once, at its best candidate. Distinct tied extrema are separated by a stationary
  // point of the other kind, whose distance does not tie.
  const auto inside = [&](T t) {
    return std::any_of(r.intervals.begin(), r.intervals.end(), [&](const Interval<T>& iv) { return t >= iv.lo && t <= iv.hi; });
  };
  // A run's best candidate from a part of a piece with extreme weights: located again on
  // the piece, from the sign of the distance's slope there (detail::distance_slope), and
  // taken if its distance ties (t within 1e-30 of 1 has no double of its own: the part's
  // rounded image stays). The signs are taken at the piece's own parameters of the run's
  // candidates and of those either side (the piece's ends where those are on other
  // pieces); the extremum is the change of sign (from < 0 to > 0 for the closest point)
  // nearest to the pick, bisected.
  const auto refine_pick = [&](std::size_t first, std::size_t end, std::size_t pick) {
    const std::size_t k = cand[pick].piece;
    std::vector<T> at{T(0), T(1)};
    for (std::size_t c = first > 0 ? first - 1 : first; c < std::min(end + 1, cand.size()); ++c)
      if (cand[c].piece == k) at.push_back(cand[c].own);
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    std::visit(
        [&](const auto& rp) {
          if constexpr (requires { rp.jet(T(0), false); }) {
            if (rp.degree() > detail::rational_jet_max_degree) return;
            const int before = farthest ? 1 : -1;
            std::vector<int> sg(at.size());
            for (std::size_t x = 0; x < at.size(); ++x) sg[x] = detail::distance_slope(rp, at[x]);
            std::optional<std::pair<T, T>> found;
            T gap = std::numeric_limits<T>::infinity();
            for (std::size_t x = 0; x < at.size(); ++x) {
              std::optional<std::pair<T, T>> here;
              if (sg[x] == 0) here = std::pair<T, T>{at[x], at[x]};
              if (x + 1 < at.size() && sg[x] == before && sg[x + 1] == -before) here = std::pair<T, T>{at[x], at[x + 1]};
              if (!here) continue;
              const T g = std::max({T(0), here->first - cand[pick].own, cand[pick].own - here->second});
              if (g < gap) {
                gap = g;
                found = here;
              }
            }
            if (!found) return;
            if (found->first < found->second) found = detail::bisect_slope(rp, found->first, found->second, before);
            T s = found->first, d = distance_at(rp, s);
            if (const T d2 = distance_at(rp, found->second); better(d2, d)) {
              s = found->second;
              d = d2;
            }
            if (!ties(d)) return;
            const Point<T, D> point = std::visit([&](const auto& piece) { return piece(s); }, p.segments()[k]);
            cand[pick] = {p.lift(k, s), d, false, point, k, s};
          }
        },
        rel_segment(k));
  };
  // Whether each all_t entry's own point ties: a tie found on a part of a piece with extreme
  // weights whose parameter has no double of its own (within 5e-17 of t = 1 at weight
  // 1e16) is rounded to a parameter whose point is elsewhere (t = 1: the corner's far end,
  // 0.707 from the query for the distance 0.5). Listed only when no tie resolves (below).
  std::vector<char> resolved;
  for (std::size_t i = 0; i < cand.size();) {
    if (!ties(cand[i].d)) {
      ++i;
      continue;
    }
    std::size_t j = i, pick = i;
    bool in_interval = false;
    for (; j < cand.size() && ties(cand[j].d); ++j) {
      in_interval = in_interval || inside(cand[j].t);
      if (better(cand[j].d, cand[pick].d)) pick = j;
    }
    if (!in_interval && !cand[pick].exact) refine_pick(i, j, pick);
    i = j;
    if (in_interval) continue;  // the interval stands for it
    const T t = cand[pick].t;
    if (!r.all_t.empty() && t - r.all_t.back() <= merge) continue;
    r.all_t.push_back(t);
    const Candidate& c = cand[pick];
    resolved.push_back(c.exact || ties(std::visit([&](const auto& rp) { return distance_at(rp, c.own); }, rel_segment(c.piece))));
  }
  if (std::find(resolved.begin(), resolved.end(), 1) != resolved.end()) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < r.all_t.size(); ++k)
      if (resolved[k]) r.all_t[kept++] = r.all_t[k];
    r.all_t.resize(kept);
  }
  r.t = r.all_t.empty() ? r.intervals.front().lo : r.all_t.front();
  if (!r.intervals.empty()) r.t = std::min(r.t, r.intervals.front().lo);
  if (r.all_t.size() == 1 && r.intervals.empty()) r.all_t.clear();
  r.point = p(r.t);
  // The distance reported is the one at the reported parameter (equal to best within tol).
  {
    const auto at = p.locate(r.t);
    r.distance = std::visit([&](const auto& s) { return 2 * norm(s(at.t).to_vector()); }, rel_segment(at.index));
  }
  // A candidate of a part of a piece with extreme weights: its parameter is a rounded
  // image (a point within 1e-30 of a parameter end has no double of its own), so its
  // point and distance are the ones found on the part.
  const Candidate* chosen = nullptr;
  for (const auto& x : cand)
    if (x.t == r.t && (!chosen || better(x.d, chosen->d))) chosen = &x;
  if (chosen && !chosen->exact && (r.intervals.empty() || r.t < r.intervals.front().lo)) {
    r.point = chosen->point;
    r.distance = chosen->d;
  }
  // The end of a piece before a jump (a path's gap, a B-spline's knot of multiplicity
  // p + 1) was lifted to the double below the break (Pieces::lift): the point and distance
  // above are the piece's, its left limit to rounding, as evaluation at r.t gives them.
  return r;
}

/// Every other curve type: the same, on its exact pieces (see detail::is_pieces).
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_pieces<C>)
Projection<typename C::Scalar, C::dimension> project(const C& c, const Point<typename C::Scalar, C::dimension>& q,
                                                      bool farthest = false) {
  return project(pieces(c), q, farthest);
}

}  // namespace casteljau
