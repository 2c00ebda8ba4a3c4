// A curve of any type and dimension known at run time (1..4, double): what the io layer
// reads from curve JSON and what the command line and the renderer work on.
#pragma once

#include <utility>
#include <variant>

#include "casteljau/curves/path.hpp"

namespace casteljau::io {

/// The largest dimension the run-time interfaces dispatch to (the library itself has no
/// such limit: its types are templated on D).
inline constexpr int max_dimension = 4;

namespace detail {
template <template <class, int> class Curve>
struct AnyCurveOf {
  template <int... Ds>
  static auto make(std::integer_sequence<int, Ds...>) -> std::variant<Curve<double, Ds + 1>...>;
};
template <class... A>
struct Concat;
template <class... A, class... B, class... C>
struct Concat<std::variant<A...>, std::variant<B...>, std::variant<C...>> {
  using type = std::variant<A..., B..., C...>;
};
using Dims = std::make_integer_sequence<int, max_dimension>;
}  // namespace detail

/// Every curve type at every dimension 1..max_dimension, one flat variant so that
/// std::visit hands a generic lambda the concrete type.
using AnyCurve = typename detail::Concat<decltype(detail::AnyCurveOf<Bezier>::make(detail::Dims{})),
                                         decltype(detail::AnyCurveOf<RationalBezier>::make(detail::Dims{})),
                                         decltype(detail::AnyCurveOf<Path>::make(detail::Dims{}))>::type;

/// The dimension d of the curve.
inline int dimension(const AnyCurve& c) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::dimension; }, c);
}

}  // namespace casteljau::io
