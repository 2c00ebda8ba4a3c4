// Degree reduction of B-splines and NURBS by fitting: the lower-degree spline on the same
// breaks fitted to the curve by weighted least squares, then refined towards the min-max
// fit by Lawson's reweighting. The candidates io::reduce measures next to [PT97] A5.11.
// Flat coordinates (a run-time count E per point) so that one instantiation per scalar
// serves every dimension and both the Cartesian and the homogeneous fits.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/knot_form.hpp"

namespace casteljau::detail {

/// A B-spline with flat coordinates: degree p, knots U, E numbers per control point
/// (P.size() = E (U.size() - p - 1)).
template <class T>
struct FlatSpline {
  int p = 0;
  int E = 0;
  std::vector<T> U;
  std::vector<T> P;
};

/// The knots of the reduction of a degree-p spline with knots U by r (1 <= r < p), on its
/// domain [U_p, U_n], clamped there: degree q = p - r, every break inside the domain kept
/// with multiplicity max(m - r, 1) (m its multiplicity in U: the original continuity
/// C^(p - m) where degree q allows it, C^(q - 1) otherwise), a break of multiplicity p + 1
/// (a jump) q + 1 times. Degree elevation by r adds r to every multiplicity, so an
/// elevated curve's knots come back.
template <class T>
std::vector<T> reduced_knots(std::span<const T> U, int p, int r) {
  const int q = p - r;
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  const T a = U[static_cast<std::size_t>(p)], b = U[n];
  std::vector<T> W(static_cast<std::size_t>(q) + 1, a);
  for (std::size_t i = 0; i < U.size();) {
    std::size_t j = i;
    while (j < U.size() && U[j] == U[i]) ++j;
    if (U[i] > a && U[i] < b) {
      const int m = static_cast<int>(j - i);
      const int mult = m == p + 1 ? q + 1 : std::max(m - r, 1);
      W.insert(W.end(), static_cast<std::size_t>(mult), U[i]);
    }
    i = j;
  }
  W.insert(W.end(), static_cast<std::size_t>(q) + 1, b);
  return W;
}

/// f's value at u on its span s (the piece of that span, continued to its ends: at a
/// break, the limit from inside the span) into out (E numbers). N: scratch of p + 1.
template <class T>
void piece_value(const FlatSpline<T>& f, std::size_t s, T u, std::span<T> N, std::span<T> out) {
  basis_functions<T>(std::span<const T>(f.U), f.p, s, u, N);
  std::fill(out.begin(), out.end(), T(0));
  const std::size_t E = static_cast<std::size_t>(f.E), first = s - static_cast<std::size_t>(f.p);
  for (std::size_t k = 0; k <= static_cast<std::size_t>(f.p); ++k)
    for (std::size_t e = 0; e < E; ++e) out[e] += N[k] * f.P[(first + k) * E + e];
}

/// A degree-q spline on knots W fitted to a curve on its pieces: the problem io::reduce
/// poses. Pieces j = 0.. of the curve's domain: [lo_j, hi_j], the original's span
/// source_span[j] and the fit's span fit_span[j] there; K samples per piece at the Chebyshev
/// points of the first kind (interior: at a break the two sides are the two pieces');
/// fixed control points (the domain's ends, both limits at a jump) with their values in
/// C0, which holds E numbers per control point of the fit.
template <class T>
struct SplineFit {
  int q = 0;
  int E = 0;
  std::vector<T> W;
  std::vector<char> fixed;
  std::vector<T> C0;
  std::vector<T> lo, hi;
  std::vector<std::size_t> source_span, fit_span;
  int K = 0;

  [[nodiscard]] std::size_t samples() const { return lo.size() * static_cast<std::size_t>(K); }
  [[nodiscard]] std::size_t piece(std::size_t i) const { return i / static_cast<std::size_t>(K); }
  [[nodiscard]] T sample(std::size_t i) const {
    const std::size_t j = i / static_cast<std::size_t>(K), k = i % static_cast<std::size_t>(K);
    const T c = std::cos(std::numbers::pi_v<T> * static_cast<T>(2 * k + 1) / static_cast<T>(2 * K));
    const T mid = (lo[j] + hi[j]) / 2, half = (hi[j] - lo[j]) / 2;
    return mid + half * c;
  }
};

/// The fit's value at sample i (E numbers) for control points C. N: scratch of q + 1.
template <class T>
void fit_value(const SplineFit<T>& f, const std::vector<T>& C, std::size_t i, std::span<T> N, std::span<T> out) {
  const std::size_t s = f.fit_span[i / static_cast<std::size_t>(f.K)];
  basis_functions<T>(std::span<const T>(f.W), f.q, s, f.sample(i), N);
  std::fill(out.begin(), out.end(), T(0));
  const std::size_t E = static_cast<std::size_t>(f.E), first = s - static_cast<std::size_t>(f.q);
  for (std::size_t k = 0; k <= static_cast<std::size_t>(f.q); ++k)
    for (std::size_t e = 0; e < E; ++e) out[e] += N[k] * C[(first + k) * E + e];
}

/// The weighted least-squares fit: the free control points of C (C0's fixed ones kept)
/// minimising sum_i w_i |fit(t_i) - y_i|^2, y_i = target(i, out) (E numbers). The rows
/// (at most q + 1 consecutive columns each, the fixed columns moved to the right-hand
/// side) are reduced one at a time to an upper triangular band of width q + 1 by Givens
/// rotations [GolubVanLoan13, 5.1.8], without forming the normal equations. Returns false
/// when a pivot is negligible (below 1e-14 of the largest) or the solution is not finite.
/// Cost O(N q^2 + N cost(target)) for N samples, memory O(n (q + E)).
template <class T, class Target>
bool weighted_fit(const SplineFit<T>& f, const std::vector<T>& w, Target&& target, std::vector<T>& C) {
  const std::size_t E = static_cast<std::size_t>(f.E), q = static_cast<std::size_t>(f.q), Wd = q + 1;
  const std::size_t n = f.fixed.size();
  C = f.C0;
  std::vector<std::size_t> column(n, 0);
  std::size_t F = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!f.fixed[i]) column[i] = F++;
  if (F == 0) return true;
  std::vector<T> R(F * Wd, T(0)), z(F * E, T(0)), row(Wd), rhs(E), y(E), N(Wd);
  for (std::size_t i = 0; i < f.samples(); ++i) {
    const std::size_t s = f.fit_span[i / static_cast<std::size_t>(f.K)];
    basis_functions<T>(std::span<const T>(f.W), f.q, s, f.sample(i), std::span<T>(N));
    target(i, std::span<T>(y));
    const T sw = std::sqrt(w[i]);
    const std::size_t first = s - q;
    std::size_t c0 = F;
    for (std::size_t k = 0; k < Wd; ++k) {
      const std::size_t col = first + k;
      if (f.fixed[col]) {
        for (std::size_t e = 0; e < E; ++e) y[e] -= N[k] * f.C0[col * E + e];
      } else {
        c0 = std::min(c0, column[col]);
      }
    }
    if (c0 == F || !(sw > 0)) continue;
    std::fill(row.begin(), row.end(), T(0));
    for (std::size_t k = 0; k < Wd; ++k)
      if (!f.fixed[first + k]) row[column[first + k] - c0] = sw * N[k];
    for (std::size_t e = 0; e < E; ++e) rhs[e] = sw * y[e];
    // row holds columns c .. c + q; rotate it into R's row c, then move on to c + 1.
    for (std::size_t c = c0; c < F; ++c) {
      const T a = row[0];
      if (a != 0) {
        T* Rc = &R[c * Wd];
        const T r = Rc[0], rho = std::hypot(r, a), cs = r / rho, sn = a / rho;
        for (std::size_t l = 0; l < Wd; ++l) {
          const T rl = Rc[l], wl = row[l];
          Rc[l] = cs * rl + sn * wl;
          row[l] = -sn * rl + cs * wl;
        }
        for (std::size_t e = 0; e < E; ++e) {
          const T zl = z[c * E + e], bl = rhs[e];
          z[c * E + e] = cs * zl + sn * bl;
          rhs[e] = -sn * zl + cs * bl;
        }
      }
      bool rest = false;
      for (std::size_t l = 1; l < Wd; ++l) {
        row[l - 1] = row[l];
        rest = rest || row[l] != 0;
      }
      row[Wd - 1] = 0;
      if (!rest) break;
    }
  }
  T rmax = 0;
  for (std::size_t i = 0; i < F; ++i) rmax = std::max(rmax, std::abs(R[i * Wd]));
  std::vector<T> x(F * E, T(0));
  for (std::size_t i = F; i-- > 0;) {
    const T diag = R[i * Wd];
    if (!(std::abs(diag) > rmax * T(1e-14))) return false;
    for (std::size_t e = 0; e < E; ++e) {
      T sum = z[i * E + e];
      for (std::size_t l = 1; l < Wd && i + l < F; ++l) sum -= R[i * Wd + l] * x[(i + l) * E + e];
      x[i * E + e] = sum / diag;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (f.fixed[i]) continue;
    for (std::size_t e = 0; e < E; ++e) {
      C[i * E + e] = x[column[i] * E + e];
      if (!std::isfinite(C[i * E + e])) return false;
    }
  }
  return true;
}

/// The least-squares fit with weights proportional to the pieces' lengths (a discrete
/// Chebyshev-weighted L2 fit per piece, near the min-max fit for polynomials), then up to
/// `iterations` steps of Lawson's algorithm [Lawson61; RiceUsow68]: each weight
/// multiplied by its sample's error, error(i, fitted) (the distance that counts, >= 0),
/// and the fit solved again, which moves the fit towards the discrete min-max one. Returns
/// the fit of least sampled max error among the steps, then the first fit when a step
/// improved on it (none when the first solve failed), each with its largest sampled error
/// (a value from below of its max error: the samples are points of both curves). Weights below 1e-12 of the
/// largest are raised to it (the system stays non-singular). Cost O(iterations N q^2).
template <class T>
struct LawsonFit {
  std::vector<T> C;
  T sampled_error;
};
template <class T, class Target, class Error>
std::vector<LawsonFit<T>> lawson_fits(const SplineFit<T>& f, Target&& target, Error&& error, int iterations) {
  const std::size_t N = f.samples(), E = static_cast<std::size_t>(f.E);
  std::vector<T> w(N), err(N), val(E), scratch(static_cast<std::size_t>(f.q) + 1);
  for (std::size_t i = 0; i < N; ++i) w[i] = f.hi[i / static_cast<std::size_t>(f.K)] - f.lo[i / static_cast<std::size_t>(f.K)];
  std::vector<T> C;
  if (!weighted_fit(f, w, target, C)) return {};
  std::vector<LawsonFit<T>> out{{C, T(0)}, {C, T(0)}};  // the best, the first
  T best = -1;
  for (int it = 0;; ++it) {
    T top = 0, total = 0;
    for (std::size_t i = 0; i < N; ++i) {
      fit_value<T>(f, C, i, std::span<T>(scratch), std::span<T>(val));
      err[i] = error(i, std::span<const T>(val));
      top = std::max(top, err[i]);
    }
    if (!std::isfinite(top)) top = std::numeric_limits<T>::infinity();
    if (it == 0) out[1].sampled_error = top;
    if (best < 0 || top < best) {
      best = top;
      out[0] = {C, top};
    }
    if (it >= iterations || !(top > 0) || !std::isfinite(top)) break;
    T wmax = 0;
    for (std::size_t i = 0; i < N; ++i) {
      w[i] *= err[i] / top;
      total += w[i];
      wmax = std::max(wmax, w[i]);
    }
    if (!(total > 0)) break;
    for (std::size_t i = 0; i < N; ++i) w[i] = std::max(w[i], wmax * T(1e-12)) / wmax;
    if (!weighted_fit(f, w, target, C)) break;
  }
  if (out[0].C == out[1].C) out.pop_back();
  return out;
}

}  // namespace casteljau::detail
