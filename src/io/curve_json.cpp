// Curve objects of the contract (docs/cli.md): the registry of curve types (one
// Format entry per type: its name, fields, reader and writer) and the conversion between
// curve JSON and AnyCurve.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/curves/conics.hpp"
#include "casteljau/curves/parametrization.hpp"
#include "casteljau/curves/rational_jet.hpp"
#include "casteljau/io/arrays.hpp"
#include "casteljau/io/json.hpp"
#include "text.hpp"

namespace casteljau::io {

namespace {

using detail::index_path;
using detail::join;

// ---------------------------------------------------------------------------------------
// Field readers shared by the entries.

/// Points as read, before the dimension is known at compile time.
struct RawPoints {
  int dim = 0;
  std::vector<std::array<double, max_dimension>> coords;

  [[nodiscard]] std::size_t size() const { return coords.size(); }
  template <int D>
  [[nodiscard]] std::vector<Point<double, D>> points() const {
    std::vector<Point<double, D>> P(coords.size());
    for (std::size_t i = 0; i < P.size(); ++i)
      for (int k = 0; k < D; ++k) P[i][k] = coords[i][static_cast<std::size_t>(k)];
    return P;
  }
};

/// An array of at least `min_count` points of one dimension 1..max_dimension with finite
/// coordinates; `noun` names the curve in the count message ("a polyline").
RawPoints read_points(const Json& j, std::size_t min_count, std::string_view noun) {
  if (!j.is_array()) throw InvalidArgument("points", "must be an array of points, got " + std::string(kind_of(j)));
  if (j.size() < min_count) {
    throw InvalidArgument("points", std::string(noun) + " needs at least " +
                                        (min_count == 1 ? std::string("one control point") : std::to_string(min_count) + " points") +
                                        ", got " + std::to_string(j.size()));
  }
  RawPoints r;
  r.coords.resize(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = index_path("points", i);
    const Json& p = j[i];
    if (!p.is_array()) throw InvalidArgument(where, "a point must be an array of numbers, got " + std::string(kind_of(p)));
    if (p.empty()) throw InvalidArgument(where, "a point needs at least one coordinate");
    const int d = static_cast<int>(std::min<std::size_t>(p.size(), std::numeric_limits<int>::max()));
    if (i == 0) {
      if (d > max_dimension) {
        throw InvalidArgument(where, "point has " + std::to_string(p.size()) + " coordinates; supported dimensions are 1.." +
                                         std::to_string(max_dimension));
      }
      r.dim = d;
    } else if (d != r.dim) {
      throw InvalidArgument(where, "point has " + std::to_string(p.size()) + " coordinates but points[0] has " +
                                       std::to_string(r.dim) + " (all points of a curve have one dimension)");
    }
    for (int k = 0; k < d; ++k) {
      r.coords[i][static_cast<std::size_t>(k)] =
          number_from_json(p[static_cast<std::size_t>(k)], index_path(where, static_cast<std::size_t>(k)), "coordinate");
    }
  }
  return r;
}

/// The optional `dim` field, checked for range before the data is read.
std::optional<int> read_dim(const Fields& f) {
  const Json* dj = f.optional("dim");
  if (!dj) return std::nullopt;
  const int dim = integer_from_json(*dj, "dim");
  if (dim < 1 || dim > max_dimension) {
    throw InvalidArgument("dim", "dimension must be 1.." + std::to_string(max_dimension) + ", got " + std::to_string(dim));
  }
  return dim;
}

/// Checks a stated `dim` against the data's dimension.
void check_dim(std::optional<int> dim, int data_dim) {
  if (dim && *dim != data_dim) {
    throw InvalidArgument("dim", "dim is " + std::to_string(*dim) + " but the points have " + std::to_string(data_dim) +
                                     " coordinates");
  }
}

/// The control points of a Bézier-like curve: the optional `degree` must agree with them,
/// and the degree may not exceed max_degree.
RawPoints read_control_points(const Fields& f, std::string_view noun) {
  const std::optional<int> dim = read_dim(f);
  RawPoints P = read_points(f.required("points"), 1, noun);
  check_dim(dim, P.dim);
  const std::size_t n = P.size() - 1;
  if (const Json* dj = f.optional("degree")) {
    const int degree = integer_from_json(*dj, "degree");
    if (degree < 0 || static_cast<std::size_t>(degree) != n) {
      throw InvalidArgument("degree", "degree is " + std::to_string(degree) + " but " + std::to_string(n + 1) +
                                          " control points give degree " + std::to_string(n));
    }
  }
  if (n > static_cast<std::size_t>(max_degree)) {
    throw InvalidArgument("points", std::to_string(n + 1) + " control points give degree " + std::to_string(n) +
                                        ", above the highest supported degree " + std::to_string(max_degree));
  }
  return P;
}

template <class T, int D>
OrderedJson points_json(const std::vector<Point<T, D>>& P) {
  OrderedJson a = OrderedJson::array();
  for (const auto& p : P) a.push_back(to_json(p));
  return a;
}

// ---------------------------------------------------------------------------------------
// The registry: one Format entry per curve type of CurveTypes (any_curve.hpp), with the
// type's curve-JSON name, its reader (fields -> AnyCurve, every check of the contract
// that the type's constructor does not make) and its writer.

template <template <class, int> class C>
struct Format;

template <>
struct Format<Bezier> {
  static constexpr std::string_view name = "bezier";
  static constexpr std::string_view class_name = "Bezier";
  static constexpr std::string_view fields[] = {"type", "points", "degree", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a bezier");
    const RawPoints P = read_control_points(f, "a bezier");
    return dispatch_dimension(P.dim, [&]<int D>() { return AnyCurve(Bezier<double, D>(P.points<D>())); });
  }
  template <int D>
  static OrderedJson write(const Bezier<double, D>& c) {
    return OrderedJson{{"type", name}, {"points", points_json(c.points())}};
  }
};

template <>
struct Format<RationalBezier> {
  static constexpr std::string_view name = "rational_bezier";
  static constexpr std::string_view class_name = "RationalBezier";
  static constexpr std::string_view fields[] = {"type", "points", "weights", "degree", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a rational_bezier");
    const RawPoints P = read_control_points(f, "a rational_bezier");
    // The weight count and positivity are the constructor's checks.
    const std::vector<double> w = numbers_from_json(f.required("weights"), "weights");
    return dispatch_dimension(P.dim, [&]<int D>() { return AnyCurve(RationalBezier<double, D>(P.points<D>(), w)); });
  }
  template <int D>
  static OrderedJson write(const RationalBezier<double, D>& c) {
    return OrderedJson{{"type", name}, {"points", points_json(c.points())}, {"weights", c.weights()}};
  }
};

template <>
struct Format<Polyline> {
  static constexpr std::string_view name = "polyline";
  static constexpr std::string_view class_name = "Polyline";
  static constexpr std::string_view fields[] = {"type", "points", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a polyline");
    const std::optional<int> dim = read_dim(f);
    const RawPoints P = read_points(f.required("points"), 2, "a polyline");
    check_dim(dim, P.dim);
    return dispatch_dimension(P.dim, [&]<int D>() { return AnyCurve(Polyline<double, D>(P.points<D>())); });
  }
  template <int D>
  static OrderedJson write(const Polyline<double, D>& c) {
    return OrderedJson{{"type", name}, {"points", points_json(c.points())}};
  }
};

template <>
struct Format<Lagrange> {
  static constexpr std::string_view name = "lagrange";
  static constexpr std::string_view class_name = "Lagrange";
  static constexpr std::string_view fields[] = {"type", "params", "points", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a lagrange");
    const std::optional<int> dim = read_dim(f);
    const RawPoints P = read_points(f.required("points"), 1, "a lagrange curve");
    check_dim(dim, P.dim);
    if (P.size() - 1 > static_cast<std::size_t>(max_degree)) {
      throw InvalidArgument("points", std::to_string(P.size()) + " points give degree " + std::to_string(P.size() - 1) +
                                          ", above the highest supported degree " + std::to_string(max_degree));
    }
    // The count, distinctness and weight checks are the constructor's.
    const std::vector<double> u = numbers_from_json(f.required("params"), "params");
    return dispatch_dimension(P.dim, [&]<int D>() { return AnyCurve(Lagrange<double, D>(u, P.points<D>())); });
  }
  template <int D>
  static OrderedJson write(const Lagrange<double, D>& c) {
    return OrderedJson{{"type", name}, {"params", c.params()}, {"points", points_json(c.points())}};
  }
};

/// The name of `j` among `names` (a string field), or InvalidArgument(where, "must be 'a',
/// 'b' or 'c', got 'x'").
std::size_t choice_from_json(const Json& j, std::string_view where, std::span<const std::string_view> names) {
  const std::string s = string_from_json(j, where);
  std::size_t i = 0;
  std::string list;
  for (const std::string_view n : names) {
    if (s == n) return i;
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + io::quoted(n);
    ++i;
  }
  throw InvalidArgument(std::string(where), "must be " + list + ", got " + io::quoted(s));
}

std::size_t choice_from_json(const Json& j, std::string_view where, std::initializer_list<std::string_view> names) {
  return choice_from_json(j, where, std::span<const std::string_view>(names.begin(), names.size()));
}

constexpr std::string_view ends_names[] = {"inner", "reflect"};  // CatmullRomEnds' order

template <>
struct Format<CatmullRom> {
  static constexpr std::string_view name = "catmull_rom";
  static constexpr std::string_view class_name = "CatmullRom";
  static constexpr std::string_view fields[] = {"type", "points", "alpha", "closed", "ends", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a catmull_rom");
    const std::optional<int> dim = read_dim(f);
    const bool closed = f.has("closed") && boolean_from_json(*f.optional("closed"), "closed");
    CatmullRomEnds ends = CatmullRomEnds::inner;
    if (const Json* ej = f.optional("ends")) {
      ends = static_cast<CatmullRomEnds>(choice_from_json(*ej, "ends", ends_names));
      if (closed) throw InvalidArgument("ends", "belongs to open curves: a closed catmull_rom has no end points");
    }
    const bool reflect = ends == CatmullRomEnds::reflect;
    const RawPoints P = read_points(f.required("points"), closed ? 3 : reflect ? 2 : 4,
                                    closed    ? "a closed catmull_rom"
                                    : reflect ? "an open catmull_rom with ends 'reflect'"
                                              : "an open catmull_rom");
    check_dim(dim, P.dim);
    const double alpha = f.has("alpha") ? number_from_json(*f.optional("alpha"), "alpha") : 0.5;
    // The alpha range and the coincident points are the constructor's checks.
    return dispatch_dimension(P.dim, [&]<int D>() { return AnyCurve(CatmullRom<double, D>(P.points<D>(), alpha, closed, ends)); });
  }
  template <int D>
  static OrderedJson write(const CatmullRom<double, D>& c) {
    if (!c.knots_follow_points()) {
      throw InvalidArgument("curve", "this catmull_rom curve (an image under a map that is not a similarity) keeps knots that its "
                                     "points do not give: curve JSON cannot express it");
    }
    OrderedJson out{{"type", name}, {"points", points_json(c.points())}, {"alpha", c.alpha()}, {"closed", c.closed()}};
    if (c.ends() == CatmullRomEnds::reflect) out["ends"] = "reflect";  // the default is left out, as before ends existed
    return out;
  }
};

/// The degree, knots and points of a bspline or nurbs object: the optional `dim` must
/// agree, the degree may not exceed max_degree; the knot rules are the constructor's.
struct RawSpline {
  int degree = 0;
  std::vector<double> knots;
  RawPoints P;
};

RawSpline read_spline(const Fields& f, std::string_view noun) {
  RawSpline r;
  const std::optional<int> dim = read_dim(f);
  r.degree = integer_from_json(f.required("degree"), "degree");
  if (r.degree < 0) throw InvalidArgument("degree", std::string(noun) + " needs degree >= 0, got " + std::to_string(r.degree));
  if (r.degree > max_degree) {
    throw InvalidArgument("degree", "degree " + std::to_string(r.degree) + " is above the highest supported degree " +
                                        std::to_string(max_degree));
  }
  r.P = read_points(f.required("points"), 1, noun);
  check_dim(dim, r.P.dim);
  r.knots = numbers_from_json(f.required("knots"), "knots");
  return r;
}

template <>
struct Format<BSpline> {
  static constexpr std::string_view name = "bspline";
  static constexpr std::string_view class_name = "BSpline";
  static constexpr std::string_view fields[] = {"type", "degree", "knots", "points", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a bspline");
    const RawSpline r = read_spline(f, "a bspline");
    return dispatch_dimension(r.P.dim, [&]<int D>() { return AnyCurve(BSpline<double, D>(r.degree, r.knots, r.P.points<D>())); });
  }
  template <int D>
  static OrderedJson write(const BSpline<double, D>& c) {
    return OrderedJson{{"type", name}, {"degree", c.degree()}, {"knots", c.knots()}, {"points", points_json(c.points())}};
  }
};

template <>
struct Format<Nurbs> {
  static constexpr std::string_view name = "nurbs";
  static constexpr std::string_view class_name = "Nurbs";
  static constexpr std::string_view fields[] = {"type", "degree", "knots", "points", "weights", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a nurbs");
    const RawSpline r = read_spline(f, "a nurbs");
    const std::vector<double> w = numbers_from_json(f.required("weights"), "weights");
    return dispatch_dimension(r.P.dim, [&]<int D>() { return AnyCurve(Nurbs<double, D>(r.degree, r.knots, r.P.points<D>(), w)); });
  }
  template <int D>
  static OrderedJson write(const Nurbs<double, D>& c) {
    return OrderedJson{{"type", name}, {"degree", c.degree()}, {"knots", c.knots()}, {"points", points_json(c.points())},
                       {"weights", c.weights()}};
  }
};

// ---------------------------------------------------------------------------------------
// Interpolating types: params given or computed from the points.

/// Vectors of the curve's dimension d (derivative values): an array of d finite numbers.
std::array<double, max_dimension> read_vector(const Json& j, const std::string& where, int d) {
  const std::vector<double> v = numbers_from_json(j, where);
  if (v.size() != static_cast<std::size_t>(d)) {
    throw InvalidArgument(where, "has " + std::to_string(v.size()) + " coordinates but the points have " + std::to_string(d));
  }
  std::array<double, max_dimension> a{};
  std::copy(v.begin(), v.end(), a.begin());
  return a;
}

template <int D>
Vector<double, D> vector_of(const std::array<double, max_dimension>& a) {
  Vector<double, D> v;
  for (int k = 0; k < D; ++k) v[k] = a[static_cast<std::size_t>(k)];
  return v;
}

/// The points and params of a cubic_spline or hermite: `params`, or `parametrization`
/// (uniform, chord, centripetal) to compute them from the points; one of the two.
struct RawInterpolation {
  RawPoints P;
  std::vector<double> params;
};

RawInterpolation read_interpolation_data(const Fields& f, std::string_view noun) {
  RawInterpolation r;
  const std::optional<int> dim = read_dim(f);
  r.P = read_points(f.required("points"), 2, noun);
  check_dim(dim, r.P.dim);
  const Json* pj = f.optional("params");
  const Json* rule = f.optional("parametrization");
  if (pj && rule) throw InvalidArgument("parametrization", "give params or parametrization, not both");
  if (pj) {
    r.params = numbers_from_json(*pj, "params");
  } else if (rule) {
    const auto kind = static_cast<Parametrization>(choice_from_json(*rule, "parametrization", parametrization_names));
    r.params = dispatch_dimension(r.P.dim, [&]<int D>() { return parameters_from_points(r.P.template points<D>(), kind); });
  } else {
    throw InvalidArgument("params", "required field is missing (or give parametrization)");
  }
  return r;
}

template <>
struct Format<Hermite> {
  static constexpr std::string_view name = "hermite";
  static constexpr std::string_view class_name = "Hermite";
  static constexpr std::string_view fields[] = {"type", "params", "parametrization", "points", "tangents", "tangent_rule", "tension", "continuity", "bias", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a hermite");
    const RawInterpolation r = read_interpolation_data(f, "a hermite");
    const Json* tj = f.optional("tangents");
    const Json* rj = f.optional("tangent_rule");
    if (tj && rj) throw InvalidArgument("tangent_rule", "give tangents or tangent_rule, not both");
    if (!tj && !rj) throw InvalidArgument("tangents", "required field is missing (or give tangent_rule)");
    enum Rule { finite_difference, catmull_rom, cardinal, kochanek_bartels, monotone, akima, given };
    const Rule rule = rj ? static_cast<Rule>(choice_from_json(*rj, "tangent_rule", {"finite_difference", "catmull_rom", "cardinal",
                                                                                     "kochanek_bartels", "monotone", "akima"}))
                         : given;
    const std::string rule_name = rj ? string_from_json(*rj, "tangent_rule") : std::string();
    // The shape parameters belong to their rules.
    for (const char* field : {"tension", "continuity", "bias"}) {
      if (!f.has(field)) continue;
      const bool tension = std::string_view(field) == "tension";
      const bool ok = rule == kochanek_bartels || (tension && rule == cardinal);
      if (!ok) {
        throw InvalidArgument(field, std::string("belongs to tangent_rule ") + (tension ? "'cardinal' or " : "") +
                                         "'kochanek_bartels'" +
                                         (rj ? ", not " + io::quoted(rule_name) : std::string(" (this hermite gives tangents)")));
      }
    }
    const auto number_or_zero = [&](const char* field) {
      const Json* j = f.optional(field);
      return j ? number_from_json(*j, field) : 0.0;
    };
    std::vector<std::array<double, max_dimension>> tangents;
    if (tj) {
      if (!tj->is_array()) throw InvalidArgument("tangents", "must be an array of vectors, got " + std::string(kind_of(*tj)));
      for (std::size_t i = 0; i < tj->size(); ++i) tangents.push_back(read_vector((*tj)[i], index_path("tangents", i), r.P.dim));
    }
    return dispatch_dimension(r.P.dim, [&]<int D>() {
      using V = Vector<double, D>;
      const std::vector<Point<double, D>> P = r.P.points<D>();
      std::vector<V> m;
      switch (rule) {
        case given:
          for (const auto& a : tangents) m.push_back(vector_of<D>(a));
          break;
        case finite_difference: m = finite_difference_tangents(r.params, P); break;
        case catmull_rom: m = catmull_rom_tangents(r.params, P); break;
        case cardinal: m = cardinal_tangents(r.params, P, number_or_zero("tension")); break;
        case monotone: m = monotone_tangents(r.params, P); break;
        case akima: m = akima_tangents(r.params, P); break;
        case kochanek_bartels: {
          const KochanekBartels<double> kb{number_or_zero("tension"), number_or_zero("continuity"), number_or_zero("bias")};
          auto s = kochanek_bartels_tangents(r.params, P, kb);
          return AnyCurve(Hermite<double, D>(r.params, P, std::move(s.incoming), std::move(s.outgoing)));
        }
      }
      return AnyCurve(Hermite<double, D>(r.params, P, std::move(m)));
    });
  }
  /// One tangent per point (the outgoing ones, and the incoming one at the last point);
  /// a curve with different tangents on the two sides of an interior point
  /// (Kochanek-Bartels continuity) has no such form and is written as a path of two-point hermite segments on the same
  /// breaks (the same curve and parametrisation).
  template <int D>
  static OrderedJson write(const Hermite<double, D>& c) {
    if (c.one_sided()) {
      OrderedJson segs = OrderedJson::array();
      for (std::size_t i = 0; i < c.size(); ++i) {
        const Hermite<double, D> one({c.params()[i], c.params()[i + 1]}, {c.points()[i], c.points()[i + 1]},
                                     {c.tangents()[i], c.incoming_tangents()[i + 1]});
        segs.push_back(write(one));
      }
      return OrderedJson{{"type", "path"}, {"segments", std::move(segs)}, {"breaks", c.params()}};
    }
    // The tangent at the last point is the one its piece uses: the incoming one.
    OrderedJson m = OrderedJson::array();
    for (std::size_t i = 0; i + 1 < c.tangents().size(); ++i) m.push_back(to_json(c.tangents()[i]));
    m.push_back(to_json(c.incoming_tangents().back()));
    return OrderedJson{{"type", name}, {"params", c.params()}, {"points", points_json(c.points())}, {"tangents", std::move(m)}};
  }
};

template <>
struct Format<CubicSpline> {
  static constexpr std::string_view name = "cubic_spline";
  static constexpr std::string_view class_name = "CubicSpline";
  static constexpr std::string_view fields[] = {"type", "params", "parametrization", "points", "boundary", "start_derivative", "end_derivative", "dim"};
  static AnyCurve read(const Fields& f) {
    f.allow_only(fields, "a cubic_spline");
    const RawInterpolation r = read_interpolation_data(f, "a cubic_spline");
    const int d = r.P.dim;
    enum Kind { natural, clamped, not_a_knot, periodic, general };
    Kind kind = natural;
    std::array<int, 2> order{2, 2};
    std::array<std::array<double, max_dimension>, 2> value{};
    if (const Json* bj = f.optional("boundary")) {
      if (bj->is_object()) {
        kind = general;
        const Fields b(*bj, "boundary");
        try {
          b.allow_only({"start", "end"}, "a general boundary");
        } catch (const InvalidArgument& err) {
          throw err.within("boundary");
        }
        for (int e = 0; e < 2; ++e) {
          const char* side = e == 0 ? "start" : "end";
          const Json* sj = b.optional(side);
          if (!sj) throw InvalidArgument(std::string("boundary.") + side, "required field is missing");
          try {
            const Fields s(*sj, "an end condition");
            s.allow_only({"order", "value"}, "an end condition");
            order[e] = integer_from_json(s.required("order"), "order");
            if (order[e] != 1 && order[e] != 2) {
              throw InvalidArgument("order", "the derivative order must be 1 or 2, got " + std::to_string(order[e]));
            }
            value[e] = read_vector(s.required("value"), "value", d);
          } catch (const InvalidArgument& err) {
            throw err.within(side).within("boundary");
          }
        }
      } else if (bj->is_string()) {
        kind = static_cast<Kind>(choice_from_json(*bj, "boundary", {"natural", "clamped", "not-a-knot", "periodic"}));
      } else {
        throw InvalidArgument("boundary", "must be a string or an object {start, end}, got " + std::string(kind_of(*bj)));
      }
    }
    constexpr std::array<std::string_view, 5> label = {"'natural'", "'clamped'", "'not-a-knot'", "'periodic'", "the general form"};
    for (int e = 0; e < 2; ++e) {
      const char* field = e == 0 ? "start_derivative" : "end_derivative";
      const Json* j = f.optional(field);
      if (kind == clamped) {
        if (!j) throw InvalidArgument(field, "required field is missing (boundary 'clamped' gives both end derivatives)");
        order[e] = 1;
        value[e] = read_vector(*j, field, d);
      } else if (j) {
        throw InvalidArgument(field, "belongs to boundary 'clamped', not " + std::string(label[kind]) +
                                         (f.has("boundary") ? "" : " (the default)"));
      }
    }
    return dispatch_dimension(d, [&]<int D>() {
      using B = SplineBoundary<double, D>;
      B bc;
      switch (kind) {
        case natural: bc = B::natural(); break;
        case clamped: bc = B::clamped(vector_of<D>(value[0]), vector_of<D>(value[1])); break;
        case not_a_knot: bc = B::not_a_knot(); break;
        case periodic: bc = B::periodic(); break;
        case general: bc = B::general({order[0], vector_of<D>(value[0])}, {order[1], vector_of<D>(value[1])}); break;
      }
      return AnyCurve(CubicSpline<double, D>(r.params, r.P.points<D>(), bc));
    });
  }
  template <int D>
  static OrderedJson write(const CubicSpline<double, D>& c) {
    using Kind = typename SplineBoundary<double, D>::Kind;
    const auto& b = c.boundary();
    OrderedJson out{{"type", name}, {"params", c.params()}, {"points", points_json(c.points())}};
    switch (b.kind) {
      case Kind::natural: out["boundary"] = "natural"; break;
      case Kind::not_a_knot: out["boundary"] = "not-a-knot"; break;
      case Kind::periodic: out["boundary"] = "periodic"; break;
      case Kind::clamped:
        out["boundary"] = "clamped";
        out["start_derivative"] = to_json(b.start.value);
        out["end_derivative"] = to_json(b.end.value);
        break;
      case Kind::general:
        out["boundary"] = OrderedJson{{"start", {{"order", b.start.order}, {"value", to_json(b.start.value)}}},
                                      {"end", {{"order", b.end.order}, {"value", to_json(b.end.value)}}}};
        break;
    }
    return out;
  }
};

/// How deeply paths may nest in curve JSON (a path segment may itself be a path): far
/// more than any real use, and a bound on the reader's recursion.
constexpr int max_path_nesting = 32;

template <>
struct Format<Path> {
  static constexpr std::string_view name = "path";
  static constexpr std::string_view class_name = "Path";
  static constexpr std::string_view fields[] = {"type", "segments", "breaks", "dim"};
  static AnyCurve read(const Fields& f);
  template <int D>
  static OrderedJson write(const Path<double, D>& c);
};

// ---------------------------------------------------------------------------------------
// Walking the registry.

template <class X, template <class, int> class C>
struct IsOf : std::false_type {};
template <class T, int D, template <class, int> class C>
struct IsOf<C<T, D>, C> : std::true_type {};

template <template <class, int> class... C, class F>
void for_each_type(CurveTypeList<C...>, F&& f) {
  (f.template operator()<C>(), ...);
}


// ---------------------------------------------------------------------------------------
// Shorthands: circle, ellipse and arc, read as the exact nurbs they stand for (conics.hpp,
// [PT97, A7.1]: quadratic pieces of at most 90 degrees, starting at the start angle). They
// are not types of the registry: what is read is a Nurbs, and a response writes it as one.

constexpr std::string_view shorthand_names[] = {"circle", "ellipse", "arc"};

/// A finite number field that must be > 0.
double positive_from_json(const Json& j, const std::string& where) {
  const double v = number_from_json(j, where);
  if (!(v > 0)) throw InvalidArgument(where, "must be > 0, got " + casteljau::detail::format_number(v));
  return v;
}

/// The center: 2-D, or 3-D when `normal` is allowed and given (its dimension must then be 3).
RawPoints read_center(const Fields& f, bool normal_allowed) {
  const std::optional<int> dim = read_dim(f);
  const std::vector<double> c = numbers_from_json(f.required("center"), "center");
  const bool has_normal = normal_allowed && f.has("normal");
  const std::size_t want = has_normal ? 3 : 2;
  if (c.size() != want) {
    throw InvalidArgument("center", "needs " + std::to_string(want) + " coordinates" +
                                        (has_normal ? std::string(" (a circle with a normal is 3-D)")
                                                    : normal_allowed ? std::string(" (3 with a normal)") : std::string(" (a plane curve)")) +
                                        ", got " + std::to_string(c.size()));
  }
  RawPoints P;
  P.dim = static_cast<int>(want);
  P.coords.resize(1);
  std::copy(c.begin(), c.end(), P.coords[0].begin());
  check_dim(dim, P.dim);
  return P;
}

AnyCurve read_circle(const Fields& f) {
  f.allow_only({"type", "center", "radius", "normal", "dim"}, "a circle");
  const RawPoints O = read_center(f, true);
  const double r = positive_from_json(f.required("radius"), "radius");
  const double two_pi = 2 * std::numbers::pi;
  if (O.dim == 2) return AnyCurve(nurbs_ellipse_arc(O.points<2>()[0], Vector<double, 2>(r, 0.0), Vector<double, 2>(0.0, r), 0.0, two_pi, "radius"));
  // 3-D: the plane through the center perpendicular to the normal; angle 0 points along
  // the coordinate axis least aligned with the normal (the first of x, y, z on ties),
  // projected into the plane, and the circle runs counter-clockwise seen from the normal's
  // tip (Y = n x X).
  const std::vector<double> nv = numbers_from_json(f.required("normal"), "normal");
  if (nv.size() != 3) throw InvalidArgument("normal", "needs 3 coordinates, got " + std::to_string(nv.size()));
  Vector<double, 3> n(nv[0], nv[1], nv[2]);
  const double scale = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
  if (!(scale > 0)) throw InvalidArgument("normal", "must be a non-zero vector");
  n = (1 / scale) * n;  // no overflow or underflow in the norm
  n = (1 / norm(n)) * n;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[axis])) axis = k;
  Vector<double, 3> e(0.0, 0.0, 0.0);
  e[axis] = 1;
  Vector<double, 3> X = e - dot(e, n) * n;
  X = (1 / norm(X)) * X;
  const Vector<double, 3> Y(n[1] * X[2] - n[2] * X[1], n[2] * X[0] - n[0] * X[2], n[0] * X[1] - n[1] * X[0]);  // n x X
  return AnyCurve(nurbs_ellipse_arc(O.points<3>()[0], r * X, r * Y, 0.0, two_pi, "radius"));
}

AnyCurve read_ellipse(const Fields& f) {
  f.allow_only({"type", "center", "radii", "rotation", "dim"}, "an ellipse");
  const RawPoints O = read_center(f, false);
  const Json& rj = f.required("radii");
  const std::vector<double> radii = numbers_from_json(rj, "radii");
  if (radii.size() != 2) throw InvalidArgument("radii", "needs 2 numbers [a, b], got " + std::to_string(radii.size()));
  for (std::size_t i = 0; i < 2; ++i) positive_from_json(rj[i], index_path("radii", i));
  const double rot = f.has("rotation") ? number_from_json(*f.optional("rotation"), "rotation") : 0.0;
  const double c = std::cos(rot), s = std::sin(rot);
  return AnyCurve(nurbs_ellipse_arc(O.points<2>()[0], Vector<double, 2>(radii[0] * c, radii[0] * s),
                                    Vector<double, 2>(-radii[1] * s, radii[1] * c), 0.0, 2 * std::numbers::pi, "radii"));
}

AnyCurve read_arc(const Fields& f) {
  f.allow_only({"type", "center", "radius", "start_angle", "end_angle", "dim"}, "an arc");
  const RawPoints O = read_center(f, false);
  const double r = positive_from_json(f.required("radius"), "radius");
  const double a0 = number_from_json(f.required("start_angle"), "start_angle");
  const double a1 = number_from_json(f.required("end_angle"), "end_angle");
  // Counter-clockwise from start to end: end > start sweeps end - start (at most 2 pi);
  // end < start wraps, sweeping counter-clockwise from the start direction to the end
  // direction, less than a full turn (start 3 pi / 2, end pi / 2: the left half circle).
  const double two_pi = 2 * std::numbers::pi;
  double end = a1;
  if (a1 == a0) {
    throw InvalidArgument("end_angle", "equals start_angle, an empty arc: it must be greater than start_angle (at most 2 pi "
                                       "more: start_angle + 2 pi is the full circle) or smaller (the arc wraps past 2 pi)");
  }
  if (a1 < a0) {
    const double sweep = std::fmod(a1 - a0, two_pi) + two_pi;  // in (0, 2 pi]
    if (!(sweep < two_pi)) {
      throw InvalidArgument("end_angle", "end_angle " + casteljau::detail::format_number(a1) + " is start_angle " +
                                             casteljau::detail::format_number(a0) +
                                             " less a whole number of turns: the arc from a direction back to itself is "
                                             "ambiguous (for the full circle give end_angle = start_angle + 2 pi)");
    }
    end = a0 + sweep;
  }
  // A sweep over 2 pi by the rounding of end = start + 2 pi (a few ulps) is the full turn.
  if (!(end - a0 <= two_pi + full_turn_slack(a0, end))) {
    throw InvalidArgument("end_angle", "the sweep end_angle - start_angle must be at most 2 pi, got " + casteljau::detail::format_number(a1 - a0));
  }
  return AnyCurve(nurbs_ellipse_arc(O.points<2>()[0], Vector<double, 2>(r, 0.0), Vector<double, 2>(0.0, r), a0, end, "radius"));
}

thread_local int path_depth = 0;

AnyCurve read_curve_object(const Json& j) {
  const Fields f(j, "a curve");
  const std::string type = string_from_json(f.required("type"), "type");
  if (type == "circle") return read_circle(f);
  if (type == "ellipse") return read_ellipse(f);
  if (type == "arc") return read_arc(f);
  std::optional<AnyCurve> out;
  for_each_type(CurveTypes{}, [&]<template <class, int> class C>() {
    if (!out && type == Format<C>::name) out = Format<C>::read(f);
  });
  if (out) return std::move(*out);
  throw InvalidArgument("type", "unknown curve type " + io::quoted(type) + " (known: " + join(curve_type_names()) +
                                    "; shorthands read as nurbs: " + join(shorthand_names) + ")");
}

/// Adds one path segment (any curve object of dimension D) on the break interval `onto`:
/// a nested path is spliced in, its segments on their mapped break intervals.
template <int D>
void append_segment(const AnyCurve& any, const Interval<double>& onto, std::vector<Segment<double, D>>& segs,
                    std::vector<double>& breaks) {
  std::visit(
      [&]<class X>(const X& x) {
        if constexpr (X::dimension != D) {
          throw InvalidArgument("", "segment has dimension " + std::to_string(X::dimension) + " but segments[0] has " +
                                        std::to_string(D));
        } else if constexpr (std::is_same_v<X, Path<double, D>>) {
          append_pieces(x, onto, segs, breaks);
        } else {
          segs.push_back(Segment<double, D>(x));
          breaks.push_back(onto.hi);
        }
      },
      any);
}

AnyCurve Format<Path>::read(const Fields& f) {
  f.allow_only(fields, "a path");
  const std::optional<int> dim = read_dim(f);
  const Json& sj = f.required("segments");
  if (!sj.is_array()) throw InvalidArgument("segments", "must be an array of curve objects, got " + std::string(kind_of(sj)));
  if (sj.empty()) throw InvalidArgument("segments", "a path needs at least one segment");
  if (path_depth >= max_path_nesting) {
    throw InvalidArgument("segments", "paths nest more than " + std::to_string(max_path_nesting) + " levels deep");
  }
  struct Depth {
    Depth() { ++path_depth; }
    ~Depth() { --path_depth; }
  } depth;
  std::vector<AnyCurve> parts;
  parts.reserve(sj.size());
  for (std::size_t i = 0; i < sj.size(); ++i) {
    try {
      parts.push_back(read_curve_object(sj[i]));
    } catch (const InvalidArgument& e) {
      throw e.within(index_path("segments", i));
    }
  }
  const int d = dimension(parts.front());
  check_dim(dim, d);
  std::vector<double> given;
  if (const Json* bj = f.optional("breaks")) {
    given = numbers_from_json(*bj, "breaks");
    casteljau::detail::check_breaks(given, parts.size());
  } else {
    for (std::size_t i = 0; i <= parts.size(); ++i) given.push_back(static_cast<double>(i));
  }
  return dispatch_dimension(d, [&]<int D>() {
    std::vector<Segment<double, D>> segs;
    std::vector<double> breaks{given.front()};
    for (std::size_t i = 0; i < parts.size(); ++i) {
      try {
        append_segment<D>(parts[i], {given[i], given[i + 1]}, segs, breaks);
      } catch (const InvalidArgument& e) {
        throw e.within(index_path("segments", i));
      }
    }
    return AnyCurve(Path<double, D>(std::move(segs), std::move(breaks)));
  });
}

template <int D>
OrderedJson Format<Path>::write(const Path<double, D>& c) {
  OrderedJson segs = OrderedJson::array();
  for (const auto& s : c.segments()) segs.push_back(std::visit([](const auto& x) { return to_json(AnyCurve(x)); }, s));
  return OrderedJson{{"type", name}, {"segments", std::move(segs)}, {"breaks", c.breaks()}};
}

}  // namespace

AnyCurve curve_from_json(const Json& j) { return read_curve_object(j); }

AnyCurve cubic_spline_from_arrays(std::span<const double> params, const double* points, int d, std::string_view boundary) {
  if (boundary != "natural" && boundary != "not-a-knot" && boundary != "periodic") {
    throw InvalidArgument("boundary", "must be natural, not-a-knot or periodic here, got " + io::quoted(std::string(boundary)));
  }
  return dispatch_dimension(d, [&]<int D>() {
    using B = SplineBoundary<double, D>;
    std::vector<Point<double, D>> P(params.size());
    for (std::size_t i = 0; i < P.size(); ++i)
      for (int k = 0; k < D; ++k) P[i][k] = points[i * D + static_cast<std::size_t>(k)];
    const B bc = boundary == "natural" ? B::natural() : boundary == "periodic" ? B::periodic() : B::not_a_knot();
    return AnyCurve(CubicSpline<double, D>(std::vector<double>(params.begin(), params.end()), std::move(P), bc));
  });
}

std::span<const CurveTypeInfo> curve_types() {
  static const std::vector<CurveTypeInfo> types = [] {
    std::vector<CurveTypeInfo> out;
    for_each_type(CurveTypes{}, [&]<template <class, int> class C>() {
      out.push_back({Format<C>::name, Format<C>::class_name, Format<C>::fields});
    });
    return out;
  }();
  return types;
}

std::span<const std::string_view> curve_type_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for_each_type(CurveTypes{}, [&]<template <class, int> class C>() { out.push_back(Format<C>::name); });
    return out;
  }();
  return names;
}

OrderedJson to_json(const AnyCurve& c) {
  return std::visit(
      [](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        OrderedJson out;
        for_each_type(CurveTypes{}, [&]<template <class, int> class C>() {
          if constexpr (IsOf<X, C>::value) out = Format<C>::write(x);
        });
        return out;
      },
      c);
}

std::string_view type_name(const AnyCurve& c) {
  return std::visit(
      [](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        std::string_view name;
        for_each_type(CurveTypes{}, [&]<template <class, int> class C>() {
          if constexpr (IsOf<X, C>::value) name = Format<C>::name;
        });
        return name;
      },
      c);
}

// ---------------------------------------------------------------------------------------
// DerivativeTable (io/arrays.hpp)

namespace {

/// The point at s of the degree-q Bézier curve P (q + 1 points of w numbers) into out,
/// by de Casteljau's algorithm in b ((q + 1) w numbers of scratch).
void de_casteljau_flat(const double* P, std::size_t q, std::size_t w, double s, double* b, double* out) {
  const std::size_t n1 = q + 1;
  std::copy_n(P, n1 * w, b);
  const double r = 1 - s;
  for (std::size_t level = 1; level < n1; ++level)
    for (std::size_t i = 0; i + level < n1; ++i)
      for (std::size_t x = 0; x < w; ++x) b[i * w + x] = r * b[i * w + x] + s * b[(i + 1) * w + x];
  std::copy_n(b, w, out);
}

/// The number of points of order r's hodograph of a degree-n piece (one zero point past
/// the degree).
std::size_t hodograph_size(int n, std::size_t r) { return static_cast<std::size_t>(std::max(n - static_cast<int>(r), 0)) + 1; }

bool finite_values(const double* v, std::size_t n) {
  bool ok = true;
  for (std::size_t i = 0; i < n; ++i) ok &= std::abs(v[i]) <= std::numeric_limits<double>::max();  // NaN fails
  return ok;
}

}  // namespace

DerivativeTable::DerivativeTable(const AnyCurve& c, int k) : k_(k) {
  if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  std::visit([&](const auto& p) { read(p); }, io::pieces(c));
}

template <class P>
void DerivativeTable::read(const P& p) {
  constexpr int D = P::dimension;
  using Rational = RationalBezier<double, D>;
  d_ = D;
  breaks_ = p.breaks();
  for (const auto& seg : p.segments())
    if (std::holds_alternative<Rational>(seg)) rational_ = true;
  const std::size_t w = static_cast<std::size_t>(D) + (rational_ ? 1 : 0), K = static_cast<std::size_t>(k_);
  for (std::size_t i = 0; i < p.segments().size(); ++i) {
    // The control points, homogeneous (w P, w) when some piece is rational (a polynomial
    // piece with weights 1).
    std::vector<double> h;
    std::visit(
        [&]<class B>(const B& b) {
          const auto& pts = b.points();
          double scale = 1;
          if constexpr (std::is_same_v<B, Rational>) {
            // Weights spread beyond 2^20: the quotient rule below loses the derivatives;
            // the library's forms for such weights answer instead (evaluate() declines).
            if (k_ >= 1 && casteljau::detail::extreme_weight_spread(std::span<const double>(b.weights()))) declined_ = true;
            int e = 0;
            std::frexp(*std::max_element(b.weights().begin(), b.weights().end()), &e);
            scale = std::ldexp(1.0, -e);
          }
          for (std::size_t j = 0; j < pts.size(); ++j) {
            double wj = 1;
            if constexpr (std::is_same_v<B, Rational>) wj = b.weights()[j] * scale;
            for (int x = 0; x < D; ++x) h.push_back(rational_ ? wj * pts[j][x] : pts[j][x]);
            if (rational_) h.push_back(wj);
          }
        },
        p.segments()[i]);
    const int n = static_cast<int>(h.size() / w) - 1;
    max_degree_ = std::max(max_degree_, static_cast<std::size_t>(n));
    degree_.push_back(n);
    starts_.push_back(coef_.size());
    const double len = breaks_[i + 1] - breaks_[i];
    for (std::size_t r = 0; r <= K; ++r) {
      if (rational_ || r == K) coef_.insert(coef_.end(), h.begin(), h.end());
      const std::size_t q = h.size() / w - 1;
      if (q == 0) {
        std::fill(h.begin(), h.end(), 0.0);
        continue;
      }
      std::vector<double> next(q * w);
      for (std::size_t j = 0; j < q; ++j)
        for (std::size_t x = 0; x < w; ++x) next[j * w + x] = static_cast<double>(q) * (h[(j + 1) * w + x] - h[j * w + x]) / len;
      h = std::move(next);
    }
  }
}

bool DerivativeTable::evaluate(std::span<const double> t, double* out) const {
  if (declined_ || !finite_values(t.data(), t.size())) return false;
  const std::size_t m = starts_.size(), d = static_cast<std::size_t>(d_), K = static_cast<std::size_t>(k_);
  const std::size_t w = d + (rational_ ? 1 : 0);
  const double lo = breaks_.front(), hi = breaks_.back();
  std::vector<double> scratch((max_degree_ + 1) * w), hd((K + 1) * w), cd((K + 1) * d);
  std::size_t i = 0;
  for (std::size_t j = 0; j < t.size(); ++j) {
    const double u = t[j];
    if (!(breaks_[i] <= u && (u < breaks_[i + 1] || i + 1 == m))) {
      i = static_cast<std::size_t>(std::upper_bound(breaks_.begin() + 1, breaks_.end() - 1, u) - breaks_.begin()) - 1;
    }
    double s = (u - breaks_[i]) / (breaks_[i + 1] - breaks_[i]);
    if (u >= lo && u <= hi) s = std::clamp(s, 0.0, 1.0);
    const int n = degree_[i];
    // The (homogeneous) derivatives of orders 0..k (rational), or of order k alone; order
    // r's points follow orders 0..r-1's in coef_.
    std::size_t at = starts_[i];
    for (std::size_t r = 0; r <= K; ++r) {
      const std::size_t size = hodograph_size(n, r);
      if (rational_ || r == K) {
        de_casteljau_flat(coef_.data() + at, size - 1, w, s, scratch.data(), hd.data() + r * w);
        if (rational_) at += size * w;
      }
    }
    double* o = out + j * d;
    if (!rational_) {
      std::copy_n(hd.data() + K * w, d, o);
      continue;
    }
    const double wt = hd[d];
    for (std::size_t r = 0; r <= K; ++r) {
      for (std::size_t x = 0; x < d; ++x) {
        double a = hd[r * w + x];
        double binom = 1;  // C(r, q)
        for (std::size_t q = 1; q <= r; ++q) {
          binom = binom * static_cast<double>(r - q + 1) / static_cast<double>(q);
          a -= binom * hd[q * w + d] * cd[(r - q) * d + x];
        }
        cd[r * d + x] = a / wt;
      }
    }
    std::copy_n(cd.data() + K * d, d, o);
  }
  return finite_values(out, t.size() * d);
}

}  // namespace casteljau::io
