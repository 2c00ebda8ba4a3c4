// KnotVector: a B-spline knot vector with its degree, validated once when made, with its
// domain, distinct knots and multiplicities, span search (binary and hinted for sorted
// batches) and the usual generators: uniform, clamped uniform, periodic, averaging
// [PT97, chapters 2 and 9].
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

namespace detail {

/// floor(k / n) for n > 0 and any integer k (C++ division truncates toward zero).
inline std::ptrdiff_t floor_div(std::ptrdiff_t k, std::ptrdiff_t n) { return k >= 0 ? k / n : -((-k + n - 1) / n); }

/// Knot k, for any integer k, of the periodic sequence with one period's breaks
/// b_0 < .. < b_(L-1): b_(k mod L) + floor(k / L) period. The one formula behind
/// KnotVector::periodic and the closed fits (algo/fit.hpp).
template <class T>
T periodic_knot(std::span<const T> breaks, T period, std::ptrdiff_t k) {
  const std::ptrdiff_t L = static_cast<std::ptrdiff_t>(breaks.size()), q = floor_div(k, L);
  return breaks[static_cast<std::size_t>(k - q * L)] + static_cast<T>(q) * period;
}

}  // namespace detail

/// One distinct knot and how many times it occurs.
template <class T>
struct KnotRun {
  T value;
  std::size_t multiplicity;
  friend bool operator==(const KnotRun&, const KnotRun&) = default;
};

/// The knots U_0..U_m of a B-spline of degree p >= 0 with n = m - p control points, on
/// the domain [U_p, U_n]. Invariants (checked once, by the constructors, with the messages
/// of check_knot_count and check_knots): the knot rules of check_knots (finite,
/// non-decreasing, multiplicity <= p + 1, U_p < U_n; an interior knot of multiplicity
/// p + 1 is a break where the curve may jump). Nothing assumes clamped ends. Span search
/// follows find_span's rule: the right limit at an interior knot (at a jump, the span to
/// its right), the last non-empty span at U_n, the end spans outside the domain;
/// the first and last non-empty spans are found once here, so a search costs only the
/// binary search (or the walk from a hint).
template <class T>
class KnotVector {
 public:
  /// The knots for degree p, the control point count following from their number
  /// (n = U.size() - p - 1). Throws InvalidArgument as check_knots says.
  KnotVector(int degree, std::vector<T> knots) : p_(degree), U_(std::move(knots)) {
    check_knots<T>(U_, p_);
    find_end_spans();
  }

  /// The knots for degree p and `points` control points: also checks the count
  /// (check_knot_count: "degree", "points" for fewer than p + 1, "knots" for a count other
  /// than points + p + 1) before the knot rules, in the order of the curve constructors.
  KnotVector(int degree, std::vector<T> knots, std::size_t points) : p_(degree), U_(std::move(knots)) {
    check_knot_count(p_, U_.size(), points);
    check_knots<T>(U_, p_);
    find_end_spans();
  }

  [[nodiscard]] int degree() const { return p_; }
  /// U_0..U_m.
  [[nodiscard]] const std::vector<T>& knots() const { return U_; }
  [[nodiscard]] std::span<const T> span() const { return U_; }
  /// m + 1, the number of knots.
  [[nodiscard]] std::size_t size() const { return U_.size(); }
  [[nodiscard]] T operator[](std::size_t i) const { return U_[i]; }
  /// n = m - p: the number of control points these knots take.
  [[nodiscard]] std::size_t points() const { return U_.size() - static_cast<std::size_t>(p_) - 1; }
  /// [U_p, U_n].
  [[nodiscard]] Interval<T> domain() const { return {U_[static_cast<std::size_t>(p_)], U_[points()]}; }
  /// True when both end knots occur p + 1 times (the curve starts at its first control
  /// point and ends at its last).
  [[nodiscard]] bool is_clamped() const { return U_.front() == U_[static_cast<std::size_t>(p_)] && U_.back() == U_[points()]; }
  /// The first and the last non-empty span of the domain (U_s < U_{s+1}, p <= s < n).
  [[nodiscard]] std::size_t first_span() const { return first_; }
  [[nodiscard]] std::size_t last_span() const { return last_; }

  /// The distinct knots in increasing order with their multiplicities. O(m).
  [[nodiscard]] std::vector<KnotRun<T>> distinct() const {
    std::vector<KnotRun<T>> runs;
    for (const T u : U_) {
      if (!runs.empty() && runs.back().value == u) {
        ++runs.back().multiplicity;
      } else {
        runs.push_back({u, 1});
      }
    }
    return runs;
  }

  /// How many times u occurs (0 if it is not a knot). O(log m).
  [[nodiscard]] std::size_t multiplicity(T u) const { return knot_multiplicity<T>(U_, u); }

  /// The span s of u by binary search, O(log m): U_s <= u < U_{s+1} inside the domain,
  /// the last non-empty span for u >= its left knot (so the left limit at U_n and beyond),
  /// the first non-empty span for u <= U_p. The same answer as find_span(U, p, u).
  [[nodiscard]] std::size_t find_span(T u) const {
    if (u >= U_[last_]) return last_;
    if (!(u > U_[first_])) return first_;
    return binary_span(u);
  }

  /// The same span as find_span(u), starting from the guess `hint` (any value; best the
  /// previous answer of a sorted batch): walks at most max_hint_steps knots from the hint
  /// and falls back to the binary search when u is farther. O(1) for parameters in the
  /// hint's span or a neighbour, O(log m) otherwise; the hint never changes the answer.
  [[nodiscard]] std::size_t find_span(T u, std::size_t hint) const {
    if (u >= U_[last_]) return last_;
    if (!(u > U_[first_])) return first_;
    // Here U_first < u < U_last: the answer s (U_s <= u < U_{s+1}) lies in [first, last).
    std::size_t s = std::clamp(hint, first_, last_ - 1);
    if (U_[s] <= u) {
      for (int k = 0; k < max_hint_steps; ++k) {
        if (u < U_[s + 1]) return s;
        ++s;  // s + 1 <= last - 1 here, since u < U_last
      }
    } else {
      for (int k = 0; k < max_hint_steps; ++k) {
        --s;  // s >= first here, since U_first < u < U_s
        if (U_[s] <= u) return s;
      }
    }
    return binary_span(u);
  }

  /// How many knots find_span(u, hint) walks before it searches: a batch sorted at about
  /// one parameter per span or denser stays on the walk; anything sparser pays one binary
  /// search plus these few comparisons.
  static constexpr int max_hint_steps = 8;

  // -- Generators -------------------------------------------------------------------

  /// The uniform (unclamped) knots for n >= p + 1 control points on the domain [a, b]:
  /// spacing h = (b - a) / (n - p), U_j = a + (j - p) h for j = 0..n + p, so U_p = a and
  /// U_n = b exactly. Every knot simple: the curve is C^(p-1) and its ends are not at
  /// control points. Errors as the constructor ("points", "domain" for a or b not finite
  /// or a >= b).
  [[nodiscard]] static KnotVector uniform(std::size_t n, int p, T a = T(0), T b = T(1)) {
    check_generator(n, p, a, b);
    const std::size_t spans = n - static_cast<std::size_t>(p);
    std::vector<T> U(n + static_cast<std::size_t>(p) + 1);
    for (std::size_t j = 0; j < U.size(); ++j) {
      const T k = static_cast<T>(static_cast<std::ptrdiff_t>(j) - p);
      U[j] = spaced(a, b, k, static_cast<T>(spans));
    }
    U[static_cast<std::size_t>(p)] = a;  // the domain's ends exactly, whatever the rounding
    U[n] = b;
    return KnotVector(p, std::move(U), n);
  }

  /// The clamped (open) uniform knots for n >= p + 1 control points on [a, b]: a and b
  /// each p + 1 times and n - p - 1 interior knots equally spaced between them ([PT97,
  /// ch. 2]'s nonperiodic knot vector with uniform interior knots). Interior knot j is
  /// a + j (b - a) / (n - p), computed so that integer knots stay exact (a = 0, b = n - p
  /// gives 0, 1, 2, ..). Errors as uniform.
  [[nodiscard]] static KnotVector clamped_uniform(std::size_t n, int p, T a = T(0), T b = T(1)) {
    check_generator(n, p, a, b);
    const std::size_t P = static_cast<std::size_t>(p), spans = n - P;
    std::vector<T> U(P + 1, a);
    for (std::size_t j = 1; j < spans; ++j) U.push_back(spaced(a, b, static_cast<T>(j), static_cast<T>(spans)));
    U.insert(U.end(), P + 1, b);
    return KnotVector(p, std::move(U), n);
  }

  /// The knots of a closed periodic B-spline of degree p through L = breaks.size() >= 2
  /// distinct control points wrapped around: the curve has the L + p control points
  /// Q_i = P_(i mod L) and the knots U_j = breaks[(j - p) mod L] + floor((j - p) / L)
  /// period, j = 0..L + 2p, so the domain is [breaks[0], breaks[0] + period] and the
  /// curve closes with C^(p-1) continuity there [deBoor78, ch. XIII; PT97, §12.2
  /// on unclamped knot vectors]. breaks must be finite, strictly increasing and within one period
  /// (breaks.back() < breaks[0] + period); InvalidArgument "breaks[i]" or "period"
  /// otherwise, "degree" for p < 1, "breaks" for L < 2. L < p is allowed (the points then
  /// wrap more than once).
  [[nodiscard]] static KnotVector periodic(int p, std::span<const T> breaks, T period) {
    if (p < 1) throw InvalidArgument("degree", "a B-spline needs degree >= 1, got " + std::to_string(p));
    const std::size_t L = breaks.size();
    if (L < 2) throw InvalidArgument("breaks", "a closed curve needs at least 2 distinct points, got " + std::to_string(L));
    require_finite(period, "period");
    for (std::size_t i = 0; i < L; ++i) {
      const std::string where = "breaks[" + std::to_string(i) + "]";
      require_finite(breaks[i], where);
      if (i > 0 && !(breaks[i] > breaks[i - 1])) throw InvalidArgument(where, "breaks must be strictly increasing");
    }
    if (!(breaks.back() < breaks.front() + period)) {
      throw InvalidArgument("period", "the breaks must lie within one period: " + detail::format_number(breaks.back()) +
                                          " is not below " + detail::format_number(breaks.front()) + " + " +
                                          detail::format_number(period));
    }
    std::vector<T> U(L + 2 * static_cast<std::size_t>(p) + 1);
    for (std::size_t j = 0; j < U.size(); ++j) U[j] = detail::periodic_knot(breaks, period, static_cast<std::ptrdiff_t>(j) - p);
    return KnotVector(p, std::move(U), L + static_cast<std::size_t>(p));
  }

  /// The periodic knots (periodic) for L equally spaced breaks on [a, b]: breaks
  /// a + i (b - a) / L, period b - a. With a = p, b = L + p the knots are the integers
  /// 0, 1, .., L + 2p.
  [[nodiscard]] static KnotVector periodic_uniform(std::size_t L, int p, T a = T(0), T b = T(1)) {
    check_domain(a, b);
    std::vector<T> breaks(L);
    for (std::size_t i = 0; i < L; ++i) breaks[i] = spaced(a, b, static_cast<T>(i), static_cast<T>(L));
    return periodic(p, breaks, b - a);
  }

  /// The clamped knots of global interpolation by averaging the parameters t_0..t_m
  /// [PT97, eq. 9.8]: t_0 and t_m each p + 1 times and the interior knots
  /// U_(j+p) = (t_j + .. + t_(j+p-1)) / p, j = 1..m - p, for m + 1 control points. The
  /// parameters may repeat an end value (the end-derivative variants of [PT97, §9.2.2]
  /// repeat t_0 or t_m once). Requires m >= p, parameters finite and non-decreasing with
  /// t_0 < t_m (InvalidArgument "parameters", "parameters[k]"); the knot rules then hold
  /// whenever no p + 1 consecutive parameters are equal, and are checked.
  [[nodiscard]] static KnotVector averaging(int p, std::span<const T> t) {
    if (p < 1) throw InvalidArgument("degree", "a B-spline needs degree >= 1, got " + std::to_string(p));
    const std::size_t P = static_cast<std::size_t>(p);
    if (t.size() < P + 1) {
      throw InvalidArgument("parameters", "degree " + std::to_string(p) + " needs at least " + std::to_string(P + 1) +
                                              " parameters, got " + std::to_string(t.size()));
    }
    for (std::size_t k = 0; k < t.size(); ++k) {
      const std::string where = "parameters[" + std::to_string(k) + "]";
      require_finite(t[k], where);
      if (k > 0 && t[k] < t[k - 1]) throw InvalidArgument(where, "parameters must be non-decreasing");
    }
    if (!(t.front() < t.back())) throw InvalidArgument("parameters", "the parameters must not all be equal");
    std::vector<T> U(P + 1, t.front());
    for (std::size_t j = 1; j + P < t.size(); ++j) {
      T s = 0;
      for (std::size_t i = j; i < j + P; ++i) s += t[i];
      U.push_back(s / static_cast<T>(p));
    }
    U.insert(U.end(), P + 1, t.back());
    return KnotVector(p, std::move(U), t.size());
  }

  friend bool operator==(const KnotVector& a, const KnotVector& b) { return a.p_ == b.p_ && a.U_ == b.U_; }

 private:
  void find_end_spans() {
    const std::size_t n = points();
    first_ = static_cast<std::size_t>(p_);
    while (first_ + 1 < n && !(U_[first_] < U_[first_ + 1])) ++first_;
    last_ = n - 1;
    while (last_ > first_ && !(U_[last_] < U_[last_ + 1])) --last_;
  }

  /// The s with U_s <= u < U_{s+1}, for U_first < u < U_last.
  [[nodiscard]] std::size_t binary_span(T u) const {
    const auto it = std::upper_bound(U_.begin() + static_cast<std::ptrdiff_t>(first_), U_.begin() + static_cast<std::ptrdiff_t>(last_) + 1, u);
    return static_cast<std::size_t>(it - U_.begin()) - 1;
  }

  /// a + k (b - a) / count, written so that integer a, b and k give exact integers.
  static T spaced(T a, T b, T k, T count) { return a + (k * (b - a)) / count; }

  static void check_domain(T a, T b) {
    require_finite(a, "domain.lo");
    require_finite(b, "domain.hi");
    if (!(a < b) || !std::isfinite(b - a)) {
      throw InvalidArgument("domain", "needs a < b with a finite length, got [" + detail::format_number(a) + ", " +
                                          detail::format_number(b) + "]");
    }
  }

  static void check_generator(std::size_t n, int p, T a, T b) {
    check_knot_count(p, n + static_cast<std::size_t>(std::max(p, 0)) + 1, n);
    check_domain(a, b);
  }

  int p_;
  std::vector<T> U_;
  std::size_t first_ = 0, last_ = 0;
};

}  // namespace casteljau
