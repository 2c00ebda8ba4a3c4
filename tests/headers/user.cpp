// A user's file: the public headers used as a program would, instantiating the
// algorithms whose code sits in the headers (tests/headers/check_headers.py compiles it
// with g++ and clang at -O0 and -O2 under -Wall -Wextra -Wpedantic -Werror).
#include "casteljau/casteljau.hpp"

#include <vector>

namespace user {

using namespace casteljau;

std::size_t flatten_all(const Bezier<double, 2>& cubic, const RationalBezier<double, 2>& arc, const Bezier<float, 2>& small) {
  std::vector<Point<double, 2>> out;
  flatten(cubic, 0.1, out.empty() ? FlattenMethod::optimal : FlattenMethod::uniform, out);
  flatten(arc, 0.1, FlattenMethod::subdivision, out);
  return out.size() + flatten(small, 0.1f).size() + static_cast<std::size_t>(flatten_count_estimate(cubic, 0.1));
}

double queries(const Bezier<double, 2>& a, const Bezier<double, 2>& b, const BSpline<double, 3>& s) {
  const auto hits = intersect(a, b);
  const auto box = bounds(a);
  return static_cast<double>(hits.points.size()) + box.hi[0] + arc_length(a) + s(s.domain().lo)[2];
}

std::size_t fitted(const std::vector<Point<double, 2>>& points) {
  FitRequest<double, 2> request;
  request.parametrization = Parametrization::centripetal;
  return fit(points, request).curve.points().size();
}

}  // namespace user
