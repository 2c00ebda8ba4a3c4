// Arc length of curves (of any sub-interval), the parameter at a given arc length, and
// resampling at equal arc lengths: adaptive Gauss-Kronrod on every Bézier piece, split
// where a coordinate's derivative vanishes (so at every cusp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/algo/scalar_forms.hpp"
#include "casteljau/basis/quadrature.hpp"
#include "casteljau/curves/concepts.hpp"

namespace casteljau {

/// Relative accuracy that the arc length functions aim at (the sum of the Gauss-Kronrod
/// error estimates is below it): 1e-13 for double, a margin of ten under the 1e-12 they
/// promise; the same number of units in the last place at other scalars
/// (detail::target_at: 5.4e-5 for float, where 1e-13 is below the rounding of the
/// integrand and the quadrature could not meet it; 4.9e-17 for long double).
template <class T>
inline constexpr T arc_length_tolerance = detail::target_at<T>(1e-13);

namespace detail {

/// The speed |c'(t)| of a piece on [0, 1] from its scalar forms, as 2^e times the value of
/// operator() = |N(t)| / w(t)^2 with N_k the derivative numerators (w = 1 for a polynomial
/// piece): integrals are taken of the scaled speed and multiplied by 2^e once, so that
/// coordinates near the largest double give a length that overflows only if the length
/// itself does. Also the parameters in (0, 1) where some N_k vanishes: the speed is smooth
/// between them (a cusp, where all vanish, is among them).
template <class T, int D>
struct PieceSpeed {
  ScalarForms<T, D> f;
  std::vector<std::vector<T>> num;
  std::vector<T> splits;  // 0, the roots, 1

  template <class Piece>
  explicit PieceSpeed(const Piece& c) : f(scalar_forms<T, D>(c, c.points().front())) {
    splits.push_back(T(0));
    for (int k = 0; k < D; ++k) {
      num.push_back(derivative_numerator(f, k));
      if (num.back().size() > 1)
        for (T r : bernstein_roots<T>(num.back()))
          if (r > 0 && r < 1) splits.push_back(r);
    }
    splits.push_back(T(1));
    std::sort(splits.begin(), splits.end());
    splits.erase(std::unique(splits.begin(), splits.end()), splits.end());
  }

  /// The scaled speed at t in [0, 1]: O(n) per call past degree 32 (the Bernstein-Horner
  /// scheme of bernstein_value_fast, de Casteljau below). Quadrature evaluates the speed
  /// thousands of times at high degree, where O(n^2) de Casteljau made a degree-1000 arc
  /// length take 30 s; the Horner scheme's error was measured no worse than de
  /// Casteljau's on random degree-1000 hodographs (about 1e-13 of max |coefficient|
  /// against an mpmath reference, 2e-14 relative on the speed; docs/accuracy.md).
  T operator()(T t) const {
    Vector<T, D> v;
    for (int k = 0; k < D; ++k) v[k] = bernstein_value_fast<T>(std::span<const T>(num[k]), t);
    T s = norm(v);
    if (f.rational) {
      const T w = bernstein_value_fast<T>(std::span<const T>(f.w), t);
      s = s / w / w;
    }
    return s;
  }
};

/// Integrates the scaled speed of one piece over [t0, t1] within [0, 1], split at its
/// smooth breaks (multiply by 2^sp.f.e for the length); appends the partition (piece
/// parameters, scaled values) to `parts` when given.
template <class T, int D>
T piece_length(const PieceSpeed<T, D>& sp, T t0, T t1, std::vector<QuadratureInterval<T>>* parts = nullptr) {
  T total = 0;
  for (std::size_t j = 0; j + 1 < sp.splits.size(); ++j) {
    const T a = std::max(t0, sp.splits[j]), b = std::min(t1, sp.splits[j + 1]);
    if (!(a < b)) continue;
    Quadrature<T> q;
    try {
      q = integrate_adaptive<T>(sp, a, b, arc_length_tolerance<T>);
    } catch (const NumericalError&) {
      // Said in the terms of the request (the quadrature's own message names its internals).
      throw NumericalError("the arc length cannot be computed to its accuracy target (" +
                           (std::is_same_v<T, double> ? std::string("1e-12")
                                                      : detail::format_number(static_cast<double>(10 * arc_length_tolerance<T>))) +
                           " relative) on this curve: its "
                           "speed varies too sharply for adaptive quadrature within 4000 intervals per piece");
    }
    total += q.value;
    if (parts) parts->insert(parts->end(), q.intervals.begin(), q.intervals.end());
  }
  return total;
}

/// The arc length over [a, b] (0 <= a < b <= 1/2) of a rational piece with extreme
/// weights, integrated in x = log2 t: its speed is concentrated within about 1 / rho of
/// t = 0 (rho the ratio of its standard-form weights, up to 1e300 and beyond), where
/// quadrature in t sees nothing, while |R'(t)| t is a bump of width O(1) in x at each
/// scale where the dominant weight changes. Intervals of 4 in x from log2 b down to log2 a
/// (to -1200 for a = 0: below, t |R'| < 2^-1200 |R'(0)| is negligible), each integrated
/// adaptively; the speed by rational_jet (no cancellation, t far below the smallest double).
/// Appends the partition (x intervals, ascending) to `parts` when given.
template <class T, int D>
T log_speed(const RationalBezier<T, D>& c, T x) {
  JetParameter<T> p;
  p.e = static_cast<int>(std::floor(x)) + 1;
  p.m = std::exp2(x - static_cast<T>(p.e));
  p.s = x < T(-80) ? T(1) : 1 - std::exp2(x);
  const auto j = rational_jet<T, D>(std::span<const Point<T, D>>(c.points()), std::span<const T>(c.weights()), p, false);
  return std::ldexp(norm(j.r) * p.m * std::numbers::ln2_v<T>, j.er + p.e);
}

template <class T, int D>
T log_side_length(const RationalBezier<T, D>& c, T a, T b, std::vector<QuadratureInterval<T>>* parts = nullptr) {
  if (!(a < b)) return T(0);
  const T xb = std::log2(b), xa = a > 0 ? std::log2(a) : T(-1200);
  auto g = [&](T x) { return log_speed(c, x); };
  T total = 0;
  std::vector<QuadratureInterval<T>> ivs;
  for (T hi = xb; hi > xa;) {
    const T lo = std::max(xa, hi - 4);
    try {
      const auto q = integrate_adaptive<T>(g, lo, hi, arc_length_tolerance<T>);
      total += q.value;
      if (parts) ivs.insert(ivs.begin(), q.intervals.begin(), q.intervals.end());
    } catch (const NumericalError&) {
      throw NumericalError("the arc length cannot be computed to its accuracy target on this curve: its speed varies too "
                           "sharply for adaptive quadrature within 4000 intervals");
    }
    hi = lo;
  }
  if (parts) parts->insert(parts->end(), ivs.begin(), ivs.end());
  return total;
}

/// The arc length over [t0, t1] of a rational piece with extreme weights: [t0, 1/2] in
/// log2 t, [1/2, t1] in log2 (1 - t) on the reversed piece (1 - t is exact there), so that
/// the ends, where the speed concentrates, are resolved on both sides.
template <class T, int D>
T extreme_arc_length(const RationalBezier<T, D>& c, T t0, T t1) {
  T total = 0;
  if (t0 < T(0.5)) total += log_side_length(c, t0, std::min(t1, T(0.5)));
  if (t1 > T(0.5)) total += log_side_length(c.reverse(), 1 - t1, 1 - std::max(t0, T(0.5)));
  return total;
}

}  // namespace detail

/// The arc length of the curve between the parameters from <= to (both in the domain):
/// the integral of the speed |c'| over every Bézier piece, by adaptive Gauss-Kronrod 7-15
/// (integrate_adaptive) split at the pieces' breaks and wherever a coordinate of c'
/// vanishes (so at every cusp, where the speed has a kink). Accuracy: relative 1e-12
/// (the error estimates sum to below 1e-13 of the length, and they overestimate: see
/// gauss_kronrod_15). A curve or range of length zero (coincident control points) gives
/// exactly 0. Throws InvalidArgument("from"/"to", ...) for a range outside the domain or
/// reversed, NumericalError if the quadrature cannot meet its target (never observed:
/// the speed is smooth between the splits). Cost: the root isolation of the D derivative
/// numerators plus 15 speed evaluations (O(n) each, see PieceSpeed) per quadrature
/// interval; a cubic needs 1 to 4 intervals, a random degree-1000 curve about 2000
/// (0.08 s of CPU in all; docs/accuracy.md).
template <class C>
  requires detail::is_pieces<C>
typename C::Scalar arc_length(const C& c, typename C::Scalar from, typename C::Scalar to) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const auto& p = pieces(c);
  detail::check_range<T>(p.domain(), from, to);
  T total = 0;
  if (from == to) return total;  // a point has no length
  p.for_each_piece({from, to}, [&](std::size_t, const auto& piece, const Interval<T>& own) {
    const T t0 = own.lo, t1 = own.hi;
    if (detail::regular_parts(piece).front().map.identity) {
      const detail::PieceSpeed<T, D> sp(piece);
      total += std::ldexp(detail::piece_length<T, D>(sp, t0, t1), sp.f.e);
      return;
    }
    // Extreme weights. A part of the piece: in log t and log (1 - t) (its portion, in
    // Cartesian control points, rounds away what lies within 1e-30 of a corner).
    if constexpr (requires { piece.jet(t0, false); }) {
      if (!(t0 == 0 && t1 == 1) && piece.degree() <= detail::rational_jet_max_degree) {
        total += detail::extreme_arc_length(piece, t0, t1);
        return;
      }
    }
    // The whole piece: in parts with tame parametrisations.
    T sum = 0;
    for (const auto& part : detail::regular_parts(t0 == 0 && t1 == 1 ? piece : piece.portion(t0, t1))) {
      const detail::PieceSpeed<T, D> sp(part.piece);
      sum += std::ldexp(detail::piece_length<T, D>(sp, T(0), T(1)), sp.f.e);
    }
    total += sum;
  });
  if (!std::isfinite(total)) throw InvalidArgument("curve", "the arc length is not representable (it exceeds the largest double)");
  return total;
}

/// Every other curve type: the same, on its exact pieces (see detail::is_pieces).
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_pieces<C>)
typename C::Scalar arc_length(const C& c, typename C::Scalar from, typename C::Scalar to) {
  return arc_length(pieces(c), from, to);
}

/// The arc length of the whole curve over its domain (see the ranged overload).
template <class C>
  requires PiecewiseBezierCurve<C>
typename C::Scalar arc_length(const C& c) {
  const auto dom = c.domain();
  return arc_length(c, dom.lo, dom.hi);
}

/// The arc length function of a curve, integrated once: total() and the parameter at any
/// arc length from the domain's start (the inverse), for many queries on one curve.
template <class T, int D>
class ArcLengthTable {
 public:
  /// Integrates every piece as arc_length does and keeps the partitions. Cost as arc_length.
  template <class C>
    requires PiecewiseBezierCurve<C>
  explicit ArcLengthTable(const C& c) : pieces_(pieces(c)) {
    pieces_.for_each_piece([&](std::size_t i, const auto& piece, const Interval<T>&) {
      if constexpr (requires { piece.jet(T(0), false); }) {
        if (piece.degree() <= detail::rational_jet_max_degree && !detail::regular_parts(piece).front().map.identity) {
          // Extreme weights: cells in x = log2 t up to t = 1/2, then in x = log2 (1 - t) on
          // the reversed piece (see detail::extreme_arc_length), so that a length is
          // located where the speed concentrates and mapped to t without a Möbius map
          // (whose images round to 1 for every part near the far end).
          for (int side = 1; side <= 2; ++side) {
            logs_.push_back(side == 1 ? piece : piece.reverse());
            std::vector<QuadratureInterval<T>> parts;
            detail::log_side_length(logs_.back(), T(0), T(0.5), &parts);
            if (side == 2) std::reverse(parts.begin(), parts.end());
            for (const auto& q : parts) {
              // In t order: a side-2 cell starts at its larger x.
              cells_.push_back({i, logs_.size() - 1, side, side == 1 ? q.a : q.b, side == 1 ? q.b : q.a, total_, q.value});
              total_ += q.value;
            }
          }
          return;
        }
      }
      // One speed per part (the piece itself unless its weights are extreme).
      for (const auto& part : detail::regular_parts(piece)) {
        speeds_.emplace_back(part.piece);
        maps_.push_back(part.map);
        std::vector<QuadratureInterval<T>> parts;
        detail::piece_length<T, D>(speeds_.back(), T(0), T(1), &parts);
        const int e = speeds_.back().f.e;
        for (const auto& q : parts) {
          cells_.push_back({i, speeds_.size() - 1, 0, q.a, q.b, total_, std::ldexp(q.value, e)});
          total_ += std::ldexp(q.value, e);
        }
      }
    });
    if (!std::isfinite(total_)) throw InvalidArgument("curve", "the arc length is not representable (it exceeds the largest double)");
  }

  [[nodiscard]] T total() const { return total_; }

  /// The parameter u where the arc length from the domain's start is s, for s in
  /// [0, total()] (values above total() by at most 1e-12 relative, an oracle's rounding,
  /// count as total()). Located in the table's partition, then solved by Newton's method
  /// on a bracket (bisection when a step leaves it or the speed is 0) with the partial
  /// integral by one Gauss-Kronrod rule. Where the curve stands still (a zero-length
  /// piece or a stop), the first such parameter. Accuracy: the arc length at the result
  /// is s to about 1e-12 relative to the total. Throws InvalidArgument("s", ...) for s
  /// outside the range, NumericalError if the solve does not converge in 200 steps.
  [[nodiscard]] T parameter_at(T s) const {
    require_finite(s, "s");
    const T slack = detail::target_at<T>(1e-12) * total_;
    if (s < 0 || s > total_ + slack) {
      throw InvalidArgument("s", "arc length must lie in [0, " + detail::format_number(total_) + "] (the curve's length), got " +
                                     detail::format_number(s));
    }
    const Interval<T> dom = pieces_.domain();
    if (s <= 0 || cells_.empty()) return dom.lo;
    if (s >= total_) return dom.hi;
    // First cell whose end reaches s within the solve's tolerance (below): where the arc
    // length barely grows (a stretch within 1e-100 of a corner at extreme weights, a
    // stop) the rounding of the cells' sums (1e-16) must not carry s past it to a
    // parameter whose arc length is far beyond (t = 1 for s = 1 on the conic with weights
    // 1, 1e100, 1, arc length 2).
    const T reach = s - 4 * std::numeric_limits<T>::epsilon() * total_;
    const auto it = std::lower_bound(cells_.begin(), cells_.end(), reach,
                                     [](const Cell& c, T v) { return c.start + c.length < v; });
    const Cell& cell = it == cells_.end() ? cells_.back() : *it;
    const T target = std::clamp(s - cell.start, T(0), cell.length);
    if (cell.kind != 0) {
      // A cell in x = log2 t (kind 1) or x = log2 (1 - t) (kind 2, x decreasing with t):
      // solved in y = x or -x, along which the arc length grows.
      const auto& c = logs_[cell.part];
      const T sgn = cell.kind == 1 ? T(1) : T(-1);
      auto g = [&](T x) { return detail::log_speed(c, x); };
      return solve(sgn * cell.a, sgn * cell.b, cell.length, target, [&](T y) { return g(sgn * y); },
                   [&](T y) {
                     const T x = sgn * y;
                     if (y <= sgn * cell.a) return T(0);
                     return gauss_kronrod_15<T>(g, std::min(x, cell.a), std::max(x, cell.a)).value;
                   },
                   [&](T y) {
                     const T x = sgn * y;
                     return pieces_.lift(cell.piece, cell.kind == 1 ? std::exp2(x) : 1 - std::exp2(x));
                   });
    }
    const auto& scaled_speed = speeds_[cell.part];
    const auto lift = [&](T u) { return pieces_.lift(cell.piece, maps_[cell.part].t_of(u)); };
    const int e = scaled_speed.f.e;
    auto speed = [&](T t) { return std::ldexp(scaled_speed(t), e); };
    auto partial = [&](T t) { return t <= cell.a ? T(0) : std::ldexp(gauss_kronrod_15<T>(scaled_speed, cell.a, t).value, e); };
    return solve(cell.a, cell.b, cell.length, target, speed, partial, lift);
  }

 private:
  /// The u in [a, b] where partial(u) = target (partial increasing, its derivative
  /// speed), lifted to the curve's parameter: Newton's method on a bracket (bisection when
  /// a step leaves it or the speed is 0).
  template <class Speed, class Partial, class Lift>
  T solve(T a, T b, T length, T target, Speed speed, Partial partial, Lift lift) const {
    T lo = a, hi = b;
    T t = a + (b - a) * (length > 0 ? target / length : T(0));
    const T goal = 4 * std::numeric_limits<T>::epsilon() * total_;
    for (int it2 = 0; it2 < 200; ++it2) {
      const T r = partial(t) - target;
      if (std::abs(r) <= goal) return lift(t);
      if (r < 0) lo = t; else hi = t;
      if (!(hi - lo > 2 * std::numeric_limits<T>::epsilon() * std::max(T(1), std::abs(hi)))) {
        return lift(lo + (hi - lo) / 2);
      }
      const T v = speed(t);
      T next = v > 0 ? t - r / v : lo + (hi - lo) / 2;
      if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;
      t = next;
    }
    throw NumericalError("the parameter at the given arc length was not found: its Newton-bisection solve did not converge in 200 steps");
  }

  struct Cell {
    std::size_t piece;
    std::size_t part;  // index in speeds_ and maps_ (kind 0), in logs_ (kinds 1, 2)
    int kind;          // 0: a part's parameter; 1: x = log2 t; 2: x = log2 (1 - t)
    T a, b;       // part parameters, or x at the cell's start and end (in t order)
    T start;      // arc length before a
    T length;     // arc length over [a, b]
  };
  Pieces<T, D> pieces_;
  std::vector<detail::PieceSpeed<T, D>> speeds_;
  std::vector<detail::PartMap<T>> maps_;  // part parameter -> piece parameter
  std::vector<RationalBezier<T, D>> logs_;  // pieces with extreme weights, and their reverses
  std::vector<Cell> cells_;
  T total_ = 0;
};

/// The parameter at arc length s from the domain's start (see ArcLengthTable::parameter_at).
template <class C>
  requires PiecewiseBezierCurve<C>
typename C::Scalar parameter_at_length(const C& c, typename C::Scalar s) {
  return ArcLengthTable<typename C::Scalar, C::dimension>(c).parameter_at(s);
}

/// `count` >= 2 parameters at equal arc-length steps total / (count - 1), from the
/// domain's start to its end (resampling a curve uniformly along its length). Accuracy
/// as ArcLengthTable::parameter_at. Throws InvalidArgument("count", ...) for count < 2.
template <class C>
  requires PiecewiseBezierCurve<C>
std::vector<typename C::Scalar> equal_length_parameters(const C& c, int count) {
  using T = typename C::Scalar;
  if (count < 2) throw InvalidArgument("count", "needs at least 2 samples, got " + std::to_string(count));
  const ArcLengthTable<T, C::dimension> table(c);
  std::vector<T> u(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    u[static_cast<std::size_t>(k)] =
        k == count - 1 ? table.parameter_at(table.total()) : table.parameter_at(table.total() * static_cast<T>(k) / static_cast<T>(count - 1));
  }
  return u;
}

}  // namespace casteljau
