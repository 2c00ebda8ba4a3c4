// Curve objects of the contract (shared/spec/cli.md): reading them into AnyCurve and
// writing them back.
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/io/json.hpp"

namespace casteljau::io {

namespace {

std::string index_path(std::string_view where, std::size_t i) {
  return std::string(where) + "[" + std::to_string(i) + "]";
}

template <class Names>
std::string join(const Names& names) {
  std::string s;
  for (auto n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

std::string quote_name(std::string_view s) { return quoted(s); }
// ---------------------------------------------------------------------------------------
// Curve objects.

/// Control points as read, before the dimension is known at compile time.
struct RawPoints {
  int dim = 0;
  std::vector<std::array<double, max_dimension>> coords;
};

/// A bezier or rational_bezier object, read and checked.
struct RawBezier {
  bool rational = false;
  RawPoints P;
  std::vector<double> w;
};

constexpr std::array<std::string_view, 3> supported_types = {"bezier", "rational_bezier", "path"};
constexpr std::array<std::string_view, 6> later_types = {"bspline", "nurbs", "lagrange", "cubic_spline", "hermite", "catmull_rom"};

template <class Names>
bool one_of(std::string_view s, const Names& list) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

RawPoints read_points(const Json& j) {
  if (!j.is_array()) throw InvalidArgument("points", "must be an array of points, got " + std::string(kind_of(j)));
  if (j.empty()) throw InvalidArgument("points", "needs at least one control point");
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

/// Reads `type` and rejects unknown and not yet supported types.
std::string read_type(const Fields& f) {
  const std::string type = string_from_json(f.required("type"), "type");
  if (one_of(type, supported_types)) return type;
  if (one_of(type, later_types)) {
    throw InvalidArgument("type", "curve type " + quote_name(type) + " is not supported yet (supported: " + join(supported_types) + ")");
  }
  throw InvalidArgument("type", "unknown curve type " + quote_name(type) + " (known: " + join(supported_types) + ", " +
                                    join(later_types) + ")");
}

RawBezier read_bezier(const Fields& f, const std::string& type) {
  RawBezier b;
  b.rational = type == "rational_bezier";
  if (b.rational) {
    f.allow_only({"type", "points", "weights", "degree", "dim"}, "a rational_bezier");
  } else {
    f.allow_only({"type", "points", "degree", "dim"}, "a bezier");
  }
  const std::optional<int> dim = read_dim(f);
  b.P = read_points(f.required("points"));
  check_dim(dim, b.P.dim);
  if (const Json* dj = f.optional("degree")) {
    const int degree = integer_from_json(*dj, "degree");
    const std::size_t n = b.P.coords.size() - 1;
    if (degree < 0 || static_cast<std::size_t>(degree) != n) {
      throw InvalidArgument("degree", "degree is " + std::to_string(degree) + " but " + std::to_string(n + 1) +
                                          " control points give degree " + std::to_string(n));
    }
  }
  // The weight count and positivity are the constructor's checks.
  if (b.rational) b.w = numbers_from_json(f.required("weights"), "weights");
  return b;
}

template <int D>
Segment<double, D> make_segment(const RawBezier& b) {
  std::vector<Point<double, D>> P(b.P.coords.size());
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int k = 0; k < D; ++k) P[i][k] = b.P.coords[i][static_cast<std::size_t>(k)];
  if (b.rational) return RationalBezier<double, D>(std::move(P), b.w);
  return Bezier<double, D>(std::move(P));
}

template <int D>
AnyCurve make_single(const RawBezier& b) {
  return std::visit([](auto&& c) { return AnyCurve(std::move(c)); }, make_segment<D>(b));
}

template <int D>
AnyCurve make_path(const std::vector<RawBezier>& segs, std::optional<std::vector<double>> breaks) {
  std::vector<Segment<double, D>> s;
  s.reserve(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    try {
      s.push_back(make_segment<D>(segs[i]));
    } catch (const InvalidArgument& e) {
      throw e.within(index_path("segments", i));
    }
  }
  if (breaks) return Path<double, D>(std::move(s), std::move(*breaks));
  return Path<double, D>(std::move(s));
}

/// Calls f.template operator()<D>() for the run-time dimension d in 1..max_dimension.
template <class F>
AnyCurve dispatch_dimension(int d, F&& f) {
  static_assert(max_dimension == 4, "extend dispatch_dimension with the new dimensions");
  switch (d) {
    case 1: return f.template operator()<1>();
    case 2: return f.template operator()<2>();
    case 3: return f.template operator()<3>();
    case 4: return f.template operator()<4>();
    default: throw InvalidArgument("", "dimension must be 1.." + std::to_string(max_dimension) + ", got " + std::to_string(d));
  }
}

AnyCurve read_path(const Fields& f) {
  f.allow_only({"type", "segments", "breaks", "dim"}, "a path");
  const std::optional<int> dim = read_dim(f);
  const Json& sj = f.required("segments");
  if (!sj.is_array()) throw InvalidArgument("segments", "must be an array of curve objects, got " + std::string(kind_of(sj)));
  if (sj.empty()) throw InvalidArgument("segments", "a path needs at least one segment");
  std::vector<RawBezier> segs;
  segs.reserve(sj.size());
  for (std::size_t i = 0; i < sj.size(); ++i) {
    const std::string where = index_path("segments", i);
    try {
      const Fields sf(sj[i], "a path segment");
      const std::string type = string_from_json(sf.required("type"), "type");
      if (type != "bezier" && type != "rational_bezier") {
        throw InvalidArgument("type", "a path segment must be a bezier or rational_bezier, got " + quote_name(type));
      }
      segs.push_back(read_bezier(sf, type));
    } catch (const InvalidArgument& e) {
      throw e.within(where);
    }
    if (segs.back().P.dim != segs.front().P.dim) {
      throw InvalidArgument(where, "segment has dimension " + std::to_string(segs.back().P.dim) + " but segments[0] has " +
                                       std::to_string(segs.front().P.dim));
    }
  }
  check_dim(dim, segs.front().P.dim);
  std::optional<std::vector<double>> breaks;
  if (const Json* bj = f.optional("breaks")) breaks = numbers_from_json(*bj, "breaks");
  return dispatch_dimension(segs.front().P.dim, [&]<int D>() { return make_path<D>(segs, std::move(breaks)); });
}

// ---------------------------------------------------------------------------------------
// Writing.

template <class T, int D>
OrderedJson points_json(const std::vector<Point<T, D>>& P) {
  OrderedJson a = OrderedJson::array();
  for (const auto& p : P) a.push_back(to_json(p));
  return a;
}

template <class T, int D>
OrderedJson curve_json(const Bezier<T, D>& c) {
  return OrderedJson{{"type", "bezier"}, {"points", points_json(c.points())}};
}

template <class T, int D>
OrderedJson curve_json(const RationalBezier<T, D>& c) {
  return OrderedJson{{"type", "rational_bezier"}, {"points", points_json(c.points())}, {"weights", c.weights()}};
}

template <class T, int D>
OrderedJson curve_json(const Path<T, D>& c) {
  OrderedJson segs = OrderedJson::array();
  for (const auto& s : c.segments()) segs.push_back(std::visit([](const auto& x) { return curve_json(x); }, s));
  return OrderedJson{{"type", "path"}, {"segments", std::move(segs)}, {"breaks", c.breaks()}};
}

}  // namespace

AnyCurve curve_from_json(const Json& j) {
  const Fields f(j, "a curve");
  const std::string type = read_type(f);
  if (type == "path") return read_path(f);
  const RawBezier b = read_bezier(f, type);
  return dispatch_dimension(b.P.dim, [&]<int D>() { return make_single<D>(b); });
}

OrderedJson to_json(const AnyCurve& c) {
  return std::visit([](const auto& x) { return curve_json(x); }, c);
}


}  // namespace casteljau::io
