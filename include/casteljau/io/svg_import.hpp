// Reading SVG: path data (the `d` grammar of SVG 1.1/2) and the drawing elements of a
// document (path, rect, circle, ellipse, line, polyline, polygon inside nested g, a and
// svg with their transforms) as exact Bézier and rational quadratic Bézier segments.
// Plain data (no curve types): compiled in src/io/path_data.cpp and src/io/svg_import.cpp,
// written as curve JSON by the `import_svg` command (src/io/commands_ops.cpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::io {

using SvgPoint = std::array<double, 2>;

/// One segment: a Bézier of degree points.size() - 1 (1..3) when weights is empty, else a
/// rational quadratic Bézier (3 points, weights {1, cos(theta/2), 1}: an elliptical arc of
/// theta <= 90 degrees).
struct SvgSegment {
  std::vector<SvgPoint> points;
  std::vector<double> weights;
};

/// One subpath: consecutive segments (each starts where the one before ends), at least
/// one. A closed one ends at its start (the closing line is a segment of its own when the
/// last drawn point differs from the start).
struct SvgSubpath {
  std::vector<SvgSegment> segments;
  bool closed = false;
};

/// A 2-D affine map x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct SvgTransform {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  [[nodiscard]] SvgPoint operator()(const SvgPoint& p) const { return {a * p[0] + c * p[1] + e, b * p[0] + d * p[1] + f}; }
  /// this after inner: (this * inner)(p) = this(inner(p)).
  [[nodiscard]] SvgTransform operator*(const SvgTransform& inner) const;
};

/// The subpaths of SVG path data d (SVG 1.1 section 8.3 and its grammar 8.3.9; SVG 2 9.3):
/// moveto, lineto (L, H, V), cubic (C, S) and quadratic (Q, T) Béziers, elliptical arcs
/// (A) and closepath (Z), absolute and relative, with implicit repeated commands (pairs
/// after M are lines). S and T reflect the previous control point only after C/S (resp.
/// Q/T), else their first control point is the current point. Arcs follow the
/// implementation notes F.6: end points equal gives no segment (F.6.2), a zero radius a
/// line, negative radii their absolute value, radii too small for the end points scaled
/// up by sqrt(Lambda) (F.6.6); the arc (F.6.5's centre parametrisation) becomes
/// ceil(|delta theta| / 90 degrees) rational quadratic pieces of equal angle delta, each
/// in the ellipse's frame the unit circle's exact piece (control point at the bisecting
/// angle, distance 1 / cos(delta / 2), weight cos(delta / 2)), mapped by centre, radii
/// and x-axis-rotation. After Z the current point is the subpath's start and a command
/// other than M starts a new subpath there. Subpaths without segments (a lone M, "M 1 1
/// Z") are left out. Every point is mapped by `transform` (affine maps keep Bézier and
/// rational Bézier forms exact; the weights do not change).
///
/// Numbers are SVG's: [sign] (digits [. digits*] | . digits) [e [sign] digits], so
/// ".5.5" is two numbers and "10-5" too; flags of A are one character 0 or 1 and need no
/// separator ("a1 1 0 00 1 1"). Errors (InvalidArgument, where "d[k]": k the offset of
/// the offending character in d): path data not starting with M or m, an unknown
/// command letter, a missing or malformed number ("expected a number after 'L'"), a
/// flag that is not 0 or 1, a comma not followed by a number, a coordinate that
/// overflows (not finite after the transform).
[[nodiscard]] std::vector<SvgSubpath> parse_path_data(std::string_view d, const SvgTransform& transform = {});

/// Appends the elliptical arc from `from` to `to` (SVG's A: radii rx, ry, x-axis rotation
/// phi in degrees, large-arc and sweep flags) to segments as parse_path_data does (F.6.2,
/// F.6.5, F.6.6), untransformed; `from` and `to` are kept exactly as the first and last
/// points. Used for rect corners, circles and ellipses too.
void append_arc(std::vector<SvgSegment>& segments, const SvgPoint& from, double rx, double ry, double phi_degrees, bool large_arc,
                bool sweep, const SvgPoint& to);

/// One drawing element read: its id attribute (or none), its element name and its
/// subpaths in user coordinates after every transform (empty when it draws nothing: a
/// rect of zero width, a circle of radius 0, a path with empty d).
struct SvgShape {
  std::string element;
  std::optional<std::string> id;
  std::vector<SvgSubpath> subpaths;
};

/// An element that draws but is not read (text, image, use, switch, foreignObject, an
/// element unknown to SVG 1.1/2's drawing model...).
struct SvgSkipped {
  std::string element;
  std::optional<std::string> id;
};

struct SvgImport {
  std::vector<SvgShape> paths;
  std::vector<SvgSkipped> skipped;
};

/// Reads the SVG document `svg` (XML by pugixml): the drawing elements in document order
/// (see docs/cli.md, import_svg, for the element rules: rect corners, auto radii and
/// clamping; polygon points; lengths in px or absolute units; nested svg viewports;
/// what is skipped). The root element's viewBox is not applied. Errors: InvalidArgument
/// with where "svg" (malformed XML, root not svg, nesting deeper than 256), or
/// "svg.paths[i](#id).ATTRIBUTE[k]" for an attribute of the i-th drawing element (k the
/// offset in the attribute's text, where it has one), "svg.g[j](#id).transform[k]" (and
/// svg, a) for a container's attribute.
[[nodiscard]] SvgImport import_svg(std::string_view svg);

/// A list of numbers separated by whitespace and at most one comma each (the `points` of
/// polyline and polygon, viewBox), with path data's number grammar. Errors:
/// InvalidArgument "<field>[k]".
[[nodiscard]] std::vector<double> parse_number_list(std::string_view text, std::string_view field);

/// SVG's transform list (SVG 1.1 section 7.6): matrix, translate, scale, rotate (about a
/// point), skewX, skewY, separated by whitespace and commas, composed left to right.
/// Errors: InvalidArgument "transform[k]".
[[nodiscard]] SvgTransform parse_transform(std::string_view text);

}  // namespace casteljau::io
