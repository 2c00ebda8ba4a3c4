// Reading an SVG document (io/svg_import.hpp): the XML tree by pugixml, walked in document
// order with the current transform; the drawing elements as SVG 2 defines their
// equivalent paths (rect, circle, ellipse, line, polyline, polygon), path data by
// parse_path_data (src/io/path_data.cpp).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include <pugixml.hpp>

#include "casteljau/core/error.hpp"
#include "casteljau/io/svg_import.hpp"

namespace casteljau::io {

namespace {

constexpr int max_depth = 256;
constexpr std::string_view svg_namespace = "http://www.w3.org/2000/svg";

std::string_view trimmed(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

/// Text from the input for a message: at most 32 bytes, then "…".
std::string clipped(std::string_view s) { return s.size() <= 32 ? std::string(s) : std::string(s.substr(0, 32)) + "\u2026"; }

/// A length: a number with an optional unit. px and none as they are, the absolute units
/// by CSS's fixed ratios (1in = 96px = 2.54cm = 25.4mm = 72pt = 6pc = 101.6Q); relative
/// units (%, em, ex, ...) need a viewport or a font this reader does not have: refused.
double length(std::string_view text, std::string_view field) {
  const std::string_view t = trimmed(text);
  std::size_t unit = t.size();
  while (unit > 0 && (std::isalpha(static_cast<unsigned char>(t[unit - 1])) || t[unit - 1] == '%')) --unit;
  // An exponent's 'e' belongs to the number ("1e2"): only letters after the last digit.
  const std::string_view u = t.substr(unit);
  std::vector<double> v;
  try {
    v = parse_number_list(t.substr(0, unit), field);
  } catch (const InvalidArgument&) {
    v.clear();
  }
  if (v.size() != 1) throw InvalidArgument(std::string(field), "expected a length (a number with an optional unit), got '" + clipped(t) + "'");
  double scale = 1;
  if (u.empty() || u == "px") scale = 1;
  else if (u == "in") scale = 96;
  else if (u == "cm") scale = 96 / 2.54;
  else if (u == "mm") scale = 96 / 25.4;
  else if (u == "pt") scale = 96.0 / 72;
  else if (u == "pc") scale = 16;
  else if (u == "Q" || u == "q") scale = 96 / 101.6;
  else {
    throw InvalidArgument(std::string(field), "'" + clipped(t) + "': the unit '" + clipped(u) +
                                                  "' is relative or unknown (read: px, in, cm, mm, pt, pc, Q)");
  }
  const double x = v[0] * scale;
  if (!std::isfinite(x)) throw InvalidArgument(std::string(field), "'" + clipped(t) + "' is out of range");
  return x;
}

struct Walker {
  SvgImport doc;
  std::size_t g_count = 0, svg_count = 0, a_count = 0;

  static std::optional<std::string> id_of(const pugi::xml_node& n) {
    const pugi::xml_attribute a = n.attribute("id");
    return a ? std::optional<std::string>(a.value()) : std::nullopt;
  }

  static std::string owner(std::string_view list, std::size_t index, const std::optional<std::string>& id) {
    std::string s = "svg." + std::string(list) + "[" + std::to_string(index) + "]";
    if (id) s += "(#" + *id + ")";
    return s;
  }

  /// The local name of an SVG element, or empty for an element of another namespace
  /// (an editor's own elements: sodipodi:namedview, inkscape:...). `default_ns` is the
  /// default namespace in scope (xmlns). A prefix is resolved by the nearest xmlns:prefix
  /// declaration; leniently, a document without declarations is SVG (no xmlns: the SVG
  /// namespace; the prefix svg undeclared: too).
  static std::string_view local_name(const pugi::xml_node& n, std::string_view default_ns) {
    std::string_view name = n.name();
    const auto colon = name.find(':');
    if (colon == std::string_view::npos) return default_ns == svg_namespace ? name : std::string_view();
    const std::string_view prefix = name.substr(0, colon);
    const std::string declaration = "xmlns:" + std::string(prefix);
    std::string_view ns = prefix == "svg" ? svg_namespace : std::string_view();
    for (pugi::xml_node p = n; p; p = p.parent()) {
      if (const pugi::xml_attribute a = p.attribute(declaration.c_str())) {
        ns = a.value();
        break;
      }
    }
    return ns == svg_namespace ? name.substr(colon + 1) : std::string_view();
  }

  /// The default namespace of n's content: its xmlns, else the one in scope.
  static std::string_view default_namespace(const pugi::xml_node& n, std::string_view in_scope) {
    const pugi::xml_attribute a = n.attribute("xmlns");
    return a ? std::string_view(a.value()) : in_scope;
  }

  static SvgTransform own_transform(const pugi::xml_node& n) {
    const pugi::xml_attribute t = n.attribute("transform");
    return t ? parse_transform(t.value()) : SvgTransform{};
  }

  static double length_attr(const pugi::xml_node& n, const char* name, double fallback) {
    const pugi::xml_attribute a = n.attribute(name);
    return a ? length(a.value(), name) : fallback;
  }

  /// rx or ry of rect and ellipse: a length, or auto (absent or "auto": std::nullopt).
  static std::optional<double> auto_length(const pugi::xml_node& n, const char* name) {
    const pugi::xml_attribute a = n.attribute(name);
    if (!a || trimmed(a.value()) == "auto") return std::nullopt;
    return length(a.value(), name);
  }

  static void non_negative(double v, const char* name) {
    if (v < 0) {
      char text[32];
      const auto r = std::to_chars(text, text + sizeof text, v);  // shortest round-trip form
      throw InvalidArgument(name, "must be >= 0, got " + std::string(text, r.ptr));
    }
  }

  /// The element's subpaths in its own user space (before the transform).
  static std::vector<SvgSubpath> shape(std::string_view name, const pugi::xml_node& n, const SvgTransform& m) {
    std::vector<SvgSubpath> out;
    const auto closed_loop = [&](std::vector<SvgSegment> segs) {
      if (!segs.empty()) out.push_back({std::move(segs), true});
    };
    if (name == "path") return parse_path_data(n.attribute("d").value(), m);
    if (name == "rect") {
      const double x = length_attr(n, "x", 0), y = length_attr(n, "y", 0);
      const double w = length_attr(n, "width", 0), h = length_attr(n, "height", 0);
      non_negative(w, "width");
      non_negative(h, "height");
      std::optional<double> rx = auto_length(n, "rx"), ry = auto_length(n, "ry");
      if (rx) non_negative(*rx, "rx");
      if (ry) non_negative(*ry, "ry");
      if (w == 0 || h == 0) return out;  // rendering disabled (SVG 2, 10.2)
      // SVG 2 10.2: an auto radius takes the other's value (both auto: 0), then each is
      // clamped to half the side.
      double rxv = rx ? *rx : ry ? *ry : 0, ryv = ry ? *ry : rx ? *rx : 0;
      rxv = std::min(rxv, w / 2);
      ryv = std::min(ryv, h / 2);
      std::vector<SvgSegment> s;
      if (rxv == 0 || ryv == 0) {
        const SvgPoint a{x, y}, b{x + w, y}, c{x + w, y + h}, d{x, y + h};
        s = {{{a, b}, {}}, {{b, c}, {}}, {{c, d}, {}}, {{d, a}, {}}};
      } else {
        // The equivalent path of SVG 2 10.2: from (x + rx, y) clockwise on screen (y down),
        // a line along each side (left out when the corners meet) and a quarter arc at
        // each corner.
        const auto side = [&](const SvgPoint& a, const SvgPoint& b) {
          if (a != b) s.push_back({{a, b}, {}});
        };
        const auto corner = [&](const SvgPoint& a, const SvgPoint& b) { append_arc(s, a, rxv, ryv, 0, false, true, b); };
        side({x + rxv, y}, {x + w - rxv, y});
        corner({x + w - rxv, y}, {x + w, y + ryv});
        side({x + w, y + ryv}, {x + w, y + h - ryv});
        corner({x + w, y + h - ryv}, {x + w - rxv, y + h});
        side({x + w - rxv, y + h}, {x + rxv, y + h});
        corner({x + rxv, y + h}, {x, y + h - ryv});
        side({x, y + h - ryv}, {x, y + ryv});
        corner({x, y + ryv}, {x + rxv, y});
      }
      closed_loop(std::move(s));
    } else if (name == "circle" || name == "ellipse") {
      const double cx = length_attr(n, "cx", 0), cy = length_attr(n, "cy", 0);
      double rx = 0, ry = 0;
      if (name == "circle") {
        rx = ry = length_attr(n, "r", 0);
        non_negative(rx, "r");
      } else {
        const std::optional<double> a = auto_length(n, "rx"), b = auto_length(n, "ry");
        if (a) non_negative(*a, "rx");
        if (b) non_negative(*b, "ry");
        rx = a ? *a : b ? *b : 0;
        ry = b ? *b : a ? *a : 0;
      }
      if (rx == 0 || ry == 0) return out;  // rendering disabled
      // SVG 2 10.3/10.4: from (cx + rx, cy), four quarter arcs in the positive angle
      // direction (clockwise on screen).
      const SvgPoint p[] = {{cx + rx, cy}, {cx, cy + ry}, {cx - rx, cy}, {cx, cy - ry}};
      std::vector<SvgSegment> s;
      for (int i = 0; i < 4; ++i) append_arc(s, p[i], rx, ry, 0, false, true, p[(i + 1) % 4]);
      closed_loop(std::move(s));
    } else if (name == "line") {
      const SvgPoint a{length_attr(n, "x1", 0), length_attr(n, "y1", 0)}, b{length_attr(n, "x2", 0), length_attr(n, "y2", 0)};
      out.push_back({{{{a, b}, {}}}, false});
    } else {  // polyline, polygon
      const std::vector<double> v = parse_number_list(n.attribute("points").value(), "points");
      if (v.size() % 2 != 0) {
        throw InvalidArgument("points", "an odd number of coordinates (" + std::to_string(v.size()) + "): the last point has no y");
      }
      std::vector<SvgSegment> s;
      for (std::size_t i = 2; i + 1 < v.size(); i += 2) s.push_back({{{v[i - 2], v[i - 1]}, {v[i], v[i + 1]}}, {}});
      const bool closed = name == "polygon";
      if (closed && v.size() >= 4) {
        const SvgPoint last{v[v.size() - 2], v[v.size() - 1]}, first{v[0], v[1]};
        if (last != first) s.push_back({{last, first}, {}});
      }
      if (!s.empty()) out.push_back({std::move(s), closed});
    }
    for (auto& sub : out) {
      for (auto& seg : sub.segments) {
        for (auto& p : seg.points) {
          p = m(p);
          if (!std::isfinite(p[0]) || !std::isfinite(p[1])) throw InvalidArgument("transform", "a coordinate overflows after the transform");
        }
      }
    }
    return out;
  }

  /// A nested svg's viewport: translate(x, y), then its viewBox onto (width, height) by
  /// preserveAspectRatio (SVG 1.1 7.8; default xMidYMid meet).
  static SvgTransform viewport(const pugi::xml_node& n) {
    SvgTransform t{1, 0, 0, 1, length_attr(n, "x", 0), length_attr(n, "y", 0)};
    const pugi::xml_attribute vb = n.attribute("viewBox");
    if (!vb) return t;
    const std::vector<double> v = parse_number_list(vb.value(), "viewBox");
    if (v.size() != 4) throw InvalidArgument("viewBox", "needs 4 numbers (min-x min-y width height), got " + std::to_string(v.size()));
    if (!(v[2] > 0 && v[3] > 0)) throw InvalidArgument("viewBox", "width and height must be > 0");
    if (!n.attribute("width") || !n.attribute("height")) {
      throw InvalidArgument("viewBox", "a nested svg with a viewBox needs width and height (the default 100% is relative)");
    }
    const double w = length_attr(n, "width", 0), h = length_attr(n, "height", 0);
    double sx = w / v[2], sy = h / v[3];
    std::string_view par = trimmed(n.attribute("preserveAspectRatio").value());
    if (par.empty()) par = "xMidYMid meet";
    double ax = 0.5, ay = 0.5;
    if (par.substr(0, 4) == "none") {
      ax = ay = 0;
    } else {
      if (par.size() < 8 || par[0] != 'x' || par[4] != 'Y') {
        throw InvalidArgument("preserveAspectRatio", "expected none or x(Min|Mid|Max)Y(Min|Mid|Max) [meet|slice]");
      }
      const auto align = [&](std::string_view a) {
        if (a == "Min") return 0.0;
        if (a == "Mid") return 0.5;
        if (a == "Max") return 1.0;
        throw InvalidArgument("preserveAspectRatio", "expected Min, Mid or Max, got '" + std::string(a) + "'");
      };
      ax = align(par.substr(1, 3));
      ay = align(par.substr(5, 3));
      const bool slice = trimmed(par.substr(8)) == "slice";
      const double s = slice ? std::max(sx, sy) : std::min(sx, sy);
      sx = sy = s;
    }
    const double tx = -v[0] * sx + ax * (w - v[2] * sx), ty = -v[1] * sy + ay * (h - v[3] * sy);
    return t * SvgTransform{sx, 0, 0, sy, tx, ty};
  }

  void walk(const pugi::xml_node& parent, const SvgTransform& m, int depth, std::string_view parent_ns) {
    if (depth > max_depth) throw InvalidArgument("svg", "elements nest deeper than " + std::to_string(max_depth) + " levels");
    for (pugi::xml_node n = parent.first_child(); n; n = n.next_sibling()) {
      if (n.type() != pugi::node_element) continue;
      const std::string_view ns = default_namespace(n, parent_ns);
      const std::string_view name = local_name(n, ns);
      if (name.empty()) continue;
      if (name == "path" || name == "rect" || name == "circle" || name == "ellipse" || name == "line" || name == "polyline" ||
          name == "polygon") {
        SvgShape s{std::string(name), id_of(n), {}};
        const std::size_t index = doc.paths.size();
        try {
          s.subpaths = shape(name, n, m * own_transform(n));
        } catch (const InvalidArgument& e) {
          throw e.within(owner("paths", index, s.id));
        }
        doc.paths.push_back(std::move(s));
      } else if (name == "g" || name == "a" || name == "svg") {
        std::size_t& count = name == "g" ? g_count : name == "a" ? a_count : svg_count;
        const std::size_t index = count++;
        SvgTransform inner;
        try {
          inner = m * own_transform(n);
          if (name == "svg") inner = inner * viewport(n);
        } catch (const InvalidArgument& e) {
          throw e.within(owner(name, index, id_of(n)));
        }
        walk(n, inner, depth + 1, ns);
      } else if (is_non_rendering(name)) {
        continue;
      } else {
        doc.skipped.push_back({std::string(name), id_of(n)});
      }
    }
  }

  /// Elements that draw nothing themselves (definitions, resources, descriptions,
  /// animation): neither read nor listed.
  static bool is_non_rendering(std::string_view name) {
    static constexpr std::string_view names[] = {
        "defs", "symbol", "clipPath", "mask", "marker", "pattern", "linearGradient", "radialGradient", "meshgradient",
        "filter", "style", "script", "title", "desc", "metadata", "font", "font-face", "glyph", "missing-glyph",
        "color-profile", "cursor", "view", "animate", "animateColor", "animateMotion", "animateTransform", "set", "mpath",
        "solidcolor", "hatch", "discard"};
    return std::find(std::begin(names), std::end(names), name) != std::end(names);
  }
};

}  // namespace

SvgImport import_svg(std::string_view svg) {
  pugi::xml_document xml;
  const pugi::xml_parse_result r = xml.load_buffer(svg.data(), svg.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!r) {
    throw InvalidArgument("svg[" + std::to_string(r.offset) + "]", std::string("malformed XML: ") + r.description());
  }
  const pugi::xml_node root = xml.document_element();
  const std::string_view ns = root ? Walker::default_namespace(root, svg_namespace) : svg_namespace;
  if (!root || Walker::local_name(root, ns) != "svg") {
    const std::string other = ns == svg_namespace ? "" : " in namespace '" + clipped(ns) + "'";
    throw InvalidArgument("svg", "the document's root element is <" + clipped(root ? root.name() : "") + ">" + other + ", not <svg>");
  }
  Walker w;
  SvgTransform m;
  try {
    m = Walker::own_transform(root);
  } catch (const InvalidArgument& e) {
    throw e.within("svg.svg[0]");
  }
  w.svg_count = 1;
  w.walk(root, m, 1, ns);
  return std::move(w.doc);
}

}  // namespace casteljau::io
