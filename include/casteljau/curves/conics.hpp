// Exact conics as NURBS: circular arcs of any sweep, full circles and ellipses (and their
// arcs), as rational quadratic B-splines [PT97, A7.1 and §7.5].
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/nurbs.hpp"

namespace casteljau {

/// The elliptic arc C(theta) = O + cos(theta) X + sin(theta) Y for theta from `start` to
/// `end` (radians, end > start, end - start <= 2 pi), as a degree-2 NURBS on [0, 1], in
/// any dimension D >= 2. X and Y are conjugate semi-diameters: perpendicular and of equal
/// length r give the circle of radius r, perpendicular of lengths a and b the ellipse with
/// those semi-axes; any independent pair gives the affine image of the circle, which is
/// an ellipse too. Construction [PT97, A7.1]: the sweep is cut into k = ceil(sweep /
/// (pi / 2)) equal arcs of angle d (at most a quarter, so every weight is >= cos(pi / 4));
/// each is the rational quadratic Bézier with end points on the curve, middle point
/// O + (cos(mid) X + sin(mid) Y) / cos(d / 2) (where the end tangents meet) and middle
/// weight cos(d / 2); knots 0 (3 times), 1/k, 1/k, .., 1 (3 times). Exact: the points lie
/// on the conic up to rounding (a few eps of |O| + |X| + |Y|); a full turn ends exactly at
/// its start point; the parametrization is not the angle (it is rational). A sweep within
/// the rounding of the angles of 2 pi (4 eps max(|start|, |end|, 2 pi), see
/// full_turn_slack), over or under, is the full turn, closed exactly: end = start + 2 pi
/// computed in floating point is one. Scale-invariant: any semi-diameters whose control points are finite work (radius
/// 1e-300 or 1e300). Errors: "start_angle"/"end_angle" non-finite, "end_angle" for a
/// sweep not in (0, 2 pi], `axes_field` (default "axes") for non-finite, zero or
/// dependent X, Y, or for control points that overflow (|O| + sqrt 2 |X| beyond the
/// largest T).
template <class T, int D>
Nurbs<T, D> nurbs_ellipse_arc(const Point<T, D>& O, const Vector<T, D>& X, const Vector<T, D>& Y, T start, T end,
                              std::string_view axes_field = "axes");

/// The slack allowed over 2 pi for a full turn from `start` to `end`: the rounding of
/// end = start + 2 pi and of end - start (a few ulps of the largest angle).
template <class T>
T full_turn_slack(T start, T end) {
  return 4 * std::numeric_limits<T>::epsilon() * std::max({std::abs(start), std::abs(end), 2 * std::numbers::pi_v<T>});
}

template <class T, int D>
Nurbs<T, D> nurbs_ellipse_arc(const Point<T, D>& O, const Vector<T, D>& X, const Vector<T, D>& Y, T start, T end,
                              std::string_view axes_field) {
  static_assert(D >= 2, "a conic needs at least two dimensions");
  const std::string axes(axes_field);
  require_finite(start, "start_angle");
  require_finite(end, "end_angle");
  require_finite_point(O, "center");
  require_finite_point(Point<T, D>::from_vector(X), axes);
  require_finite_point(Point<T, D>::from_vector(Y), axes);
  const T two_pi = 2 * std::numbers::pi_v<T>;
  const bool full_turn = std::abs((end - start) - two_pi) <= full_turn_slack(start, end);
  const T sweep = full_turn ? two_pi : end - start;
  if (!(sweep > 0) || sweep > two_pi) {
    throw InvalidArgument("end_angle", "the sweep end_angle - start_angle must be in (0, 2 pi], got " + detail::format_number(end - start));
  }
  // Independence: |X|^2 |Y|^2 - (X.Y)^2 > 0 (the Gram determinant), relative, computed on
  // X and Y divided by their largest coordinates (no overflow or underflow at any scale).
  T sx = 0, sy = 0;
  for (int i = 0; i < D; ++i) {
    sx = std::max(sx, std::abs(X[i]));
    sy = std::max(sy, std::abs(Y[i]));
  }
  if (!(sx > 0 && sy > 0)) throw InvalidArgument(axes, "the two semi-diameters must be non-zero");
  const Vector<T, D> Xs = (1 / sx) * X, Ys = (1 / sy) * Y;
  const T xx = dot(Xs, Xs), yy = dot(Ys, Ys), xy = dot(Xs, Ys);
  if (!(xx * yy - xy * xy > xx * yy * T(1e-24))) {
    throw InvalidArgument(axes, "the two semi-diameters must be independent");
  }
  int k = 1;
  while (k < 4 && sweep > static_cast<T>(k) * (std::numbers::pi_v<T> / 2)) ++k;
  const T d = sweep / static_cast<T>(k);
  const T w1 = std::cos(d / 2);
  const auto at = [&](T theta, T scale) { return O + (scale * std::cos(theta)) * X + (scale * std::sin(theta)) * Y; };
  std::vector<Point<T, D>> P;
  std::vector<T> w;
  std::vector<T> U{0, 0, 0};
  P.push_back(at(start, 1));
  w.push_back(1);
  for (int i = 0; i < k; ++i) {
    const T a0 = start + static_cast<T>(i) * d;
    // The last arc ends exactly at `end` (no accumulated rounding in the angle).
    const T a1 = i + 1 == k ? end : start + static_cast<T>(i + 1) * d;
    P.push_back(at(a0 / 2 + a1 / 2, 1 / w1));
    w.push_back(w1);
    P.push_back(at(a1, 1));
    w.push_back(1);
    if (i + 1 < k) {
      const T u = static_cast<T>(i + 1) / static_cast<T>(k);
      U.push_back(u);
      U.push_back(u);
    }
  }
  // A full turn closes exactly (cos and sin of start + 2 pi in floating point miss the
  // start point by an ulp or two).
  if (full_turn) P.back() = P.front();
  for (const Point<T, D>& p : P) {
    for (int i = 0; i < D; ++i) {
      if (!std::isfinite(p[i])) {
        throw InvalidArgument(axes, "too large: the conic's control points (center + up to sqrt 2 times the semi-diameters) "
                                    "overflow");
      }
    }
  }
  U.insert(U.end(), {T(1), T(1), T(1)});
  return Nurbs<T, D>(2, std::move(U), std::move(P), std::move(w));
}

/// The full ellipse O + cos(theta) X + sin(theta) Y, theta in [0, 2 pi]: four quarter
/// arcs, nine control points, weights 1, 1/sqrt 2, 1, .. [PT97, Ex. 7.2 for the circle].
template <class T, int D>
Nurbs<T, D> nurbs_ellipse(const Point<T, D>& O, const Vector<T, D>& X, const Vector<T, D>& Y) {
  return nurbs_ellipse_arc(O, X, Y, T(0), 2 * std::numbers::pi_v<T>);
}

/// The circular arc of radius r > 0 about O in the plane from angle `start` to `end`
/// (counter-clockwise; sweep in (0, 2 pi]). Errors also "radius".
template <class T>
Nurbs<T, 2> nurbs_arc(const Point<T, 2>& O, T radius, T start, T end) {
  require_finite(radius, "radius");
  if (!(radius > 0)) throw InvalidArgument("radius", "radius must be > 0, got " + detail::format_number(radius));
  return nurbs_ellipse_arc(O, Vector<T, 2>(radius, T(0)), Vector<T, 2>(T(0), radius), start, end, "radius");
}

/// The full circle of radius r > 0 about O, starting at O + (r, 0), counter-clockwise.
template <class T>
Nurbs<T, 2> nurbs_circle(const Point<T, 2>& O, T radius) {
  return nurbs_arc(O, radius, T(0), 2 * std::numbers::pi_v<T>);
}

}  // namespace casteljau
