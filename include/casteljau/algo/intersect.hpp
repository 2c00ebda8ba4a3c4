// Intersections of plane curves: curve with curve (a line segment or polyline is a curve)
// and the self-intersections of one curve, with tangential touches and overlaps. The
// engine is in algo/intersect/, one header per phase (docs/architecture.md): prepare
// (unit frame, arcs, near-miss distance), pairs and subdivide (candidate pairs of arcs,
// subdivision and clipping, band.hpp for near-coincident parts), refine (root polishing),
// overlap (detection, joining, confirming), near and classify (near regions, touches,
// kinds), merge (one point per near region, joints and closing points) and solve (the
// driver, with the fast paths of low_degree.hpp and the tame parts of tame.hpp).
#pragma once

#include <concepts>

#include "casteljau/algo/intersect/solve.hpp"

namespace casteljau {

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
    if (auto r = detail::isect::low_degree_pieces(pa, pb)) {
      detail::isect::once_per_rest(pa, &pb, *r);
      return std::move(*r);
    }
  }
  Intersections<T> r = detail::isect::solve_extreme(pa, &pb);
  detail::isect::once_per_rest(pa, &pb, r);
  return r;
}

/// The self-intersections of a plane curve: pairs ta < tb with c(ta) = c(tb), and the
/// stretches where the curve runs over itself (overlaps, a before b). Not reported: the
/// joints of consecutive pieces, the closing point of a closed curve (c at the start and
/// end of its domain), and cusps (a "loop" smaller than 1e-8 of the curve's size, or a
/// hairpin under 1e-6 of it whose two branches stay within the near-miss distance of each
/// other: a path reversing at a joint).
/// Method, accuracy and cost as intersect(), on the pairs of distinct arcs of one curve.
template <class C>
  requires PiecewiseBezierCurve<C> && (C::dimension == 2)
Intersections<typename C::Scalar> self_intersect(const C& c) {
  const auto& p = pieces(c);
  Intersections<typename C::Scalar> r = detail::isect::solve_extreme(p, static_cast<decltype(&p)>(nullptr));
  detail::isect::once_per_rest(p, static_cast<decltype(&p)>(nullptr), r);
  return r;
}

}  // namespace casteljau
