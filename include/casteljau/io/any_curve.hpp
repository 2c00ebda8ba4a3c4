// A curve of any registered type and dimension known at run time (1..4, double), and the
// operations the run-time interfaces (command line, renderer, later Python and the web
// explorer) call on it. The operations are compiled once, in src/io/any_curve.cpp: a
// translation unit that includes this header instantiates no curve algorithm.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/flatten_method.hpp"
#include "casteljau/curves/path.hpp"

namespace casteljau::io {

/// The largest dimension the run-time interfaces dispatch to (the library itself has no
/// such limit: its types are templated on D).
inline constexpr int max_dimension = 4;

/// The highest degree the run-time interfaces accept, in curve input and as the result
/// of `elevate`: bounds and flattening cost O(n^2) per piece, and at this degree a
/// request still answers in well under a second.
inline constexpr int max_degree = 1000;

/// The most vertices `flatten` answers with: a request whose Wang estimate (see
/// src/io/any_curve.cpp) exceeds it is refused before any work, naming the tolerance.
inline constexpr std::size_t max_flatten_vertices = 1'000'000;

/// The registry: every curve type the run-time interfaces serve, the library's own list
/// (curves/path.hpp). Its curve-JSON name, fields, reader and writer are its Format entry
/// in src/io/curve_json.cpp.
using CurveTypes = casteljau::CurveTypes;

namespace detail {
template <class List, class Dims>
struct AnyCurveOf;
template <template <class, int> class... C, int... Ds>
struct AnyCurveOf<CurveTypeList<C...>, std::integer_sequence<int, Ds...>> {
  template <template <class, int> class One>
  using AllDims = std::variant<One<double, Ds + 1>...>;
  template <class... V>
  struct Concat;
  template <class... A>
  struct Concat<std::variant<A...>> {
    using type = std::variant<A...>;
  };
  template <class... A, class... B, class... Rest>
  struct Concat<std::variant<A...>, std::variant<B...>, Rest...> {
    using type = typename Concat<std::variant<A..., B...>, Rest...>::type;
  };
  using type = typename Concat<AllDims<C>...>::type;
};
}  // namespace detail

/// Every registered curve type at every dimension 1..max_dimension, one flat variant so
/// that std::visit hands a generic lambda the concrete type.
using AnyCurve = typename detail::AnyCurveOf<CurveTypes, std::make_integer_sequence<int, max_dimension>>::type;

/// Calls f.template operator()<D>() for the run-time dimension d in 1..max_dimension (the
/// one switch from a run-time dimension to a template argument). Throws
/// InvalidArgument("", "dimension must be 1..4, got d") for any other d.
template <class F, int D = 1>
decltype(auto) dispatch_dimension(int d, F&& f) {
  if constexpr (D < max_dimension) {
    if (d != D) return dispatch_dimension<F, D + 1>(d, std::forward<F>(f));
  } else if (d != D) {
    throw InvalidArgument("", "dimension must be 1.." + std::to_string(max_dimension) + ", got " + std::to_string(d));
  }
  return f.template operator()<D>();
}

/// What only some curve types can do: the member a run-time operation calls.
enum class Capability {
  split,           ///< split(t) (SplittableCurve)
  elevate,         ///< elevate(times)
  knot_insertion,  ///< insert_knot(u, times)
  knot_removal,    ///< remove_knot(u, times, tolerance)
  degree_reduction,  ///< reduce_degree(curve, m) (Bézier) or reduce_degree(tolerance) (B-spline, NURBS)
};

/// The curve-JSON names of every registered type, in the order of CurveTypes.
[[nodiscard]] std::span<const std::string_view> curve_type_names();

/// The names of the registered types that have the capability, in registry order (from
/// the types themselves: a type that gains the member is listed with no other change).
[[nodiscard]] std::vector<std::string_view> types_with(Capability c);

/// "a bezier, rational_bezier, bspline or nurbs curve": types_with(c) for messages.
[[nodiscard]] std::string types_phrase(Capability c);

/// The dimension d of the curve.
[[nodiscard]] int dimension(const AnyCurve& c);
/// The curve's type name in curve JSON ("bezier", "polyline", ...).
[[nodiscard]] std::string_view type_name(const AnyCurve& c);
/// The curve's parameter domain.
[[nodiscard]] Interval<double> domain(const AnyCurve& c);

/// Points of one run-time dimension, stored contiguously: point i is coords[i*dim ..
/// i*dim + dim) (a (count, dim) array for numpy).
struct PointList {
  int dim = 0;
  std::vector<double> coords;

  [[nodiscard]] std::size_t size() const { return dim == 0 ? 0 : coords.size() / static_cast<std::size_t>(dim); }
  [[nodiscard]] std::span<const double> operator[](std::size_t i) const {
    return std::span<const double>(coords).subspan(i * static_cast<std::size_t>(dim), static_cast<std::size_t>(dim));
  }
  template <class V>
  void push_back(const V& p) {
    for (int k = 0; k < dim; ++k) coords.push_back(static_cast<double>(p[k]));
  }
};

/// S<double, D> for every D in 1..max_dimension, one variant: a result of the library at
/// the curve's dimension (written by the to_json of io/results.hpp).
template <template <class, int> class S>
using PerDimension = typename detail::AnyCurveOf<CurveTypeList<S>, std::make_integer_sequence<int, max_dimension>>::type;

/// An axis-aligned box in the curve's dimension.
using AnyBox = PerDimension<Box>;

/// The curve's points at the parameters t (any finite t; outside the domain the first or
/// last piece is extrapolated). Errors name "t[j]": a non-finite parameter, a point that
/// overflows, a pole of a rational curve.
[[nodiscard]] PointList evaluate(const AnyCurve& c, std::span<const double> t);

/// The order-k derivative vectors (k >= 0) at the parameters t; errors as evaluate().
[[nodiscard]] PointList derivatives(const AnyCurve& c, std::span<const double> t, int k);

/// The tight axis-aligned box of the curve over its domain.
[[nodiscard]] AnyBox bounds(const AnyCurve& c);

/// A polyline within `tolerance` of the curve, from its start to its end (algo/flatten),
/// by the given method (by default `optimal`, as flatten() and the command line). Refused
/// with InvalidArgument("tolerance", ...) when it would need more than about
/// max_flatten_vertices vertices.
[[nodiscard]] PointList flatten(const AnyCurve& c, double tolerance, FlattenMethod method = FlattenMethod::optimal);

/// The curve as a path of bezier / rational_bezier segments with the same parametrisation.
[[nodiscard]] AnyCurve to_bezier(const AnyCurve& c);

/// The same curve as its exact Bézier pieces (a Pieces<double, D> in a variant).
using AnyPieces = typename detail::AnyCurveOf<CurveTypeList<Pieces>, std::make_integer_sequence<int, max_dimension>>::type;
[[nodiscard]] AnyPieces pieces(const AnyCurve& c);

/// The halves of a curve split at t (types with a split member: bezier, rational_bezier,
/// bspline and nurbs, whose halves keep their parameter). Throws InvalidArgument
/// ("curve.type", ...) for other types, ("t", ...) for t outside the domain (for bspline
/// and nurbs: not strictly inside).
struct AnySplit {
  AnyCurve left;
  AnyCurve right;
};
[[nodiscard]] AnySplit split(const AnyCurve& c, double t);

/// The curve at degree + times (types with an elevate member); the result's degree is at
/// most max_degree, else InvalidArgument("times", ...).
[[nodiscard]] AnyCurve elevate(const AnyCurve& c, int times);

}  // namespace casteljau::io
