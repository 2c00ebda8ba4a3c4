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

/// Figures of the geometric queries (figures_queries.cpp).
Figure closest_points();
Figure curvature_comb();
/// Figures of intersections and flattening (figures_intersect.cpp).
Figure intersections();
Figure flattening_methods();
/// Figures of the interpolating polynomial curves (figures_interp_poly.cpp).
Figure runge_phenomenon();
Figure catmull_rom_alpha();
Figure hermite_basis();

/// Every figure in page order. To add one: write a FigureFunction in figures.cpp and
/// append it here (docs/gallery.md).
const std::vector<FigureFunction>& figure_list();

/// B-spline, NURBS and subdivision figures (figures_bspline.cpp).
Figure knot_insertion();
Figure nurbs_circle_figure();
Figure subdivision_schemes();
Figure four_point_scheme();
/// B-spline bases, local control and fitting (figures_bspline_basis.cpp).
Figure bspline_basis_functions();
Figure local_control();
Figure noisy_fit();
/// Interpolating cubics (figures_interp.cpp): the four cubic spline end conditions on one
/// data set; monotone (PCHIP) Hermite interpolation against the natural spline.
Figure spline_boundaries();
Figure monotone_vs_natural();

/// A word in a TrueType and a CFF font with its flattening (figures_glyphs.cpp).
Figure glyph_outlines_figure();

/// Surfaces (figures_surfaces.cpp, issue 19): drawn by the `render` command.
Figure surface_of_revolution();
Figure lofted_hull();
Figure coons_patch();
Figure bicubic_patch_with_net();
Figure torus_tessellation();

/// Constructions and frames (figures_constructions.cpp): de Boor's construction, the
/// blossom, a NURBS family under one weight, knot removal, Frenet and rotation-minimizing
/// frames of a space curve.
Figure de_boor_construction();
Figure blossoming();
Figure nurbs_weight_family();
Figure knot_removal();
Figure space_curve_frames();

/// The page: a self-contained HTML document (inline CSS and SVG, no scripts).
std::string html_page(const std::vector<Figure>& figures);

}  // namespace casteljau::gallery
