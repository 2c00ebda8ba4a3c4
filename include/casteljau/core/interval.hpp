// Closed parameter intervals and axis-aligned boxes, with their invariants checked when made.
#pragma once

#include <algorithm>
#include <limits>
#include <ostream>
#include <string>

#include "casteljau/core/point.hpp"

namespace casteljau {

/// The closed interval [lo, hi] of finite numbers with lo <= hi (a single point when
/// lo == hi). Invariant checked by the two-number constructor, which throws
/// InvalidArgument("interval.lo" / "interval.hi", ...) for a non-finite end and
/// ("interval", ...) for lo > hi. The fields stay public for reading (as in
/// `ab.lo`); code that assigns them takes over the invariant.
template <class T>
struct Interval {
  T lo{};
  T hi{};

  /// [0, 0].
  constexpr Interval() = default;
  constexpr Interval(T lo_, T hi_) : lo(lo_), hi(hi_) {
    // One comparison pair on the fast path: lo <= hi with a finite difference implies
    // both ends finite; anything else (including a merely huge finite length) is sorted
    // out by check().
    if (!(lo_ <= hi_) || !(hi_ - lo_ < std::numeric_limits<T>::infinity())) check(lo_, hi_);
  }

  [[nodiscard]] constexpr T length() const { return hi - lo; }
  [[nodiscard]] constexpr bool contains(T x) const { return lo <= x && x <= hi; }
  /// The parameter lo + s (hi - lo) of the fraction s.
  [[nodiscard]] constexpr T at(T s) const { return lerp(lo, hi, s); }
  /// The fraction s with at(s) == x. Precondition: length() > 0 (a one-point interval
  /// has no fractions; the result would not be finite).
  [[nodiscard]] constexpr T fraction(T x) const { return (x - lo) / (hi - lo); }
  friend constexpr bool operator==(const Interval&, const Interval&) = default;
  /// Prints "[0, 1]" (shortest round-trip numbers).
  friend std::ostream& operator<<(std::ostream& os, const Interval& ab) {
    return os << '[' << detail::format_number(ab.lo) << ", " << detail::format_number(ab.hi) << ']';
  }

 private:
  // Off the fast path: reached for a violated invariant, or for finite ends whose
  // difference overflows (allowed).
  static void check(T a, T b) {
    require_finite(a, "interval.lo");
    require_finite(b, "interval.hi");
    if (!(a <= b)) {
      throw InvalidArgument("interval", "needs lo <= hi, got [" + detail::format_number(a) + ", " +
                                            detail::format_number(b) + "]");
    }
  }
};

/// An axis-aligned box: either empty (the default, and empty_box(); no point inside, lo
/// = +inf and hi = -inf in every coordinate) or lo[i] <= hi[i] in every coordinate. The
/// two-corner constructor checks the invariant (InvalidArgument("box", ...) for lo[i] >
/// hi[i] or NaN); add() keeps it. Fields are public for reading; code that assigns them
/// takes over the invariant.
template <class T, int D>
struct Box {
  Point<T, D> lo;
  Point<T, D> hi;

  /// The empty box.
  constexpr Box() {
    for (int i = 0; i < D; ++i) {
      lo[i] = std::numeric_limits<T>::infinity();
      hi[i] = -std::numeric_limits<T>::infinity();
    }
  }
  /// The box with corners lo and hi; needs lo[i] <= hi[i] for every i.
  constexpr Box(const Point<T, D>& lo_, const Point<T, D>& hi_) : lo(lo_), hi(hi_) {
    for (int i = 0; i < D; ++i) {
      if (!(lo[i] <= hi[i])) {
        throw InvalidArgument("box", "needs lo <= hi in every coordinate, got lo[" + std::to_string(i) + "] = " +
                                         detail::format_number(lo[i]) + " and hi[" + std::to_string(i) +
                                         "] = " + detail::format_number(hi[i]));
      }
    }
  }

  static constexpr Box empty_box() { return Box(); }
  [[nodiscard]] constexpr bool empty() const { return !(lo[0] <= hi[0]); }
  constexpr void add(const Point<T, D>& p) {
    for (int i = 0; i < D; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  constexpr void add(const Box& b) {
    if (b.empty()) return;
    add(b.lo);
    add(b.hi);
  }
  [[nodiscard]] constexpr bool contains(const Point<T, D>& p, T tolerance = 0) const {
    for (int i = 0; i < D; ++i) {
      if (p[i] < lo[i] - tolerance || p[i] > hi[i] + tolerance) return false;
    }
    return true;
  }
  friend constexpr bool operator==(const Box&, const Box&) = default;
  /// Prints "[(0, 0), (4, 1.5)]", or "[empty]".
  friend std::ostream& operator<<(std::ostream& os, const Box& b) {
    if (b.empty()) return os << "[empty]";
    return os << '[' << b.lo << ", " << b.hi << ']';
  }
};

/// The box of a set of points (empty for none): the control box of every curve type.
template <class T, int D, class Points>
Box<T, D> box_of(const Points& points) {
  Box<T, D> b = Box<T, D>::empty_box();
  for (const auto& p : points) b.add(p);
  return b;
}

namespace detail {

/// Checks a parameter range [from, to] of a query against the domain dom: both finite,
/// inside dom, from <= to. Throws InvalidArgument("from" / "to", ...) naming the rule.
template <class T>
void check_range(Interval<T> dom, T from, T to) {
  require_finite(from, "from");
  require_finite(to, "to");
  const std::string d = "[" + format_number(dom.lo) + ", " + format_number(dom.hi) + "]";
  if (from < dom.lo || from > dom.hi) throw InvalidArgument("from", "must lie in the domain " + d + ", got " + format_number(from));
  if (to < dom.lo || to > dom.hi) throw InvalidArgument("to", "must lie in the domain " + d + ", got " + format_number(to));
  if (from > to) throw InvalidArgument("to", "must be >= from (" + format_number(from) + "), got " + format_number(to));
}

}  // namespace detail

}  // namespace casteljau
