// The run-time knot operations of io/knots.hpp: each visits the curve and calls the
// B-spline or NURBS member of curves/bspline.hpp.
#include "casteljau/io/knots.hpp"

#include <string>
#include <variant>

namespace casteljau::io {

AnyCurve insert_knot(const AnyCurve& c, double u, int times) {
  return std::visit(
      [&]<class C>(const C& x) -> AnyCurve {
        if constexpr (requires { x.insert_knot(u, times); }) {
          return AnyCurve(x.insert_knot(u, times));
        } else {
          throw InvalidArgument("curve.type", "insert_knot needs a bspline or nurbs curve, got a " + std::string(type_name(c)));
        }
      },
      c);
}

AnyKnotRemoval remove_knot(const AnyCurve& c, double u, int times, double tolerance) {
  return std::visit(
      [&]<class C>(const C& x) -> AnyKnotRemoval {
        if constexpr (requires { x.remove_knot(u, times, tolerance); }) {
          auto r = x.remove_knot(u, times, tolerance);
          return {AnyCurve(std::move(r.curve)), r.removed};
        } else {
          throw InvalidArgument("curve.type", "remove_knot needs a bspline or nurbs curve, got a " + std::string(type_name(c)));
        }
      },
      c);
}

}  // namespace casteljau::io
