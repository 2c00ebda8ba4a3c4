// A tour of the Bézier core: evaluation, derivatives, split, elevation, tight bounds, an
// exact rational quarter circle and a C2 composite curve. Run it: build/examples/basics
#include <cmath>
#include <cstdio>
#include <numbers>

#include <casteljau/casteljau.hpp>

using namespace casteljau;
using P = Point<double, 2>;

int main() {
  // A cubic: P(t) = sum B(i,3)(t) P_i over [0, 1].
  const Bezier<double, 2> c{P(0, 0), P(1, 2), P(3, 2), P(4, 0)};
  const P mid = c(0.5);                            // de Casteljau: (2, 1.5)
  const Vector<double, 2> tangent = c.derivative_at(0.5);  // (4.5, 0)
  std::printf("c(0.5) = (%g, %g), c'(0.5) = (%g, %g)\n", mid[0], mid[1], tangent[0], tangent[1]);

  // Split at 0.4: two cubics that together trace the same curve.
  const auto [left, right] = c.split(0.4);
  std::printf("left ends at (%g, %g) = c(0.4)\n", left.points().back()[0], left.points().back()[1]);

  // Degree elevation keeps the curve; reduction finds the best lower-degree curve.
  const auto reduced = reduce_degree(c.elevate(2), 3);
  std::printf("elevate 3->5 then reduce to 3: error bound %.2g\n", reduced.error_bound);

  // The tight box comes from the roots of the derivative, not the control points.
  const auto box = bounds(c), loose = c.control_bounds();
  std::printf("bounds y in [%g, %g]; control points reach %g\n", box.lo[1], box.hi[1], loose.hi[1]);

  // An exact quarter circle: weights 1, cos(45 deg), 1.
  const auto arc = RationalBezier<double, 2>::circular_arc(P(0, 0), 1.0, 0.0, std::numbers::pi / 2);
  const P q = arc(0.3);
  std::printf("quarter circle: |q(0.3)| = %.17g, curvature %.17g\n", std::hypot(q[0], q[1]), *curvature(arc, 0.3));

  // A composite curve joined with C2 continuity: the next segment's first three control
  // points follow from the previous segment.
  auto head = cr_join_points(c, 1.0, 3, 1.0, 2);
  head.push_back(P(8, 1));
  const Path<double, 2> path({c, Bezier<double, 2>(head)});
  std::printf("joint is C%d\n", parametric_continuity(path, 1, 3, 1e-9));
  return 0;
}
