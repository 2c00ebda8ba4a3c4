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
  if (auto* q = std::get_if<Pieces<double, 2>>(&p)) return std::move(*q);
  throw InvalidArgument(where, "intersect needs 2-D curves, got a curve of dimension " + std::to_string(dimension(c)));
}

AnyIntersections convert(const Intersections<double>& r) {
  AnyIntersections out;
  for (const auto& p : r.points)
    out.points.push_back({p.ta, p.tb, {p.point[0], p.point[1]}, p.kind == IntersectionKind::tangent});
  for (const auto& o : r.overlaps) out.overlaps.push_back({o.a.lo, o.a.hi, o.b_start, o.b_end});
  return out;
}

}  // namespace

AnyIntersections intersect(const AnyCurve& a, const AnyCurve& b) {
  const Pieces<double, 2> pa = planar(a, "curves[0]");
  const Pieces<double, 2> pb = planar(b, "curves[1]");
  return convert(casteljau::intersect(pa, pb));
}

AnyIntersections self_intersect(const AnyCurve& a) { return convert(casteljau::self_intersect(planar(a, "curves[0]"))); }

}  // namespace casteljau::io
