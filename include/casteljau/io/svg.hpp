// SVG output: a small document writer with a model-to-page transform, and the renderer
// of the `render` command. (Being written; see the gallery.)
#pragma once

#include <span>
#include <string>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// Styling of render_svg; every field has a default. The CLI reads these from the
/// request's optional fields of the same names.
struct RenderStyle {
  double width = 640;                 ///< page width in px, > 0
  double height = 480;                ///< page height in px, > 0
  double padding = 24;                ///< margin around the curves' bounds in px, >= 0
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
std::string render_svg(std::span<const AnyCurve> curves, const RenderStyle& style = {});

}  // namespace casteljau::io
