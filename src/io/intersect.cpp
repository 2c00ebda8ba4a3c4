// The `intersect` operation on AnyCurve, compiled once: every curve becomes its exact
// Bézier pieces, so the algorithm is instantiated for Pieces<double, 2> alone.
#include "casteljau/io/intersect.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <variant>

#include "casteljau/algo/intersect.hpp"
#include "casteljau/algo/scalar_forms.hpp"
#include "work_limits.hpp"

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

/// The sums over a curve's pieces of (n + 1), (n + 1)^2 and (n + 1)^3, n a piece's degree.
struct PieceSums {
  double s1 = 0, s2 = 0, s3 = 0;
};

/// A piece with extreme weights is intersected through its tame parts
/// (algo/intersect/tame.hpp: 256 at weights 1, 1e300, 1, those within 1e-13 of the size
/// of each other taken as one chord: about 80 pieces), each a piece of the same degree (a chord: degree 1):
/// counted as such, with the runs of the piece's own size (at most the parts solve_extreme
/// makes, whose runs are of the larger size of both curves).
PieceSums piece_sums(const Pieces<double, 2>& p) {
  namespace isect = casteljau::detail::isect;
  PieceSums s;
  auto add = [&](double m) {
    s.s1 += m;
    s.s2 += m * m;
    s.s3 += m * m * m;
  };
  for (const auto& seg : p.segments()) {
    if (isect::standard_weight_spread(seg) > isect::tame_trigger<double>) {
      const Box<double, 2> box = std::visit([](const auto& x) { return x.control_bounds(); }, seg);
      const auto t = isect::tame(Pieces<double, 2>(std::vector<BezierPiece<double, 2>>{seg}), 1e-13 * norm(box.hi - box.lo));
      for (const auto& part : t.curve.segments()) add(static_cast<double>(std::visit([](const auto& x) { return x.points().size(); }, part)));
      continue;
    }
    add(static_cast<double>(std::visit([](const auto& x) { return x.points().size(); }, seg)));
  }
  return s;
}

/// The same sums for the curve as given, before its pieces are made (for a B-spline of
/// degree p on n control points that alone costs O(n p^2)): at most n - p pieces of degree
/// p. Nothing for the types without a single degree (paths, interpolating splines), which
/// are checked on their pieces.
std::optional<PieceSums> given_sums(const AnyCurve& c) {
  return std::visit(
      [](const auto& x) -> std::optional<PieceSums> {
        if constexpr (requires { x.degree(); x.points(); }) {
          const double m = static_cast<double>(x.degree()) + 1;
          const double k = std::max(1.0, static_cast<double>(x.points().size()) - m + 1);
          return PieceSums{k * m, k * m * m, k * m * m * m};
        } else {
          return std::nullopt;
        }
      },
      c);
}

/// Refuses a curve whose conversion to Bézier pieces alone would take more than the
/// other queries' limit (see io/queries.hpp): pieces x (degree + 1)^2 from given_sums.
void check_conversion(const AnyCurve& c, const char* where) {
  const auto x = given_sums(c);
  if (x && x->s2 > casteljau::detail::max_query_work) {
    throw InvalidArgument(where, "making the curve's Bézier pieces would take about " + limits::amount_text(x->s2) +
                                     " units of work (pieces x (degree + 1)^2), more than the limit of " +
                                     limits::amount_text(casteljau::detail::max_query_work) +
                                     ": use fewer control points or a lower degree");
  }
}

/// The estimate of intersect_work from the sums (y null: the self-intersections of x).
double work_of(const PieceSums& x, const PieceSums* y) {
  // Over i, j: a_i b_j (a_i + b_j) / 2 with a_i = n_i + 1, b_j = m_j + 1.
  if (y) return (x.s2 * y->s1 + x.s1 * y->s2) / 2;
  // The pairs i < j of one curve: half the sum over i != j.
  return (x.s2 * x.s1 - x.s3) / 2;
}

/// Refuses a request whose estimate (intersect_work) is past max_intersect_work, naming
/// `field` and the figures.
void check_intersect_work(double work, const std::string& field) {
  if (work > max_intersect_work) {
    throw InvalidArgument(field, "intersect would take about " + limits::amount_text(work) +
                                     " units of work (pairs of Bézier pieces, (n + 1)(m + 1)(n + m + 2) / 2 summed over them for "
                                     "degrees n and m), more than the limit of " +
                                     limits::amount_text(max_intersect_work) +
                                     ": use fewer pieces or points, or a lower degree");
  }
}

/// The parameters of a curve on a single parameter (a one-point lagrange, whose pieces
/// run to the next double) set to that parameter; others are left as they are.
Intersections<double> on_domains(Intersections<double> r, const Interval<double>& da, const Interval<double>& db) {
  if (da.lo == da.hi) {
    for (auto& x : r.points) x.ta = da.lo;
    for (auto& o : r.overlaps) o.a = da;
  }
  if (db.lo == db.hi) {
    for (auto& x : r.points) x.tb = db.lo;
    for (auto& o : r.overlaps) o.b_start = o.b_end = db.lo;
  }
  return r;
}

}  // namespace

double intersect_work(const Pieces<double, 2>& a, const Pieces<double, 2>* b) {
  const PieceSums x = piece_sums(a);
  if (!b) return work_of(x, nullptr);
  const PieceSums y = piece_sums(*b);
  return work_of(x, &y);
}

Intersections<double> intersect(const AnyCurve& a, const AnyCurve& b) {
  if (const auto x = given_sums(a), y = given_sums(b); x && y && dimension(a) == 2 && dimension(b) == 2)
    check_intersect_work(work_of(*x, &*y), "curves");
  check_conversion(a, "curves[0]");
  check_conversion(b, "curves[1]");
  const Pieces<double, 2> pa = planar(a, "curves[0]");
  const Pieces<double, 2> pb = planar(b, "curves[1]");
  check_intersect_work(intersect_work(pa, &pb), "curves");
  return on_domains(casteljau::intersect(pa, pb), domain(a), domain(b));
}

Intersections<double> self_intersect(const AnyCurve& a) {
  if (const auto x = given_sums(a); x && dimension(a) == 2) check_intersect_work(work_of(*x, nullptr), "curves[0]");
  check_conversion(a, "curves[0]");
  const Pieces<double, 2> p = planar(a, "curves[0]");
  check_intersect_work(intersect_work(p, nullptr), "curves[0]");
  return on_domains(casteljau::self_intersect(p), domain(a), domain(a));
}

}  // namespace casteljau::io
