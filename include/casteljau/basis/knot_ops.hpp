// Knot-vector operations on plain B-spline data (degree, knots, control points of any
// point type, e.g. homogeneous ones): knot insertion, refinement, removal, degree
// elevation and re-knotting of the ends [PT97, chapter 5; Ramshaw87]. Callable without a
// curve object; BSpline and Nurbs (curves/bspline.hpp) wrap them with validation.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/de_casteljau.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau {

/// A B-spline as plain data: degree p, knots U_0..U_{n+p}, control points P_0..P_{n-1}.
/// No invariant is enforced here: the functions below state their preconditions, which
/// the curve types guarantee.
template <class T, class V>
struct KnotForm {
  int p = 0;
  std::vector<T> U;
  std::vector<V> P;
};

namespace detail {

inline std::size_t sz(int i) { return static_cast<std::size_t>(i); }

/// The blossom of span s of the B-spline (U, p, P) at the p arguments u[0..p-1] by de
/// Boor's recurrence with one argument per level [Ramshaw87; PT97, A3.1 for equal
/// arguments]: d_j = P_{s-p+j}; at level r, d_j = lerp(d_{j-1}, d_j, (u_r - U_i) /
/// (U_{i+p+1-r} - U_i)), i = s - p + j. Symmetric in its arguments; equal arguments u
/// give the curve point. Every denominator is a knot difference >= U_{s+1} - U_s > 0.
/// Convex combinations for arguments in [U_s, U_{s+1}]. Cost O(p^2).
template <class V, class T>
V de_boor_blossom(std::span<const T> U, int p, std::size_t s, std::span<const V> P, std::span<const T> u) {
  Scratch<V> scratch(static_cast<std::size_t>(p) + 1);
  V* d = scratch.data();
  for (int j = 0; j <= p; ++j) d[j] = P[s - static_cast<std::size_t>(p) + static_cast<std::size_t>(j)];
  for (int r = 1; r <= p; ++r) {
    for (int j = p; j >= r; --j) {
      const std::size_t i = s - static_cast<std::size_t>(p) + static_cast<std::size_t>(j);
      const T alpha = (u[static_cast<std::size_t>(r - 1)] - U[i]) / (U[i + static_cast<std::size_t>(p + 1 - r)] - U[i]);
      d[j] = lerp(d[j - 1], d[j], alpha);
    }
  }
  return d[p];
}

/// The index k of the last knot <= u (U_k <= u < U_{k+1}, or k = last index of the run
/// of u). Precondition: U_0 <= u < U_m (u below the last knot).
template <class T>
std::size_t last_knot_at_or_below(std::span<const T> U, T u) {
  return static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
}

}  // namespace detail

/// Inserts u once (Boehm's algorithm [Boehm80; PT97, eq. 5.15]): with U_k <= u < U_{k+1},
/// Q_i = alpha_i P_i + (1 - alpha_i) P_{i-1}, alpha_i = (u - U_i) / (U_{i+p} - U_i) for
/// k-p+1 <= i <= k, the other points shifted. The curve is unchanged; every new point is
/// a convex combination of two old ones (raising a multiplicity from p to p + 1 repeats
/// the point where the curve passes). Preconditions: U_p <= u <= U_n and the run of u
/// does not reach the last knot (the caller checks the multiplicity). Cost O(n + p).
template <class T, class V>
KnotForm<T, V> insert_knot_once(const KnotForm<T, V>& f, T u) {
  const std::span<const T> U(f.U);
  const std::size_t p = detail::sz(f.p);
  // At the domain's right end u = U_(n+1) the span is the last one, n (u ends its run
  // there, and the formula needs P_(k-p) .. P_k).
  const std::size_t k = std::min(detail::last_knot_at_or_below(U, u), f.P.size() - 1);
  KnotForm<T, V> g{f.p, {}, {}};
  g.U.reserve(f.U.size() + 1);
  g.U.insert(g.U.end(), f.U.begin(), f.U.begin() + static_cast<std::ptrdiff_t>(k) + 1);
  g.U.push_back(u);
  g.U.insert(g.U.end(), f.U.begin() + static_cast<std::ptrdiff_t>(k) + 1, f.U.end());
  g.P.resize(f.P.size() + 1);
  for (std::size_t i = 0; i + p <= k; ++i) g.P[i] = f.P[i];
  for (std::size_t i = k - p + 1; i <= k; ++i) {
    const T alpha = (u - U[i]) / (U[i + p] - U[i]);
    g.P[i] = lerp(f.P[i - 1], f.P[i], alpha);
  }
  for (std::size_t i = k + 1; i < g.P.size(); ++i) g.P[i] = f.P[i - 1];
  return g;
}

/// Inserts the sorted knots X_0 <= ... <= X_r all at once [PT97, A5.4, knot refinement]:
/// the new points are built from the right end backwards, each a convex combination, in
/// O(n + (r + 1) p). Preconditions: every X_j in [U_p, U_n], and no knot's multiplicity
/// exceeds p afterwards (the caller checks). The curve is unchanged.
template <class T, class V>
KnotForm<T, V> refine_knots(const KnotForm<T, V>& f, std::span<const T> X) {
  if (X.empty()) return f;
  const std::span<const T> U(f.U);
  const int p = f.p;
  const int m = static_cast<int>(U.size()) - 1;
  const int n = m - p - 1;  // index of the last control point
  const int r = static_cast<int>(X.size()) - 1;
  // a: span of X_0; b: one past the span of X_r (spans as U_k <= x < U_{k+1}, capped at n).
  const auto span_of = [&](T x) { return std::min(static_cast<int>(detail::last_knot_at_or_below(U, x)), n); };
  const int a = span_of(X.front());
  const int b = span_of(X.back()) + 1;
  KnotForm<T, V> g{p, std::vector<T>(U.size() + X.size()), std::vector<V>(f.P.size() + X.size())};
  auto& Q = g.P;
  auto& Ub = g.U;
  for (int j = 0; j <= a - p; ++j) Q[detail::sz(j)] = f.P[detail::sz(j)];
  for (int j = b - 1; j <= n; ++j) Q[detail::sz(j + r + 1)] = f.P[detail::sz(j)];
  for (int j = 0; j <= a; ++j) Ub[detail::sz(j)] = U[detail::sz(j)];
  for (int j = b + p; j <= m; ++j) Ub[detail::sz(j + r + 1)] = U[detail::sz(j)];
  int i = b + p - 1;
  int k = b + p + r;
  for (int j = r; j >= 0; --j) {
    const T x = X[detail::sz(j)];
    // Old knots above x (and their points) move right by the knots still to insert.
    while (x <= U[detail::sz(i)] && i > a) {
      Q[detail::sz(k - p - 1)] = f.P[detail::sz(i - p - 1)];
      Ub[detail::sz(k)] = U[detail::sz(i)];
      --k;
      --i;
    }
    Q[detail::sz(k - p - 1)] = Q[detail::sz(k - p)];
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      const T num = Ub[detail::sz(k + l)] - x;
      if (num == 0) {
        Q[detail::sz(ind - 1)] = Q[detail::sz(ind)];
      } else {
        const T alpha = num / (Ub[detail::sz(k + l)] - U[detail::sz(i - p + l)]);
        Q[detail::sz(ind - 1)] = lerp(Q[detail::sz(ind)], Q[detail::sz(ind - 1)], alpha);
      }
    }
    Ub[detail::sz(k)] = x;
    --k;
  }
  return g;
}

/// Removes one copy of the interior knot U_r = u (r the last index of its run of s
/// copies, U_p < u < U_n) without any check: the p - s unknown points solve
/// P_i = alpha_i Q_i + (1 - alpha_i) Q_{i-1}, alpha_i = (u - U_i) / (U_{i+p+1} - U_i),
/// i = r-p..r-s, half from the left and half from the right, and the one equation left
/// over is ignored [PT97, eq. 5.28-5.29 and A5.8]. Exact when the curve is C^(p-s) at u;
/// otherwise the curve moves, and the caller measures by how much (removal_deviation).
/// A break of multiplicity s = p + 1 (where the curve may jump) has no equation: its two
/// limits P_(r-p-1) and P_(r-p) become one point, their midpoint (exact when the curve is
/// continuous there; otherwise it moves by half the jump). Cost O(n + p).
template <class T, class V>
KnotForm<T, V> remove_knot_once(const KnotForm<T, V>& f, T u) {
  const std::span<const T> U(f.U);
  const int p = f.p;
  const int r = static_cast<int>(detail::last_knot_at_or_below(U, u));
  const int s = static_cast<int>(knot_multiplicity<T>(U, u));
  const int first = r - p, last = r - s;  // equations i = first..last
  KnotForm<T, V> g{p, {}, std::vector<V>(f.P.size() - 1)};
  g.U.reserve(U.size() - 1);
  for (int j = 0; j < static_cast<int>(U.size()); ++j)
    if (j != r) g.U.push_back(U[detail::sz(j)]);
  auto& Q = g.P;
  for (int i = 0; i < first; ++i) Q[detail::sz(i)] = f.P[detail::sz(i)];
  for (int i = last + 1; i < static_cast<int>(f.P.size()); ++i) Q[detail::sz(i - 1)] = f.P[detail::sz(i)];
  if (s == p + 1) {
    Q[detail::sz(first - 1)] = lerp(f.P[detail::sz(first - 1)], f.P[detail::sz(first)], T(0.5));
    return g;
  }
  const auto alpha = [&](int i) { return (u - U[detail::sz(i)]) / (U[detail::sz(i + p + 1)] - U[detail::sz(i)]); };
  // Unknowns Q_first..Q_{last-1}: the left recurrence divides by alpha_i, the right one by
  // 1 - alpha_i; each is used where its divisor is the larger, near its own end.
  const int left_count = (last - first) / 2;
  for (int i = first; i < first + left_count; ++i) {
    const T a = alpha(i);
    Q[detail::sz(i)] = Q[detail::sz(i - 1)] + (f.P[detail::sz(i)] - Q[detail::sz(i - 1)]) / a;
  }
  for (int i = last; i > first + left_count; --i) {
    const T a = alpha(i);
    Q[detail::sz(i - 1)] = Q[detail::sz(i)] + (f.P[detail::sz(i)] - Q[detail::sz(i)]) / (1 - a);
  }
  return g;
}

/// The largest distance between the control points of f and those of g after u is
/// inserted `times` times into g: a bound on max |f(x) - g(x)| over the whole knot range,
/// because the difference of the two curves is the B-spline of the point differences on
/// f's knots (basis functions >= 0 summing to 1). Precondition: g is f with u removed
/// `times` times. Cost O(times (n + p)).
template <class T, class V>
T removal_deviation(const KnotForm<T, V>& f, KnotForm<T, V> g, T u, int times) {
  for (int j = 0; j < times; ++j) g = insert_knot_once(g, u);
  T d = 0;
  for (std::size_t i = 0; i < f.P.size(); ++i) d = std::max(d, norm(f.P[i] - g.P[i]));
  return d;
}

/// The control points of a B-spline for new knots Ub that keep the curve's polynomial
/// pieces: Q_i is the blossom of the piece of span s at Ub_{i+1}..Ub_{i+p} [Ramshaw87;
/// PT97, §5.3 on the blossom form of knot insertion], computed only for i < count_left
/// (from the first non-empty span) and i >= Q.size() - count_right (from the last); the
/// other points are copied from `middle` (the curve's points where the windows agree).
/// Used to clamp and unclamp the ends. Cost O(p^3) per recomputed point.
template <class T, class V>
std::vector<V> reblossom_ends(const KnotForm<T, V>& f, std::span<const T> Ub, std::size_t count_left, std::size_t count_right,
                              std::vector<V> middle) {
  const std::span<const T> U(f.U);
  const std::size_t p = detail::sz(f.p);
  const std::size_t n = f.P.size();
  std::size_t first = p, last = n - 1;
  while (first < last && !(U[first] < U[first + 1])) ++first;
  while (last > first && !(U[last] < U[last + 1])) --last;
  std::vector<T> args(p);
  const auto window = [&](std::size_t i) {
    for (std::size_t j = 0; j < p; ++j) args[j] = Ub[i + 1 + j];
    return std::span<const T>(args);
  };
  for (std::size_t i = 0; i < count_left; ++i) middle[i] = detail::de_boor_blossom<V, T>(U, f.p, first, f.P, window(i));
  for (std::size_t i = middle.size() - count_right; i < middle.size(); ++i)
    middle[i] = detail::de_boor_blossom<V, T>(U, f.p, last, f.P, window(i));
  return middle;
}

}  // namespace casteljau
