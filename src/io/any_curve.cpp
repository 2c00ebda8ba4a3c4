// The run-time operations on AnyCurve, compiled once: every registered curve type at
// every dimension meets each algorithm here and nowhere else.
#include "casteljau/io/any_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "casteljau/algo/bounds.hpp"
#include "casteljau/algo/flatten.hpp"
#include "casteljau/algo/reduce.hpp"
#include "casteljau/basis/extrapolate.hpp"
#include "work_limits.hpp"

namespace casteljau::io {

namespace {

std::string t_path(std::size_t j) { return "t[" + std::to_string(j) + "]"; }

/// Runs g() for parameter j: an error the library reports for "t" names "t[j]".
template <class G>
auto at_parameter(std::size_t j, G&& g) {
  try {
    return g();
  } catch (const InvalidArgument& e) {
    if (e.where() == "t") throw InvalidArgument(t_path(j), e.problem());
    throw;
  }
}

template <class V>
bool all_finite(const V& v) {
  for (int d = 0; d < V::dimension; ++d) {
    if (!std::isfinite(v[d])) return false;
  }
  return true;
}

/// Whether curve type C has the capability (a member the operation calls; only its
/// declaration is looked at, nothing is instantiated).
template <class C>
constexpr bool has(Capability k) {
  switch (k) {
    case Capability::split: return SplittableCurve<C>;
    case Capability::elevate: return requires(const C& x) { x.elevate(1); };
    case Capability::knot_insertion: return requires(const C& x) { x.insert_knot(0.0, 1); };
    case Capability::knot_removal: return requires(const C& x) { x.remove_knot(0.0, 1, 0.0); };
    case Capability::degree_reduction: return DegreeReducibleCurve<C>;
  }
  return false;
}

}  // namespace

std::vector<std::string_view> types_with(Capability k) {
  const auto names = curve_type_names();
  return [&]<template <class, int> class... C>(CurveTypeList<C...>) {
    const bool flags[] = {has<C<double, 2>>(k)...};
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (flags[i]) out.push_back(names[i]);
    }
    return out;
  }(CurveTypes{});
}

std::string types_phrase(Capability k) {
  const auto names = types_with(k);
  std::string s = "a ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) s += i + 1 == names.size() ? " or " : ", ";
    s += names[i];
  }
  return s + " curve";
}

int dimension(const AnyCurve& c) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::dimension; }, c);
}

Interval<double> domain(const AnyCurve& c) {
  return std::visit([](const auto& x) { return Interval<double>(x.domain()); }, c);
}

PointList evaluate(const AnyCurve& c, std::span<const double> t) { return derivatives(c, t, 0); }

PointList derivatives(const AnyCurve& c, std::span<const double> t, int k) {
  if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  return std::visit(
      [&](const auto& x) {
        PointList out{std::decay_t<decltype(x)>::dimension, {}};
        out.coords.reserve(t.size() * static_cast<std::size_t>(out.dim));
        for (std::size_t j = 0; j < t.size(); ++j) {
          const auto v = at_parameter(j, [&] {
            require_finite(t[j], "t");
            return k == 0 ? x(t[j]).to_vector() : x.derivative_at(t[j], k);
          });
          if (!all_finite(v)) {
            throw InvalidArgument(t_path(j), (k == 0 ? std::string("the curve's point") : "the order " + std::to_string(k) + " derivative") +
                                                 " at t = " + casteljau::detail::format_number(t[j]) +
                                                 " is not finite (overflow, or a pole of a rational curve)");
          }
          out.push_back(v);
        }
        return out;
      },
      c);
}

AnyBox bounds(const AnyCurve& c) {
  limits::check_curve_work(c, "curve");  // before the Bézier pieces (src/io/work_limits.hpp)
  return std::visit([](const auto& x) { return AnyBox(casteljau::bounds(x)); }, c);
}

PointList flatten(const AnyCurve& c, double tolerance, FlattenMethod method) {
  limits::check_curve_work(c, "curve", "flattening");  // before the pieces, which the vertex estimate needs
  return std::visit(
      [&](const auto& x) {
        // The pieces once: for the size estimate and for the flattening itself.
        const auto p = casteljau::pieces(x);
        if (std::isfinite(tolerance) && tolerance > 0) {
          double estimate = 0;
          for (const auto& piece : p.segments())
            // Wang's count of each piece (algo/flatten/uniform.hpp) on its coordinates as
            // given and the tolerance in model units, overflow-safe; for a rational piece
            // the Cartesian points give an estimate, which is all a limit needs.
            estimate = std::min(std::numeric_limits<double>::max(),
                                estimate + std::visit([&](const auto& b) { return casteljau::detail::wang_count(b, tolerance); }, piece));
          if (!(estimate <= static_cast<double>(max_flatten_vertices))) {
            throw InvalidArgument("tolerance", "the polyline would have about " + casteljau::detail::format_number(estimate) +
                                                   " vertices, more than the limit of " + std::to_string(max_flatten_vertices) +
                                                   ": use a larger tolerance");
          }
        }
        PointList out{std::decay_t<decltype(x)>::dimension, {}};
        for (const auto& q : casteljau::flatten(p, tolerance, method)) out.push_back(q);
        return out;
      },
      c);
}

AnyPieces pieces(const AnyCurve& c) {
  return std::visit([](const auto& x) { return AnyPieces(casteljau::pieces(x)); }, c);
}

AnyCurve to_bezier(const AnyCurve& c) {
  limits::check_curve_work(c, "curve", "the conversion");
  return std::visit([](const auto& x) { return AnyCurve(to_bezier_path(x)); }, c);
}

AnySplit split(const AnyCurve& c, double t) {
  return std::visit(
      [&]<class C>(const C& x) -> AnySplit {
        if constexpr (SplittableCurve<C>) {
          const Interval<double> dom = x.domain();
          require_finite(t, "t");
          if (!dom.contains(t)) {
            throw InvalidArgument("t", "split parameter must lie in the domain [" + casteljau::detail::format_number(dom.lo) +
                                           ", " + casteljau::detail::format_number(dom.hi) + "], got " +
                                           casteljau::detail::format_number(t));
          }
          auto halves = x.split(t);
          return {AnyCurve(std::move(halves.left)), AnyCurve(std::move(halves.right))};
        } else {
          throw InvalidArgument("curve.type", "split needs " + types_phrase(Capability::split) + ", got a " + std::string(type_name(c)) +
                                                  (std::is_same_v<C, Path<double, C::dimension>> ? " (split its segments instead)" : ""));
        }
      },
      c);
}

AnyCurve elevate(const AnyCurve& c, int times) {
  if (times < 1) throw InvalidArgument("times", "elevation count must be >= 1, got " + std::to_string(times));
  return std::visit(
      [&]<class C>(const C& x) -> AnyCurve {
        if constexpr (requires { x.elevate(times); }) {
          if (times > max_degree - x.degree()) {
            throw InvalidArgument("times", "elevating degree " + std::to_string(x.degree()) + " by " + std::to_string(times) +
                                               " exceeds the highest supported degree " + std::to_string(max_degree));
          }
          if constexpr (requires { x.knots(); }) {
            // B-spline and NURBS: every distinct knot of the domain's interior gains
            // `times` copies; refuse a response larger than flatten's.
            const auto& U = x.knots();
            const auto dom = x.domain();
            std::size_t distinct = 0;
            for (std::size_t i = 0; i < U.size(); ++i)
              if (U[i] > dom.lo && U[i] < dom.hi && (i == 0 || U[i] != U[i - 1])) ++distinct;
            const double count = static_cast<double>(x.points().size()) + static_cast<double>(times) * static_cast<double>(distinct + 1);
            if (count > static_cast<double>(max_flatten_vertices)) {
              throw InvalidArgument("times", "the elevated curve would have about " + casteljau::detail::format_number(count) +
                                                 " control points, more than the limit of " + std::to_string(max_flatten_vertices));
            }
          }
          try {
            return AnyCurve(x.elevate(times));
          } catch (const InvalidArgument& e) {
            // The library names the count r; the request calls it times.
            if (e.where() == "r") throw InvalidArgument("times", e.problem());
            throw;
          }
        } else {
          throw InvalidArgument("curve.type", "elevate needs " + types_phrase(Capability::elevate) + ", got a " + std::string(type_name(c)));
        }
      },
      c);
}

}  // namespace casteljau::io
