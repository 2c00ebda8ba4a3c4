// Fitting B-spline curves to points [PT97, chapter 9]: global interpolation with optional
// end derivatives, closed (periodic) interpolation, least-squares approximation with a
// given number of control points (open: end points interpolated; closed: periodic), and
// approximation to a tolerance with the fewest control points found. Sparse (banded) linear algebra with
// Eigen. Not part of casteljau.hpp: it brings Eigen's sparse solvers; include it where
// fitting is used (the io layer compiles it once).
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/parametrization.hpp"

namespace casteljau {

/// A fitted curve and its error: the largest |C(t_k) - Q_k| over the data; the control
/// point count of the curve (for a closed fit the n of the periodic spline, before its
/// writing on [0, 1] repeats p of them), and for a tolerance search whether the count is
/// proven the fewest for the curve's knots: true only when they are the knots of
/// [PT97, eq. 9.68-9.69] and every smaller count was tried with them and failed; false
/// when the search's knot placement gave the answer (fewer control points than those
/// knots allow, but no placement is proven best) or the work limit cut the scan short.
template <class T, int D>
struct FitResult {
  BSpline<T, D> curve;
  T max_error;
  std::size_t count = 0;
  bool proven_fewest = false;
};

/// The most work one fit request may do, in the units of detail::fit_work: about one
/// second of one core at the slowest measured rate (18 ns per step). Above it a fit is
/// refused naming "degree" or "points" (one fit too costly) or "tolerance" (the search's
/// bisection alone too costly); the tolerance search spends what is left after its
/// bisection on knot placement (at most half of it) and on the counts below the one found.
inline constexpr double fit_work_limit = 6e7;

namespace detail {

/// A least-squares system that is numerically rank deficient: too many control points for
/// the spread of the data parameters (fit names "control_points" for it).
class RankDeficientFit : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

/// Right-hand sides and solutions: one column per coordinate, the column count a run-time
/// value, so that the sparse solvers are instantiated once per scalar type and not once
/// per dimension (their compile time dominates this header's).
template <class T, int D>
using Rhs = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// The non-zero basis functions (derivative order k) at u on span s of U, as (column, value).
template <class T>
void basis_row(std::span<const T> U, int p, T u, int k, std::vector<std::pair<std::size_t, T>>& row) {
  row.clear();
  const std::size_t s = find_span<T>(U, p, u);
  if (k == 0) {  // values only: no (p + 1) x (p + 1) table (its allocations dominated at high degree)
    std::vector<T> N(static_cast<std::size_t>(p) + 1);
    basis_functions<T>(U, p, s, u, N);
    for (int r = 0; r <= p; ++r) row.emplace_back(s - static_cast<std::size_t>(p) + static_cast<std::size_t>(r), N[static_cast<std::size_t>(r)]);
    return;
  }
  const auto ders = basis_function_derivatives<T>(U, p, s, u, k);
  for (int r = 0; r <= p; ++r) row.emplace_back(s - static_cast<std::size_t>(p) + static_cast<std::size_t>(r), ders[static_cast<std::size_t>(k)][static_cast<std::size_t>(r)]);
}

/// The work of one fit of degree p with `rows` conditions (data points and end
/// derivatives): each row costs O((p + 1)^2) in its basis functions [PT97, A2.2], in the
/// elimination (Givens rotations of a window of up to 2 (p + 1) columns against rows of
/// p + 1, or the sparse LU) and in the evaluation of the curve at it for max_error:
/// counted as 2 (p + 1)^2, plus a fixed part (allocation, the sparse LU's bookkeeping)
/// worth about 300 steps. Measured (the casteljau program, x86-64, one core, user +
/// system time): 1e5 points interpolated at degree 3 in 0.6 s (18 ns per step), 1001
/// points at degree 170 (6e7 steps) in 0.16 s by interpolation and 0.07 s by least
/// squares, 1e4 points at degree 3 to a tolerance (bisection and scan) in 0.14 s. The
/// slowest rate sets the limit.
inline double fit_work(std::size_t rows, int p) {
  const double q = static_cast<double>(p) + 1;
  return static_cast<double>(rows) * (2 * q * q + 300);
}

/// How many fits of the given work fit_work_limit allows (at least 1).
inline std::size_t fit_trials(double work) { return std::max<std::size_t>(1, static_cast<std::size_t>(fit_work_limit / work)); }

template <class T, int D>
T max_fit_error(const BSpline<T, D>& c, const std::vector<Point<T, D>>& Q, const std::vector<T>& t) {
  T e = 0;
  for (std::size_t k = 0; k < Q.size(); ++k) e = std::max(e, distance(c(t[k]), Q[k]));
  return e;
}

template <class T, int D>
std::vector<Point<T, D>> to_points(const Rhs<T, D>& x) {
  std::vector<Point<T, D>> P(static_cast<std::size_t>(x.rows()));
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int d = 0; d < D; ++d) P[i][d] = x(static_cast<Eigen::Index>(i), d);
  // Overflow (coordinates near the largest double) or a singular system that the solver
  // did not flag: reported, not passed on as a curve error naming an output index.
  for (const auto& q : P)
    if (!all_finite_point(q)) throw NumericalError("fit: the solution is not finite (overflow or a singular system)");
  return P;
}

inline void require_solved(Eigen::ComputationInfo info, const char* what) {
  if (info != Eigen::Success) throw NumericalError(std::string("fit: the ") + what + " system is singular");
}

}  // namespace detail

/// Global interpolation [PT97, A9.1]: the clamped degree-p B-spline with C(t_k) = Q_k,
/// knots by averaging the parameters (eq. 9.8), and optionally C'(0) = d0, C'(1) = d1
/// (derivatives with respect to the parameter on [0, 1]; [PT97, §9.2.2]: each adds a
/// control point, and the averaging runs over the parameters with t_0 or t_last
/// repeated, which is eq. 9.22 when both are given). The system is banded (bandwidth p)
/// and solved by sparse LU. Requires p >= 1 (p >= 2 with a derivative), at least p + 1
/// conditions, parameters strictly increasing. Cost O(m p^2).
template <class T, int D>
BSpline<T, D> interpolate(const std::vector<Point<T, D>>& Q, int p, const std::vector<T>& t, const std::optional<Vector<T, D>>& d0,
                          const std::optional<Vector<T, D>>& d1) {
  std::vector<T> ext;
  ext.push_back(t.front());
  if (d0) ext.push_back(t.front());
  ext.insert(ext.end(), t.begin() + 1, t.end() - 1);
  if (d1) ext.push_back(t.back());
  ext.push_back(t.back());
  const std::size_t N = ext.size();
  KnotVector<T> knots = KnotVector<T>::averaging(p, ext);
  const std::span<const T> U = knots.span();
  Eigen::SparseMatrix<T> A(static_cast<Eigen::Index>(N), static_cast<Eigen::Index>(N));
  std::vector<Eigen::Triplet<T>> entries;
  detail::Rhs<T, D> b(static_cast<Eigen::Index>(N), D);
  std::vector<std::pair<std::size_t, T>> row;
  std::size_t r = 0;
  const auto add = [&](T u, int k, const auto& value) {
    detail::basis_row<T>(U, p, u, k, row);
    for (const auto& [col, v] : row)
      if (v != 0) entries.emplace_back(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(col), v);
    for (int d = 0; d < D; ++d) b(static_cast<Eigen::Index>(r), d) = value[d];
    ++r;
  };
  add(t.front(), 0, Q.front());
  if (d0) add(t.front(), 1, *d0);
  for (std::size_t k = 1; k + 1 < Q.size(); ++k) add(t[k], 0, Q[k]);
  if (d1) add(t.back(), 1, *d1);
  add(t.back(), 0, Q.back());
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<T>> lu;
  lu.compute(A);
  detail::require_solved(lu.info(), "interpolation");
  const detail::Rhs<T, D> x = lu.solve(b);
  detail::require_solved(lu.info(), "interpolation");
  return BSpline<T, D>(std::move(knots), detail::to_points<T, D>(x));
}

namespace detail {

/// The knots of a periodic spline of period 1: breakpoints b_0 < ... < b_{n-1} in one
/// period, knot(j) = b_(j mod n) + floor(j / n) for every integer j (periodic_knot with
/// period 1, as KnotVector::periodic; simple knots, so the spline is C^(p-1) everywhere),
/// and control point j is C_(j mod n).
template <class T>
struct PeriodicKnots {
  std::vector<T> b;

  [[nodiscard]] std::ptrdiff_t size() const { return static_cast<std::ptrdiff_t>(b.size()); }
  [[nodiscard]] std::size_t wrap(std::ptrdiff_t j) const { return static_cast<std::size_t>(j - floor_div(j, size()) * size()); }
  [[nodiscard]] T knot(std::ptrdiff_t j) const { return periodic_knot<T>(b, T(1), j); }
  /// The span s with knot(s) <= u < knot(s + 1), for u in [0, 1) (b_0 may exceed 0: then
  /// s = -1 for u < b_0).
  [[nodiscard]] std::ptrdiff_t span(T u) const {
    return static_cast<std::ptrdiff_t>(std::upper_bound(b.begin(), b.end(), u) - b.begin()) - 1;
  }
  /// The p + 1 non-zero basis functions at u on span s (knot(s) <= u < knot(s + 1)),
  /// for control points s - p .. s (before wrapping) [PT97, A2.2 on the local knots].
  void basis(int p, std::ptrdiff_t s, T u, std::vector<T>& local, std::vector<T>& N) const {
    local.resize(2 * static_cast<std::size_t>(p) + 2);
    N.resize(static_cast<std::size_t>(p) + 1);
    for (std::ptrdiff_t j = 0; j < 2 * p + 2; ++j) local[static_cast<std::size_t>(j)] = knot(s - p + j);
    basis_functions<T>(local, p, static_cast<std::size_t>(p), u, N);
  }
};

/// The periodic spline (degree p, knots K, control points C wrapped) written as an
/// unclamped B-spline on [0, 1]: a long stretch of it, then 0 and 1 inserted as knots
/// where they are not breakpoints (Boehm, exact up to rounding), then the window [0, 1]
/// with its p knots on either side. The result has len(C) + (0 or 1) control points
/// (one more when 0 is not a breakpoint) and C^(p-1) continuity across the seam.
template <class T, int D>
BSpline<T, D> periodic_bspline(int p, const PeriodicKnots<T>& K, const std::vector<Point<T, D>>& C) {
  const std::ptrdiff_t L = K.size();
  KnotForm<T, Point<T, D>> f{p, {}, {}};
  const std::ptrdiff_t lo = -2 * p - 2, hi = L + 2 * p + 2;
  for (std::ptrdiff_t j = lo; j <= hi; ++j) f.U.push_back(K.knot(j));
  for (std::ptrdiff_t j = lo; j + p + 1 <= hi; ++j) f.P.push_back(C[K.wrap(j)]);
  for (const T u : {T(0), T(1)}) {
    if (knot_multiplicity<T>(f.U, u) == 0) f = insert_knot_once(f, u);
  }
  const std::size_t i0 = static_cast<std::size_t>(std::lower_bound(f.U.begin(), f.U.end(), T(0)) - f.U.begin());
  const std::size_t i1 = static_cast<std::size_t>(std::lower_bound(f.U.begin(), f.U.end(), T(1)) - f.U.begin());
  const std::size_t P = static_cast<std::size_t>(p);
  std::vector<T> U(f.U.begin() + static_cast<std::ptrdiff_t>(i0 - P), f.U.begin() + static_cast<std::ptrdiff_t>(i1 + P) + 1);
  std::vector<Point<T, D>> Pts(f.P.begin() + static_cast<std::ptrdiff_t>(i0 - P), f.P.begin() + static_cast<std::ptrdiff_t>(i1));
  return BSpline<T, D>(p, std::move(U), std::move(Pts));
}

/// The breakpoints of a closed fit with n control points through L data with closed
/// parameters t_0 = 0 < ... < t_L = 1: b_j = t at the fractional index (j + delta) L / n,
/// linearly interpolated between neighbouring parameters, delta = 0 for odd p and 1/2 for
/// even p. This is the periodic form of [PT97, eq. 9.68-9.69]: every knot span holds at
/// least one parameter when n <= L (the spans are L / n >= 1 indices wide), and for
/// n = L it gives the knots of closed interpolation (the parameters, or the midpoints
/// between them for even p, where knots at the data can make the cyclic system singular).
template <class T>
PeriodicKnots<T> closed_fit_knots(const std::vector<T>& t, int p, std::size_t n) {
  const std::size_t L = t.size() - 1;
  const T d = static_cast<T>(L) / static_cast<T>(n), delta = p % 2 == 1 ? T(0) : T(0.5);
  PeriodicKnots<T> K;
  for (std::size_t j = 0; j < n; ++j) {
    const T x = (static_cast<T>(j) + delta) * d;
    const std::size_t i = std::min(static_cast<std::size_t>(x), L - 1);
    const T alpha = x - static_cast<T>(i);
    K.b.push_back(alpha == 0 ? t[i] : (1 - alpha) * t[i] + alpha * t[i + 1]);
  }
  return K;
}

/// The clamped knots of an open least-squares fit with `count` control points to data with
/// parameters t_0 = 0 < ... < t_m = 1 [PT97, eq. 9.68-9.69]: d = (m + 1) / (n - p + 1)
/// (n = count - 1), interior knot j at t_(i-1) + alpha (t_i - t_(i-1)), i = floor(j d),
/// alpha = j d - i. Every knot span holds at least one parameter.
template <class T>
std::vector<T> open_fit_knots(const std::vector<T>& t, int p, std::size_t count) {
  const std::size_t n = count - 1, m = t.size() - 1, P = static_cast<std::size_t>(p);
  std::vector<T> U(P + 1, T(0));
  const T d = static_cast<T>(m + 1) / static_cast<T>(n - P + 1);
  for (std::size_t j = 1; j + P <= n; ++j) {
    const T jd = static_cast<T>(j) * d;
    const std::size_t i = static_cast<std::size_t>(jd);
    const T alpha = jd - static_cast<T>(i);
    U.push_back((1 - alpha) * t[i - 1] + alpha * t[std::min(i, m)]);
  }
  U.insert(U.end(), P + 1, T(1));
  return U;
}

}  // namespace detail

/// Closed (periodic) interpolation through Q_0..Q_{L-1} with the closing parameters t
/// (L + 1 values, t_L = 1 for the return to Q_0): the periodic degree-p spline, C^(p-1)
/// everywhere, with breakpoints at the parameters for odd p and halfway between them for
/// even p (where knots at the data can make the cyclic system singular) [deBoor78,
/// ch. XIII; PT97, §9.2.4 for the knot choice]. The cyclic banded system is solved by
/// sparse LU. The result is written as an unclamped B-spline on [0, 1] (0 and 1 inserted
/// as knots where they are not breakpoints). Requires L >= p + 1.
template <class T, int D>
BSpline<T, D> interpolate_closed(const std::vector<Point<T, D>>& Q, int p, const std::vector<T>& t) {
  const std::ptrdiff_t L = static_cast<std::ptrdiff_t>(Q.size());
  const detail::PeriodicKnots<T> K = detail::closed_fit_knots(t, p, Q.size());
  Eigen::SparseMatrix<T> A(L, L);
  std::vector<Eigen::Triplet<T>> entries;
  detail::Rhs<T, D> rhs(L, D);
  std::vector<T> local, N;
  for (std::ptrdiff_t i = 0; i < L; ++i) {
    const T u = t[static_cast<std::size_t>(i)];
    const std::ptrdiff_t s = K.span(u);
    K.basis(p, s, u, local, N);
    // p + 1 <= L: the wrapped columns are distinct (setFromTriplets would sum repeats anyway).
    for (int r = 0; r <= p; ++r)
      if (N[static_cast<std::size_t>(r)] != 0) entries.emplace_back(i, static_cast<std::ptrdiff_t>(K.wrap(s - p + r)), N[static_cast<std::size_t>(r)]);
    for (int d = 0; d < D; ++d) rhs(i, d) = Q[static_cast<std::size_t>(i)][d];
  }
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<T>> lu;
  lu.compute(A);
  detail::require_solved(lu.info(), "closed interpolation");
  const detail::Rhs<T, D> x = lu.solve(rhs);
  detail::require_solved(lu.info(), "closed interpolation");
  return detail::periodic_bspline<T, D>(p, K, detail::to_points<T, D>(x));
}

/// Closed (periodic) least-squares approximation: the periodic degree-p spline with
/// n control points (wrapped, C^(p-1) everywhere, including the seam) and the n
/// breakpoints K in [0, 1) (approximate_closed passes those of detail::closed_fit_knots;
/// the tolerance search's knot placement its own), minimising sum_k |C(t_k) - Q_k|^2 over the L distinct
/// points Q_k at their closed parameters t_0..t_{L-1} [PT97, §9.4.1 made periodic, as
/// in their closed-curve variants of §9.2.4]. No point is held fixed: a closed curve has
/// no ends. For n = L it is closed interpolation (the same knots; the square system then
/// has the interpolant as its exact solution).
///
/// The design matrix is cyclic-banded: each row has p + 1 consecutive columns modulo n.
/// With the columns ordered p, .., n - 1, 0, .., p - 1, every row is a band part (a
/// window of at most p + 1 columns below n - p) plus a border of the last p columns, and
/// Givens QR row by row [GolubVanLoan13, §5.1.8] keeps that shape in R: a band of
/// width p + 1 plus a dense border of p columns (the wrap-around as a rank-p border, in
/// place of a dense solve or the normal equations, whose condition number is the square).
/// Cost O(L p^2) time, O(n p) memory. Requires p + 1 <= n <= L; a rank-deficient system
/// (a negligible diagonal of R) is a NumericalError.
template <class T, int D>
BSpline<T, D> approximate_closed_on(const std::vector<Point<T, D>>& Q, int p, const std::vector<T>& t, const detail::PeriodicKnots<T>& K) {
  const std::size_t n = K.b.size();
  const std::size_t P = static_cast<std::size_t>(p), W = P + 1, nb = n - P;
  std::vector<T> Rb(nb * W, T(0));  // Rb[i * W + l] = R(i, i + l), band columns i < nb
  std::vector<T> Re(n * P, T(0));   // Re[i * P + e] = R(i, nb + e), the border
  std::vector<T> z(n * D, T(0));    // the rotated right-hand sides
  std::vector<T> wb(W), we(P), rhs(D), local, N;
  const auto rotate = [](T& r, T& w, T cs, T sn) {
    const T rl = r, wl = w;
    r = cs * rl + sn * wl;
    w = -sn * rl + cs * wl;
  };
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const T u = t[k];
    const std::ptrdiff_t s = K.span(u);
    K.basis(p, s, u, local, N);
    std::fill(wb.begin(), wb.end(), T(0));
    std::fill(we.begin(), we.end(), T(0));
    // Original column c >= p is band column c - p, c < p is border column c; the band
    // part of the window is contiguous and starts at c0.
    std::size_t c0 = nb;
    for (int r = 0; r <= p; ++r) {
      const std::size_t c = K.wrap(s - p + r);
      if (c >= P) c0 = std::min(c0, c - P);
    }
    for (int r = 0; r <= p; ++r) {
      const std::size_t c = K.wrap(s - p + r);
      if (c >= P) {
        wb[c - P - c0] += N[static_cast<std::size_t>(r)];
      } else {
        we[c] += N[static_cast<std::size_t>(r)];
      }
    }
    for (int d = 0; d < D; ++d) rhs[static_cast<std::size_t>(d)] = Q[k][d];
    // Band columns: rotate the row against R's row c while its window holds anything.
    for (std::size_t c = c0; c < nb; ++c) {
      if (std::all_of(wb.begin(), wb.end(), [](T v) { return v == 0; })) break;
      const T a = wb[0];
      if (a != 0) {
        const T rho = std::hypot(Rb[c * W], a);
        const T cs = Rb[c * W] / rho, sn = a / rho;
        for (std::size_t l = 0; l < W; ++l) rotate(Rb[c * W + l], wb[l], cs, sn);
        for (std::size_t e = 0; e < P; ++e) rotate(Re[c * P + e], we[e], cs, sn);
        for (std::size_t d = 0; d < static_cast<std::size_t>(D); ++d) rotate(z[c * D + d], rhs[d], cs, sn);
      }
      std::rotate(wb.begin(), wb.begin() + 1, wb.end());  // slide the window one column right
      wb[W - 1] = 0;
    }
    // Border columns: R's rows nb .. n - 1 are a dense upper triangle there.
    for (std::size_t e = 0; e < P; ++e) {
      const T a = we[e];
      if (a == 0) continue;
      const std::size_t i = nb + e;
      const T rho = std::hypot(Re[i * P + e], a);
      const T cs = Re[i * P + e] / rho, sn = a / rho;
      for (std::size_t l = e; l < P; ++l) rotate(Re[i * P + l], we[l], cs, sn);
      for (std::size_t d = 0; d < static_cast<std::size_t>(D); ++d) rotate(z[i * D + d], rhs[d], cs, sn);
    }
  }
  // Back substitution; a negligible diagonal (relative to the largest) is rank deficiency.
  T rmax = 0;
  for (std::size_t i = 0; i < nb; ++i) rmax = std::max(rmax, std::abs(Rb[i * W]));
  for (std::size_t e = 0; e < P; ++e) rmax = std::max(rmax, std::abs(Re[(nb + e) * P + e]));
  const auto check = [&](T diag) {
    if (!(std::abs(diag) > rmax * T(1e-14))) {
      throw detail::RankDeficientFit("the closed least-squares system is numerically singular (a pivot " + detail::format_number(std::abs(diag) / rmax) +
                           " times the largest): " + std::to_string(n) +
                           " control points are too many for the spread of the data parameters (a basis function is almost zero at "
                           "every parameter)");
    }
  };
  std::vector<T> x(n * D, T(0));  // in the permuted column order
  for (std::size_t e = P; e-- > 0;) {
    const std::size_t i = nb + e;
    check(Re[i * P + e]);
    for (std::size_t d = 0; d < static_cast<std::size_t>(D); ++d) {
      T sum = z[i * D + d];
      for (std::size_t l = e + 1; l < P; ++l) sum -= Re[i * P + l] * x[(nb + l) * D + d];
      x[i * D + d] = sum / Re[i * P + e];
    }
  }
  for (std::size_t i = nb; i-- > 0;) {
    check(Rb[i * W]);
    for (std::size_t d = 0; d < static_cast<std::size_t>(D); ++d) {
      T sum = z[i * D + d];
      for (std::size_t l = 1; l < W && i + l < nb; ++l) sum -= Rb[i * W + l] * x[(i + l) * D + d];
      for (std::size_t e = 0; e < P; ++e) sum -= Re[i * P + e] * x[(nb + e) * D + d];
      x[i * D + d] = sum / Rb[i * W];
    }
  }
  std::vector<Point<T, D>> C(n);
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t j = c >= P ? c - P : nb + c;
    for (int d = 0; d < D; ++d) C[c][d] = x[j * D + static_cast<std::size_t>(d)];
    if (!detail::all_finite_point(C[c])) {
      throw NumericalError("fit: the closed least-squares solution is not finite (overflow near the largest double, or a singular system)");
    }
  }
  return detail::periodic_bspline<T, D>(p, K, C);
}

/// approximate_closed_on with the breakpoints of detail::closed_fit_knots for n control points.
template <class T, int D>
BSpline<T, D> approximate_closed(const std::vector<Point<T, D>>& Q, int p, const std::vector<T>& t, std::size_t n) {
  return approximate_closed_on(Q, p, t, detail::closed_fit_knots(t, p, n));
}

/// Least-squares approximation [PT97, §9.4.1] on the clamped knots U: n + 1 = |U| - p - 1
/// control points (approximate, below, passes the knots of eq. 9.68-9.69; the tolerance
/// search's knot placement its own), C(0) = Q_0 and C(1) = Q_last exactly (P_0, P_n fixed), and
/// with d0 / d1 also C'(0) = d0, C'(1) = d1 exactly (P_1 = P_0 + U_{p+1} d0 / p,
/// P_{n-1} = P_n - (1 - U_n) d1 / p); the other points minimise sum_k |C(t_k) - Q_k|^2
/// over the interior data. [PT97] solves the normal equations (banded, symmetric positive
/// definite); this solves the banded overdetermined system by Givens QR instead, whose
/// error grows with its condition number rather than with its square (data clustered so
/// that a knot span holds almost none make it large). Requires p + 1 <= n + 1 <= number
/// of points + derivatives; a rank-deficient system is a NumericalError.
template <class T, int D>
BSpline<T, D> approximate_on(const std::vector<Point<T, D>>& Q, int p, const std::vector<T>& t, std::vector<T> U,
                             const std::optional<Vector<T, D>>& d0, const std::optional<Vector<T, D>>& d1) {
  const std::size_t P = static_cast<std::size_t>(p), count = U.size() - P - 1, n = count - 1, m = Q.size() - 1;
  std::vector<Point<T, D>> C(count);
  std::vector<bool> fixed(count, false);
  C[0] = Q.front();
  C[n] = Q.back();
  fixed[0] = fixed[n] = true;
  if (d0) {
    C[1] = Q.front() + (U[P + 1] / static_cast<T>(p)) * *d0;
    fixed[1] = true;
  }
  if (d1) {
    C[n - 1] = Q.back() - ((1 - U[n]) / static_cast<T>(p)) * *d1;
    fixed[n - 1] = true;
  }
  std::vector<Eigen::Index> column(count, -1);
  Eigen::Index free = 0;
  for (std::size_t i = 0; i < count; ++i)
    if (!fixed[i]) column[i] = free++;
  if (free > 0) {
    // The overdetermined system itself (one row per interior data point, at most p + 1
    // consecutive entries each), reduced row by row to an upper triangular band R
    // (bandwidth p + 1) by Givens rotations [GolubVanLoan13, §5.1.8, 5.3]: the normal
    // equations of [PT97] would square the condition number, which grows large when few
    // data fall in a knot span. The free columns are
    // contiguous, so a row is a window starting at its first free column; rotating it
    // against R's rows slides the window right until it meets an empty row of R or dies.
    // Cost O(m p^2), memory O(n p).
    const std::size_t F = static_cast<std::size_t>(free), W = P + 1;
    std::vector<T> R(F * W, T(0));                 // R[i * W + l] = entry (i, i + l)
    std::vector<T> z(F * D, T(0));                 // rotated right-hand sides
    std::vector<T> w(2 * W + 1), rhs_row(D);
    std::vector<std::pair<std::size_t, T>> row;
    for (std::size_t k = 1; k < m; ++k) {
      detail::basis_row<T>(U, p, t[k], 0, row);
      Point<T, D> target = Q[k];
      std::size_t c0 = F;  // first free column of the row
      for (const auto& [col, v] : row) {
        if (fixed[col]) {
          target = target - v * (C[col] - Point<T, D>{});
        } else {
          c0 = std::min(c0, static_cast<std::size_t>(column[col]));
        }
      }
      if (c0 == F) continue;  // a row with only fixed columns: nothing to fit
      std::fill(w.begin(), w.end(), T(0));
      for (const auto& [col, v] : row)
        if (!fixed[col]) w[static_cast<std::size_t>(column[col]) - c0] = v;
      for (int dd = 0; dd < D; ++dd) rhs_row[static_cast<std::size_t>(dd)] = target[dd];
      // w holds columns c0 + j; rotate against row c = c0 + j of R while w[j] != 0.
      for (std::size_t j = 0; j < W + W && c0 + j < F; ++j) {
        const T a = w[j];
        if (a == 0) continue;
        const std::size_t c = c0 + j;
        T* Rc = &R[c * W];
        const T r = Rc[0];
        const T rho = std::hypot(r, a);
        const T cs = r / rho, sn = a / rho;
        for (std::size_t l = 0; l < W; ++l) {
          const std::size_t wi = j + l;
          const T wl = wi < w.size() ? w[wi] : T(0);
          const T rl = Rc[l];
          Rc[l] = cs * rl + sn * wl;
          if (wi < w.size()) w[wi] = -sn * rl + cs * wl;
        }
        w[j] = 0;
        for (std::size_t dd = 0; dd < static_cast<std::size_t>(D); ++dd) {
          const T zl = z[c * D + dd], bl = rhs_row[dd];
          z[c * D + dd] = cs * zl + sn * bl;
          rhs_row[dd] = -sn * zl + cs * bl;
        }
      }
    }
    // Back substitution; a negligible diagonal of R (relative to the largest) is numerical
    // rank deficiency: with the knots of eq. 9.68-9.69 every span holds data, but when the
    // control points are many for the spread of the parameters some basis function is
    // almost zero at every data parameter, and its column is nearly dependent on the others.
    T rmax = 0;
    for (std::size_t i = 0; i < F; ++i) rmax = std::max(rmax, std::abs(R[i * W]));
    std::vector<T> x(F * D, T(0));
    for (std::size_t i = F; i-- > 0;) {
      const T diag = R[i * W];
      if (!(std::abs(diag) > rmax * T(1e-14))) {
        throw detail::RankDeficientFit("the least-squares system is numerically singular (a pivot " + detail::format_number(std::abs(diag) / rmax) +
                             " times the largest): " + std::to_string(count) +
                             " control points are too many for the spread of the data parameters (a basis function is almost zero at "
                             "every parameter)");
      }
      for (std::size_t dd = 0; dd < static_cast<std::size_t>(D); ++dd) {
        T sum = z[i * D + dd];
        for (std::size_t l = 1; l < W && i + l < F; ++l) sum -= R[i * W + l] * x[(i + l) * D + dd];
        x[i * D + dd] = sum / diag;
      }
    }
    for (std::size_t i = 0; i < count; ++i)
      if (!fixed[i])
        for (int dd = 0; dd < D; ++dd) C[i][dd] = x[static_cast<std::size_t>(column[i]) * D + static_cast<std::size_t>(dd)];
    for (const auto& q : C)
      if (!detail::all_finite_point(q)) throw NumericalError("the least-squares solution is not finite (overflow near the largest double)");
  }
  return BSpline<T, D>(p, std::move(U), std::move(C));
}

/// approximate with the knots of eq. 9.68-9.69 for `count` control points.
template <class T, int D>
BSpline<T, D> approximate(const std::vector<Point<T, D>>& Q, int p, const std::vector<T>& t, std::size_t count,
                          const std::optional<Vector<T, D>>& d0, const std::optional<Vector<T, D>>& d1) {
  return approximate_on(Q, p, t, detail::open_fit_knots(t, p, count), d0, d1);
}

namespace detail {

/// Knot placement for the tolerance search, by equidistribution [deBoor78, ch. XII, the
/// subroutine NEWNOT; de Boor, "Good approximation by splines with variable knots II",
/// 1974]: the error of a degree-p spline on a span of width h is about
/// h^(p+1) |D^(p+1) f| there, so knots spaced to make h |D^(p+1) f|^(1/(p+1)) the same on
/// every span make the errors alike. The new breakpoints cut the integral of a monitor g
/// (constant on each span of the fit at hand) into equal parts. Two monitors:
/// - without `residual`, de Boor's: |D^(p+1) f| estimated from the fit c (whose p-th
///   derivative is constant on each span) as, at each breakpoint, the jump of the p-th
///   derivative over the mean width of the two spans beside it, and on a span the mean
///   of its two ends; g = that^(1/(p+1)).
/// - with `residual` (the largest distance from a data point to c on each span), the
///   measured error in place of the estimate (our variant, for data whose error is not
///   the smooth h^(p+1) law, noise above all): g = sqrt(residual) / h, the fit's own knot
///   density scaled up where its error is large and down where it is small, so that
///   knots move towards where the error concentrates.
/// g is given a floor, a quarter of its mean (de Boor's has none; without it a span
/// where g vanishes, a straight run or an exact fit, would lose every knot to the rest).
/// x: the fit's breakpoints, open 0 = x_0 < ... < x_S = 1, closed the n breakpoints of
/// one period in [0, 1) (the last span wraps). Returns the interior knots (open:
/// pieces - 1 of them) or the breakpoints (closed: pieces of them, the first at the
/// fraction `phase` of one part). Cost: one p-th derivative per span, O(S p^2 + pieces).
template <class T, int D>
std::vector<T> equidistributed_breaks(const BSpline<T, D>& c, int p, const std::vector<T>& x, bool closed, std::size_t pieces, T phase,
                                      const std::vector<T>* residual = nullptr) {
  const std::size_t S = closed ? x.size() : x.size() - 1;
  std::vector<T> h(S), g(S, T(0)), J(S + 1, T(0));
  std::vector<Vector<T, D>> v(S);
  for (std::size_t i = 0; i < S; ++i) {
    const T a = x[i], b = i + 1 < x.size() ? x[i + 1] : x[0] + 1;
    h[i] = b - a;
    T mid = (a + b) / 2;
    if (mid >= 1) mid -= 1;
    v[i] = c.derivative_at(mid, p);
  }
  // J[i]: the estimate at the left end of span i (J[S]: the right end of the last).
  for (std::size_t i = closed ? 0 : 1; i < S; ++i) {
    const std::size_t l = i == 0 ? S - 1 : i - 1;
    J[i] = norm(v[i] - v[l]) / ((h[l] + h[i]) / 2);
  }
  if (closed) {
    J[S] = J[0];
  } else if (S > 1) {
    J[0] = J[1];
    J[S] = J[S - 1];
  }
  T mean = 0;
  for (std::size_t i = 0; i < S; ++i) {
    g[i] = residual ? std::sqrt((*residual)[i]) / h[i] : std::pow((J[i] + J[i + 1]) / 2, T(1) / static_cast<T>(p + 1));
    mean += g[i] * h[i];
  }
  for (std::size_t i = 0; i < S; ++i) g[i] = std::isfinite(mean) && mean > 0 ? std::max(g[i], mean / 4) : T(1);
  // The spans in order over [0, 1] (closed: the wrapping one cut at 0), with g on each.
  std::vector<std::pair<T, T>> spans;  // (right end, g)
  if (closed && x[0] > 0) spans.emplace_back(x[0], g[S - 1]);
  for (std::size_t i = 0; i < S; ++i) spans.emplace_back(i + 1 < x.size() ? x[i + 1] : T(1), g[i]);
  T total = 0, left = 0;
  for (const auto& [r, gi] : spans) {
    total += (r - left) * gi;
    left = r;
  }
  std::vector<T> out;
  T acc = 0;
  left = 0;
  std::size_t k = 0;
  for (std::size_t j = closed ? 0 : 1; j < pieces; ++j) {
    const T target = (static_cast<T>(j) + (closed ? phase : T(0))) / static_cast<T>(pieces) * total;
    while (k + 1 < spans.size() && acc + (spans[k].first - left) * spans[k].second < target) {
      acc += (spans[k].first - left) * spans[k].second;
      left = spans[k].first;
      ++k;
    }
    out.push_back(std::min(spans[k].first, left + (target - acc) / spans[k].second));
  }
  return out;
}

/// The largest distance from a data point to c on each span of the breakpoints x (as in
/// equidistributed_breaks; closed, a parameter below x_0 is on the wrapping last span).
template <class T, int D>
std::vector<T> span_residuals(const BSpline<T, D>& c, const std::vector<T>& x, bool closed, const std::vector<Point<T, D>>& Q,
                              const std::vector<T>& t) {
  const std::ptrdiff_t S = static_cast<std::ptrdiff_t>(closed ? x.size() : x.size() - 1);
  std::vector<T> r(static_cast<std::size_t>(S), T(0));
  for (std::size_t k = 0; k < t.size(); ++k) {
    std::ptrdiff_t i = std::upper_bound(x.begin(), x.end(), t[k]) - x.begin() - 1;
    i = i < 0 ? S - 1 : std::min(i, S - 1);
    r[static_cast<std::size_t>(i)] = std::max(r[static_cast<std::size_t>(i)], distance(c(t[k]), Q[k]));
  }
  return r;
}

/// Whether clamped knots U suit an open least-squares fit to parameters t (d0, d1: the
/// end derivatives held): every span [U_i, U_(i+1)), p <= i <= n, holds a parameter (the
/// guarantee of eq. 9.68-9.69), and the Schoenberg-Whitney condition holds for the free
/// control points and the interior data [deBoor78, ch. XIII]: increasing parameters
/// t_(k_j) with N_j(t_(k_j)) > 0, U_j < t_(k_j) < U_(j+p+1), one for each free column j
/// (found greedily, which finds one whenever one exists, the supports' ends being
/// increasing in j). Without it the least-squares system is rank deficient.
template <class T>
bool open_knots_hold_data(const std::vector<T>& U, int p, const std::vector<T>& t, bool d0, bool d1) {
  const std::size_t P = static_cast<std::size_t>(p), n = U.size() - P - 2, m = t.size() - 1;
  std::size_t k = 0;
  for (std::size_t i = P; i <= n; ++i) {
    if (!(U[i] < U[i + 1])) return false;
    while (k <= m && t[k] < U[i]) ++k;
    if (k > m || !(t[k] < U[i + 1] || (i == n && t[k] <= U[i + 1]))) return false;
  }
  k = 1;
  for (std::size_t j = d0 ? 2 : 1; j + (d1 ? 2 : 1) <= n; ++j) {
    while (k < m && !(t[k] > U[j])) ++k;
    if (k >= m || !(t[k] < U[j + P + 1])) return false;
    ++k;
  }
  return true;
}

/// Whether periodic breakpoints b (increasing, in [0, 1)) suit a closed least-squares fit
/// to the closed parameters t (t_L = 1): every span of one period holds a parameter, as
/// with closed_fit_knots.
template <class T>
bool closed_knots_hold_data(const std::vector<T>& b, const std::vector<T>& t) {
  const std::size_t n = b.size(), L = t.size() - 1;
  if (!(b[0] >= 0) || !(b[n - 1] < 1)) return false;
  std::size_t k = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (!(b[i] < b[i + 1])) return false;
    while (k < L && t[k] < b[i]) ++k;
    if (k >= L || !(t[k] < b[i + 1])) return false;
  }
  return t[L - 1] >= b[n - 1] || t[0] < b[0];
}

}  // namespace detail

/// What to fit: degree, and either a control point count (least squares; the point
/// count plus the number of end derivatives means interpolation) or a tolerance (the
/// fewest control points found whose max_error is within it).
template <class T, int D>
struct FitRequest {
  int degree = 3;
  std::optional<std::size_t> control_points;
  std::optional<T> tolerance;
  Parametrization parametrization = Parametrization::chord;
  std::optional<Vector<T, D>> start_derivative;
  std::optional<Vector<T, D>> end_derivative;
  bool closed = false;
};

/// Fits the points as the request says; max_error is the largest distance from a data
/// point to the curve at that point's parameter, count the control point count used.
/// With a tolerance the count is searched: bisection between the least that can be fitted
/// and interpolation (knots of eq. 9.68-9.69 for each count) finds a count that passes;
/// knot placement (equidistribution, detail::equidistributed_breaks) then meets the
/// tolerance with fewer where it can; max_error is not monotone in the count, so the
/// counts below the answer are then tried with eq. 9.68-9.69's knots, all of them upwards
/// from the least when the work limit allows, else as many just below as it allows; a
/// count whose system is singular counts as failing; if only interpolation is within the
/// tolerance it is the answer. count is the answer's (closed: n, as below);
/// proven_fewest is true only when the answer's knots are eq. 9.68-9.69's and every
/// smaller count was tried with them (the fewest for those knots; never when the
/// placement found it: no placement is proven best). Work: about
/// detail::fit_work(points, p) per fit; a request above fit_work_limit is refused
/// ("degree", or "points" when no degree would do; "tolerance" when the bisection alone
/// exceeds it), so that every request answers in about a second. Closed fits (the closing
/// point may repeat the first; L distinct points remain) are periodic: n control points
/// with p + 1 <= n <= L, least squares below L (approximate_closed) and interpolation at
/// L (interpolate_closed); the curve is written on [0, 1] with n + p control points (odd
/// p) or n + p + 1 (even p, whose breakpoints miss 0), the first p repeated at the end
/// (odd p). Errors (InvalidArgument): "degree" (< 1; >= 2 with a derivative), "points"
/// (too few: p + 1 conditions, or p + 1 distinct points closed; coincident consecutive
/// points under chord / centripetal), "control_points" (below p + 1 or the ends it must
/// hold, above the point count plus derivatives; closed: outside p + 1 .. L; a
/// least-squares system that is numerically singular: too many for the spread of the
/// parameters), "tolerance" (not > 0), "start_derivative" / "end_derivative" (with closed).
template <class T, int D>
FitResult<T, D> fit(std::vector<Point<T, D>> Q, const FitRequest<T, D>& req) {
  const int p = req.degree;
  if (p < 1) throw InvalidArgument("degree", "degree must be >= 1, got " + std::to_string(p));
  require_finite_points(Q, "points");
  const std::size_t extra = (req.start_derivative ? 1 : 0) + (req.end_derivative ? 1 : 0);
  if (extra > 0 && p < 2) throw InvalidArgument("degree", "end derivatives need degree >= 2, got " + std::to_string(p));
  if (req.tolerance && !(*req.tolerance > 0)) throw InvalidArgument("tolerance", "tolerance must be > 0, got " + detail::format_number(*req.tolerance));
  std::size_t least = 0, most = 0;
  std::vector<T> t;
  std::vector<T> t_data;  // the data's parameters (closed: without the closing one)
  if (req.closed) {
    if (req.start_derivative) throw InvalidArgument("start_derivative", "a closed fit takes no end derivatives");
    if (req.end_derivative) throw InvalidArgument("end_derivative", "a closed fit takes no end derivatives");
    if (Q.size() > 1 && Q.front() == Q.back()) Q.pop_back();  // the closing point may be repeated
    if (Q.size() < static_cast<std::size_t>(p) + 1) {
      throw InvalidArgument("points", "a closed fit of degree " + std::to_string(p) + " needs at least " + std::to_string(p + 1) +
                                          " distinct points, got " + std::to_string(Q.size()));
    }
    least = static_cast<std::size_t>(p) + 1;
    most = Q.size();
    t = unit_parameters(Q, req.parametrization, true);
    t_data.assign(t.begin(), t.end() - 1);
  } else {
    most = Q.size() + extra;
    least = std::max(static_cast<std::size_t>(p) + 1, 2 + extra);
    if (Q.size() < 2 || most < static_cast<std::size_t>(p) + 1) {
      throw InvalidArgument("points", "degree " + std::to_string(p) + " needs at least " + std::to_string(p + 1) +
                                          " conditions (points and end derivatives), got " + std::to_string(most));
    }
    t = unit_parameters(Q, req.parametrization, false);
    t_data = t;
  }
  const T work = detail::fit_work(Q.size() + extra, p);
  if (work > fit_work_limit) {
    int pmax = 0;  // the highest degree within the limit for these points (0: none)
    while (pmax < p && detail::fit_work(Q.size() + extra, pmax + 1) <= fit_work_limit) ++pmax;
    const std::string figure = "a fit of degree " + std::to_string(p) + " to " + std::to_string(Q.size()) + " points needs about " +
                               detail::format_number(work) + " steps (points x (2 (degree + 1)^2 + 300)), above the limit of " +
                               detail::format_number(fit_work_limit) + " per request (about a second)";
    if (pmax >= 1) throw InvalidArgument("degree", figure + ": use degree <= " + std::to_string(pmax) + " for this many points");
    throw InvalidArgument("points", figure + ": fit fewer points");
  }
  const auto with_count = [&](std::size_t count) -> FitResult<T, D> {
    BSpline<T, D> c = req.closed ? (count == most ? interpolate_closed(Q, p, t) : approximate_closed(Q, p, t, count))
                                 : (count == most ? interpolate(Q, p, t, req.start_derivative, req.end_derivative)
                                                  : approximate(Q, p, t, count, req.start_derivative, req.end_derivative));
    const T e = detail::max_fit_error(c, Q, t_data);
    return {std::move(c), e};
  };
  if (req.control_points) {
    const std::size_t count = *req.control_points;
    if (count < least || count > most) {
      throw InvalidArgument("control_points", "must be in " + std::to_string(least) + ".." + std::to_string(most) + " for degree " +
                                                  std::to_string(p) + (req.closed ? " and these distinct points (closed)" : " and these points") +
                                                  ", got " + std::to_string(count));
    }
    try {
      FitResult<T, D> f = with_count(count);
      f.count = count;
      return f;
    } catch (const detail::RankDeficientFit& e) {
      throw InvalidArgument("control_points", e.what() + std::string("; use fewer control_points"));
    }
  }
  const T tol = *req.tolerance;
  // The tolerance search: every count tried costs one fit, within a budget of B fits.
  // The bisection (about log2 of the range, with the knots of eq. 9.68-9.69) finds a
  // count hi that passes; the knot placement and the scan below it follow (below).
  const std::size_t budget = detail::fit_trials(work);
  const std::size_t range = most - least + 1;
  std::size_t bisection_trials = 1;  // the first try, at most
  for (std::size_t r = range; r > 1; r = (r + 1) / 2) ++bisection_trials;
  if (bisection_trials > budget) {
    throw InvalidArgument("tolerance", "the search over " + std::to_string(range) + " control point counts would need about " +
                                           std::to_string(bisection_trials) + " fits of " + detail::format_number(work) +
                                           " steps each (points x (2 (degree + 1)^2 + 300)), above the limit of " +
                                           detail::format_number(fit_work_limit) + " per request (about a second): give control_points instead");
  }
  std::size_t trials = 0;
  std::optional<FitResult<T, D>> best;
  std::size_t best_count = 0;
  bool best_placed = false;    // best's knots are placed ones (not eq. 9.68-9.69's)
  std::vector<T> best_breaks;  // then its breakpoints (open: 0 .. 1; closed: one period)
  const auto try_count = [&](std::size_t count) -> bool {
    ++trials;
    try {
      FitResult<T, D> f = with_count(count);
      if (!(f.max_error <= tol)) return false;
      if (!best || count < best_count) {
        best = std::move(f);
        best_count = count;
        best_placed = false;
      }
      return true;
    } catch (const NumericalError&) {
      return false;  // a near-singular count counts as failing
    }
  };
  if (!try_count(most)) {
    FitResult<T, D> f = with_count(most);  // nothing meets the tolerance: the interpolant
    f.count = most;
    return f;
  }
  std::size_t lo = least, hi = most;  // every count tried below lo failed; hi passes
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (try_count(mid)) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  // Knot placement: the counts found are the fewest for the knots of eq. 9.68-9.69, which
  // follow the data's density, not the shape's. From the answer, fewer control points are
  // tried with knots placed by equidistribution (detail::equidistributed_breaks): the
  // first round from de Boor's derivative estimate on the passing fit, then up to
  // placement_rounds - 1 more from the measured error of the latest fit at that count
  // (which failed), as de Boor iterates NEWNOT. The step down starts at one control point
  // and doubles after each success, halves after a failure; when a step of one fails
  // every round, two and then three fewer are tried (placement_skips: whether a count
  // passes is not monotone here either), and the placement stops when those fail too or
  // its budget is spent. Each round counts as one fit of the budget, two when it
  // measures the error first (a pass over the data, an evaluation per point, about what
  // the fit's own costs; the derivative per span of the knot step is fewer evaluations
  // than that). Knots that leave a span without data or break the Schoenberg-Whitney
  // condition are moved a quarter, a half, three quarters of the way towards those of
  // eq. 9.68-9.69 (which satisfy both) until they pass; if none does, or the solver
  // still finds the system singular, that count fails. Measured on 200 noisy points
  // (docs/performance.md): 10 rounds gave most of what 20 do; the two skips lowered the
  // counts most near the noise.
  constexpr int placement_rounds = 10;
  constexpr int placement_skips = 2;
  const T phase = p % 2 == 1 ? T(0) : T(0.5);
  const auto place = [&](std::size_t cap) {
    BSpline<T, D> seed = best->curve;
    std::vector<T> seed_breaks = best_breaks;
    if (!best_placed) {
      if (req.closed) {
        seed_breaks = detail::closed_fit_knots(t, p, best_count).b;
      } else {
        const auto& U = seed.knots();
        seed_breaks.assign(U.begin() + p, U.end() - p);
      }
    }
    std::size_t stride = 1;
    int skipped = 0;
    while (best_count > least && trials < cap) {
      const std::size_t count = best_count - std::min(stride, best_count - least);
      const std::vector<T> averaging = req.closed ? detail::closed_fit_knots(t, p, count).b : detail::open_fit_knots(t, p, count);
      BSpline<T, D> at = seed;
      std::vector<T> at_breaks = seed_breaks;
      bool passed = false;
      for (int round = 0; round < placement_rounds && trials < cap && !passed; ++round) {
        std::vector<T> knots;  // open: clamped knots; closed: breakpoints
        try {
          const std::vector<T> res = round > 0 ? detail::span_residuals(at, at_breaks, req.closed, Q, t_data) : std::vector<T>{};
          const std::vector<T> x = detail::equidistributed_breaks<T, D>(at, p, at_breaks, req.closed,
                                                                        req.closed ? count : count - static_cast<std::size_t>(p), phase,
                                                                        res.empty() ? nullptr : &res);
          for (const T w : {T(0), T(0.25), T(0.5), T(0.75)}) {
            std::vector<T> k = req.closed ? x : std::vector<T>(static_cast<std::size_t>(p) + 1, T(0));
            if (!req.closed) {
              k.insert(k.end(), x.begin(), x.end());
              k.insert(k.end(), static_cast<std::size_t>(p) + 1, T(1));
            }
            for (std::size_t i = 0; i < k.size(); ++i) k[i] = (1 - w) * k[i] + w * averaging[i];
            if (req.closed ? detail::closed_knots_hold_data(k, t)
                           : detail::open_knots_hold_data(k, p, t, req.start_derivative.has_value(), req.end_derivative.has_value())) {
              knots = std::move(k);
              break;
            }
          }
        } catch (const NumericalError&) {  // a derivative that overflows: no placement
        }
        if (knots.empty()) break;
        trials += round > 0 ? 2 : 1;  // a round with the error pass: one more evaluation per point
        try {
          BSpline<T, D> c = req.closed ? approximate_closed_on(Q, p, t, detail::PeriodicKnots<T>{knots})
                                       : approximate_on(Q, p, t, knots, req.start_derivative, req.end_derivative);
          const T e = detail::max_fit_error(c, Q, t_data);
          at_breaks = req.closed ? knots : std::vector<T>(knots.begin() + p, knots.end() - p);
          if (e <= tol) {
            best = FitResult<T, D>{c, e};
            best_count = count;
            best_breaks = at_breaks;
            best_placed = passed = true;
            seed = std::move(c);
            seed_breaks = at_breaks;
          } else {
            at = std::move(c);
          }
        } catch (const NumericalError&) {
          break;  // a near-singular system: this count fails
        }
      }
      if (passed) {
        stride *= 2;
        skipped = 0;
      } else if (stride > 1) {
        stride /= 2;
      } else if (skipped < placement_skips) {
        ++skipped;
        stride = 1 + static_cast<std::size_t>(skipped);  // two fewer, then three
      } else {
        break;
      }
    }
  };
  // The budget after the bisection: the placement first, with at most half of it (it
  // stops early where it fails, and what it leaves goes on), then the counts below the
  // answer with the knots of eq. 9.68-9.69: all of them upwards from the least when what
  // is left allows (the first that passes is then the fewest for those knots: proven),
  // otherwise downwards from the answer as far as it goes (max_error is not monotone in
  // the count, so a count below a failing one may pass). If that found a count below the
  // placement's, the placement runs again from it with what is left.
  const auto left = [&] { return budget > trials ? budget - trials : 0; };
  place(trials + left() / 2);
  const std::size_t placed_count = best_count;
  bool exhaustive = false;
  if (best_count - least <= left()) {
    for (std::size_t c = least; c < best_count; ++c)
      if (try_count(c)) break;
    exhaustive = true;
  } else {
    for (std::size_t c = best_count; c-- > least && trials < budget;) try_count(c);
  }
  const bool proven = exhaustive && !best_placed;  // for the knots of eq. 9.68-9.69
  if (best_count < placed_count) place(budget);
  FitResult<T, D> f = std::move(*best);
  f.count = best_count;
  f.proven_fewest = proven && !best_placed;  // the second placement did not lower it
  return f;
}

}  // namespace casteljau
