// The capabilities a curve type can have, one small concept each. Algorithms ask for the
// least they need; each curve type static_asserts the concepts it models.
#pragma once

#include <concepts>

#include "casteljau/core/interval.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau {

/// A parametric curve: a point for every parameter of its domain (and beyond it, by
/// extrapolating the first or last piece).
template <class C>
concept Curve = requires(const C& c, typename C::Scalar t) {
  typename C::Scalar;
  { C::dimension } -> std::convertible_to<int>;
  { c.domain() } -> std::same_as<Interval<typename C::Scalar>>;
  { c(t) } -> std::same_as<Point<typename C::Scalar, C::dimension>>;
};

/// A curve with derivatives of any order k >= 1 with respect to its parameter.
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

/// A curve that lies in the convex hull of its control points (Bézier with any weights
/// > 0, B-spline): control_bounds() is then a conservative box.
template <class C>
concept ControlPolygonCurve = Curve<C> && requires(const C& c) {
  { c.points() };
  { c.control_bounds() } -> std::same_as<Box<typename C::Scalar, C::dimension>>;
};

}  // namespace casteljau
