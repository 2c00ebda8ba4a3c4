// Gallery figures of B-splines, NURBS and subdivision curves: knot insertion, the NURBS
// circle with its weights, Chaikin / Lane-Riesenfeld iterations converging to their
// B-spline, and the interpolating 4-point scheme. Every picture and number is computed by
// the library here.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/casteljau.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

namespace {




/// max |a(u) - b(u)| over 2001 parameters of [lo, hi].
template <class A, class B>
double gap(const A& a, const B& b, double lo, double hi) {
  double d = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double u = lo + (hi - lo) * i / 2000;
    d = std::max(d, distance(a(u), b(u)));
  }
  return d;
}

/// The largest distance from the points to samples of the curve (a fine sampling: an
/// upper bound on the true distance within the sample spacing).
double polygon_distance(const std::vector<P2>& Q, const BSpline<double, 2>& c) {
  std::vector<P2> S;
  const auto [lo, hi] = c.domain();
  for (int i = 0; i <= 20000; ++i) S.push_back(c(lo + (hi - lo) * i / 20000));
  const NearestOn samples(S, false);
  double worst = 0;
  for (const auto& q : Q) worst = std::max(worst, samples.distance(q));
  return worst;
}

}  // namespace

Figure knot_insertion() {
  const BSpline<double, 2> c(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                             {P2{{0.0, 0.0}}, P2{{0.8, 2.6}}, P2{{2.4, 3.0}}, P2{{3.6, 0.2}}, P2{{5.2, 0.6}}, P2{{6.0, 2.8}}});
  const BSpline<double, 2> once = c.insert_knot(1.5);
  const BSpline<double, 2> full = c.insert_knot(1.5, 3);
  SvgDocument doc(width, 380);
  doc.title("Knot insertion");
  doc.set_map(PageMap::fit(grown_relative(c.control_bounds(), 0.12), {40, 30, width - 80, 300}));
  doc.polyline(c.points(), stroke(light, 1.3));
  doc.polyline(once.points(), stroke(grey, 1.4, "5 3"));
  doc.polyline(full.points(), stroke(accent, 1.4));
  doc.curve(pieces(c), stroke(ink, 2.6));
  control_points(doc, c.points(), light);
  control_points(doc, once.points(), grey, 3);
  control_points(doc, full.points(), accent, 3);
  const P2 at = c(1.5);
  doc.circle(at, 5, Paint{.stroke = accent, .stroke_width = 1, .fill = accent});
  // The legend below the picture (a label this long finds no free place among the polygons).
  doc.set_map(PageMap{});
  doc.circle({50, 362}, 5, Paint{.stroke = accent, .stroke_width = 1, .fill = accent});
  doc.text({62, 366}, "C(1.5): a control point once the knot has multiplicity 3", label(12));
  doc.line({470, 362}, {500, 362}, stroke(grey, 1.4, "5 3"));
  doc.text({508, 366}, "once", label(12));
  doc.line({560, 362}, {590, 362}, stroke(accent, 1.4));
  doc.text({598, 366}, "three times", label(12));
  const double d1 = gap(c, once, 0, 3), d3 = gap(c, full, 0, 3);
  Figure f;
  f.id = "knot-insertion";
  f.title = "Knot insertion (Boehm)";
  f.svg = doc.str();
  f.caption = "A cubic B-spline with knots 0, 0, 0, 0, 1, 2, 3, 3, 3, 3 "
              "(light polygon). Inserting u = 1.5 once cuts two corners (dashed grey, " +
              std::to_string(once.points().size()) +
              " points); three times (red) brings the knot to multiplicity p = 3 and the curve through a control point: the "
              "split point of <code>BSpline::split</code>. Each new point is a convex combination of two old ones [PT97, A5.1]; "
              "the curve moves by " + sci(d1) + " and " + sci(d3) + " (2001 parameters).";
  return f;
}

Figure nurbs_circle_figure() {
  const auto c = nurbs_circle(P2{{0.0, 0.0}}, 1.0);
  double radial = 0;
  for (int i = 0; i <= 10000; ++i) {
    const P2 q = c(i / 10000.0);
    radial = std::max(radial, std::abs(std::hypot(q[0], q[1]) - 1));
  }
  const auto arc = nurbs_arc(P2{{0.0, 0.0}}, 1.0, 0.0, 4.0);
  SvgDocument doc(width, 340);
  doc.title("NURBS circle");
  doc.set_map(PageMap::fit(Box2{{-1.5, -1.35}, {1.5, 1.35}}, {20, 20, 420, 300}));
  doc.polyline(c.points(), stroke(grey, 1.3));
  doc.curve(pieces(c), stroke(ink, 3));
  control_points(doc, c.points(), "#3d4a5c");
  for (std::size_t i = 0; i < c.points().size() - 1; ++i) {
    TextStyle t = label(11, Anchor::middle);
    const P2 q = c.points()[i];
    t.dx = q[0] * 22;
    t.dy = -q[1] * 16 + 4;
    doc.text(q, i % 2 ? "w = \u221a2/2" : "w = 1", t);
  }
  doc.set_map(PageMap::fit(Box2{{-1.5, -1.35}, {1.5, 1.35}}, {450, 20, 420, 300}));
  doc.polyline(arc.points(), stroke(grey, 1.3));
  doc.curve(pieces(arc), stroke(accent, 3));
  control_points(doc, arc.points(), "#3d4a5c");
  doc.set_map(PageMap{});
  doc.text({470, 330}, "arc of 4 rad: " + std::to_string((arc.points().size() - 1) / 2) + " pieces, middle weights cos(d/2) = " +
                           fixed(arc.weights()[1], 4),
           label(12));
  Figure f;
  f.id = "nurbs-circle";
  f.title = "NURBS circle";
  f.svg = doc.str();
  f.caption = "Left: <code>nurbs_circle</code>, the nine-point circle of [PT97, Ex. 7.2]: "
              "degree 2, knots 0, 0, 0, &frac14;, &frac14;, &frac12;, &frac12;, &frac34;, &frac34;, 1, 1, 1, weights 1 at the "
              "edge midpoints and &radic;2/2 at the corners. Its largest radial error over 10<sup>4</sup> parameters is " +
              sci(radial) + ". Right: <code>nurbs_arc</code> of sweep 4 rad in equal pieces of at most a quarter turn [PT97, A7.1].";
  return f;
}

Figure subdivision_schemes() {
  const std::vector<P2> P{P2{{0.0, 0.0}}, P2{{3.0, 0.4}}, P2{{3.6, 3.0}}, P2{{1.4, 3.6}}, P2{{-0.8, 2.4}}};
  const BSpline<double, 2> limit2 = lane_riesenfeld_limit(P, 2, true);
  const BSpline<double, 2> limit3 = lane_riesenfeld_limit(P, 3, true);
  SvgDocument doc(width, 380);
  doc.title("Chaikin and Lane-Riesenfeld subdivision");
  std::vector<P2> closed(P);
  closed.push_back(P.front());
  std::string rows;
  double previous = 0;
  const std::vector<std::string> shades{"#d9dee4", "#aab6c3", "#7b8ea3", "#4c6682"};
  for (int panel = 0; panel < 2; ++panel) {
    const int p = panel == 0 ? 2 : 3;
    const auto& L = panel == 0 ? limit2 : limit3;
    doc.set_map(PageMap::fit(grown_relative(box_of<double, 2>(P), 0.1), {30.0 + panel * 430.0, 30, 400, 300}));
    doc.polyline(closed, stroke(grey, 1.2, "4 3"));
    for (int k = 1; k <= 4; ++k) {
      std::vector<P2> Q = lane_riesenfeld(P, p, k, true);
      Q.push_back(Q.front());
      doc.polyline(Q, stroke(shades[static_cast<std::size_t>(k - 1)], 1.4));
      if (panel == 0 || k == 4) {
        Q.pop_back();
        const double d = polygon_distance(Q, L);
        if (panel == 0) {
          rows += "<tr><td>" + std::to_string(k) + "</td><td>" + std::to_string(Q.size()) + "</td><td>" + sci(d) + "</td><td>" +
                  (k > 1 ? fixed(previous / d, 2) : std::string("")) + "</td></tr>";
          previous = d;
        }
      }
    }
    doc.curve(pieces(L), stroke(panel == 0 ? ink : accent, 2.2));
    control_points(doc, P, "#3d4a5c");
    doc.set_map(PageMap{});
    doc.text({40.0 + panel * 430.0, 350}, panel == 0 ? "Chaikin (LR degree 2), 1-4 steps, limit: quadratic B-spline"
                                                      : "Lane-Riesenfeld degree 3, 1-4 steps, limit: cubic B-spline",
             label(12));
  }
  Figure f;
  f.id = "subdivision-schemes";
  f.title = "Chaikin and Lane-Riesenfeld subdivision";
  f.svg = doc.str();
  f.caption = "A closed pentagon (dashed) and its polygons "
              "after 1 to 4 steps (light to dark), with the limit returned by <code>lane_riesenfeld_limit</code>: the periodic "
              "uniform B-spline of the scheme's degree [LR80; Chaikin74]. The largest distance from the Chaikin polygon to its "
              "limit (20001 samples) falls by about 4 per step (O(h<sup>2</sup>)):"
              "<table><tr><th>steps</th><th>points</th><th>distance</th><th>ratio</th></tr>" +
              rows + "</table>";
  return f;
}

Figure four_point_scheme() {
  const std::vector<P2> P{P2{{0.0, 0.0}}, P2{{1.5, 2.2}}, P2{{3.4, 2.6}}, P2{{4.2, 0.4}}, P2{{6.0, 0.8}}, P2{{7.2, 3.0}}};
  SvgDocument doc(width, 320);
  doc.title("The 4-point scheme");
  doc.set_map(PageMap::fit(grown_relative(box_of<double, 2>(P), 0.12), {40, 20, width - 80, 270}));
  doc.polyline(P, stroke(grey, 1.2, "4 3"));
  const std::vector<std::string> colours{"#d9dee4", "#aab6c3", "#4c6682"};
  bool interpolates = true;
  std::size_t last_count = 0;
  for (int k = 1; k <= 5; k += 2) {
    const auto Q = four_point(P, k, false);
    for (std::size_t i = 0; i < P.size(); ++i) interpolates = interpolates && Q[i << k] == P[i];
    doc.polyline(Q, stroke(colours[static_cast<std::size_t>(k / 2)], k == 5 ? 2.4 : 1.4));
    last_count = Q.size();
  }
  const auto tight = four_point(P, 5, false, 0.0);
  doc.polyline(tight, stroke(accent, 1, "2 3"));
  control_points(doc, P, "#3d4a5c", 4);
  doc.set_map(PageMap{});
  doc.text({50, 310}, "4-point scheme, w = 1/16: 1, 3 and 5 steps (dotted red: w = 0, the polygon itself)", label(12));
  Figure f;
  f.id = "four-point";
  f.title = "The interpolating 4-point scheme";
  f.svg = doc.str();
  f.caption = "Dyn, Levin and Gregory's scheme [DLG87] keeps every "
              "point and adds (1/2 + w)(P<sub>i</sub> + P<sub>i+1</sub>) &minus; w(P<sub>i&minus;1</sub> + P<sub>i+2</sub>) on "
              "each edge; open ends reflect the end points. After 5 steps (" +
              std::to_string(last_count) + " points) the original points are " + (interpolates ? "still exactly there" : "NOT all there") +
              ". Its C<sup>1</sup> limit is not a B-spline, so <code>subdivide</code> returns no <code>limit</code> for it.";
  return f;
}

}  // namespace casteljau::gallery
