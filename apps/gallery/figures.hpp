// The gallery's figures: each one a function that computes its picture and its numbers
// with the library and returns them as an inline SVG plus an HTML caption.
#pragma once

#include <string>
#include <vector>

namespace casteljau::gallery {

/// One figure of the page.
struct Figure {
  std::string id;       ///< HTML anchor, e.g. "bernstein"
  std::string title;    ///< the property shown; the caption's heading (plain text)
  std::string svg;      ///< an <svg> element (SvgDocument::str())
  std::string caption;  ///< explanation with the measured numbers (HTML)
};

using FigureFunction = Figure (*)();

/// Every figure in page order. To add one: write a FigureFunction in figures.cpp and
/// append it here (docs/gallery.md).
const std::vector<FigureFunction>& figure_list();

/// Interpolating cubics (figures_interp.cpp): the four cubic spline end conditions on one
/// data set; monotone (PCHIP) Hermite interpolation against the natural spline.
Figure spline_boundaries();
Figure monotone_vs_natural();

/// The page: a self-contained HTML document (inline CSS and SVG, no scripts).
std::string html_page(const std::vector<Figure>& figures);

}  // namespace casteljau::gallery
