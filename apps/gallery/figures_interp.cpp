// The gallery's figures of interpolating cubics: the four cubic spline boundaries on the
// same data, and monotone (PCHIP) interpolation against the natural spline's overshoot.
// Every curve and number is computed by the library at run time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/casteljau.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

namespace {

using P1 = Point<double, 1>;



/// The graph (x, y(x)) of a 1-D curve at n + 1 parameters over [a, b].
template <class C>
std::vector<P2> graph(const C& c, double a, double b, int n = 400) {
  std::vector<P2> g;
  for (int i = 0; i <= n; ++i) {
    const double x = a + (b - a) * i / n;
    g.push_back({x, c(x)[0]});
  }
  return g;
}

/// A framed plot area with a light grid at the integers, mapped to `model` (stretched).
void frame(SvgDocument& doc, const PageRect& plot, const Box2& model) {
  doc.set_map(PageMap{});
  doc.rect(plot, Paint{.stroke = "#d5d9de", .stroke_width = 1});
  doc.set_map(PageMap::fit(model, plot, Aspect::stretch));
  for (double x = std::ceil(model.lo[0]); x <= model.hi[0]; x += 1)
    doc.line({x, model.lo[1]}, {x, model.hi[1]}, Paint{.stroke = "#eef0f2", .stroke_width = 1});
  for (double y = std::ceil(model.lo[1]); y <= model.hi[1]; y += 1)
    doc.line({model.lo[0], y}, {model.hi[0], y}, Paint{.stroke = "#eef0f2", .stroke_width = 1});
}

/// The graph's runs of consecutive points inside `model` (no drawing outside the frame).
void clipped_graph(SvgDocument& doc, const std::vector<P2>& g, const Box2& model, const Paint& paint) {
  std::vector<P2> run;
  for (const P2& p : g) {
    if (model.contains(p)) {
      run.push_back(p);
      continue;
    }
    if (run.size() > 1) doc.polyline(run, paint);
    run.clear();
  }
  if (run.size() > 1) doc.polyline(run, paint);
}

void dots(SvgDocument& doc, const std::vector<double>& x, const std::vector<P1>& y) {
  for (std::size_t i = 0; i < x.size(); ++i)
    doc.circle({x[i], y[i][0]}, 4, Paint{.stroke = "#222", .stroke_width = 1.4, .fill = "white"});
}

void legend(SvgDocument& doc, double x, double y, const std::string& colour, const std::string& text, const std::string& dash = {}) {
  doc.set_map(PageMap{});
  doc.line({x, y - 4}, {x + 26, y - 4}, Paint{.stroke = colour, .stroke_width = 2.4, .dash = dash});
  doc.text({x + 32, y}, text, TextStyle{.size = 12, .colour = "#222", .family = sans});
}

}  // namespace

Figure spline_boundaries() {
  // Data whose ends agree, so that the periodic boundary applies too.
  const std::vector<double> x = {0, 1, 2.2, 3, 4.5, 5.4, 7};
  const std::vector<P1> y = {P1(1.0), P1(2.6), P1(0.7), P1(1.9), P1(0.4), P1(2.2), P1(1.0)};
  using B = SplineBoundary<double, 1>;
  const CubicSpline<double, 1> natural(x, y), clamped(x, y, B::clamped(Vector<double, 1>(0.0), Vector<double, 1>(0.0))),
      not_a_knot(x, y, B::not_a_knot()), periodic(x, y, B::periodic());
  const double a = x.front() - 0.6, b = x.back() + 0.6;
  const Box2 model{{a, -0.6}, {b, 3.6}};
  SvgDocument doc(width, 360);
  doc.title("Cubic splines through the same data with four end conditions");
  const PageRect plot{30, 15, width - 60, 290};
  frame(doc, plot, model);
  const std::string colours[4] = {"#1d3557", "#c23b5a", "#2a9d8f", "#e9a23b"};
  const CubicSpline<double, 1>* splines[4] = {&natural, &clamped, &not_a_knot, &periodic};
  for (int i = 0; i < 4; ++i) clipped_graph(doc, graph(*splines[i], a, b, 1200), model, Paint{.stroke = colours[i], .stroke_width = 2.2});
  // The domain's ends: beyond them each spline extends its end cubic.
  for (double e : {x.front(), x.back()})
    doc.line({e, model.lo[1]}, {e, model.hi[1]}, Paint{.stroke = "#8d99ae", .stroke_width = 1, .dash = "4 4"});
  dots(doc, x, y);
  legend(doc, 40, 340, colours[0], "natural: y'' = 0 at the ends");
  legend(doc, 250, 340, colours[1], "clamped: y' = 0 at the ends");
  legend(doc, 460, 340, colours[2], "not-a-knot");
  legend(doc, 600, 340, colours[3], "periodic");
  // The measured end conditions.
  const double lo = x.front(), hi = x.back();
  const double nat2 = std::max(std::abs(natural.derivative_at(lo, 2)[0]), std::abs(natural.derivative_at(hi, 2)[0]));
  const double cl1 = std::max(std::abs(clamped.derivative_at(lo, 1)[0]), std::abs(clamped.derivative_at(hi, 1)[0]));
  // Not-a-knot: the third derivative does not jump at the second and second-to-last params.
  const double jump1 = std::abs(not_a_knot.hermite().piece(0).derivative_at(1.0, 3)[0] / std::pow(x[1] - x[0], 3) -
                                not_a_knot.derivative_at(x[1], 3)[0]);
  const double per1 = std::abs(periodic.derivative_at(lo, 1)[0] - periodic.hermite().piece(x.size() - 2).derivative_at(1.0, 1)[0] / (hi - x[x.size() - 2]));
  const double per2 = std::abs(periodic.derivative_at(lo, 2)[0] - periodic.hermite().piece(x.size() - 2).derivative_at(1.0, 2)[0] /
                                                                      std::pow(hi - x[x.size() - 2], 2));
  std::string cap =
      "Four <code>cubic_spline</code>s through the same seven points (uneven x), differing only in their end conditions; "
      "dashed lines mark the domain, beyond which each extends its end cubic. All four are C<sup>2</sup> inside and "
      "solved in O(n) by one tridiagonal (periodic: cyclic) system. Measured: natural |y''| at the ends " + sci(nat2) +
      "; clamped |y'| at the ends " + sci(cl1) + "; not-a-knot jump of y''' at x<sub>1</sub> " + sci(jump1) +
      " (the first two pieces are one cubic); periodic |y'(x<sub>0</sub>) &minus; y'(x<sub>n</sub>)| = " + sci(per1) +
      ", |y''(x<sub>0</sub>) &minus; y''(x<sub>n</sub>)| = " + sci(per2) + ". The ends differ most: y'(x<sub>0</sub>) is " +
      fixed(natural.derivative_at(lo, 1)[0], 2) + " (natural), 0 (clamped), " + fixed(not_a_knot.derivative_at(lo, 1)[0], 2) +
      " (not-a-knot), " + fixed(periodic.derivative_at(lo, 1)[0], 2) + " (periodic).";
  return {"spline-boundaries", "Cubic spline end conditions", doc.str(), cap};
}

Figure monotone_vs_natural() {
  // Monotone (non-decreasing) data with a steep step.
  const std::vector<double> x = {0, 1, 2, 3, 3.6, 5, 6, 7};
  const std::vector<P1> y = {P1(0.0), P1(0.1), P1(0.15), P1(0.3), P1(2.8), P1(3.0), P1(3.05), P1(3.1)};
  const CubicSpline<double, 1> natural(x, y);
  const Hermite<double, 1> pchip(x, y, monotone_tangents(x, y));
  const Box2 model{{-0.3, -0.8}, {7.3, 3.9}};
  SvgDocument doc(width, 340);
  doc.title("Monotone data: natural cubic spline against monotone (PCHIP) Hermite interpolation");
  const PageRect plot{30, 15, width - 60, 270};
  frame(doc, plot, model);
  doc.polyline(graph(natural, 0, 7), Paint{.stroke = "#c23b5a", .stroke_width = 2.2});
  doc.polyline(graph(pchip, 0, 7), Paint{.stroke = "#1d3557", .stroke_width = 2.4});
  doc.line({0, 3.1}, {7, 3.1}, Paint{.stroke = "#8d99ae", .stroke_width = 1, .dash = "4 4"});
  doc.line({0, 0}, {7, 0}, Paint{.stroke = "#8d99ae", .stroke_width = 1, .dash = "4 4"});
  dots(doc, x, y);
  legend(doc, 40, 320, "#c23b5a", "natural cubic spline (C2, overshoots)");
  legend(doc, 330, 320, "#1d3557", "hermite, tangent_rule monotone (C1, PCHIP)");
  // Measured overshoot and monotonicity on a fine grid.
  double nat_lo = 0, nat_hi = 0, worst_step = 0, last = pchip(0.0)[0];
  for (int i = 0; i <= 7000; ++i) {
    const double t = 7.0 * i / 7000;
    nat_lo = std::min(nat_lo, natural(t)[0]);
    nat_hi = std::max(nat_hi, natural(t)[0]);
    const double v = pchip(t)[0];
    worst_step = std::min(worst_step, v - last);
    last = v;
  }
  std::string cap =
      "Non-decreasing data with a steep step. The natural cubic spline is C<sup>2</sup> but leaves the data's range: "
      "measured on 7001 parameters it dips to " + fixed(nat_lo) + " (below the first value 0) and rises to " + fixed(nat_hi) +
      " (above the last value 3.1). The Hermite curve with <code>tangent_rule</code> <code>monotone</code> (exactly "
      "scipy's PchipInterpolator: zero slope at flat or turning data, else a weighted harmonic mean of the chord slopes) "
      "is only C<sup>1</sup> but stays monotone: its largest decrease between consecutive samples is " + sci(std::max(0.0, -worst_step)) +
      ".";
  return {"monotone-interpolation", "Monotone interpolation against spline overshoot", doc.str(), cap};
}

}  // namespace casteljau::gallery
