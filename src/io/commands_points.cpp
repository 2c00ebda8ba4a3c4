// The commands on point sets: subdivide (subdivision curves of a polygon) and fit
// (B-spline fitting). Each is one entry of the registry (io/commands.hpp); their
// conditional rules (a field only with some scheme, control_points xor tolerance) are
// checked here. Examples are real responses (tests/cli).
#include <algorithm>
#include <iterator>
#include <string>

#include "casteljau/io/fit.hpp"
#include "casteljau/io/knots.hpp"
#include "casteljau/io/results.hpp"
#include "commands_family.hpp"

namespace casteljau::io::detail {

namespace {

constexpr std::string_view schemes[] = {"chaikin", "lane_riesenfeld", "four_point"};

Response subdivide(const Args& a) {
  const std::string& name = a.string("scheme");
  const SubdivisionScheme scheme = name == "chaikin"           ? SubdivisionScheme::chaikin
                                   : name == "lane_riesenfeld" ? SubdivisionScheme::lane_riesenfeld
                                                               : SubdivisionScheme::four_point;
  int degree = 2;
  if (scheme == SubdivisionScheme::lane_riesenfeld) {
    if (!a.has("degree")) throw InvalidArgument("degree", "required field is missing");
    degree = a.integer("degree");
    if (degree < 1 || degree > max_degree) {
      throw InvalidArgument("degree", "degree must be in 1.." + std::to_string(max_degree) + ", got " + std::to_string(degree));
    }
  } else if (a.has("degree")) {
    throw InvalidArgument("degree", "only the lane_riesenfeld scheme takes a degree");
  }
  if (a.has("tension") && scheme != SubdivisionScheme::four_point) {
    throw InvalidArgument("tension", "only the four_point scheme takes a tension");
  }
  const AnySubdivision s =
      io::subdivide(a.points("points"), scheme, degree, a.number("tension"), a.integer("iterations"), a.boolean("closed"));
  return {to_json(s)};
}

constexpr Field subdivide_fields[] = {
    {"points", FieldType::points, true, {}, "the control polygon"},
    {"scheme", FieldType::string, true, {}, {}, schemes},
    {"degree", FieldType::integer, false, {}, "lane_riesenfeld only (and required there): p in 1..1000; chaikin is p = 2"},
    {"tension", FieldType::number, false, "0.0625", "four_point only: w in [0, (sqrt 5 - 1) / 8)"},
    {"iterations", FieldType::integer, true, {}, "k >= 0 steps"},
    {"closed", FieldType::boolean, false, "false", "a closed polygon"},
};

constexpr std::string_view smoothing_choices[] = {"gcv"};

/// The smoothing fit's fields. The smoothing spline is the natural cubic spline (the
/// minimiser over all functions with a square-integrable second derivative): degree 3,
/// free (natural) ends, knots at every parameter; every field asking for something else
/// is refused, naming it.
void read_smoothing(const Args& a, bool cp, bool tol, AnyFitRequest& r) {
  if (cp) throw InvalidArgument("control_points", "give one of control_points, tolerance or smoothing (a smoothing fit has a knot at every point)");
  if (tol) throw InvalidArgument("tolerance", "give one of control_points, tolerance or smoothing");
  if (r.degree != 3) {
    throw InvalidArgument("degree", "a smoothing fit is cubic (the minimiser of the penalty on the second derivative is a natural cubic spline): degree must be 3, got " +
                                        std::to_string(r.degree));
  }
  for (const char* name : {"start_derivative", "end_derivative"}) {
    if (a.has(name)) throw InvalidArgument(name, "a smoothing fit has natural ends (zero second derivative) and takes no end derivatives");
  }
  if (a.boolean("closed")) throw InvalidArgument("closed", "a smoothing fit is open (periodic smoothing is not served)");
  if (a.choice("smoothing") == "gcv") {
    r.smoothing_gcv = true;
  } else {
    const double lambda = a.number("smoothing");
    if (!(lambda >= 0)) throw InvalidArgument("smoothing", "lambda must be >= 0, got " + number_text(lambda));
    r.smoothing = lambda;
  }
}

Response fit(const Args& a) {
  AnyFitRequest r;
  r.degree = a.integer("degree");
  if (r.degree < 1 || r.degree > max_degree) {
    throw InvalidArgument("degree", "degree must be in 1.." + std::to_string(max_degree) + ", got " + std::to_string(r.degree));
  }
  const bool cp = a.has("control_points"), tol = a.has("tolerance");
  if (a.has("smoothing")) {
    read_smoothing(a, cp, tol, r);
  } else {
    if (cp && tol) throw InvalidArgument("tolerance", "give either control_points or tolerance, not both");
    if (!cp && !tol) throw InvalidArgument("control_points", "required field is missing (or give tolerance or smoothing)");
    if (cp) {
      const int n = a.integer("control_points");
      if (n < 1) throw InvalidArgument("control_points", "must be >= 1, got " + std::to_string(n));
      r.control_points = static_cast<std::size_t>(n);
    } else {
      r.tolerance = a.number("tolerance");
      if (!(*r.tolerance > 0)) throw InvalidArgument("tolerance", "tolerance must be > 0, got " + number_text(*r.tolerance));
    }
  }
  // The choices are listed in the order of the Parametrization enum (curves/parametrization.hpp).
  const std::string& rule = a.string("parametrization");
  r.parametrization = *parametrization_named(rule);
  r.start_derivative = a.optional_numbers("start_derivative");
  r.end_derivative = a.optional_numbers("end_derivative");
  r.closed = a.boolean("closed");
  return {to_json(io::fit(a.points("points"), r))};
}

constexpr Field fit_fields[] = {
    {"points", FieldType::points, true, {}, "the points to fit"},
    {"degree", FieldType::integer, true, {}, "p in 1..1000"},
    {"control_points", FieldType::integer, false, {}, "how many (>= 1); or give tolerance"},
    {"tolerance", FieldType::number, false, {}, "> 0: the fewest control points within it; or give control_points"},
    {"smoothing", FieldType::number_or_choice, false, {}, "lambda >= 0 or \"gcv\": the cubic smoothing spline (degree 3); or give control_points", smoothing_choices},
    {"parametrization", FieldType::string, false, "\"chord\"", "the points' parameters, divided by the last", parametrization_names},
    {"start_derivative", FieldType::vector, false, {}, "the curve's derivative at its start (open curves)"},
    {"end_derivative", FieldType::vector, false, {}, "the curve's derivative at its end (open curves)"},
    {"closed", FieldType::boolean, false, "false", "a periodic curve"},
};

constexpr Command point_family[] = {
    {"subdivide", "Subdivision curves: Chaikin, Lane-Riesenfeld, 4-point",
     "Subdivision curves: `iterations` steps of a scheme on a control polygon. chaikin\n"
     "(corner cutting), lane_riesenfeld (degree p >= 1; chaikin is p = 2) and four_point\n"
     "(interpolating, Dyn-Levin-Gregory; tension in [0, 0.1545...), default 1/16). Open\n"
     "polygons keep their end points: Lane-Riesenfeld steps are then knot insertion at the\n"
     "span midpoints of the clamped uniform B-spline; the 4-point scheme reflects the end\n"
     "points. `limit` is the limit curve as a bspline (uniform knots; periodic when closed);\n"
     "four_point has none.",
     "points (after k steps), limit (bspline, except for four_point)",
     R"(  echo '{"points": [[0,0],[4,0],[4,4],[0,4]], "scheme": "chaikin", "iterations": 1, "closed": true}' | casteljau subdivide
  {"points":[[1.0,0.0],[3.0,0.0],[4.0,1.0],[4.0,3.0],[3.0,4.0],[1.0,4.0],[0.0,3.0],[0.0,1.0]],"limit":{"type":"bspline","degree":2,"knots":[0.0,1.0,2.0,3.0,4.0,5.0,6.0,7.0,8.0],"points":[[0.0,0.0],[4.0,0.0],[4.0,4.0],[0.0,4.0],[0.0,0.0],[4.0,0.0]]}})",
     subdivide_fields, subdivide, "", ""},
    {"fit", "Fit a B-spline to points: interpolation, least squares, tolerance",
     "Fits a bspline to points ([PT97] chapter 9): clamped, or unclamped and\n"
     "periodic when closed. Parameters by the parametrization (uniform, chord (default),\n"
     "centripetal), divided by the last so that the curve's domain is [0, 1].\n"
     "\n"
     "  control_points = number of points (+ 1 per end derivative): global interpolation\n"
     "      (knots by averaging the parameters, [PT97] A9.1, eq. 9.8; end derivatives 9.2.2);\n"
     "  control_points smaller: least squares with the end points (and given end derivatives)\n"
     "      matched exactly, knots by [PT97] eq. 9.68-9.69;\n"
     "  tolerance: the fewest control points found (bisection) whose max_error is within it;\n"
     "      interpolation when nothing fewer is;\n"
     "  closed: a periodic curve (C^(degree-1) where it closes; the last point may repeat the\n"
     "      first): interpolation with control_points = the number of distinct points, periodic\n"
     "      least squares with fewer (at least degree + 1), or the fewest within tolerance;\n"
     "  smoothing: lambda >= 0 or \"gcv\": the cubic (degree 3) natural spline with a knot at\n"
     "      every parameter minimising sum |Q_k - C(t_k)|^2 + lambda * integral |C''|^2, as\n"
     "      scipy's make_smoothing_spline per coordinate; gcv chooses lambda by generalised\n"
     "      cross-validation (stacked over the coordinates). Open curves, no end derivatives.",
     "curve (bspline), max_error (largest distance from a point to the curve at the\n"
     "          point's parameter), smoothing (the lambda of a smoothing fit)",
     R"(  echo '{"points": [[0,0],[1,1],[2,0]], "degree": 2, "control_points": 3, "parametrization": "uniform"}' | casteljau fit
  {"curve":{"type":"bspline","degree":2,"knots":[0.0,0.0,0.0,1.0,1.0,1.0],"points":[[0.0,0.0],[1.0,2.0],[2.0,0.0]]},"max_error":0.0})",
     fit_fields, fit, "", "points"},
};

}  // namespace

std::span<const Command> point_commands() { return point_family; }

}  // namespace casteljau::io::detail
