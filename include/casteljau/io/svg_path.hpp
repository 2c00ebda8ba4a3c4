// SVG path data out (issue 17): any 2-D curve as the `d` attribute of an SVG `path`,
// exact where SVG can hold the piece (M, L, Q, C, A), cubics within a tolerance elsewhere.
// Compiled once, in src/io/svg_path.cpp (on Pieces<double, 2>).
#pragma once

#include <optional>
#include <string>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// The path data of a curve and how faithful it is.
struct SvgPathData {
  std::string d;             ///< "M x y C ... Z": numbers in shortest round-trip form
  bool exact = true;         ///< every piece written exactly (no approximation)
  double max_deviation = 0;  ///< largest distance (at equal parameters) of an approximating cubic from its piece; 0 when exact
  std::size_t cubics = 0;    ///< how many approximating cubics were written (0 when exact)
};

/// The curve (2-D) as SVG path data, one command per exact Bézier piece (pieces(c)):
/// - polynomial pieces of degree 0..3 exactly: a point (only an M when it starts a
///   subpath, nothing when it is the current point), L, Q, C; a rational piece with equal
///   weights is polynomial, a rational line is its segment (L);
/// - rational quadratics, normalised to end weights 1 (w = w1 / sqrt(w0 w2)): w = 1
///   (within 1e-12) is a parabola (Q); w < 1 an elliptical arc, written as A with its
///   radii, rotation and flags (centre (M - w^2 P1) / (1 - w^2), M the chord's midpoint;
///   conjugate semi-diameters w (M - P1) / (1 - w^2) and (P2 - P0) / (2 sqrt(1 - w^2)),
///   whose 2x2 SVD gives the axes [Lee87; Farin02, 12.5]); an arc of more than about 91
///   degrees (w < 0.7) is split at t = 1/2 into two A commands (an A near a half ellipse
///   is ill-conditioned to read back); a degenerate (collinear) arc whose middle point
///   lies between its ends is its segment (L);
/// - every other piece (polynomial of degree > 3, rational of degree > 2 with unequal
///   weights, hyperbolic or collinear-folded conics) by cubics, each the Hermite cubic
///   matching the piece's points and first derivatives at both ends of a parameter
///   interval, greedily as long as it stays within `tolerance` (the distance at equal
///   parameters, measured by algo/deviation.hpp, bounds the Hausdorff distance): the
///   fewest cubics when a shorter interval fits whenever a longer one does.
/// Consecutive pieces that meet (within 1e-12 of the curve's size, the largest absolute
/// coordinate of a control point) continue the subpath; a gap starts a new one with M.
/// A subpath whose end meets its start is closed with Z.
/// Accuracy: exact pieces read back to rounding (an A to about 1e-16 of its larger
/// radius, which grows as 1 / (1 - w^2) for w near 1). Errors: InvalidArgument "curve"
/// (not 2-D; the work limit), "tolerance" (needed and absent, not > 0, or too small to
/// reach within 10000 cubics or below the rounding of the curve).
[[nodiscard]] SvgPathData to_svg_path(const AnyCurve& c, std::optional<double> tolerance);

}  // namespace casteljau::io
