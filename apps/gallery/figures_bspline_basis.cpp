// Gallery figures of B-spline bases and fitting: the cubic basis functions for uniform,
// clamped and non-uniform knots (a repeated knot losing continuity), local control (one
// control point moved changes exactly p + 1 spans) and least-squares fits through noisy
// data, open and closed. Every picture and number is computed by the library here.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "casteljau/casteljau.hpp"
#include "casteljau/io/fit.hpp"
#include "casteljau/io/svg.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

namespace {

using Spline = BSpline<double, 2>;


/// A knot value as the captions write it: integers without decimals.
std::string knot_text(double u) { return u == std::floor(u) ? plain(u, 0) : plain(u, 1); }

/// Standard normal deviates from a seeded mt19937 (whose output the standard fixes) by
/// Box-Muller written here: std::normal_distribution differs between standard libraries,
/// and the gallery should draw the same figure everywhere.
class Noise {
 public:
  explicit Noise(std::uint32_t seed) : g_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(g_()) + 0.5) / 4294967296.0, u2 = (static_cast<double>(g_()) + 0.5) / 4294967296.0;
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
  }

 private:
  std::mt19937 g_;
};

// ---------------------------------------------------------------------------------------
// (a) Basis functions.

struct BasisPanel {
  std::string name;
  std::vector<double> U;
};

/// The values N_{i,p}(u), i = 0..n-1, by the library's basis_functions on the span of u.
std::vector<double> all_basis(const std::vector<double>& U, int p, double u) {
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  std::vector<double> out(n, 0.0);
  // Any u in [U_0, U_last): the span s with U_s <= u < U_{s+1}, clipped to p..n-1 would
  // miss the outer functions of unclamped knots, so the span is looked up on the whole
  // knot vector (every span s with p <= s and s + p + 1 <= size - 1 has p + 1 functions).
  std::size_t s = static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  std::vector<double> N(static_cast<std::size_t>(p) + 1);
  // Outside [U_p, U_n] fewer than p + 1 functions are defined: pad the knots by p copies
  // of the ends (functions N_{i,p} depend only on U_i..U_{i+p+1}, so the padding does not
  // change them) and evaluate there.
  std::vector<double> V(static_cast<std::size_t>(p), U.front());
  V.insert(V.end(), U.begin(), U.end());
  V.insert(V.end(), static_cast<std::size_t>(p), U.back());
  s += static_cast<std::size_t>(p);
  basis_functions<double>(V, p, s, u, N);
  for (int r = 0; r <= p; ++r) {
    const std::ptrdiff_t i = static_cast<std::ptrdiff_t>(s) - 2 * p + r;  // index in U's functions
    if (i >= 0 && i < static_cast<std::ptrdiff_t>(n)) out[static_cast<std::size_t>(i)] = N[static_cast<std::size_t>(r)];
  }
  return out;
}

}  // namespace

Figure bspline_basis_functions() {
  const int p = 3;
  const std::vector<BasisPanel> panels{
      {"uniform", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}},
      {"clamped", {0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4}},
      {"non-uniform, triple knot", {0, 0, 0, 0, 1, 1.6, 2.5, 2.5, 2.5, 3.4, 4, 4, 4, 4}},
  };
  SvgDocument doc(width, 300);
  doc.title("Cubic B-spline basis functions");
  const double pw = 256, gap_px = 34, top = 40, ph = 180;
  double partition = 0;  // the largest |sum_i N_i(u) - 1| over the domains
  double jump = 0;       // the first-derivative jump at the triple knot
  std::size_t jump_index = 0;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const auto& U = panels[k].U;
    const double x0 = 30 + static_cast<double>(k) * (pw + gap_px);
    const double a = U.front(), b = U.back();
    doc.set_map(PageMap::fit(Box2{{a, -0.08}, {b, 1.08}}, {x0, top, pw, ph}, Aspect::stretch));
    const std::size_t n = U.size() - p - 1;
    const double lo = U[p], hi = U[n];
    // The domain [U_p, U_n], where the functions sum to 1.
    doc.polygon(std::vector<P2>{{lo, 0.0}, {hi, 0.0}, {hi, 1.0}, {lo, 1.0}}, Paint{.fill = "#eef1f4"});
    // Axes: u along the bottom, the value up the left side (0 and 1 marked).
    doc.line({a, 0.0}, {b, 0.0}, stroke(grey, 1));
    doc.line({a, 0.0}, {a, 1.08}, stroke(grey, 1));
    doc.line({a, 1.0}, {b, 1.0}, stroke(light, 0.8, "3 3"));
    for (const double v : {0.0, 1.0}) {
      TextStyle t = label(10, Anchor::end, text_grey);
      t.dx = -5;
      t.dy = 3.5;
      doc.text({a, v}, plain(v, 0), t);
    }
    {
      TextStyle t = math(13, Anchor::start, text_grey);
      t.dx = 6;
      t.dy = 4;
      doc.text({b, 0.0}, "u", t);
    }
    // Curves sampled densely (400 parameters a panel).
    std::vector<std::vector<P2>> curves(n);
    std::vector<P2> sum;
    for (int j = 0; j <= 400; ++j) {
      const double u = std::min(a + (b - a) * j / 400.0, std::nextafter(b, a));
      const auto N = all_basis(U, p, u);
      double total = 0;
      for (std::size_t i = 0; i < n; ++i) {
        curves[i].push_back({u, N[i]});
        total += N[i];
      }
      if (u >= lo && u < hi) partition = std::max(partition, std::abs(total - 1));
      sum.push_back({u, total});
    }
    doc.polyline(sum, stroke(light, 1.2, "5 3"));
    for (std::size_t i = 0; i < n; ++i) doc.polyline(curves[i], stroke(std::string(io::palette(i)), 1.8));
    // Knot ticks, with the multiplicity where a knot repeats.
    for (std::size_t j = 0; j < U.size(); ++j) {
      if (j > 0 && U[j] == U[j - 1]) continue;
      const std::size_t m = knot_multiplicity<double>(U, U[j]);
      const bool interior = U[j] > lo && U[j] < hi;
      const bool marked = m > 1 && interior;
      doc.line({U[j], -0.04}, {U[j], 0.04}, stroke(marked ? accent : ink, marked ? 2 : 1.2));
      {
        TextStyle t = label(10, Anchor::middle, marked ? accent : "#222");
        t.dy = 13;
        doc.text({U[j], -0.04}, knot_text(U[j]), t);
      }
      if (m > 1) {
        TextStyle t = label(9.5, Anchor::middle, marked ? accent : text_grey);
        t.dy = 25;
        doc.text({U[j], -0.04}, "\u00d7" + std::to_string(m), t);
      }
      if (marked) {
        doc.line({U[j], 0.0}, {U[j], 1.0}, stroke(accent, 1, "2 3"));
        // The jump of N'_i at the knot, left and right limits from the spans on either side.
        const std::size_t right = static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), U[j]) - U.begin()) - 1;
        const std::size_t left = j - 1;  // the last span ending at U[j]
        const auto dl = basis_function_derivatives<double>(U, p, left, U[j], 1);
        const auto dr = basis_function_derivatives<double>(U, p, right, U[j], 1);
        std::vector<double> dleft(n, 0.0), dright(n, 0.0);
        for (int r = 0; r <= p; ++r) {
          dleft[left - p + static_cast<std::size_t>(r)] = dl[1][static_cast<std::size_t>(r)];
          dright[right - p + static_cast<std::size_t>(r)] = dr[1][static_cast<std::size_t>(r)];
        }
        for (std::size_t i = 0; i < n; ++i) {
          if (std::abs(dright[i] - dleft[i]) > jump) {
            jump = std::abs(dright[i] - dleft[i]);
            jump_index = i;
          }
        }
        TextStyle t2 = label(11, Anchor::middle, accent);
        t2.dy = -6;
        doc.text({U[j], 1.0}, "C\u2070 at u = " + knot_text(U[j]), t2);
      }
    }
    doc.set_map(PageMap{});
    doc.text({x0 - 24, 16}, panels[k].name + ": N\u1d62,\u2083(u)", heading(12.5));
    doc.text({x0 + pw / 2, top + ph + 48}, std::to_string(U.size()) + " knots (\u00d7m: repeated m times), " + std::to_string(n) + " functions",
             label(11, Anchor::middle, text_grey));
  }
  Figure f;
  f.id = "bspline-basis";
  f.title = "Cubic B-spline basis functions";
  f.svg = doc.str();
  f.caption = "The functions N<sub>i,3</sub>(u) of degree 3, computed by the Cox-de Boor recurrence "
              "(<code>basis_functions</code>, [PT97, A2.2]) on three knot vectors; ticks mark the knots with their values "
              "(&times;m: the multiplicity), the shaded band the domain [U<sub>p</sub>, U<sub>n</sub>], the dashed line the sum of the "
              "functions. Uniform knots 0..9: translates of one bell, summing to 1 only on [3, 6]. Clamped: the end knots "
              "repeated p + 1 = 4 times make the first and last function 1 at the ends (the curve starts at P<sub>0</sub>). "
              "Non-uniform with the knot 2.5 repeated 3 times: continuity there drops from C<sup>2</sup> to "
              "C<sup>p&minus;m</sup> = C<sup>0</sup>; N<sub>" + std::to_string(jump_index) + ",3</sub> reaches 1 with a corner, "
              "its slope jumping by " + fixed(jump, 3) + " (left and right derivatives from the spans on either side, "
              "[PT97, A2.3]). On the domains, |&Sigma; N<sub>i</sub> &minus; 1| &le; " + sci(partition) + " (1203 parameters).";
  return f;
}

Figure local_control() {
  const int p = 3;
  const std::vector<double> U{0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 9};
  const std::vector<P2> P{{0.0, 0.0}, {1.0, 1.6}, {2.0, 2.2}, {3.0, 0.6}, {4.0, 0.2}, {5.0, 1.2},
                          {6.0, 2.4}, {7.0, 2.0}, {8.0, 0.4}, {9.0, 0.6}, {10.0, 2.0}, {11.0, 1.2}};
  const std::size_t moved = 5;
  std::vector<P2> Q = P;
  Q[moved] = P[moved] + Vector<double, 2>(0.3, 2.0);
  const Spline a(p, U, P), b(p, U, Q);
  // Which spans changed: compare the exact Bézier pieces span by span (blossoms of the
  // p + 1 control points acting on the span, so a span whose points are untouched gives
  // bit-identical pieces).
  const Pieces<double, 2> pa = pieces(a), pb = pieces(b);
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < pa.size(); ++i)
    if (!(pa.segments()[i] == pb.segments()[i])) changed.push_back(i);
  const double u0 = pa.breaks()[changed.front()], u1 = pa.breaks()[changed.back() + 1];
  SvgDocument doc(width, 330);
  doc.title("Local control");
  Box2 box = a.control_bounds();
  box.add(b.control_bounds());
  doc.set_map(PageMap::fit(grown_relative(box, 0.06), {40, 20, width - 80, 270}));
  doc.polyline(P, stroke(grey, 1.2, "5 3"));
  doc.polyline(Q, stroke(grey, 1.3));
  doc.curve(pa, stroke(light, 2.4, "7 4"));
  // The moved curve: unchanged spans in ink, changed ones in the accent colour.
  for (std::size_t i = 0; i < pb.size(); ++i) {
    const bool c = std::find(changed.begin(), changed.end(), i) != changed.end();
    doc.curve(std::get<Bezier<double, 2>>(pb.segments()[i]), stroke(c ? accent : ink, c ? 3 : 2.4));
  }
  for (std::size_t i = 0; i < pb.size() + 1; ++i) doc.circle(b(pb.breaks()[i]), 2.6, Paint{.stroke = "#fff", .stroke_width = 0.8, .fill = ink});
  control_points(doc, P, grey, 3);
  control_points(doc, Q, "#3d4a5c");
  doc.arrow(P[moved], Q[moved], stroke(accent, 1.4), 7);
  TextStyle t = label(12, Anchor::start, accent);
  t.dx = 10;
  t.dy = 4;
  doc.text(Q[moved], "P\u2085 moved", t);
  doc.set_map(PageMap{});
  doc.text({50, 318}, std::to_string(changed.size()) + " of " + std::to_string(pa.size()) + " spans change (red): u in [" + knot_text(u0) +
                          ", " + knot_text(u1) + "] = [U\u2085, U\u2089], the support of N\u2085,\u2083; dots: the knots on the curve",
           label(12));
  Figure f;
  f.id = "local-control";
  f.title = "Local control";
  f.svg = doc.str();
  f.caption = "A clamped cubic B-spline with knots 0, 0, 0, 0, 1, .., 8, 9, 9, 9, 9 "
              "(dashed, light) and the same curve with P<sub>5</sub> moved. Only N<sub>5,3</sub> multiplies P<sub>5</sub>, and "
              "it vanishes outside [U<sub>5</sub>, U<sub>9</sub>): comparing the exact Bézier pieces of the two curves span by "
              "span finds " + std::to_string(changed.size()) + " changed spans (red), u &isin; [" + knot_text(u0) + ", " +
              knot_text(u1) + "], exactly p + 1 = " + std::to_string(p + 1) + "; the other " +
              std::to_string(pa.size() - changed.size()) + " pieces are bit for bit the same [PT97, §2.2 and §3.2: local support, local modification].";
  return f;
}

Figure noisy_fit() {
  Noise noise(20261130);
  // Open: y = sin x + 0.25 cos 3x on [0, 2 pi], 45 samples at jittered x, noise 0.1.
  const double sigma_open = 0.1, sigma_closed = 0.05;
  const auto truth = [](double x) { return std::sin(x) + 0.25 * std::cos(3 * x); };
  std::mt19937 spread(7);
  io::PointList open_data{2, {}};
  std::vector<P2> open_pts;
  for (int k = 0; k < 45; ++k) {
    const double jitter = 0.35 * (static_cast<double>(spread()) / 4294967296.0 - 0.5);
    const double x = std::clamp(2 * std::numbers::pi * (k + jitter) / 44.0, 0.0, 2 * std::numbers::pi);
    const P2 q{x, truth(x) + sigma_open * noise()};
    open_pts.push_back(q);
    open_data.push_back(q);
  }
  io::AnyFitRequest open_req;
  open_req.degree = 3;
  open_req.control_points = 9;
  const io::AnyFit open_fit = io::fit(open_data, open_req);
  const Spline& oc = std::get<Spline>(open_fit.curve);
  // Closed: a three-lobed loop r = 1 + 0.3 sin(3 a), 60 samples, noise 0.05, fitted to a
  // tolerance of 3 sigma (the fewest periodic control points whose max_error is within it).
  const auto loop = [](double a) {
    const double r = 1 + 0.3 * std::sin(3 * a);
    return P2{r * std::cos(a), r * std::sin(a)};
  };
  io::PointList closed_data{2, {}};
  std::vector<P2> closed_pts;
  for (int k = 0; k < 60; ++k) {
    const P2 c = loop(2 * std::numbers::pi * k / 60.0);
    const P2 q{c[0] + sigma_closed * noise(), c[1] + sigma_closed * noise()};
    closed_pts.push_back(q);
    closed_data.push_back(q);
  }
  io::AnyFitRequest closed_req;
  closed_req.degree = 3;
  closed_req.tolerance = 3 * sigma_closed;
  closed_req.closed = true;
  const io::AnyFit closed_fit = io::fit(closed_data, closed_req);
  const Spline& cc = std::get<Spline>(closed_fit.curve);
  const std::size_t closed_count = cc.points().size() - 3;  // n + p points for odd p
  // The contract's error: data point to the curve at the point's own parameter (chord
  // length, recomputed here as fit computes it).
  const auto params = [](const std::vector<P2>& D, bool closed) {
    std::vector<double> t{0};
    const std::size_t steps = closed ? D.size() : D.size() - 1;
    for (std::size_t k = 1; k <= steps; ++k) t.push_back(t.back() + distance(D[k % D.size()], D[k - 1]));
    for (auto& x : t) x /= t.back();
    return t;
  };
  const std::vector<double> to = params(open_pts, false), tc = params(closed_pts, true);
  // How far the open fit strays from the noise-free curve (vertically, RMS over 2001
  // samples), against the RMS of the noise the data carry.
  double rms_fit = 0, rms_noise = 0;
  for (int i = 0; i <= 2000; ++i) {
    const P2 c = oc(i / 2000.0);
    rms_fit += (c[1] - truth(c[0])) * (c[1] - truth(c[0]));
  }
  rms_fit = std::sqrt(rms_fit / 2001);
  for (const auto& q : open_pts) rms_noise += (q[1] - truth(q[0])) * (q[1] - truth(q[0]));
  rms_noise = std::sqrt(rms_noise / static_cast<double>(open_pts.size()));
  // The seam of the closed fit: value, first and second derivative at 0 and at 1.
  double seam = 0;
  for (int k = 0; k < 3; ++k) seam = std::max(seam, norm(cc.derivative_at(0.0, k) - cc.derivative_at(1.0, k)) / std::max(1.0, norm(cc.derivative_at(0.0, k))));
  SvgDocument doc(width, 360);
  doc.title("Least-squares fits through noisy data");
  const auto draw = [&](const Spline& c, const std::vector<P2>& D, const std::vector<double>& t, const std::vector<P2>& true_curve,
                        double err, const PageRect& r) {
    Box2 box = box_of<double, 2>(D);
    box.add(c.control_bounds());
    doc.set_map(PageMap::fit(grown_relative(box, 0.04), r));
    doc.polyline(c.points(), stroke(light, 1.1, "4 3"));
    doc.polyline(true_curve, stroke(grey, 1.4, "6 4"));
    doc.curve(pieces(c), stroke(ink, 2.4));
    std::size_t worst = 0;
    for (std::size_t k = 0; k < D.size(); ++k) {
      const P2 at = c(t[k]);
      doc.line(D[k], at, stroke(accent, 1.5));
      if (distance(D[k], at) > distance(D[worst], c(t[worst]))) worst = k;
    }
    for (const auto& q : D) doc.circle(q, 2.4, Paint{.stroke = "#3d4a5c", .stroke_width = 1, .fill = "#fff"});
    doc.circle(D[worst], 5, Paint{.stroke = accent, .stroke_width = 1.6});
    LabelPlacer labels(doc);
    labels.avoid(c.points());
    labels.avoid(true_curve);
    labels.avoid_curve(c, 300);
    for (std::size_t k = 0; k < D.size(); ++k) labels.avoid(std::vector<P2>{D[k], c(t[k])});
    labels.place(D[worst], "max_error " + plain(err, 3), label(11, Anchor::start, accent), V2(1.0, -1.0), 7);
  };
  std::vector<P2> open_truth, closed_truth;
  for (int i = 0; i <= 400; ++i) {
    const double x = 2 * std::numbers::pi * i / 400.0;
    open_truth.push_back({x, truth(x)});
    closed_truth.push_back(loop(x));
  }
  draw(oc, open_pts, to, open_truth, open_fit.max_error, {20, 30, 520, 290});
  draw(cc, closed_pts, tc, closed_truth, closed_fit.max_error, {560, 30, 300, 290});
  doc.set_map(PageMap{});
  doc.text({20, 20}, "open: 45 points, 9 control points (least squares)", label(12));
  doc.text({560, 20}, "closed: 60 points, tolerance 0.15", label(12));
  doc.text({20, 345}, "red: each point to the curve at its own parameter (what max_error measures); dashed grey: the curve without noise",
           label(11, Anchor::start, text_grey));
  Figure f;
  f.id = "noisy-fit";
  f.title = "Least-squares fits through noisy data";
  f.svg = doc.str();
  f.caption = "<code>fit</code> with chord-length parameters "
              "[PT97, &sect;9.4.1], control polygons dashed. Left: 45 samples of y = sin x + &frac14; cos 3x with seeded "
              "Gaussian noise (&sigma; = 0.1; RMS of this draw " + fixed(rms_noise, 3) + "), 9 control points, the ends "
              "interpolated: <code>max_error</code> = " + fixed(open_fit.max_error, 3) + ", while the fitted curve is " +
              fixed(rms_fit, 3) + " RMS from the noise-free curve (vertically, 2001 samples): least squares averages much of "
              "the noise out. Right: a closed three-lobed loop, 60 samples with &sigma; = 0.05, fitted with <code>closed</code> "
              "and <code>tolerance</code> 0.15 (3&sigma;): the fewest periodic control points found is " +
              std::to_string(closed_count) + ", <code>max_error</code> = " + fixed(closed_fit.max_error, 3) +
              ", and the curve is C<sup>2</sup> across its seam (value and first two derivatives at 0 and 1 agree to " +
              sci(seam) + " relative).";
  return f;
}

}  // namespace casteljau::gallery
