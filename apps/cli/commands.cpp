// The commands of the `casteljau` program: each converts the request, calls the library
// and converts the result. No geometry here; errors keep the library's InvalidArgument,
// prefixed with their place in the request.
#include "commands.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/io/any_curve.hpp"
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
    constexpr std::array<std::string_view, 5> fields = {"curve", "curves", "t", "times", "tolerance"};
    if (std::find(fields.begin(), fields.end(), root) != fields.end()) throw;
    throw InvalidArgument("curve", "the computation failed on this curve: " + std::string(e.what()));
  } catch (const NumericalError& e) {
    throw InvalidArgument(std::string(numerical_field), e.what());
  }
}

// ---------------------------------------------------------------------------------------

Response eval(const Json& req) {
  const io::Fields f(req, "an eval request");
  f.allow_only({"curve", "t", "derivatives"}, "an eval request");
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
  Response r;
  call_library([&] {
    r.json = OrderedJson{{"points", points_json(io::evaluate(curve, ts))}};
    if (k > 0) {
      OrderedJson derivatives = OrderedJson::array();
      for (int order = 1; order <= k; ++order) derivatives.push_back(points_json(io::derivatives(curve, ts, order)));
      r.json["derivatives"] = std::move(derivatives);
    }
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

Response bounds(const Json& req) {
  const io::Fields f(req, "a bounds request");
  f.allow_only({"curve"}, "a bounds request");
  const io::AnyCurve curve = read_curve(f);
  Response r;
  call_library([&] {
    const io::AnyBox box = io::bounds(curve);
    r.json = OrderedJson{{"min", numbers_json(box.lo)}, {"max", numbers_json(box.hi)}};
  });
  return r;
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
// Descriptions. Examples are real responses of this program (checked by tests/cli).

constexpr std::string_view eval_details = R"(Evaluates a curve at parameters, optionally with derivatives with respect to the
curve's parameter.

Request:  curve, t (array of numbers), derivatives (optional integer k >= 0, default 0)
Response: points (one per t); when k > 0, derivatives: k arrays (orders 1..k), each with
          one vector per t. Parameters outside the domain extrapolate the first or last piece.

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}, "t": [0, 0.5], "derivatives": 1}' | casteljau eval
  {"points":[[0.0,0.0],[2.0,1.5]],"derivatives":[[[3.0,6.0],[4.5,0.0]]]})";

constexpr std::string_view split_details = R"(Splits a bezier or rational_bezier curve at t in [0, 1] into two curves of the
same type, each on [0, 1].

Request:  curve (bezier or rational_bezier), t (number in [0, 1])
Response: curves: [left, right]

Example:
  echo '{"curve": {"type": "bezier", "points": [[0],[2],[4]]}, "t": 0.5}' | casteljau split
  {"curves":[{"type":"bezier","points":[[0.0],[1.0],[2.0]]},{"type":"bezier","points":[[2.0],[3.0],[4.0]]}]})";

constexpr std::string_view elevate_details = R"(Raises the degree of a bezier or rational_bezier curve without changing it.

Request:  curve (bezier or rational_bezier), times (integer r >= 1)
Response: curve (same type, degree + r)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "times": 1}' | casteljau elevate
  {"curve":{"type":"bezier","points":[[0.0,0.0],[0.6666666666666666,1.3333333333333333],[1.3333333333333333,1.3333333333333335],[2.0,0.0]]}})";

constexpr std::string_view bounds_details = R"(The tight axis-aligned box of a curve over its domain (not of its control points).

Request:  curve
Response: min, max (points)

Example:
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}}' | casteljau bounds
  {"min":[0.0,0.0],"max":[2.0,1.0]})";

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

constexpr std::string_view later_details = R"(Defined by the command line contract (shared/spec/cli.md) but not supported by this
version: running it is an error (exit status 2).)";

// One line per command of the contract; a helper's command flips its own line to
// supported (the array's size is deduced, so adding a command touches one line).
constexpr Command all_commands[] = {
    {"eval", "Evaluate a curve (and its derivatives) at parameters", eval_details, true},
    {"split", "Split a bezier or rational_bezier curve at t in [0, 1]", split_details, true},
    {"elevate", "Raise the degree of a bezier or rational_bezier curve", elevate_details, true},
    {"bounds", "Tight axis-aligned bounding box of a curve", bounds_details, true},
    {"to_bezier", "Convert a curve to a path of Bezier segments", to_bezier_details, true},
    {"flatten", "Polyline within a distance tolerance of a curve", flatten_details, true},
    {"render", "Draw curves as an SVG document", render_details, true},
    {"insert_knot", "Insert a knot into a B-spline (not supported yet)", later_details, false},
    {"length", "Arc length of a curve (not supported yet)", later_details, false},
    {"project", "Nearest point of a curve (not supported yet)", later_details, false},
    {"intersect", "Intersections and overlaps of plane curves, or of one curve with itself", intersect_details, true},
    {"fit", "Fit a B-spline to points (not supported yet)", later_details, false},
    {"remove_knot", "Remove a knot from a B-spline within a tolerance (not supported yet)", later_details, false},
    {"subdivide", "Subdivision curves: Chaikin, Lane-Riesenfeld, 4-point (not supported yet)", later_details, false},
    {"param_at_length", "Parameters at given arc lengths (not supported yet)", later_details, false},
    {"features", "Inflections, cusps and extrema of a curve (not supported yet)", later_details, false},
    {"distance", "Minimum distance between two curves (not supported yet)", later_details, false},
    {"area", "Signed area of a closed plane curve (not supported yet)", later_details, false},
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
