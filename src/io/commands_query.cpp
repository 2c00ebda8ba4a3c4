// The geometric queries: bounds, length, param_at_length, project, features, distance,
// area, intersect. Each is one entry of the registry (io/commands.hpp). The library names
// the request's own fields in its errors ("point", "from", "lengths[2]", "curves[1]"):
// those pass through as they are (io::run). Examples are real responses (tests/cli).
#include <string>
#include <vector>

#include "casteljau/io/intersect.hpp"
#include "casteljau/io/queries.hpp"
#include "casteljau/io/results.hpp"
#include "commands_family.hpp"
#include "text.hpp"

namespace casteljau::io::detail {

namespace {

// bounds: over the domain, or over [from, to] (an extension of the contract; docs/cli.md).
Response bounds(const Args& a) {
  const AnyCurve& curve = a.curve("curve");
  const auto from = a.optional_number("from"), to = a.optional_number("to");
  return {to_json(from || to ? io::bounds(curve, from, to) : io::bounds(curve))};
}

constexpr Field range_fields[] = {
    {"curve", FieldType::curve, true},
    {"from", FieldType::number, false, {}, "in the domain, from <= to (default: the domain's start)"},
    {"to", FieldType::number, false, {}, "in the domain (default: the domain's end)"},
};

Response length(const Args& a) {
  return {OrderedJson{{"length", io::length(a.curve("curve"), a.optional_number("from"), a.optional_number("to"))}}};
}

Response param_at_length(const Args& a) {
  return {OrderedJson{{"t", to_json(io::param_at_length(a.curve("curve"), a.numbers("lengths")))}}};
}

constexpr Field param_at_length_fields[] = {
    {"curve", FieldType::curve, true},
    {"lengths", FieldType::numbers, true, {}, "arc lengths from the domain's start, each in [0, the curve's length]"},
};

Response project(const Args& a) {
  return {to_json(io::project(a.curve("curve"), a.numbers("point"), a.boolean("farthest")))};
}

constexpr Field project_fields[] = {
    {"curve", FieldType::curve, true},
    {"point", FieldType::point, true, {}, "the curve's dimension"},
    {"farthest", FieldType::boolean, false, "false", "the farthest point instead of the nearest"},
};

Response features(const Args& a) {
  return {to_json(io::features(a.curve("curve")))};
}

constexpr Field curve_only[] = {
    {"curve", FieldType::curve, true},
};

Response distance(const Args& a) {
  const auto curves = a.curves("curves");
  return {to_json(io::distance(curves[0], curves[1]))};
}

constexpr Field distance_fields[] = {
    {"curves", FieldType::curves, true, {}, "[a, b], of one dimension", {}, {}, 2, 2},
};

Response area(const Args& a) { return {OrderedJson{{"area", io::area(a.curve("curve"))}}}; }

constexpr Field area_fields[] = {
    {"curve", FieldType::curve, true, {}, "2-D and closed"},
};

Response intersect(const Args& a) {
  const auto curves = a.curves("curves");
  for (std::size_t i = 0; i < curves.size(); ++i) {
    if (dimension(curves[i]) != 2) {
      throw InvalidArgument(index_path("curves", i), "intersect needs 2-D curves, got dimension " + std::to_string(dimension(curves[i])));
    }
  }
  return {to_json(curves.size() == 1 ? io::self_intersect(curves[0]) : io::intersect(curves[0], curves[1]))};
}

constexpr Field intersect_fields[] = {
    {"curves", FieldType::curves, true, {}, "[a, b] (2-D), or [a] alone for its self-intersections", {}, {}, 1, 2},
};

// ---------------------------------------------------------------------------------------

constexpr Command query_family[] = {
    {"bounds", "Tight axis-aligned bounding box of a curve",
     "The tight axis-aligned box of a curve over its domain (not of its control points),\n"
     "or over the parameter range [from, to] (an extension of the contract).",
     "min, max (points)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}}' | casteljau bounds
  {"min":[0.0,0.0],"max":[2.0,1.0]}
  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "to": 0.25}' | casteljau bounds
  {"min":[0.0,0.0],"max":[0.5,0.75]})",
     range_fields, bounds},
    {"length", "Arc length of a curve",
     "Arc length of a curve over its domain or between two parameters, to a relative\n"
     "accuracy of 1e-12 (adaptive Gauss-Kronrod on the Bezier pieces, split at cusps).",
     "length",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[3,4]]}}' | casteljau length
  {"length":5.0})",
     range_fields, length},
    {"param_at_length", "Parameters at given arc lengths",
     "The parameters at given arc lengths from the domain's start (the inverse of length).", "t (one parameter per length)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,0],[2,0]]}, "lengths": [0, 0.5, 2]}' | casteljau param_at_length
  {"t":[0.0,0.25,1.0]})",
     param_at_length_fields, param_at_length},
    {"project", "Nearest (or farthest) point of a curve to a point",
     "The point of a curve nearest to a point (farthest with farthest: true), the global\n"
     "extremum over the whole domain.",
     "t, point, distance; all_t when several parameters tie (distances equal within\n"
     "          1e-12 relative); intervals where the distance is constant and extreme on a whole\n"
     "          interval (a circular arc about the point, a curve that is a single point)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "point": [1,3]}' | casteljau project
  {"t":0.5,"point":[1.0,1.0],"distance":2.0})",
     project_fields, project},
    {"features", "Inflections, cusps and extrema of a curve",
     "Inflections and cusps (plane curves) and, per axis, the parameters where that\n"
     "coordinate has a local extremum (inside the domain, breaks included).",
     "inflections, cusps (parameters; empty unless the curve is 2-D), extrema (one\n"
     "          array of parameters per axis)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,1],[2,-1],[3,0]]}}' | casteljau features
  {"inflections":[0.5],"cusps":[],"extrema":[[],[0.21132486540518713,0.7886751345948129]]})",
     curve_only, features},
    {"distance", "Minimum distance between two curves",
     "The minimum distance between two curves of one dimension, over both domains.",
     "distance, t: [ta, tb], points: [a(ta), b(tb)]",
     R"(  echo '{"curves": [{"type": "bezier", "points": [[0,0],[2,0]]}, {"type": "bezier", "points": [[1,1],[1,3]]}]}' | casteljau distance
  {"distance":1.0,"t":[0.5,0.0],"points":[[1.0,0.0],[1.0,1.0]]})",
     distance_fields, distance, "curves", "curves"},
    {"area", "Signed area of a closed plane curve",
     "The signed area enclosed by a closed plane curve (its end equal to its start within\n"
     "1e-9 of its extent), positive counter-clockwise; exact for polynomial pieces (Green's\n"
     "theorem in Bernstein form).",
     "area",
     R"(  echo '{"curve": {"type": "polyline", "points": [[0,0],[2,0],[2,1],[0,1],[0,0]]}}' | casteljau area
  {"area":2.0})",
     area_fields, area},
    {"intersect", "Intersections and overlaps of plane curves, or of one curve with itself",
     "The common points of two plane curves, or the self-intersections of one (a line\n"
     "segment is a degree-1 bezier or a polyline).",
     "intersections: [{t: [ta, tb], point, kind: \"crossing\" or \"tangent\"}], sorted by\n"
     "          ta (ta < tb for self-intersections); overlaps: [{a: [t0, t1], b: [u0, u1]}],\n"
     "          where a on [t0, t1] (t0 < t1) traces b from u0 to u1. Points are common when\n"
     "          the curves come within 1e-10 of their size; crossings are refined to full\n"
     "          double precision.",
     R"(  echo '{"curves": [{"type": "bezier", "points": [[0,0],[2,2]]}, {"type": "polyline", "points": [[0,2],[2,0]]}]}' | casteljau intersect
  {"intersections":[{"t":[0.5,0.5],"point":[1.0,1.0],"kind":"crossing"}],"overlaps":[]})",
     intersect_fields, intersect, "curves", "curves"},
};

}  // namespace

std::span<const Command> query_commands() { return query_family; }

}  // namespace casteljau::io::detail
