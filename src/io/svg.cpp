// SVG writer (SvgDocument, PageMap, number and text formatting) and render_svg.
#include "casteljau/io/svg.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <system_error>
#include <type_traits>
#include <variant>

#include "casteljau/algo/bounds.hpp"
#include "casteljau/algo/flatten.hpp"
#include "work_limits.hpp"

namespace casteljau::io {

namespace {

void require_positive(double v, std::string_view where) {
  require_finite(v, where);
  if (!(v > 0)) throw InvalidArgument(std::string(where), "must be > 0, got " + casteljau::detail::format_number(v));
}

void require_non_negative(double v, std::string_view where) {
  require_finite(v, where);
  if (!(v >= 0)) throw InvalidArgument(std::string(where), "must be >= 0, got " + casteljau::detail::format_number(v));
}

/// The resolution of the numbers svg_number writes, in px: 3 decimals.
constexpr double written_resolution_px = 1e-3;

/// Largest page width and height render_svg accepts, in px: far beyond any screen or print
/// (a 1 m poster at 600 dpi is 24000 px). Curves are flattened to a fraction of a px, so
/// the page size bounds the size and the cost of the document: with width 1e308 there
/// would be no end to either.
constexpr double max_page_px = 1e6;

/// Smallest page side and drawing area (page less padding) render_svg accepts, in px:
/// below one px nothing can be seen, and the page scale of a huge model could underflow
/// to 0. The messages write both limits out (1, 1000000).
constexpr double min_drawing_px = 1;

}  // namespace

// ---------------------------------------------------------------------------------------
// Formatting.

std::string svg_number(double v, std::string_view where) {
  require_finite(v, where);
  std::array<char, 64> buf{};
  // Fixed point needs as many characters as the integer part has digits; 1e15 keeps it
  // short (and 3 decimals of a number that large are below double resolution anyway).
  if (std::abs(v) >= 1e15) {
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    return std::string(buf.data(), r.ptr);
  }
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, 3);
  std::string s(buf.data(), r.ptr);
  // Drop trailing zeros and a trailing point: "2.500" -> "2.5", "3.000" -> "3".
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: {
        const auto u = static_cast<unsigned char>(ch);
        // XML 1.0 allows tab, newline and carriage return among the C0 controls only.
        if (u < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') break;
        out += ch;
      }
    }
  }
  return out;
}

std::string_view palette(std::size_t i) {
  // Eight hues of similar weight that stay apart for common colour-vision deficiencies
  // better than a rainbow does; the first is RenderStyle's default stroke.
  static constexpr std::array<std::string_view, 8> colours = {"#1f77b4", "#d9641c", "#2a9d5c", "#c23b5a",
                                                              "#7b5ea7", "#8c6d31", "#d17cb6", "#5f6b73"};
  return colours[i % colours.size()];
}

std::vector<double> nice_ticks(double lo, double hi, int count) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo) || count < 1) return ticks;
  // hi / count - lo / count: hi - lo overflows for [-1e308, 1e308].
  const double raw = hi / count - lo / count;
  if (!(raw > 0) || !std::isfinite(raw)) return ticks;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * mag;
  for (const double m : {1.0, 2.0, 5.0}) {
    if (raw <= m * mag * 1.0000001) {
      step = m * mag;
      break;
    }
  }
  if (!std::isfinite(step)) return ticks;  // 2 x 1e308
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  // Far more ticks than asked means the interval is below the resolution of its
  // position (huge offset, tiny width): no sensible ticks. Beyond 2^52 steps from zero
  // consecutive multiples of the step are no longer distinct doubles: the same.
  if (!(last - first < 10.0 * count + 10) || !(std::abs(first) < 0x1p52 && std::abs(last) < 0x1p52)) return ticks;
  // Counted in integers: k += 1 on a double would stop moving beyond 2^53.
  for (auto k = static_cast<std::int64_t>(first); k <= static_cast<std::int64_t>(last); ++k) {
    double v = static_cast<double>(k) * step;
    if (!std::isfinite(v)) continue;
    if (std::abs(v) < step * 1e-9) v = 0;  // a clean zero, not 1e-17
    ticks.push_back(v);
  }
  return ticks;
}

std::string tick_label(double v, double step) {
  std::array<char, 64> buf{};
  if (!std::isfinite(v)) return "?";
  if (step > 0 && std::abs(v) < step * 1e-6) v = 0;  // a tick at zero computed as 1e-17
  // As many decimals as the step needs to be written exactly (0.25 needs 2), then
  // trailing zeros dropped per label (1.00 -> 1).
  int decimals = 0;
  if (step > 0 && std::isfinite(step)) {
    double scaled = step;
    while (decimals < 12 && std::abs(scaled - std::round(scaled)) > 1e-6 * scaled) {
      scaled *= 10;
      ++decimals;
    }
  }
  if (std::abs(v) >= 1e7 || (v != 0 && std::abs(v) < 1e-4)) {
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 4);
    return std::string(buf.data(), r.ptr);
  }
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, decimals);
  std::string s(buf.data(), r.ptr);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s.find_first_not_of("-0.") == std::string::npos) s = "0";
  // A typographic minus sign reads better than a hyphen.
  if (!s.empty() && s[0] == '-') s = "\u2212" + s.substr(1);
  return s;
}

// ---------------------------------------------------------------------------------------
// PageMap.

PageMap PageMap::fit(const Box2& model_in, const PageRect& page, Aspect aspect) {
  require_finite(page.x, "page.x");
  require_finite(page.y, "page.y");
  require_positive(page.width, "page.width");
  require_positive(page.height, "page.height");
  Box2 model = model_in;
  if (model.empty()) model = Box2{{-1.0, -1.0}, {1.0, 1.0}};
  for (int i = 0; i < 2; ++i) {
    require_finite(model.lo[i], i == 0 ? "model.lo.x" : "model.lo.y");
    require_finite(model.hi[i], i == 0 ? "model.hi.x" : "model.hi.y");
  }
  const std::array<double, 2> avail = {page.width, page.height};
  std::array<double, 2> centre{}, half{}, scale{};
  std::array<bool, 2> flat{};
  for (int i = 0; i < 2; ++i) {
    // Halves first: max - min may overflow (-1e308 to 1e308), max/2 - min/2 does not; and
    // the scale is (avail / 2) / half, not avail / (2 half), which would overflow too.
    centre[i] = model.lo[i] / 2 + model.hi[i] / 2;
    half[i] = model.hi[i] / 2 - model.lo[i] / 2;
    // Flat: no extent; or a half extent within 2^-46 of the position (64 to 128 ulps),
    // which is rounding in the bounds of a point or a straight line rather than geometry;
    // or one so small that the scale would overflow. The test is against the resolution
    // of the position, not a fixed fraction of it: a curve 4 units wide at 1e13 (ulp
    // 0.002) spans 2000 ulps and is drawn as it is.
    const double resolution = std::abs(centre[i]) * 0x1p-46;
    flat[i] = !(half[i] > resolution) || !std::isfinite(avail[i] / 2 / half[i]);
    if (flat[i]) half[i] = std::max(1.0, std::abs(centre[i]) * 1e-3);
    scale[i] = avail[i] / 2 / half[i];
  }
  if (aspect == Aspect::keep) {
    // A flat axis holds no extent to fit (its widened half is a placeholder): the other
    // axis alone sets the scale.
    double s = std::min(scale[0], scale[1]);
    if (flat[0] && !flat[1]) s = scale[1];
    if (flat[1] && !flat[0]) s = scale[0];
    scale = {s, s};
  }
  if (!(scale[0] > 0 && scale[1] > 0)) {
    throw InvalidArgument("page", "too small for the extent of the model (the page scale underflows)");
  }
  return {centre[0], centre[1], page.x + page.width / 2, page.y + page.height / 2, scale[0], -scale[1]};
}

Affine<double, 2> PageMap::affine() const {
  Affine<double, 2> m;
  m.linear = {{{sx_, 0.0}, {0.0, sy_}}};
  m.translation = Vector<double, 2>(qx_ - sx_ * cx_, qy_ - sy_ * cy_);
  return m;
}

double PageMap::px_to_model(double px) const { return px / std::min(scale_x(), scale_y()); }

Box2 PageMap::view(const PageRect& page) const {
  // A wide padding around a model near the range of double can reach beyond it: the
  // corners are clamped to the finite range (the map sends them off the page anyway).
  constexpr double big = std::numeric_limits<double>::max();
  const auto finite = [&](const Point2& p) { return Point2(std::clamp(p[0], -big, big), std::clamp(p[1], -big, big)); };
  Box2 b = Box2::empty_box();
  b.add(finite(to_model({page.x, page.y})));
  b.add(finite(to_model({page.x + page.width, page.y + page.height})));
  return b;
}

// ---------------------------------------------------------------------------------------
// SvgDocument.

SvgDocument::SvgDocument(double width, double height) : width_(width), height_(height) {
  require_positive(width, "width");
  require_positive(height, "height");
}

void SvgDocument::title(std::string_view text) { title_ = xml_escape(text); }

void SvgDocument::open(std::string_view tag) {
  body_ += '<';
  body_ += tag;
}

void SvgDocument::attr(std::string_view name, double v) {
  body_ += ' ';
  body_ += name;
  body_ += "=\"";
  body_ += svg_number(v, name);
  body_ += '"';
}

void SvgDocument::attr(std::string_view name, std::string_view v) {
  body_ += ' ';
  body_ += name;
  body_ += "=\"";
  body_ += xml_escape(v);
  body_ += '"';
}

void SvgDocument::paint_attrs(const Paint& p) {
  attr("fill", p.fill.empty() ? std::string_view("none") : std::string_view(p.fill));
  if (p.fill_opacity != 1) attr("fill-opacity", std::clamp(p.fill_opacity, 0.0, 1.0));
  attr("stroke", p.stroke.empty() ? std::string_view("none") : std::string_view(p.stroke));
  if (!p.stroke.empty() && p.stroke != "none") {
    require_non_negative(p.stroke_width, "stroke_width");
    attr("stroke-width", p.stroke_width);
    if (!p.dash.empty()) attr("stroke-dasharray", p.dash);
  }
  if (p.opacity != 1) {
    require_finite(p.opacity, "opacity");
    attr("opacity", std::clamp(p.opacity, 0.0, 1.0));
  }
}

void SvgDocument::points_attr(std::span<const Point2> points) {
  body_ += " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point2 q = map_(points[i]);
    const std::string where = "points[" + std::to_string(i) + "]";
    if (i > 0) body_ += ' ';
    body_ += svg_number(q[0], where);
    body_ += ',';
    body_ += svg_number(q[1], where);
  }
  body_ += '"';
}

void SvgDocument::rect(const PageRect& r, const Paint& paint, double corner_radius) {
  require_non_negative(r.width, "rect.width");
  require_non_negative(r.height, "rect.height");
  open("rect");
  attr("x", r.x);
  attr("y", r.y);
  attr("width", r.width);
  attr("height", r.height);
  if (corner_radius > 0) attr("rx", corner_radius);
  paint_attrs(paint);
  body_ += "/>\n";
}

void SvgDocument::line(const Point2& a, const Point2& b, const Paint& paint) {
  const Point2 p = map_(a), q = map_(b);
  open("line");
  attr("x1", p[0]);
  attr("y1", p[1]);
  attr("x2", q[0]);
  attr("y2", q[1]);
  paint_attrs(paint);
  body_ += "/>\n";
}

void SvgDocument::polyline(std::span<const Point2> points, const Paint& paint) {
  if (points.empty()) return;
  open("polyline");
  points_attr(points);
  paint_attrs(paint);
  body_ += " stroke-linejoin=\"round\" stroke-linecap=\"round\"/>\n";
}

void SvgDocument::polygon(std::span<const Point2> points, const Paint& paint) {
  if (points.empty()) return;
  open("polygon");
  points_attr(points);
  paint_attrs(paint);
  body_ += " stroke-linejoin=\"round\"/>\n";
}

void SvgDocument::circle(const Point2& c, double radius_px, const Paint& paint) {
  require_non_negative(radius_px, "radius_px");
  const Point2 p = map_(c);
  open("circle");
  attr("cx", p[0]);
  attr("cy", p[1]);
  attr("r", radius_px);
  paint_attrs(paint);
  body_ += "/>\n";
}

void SvgDocument::arrow(const Point2& a, const Point2& b, const Paint& paint, double head_px) {
  require_non_negative(head_px, "head_px");
  const Point2 p = map_(a), q = map_(b);
  const Vector<double, 2> d = q - p;
  const double len = norm(d);
  if (!(len > 0)) return;
  const Vector<double, 2> u = d / len, n(-u[1], u[0]);
  const double head = std::min(head_px, len);
  // The shaft stops at the head's base so that a wide stroke does not poke through.
  const Point2 base = q - head * u;
  const PageMap saved = map_;
  map_ = PageMap{};
  line(p, base + 0.2 * head * u, paint);
  const std::array<Point2, 3> tri = {q, base + 0.38 * head * n, base - 0.38 * head * n};
  polygon(tri, Paint{.stroke = "none", .fill = paint.stroke, .opacity = paint.opacity});
  map_ = saved;
}

void SvgDocument::text(const Point2& at, std::string_view s, const TextStyle& style) {
  const Point2 p = map_(at);
  open("text");
  attr("x", p[0] + style.dx);
  attr("y", p[1] + style.dy);
  require_positive(style.size, "size");
  attr("font-size", style.size);
  if (!style.family.empty()) attr("font-family", style.family);
  if (style.italic) attr("font-style", "italic");
  if (style.bold) attr("font-weight", "bold");
  if (style.anchor == Anchor::middle) attr("text-anchor", "middle");
  if (style.anchor == Anchor::end) attr("text-anchor", "end");
  attr("fill", style.colour);
  body_ += '>';
  body_ += xml_escape(s);
  body_ += "</text>\n";
}

namespace {

/// Path data in page px, with joins detected so that a composite curve is one subpath.
class PathData {
 public:
  void move_or_join(const Point2& p) {
    if (started_ && distance(p, current_) <= written_resolution_px * 1e-3) return;
    add('M', p);
    started_ = true;
  }
  void add(char cmd, const Point2& p) {
    d_ += cmd;
    append(p);
    current_ = p;
  }
  void add(char cmd, std::span<const Point2> ps) {
    d_ += cmd;
    for (const auto& p : ps) append(p);
    current_ = ps.back();
  }
  [[nodiscard]] const std::string& str() const { return d_; }

 private:
  void append(const Point2& p) {
    if (!d_.empty() && d_.back() != 'M' && d_.back() != 'L' && d_.back() != 'Q' && d_.back() != 'C') d_ += ' ';
    d_ += svg_number(p[0], "curve point");
    d_ += ',';
    d_ += svg_number(p[1], "curve point");
  }
  std::string d_;
  Point2 current_{};
  bool started_ = false;
};

template <class C>
void require_finite_control_points(const C& c) {
  for (const auto& p : c.points()) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) {
      throw InvalidArgument("curve", "coordinates overflow when mapped to the page");
    }
  }
}

void flattened(PathData& d, const std::vector<Point2>& pts) {
  d.move_or_join(pts.front());
  if (pts.size() == 1) {
    d.add('L', pts.front());
    return;
  }
  // Consecutive equal vertices add nothing: a zero-length L would still draw a cap.
  for (std::size_t i = 1; i < pts.size(); ++i) d.add('L', pts[i]);
}

/// One page-space Bézier segment: exact commands up to degree 3, else flattened.
void append_segment(PathData& d, const Bezier<double, 2>& c, double tolerance_px) {
  require_finite_control_points(c);
  const auto& P = c.points();
  d.move_or_join(P.front());
  switch (c.degree()) {
    case 0: d.add('L', P[0]); return;  // a dot: zero length with a round cap
    case 1: d.add('L', P[1]); return;
    case 2: d.add('Q', std::span<const Point2>(P).subspan(1)); return;
    case 3: d.add('C', std::span<const Point2>(P).subspan(1)); return;
    default: flattened(d, flatten(c, tolerance_px));
  }
}

void append_segment(PathData& d, const RationalBezier<double, 2>& c, double tolerance_px) {
  require_finite_control_points(c);
  // Equal weights make the rational curve the polynomial one: write it exactly.
  const auto& w = c.weights();
  if (std::all_of(w.begin(), w.end(), [&](double x) { return x == w.front(); })) {
    append_segment(d, Bezier<double, 2>(c.points()), tolerance_px);
    return;
  }
  flattened(d, flatten(c, tolerance_px));
}

}  // namespace

void SvgDocument::path_element(const std::string& d, const Paint& paint) {
  open("path");
  body_ += " d=\"";
  body_ += d;
  body_ += '"';
  paint_attrs(paint);
  body_ += " stroke-linejoin=\"round\" stroke-linecap=\"round\"/>\n";
}

namespace {
// The curve on the page: its control points mapped one by one (affine invariance; weights
// unchanged), through PageMap's centred form rather than Affine's A x + b.
std::vector<Point2> mapped(const PageMap& m, const std::vector<Point2>& P) {
  std::vector<Point2> Q(P.size());
  std::transform(P.begin(), P.end(), Q.begin(), [&](const Point2& p) { return m(p); });
  return Q;
}
Bezier<double, 2> on_page(const PageMap& m, const Bezier<double, 2>& c) { return Bezier<double, 2>(mapped(m, c.points())); }
RationalBezier<double, 2> on_page(const PageMap& m, const RationalBezier<double, 2>& c) {
  return RationalBezier<double, 2>(mapped(m, c.points()), c.weights());
}
}  // namespace

void SvgDocument::curve(const Bezier<double, 2>& c, const Paint& paint, double tolerance_px) {
  require_non_negative(tolerance_px, "tolerance_px");
  PathData d;
  append_segment(d, on_page(map_, c), std::max(tolerance_px, written_resolution_px));
  path_element(d.str(), paint);
}

void SvgDocument::curve(const RationalBezier<double, 2>& c, const Paint& paint, double tolerance_px) {
  require_non_negative(tolerance_px, "tolerance_px");
  PathData d;
  append_segment(d, on_page(map_, c), std::max(tolerance_px, written_resolution_px));
  path_element(d.str(), paint);
}

void SvgDocument::curve(const Pieces<double, 2>& c, const Paint& paint, double tolerance_px) {
  require_non_negative(tolerance_px, "tolerance_px");
  PathData d;
  const double tol = std::max(tolerance_px, written_resolution_px);
  for (const auto& s : c.segments()) std::visit([&](const auto& seg) { append_segment(d, on_page(map_, seg), tol); }, s);
  path_element(d.str(), paint);
}

void SvgDocument::curve(const Path<double, 2>& c, const Paint& paint, double tolerance_px) { curve(pieces(c), paint, tolerance_px); }

void SvgDocument::begin_group(std::string_view css_class) {
  open("g");
  if (!css_class.empty()) attr("class", css_class);
  body_ += ">\n";
  ++depth_;
}

void SvgDocument::end_group() {
  if (depth_ == 0) return;
  body_ += "</g>\n";
  --depth_;
}

std::string SvgDocument::str() const {
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svg_number(width_) + "\" height=\"" +
                  svg_number(height_) + "\" viewBox=\"0 0 " + svg_number(width_) + " " + svg_number(height_) + "\"";
  s += title_.empty() ? ">\n" : " role=\"img\">\n<title>" + title_ + "</title>\n";
  s += body_;
  for (int i = 0; i < depth_; ++i) s += "</g>\n";
  s += "</svg>\n";
  return s;
}

// ---------------------------------------------------------------------------------------
// render_svg.

namespace {

/// The graph (t, y(t)) of a 1D Bézier curve: by linear precision, t = sum B(i,n)(t) i/n,
/// so the graph is the 2D Bézier curve with control points (i/n, y_i) [Farin02, 4.5]. A
/// constant (degree 0) is raised to degree 1 first, so that its graph is a segment.
Bezier<double, 2> graph(const Bezier<double, 1>& c) {
  const Bezier<double, 1> b = c.degree() == 0 ? c.elevate(1) : c;
  const int n = b.degree();
  std::vector<Point2> P;
  for (int i = 0; i <= n; ++i) P.emplace_back(static_cast<double>(i) / n, b.points()[static_cast<std::size_t>(i)][0]);
  return Bezier<double, 2>(std::move(P));
}

/// The graph (t, y(t)) of a 1D rational Bézier curve y = A/W of degree n: with t W(t) in
/// the degree n + 1 Bernstein basis (t B(i,n) = (i+1)/(n+1) B(i+1,n+1)) and (A, W)
/// elevated to n + 1, the graph is the rational curve of degree n + 1 with weights W_j
/// (positive: convex combinations of the w_i) and points (j w_{j-1} / ((n+1) W_j), A_j / W_j).
RationalBezier<double, 2> graph(const RationalBezier<double, 1>& c) {
  const auto h = c.homogeneous().elevate(1);  // points (A_j, W_j), j = 0..n+1
  const int n = c.degree();
  const auto& w = c.weights();
  std::vector<Point2> P;
  std::vector<double> W;
  for (int j = 0; j <= n + 1; ++j) {
    const auto& q = h.points()[static_cast<std::size_t>(j)];
    const double xw = j == 0 ? 0.0 : static_cast<double>(j) / (n + 1) * w[static_cast<std::size_t>(j - 1)];
    P.emplace_back(xw / q[1], q[0] / q[1]);
    W.push_back(q[1]);
  }
  return RationalBezier<double, 2>(std::move(P), std::move(W));
}

/// The control points with x in [0, 1] mapped onto [lo, hi] as (1 - x) lo + x hi: the
/// affine map x -> lo + x (hi - lo) without forming hi - lo, which overflows for breaks
/// [-1e308, 1e308] (it gave NaN coordinates).
std::vector<Point2> onto(const std::vector<Point2>& P, const Interval<double>& dom) {
  std::vector<Point2> Q(P.size());
  std::transform(P.begin(), P.end(), Q.begin(), [&](const Point2& p) { return Point2((1 - p[0]) * dom.lo + p[0] * dom.hi, p[1]); });
  return Q;
}
Bezier<double, 2> onto(const Bezier<double, 2>& c, const Interval<double>& dom) { return Bezier<double, 2>(onto(c.points(), dom)); }
RationalBezier<double, 2> onto(const RationalBezier<double, 2>& c, const Interval<double>& dom) {
  return RationalBezier<double, 2>(onto(c.points(), dom), c.weights());
}

/// The graph of a 1-D curve's pieces: each piece's graph mapped from [0, 1] onto its
/// break interval.
Pieces<double, 2> graph(const Pieces<double, 1>& c) {
  std::vector<BezierPiece<double, 2>> segs;
  c.for_each_piece([&](std::size_t i, const auto& s, const Interval<double>& own) {
    segs.push_back(BezierPiece<double, 2>(onto(graph(s), c.lift(i, own))));  // the piece's break interval
  });
  return Pieces<double, 2>(std::move(segs), c.breaks());
}

struct Drawable {
  Pieces<double, 2> path;
  bool is_graph;
};

Drawable drawable(const AnyCurve& any, std::string_view where) {
  limits::check_curve_work(any, std::string(where), "drawing");  // before the Bézier pieces
  return std::visit(
      [&](const auto& c) -> Drawable {
        using C = std::decay_t<decltype(c)>;
        if constexpr (C::dimension == 1) {
          return {graph(c), true};
        } else if constexpr (C::dimension == 2) {
          return {c, false};
        } else {
          throw InvalidArgument(std::string(where), "render_svg draws 1D curves (as graphs) and 2D curves, got a " +
                                                        std::to_string(C::dimension) + "D curve");
        }
      },
      pieces(any));
}

/// Runs f, which computes from one curve (its bounds, its page points, its flattening),
/// and reports a failure against that curve: an overflow when mapping it to the page, or
/// a flattening tolerance below the resolution of its mapped control points, is about
/// the curve, not about an argument the caller gave.
template <class F>
void about_curve(const std::string& where, F&& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    if (e.where() == where) throw;  // already about the curve (a 3D curve)
    throw InvalidArgument(where, "cannot be drawn: " + (e.where() == "curve" ? e.problem() : std::string(e.what())));
  } catch (const NumericalError& e) {
    throw InvalidArgument(where, "cannot be drawn: " + std::string(e.what()));
  }
}

void validate(const RenderStyle& s) {
  require_positive(s.width, "width");
  require_positive(s.height, "height");
  require_non_negative(s.padding, "padding");
  require_positive(s.stroke_width, "stroke_width");
  require_non_negative(s.tolerance, "tolerance");
  for (const auto& [v, name] : {std::pair{s.width, "width"}, std::pair{s.height, "height"}}) {
    if (!(v >= min_drawing_px && v <= max_page_px)) {
      throw InvalidArgument(name, std::string(name) + " must be >= 1 and <= 1000000 px, got " + casteljau::detail::format_number(v));
    }
  }
  // Compared as padding <= (side - 1) / 2, which cannot overflow as 2 * padding would.
  const double side = std::min(s.width, s.height);
  if (!(s.padding <= (side - min_drawing_px) / 2)) {
    throw InvalidArgument("padding", "leaves no room to draw: min(width, height) - 2 * padding must be >= " +
                                         casteljau::detail::format_number(min_drawing_px) + " px, got padding " +
                                         casteljau::detail::format_number(s.padding) + " with min(width, height) = " +
                                         casteljau::detail::format_number(side));
  }
}

/// The axes through the origin when it is in view, with ticks and labels. Positions are
/// computed with the map and drawn in page px (identity map), so that a view reaching the
/// range of double (clamped by PageMap::view) never has to be mapped back to the model.
void draw_axes(SvgDocument& doc, const PageMap& map, const RenderStyle& style, bool graphs) {
  const PageRect page{0, 0, style.width, style.height};
  const Box2 v = map.view(page);
  const Paint axis{.stroke = "#777", .stroke_width = 1};
  const Paint grid{.stroke = "#777", .stroke_width = 1};
  const TextStyle label{.size = 10, .colour = "#555", .family = "sans-serif"};
  const double tick_px = 4;
  // About one tick per 90 px (x) and 70 px (y); validate() bounds the page, so these fit an int.
  const int count_x = std::max(2, static_cast<int>(style.width / 90)), count_y = std::max(2, static_cast<int>(style.height / 70));
  doc.set_map(PageMap{});
  if (v.lo[1] <= 0 && 0 <= v.hi[1]) {
    const double y0 = map({v.lo[0], 0.0})[1];
    doc.arrow({0.0, y0}, {style.width, y0}, axis);
    const auto tx = nice_ticks(v.lo[0], v.hi[0], count_x);
    const double step = tx.size() > 1 ? tx[1] - tx[0] : 1;
    for (const double x : tx) {
      if (x == 0 && v.lo[0] <= 0 && 0 <= v.hi[0]) continue;  // the origin belongs to both axes
      const Point2 p = map({x, 0.0});
      if (p[0] > style.width - 12) continue;  // keep clear of the arrow head
      doc.line(p, {p[0], p[1] + tick_px}, grid);
      doc.text(p, tick_label(x, step), TextStyle{.size = label.size, .colour = label.colour, .anchor = Anchor::middle, .dy = 15, .family = label.family});
    }
    doc.text({style.width, y0}, graphs ? "t" : "x", TextStyle{.size = 12, .colour = "#555", .anchor = Anchor::end, .italic = true, .dx = -4, .dy = -6, .family = "serif"});
  }
  if (v.lo[0] <= 0 && 0 <= v.hi[0]) {
    const double x0 = map({0.0, v.lo[1]})[0];
    doc.arrow({x0, style.height}, {x0, 0.0}, axis);
    const auto ty = nice_ticks(v.lo[1], v.hi[1], count_y);
    const double step = ty.size() > 1 ? ty[1] - ty[0] : 1;
    for (const double y : ty) {
      if (y == 0 && v.lo[1] <= 0 && 0 <= v.hi[1]) continue;
      const Point2 p = map({0.0, y});
      if (p[1] < 12) continue;
      doc.line(p, {p[0] - tick_px, p[1]}, grid);
      doc.text(p, tick_label(y, step), TextStyle{.size = label.size, .colour = label.colour, .anchor = Anchor::end, .dx = -6, .dy = 3.5, .family = label.family});
    }
    doc.text({x0, 0.0}, "y", TextStyle{.size = 12, .colour = "#555", .italic = true, .dx = 8, .dy = 10, .family = "serif"});
  }
  doc.set_map(map);
}

}  // namespace

std::string render_svg(std::span<const AnyCurve> curves, const RenderStyle& style) {
  validate(style);
  std::vector<Drawable> items;
  items.reserve(curves.size());
  const auto name = [&](std::size_t i) { return curves.size() == 1 ? std::string("curve") : "curves[" + std::to_string(i) + "]"; };
  for (std::size_t i = 0; i < curves.size(); ++i) about_curve(name(i), [&] { items.push_back(drawable(curves[i], name(i))); });

  Box2 box = Box2::empty_box();
  bool all_graphs = !items.empty();
  for (std::size_t i = 0; i < items.size(); ++i) {
    about_curve(name(i), [&] {
      box.add(bounds(items[i].path));
      if (style.control_polygon) box.add(items[i].path.control_bounds());
    });
    all_graphs = all_graphs && items[i].is_graph;
  }
  const PageRect inner{style.padding, style.padding, style.width - 2 * style.padding, style.height - 2 * style.padding};
  const PageMap map = PageMap::fit(box, inner, all_graphs ? Aspect::stretch : Aspect::keep);

  SvgDocument doc(style.width, style.height);
  doc.set_map(map);
  if (!style.background.empty() && style.background != "none") {
    doc.rect({0, 0, style.width, style.height}, Paint{.fill = style.background});
  }
  if (style.axes) draw_axes(doc, map, style, all_graphs);

  const bool stroke_unset = style.stroke.empty() || style.stroke == RenderStyle{}.stroke;
  // A model tolerance in px along the more compressed axis (so it holds along both); a
  // huge one is capped at 1e9 px (a straight chord either way) to stay finite.
  const double tolerance_px = style.tolerance > 0
                                  ? std::min(style.tolerance * std::min(map.scale_x(), map.scale_y()), 1e9)
                                  : SvgDocument::default_tolerance_px;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string colour =
        stroke_unset ? std::string(items.size() > 1 ? palette(i) : palette(0)) : style.stroke;
    const auto& path = items[i].path;
    about_curve(name(i), [&] {
      doc.begin_group("curve");
      if (style.control_polygon) {
        for (const auto& s : path.segments()) {
          std::visit([&](const auto& seg) {
            doc.polyline(seg.points(), Paint{.stroke = colour, .stroke_width = 1, .opacity = 0.55, .dash = "4 3"});
          }, s);
        }
      }
      doc.curve(path, Paint{.stroke = colour, .stroke_width = style.stroke_width}, tolerance_px);
      if (style.control_polygon) {
        for (const auto& s : path.segments()) {
          std::visit([&](const auto& seg) {
            for (const auto& p : seg.points()) doc.circle(p, 3, Paint{.stroke = colour, .stroke_width = 1.25, .fill = "white"});
          }, s);
        }
      }
      doc.end_group();
    });
  }
  return doc.str();
}

}  // namespace casteljau::io
