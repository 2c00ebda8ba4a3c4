// Flattening by uniform parameter steps, their count from Wang's bound [Wang84; Filip86].
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "casteljau/algo/flatten/chord.hpp"
#include "casteljau/algo/flatten/small_piece.hpp"

namespace casteljau::detail {

/// Wang's count for a polynomial piece with control points P [Wang84; Filip86]: with n =
/// ceil(sqrt(p (p - 1) / 8 max_i |P_i - 2 P_(i+1) + P_(i+2)| / tol)) uniform steps, the
/// chord of each step is within tol of the curve (|B(t) - chord(t)| <= h^2 / 8 max |B''|
/// and |B''| <= p (p - 1) max |second differences|). For a rational piece the same formula
/// on its Cartesian points is an estimate only (flatten_uniform checks it). At least 1.
/// The points should be in the unit frame (to_unit), where no difference overflows.
template <class T, int D>
double wang_count(std::span<const Point<T, D>> P, T tol) {
  const int p = static_cast<int>(P.size()) - 1;
  if (p < 2) return 1;
  double second = 0;
  for (std::size_t i = 0; i + 2 < P.size(); ++i) second = std::max(second, static_cast<double>(norm((P[i + 2] - P[i + 1]) - (P[i + 1] - P[i]))));
  return std::max(1.0, std::ceil(std::sqrt(p * (p - 1) / 8.0 * second / static_cast<double>(tol))));
}

/// wang_count of a piece's control points.
template <class C>
double wang_count(const C& c, typename C::Scalar tol) {
  return wang_count(std::span<const Point<typename C::Scalar, C::dimension>>(c.points()), tol);
}

/// Uniform steps: Wang's count for a polynomial piece (a proven bound); for a rational
/// piece Wang's formula on the Cartesian points as a start, doubled until every step
/// passes chord_within (uniform steps with a verified count).
template <class C>
void flatten_uniform(const C& c, typename C::Scalar tol, std::vector<Point<typename C::Scalar, C::dimension>>& out) {
  using T = typename C::Scalar;
  double n = wang_count(c, tol);
  constexpr bool rational = requires { c.weights(); };
  for (;;) {
    if (n > max_piece_segments) {
      throw NumericalError("flatten: the uniform method would need more than 2^26 segments for one piece at tolerance " +
                           format_number(tol) + " (relative to the piece's extent)");
    }
    bool ok = true;
    if constexpr (rational) {
      for (double i = 0; i < n && ok; ++i) ok = chord_within(c, static_cast<T>(i / n), static_cast<T>((i + 1) / n), tol);
    }
    if (ok) break;
    n *= 2;
  }
  constexpr int D = C::dimension;
  const auto& P = c.points();
  const std::size_t m = P.size();
  // Past degree 32 de Casteljau's O(p^2) per vertex dominates (degree 1000 at 1e5 vertices:
  // a minute): the Bernstein-Horner form (O(p), error about p eps of the unit-scale
  // coordinates) when the tolerance is 1000 times that error, else de Casteljau.
  const bool horner = m > 33 && tol > T(1000) * static_cast<T>(m) * std::numeric_limits<T>::epsilon();
  std::vector<std::vector<T>> coef;
  std::vector<T> wts;
  if (horner) {
    wts.assign(m, T(1));
    if constexpr (rational) {
      const T wmax = *std::max_element(c.weights().begin(), c.weights().end());
      for (std::size_t i = 0; i < m; ++i) wts[i] = c.weights()[i] / wmax;
    }
    coef.assign(D, std::vector<T>(m));
    for (int d = 0; d < D; ++d)
      for (std::size_t i = 0; i < m; ++i) coef[d][i] = wts[i] * P[i][d];
  }
  for (double i = 1; i < n; ++i) {
    const T t = static_cast<T>(i / n);
    if (horner) {
      const T w = rational ? bernstein_value_fast<T>(wts, t) : T(1);
      Point<T, D> q;
      for (int d = 0; d < D; ++d) q[d] = bernstein_value_fast<T>(coef[d], t) / w;
      out.push_back(q);
    } else {
      out.push_back(c(t));
    }
  }
  out.push_back(P.back());
}

/// Uniform steps on a small piece: the interior vertices q(i / n), i = 1 .. n - 1, with
/// n = Wang's count (a proven bound for polynomial pieces), to emit; the caller writes
/// the end points. Same vertices as flatten_uniform.
template <class T, int D, class Emit>
void small_uniform(const SmallPiece<T, D>& s, T tol, Emit&& emit) {
  const double n = wang_count(std::span<const Point<T, D>>(s.q.data(), static_cast<std::size_t>(s.m)), tol);
  if (n > max_piece_segments) {
    throw NumericalError("flatten: the uniform method would need more than 2^26 segments for one piece at tolerance " +
                         format_number(tol) + " (relative to the piece's extent)");
  }
  for (double i = 1; i < n; ++i) emit(s.at(static_cast<T>(i / n)));
}

}  // namespace casteljau::detail
