// The `offset` operation of io/ops.hpp on AnyCurve, compiled once on Pieces<double, 2>. It
// sits in the unity group of src/io/intersect.cpp ("solvers"), which already instantiates
// the self-intersections that its trim uses.
#include <cmath>
#include <string>
#include <string_view>
#include <variant>

#include "casteljau/algo/offset.hpp"
#include "casteljau/io/ops.hpp"
#include "work_limits.hpp"

namespace casteljau::io {

namespace {

/// The most cubics an offset may make: with trim, the raw offset's self-intersections cost
/// about 32 n^2 units for n cubics (io/intersect.hpp's intersect_work), 8e8 at 5000, under
/// its limit of 1e9; the fitting alone takes about 1.5 ms of CPU a cubic (a 2400-point
/// polyline, 2768 cubics with its round joins: 4.2 s, measured on the shared machine), so
/// the same limit without trim: several seconds at most.
constexpr double max_offset_segments = 5000;

/// The fitting samples each piece at 16 (n + 1) points and measures each candidate cubic
/// with a few thousand evaluations, each O(n^2) for a piece of degree n: the sum over the
/// pieces of (n + 1)^2 (16 (n + 1) + 20000), limited to 1e9 (a few seconds: a 2400-point
/// polyline is 1.9e8 units, one degree-100 piece 2.2e8).
constexpr double max_offset_piece_work = 1e9;

}  // namespace

AnyCurve offset(const AnyCurve& c, double distance, double tolerance, bool trim, std::string_view join, double miter_limit) {
  if (dimension(c) != 2) {
    throw InvalidArgument("curve", "offset needs a 2-D curve, got a curve of dimension " + std::to_string(dimension(c)));
  }
  require_finite(distance, "distance");
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + casteljau::detail::format_number(tolerance));
  OffsetOptions<double> o;
  o.distance = distance;
  o.tolerance = tolerance;
  o.trim = trim;
  if (join == "round") {
    o.join = OffsetJoin::round;
  } else if (join == "miter") {
    o.join = OffsetJoin::miter;
  } else if (join == "bevel") {
    o.join = OffsetJoin::bevel;
  } else {
    throw InvalidArgument("join", "unknown join '" + std::string(join) + "' (round, miter, bevel)");
  }
  require_finite(miter_limit, "miter_limit");
  if (!(miter_limit >= 1)) {
    throw InvalidArgument("miter_limit", "must be >= 1 (the miter length over |distance|), got " + casteljau::detail::format_number(miter_limit));
  }
  o.miter_limit = miter_limit;
  limits::check_curve_work(c, "curve", "the offset");
  AnyPieces any = pieces(c);
  const auto& p = std::get<Pieces<double, 2>>(any);
  limits::check_work(p, "curve", "the offset");
  double work = 0;
  for (const auto& s : p.segments()) {
    const double m = static_cast<double>(std::visit([](const auto& x) { return x.degree(); }, s)) + 1;
    work += m * m * (16 * m + 20000);
  }
  if (work > max_offset_piece_work) {
    throw InvalidArgument("curve", "the offset would take about " + limits::amount_text(work) +
                                       " units of work ((degree + 1)^2 (16 (degree + 1) + 20000) summed over the Bézier pieces), "
                                       "more than the limit of " +
                                       limits::amount_text(max_offset_piece_work) +
                                       ": use fewer pieces or a lower degree");
  }
  const double limit = max_offset_segments;
  const double estimate = offset_segments_estimate(p, distance, tolerance);
  if (estimate > limit) {
    throw InvalidArgument("tolerance", "the offset would need about " + limits::amount_text(estimate) +
                                           " cubic segments, more than the limit of " + limits::amount_text(limit) +
                                           ": use a larger tolerance or fewer pieces");
  }
  o.max_segments = static_cast<std::size_t>(limit);
  OffsetCurve<double> r = casteljau::offset(p, o);
  std::vector<Segment<double, 2>> segs;
  segs.reserve(r.segments.size());
  for (auto& b : r.segments) segs.emplace_back(std::move(b));
  return AnyCurve(Path<double, 2>(std::move(segs)));
}

}  // namespace casteljau::io
