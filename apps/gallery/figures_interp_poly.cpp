// Gallery figures of the interpolating polynomial curves: the Runge phenomenon and
// Catmull-Rom parametrisations.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/casteljau.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

namespace {

using P1 = Point<double, 1>;

std::string sci2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", v);
  return buf;
}

/// Max error to Runge's function over 2001 points of the interpolant on n nodes; graph
/// gets the interpolant (clipped to [-1, 2]), error_graph log10 |f - p_n| (floored at
/// -6: the error is 0 at the nodes, and the dips there would hide the envelopes).
double runge_error(Nodes kind, std::size_t n, std::vector<P2>* graph = nullptr, std::vector<P2>* error_graph = nullptr) {
  const auto f = [](double x) { return 1 / (1 + 25 * x * x); };
  std::vector<P1> P;
  for (double v : interpolation_nodes<double>(kind, n, -1.0, 1.0)) P.emplace_back(f(v));
  const auto c = Lagrange<double, 1>::on_nodes(kind, {-1.0, 1.0}, P);
  double e = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double x = -1 + i / 1000.0;
    const double y = c(x)[0];
    e = std::max(e, std::abs(y - f(x)));
    if (graph) graph->push_back({x, std::clamp(y, -1.0, 2.0)});
    if (error_graph) error_graph->push_back({x, std::log10(std::max(std::abs(y - f(x)), 1e-6))});
  }
  return e;
}

/// A framed panel in r: its title above the frame (clear of what is drawn inside), the
/// model fitted inside the frame with a margin; the document's map is left on the model.
void frame(SvgDocument& doc, const PageRect& r, const Box<double, 2>& model, const std::string& title,
           io::Aspect aspect = io::Aspect::keep) {
  doc.set_map(PageMap{});
  const PageRect inner{r.x, r.y + 22, r.width, r.height - 22};
  doc.rect(inner, Paint{.stroke = "#ccc", .stroke_width = 1});
  doc.text({r.x + 2, r.y + 14}, title, heading(12.5));
  doc.set_map(PageMap::fit(model, {inner.x + 6, inner.y + 6, inner.width - 12, inner.height - 12}, aspect));
}

/// The part of the segment ab inside the box (Liang-Barsky), if any.
std::optional<std::pair<P2, P2>> clipped(const P2& a, const P2& b, const Box<double, 2>& box) {
  double t0 = 0, t1 = 1;
  const V2 d = b - a;
  for (int i = 0; i < 2; ++i) {
    for (const auto& [den, num] : {std::pair{-d[i], a[i] - box.lo[i]}, std::pair{d[i], box.hi[i] - a[i]}}) {
      if (den == 0) {
        if (num < 0) return std::nullopt;
        continue;
      }
      const double v = num / den;
      if (den < 0) t0 = std::max(t0, v);
      else t1 = std::min(t1, v);
    }
  }
  if (t0 >= t1) return std::nullopt;
  return std::pair{a + t0 * d, a + t1 * d};
}

}  // namespace

Figure runge_phenomenon() {
  SvgDocument doc(860, 640);
  const auto f = [](double x) { return 1 / (1 + 25 * x * x); };
  std::vector<P2> fx;
  for (int i = 0; i <= 400; ++i) fx.push_back({-1 + i / 200.0, f(-1 + i / 200.0)});
  const Nodes kinds[2] = {Nodes::equispaced, Nodes::chebyshev1};
  const char* names[2] = {"11 equispaced nodes", "11 Chebyshev nodes (first kind)"};
  for (int k = 0; k < 2; ++k) {
    const PageRect r{10.0 + 430 * k, 10, 410, 320};
    frame(doc, r, Box<double, 2>{{-1.05, -0.6}, {1.05, 2.05}}, names[k], io::Aspect::stretch);
    doc.line({-1, 0}, {1, 0}, Paint{.stroke = "#999"});
    doc.polyline(fx, Paint{.stroke = "#555", .stroke_width = 1.5, .dash = "5 3"});
    std::vector<P2> g;
    runge_error(kinds[k], 11, &g);
    doc.polyline(g, Paint{.stroke = std::string(io::palette(static_cast<std::size_t>(k))), .stroke_width = 2});
    for (double v : interpolation_nodes<double>(kinds[k], 11, -1.0, 1.0)) doc.circle({v, f(v)}, 3, Paint{.stroke = "#222", .fill = "white"});
  }
  // The error curves |f - p_n| on a log scale: n = 11 (solid) and 21 (dashed), both kinds.
  {
    const PageRect r{10, 340, 840, 290};
    const Box<double, 2> model{{-1.12, -6.3}, {1.05, 1.9}};
    frame(doc, r, model, "Error |f \u2212 p_n| (log scale): equispaced vs Chebyshev, n = 11 solid, n = 21 dashed",
          io::Aspect::stretch);
    for (int e = 0; e >= -6; e -= 2) {
      doc.line({-1, double(e)}, {1, double(e)}, Paint{.stroke = "#ddd"});
      const PageMap m = doc.map();
      const P2 at = m({-1.02, double(e)});
      doc.set_map(PageMap{});
      doc.text({at[0] - 34, at[1] + 4}, e == 0 ? "1" : "1e" + std::to_string(e), TextStyle{.size = 11});
      doc.set_map(m);
    }
    for (int k = 0; k < 2; ++k) {
      for (const std::size_t n : {std::size_t{11}, std::size_t{21}}) {
        std::vector<P2> err;
        runge_error(kinds[k], n, nullptr, &err);
        doc.polyline(err, Paint{.stroke = std::string(io::palette(static_cast<std::size_t>(k))), .stroke_width = 1.5,
                                .dash = n == 11 ? "" : "6 3"});
      }
    }
  }
  std::string eq, ch;
  for (std::size_t n = 5; n <= 40; n += 5) {
    eq += (n > 5 ? ", " : "") + sci2(runge_error(Nodes::equispaced, n));
    ch += (n > 5 ? ", " : "") + sci2(runge_error(Nodes::chebyshev1, n));
  }
  std::string cap =
      "Lagrange interpolation of 1/(1 + 25x<sup>2</sup>) (dashed) on [&minus;1, 1] with 11 nodes, evaluated by the "
      "barycentric formula (<code>Lagrange::on_nodes</code>; values clipped to [&minus;1, 2]). On equispaced nodes the "
      "interpolant swings near the ends and gets worse with more nodes; on Chebyshev nodes it converges. Below, the "
      "error |f &minus; p<sub>n</sub>| on a log scale (0 at the nodes; drawn down to 1e-6) for n = 11 and 21: equispaced "
      "(first colour) grows near the ends with n, Chebyshev (second colour) falls evenly over the interval. Max error for "
      "n = 5, 10, ..., 40: equispaced " + eq + "; Chebyshev " + ch + ".";
  return {"runge", "The Runge phenomenon: equispaced vs Chebyshev nodes", doc.str(), cap};
}

Figure catmull_rom_alpha() {
  SvgDocument doc(860, 560);
  // Two close points between far ones: the uniform spline loops there.
  const std::vector<P2> P{{0, 0}, {1, 3}, {4, 3.2}, {4.3, 3}, {6, 0}, {7, 2}};
  const double alphas[3] = {0, 0.5, 1};
  const char* names[3] = {"uniform (alpha = 0)", "centripetal (alpha = 0.5)", "chordal (alpha = 1)"};
  std::string notes;
  // The segment from P2 to P3 of each spline, sampled: its box (all three) is the zoom.
  std::vector<std::vector<P2>> middle(3);
  Box<double, 2> zoom = box_of<double, 2>(std::vector<P2>{P[2], P[3]});
  for (int k = 0; k < 3; ++k) {
    const CatmullRom<double, 2> c(P, alphas[k]);
    for (int i = 0; i <= 400; ++i) middle[k].push_back(c(c.breaks()[1] + (c.breaks()[2] - c.breaks()[1]) * i / 400.0));
    for (const auto& q : middle[k]) zoom.add(q);
  }
  zoom = grown_relative(zoom, 0.25);
  const std::vector<P2> zoom_outline{zoom.lo, {zoom.hi[0], zoom.lo[1]}, zoom.hi, {zoom.lo[0], zoom.hi[1]}, zoom.lo};
  double magnification = 0;
  for (int k = 0; k < 3; ++k) {
    const std::string colour(io::palette(static_cast<std::size_t>(k)));
    const PageRect r{10.0 + 285 * k, 8, 270, 280};
    frame(doc, r, Box<double, 2>{{-0.5, -0.5}, {7.5, 4.5}}, names[k]);
    const double overview_scale = doc.map()({1.0, 0.0})[0] - doc.map()({0.0, 0.0})[0];
    doc.polyline(P, Paint{.stroke = "#bbb", .stroke_width = 1, .dash = "4 3"});
    const CatmullRom<double, 2> c(P, alphas[k]);
    doc.curve(c.bezier_pieces(), Paint{.stroke = colour, .stroke_width = 2});
    for (const auto& p : P) doc.circle(p, 3, Paint{.stroke = "#222", .fill = "white"});
    doc.polyline(zoom_outline, Paint{.stroke = "#888", .stroke_width = 0.8});
    // The zoom: the segment from P2 to P3 and its neighbours' ends.
    frame(doc, {10.0 + 285 * k, 296, 270, 256}, zoom, "the segment P\u2082P\u2083, enlarged");
    magnification = (doc.map()({1.0, 0.0})[0] - doc.map()({0.0, 0.0})[0]) / overview_scale;
    for (std::size_t i = 1; i < P.size(); ++i) {
      if (const auto e = clipped(P[i - 1], P[i], zoom)) doc.line(e->first, e->second, Paint{.stroke = "#bbb", .stroke_width = 1, .dash = "4 3"});
    }
    doc.polyline(middle[k], Paint{.stroke = colour, .stroke_width = 2.4});
    for (const auto& p : P) {
      if (zoom.contains(p)) doc.circle(p, 4, Paint{.stroke = "#222", .fill = "white"});
    }
    // Does the segment from P_2 to P_3 cross itself? 400 samples, proper crossings of
    // non-adjacent chords.
    const auto& q = middle[k];
    const auto side = [](const P2& o, const P2& a, const P2& b) { return cross(a - o, b - o); };
    int crossings = 0;
    for (std::size_t i = 0; i + 1 < q.size(); ++i)
      for (std::size_t j = i + 2; j + 1 < q.size(); ++j)
        if (side(q[i], q[i + 1], q[j]) * side(q[i], q[i + 1], q[j + 1]) < 0 && side(q[j], q[j + 1], q[i]) * side(q[j], q[j + 1], q[i + 1]) < 0)
          ++crossings;
    notes += std::string(k ? "; " : "") + names[k] + ": " + std::to_string(crossings);
  }
  char mag[32];
  std::snprintf(mag, sizeof mag, "%.0f", magnification);
  std::string cap =
      "Catmull-Rom splines through the same six points with knot intervals |P<sub>i+1</sub> &minus; P<sub>i</sub>|"
      "<sup>alpha</sup> (<code>CatmullRom</code>; tangents of Barry and Goldman). The uniform spline overshoots and "
      "loops between the two close points P<sub>2</sub> and P<sub>3</sub>; the centripetal and chordal ones do not. "
      "The loop is small beside the whole curve: the lower row shows that segment enlarged " + std::string(mag) +
      " times (the grey box above). Self-crossings of the segment from P<sub>2</sub> to P<sub>3</sub> (400 samples): " + notes + ".";
  return {"catmull-rom", "Catmull-Rom: uniform, centripetal, chordal", doc.str(), cap};
}

Figure hermite_basis() {
  SvgDocument doc(860, 300);
  const PageRect r{10, 10, 840, 280};
  frame(doc, r, Box<double, 2>{{-0.05, -0.25}, {1.05, 1.1}}, "Hermite basis functions from the basis matrix",
        io::Aspect::stretch);
  doc.line({0, 0}, {1, 0}, Paint{.stroke = "#999"});
  // h_j(t) = [1 t t^2 t^3] B e_j: column j of the Hermite basis matrix.
  const RationalMatrix4 B = basis_matrix(CubicForm::hermite);
  const char* names[4] = {"h00", "h01", "h10", "h11"};
  double worst_sum = 0;
  std::vector<std::vector<P2>> graphs;
  for (int j = 0; j < 4; ++j) {
    std::vector<P2> g;
    for (int i = 0; i <= 200; ++i) {
      const double t = i / 200.0, tp[4] = {1, t, t * t, t * t * t};
      double h = 0, h_other = 0;
      for (int k = 0; k < 4; ++k) {
        h += tp[k] * B.at<double>(k, j);
        if (j == 0) h_other += tp[k] * B.at<double>(k, 1);
      }
      if (j == 0) worst_sum = std::max(worst_sum, std::abs(h + h_other - 1));
      g.push_back({t, h});
    }
    doc.polyline(g, Paint{.stroke = std::string(io::palette(static_cast<std::size_t>(j))), .stroke_width = 2});
    graphs.push_back(g);
  }
  LabelPlacer labels(doc);
  for (const auto& g : graphs) labels.avoid(g);
  for (int j = 0; j < 4; ++j) {
    const auto& g = graphs[static_cast<std::size_t>(j)];
    labels.place(g[j == 1 || j == 3 ? 170 : 30], names[j], TextStyle{.size = 13, .colour = std::string(io::palette(static_cast<std::size_t>(j)))},
                 V2(0.0, -1.0), 5);
  }
  std::string cap =
      "The cubic Hermite basis h00 = 1 &minus; 3t<sup>2</sup> + 2t<sup>3</sup>, h01 = 3t<sup>2</sup> &minus; 2t<sup>3</sup>, "
      "h10 = t &minus; 2t<sup>2</sup> + t<sup>3</sup>, h11 = t<sup>3</sup> &minus; t<sup>2</sup>: the columns of the "
      "Hermite basis matrix B = C<sup>&minus;1</sup> (<code>basis_matrix(CubicForm::hermite)</code>, exact rationals), "
      "weights of p(0), p(1), p'(0), p'(1). h00 + h01 = 1 (measured max deviation " + sci2(worst_sum) + " over 201 "
      "parameters), so the end points carry the position and the tangent functions vanish at both ends.";
  return {"hermite-basis", "Hermite basis functions", doc.str(), cap};
}

}  // namespace casteljau::gallery
