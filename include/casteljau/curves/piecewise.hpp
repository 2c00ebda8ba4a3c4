// Piecewise curves: segments joined at breaks u_0 < u_1 < ... < u_k, each segment's own
// domain mapped affinely onto its break interval. `Pieces` (Bézier and rational Bézier
// segments) is the exact form every curve type converts to and every query works on.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "casteljau/curves/bezier.hpp"
#include "casteljau/curves/rational_bezier.hpp"

namespace casteljau {

/// A curve parameter located on its piece: the piece's index and its own parameter there
/// (PiecewiseCurve::locate).
template <class T>
struct PieceParameter {
  std::size_t index;
  T t;
};

namespace detail {

/// The parameter in [to.lo, to.hi] of the parameter s of [from.lo, from.hi] under the
/// increasing affine map between them; the ends map exactly onto the ends.
template <class T>
T map_parameter(T s, const Interval<T>& from, const Interval<T>& to) {
  if (s == from.lo) return to.lo;
  if (s == from.hi) return to.hi;
  return to.lo + (s - from.lo) / from.length() * to.length();
}

/// Checks breaks for k segments: k >= 1, k + 1 finite, strictly increasing breaks.
/// Throws InvalidArgument naming "segments", "breaks" or "breaks[i]".
template <class T>
void check_breaks(const std::vector<T>& breaks, std::size_t k) {
  if (k == 0) throw InvalidArgument("segments", "a path needs at least one segment");
  if (breaks.size() != k + 1) {
    throw InvalidArgument("breaks", "needs one more break than segments: " + std::to_string(k) + " segments but " +
                                        std::to_string(breaks.size()) + " breaks");
  }
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    const std::string where = "breaks[" + std::to_string(i) + "]";
    require_finite(breaks[i], where);
    if (i > 0 && !(breaks[i] > breaks[i - 1])) {
      throw InvalidArgument(where, "breaks must be strictly increasing (" + format_number(breaks[i]) + " after " +
                                       format_number(breaks[i - 1]) + ")");
    }
  }
  // Parameters are mapped through break lengths: the domain's length must be a double.
  if (!std::isfinite(breaks.back() - breaks.front())) {
    throw InvalidArgument("breaks", "the domain [" + format_number(breaks.front()) + ", " + format_number(breaks.back()) +
                                        "] is longer than the largest double");
  }
}

/// Shared implementation of Path and Pieces (CRTP: Derived is the concrete type, built by
/// reverse() and transform()). Segment is a std::variant of curve types, each with
/// domain(), operator(), derivative_at(t, k) and reverse(), transform() that keep its
/// domain. Invariants (checked in the constructor): at least one segment, k + 1 finite,
/// strictly increasing breaks for k segments.
template <class Derived, class T, int D, class Segment>
class PiecewiseCurve {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using SegmentType = Segment;
  static constexpr int dimension = D;

  /// Segments with the default breaks 0, 1, ..., k.
  explicit PiecewiseCurve(std::vector<Segment> segments)
      : segments_(std::move(segments)), breaks_(default_breaks(segments_.size())) {
    validate();
  }
  PiecewiseCurve(std::vector<Segment> segments, std::vector<T> breaks)
      : segments_(std::move(segments)), breaks_(std::move(breaks)) {
    validate();
  }

  [[nodiscard]] const std::vector<Segment>& segments() const { return segments_; }
  [[nodiscard]] const std::vector<T>& breaks() const { return breaks_; }
  [[nodiscard]] std::size_t size() const { return segments_.size(); }
  [[nodiscard]] Interval<T> domain() const { return {breaks_.front(), breaks_.back()}; }
  /// The break interval [u_i, u_{i+1}] of segment i.
  [[nodiscard]] Interval<T> segment_domain(std::size_t i) const { return {breaks_[i], breaks_[i + 1]}; }
  /// Segment i's own domain (for example [0, 1] for a Bézier segment).
  [[nodiscard]] Interval<T> own_domain(std::size_t i) const {
    return std::visit([](const auto& s) { return Interval<T>(s.domain()); }, segments_[i]);
  }

  /// The segment whose interval holds u: the right one at an interior break, the first
  /// or last one outside the domain (extrapolation). O(log k).
  [[nodiscard]] std::size_t segment_index(T u) const {
    const auto it = std::upper_bound(breaks_.begin() + 1, breaks_.end() - 1, u);
    return static_cast<std::size_t>(it - (breaks_.begin() + 1));
  }

  /// Segment i's own parameter at the curve parameter u.
  [[nodiscard]] T local_parameter(std::size_t i, T u) const { return map_parameter(u, segment_domain(i), own_domain(i)); }

  // The piecewise algebra: every query is a kernel on one piece (in the piece's own
  // parameter) plus these combinators, which are the only places where a piece's
  // parameter and the curve's meet (docs/architecture.md, "Queries are written once").

  /// The piece holding the curve parameter u and its own parameter there, as evaluation
  /// chooses them: the right piece at an interior break, the first or last piece outside
  /// the domain (extrapolation). The step down from the curve to a piece kernel. O(log k).
  [[nodiscard]] PieceParameter<T> locate(T u) const {
    const std::size_t i = segment_index(u);
    return {i, local_parameter(i, u)};
  }

  /// Whether the curve jumps at the end of piece i: piece i + 1 starts elsewhere than
  /// piece i ends (a path's gap, a B-spline's knot of multiplicity p + 1, a degree-0 step),
  /// by more than 64 eps of the largest control coordinate of the two pieces (two pieces
  /// of a continuous curve meet to rounding). False for the last piece. Cost: the two end
  /// points and the two control boxes.
  [[nodiscard]] bool jumps_after(std::size_t i) const {
    if (i + 1 >= segments_.size()) return false;
    const auto end = [](const auto& s, bool last) {
      using S = std::decay_t<decltype(s)>;
      if constexpr (std::is_same_v<S, Bezier<T, D>> || std::is_same_v<S, RationalBezier<T, D>>) {
        return last ? s.points().back() : s.points().front();  // exact, O(1)
      } else {
        return s(last ? s.domain().hi : s.domain().lo);
      }
    };
    const PointType a = std::visit([&](const auto& s) { return end(s, true); }, segments_[i]);
    const PointType b = std::visit([&](const auto& s) { return end(s, false); }, segments_[i + 1]);
    T m = 0, gap = 0;
    for (std::size_t j : {i, i + 1}) {
      const Box<T, D> box = std::visit([](const auto& s) { return s.control_bounds(); }, segments_[j]);
      for (int k = 0; k < D; ++k) m = std::max({m, std::abs(box.lo[k]), std::abs(box.hi[k])});
    }
    for (int k = 0; k < D; ++k) gap = std::max(gap, std::abs(a[k] - b[k]));
    return gap > 64 * std::numeric_limits<T>::epsilon() * m;
  }

  /// The curve parameter at which the curve is piece i's end point (the left limit at
  /// u_{i+1}): u_{i+1} itself where the curve does not jump there (and at the domain's
  /// end), else the double below u_{i+1}, whose point (on piece i, as evaluation takes
  /// it) is that left limit to rounding: evaluation at u_{i+1} gives piece i + 1's start.
  /// The one rule by which every query reports a point of the closure of a piece before a
  /// jump (docs/cli.md, "Curves that jump").
  [[nodiscard]] T end_parameter(std::size_t i) const {
    const T u = breaks_[i + 1];
    return jumps_after(i) ? below_break(u, breaks_[i]) : u;
  }

  /// The double below the break u, not below the piece's start lo: where the curve is
  /// piece i's end point before a jump at u (end_parameter; solve's intervals).
  [[nodiscard]] static T below_break(T u, T lo) { return std::max(std::nextafter(u, -std::numeric_limits<T>::infinity()), lo); }

  /// The curve parameter of piece i's own parameter t: the increasing affine map of its
  /// own domain onto [u_i, u_{i+1}], the start exactly onto the break u_i, the end onto
  /// end_parameter(i) (u_{i+1}, or the double below it where the curve jumps there, so
  /// that the curve at the lifted parameter is piece i's point: the step up from a piece
  /// kernel's answer to the curve's). Rounding: a few eps of the break interval.
  [[nodiscard]] T lift(std::size_t i, T t) const {
    const T u = map_parameter(t, own_domain(i), segment_domain(i));
    return u == breaks_[i + 1] ? end_parameter(i) : u;
  }
  /// An interval of piece i's own parameters lifted (its ends by lift(i, t)).
  [[nodiscard]] Interval<T> lift(std::size_t i, const Interval<T>& own) const { return {lift(i, own.lo), lift(i, own.hi)}; }

  /// Appends the lifts of piece i's parameters ts (sorted, as a root finder gives them)
  /// to out, in order, keeping a joint duplicate once: a root at the start of piece i
  /// (t = its own domain's start, lifted exactly to the break u_i) is left out when out
  /// already ends with u_i, i.e. with the end root of piece i - 1 at the same break (the
  /// ends lift exactly, so the test is an equality; at a jump piece i - 1's end lifts to
  /// the double below u_i, and both are kept: two points of the curve). Calling it for i = 0, 1, ... in turn
  /// gives every root of the curve once, in increasing order. Roots inside a piece that
  /// are close to each other, or equal, are the kernel's business: all kept.
  void lift_roots(std::size_t i, std::span<const T> ts, std::vector<T>& out) const {
    const T start = own_domain(i).lo;
    for (const T t : ts) {
      if (t == start && i > 0 && !out.empty() && out.back() == breaks_[i]) continue;
      out.push_back(lift(i, t));
    }
  }

  /// Calls f(i, piece, own) for each piece i, in order, that meets the parameter range
  /// [range.lo, range.hi] of the domain in an interval of positive length; piece is the
  /// segment's alternative (std::visit'ed) and own the part of its own domain inside the
  /// range. Clipping: a range end inside a piece becomes that piece's own parameter
  /// (local_parameter, so a query evaluates the range's end on the piece that holds it);
  /// a piece wholly inside gets its whole own domain, its ends exact. A piece that only
  /// touches the range at a break is not visited: a range from one break to another
  /// visits exactly the pieces between them. A degenerate range [u, u] visits the one
  /// piece holding u, as evaluation chooses it (the right one at an interior break, the
  /// last at the domain's end), with own = [t, t]: a query over it sees the curve's
  /// point there. Precondition: range.lo <= range.hi within the domain (queries check
  /// it first, naming their arguments). f may return bool: false ends the walk (a query
  /// that has its answer). Cost: O(log k) to find the first piece, then the calls.
  template <class F>
  void for_each_piece(const Interval<T>& range, F&& f) const {
    if (range.lo == range.hi) {
      const PieceParameter<T> at = locate(range.lo);
      visit_piece(at.index, Interval<T>(at.t, at.t), f);
      return;
    }
    for (std::size_t i = segment_index(range.lo); i < segments_.size(); ++i) {
      const Interval<T> seg = segment_domain(i);
      if (seg.lo >= range.hi) break;
      if (seg.hi <= range.lo) continue;  // only before the domain's start (extrapolation)
      const Interval<T> own = own_domain(i);
      const T t0 = range.lo <= seg.lo ? own.lo : local_parameter(i, range.lo);
      const T t1 = range.hi >= seg.hi ? own.hi : local_parameter(i, range.hi);
      if (!visit_piece(i, Interval<T>(t0, t1), f)) return;
    }
  }
  /// Calls f(i, piece, own) for every piece over its whole own domain (the range being
  /// the whole domain), in order; f may return false to end the walk.
  template <class F>
  void for_each_piece(F&& f) const {
    for (std::size_t i = 0; i < segments_.size(); ++i)
      if (!visit_piece(i, own_domain(i), f)) return;
  }

  /// The derivative of piece i's own parameter with respect to the curve's: its own
  /// domain's length over its break interval's (the chain rule's factor, per order, that
  /// turns a piece's derivatives into the curve's).
  [[nodiscard]] T parameter_scale(std::size_t i) const { return own_domain(i).length() / segment_domain(i).length(); }

  /// The curve over the range [from, to] (from < to, within the domain) with the same
  /// parametrisation: the pieces for_each_piece visits, those cut by a range end
  /// replaced by their portion over the clipped own range (the segment's portion(a, b)),
  /// the breaks inside the range kept and the range's ends as the first and last breaks.
  /// A piece cut to a sliver may round to one point (a range end within eps of a break).
  /// Cost: one portion per cut piece (O(n^2) for a Bézier piece of degree n), copies of
  /// the others. Throws InvalidArgument("range", ...) unless from < to within the domain.
  [[nodiscard]] Derived portion(const Interval<T>& range) const {
    const Interval<T> dom = domain();
    if (!(range.lo < range.hi) || range.lo < dom.lo || range.hi > dom.hi) {
      throw InvalidArgument("range", "a portion needs from < to within the domain [" + format_number(dom.lo) + ", " +
                                         format_number(dom.hi) + "], got [" + format_number(range.lo) + ", " +
                                         format_number(range.hi) + "]");
    }
    std::vector<Segment> segs;
    std::vector<T> br{range.lo};
    for_each_piece(range, [&](std::size_t i, const auto& s, const Interval<T>& own) {
      segs.push_back(own == Interval<T>(s.domain()) ? Segment(s) : Segment(s.portion(own.lo, own.hi)));
      br.push_back(std::min(breaks_[i + 1], range.hi));
    });
    return Derived(std::move(segs), std::move(br));
  }

  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    const PieceParameter<T> at = locate(u);
    return in_curve_parameter(u, at.t, [&] { return std::visit([&](const auto& s) { return s(at.t); }, segments_[at.index]); });
  }

  /// The k-th derivative (k >= 0; k = 0 gives the point as a vector) with respect to the
  /// curve parameter: the segment's derivative times (own length / break length)^k
  /// (chain rule). At an interior break the right segment answers, at the end the last.
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    const PieceParameter<T> at = locate(u);
    return in_curve_parameter(u, at.t, [&] { return segment_derivative(at.index, at.t, k); });
  }

  /// The k-th derivative (k >= 0) of segment i at the fraction s of its own domain (s = 0
  /// its start, s = 1 its end), scaled to the curve parameter: what continuity checks
  /// compare on either side of a break.
  [[nodiscard]] VectorType one_sided_derivative(std::size_t i, T s, int k) const {
    if (i >= segments_.size()) {
      throw InvalidArgument("segment", "must name a segment 0.." + std::to_string(segments_.size() - 1) + ", got " +
                                           std::to_string(i));
    }
    require_finite(s, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    return segment_derivative(i, own_domain(i).at(s), k);
  }

  /// Box of all control points; contains the curve over its domain.
  [[nodiscard]] Box<T, D> control_bounds() const {
    Box<T, D> b = Box<T, D>::empty_box();
    for (const auto& s : segments_) b.add(std::visit([](const auto& c) { return c.control_bounds(); }, s));
    return b;
  }

  /// The same curve traversed backwards on the same domain: u -> u_0 + u_k - u.
  [[nodiscard]] Derived reverse() const {
    std::vector<Segment> segs;
    std::vector<T> br;
    segs.reserve(segments_.size());
    br.reserve(breaks_.size());
    for (auto it = segments_.rbegin(); it != segments_.rend(); ++it)
      segs.push_back(std::visit([](const auto& c) { return Segment(c.reverse()); }, *it));
    for (auto it = breaks_.rbegin(); it != breaks_.rend(); ++it) br.push_back(breaks_.front() + breaks_.back() - *it);
    br.front() = breaks_.front();  // exact ends despite rounding
    br.back() = breaks_.back();
    return Derived(std::move(segs), std::move(br));
  }

  [[nodiscard]] Derived transform(const Affine<T, D>& m) const {
    std::vector<Segment> segs;
    segs.reserve(segments_.size());
    for (const auto& s : segments_) segs.push_back(std::visit([&](const auto& c) { return Segment(c.transform(m)); }, s));
    return Derived(std::move(segs), breaks_);
  }

  friend bool operator==(const PiecewiseCurve&, const PiecewiseCurve&) = default;

 private:
  /// Runs f(), a segment's evaluation at its own parameter t for the curve parameter u: a
  /// segment's error about its parameter ("t") quotes u, the value the caller passed,
  /// rather than t (a path on [10, 30] evaluated at 1e5 is a polyline segment at 9998).
  template <class F>
  static auto in_curve_parameter(T u, T t, F&& f) {
    try {
      return f();
    } catch (const InvalidArgument& e) {
      if (e.where() != "t" || t == u) throw;
      std::string problem = e.problem();
      const std::string local = "t = " + format_number(t);
      for (auto at = problem.find(local); at != std::string::npos; at = problem.find(local, at + 1)) {
        const std::size_t end = at + local.size();
        if (end < problem.size() && std::string_view("0123456789.e+-").find(problem[end]) != std::string_view::npos) continue;
        problem.replace(at, local.size(), "t = " + format_number(u));
        break;
      }
      throw InvalidArgument("t", problem);
    }
  }

  // f(i, piece, own) on segment i's alternative; false when f returned false (stop).
  template <class F>
  bool visit_piece(std::size_t i, const Interval<T>& own, F& f) const {
    return std::visit(
        [&](const auto& s) {
          if constexpr (std::is_void_v<decltype(f(i, s, own))>) {
            f(i, s, own);
            return true;
          } else {
            return static_cast<bool>(f(i, s, own));
          }
        },
        segments_[i]);
  }

  VectorType segment_derivative(std::size_t i, T t, int k) const {
    const T scale = parameter_scale(i);
    return std::visit(
        [&](const auto& s) {
          if (k == 0) return s(t).to_vector();
          VectorType v = s.derivative_at(t, k);
          for (int j = 0; j < k; ++j) v *= scale;
          return v;
        },
        segments_[i]);
  }

  void validate() const { check_breaks(breaks_, segments_.size()); }

  static std::vector<T> default_breaks(std::size_t k) {
    std::vector<T> b(k + 1);
    for (std::size_t i = 0; i <= k; ++i) b[i] = static_cast<T>(i);
    return b;
  }

  std::vector<Segment> segments_;
  std::vector<T> breaks_;
};

}  // namespace detail

/// One piece of the exact piecewise Bézier form: a polynomial or a rational Bézier curve.
template <class T, int D>
using BezierPiece = std::variant<Bezier<T, D>, RationalBezier<T, D>>;

/// The exact piecewise (rational) Bézier form of a curve, with the curve's own
/// parametrisation: piece i on [u_i, u_{i+1}], its [0, 1] mapped affinely onto it. Every
/// curve type converts to it (the free function pieces(c)), and the queries (bounds,
/// flatten, and later length, closest point, intersections) are written once on it,
/// with one kernel per piece type and the combinators of PiecewiseCurve (for_each_piece,
/// locate, lift, lift_roots, portion) between the pieces' parameters and the curve's.
template <class T, int D>
class Pieces : public detail::PiecewiseCurve<Pieces<T, D>, T, D, BezierPiece<T, D>> {
  using Base = detail::PiecewiseCurve<Pieces<T, D>, T, D, BezierPiece<T, D>>;

 public:
  using Base::Base;
  friend bool operator==(const Pieces&, const Pieces&) = default;
};

static_assert(DifferentiableCurve<Pieces<double, 2>>);

namespace detail {
/// Whether C is a piece type (Bézier or rational Bézier): the types that queries have
/// kernels for. Every other curve type reaches the kernels through pieces(c).
template <class C>
inline constexpr bool is_bezier_piece = false;
template <class T, int D>
inline constexpr bool is_bezier_piece<Bezier<T, D>> = true;
template <class T, int D>
inline constexpr bool is_bezier_piece<RationalBezier<T, D>> = true;

/// Whether C is Pieces<T, D>. The queries that work on the exact pieces alone are written
/// for Pieces and reached from every other curve type through pieces(c) (a one-line
/// overload), so that their bodies are compiled once per scalar and dimension, not once
/// per curve type.
template <class C>
inline constexpr bool is_pieces = false;
template <class T, int D>
inline constexpr bool is_pieces<Pieces<T, D>> = true;
}  // namespace detail

/// The piecewise Bézier form of a Bézier or rational Bézier curve: itself, on [0, 1].
template <class T, int D>
Pieces<T, D> pieces(const Bezier<T, D>& c) {
  return Pieces<T, D>({BezierPiece<T, D>(c)}, {T(0), T(1)});
}
template <class T, int D>
Pieces<T, D> pieces(const RationalBezier<T, D>& c) {
  return Pieces<T, D>({BezierPiece<T, D>(c)}, {T(0), T(1)});
}
/// Pieces are their own piecewise form: returned by reference, so queries on pieces copy
/// nothing.
template <class T, int D>
const Pieces<T, D>& pieces(const Pieces<T, D>& c) {
  return c;
}
static_assert(PiecewiseBezierCurve<Bezier<double, 2>>);
static_assert(PiecewiseBezierCurve<RationalBezier<double, 2>>);
static_assert(PiecewiseBezierCurve<Pieces<double, 2>>);

/// Appends the segments of a composite curve (Pieces, Path) whose domain is mapped
/// affinely onto [lo, hi] of another composite curve: the one splice of a segment's pieces
/// into a path's pieces and of a nested path into a path.
template <class Composite, class Seg, class T>
void append_pieces(const Composite& p, const Interval<T>& onto, std::vector<Seg>& segs, std::vector<T>& breaks) {
  const Interval<T> from = p.domain();
  if (breaks.empty()) breaks.push_back(onto.lo);
  for (std::size_t j = 0; j < p.size(); ++j) {
    segs.push_back(p.segments()[j]);
    breaks.push_back(detail::map_parameter(p.breaks()[j + 1], from, onto));
  }
}

}  // namespace casteljau
