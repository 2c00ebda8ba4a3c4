// Gallery figures of the geometric queries (issue 8): closest points from a grid of points,
// and a curvature comb with its inflections, cusp and equal-arc-length samples.
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

using Bez = Bezier<double, 2>;



}  // namespace

Figure closest_points() {
  const Bez c({{0.0, 0.0}, {1.0, 3.2}, {3.2, -1.2}, {4.4, 2.2}, {5.4, 0.4}});
  Box<double, 2> box = c.control_bounds();
  SvgDocument doc(width, 380);
  doc.title("Closest points from a grid");
  doc.set_map(PageMap::fit(Box<double, 2>(P2(box.lo[0] - 0.4, box.lo[1] - 0.6), P2(box.hi[0] + 0.4, box.hi[1] + 0.6)),
                           {30, 20, 820, 340}));
  // Every grid point joined to its nearest point; a grid point with a tie (several
  // nearest points: it lies on the medial axis) in the accent colour with every segment.
  double worst = 0;  // how much nearer than project's answer the best of 2001 samples is
  int ties = 0, total = 0;
  std::vector<P2> dense;
  for (int k = 0; k <= 2000; ++k) dense.push_back(c(k / 2000.0));
  for (int i = 0; i <= 22; ++i) {
    for (int j = 0; j <= 12; ++j) {
      const P2 q(box.lo[0] - 0.3 + i * (box.hi[0] - box.lo[0] + 0.6) / 22, box.lo[1] - 0.5 + j * (box.hi[1] - box.lo[1] + 1.0) / 12);
      const auto r = project(c, q);
      ++total;
      double best = r.distance;
      for (const P2& s : dense) best = std::min(best, distance(s, q));
      worst = std::max(worst, r.distance - best);
      const bool tie = !r.all_t.empty();
      ties += tie;
      if (tie) {
        for (double t : r.all_t) doc.line(q, c(t), Paint{.stroke = accent, .stroke_width = 1.1});
      } else {
        doc.line(q, r.point, Paint{.stroke = grey, .stroke_width = 0.8});
      }
      dot(doc, q, tie ? accent : grey, 2.2);
    }
  }
  // The equidistance set (points with two nearest points): on a fine grid, where the
  // nearest parameter jumps between neighbours, a dot at the pair's midpoint.
  int jumps = 0;
  const int fx = 160, fy = 70;
  std::vector<double> tn(static_cast<std::size_t>((fx + 1) * (fy + 1)));
  auto fine = [&](int i, int j) {
    return P2(box.lo[0] - 0.3 + i * (box.hi[0] - box.lo[0] + 0.6) / fx, box.lo[1] - 0.5 + j * (box.hi[1] - box.lo[1] + 1.0) / fy);
  };
  for (int i = 0; i <= fx; ++i)
    for (int j = 0; j <= fy; ++j) tn[static_cast<std::size_t>(i * (fy + 1) + j)] = project(c, fine(i, j)).t;
  for (int i = 0; i <= fx; ++i) {
    for (int j = 0; j <= fy; ++j) {
      const double t = tn[static_cast<std::size_t>(i * (fy + 1) + j)];
      if (i < fx && std::abs(tn[static_cast<std::size_t>((i + 1) * (fy + 1) + j)] - t) > 0.1) {
        doc.circle(fine(i, j) + 0.5 * (fine(i + 1, j) - fine(i, j)), 1.3, Paint{.fill = accent});
        ++jumps;
      }
      if (j < fy && std::abs(tn[static_cast<std::size_t>(i * (fy + 1) + j + 1)] - t) > 0.1) {
        doc.circle(fine(i, j) + 0.5 * (fine(i, j + 1) - fine(i, j)), 1.3, Paint{.fill = accent});
        ++jumps;
      }
    }
  }
  doc.curve(c, Paint{.stroke = ink, .stroke_width = 2.8});
  std::string cap = "Each of " + std::to_string(total) + " grid points is joined to its nearest point on a quartic, found by "
                    "<code>project()</code>: the candidates are the ends and every root of (C(t) &minus; P)&middot;C&prime;(t) "
                    "(degree 7), so the minimum is global. Against 2001 samples per point, no sample is nearer than the answer "
                    "(largest excess " + sci(worst) + "). The red dots (" + std::to_string(jumps) + ") trace the equidistance set: "
                    "on a 161 &times; 71 grid, the midpoints of neighbours whose nearest parameters differ by more than 0.1, "
                    "where the nearest point jumps from one branch of the curve to another; a point exactly on it has two "
                    "nearest points, which <code>project()</code> lists in <code>all_t</code> (ties within 1e-12; " +
                    std::to_string(ties) + " of the coarse grid's points fall on it).";
  return {"closest-points", "Closest points and the equidistance set", doc.str(), cap};
}

Figure curvature_comb() {
  // A cubic with a loop-free inflection and, beside it, a cusp.
  const Bez a({{0.0, 0.0}, {1.2, 2.4}, {2.2, -1.8}, {3.6, 0.8}});
  const Bez b({{4.4, 0.0}, {6.6, 2.4}, {4.4, 2.4}, {6.6, 0.0}});
  SvgDocument doc(width, 360);
  doc.title("Curvature comb, inflections, cusp, equal arc lengths");
  doc.set_map(PageMap::fit(Box<double, 2>(P2(-0.4, -1.6), P2(7.0, 2.6)), {30, 20, 820, 330}));
  int samples_total = 0;
  double spread = 0;  // largest relative deviation of the sample spacing (arc length)
  for (const Bez* c : {&a, &b}) {
    // Comb: the normal scaled by -curvature (pointing away from the turn), 0.25 units per
  // unit of curvature.
    for (int i = 0; i <= 120; ++i) {
      const double t = i / 120.0;
      const auto d1 = c->derivative_at(t);
      const auto k = curvature(*c, t);
      if (!k || norm(d1) < 1e-9) continue;
      const Vector<double, 2> n(-d1[1] / norm(d1), d1[0] / norm(d1));
      const double len = -0.25 * *k;
      if (std::abs(len) > 0.8) continue;  // near the cusp curvature grows without bound: cut
      doc.line((*c)(t), (*c)(t) + len * n, Paint{.stroke = "#a8c5e0", .stroke_width = 0.9});
    }
    doc.curve(*c, Paint{.stroke = ink, .stroke_width = 2.6});
    const auto f = features(*c);
    for (double t : f.inflections) dot(doc, (*c)(t), green, 5);
    for (double t : f.cusps) dot(doc, (*c)(t), accent, 5.5);
    // Equal-arc-length resampling: 13 points 1/12 of the length apart.
    const auto u = equal_length_parameters(*c, 13);
    const double step = arc_length(*c) / 12;
    for (std::size_t i = 0; i < u.size(); ++i) {
      doc.circle((*c)(u[i]), 2.6, Paint{.stroke = ink, .stroke_width = 1.2, .fill = "white"});
      if (i > 0) spread = std::max(spread, std::abs(arc_length(*c, u[i - 1], u[i]) - step) / step);
      ++samples_total;
    }
  }
  doc.set_map(PageMap{});
  dot(doc, {40, 318}, green, 5);
  doc.text({52, 322}, "inflection", label());
  dot(doc, {140, 318}, accent, 5.5);
  doc.text({152, 322}, "cusp", label());
  doc.circle({210, 318}, 2.6, Paint{.stroke = ink, .stroke_width = 1.2, .fill = "white"});
  doc.text({220, 322}, "equal arc-length samples", label());
  std::string cap = "Curvature combs of two cubics (teeth of length proportional to the signed curvature), with the "
                    "parameters of <code>features()</code>: the inflection, a sign change of x&prime;y&Prime; &minus; "
                    "y&prime;x&Prime;, and the cusp, a double root of a coordinate of the hodograph where the velocity "
                    "vanishes (the comb is cut there: curvature is undefined). The " + std::to_string(samples_total) +
                    " circles are <code>equal_length_parameters()</code>: consecutive samples are equally far apart along the "
                    "curve to " + sci(spread) + " relative, through the cusp too (the quadrature splits there).";
  return {"curvature-comb", "Curvature comb, features and equal arc lengths", doc.str(), cap};
}

}  // namespace casteljau::gallery
