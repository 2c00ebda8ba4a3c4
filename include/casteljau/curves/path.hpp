// Composite curves: segments of any curve type joined at breaks t0 < t1 < ... < tk,
// each segment's own domain mapped affinely onto [t_i, t_{i+1}].
#pragma once

#include <variant>
#include <vector>

#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/nurbs.hpp"
#include "casteljau/curves/catmull_rom.hpp"
#include "casteljau/curves/lagrange.hpp"
#include "casteljau/curves/cubic_spline.hpp"
#include "casteljau/curves/hermite.hpp"
#include "casteljau/curves/piecewise.hpp"
#include "casteljau/curves/polyline.hpp"

namespace casteljau {

/// The curve types a path segment may be, as templates over <T, D>: the one list a new
/// curve type joins (docs/architecture.md). CurveTypes (below) is this list and Path.
template <template <class, int> class... C>
struct CurveTypeList {};
using SegmentTypes =
    CurveTypeList<Bezier, RationalBezier, BSpline, Nurbs, Polyline, Lagrange, CatmullRom, CubicSpline, Hermite>;

namespace detail {
template <class T, int D, class List>
struct VariantOf;
template <class T, int D, template <class, int> class... C>
struct VariantOf<T, D, CurveTypeList<C...>> {
  using type = std::variant<C<T, D>...>;
};
}  // namespace detail

/// One segment of a Path: a concrete curve type (kurbo's path element enum, not a
/// virtual hierarchy).
template <class T, int D>
using Segment = typename detail::VariantOf<T, D, SegmentTypes>::type;

/// A composite curve of segments of any type (see detail::PiecewiseCurve for the
/// parametrisation, the invariants and the members). A path is continuous only where its
/// segments meet: nothing requires it (see algo/continuity.hpp to check joins).
template <class T, int D>
class Path : public detail::PiecewiseCurve<Path<T, D>, T, D, Segment<T, D>> {
  using Base = detail::PiecewiseCurve<Path<T, D>, T, D, Segment<T, D>>;

 public:
  using Base::Base;
  friend bool operator==(const Path&, const Path&) = default;
};

static_assert(DifferentiableCurve<Path<double, 2>>);

/// The pieces of every segment, each segment's break interval holding its pieces.
template <class T, int D>
Pieces<T, D> pieces(const Path<T, D>& c) {
  std::vector<BezierPiece<T, D>> segs;
  std::vector<T> breaks;
  for (std::size_t i = 0; i < c.size(); ++i) {
    append_pieces(std::visit([](const auto& s) { return pieces(s); }, c.segments()[i]), c.segment_domain(i), segs, breaks);
  }
  return Pieces<T, D>(std::move(segs), std::move(breaks));
}
static_assert(PiecewiseBezierCurve<Path<double, 2>>);

namespace detail {
template <class List>
struct AppendPath;
template <template <class, int> class... C>
struct AppendPath<CurveTypeList<C...>> {
  using type = CurveTypeList<C..., Path>;
};
}  // namespace detail

/// Every curve type of the library: the segment types and Path. The run-time interfaces
/// serve exactly these (io::CurveTypes), and the tests derive their lists from it: the
/// conformance suite, the JSON round trip and the float / long double checks each fail
/// to compile for a type without its sample (docs/architecture.md, "Adding a curve type").
using CurveTypes = typename detail::AppendPath<SegmentTypes>::type;

/// Every curve as a Path of Bézier and rational Bézier segments with the curve's own
/// parametrisation and breaks at its piece boundaries (the `to_bezier` command).
template <class C>
  requires PiecewiseBezierCurve<C>
Path<typename C::Scalar, C::dimension> to_bezier_path(const C& c) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const Pieces<T, D> p = pieces(c);
  std::vector<Segment<T, D>> segs;
  segs.reserve(p.size());
  for (const auto& s : p.segments()) segs.push_back(std::visit([](const auto& x) { return Segment<T, D>(x); }, s));
  return Path<T, D>(std::move(segs), p.breaks());
}

}  // namespace casteljau
