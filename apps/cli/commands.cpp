// The commands of the `casteljau` program: each converts the request, calls the library
// and converts the result. No geometry here; errors keep the library's InvalidArgument,
// prefixed with their place in the request.
#include "commands.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/fit.hpp"
#include "casteljau/io/knots.hpp"
#include "casteljau/io/queries.hpp"
#include "casteljau/io/intersect.hpp"
#include "casteljau/io/svg.hpp"

namespace casteljau::cli {

namespace {

using io::Json;
using io::OrderedJson;

/// Highest derivative order `eval` computes. Far above any order that is accurate in
/// double for the degrees people use; it keeps a typo (1000000) from allocating a
/// response of that many arrays.
constexpr int max_derivative_order = 64;

/// Render colours: CSS colour names, #hex, rgb()/hsl() forms. No quotes or angle brackets,
/// so a colour cannot break out of an SVG attribute whatever the renderer does.
constexpr std::string_view colour_chars =
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789#(),.% -";

/// The curve object in field `name` of the request.
io::AnyCurve read_curve(const io::Fields& f, const std::string& name = "curve") {
  const Json& j = f.required(name);
  try {
    return io::curve_from_json(j);
  } catch (const InvalidArgument& e) {
    throw e.within(name);
  }
}

std::string index_path(std::string_view where, std::size_t i) {
  return std::string(where) + "[" + std::to_string(i) + "]";
}

/// A finite number as JSON writes it (shortest round-trip form), for messages.
std::string number_text(double v) { return Json(v).dump(); }

OrderedJson points_json(const io::PointList& P) {
  OrderedJson a = OrderedJson::array();
  for (std::size_t i = 0; i < P.size(); ++i) {
    OrderedJson p = OrderedJson::array();
    for (const double x : P[i]) p.push_back(x);
    a.push_back(std::move(p));
  }
  return a;
}

OrderedJson numbers_json(const std::vector<double>& v) {
  OrderedJson a = OrderedJson::array();
  for (const double x : v) a.push_back(x);
  return a;
}

/// Runs library calls on a curve read from the request. Errors that name a request field
/// ("t[2]", "tolerance", "curve.type") pass through; any other error concerns an
/// intermediate value inside an algorithm on a valid curve (e.g. an overflow), so it is
/// reported against the curve rather than under a name the request does not have. A
/// NumericalError (a limit of the algorithm reached on this input) is bad input too:
/// reported against `numerical_field` when the request has a field that controls it.
template <class F>
void call_library(F&& f, std::string_view numerical_field = "curve") {
  try {
    f();
  } catch (const InvalidArgument& e) {
    const std::string root = e.where().substr(0, e.where().find_first_of(".["));
    constexpr std::array<std::string_view, 6> fields = {"curve", "curves", "t", "times", "tolerance", "knot"};
    if (std::find(fields.begin(), fields.end(), root) != fields.end()) throw;
    throw InvalidArgument("curve", "the computation failed on this curve: " + std::string(e.what()));
  } catch (const NumericalError& e) {
    throw InvalidArgument(std::string(numerical_field), e.what());
  }
}

/// eval's `frame`: one list per quantity, one entry per parameter; the lists a dimension
/// does not have (normal in 1-D, binormal and torsion outside 3-D) are left out.
OrderedJson frame_json(const std::vector<io::AnyFrame>& frames) {
  OrderedJson tangent = OrderedJson::array(), normal = OrderedJson::array(), binormal = OrderedJson::array(),
              curvature = OrderedJson::array(), torsion = OrderedJson::array();
  for (const auto& f : frames) {
    tangent.push_back(numbers_json(f.tangent));
    if (!f.normal.empty()) normal.push_back(numbers_json(f.normal));
    if (!f.binormal.empty()) binormal.push_back(numbers_json(f.binormal));
    curvature.push_back(f.curvature);
    if (f.torsion) torsion.push_back(*f.torsion);
  }
  OrderedJson out{{"tangent", std::move(tangent)}};
  if (!normal.empty()) out["normal"] = std::move(normal);
  if (!binormal.empty()) out["binormal"] = std::move(binormal);
  out["curvature"] = std::move(curvature);
  if (!torsion.empty()) out["torsion"] = std::move(torsion);
  return out;
}

// ---------------------------------------------------------------------------------------

Response eval(const Json& req) {
  const io::Fields f(req, "an eval request");
  f.allow_only({"curve", "t", "derivatives", "curvature", "frame"}, "an eval request");
  const io::AnyCurve curve = read_curve(f);
  const std::vector<double> ts = io::numbers_from_json(f.required("t"), "t");
  int k = 0;
  if (const Json* kj = f.optional("derivatives")) {
    k = io::integer_from_json(*kj, "derivatives");
    if (k < 0) throw InvalidArgument("derivatives", "derivative count must be >= 0, got " + std::to_string(k));
    if (k > max_derivative_order) {
      throw InvalidArgument("derivatives", "derivative count must be <= " + std::to_string(max_derivative_order) + ", got " +
                                               std::to_string(k));
    }
  }
  bool with_curvature = false;
  if (const Json* cj = f.optional("curvature")) with_curvature = io::boolean_from_json(*cj, "curvature");
  bool with_frame = false;  // beyond shared/spec/cli.md (docs/cli.md)
  if (const Json* fj = f.optional("frame")) with_frame = io::boolean_from_json(*fj, "frame");
  Response r;
  call_library([&] {
    r.json = OrderedJson{{"points", points_json(io::evaluate(curve, ts))}};
    if (k > 0) {
      OrderedJson derivatives = OrderedJson::array();
      for (int order = 1; order <= k; ++order) derivatives.push_back(points_json(io::derivatives(curve, ts, order)));
      r.json["derivatives"] = std::move(derivatives);
    }
    if (with_curvature) r.json["curvature"] = numbers_json(io::curvature(curve, ts));
    if (with_frame) r.json["frame"] = frame_json(io::frames(curve, ts));
  });
  return r;
}

Response split(const Json& req) {
  const io::Fields f(req, "a split request");
  f.allow_only({"curve", "t"}, "a split request");
  const io::AnyCurve curve = read_curve(f);
  const double t = io::number_from_json(f.required("t"), "t", "split parameter");
  Response r;
  call_library([&] {
    const io::AnySplit halves = io::split(curve, t);
    r.json = OrderedJson{{"curves", OrderedJson::array({io::to_json(halves.left), io::to_json(halves.right)})}};
  });
  return r;
}

Response elevate(const Json& req) {
  const io::Fields f(req, "an elevate request");
  f.allow_only({"curve", "times"}, "an elevate request");
  const io::AnyCurve curve = read_curve(f);
  const int times = io::integer_from_json(f.required("times"), "times");
  Response r;
  call_library([&] { r.json = OrderedJson{{"curve", io::to_json(io::elevate(curve, times))}}; });
  return r;
}

/// `times` of insert_knot / remove_knot: an integer >= 1, default 1.
int knot_times(const io::Fields& f) {
  const Json* j = f.optional("times");
  if (!j) return 1;
  const int times = io::integer_from_json(*j, "times");
  if (times < 1) throw InvalidArgument("times", "count must be >= 1, got " + std::to_string(times));
  return times;
}

Response insert_knot(const Json& req) {
  const io::Fields f(req, "an insert_knot request");
  f.allow_only({"curve", "knot", "times"}, "an insert_knot request");
  const io::AnyCurve curve = read_curve(f);
  const double u = io::number_from_json(f.required("knot"), "knot", "knot");
  const int times = knot_times(f);
  Response r;
  call_library([&] { r.json = OrderedJson{{"curve", io::to_json(io::insert_knot(curve, u, times))}}; });
  return r;
}

Response remove_knot(const Json& req) {
  const io::Fields f(req, "a remove_knot request");
  f.allow_only({"curve", "knot", "times", "tolerance"}, "a remove_knot request");
  const io::AnyCurve curve = read_curve(f);
  const double u = io::number_from_json(f.required("knot"), "knot", "knot");
  const int times = knot_times(f);
  double tolerance = 1e-12;
  if (const Json* j = f.optional("tolerance")) tolerance = io::number_from_json(*j, "tolerance", "tolerance");
  Response r;
  call_library([&] {
    const io::AnyKnotRemoval k = io::remove_knot(curve, u, times, tolerance);
    r.json = OrderedJson{{"curve", io::to_json(k.curve)}, {"removed", k.removed}};
  });
  return r;
}

/// The polygon in field `name`: an array of points, each an array of 1..max_dimension
/// finite numbers, all of one dimension.
io::PointList polygon_from_json(const io::Fields& f, std::string_view name) {
  const Json& j = f.required(name);
  const std::string where(name);
  if (!j.is_array()) throw InvalidArgument(where, "must be an array of points, got " + std::string(io::kind_of(j)));
  io::PointList P;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = index_path(where, i);
    const std::vector<double> x = io::numbers_from_json(j[i], at);
    if (x.empty() || x.size() > static_cast<std::size_t>(io::max_dimension)) {
      throw InvalidArgument(at, "a point has 1 to " + std::to_string(io::max_dimension) + " coordinates, got " + std::to_string(x.size()));
    }
    if (i == 0) P.dim = static_cast<int>(x.size());
    if (x.size() != static_cast<std::size_t>(P.dim)) {
      throw InvalidArgument(at, "all points must have the same dimension: " + std::to_string(x.size()) + " coordinates after " +
                                    std::to_string(P.dim));
    }
    P.coords.insert(P.coords.end(), x.begin(), x.end());
  }
  if (P.dim == 0) throw InvalidArgument(where, "needs at least one point");
  return P;
}

Response subdivide(const Json& req) {
  const io::Fields f(req, "a subdivide request");
  f.allow_only({"points", "scheme", "degree", "tension", "iterations", "closed"}, "a subdivide request");
  const io::PointList P = polygon_from_json(f, "points");
  const std::string name = io::string_from_json(f.required("scheme"), "scheme");
  io::SubdivisionScheme scheme{};
  if (name == "chaikin") {
    scheme = io::SubdivisionScheme::chaikin;
  } else if (name == "lane_riesenfeld") {
    scheme = io::SubdivisionScheme::lane_riesenfeld;
  } else if (name == "four_point") {
    scheme = io::SubdivisionScheme::four_point;
  } else {
    throw InvalidArgument("scheme", "unknown scheme " + io::quoted(name) + " (chaikin, lane_riesenfeld, four_point)");
  }
  int degree = 2;
  if (scheme == io::SubdivisionScheme::lane_riesenfeld) {
    degree = io::integer_from_json(f.required("degree"), "degree");
    if (degree < 1 || degree > io::max_degree) {
      throw InvalidArgument("degree", "degree must be in 1.." + std::to_string(io::max_degree) + ", got " + std::to_string(degree));
    }
  } else if (f.has("degree")) {
    throw InvalidArgument("degree", "only the lane_riesenfeld scheme takes a degree");
  }
  double tension = 1.0 / 16;
  if (const Json* j = f.optional("tension")) {
    if (scheme != io::SubdivisionScheme::four_point) throw InvalidArgument("tension", "only the four_point scheme takes a tension");
    tension = io::number_from_json(*j, "tension", "tension");
  }
  const int iterations = io::integer_from_json(f.required("iterations"), "iterations");
  bool closed = false;
  if (const Json* j = f.optional("closed")) closed = io::boolean_from_json(*j, "closed");
  Response r;
  const io::AnySubdivision s = io::subdivide(P, scheme, degree, tension, iterations, closed);
  r.json = OrderedJson{{"points", points_json(s.points)}};
  if (s.limit) r.json["limit"] = io::to_json(*s.limit);
  return r;
}

Response fit(const Json& req) {
  const io::Fields f(req, "a fit request");
  f.allow_only({"points", "degree", "control_points", "tolerance", "parametrization", "start_derivative", "end_derivative", "closed"},
               "a fit request");
  const io::PointList P = polygon_from_json(f, "points");
  io::AnyFitRequest r;
  r.degree = io::integer_from_json(f.required("degree"), "degree");
  if (r.degree < 1 || r.degree > io::max_degree) {
    throw InvalidArgument("degree", "degree must be in 1.." + std::to_string(io::max_degree) + ", got " + std::to_string(r.degree));
  }
  const Json* cp = f.optional("control_points");
  const Json* tol = f.optional("tolerance");
  if (cp && tol) throw InvalidArgument("tolerance", "give either control_points or tolerance, not both");
  if (!cp && !tol) throw InvalidArgument("control_points", "required field is missing (or give tolerance)");
  if (cp) {
    const int n = io::integer_from_json(*cp, "control_points");
    if (n < 1) throw InvalidArgument("control_points", "must be >= 1, got " + std::to_string(n));
    r.control_points = static_cast<std::size_t>(n);
  } else {
    r.tolerance = io::number_from_json(*tol, "tolerance", "tolerance");
    if (!(*r.tolerance > 0)) throw InvalidArgument("tolerance", "tolerance must be > 0, got " + number_text(*r.tolerance));
  }
  if (const Json* j = f.optional("parametrization")) {
    const std::string s = io::string_from_json(*j, "parametrization");
    if (s == "uniform") {
      r.parametrization = Parametrization::uniform;
    } else if (s == "chord") {
      r.parametrization = Parametrization::chord;
    } else if (s == "centripetal") {
      r.parametrization = Parametrization::centripetal;
    } else {
      throw InvalidArgument("parametrization", "unknown parametrization " + io::quoted(s) + " (uniform, chord, centripetal)");
    }
  }
  if (const Json* j = f.optional("start_derivative")) r.start_derivative = io::numbers_from_json(*j, "start_derivative");
  if (const Json* j = f.optional("end_derivative")) r.end_derivative = io::numbers_from_json(*j, "end_derivative");
  if (const Json* j = f.optional("closed")) r.closed = io::boolean_from_json(*j, "closed");
  Response out;
  try {
    const io::AnyFit a = io::fit(P, r);
    out.json = OrderedJson{{"curve", io::to_json(a.curve)}, {"max_error", a.max_error}};
  } catch (const NumericalError& e) {
    throw InvalidArgument("points", e.what());
  }
  return out;
}

Response to_bezier(const Json& req) {
  const io::Fields f(req, "a to_bezier request");
  f.allow_only({"curve"}, "a to_bezier request");
  const io::AnyCurve curve = read_curve(f);
  Response r;
  call_library([&] { r.json = OrderedJson{{"curve", io::to_json(io::to_bezier(curve))}}; });
  return r;
}

Response flatten(const Json& req) {
  const io::Fields f(req, "a flatten request");
  f.allow_only({"curve", "tolerance", "method"}, "a flatten request");
  const io::AnyCurve curve = read_curve(f);
  const double tolerance = io::number_from_json(f.required("tolerance"), "tolerance", "tolerance");
  FlattenMethod method = FlattenMethod::optimal;
  if (const Json* mj = f.optional("method")) {
    const std::string m = io::string_from_json(*mj, "method");
    if (m == "uniform") method = FlattenMethod::uniform;
    else if (m == "subdivision") method = FlattenMethod::subdivision;
    else if (m == "optimal") method = FlattenMethod::optimal;
    else throw InvalidArgument("method", "must be \"uniform\", \"subdivision\" or \"optimal\", got \"" + m.substr(0, 40) + "\"");
  }
  Response r;
  // The tolerance below the resolution of the coordinates (NumericalError) is a bad request.
  call_library([&] { r.json = OrderedJson{{"points", points_json(io::flatten(curve, tolerance, method))}}; }, "tolerance");
  return r;
}

Response intersect(const Json& req) {
  const io::Fields f(req, "an intersect request");
  f.allow_only({"curves"}, "an intersect request");
  const Json& cj = f.required("curves");
  if (!cj.is_array()) throw InvalidArgument("curves", "must be an array of one or two curve objects, got " + std::string(io::kind_of(cj)));
  if (cj.empty() || cj.size() > 2) {
    throw InvalidArgument("curves", "needs one curve (self-intersections) or two, got " + std::to_string(cj.size()));
  }
  std::vector<io::AnyCurve> curves;
  for (std::size_t i = 0; i < cj.size(); ++i) {
    try {
      curves.push_back(io::curve_from_json(cj[i]));
    } catch (const InvalidArgument& e) {
      throw e.within(index_path("curves", i));
    }
    if (io::dimension(curves.back()) != 2) {
      throw InvalidArgument(index_path("curves", i), "intersect needs 2-D curves, got dimension " +
                                                         std::to_string(io::dimension(curves.back())));
    }
  }
  Response r;
  call_library(
      [&] {
        const io::AnyIntersections x = curves.size() == 1 ? io::self_intersect(curves[0]) : io::intersect(curves[0], curves[1]);
        OrderedJson points = OrderedJson::array(), overlaps = OrderedJson::array();
        for (const auto& p : x.points) {
          points.push_back(OrderedJson{{"t", OrderedJson::array({p.ta, p.tb})},
                                       {"point", OrderedJson::array({p.point[0], p.point[1]})},
                                       {"kind", p.tangent ? "tangent" : "crossing"}});
        }
        for (const auto& o : x.overlaps)
          overlaps.push_back(OrderedJson{{"a", OrderedJson::array({o.a0, o.a1})}, {"b", OrderedJson::array({o.b0, o.b1})}});
        r.json = OrderedJson{{"intersections", std::move(points)}, {"overlaps", std::move(overlaps)}};
      },
      "curves");
  return r;
}

double positive(const io::Fields& f, std::string_view name, double fallback, bool allow_zero) {
  const Json* j = f.optional(name);
  if (!j) return fallback;
  const double v = io::number_from_json(*j, name, std::string(name));
  if (allow_zero ? !(v >= 0) : !(v > 0)) {
    throw InvalidArgument(std::string(name), std::string(name) + (allow_zero ? " must be >= 0" : " must be > 0") + ", got " +
                                                 number_text(v));
  }
  return v;
}

std::string colour(const io::Fields& f, std::string_view name, const std::string& fallback) {
  const Json* j = f.optional(name);
  if (!j) return fallback;
  std::string s = io::string_from_json(*j, name);
  if (s.empty() || s.size() > 64 || s.find_first_not_of(colour_chars) != std::string::npos) {
    throw InvalidArgument(std::string(name), "must be a CSS colour such as \"red\", \"#1f77b4\", \"rgb(0, 128, 255)\" or \"none\"");
  }
  return s;
}

Response render(const Json& req) {
  const io::Fields f(req, "a render request");
  f.allow_only({"curve", "curves", "width", "height", "padding", "background", "stroke", "stroke_width", "control_polygon",
                "axes", "tolerance"},
               "a render request");
  std::vector<io::AnyCurve> curves;
  const bool single = f.has("curve");
  if (single && f.has("curves")) throw InvalidArgument("curves", "give either curve or curves, not both");
  if (single || !f.has("curves")) {
    curves.push_back(read_curve(f));  // "curve: required field is missing" when neither is given
  } else {
    const Json& cj = f.required("curves");
    if (!cj.is_array()) throw InvalidArgument("curves", "must be an array of curve objects, got " + std::string(io::kind_of(cj)));
    if (cj.empty()) throw InvalidArgument("curves", "needs at least one curve");
    for (std::size_t i = 0; i < cj.size(); ++i) {
      try {
        curves.push_back(io::curve_from_json(cj[i]));
      } catch (const InvalidArgument& e) {
        throw e.within(index_path("curves", i));
      }
    }
  }
  const io::RenderStyle defaults;
  io::RenderStyle style;
  style.width = positive(f, "width", defaults.width, false);
  style.height = positive(f, "height", defaults.height, false);
  style.padding = positive(f, "padding", defaults.padding, true);
  style.background = colour(f, "background", defaults.background);
  style.stroke = colour(f, "stroke", defaults.stroke);
  style.stroke_width = positive(f, "stroke_width", defaults.stroke_width, false);
  if (const Json* j = f.optional("control_polygon")) style.control_polygon = io::boolean_from_json(*j, "control_polygon");
  if (const Json* j = f.optional("axes")) style.axes = io::boolean_from_json(*j, "axes");
  style.tolerance = positive(f, "tolerance", defaults.tolerance, true);
  Response r;
  r.is_svg = true;
  try {
    r.svg = io::render_svg(curves, style);
  } catch (const InvalidArgument& e) {
    // Name the curve as the request did: the renderer says "curve" for a lone curve and
    // "curves[i]" otherwise, whether it came in `curve` or in a one-element `curves`.
    const std::string& w = e.where();
    const bool says_curve = w == "curve" || w.rfind("curve.", 0) == 0 || w.rfind("curve[", 0) == 0;
    if (single && w.rfind("curves[0]", 0) == 0) throw InvalidArgument("curve" + w.substr(9), e.problem());
    if (!single && says_curve) throw InvalidArgument("curves[0]" + w.substr(5), e.problem());
    throw;
  }
  r.json = OrderedJson{{"svg", r.svg}};
  return r;
}

// ---------------------------------------------------------------------------------------
// Geometric queries (issue 8): length, param_at_length, project, features, distance,
// area. The library names its own request fields ("point", "from", "lengths[2]"): those
// pass through as they are.

template <class F>
void call_query(F&& f, std::initializer_list<std::string_view> own_fields) {
  std::optional<InvalidArgument> own;
  call_library([&] {
    try {
      f();
    } catch (const InvalidArgument& e) {
      const std::string root = e.where().substr(0, e.where().find_first_of(".["));
      if (std::find(own_fields.begin(), own_fields.end(), root) == own_fields.end()) throw;
      own = e;
    }
  });
  if (own) throw *own;
}

std::optional<double> optional_number(const io::Fields& f, std::string_view name) {
  const Json* j = f.optional(name);
  if (!j) return std::nullopt;
  return io::number_from_json(*j, name, std::string(name));
}

Response length(const Json& req) {
  const io::Fields f(req, "a length request");
  f.allow_only({"curve", "from", "to"}, "a length request");
  const io::AnyCurve curve = read_curve(f);
  const auto from = optional_number(f, "from"), to = optional_number(f, "to");
  Response r;
  call_query([&] { r.json = OrderedJson{{"length", io::length(curve, from, to)}}; }, {"from", "to"});
  return r;
}

// bounds (here beside the other queries for call_query: its optional from / to go
// beyond shared/spec/cli.md, see docs/cli.md).
Response bounds(const Json& req) {
  const io::Fields f(req, "a bounds request");
  f.allow_only({"curve", "from", "to"}, "a bounds request");
  const io::AnyCurve curve = read_curve(f);
  const auto from = optional_number(f, "from"), to = optional_number(f, "to");
  Response r;
  call_query(
      [&] {
        const io::AnyBox box = from || to ? io::bounds(curve, from, to) : io::bounds(curve);
        r.json = OrderedJson{{"min", numbers_json(box.lo)}, {"max", numbers_json(box.hi)}};
      },
      {"from", "to"});
  return r;
}

Response param_at_length(const Json& req) {
  const io::Fields f(req, "a param_at_length request");
  f.allow_only({"curve", "lengths"}, "a param_at_length request");
  const io::AnyCurve curve = read_curve(f);
  const std::vector<double> lengths = io::numbers_from_json(f.required("lengths"), "lengths");
  Response r;
  call_query([&] { r.json = OrderedJson{{"t", numbers_json(io::param_at_length(curve, lengths))}}; }, {"lengths"});
  return r;
}

Response project(const Json& req) {
  const io::Fields f(req, "a project request");
  f.allow_only({"curve", "point", "farthest"}, "a project request");
  const io::AnyCurve curve = read_curve(f);
  const std::vector<double> point = io::numbers_from_json(f.required("point"), "point");
  bool farthest = false;
  if (const Json* j = f.optional("farthest")) farthest = io::boolean_from_json(*j, "farthest");
  Response r;
  call_query(
      [&] {
        const io::AnyProjection p = io::project(curve, point, farthest);
        r.json = OrderedJson{{"t", p.t}, {"point", numbers_json(p.point)}, {"distance", p.distance}};
        if (!p.all_t.empty()) r.json["all_t"] = numbers_json(p.all_t);
        if (!p.intervals.empty()) {
          OrderedJson iv = OrderedJson::array();
          for (const auto& [lo, hi] : p.intervals) iv.push_back(OrderedJson::array({lo, hi}));
          r.json["intervals"] = std::move(iv);
        }
      },
      {"point"});
  return r;
}

Response features(const Json& req) {
  const io::Fields f(req, "a features request");
  f.allow_only({"curve"}, "a features request");
  const io::AnyCurve curve = read_curve(f);
  Response r;
  call_library([&] {
    const io::AnyFeatures x = io::features(curve);
    OrderedJson extrema = OrderedJson::array();
    for (const auto& e : x.extrema) extrema.push_back(numbers_json(e));
    r.json = OrderedJson{{"inflections", numbers_json(x.inflections)}, {"cusps", numbers_json(x.cusps)}, {"extrema", std::move(extrema)}};
  });
  return r;
}

Response distance(const Json& req) {
  const io::Fields f(req, "a distance request");
  f.allow_only({"curves"}, "a distance request");
  const Json& cj = f.required("curves");
  if (!cj.is_array()) throw InvalidArgument("curves", "must be an array of two curve objects, got " + std::string(io::kind_of(cj)));
  if (cj.size() != 2) throw InvalidArgument("curves", "needs exactly two curves, got " + std::to_string(cj.size()));
  std::vector<io::AnyCurve> curves;
  for (std::size_t i = 0; i < 2; ++i) {
    try {
      curves.push_back(io::curve_from_json(cj[i]));
    } catch (const InvalidArgument& e) {
      throw e.within(index_path("curves", i));
    }
  }
  Response r;
  call_library([&] {
    const io::AnyDistance d = io::distance(curves[0], curves[1]);
    r.json = OrderedJson{{"distance", d.distance},
                         {"t", OrderedJson::array({d.t[0], d.t[1]})},
                         {"points", OrderedJson::array({numbers_json(d.points[0]), numbers_json(d.points[1])})}};
  });
  return r;
}

Response area(const Json& req) {
  const io::Fields f(req, "an area request");
  f.allow_only({"curve"}, "an area request");
  const io::AnyCurve curve = read_curve(f);
  Response r;
  call_library([&] { r.json = OrderedJson{{"area", io::area(curve)}}; });
  return r;
}

// ---------------------------------------------------------------------------------------
// Descriptions. Examples are real responses of this program (checked by tests/cli).

constexpr std::string_view eval_details = R"(Evaluates a curve at parameters, optionally with derivatives with respect to the
curve's parameter.

Request:  curve, t (array of numbers), derivatives (optional integer k >= 0, default 0),
          curvature (optional boolean, default false), frame (optional boolean, default
          false; an extension of the contract)
Response: points (one per t); when k > 0, derivatives: k arrays (orders 1..k), each with
          one vector per t; with curvature, curvature: one number per t (signed in 2-D,
          positive turning left; >= 0 otherwise; an error where the velocity is zero).
          With frame, frame: {tangent, normal, binormal, curvature, torsion}, one entry
          per t: unit tangent; normal (2-D: the tangent turned left; 3-D, 4-D: the
          principal normal, an error where the curvature is zero); binormal and torsion in
          3-D only; an error where the velocity is zero. At a break the right-hand piece
          answers. Parameters outside the domain extrapolate the first or last piece.

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}, "t": [0, 0.5], "derivatives": 1}' | casteljau eval
  {"points":[[0.0,0.0],[2.0,1.5]],"derivatives":[[[3.0,6.0],[4.5,0.0]]]}
  echo '{"curve": {"type": "bezier", "points": [[0,0,0],[1,0,0],[1,1,0],[1,1,1]]}, "t": [0], "frame": true}' | casteljau eval
  {"points":[[0.0,0.0,0.0]],"frame":{"tangent":[[1.0,0.0,0.0]],"normal":[[0.0,1.0,0.0]],"binormal":[[0.0,0.0,1.0]],"curvature":[0.6666666666666666],"torsion":[0.3333333333333333]}})";

constexpr std::string_view split_details = R"(Splits a curve at t into two curves of the same type. Bezier and rational_bezier
halves are each on [0, 1] (t in [0, 1]); bspline and nurbs halves keep their parameter
(t strictly inside the domain; the knot t is inserted up to the degree).

Request:  curve (bezier, rational_bezier, bspline or nurbs), t (number)
Response: curves: [left, right]

Example:
  echo '{"curve": {"type": "bezier", "points": [[0],[2],[4]]}, "t": 0.5}' | casteljau split
  {"curves":[{"type":"bezier","points":[[0.0],[1.0],[2.0]]},{"type":"bezier","points":[[2.0],[3.0],[4.0]]}]}
  echo '{"curve": {"type": "bspline", "degree": 1, "knots": [0,0,2,2], "points": [[0],[4]]}, "t": 1}' | casteljau split
  {"curves":[{"type":"bspline","degree":1,"knots":[0.0,0.0,1.0,1.0],"points":[[0.0],[2.0]]},{"type":"bspline","degree":1,"knots":[1.0,1.0,2.0,2.0],"points":[[2.0],[4.0]]}]})";

constexpr std::string_view elevate_details = R"(Raises the degree of a curve without changing it. A bspline or nurbs keeps its
continuity: every interior knot gains `times` copies (decompose into Bezier pieces,
elevate each, remove the extra knots [PT97, 5.5]).

Request:  curve (bezier, rational_bezier, bspline or nurbs), times (integer r >= 1)
Response: curve (same type, degree + r)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "times": 1}' | casteljau elevate
  {"curve":{"type":"bezier","points":[[0.0,0.0],[0.6666666666666666,1.3333333333333333],[1.3333333333333333,1.3333333333333335],[2.0,0.0]]}})";

constexpr std::string_view insert_knot_details = R"(Inserts a knot into a bspline or nurbs curve without changing the curve
(Boehm's algorithm [PT97, A5.1]).

Request:  curve (bspline or nurbs), knot (in the domain), times (optional integer >= 1,
          default 1; the knot's multiplicity afterwards is at most the degree)
Response: curve

Example:
  echo '{"curve": {"type": "bspline", "degree": 1, "knots": [0,0,2,2], "points": [[0],[4]]}, "knot": 1}' | casteljau insert_knot
  {"curve":{"type":"bspline","degree":1,"knots":[0.0,0.0,1.0,2.0,2.0],"points":[[0.0],[2.0],[4.0]]}})";

constexpr std::string_view remove_knot_details = R"(Removes an interior knot of a bspline or nurbs curve up to `times` times, each
removal kept only if the curve moves by at most `tolerance` (a guaranteed bound on the
distance over the whole domain) [PT97, A5.8].

Request:  curve (bspline or nurbs), knot (an interior knot), times (optional integer >= 1,
          default 1, at most the knot's multiplicity), tolerance (optional, > 0, default 1e-12)
Response: curve, removed (how many times the knot was removed)

Example:
  echo '{"curve": {"type": "bspline", "degree": 1, "knots": [0,0,1,2,2], "points": [[0],[2],[4]]}, "knot": 1}' | casteljau remove_knot
  {"curve":{"type":"bspline","degree":1,"knots":[0.0,0.0,2.0,2.0],"points":[[0.0],[4.0]]},"removed":1})";

constexpr std::string_view subdivide_details = R"(Subdivision curves: `iterations` steps of a scheme on a control polygon. chaikin
(corner cutting), lane_riesenfeld (degree p >= 1; chaikin is p = 2) and four_point
(interpolating, Dyn-Levin-Gregory; tension in [0, 0.1545...), default 1/16). Open
polygons keep their end points: Lane-Riesenfeld steps are then knot insertion at the
span midpoints of the clamped uniform B-spline; the 4-point scheme reflects the end
points. `limit` is the limit curve as a bspline (uniform knots; periodic when closed);
four_point has none.

Request:  points, scheme, degree (lane_riesenfeld only), tension (four_point only),
          iterations (integer k >= 0), closed (optional boolean, default false)
Response: points (after k steps), limit (bspline, except for four_point)

Example:
  echo '{"points": [[0,0],[4,0],[4,4],[0,4]], "scheme": "chaikin", "iterations": 1, "closed": true}' | casteljau subdivide
  {"points":[[1.0,0.0],[3.0,0.0],[4.0,1.0],[4.0,3.0],[3.0,4.0],[1.0,4.0],[0.0,3.0],[0.0,1.0]],"limit":{"type":"bspline","degree":2,"knots":[0.0,1.0,2.0,3.0,4.0,5.0,6.0,7.0,8.0],"points":[[0.0,0.0],[4.0,0.0],[4.0,4.0],[0.0,4.0],[0.0,0.0],[4.0,0.0]]}})";

constexpr std::string_view fit_details = R"(Fits a bspline to points ([PT97] chapter 9): clamped, or unclamped and
periodic when closed. Parameters by the parametrization (uniform, chord (default),
centripetal), divided by the last so that the curve's domain is [0, 1].

  control_points = number of points (+ 1 per end derivative): global interpolation
      (knots by averaging the parameters, [PT97] A9.1, eq. 9.8; end derivatives 9.2.2);
  control_points smaller: least squares with the end points (and given end derivatives)
      matched exactly, knots by [PT97] eq. 9.68-9.69;
  tolerance: the fewest control points found (bisection) whose max_error is within it;
      interpolation when nothing fewer is;
  closed: a periodic curve (C^(degree-1) where it closes; the last point may repeat the
      first): interpolation with control_points = the number of distinct points, periodic
      least squares with fewer (at least degree + 1), or the fewest within tolerance.

Request:  points, degree, control_points or tolerance, parametrization (optional),
          start_derivative, end_derivative (optional vectors), closed (optional boolean)
Response: curve (bspline), max_error (largest distance from a point to the curve at the
          point's parameter)

Example:
  echo '{"points": [[0,0],[1,1],[2,0]], "degree": 2, "control_points": 3, "parametrization": "uniform"}' | casteljau fit
  {"curve":{"type":"bspline","degree":2,"knots":[0.0,0.0,0.0,1.0,1.0,1.0],"points":[[0.0,0.0],[1.0,2.0],[2.0,0.0]]},"max_error":0.0})";

constexpr std::string_view bounds_details = R"(The tight axis-aligned box of a curve over its domain (not of its control points),
or over the parameter range [from, to] (an extension of the contract).

Request:  curve, from, to (optional numbers in the domain, from <= to; default: the
          domain's ends)
Response: min, max (points)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}}' | casteljau bounds
  {"min":[0.0,0.0],"max":[2.0,1.0]}
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "to": 0.25}' | casteljau bounds
  {"min":[0.0,0.0],"max":[0.5,0.75]})";

constexpr std::string_view to_bezier_details = R"(Converts a curve to a path of bezier / rational_bezier segments with the same
parametrisation (the same breaks). A bezier or rational_bezier becomes one segment on [0, 1].

Request:  curve
Response: curve (type path, with segments and breaks)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,1]]}}' | casteljau to_bezier
  {"curve":{"type":"path","segments":[{"type":"bezier","points":[[0.0,0.0],[1.0,1.0]]}],"breaks":[0.0,1.0]}})";

constexpr std::string_view flatten_details = R"(A polyline from the curve's start to its end within `tolerance` (model units) of
the curve; its vertices lie on the curve.

Request:  curve, tolerance (number > 0), method (optional): "uniform" (equal parameter
          steps, their count from Wang's bound), "subdivision" (recursive halving with the
          flatness test), "optimal" (default: near the fewest segments, each step checked
          exactly)
Response: points (the polyline's vertices)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,1],[2,0]]}, "tolerance": 0.2, "method": "subdivision"}' | casteljau flatten
  {"points":[[0.0,0.0],[0.5,0.375],[1.0,0.5],[1.5,0.375],[2.0,0.0]]})";

constexpr std::string_view intersect_details = R"(The common points of two plane curves, or the self-intersections of one.

Request:  curves: [a, b] (2-D curves of any type; a line segment is a degree-1 bezier or a
          polyline), or [a] alone for the points where a meets itself
Response: intersections: [{t: [ta, tb], point, kind: "crossing" or "tangent"}], sorted by
          ta (ta < tb for self-intersections); overlaps: [{a: [t0, t1], b: [u0, u1]}],
          where a on [t0, t1] (t0 < t1) traces b from u0 to u1. Points are common when
          the curves come within 1e-10 of their size; crossings are refined to full
          double precision.

Example:
  echo '{"curves": [{"type": "bezier", "points": [[0,0],[2,2]]}, {"type": "polyline", "points": [[0,2],[2,0]]}]}' | casteljau intersect
  {"intersections":[{"t":[0.5,0.5],"point":[1.0,1.0],"kind":"crossing"}],"overlaps":[]})";

constexpr std::string_view render_details = R"(Draws curves as an SVG document, written to stdout as is (not JSON; with --jsonl,
each answer is {"svg": "..."}). 1D curves are drawn as graphs y(t).

Request:  curve, or curves (array of curve objects); optional styling:
          width, height (px, > 0; default 640, 480), padding (px, >= 0; default 24),
          background (CSS colour or "none"; default "white"), stroke (CSS colour;
          default "#1f77b4", a palette for several curves), stroke_width (px, > 0;
          default 2), control_polygon (boolean; default true), axes (boolean; default
          false), tolerance (model units, >= 0; 0 means 0.25 px)
Response: an SVG document

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "width": 320, "height": 240}' | casteljau render > curve.svg)";

constexpr std::string_view length_details = R"(Arc length of a curve over its domain or between two parameters, to a relative
accuracy of 1e-12 (adaptive Gauss-Kronrod on the Bezier pieces, split at cusps).

Request:  curve, from, to (optional parameters in the domain, from <= to; default its ends)
Response: length

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[3,4]]}}' | casteljau length
  {"length":5.0})";

constexpr std::string_view param_at_length_details = R"(The parameters at given arc lengths from the domain's start (the inverse of length).

Request:  curve, lengths (array, each in [0, the curve's length])
Response: t (one parameter per length)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,0],[2,0]]}, "lengths": [0, 0.5, 2]}' | casteljau param_at_length
  {"t":[0.0,0.25,1.0]})";

constexpr std::string_view project_details = R"(The point of a curve nearest to a point (farthest with farthest: true), the global
extremum over the whole domain.

Request:  curve, point, farthest (optional boolean, default false)
Response: t, point, distance; all_t when several parameters tie (distances equal within
          1e-12 relative); intervals where the distance is constant and extreme on a whole
          interval (a circular arc about the point, a curve that is a single point)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "point": [1,3]}' | casteljau project
  {"t":0.5,"point":[1.0,1.0],"distance":2.0})";

constexpr std::string_view features_details = R"(Inflections and cusps (plane curves) and, per axis, the parameters where that
coordinate has a local extremum (inside the domain, breaks included).

Request:  curve
Response: inflections, cusps (parameters; empty unless the curve is 2-D), extrema (one
          array of parameters per axis)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,1],[2,-1],[3,0]]}}' | casteljau features
  {"inflections":[0.5],"cusps":[],"extrema":[[],[0.21132486540518713,0.7886751345948129]]})";

constexpr std::string_view distance_details = R"(The minimum distance between two curves of one dimension, over both domains.

Request:  curves: [a, b]
Response: distance, t: [ta, tb], points: [a(ta), b(tb)]

Example:
  echo '{"curves": [{"type": "bezier", "points": [[0,0],[2,0]]}, {"type": "bezier", "points": [[1,1],[1,3]]}]}' | casteljau distance
  {"distance":1.0,"t":[0.5,0.0],"points":[[1.0,0.0],[1.0,1.0]]})";

constexpr std::string_view area_details = R"(The signed area enclosed by a closed plane curve (its end equal to its start within
1e-9 of its extent), positive counter-clockwise; exact for polynomial pieces (Green's
theorem in Bernstein form).

Request:  curve (2-D, closed)
Response: area

Example:
  echo '{"curve": {"type": "polyline", "points": [[0,0],[2,0],[2,1],[0,1],[0,0]]}}' | casteljau area
  {"area":2.0})";

// One line per command of the contract; a helper's command flips its own line to
// supported (the array's size is deduced, so adding a command touches one line).
constexpr Command all_commands[] = {
    {"eval", "Evaluate a curve (and its derivatives) at parameters", eval_details, true},
    {"split", "Split a bezier, rational_bezier, bspline or nurbs curve at t", split_details, true},
    {"elevate", "Raise the degree of a bezier, rational_bezier, bspline or nurbs curve", elevate_details, true},
    {"bounds", "Tight axis-aligned bounding box of a curve", bounds_details, true},
    {"to_bezier", "Convert a curve to a path of Bezier segments", to_bezier_details, true},
    {"flatten", "Polyline within a distance tolerance of a curve", flatten_details, true},
    {"render", "Draw curves as an SVG document", render_details, true},
    {"insert_knot", "Insert a knot into a bspline or nurbs curve", insert_knot_details, true},
    {"length", "Arc length of a curve", length_details, true},
    {"project", "Nearest (or farthest) point of a curve to a point", project_details, true},
    {"intersect", "Intersections and overlaps of plane curves, or of one curve with itself", intersect_details, true},
    {"fit", "Fit a B-spline to points: interpolation, least squares, tolerance", fit_details, true},
    {"remove_knot", "Remove a knot from a bspline or nurbs curve within a tolerance", remove_knot_details, true},
    {"subdivide", "Subdivision curves: Chaikin, Lane-Riesenfeld, 4-point", subdivide_details, true},
    {"param_at_length", "Parameters at given arc lengths", param_at_length_details, true},
    {"features", "Inflections, cusps and extrema of a curve", features_details, true},
    {"distance", "Minimum distance between two curves", distance_details, true},
    {"area", "Signed area of a closed plane curve", area_details, true},
};

}  // namespace

std::span<const Command> commands() { return all_commands; }

const Command* find_command(std::string_view name) {
  for (const auto& c : all_commands) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

Response run(const Command& command, const Json& request) {
  using Handler = Response (*)(const Json&);
  static constexpr std::pair<std::string_view, Handler> handlers[] = {
      {"eval", eval},
      {"split", split},
      {"elevate", elevate},
      {"bounds", bounds},
      {"to_bezier", to_bezier},
      {"flatten", flatten},
      {"render", render},
      {"insert_knot", insert_knot},
      {"remove_knot", remove_knot},
      {"subdivide", subdivide},
      {"fit", fit},
      {"length", length}, {"param_at_length", param_at_length}, {"project", project}, {"features", features}, {"distance", distance}, {"area", area},
      {"intersect", intersect},
  };
  for (const auto& [name, handler] : handlers) {
    if (name == command.name) {
      Response r = handler(request);
      if (!r.is_svg) {
        // JSON has no NaN or infinity; a result that overflowed is refused, not written as null.
        if (auto where = io::find_non_finite(r.json)) {
          throw InvalidArgument("request", "the result is not finite at " + *where + " (overflow)");
        }
      }
      return r;
    }
  }
  throw InvalidArgument("command", "command '" + std::string(command.name) + "' is not supported yet");
}

}  // namespace casteljau::cli
