// The gallery's look and its number formats, shared by every figures_*.cpp: one set of
// colours, strokes, point marks and text styles, and one way to write a number in a
// caption (HTML) or in a picture (plain SVG text).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <sstream>
#include <string>

#include "casteljau/core/interval.hpp"
#include "casteljau/core/point.hpp"
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

}  // namespace casteljau::gallery
