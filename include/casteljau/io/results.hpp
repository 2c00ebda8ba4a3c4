// The library's result structs at run time and their JSON. A result of a query on an
// AnyCurve is the library's own struct at the curve's dimension, held in a variant over
// the dimensions 1..max_dimension (PerDimension, generated as AnyCurve is); no copy into
// std::vector<double>. Each struct lists its JSON fields once (Describe<S>::fields: name
// and member, or name and a function of the struct for a field the struct holds in
// another shape), and one set of to_json overloads writes any of them, so the command
// line, the server and the bindings write and read the same fields.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/fit.hpp"
#include "casteljau/io/frames.hpp"
#include "casteljau/io/intersect.hpp"
#include "casteljau/io/json.hpp"
#include "casteljau/io/knots.hpp"
#include "casteljau/io/ops.hpp"
#include "casteljau/io/queries.hpp"

namespace casteljau::io {

// The results' variants (AnyProjection, AnyFrames, ...) are declared with their
// functions, in io/queries.hpp; AnyBox in io/any_curve.hpp.

// ---------------------------------------------------------------------------------------
// Describing a struct: its JSON fields, once.

/// A field of struct S written from its member m. With omit_empty, an empty array is left
/// out (an absent std::optional always is).
template <class S, class M>
struct MemberField {
  std::string_view name;
  M S::*member;
  bool omit_empty = false;
  [[nodiscard]] const M& of(const S& s) const { return s.*member; }
};

/// A field of struct S computed from it (the struct holds it in another shape).
template <class S, class F>
struct ComputedField {
  std::string_view name;
  F get;
  bool omit_empty = false;
  [[nodiscard]] auto of(const S& s) const { return get(s); }
};

template <class S, class M>
constexpr MemberField<S, M> field(std::string_view name, M S::*member, bool omit_empty = false) {
  return {name, member, omit_empty};
}
template <class S, class F>
constexpr ComputedField<S, F> computed(std::string_view name, F get, bool omit_empty = false) {
  return {name, get, omit_empty};
}

/// Describe<S>::fields: a tuple of fields, in the order they are written.
template <class S>
struct Describe;

template <class S>
concept Described = requires { Describe<S>::fields; };

template <class T, int D>
struct Describe<Projection<T, D>> {
  using S = Projection<T, D>;
  static constexpr auto fields = std::tuple{field("t", &S::t), field("point", &S::point), field("distance", &S::distance),
                                            field("all_t", &S::all_t, true), field("intervals", &S::intervals, true)};
};

template <class T, int D>
struct Describe<Features<T, D>> {
  using S = Features<T, D>;
  static constexpr auto fields = std::tuple{field("inflections", &S::inflections), field("cusps", &S::cusps), field("extrema", &S::extrema)};
};

template <class T, int D>
struct Describe<CurveDistance<T, D>> {
  using S = CurveDistance<T, D>;
  static constexpr auto fields = std::tuple{field("distance", &S::distance), field("t", &S::t), field("points", &S::points)};
};

template <class T, int D>
struct Describe<Frame<T, D>> {
  using S = Frame<T, D>;
  static constexpr auto fields = std::tuple{field("tangent", &S::tangent), field("normal", &S::normal), field("binormal", &S::binormal),
                                            field("curvature", &S::curvature), field("torsion", &S::torsion)};
};

template <class T, int D>
struct Describe<Box<T, D>> {
  using S = Box<T, D>;
  static constexpr auto fields = std::tuple{field("min", &S::lo), field("max", &S::hi)};
};

template <class T>
struct Describe<CurveIntersection<T>> {
  using S = CurveIntersection<T>;
  static constexpr auto fields = std::tuple{computed<S>("t", [](const S& x) { return std::array<T, 2>{x.ta, x.tb}; }),
                                            field("point", &S::point), field("kind", &S::kind)};
};

template <class T>
struct Describe<CurveOverlap<T>> {
  using S = CurveOverlap<T>;
  static constexpr auto fields =
      std::tuple{field("a", &S::a), computed<S>("b", [](const S& x) { return std::array<T, 2>{x.b_start, x.b_end}; })};
};

template <class T>
struct Describe<Intersections<T>> {
  using S = Intersections<T>;
  static constexpr auto fields = std::tuple{field("intersections", &S::points), field("overlaps", &S::overlaps)};
};

template <class T>
struct Describe<LevelSet<T>> {
  using S = LevelSet<T>;
  static constexpr auto fields = std::tuple{field("t", &S::t), field("intervals", &S::intervals)};
};

// The io layer's own results, which hold curves of any type (AnyCurve).

template <>
struct Describe<AnyKnotRemoval> {
  using S = AnyKnotRemoval;
  static constexpr auto fields = std::tuple{field("curve", &S::curve), field("removed", &S::removed)};
};

template <>
struct Describe<AnyFit> {
  using S = AnyFit;
  static constexpr auto fields = std::tuple{field("curve", &S::curve), field("max_error", &S::max_error), field("smoothing", &S::smoothing)};
};

template <>
struct Describe<AnyReduction> {
  using S = AnyReduction;
  static constexpr auto fields = std::tuple{field("curve", &S::curve), field("max_error", &S::max_error)};
};

template <>
struct Describe<MovingFrames> {
  using S = MovingFrames;
  static constexpr auto fields =
      std::tuple{field("tangents", &S::tangents), field("normals", &S::normals), field("binormals", &S::binormals)};
};

template <>
struct Describe<AnySubdivision> {
  using S = AnySubdivision;
  static constexpr auto fields = std::tuple{field("points", &S::points), field("limit", &S::limit)};
};

// ---------------------------------------------------------------------------------------
// Writing. Numbers as doubles (nlohmann's shortest round-trip form); Point and Vector
// are in io/json.hpp.

template <class T>
  requires std::is_floating_point_v<T>
[[nodiscard]] OrderedJson to_json(T x) {
  return static_cast<double>(x);
}

template <class T>
[[nodiscard]] OrderedJson to_json(const Interval<T>& iv) {
  return OrderedJson::array({static_cast<double>(iv.lo), static_cast<double>(iv.hi)});
}

template <class T>
  requires(std::is_integral_v<T> && !std::is_same_v<T, bool>)
[[nodiscard]] OrderedJson to_json(T x) {
  return x;
}

/// Points of one run-time dimension as an array of coordinate arrays.
[[nodiscard]] inline OrderedJson to_json(const PointList& P) {
  OrderedJson a = OrderedJson::array();
  for (std::size_t i = 0; i < P.size(); ++i) {
    OrderedJson p = OrderedJson::array();
    for (const double x : P[i]) p.push_back(x);
    a.push_back(std::move(p));
  }
  return a;
}

[[nodiscard]] inline OrderedJson to_json(IntersectionKind k) { return k == IntersectionKind::tangent ? "tangent" : "crossing"; }

template <class X>
[[nodiscard]] OrderedJson to_json(const std::optional<X>& x);
template <class X>
[[nodiscard]] OrderedJson to_json(const std::vector<X>& v);
template <class X, std::size_t N>
[[nodiscard]] OrderedJson to_json(const std::array<X, N>& v);
template <Described S>
[[nodiscard]] OrderedJson to_json(const S& s);

/// An entry of a list that may be undefined (a Frenet normal where the curvature
/// vanishes): null.
template <class X>
OrderedJson to_json(const std::optional<X>& x) {
  return x ? to_json(*x) : OrderedJson(nullptr);
}

template <class X>
OrderedJson to_json(const std::vector<X>& v) {
  OrderedJson a = OrderedJson::array();
  for (const auto& x : v) a.push_back(to_json(x));
  return a;
}

template <class X, std::size_t N>
OrderedJson to_json(const std::array<X, N>& v) {
  OrderedJson a = OrderedJson::array();
  for (const auto& x : v) a.push_back(to_json(x));
  return a;
}

namespace detail {
template <class X>
bool absent(const X& x, bool omit_empty) {
  if constexpr (requires { x.has_value(); }) {
    return !x.has_value();
  } else if constexpr (requires { x.empty(); }) {
    return omit_empty && x.empty();
  } else {
    return false;
  }
}

template <class X>
OrderedJson value_json(const X& x) {
  if constexpr (requires { x.has_value(); }) {
    return to_json(*x);
  } else {
    return to_json(x);
  }
}
}  // namespace detail

/// A described struct as a JSON object of its fields, in their order; absent optionals
/// (and empty arrays marked omit_empty) left out.
template <Described S>
OrderedJson to_json(const S& s) {
  OrderedJson out = OrderedJson::object();
  std::apply(
      [&](const auto&... f) {
        (
            [&] {
              const auto& v = f.of(s);
              if (!detail::absent(v, f.omit_empty)) out[std::string(f.name)] = detail::value_json(v);
            }(),
            ...);
      },
      Describe<S>::fields);
  return out;
}

/// A result at the curve's dimension.
template <class... S>
  requires(Described<S> && ...)
[[nodiscard]] OrderedJson to_json(const std::variant<S...>& v) {
  return std::visit([](const auto& x) { return to_json(x); }, v);
}

/// Rows of a described struct as columns: {"field": [one entry per row], ...}; a field
/// absent from every row (an optional the dimension does not have) is left out.
template <Described S>
[[nodiscard]] OrderedJson columns_json(const std::vector<S>& rows) {
  OrderedJson out = OrderedJson::object();
  std::apply(
      [&](const auto&... f) {
        (
            [&] {
              OrderedJson column = OrderedJson::array();
              bool any = false;
              for (const auto& row : rows) {
                const auto& v = f.of(row);
                if (detail::absent(v, false)) continue;
                column.push_back(detail::value_json(v));
                any = true;
              }
              if (any || !requires { f.of(rows.front()).has_value(); }) out[std::string(f.name)] = std::move(column);
            }(),
            ...);
      },
      Describe<S>::fields);
  return out;
}

/// Rows at the curve's dimension (AnyFrames) as columns.
template <class... S>
[[nodiscard]] OrderedJson columns_json(const std::variant<S...>& v) {
  return std::visit([](const auto& x) { return columns_json(x); }, v);
}

}  // namespace casteljau::io
