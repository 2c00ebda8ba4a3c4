// The surface registry (io/surfaces.hpp): one entry per surface type (its name, whether
// it is rational, whether it is a Bézier kind), surface JSON read and written, and curves
// as run-time B-spline forms for the constructions.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/io/arrays.hpp"
#include "casteljau/io/ops.hpp"
#include "casteljau/io/surfaces.hpp"
#include "text.hpp"

namespace casteljau::io {

namespace {

using detail::index_path;

/// One registry entry per surface type.
struct SurfaceEntry {
  SurfaceKind kind;
  std::string_view name;
  bool rational;
  bool bezier;
};

constexpr SurfaceEntry entries[] = {
    {SurfaceKind::bezier, "bezier_surface", false, true},
    {SurfaceKind::rational_bezier, "rational_bezier_surface", true, true},
    {SurfaceKind::bspline, "bspline_surface", false, false},
    {SurfaceKind::nurbs, "nurbs_surface", true, false},
};
constexpr std::string_view names[] = {"bezier_surface", "rational_bezier_surface", "bspline_surface", "nurbs_surface"};
// The fields of each type's surface JSON, in the order the reader lists them (type,
// points, degree, dim, then weights when rational, knots when not Bezier): the reader's
// allow-list and surface_types() alike.
constexpr std::string_view bezier_fields[] = {"type", "points", "degree", "dim"};
constexpr std::string_view rational_bezier_fields[] = {"type", "points", "degree", "dim", "weights"};
constexpr std::string_view bspline_fields[] = {"type", "points", "degree", "dim", "knots"};
constexpr std::string_view nurbs_fields[] = {"type", "points", "degree", "dim", "weights", "knots"};
constexpr SurfaceTypeInfo type_infos[] = {{SurfaceKind::bezier, names[0], bezier_fields},
                                          {SurfaceKind::rational_bezier, names[1], rational_bezier_fields},
                                          {SurfaceKind::bspline, names[2], bspline_fields},
                                          {SurfaceKind::nurbs, names[3], nurbs_fields}};

const SurfaceEntry& entry(SurfaceKind k) {
  for (const auto& e : entries)
    if (e.kind == k) return e;
  return entries[0];
}

/// The points grid: rows of points, every row as long as the first, every point of one
/// dimension 1..max_dimension, finite coordinates.
struct Grid {
  std::size_t rows = 0, cols = 0;
  int dim = 0;
  std::vector<double> coords;  // rows * cols * dim
};

Grid read_grid(const Json& j) {
  if (!j.is_array()) throw InvalidArgument("points", "must be an array of rows of points, got " + std::string(kind_of(j)));
  if (j.empty()) throw InvalidArgument("points", "a surface needs at least one row of points");
  Grid g;
  g.rows = j.size();
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string row = index_path("points", i);
    const Json& r = j[i];
    if (!r.is_array()) throw InvalidArgument(row, "a row must be an array of points, got " + std::string(kind_of(r)));
    if (i == 0) {
      if (r.empty()) throw InvalidArgument(row, "a row needs at least one point");
      g.cols = r.size();
    } else if (r.size() != g.cols) {
      throw InvalidArgument(row, "row " + std::to_string(i) + " has " + std::to_string(r.size()) + " points, row 0 has " +
                                     std::to_string(g.cols));
    }
    for (std::size_t k = 0; k < r.size(); ++k) {
      const std::string where = index_path(row, k);
      const Json& p = r[k];
      if (!p.is_array()) throw InvalidArgument(where, "a point must be an array of numbers, got " + std::string(kind_of(p)));
      if (p.empty()) throw InvalidArgument(where, "a point needs at least one coordinate");
      if (i == 0 && k == 0) {
        if (p.size() > static_cast<std::size_t>(max_dimension)) {
          throw InvalidArgument(where, "point has " + std::to_string(p.size()) + " coordinates; supported dimensions are 1.." +
                                           std::to_string(max_dimension));
        }
        g.dim = static_cast<int>(p.size());
        g.coords.reserve(j.size() * g.cols * p.size());
      } else if (p.size() != static_cast<std::size_t>(g.dim)) {
        throw InvalidArgument(where, "point has " + std::to_string(p.size()) + " coordinates but points[0][0] has " +
                                         std::to_string(g.dim) + " (all points of a surface have one dimension)");
      }
      for (std::size_t c = 0; c < p.size(); ++c) g.coords.push_back(number_from_json(p[c], index_path(where, c), "coordinate"));
    }
  }
  return g;
}

std::vector<double> read_weights(const Json& j, const Grid& g) {
  if (!j.is_array()) throw InvalidArgument("weights", "must be an array of rows of weights, got " + std::string(kind_of(j)));
  if (j.size() != g.rows) {
    throw InvalidArgument("weights", "has " + std::to_string(j.size()) + " rows, points has " + std::to_string(g.rows));
  }
  std::vector<double> w;
  w.reserve(g.rows * g.cols);
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string row = index_path("weights", i);
    const std::vector<double> r = numbers_from_json(j[i], row);
    if (r.size() != g.cols) {
      throw InvalidArgument(row, "row " + std::to_string(i) + " has " + std::to_string(r.size()) + " weights, the points' rows have " +
                                     std::to_string(g.cols));
    }
    w.insert(w.end(), r.begin(), r.end());
  }
  return w;
}

/// An array of two integers ("degree": [p, q]).
std::array<int, 2> read_pair(const Json& j, const char* name) {
  if (!j.is_array() || j.size() != 2) {
    throw InvalidArgument(name, std::string("must be an array of two integers [u, v], got ") +
                                    (j.is_array() ? std::to_string(j.size()) + " values" : std::string(kind_of(j))));
  }
  return {integer_from_json(j[0], std::string(name) + "[0]"), integer_from_json(j[1], std::string(name) + "[1]")};
}

}  // namespace

std::string_view type_name(SurfaceKind k) { return entry(k).name; }
std::span<const std::string_view> surface_type_names() { return names; }
std::span<const SurfaceTypeInfo> surface_types() { return type_infos; }

void surface_points(const AnySurface& s, const double* u, const double* v, std::size_t n, double* out) {
  const std::size_t d = s.form.cartesian();
  for (std::size_t j = 0; j < n; ++j) {
    if (!std::isfinite(u[j]) || !std::isfinite(v[j])) {
      throw InvalidArgument("u[" + std::to_string(j) + "]", "the parameter pair (" + casteljau::detail::format_number(u[j]) + ", " +
                                                                 casteljau::detail::format_number(v[j]) + ") is not finite");
    }
    const std::vector<double> x = casteljau::detail::point(s.form, u[j], v[j]);
    std::copy(x.begin(), x.end(), out + j * d);
  }
}

void surface_partials(const AnySurface& s, const double* u, const double* v, std::size_t n, int k, double* out) {
  const std::size_t block = static_cast<std::size_t>(k + 1) * static_cast<std::size_t>(k + 1) * s.form.cartesian();
  for (std::size_t j = 0; j < n; ++j) {
    const std::string where = "uv[" + std::to_string(j) + "]";
    if (!std::isfinite(u[j]) || !std::isfinite(v[j])) {
      throw InvalidArgument(where, "the parameter pair (" + casteljau::detail::format_number(u[j]) + ", " +
                                       casteljau::detail::format_number(v[j]) + ") is not finite");
    }
    try {
      const std::vector<double> d = casteljau::detail::partials(s.form, u[j], v[j], k);
      std::copy(d.begin(), d.end(), out + j * block);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(where, e.problem());
    }
  }
}

AnySurface make_surface(SurfaceKind kind, casteljau::detail::SurfaceForm<double> f) {
  const SurfaceEntry& e = entry(kind);
  if (f.rational != e.rational) throw std::logic_error("make_surface: the form's rationality is not the kind's");
  if (e.bezier) {
    f.p = static_cast<int>(f.rows) - 1;
    f.q = static_cast<int>(f.cols) - 1;
    f.U.assign(f.rows, 0.0);
    f.U.insert(f.U.end(), f.rows, 1.0);
    f.V.assign(f.cols, 0.0);
    f.V.insert(f.V.end(), f.cols, 1.0);
  }
  casteljau::detail::check_surface_form(f);
  return AnySurface{kind, std::move(f)};
}

AnySurface surface_from_json(const Json& j) {
  const Fields f(j, "a surface");
  const std::string type = string_from_json(f.required("type"), "type");
  const SurfaceEntry* e = nullptr;
  for (const auto& x : entries)
    if (x.name == type) e = &x;
  if (!e) throw InvalidArgument("type", "unknown surface type " + io::quoted(type) + " (" + detail::join(std::span<const std::string_view>(names)) + ")");
  std::span<const std::string_view> fields;
  for (const auto& t : type_infos)
    if (t.kind == e->kind) fields = t.fields;
  f.allow_only(fields, "a " + type);
  std::optional<int> dim;
  if (const Json* dj = f.optional("dim")) {
    dim = integer_from_json(*dj, "dim");
    if (*dim < 1 || *dim > max_dimension) {
      throw InvalidArgument("dim", "dimension must be 1.." + std::to_string(max_dimension) + ", got " + std::to_string(*dim));
    }
  }
  const Grid g = read_grid(f.required("points"));
  if (dim && *dim != g.dim) {
    throw InvalidArgument("dim", "dim is " + std::to_string(*dim) + " but the points have " + std::to_string(g.dim) + " coordinates");
  }
  std::vector<double> w;
  if (e->rational) w = read_weights(f.required("weights"), g);
  casteljau::detail::SurfaceForm<double> s;
  s.rows = g.rows;
  s.cols = g.cols;
  s.rational = e->rational;
  s.dim = static_cast<std::size_t>(g.dim) + (e->rational ? 1 : 0);
  if (e->bezier) {
    const int n = static_cast<int>(g.rows) - 1, m = static_cast<int>(g.cols) - 1;
    if (const Json* dj = f.optional("degree")) {
      const std::array<int, 2> d = read_pair(*dj, "degree");
      if (d[0] != n || d[1] != m) {
        throw InvalidArgument("degree", "degree is [" + std::to_string(d[0]) + ", " + std::to_string(d[1]) + "] but the " +
                                            std::to_string(g.rows) + " x " + std::to_string(g.cols) + " grid gives [" +
                                            std::to_string(n) + ", " + std::to_string(m) + "]");
      }
    }
    if (n > max_degree || m > max_degree) {
      throw InvalidArgument("points", "a " + std::to_string(g.rows) + " x " + std::to_string(g.cols) + " grid gives degree above " +
                                          std::to_string(max_degree) + ", the highest supported");
    }
  } else {
    const std::array<int, 2> d = read_pair(f.required("degree"), "degree");
    for (int k = 0; k < 2; ++k) {
      if (d[static_cast<std::size_t>(k)] < 1 || d[static_cast<std::size_t>(k)] > max_degree) {
        throw InvalidArgument("degree[" + std::to_string(k) + "]", "degree must be 1.." + std::to_string(max_degree) + ", got " +
                                                                       std::to_string(d[static_cast<std::size_t>(k)]));
      }
    }
    s.p = d[0];
    s.q = d[1];
    const Json& kj = f.required("knots");
    if (!kj.is_array() || kj.size() != 2) {
      throw InvalidArgument("knots", std::string("must be [U, V], two arrays of knots, got ") +
                                         (kj.is_array() ? std::to_string(kj.size()) + " values" : std::string(kind_of(kj))));
    }
    s.U = numbers_from_json(kj[0], "knots[0]");
    s.V = numbers_from_json(kj[1], "knots[1]");
  }
  s.P.reserve(g.rows * g.cols * s.dim);
  for (std::size_t i = 0; i < g.rows * g.cols; ++i) {
    s.P.insert(s.P.end(), g.coords.begin() + static_cast<std::ptrdiff_t>(i * static_cast<std::size_t>(g.dim)),
               g.coords.begin() + static_cast<std::ptrdiff_t>((i + 1) * static_cast<std::size_t>(g.dim)));
    if (e->rational) s.P.push_back(w[i]);
  }
  return make_surface(e->kind, std::move(s));
}

OrderedJson to_json(const AnySurface& s) {
  const auto& f = s.form;
  const std::size_t cd = f.cartesian();
  OrderedJson points = OrderedJson::array(), weights = OrderedJson::array();
  for (std::size_t i = 0; i < f.rows; ++i) {
    OrderedJson row = OrderedJson::array(), wrow = OrderedJson::array();
    for (std::size_t j = 0; j < f.cols; ++j) {
      const double* x = f.at(i, j);
      row.push_back(std::vector<double>(x, x + cd));
      if (f.rational) wrow.push_back(x[cd]);
    }
    points.push_back(std::move(row));
    if (f.rational) weights.push_back(std::move(wrow));
  }
  OrderedJson out{{"type", type_name(s.kind)}};
  if (!s.is_bezier()) {
    out["degree"] = {f.p, f.q};
    out["knots"] = {f.U, f.V};
  }
  out["points"] = std::move(points);
  if (f.rational) out["weights"] = std::move(weights);
  return out;
}

casteljau::detail::CurveForm<double> curve_form(const AnyCurve& c) {
  // The curve JSON of its B-spline form: exact numbers, and no curve template
  // instantiated here.
  const OrderedJson j = to_json(io::to_bspline(c));
  casteljau::detail::CurveForm<double> f;
  f.p = j.at("degree").get<int>();
  f.U = j.at("knots").get<std::vector<double>>();
  f.rational = j.contains("weights");
  const auto& pts = j.at("points");
  const std::size_t cd = pts.at(0).size();
  f.dim = cd + (f.rational ? 1 : 0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t k = 0; k < cd; ++k) f.P.push_back(pts[i][k].get<double>());
    if (f.rational) f.P.push_back(j.at("weights")[i].get<double>());
  }
  return f;
}

OrderedJson curve_form_json(const casteljau::detail::CurveForm<double>& c, bool bezier) {
  const std::size_t cd = c.rational ? c.dim - 1 : c.dim;
  OrderedJson points = OrderedJson::array();
  std::vector<double> w;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double* x = c.P.data() + i * c.dim;
    points.push_back(std::vector<double>(x, x + cd));
    if (c.rational) w.push_back(x[cd]);
  }
  OrderedJson out{{"type", bezier ? (c.rational ? "rational_bezier" : "bezier") : (c.rational ? "nurbs" : "bspline")}};
  if (!bezier) {
    out["degree"] = c.p;
    out["knots"] = c.U;
  }
  out["points"] = std::move(points);
  if (c.rational) out["weights"] = w;
  return out;
}

std::optional<std::array<double, 3>> limit_normal(const AnySurface& s, double u, double v) {
  return casteljau::detail::limit_normal(s.form, u, v);
}

}  // namespace casteljau::io
