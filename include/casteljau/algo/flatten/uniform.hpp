// Flattening by uniform parameter steps, their count from Wang's bound [Wang84; Filip86].
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "casteljau/algo/flatten/chord.hpp"
#include "casteljau/algo/flatten/small_piece.hpp"
#include "casteljau/basis/extrapolate.hpp"

namespace casteljau::detail {

/// Wang's count for a polynomial piece with control points P [Wang84; Filip86]: with n =
/// ceil(sqrt(p (p - 1) / 8 max_i |P_i - 2 P_(i+1) + P_(i+2)| / tol)) equal steps the
/// chord of each step is within tol of the curve (|B(t) - chord(t)| <= h^2 / 8 max |B''|
/// and |B''| <= p (p - 1) max |second differences|). For a rational piece the same formula
/// on its Cartesian points is an estimate only (flatten_uniform checks it). At least 1.
/// Overflow-safe: where a second difference or the quotient would overflow (coordinates
/// near 1e300, a tolerance near 1e-300) it is formed on the points scaled by a power of
/// two, as a product of square roots, so the count is a finite number (at most the
/// largest double; those in
/// the unit frame of to_unit, as flatten passes them, never take that branch).
template <class T, int D>
double wang_count(std::span<const Point<T, D>> P, T tol) {
  const int p = static_cast<int>(P.size()) - 1;
  if (p < 2) return 1;
  const double factor = p * (p - 1) / 8.0;
  double second = 0;
  bool finite = true;
  for (std::size_t i = 0; i + 2 < P.size(); ++i) {
    const double s = static_cast<double>(norm((P[i + 2] - P[i + 1]) - (P[i + 1] - P[i])));
    finite = finite && std::isfinite(s);
    second = std::max(second, s);
  }
  const double q = factor * second / static_cast<double>(tol);
  if (finite && std::isfinite(q)) return std::max(1.0, std::ceil(std::sqrt(q)));
  // second * 2^e / tol on the points scaled by 2^-e (each second difference then at most
  // 4 in each coordinate), as sqrt(factor second) sqrt(2^e) / sqrt(tol): finite.
  const int e = scale_exponent<Point<T, D>>(P);
  second = 0;
  for (std::size_t i = 0; i + 2 < P.size(); ++i) {
    const auto a = scaled(P[i], -e), b = scaled(P[i + 1], -e), c = scaled(P[i + 2], -e);
    second = std::max(second, static_cast<double>(norm((c - b) - (b - a))));
  }
  // sqrt(2^e) = 2^(e / 2) sqrt(2^(e % 2)): 2^e itself overflows for e = 1024.
  const double root = std::ldexp(std::sqrt(std::ldexp(1.0, e % 2)), e / 2);
  const double n = std::sqrt(factor * second) * (root / std::sqrt(static_cast<double>(tol)));
  // Beyond the largest double only for a tolerance far below the coordinates' scale (a
  // subnormal tolerance with coordinates near 1e308): the largest double stands for it.
  return std::isfinite(n) ? std::max(1.0, std::ceil(n)) : std::numeric_limits<double>::max();
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
