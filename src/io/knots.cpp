// The run-time knot operations of io/knots.hpp: each visits the curve and calls the
// B-spline or NURBS member of curves/bspline.hpp.
#include "casteljau/io/knots.hpp"

#include <string>
#include <utility>
#include <variant>

#include "casteljau/algo/subdivision.hpp"

namespace casteljau::io {

AnyCurve insert_knot(const AnyCurve& c, double u, int times) {
  return std::visit(
      [&]<class C>(const C& x) -> AnyCurve {
        if constexpr (requires { x.insert_knot(u, times); }) {
          return AnyCurve(x.insert_knot(u, times));
        } else {
          throw InvalidArgument("curve.type", "insert_knot needs " + types_phrase(Capability::knot_insertion) + ", got a " + std::string(type_name(c)));
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
          throw InvalidArgument("curve.type", "remove_knot needs " + types_phrase(Capability::knot_removal) + ", got a " + std::string(type_name(c)));
        }
      },
      c);
}

namespace {

template <int D>
AnySubdivision subdivide_in(const PointList& L, SubdivisionScheme scheme, int degree, double tension, int k, bool closed) {
  std::vector<Point<double, D>> P(L.size());
  for (std::size_t i = 0; i < L.size(); ++i)
    for (int d = 0; d < D; ++d) P[i][d] = L[i][static_cast<std::size_t>(d)];
  AnySubdivision out{PointList{D, {}}, std::nullopt};
  std::vector<Point<double, D>> Q;
  if (scheme == SubdivisionScheme::four_point) {
    Q = four_point(P, k, closed, tension);
  } else {
    const int p = scheme == SubdivisionScheme::chaikin ? 2 : degree;
    Q = lane_riesenfeld(P, p, k, closed);
    out.limit = AnyCurve(lane_riesenfeld_limit(P, p, closed));
  }
  out.points.coords.reserve(Q.size() * D);
  for (const auto& q : Q) out.points.push_back(q);
  return out;
}

}  // namespace

AnySubdivision subdivide(const PointList& P, SubdivisionScheme scheme, int degree, double tension, int iterations, bool closed) {
  return dispatch_dimension(P.dim, [&]<int D>() { return subdivide_in<D>(P, scheme, degree, tension, iterations, closed); });
}

}  // namespace casteljau::io
