// The operations of issue 20: solve (where a coordinate or a linear functional of the curve
// takes a value), refine (many knots inserted at once), to_bspline, reduce, basis, frames
// and offset. Each is one entry of the
// registry (io/commands.hpp); the io functions are in io/ops.hpp. Examples are real
// responses (tests/cli).
#include <optional>
#include <span>
#include <vector>

#include "casteljau/io/basis.hpp"
#include "casteljau/io/frames.hpp"
#include "casteljau/io/ops.hpp"
#include "casteljau/io/results.hpp"
#include "commands_family.hpp"

namespace casteljau::io::detail {

namespace {

Response solve(const Args& a) {
  const std::optional<int> axis = a.has("axis") ? std::optional<int>(a.integer("axis")) : std::nullopt;
  std::optional<std::span<const double>> direction;
  if (a.has("direction")) direction = std::span<const double>(a.numbers("direction"));
  return {to_json(io::solve(a.curve("curve"), axis, direction, a.number("value")))};
}

constexpr Field solve_fields[] = {
    {"curve", FieldType::curve, true},
    {"value", FieldType::number, true, {}, "the level: solves C_axis(t) = value, or a . C(t) = value"},
    {"axis", FieldType::integer, false, {}, "a coordinate index 0..d-1 (give axis or direction)"},
    {"direction", FieldType::vector, false, {}, "a non-zero vector a of the curve's dimension (give axis or direction)"},
};

Response refine(const Args& a) { return {OrderedJson{{"curve", to_json(io::refine(a.curve("curve"), a.numbers("knots")))}}}; }

constexpr Field refine_fields[] = {
    {"curve", FieldType::curve, true, {}, {}, {}, {}, 0, 0, Capability::knot_insertion},
    {"knots", FieldType::numbers, true, {}, "non-decreasing, in the domain; each knot's multiplicity afterwards at most p + 1"},
};

Response to_bspline(const Args& a) { return {OrderedJson{{"curve", to_json(io::to_bspline(a.curve("curve")))}}}; }

constexpr Field to_bspline_fields[] = {
    {"curve", FieldType::curve, true},
};

Response reduce(const Args& a) { return {to_json(io::reduce(a.curve("curve"), a.integer("times"), a.number("tolerance")))}; }

constexpr Field reduce_fields[] = {
    {"curve", FieldType::curve, true, {}, {}, {}, {}, 0, 0, Capability::degree_reduction},
    {"times", FieldType::integer, false, "1", "r with 1 <= r <= p: the degree drops by r (a degree-0 result is a constant)"},
    {"tolerance", FieldType::number, true, {}, "> 0: the largest distance allowed between the curves at equal parameters"},
};

OrderedJson matrix_json(const Eigen::Matrix4d& m) {
  OrderedJson rows = OrderedJson::array();
  for (int i = 0; i < 4; ++i) {
    OrderedJson row = OrderedJson::array();
    for (int j = 0; j < 4; ++j) row.push_back(m(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

Response to_quadratic(const Args& a) {
  return {OrderedJson{{"curve", to_json(io::to_quadratic(a.curve("curve"), a.number("tolerance")))}}};
}

constexpr Field to_quadratic_fields[] = {
    {"curve", FieldType::curve, true},
    {"tolerance", FieldType::number, true, {}, "> 0: the largest distance allowed between the curve and the quadratics (Hausdorff)"},
};

Response basis(const Args& a) {
  const std::optional<int> degree = a.has("degree") ? std::optional<int>(a.integer("degree")) : std::nullopt;
  const std::optional<double> tension = a.has("tension") ? std::optional<double>(a.number("tension")) : std::nullopt;
  const int k = a.integer("derivatives");
  // Written field by field, not by a Describe entry: which fields appear depends on the
  // request (derivatives only when asked, the matrices only for the cubic forms, with a
  // null constraint where it is singular).
  const BasisTable table =
      io::basis(a.string("kind"), degree, a.optional_numbers("knots"), a.optional_numbers("params"), tension, a.numbers("t"), k);
  OrderedJson r;
  r["values"] = table.value[0];
  if (k > 0) {
    OrderedJson d = OrderedJson::array();
    for (std::size_t j = 1; j < table.value.size(); ++j) d.push_back(table.value[j]);
    r["derivatives"] = std::move(d);
  }
  if (table.matrix) {
    r["matrix"] = matrix_json(*table.matrix);
    r["constraint"] = table.constraint ? matrix_json(*table.constraint) : OrderedJson(nullptr);
    r["basis_matrix"] = matrix_json(*table.matrix);
  }
  return {r};
}

constexpr Field basis_fields[] = {
    {"kind", FieldType::string, true, {}, "bernstein, bspline, lagrange, hermite, catmull_rom, cardinal or uniform_bspline"},
    {"degree", FieldType::integer, false, {}, "bernstein (>= 0) and bspline (>= 0) only"},
    {"knots", FieldType::numbers, false, {}, "bspline only: non-decreasing, len = functions + degree + 1, as a bspline curve's"},
    {"params", FieldType::numbers, false, {}, "lagrange only: distinct nodes (one function per node)"},
    {"tension", FieldType::number, false, {}, "cardinal only: s in [0, 1] (tangents (1 - s) times Catmull-Rom's)"},
    {"t", FieldType::numbers, true, {}, "the parameters (any finite numbers: outside the domain the end pieces continue)"},
    {"derivatives", FieldType::integer, false, "0", "k >= 0: also the derivatives of orders 1..k"},
};

Response frames(const Args& a) {
  std::optional<std::span<const double>> initial;
  if (a.has("initial_normal")) initial = std::span<const double>(a.numbers("initial_normal"));
  return {to_json(io::moving_frames(a.curve("curve"), a.numbers("t"), a.string("method"), initial))};
}

constexpr std::string_view frame_methods[] = {"rotation_minimizing", "frenet"};

constexpr Field frames_fields[] = {
    {"curve", FieldType::curve, true, {}, "a 3-D curve"},
    {"t", FieldType::numbers, true, {}, "increasing parameters"},
    {"method", FieldType::string, false, "\"rotation_minimizing\"",
     "rotation_minimizing (double reflection) or frenet (normals and binormals null where undefined)", frame_methods},
    {"initial_normal", FieldType::vector, false, {},
     "rotation_minimizing: the normal at t[0] (projected onto the normal plane, normalised); default the Frenet normal"},
};

Response offset(const Args& a) {
  // A field of another choice is an error (the contract's rule for curve objects).
  if (a.has("miter_limit") && a.string("join") != "miter") {
    throw InvalidArgument("miter_limit", "belongs to join 'miter', not " +
                                             (a.has("join") ? "'" + std::string(a.string("join")) + "'" : std::string("the default 'round'")));
  }
  return {OrderedJson{{"curve", to_json(io::offset(a.curve("curve"), a.number("distance"), a.number("tolerance"), a.boolean("trim"),
                                                   a.string("join"), a.number("miter_limit")))}}};
}

constexpr std::string_view offset_joins[] = {"round", "miter", "bevel"};

constexpr Field offset_fields[] = {
    {"curve", FieldType::curve, true, {}, "a 2-D curve"},
    {"distance", FieldType::number, true, {}, "d: the signed distance, positive to the left of the direction of travel"},
    {"tolerance", FieldType::number, true, {}, "> 0: the largest distance between the cubics and the exact offset (both ways)"},
    {"trim", FieldType::boolean, false, "true", "cut away the loops where |d| exceeds the radius of curvature, and at inner corners"},
    {"join", FieldType::string, false, "\"round\"", "at the outer side of the input's corners: round, miter or bevel", offset_joins},
    {"miter_limit", FieldType::number, false, "4", ">= 1: a miter longer than this times |d| becomes a bevel (as SVG's)"},
};

// ---------------------------------------------------------------------------------------

constexpr Command ops_family[] = {
    {"solve", "Parameters where a coordinate (or a . C(t)) takes a value",
     "Every parameter of the domain where coordinate `axis` of the curve, or the dot\n"
     "product a . C(t) with `direction` a, equals `value`: the roots of the exact Bernstein\n"
     "form of each piece (rational pieces: of its numerator), found with their\n"
     "multiplicities so that a tangency (the curve touching the level without crossing\n"
     "it) is not lost. A piece on which it holds throughout (zero within its rounding\n"
     "error) gives an interval; intervals merge across pieces. Roots within 1e-10 of the\n"
     "domain's length of each other (a root at a break, seen from both pieces) are one.",
     "t: the isolated parameters, ascending, each once; intervals: [[t0, t1], ...] where\n"
     "          it holds on a whole interval ([] when none; no parameter of t lies in one)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[2,0]]}, "axis": 1, "value": 0.5}' | casteljau solve
  {"t":[0.1464466094067262,0.8535533905932737],"intervals":[]})",
     solve_fields, solve},
    {"refine", "Insert many knots at once into a bspline or nurbs curve",
     "Knot refinement (The NURBS Book, A5.4): every knot of `knots` inserted in one pass,\n"
     "the curve unchanged (a nurbs on its homogeneous form).",
     "curve (the input's type, with the knots inserted)",
     R"(  echo '{"curve": {"type": "bspline", "degree": 2, "knots": [0,0,0,1,1,1], "points": [[0,0],[1,2],[2,0]]}, "knots": [0.5, 0.5]}' | casteljau refine
  {"curve":{"type":"bspline","degree":2,"knots":[0.0,0.0,0.0,0.5,0.5,1.0,1.0,1.0],"points":[[0.0,0.0],[0.5,1.0],[1.0,1.0],[1.5,1.0],[2.0,0.0]]}})",
     refine_fields, refine},
    {"to_bspline", "Any curve as one bspline (nurbs when a piece is rational)",
     "The curve as one B-spline with the same parameter: its exact Bezier pieces elevated\n"
     "to the highest degree p, joined, and each joint's knot removed as often as the\n"
     "(homogeneous) curve's continuity there allows: multiplicity p - k where it is C^k,\n"
     "none where the two pieces are one polynomial, p + 1 where it jumps (a gap). Continuity is\n"
     "decided to rounding, so the result traces the curve exactly: end points meet when\n"
     "within 64 eps of their magnitudes, and a knot removal is made when its guaranteed\n"
     "bound is within 64 eps of the rounding the control points' magnitudes carry through\n"
     "the removal; a larger defect (a control point 1e-12 off its C^2 position) keeps\n"
     "its copy of the knot.",
     "curve (bspline, or nurbs when a piece is rational)",
     R"(  echo '{"curve": {"type": "path", "segments": [{"type": "bezier", "points": [[-1,-1],[1,1]]}, {"type": "bezier", "points": [[1,1],[2,2],[3,0]]}]}}' | casteljau to_bspline
  {"curve":{"type":"bspline","degree":2,"knots":[0.0,0.0,0.0,1.0,2.0,2.0,2.0],"points":[[-1.0,-1.0],[0.0,0.0],[2.0,2.0],[3.0,0.0]]}})",
     to_bspline_fields, to_bspline},
    {"reduce", "Degree reduction of a bezier, bspline or nurbs within a tolerance",
     "The curve with its degree lowered by `times` r: a bezier by least squares with its end\n"
     "points kept; a bspline or nurbs as the best of several candidates on its own breaks\n"
     "(each break's multiplicity lowered by r, at least 1; ends kept): a least-squares fit\n"
     "refined towards min-max by Lawson's steps (for a nurbs a polynomial and a homogeneous\n"
     "one) and r steps of The NURBS Book's A5.11, the one of least error kept, whatever the\n"
     "tolerance; a degree-0 result is the curve's mean over its domain. max_error is the\n"
     "largest distance between the two curves at equal parameters, measured (dense sampling\n"
     "and a local maximisation, to about 1e-9 relative); a result farther than the\n"
     "tolerance is refused with that figure.",
     "curve (the input's type, degree p - r), max_error",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}, "tolerance": 0.5}' | casteljau reduce
  {"curve":{"type":"bezier","points":[[0.0,0.0],[2.0000000000000004,3.0],[4.0,0.0]]},"max_error":0.09622504486493799})",
     reduce_fields, reduce},
    {"to_quadratic", "Any curve as a path of quadratic beziers within a tolerance",
     "The curve as a chain of quadratic Bezier segments, each piece on its own: degree <= 2\n"
     "exactly, other pieces cut at their cusps and covered greedily by the longest segments\n"
     "that start and end on the curve with its tangent directions (the middle control point\n"
     "where the two tangent lines meet; two quadratics joined smoothly where the lines of a\n"
     "space curve are skew). Joints are tangent-continuous wherever the curve is (input\n"
     "joints within 1e-6 rad get one shared direction); corners stay corners. Each segment's\n"
     "distance to the part it replaces is bounded within the tolerance: for a cubic part\n"
     "first by the Bernstein coefficients of c(s) - q(sigma(s)), sigma a cubic change of\n"
     "parameter matching the end speeds; else by 5, 9, 17 or 33 samples, coarse to fine,\n"
     "with their nearest points on the quadratic, plus a second-derivative margin between\n"
     "samples.",
     "curve: a path of quadratic bezier segments (3 points each), breaks at the curve's\n"
     "          parameters of the joints",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}, "tolerance": 0.1}' | casteljau to_quadratic
  {"curve":{"type":"path","segments":[{"type":"bezier","points":[[0.0,0.0],[0.75,1.5],[2.0,1.5]]},{"type":"bezier","points":[[2.0,1.5],[3.25,1.5],[4.0,0.0]]}],"breaks":[0.0,0.5,1.0]}})",
     to_quadratic_fields, to_quadratic},
    {"basis", "Values and derivatives of the basis functions of a kind",
     "The basis functions of `kind` at each t: bernstein B(i, n) (degree n), bspline N(i, p)\n"
     "on `knots` (The NURBS Book A2.3; outside the domain the end spans continue), lagrange\n"
     "l_j of `params` (barycentric form), and the cubic kinds hermite (h00, h01, h10, h11 for\n"
     "[p0, p1, m0, m1]), catmull_rom and cardinal ([P(i-1), P(i), P(i+1), P(i+2)]; cardinal\n"
     "with tangents (1 - tension) times Catmull-Rom's) and uniform_bspline (four de Boor\n"
     "points) as [1 t t^2 t^3] M. The cubic kinds and bernstein of degree 3 also give M, its\n"
     "inverse C and basis_matrix = M, exact rationals rounded once (cardinal: closed forms\n"
     "in the tension s, C's factor 1 / (1 - s) divided out by hand; C null at s = 1 only).",
     "values: one row per t, one value per basis function; derivatives (k > 0): k tables\n"
     "          of the same shape, orders 1..k; matrix, constraint, basis_matrix (cubic kinds)",
     R"(  echo '{"kind": "bernstein", "degree": 2, "t": [0.5]}' | casteljau basis
  {"values":[[0.25,0.5,0.25]]})",
     basis_fields, basis, "", ""},
    {"frames", "Tangents, normals and binormals of a 3-D curve at increasing t",
     "Unit frames of a space curve at increasing parameters, binormal = tangent x normal.\n"
     "rotation_minimizing (default): the double reflection method (Wang, Juttler, Zheng and\n"
     "Liu 2008) on an internal grid, each piece's steps halved until the frame carried\n"
     "across it changes by less than 1e-10 rad (so a frame does not depend on the other t\n"
     "asked), from the Frenet normal at t[0], or from initial_normal projected onto the\n"
     "plane normal to the tangent there and normalised. frenet: the Frenet frames, normals and binormals null where the\n"
     "curvature is zero.",
     "tangents, normals, binormals: one unit vector (or null: frenet) per t",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0,0],[1,0,0],[1,1,0],[1,1,1]]}, "t": [0, 1], "method": "frenet"}' | casteljau frames
  {"tangents":[[1.0,0.0,0.0],[0.0,0.0,1.0]],"normals":[[0.0,1.0,0.0],[0.0,-1.0,0.0]],"binormals":[[0.0,0.0,1.0],[1.0,0.0,-0.0]]})",
     frames_fields, frames},
    {"offset", "The offset of a 2-D curve as cubic Bezier segments within a tolerance",
     "The curve moved by `distance` d along its unit normal (positive: to the left of the\n"
     "direction of travel), C(t) + d N(t), as a path of cubic bezier segments within\n"
     "`tolerance` of it, measured both ways (each cubic against its stretch of the exact\n"
     "offset along the curve's normal lines, or by projected samples where those miss the\n"
     "cubic). The curve's exact pieces are cut at their cusps and\n"
     "where the offset has cusps (1 - d kappa = 0, kappa > 0 turning left); each stretch gets the longest cubics\n"
     "the tolerance allows. Corners of the input get `join` on their outer side (round:\n"
     "an arc of radius |d|; miter, a bevel beyond miter_limit; bevel); the inner side a\n"
     "line. With `trim`, only the points of the raw offset at least |d| from the curve are\n"
     "kept (cut at its self-intersections, cusps and joins): swallowtails, inner corners and\n"
     "the offsets of parts nearer than 2 |d| to each other go.",
     "curve: a path of cubic bezier segments, each starting where the previous ends, except\n"
     "where the trim leaves parts that do not meet (a gap starts a new part)",
     R"(  echo '{"curve": {"type": "bezier", "points": [[0,0],[2,0]]}, "distance": 1, "tolerance": 0.001}' | casteljau offset
  {"curve":{"type":"path","segments":[{"type":"bezier","points":[[0.0,1.0],[0.6666666666666666,1.0],[1.3333333333333335,1.0],[2.0,1.0]]}],"breaks":[0.0,1.0]}})",
     offset_fields, offset},
};

}  // namespace

std::span<const Command> ops_commands() { return ops_family; }

}  // namespace casteljau::io::detail
