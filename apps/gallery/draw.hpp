// The gallery's look and its number formats, shared by every figures_*.cpp: one set of
// colours, strokes, point marks and text styles, and one way to write a number in a
// caption (HTML) or in a picture (plain SVG text).
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/interval.hpp"
#include "casteljau/core/point.hpp"
#include "casteljau/core/segment.hpp"
#include "casteljau/io/svg.hpp"

namespace casteljau::gallery {

using io::Anchor;
using io::Aspect;
using io::PageMap;
using io::PageRect;
using io::Paint;
using io::SvgDocument;
using io::TextStyle;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;
using Box2 = Box<double, 2>;

// ---------------------------------------------------------------------------------------
// Colours and strokes.

inline constexpr double fig_width = 880;  // px, the page's column width
inline const std::string ink = "#1d3557";           // curves
inline const std::string polygon_grey = "#8d99ae";  // control polygons, secondary curves
inline const std::string point_edge = "#3d4a5c";
inline const std::string text_grey = "#4a5563";
inline const std::string accent = "#c23b5a";  // the point or property a figure is about
inline const std::string grey = polygon_grey;         // short names the figure files share
inline const std::string light = "#b9c1ca";           // faint guides
inline const std::string green = "#2a9d5c";           // a second highlighted kind of point
inline constexpr double width = fig_width;
inline const std::string sans = "system-ui, 'Helvetica Neue', Arial, sans-serif";

inline Paint curve_paint(const std::string& colour = ink, double width = 2.6) { return Paint{.stroke = colour, .stroke_width = width}; }
inline Paint polygon_paint(const std::string& colour = polygon_grey, double width = 1.3) {
  return Paint{.stroke = colour, .stroke_width = width, .dash = "5 4"};
}
inline Paint thin(const std::string& colour, double width = 1) { return Paint{.stroke = colour, .stroke_width = width}; }
/// A stroke of any width, dashed when dash is a CSS dash array.
inline Paint stroke(const std::string& colour, double width, const std::string& dash = "") {
  return Paint{.stroke = colour, .stroke_width = width, .dash = dash};
}

/// Control points: open white circles edged in a colour.
inline void control_points(SvgDocument& doc, std::span<const P2> pts, const std::string& edge = point_edge, double r = 3.6) {
  for (const auto& p : pts) doc.circle(p, r, Paint{.stroke = edge, .stroke_width = 1.4, .fill = "white"});
}
/// A marked point: a filled dot with a white rim.
inline void dot(SvgDocument& doc, const P2& p, const std::string& colour, double r = 4) {
  doc.circle(p, r, Paint{.stroke = "white", .stroke_width = 1.2, .fill = colour});
}

// ---------------------------------------------------------------------------------------
// Text styles: math in a serif italic, labels in the page's sans.

inline TextStyle math(double size = 15, Anchor anchor = Anchor::middle, const std::string& colour = "#222") {
  return TextStyle{.size = size, .colour = colour, .anchor = anchor, .italic = true, .family = "Georgia, 'Times New Roman', serif"};
}
inline TextStyle label(double size = 12, Anchor anchor = Anchor::start, const std::string& colour = "#222") {
  return TextStyle{.size = size, .colour = colour, .anchor = anchor, .family = sans};
}
inline TextStyle small(double size = 11, Anchor anchor = Anchor::middle, const std::string& colour = text_grey) {
  return label(size, anchor, colour);
}
inline TextStyle heading(double size = 13, Anchor anchor = Anchor::start) {
  TextStyle s = label(size, anchor);
  s.bold = true;
  return s;
}

/// A label placed px_away pixels from p in the page direction away from `from`.
inline void label_away(SvgDocument& doc, const P2& p, const P2& from, const std::string& s, TextStyle style, double px_away = 15) {
  const P2 q = doc.map()(p), c = doc.map()(from);
  V2 d = q - c;
  const double len = norm(d);
  d = len > 0 ? d / len : V2(0.0, -1.0);
  style.anchor = Anchor::middle;
  style.dx = d[0] * px_away;
  style.dy = d[1] * px_away + style.size * 0.35;  // centre the glyphs vertically
  doc.text(p, s, style);
}

/// The width in px of s in a sans or serif font of `size` px, estimated from its
/// characters (narrow, digits, wide, sub- and superscripts), a little generous (DejaVu
/// Sans, the widest of the page's fallback fonts, sets lowercase and digits at about 0.6
/// em); the
/// label-placement check of tests/gallery/label_boxes.py uses the same estimate.
inline double text_width_px(const std::string& s, double size) {
  double em = 0;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c < 0xe0 ? 2 : (c < 0xf0 ? 3 : 4));
    const std::string ch = s.substr(i, n);
    i += n;
    if (n == 1) {
      const std::string_view narrow = "ijl.,:;'|!", thin = "frtI()[]-/ ", wide = "mwMW";
      if (narrow.find(ch[0]) != std::string_view::npos) em += 0.28;
      else if (thin.find(ch[0]) != std::string_view::npos) em += 0.36;
      else if (wide.find(ch[0]) != std::string_view::npos) em += 0.9;
      else if (std::isupper(c)) em += 0.72;
      else em += 0.62;
    } else {
      // Sub- and superscripts (U+2070..U+209F, ¹ ² ³, ᵢ, ⱼ) are small; other symbols about 0.6 em.
      const auto b = [&](std::size_t k) { return static_cast<unsigned char>(ch[k]); };
      const bool script = (n == 3 && b(0) == 0xe2 && ((b(1) == 0x81 && b(2) >= 0xb0) || (b(1) == 0x82 && b(2) <= 0x9f))) ||
                          ch == "\u00b9" || ch == "\u00b2" || ch == "\u00b3" || ch == "\u1d62" || ch == "\u2c7c";
      em += script ? 0.36 : 0.6;
    }
  }
  return em * size;
}

/// A label placed px_away pixels from the page point of p in the unit page direction
/// `dir` (y down), its estimated box (text_width_px) clear of p: the box's nearest side,
/// not its centre, is px_away from p.
inline void label_at(SvgDocument& doc, const P2& p, V2 dir, const std::string& s, TextStyle style, double px_away = 6) {
  const double len = norm(dir);
  dir = len > 0 ? dir / len : V2(0.0, -1.0);
  const double w = text_width_px(s, style.size), h = style.size * 0.97;
  const double reach = px_away + 0.5 * std::abs(dir[0]) * w + 0.5 * std::abs(dir[1]) * h;
  style.anchor = Anchor::middle;
  style.dx = dir[0] * reach;
  style.dy = dir[1] * reach + style.size * (0.75 - 0.97 / 2);  // the box's middle at the offset
  doc.text(p, s, style);
}

/// Places labels clear of the lines drawn and of each other, as the label check of
/// tests/gallery/label_boxes.py wants them (a text box from text_width_px, from 0.75 em
/// above the baseline to 0.22 em below): the obstacles are polylines in page px, given in
/// model coordinates through the document's map at the time; each label tries 16
/// directions about its point, the preferred one first, at three distances.
class LabelPlacer {
 public:
  explicit LabelPlacer(SvgDocument& doc) : doc_(doc) {}

  /// A polyline (model coordinates, the document's current map).
  void avoid(std::span<const P2> model_points) {
    std::vector<P2> page;
    for (const auto& p : model_points) page.push_back(doc_.map()(p));
    lines_.push_back(std::move(page));
  }
  /// A curve, sampled at n + 1 parameters of its domain.
  template <class C>
  void avoid_curve(const C& c, int n = 240) {
    std::vector<P2> pts;
    const auto dom = c.domain();
    for (int i = 0; i <= n; ++i) pts.push_back(c(dom.lo + (dom.hi - dom.lo) * i / n));
    avoid(pts);
  }
  /// A disc of radius r px about the model point p (a marked point).
  void avoid_point(const P2& p, double r) {
    const P2 q = doc_.map()(p);
    boxes_.push_back({q[0] - r, q[1] - r, q[0] + r, q[1] + r});
  }

  /// The label s near the model point p, px_away from it: in the first clear direction
  /// (the preferred page direction, y down, then the others alternating either side of
  /// it), else in the preferred one. Returns whether a clear place was found.
  bool place(const P2& p, const std::string& s, TextStyle style, V2 preferred = V2(0.0, -1.0), double px_away = 5) {
    const P2 q = doc_.map()(p);
    const double len = norm(preferred);
    preferred = len > 0 ? preferred / len : V2(0.0, -1.0);
    const double w = text_width_px(s, style.size), h = style.size * 0.97;
    for (const double factor : {1.0, 2.0, 3.2}) {
      for (int k = 0; k < 16; ++k) {
        const double a = (k % 2 ? -1 : 1) * ((k + 1) / 2) * std::numbers::pi / 8;
        const V2 d(preferred[0] * std::cos(a) - preferred[1] * std::sin(a), preferred[0] * std::sin(a) + preferred[1] * std::cos(a));
        const double reach = px_away * factor + 0.5 * std::abs(d[0]) * w + 0.5 * std::abs(d[1]) * h;
        const P2 c = q + reach * d;
        const Rect r{c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2};
        if (clear(r)) {
          boxes_.push_back(r);
          label_at(doc_, p, d, s, style, px_away * factor);
          return true;
        }
      }
    }
    label_at(doc_, p, preferred, s, style, px_away);
    return false;
  }

 private:
  struct Rect {
    double x0, y0, x1, y1;
  };
  static bool segment_meets(const P2& a, const P2& b, const Rect& r) {  // Liang-Barsky
    double t0 = 0, t1 = 1;
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const std::array<std::array<double, 2>, 4> tests = {{{-dx, a[0] - r.x0}, {dx, r.x1 - a[0]}, {-dy, a[1] - r.y0}, {dy, r.y1 - a[1]}}};
    for (const auto& [den, num] : tests) {
      if (den == 0) {
        if (num < 0) return false;
        continue;
      }
      const double v = num / den;
      if (den < 0) t0 = std::max(t0, v);
      else t1 = std::min(t1, v);
      if (t0 > t1) return false;
    }
    return true;
  }
  bool clear(Rect r) const {
    constexpr double m = 2;  // px: stricter than the check's margins
    if (r.x0 < 2 || r.y0 < 2 || r.x1 > doc_.width() - 2 || r.y1 > doc_.height() - 2) return false;
    r = {r.x0 - m, r.y0 - m, r.x1 + m, r.y1 + m};
    for (const auto& b : boxes_) {
      if (r.x0 < b.x1 && b.x0 < r.x1 && r.y0 < b.y1 && b.y0 < r.y1) return false;
    }
    for (const auto& line : lines_) {
      for (std::size_t i = 1; i < line.size(); ++i) {
        if (segment_meets(line[i - 1], line[i], r)) return false;
      }
    }
    return true;
  }

  SvgDocument& doc_;
  std::vector<std::vector<P2>> lines_;
  std::vector<Rect> boxes_;
};

/// A colour ramp from deep blue through teal and gold to red, s in [0, 1] (for ordered
/// families: basis functions, degrees).
inline std::string ramp(double s) {
  static constexpr std::array<std::array<double, 3>, 4> stops = {{{43, 76, 155}, {26, 150, 120}, {212, 160, 23}, {192, 57, 43}}};
  s = std::clamp(s, 0.0, 1.0) * 3;
  const int i = std::min(2, static_cast<int>(s));
  const double f = s - i;
  char buf[8];
  int c[3];
  for (int k = 0; k < 3; ++k) c[k] = static_cast<int>(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buf;
}

// ---------------------------------------------------------------------------------------
// Boxes.

/// b with a margin m on every side.
inline Box2 grown(Box2 b, double m) {
  for (int i = 0; i < 2; ++i) {
    b.lo[i] -= m;
    b.hi[i] += m;
  }
  return b;
}
/// b with a margin of the fraction f of its extent on every side.
inline Box2 grown_relative(const Box2& b, double f) {
  const double dx = (b.hi[0] - b.lo[0]) * f, dy = (b.hi[1] - b.lo[1]) * f;
  return Box2{{b.lo[0] - dx, b.lo[1] - dy}, {b.hi[0] + dx, b.hi[1] + dy}};
}

// ---------------------------------------------------------------------------------------
// Numbers: fixed and sci for captions (HTML), plain for text inside the pictures.

/// v with a fixed number of decimals for HTML (&minus;, no negative zero).
inline std::string fixed(double v, int decimals = 3) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(decimals);
  os << v;
  std::string s = os.str();
  if (s.find_first_not_of("-0.") == std::string::npos) s = s.substr(s[0] == '-' ? 1 : 0);
  if (!s.empty() && s[0] == '-') s = "&minus;" + s.substr(1);
  return s;
}

/// v in scientific notation for HTML, two significant digits: 2.2 &times; 10<sup>-16</sup>
/// (fixed notation for 0.01 <= |v| < 10^4).
inline std::string sci(double v) {
  if (v == 0) return "0";
  const int e = static_cast<int>(std::floor(std::log10(std::abs(v))));
  if (e >= -2 && e <= 3) return fixed(v, std::max(0, 2 - e));
  double m = v / std::pow(10.0, e);
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(1);
  os << m;
  return os.str() + "&thinsp;&times;&thinsp;10<sup>" + (e < 0 ? "&minus;" + std::to_string(-e) : std::to_string(e)) + "</sup>";
}

/// v with a fixed number of decimals as plain text for SVG (U+2212 minus).
inline std::string plain(double v, int decimals) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(decimals);
  os << v;
  std::string s = os.str();
  if (s.find_first_not_of("-0.") == std::string::npos) return s.substr(s[0] == '-' ? 1 : 0);
  return s[0] == '-' ? "\u2212" + s.substr(1) : s;
}

inline std::string point_text(const P2& p, int decimals = 3) { return "(" + fixed(p[0], decimals) + ", " + fixed(p[1], decimals) + ")"; }

// ---------------------------------------------------------------------------------------
// Measures: the distance from many points to one polyline or point set, exactly the
// smallest over every segment (or point), with runs of 32 segments skipped when their box
// is farther than the best distance found so far. The gallery is compiled at -O0 (build
// time): scanning every segment for each of thousands of points was 80% of its run.

class NearestOn {
 public:
  /// The polyline through pts (segments = true) or the points themselves.
  NearestOn(std::span<const P2> pts, bool segments) : pts_(pts.begin(), pts.end()), segments_(segments && pts.size() > 1) {
    const std::size_t items = count();
    for (std::size_t first = 0; first < items; first += run) {
      const std::size_t last = std::min(items, first + run) - 1 + (segments_ ? 1 : 0);
      Box2 b{pts_[first], pts_[first]};
      for (std::size_t i = first; i <= last; ++i) {
        for (int d = 0; d < 2; ++d) {
          b.lo[d] = std::min(b.lo[d], pts_[i][d]);
          b.hi[d] = std::max(b.hi[d], pts_[i][d]);
        }
      }
      boxes_.push_back(b);
    }
  }

  double distance(const P2& p) const {
    // The run whose box is nearest first, then every run that could hold a nearer item.
    std::vector<double> lower(boxes_.size());
    std::size_t nearest = 0;
    for (std::size_t r = 0; r < boxes_.size(); ++r) {
      const double dx = std::max({boxes_[r].lo[0] - p[0], 0.0, p[0] - boxes_[r].hi[0]});
      const double dy = std::max({boxes_[r].lo[1] - p[1], 0.0, p[1] - boxes_[r].hi[1]});
      lower[r] = std::hypot(dx, dy);
      if (lower[r] < lower[nearest]) nearest = r;
    }
    double best = scan(p, nearest, INFINITY);
    for (std::size_t r = 0; r < boxes_.size(); ++r) {
      // The box's distance can round above a segment's own by an ulp: a margin keeps exact.
      if (r != nearest && lower[r] * (1 - 1e-12) < best) best = scan(p, r, best);
    }
    return best;
  }

 private:
  static constexpr std::size_t run = 32;
  std::size_t count() const { return segments_ ? pts_.size() - 1 : pts_.size(); }
  double scan(const P2& p, std::size_t r, double best) const {
    const std::size_t end = std::min(count(), (r + 1) * run);
    for (std::size_t i = r * run; i < end; ++i) {
      best = std::min(best, segments_ ? distance_to_segment(p, pts_[i], pts_[i + 1]) : casteljau::distance(p, pts_[i]));
    }
    return best;
  }
  std::vector<P2> pts_;
  bool segments_;
  std::vector<Box2> boxes_;
};

}  // namespace casteljau::gallery
