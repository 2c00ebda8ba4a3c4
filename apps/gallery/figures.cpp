// The gallery's figures. Every picture and every number in a caption is computed here by
// the library at run time; nothing is drawn from hand-made coordinates except the input
// control points.
#include "figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/casteljau.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"

namespace casteljau::gallery {

namespace {

using Bez = Bezier<double, 2>;

// ---------------------------------------------------------------------------------------
// Geometry helpers for measuring (not drawing) the figures' claims.

P2 centroid(std::span<const P2> pts) {
  V2 s{};
  for (const auto& p : pts) s += p.to_vector();
  return P2::from_vector(s / static_cast<double>(pts.size()));
}

template <class C>
std::vector<P2> samples(const C& c, int n) {
  std::vector<P2> out;
  const auto dom = c.domain();
  for (int i = 0; i <= n; ++i) out.push_back(c(dom.at(static_cast<double>(i) / n)));
  return out;
}

/// The sample nearest to p (for placing labels clear of a curve).
P2 nearest(const P2& p, std::span<const P2> pts) {
  return *std::min_element(pts.begin(), pts.end(), [&](const P2& a, const P2& b) { return distance(p, a) < distance(p, b); });
}

/// One-sided distance from a control polygon to the curve: the farthest of 40 samples per
/// polygon edge from a flattening of the curve within 1e-7 (accurate to about that).
double polygon_to_curve(std::span<const P2> polygon, const std::vector<P2>& curve_polyline) {
  const NearestOn curve(curve_polyline, true);
  double d = 0;
  for (std::size_t i = 1; i < polygon.size(); ++i) {
    for (int k = 0; k <= 40; ++k) d = std::max(d, curve.distance(lerp(polygon[i - 1], polygon[i], k / 40.0)));
  }
  return d;
}

/// The convex hull, counter-clockwise, without collinear points (Andrew's monotone chain,
/// [Andrew79]): O(n log n).
std::vector<P2> convex_hull(std::vector<P2> pts) {
  std::sort(pts.begin(), pts.end(), [](const P2& a, const P2& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<P2> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {  // lower hull
    while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lo = k + 1; i-- > 0;) {  // upper hull
    while (k >= lo && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);  // the last point repeats the first
  return h;
}

/// Signed distance of p outside a counter-clockwise convex polygon (<= 0 inside: minus
/// the distance to the nearest edge line).
double outside_distance(const P2& p, std::span<const P2> hull) {
  double d = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const P2& a = hull[i];
    const P2& b = hull[(i + 1) % hull.size()];
    const V2 e = b - a;
    d = std::max(d, -cross(e, p - a) / norm(e));
  }
  return d;
}

double polygon_area(std::span<const P2> poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) a += cross(poly[i].to_vector(), poly[(i + 1) % poly.size()].to_vector());
  return a / 2;
}

/// A framed graph panel: light grid at the ticks, axes at the box edges, tick labels.
/// Sets the document map to the panel's plot area and returns it.
PageMap graph_panel(SvgDocument& doc, const PageRect& plot, const Box2& model, const std::vector<double>& xt,
                    const std::vector<double>& yt, const std::string& x_name, const std::string& y_name) {
  const PageMap map = PageMap::fit(model, plot, Aspect::stretch);
  doc.set_map(map);
  for (const double y : yt) doc.line({model.lo[0], y}, {model.hi[0], y}, thin("#e3e6ea"));
  for (const double x : xt) doc.line({x, model.lo[1]}, {x, model.hi[1]}, thin("#e3e6ea"));
  doc.line({model.lo[0], model.lo[1]}, {model.hi[0], model.lo[1]}, thin("#9aa3ad"));
  doc.line({model.lo[0], model.lo[1]}, {model.lo[0], model.hi[1]}, thin("#9aa3ad"));
  const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1, ys = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (const double x : xt) doc.text({x, model.lo[1]}, io::tick_label(x, xs), [] { auto s = small(10); s.dy = 14; return s; }());
  for (const double y : yt) {
    auto s = small(10, Anchor::end);
    s.dx = -5;
    s.dy = 3.5;
    doc.text({model.lo[0], y}, io::tick_label(y, ys), s);
  }
  if (!x_name.empty()) {
    auto s = math(13, Anchor::end, text_grey);
    s.dy = 14;
    s.dx = 14;
    doc.text({model.hi[0], model.lo[1]}, x_name, s);
  }
  if (!y_name.empty()) {
    auto s = math(13, Anchor::start, text_grey);
    s.dy = -6;
    s.dx = -4;
    doc.text({model.lo[0], model.hi[1]}, y_name, s);
  }
  return map;
}

const char* const sub_digits[] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084", "\u2085", "\u2086", "\u2087", "\u2088", "\u2089"};
const char* const sup_digits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074", "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};

std::string digits(int v, const char* const table[]) {
  std::string s;
  for (const char ch : std::to_string(v)) s += table[ch - '0'];
  return s;
}
std::string sub(int v) { return digits(v, sub_digits); }
std::string sup(int v) { return digits(v, sup_digits); }

// ---------------------------------------------------------------------------------------
// 1. Bernstein basis.

Figure bernstein_basis() {
  const int cols = 3, rows = 2;
  const double panel_w = fig_width / cols, panel_h = 230;
  SvgDocument doc(fig_width, rows * panel_h + 10);
  doc.title("Bernstein basis polynomials of degrees 1 to 6");
  double worst_sum = 0, least = 1;
  constexpr int samples_per_panel = 240;
  for (int n = 1; n <= 6; ++n) {
    const int col = (n - 1) % cols, row = (n - 1) / cols;
    const PageRect plot{col * panel_w + 44, row * panel_h + 30, panel_w - 64, panel_h - 62};
    const Box2 model{{0.0, 0.0}, {1.0, 1.12}};
    graph_panel(doc, plot, model, {0, 0.25, 0.5, 0.75, 1}, {0, 0.5, 1}, "t", "");
    std::vector<std::vector<P2>> graphs(static_cast<std::size_t>(n) + 1);
    std::vector<P2> sum_line;
    for (int k = 0; k <= samples_per_panel; ++k) {
      const double t = static_cast<double>(k) / samples_per_panel;
      const std::vector<double> b = bernstein_all(n, t);
      double s = 0;
      for (int i = 0; i <= n; ++i) {
        graphs[static_cast<std::size_t>(i)].push_back({t, b[static_cast<std::size_t>(i)]});
        s += b[static_cast<std::size_t>(i)];
        least = std::min(least, b[static_cast<std::size_t>(i)]);
      }
      worst_sum = std::max(worst_sum, std::abs(s - 1));
      sum_line.push_back({t, s});
    }
    doc.polyline(sum_line, Paint{.stroke = "#555", .stroke_width = 1.4, .dash = "6 4"});
    for (int i = 0; i <= n; ++i) doc.polyline(graphs[static_cast<std::size_t>(i)], curve_paint(ramp(static_cast<double>(i) / n), 2.2));
    // Labels: interior functions above their maximum at t = i/n, the two end functions
    // above the curve near their ends (where it is 1 they would collide with the sum line).
    if (n <= 4) {
      LabelPlacer labels(doc);
      labels.avoid(sum_line);
      for (const auto& g : graphs) labels.avoid(g);
      for (int i = 0; i <= n; ++i) {
        const double t = i == 0 ? 0.1 : (i == n ? 0.9 : static_cast<double>(i) / n);
        labels.place({t, bernstein(i, n, t)}, "B" + sub(i) + "," + sub(n), math(12, Anchor::middle, ramp(static_cast<double>(i) / n)),
                     V2(i == 0 ? 1.0 : (i == n ? -1.0 : 0.0), -1.0), 4);
      }
    }
    doc.set_map(PageMap{});
    doc.text({plot.x, plot.y - 12}, "degree n = " + std::to_string(n), heading(13));
    auto s = small(10.5, Anchor::end);
    doc.text({plot.x + plot.width, plot.y - 12}, "\u03a3 B\u1d62,\u2099(t) = 1", s);
  }
  std::string cap = "The n + 1 Bernstein polynomials B<sub>i,n</sub>(t) = C(n,i) t<sup>i</sup>(1&minus;t)<sup>n&minus;i</sup> "
                    "of each degree (blue i = 0 to red i = n), computed with <code>bernstein_all</code>. "
                    "Each is non-negative on [0, 1] and B<sub>i,n</sub> peaks at t = i/n. The dashed line is their sum: "
                    "a partition of unity, so a B&eacute;zier point is an affine (and on [0, 1] a convex) combination of "
                    "its control points. Measured over " + std::to_string(samples_per_panel + 1) +
                    " parameters per degree: max |&Sigma;<sub>i</sub> B<sub>i,n</sub>(t) &minus; 1| = " + sci(worst_sum) +
                    " (rounding), smallest value " + sci(least) + ".";
  return {"bernstein", "Bernstein basis polynomials: partition of unity", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 2. de Casteljau construction.

Figure de_casteljau_construction() {
  const std::vector<P2> P = {{0.0, 0.0}, {0.9, 2.7}, {3.4, 3.0}, {4.4, 0.3}};
  const Bez c(P);
  const double t = 0.4;
  // The triangle, level by level: b(r,i) = (1 - t) b(r-1,i) + t b(r-1,i+1) [Farin02, 3.1].
  std::vector<std::vector<P2>> level{P};
  while (level.back().size() > 1) {
    const auto& prev = level.back();
    std::vector<P2> next;
    for (std::size_t i = 0; i + 1 < prev.size(); ++i) next.push_back(lerp(prev[i], prev[i + 1], t));
    level.push_back(next);
  }
  const P2 b = level.back().front();

  SvgDocument doc(fig_width, 400);
  doc.title("de Casteljau construction at t = 0.4");
  const PageRect left{30, 30, 450, 340};
  doc.set_map(PageMap::fit(grown(c.control_bounds(), 0.25), left));
  const std::array<std::string, 4> colours = {polygon_grey, "#2a9d5c", "#d9641c", accent};
  doc.curve(c, curve_paint(ink, 2.6));
  for (std::size_t r = 0; r + 1 < level.size(); ++r) {
    doc.polyline(level[r], r == 0 ? polygon_paint() : thin(colours[r], 1.6));
  }
  const P2 mid = centroid(P);
  control_points(doc, P);
  // Labels clear of the curve, the polygons and each other (LabelPlacer): the control
  // points' away from the polygon's centre, the levels' below their points where free.
  LabelPlacer labels(doc);
  labels.avoid_curve(c);
  for (std::size_t r = 0; r + 1 < level.size(); ++r) labels.avoid(level[r]);
  for (std::size_t r = 1; r < level.size(); ++r) {
    for (const auto& q : level[r]) labels.avoid_point(q, r + 1 == level.size() ? 5.5 : 4);
  }
  for (std::size_t i = 0; i < P.size(); ++i) labels.place(P[i], "P" + sub(static_cast<int>(i)), math(16), doc.map()(P[i]) - doc.map()(mid), 8);
  for (std::size_t r = 1; r < level.size(); ++r) {
    for (std::size_t i = 0; i < level[r].size(); ++i) {
      const P2& q = level[r][i];
      dot(doc, q, colours[r], r + 1 == level.size() ? 5.5 : 4);
      labels.place(q, "P" + sub(static_cast<int>(i)) + sup(static_cast<int>(r)),
                   math(14, Anchor::middle, colours[r] == polygon_grey ? "#222" : colours[r]), V2(0.0, 1.0), 6);
    }
  }
  // The ratio on the first edge: t : (1 - t).
  labels.place(lerp(P[0], level[1][0], 0.5), "t = 0.4", small(11, Anchor::end, text_grey), V2(-1.0, 0.0), 8);

  // The scheme on the right: the triangle of points with the coordinates computed.
  doc.set_map(PageMap{});
  // Rows 2i + r, columns r; each entry joined to its two parents (weights 1 - t, t).
  const double x0 = 508, dx = 96, y0 = 86, dy = 42;
  doc.text({x0, 40}, "the de Casteljau triangle", heading(13));
  doc.text({x0, 58}, "each entry: (1 \u2212 t) \u00d7 upper parent + t \u00d7 lower parent", small(10.5, Anchor::start));
  for (std::size_t r = 0; r < level.size(); ++r) {
    for (std::size_t i = 0; i < level[r].size(); ++i) {
      const P2 at{x0 + r * dx, y0 + (2 * i + r) * dy};
      if (r > 0) {
        // From the right of the upper parent's coordinates and of the lower parent's name,
        // so that no line crosses a number.
        const P2& up = level[r - 1][i];
        const double w_up = text_width_px("(" + io::tick_label(up[0], 0.001) + ", " + io::tick_label(up[1], 0.001) + ")", 9.5);
        const double w_name = text_width_px("P" + sub(static_cast<int>(i + 1)) + (r > 1 ? sup(static_cast<int>(r - 1)) : ""), 15);
        doc.line({at[0] - dx + w_up + 4, at[1] - dy + 9}, {at[0] - 5, at[1] - 6}, thin("#c3cad2"));
        doc.line({at[0] - dx + w_name + 4, at[1] + dy - 6}, {at[0] - 5, at[1] + 1}, thin("#c3cad2"));
      }
      const std::string colour = r == 0 ? "#222" : colours[r];
      doc.text(at, "P" + sub(static_cast<int>(i)) + (r > 0 ? sup(static_cast<int>(r)) : ""), math(15, Anchor::start, colour));
      auto s = small(9.5, Anchor::start, text_grey);
      s.dy = 13;
      const P2& q = level[r][i];
      doc.text(at, "(" + io::tick_label(q[0], 0.001) + ", " + io::tick_label(q[1], 0.001) + ")", s);
    }
  }

  const P2 direct = c(t);
  P2 by_basis{0.0, 0.0};
  for (int i = 0; i <= 3; ++i) by_basis += bernstein(i, 3, t) * P[static_cast<std::size_t>(i)].to_vector();
  std::string cap = "Evaluating a cubic at t = 0.4 by repeated linear interpolation: each level divides every edge of "
                    "the previous polygon in the ratio t : (1 &minus; t) (green: level 1, orange: level 2), and the last "
                    "point P<sub>0</sub><sup>3</sup> = " + point_text(b, 4) +
                    " is the curve point; the segment P<sub>0</sub><sup>2</sup>P<sub>1</sub><sup>2</sup> through it is the "
                    "tangent there. Only convex combinations are used, which makes the algorithm stable. The library's "
                    "<code>c(t)</code> differs from it by " + sci(distance(direct, b)) + " and the Bernstein sum "
                    "&Sigma; B<sub>i,3</sub>(0.4) P<sub>i</sub> (<code>bernstein</code>) by " + sci(distance(by_basis, b)) + ".";
  return {"de-casteljau", "de Casteljau construction at t = 0.4", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 3. Subdivision.

Figure subdivision() {
  const Bez c({{0.0, 0.4}, {0.8, 3.4}, {3.2, -1.6}, {4.6, 2.0}});
  const auto halves = c.split(0.5);
  const std::string cl = io::palette(0).data(), cr = io::palette(1).data();
  SvgDocument doc(fig_width, 380);
  doc.title("Subdivision of a cubic at t = 0.5");
  Box2 box = c.control_bounds();
  doc.set_map(PageMap::fit(grown(box, 0.3), {40, 20, fig_width - 80, 340}));
  doc.polyline(c.points(), polygon_paint("#b9c1ca", 1.2));
  doc.polyline(halves.left.points(), thin(cl, 1.6));
  doc.polyline(halves.right.points(), thin(cr, 1.6));
  doc.curve(halves.left, curve_paint(cl, 3));
  doc.curve(halves.right, curve_paint(cr, 3));
  control_points(doc, c.points(), "#9aa3ad", 3.2);
  control_points(doc, halves.left.points(), cl, 3.8);
  control_points(doc, halves.right.points(), cr, 3.8);
  dot(doc, halves.left.points().back(), accent, 5.5);
  const P2 mid = centroid(c.points());
  for (std::size_t i = 0; i < 4; ++i) label_away(doc, c.points()[i], mid, "P" + sub(static_cast<int>(i)), math(15, Anchor::middle, "#6c757d"));
  const auto left_line = samples(halves.left, 200), right_line = samples(halves.right, 200);
  for (std::size_t i = 1; i < 3; ++i) {
    label_away(doc, halves.left.points()[i], nearest(halves.left.points()[i], left_line), "L" + sub(static_cast<int>(i)),
               math(15, Anchor::middle, cl));
    label_away(doc, halves.right.points()[i], nearest(halves.right.points()[i], right_line), "R" + sub(static_cast<int>(i)),
               math(15, Anchor::middle, cr));
  }
  {
    auto s = math(15, Anchor::start, accent);
    s.dx = 10;
    s.dy = -8;
    doc.text(halves.left.points().back(), "L\u2083 = R\u2080 = P(\u00bd)", s);
  }
  double err_l = 0, err_r = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    err_l = std::max(err_l, distance(halves.left(t), c(t / 2)));
    err_r = std::max(err_r, distance(halves.right(t), c(0.5 + t / 2)));
  }
  const auto line = flatten(c, 1e-7);
  const double before = polygon_to_curve(c.points(), line);
  const double after = std::max(polygon_to_curve(halves.left.points(), line), polygon_to_curve(halves.right.points(), line));
  std::string cap = "<code>split(0.5)</code> cuts the cubic into two cubics whose control polygons (blue L<sub>i</sub>, "
                    "orange R<sub>i</sub>) are the two outer edges of the de Casteljau triangle at t = &frac12;; together "
                    "they describe exactly the same curve. Measured over 1001 parameters: max |L(t) &minus; P(t/2)| = " +
                    sci(err_l) + ", max |R(t) &minus; P((1+t)/2)| = " + sci(err_r) +
                    ". The new polygons hug the curve more closely: the farthest polygon point is " + fixed(before, 3) +
                    " from the curve before and " + fixed(after, 3) + " after (ratio " + fixed(after / before, 2) +
                    ", about &frac14; per halving, which is why repeated subdivision converges fast and drives "
                    "<code>flatten</code>).";
  return {"subdivision", "Subdivision at t = 0.5", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 4. Degree elevation.

Figure degree_elevation() {
  const Bez c({{0.0, 0.0}, {0.4, 3.3}, {4.0, 3.7}, {4.6, 0.2}});
  const std::array<int, 4> degrees = {3, 4, 8, 20};
  SvgDocument doc(fig_width, 400);
  doc.title("Degree elevation 3, 4, 8, 20");
  doc.set_map(PageMap::fit(grown(c.control_bounds(), 0.2), {40, 20, 600, 360}));
  const auto line = flatten(c, 1e-7);
  std::vector<double> dist;
  std::vector<Bez> polys;
  for (const int n : degrees) polys.push_back(c.elevate(n - 3));
  for (std::size_t k = 0; k < polys.size(); ++k) {
    const std::string colour = ramp(static_cast<double>(k) / (polys.size() - 1));
    doc.polyline(polys[k].points(), thin(colour, 1.5));
    dist.push_back(polygon_to_curve(polys[k].points(), line));
  }
  doc.curve(c, curve_paint(ink, 3));
  for (std::size_t k = 0; k < polys.size(); ++k) {
    const std::string colour = ramp(static_cast<double>(k) / (polys.size() - 1));
    control_points(doc, polys[k].points(), colour, k == 3 ? 2.4 : 3.2);
  }
  // Legend.
  doc.set_map(PageMap{});
  doc.text({670, 60}, "control polygon", heading(12));
  doc.text({800, 60}, "distance", heading(12));
  for (std::size_t k = 0; k < polys.size(); ++k) {
    const double y = 88 + 26.0 * k;
    const std::string colour = ramp(static_cast<double>(k) / (polys.size() - 1));
    doc.line({670, y - 4}, {700, y - 4}, thin(colour, 2));
    doc.circle({685, y - 4}, 3, Paint{.stroke = colour, .stroke_width = 1.4, .fill = "white"});
    doc.text({710, y}, "degree " + std::to_string(degrees[k]), small(12, Anchor::start, "#222"));
    doc.text({850, y}, plain(dist[k], 3), small(12, Anchor::end, "#222"));
  }
  doc.line({670, 198}, {700, 198}, curve_paint(ink, 3));
  doc.text({710, 202}, "the curve (unchanged)", small(12, Anchor::start, "#222"));

  double moved = 0;
  for (const auto& p : polys) {
    for (int k = 0; k <= 200; ++k) moved = std::max(moved, distance(p(k / 200.0), c(k / 200.0)));
  }
  std::string cap = "<code>elevate(r)</code> writes the same cubic with n + r control points, each new point a convex "
                    "combination of the old ones (Forrest's formula). The polygons of degree 3, 4, 8 and 20 close in on "
                    "the curve; their distance to it (farthest polygon point) is ";
  for (std::size_t k = 0; k < dist.size(); ++k) cap += (k ? ", " : "") + fixed(dist[k], 3) + " (n = " + std::to_string(degrees[k]) + ")";
  cap += ": it shrinks like 1/n (n &times; distance: ";
  for (std::size_t k = 0; k < dist.size(); ++k) cap += (k ? ", " : "") + fixed(dist[k] * degrees[k], 2);
  cap += "), so elevation converges, but slowly; subdivision converges like 1/4<sup>k</sup>. The curve itself does not move: "
         "max distance between the elevated curves and the cubic over 201 parameters is " + sci(moved) + ".";
  return {"elevation", "Degree elevation 3 \u2192 4 \u2192 8 \u2192 20", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 5. Convex hull property.

Figure convex_hull_property() {
  const Bez c({{0.0, 0.3}, {1.0, 3.6}, {1.9, 0.4}, {3.2, 4.2}, {4.2, 0.9}, {5.5, 3.5}, {6.3, 0.0}});
  const auto hull = convex_hull(c.points());
  SvgDocument doc(fig_width, 400);
  doc.title("Convex hull property");
  doc.set_map(PageMap::fit(grown(c.control_bounds(), 0.25), {40, 20, fig_width - 80, 360}));
  doc.polygon(hull, Paint{.stroke = "#d4a017", .stroke_width = 1.5, .fill = "#f6d776", .fill_opacity = 0.35});
  doc.polyline(c.points(), polygon_paint());
  doc.curve(c, curve_paint(ink, 3));
  control_points(doc, c.points());
  for (const auto& h : hull) doc.circle(h, 6.5, Paint{.stroke = "#d4a017", .stroke_width = 1.6});
  const P2 mid = centroid(c.points());
  // Labels clear of the hull's edge (closed), the polygon and the curve.
  LabelPlacer labels(doc);
  auto closed = hull;
  closed.push_back(hull.front());
  labels.avoid(closed);
  labels.avoid(c.points());
  labels.avoid_curve(c);
  for (std::size_t i = 0; i < c.points().size(); ++i)
    labels.place(c.points()[i], "P" + sub(static_cast<int>(i)), math(15), doc.map()(c.points()[i]) - doc.map()(mid), 12);
  {
    auto s = small(12, Anchor::middle, "#9c7a0c");
    doc.text({3.2, 1.2}, "conv{P\u2080, \u2026, P\u2086}", s);
  }
  constexpr int n_samples = 2000;
  double worst = -std::numeric_limits<double>::infinity();
  for (const auto& p : samples(c, n_samples)) worst = std::max(worst, outside_distance(p, hull));
  std::string cap = "Every point of a B&eacute;zier curve over [0, 1] is a convex combination of the control points "
                    "(the Bernstein weights are &ge; 0 and sum to 1), so the curve lies in their convex hull (shaded; "
                    "computed here by Andrew's monotone chain: " + std::to_string(hull.size()) + " of the " +
                    std::to_string(c.points().size()) + " control points are hull vertices, ringed, area " +
                    fixed(polygon_area(hull), 2) + "). Degree 6 with a zig-zag polygon: all " + std::to_string(n_samples + 1) +
                    " curve samples are inside; the largest signed distance outside the hull is " + sci(worst) +
                    " (touching, at the end points, which are hull vertices). This is what makes "
                    "<code>control_bounds()</code> a safe box and the flatness test of <code>flatten</code> a guarantee.";
  return {"convex-hull", "Convex hull property", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 6. Affine invariance.

Figure affine_invariance() {
  const Bez c({{0.0, 0.0}, {0.9, 2.4}, {2.3, -0.8}, {3.4, 2.6}, {4.4, 0.9}});
  Affine<double, 2> shear;  // a non-uniform scale with shear, then a rotation and a shift
  shear.linear = {{{1.15, 0.55}, {0.0, 0.75}}};
  const Affine<double, 2> m = Affine<double, 2>::translate(V2(7.4, -1.2)) * rotation(0.5) * shear;
  const Bez image = c.transform(m);  // transform the control points, then build the curve
  constexpr int n_dots = 40, n_check = 1000;
  std::vector<P2> mapped;  // transform points sampled on the curve
  double worst = 0;
  for (int k = 0; k <= n_check; ++k) {
    const double t = static_cast<double>(k) / n_check;
    worst = std::max(worst, distance(m(c(t)), image(t)));
  }
  for (int k = 0; k <= n_dots; ++k) mapped.push_back(m(c(static_cast<double>(k) / n_dots)));

  SvgDocument doc(fig_width, 380);
  doc.title("Affine invariance");
  Box2 box = c.control_bounds();
  box.add(image.control_bounds());
  doc.set_map(PageMap::fit(grown(box, 0.3), {30, 20, fig_width - 60, 340}));
  doc.polyline(c.points(), polygon_paint());
  doc.curve(c, curve_paint(ink, 2.6));
  control_points(doc, c.points());
  doc.polyline(image.points(), polygon_paint("#e0a07a"));
  doc.curve(image, Paint{.stroke = "#f4a261", .stroke_width = 9, .opacity = 0.55});
  control_points(doc, image.points(), "#d9641c");
  for (const auto& p : mapped) doc.circle(p, 2.2, Paint{.fill = ink});
  const P2 from = c(0.5) + V2(1.4, 1.2), to = m(c(0.5)) + V2(-1.6, 0.9);
  doc.arrow(from, to, thin("#6c757d", 1.4));
  {
    auto s = math(18, Anchor::middle, "#6c757d");
    s.dy = -10;
    doc.text(lerp(from, to, 0.5), "A", s);
  }
  doc.set_map(PageMap{});
  doc.line({40, 300}, {70, 300}, curve_paint(ink, 2.6));
  doc.text({80, 304}, "the curve P(t)", small(12, Anchor::start, "#222"));
  doc.line({40, 324}, {70, 324}, Paint{.stroke = "#f4a261", .stroke_width = 9, .opacity = 0.55});
  doc.text({80, 328}, "curve of the mapped control points A(P\u1d62)", small(12, Anchor::start, "#222"));
  doc.circle({55, 348}, 2.2, Paint{.fill = ink});
  doc.text({80, 352}, "mapped curve points A(P(t)), t = k/40", small(12, Anchor::start, "#222"));

  const auto& L = m.linear;
  std::string cap = "Mapping the control points by the affine map A(x) = M x + b and building the curve from them "
                    "(wide orange) gives the same curve as mapping the points of the original curve (dark dots), because "
                    "the Bernstein weights sum to 1. Here M = [[" + fixed(L[0][0], 3) + ", " + fixed(L[0][1], 3) + "], [" +
                    fixed(L[1][0], 3) + ", " + fixed(L[1][1], 3) + "]] (shear, non-uniform scale and a rotation by 0.5 rad), "
                    "b = " + point_text(P2::from_vector(m.translation), 3) + ". Max distance between A(P(t)) and the "
                    "transformed curve over " + std::to_string(n_check + 1) + " parameters: " + sci(worst) +
                    ". So <code>transform</code> costs n + 1 point maps, and the renderer writes exact SVG curves by mapping "
                    "control points to the page.";
  return {"affine", "Affine invariance", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 7. Continuity and curvature combs.

Figure continuity() {
  using Seg = Segment<double, 2>;
  const Bez s0({{0.0, 0.0}, {0.5, 1.5}, {1.7, 1.7}, {2.4, 0.7}});
  // Joint 1, C0 only: the next segment starts where s0 ends, in another direction.
  const Bez s1({{2.4, 0.7}, {3.2, 1.3}, {3.8, 2.2}, {4.4, 1.3}});
  // Joint 2, G1 but not C1: the first leg points the same way, but twice as long.
  const P2 e1 = s1.points()[3];
  const V2 leg = e1 - s1.points()[2];
  const Bez s2({e1, e1 + 1.6 * leg, {5.6, -0.6}, {6.4, 0.2}});
  // Joint 3, C1 and joint 4, C2: the first points from cr_join_points, the rest free.
  auto q3 = cr_join_points(s2, 1.0, 3, 1.0, 1);
  q3.push_back({7.9, 1.5});
  q3.push_back({8.8, 1.5});
  const Bez s3(q3);
  auto q4 = cr_join_points(s3, 1.0, 3, 1.0, 2);
  q4.push_back({11.4, 0.0});
  const Bez s4(q4);
  const std::vector<Bez> segs = {s0, s1, s2, s3, s4};
  const Path<double, 2> path({Seg(s0), Seg(s1), Seg(s2), Seg(s3), Seg(s4)});

  // Verified continuity at each joint (tolerance: 1e-9, far above rounding of these
  // O(1) coordinates, far below any deliberate difference).
  constexpr double tol = 1e-9;
  struct Joint {
    int c;
    bool g1;
    double k_left, k_right, angle;
  };
  std::vector<Joint> joints;
  for (std::size_t j = 1; j < path.size(); ++j) {
    const int c = parametric_continuity(path, j, 3, tol);
    const bool g1 = is_g1(path, j, tol, tol);
    const auto kl = curvature(segs[j - 1], 1.0), kr = curvature(segs[j], 0.0);
    const auto tl = end_tangent(path, j - 1, true), tr = end_tangent(path, j, false);
    const double angle = (tl && tr) ? std::acos(std::clamp(dot(*tl, *tr), -1.0, 1.0)) * 180 / std::numbers::pi : 0;
    joints.push_back({c, g1, kl.value_or(0), kr.value_or(0), angle});
  }
  auto name = [](const Joint& j) -> std::string {
    if (j.c >= 0) {
      if (j.c == 0 && j.g1) return "G1";
      return "C" + std::to_string(j.c);
    }
    return "none";
  };

  SvgDocument doc(fig_width, 330);
  doc.title("Composite curve with C0, G1, C1 and C2 joints and its curvature comb");
  // Curvature comb: teeth -kappa(t) N(t) (N the left normal), so they point away from the
  // centre of curvature; the scale makes the longest tooth 0.9 model units.
  constexpr int teeth = 48;
  double kmax = 0;
  for (const auto& s : segs) {
    for (int k = 0; k <= teeth; ++k) kmax = std::max(kmax, std::abs(curvature(s, static_cast<double>(k) / teeth).value_or(0)));
  }
  const double comb = 0.9 / kmax;
  Box2 box = path.control_bounds();
  std::vector<std::vector<P2>> tips(segs.size());
  std::vector<std::pair<P2, P2>> tooth;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    for (int k = 0; k <= teeth; ++k) {
      const double t = static_cast<double>(k) / teeth;
      const V2 d = segs[i].derivative_at(t);
      const double len = norm(d);
      if (!(len > 0)) continue;
      const V2 nrm(-d[1] / len, d[0] / len);
      const P2 p = segs[i](t), tip = p - comb * curvature(segs[i], t).value_or(0) * nrm;
      tips[i].push_back(tip);
      tooth.emplace_back(p, tip);
      box.add(tip);
    }
  }
  doc.set_map(PageMap::fit(grown(box, 0.2), {30, 15, fig_width - 60, 270}));
  for (const auto& [p, tip] : tooth) doc.line(p, tip, thin("#e9a3b4", 0.9));
  for (const auto& t : tips) doc.polyline(t, thin(accent, 1.4));
  for (const auto& s : segs) doc.polyline(s.points(), polygon_paint("#c3cad2", 1));
  for (std::size_t i = 0; i < segs.size(); ++i) doc.curve(segs[i], curve_paint(i % 2 ? "#2f6690" : ink, 2.8));
  for (const auto& s : segs) control_points(doc, s.points(), "#9aa3ad", 2.6);
  LabelPlacer labels(doc);
  for (const auto& t : tips) labels.avoid(t);
  for (const auto& sg : segs) {
    labels.avoid(sg.points());
    labels.avoid_curve(sg, 60);
  }
  for (std::size_t j = 1; j < path.size(); ++j) {
    const P2 at = segs[j](0.0);
    dot(doc, at, "#222", 5);
    const auto s = TextStyle{.size = 15, .colour = "#222", .anchor = Anchor::middle, .bold = true, .family = "Georgia, serif"};
    const std::string n = name(joints[j - 1]);
    labels.place(at, n.substr(0, 1) + sup(n[1] - '0'), s, V2(0.0, 1.0), 10);
  }
  // Legend below the plot.
  doc.set_map(PageMap{});
  doc.line({40, 308}, {70, 308}, curve_paint(ink, 2.8));
  doc.text({78, 312}, "five cubic segments, breaks 0, 1, 2, 3, 4, 5", small(12, Anchor::start, "#222"));
  doc.line({380, 308}, {410, 308}, thin(accent, 1.4));
  doc.line({395, 302}, {395, 314}, thin("#e9a3b4", 0.9));
  doc.text({418, 312}, "curvature comb \u2212\u03ba(t) N(t), longest tooth " + io::tick_label(comb * kmax, 0.01) +
                           " at \u03ba = " + io::tick_label(kmax, 0.01),
           small(12, Anchor::start, "#222"));

  std::string cap = "A composite curve of five cubic B&eacute;zier segments on unit intervals. The joints were built to "
                    "be C<sup>0</sup> (a corner), G<sup>1</sup> (same tangent direction, first leg 1.6 times as long) and, "
                    "with <code>cr_join_points</code>, C<sup>1</sup> and C<sup>2</sup>; the labels show the continuity "
                    "<em>verified</em> by <code>parametric_continuity</code> (up to order 3) and <code>is_g1</code> at "
                    "tolerance 10<sup>&minus;9</sup> (positions and derivatives with respect to the path parameter):";
  cap += "<table><tr><th>joint</th><th>at u</th><th>built as</th><th>verified C<sup>r</sup></th><th>G<sup>1</sup></th>"
         "<th>tangent angle</th><th>&kappa; left</th><th>&kappa; right</th></tr>";
  const std::array<const char*, 4> built = {"C<sup>0</sup>", "G<sup>1</sup>", "C<sup>1</sup>", "C<sup>2</sup>"};
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& J = joints[j];
    cap += "<tr><td>" + std::to_string(j + 1) + "</td><td>" + fixed(path.breaks()[j + 1], 0) + "</td><td>" + built[j] + "</td><td>" +
           (J.c >= 0 ? "C<sup>" + std::to_string(J.c) + "</sup>" : "none") + "</td><td>" + (J.g1 ? "yes" : "no") +
           "</td><td>" + fixed(J.angle, 1) + "&deg;</td><td>" + fixed(J.k_left, 3) + "</td><td>" + fixed(J.k_right, 3) +
           "</td></tr>";
  }
  cap += "</table>The curvature comb (teeth of length proportional to the signed curvature from <code>curvature</code>, "
         "pointing away from the centre of curvature) shows what the labels mean: the comb breaks at the C<sup>0</sup> "
         "corner, and it jumps at the G<sup>1</sup> and C<sup>1</sup> joints, where the second derivative differs, but is "
         "continuous at the C<sup>2</sup> joint.";
  return {"continuity", "Continuity of a composite curve: C0, G1, C1, C2 joints with curvature combs", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 8. Rational quarter circle.

Figure rational_circle() {
  using RB = RationalBezier<double, 2>;
  using Seg = Segment<double, 2>;
  const double pi = std::numbers::pi;
  const RB quarter = RB::circular_arc({0.0, 0.0}, 1.0, 0.0, pi / 2);
  std::vector<Seg> arcs;
  for (int k = 0; k < 4; ++k) arcs.emplace_back(RB::circular_arc({0.0, 0.0}, 1.0, k * pi / 2, (k + 1) * pi / 2));
  const Path<double, 2> circle(arcs);
  // The usual polynomial stand-in: a cubic with inner points at distance 4/3 tan(theta/4).
  const double kappa = 4.0 / 3.0 * std::tan(pi / 8);
  const Bez cubic({{1.0, 0.0}, {1.0, kappa}, {kappa, 1.0}, {0.0, 1.0}});

  constexpr int n = 10000;
  double dev_quarter = 0, dev_circle = 0, dev_cubic = 0;
  std::vector<P2> cubic_err, rational_err;
  const double err_scale = 1e4;  // plotted in units of 1e-4
  for (int k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) / n;
    const double rq = norm(quarter(t).to_vector()) - 1, rc = norm(cubic(t).to_vector()) - 1;
    dev_quarter = std::max(dev_quarter, std::abs(rq));
    dev_cubic = std::max(dev_cubic, std::abs(rc));
    dev_circle = std::max(dev_circle, std::abs(norm(circle(4.0 * t).to_vector()) - 1));
    if (k % 50 == 0) {
      cubic_err.push_back({t, rc * err_scale});
      rational_err.push_back({t, rq * err_scale});
    }
  }

  SvgDocument doc(fig_width, 360);
  doc.title("Rational quarter circle and full circle from four arcs");
  // The true circle, drawn from cos and sin (not from the library's curves), thin and
  // dashed on top of the wide rational curve so that both stay visible.
  auto true_circle = [&](double a0, double a1) {
    std::vector<P2> pts;
    for (int k = 0; k <= 360; ++k) {
      const double a = a0 + (a1 - a0) * k / 360.0;
      pts.push_back({std::cos(a), std::sin(a)});
    }
    doc.polyline(pts, Paint{.stroke = "#111", .stroke_width = 1, .dash = "4 3"});
  };
  const Paint wide{.stroke = "#8fb3d9", .stroke_width = 7, .opacity = 0.9};
  // Left: the quarter arc with its control polygon and weights.
  doc.set_map(PageMap::fit(Box2{{-0.12, -0.16}, {1.62, 1.2}}, {20, 40, 300, 290}));
  doc.line({0.0, 0.0}, {1.0, 0.0}, thin("#ced4da"));
  doc.line({0.0, 0.0}, {0.0, 1.0}, thin("#ced4da"));
  doc.polyline(quarter.points(), polygon_paint());
  doc.curve(quarter, wide);
  true_circle(-0.08, pi / 2 + 0.08);
  control_points(doc, quarter.points());
  dot(doc, {0.0, 0.0}, "#adb5bd", 3);
  const std::array<std::string, 3> wl = {"P\u2080,  w\u2080 = 1", "P\u2081,  w\u2081 = \u221a2/2 \u2248 " + io::tick_label(quarter.weights()[1], 0.0001),
                                         "P\u2082,  w\u2082 = 1"};
  LabelPlacer labels(doc);
  labels.avoid(quarter.points());
  labels.avoid_curve(quarter, 120);
  const std::array<V2, 3> towards = {V2(1.0, 0.3), V2(1.0, 0.3), V2(0.3, -1.0)};
  for (std::size_t i = 0; i < 3; ++i) labels.place(quarter.points()[i], wl[i], math(13), towards[i], 8);
  doc.set_map(PageMap{});
  doc.text({30, 22}, "quarter arc: a rational quadratic", heading(12));

  // Middle: the full circle from four arcs.
  doc.set_map(PageMap::fit(Box2{{-1.2, -1.2}, {1.2, 1.2}}, {350, 40, 250, 270}));
  std::vector<P2> square;
  for (const auto& a : arcs) {
    const auto& pts = std::get<RB>(a).points();
    square.insert(square.end(), pts.begin(), pts.end() - 1);
  }
  square.push_back(square.front());
  doc.polyline(square, polygon_paint());
  doc.curve(circle, wide);
  true_circle(0, 2 * pi);
  control_points(doc, square);
  for (const auto& a : arcs) dot(doc, std::get<RB>(a).points().front(), ink, 4);
  doc.set_map(PageMap{});
  doc.text({360, 22}, "full circle: 4 arcs in a Path", heading(12));

  // Right: radial error graphs.
  const PageRect plot{660, 40, 200, 250};
  const Box2 model{{0.0, -0.5}, {1.0, 3.0}};
  graph_panel(doc, plot, model, {0, 0.5, 1}, {0, 1, 2, 3}, "t", "");
  doc.polyline(cubic_err, curve_paint("#d9641c", 2.2));
  doc.polyline(rational_err, curve_paint(ink, 2.6));
  doc.set_map(PageMap{});
  doc.text({640, 22}, "radial error |P(t)| \u2212 1  (\u00d710\u207b\u2074)", heading(12));
  doc.text({670, 325}, "cubic B\u00e9zier approximation", small(11.5, Anchor::start, "#d9641c"));
  doc.text({670, 341}, "rational arc (zero to rounding)", small(11.5, Anchor::start, ink));

  std::string cap = "A rational quadratic with weights 1, &radic;2/2, 1 on the corner of the unit square "
                    "(<code>RationalBezier::circular_arc</code>) is exactly a quarter of the unit circle, which no "
                    "polynomial curve can be. Max radial deviation ||P(t)| &minus; 1| over " + std::to_string(n + 1) +
                    " parameters: " + sci(dev_quarter) + " for the quarter arc and " + sci(dev_circle) +
                    " for the full circle made of four arcs (a <code>Path</code> on [0, 4]), i.e. rounding. For "
                    "comparison, the usual cubic B&eacute;zier approximation (inner points at 4/3 tan(&pi;/8) = " +
                    fixed(kappa, 4) + ") deviates by up to " + sci(dev_cubic) + " (right, orange). Wide blue: the library's "
                    "curves; thin dashed: the true circle from cos and sin.";
  return {"rational-circle", "Rational quarter circle: exact conic", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 9. Tight bounds vs control bounds.

Figure tight_bounds() {
  const Bez c({{0.0, 0.8}, {0.6, 4.0}, {3.9, -1.6}, {5.0, 2.8}});
  const Box2 cb = c.control_bounds(), tb = bounds(c);
  SvgDocument doc(fig_width, 360);
  doc.title("Tight bounds and control bounds");
  doc.set_map(PageMap::fit(grown(cb, 0.3), {40, 20, 560, 320}));
  auto rect_pts = [](const Box2& b) {
    return std::vector<P2>{b.lo, {b.hi[0], b.lo[1]}, b.hi, {b.lo[0], b.hi[1]}};
  };
  doc.polygon(rect_pts(cb), Paint{.stroke = "#adb5bd", .stroke_width = 1.2, .dash = "6 4"});
  doc.polygon(rect_pts(tb), Paint{.stroke = "#2a9d5c", .stroke_width = 1.8, .fill = "#2a9d5c", .fill_opacity = 0.08});
  doc.polyline(c.points(), polygon_paint());
  doc.curve(c, curve_paint(ink, 2.8));
  control_points(doc, c.points());
  // The extremes: parameters where a coordinate of the hodograph vanishes.
  std::vector<double> ts;
  const auto& P = c.points();
  for (int k = 0; k < 2; ++k) {
    std::vector<double> d;
    for (int i = 0; i < 3; ++i) d.push_back(P[static_cast<std::size_t>(i) + 1][k] - P[static_cast<std::size_t>(i)][k]);
    for (const double r : bernstein_roots<double>(d)) {
      if (r > 0 && r < 1) ts.push_back(r);
    }
  }
  for (const double t : ts) dot(doc, c(t), "#2a9d5c", 4.5);
  doc.set_map(PageMap{});
  doc.line({630, 80}, {660, 80}, Paint{.stroke = "#adb5bd", .stroke_width = 1.2, .dash = "6 4"});
  doc.text({668, 84}, "control_bounds(): conservative", small(12, Anchor::start, "#222"));
  doc.line({630, 108}, {660, 108}, thin("#2a9d5c", 1.8));
  doc.text({668, 112}, "bounds(): tight", small(12, Anchor::start, "#222"));
  dot(doc, {645, 134}, "#2a9d5c", 4.5);
  doc.text({668, 138}, "extremes, roots of x\u2032(t), y\u2032(t)", small(12, Anchor::start, "#222"));
  auto area = [](const Box2& b) { return (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]); };
  double outside = 0;
  for (const auto& p : samples(c, 5000)) {
    for (int k = 0; k < 2; ++k) outside = std::max({outside, tb.lo[k] - p[k], p[k] - tb.hi[k]});
  }
  std::string ts_text;
  for (std::size_t i = 0; i < ts.size(); ++i) ts_text += (i ? ", " : "") + fixed(ts[i], 4);
  std::string cap = "The box of the control points contains the curve (convex hull property) but is loose. "
                    "<code>bounds()</code> adds the end points and the curve at the roots in (0, 1) of each coordinate of "
                    "the hodograph, found by Bernstein root finding (here t = " + ts_text + "). The tight box has " +
                    fixed(100 * area(tb) / area(cb), 1) + "% of the control box's area; over 5001 samples the curve "
                    "exceeds it by at most " + sci(outside) + ".";
  return {"bounds", "Tight bounds vs control bounds", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 10. Hodograph.

Figure hodograph() {
  const Bez c({{0.0, 0.0}, {1.0, 2.4}, {3.0, 2.6}, {4.2, 0.6}});
  const Bez h = c.derivative();
  SvgDocument doc(fig_width, 340);
  doc.title("Derivative vectors and the hodograph");
  const std::array<double, 5> ts = {0.0, 0.25, 0.5, 0.75, 1.0};
  const double show = 0.25;  // tangent vectors drawn at a quarter of their length
  Box2 lb = c.control_bounds();
  for (const double t : ts) lb.add(c(t) + show * c.derivative_at(t));
  doc.set_map(PageMap::fit(grown(lb, 0.2), {30, 30, 470, 280}));
  doc.polyline(c.points(), polygon_paint());
  doc.curve(c, curve_paint(ink, 2.8));
  control_points(doc, c.points());
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const P2 p = c(ts[i]);
    doc.arrow(p, p + show * c.derivative_at(ts[i]), thin(ramp(i / 4.0), 2));
    dot(doc, p, ramp(i / 4.0), 3.5);
  }
  doc.set_map(PageMap{});
  doc.text({30, 22}, "P(t) with P\u2032(t)/4 at t = 0, \u00bc, \u00bd, \u00be, 1", heading(12));

  Box2 rb = h.control_bounds();
  rb.add(P2{0.0, 0.0});
  doc.set_map(PageMap::fit(grown(rb, 0.6), {540, 30, 320, 280}));
  const Box2 v = doc.map().view({540, 30, 320, 280});
  doc.line({v.lo[0], 0.0}, {v.hi[0], 0.0}, thin("#ced4da"));
  doc.line({0.0, v.lo[1]}, {0.0, v.hi[1]}, thin("#ced4da"));
  doc.polyline(h.points(), polygon_paint());
  doc.curve(h, curve_paint("#6c757d", 2.2));
  control_points(doc, h.points());
  for (std::size_t i = 0; i < ts.size(); ++i) doc.arrow({0.0, 0.0}, P2::from_vector(c.derivative_at(ts[i])), thin(ramp(i / 4.0), 2));
  for (std::size_t i = 0; i < h.points().size(); ++i) {
    auto s = math(13, Anchor::start);
    s.dx = 8;
    s.dy = i == 1 ? -8 : 14;
    doc.text(h.points()[i], "3\u0394P" + sub(static_cast<int>(i)), s);
  }
  doc.set_map(PageMap{});
  doc.text({540, 22}, "hodograph P\u2032(t), a quadratic", heading(12));
  double worst = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    worst = std::max(worst, norm(P2::from_vector(c.derivative_at(t)) - h(t)));
  }
  std::string cap = "The derivative of a degree-n B&eacute;zier curve is a degree n &minus; 1 B&eacute;zier curve with "
                    "control points n&Delta;P<sub>i</sub> = n(P<sub>i+1</sub> &minus; P<sub>i</sub>) (<code>derivative()</code>). "
                    "Drawn from the origin, the derivative vectors (right, same colours as on the left) end on this "
                    "hodograph; max |P&prime;(t) &minus; hodograph(t)| over 1001 parameters is " + sci(worst) +
                    ". The hodograph lies in the convex hull of its control points, which bounds the velocities; here that "
                    "hull avoids the "
                    "origin, which proves the curve regular (P&prime;(t) &ne; 0 for every t).";
  return {"hodograph", "Derivatives: the hodograph", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// 11. Degree reduction.

Figure degree_reduction() {
  const Bez c({{0.0, 0.0}, {0.3, 2.2}, {1.4, 3.4}, {2.2, 0.4}, {3.2, -0.4}, {4.0, 2.6}, {5.0, 2.9}, {5.6, 0.5}});
  SvgDocument doc(fig_width, 360);
  doc.title("Degree reduction");
  doc.set_map(PageMap::fit(grown(c.control_bounds(), 0.25), {30, 20, 560, 320}));
  doc.polyline(c.points(), polygon_paint());
  const std::array<int, 3> targets = {3, 4, 5};
  std::vector<Reduction<double, 2>> red;
  for (const int m : targets) red.push_back(reduce_degree(c, m));
  for (std::size_t k = 0; k < red.size(); ++k) doc.curve(red[k].curve, curve_paint(ramp(k / 2.0), 2));
  doc.curve(c, curve_paint(ink, 2.6));
  control_points(doc, c.points());
  doc.set_map(PageMap{});
  doc.text({620, 60}, "degree", heading(12));
  doc.text({800, 60}, "max error", heading(12, Anchor::end));
  doc.line({620, 84}, {650, 84}, curve_paint(ink, 2.6));
  doc.text({660, 88}, "7 (given)", small(12, Anchor::start, "#222"));
  for (std::size_t k = 0; k < red.size(); ++k) {
    const double y = 112 + 26.0 * k;
    doc.line({620, y - 4}, {650, y - 4}, curve_paint(ramp(k / 2.0), 2));
    doc.text({660, y}, std::to_string(targets[k]), small(12, Anchor::start, "#222"));
    doc.text({800, y}, plain(red[k].max_error, 4), small(12, Anchor::end, "#222"));
  }
  std::string cap = "<code>reduce_degree(c, m)</code> finds the degree-m curve closest to a degree-7 curve in the L<sup>2</sup> "
                    "sense with the end points kept. The error it reports (max distance sampled, and a guaranteed bound "
                    "from elevating back): ";
  for (std::size_t k = 0; k < red.size(); ++k) {
    cap += (k ? "; " : "") + std::string("m = ") + std::to_string(targets[k]) + ": " + fixed(red[k].max_error, 4) +
           " (bound " + fixed(red[k].error_bound, 4) + ")";
  }
  cap += ". Every reduction loses shape; the error falls with m.";
  return {"reduction", "Degree reduction 7 \u2192 5, 4, 3", doc.str(), cap};
}

}  // namespace

// ---------------------------------------------------------------------------------------
// 12. One form for every curve: exact Bézier pieces.

Figure pieces_of_a_path() {
  using S = Segment<double, 2>;
  // A polyline on [0, 1.5], a cubic on [1.5, 3] and a rational quarter circle on [3, 4]:
  // three curve types in one path, each segment's own domain mapped onto its interval.
  const Polyline<double, 2> zigzag{{0.0, 0.0}, {0.7, 1.4}, {1.4, 0.3}, {2.0, 1.2}};
  const Bez cubic({{2.0, 1.2}, {2.8, 2.6}, {3.6, -0.8}, {4.4, 0.6}});
  const auto arc = RationalBezier<double, 2>::circular_arc(P2(4.4, 1.6), 1.0, -std::numbers::pi / 2, 0.0);
  const Path<double, 2> path({S(zigzag), S(cubic), S(arc)}, {0.0, 1.5, 3.0, 4.0});
  const Pieces<double, 2> p = pieces(path);
  const Box2 tb = bounds(path);
  const double tol = 0.02;
  const std::vector<P2> poly = flatten(path, tol);

  SvgDocument doc(fig_width, 380);
  doc.title("A path of a polyline, a cubic and a rational arc, and its Bézier pieces");
  doc.set_map(PageMap::fit(grown(path.control_bounds(), 0.25), {30, 20, 600, 340}));
  auto rect_pts = [](const Box2& b) { return std::vector<P2>{b.lo, {b.hi[0], b.lo[1]}, b.hi, {b.lo[0], b.hi[1]}}; };
  doc.polygon(rect_pts(tb), Paint{.stroke = "#2a9d5c", .stroke_width = 1.4, .fill = "#2a9d5c", .fill_opacity = 0.06});
  const std::array<std::string, 2> colours = {ink, accent};
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::visit([&](const auto& piece) {
      doc.polyline(piece.points(), polygon_paint(polygon_grey, 0.9));
      doc.curve(piece, curve_paint(colours[i % 2], 2.6));
    }, p.segments()[i]);
  }
  LabelPlacer labels(doc);
  labels.avoid_curve(path, 400);
  auto box_edge = rect_pts(tb);
  box_edge.push_back(tb.lo);
  labels.avoid(box_edge);  // the bounds' edge (a filled box: the label check counts its outline)
  for (std::size_t i = 0; i < p.size(); ++i) std::visit([&](const auto& piece) { labels.avoid(piece.points()); }, p.segments()[i]);
  for (std::size_t i = 0; i < p.breaks().size(); ++i) {
    const double u = p.breaks()[i];
    const P2 at = path(u);
    dot(doc, at, "white", 4.2);
    dot(doc, at, point_edge, 2.2);
    labels.place(at, "u=" + detail::format_number(u), small(11, Anchor::middle, "#222"), V2(0.0, i % 2 == 0 ? 1.0 : -1.0), 6);
  }
  // The polyline of flatten(), offset below for legibility.
  doc.set_map(PageMap{});
  doc.line({640, 80}, {670, 80}, curve_paint(ink, 2.6));
  doc.line({670, 80}, {700, 80}, curve_paint(accent, 2.6));
  doc.text({708, 84}, "pieces(path), alternating", small(12, Anchor::start, "#222"));
  doc.line({640, 108}, {700, 108}, thin("#2a9d5c", 1.4));
  doc.text({708, 112}, "bounds(): from the pieces", small(12, Anchor::start, "#222"));
  dot(doc, {670, 134}, point_edge, 2.5);
  doc.text({708, 138}, "breaks of the pieces", small(12, Anchor::start, "#222"));

  // Measured claims: the pieces trace the path (points at 4001 parameters), the flattened
  // polyline is within the tolerance of 4001 samples, the box holds every sample.
  double trace = 0, flat = 0, outside = 0;
  const NearestOn flattened(poly, true);
  for (int k = 0; k <= 4000; ++k) {
    const double u = path.domain().at(k / 4000.0);
    const P2 a = path(u);
    trace = std::max(trace, distance(a, p(u)));
    flat = std::max(flat, flattened.distance(a));
    for (int d = 0; d < 2; ++d) outside = std::max({outside, tb.lo[d] - a[d], a[d] - tb.hi[d]});
  }
  std::string br;
  for (std::size_t i = 0; i < p.breaks().size(); ++i) br += (i ? ", " : "") + detail::format_number(p.breaks()[i]);
  const std::string cap =
      "Every curve type converts exactly to <code>Pieces</code>: Bézier and rational Bézier pieces with breaks, in the "
      "curve's own parameter. This path holds a polyline (own domain [0, 3], mapped onto [0, 1.5]), a cubic and a "
      "rational quarter circle; its " + std::to_string(p.size()) + " pieces have breaks " + br + ". They trace the "
      "path to " + sci(trace) + " over 4001 parameters. Queries are written once on the pieces: <code>bounds()</code> "
      "(the union of the pieces' tight boxes; no sample lies outside it by more than " + sci(outside) + ") and "
      "<code>flatten()</code> (" + std::to_string(poly.size()) + " vertices within the tolerance " + plain(tol, 2) +
      "; measured deviation " + fixed(flat, 4) + ").";
  return {"pieces", "One form for every curve: exact Bézier pieces", doc.str(), cap};
}

const std::vector<FigureFunction>& figure_list() {
  static const std::vector<FigureFunction> list = {
      bernstein_basis, de_casteljau_construction, subdivision, degree_elevation, convex_hull_property,
      affine_invariance, continuity, rational_circle, tight_bounds, hodograph, degree_reduction, pieces_of_a_path,
      bspline_basis_functions, local_control, knot_insertion, nurbs_circle_figure, noisy_fit, subdivision_schemes, four_point_scheme,
      closest_points, curvature_comb,
      intersections, flattening_methods,
      runge_phenomenon, catmull_rom_alpha, hermite_basis,
      spline_boundaries, monotone_vs_natural,
      glyph_outlines_figure,
      surface_of_revolution, lofted_hull, coons_patch, bicubic_patch_with_net, torus_tessellation,
      de_boor_construction, blossoming, nurbs_weight_family, knot_removal, space_curve_frames,
  };
  return list;
}

// ---------------------------------------------------------------------------------------
// The page.

namespace {

/// The explorer (`make explorer`, apps/explorer) view that shows a figure's subject live,
/// by figure id, with the name of its tab; none for the figures the explorer has no view
/// of (affine maps, degree reduction, the pieces of a path, fitting, knot removal, fonts,
/// surfaces, 3-D frames).
struct ExplorerView {
  std::string_view figure, view, tab;
};
constexpr ExplorerView explorer_views[] = {
    {"bernstein", "bezier", "de Casteljau"},           {"de-casteljau", "bezier", "de Casteljau"},
    {"subdivision", "bezier", "de Casteljau"},         {"elevation", "bezier", "de Casteljau"},
    {"convex-hull", "bezier", "de Casteljau"},
    {"continuity", "composite", "Composite curves"},   {"rational-circle", "bspline", "B-splines and NURBS"},
    {"bounds", "queries", "Queries"},                  {"hodograph", "bezier", "de Casteljau"},
    {"blossom", "bezier", "de Casteljau"},             {"bspline-basis", "bspline", "B-splines and NURBS"},
    {"de-boor", "bspline", "B-splines and NURBS"},     {"local-control", "bspline", "B-splines and NURBS"},
    {"knot-insertion", "bspline", "B-splines and NURBS"},
    {"nurbs-circle", "bspline", "B-splines and NURBS"}, {"nurbs-weights", "bspline", "B-splines and NURBS"},
    {"subdivision-schemes", "subdivision", "Subdivision curves"}, {"four-point", "subdivision", "Subdivision curves"},
    {"closest-points", "queries", "Queries"},          {"curvature-comb", "composite", "Composite curves"},
    {"intersect", "queries", "Queries"},               {"flatten-methods", "queries", "Queries"},
    {"runge", "interpolation", "Interpolation"},       {"catmull-rom", "catmull", "Catmull-Rom α"},
    {"hermite-basis", "hermite", "Hermite and tangent rules"}, {"spline-boundaries", "interpolation", "Interpolation"},
    {"monotone-interpolation", "hermite", "Hermite and tangent rules"},
    {"affine", "affine", "Affine maps"},               {"reduction", "reduce", "Degree reduction"},
    {"pieces", "pieces", "Path pieces"},               {"noisy-fit", "fit", "Fitting"},
    {"knot-removal", "bspline", "B-splines and NURBS"}, {"glyphs", "import", "SVG import and fonts"},
    {"surface-of-revolution", "surface", "Surfaces"},  {"lofted-hull", "surface", "Surfaces"},
    {"coons-patch", "surface", "Surfaces"},            {"bicubic-patch", "surface", "Surfaces"},
    {"torus-tessellation", "surface", "Surfaces"},     {"frames", "frames", "3-D frames"},
};

/// The explorer's address as `make explorer` prints it (its default port).
constexpr std::string_view explorer_address = "http://127.0.0.1:8080/";

}  // namespace

std::string html_page(const std::vector<Figure>& figures) {
  std::string h;
  h += R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>casteljau gallery</title>
<style>
  :root { --ink: #1d3557; --muted: #5c6670; --rule: #e3e6ea; }
  body { margin: 0; background: #f7f7f5; color: #222; font: 16px/1.55 Georgia, 'Times New Roman', serif; }
  header, main, footer { max-width: 920px; margin: 0 auto; padding: 0 20px; }
  header { padding-top: 36px; }
  h1 { font: 600 30px/1.2 system-ui, 'Helvetica Neue', Arial, sans-serif; color: var(--ink); margin: 0 0 6px; }
  header p { color: var(--muted); margin: 0 0 14px; }
  nav ol { columns: 2; margin: 0 0 24px; padding-left: 22px; font: 14px/1.7 system-ui, 'Helvetica Neue', Arial, sans-serif; }
  nav a { color: var(--ink); text-decoration: none; }
  nav a:hover { text-decoration: underline; }
  figure { background: #fff; border: 1px solid var(--rule); border-radius: 6px; margin: 0 0 28px; padding: 14px 0 16px; }
  figure svg { display: block; margin: 0 auto; max-width: 100%; height: auto; }
  figcaption { padding: 8px 20px 0; font-size: 15px; }
  figcaption table { border-collapse: collapse; margin: 8px 0 10px; font: 13px/1.5 system-ui, 'Helvetica Neue', Arial, sans-serif; }
  figcaption th, figcaption td { padding: 2px 12px; border-bottom: 1px solid var(--rule); text-align: right; }
  figcaption th { font-weight: 600; color: var(--muted); }
  figcaption .title { display: block; font: 600 15.5px/1.4 system-ui, 'Helvetica Neue', Arial, sans-serif; color: var(--ink); margin-bottom: 3px; }
  figcaption a.live { display: block; margin-top: 4px; font: 13px/1.5 system-ui, 'Helvetica Neue', Arial, sans-serif; color: var(--ink); }
  code { font: 13px ui-monospace, 'DejaVu Sans Mono', Menlo, monospace; background: #f1f3f5; padding: 0 3px; border-radius: 3px; }
  footer { color: var(--muted); font-size: 13px; padding-bottom: 36px; }
</style>
</head>
<body>
<header>
<h1>casteljau gallery</h1>
<p>The casteljau library in pictures: B&eacute;zier, rational B&eacute;zier, B-spline and NURBS curves with their
constructions (de Casteljau, de Boor, blossoms, knot insertion and removal), composite and interpolating curves,
subdivision schemes, the geometric queries (bounds, closest points, intersections, flattening, curvature, 3-D frames),
font outlines and surfaces. Each figure and every number in its caption is computed by the library when this page is
generated (<code>make demo</code>); every figure links to the view of the explorer that shows it live
(<code>make explorer</code> serves it at <code>127.0.0.1:8080</code>).</p>
<nav><ol>
)";
  for (const auto& f : figures) h += "<li><a href=\"#" + io::xml_escape(f.id) + "\">" + io::xml_escape(f.title) + "</a></li>\n";
  h += "</ol></nav>\n</header>\n<main>\n";
  for (std::size_t i = 0; i < figures.size(); ++i) {
    const auto& f = figures[i];
    std::string live;
    for (const auto& v : explorer_views) {
      if (v.figure != f.id) continue;
      live = " <a class=\"live\" href=\"" + std::string(explorer_address) + "#" + std::string(v.view) + "\">Live in the explorer: " +
             io::xml_escape(v.tab) + " &rarr;</a>";
    }
    h += "<figure id=\"" + io::xml_escape(f.id) + "\">\n" + f.svg + "<figcaption><span class=\"title\">Figure " +
         std::to_string(i + 1) + ". " + io::xml_escape(f.title) + "</span>" + f.caption + live + "</figcaption>\n</figure>\n";
  }
  h += "</main>\n<footer>Generated by casteljau-gallery. Self-contained: inline SVG and CSS, no scripts, no external "
       "resources; the only links out are those to the explorer on this machine (<code>make explorer</code>).</footer>\n"
       "</body>\n</html>\n";
  return h;
}

}  // namespace casteljau::gallery
