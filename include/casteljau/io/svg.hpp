// SVG output: a small document writer with a model-to-page transform (SvgDocument,
// PageMap), and render_svg, the renderer of the `render` command and of the gallery.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// Styling of render_svg; every field has a default. The CLI reads these from the
/// request's optional fields of the same names.
struct RenderStyle {
  double width = 640;                 ///< page width in px, 1..1e6
  double height = 480;                ///< page height in px, 1..1e6
  double padding = 24;                ///< margin around the curves' bounds in px, >= 0, leaving >= 1 px to draw in
  std::string background = "white";   ///< CSS colour, or "none"
  std::string stroke = "#1f77b4";     ///< curve colour (a palette is used when several curves are drawn and stroke is unset)
  double stroke_width = 2;            ///< px, > 0
  bool control_polygon = true;        ///< draw control points and polygon
  bool axes = false;                  ///< draw the coordinate axes when they are in view
  double tolerance = 0;               ///< flattening tolerance in model units; 0: 0.25 px mapped to model units
};

/// An SVG document drawing 2D curves (1D curves as graphs y(t) over their domain) fitted
/// into the page with the y axis pointing up. Throws InvalidArgument for curves of
/// dimension 3 or 4 or a bad style.
///
/// Details: a style field that breaks its rule is named in the error ("width", ...), as is
/// a padding that leaves less than 1 px to draw in (min(width, height) - 2 padding < 1).
/// Width and height are 1 to 1e6 px (curves are flattened to a fraction of a px: the page
/// size bounds the document). A curve of the wrong dimension is named "curve" when it is
/// the only one, "curves[i]" otherwise, as is a curve that cannot be drawn (its mapped
/// control points overflow, or lie so far off the page that flattening it within the
/// tolerance is below their resolution). The view is the union of the curves' tight
/// bounds (and of their control points when the control polygon is drawn); 2D curves
/// keep their aspect ratio, 1D graphs alone are stretched to the page. A view of zero
/// width or height (a point, a horizontal line), or one within rounding of its position,
/// is widened about its centre (PageMap::fit). Bézier segments of degree <= 3 are written
/// exactly as SVG L/Q/C commands; other segments are flattened (flatten) in page space
/// within style.tolerance times the page scale, or within 0.25 px when tolerance is 0,
/// but never below 0.001 px, the resolution of the numbers written. A stroke that is
/// empty or equal to the default means "unset": one curve is drawn in the default colour,
/// several in palette colours. An empty background means "none". Colour strings are
/// XML-escaped, not checked. No curves: an empty page (with axes about the origin if
/// asked).
std::string render_svg(std::span<const AnyCurve> curves, const RenderStyle& style = {});

// ---------------------------------------------------------------------------------------
// The document writer.

using Point2 = Point<double, 2>;
using Box2 = Box<double, 2>;

/// A rectangle in page coordinates (px, y pointing down, as in SVG).
struct PageRect {
  double x = 0;
  double y = 0;
  double width = 0;
  double height = 0;
};

/// How PageMap::fit fills the page: `keep` uses one scale for both axes (geometry keeps
/// its shape), `stretch` scales each axis to fill the rectangle (graphs, where x and y
/// have different units).
enum class Aspect { keep, stretch };

/// The affine map from model coordinates to page px, page = q + S (x - c) with S =
/// diag(sx, sy): written about the model centre c and its page position q, so that a
/// model far from the origin keeps its precision (the form A x + b would cancel
/// catastrophically). The default is the identity (model coordinates are page px, y
/// down); fit() gives y up.
class PageMap {
 public:
  PageMap() = default;

  /// The map that fits `model` into `page`, centred, y up. Extents are computed as
  /// hi/2 - lo/2, so a model box spanning [-1e308, 1e308] fits. A zero extent along an
  /// axis, or one within 2^-46 of the box's centre (64 to 128 ulps: rounding, not
  /// geometry; a box 4 units wide at 1e13 is not flat), is widened to a unit extent, or to
  /// 1e-3 of the centre's magnitude when that is larger, so that a point or a horizontal
  /// segment maps to the centre of the page without dividing by zero; with Aspect::keep
  /// the other axis then sets the scale. An empty model box is taken as [-1, 1]^2. Throws
  /// InvalidArgument("model", ...) for non-finite bounds and ("page", ...) for a
  /// rectangle with a non-finite field or without positive width and height, or one so
  /// small against the model that the scale underflows to 0.
  static PageMap fit(const Box2& model, const PageRect& page, Aspect aspect = Aspect::keep);

  /// The page position of model point p: q + s (p - c), or q + (s p - s c) where p - c
  /// overflows (p and c near the range of double, of opposite signs; s is small there).
  [[nodiscard]] Point2 operator()(const Point2& p) const { return {along(p[0], cx_, qx_, sx_), along(p[1], cy_, qy_, sy_)}; }
  /// The model point at page position q.
  [[nodiscard]] Point2 to_model(const Point2& q) const { return {cx_ + (q[0] - qx_) / sx_, cy_ + (q[1] - qy_) / sy_}; }
  /// The same map as an Affine A x + b. Less accurate than operator() for models far from
  /// the origin; the document maps curves point by point instead.
  [[nodiscard]] Affine<double, 2> affine() const;
  /// Page px per model unit along x and y (> 0).
  [[nodiscard]] double scale_x() const { return sx_ < 0 ? -sx_ : sx_; }
  [[nodiscard]] double scale_y() const { return sy_ < 0 ? -sy_ : sy_; }
  /// A page length in model units: px / min(scale_x, scale_y), so that a model distance
  /// below the result is below px on the page in every direction.
  [[nodiscard]] double px_to_model(double px) const;
  /// The model box that the map sends onto the page rectangle (the whole visible region,
  /// padding included when the rectangle is the page), clamped to the finite doubles.
  [[nodiscard]] Box2 view(const PageRect& page) const;

 private:
  static double along(double p, double c, double q, double s) {
    const double d = p - c;
    return q + (std::isfinite(d) ? s * d : s * p - s * c);
  }
  PageMap(double cx, double cy, double qx, double qy, double sx, double sy)
      : cx_(cx), cy_(cy), qx_(qx), qy_(qy), sx_(sx), sy_(sy) {}
  double cx_ = 0, cy_ = 0;  ///< model centre
  double qx_ = 0, qy_ = 0;  ///< its page position
  double sx_ = 1, sy_ = 1;  ///< px per model unit (sy < 0: y up)
};

/// Stroke and fill of a drawn element; colours are any CSS colour string ("none" for no
/// paint). Widths in px (unaffected by the model scale).
struct Paint {
  std::string stroke = "none";
  double stroke_width = 1;
  std::string fill = "none";
  double opacity = 1;       ///< of the whole element, in [0, 1]
  double fill_opacity = 1;  ///< of the fill only, in [0, 1]
  std::string dash = {};    ///< stroke-dasharray in px, e.g. "5 3"; empty: solid
};

enum class Anchor { start, middle, end };

/// Text appearance. The anchor point is a model point; dx, dy shift it in px (dy down).
struct TextStyle {
  double size = 12;  ///< font size in px
  std::string colour = "#222";
  Anchor anchor = Anchor::start;
  bool italic = false;
  bool bold = false;
  double dx = 0;
  double dy = 0;
  std::string family = {};  ///< CSS font-family; empty: inherited
};

/// A categorical colour: i-th of 8 distinguishable hues (cycles), the first being
/// RenderStyle's default stroke.
std::string_view palette(std::size_t i);

/// s with & < > " ' replaced by entities and the control characters that XML 1.0 forbids
/// removed: safe inside text and attribute values.
std::string xml_escape(std::string_view s);

/// A finite number as written in SVG: fixed point with at most 3 decimals (1/1000 px),
/// trailing zeros and "-0" dropped; magnitudes >= 1e15 in shortest exponent form.
/// Throws InvalidArgument(where, ...) for NaN or infinity.
std::string svg_number(double v, std::string_view where = "value");

/// About `count` round tick values (1, 2 or 5 times a power of 10 apart) covering
/// [lo, hi]; empty when the interval is empty, not finite or count < 1.
std::vector<double> nice_ticks(double lo, double hi, int count);

/// A tick label: v with the decimals the step needs to be exact (step 0.25: two), trailing
/// zeros dropped, a typographic minus (U+2212); exponent form beyond 1e7 or below 1e-4.
std::string tick_label(double v, double step);

/// Writes an SVG document element by element. Drawing calls take model points and send
/// them through the current map (set_map; the identity by default), so each panel of a
/// figure can have its own fit; sizes (stroke widths, radii, fonts) are px. Every number
/// is checked: a non-finite one throws InvalidArgument naming the argument, so the output
/// never holds "nan" or "inf".
class SvgDocument {
 public:
  /// The default flattening tolerance of curve(): a quarter pixel.
  static constexpr double default_tolerance_px = 0.25;

  /// A width x height px page. Throws InvalidArgument("width"/"height") unless finite > 0.
  SvgDocument(double width, double height);

  [[nodiscard]] double width() const { return width_; }
  [[nodiscard]] double height() const { return height_; }

  void set_map(const PageMap& map) { map_ = map; }
  [[nodiscard]] const PageMap& map() const { return map_; }

  /// The accessible name of the picture (<title>, shown as a tooltip by browsers).
  void title(std::string_view text);
  /// Fills (and strokes) a page rectangle, in page px: not sent through the map.
  void rect(const PageRect& r, const Paint& paint, double corner_radius = 0);
  void line(const Point2& a, const Point2& b, const Paint& paint);
  void polyline(std::span<const Point2> points, const Paint& paint);
  /// A closed polygon.
  void polygon(std::span<const Point2> points, const Paint& paint);
  /// A circle of radius_px page pixels about the model point c.
  void circle(const Point2& c, double radius_px, const Paint& paint);
  /// A line from a to b with a filled arrow head of length head_px at b (stroke colour).
  void arrow(const Point2& a, const Point2& b, const Paint& paint, double head_px = 8);
  void text(const Point2& at, std::string_view s, const TextStyle& style = {});

  /// A curve as one <path>: Bézier segments of degree <= 3 exactly (L, Q, C commands in
  /// page space, exact because Bézier curves are affinely invariant), the others
  /// flattened in page space within tolerance_px (>= 0.001 px, the written resolution).
  void curve(const Bezier<double, 2>& c, const Paint& paint, double tolerance_px = default_tolerance_px);
  void curve(const RationalBezier<double, 2>& c, const Paint& paint, double tolerance_px = default_tolerance_px);
  void curve(const Pieces<double, 2>& c, const Paint& paint, double tolerance_px = default_tolerance_px);
  void curve(const Path<double, 2>& c, const Paint& paint, double tolerance_px = default_tolerance_px);

  /// <g class="css_class"> ... </g>; groups nest. str() closes any left open.
  void begin_group(std::string_view css_class = {});
  void end_group();

  /// The document: <svg xmlns=... width height viewBox> + elements + </svg>.
  [[nodiscard]] std::string str() const;

 private:
  void open(std::string_view tag);
  void attr(std::string_view name, double v);
  void attr(std::string_view name, std::string_view v);
  void paint_attrs(const Paint& p);
  void points_attr(std::span<const Point2> points);
  void path_element(const std::string& d, const Paint& paint);

  double width_;
  double height_;
  PageMap map_{};
  std::string title_;
  std::string body_;
  int depth_ = 0;
};

}  // namespace casteljau::io
