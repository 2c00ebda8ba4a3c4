// The commands on one curve that answer a curve or points: eval, split, elevate,
// to_bezier, flatten, insert_knot, remove_knot, and render (SVG). Each is one entry of
// the registry (io/commands.hpp): its fields, its texts and its function. Examples are
// real responses of the program (checked by tests/cli).
#include <string>
#include <vector>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/knots.hpp"
#include "casteljau/io/queries.hpp"
#include "casteljau/io/results.hpp"
#include "casteljau/io/svg.hpp"
#include "commands_family.hpp"

namespace casteljau::io::detail {

namespace {

/// Highest derivative order `eval` computes. Far above any order that is accurate in
/// double for the degrees people use; it keeps a typo (1000000) from allocating a
/// response of that many arrays.
constexpr int max_derivative_order = 64;

// ---------------------------------------------------------------------------------------
// eval

Response eval(const Args& a) {
  const AnyCurve& curve = a.curve("curve");
  const std::vector<double>& ts = a.numbers("t");
  const int k = a.integer("derivatives");
  if (k < 0) throw InvalidArgument("derivatives", "derivative count must be >= 0, got " + std::to_string(k));
  if (k > max_derivative_order) {
    throw InvalidArgument("derivatives",
                          "derivative count must be <= " + std::to_string(max_derivative_order) + ", got " + std::to_string(k));
  }
  Response r;
  r.json = OrderedJson{{"points", to_json(io::evaluate(curve, ts))}};
  if (k > 0) {
    OrderedJson derivatives = OrderedJson::array();
    for (int order = 1; order <= k; ++order) derivatives.push_back(to_json(io::derivatives(curve, ts, order)));
    r.json["derivatives"] = std::move(derivatives);
  }
  if (a.boolean("curvature")) r.json["curvature"] = to_json(io::curvature(curve, ts));
  // frame: one list per quantity, one entry per parameter; the lists a dimension does not
  // have (normal in 1-D, binormal and torsion outside 3-D) are left out.
  if (a.boolean("frame")) r.json["frame"] = columns_json(io::frames(curve, ts));
  return r;
}

constexpr Field eval_fields[] = {
    {"curve", FieldType::curve, true},
    {"t", FieldType::numbers, true, {}, "parameters (any finite t; outside the domain the end pieces extrapolate)"},
    {"derivatives", FieldType::integer, false, "0", "k >= 0 (at most 64): derivatives of orders 1..k"},
    {"curvature", FieldType::boolean, false, "false", "also the curvature at each t"},
    {"frame", FieldType::boolean, false, "false", "also the Frenet frame at each t (an extension of the contract)"},
};

// ---------------------------------------------------------------------------------------
// split, elevate, to_bezier, flatten

Response split(const Args& a) {
  const AnySplit halves = io::split(a.curve("curve"), a.number("t"));
  return {OrderedJson{{"curves", OrderedJson::array({to_json(halves.left), to_json(halves.right)})}}};
}

constexpr Field split_fields[] = {
    {"curve", FieldType::curve, true, {}, {}, {}, {}, 0, 0, Capability::split},
    {"t", FieldType::number, true, {}, "in the domain (bspline, nurbs: strictly inside)", {}, "split parameter"},
};

Response elevate(const Args& a) { return {OrderedJson{{"curve", to_json(io::elevate(a.curve("curve"), a.integer("times")))}}}; }

constexpr Field elevate_fields[] = {
    {"curve", FieldType::curve, true, {}, {}, {}, {}, 0, 0, Capability::elevate},
    {"times", FieldType::integer, true, {}, "r >= 1: the degree grows by r (to at most 1000)"},
};

Response to_bezier(const Args& a) { return {OrderedJson{{"curve", to_json(io::to_bezier(a.curve("curve")))}}}; }

constexpr Field to_bezier_fields[] = {
    {"curve", FieldType::curve, true},
};

constexpr std::string_view flatten_methods[] = {"uniform", "subdivision", "optimal"};

Response flatten(const Args& a) {
  const std::string& m = a.string("method");
  const FlattenMethod method = m == "uniform"       ? FlattenMethod::uniform
                               : m == "subdivision" ? FlattenMethod::subdivision
                                                    : FlattenMethod::optimal;
  return {OrderedJson{{"points", to_json(io::flatten(a.curve("curve"), a.number("tolerance"), method))}}};
}

constexpr Field flatten_fields[] = {
    {"curve", FieldType::curve, true},
    {"tolerance", FieldType::number, true, {}, "> 0, model units"},
    {"method", FieldType::string, false, "\"optimal\"",
     "uniform (equal parameter steps, their count from Wang's bound), subdivision (recursive halving with the flatness "
     "test), optimal (near the fewest segments, each step checked exactly)",
     flatten_methods},
};

// ---------------------------------------------------------------------------------------
// insert_knot, remove_knot

/// `times` of insert_knot / remove_knot: an integer >= 1.
int knot_times(const Args& a) {
  const int times = a.integer("times");
  if (times < 1) throw InvalidArgument("times", "count must be >= 1, got " + std::to_string(times));
  return times;
}

Response insert_knot(const Args& a) {
  const double u = a.number("knot");
  return {OrderedJson{{"curve", to_json(io::insert_knot(a.curve("curve"), u, knot_times(a)))}}};
}

constexpr Field insert_knot_fields[] = {
    {"curve", FieldType::curve, true, {}, {}, {}, {}, 0, 0, Capability::knot_insertion},
    {"knot", FieldType::number, true, {}, "in the domain"},
    {"times", FieldType::integer, false, "1", ">= 1; the knot's multiplicity afterwards is at most p + 1 (p + 1: a break)"},
};

Response remove_knot(const Args& a) {
  const double u = a.number("knot");
  const int times = knot_times(a);
  return {to_json(io::remove_knot(a.curve("curve"), u, times, a.number("tolerance")))};
}

constexpr Field remove_knot_fields[] = {
    {"curve", FieldType::curve, true, {}, {}, {}, {}, 0, 0, Capability::knot_removal},
    {"knot", FieldType::number, true, {}, "an interior knot"},
    {"times", FieldType::integer, false, "1", ">= 1, at most the knot's multiplicity"},
    {"tolerance", FieldType::number, false, "1e-12", "> 0: how far the curve may move (a guaranteed bound over the domain)"},
};

// ---------------------------------------------------------------------------------------
// render

/// Render colours: CSS colour names, #hex, rgb()/hsl() forms. No quotes or angle brackets,
/// so a colour cannot break out of an SVG attribute whatever the renderer does.
constexpr std::string_view colour_chars = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789#(),.% -";

double positive(const Args& a, std::string_view name, bool allow_zero) {
  const double v = a.number(name);
  if (allow_zero ? !(v >= 0) : !(v > 0)) {
    throw InvalidArgument(std::string(name),
                          std::string(name) + (allow_zero ? " must be >= 0" : " must be > 0") + ", got " + number_text(v));
  }
  return v;
}

std::string colour(const Args& a, std::string_view name) {
  const std::string& s = a.string(name);
  if (s.empty() || s.size() > 64 || s.find_first_not_of(colour_chars) != std::string::npos) {
    throw InvalidArgument(std::string(name), "must be a CSS colour such as \"red\", \"#1f77b4\", \"rgb(0, 128, 255)\" or \"none\"");
  }
  return s;
}

Response render(const Args& a) {
  const bool single = a.has("curve");
  if (single && a.has("curves")) throw InvalidArgument("curves", "give either curve or curves, not both");
  if (!single && !a.has("curves")) throw InvalidArgument("curve", "required field is missing");
  const std::span<const AnyCurve> curves = single ? a.curves("curve") : a.curves("curves");
  RenderStyle style;
  style.width = positive(a, "width", false);
  style.height = positive(a, "height", false);
  style.padding = positive(a, "padding", true);
  style.background = colour(a, "background");
  style.stroke = colour(a, "stroke");
  style.stroke_width = positive(a, "stroke_width", false);
  style.control_polygon = a.boolean("control_polygon");
  style.axes = a.boolean("axes");
  style.tolerance = positive(a, "tolerance", true);
  Response r;
  r.is_svg = true;
  try {
    r.svg = render_svg(curves, style);
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

// The defaults are RenderStyle's (tests/unit/commands_test.cpp checks that they agree).
constexpr Field render_fields[] = {
    {"curve", FieldType::curve, false, {}, "the curve to draw (or curves)"},
    {"curves", FieldType::curves, false, {}, "the curves to draw (or curve)", {}, {}, 1, 0},
    {"width", FieldType::number, false, "640", "page width in px, 1 to 1000000"},
    {"height", FieldType::number, false, "480", "page height in px, 1 to 1000000"},
    {"padding", FieldType::number, false, "24", "px, >= 0, leaving at least 1 px to draw in"},
    {"background", FieldType::string, false, "\"white\"", "CSS colour or \"none\""},
    {"stroke", FieldType::string, false, "\"#1f77b4\"", "CSS colour (a palette for several curves when unset)"},
    {"stroke_width", FieldType::number, false, "2", "px, > 0"},
    {"control_polygon", FieldType::boolean, false, "true", "draw the control points and polygon"},
    {"axes", FieldType::boolean, false, "false", "draw the coordinate axes"},
    {"tolerance", FieldType::number, false, "0", "flattening tolerance in model units, >= 0; 0: a quarter pixel"},
};

// ---------------------------------------------------------------------------------------

constexpr Command curve_family[] = {
    {"eval", "Evaluate a curve (and its derivatives) at parameters",
     "Evaluates a curve at parameters, optionally with derivatives with respect to the\n"
     "curve's parameter.",
     "points (one per t); when k > 0, derivatives: k arrays (orders 1..k), each with\n"
     "          one vector per t; with curvature, curvature: one number per t (signed in 2-D,\n"
     "          positive turning left; >= 0 otherwise; an error where the velocity is zero).\n"
     "          With frame, frame: {tangent, normal, binormal, curvature, torsion}, one entry\n"
     "          per t: unit tangent; normal (2-D: the tangent turned left; 3-D, 4-D: the\n"
     "          principal normal, an error where the curvature is zero); binormal and torsion in\n"
     "          3-D only; an error where the velocity is zero. At a break the right-hand piece\n"
     "          answers. Parameters outside the domain extrapolate the first or last piece.",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}, "t": [0, 0.5], "derivatives": 1}' | casteljau eval
  {"points":[[0.0,0.0],[2.0,1.5]],"derivatives":[[[3.0,6.0],[4.5,0.0]]]}
  echo '{"curve": {"type": "bezier", "points": [[0,0,0],[1,0,0],[1,1,0],[1,1,1]]}, "t": [0], "frame": true}' | casteljau eval
  {"points":[[0.0,0.0,0.0]],"frame":{"tangent":[[1.0,0.0,0.0]],"normal":[[0.0,1.0,0.0]],"binormal":[[0.0,0.0,1.0]],"curvature":[0.6666666666666666],"torsion":[0.3333333333333333]}})",
     eval_fields, eval},
    {"split", "Split a curve at t into two of its type",
     "Splits a curve at t into two curves of the same type. Bezier and rational_bezier\n"
     "halves are each on [0, 1] (t in [0, 1]); bspline and nurbs halves keep their parameter\n"
     "(t strictly inside the domain; the knot t is inserted up to the degree).",
     "curves: [left, right]",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0],[2],[4]]}, "t": 0.5}' | casteljau split
  {"curves":[{"type":"bezier","points":[[0.0],[1.0],[2.0]]},{"type":"bezier","points":[[2.0],[3.0],[4.0]]}]}
  echo '{"curve": {"type": "bspline", "degree": 1, "knots": [0,0,2,2], "points": [[0],[4]]}, "t": 1}' | casteljau split
  {"curves":[{"type":"bspline","degree":1,"knots":[0.0,0.0,1.0,1.0],"points":[[0.0],[2.0]]},{"type":"bspline","degree":1,"knots":[1.0,1.0,2.0,2.0],"points":[[2.0],[4.0]]}]})",
     split_fields, split},
    {"elevate", "Raise the degree of a curve without changing it",
     "Raises the degree of a curve without changing it. A bspline or nurbs keeps its\n"
     "continuity: every interior knot gains `times` copies (decompose into Bezier pieces,\n"
     "elevate each, remove the extra knots [PT97, 5.5]).",
     "curve (same type, degree + r)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "times": 1}' | casteljau elevate
  {"curve":{"type":"bezier","points":[[0.0,0.0],[0.6666666666666666,1.3333333333333333],[1.3333333333333333,1.3333333333333335],[2.0,0.0]]}})",
     elevate_fields, elevate},
    {"to_bezier", "Convert a curve to a path of Bezier segments",
     "Converts a curve to a path of bezier / rational_bezier segments with the same\n"
     "parametrisation (the same breaks). A bezier or rational_bezier becomes one segment on [0, 1].",
     "curve (type path, with segments and breaks)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,1]]}}' | casteljau to_bezier
  {"curve":{"type":"path","segments":[{"type":"bezier","points":[[0.0,0.0],[1.0,1.0]]}],"breaks":[0.0,1.0]}})",
     to_bezier_fields, to_bezier},
    {"flatten", "Polyline within a distance tolerance of a curve",
     "A polyline from the curve's start to its end within `tolerance` (model units) of\n"
     "the curve; its vertices lie on the curve.",
     "points (the polyline's vertices)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,1],[2,0]]}, "tolerance": 0.2, "method": "subdivision"}' | casteljau flatten
  {"points":[[0.0,0.0],[0.5,0.375],[1.0,0.5],[1.5,0.375],[2.0,0.0]]})",
     flatten_fields, flatten, "curve", "tolerance"},  // a tolerance below the coordinates' resolution
    {"insert_knot", "Insert a knot into a bspline or nurbs curve",
     "Inserts a knot into a bspline or nurbs curve without changing the curve\n"
     "(Boehm's algorithm [PT97, A5.1]).",
     "curve",
     R"(  echo '{"curve": {"type": "bspline", "degree": 1, "knots": [0,0,2,2], "points": [[0],[4]]}, "knot": 1}' | casteljau insert_knot
  {"curve":{"type":"bspline","degree":1,"knots":[0.0,0.0,1.0,2.0,2.0],"points":[[0.0],[2.0],[4.0]]}})",
     insert_knot_fields, insert_knot},
    {"remove_knot", "Remove a knot from a bspline or nurbs curve within a tolerance",
     "Removes an interior knot of a bspline or nurbs curve up to `times` times, each\n"
     "removal kept only if the curve moves by at most `tolerance` (a guaranteed bound on the\n"
     "distance over the whole domain) [PT97, A5.8].",
     "curve, removed (how many times the knot was removed)",
     R"(  echo '{"curve": {"type": "bspline", "degree": 1, "knots": [0,0,1,2,2], "points": [[0],[2],[4]]}, "knot": 1}' | casteljau remove_knot
  {"curve":{"type":"bspline","degree":1,"knots":[0.0,0.0,2.0,2.0],"points":[[0.0],[4.0]]},"removed":1})",
     remove_knot_fields, remove_knot},
    {"render", "Draw curves as an SVG document",
     "Draws curves as an SVG document, written to stdout as is (not JSON; with --jsonl,\n"
     "each answer is {\"svg\": \"...\"}). 1D curves are drawn as graphs y(t).",
     "an SVG document",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "width": 320, "height": 240}' | casteljau render > curve.svg)",
     render_fields, render, "", ""},  // the renderer names its curves itself
};

}  // namespace

std::span<const Command> curve_commands() { return curve_family; }

}  // namespace casteljau::io::detail
