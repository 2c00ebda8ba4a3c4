// B-spline knot vectors and basis functions: validation, knot spans, multiplicities, the
// non-zero basis functions at a parameter and their derivatives [PT97, chapter 2]. Plain
// functions over a knot sequence, callable without a curve object.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "casteljau/core/error.hpp"

namespace casteljau {

/// Checks the sizes of a B-spline: degree p >= 0 ("degree"), at least p + 1 control
/// points ("points") and points + p + 1 knots ("knots"). The one place these messages
/// live: the curve constructors and KnotVector call it before check_knots.
inline void check_knot_count(int p, std::size_t knots, std::size_t points) {
  if (p < 0) throw InvalidArgument("degree", "a B-spline needs degree >= 0, got " + std::to_string(p));
  if (points < static_cast<std::size_t>(p) + 1) {
    throw InvalidArgument("points", "degree " + std::to_string(p) + " needs at least " + std::to_string(p + 1) +
                                        " control points, got " + std::to_string(points));
  }
  if (knots != points + static_cast<std::size_t>(p) + 1) {
    throw InvalidArgument("knots", "needs len(points) + degree + 1 = " + std::to_string(points + static_cast<std::size_t>(p) + 1) +
                                       " knots, got " + std::to_string(knots));
  }
}

/// Checks a knot vector U_0..U_m for degree p >= 0 with n = m - p control points
/// (m + 1 = n + p + 1 knots): every knot finite, non-decreasing, repeated at most p + 1
/// times (an interior knot of multiplicity p + 1 is a break where the curve may jump;
/// degree 0 thus has distinct knots), n >= p + 1, and U_p < U_n (a non-empty domain).
/// Throws InvalidArgument naming "degree", "knots" or "knots[i]" with the rule.
template <class T>
void check_knots(std::span<const T> U, int p) {
  if (p < 0) throw InvalidArgument("degree", "a B-spline needs degree >= 0, got " + std::to_string(p));
  const std::size_t order = static_cast<std::size_t>(p) + 1;
  if (U.size() < 2 * order) {
    throw InvalidArgument("knots", "degree " + std::to_string(p) + " needs at least " + std::to_string(2 * order) +
                                       " knots (p + 1 control points), got " + std::to_string(U.size()));
  }
  for (std::size_t i = 0; i < U.size(); ++i) {
    const std::string where = "knots[" + std::to_string(i) + "]";
    require_finite(U[i], where);
    if (i > 0 && U[i] < U[i - 1]) {
      throw InvalidArgument(where, "knots must be non-decreasing (" + detail::format_number(U[i]) + " after " +
                                       detail::format_number(U[i - 1]) + ")");
    }
  }
  // Multiplicities: runs of equal knots.
  for (std::size_t i = 0; i < U.size();) {
    std::size_t j = i;
    while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
    const std::size_t mult = j - i + 1;
    const bool at_end = i == 0 || j == U.size() - 1;
    if (mult > order) {
      throw InvalidArgument("knots[" + std::to_string(i + order) + "]",
                            "knot " + detail::format_number(U[i]) + " is repeated " + std::to_string(mult) + " times; " +
                                (at_end ? "an end knot" : "an interior knot") + " may be repeated at most " +
                                (order == 1 ? std::string("once") : std::to_string(order) + " times") + " (p + 1) for degree " +
                                std::to_string(p));
    }
    i = j + 1;
  }
  const std::size_t n = U.size() - order;  // control points
  if (!(U[static_cast<std::size_t>(p)] < U[n])) {
    throw InvalidArgument("knots", "the domain [knots[" + std::to_string(p) + "], knots[" + std::to_string(n) + "]] = [" +
                                       detail::format_number(U[static_cast<std::size_t>(p)]) + ", " +
                                       detail::format_number(U[n]) + "] is empty");
  }
  // Evaluation divides by knot differences: every one must be a double.
  if (!std::isfinite(U.back() - U.front())) {
    throw InvalidArgument("knots", "the knots span [" + detail::format_number(U.front()) + ", " +
                                       detail::format_number(U.back()) + "], longer than the largest double");
  }
}

/// The knot span s (p <= s <= n - 1, n = U.size() - p - 1 control points) whose interval
/// [U_s, U_{s+1}) holds u [PT97, A2.1]: the right limit at an interior knot, the last
/// non-empty span at the domain's end U_n, the first or last span outside the domain (so
/// that evaluation there extrapolates the end pieces). Binary search, O(log n).
/// Precondition (unchecked: internal to the curve types, which validate U once): U is a
/// valid knot vector for degree p (check_knots).
template <class T>
std::size_t find_span(std::span<const T> U, int p, T u) {
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  const std::size_t lo = static_cast<std::size_t>(p);
  // The last span with U_s < U_{s+1} at or before n - 1: at u >= U_n it answers, so the
  // left limit is taken at the right end.
  std::size_t last = n - 1;
  while (last > lo && !(U[last] < U[last + 1])) --last;
  if (u >= U[last]) return last;
  if (!(u > U[lo])) {
    // Below (or at) the domain's start: the first non-empty span.
    std::size_t first = lo;
    while (first < last && !(U[first] < U[first + 1])) ++first;
    return first;
  }
  // U[lo] < u < U[last]: the s with U_s <= u < U_{s+1}.
  const auto it = std::upper_bound(U.begin() + static_cast<std::ptrdiff_t>(lo), U.begin() + static_cast<std::ptrdiff_t>(last) + 1, u);
  return static_cast<std::size_t>(it - U.begin()) - 1;
}

/// How many times u occurs in U (0 if it is not a knot). O(log m).
template <class T>
std::size_t knot_multiplicity(std::span<const T> U, T u) {
  const auto [a, b] = std::equal_range(U.begin(), U.end(), u);
  return static_cast<std::size_t>(b - a);
}

/// The p + 1 basis functions N_{s-p,p}(u) .. N_{s,p}(u) that can be non-zero on span s,
/// by the triangular Cox-de Boor scheme [PT97, A2.2] (no 0/0: on a non-empty span every
/// denominator is a positive knot difference). Non-negative and summing to 1 for u in the
/// span; outside it (extrapolation) the same polynomials continued. Cost O(p^2).
template <class T>
void basis_functions(std::span<const T> U, int p, std::size_t s, T u, std::span<T> N) {
  N[0] = 1;
  std::vector<T> left(static_cast<std::size_t>(p) + 1), right(static_cast<std::size_t>(p) + 1);
  for (int j = 1; j <= p; ++j) {
    left[static_cast<std::size_t>(j)] = u - U[s + 1 - static_cast<std::size_t>(j)];
    right[static_cast<std::size_t>(j)] = U[s + static_cast<std::size_t>(j)] - u;
    T saved = 0;
    for (int r = 0; r < j; ++r) {
      const T temp = N[static_cast<std::size_t>(r)] / (right[static_cast<std::size_t>(r) + 1] + left[static_cast<std::size_t>(j - r)]);
      N[static_cast<std::size_t>(r)] = saved + right[static_cast<std::size_t>(r) + 1] * temp;
      saved = left[static_cast<std::size_t>(j - r)] * temp;
    }
    N[static_cast<std::size_t>(j)] = saved;
  }
}

/// The derivatives of orders 0..k of the p + 1 basis functions of span s at u [PT97, A2.3]:
/// ders[j][r] = d^j/du^j N_{s-p+r,p}(u), j = 0..k, r = 0..p; rows j > p are zero.
/// Cost O(p^2 + k p).
template <class T>
std::vector<std::vector<T>> basis_function_derivatives(std::span<const T> U, int p, std::size_t s, T u, int k) {
  const std::size_t P = static_cast<std::size_t>(p);
  std::vector<std::vector<T>> ndu(P + 1, std::vector<T>(P + 1)), a(2, std::vector<T>(P + 1));
  std::vector<T> left(P + 1), right(P + 1);
  ndu[0][0] = 1;
  for (std::size_t j = 1; j <= P; ++j) {
    left[j] = u - U[s + 1 - j];
    right[j] = U[s + j] - u;
    T saved = 0;
    for (std::size_t r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const T temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle: basis functions
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  std::vector<std::vector<T>> ders(static_cast<std::size_t>(k) + 1, std::vector<T>(P + 1, T(0)));
  for (std::size_t j = 0; j <= P; ++j) ders[0][j] = ndu[j][P];
  const int kk = std::min(k, p);
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1;
    for (int q = 1; q <= kk; ++q) {
      T d = 0;
      const int rq = r - q, pq = p - q;
      if (r >= q) {
        a[s2][0] = a[s1][0] / ndu[pq + 1][rq];
        d = a[s2][0] * ndu[rq][pq];
      }
      const int j1 = rq >= -1 ? 1 : -rq;
      const int j2 = (r - 1 <= pq) ? q - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pq + 1][rq + j];
        d += a[s2][j] * ndu[rq + j][pq];
      }
      if (r <= pq) {
        a[s2][q] = -a[s1][q - 1] / ndu[pq + 1][r];
        d += a[s2][q] * ndu[r][pq];
      }
      ders[q][r] = d;
      std::swap(s1, s2);
    }
  }
  // Multiply by p! / (p - q)!.
  T f = static_cast<T>(p);
  for (int q = 1; q <= kk; ++q) {
    for (std::size_t j = 0; j <= P; ++j) ders[q][j] *= f;
    f *= static_cast<T>(p - q);
  }
  return ders;
}

}  // namespace casteljau
