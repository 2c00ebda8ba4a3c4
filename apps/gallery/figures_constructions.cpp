// Gallery figures of the constructions a course teaches beside de Casteljau's: de Boor's
// construction, the blossom, a family of NURBS as one weight changes, knot removal, and a
// space curve with its Frenet and rotation-minimizing frames. Knot removal and the frames
// go through the command registry (remove_knot, eval, frames requests), as
// figures_surfaces.cpp does, so that this file instantiates few templates of its own.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "casteljau/casteljau.hpp"
#include "casteljau/io/commands.hpp"
#include "casteljau/io/json.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

namespace {
namespace constructions {  // named: the gallery is one unity unit, its anonymous namespaces one

using Spline = BSpline<double, 2>;

io::Json run_command(const char* command, const io::Json& request) {
  const io::Command* c = io::find_command(command);
  if (c == nullptr) throw std::runtime_error(std::string("no command ") + command);
  const io::Response r = io::run(*c, request);
  return io::Json::parse(r.json.dump());
}

io::Json spline_json(const Spline& c) {
  io::Json pts = io::Json::array();
  for (const auto& p : c.points()) pts.push_back({p[0], p[1]});
  return {{"type", "bspline"}, {"degree", c.degree()}, {"knots", c.knot_vector().knots()}, {"points", pts}};
}

Spline spline_from_json(const io::Json& j) {
  std::vector<P2> pts;
  for (const auto& p : j["points"]) pts.push_back({p[0].get<double>(), p[1].get<double>()});
  return Spline(j["degree"].get<int>(), j["knots"].get<std::vector<double>>(), pts);
}

template <class C>
std::vector<P2> sampled(const C& c, int n) {
  std::vector<P2> out;
  const auto dom = c.domain();
  for (int i = 0; i <= n; ++i) out.push_back(c(dom.lo + (dom.hi - dom.lo) * i / n));
  return out;
}

/// The page direction (y down) pointing from the sample of `curve` nearest to p towards p:
/// a label placed that way from a control point sits off the curve.
V2 away_from(const SvgDocument& doc, const P2& p, const std::vector<P2>& curve) {
  const P2 q = *std::min_element(curve.begin(), curve.end(), [&](const P2& a, const P2& b) { return distance(a, p) < distance(b, p); });
  return doc.map()(p) - doc.map()(q);
}

/// The unit page normal of a curve at a point, on the side away from `from` (page y down).
V2 normal_away(const SvgDocument& doc, const P2& at, const V2& tangent, const P2& from) {
  const P2 a = doc.map()(at), b = doc.map()(at + tangent);
  V2 n(-(b[1] - a[1]), b[0] - a[0]);
  if (dot(n, a - doc.map()(from)) < 0) n = -n;
  return n / norm(n);
}

std::string dist_text(double d) { return sci(d); }

/// "P" and i in subscript digits.
std::string point_name(std::size_t i) {
  static const char* const digit[] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084", "\u2085", "\u2086", "\u2087", "\u2088", "\u2089"};
  std::string s = "P";
  for (const char ch : std::to_string(i)) s += digit[ch - '0'];
  return s;
}

}  // namespace constructions
}  // namespace

// ---------------------------------------------------------------------------------------
// de Boor's construction.

Figure de_boor_construction() {
  using namespace constructions;
  const int p = 3;
  const std::vector<double> U{0, 0, 0, 0, 1, 2, 4, 5, 5, 5, 5};
  const std::vector<P2> P{{0.0, 0.2}, {0.7, 2.9}, {2.6, 3.7}, {4.0, -0.8}, {6.4, -1.0}, {7.2, 3.3}, {8.8, 2.6}};
  const Spline c(p, U, P);
  const double u = 2.6;
  // The span k with U_k <= u < U_{k+1}: the functions N_{k-p..k} are not zero at u.
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  // The levels d_i^r, i = k-p+r .. k: d_i^r = (1 - a) d_{i-1}^{r-1} + a d_i^{r-1} with
  // a = (u - U_i) / (U_{i+p-r+1} - U_i) [PT97, eq. 5.15; deBoor78], written here.
  std::vector<std::vector<P2>> level{{P.begin() + static_cast<std::ptrdiff_t>(k - p), P.begin() + static_cast<std::ptrdiff_t>(k + 1)}};
  std::vector<std::vector<double>> alpha;
  for (int r = 1; r <= p; ++r) {
    const auto& prev = level.back();
    std::vector<P2> next;
    std::vector<double> as;
    for (std::size_t i = k - p + r; i <= k; ++i) {
      const double a = (u - U[i]) / (U[i + p - r + 1] - U[i]);
      const std::size_t j = i - (k - p + r);
      next.push_back(lerp(prev[j], prev[j + 1], a));
      as.push_back(a);
    }
    level.push_back(next);
    alpha.push_back(as);
  }
  const P2 point = level.back().front();
  // Checks: the curve's own evaluation, and each level among the control points after
  // inserting u r times (insert_knot, [PT97, A5.1]): positions k-p+r .. k.
  const double to_eval = distance(point, c(u));
  double to_insertion = 0;
  for (int r = 1; r <= p; ++r) {
    const Spline q = c.insert_knot(u, r);
    for (std::size_t i = k - p + r; i <= k; ++i) to_insertion = std::max(to_insertion, distance(q.points()[i], level[r][i - (k - p + r)]));
  }

  SvgDocument doc(fig_width, 430);
  doc.title("de Boor's construction at u = 2.6");
  doc.set_map(PageMap::fit(grown(c.control_bounds(), 0.45), {16, 16, 560, 400}));
  const auto line = sampled(c, 400);
  const std::array<std::string, 4> colours = {polygon_grey, "#2a9d5c", "#d9641c", accent};
  doc.polyline(P, polygon_paint());
  doc.curve(pieces(c), curve_paint(ink, 2.6));
  doc.polyline(level[0], thin(ink, 1.6));
  for (std::size_t r = 1; r + 1 < level.size(); ++r) doc.polyline(level[r], thin(colours[r], 1.6));
  for (std::size_t r = 1; r < level.size(); ++r) {
    for (const auto& q : level[r]) dot(doc, q, colours[r], r + 1 == level.size() ? 5.5 : 4);
  }
  control_points(doc, P);
  LabelPlacer labels(doc);
  labels.avoid(line);
  labels.avoid(P);
  for (const auto& l : level) labels.avoid(l);
  for (std::size_t i = 0; i < P.size(); ++i) labels.place(P[i], point_name(i), math(15), away_from(doc, P[i], line), 7);
  labels.place(point, "C(2.6)", math(15, Anchor::middle, accent), normal_away(doc, point, c.derivative_at(u), level[1][1]), 9);

  // Right: the basis functions over the knots, the p + 1 that act at u drawn strong.
  const PageRect plot{620, 60, 240, 130};
  doc.set_map(PageMap::fit(Box2{{0.0, 0.0}, {5.0, 1.0}}, plot, Aspect::stretch));
  const std::size_t n = P.size();
  std::vector<std::vector<P2>> graphs(n);
  std::vector<double> N(p + 1);
  for (int j = 0; j <= 300; ++j) {
    const double x = std::min(5.0 * j / 300, std::nextafter(5.0, 0.0));
    const std::size_t s = static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), x) - U.begin()) - 1;
    basis_functions<double>(U, p, s, x, N);
    for (std::size_t i = 0; i < n; ++i) {
      const double v = i + p >= s && i <= s ? N[i + p - s] : 0.0;
      graphs[i].push_back({x, v});
    }
  }
  doc.line({0.0, 0.0}, {5.0, 0.0}, thin("#9aa3ad"));
  doc.line({0.0, 0.0}, {0.0, 1.0}, thin("#9aa3ad"));
  doc.polygon(std::vector<P2>{{U[k], 0.0}, {U[k + 1], 0.0}, {U[k + 1], 1.0}, {U[k], 1.0}}, Paint{.fill = "#f6d776", .fill_opacity = 0.35});
  for (std::size_t i = 0; i < n; ++i) {
    const bool acts = i + p >= k && i <= k;
    doc.polyline(graphs[i], acts ? curve_paint(ramp(static_cast<double>(i - (k - p)) / p), 2) : thin(light, 1.2));
  }
  doc.line({u, 0.0}, {u, 1.0}, stroke(accent, 1.2, "3 3"));
  for (std::size_t j = 0; j < U.size(); ++j) {
    if (j > 0 && U[j] == U[j - 1]) continue;
    doc.line({U[j], 0.0}, {U[j], -0.06}, thin(ink, 1.2));
    auto t = small(10);
    t.dy = 16;
    doc.text({U[j], 0.0}, plain(U[j], 0) + (knot_multiplicity<double>(U, U[j]) > 1 ? "\u00d7" + std::to_string(knot_multiplicity<double>(U, U[j])) : ""), t);
  }
  {
    auto t = small(10, Anchor::end);
    t.dx = -4;
    t.dy = 4;
    doc.text({0.0, 1.0}, "1", t);
    auto tu = math(12, Anchor::middle, accent);
    tu.dy = -6;
    doc.text({u, 1.0}, "u", tu);
  }
  doc.set_map(PageMap{});
  doc.text({plot.x, plot.y - 22}, "N\u1d62,\u2083(u): N\u2082 \u2026 N\u2085 act on [2, 4)", heading(12));
  // The legend of the levels.
  const std::array<std::string, 4> names = {"d\u1d62\u2070 = P\u2082 \u2026 P\u2085 (the span's points)", "level 1: 3 points",
                                            "level 2: 2 points", "level 3: C(u)"};
  for (std::size_t r = 0; r < 4; ++r) {
    const double y = 262 + 24.0 * r;
    doc.line({620, y - 4}, {650, y - 4}, thin(r == 0 ? ink : colours[r], 2));
    if (r > 0) dot(doc, {635, y - 4}, colours[r], r == 3 ? 5 : 4);
    doc.text({660, y}, names[r], small(11.5, Anchor::start, "#222"));
  }

  std::string rows;
  for (int r = 1; r <= p; ++r) {
    rows += "<tr><td>" + std::to_string(r) + "</td>";
    for (std::size_t i = 0; i < alpha[r - 1].size(); ++i) rows += "<td>" + fixed(alpha[r - 1][i], 3) + "</td>";
    for (std::size_t i = alpha[r - 1].size(); i < 3; ++i) rows += "<td></td>";
    rows += "</tr>";
  }
  std::string cap =
      "The cubic B-spline with knots 0, 0, 0, 0, 1, 2, 4, 5, 5, 5, 5 evaluated at u = 2.6 by repeated linear interpolation, "
      "as de Casteljau's algorithm does for a B&eacute;zier curve, but with a different ratio on every edge: u lies in the span "
      "[U<sub>5</sub>, U<sub>6</sub>) = [2, 4), so only P<sub>2</sub> &hellip; P<sub>5</sub> take part (right: the four basis "
      "functions not zero there), and level r replaces d<sub>i&minus;1</sub>, d<sub>i</sub> by (1 &minus; &alpha;) "
      "d<sub>i&minus;1</sub> + &alpha; d<sub>i</sub> with &alpha; = (u &minus; U<sub>i</sub>) / (U<sub>i+p&minus;r+1</sub> "
      "&minus; U<sub>i</sub>) [PT97, eq. 5.15]:"
      "<table><tr><th>level r</th><th>&alpha; (first)</th><th>&alpha;</th><th>&alpha; (last)</th></tr>" + rows +
      "</table>The last point is the curve point; the library's <code>c(u)</code> differs from it by " + dist_text(to_eval) +
      ". Each level is also what knot insertion leaves: after inserting u r times (<code>insert_knot</code>), the new "
      "control points are the level-r points, to " + dist_text(to_insertion) + ".";
  return {"de-boor", "de Boor's construction at u = 2.6", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// Blossoming.

Figure blossoming() {
  using namespace constructions;
  const std::vector<P2> P{{0.0, 0.0}, {1.0, 3.2}, {4.4, 3.6}, {5.6, 0.3}};
  const Bezier<double, 2> c(P);
  const auto b = [&](double u1, double u2, double u3) {
    const std::array<double, 3> u{u1, u2, u3};
    return blossom<P2, double>(std::span<const P2>(P), std::span<const double>(u));
  };
  const double t = 0.4, a = 0.2, e = 0.75;  // e: the portion's end (b would shadow the blossom)
  SvgDocument doc(fig_width, 400);
  doc.title("The blossom of a cubic");
  const auto line = sampled(c, 400);
  const Box2 box = grown(c.control_bounds(), 0.5);
  const std::array<std::string, 4> colours = {polygon_grey, "#2a9d5c", "#d9641c", accent};

  // Left: de Casteljau's points at t, named by their blossom arguments.
  doc.set_map(PageMap::fit(box, {10, 40, 425, 340}));
  doc.polyline(P, polygon_paint());
  doc.curve(c, curve_paint(ink, 2.6));
  const std::vector<std::vector<std::array<double, 3>>> args = {
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}}, {{0, 0, t}, {0, t, 1}, {t, 1, 1}}, {{0, t, t}, {t, t, 1}}, {{t, t, t}}};
  const auto name = [&](const std::array<double, 3>& u) {
    std::string s;
    for (const double v : u) s += v == 0 ? "0" : (v == 1 ? "1" : "t");
    return s;
  };
  for (std::size_t r = 1; r < args.size(); ++r) {
    std::vector<P2> pts;
    for (const auto& u : args[r]) pts.push_back(b(u[0], u[1], u[2]));
    if (pts.size() > 1) doc.polyline(pts, thin(colours[r], 1.5));
    for (const auto& q : pts) dot(doc, q, colours[r], r == 3 ? 5.5 : 4);
  }
  control_points(doc, P);
  LabelPlacer labels(doc);
  labels.avoid(line);
  labels.avoid(P);
  for (std::size_t r = 1; r < args.size(); ++r) {
    std::vector<P2> pts;
    for (const auto& u : args[r]) pts.push_back(b(u[0], u[1], u[2]));
    labels.avoid(pts);
    for (const auto& q : pts) labels.avoid_point(q, 4);
  }
  for (std::size_t r = 0; r < args.size(); ++r) {
    for (const auto& u : args[r]) {
      const P2 q = b(u[0], u[1], u[2]);
      const V2 dir = r == 3 ? normal_away(doc, q, c.derivative_at(t), b(0, t, 1)) : (r == 0 ? away_from(doc, q, line) : V2(0.0, 1.0));
      labels.place(q, name(u), math(13.5, Anchor::middle, r == 0 ? "#222" : colours[r]), dir, r == 0 ? 7 : 6);
    }
  }
  doc.set_map(PageMap{});
  doc.text({20, 24}, "de Casteljau at t = 0.4: every point a blossom value", heading(12.5));

  // Right: the portion [a, e] of the curve: its control points are b(a,a,a) ... b(e,e,e).
  doc.set_map(PageMap::fit(box, {445, 40, 425, 340}));
  doc.polyline(P, polygon_paint(light));
  doc.curve(c, curve_paint(light, 2));
  const Bezier<double, 2> part = c.portion(a, e);
  const std::array<std::array<double, 3>, 4> part_args = {{{a, a, a}, {a, a, e}, {a, e, e}, {e, e, e}}};
  std::vector<P2> Q;
  for (const auto& u : part_args) Q.push_back(b(u[0], u[1], u[2]));
  doc.polyline(Q, thin(accent, 1.6));
  doc.curve(part, curve_paint(accent, 2.8));
  control_points(doc, Q, accent);
  const char* part_names[] = {"aaa", "aab", "abb", "bbb"};
  const auto part_line = sampled(part, 200);
  LabelPlacer part_labels(doc);
  part_labels.avoid(line);
  part_labels.avoid(P);
  part_labels.avoid(Q);
  for (std::size_t i = 0; i < Q.size(); ++i) {
    const V2 dir = i == 0 || i == 3 ? normal_away(doc, Q[i], c.derivative_at(part_args[i][0]), Q[i == 0 ? 1 : 2]) : away_from(doc, Q[i], part_line);
    part_labels.place(Q[i], part_names[i], math(13.5, Anchor::middle, accent), dir, 7);
  }
  doc.set_map(PageMap{});
  doc.text({455, 24}, "the portion [a, b] = [0.2, 0.75]: points b(a,a,b) \u2026", heading(12.5));

  // Measured: the portion against two de Casteljau splits (independent of the blossom),
  // symmetry, the diagonal, and affinity in each argument.
  const Bezier<double, 2> by_splits = c.split(e).left.split(a / e).right;
  double portion_gap = 0, split_gap = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    portion_gap = std::max(portion_gap, distance(Q[i], part.points()[i]));
    split_gap = std::max(split_gap, distance(Q[i], by_splits.points()[i]));
  }
  double symmetry = 0, diagonal = 0, affine = 0;
  for (int i = 0; i <= 20; ++i) {
    const double x = i / 20.0, y = 1 - x * x, z = 0.3 + 0.5 * x;
    symmetry = std::max({symmetry, distance(b(x, y, z), b(z, x, y)), distance(b(x, y, z), b(y, z, x))});
    diagonal = std::max(diagonal, distance(b(x, x, x), c(x)));
    const double lam = 0.37;
    const P2 mixed = P2::from_vector(lam * b(x, y, z).to_vector() + (1 - lam) * b(2.0 - x, y, z).to_vector());
    affine = std::max(affine, distance(b(lam * x + (1 - lam) * (2.0 - x), y, z), mixed));
  }
  std::string cap =
      "The blossom (polar form) b(u<sub>1</sub>, u<sub>2</sub>, u<sub>3</sub>) of a cubic is the one function that is "
      "symmetric, affine in each argument, and equal to the curve on the diagonal, b(t, t, t) = c(t) [Ramshaw87]; "
      "<code>blossom</code> computes it by de Casteljau's algorithm with a different parameter at each level. Left: the "
      "control points are b(0,0,0), b(0,0,1), b(0,1,1), b(1,1,1), and every point of de Casteljau's construction at t is a "
      "blossom value, an argument 0 or 1 replaced by t at each level (labels: the arguments). Right: the control points of "
      "the curve on [a, b] are b(a,a,a), b(a,a,b), b(a,b,b), b(b,b,b): they equal <code>portion(0.2, 0.75)</code> to " +
      sci(portion_gap) + " and the polygon of two de Casteljau splits (at 0.75, then at 0.2/0.75 of the left half) to " +
      sci(split_gap) + ". Measured on 21 argument triples: symmetry to " + sci(symmetry) + ", the diagonal against "
      "<code>c(t)</code> to " + sci(diagonal) + ", affinity in the first argument (also outside [0, 1]) to " + sci(affine) + ".";
  return {"blossom", "Blossoming: the polar form of a cubic", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// A family of NURBS as one weight changes.

Figure nurbs_weight_family() {
  using namespace constructions;
  const int p = 3;
  const std::vector<double> U{0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4};
  const std::vector<P2> P{{0.0, 0.0}, {0.8, 2.4}, {2.6, 3.0}, {4.0, 4.6}, {5.4, 3.0}, {7.2, 2.4}, {8.0, 0.0}};
  const std::size_t moved = 3;
  const std::vector<double> ws{0.2, 0.5, 1, 2, 5, 20};
  const double u0 = 2;  // where N_3,3 peaks: the point moved most
  SvgDocument doc(fig_width, 400);
  doc.title("A family of NURBS: the weight of P3 from 0.2 to 20");
  doc.set_map(PageMap::fit(grown(box_of<double, 2>(P), 0.4), {16, 16, 640, 370}));
  doc.polyline(P, polygon_paint());
  std::vector<P2> at_u0;
  double pulled_last = 0;
  for (std::size_t k = 0; k < ws.size(); ++k) {
    std::vector<double> w(P.size(), 1.0);
    w[moved] = ws[k];
    const Nurbs<double, 2> c(p, U, P, w);
    doc.curve(pieces(c), curve_paint(ramp(static_cast<double>(k) / (ws.size() - 1)), ws[k] == 1 ? 2.8 : 2));
    at_u0.push_back(c(u0));
    pulled_last = distance(c(u0), P[moved]);
  }
  // The points C(u0; w) lie on one line through P3 [PT97, ch. 4].
  doc.line(at_u0.front(), P[moved], stroke(text_grey, 1, "2 3"));
  for (std::size_t k = 0; k < at_u0.size(); ++k) dot(doc, at_u0[k], ramp(static_cast<double>(k) / (ws.size() - 1)), 3.6);
  control_points(doc, P);
  doc.circle(P[moved], 8, Paint{.stroke = accent, .stroke_width = 1.6});
  const P2 mid{4.0, 1.5};
  LabelPlacer labels(doc);
  labels.avoid(P);
  for (const double w3 : ws) {
    std::vector<double> w(P.size(), 1.0);
    w[moved] = w3;
    labels.avoid_curve(Nurbs<double, 2>(p, U, P, w), 300);
  }
  labels.avoid(std::vector<P2>{at_u0.front(), P[moved]});
  for (std::size_t i = 0; i < P.size(); ++i) {
    const P2 q = doc.map()(P[i]), m = doc.map()(mid);
    labels.place(P[i], point_name(i), math(15), q - m, i == moved ? 11 : 7);
  }
  double off_line = 0;
  const V2 d = P[moved] - at_u0.front();
  for (const auto& q : at_u0) off_line = std::max(off_line, std::abs(cross(d, q - at_u0.front())) / norm(d));
  // Legend.
  doc.set_map(PageMap{});
  doc.text({690, 60}, "weight of P\u2083", heading(12));
  for (std::size_t k = 0; k < ws.size(); ++k) {
    const double y = 88 + 24.0 * k;
    doc.line({690, y - 4}, {720, y - 4}, curve_paint(ramp(static_cast<double>(k) / (ws.size() - 1)), 2.4));
    doc.text({730, y}, "w\u2083 = " + plain(ws[k], ws[k] < 1 ? 1 : 0) + (ws[k] == 1 ? " (B-spline)" : ""), small(12, Anchor::start, "#222"));
  }
  doc.line({690, 246}, {720, 246}, stroke(text_grey, 1, "2 3"));
  doc.text({730, 250}, "C(2) for each w\u2083", small(12, Anchor::start, "#222"));

  std::string cap =
      "A clamped cubic NURBS with knots 0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4 and all weights 1 except w<sub>3</sub>, the weight "
      "of P<sub>3</sub>, from 0.2 to 20 (<code>nurbs</code> curves drawn from their exact rational pieces). Raising "
      "w<sub>3</sub> pulls the curve towards P<sub>3</sub>, lowering it pushes the curve away, and only on the spans "
      "(1, 4) where N<sub>3,3</sub> is not zero: the ends stay. For a fixed u the points C(u) of the family lie on one "
      "straight line through P<sub>3</sub> [PT97, ch. 4]: the six points at u = 2 are within " + sci(off_line) +
      " of the line through the first and P<sub>3</sub>; at w<sub>3</sub> = 20 the point is " + fixed(pulled_last, 3) +
      " from P<sub>3</sub>.";
  return {"nurbs-weights", "A family of NURBS as one weight changes", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// Knot removal.

Figure knot_removal() {
  using namespace constructions;
  const Spline c(3, {0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4}, {{0.0, 0.3}, {1.0, 2.9}, {2.8, 3.4}, {4.0, 1.0}, {5.6, 0.6}, {6.8, 3.2}, {8.2, 2.2}});
  // Left: insert 2.5 twice, then remove it twice: the original comes back.
  const Spline twice = c.insert_knot(2.5, 2);
  const io::Json back = run_command("remove_knot", {{"curve", spline_json(twice)}, {"knot", 2.5}, {"times", 2}, {"tolerance", 1e-9}});
  const Spline restored = spline_from_json(back["curve"]);
  double restored_gap = restored.points().size() == c.points().size() ? 0 : INFINITY;
  for (std::size_t i = 0; i < std::min(restored.points().size(), c.points().size()); ++i)
    restored_gap = std::max(restored_gap, distance(restored.points()[i], c.points()[i]));
  // Right: the original knot 2 removed, refused within 0.3 and allowed within 1.
  const io::Json refused = run_command("remove_knot", {{"curve", spline_json(c)}, {"knot", 2}, {"tolerance", 0.3}});
  const io::Json allowed = run_command("remove_knot", {{"curve", spline_json(c)}, {"knot", 2}, {"tolerance", 1.0}});
  const Spline fewer = spline_from_json(allowed["curve"]);
  double moved = 0;
  for (int i = 0; i <= 4000; ++i) moved = std::max(moved, distance(c(4.0 * i / 4000), fewer(4.0 * i / 4000)));

  SvgDocument doc(fig_width, 360);
  doc.title("Knot removal");
  const Box2 box = grown(c.control_bounds(), 0.5);
  doc.set_map(PageMap::fit(box, {10, 40, 425, 300}));
  doc.polyline(twice.points(), thin(accent, 1.4));
  control_points(doc, twice.points(), accent, 3.2);
  doc.polyline(restored.points(), polygon_paint(ink, 1.4));
  doc.curve(pieces(c), curve_paint(ink, 2.6));
  control_points(doc, restored.points(), ink, 4.2);
  doc.set_map(PageMap{});
  doc.text({20, 24}, "2.5 inserted twice (red), removed twice (blue)", heading(12.5));
  doc.set_map(PageMap::fit(box, {445, 40, 425, 300}));
  doc.polyline(c.points(), polygon_paint(polygon_grey, 1.2));
  doc.polyline(fewer.points(), thin(accent, 1.4));
  doc.curve(pieces(c), curve_paint(ink, 2.2));
  doc.curve(pieces(fewer), curve_paint(accent, 2.2));
  control_points(doc, c.points(), polygon_grey, 3.4);
  control_points(doc, fewer.points(), accent, 3.8);
  doc.set_map(PageMap{});
  doc.text({455, 24}, "the knot 2 removed within a tolerance of 1 (red)", heading(12.5));

  std::string cap =
      "<code>remove_knot</code> undoes knot insertion [PT97, A5.8]. Left: the cubic B-spline with knots 0, 0, 0, "
      "0, 1, 2, 3, 4, 4, 4, 4 (blue, 7 points) after inserting u = 2.5 twice (red, 9 points); removing 2.5 twice (removed: " +
      std::to_string(back["removed"].get<int>()) + ") gives back the original control points to " + sci(restored_gap) +
      ". Right: the original knot 2 cannot go without moving the curve: within a tolerance of 0.3 it is refused (removed: " +
      std::to_string(refused["removed"].get<int>()) + "), within 1 it goes (removed: " + std::to_string(allowed["removed"].get<int>()) +
      ", " + std::to_string(fewer.points().size()) + " points left) and the curve moves by " + fixed(moved, 3) +
      " (4001 parameters): within the tolerance, which the command guarantees by re-inserting the knot and comparing "
      "control points, not by sampling.";
  return {"knot-removal", "Knot removal", doc.str(), cap};
}

// ---------------------------------------------------------------------------------------
// A space curve with its Frenet and rotation-minimizing frames.

Figure space_curve_frames() {
  using namespace constructions;
  // A cubic S in space: the curvature is small but not zero near the middle, where the
  // Frenet normal turns over.
  const io::Json curve = {{"type", "bezier"}, {"points", {{0.0, 0.0, 0.0}, {3.2, 3.4, 1.2}, {2.6, -3.0, 1.4}, {6.0, 0.0, 2.4}}}};
  std::vector<double> ts_draw, ts_fine, ts_curve;
  for (int i = 0; i <= 14; ++i) ts_draw.push_back(i / 14.0);
  for (int i = 0; i <= 240; ++i) ts_fine.push_back(i / 240.0);
  for (int i = 0; i <= 300; ++i) ts_curve.push_back(i / 300.0);
  const io::Json pts = run_command("eval", {{"curve", curve}, {"t", ts_curve}})["points"];
  const io::Json at = run_command("eval", {{"curve", curve}, {"t", ts_draw}})["points"];
  const char* methods[] = {"frenet", "rotation_minimizing"};
  // An oblique view from above: azimuth -20 degrees about z, elevation 55 degrees.
  const double az = -20 * std::numbers::pi / 180, el = 55 * std::numbers::pi / 180;
  const auto view = [&](double x, double y, double z) {
    const double xr = std::cos(az) * x + std::sin(az) * y, yr = -std::sin(az) * x + std::cos(az) * y;
    return P2(xr, z * std::cos(el) + yr * std::sin(el));
  };
  const auto view_json = [&](const io::Json& p) { return view(p[0].get<double>(), p[1].get<double>(), p[2].get<double>()); };
  std::vector<P2> projected;
  for (const auto& p : pts) projected.push_back(view_json(p));
  const Box2 box = grown(box_of<double, 2>(projected), 1.1);

  SvgDocument doc(fig_width, 400);
  doc.title("Frenet and rotation-minimizing frames of a space curve");
  std::array<double, 2> twist{};
  std::array<double, 2> flips{};
  const double len = 0.7;
  for (int m = 0; m < 2; ++m) {
    doc.set_map(PageMap::fit(box, {10.0 + 435 * m, 36, 425, 320}));
    doc.polyline(projected, curve_paint(ink, 2.4));
    const io::Json fr = run_command("frames", {{"curve", curve}, {"t", ts_draw}, {"method", methods[m]}});
    for (std::size_t i = 0; i < ts_draw.size(); ++i) {
      const P2 o = view_json(at[i]);
      const auto tip = [&](const io::Json& v) {
        return view(at[i][0].get<double>() + len * v[0].get<double>(), at[i][1].get<double>() + len * v[1].get<double>(),
                    at[i][2].get<double>() + len * v[2].get<double>());
      };
      doc.arrow(o, tip(fr["tangents"][i]), thin(polygon_grey, 1.2), 6);
      if (!fr["normals"][i].is_null()) doc.arrow(o, tip(fr["normals"][i]), thin(accent, 1.4), 6);
      if (!fr["binormals"][i].is_null()) doc.arrow(o, tip(fr["binormals"][i]), thin(green, 1.4), 6);
    }
    // The rotation of the normal about the tangent from one frame to the next (fine
    // steps): the normal carried to the next tangent by the smallest rotation, then the
    // angle to the next normal. Zero for an exactly rotation-minimizing frame.
    const io::Json fine = run_command("frames", {{"curve", curve}, {"t", ts_fine}, {"method", methods[m]}});
    const auto vec = [](const io::Json& v) { return std::array<double, 3>{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; };
    const auto dot3 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto cross3 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    for (std::size_t i = 0; i + 1 < ts_fine.size(); ++i) {
      if (fine["normals"][i].is_null() || fine["normals"][i + 1].is_null()) throw std::runtime_error("frames: no normal");
      const auto t0 = vec(fine["tangents"][i]), t1 = vec(fine["tangents"][i + 1]);
      const auto n0 = vec(fine["normals"][i]), n1 = vec(fine["normals"][i + 1]);
      // Rodrigues: the rotation about t0 x t1 by the angle between them, applied to n0.
      const auto axis = cross3(t0, t1);
      const double s = std::sqrt(dot3(axis, axis)), cth = dot3(t0, t1);
      std::array<double, 3> carried = n0;
      if (s > 0) {
        const std::array<double, 3> k{axis[0] / s, axis[1] / s, axis[2] / s};
        const auto kxn = cross3(k, n0);
        const double kn = dot3(k, n0);
        for (int j = 0; j < 3; ++j) carried[j] = n0[j] * cth + kxn[j] * s + k[j] * kn * (1 - cth);
      }
      const double angle = std::atan2(dot3(cross3(carried, n1), t1), dot3(carried, n1));
      twist[m] += std::abs(angle);
      flips[m] = std::max(flips[m], std::abs(angle));
    }
    doc.set_map(PageMap{});
    doc.text({20.0 + 435 * m, 24}, m == 0 ? "Frenet frames (T, N, B)" : "rotation-minimizing frames (double reflection)", heading(12.5));
  }
  // Legend.
  doc.set_map(PageMap{});
  const std::array<std::pair<std::string, std::string>, 3> keys = {{{polygon_grey, "tangent T"}, {accent, "normal N"}, {green, "binormal B = T \u00d7 N"}}};
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const double x = 40 + 200.0 * i;
    doc.arrow({x, 380}, {x + 30, 380}, thin(keys[i].first, 1.6), 6);
    doc.text({x + 40, 384}, keys[i].second, small(12, Anchor::start, "#222"));
  }
  std::string cap =
      "A cubic B&eacute;zier curve in space, an S rising along z, seen obliquely, with 15 frames of "
      "the <code>frames</code> command each way (arrows of length 0.7). Left, <code>frenet</code>: the normal points to "
      "the centre of curvature, so it turns over around the S's inflection, where the curvature is least: the normal "
      "rotates about the tangent by " + fixed(twist[0], 2) + " rad in all along the curve (241 frames; at most " +
      fixed(flips[0], 3) + " rad between neighbours). Right, <code>rotation_minimizing</code> (the double reflection "
      "method [WangJuttlerZhengLiu08], started from the Frenet frame at t = 0): the normal does not spin about the tangent, "
      "it rotates by " + sci(twist[1]) + " rad in all, which is what sweeps and tubes along a path need.";
  return {"frames", "Frames along a space curve: Frenet and rotation-minimizing", doc.str(), cap};
}

}  // namespace casteljau::gallery
