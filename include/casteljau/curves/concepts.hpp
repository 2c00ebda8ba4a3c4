// The capabilities a curve type can have, one small concept each. Algorithms ask for the
// least they need; each curve type static_asserts the concepts it models.
#pragma once

#include <concepts>

#include "casteljau/core/interval.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau {

/// A parametric curve: a point for every parameter of its domain (and beyond it, by
/// extrapolating the first or last piece). The domain is the curve's own (ask domain():
/// [0, 1] only for Bézier curves); its end points are c(domain().lo), c(domain().hi).
template <class C>
concept Curve = requires(const C& c, typename C::Scalar t) {
  typename C::Scalar;
  { C::dimension } -> std::convertible_to<int>;
  { c.domain() } -> std::same_as<Interval<typename C::Scalar>>;
  { c(t) } -> std::same_as<Point<typename C::Scalar, C::dimension>>;
};

/// A curve with derivatives of any order k >= 0 with respect to its parameter (k = 0 is
/// the point as a vector; zero above the degree). At a break between pieces the right
/// piece answers, at the end of the domain the last one.
template <class C>
concept DifferentiableCurve = Curve<C> && requires(const C& c, typename C::Scalar t, int k) {
  { c.derivative_at(t, k) } -> std::same_as<Vector<typename C::Scalar, C::dimension>>;
};

/// The two halves of a curve split at one parameter.
template <class C>
struct Split {
  C left;
  C right;
};

/// A curve that splits into two curves of its own type.
template <class C>
concept SplittableCurve = Curve<C> && requires(const C& c, typename C::Scalar t) {
  { c.split(t) } -> std::same_as<Split<C>>;
};

/// A curve with an exact piecewise (rational) Bézier form: the free function pieces(c)
/// returns a Pieces<T, D> (curves/piecewise.hpp) tracing the same curve with the same
/// parametrisation. Every curve type models it; queries are written once on the pieces.
template <class C>
concept PiecewiseBezierCurve = Curve<C> && requires(const C& c) {
  { pieces(c).segments() };
  { pieces(c).breaks() };
};

/// The curve's start and end points: the points at the ends of its domain.
template <Curve C>
Point<typename C::Scalar, C::dimension> start_point(const C& c) {
  return c(c.domain().lo);
}
template <Curve C>
Point<typename C::Scalar, C::dimension> end_point(const C& c) {
  return c(c.domain().hi);
}

}  // namespace casteljau
