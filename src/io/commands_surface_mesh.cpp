// The surface mesh commands (issue 19): `tessellate` (surfaces/tessellate.hpp: JSON, OBJ or
// ASCII STL) and the surface form of `render` (an SVG picture of one or more surfaces,
// shaded triangles drawn in painter's order, with optional control nets and isocurves,
// and 3-D curves beside them). Compiled in the `surfaces` unity group; its helpers live in
// a named namespace so that they cannot clash with the group's other files.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/io/surfaces.hpp"
#include "casteljau/io/svg.hpp"
#include "casteljau/surfaces/tessellate.hpp"
#include "commands_family.hpp"
#include "text.hpp"

namespace casteljau::io::detail {

namespace surface_mesh {

using casteljau::detail::format_number;
using casteljau::detail::SurfaceForm;
using casteljau::detail::SurfaceMesh;

constexpr std::string_view formats[] = {"json", "obj", "stl"};

// ---------------------------------------------------------------------------------------
// tessellate

/// A vertex's coordinates padded to 3 (OBJ and STL are 3-D).
std::array<double, 3> xyz(const SurfaceMesh<double>& m, std::size_t k) {
  std::array<double, 3> p{0, 0, 0};
  for (std::size_t c = 0; c < m.dim; ++c) p[c] = m.vertices[k * m.dim + c];
  return p;
}

std::string obj_text(const SurfaceMesh<double>& m) {
  std::string s = "# casteljau tessellate: " + std::to_string(m.size()) + " vertices, " + std::to_string(m.triangles.size()) +
                  " triangles (vt: the surface parameters u v)\n";
  const bool normals = !m.has_normal.empty();
  std::vector<std::size_t> vn(m.size(), 0);  // 1-based index of the vertex's normal, 0: none
  std::size_t count = 0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const auto p = xyz(m, k);
    s += "v " + format_number(p[0]) + " " + format_number(p[1]) + " " + format_number(p[2]) + "\n";
  }
  for (std::size_t k = 0; k < m.size(); ++k) s += "vt " + format_number(m.uv[2 * k]) + " " + format_number(m.uv[2 * k + 1]) + "\n";
  if (normals) {
    for (std::size_t k = 0; k < m.size(); ++k) {
      if (!m.has_normal[k]) continue;
      vn[k] = ++count;
      s += "vn " + format_number(m.normals[3 * k]) + " " + format_number(m.normals[3 * k + 1]) + " " + format_number(m.normals[3 * k + 2]) + "\n";
    }
  }
  for (const auto& t : m.triangles) {
    const bool with_normals = normals && vn[t[0]] && vn[t[1]] && vn[t[2]];
    s += "f";
    for (const auto k : t) {
      const std::string i = std::to_string(k + 1);
      s += " " + i + "/" + i + (with_normals ? "/" + std::to_string(vn[k]) : "");
    }
    s += "\n";
  }
  return s;
}

std::string stl_text(const SurfaceMesh<double>& m) {
  std::string s = "solid casteljau\n";
  for (const auto& t : m.triangles) {
    const auto a = xyz(m, t[0]), b = xyz(m, t[1]), c = xyz(m, t[2]);
    const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, g[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x = len > 0 ? x / len : 0.0;
    s += "  facet normal " + format_number(n[0]) + " " + format_number(n[1]) + " " + format_number(n[2]) + "\n    outer loop\n";
    for (const auto* p : {&a, &b, &c}) {
      s += "      vertex " + format_number((*p)[0]) + " " + format_number((*p)[1]) + " " + format_number((*p)[2]) + "\n";
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid casteljau\n";
}

Response tessellate(const Args& a) {
  const AnySurface& s = a.surface("surface");
  const std::string& format = a.string("format");
  if (format != "json" && s.dim() > 3) {
    throw InvalidArgument("format", format + " needs a surface of dimension 3 or less, got " + std::to_string(s.dim()) + "-D");
  }
  const double tol = a.number("tolerance");
  if (!(tol > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + number_text(tol));
  const SurfaceMesh<double> m = casteljau::detail::tessellate(s.form, tol);
  Response r;
  if (format != "json") {
    r.is_svg = true;  // a text document written as it is (outside --jsonl)
    r.svg = format == "obj" ? obj_text(m) : stl_text(m);
    r.json = OrderedJson{{format, r.svg}};
    return r;
  }
  OrderedJson vertices = OrderedJson::array(), uv = OrderedJson::array(), normals = OrderedJson::array(),
              triangles = OrderedJson::array();
  for (std::size_t k = 0; k < m.size(); ++k) {
    vertices.push_back(std::vector<double>(m.vertices.begin() + static_cast<std::ptrdiff_t>(k * m.dim),
                                           m.vertices.begin() + static_cast<std::ptrdiff_t>((k + 1) * m.dim)));
    uv.push_back({m.uv[2 * k], m.uv[2 * k + 1]});
    if (!m.has_normal.empty() && m.has_normal[k]) normals.push_back({m.normals[3 * k], m.normals[3 * k + 1], m.normals[3 * k + 2]});
    else normals.push_back(nullptr);
  }
  for (const auto& t : m.triangles) triangles.push_back({t[0], t[1], t[2]});
  r.json = OrderedJson{{"vertices", std::move(vertices)}, {"uv", std::move(uv)}, {"normals", std::move(normals)}, {"triangles", std::move(triangles)}};
  return r;
}

constexpr Field tessellate_fields[] = {
    {"surface", FieldType::surface, true},
    {"tolerance", FieldType::number, true, {}, "> 0: the largest distance between the mesh and the surface, both ways"},
    {"format", FieldType::string, false, "\"json\"", "json (vertices, uv, normals, triangles), obj or stl (ASCII) text", formats},
};

// ---------------------------------------------------------------------------------------
// render

/// The view: orthographic, looking at the model from the direction d (towards the
/// viewer) given by azimuth (about z, from x) and elevation (above the xy plane).
struct View {
  double d[3], right[3], up[3];
  [[nodiscard]] double x(const double* p) const { return p[0] * right[0] + p[1] * right[1] + p[2] * right[2]; }
  [[nodiscard]] double y(const double* p) const { return p[0] * up[0] + p[1] * up[1] + p[2] * up[2]; }
  [[nodiscard]] double depth(const double* p) const { return p[0] * d[0] + p[1] * d[1] + p[2] * d[2]; }
};

View view_of(double azimuth_deg, double elevation_deg) {
  const double a = azimuth_deg * std::numbers::pi / 180, e = elevation_deg * std::numbers::pi / 180;
  const double ca = std::cos(a), sa = std::sin(a), ce = std::cos(e), se = std::sin(e);
  return View{{ce * ca, ce * sa, se}, {-sa, ca, 0}, {-se * ca, -se * sa, ce}};
}

/// One thing to draw: a filled triangle or a line segment, at a depth.
struct Item {
  double depth;
  std::array<Point2, 3> p;
  int kind;  ///< 0: triangle, 1: segment
  std::string colour;
  double width;
};

/// The base colours of the surfaces (front faces), in turn.
constexpr std::array<std::array<int, 3>, 4> surface_rgb = {{{70, 130, 200}, {220, 140, 60}, {90, 170, 100}, {180, 90, 170}}};

std::string rgb(double r, double g, double b) {
  const auto c = [](double x) { return std::to_string(static_cast<int>(std::lround(std::clamp(x, 0.0, 255.0)))); };
  return "rgb(" + c(r) + "," + c(g) + "," + c(b) + ")";
}

/// The surfaces of the request: `surface` or `surfaces` (an array of surface objects).
std::vector<AnySurface> read_surfaces(const Args& a) {
  std::vector<AnySurface> out;
  if (a.has("surface") && a.has("surfaces")) throw InvalidArgument("surfaces", "give either surface or surfaces, not both");
  if (a.has("surface")) {
    out.push_back(a.surface("surface"));
  } else {
    const Json& j = a.json("surfaces");
    if (!j.is_array()) throw InvalidArgument("surfaces", "must be an array of surface objects, got " + std::string(kind_of(j)));
    if (j.empty()) throw InvalidArgument("surfaces", "needs at least one surface");
    if (j.size() > 64) throw InvalidArgument("surfaces", "at most 64 surfaces, got " + std::to_string(j.size()));
    for (std::size_t i = 0; i < j.size(); ++i) {
      try {
        out.push_back(surface_from_json(j[i]));
      } catch (const InvalidArgument& e) {
        throw e.within(index_path("surfaces", i));
      }
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i].dim() < 2 || out[i].dim() > 3) {
      throw InvalidArgument(a.has("surface") ? std::string("surface") : index_path("surfaces", i),
                            "render draws surfaces of dimension 2 or 3, got " + std::to_string(out[i].dim()) + "-D");
    }
  }
  return out;
}

double number_in(const Json& j, std::string_view name, double lo, double hi) {
  const std::string where = "view." + std::string(name);
  const double v = number_from_json(j, where, "angle");
  if (!(v >= lo && v <= hi)) throw InvalidArgument(where, "must be in [" + number_text(lo) + ", " + number_text(hi) + "] degrees, got " + number_text(v));
  return v;
}

/// A point of a form padded to 3-D.
std::array<double, 3> at3(const SurfaceForm<double>& f, double u, double v) {
  const std::vector<double> x = casteljau::detail::point(f, u, v);
  std::array<double, 3> p{0, 0, 0};
  for (std::size_t c = 0; c < x.size() && c < 3; ++c) p[c] = x[c];
  return p;
}

Response render(const Args& a) {
  const std::vector<AnySurface> surfaces = read_surfaces(a);
  const std::span<const AnyCurve> curves = a.has("curves") ? a.curves("curves") : std::span<const AnyCurve>{};
  std::vector<casteljau::detail::CurveForm<double>> curve_forms;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    curve_forms.push_back(curve_form(curves[i]));
    const int d = static_cast<int>(curve_forms.back().rational ? curve_forms.back().dim - 1 : curve_forms.back().dim);
    if (d < 2 || d > 3) throw InvalidArgument(index_path("curves", i), "render draws curves of dimension 2 or 3 beside surfaces, got " + std::to_string(d) + "-D");
  }
  const Json& vj = a.json("view");
  if (!vj.is_object()) throw InvalidArgument("view", "must be an object {azimuth, elevation}, got " + std::string(kind_of(vj)));
  const Fields vf(vj, "view");
  vf.allow_only({"azimuth", "elevation"}, "view");
  const double azimuth = vf.has("azimuth") ? number_in(vf.required("azimuth"), "azimuth", -360, 360) : 30.0;
  const double elevation = vf.has("elevation") ? number_in(vf.required("elevation"), "elevation", -90, 90) : 25.0;
  const View view = view_of(azimuth, elevation);
  const double width = a.number("width"), height = a.number("height"), padding = a.number("padding");
  if (!(width >= 1 && width <= 1e6)) throw InvalidArgument("width", "must be 1 to 1000000 px, got " + number_text(width));
  if (!(height >= 1 && height <= 1e6)) throw InvalidArgument("height", "must be 1 to 1000000 px, got " + number_text(height));
  if (!(padding >= 0) || !(std::min(width, height) - 2 * padding >= 1)) {
    throw InvalidArgument("padding", "must be >= 0 and leave at least 1 px to draw in, got " + number_text(padding));
  }
  const int isocurves = a.integer("isocurves");
  if (isocurves < 0 || isocurves > 100) throw InvalidArgument("isocurves", "must be 0 to 100, got " + std::to_string(isocurves));
  const bool net = a.boolean("control_net");
  const double tolerance = a.number("tolerance");
  if (!(tolerance >= 0)) throw InvalidArgument("tolerance", "must be >= 0, got " + number_text(tolerance));

  // The view box: the projected control points (the surfaces lie in their hulls) and the
  // curves' points.
  Box2 box;
  const auto grow = [&](const double* p) { box.add(Point2{view.x(p), view.y(p)}); };
  std::vector<SurfaceForm<double>> forms;
  for (const auto& s : surfaces) {
    const SurfaceForm<double>& c = s.form;  // Cartesian points (and weights)
    for (std::size_t i = 0; i < c.rows; ++i)
      for (std::size_t j = 0; j < c.cols; ++j) {
        double p[3] = {0, 0, 0};
        for (std::size_t k = 0; k < c.cartesian(); ++k) p[k] = c.at(i, j)[k];
        grow(p);
      }
    forms.push_back(s.form);
  }
  std::vector<std::vector<std::array<double, 3>>> curve_points;
  for (const auto& cf : curve_forms) {
    const SurfaceForm<double> col{cf.p, 0, cf.U, {0.0, 1.0}, cf.size(), 1, cf.dim, cf.rational, cf.P};
    std::vector<std::array<double, 3>> pts;
    const auto& U = cf.U;
    const double t0 = U[static_cast<std::size_t>(cf.p)], t1 = U[U.size() - 1 - static_cast<std::size_t>(cf.p)];
    for (std::size_t k = static_cast<std::size_t>(cf.p); k + 1 + static_cast<std::size_t>(cf.p) < U.size(); ++k) {
      if (!(U[k + 1] > U[k])) continue;
      for (int i = 0; i < 32; ++i) pts.push_back(at3(col, U[k] + (U[k + 1] - U[k]) * i / 32.0, 0.0));
    }
    pts.push_back(at3(col, t1, 0.0));
    (void)t0;
    for (const auto& p : pts) grow(p.data());
    curve_points.push_back(std::move(pts));
  }
  const PageRect page{padding, padding, width - 2 * padding, height - 2 * padding};
  // The meshes, within half a pixel of the control points' view (or the tolerance asked).
  const double tol = tolerance > 0 ? tolerance : 0.5 * PageMap::fit(box, page).px_to_model(1.0);
  std::vector<casteljau::detail::SurfaceMesh<double>> meshes;
  for (std::size_t si = 0; si < forms.size(); ++si) {
    try {
      meshes.push_back(casteljau::detail::tessellate(forms[si], tol));
    } catch (const InvalidArgument& e) {
      if (e.where() == "tolerance") throw InvalidArgument("tolerance", e.problem());
      throw e.within(a.has("surface") ? std::string("surface") : index_path("surfaces", si));
    }
  }
  // The view: the meshes, the curves, and the control nets when drawn (the surfaces'
  // own extent rather than their nets' box, which may be much larger).
  if (!net) {
    box = Box2{};
    for (const auto& pts : curve_points)
      for (const auto& p : pts) grow(p.data());
  }
  for (const auto& m : meshes)
    for (std::size_t k = 0; k < m.size(); ++k) {
      double p[3] = {0, 0, 0};
      for (std::size_t c = 0; c < m.dim; ++c) p[c] = m.vertices[k * m.dim + c];
      grow(p);
    }
  const PageMap map = PageMap::fit(box, page);
  const double px = map.px_to_model(1.0);
  // Light from the upper left, somewhat towards the viewer.
  double light[3];
  {
    double l[3];
    for (int k = 0; k < 3; ++k) l[k] = view.d[k] + 0.6 * view.up[k] - 0.4 * view.right[k];
    const double n = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    for (int k = 0; k < 3; ++k) light[k] = l[k] / n;
  }
  std::vector<Item> items;
  const auto page_of = [&](const double* p) { return map(Point2{view.x(p), view.y(p)}); };
  const auto segment = [&](const double* p, const double* q, const std::string& colour, double w, double bias) {
    items.push_back(Item{(view.depth(p) + view.depth(q)) / 2 + bias, {page_of(p), page_of(q), page_of(q)}, 1, colour, w});
  };
  for (std::size_t si = 0; si < forms.size(); ++si) {
    const SurfaceForm<double>& f = forms[si];
    const casteljau::detail::SurfaceMesh<double>& m = meshes[si];
    const auto& base = surface_rgb[si % surface_rgb.size()];
    const auto vtx = [&](std::uint32_t k) {
      std::array<double, 3> p{0, 0, 0};
      for (std::size_t c = 0; c < m.dim; ++c) p[c] = m.vertices[k * m.dim + c];
      return p;
    };
    for (const auto& t : m.triangles) {
      const auto p = vtx(t[0]), q = vtx(t[1]), r = vtx(t[2]);
      const double e[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, g[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      double n[3] = {e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]};
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(len > 0)) continue;
      for (double& x : n) x /= len;
      const bool front = view.depth(n) >= 0;
      const double lambert = std::abs(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]);
      const double shade = 0.3 + 0.7 * lambert;
      // Back faces (the inside of a surface seen through an opening) in a paler, greyer tint.
      const double mix = front ? 0.0 : 0.55;
      const auto ch = [&](int k) { return shade * ((1 - mix) * base[static_cast<std::size_t>(k)] + mix * 190); };
      const double depth = (view.depth(p.data()) + view.depth(q.data()) + view.depth(r.data())) / 3;
      items.push_back(Item{depth, {page_of(p.data()), page_of(q.data()), page_of(r.data())}, 0, rgb(ch(0), ch(1), ch(2)), 0.6});
    }
    // Isocurves: evenly spaced inside the domain, drawn just in front of the surface.
    if (isocurves > 0) {
      const double u0 = f.U[static_cast<std::size_t>(f.p)], u1 = f.U[f.rows], v0 = f.V[static_cast<std::size_t>(f.q)], v1 = f.V[f.cols];
      const int samples = 64;
      for (int dir = 0; dir < 2; ++dir)
        for (int k = 1; k <= isocurves; ++k) {
          const double c = dir == 0 ? u0 + (u1 - u0) * k / (isocurves + 1) : v0 + (v1 - v0) * k / (isocurves + 1);
          std::array<double, 3> prev{};
          for (int i = 0; i <= samples; ++i) {
            const double s = dir == 0 ? v0 + (v1 - v0) * i / samples : u0 + (u1 - u0) * i / samples;
            const auto p = dir == 0 ? at3(f, c, s) : at3(f, s, c);
            if (i > 0) segment(prev.data(), p.data(), "#333", 0.8, 2 * tol + 2 * px);
            prev = p;
          }
        }
    }
    if (net) {
      const SurfaceForm<double>& c = f;
      const auto cp = [&](std::size_t i, std::size_t j) {
        std::array<double, 3> p{0, 0, 0};
        for (std::size_t k = 0; k < c.cartesian(); ++k) p[k] = c.at(i, j)[k];
        return p;
      };
      for (std::size_t i = 0; i < c.rows; ++i)
        for (std::size_t j = 0; j < c.cols; ++j) {
          const auto p = cp(i, j);
          if (i + 1 < c.rows) segment(p.data(), cp(i + 1, j).data(), "#c0392b", 1.0, 4 * px);
          if (j + 1 < c.cols) segment(p.data(), cp(i, j + 1).data(), "#c0392b", 1.0, 4 * px);
          items.push_back(Item{view.depth(p.data()) + 4 * px, {page_of(p.data()), page_of(p.data()), page_of(p.data())}, 2, "#c0392b", 2.5});
        }
    }
  }
  static constexpr std::array<std::string_view, 6> curve_colours = {"#111", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"};
  for (std::size_t i = 0; i < curve_points.size(); ++i) {
    const auto& pts = curve_points[i];
    for (std::size_t k = 1; k < pts.size(); ++k) segment(pts[k - 1].data(), pts[k].data(), std::string(curve_colours[i % curve_colours.size()]), 2.0, 2 * px);
  }
  // Painter's order: the farthest first.
  std::stable_sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return x.depth < y.depth; });
  SvgDocument doc(width, height);
  doc.title("casteljau render: " + std::to_string(surfaces.size()) + (surfaces.size() == 1 ? " surface" : " surfaces"));
  const std::string& background = a.string("background");
  if (background != "none") doc.rect(PageRect{0, 0, width, height}, Paint{"none", 1, background});
  doc.set_map(PageMap{});  // items are already in page px
  for (const auto& it : items) {
    if (it.kind == 0) {
      doc.polygon(std::span<const Point2>(it.p.data(), 3), Paint{it.colour, it.width, it.colour});
    } else if (it.kind == 1) {
      doc.line(it.p[0], it.p[1], Paint{it.colour, it.width});
    } else {
      doc.circle(it.p[0], it.width, Paint{"none", 1, it.colour});
    }
  }
  Response r;
  r.is_svg = true;
  r.svg = doc.str();
  r.json = OrderedJson{{"svg", r.svg}};
  return r;
}

/// Background colours: CSS colour names, #hex, rgb()/hsl() forms (no quotes or brackets).
constexpr Field render_fields[] = {
    {"surface", FieldType::surface, false, {}, "the surface to draw (or surfaces)"},
    {"surfaces", FieldType::json, false, {}, "an array of surface objects to draw (or surface)"},
    {"curves", FieldType::curves, false, {}, "2-D or 3-D curves drawn beside the surfaces", {}, {}, 1, 0},
    {"view", FieldType::json, false, "{}", "{azimuth, elevation} in degrees (default 30, 25): the direction the model is seen from"},
    {"isocurves", FieldType::integer, false, "0", "0 to 100 isocurves in each direction, evenly spaced inside the domain"},
    {"control_net", FieldType::boolean, false, "false", "draw the control net and points"},
    {"tolerance", FieldType::number, false, "0", "the tessellation's tolerance in model units; 0: half a pixel"},
    {"width", FieldType::number, false, "640", "page width in px, 1 to 1000000"},
    {"height", FieldType::number, false, "480", "page height in px, 1 to 1000000"},
    {"padding", FieldType::number, false, "24", "px, >= 0, leaving at least 1 px to draw in"},
    {"background", FieldType::string, false, "\"white\"", "CSS colour or \"none\""},
};

constexpr Command mesh_family[] = {
    {"tessellate", "Triangulate a surface within a tolerance (JSON, OBJ or STL)",
     "A triangle mesh of the surface: every point of every triangle within `tolerance` of the\n"
     "surface and every point of the surface within `tolerance` of the mesh (a bound from the\n"
     "patches' control nets, not a sample). Edges shared by patches are split alike on both\n"
     "sides (no cracks); triangles are counter-clockwise seen from the side of S_u x S_v; a\n"
     "degenerate edge (a sphere's pole) is one vertex with its limit normal. A mesh of more\n"
     "than 10^7 triangles is refused before it is built.",
     "json: vertices, uv, normals (unit, null where undefined), triangles (index triples);\n"
     "          obj, stl: the text of the file",
     R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}, "tolerance": 0.1}' | casteljau tessellate
  {"vertices":[[0.0,0.0,0.0],[1.0,0.0,0.0],[1.0,1.0,0.0],[0.0,1.0,0.0]],"uv":[[0.0,0.0],[1.0,0.0],[1.0,1.0],[0.0,1.0]],"normals":[[0.0,0.0,1.0],[0.0,0.0,1.0],[0.0,0.0,1.0],[0.0,0.0,1.0]],"triangles":[[0,1,2],[0,2,3]]})",
     tessellate_fields, tessellate, "surface", "surface"},
};

constexpr Command mesh_forms[] = {
    {"render", "Draw surfaces (and curves) as an SVG picture",
     "An SVG picture of one or more surfaces seen from `view`: shaded triangles in painter's\n"
     "order (far first), optionally the control net and isocurves, with 3-D curves beside them.",
     "an SVG document", R"(  echo '{"surface": {"type": "bezier_surface", "points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}, "isocurves": 3}' | casteljau render > surface.svg)",
     render_fields, render, "", "surface"},
};

}  // namespace surface_mesh

std::span<const Command> surface_mesh_commands() { return surface_mesh::mesh_family; }
std::span<const Command> surface_mesh_forms() { return surface_mesh::mesh_forms; }

}  // namespace casteljau::io::detail
