// The surface commands (issue 19): `surface` (the constructions: extrude, ruled, revolve,
// loft, coons, interpolate, fit), `isocurve`, and the surface forms of eval, split,
// elevate, insert_knot and to_bezier (io::surface_form: a request holding `surface`
// instead of `curve`). Everything here works on the run-time form of io/surfaces.hpp,
// compiled once for every surface type and dimension.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "casteljau/curves/parametrization.hpp"
#include "casteljau/io/surfaces.hpp"
#include "casteljau/surfaces/surface_batch.hpp"
#include "casteljau/surfaces/surface_intersect.hpp"
#include "casteljau/surfaces/surface_project.hpp"
#include "casteljau/surfaces/surface_queries.hpp"
#include "commands_family.hpp"
#include "text.hpp"
#include "work_limits.hpp"

namespace casteljau::io::detail {

namespace {

using casteljau::detail::CurveForm;
using casteljau::detail::SurfaceForm;
using casteljau::detail::format_number;

constexpr int max_derivative_order = 64;
/// The most (u, v) pairs or grid points a request may hold: a response of 10^7 points is
/// already hundreds of megabytes.
constexpr std::size_t max_points = 10'000'000;
/// Dense interpolation and fitting solve systems of order rows and columns: O(n^3).
constexpr std::size_t max_dense_order = 2000;

constexpr std::string_view directions[] = {"u", "v"};

Direction direction(const Args& a) { return a.string("direction") == "u" ? Direction::u : Direction::v; }

std::string vec_text(const double* x, std::size_t n) {
  std::string s = "(";
  for (std::size_t i = 0; i < n; ++i) s += (i ? ", " : "") + number_text(x[i]);
  return s + ")";
}

// ---------------------------------------------------------------------------------------
// eval

/// "uv": an array of [u, v] pairs of finite numbers.
std::vector<std::array<double, 2>> read_uv(const Json& j) {
  if (!j.is_array()) throw InvalidArgument("uv", "must be an array of [u, v] pairs, got " + std::string(kind_of(j)));
  if (j.size() > max_points) throw InvalidArgument("uv", "at most " + std::to_string(max_points) + " pairs, got " + std::to_string(j.size()));
  std::vector<std::array<double, 2>> uv(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = index_path("uv", i);
    if (!j[i].is_array() || j[i].size() != 2) {
      throw InvalidArgument(where, "must be [u, v], two numbers, got " +
                                       (j[i].is_array() ? std::to_string(j[i].size()) + " values" : std::string(kind_of(j[i]))));
    }
    uv[i] = {number_from_json(j[i][0], index_path(where, 0), "parameter"), number_from_json(j[i][1], index_path(where, 1), "parameter")};
  }
  return uv;
}

/// The name of the partial derivative of orders (a, b): "u" a times, then "v" b times.
std::string partial_name(int a, int b) { return std::string(static_cast<std::size_t>(a), 'u') + std::string(static_cast<std::size_t>(b), 'v'); }

void require_3d(const AnySurface& s, const char* field, const char* what) {
  if (s.dim() != 3) throw InvalidArgument(field, std::string(what) + " need a 3-D surface, got " + std::to_string(s.dim()) + "-D");
}

Response eval(const Args& a) {
  const AnySurface& s = a.surface("surface");
  const auto uv = read_uv(a.json("uv"));
  const int k = a.integer("derivatives");
  if (k < 0) throw InvalidArgument("derivatives", "derivative count must be >= 0, got " + std::to_string(k));
  if (k > max_derivative_order) {
    throw InvalidArgument("derivatives", "derivative count must be <= " + std::to_string(max_derivative_order) + ", got " + std::to_string(k));
  }
  const bool normal = a.boolean("normal"), curvature = a.boolean("curvature");
  if (normal) require_3d(s, "normal", "normals");
  if (curvature) require_3d(s, "curvature", "curvatures");
  const int order = std::max(k, curvature ? 2 : normal ? 1 : 0);
  const std::size_t K = static_cast<std::size_t>(order) + 1, cd = s.form.cartesian();
  OrderedJson points = OrderedJson::array(), normals = OrderedJson::array(), gauss = OrderedJson::array(),
              mean = OrderedJson::array(), principal = OrderedJson::array();
  std::vector<OrderedJson> partials;
  for (int o = 1; o <= k; ++o)
    for (int b = 0; b <= o; ++b) partials.push_back(OrderedJson::array());
  if (order == 0) {
    // Points only: the batch evaluators (the same values as partials, without its
    // per-point allocations); on a grid (u outer: the pairs are every u of the first
    // column with every v of the first row) each row's and column's basis once.
    std::vector<double> x(uv.size() * cd);
    std::size_t nv = 1;
    while (nv < uv.size() && uv[nv][0] == uv[0][0]) ++nv;
    bool grid = uv.size() >= 4 && nv >= 2 && uv.size() % nv == 0 && uv.size() / nv >= 2;
    for (std::size_t i = 0; grid && i < uv.size(); ++i) grid = uv[i][0] == uv[i - i % nv][0] && uv[i][1] == uv[i % nv][1];
    if (grid) {
      std::vector<double> us(uv.size() / nv), vs(nv);
      for (std::size_t i = 0; i < us.size(); ++i) us[i] = uv[i * nv][0];
      for (std::size_t j = 0; j < nv; ++j) vs[j] = uv[j][1];
      casteljau::detail::evaluate_grid<double>(s.form, us, vs, x.data(), true);
    } else {
      casteljau::detail::evaluate_points<double>(s.form, uv, x.data());
    }
    for (std::size_t i = 0; i < uv.size(); ++i) points.push_back(std::vector<double>(x.data() + i * cd, x.data() + (i + 1) * cd));
    return {OrderedJson{{"points", std::move(points)}}};
  }
  for (std::size_t i = 0; i < uv.size(); ++i) {
    const auto [u, v] = uv[i];
    std::vector<double> d;
    try {
      d = casteljau::detail::partials(s.form, u, v, order);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(index_path("uv", i), e.problem());
    }
    const auto at = [&](int i, int j) { return d.data() + (static_cast<std::size_t>(i) * K + static_cast<std::size_t>(j)) * cd; };
    points.push_back(std::vector<double>(at(0, 0), at(0, 0) + cd));
    std::size_t slot = 0;
    for (int o = 1; o <= k; ++o)
      for (int b = 0; b <= o; ++b) partials[slot++].push_back(std::vector<double>(at(o - b, b), at(o - b, b) + cd));
    if (normal || curvature) {
      const auto g = order >= 2 ? casteljau::detail::geometry<double>(at(1, 0), at(0, 1), at(2, 0), at(1, 1), at(0, 2))
                                : casteljau::detail::geometry<double>(at(1, 0), at(0, 1), at(0, 0), at(0, 0), at(0, 0));
      if (normal) normals.push_back(g.defined ? OrderedJson(std::vector<double>(g.normal, g.normal + 3)) : OrderedJson(nullptr));
      if (curvature) {
        gauss.push_back(g.defined ? OrderedJson(g.gaussian) : OrderedJson(nullptr));
        mean.push_back(g.defined ? OrderedJson(g.mean) : OrderedJson(nullptr));
        principal.push_back(g.defined ? OrderedJson({g.k1, g.k2}) : OrderedJson(nullptr));
      }
    }
  }
  Response r;
  r.json = OrderedJson{{"points", std::move(points)}};
  if (k > 0) {
    OrderedJson p = OrderedJson::object();
    std::size_t slot = 0;
    for (int o = 1; o <= k; ++o)
      for (int b = 0; b <= o; ++b) p[partial_name(o - b, b)] = std::move(partials[slot++]);
    r.json["partials"] = std::move(p);
  }
  if (normal) r.json["normals"] = std::move(normals);
  if (curvature) {
    r.json["gaussian"] = std::move(gauss);
    r.json["mean"] = std::move(mean);
    r.json["principal"] = std::move(principal);
  }
  return r;
}

constexpr Field eval_fields[] = {
    {"surface", FieldType::surface, true},
    {"uv", FieldType::json, true, {}, "[[u, v], ...]: parameters (outside the domain the end patches extrapolate)"},
    {"derivatives", FieldType::integer, false, "0", "k >= 0 (at most 64): the partial derivatives of total order 1..k"},
    {"normal", FieldType::boolean, false, "false", "also the unit normal (3-D; null where S_u x S_v vanishes)"},
    {"curvature", FieldType::boolean, false, "false", "also Gaussian, mean and principal curvatures (3-D)"},
};

// ---------------------------------------------------------------------------------------
// split, elevate, insert_knot, to_bezier, isocurve

Response split(const Args& a) {
  const AnySurface& s = a.surface("surface");
  auto [first, second] = casteljau::detail::split(s.form, direction(a), a.number("t"));
  return {OrderedJson{{"surfaces", OrderedJson::array({to_json(make_surface(s.kind, std::move(first))),
                                                       to_json(make_surface(s.kind, std::move(second)))})}}};
}

constexpr Field split_fields[] = {
    {"surface", FieldType::surface, true},
    {"direction", FieldType::string, true, {}, "the parameter to split", directions},
    {"t", FieldType::number, true, {}, "strictly inside that direction's domain", {}, "split parameter"},
};

Response elevate(const Args& a) {
  const AnySurface& s = a.surface("surface");
  const Direction dir = direction(a);
  const int times = a.integer("times");
  const int degree = dir == Direction::u ? s.form.p : s.form.q;
  if (times < 1 || times > max_degree - degree) {
    throw InvalidArgument("times", "must be 1.." + std::to_string(max_degree - degree) + " (the degree grows to at most " +
                                       std::to_string(max_degree) + "), got " + std::to_string(times));
  }
  return {OrderedJson{{"surface", to_json(make_surface(s.kind, casteljau::detail::elevate(s.form, dir, times)))}}};
}

constexpr Field elevate_fields[] = {
    {"surface", FieldType::surface, true},
    {"direction", FieldType::string, true, {}, "the degree to raise", directions},
    {"times", FieldType::integer, true, {}, "r >= 1: that degree grows by r (to at most 1000)"},
};

Response insert_knot(const Args& a) {
  const AnySurface& s = a.surface("surface");
  if (s.is_bezier()) {
    throw InvalidArgument("surface", "insert_knot needs a bspline_surface or nurbs_surface, got " + std::string(type_name(s.kind)));
  }
  const int times = a.integer("times");
  if (times < 1) throw InvalidArgument("times", "count must be >= 1, got " + std::to_string(times));
  return {OrderedJson{{"surface", to_json(make_surface(s.kind, casteljau::detail::insert_knot(s.form, direction(a), a.number("knot"), times)))}}};
}

constexpr Field insert_knot_fields[] = {
    {"surface", FieldType::surface, true, {}, "a bspline_surface or nurbs_surface"},
    {"direction", FieldType::string, true, {}, "the knot vector to insert into", directions},
    {"knot", FieldType::number, true, {}, "in that direction's domain"},
    {"times", FieldType::integer, false, "1", ">= 1; the multiplicity afterwards is at most the degree + 1"},
};

Response to_bezier(const Args& a) {
  const AnySurface& s = a.surface("surface");
  const auto sp = casteljau::detail::patches(s.form);
  const SurfaceKind patch_kind = s.form.rational ? SurfaceKind::rational_bezier : SurfaceKind::bezier;
  OrderedJson rows = OrderedJson::array();
  for (const auto& row : sp.patches) {
    OrderedJson out = OrderedJson::array();
    for (const auto& p : row) out.push_back(to_json(make_surface(patch_kind, p)));
    rows.push_back(std::move(out));
  }
  return {OrderedJson{{"patches", std::move(rows)}, {"breaks", OrderedJson::array({sp.ubreaks, sp.vbreaks})}}};
}

constexpr Field to_bezier_fields[] = {
    {"surface", FieldType::surface, true},
};

Response isocurve(const Args& a) {
  const AnySurface& s = a.surface("surface");
  const double value = a.number("value");
  return {OrderedJson{{"curve", curve_form_json(casteljau::detail::isocurve(s.form, direction(a), value), s.is_bezier())}}};
}

constexpr Field isocurve_fields[] = {
    {"surface", FieldType::surface, true},
    {"direction", FieldType::string, true, {}, "u: the curve v -> S(value, v); v: the curve u -> S(u, value)", directions},
    {"value", FieldType::number, true, {}, "the fixed parameter (outside the domain: the end patches extrapolated)", {}, "parameter"},
};

// ---------------------------------------------------------------------------------------
// bounds, area

/// bounds' tolerance: each side within 1e-9 x the diagonal of the true box (cli.md); the
/// branch and bound works to a tenth of it, against the diagonal of the points it found
/// (no larger than the true one).
constexpr double bounds_rel = 1e-10;
/// area's target: 1e-10 relative (cli.md), the adaptive quadrature asked for a tenth.
constexpr double area_rel = 1e-11;

Response bounds(const Args& a) {
  const auto box = casteljau::detail::bounds(a.surface("surface").form, bounds_rel);
  return {OrderedJson{{"min", box.lo}, {"max", box.hi}}};
}

Response area(const Args& a) {
  const AnySurface& s = a.surface("surface");
  if (s.dim() < 2) throw InvalidArgument("surface", "area needs a surface of dimension 2 or more, got 1-D");
  return {OrderedJson{{"area", casteljau::detail::area(s.form, area_rel)}}};
}

constexpr Field surface_only_fields[] = {
    {"surface", FieldType::surface, true},
};

// ---------------------------------------------------------------------------------------
// project, intersect

/// The work of the branch and bound on a surface, refused past the limit before any: the
/// Bézier patches (at most (rows - p) (cols - q)) times the cost of one patch's squared
/// distance in Bernstein form ((p + 1)^2 (q + 1)^2 products per coordinate).
constexpr double max_surface_query_work = 1e8;

void check_surface_work(const SurfaceForm<double>& f, const char* field, const char* what) {
  const double pieces = static_cast<double>(f.rows - static_cast<std::size_t>(f.p)) * static_cast<double>(f.cols - static_cast<std::size_t>(f.q));
  const double a = f.p + 1.0, b = f.q + 1.0;
  const double work = pieces * a * a * b * b * static_cast<double>(f.cartesian() + 1);
  if (work > max_surface_query_work) {
    throw InvalidArgument(field, std::string(what) + " would take about " + limits::amount_text(work) + " units of work (" +
                                     limits::amount_text(pieces) + " Bézier patches, (p + 1)^2 (q + 1)^2 per coordinate), more than the limit of " +
                                     limits::amount_text(max_surface_query_work) + ": use fewer control points or lower degrees");
  }
}

Response project(const Args& a) {
  const AnySurface& s = a.surface("surface");
  const std::vector<double>& q = a.numbers("point");
  if (q.size() != s.form.cartesian()) {
    throw InvalidArgument("point", "needs " + std::to_string(s.form.cartesian()) + " coordinates (the surface's dimension), got " +
                                       std::to_string(q.size()));
  }
  check_surface_work(s.form, "surface", "the projection");
  // The squared distance in Bernstein form has degrees 2p, 2q: binomials past C(512, 256)
  // (about 5e152) would overflow in the products.
  if (std::max(s.form.p, s.form.q) > 256) {
    throw InvalidArgument("surface", "project needs degrees <= 256, got [" + std::to_string(s.form.p) + ", " + std::to_string(s.form.q) + "]");
  }
  // The halvings allowed: about 1e9 operations, each halving costing (2p + 1) (2q + 1)
  // (2 max(p, q) + 1) x 2; at most 200000 (a bicubic patch: about 0.2 s).
  const double per = (2.0 * s.form.p + 1) * (2.0 * s.form.q + 1) * (2.0 * std::max(s.form.p, s.form.q) + 1) * 2;
  const auto max_splits = static_cast<std::size_t>(std::clamp(1e9 / per, 1000.0, 200000.0));
  const auto r = casteljau::detail::project_surface<double>(s.form, std::span<const double>(q), max_splits);
  Response out;
  out.json = OrderedJson{{"uv", {r.u, r.v}}, {"point", r.point}, {"distance", r.distance}};
  if (!r.all_uv.empty()) {
    OrderedJson all = OrderedJson::array();
    for (const auto& x : r.all_uv) all.push_back({x[0], x[1]});
    out.json["all_uv"] = std::move(all);
  }
  return out;
}

constexpr Field project_fields[] = {
    {"surface", FieldType::surface, true},
    {"point", FieldType::point, true, {}, "the surface's dimension"},
};

SurfaceForm<double> column(const CurveForm<double>& c);

Response intersect(const Args& a) {
  const AnySurface& s = a.surface("surface");
  require_3d(s, "surface", "curve-surface intersections");
  const AnyCurve& curve = a.curve("curve");
  if (dimension(curve) != 3) {
    throw InvalidArgument("curve", "curve-surface intersections need a 3-D curve, got " + std::to_string(dimension(curve)) + "-D");
  }
  limits::check_curve_work(curve, "curve", "the intersection");
  check_surface_work(s.form, "surface", "the intersection");
  const CurveForm<double> c = curve_form(curve);
  const auto r = casteljau::detail::intersect_curve_surface<double>(s.form, column(c));
  OrderedJson hits = OrderedJson::array(), overlaps = OrderedJson::array();
  for (const auto& h : r.hits) {
    hits.push_back(OrderedJson{{"t", h.t}, {"uv", {h.u, h.v}}, {"point", {h.point[0], h.point[1], h.point[2]}}, {"kind", h.tangent ? "tangent" : "crossing"}});
  }
  for (const auto& o : r.overlaps) overlaps.push_back(OrderedJson{{"t", {o[0], o[1]}}});
  return {OrderedJson{{"intersections", std::move(hits)}, {"overlaps", std::move(overlaps)}}};
}

constexpr Field intersect_fields[] = {
    {"surface", FieldType::surface, true, {}, "3-D"},
    {"curve", FieldType::curve, true, {}, "3-D"},
};

// ---------------------------------------------------------------------------------------
// Constructions: curves made compatible

/// A curve as a surface with one column (so that the surface algorithms apply to it).
SurfaceForm<double> column(const CurveForm<double>& c) {
  return SurfaceForm<double>{c.p, 0, c.U, {0.0, 1.0}, c.size(), 1, c.dim, c.rational, c.P};
}
CurveForm<double> of_column(const SurfaceForm<double>& f) { return CurveForm<double>{f.p, f.U, f.dim, f.rational, f.P}; }

/// The sorted knots to add to `have` so that every interior value of `want` has at least
/// its multiplicity there.
std::vector<double> missing_knots(const std::vector<double>& have, const std::vector<double>& want, int p) {
  std::vector<double> X;
  const double a = want[static_cast<std::size_t>(p)], b = want[want.size() - static_cast<std::size_t>(p) - 1];
  for (std::size_t i = 0; i < want.size();) {
    std::size_t j = i;
    while (j < want.size() && want[j] == want[i]) ++j;
    const double x = want[i];
    if (x > a && x < b) {
      const auto h = static_cast<std::size_t>(std::count(have.begin(), have.end(), x));
      for (std::size_t k = h; k < j - i; ++k) X.push_back(x);
    }
    i = j;
  }
  return X;
}

/// A polynomial curve's form as a rational one with every weight 1 (its homogeneous
/// control points: a coordinate 1 appended to each point).
void make_homogeneous(CurveForm<double>& c) {
  std::vector<double> P;
  for (std::size_t i = 0; i < c.P.size(); i += c.dim) {
    P.insert(P.end(), c.P.begin() + static_cast<std::ptrdiff_t>(i), c.P.begin() + static_cast<std::ptrdiff_t>(i + c.dim));
    P.push_back(1.0);
  }
  c.P = std::move(P);
  c.dim += 1;
  c.rational = true;
}

/// The same degree (elevation), the same knots (insertion), the same rationality, the
/// parameters mapped affinely onto the first curve's domain [cli.md: "curves are made
/// compatible exactly"].
void make_compatible(std::vector<CurveForm<double>>& cs) {
  bool rational = false;
  int p = 0;
  for (const auto& c : cs) {
    rational = rational || c.rational;
    p = std::max(p, c.p);
  }
  const CurveForm<double>& first = cs.front();
  const double a0 = first.U[static_cast<std::size_t>(first.p)], b0 = first.U[first.U.size() - static_cast<std::size_t>(first.p) - 1];
  for (auto& c : cs) {
    const std::size_t n = c.U.size() - static_cast<std::size_t>(c.p) - 1;
    const double a = c.U[static_cast<std::size_t>(c.p)], b = c.U[n];
    for (auto& x : c.U) x = x == a ? a0 : x == b ? b0 : a0 + (x - a) * ((b0 - a0) / (b - a));
    if (rational && !c.rational) make_homogeneous(c);
    if (c.p < p) c = of_column(casteljau::detail::elevate(column(c), Direction::u, p - c.p));
  }
  std::vector<double> all;  // every knot with its largest multiplicity
  for (const auto& c : cs) {
    const std::vector<double> X = missing_knots(all.empty() ? std::vector<double>{} : all, c.U, p);
    if (all.empty()) {
      all = c.U;
    } else if (!X.empty()) {
      all.insert(all.end(), X.begin(), X.end());
      std::sort(all.begin(), all.end());
    }
  }
  for (auto& c : cs) {
    const std::vector<double> X = missing_knots(c.U, all, p);
    if (!X.empty()) c = of_column(casteljau::detail::refine(column(c), Direction::u, std::span<const double>(X)));
  }
}

/// The curves of a request as compatible B-spline forms, all of one dimension, clamped.
std::vector<CurveForm<double>> compatible_curves(std::span<const AnyCurve> curves, const char* field) {
  std::vector<CurveForm<double>> cs;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    try {
      cs.push_back(curve_form(curves[i]));
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(index_path(field, i), e.problem());
    }
    if (dimension(curves[i]) != dimension(curves[0])) {
      throw InvalidArgument(index_path(field, i), "is " + std::to_string(dimension(curves[i])) + "-D, " + field + "[0] is " +
                                                      std::to_string(dimension(curves[0])) + "-D (the curves need one dimension)");
    }
  }
  make_compatible(cs);
  // make_compatible raises all to the highest degree: 0 only if every curve is piecewise
  // constant, and a surface's degrees are >= 1 (surfaces.md).
  if (cs[0].p == 0) {
    throw InvalidArgument(field, std::string(curves.size() == 1 ? "the curve has" : "every curve has") +
                                     " degree 0 (piecewise constant): the surface would have degree 0 along u, and a "
                                     "surface's degrees must be >= 1");
  }
  return cs;
}

/// The surface with the given columns (v direction: degree q, knots V), each a compatible
/// curve along u.
SurfaceForm<double> from_columns(const std::vector<CurveForm<double>>& cs, int q, std::vector<double> V) {
  const CurveForm<double>& c = cs.front();
  SurfaceForm<double> f{c.p, q, c.U, std::move(V), c.size(), cs.size(), c.dim, c.rational, std::vector<double>(c.size() * cs.size() * c.dim)};
  for (std::size_t j = 0; j < cs.size(); ++j)
    for (std::size_t i = 0; i < f.rows; ++i) std::copy_n(cs[j].P.data() + i * c.dim, c.dim, f.at(i, j));
  return f;
}

// ---------------------------------------------------------------------------------------
// Products of splines (the exact NURBS forms of ruled and Coons surfaces between rational
// curves: a blend of rational curves has the product of their weight functions for weight)

/// The non-rational form of data: (w x, w) of a rational curve's points as plain
/// coordinates (dim cd + 1), or the curve itself.
CurveForm<double> homogeneous(const CurveForm<double>& c) {
  CurveForm<double> h = c;
  h.rational = false;
  if (!c.rational) return h;
  for (std::size_t i = 0; i < h.P.size(); i += h.dim)
    for (std::size_t k = 0; k + 1 < h.dim; ++k) h.P[i + k] *= h.P[i + h.dim - 1];
  return h;
}

/// Coordinates first..first + count - 1 of a non-rational curve form.
CurveForm<double> coordinates(const CurveForm<double>& c, std::size_t first, std::size_t count) {
  CurveForm<double> r{c.p, c.U, count, false, {}};
  for (std::size_t i = 0; i < c.P.size(); i += c.dim) r.P.insert(r.P.end(), c.P.begin() + static_cast<std::ptrdiff_t>(i + first), c.P.begin() + static_cast<std::ptrdiff_t>(i + first + count));
  return r;
}

/// The product a(t) b(t) of a non-rational spline a (any dimension, degree pa) and a
/// scalar one b (degree pb) on the same domain: both refined to the same breaks, their
/// Bézier pieces multiplied (the Bernstein product: c_k = sum C(pa, i) C(pb, k - i) /
/// C(pa + pb, k) a_i b_(k-i), degree pa + pb), joined C^0 (each interior break pa + pb
/// times). Exact.
CurveForm<double> spline_product(CurveForm<double> a, CurveForm<double> b) {
  // Every break of one inserted (once) into the other: the same Bézier pieces.
  const auto breaks_missing = [](const CurveForm<double>& have, const CurveForm<double>& other) {
    std::vector<double> X;
    const std::size_t p = static_cast<std::size_t>(other.p);
    const double lo = other.U[p], hi = other.U[other.U.size() - p - 1];
    for (std::size_t i = 0; i < other.U.size(); ++i) {
      const double x = other.U[i];
      if (x > lo && x < hi && (i == 0 || other.U[i - 1] != x) && std::find(have.U.begin(), have.U.end(), x) == have.U.end()) X.push_back(x);
    }
    return X;
  };
  const std::vector<double> Xa = breaks_missing(a, b), Xb = breaks_missing(b, a);
  if (!Xa.empty()) a = of_column(casteljau::detail::refine(column(a), Direction::u, std::span<const double>(Xa)));
  if (!Xb.empty()) b = of_column(casteljau::detail::refine(column(b), Direction::u, std::span<const double>(Xb)));
  const auto pa = casteljau::detail::patches(column(a)), pb = casteljau::detail::patches(column(b));
  if (pa.ubreaks != pb.ubreaks) throw std::logic_error("spline_product: the pieces do not match");
  const std::size_t na = static_cast<std::size_t>(a.p), nb = static_cast<std::size_t>(b.p), da = a.dim;
  const std::vector<double> ca = binomial_row<double>(a.p), cb = binomial_row<double>(b.p), cab = binomial_row<double>(a.p + b.p);
  CurveForm<double> r{a.p + b.p, {}, da, false, {}};
  const std::size_t m = na + nb + 1;  // points of a product piece
  for (std::size_t k = 0; k < pa.patches.size(); ++k) {
    const SurfaceForm<double>& x = pa.patches[k][0];
    const SurfaceForm<double>& y = pb.patches[k][0];
    std::vector<double> prod(m * da, 0.0);
    for (std::size_t i = 0; i <= na; ++i)
      for (std::size_t j = 0; j <= nb; ++j) {
        const double f = ca[i] * cb[j] / cab[i + j] * y.at(j, 0)[0];
        for (std::size_t c = 0; c < da; ++c) prod[(i + j) * da + c] += f * x.at(i, 0)[c];
      }
    for (std::size_t i = k == 0 ? 0 : 1; i < m; ++i)
      for (std::size_t c = 0; c < da; ++c) r.P.push_back(prod[i * da + c]);
    const double b0 = pa.ubreaks[k], b1 = pa.ubreaks[k + 1];
    if (k == 0) r.U.insert(r.U.end(), m, b0);
    r.U.insert(r.U.end(), k + 1 == pa.patches.size() ? m : m - 1, b1);
  }
  return r;
}

/// A non-rational surface form (any dimension) times a scalar spline w in direction dir:
/// the surface seen as a curve whose points are its rows (or columns), times w.
SurfaceForm<double> times_along(const SurfaceForm<double>& f, const CurveForm<double>& w, Direction dir) {
  const SurfaceForm<double> g = dir == Direction::u ? f : casteljau::detail::transposed(f);
  const CurveForm<double> c{g.p, g.U, g.cols * g.dim, false, g.P};
  const CurveForm<double> r = spline_product(c, w);
  SurfaceForm<double> h{r.p, g.q, r.U, g.V, r.size(), g.cols, g.dim, false, r.P};
  return dir == Direction::u ? h : casteljau::detail::transposed(h);
}

/// The ruled surface between two compatible rational curves (Cartesian points and
/// weights) in homogeneous form: num (the numerators, non-rational, columns v = v0 and v1,
/// degree 1 in v) and the weight function W(u) (a scalar spline): S = num / W.
/// (1 - v) A/wa + v B/wb = ((1 - v) A wb + v B wa) / (wa wb); with equal weights simply
/// ((1 - v) A + v B) / w.
struct RuledForm {
  SurfaceForm<double> num;
  CurveForm<double> weight;
};

RuledForm ruled_homogeneous(const std::vector<CurveForm<double>>& cs, double v0, double v1) {
  const std::size_t cd = cs[0].dim - 1;
  const CurveForm<double> ha = homogeneous(cs[0]), hb = homogeneous(cs[1]);
  CurveForm<double> A = coordinates(ha, 0, cd), B = coordinates(hb, 0, cd), wa = coordinates(ha, cd, 1), wb = coordinates(hb, cd, 1);
  RuledForm r;
  if (wa.P == wb.P) {
    r.weight = wa;
  } else {
    A = spline_product(A, wb);
    B = spline_product(B, wa);
    r.weight = spline_product(wa, wb);
  }
  r.num = from_columns({A, B}, 1, {v0, v0, v1, v1});
  return r;
}

/// The rational surface num / W from a non-rational numerator and a positive weight surface
/// of the same degrees and knots (Cartesian points and weights).
SurfaceForm<double> rational_of(const SurfaceForm<double>& num, const SurfaceForm<double>& W) {
  SurfaceForm<double> f{num.p, num.q, num.U, num.V, num.rows, num.cols, num.dim + 1, true, {}};
  for (std::size_t i = 0; i < num.rows; ++i)
    for (std::size_t j = 0; j < num.cols; ++j) {
      const double w = W.at(i, j)[0];
      for (std::size_t c = 0; c < num.dim; ++c) f.P.push_back(num.at(i, j)[c] / w);
      f.P.push_back(w);
    }
  return f;
}

AnySurface finish(SurfaceForm<double> f, const char* field) {
  try {
    return make_surface(f.rational ? SurfaceKind::nurbs : SurfaceKind::bspline, std::move(f));
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(field, "the construction gives an invalid surface: " + std::string(e.what()));
  }
}

std::vector<double> vector3(const Json& j, const std::string& where, std::size_t dim) {
  const std::vector<double> x = numbers_from_json(j, where);
  if (x.size() != dim) {
    throw InvalidArgument(where, "needs " + std::to_string(dim) + " coordinates (the curve's dimension), got " + std::to_string(x.size()));
  }
  return x;
}

AnySurface extrude(const Args& a) {
  const AnyCurve& curve = a.curve("curve");
  if (!a.has("vector")) throw InvalidArgument("vector", "required field is missing");
  CurveForm<double> c = compatible_curves(std::span<const AnyCurve>(&curve, 1), "curve").front();
  const std::size_t cd = c.rational ? c.dim - 1 : c.dim;
  const std::vector<double> d = vector3(a.json("vector"), "vector", cd);
  CurveForm<double> top = c;
  for (std::size_t i = 0; i < top.P.size(); i += top.dim)
    for (std::size_t k = 0; k < cd; ++k) top.P[i + k] += d[k];
  return finish(from_columns({c, top}, 1, {0, 0, 1, 1}), "vector");
}

AnySurface ruled(const Args& a) {
  const auto curves = a.curves("curves");
  if (curves.size() != 2) throw InvalidArgument("curves", "ruled needs exactly two curves, got " + std::to_string(curves.size()));
  const auto cs = compatible_curves(curves, "curves");
  if (cs[0].rational) {
    bool same = true;
    for (std::size_t i = cs[0].dim - 1; i < cs[0].P.size(); i += cs[0].dim) same = same && cs[0].P[i] == cs[1].P[i];
    if (!same) {
      // Different weights: the exact NURBS form with the weight function wa(u) wb(u).
      const RuledForm r = ruled_homogeneous(cs, 0, 1);
      const SurfaceForm<double> W = from_columns({r.weight, r.weight}, 1, {0, 0, 1, 1});
      return finish(rational_of(r.num, W), "curves");
    }
  }
  return finish(from_columns(cs, 1, {0, 0, 1, 1}), "curves");
}

AnySurface revolve(const Args& a) {
  const AnyCurve& curve = a.curve("curve");
  if (dimension(curve) != 3) throw InvalidArgument("curve", "revolve needs a 3-D curve, got " + std::to_string(dimension(curve)) + "-D");
  if (!a.has("axis")) throw InvalidArgument("axis", "required field is missing");
  const Json& axis = a.json("axis");
  const Fields af(axis, "axis");
  af.allow_only({"point", "direction"}, "axis");
  std::vector<double> O, d;
  try {
    O = vector3(af.required("point"), "point", 3);
    d = vector3(af.required("direction"), "direction", 3);
  } catch (const InvalidArgument& e) {
    throw e.within("axis");
  }
  const double dl = std::hypot(d[0], d[1], d[2]);
  if (!(dl > 0) || !std::isfinite(dl)) throw InvalidArgument("axis.direction", "must be a non-zero finite vector");
  for (auto& x : d) x /= dl;
  const double two_pi = 2 * std::numbers::pi;
  const double angle = a.has("angle") ? a.number("angle") : two_pi;
  if (!(angle > 0 && angle <= two_pi)) throw InvalidArgument("angle", "must be in (0, 2 pi], got " + number_text(angle));
  CurveForm<double> c = compatible_curves(std::span<const AnyCurve>(&curve, 1), "curve").front();
  if (!c.rational) {
    std::vector<double> P;
    for (std::size_t i = 0; i < c.P.size(); i += 3) {
      P.insert(P.end(), c.P.begin() + static_cast<std::ptrdiff_t>(i), c.P.begin() + static_cast<std::ptrdiff_t>(i + 3));
      P.push_back(1.0);
    }
    c.P = std::move(P);
    c.dim = 4;
    c.rational = true;
  }
  // [PT97] A8.1: arcs of at most 90 degrees, each a rational quadratic: end points on the
  // circle, the middle one where the end tangents meet, weight cos(dtheta / 2).
  const int narcs = angle <= std::numbers::pi / 2 ? 1 : angle <= std::numbers::pi ? 2 : angle <= 1.5 * std::numbers::pi ? 3 : 4;
  const double dtheta = angle / narcs;
  // Angles at multiples of 90 degrees take their exact sines and cosines, so that a full
  // turn closes exactly and quarter arcs have their corners exactly.
  const bool quarters = dtheta == std::numbers::pi / 2;
  const auto cos_sin = [&](int k) -> std::array<double, 2> {
    if (quarters) {
      static constexpr double table[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
      return {table[k % 4][0], table[k % 4][1]};
    }
    return {std::cos(k * dtheta), std::sin(k * dtheta)};
  };
  const double wm = quarters ? std::sqrt(0.5) : std::cos(dtheta / 2);
  const double one_plus_cos = quarters ? 1.0 : 1 + std::cos(dtheta);
  std::vector<double> V{0, 0, 0};
  for (int k = 1; k < narcs; ++k) V.insert(V.end(), 2, k * dtheta);
  V.insert(V.end(), 3, angle);
  const std::size_t cols = static_cast<std::size_t>(2 * narcs + 1);
  SurfaceForm<double> f{c.p, 2, c.U, V, c.size(), cols, 4, true, std::vector<double>(c.size() * cols * 4)};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double* P = c.P.data() + 4 * i;
    const double w = P[3];
    double X[3] = {P[0] - O[0], P[1] - O[1], P[2] - O[2]};
    const double h = X[0] * d[0] + X[1] * d[1] + X[2] * d[2];
    double C[3];  // the foot of the point on the axis
    for (int k = 0; k < 3; ++k) {
      C[k] = O[k] + h * d[k];
      X[k] = P[k] - C[k];
    }
    const double Y[3] = {d[1] * X[2] - d[2] * X[1], d[2] * X[0] - d[0] * X[2], d[0] * X[1] - d[1] * X[0]};
    // The local points e_k = cos X + sin Y (|X| = |Y| = r) and the middle ones
    // (e_k + e_(k+1)) / (1 + cos dtheta) = e_(k+1/2) / cos(dtheta / 2).
    std::vector<std::array<double, 3>> e(static_cast<std::size_t>(narcs) + 1);
    for (int k = 0; k <= narcs; ++k) {
      const auto [co, si] = cos_sin(k);
      for (int m = 0; m < 3; ++m) e[static_cast<std::size_t>(k)][static_cast<std::size_t>(m)] = co * X[m] + si * Y[m];
    }
    if (angle == two_pi) e.back() = e.front();
    for (std::size_t j = 0; j < cols; ++j) {
      double* out = f.at(i, j);
      const std::size_t k = j / 2;
      for (std::size_t m = 0; m < 3; ++m) {
        out[m] = C[m] + (j % 2 == 0 ? e[k][m] : (e[k][m] + e[k + 1][m]) / one_plus_cos);
      }
      // The profile itself, unrounded: at the start, at the end of a full turn, and for a
      // point on the axis.
      const bool on_axis = X[0] == 0 && X[1] == 0 && X[2] == 0;
      if (j == 0 || on_axis || (angle == two_pi && j + 1 == cols)) std::copy_n(P, 3, out);
      out[3] = j % 2 == 0 ? w : w * wm;
    }
  }
  return finish(std::move(f), "curve");
}

/// Parameters of a grid's rows (or columns): for each line across them, the rule's
/// parameters (parameter_sums: equal points give a zero step) normalised; averaged over
/// the lines whose total is positive and finite [PT97, A9.3].
std::vector<double> grid_params(const SurfaceForm<double>& g, Parametrization r) {
  std::vector<double> t(g.rows, 0.0);
  std::size_t used = 0;
  dispatch_dimension(static_cast<int>(g.dim), [&]<int D>() {
    std::vector<Point<double, D>> line(g.rows);
    for (std::size_t j = 0; j < g.cols; ++j) {
      for (std::size_t i = 0; i < g.rows; ++i)
        for (int k = 0; k < D; ++k) line[i][k] = g.at(i, j)[k];
      std::vector<double> s = parameter_sums(line, r);
      if (!(s.back() > 0) || !std::isfinite(s.back())) continue;
      normalize_parameters(s);
      for (std::size_t i = 1; i < g.rows; ++i) t[i] += s[i];
      ++used;
    }
  });
  if (used == 0) throw InvalidArgument("points", "the grid's rows all coincide: no parameters");
  for (auto& x : t) x /= static_cast<double>(used);
  t.back() = 1;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!(t[i] > t[i - 1])) {
      throw InvalidArgument("points", "the averaged parameters of rows " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                          " coincide (the rows are equal): no interpolation through both");
    }
  }
  return t;
}

/// The collocation matrix N(t_k)_i of the basis on knots U, degree p.
Eigen::MatrixXd collocation(const std::vector<double>& U, int p, const std::vector<double>& t, std::size_t n) {
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(t.size()), static_cast<Eigen::Index>(n));
  std::vector<double> b(static_cast<std::size_t>(p) + 1);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const std::size_t s = find_span<double>(U, p, t[k]);
    basis_functions<double>(U, p, s, t[k], b);
    for (std::size_t r = 0; r <= static_cast<std::size_t>(p); ++r)
      N(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(s - static_cast<std::size_t>(p) + r)) = b[r];
  }
  return N;
}

/// Solves N X = B along u for every column of the grid at once (B: rows x (cols * dim)),
/// least squares when N has more rows than columns; the grid of the result has N's
/// column count of rows.
SurfaceForm<double> solve_rows(const SurfaceForm<double>& g, const Eigen::MatrixXd& N, int p, std::vector<double> U,
                               const char* count_field) {
  const auto m = static_cast<Eigen::Index>(g.rows), w = static_cast<Eigen::Index>(g.cols * g.dim);
  Eigen::MatrixXd B(m, w);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index c = 0; c < w; ++c) B(i, c) = g.P[static_cast<std::size_t>(i * w + c)];
  Eigen::MatrixXd X;
  if (N.rows() == N.cols()) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(N);
    X = lu.solve(B);
  } else {
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(N);
    if (qr.rank() < N.cols()) {
      throw InvalidArgument(count_field, "too many control points for the spread of the data: the least-squares system is singular");
    }
    X = qr.solve(B);
  }
  if (!X.allFinite()) throw InvalidArgument(count_field, "the system is singular for these parameters");
  SurfaceForm<double> r{p, g.q, std::move(U), g.V, static_cast<std::size_t>(N.cols()), g.cols, g.dim, false, {}};
  r.P.resize(r.rows * r.cols * r.dim);
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    for (Eigen::Index c = 0; c < w; ++c) r.P[static_cast<std::size_t>(i * w + c)] = X(i, c);
  return r;
}

/// The knots of least squares [PT97, eq. 9.68-9.69] for n control points, degree p, data
/// parameters t (t_0 = 0, t_m = 1).
std::vector<double> fit_knots(const std::vector<double>& t, int p, std::size_t n) {
  const std::size_t m = t.size() - 1, P = static_cast<std::size_t>(p);
  std::vector<double> U(P + 1, 0.0);
  const double d = static_cast<double>(m + 1) / static_cast<double>(n - P);
  for (std::size_t j = 1; j + P < n; ++j) {
    const double jd = static_cast<double>(j) * d;
    const auto i = static_cast<std::size_t>(jd);
    const double alpha = jd - static_cast<double>(i);
    U.push_back((1 - alpha) * t[i - 1] + alpha * t[std::min(i, m)]);
  }
  U.insert(U.end(), P + 1, 1.0);
  return U;
}

/// The grid of a request's `points`: rows of points of one dimension (the surface reader's
/// rules and messages).
SurfaceForm<double> read_point_grid(const Json& j) {
  Json s = Json::object();
  s["type"] = "bezier_surface";
  s["points"] = j;
  // The Bézier reader checks the grid (rows, dimensions, finite numbers); its degree
  // limit does not apply to a grid of data.
  if (j.is_array() && (j.size() > max_dense_order || (!j.empty() && j[0].is_array() && j[0].size() > max_dense_order))) {
    throw InvalidArgument("points", "at most " + std::to_string(max_dense_order) + " rows and columns, got " + std::to_string(j.size()) +
                                        " x " + std::to_string(j[0].is_array() ? j[0].size() : 0));
  }
  return surface_from_json(s).form;
}

std::array<int, 2> read_degrees(const Json& j, std::array<int, 2> limit) {
  if (!j.is_array() || j.size() != 2) throw InvalidArgument("degree", "must be [p, q], two integers, got " + std::string(kind_of(j)));
  std::array<int, 2> d{};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string where = index_path("degree", k);
    d[k] = integer_from_json(j[k], where);
    if (d[k] < 1 || d[k] > limit[k]) {
      throw InvalidArgument(where, "must be 1.." + std::to_string(limit[k]) + " (the " + (k == 0 ? "rows" : "columns") +
                                       " minus one, at most 1000), got " + std::to_string(d[k]));
    }
  }
  return d;
}

SurfaceForm<double> interpolate_grid(const SurfaceForm<double>& g, std::array<int, 2> deg, Parametrization rule,
                                     std::vector<double>& tu, std::vector<double>& tv) {
  tu = grid_params(g, rule);
  tv = grid_params(casteljau::detail::transposed(g), rule);
  std::vector<double> U = KnotVector<double>::averaging(deg[0], tu).knots(), V = KnotVector<double>::averaging(deg[1], tv).knots();
  const SurfaceForm<double> a = solve_rows(g, collocation(U, deg[0], tu, g.rows), deg[0], U, "points");
  const SurfaceForm<double> b = solve_rows(casteljau::detail::transposed(a), collocation(V, deg[1], tv, g.cols), deg[1], V, "points");
  return casteljau::detail::transposed(b);
}

AnySurface interpolate(const Args& a) {
  if (!a.has("points")) throw InvalidArgument("points", "required field is missing");
  const SurfaceForm<double> g = read_point_grid(a.json("points"));
  if (g.rows < 2 || g.cols < 2) throw InvalidArgument("points", "interpolation needs at least 2 rows and 2 columns");
  const std::array<int, 2> limit{static_cast<int>(std::min<std::size_t>(g.rows - 1, 1000)), static_cast<int>(std::min<std::size_t>(g.cols - 1, 1000))};
  const std::array<int, 2> deg = a.has("degree") ? read_degrees(a.json("degree"), limit) : std::array<int, 2>{std::min(3, limit[0]), std::min(3, limit[1])};
  std::vector<double> tu, tv;
  return finish(interpolate_grid(g, deg, *parametrization_named(a.string("parametrization")), tu, tv), "points");
}

Response fit(const Args& a) {
  for (const char* f : {"points", "degree", "control_points"})
    if (!a.has(f)) throw InvalidArgument(f, "required field is missing");
  const SurfaceForm<double> g = read_point_grid(a.json("points"));
  if (g.rows < 2 || g.cols < 2) throw InvalidArgument("points", "fitting needs at least 2 rows and 2 columns");
  const std::array<int, 2> limit{static_cast<int>(std::min<std::size_t>(g.rows - 1, 1000)), static_cast<int>(std::min<std::size_t>(g.cols - 1, 1000))};
  const std::array<int, 2> deg = read_degrees(a.json("degree"), limit);
  const Json& cj = a.json("control_points");
  if (!cj.is_array() || cj.size() != 2) throw InvalidArgument("control_points", "must be [rows, columns], two integers");
  std::array<std::size_t, 2> n{};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string where = index_path("control_points", k);
    const int x = integer_from_json(cj[k], where);
    const std::size_t have = k == 0 ? g.rows : g.cols;
    if (x < deg[k] + 1 || static_cast<std::size_t>(x) > have) {
      throw InvalidArgument(where, "must be " + std::to_string(deg[k] + 1) + ".." + std::to_string(have) + " (the degree + 1 to the " +
                                       (k == 0 ? "rows" : "columns") + " of points), got " + std::to_string(x));
    }
    n[k] = static_cast<std::size_t>(x);
  }
  const Parametrization rule = *parametrization_named(a.string("parametrization"));
  const std::vector<double> tu = grid_params(g, rule), tv = grid_params(casteljau::detail::transposed(g), rule);
  // Least squares of the tensor product on the full grid separates: the solution is
  // (N_u^+ x N_v^+) applied to the data, one direction after the other.
  std::vector<double> U = fit_knots(tu, deg[0], n[0]), V = fit_knots(tv, deg[1], n[1]);
  const SurfaceForm<double> s1 = solve_rows(g, collocation(U, deg[0], tu, n[0]), deg[0], U, "control_points");
  const SurfaceForm<double> s2 =
      solve_rows(casteljau::detail::transposed(s1), collocation(V, deg[1], tv, n[1]), deg[1], V, "control_points");
  AnySurface s = finish(casteljau::detail::transposed(s2), "points");
  double err = 0;
  for (std::size_t i = 0; i < g.rows; ++i)
    for (std::size_t j = 0; j < g.cols; ++j) {
      const std::vector<double> x = casteljau::detail::point(s.form, tu[i], tv[j]);
      double d2 = 0;
      for (std::size_t k = 0; k < g.dim; ++k) d2 += (x[k] - g.at(i, j)[k]) * (x[k] - g.at(i, j)[k]);
      err = std::max(err, std::sqrt(d2));
    }
  return {OrderedJson{{"surface", to_json(s)}, {"max_error", err}}};
}

AnySurface loft(const Args& a) {
  const auto curves = a.curves("curves");
  if (curves.size() < 2) throw InvalidArgument("curves", "loft needs at least two curves, got " + std::to_string(curves.size()));
  if (curves.size() > max_dense_order) throw InvalidArgument("curves", "at most " + std::to_string(max_dense_order) + " curves");
  std::vector<CurveForm<double>> cs = compatible_curves(curves, "curves");
  const std::size_t K = cs.size(), n = cs[0].size(), dim = cs[0].dim, cd = cs[0].rational ? dim - 1 : dim;
  int q = static_cast<int>(std::min<std::size_t>(3, K - 1));
  if (a.has("degree")) {
    q = integer_from_json(a.json("degree"), "degree");
    if (q < 1 || static_cast<std::size_t>(q) > K - 1) {
      throw InvalidArgument("degree", "must be 1.." + std::to_string(K - 1) + " (the number of curves minus one), got " + std::to_string(q));
    }
  }
  std::vector<double> t(K, 0.0);
  if (a.has("params")) {
    t = numbers_from_json(a.json("params"), "params");
    if (t.size() != K) throw InvalidArgument("params", "needs one parameter per curve (" + std::to_string(K) + "), got " + std::to_string(t.size()));
    for (std::size_t k = 1; k < K; ++k)
      if (!(t[k] > t[k - 1])) throw InvalidArgument(index_path("params", k), "params must be strictly increasing");
  } else {
    for (std::size_t k = 1; k < K; ++k) {
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        double d2 = 0;
        for (std::size_t c = 0; c < cd; ++c) {
          const double x = cs[k].P[i * dim + c] - cs[k - 1].P[i * dim + c];
          d2 += x * x;
        }
        sum += std::sqrt(d2);
      }
      const double step = sum / static_cast<double>(n);
      if (!(step > 0)) {
        throw InvalidArgument(index_path("curves", k), "coincides with curves[" + std::to_string(k - 1) + "] (give params to place them)");
      }
      t[k] = t[k - 1] + step;
    }
    const double total = t.back();
    for (auto& x : t) x /= total;
    t.back() = 1;
  }
  // Skinning [PT97, §10.3]: along v, every row of control points interpolated at the
  // curves' parameters (homogeneous coordinates when rational: S(u, v_k) is curve k).
  SurfaceForm<double> g = casteljau::detail::weighted(from_columns(cs, 0, {}), true);
  const std::vector<double> V = KnotVector<double>::averaging(q, t).knots();
  const SurfaceForm<double> tg = casteljau::detail::transposed(g);
  SurfaceForm<double> r = casteljau::detail::transposed(solve_rows(tg, collocation(V, q, t, K), q, V, "curves"));
  r.p = g.p;
  r.U = g.U;
  r.rational = g.rational;
  if (r.rational) {
    for (std::size_t i = dim - 1; i < r.P.size(); i += dim) {
      if (!(r.P[i] > 0)) throw InvalidArgument("curves", "the rational curves loft to weights <= 0 (the surface has no NURBS form of this degree)");
    }
  }
  return finish(casteljau::detail::weighted(std::move(r), false), "curves");
}

/// The Coons patch of rational boundaries (cu: c0, c1 compatible; dv: d0, d1 compatible),
/// exact: Xv / Wv(u) + Xu / Wu(v) - B over the common denominator Wv(u) Wu(v), i.e.
/// (Xv Wu + Xu Wv - B Wv Wu) / (Wv Wu), where Xv / Wv is the ruled surface between c0 and
/// c1 and Xu / Wu the one between d0 and d1; the four parts brought to common degrees
/// and knots (elevation, insertion) before they are added.
AnySurface coons_rational(std::vector<CurveForm<double>> cu, std::vector<CurveForm<double>> dv, const std::vector<CurveForm<double>>& all,
                          std::size_t dim, double u0, double u1, double v0, double v1) {
  const auto as_rational = [](std::vector<CurveForm<double>>& cs) {
    for (auto& c : cs)
      if (!c.rational) make_homogeneous(c);
  };
  as_rational(cu);
  as_rational(dv);
  const RuledForm rv = ruled_homogeneous(cu, v0, v1);  // rows along u, v linear
  const RuledForm ru = ruled_homogeneous(dv, u0, u1);  // rows along v, u linear
  const SurfaceForm<double> Xu = casteljau::detail::transposed(ru.num);
  SurfaceForm<double> N1 = times_along(rv.num, ru.weight, Direction::v);
  SurfaceForm<double> N2 = times_along(Xu, rv.weight, Direction::u);
  SurfaceForm<double> Bl{1, 1, {u0, u0, u1, u1}, {v0, v0, v1, v1}, 2, 2, dim, false, {}};
  const auto first = [&](std::size_t i) { return all[i].P.data(); };
  const auto last = [&](std::size_t i) { return all[i].P.data() + all[i].P.size() - all[i].dim; };
  for (const double* x : {first(0), first(1), last(0), last(1)}) Bl.P.insert(Bl.P.end(), x, x + dim);  // (u0,v0) (u0,v1) (u1,v0) (u1,v1)
  SurfaceForm<double> N3 = times_along(times_along(Bl, rv.weight, Direction::u), ru.weight, Direction::v);
  SurfaceForm<double> D{rv.weight.p, ru.weight.p, rv.weight.U, ru.weight.U, rv.weight.size(), ru.weight.size(), 1, false, {}};
  for (std::size_t i = 0; i < D.rows; ++i)
    for (std::size_t j = 0; j < D.cols; ++j) D.P.push_back(rv.weight.P[i] * ru.weight.P[j]);
  std::vector<SurfaceForm<double>*> parts{&N1, &N2, &N3, &D};
  int P = 0, Q = 0;
  for (const auto* f : parts) {
    P = std::max(P, f->p);
    Q = std::max(Q, f->q);
  }
  std::vector<double> Uall, Vall;
  for (auto* f : parts) {
    if (f->p < P) *f = casteljau::detail::elevate(*f, Direction::u, P - f->p);
    if (f->q < Q) *f = casteljau::detail::elevate(*f, Direction::v, Q - f->q);
    for (auto [K, all_knots, deg] : {std::tuple{&f->U, &Uall, P}, std::tuple{&f->V, &Vall, Q}}) {
      if (all_knots->empty()) {
        *all_knots = *K;
        continue;
      }
      const std::vector<double> X = missing_knots(*all_knots, *K, deg);
      all_knots->insert(all_knots->end(), X.begin(), X.end());
      std::sort(all_knots->begin(), all_knots->end());
    }
  }
  for (auto* f : parts) {
    const std::vector<double> X = missing_knots(f->U, Uall, P), Y = missing_knots(f->V, Vall, Q);
    if (!X.empty()) *f = casteljau::detail::refine(*f, Direction::u, std::span<const double>(X));
    if (!Y.empty()) *f = casteljau::detail::refine(*f, Direction::v, std::span<const double>(Y));
  }
  if (N1.P.size() != N2.P.size() || N1.P.size() != N3.P.size() || N1.rows != D.rows || N1.cols != D.cols) {
    throw std::logic_error("coons: the parts are not compatible");
  }
  for (std::size_t i = 0; i < N1.P.size(); ++i) N1.P[i] += N2.P[i] - N3.P[i];
  return finish(rational_of(N1, D), "curves");
}

AnySurface coons(const Args& a) {
  const auto curves = a.curves("curves");
  if (curves.size() != 4) throw InvalidArgument("curves", "coons needs exactly four curves [c0, c1, d0, d1], got " + std::to_string(curves.size()));
  std::vector<CurveForm<double>> all;
  for (std::size_t i = 0; i < 4; ++i) {
    all.push_back(curve_form(curves[i]));
    if (dimension(curves[i]) != dimension(curves[0])) {
      throw InvalidArgument(index_path("curves", i), "is " + std::to_string(dimension(curves[i])) + "-D, curves[0] is " +
                                                         std::to_string(dimension(curves[0])) + "-D");
    }
  }
  // dim: the Cartesian dimension (a rational curve's points are followed by their weight).
  const std::size_t dim = static_cast<std::size_t>(dimension(curves[0]));
  // The corners: c0 and c1 start on d0 and end on d1 (clamped forms: the end points are
  // the end control points), within 1e-12 of the size of the control points' box.
  double size = 0;
  {
    std::vector<double> lo(dim, INFINITY), hi(dim, -INFINITY);
    for (const auto& c : all)
      for (std::size_t i = 0; i < c.P.size(); i += c.dim)
        for (std::size_t k = 0; k < dim; ++k) {
          lo[k] = std::min(lo[k], c.P[i + k]);
          hi[k] = std::max(hi[k], c.P[i + k]);
        }
    for (std::size_t k = 0; k < dim; ++k) size += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    size = std::sqrt(size);
  }
  const auto first = [&](std::size_t i) { return all[i].P.data(); };
  const auto last = [&](std::size_t i) { return all[i].P.data() + all[i].P.size() - all[i].dim; };
  const struct {
    std::size_t curve;
    const char* which;
    const double* x;
    std::size_t other;
    const char* other_which;
    const double* y;
  } corners[] = {{2, "start", first(2), 0, "start", first(0)},
                 {2, "end", last(2), 1, "start", first(1)},
                 {3, "start", first(3), 0, "end", last(0)},
                 {3, "end", last(3), 1, "end", last(1)}};
  for (const auto& c : corners) {
    double d2 = 0;
    for (std::size_t k = 0; k < dim; ++k) d2 += (c.x[k] - c.y[k]) * (c.x[k] - c.y[k]);
    if (!(std::sqrt(d2) <= 1e-12 * size)) {
      throw InvalidArgument(index_path("curves", c.curve), "the corners do not meet (its " + std::string(c.which) + " " + vec_text(c.x, dim) +
                                                               ", the " + c.other_which + " of curves[" + std::to_string(c.other) + "] " +
                                                               vec_text(c.y, dim) + ")");
    }
  }
  std::vector<CurveForm<double>> cu{all[0], all[1]}, dv{all[2], all[3]};
  make_compatible(cu);
  make_compatible(dv);
  const int p = std::max(cu[0].p, 1), q = std::max(dv[0].p, 1);
  const double u0 = cu[0].U[static_cast<std::size_t>(cu[0].p)], u1 = cu[0].U[cu[0].U.size() - static_cast<std::size_t>(cu[0].p) - 1];
  const double v0 = dv[0].U[static_cast<std::size_t>(dv[0].p)], v1 = dv[0].U[dv[0].U.size() - static_cast<std::size_t>(dv[0].p) - 1];
  if (cu[0].rational || dv[0].rational) return coons_rational(cu, dv, all, dim, u0, u1, v0, v1);
  // Ruled in v (between c0 and c1), ruled in u (between d0 and d1), bilinear corners.
  SurfaceForm<double> A = from_columns(cu, 1, {v0, v0, v1, v1});
  SurfaceForm<double> B = casteljau::detail::transposed(from_columns(dv, 1, {u0, u0, u1, u1}));
  SurfaceForm<double> C{1, 1, {u0, u0, u1, u1}, {v0, v0, v1, v1}, 2, 2, dim, false, {}};
  for (const double* x : {first(0), first(1), last(0), last(1)}) C.P.insert(C.P.end(), x, x + dim);  // (u0,v0) (u0,v1) (u1,v0) (u1,v1)
  // One degree and one knot vector per direction for all three, then A + B - C.
  const std::vector<double> Ut = cu[0].p >= 1 ? cu[0].U : std::vector<double>{u0, u0, u1, u1};
  const std::vector<double> Vt = dv[0].p >= 1 ? dv[0].U : std::vector<double>{v0, v0, v1, v1};
  const auto lift = [&](SurfaceForm<double> f) {
    if (f.p < p) f = casteljau::detail::elevate(f, Direction::u, p - f.p);
    if (f.q < q) f = casteljau::detail::elevate(f, Direction::v, q - f.q);
    const std::vector<double> X = missing_knots(f.U, Ut, p), Y = missing_knots(f.V, Vt, q);
    if (!X.empty()) f = casteljau::detail::refine(f, Direction::u, std::span<const double>(X));
    if (!Y.empty()) f = casteljau::detail::refine(f, Direction::v, std::span<const double>(Y));
    return f;
  };
  A = lift(std::move(A));
  B = lift(std::move(B));
  C = lift(std::move(C));
  if (A.P.size() != B.P.size() || A.P.size() != C.P.size()) throw std::logic_error("coons: the three surfaces are not compatible");
  for (std::size_t i = 0; i < A.P.size(); ++i) A.P[i] += B.P[i] - C.P[i];
  return finish(std::move(A), "curves");
}

constexpr std::string_view constructions[] = {"extrude", "ruled", "revolve", "loft", "coons", "interpolate", "fit"};

/// The fields each construction takes (besides `construct`); any other given is an error.
struct Takes {
  std::string_view construct;
  std::vector<std::string_view> fields;
};

Response surface(const Args& a) {
  const std::string& c = a.string("construct");
  if (std::find(std::begin(constructions), std::end(constructions), c) == std::end(constructions)) {
    throw InvalidArgument("construct", "unknown construction " + io::quoted(c) + " (" + detail::join(constructions) + ")");
  }
  static const Takes takes[] = {
      {"extrude", {"curve", "vector"}},
      {"ruled", {"curves"}},
      {"revolve", {"curve", "axis", "angle"}},
      {"loft", {"curves", "degree", "params"}},
      {"coons", {"curves"}},
      {"interpolate", {"points", "degree", "parametrization"}},
      {"fit", {"points", "degree", "control_points", "parametrization"}},
  };
  for (const auto& t : takes) {
    if (t.construct != c) continue;
    for (const std::string_view f : {"curve", "curves", "vector", "axis", "angle", "degree", "params", "points", "control_points", "parametrization"}) {
      if (a.has(f) && std::find(t.fields.begin(), t.fields.end(), f) == t.fields.end()) {
        throw InvalidArgument(std::string(f), "unknown field for construct " + io::quoted(c) + " (it takes: " + detail::join(t.fields) + ")");
      }
    }
    if ((c == "extrude" || c == "revolve") && !a.has("curve")) throw InvalidArgument("curve", "required field is missing");
    if ((c == "ruled" || c == "loft" || c == "coons") && !a.has("curves")) throw InvalidArgument("curves", "required field is missing");
  }
  if (c == "fit") return fit(a);
  const AnySurface s = c == "extrude"       ? extrude(a)
                       : c == "ruled"       ? ruled(a)
                       : c == "revolve"     ? revolve(a)
                       : c == "loft"        ? loft(a)
                       : c == "coons"       ? coons(a)
                                            : interpolate(a);
  return {OrderedJson{{"surface", to_json(s)}}};
}

constexpr Field surface_fields[] = {
    {"construct", FieldType::string, true, {}, "extrude, ruled, revolve, loft, coons, interpolate or fit"},
    {"curve", FieldType::curve, false, {}, "extrude, revolve (3-D): the curve"},
    {"curves", FieldType::curves, false, {}, "ruled [a, b], loft (>= 2), coons [c0, c1, d0, d1]", {}, {}, 1, 0},
    {"vector", FieldType::json, false, {}, "extrude: the direction and length (the curve's dimension)"},
    {"axis", FieldType::json, false, {}, "revolve: {point, direction}, 3-D"},
    {"angle", FieldType::number, false, {}, "revolve: radians, 0 < angle <= 2 pi (default 2 pi)"},
    {"degree", FieldType::json, false, {}, "loft: the degree in v; interpolate, fit: [p, q]"},
    {"params", FieldType::json, false, {}, "loft: the v of each curve, strictly increasing"},
    {"points", FieldType::json, false, {}, "interpolate, fit: the grid of data points"},
    {"control_points", FieldType::json, false, {}, "fit: [rows, columns]"},
    {"parametrization", FieldType::string, false, "\"chord\"", "interpolate, fit: the parameters of the rows and columns",
     parametrization_names},
};

// ---------------------------------------------------------------------------------------
// The registry entries

constexpr Command surface_family[] = {
    {"surface", "Build a surface from curves or points (extrude, ruled, revolve, loft, coons, interpolate, fit)",
     "Builds a bspline_surface (nurbs_surface when an input is rational; revolve: always) from\n"
     "curves or a grid of points. Curves of any type are made compatible exactly (one degree by\n"
     "elevation, one knot vector by insertion, parameters mapped onto the first curve's domain).\n"
     "extrude: C(u) + v vector; ruled: (1 - v) a(u) + v b(u); revolve: the curve turned about\n"
     "the axis in exact arcs of at most 90 degrees; loft: through the curves at params (skinning);\n"
     "coons: the bilinearly blended patch of four boundaries; interpolate: through every grid\n"
     "point; fit: least squares with control_points [rows, columns]. The surface forms of eval,\n"
     "split, elevate, insert_knot and to_bezier take `surface` instead of `curve`.",
     "surface (fit: also max_error, the largest distance from a grid point to the surface at\n"
     "          its parameters)",
     R"(  echo '{"construct": "extrude", "curve": {"type": "bezier", "points": [[0,0,0],[1,0,0]]}, "vector": [0,0,2]}' | casteljau surface
  {"surface":{"type":"bspline_surface","degree":[1,1],"knots":[[0.0,0.0,1.0,1.0],[0.0,0.0,1.0,1.0]],"points":[[[0.0,0.0,0.0],[0.0,0.0,2.0]],[[1.0,0.0,0.0],[1.0,0.0,2.0]]]}})",
     surface_fields, surface, "", "construct"},
    {"isocurve", "The exact curve of a surface at a fixed u or v",
     "The isocurve of a surface: for direction u the curve v -> S(value, v), for v the curve\n"
     "u -> S(u, value), exactly, as a curve of the matching type (bezier, rational_bezier,\n"
     "bspline, nurbs).",
     "curve",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}, "direction": "u", "value": 0.5}' | casteljau isocurve
  {"curve":{"type":"bezier","points":[[0.5,0.0,0.0],[0.5,1.0,0.5]]}})",
     isocurve_fields, isocurve, "surface", "surface"},
};

constexpr Command surface_form_family[] = {
    {"eval", "Evaluate a surface (and its partial derivatives, normals, curvatures) at (u, v)",
     "Evaluates a surface at parameter pairs, optionally with its partial derivatives, unit\n"
     "normals and curvatures.",
     "points; partials {u, v, uu, uv, vv, ...}; normals; gaussian, mean, principal",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}, "uv": [[0.5,0.5]]}' | casteljau eval
  {"points":[[0.5,0.5,0.25]]})",
     eval_fields, eval, "surface", "surface"},
    {"split", "Split a surface in u or v", "Splits a surface at t in one direction.", "surfaces: [first, second]",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0],[0,1]],[[2,0],[2,1]]]}, "direction": "u", "t": 0.5}' | casteljau split
  {"surfaces":[{"type":"bezier_surface","points":[[[0.0,0.0],[0.0,1.0]],[[1.0,0.0],[1.0,1.0]]]},{"type":"bezier_surface","points":[[[1.0,0.0],[1.0,1.0]],[[2.0,0.0],[2.0,1.0]]]}]})",
     split_fields, split, "surface", "surface"},
    {"elevate", "Raise a surface's degree in u or v", "Degree elevation in one direction (the same surface).", "surface",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0],[1]]]}, "direction": "v", "times": 1}' | casteljau elevate
  {"surface":{"type":"bezier_surface","points":[[[0.0],[0.5],[1.0]]]}})",
     elevate_fields, elevate, "surface", "surface"},
    {"insert_knot", "Insert a knot into a B-spline or NURBS surface", "Knot insertion in one direction (the same surface).",
     "surface",
     R"(  echo '{"surface": {"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1],[0,0,1,1]], "points": [[[0],[1]],[[2],[3]]]}, "direction": "u", "knot": 0.5}' | casteljau insert_knot
  {"surface":{"type":"bspline_surface","degree":[1,1],"knots":[[0.0,0.0,0.5,1.0,1.0],[0.0,0.0,1.0,1.0]],"points":[[[0.0],[1.0]],[[1.0],[2.0]],[[2.0],[3.0]]]}})",
     insert_knot_fields, insert_knot, "surface", "surface"},
    {"to_bezier", "A surface's exact Bézier patches", "The exact Bézier (or rational Bézier) patches and their breaks.",
     "patches: rows of surface objects; breaks: [u breaks, v breaks]",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0],[1]]]}}' | casteljau to_bezier
  {"patches":[[{"type":"bezier_surface","points":[[[0.0],[1.0]]]}]],"breaks":[[0.0,1.0],[0.0,1.0]]})",
     to_bezier_fields, to_bezier, "surface", "surface"},
    {"bounds", "A box containing a surface", "A box containing the surface over its domain, each side within 1e-9 of its size.",
     "min, max",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}}' | casteljau bounds
  {"min":[0.0,0.0,0.0],"max":[1.0,1.0,1.0]})",
     surface_only_fields, bounds, "surface", "surface"},
    {"project", "The closest point of a surface to a point (guaranteed global)",
     "The global minimum of the distance from the point to the surface over its domain, by\n"
     "branch and bound on the Bézier patches' squared distance in Bernstein form (guaranteed).\n"
     "Where several isolated minimisers tie (distances equal to 1e-12 relative), uv is the one\n"
     "with the smallest u, then v, and all_uv lists each; where the minimum is attained along a\n"
     "curve (a point on the axis of a surface of revolution, a sphere's centre), uv is one of\n"
     "its points and all_uv is omitted.",
     "uv, point, distance; all_uv when several isolated minimisers tie",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}, "point": [0.25,0.5,2]}' | casteljau project
  {"uv":[0.25,0.5],"point":[0.25,0.5,0.0],"distance":2.0})",
     project_fields, project, "surface", "surface"},
    {"intersect", "The intersections of a 3-D curve with a 3-D surface",
     "Where a 3-D curve meets a 3-D surface: crossings and tangent touches sorted by the\n"
     "curve's parameter t, with the surface's (u, v) and the point; overlaps: the parameter\n"
     "intervals where the curve lies on the surface (points inside them are not listed).",
     "intersections: [{t, uv, point, kind: crossing or tangent}]; overlaps: [{t: [t0, t1]}]",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}, "curve": {"type": "bezier", "points": [[0.5,0.5,-1],[0.5,0.5,1]]}}' | casteljau intersect
  {"intersections":[{"t":0.5,"uv":[0.5,0.5],"point":[0.5,0.5,0.0],"kind":"crossing"}],"overlaps":[]})",
     intersect_fields, intersect, "surface", "surface"},
    {"area", "The area of a surface", "The surface area over the domain, to 1e-10 relative.", "area",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0],[0,1]],[[2,0],[2,1]]]}}' | casteljau area
  {"area":2.0})",
     surface_only_fields, area, "surface", "surface"},
};

}  // namespace

std::span<const Command> surface_commands() { return surface_family; }
std::span<const Command> surface_forms() { return surface_form_family; }

}  // namespace casteljau::io::detail
