// The `intersect` operation on AnyCurve, compiled once: every curve becomes its exact
// Bézier pieces, so the algorithm is instantiated for Pieces<double, 2> alone.
#include "casteljau/io/intersect.hpp"

#include <string>
#include <variant>

#include "casteljau/algo/intersect.hpp"

namespace casteljau::io {

namespace {

Pieces<double, 2> planar(const AnyCurve& c, const char* where) {
  AnyPieces p = pieces(c);
  auto* q = std::get_if<Pieces<double, 2>>(&p);
  if (!q) throw InvalidArgument(where, "intersect needs 2-D curves, got a curve of dimension " + std::to_string(dimension(c)));
  for (const auto& s : q->segments()) {
    const int n = std::visit([](const auto& x) { return x.degree(); }, s);
    if (n > max_intersect_degree) {
      throw InvalidArgument(where, "intersect handles pieces up to degree " + std::to_string(max_intersect_degree) + ", got degree " +
                                       std::to_string(n) + " (the cost grows about as the cube of the degree)");
    }
  }
  return std::move(*q);
}

}  // namespace

Intersections<double> intersect(const AnyCurve& a, const AnyCurve& b) {
  const Pieces<double, 2> pa = planar(a, "curves[0]");
  const Pieces<double, 2> pb = planar(b, "curves[1]");
  return casteljau::intersect(pa, pb);
}

Intersections<double> self_intersect(const AnyCurve& a) { return casteljau::self_intersect(planar(a, "curves[0]")); }

}  // namespace casteljau::io
