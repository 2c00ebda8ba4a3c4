// The import_svg command of issue 17 (one entry of the registry, io/commands.hpp): an SVG
// document or path data read by io/svg_import.hpp and written as curve JSON (paths of
// bezier and rational_bezier segments, as to_json writes a path).
#include <span>
#include <string>

#include "casteljau/core/error.hpp"
#include "casteljau/io/svg_import.hpp"
#include "commands_family.hpp"

namespace casteljau::io::detail {

namespace {

OrderedJson point_json(const SvgPoint& p) { return OrderedJson::array({p[0], p[1]}); }

/// A subpath as a curve-JSON path (breaks 0, 1, ..., k as the library writes them).
OrderedJson subpath_json(const SvgSubpath& s) {
  OrderedJson segments = OrderedJson::array();
  OrderedJson breaks = OrderedJson::array({0.0});
  for (const auto& seg : s.segments) {
    OrderedJson points = OrderedJson::array();
    for (const auto& p : seg.points) points.push_back(point_json(p));
    if (seg.weights.empty()) {
      segments.push_back(OrderedJson{{"type", "bezier"}, {"points", std::move(points)}});
    } else {
      segments.push_back(OrderedJson{{"type", "rational_bezier"}, {"points", std::move(points)}, {"weights", seg.weights}});
    }
    breaks.push_back(static_cast<double>(breaks.size()));
  }
  return OrderedJson{{"type", "path"}, {"segments", std::move(segments)}, {"breaks", std::move(breaks)}};
}

OrderedJson id_json(const std::optional<std::string>& id) { return id ? OrderedJson(*id) : OrderedJson(nullptr); }

OrderedJson shape_json(const std::optional<std::string>& id, const std::vector<SvgSubpath>& subpaths) {
  OrderedJson curves = OrderedJson::array(), closed = OrderedJson::array();
  for (const auto& s : subpaths) {
    curves.push_back(subpath_json(s));
    closed.push_back(s.closed);
  }
  return OrderedJson{{"id", id_json(id)}, {"subpaths", std::move(curves)}, {"closed", std::move(closed)}};
}

Response import_svg(const Args& a) {
  const bool svg = a.has("svg"), d = a.has("d");
  if (svg == d) {
    if (svg) throw InvalidArgument("d", "give svg (a document) or d (path data), not both");
    throw InvalidArgument("svg", "required field is missing (give svg, an SVG document, or d, path data)");
  }
  OrderedJson paths = OrderedJson::array(), skipped = OrderedJson::array();
  if (d) {
    paths.push_back(shape_json(std::nullopt, parse_path_data(a.string("d"))));
  } else {
    const SvgImport doc = io::import_svg(a.string("svg"));
    for (const auto& s : doc.paths) paths.push_back(shape_json(s.id, s.subpaths));
    for (const auto& s : doc.skipped) skipped.push_back(OrderedJson{{"element", s.element}, {"id", id_json(s.id)}});
  }
  return {OrderedJson{{"paths", std::move(paths)}, {"skipped", std::move(skipped)}}};
}

constexpr Field import_svg_fields[] = {
    {"svg", FieldType::string, false, {}, "an SVG document (give svg or d)"},
    {"d", FieldType::string, false, {}, "SVG path data alone (give svg or d)"},
};

constexpr Command svg_import_family[] = {
    {"import_svg", "Curves of an SVG document or of SVG path data",
     "The drawing elements of an SVG document (path, rect, circle, ellipse, line, polyline,\n"
     "polygon, inside nested g, a and svg), in document order, as paths of bezier (degree\n"
     "1..3) and rational_bezier segments, in user coordinates after every transform (the\n"
     "root's viewBox is not applied). Path data follows SVG 1.1/2: absolute and relative\n"
     "commands, implicit repeats, H/V, S/T reflecting the previous control point after\n"
     "C/S (Q/T), arcs as exact rational quadratic pieces of at most 90 degrees (weights\n"
     "cos(theta/2); end points equal: left out; a zero radius: a line; radii too small:\n"
     "scaled up, SVG F.6.6). A subpath closed by Z ends at its start. Elements that draw\n"
     "but are not read (text, image, use, switch, foreignObject, unknown elements) are\n"
     "listed in skipped; definitions (defs, symbol, clipPath, mask, marker, pattern...)\n"
     "are not read. Lengths: px or absolute units (in, cm, mm, pt, pc, Q); relative units\n"
     "(%, em...) are refused. Errors in path data give the offset: d[12], or inside a\n"
     "document svg.paths[3](#id).d[12].",
     "paths: [{id (or null), subpaths: [path curve, ...], closed: [bool, ...]}, ...];\n"
     "          skipped: [{element, id}, ...]",
     R"(  echo '{"d": "M0 0 h1 v1 z"}' | casteljau import_svg
  {"paths":[{"id":null,"subpaths":[{"type":"path","segments":[{"type":"bezier","points":[[0.0,0.0],[1.0,0.0]]},{"type":"bezier","points":[[1.0,0.0],[1.0,1.0]]},{"type":"bezier","points":[[1.0,1.0],[0.0,0.0]]}],"breaks":[0.0,1.0,2.0,3.0]}],"closed":[true]}],"skipped":[]})",
     import_svg_fields, import_svg, "", ""},
};

}  // namespace

std::span<const Command> svg_import_commands() { return svg_import_family; }

}  // namespace casteljau::io::detail
