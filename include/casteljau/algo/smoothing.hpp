// Smoothing splines: the cubic spline with knots at every data parameter that minimises
// sum_k |Q_k - C(t_k)|^2 + lambda * integral |C''(t)|^2 dt, for a given lambda >= 0 or
// with lambda chosen by generalised cross-validation, the problem and the conventions of
// scipy.interpolate.make_smoothing_spline (unit weights), solved in Reinsch's form by a
// banded QR. Not part of casteljau.hpp (it brings Eigen's dense matrices for the
// coordinates); the io layer compiles it once (src/io/fit.cpp).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/core/unit_frame.hpp"
#include "casteljau/curves/bspline.hpp"

namespace casteljau {

/// A smoothing spline: the clamped cubic B-spline (knots t_0 four times, t_1 .. t_(n-2),
/// t_(n-1) four times; n + 2 control points), the lambda it was computed with, and for a
/// lambda chosen by cross-validation the criterion's value there.
template <class T, int D>
struct SmoothingSpline {
  BSpline<T, D> curve;
  T lambda;
  T gcv;  ///< the GCV criterion at lambda (NaN when lambda was given, or for fewer than 3 points)
};

namespace detail {

/// Reinsch's form of the smoothing problem [Reinsch67; GreenSilverman94, §2.3]: with the
/// fitted values g_k = C(t_k) and the second derivatives gamma_k = C''(t_k) (zero at both
/// ends: the minimiser over all functions with a square-integrable second derivative is a
/// natural cubic spline), the penalty is gamma^T R gamma and Q^T g = R gamma, where for
/// the m = n - 2 interior points j (h_k = t_(k+1) - t_k)
///   Q (n x m): Q(j-1, j) = 1 / h_(j-1), Q(j, j) = -1 / h_(j-1) - 1 / h_j, Q(j+1, j) = 1 / h_j,
///   R (m x m, tridiagonal): R(j, j) = (h_(j-1) + h_j) / 3, R(j, j+1) = h_j / 6.
/// The minimiser solves M gamma = Q^T y with M = R + lambda Q^T Q, and g = y - r with the
/// residuals r = lambda Q gamma, one column per coordinate.
///
/// M is not formed: Q^T Q is a fourth difference, its condition number grows like n^4, and
/// rounding its entries lost up to 1e-9 of the curve at n = 80 (measured against 40
/// digits). gamma is instead the least-squares solution of
///   [sqrt(lambda) Q; C^T] gamma ~ [y / sqrt(lambda); 0]   (R = C C^T, C lower bidiagonal),
/// whose normal equations are M gamma = Q^T y, reduced by Givens rotations [GolubVanLoan13,
/// §5.1.8] row by row to M = U^T U, U upper triangular with two super-diagonals: the
/// condition number is the square root of M's, and the curve agrees with 40 digits to
/// about 1e-12 there. Eigen offers no banded QR (fit.hpp's least squares does the same).
/// lambda = 0 (interpolation, where that scaling fails) solves R gamma = Q^T y by C.
/// O(n d) per lambda, memory O(n d).
template <class T>
class ReinschSystem {
 public:
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

  ReinschSystem(const std::vector<T>& t, const Matrix& y) : y_(y) {
    const std::size_t n = t.size();
    for (std::size_t k = 0; k + 1 < n; ++k) h_.push_back(t[k + 1] - t[k]);
    m_ = n >= 2 ? n - 2 : 0;
    // The three unique bands of Q^T Q (q0 diagonal, q1 and q2 the super-diagonals), for the
    // trace; C: c0 its diagonal, c1[j] = C(j+1, j).
    q0_.assign(m_, T(0));
    q1_.assign(m_, T(0));
    q2_.assign(m_, T(0));
    c0_.assign(m_, T(0));
    c1_.assign(m_, T(0));
    for (std::size_t c = 0; c < m_; ++c) {
      const T a = q(c, c), b = q(c + 1, c), e = q(c + 2, c);  // column c: rows c, c+1, c+2
      q0_[c] = a * a + b * b + e * e;
      if (c + 1 < m_) q1_[c] = b * q(c + 1, c + 1) + e * q(c + 2, c + 1);
      if (c + 2 < m_) q2_[c] = e * q(c + 2, c + 2);
      const T off = c > 0 ? c1_[c - 1] : T(0);
      c0_[c] = std::sqrt((h_[c] + h_[c + 1]) / 3 - off * off);  // R is diagonally dominant: no breakdown
      if (c + 1 < m_) c1_[c] = h_[c + 1] / 6 / c0_[c];
    }
    U_.assign(3 * m_, T(0));
  }

  [[nodiscard]] std::size_t interior() const { return m_; }

  /// Solves for lambda: the second derivatives at the interior points (m x d), the
  /// residuals r = y - g = lambda Q gamma and the fitted values g (n x d).
  void solve(T lambda, Matrix& gamma, Matrix& r, Matrix& g) {
    const auto I = [](std::size_t i) { return static_cast<Eigen::Index>(i); };
    const Eigen::Index d = y_.cols();
    r = Matrix::Zero(y_.rows(), d);
    g = y_;
    gamma = Matrix::Zero(I(m_), d);
    if (m_ == 0) return;  // two points: the straight line for every lambda
    std::fill(U_.begin(), U_.end(), T(0));
    Matrix z = Matrix::Zero(I(m_), d);  // the rotated right-hand side
    if (lambda == 0) {
      // M = R = C C^T: U = C^T; z solves C z = Q^T y.
      for (std::size_t c = 0; c < m_; ++c) {
        U_[3 * c] = c0_[c];
        U_[3 * c + 1] = c1_[c];
        z.row(I(c)) = q(c, c) * y_.row(I(c)) + q(c + 1, c) * y_.row(I(c + 1)) + q(c + 2, c) * y_.row(I(c + 2));
        if (c > 0) z.row(I(c)) -= c1_[c - 1] * z.row(I(c - 1));
        z.row(I(c)) /= c0_[c];
      }
    } else {
      const T root = std::sqrt(lambda);
      std::vector<T> w(3), rhs(static_cast<std::size_t>(d));
      // Rows enter in non-decreasing order of their first column, so U has no entry right of
      // the entering row's last column (rotations mix only the columns of the two rows):
      // the row never outgrows its three columns while it is rotated into U.
      const auto add_row = [&](std::size_t first) {
        // Rotate the row (w: columns first .. first + 2, rhs) into U, column by column.
        for (std::size_t j = 0; j < 3 && first + j < m_; ++j) {
          const T a = w[j];
          if (a == 0) continue;
          const std::size_t c = first + j;
          T* Uc = &U_[3 * c];
          const T rho = std::hypot(Uc[0], a);
          const T cs = Uc[0] / rho, sn = a / rho;
          for (std::size_t l = 0; l < 3; ++l) {  // U row c covers columns c .. c + 2, the row j .. 2 of w
            const T wl = j + l < 3 ? w[j + l] : T(0);
            const T ul = Uc[l];
            Uc[l] = cs * ul + sn * wl;
            if (j + l < 3) w[j + l] = -sn * ul + cs * wl;
          }
          w[j] = 0;
          for (Eigen::Index k = 0; k < d; ++k) {
            const T zk = z(I(c), k), bk = rhs[static_cast<std::size_t>(k)];
            z(I(c), k) = cs * zk + sn * bk;
            rhs[static_cast<std::size_t>(k)] = -sn * zk + cs * bk;
          }
        }
      };
      for (std::size_t i = 0; i < m_ + 2; ++i) {  // data row i: sqrt(lambda) Q(i, .), columns i-2 .. i
        const std::size_t first = i >= 2 ? i - 2 : 0;
        for (std::size_t j = 0; j < 3; ++j) {
          const std::size_t c = first + j;
          w[j] = c < m_ && c <= i && i <= c + 2 ? root * q(i, c) : T(0);
        }
        for (Eigen::Index k = 0; k < d; ++k) rhs[static_cast<std::size_t>(k)] = y_(I(i), k) / root;
        add_row(first);
        if (i >= 2) {  // row i - 2 of C^T: columns i-2, i-1; it joins after the data rows that start there
          w = {c0_[i - 2], i - 1 < m_ ? c1_[i - 2] : T(0), T(0)};
          std::fill(rhs.begin(), rhs.end(), T(0));
          add_row(i - 2);
        }
      }
    }
    // Back substitution U gamma = z.
    for (std::size_t c = m_; c-- > 0;) {
      gamma.row(I(c)) = z.row(I(c));
      for (std::size_t l = 1; l < 3 && c + l < m_; ++l) gamma.row(I(c)) -= U_[3 * c + l] * gamma.row(I(c + l));
      gamma.row(I(c)) /= U_[3 * c];
    }
    if (lambda != 0) {
      for (std::size_t c = 0; c < m_; ++c)  // r = lambda Q gamma
        for (std::size_t i = c; i <= c + 2; ++i) r.row(I(i)) += (lambda * q(i, c)) * gamma.row(I(c));
      g -= r;
    }
    if (!gamma.allFinite() || !g.allFinite()) throw NumericalError("the smoothing spline for lambda = " + format_number(lambda) + " is not finite");
  }

  /// After solve(lambda): tr(M^-1 Q^T Q), so that the trace of the influence matrix A
  /// (fitted values = A y) is n - lambda tr(M^-1 Q^T Q) [GreenSilverman94, §3.2]. Needs
  /// S = M^-1 only on its five central bands: from M = U^T U = L D L^T (L = (U / diag U)^T,
  /// D = diag(U)^2) by the recurrence S = D^-1 L^-1 + (I - L^T) S, rows from the last up
  /// [HutchinsonDeHoog85]. O(n).
  [[nodiscard]] T trace_term() const {
    const std::size_t m = m_;
    std::vector<T> s0(m, T(0)), s1(m, T(0)), s2(m, T(0));  // S(c, c), S(c, c+1), S(c, c+2)
    for (std::size_t c = m; c-- > 0;) {
      const T u = U_[3 * c], l1 = U_[3 * c + 1] / u, l2 = U_[3 * c + 2] / u;
      const bool has1 = c + 1 < m, has2 = c + 2 < m;
      if (has2) s2[c] = -l1 * s1[c + 1] - l2 * s0[c + 2];
      if (has1) s1[c] = -l1 * s0[c + 1] - (has2 ? l2 * s1[c + 1] : T(0));
      s0[c] = 1 / (u * u) - (has1 ? l1 * s1[c] : T(0)) - (has2 ? l2 * s2[c] : T(0));
    }
    T tr = 0;
    for (std::size_t c = 0; c < m; ++c) tr += s0[c] * q0_[c] + 2 * (s1[c] * q1_[c] + s2[c] * q2_[c]);
    return tr;
  }

 private:
  /// Q(i, c): non-zero for i = c, c + 1, c + 2.
  [[nodiscard]] T q(std::size_t i, std::size_t c) const {
    if (i == c) return 1 / h_[c];
    if (i == c + 1) return -1 / h_[c] - 1 / h_[c + 1];
    if (i == c + 2) return 1 / h_[c + 1];
    return 0;
  }

  std::vector<T> h_;
  Matrix y_;
  std::size_t m_ = 0;
  std::vector<T> q0_, q1_, q2_, c0_, c1_;
  std::vector<T> U_;  ///< U(c, c + l) = U_[3 c + l], l = 0, 1, 2
};

/// The generalised cross-validation criterion [CravenWahba79; Wahba90, §4.3] of the
/// smoothing spline for lambda, on the stacked residuals of the d coordinates:
///   GCV(lambda) = (|Y - G|^2 / (n d)) / (1 - tr(A) / n)^2,
/// the mean of the d coordinates' criteria (each coordinate is smoothed by the same
/// influence matrix A, so the stacked problem's trace is d tr(A) over n d observations).
/// For d = 1 it is scipy's criterion. 1 - tr(A) / n is formed as lambda tr(M^-1 Q^T Q) / n
/// (no cancellation at small lambda).
template <class T>
T gcv_criterion(ReinschSystem<T>& sys, T lambda, const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>& y) {
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> gamma, r, g;
  sys.solve(lambda, gamma, r, g);
  const T n = static_cast<T>(y.rows()), d = static_cast<T>(y.cols());
  const T numerator = r.squaredNorm() / (n * d);
  const T one_minus = lambda * sys.trace_term() / n;
  return numerator / (one_minus * one_minus);
}

/// Brent's minimisation without derivatives on a bounded interval [Brent73, ch. 5;
/// ForsytheMalcolmMoler77, fmin]: golden-section steps, parabolic interpolation when it is
/// acceptable, never closer than tol1 = sqrt(2.2e-16) |x| + xatol / 3 to a point already
/// evaluated; stops when the bracket around the best point is within 2 tol1, or after
/// max_evaluations (then `converged` is false). The constants (xatol 1e-5, 500
/// evaluations, the start at the golden section of [a, b]) are those of scipy's
/// minimize_scalar(method="bounded"), which make_smoothing_spline uses on [0, n], so that
/// the same criterion gives the same lambda.
struct BrentMinimum {
  double x;
  double fx;
  int evaluations;
  bool converged;
};

template <class F>
BrentMinimum brent_bounded(F&& f, double a, double b, double xatol = 1e-5, int max_evaluations = 500) {
  const double sqrt_eps = std::sqrt(2.2e-16), golden = 0.5 * (3.0 - std::sqrt(5.0));
  // x: the best point so far; w: the second best; v: the previous w.
  double x = a + golden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  int evaluations = 1;
  double step = 0, previous_step = 0;  // the last step, and the one before it
  const auto sign = [](double s) { return s > 0 ? 1.0 : s < 0 ? -1.0 : 0.0; };
  double mid = 0.5 * (a + b), tol1 = sqrt_eps * std::abs(x) + xatol / 3, tol2 = 2 * tol1;
  while (std::abs(x - mid) > tol2 - 0.5 * (b - a)) {
    bool golden_step = true;
    if (std::abs(previous_step) > tol1) {
      // The parabola through (x, fx), (w, fw), (v, fv): its vertex at x + p / q.
      double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double older = previous_step;
      previous_step = step;
      // Accepted when it moves less than half the step before last and stays inside (a, b).
      if (std::abs(p) < std::abs(0.5 * q * older) && p > q * (a - x) && p < q * (b - x)) {
        step = p / q;
        const double u = x + step;
        if (u - a < tol2 || b - u < tol2) {
          const double s = sign(mid - x);
          step = tol1 * (s == 0 ? 1.0 : s);
        }
        golden_step = false;
      }
    }
    if (golden_step) {
      previous_step = x >= mid ? a - x : b - x;
      step = golden * previous_step;
    }
    const double s = sign(step);
    const double u = x + (s == 0 ? 1.0 : s) * std::max(std::abs(step), tol1);
    const double fu = f(u);
    ++evaluations;
    if (fu <= fx) {
      (u >= x ? a : b) = x;
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
    mid = 0.5 * (a + b);
    tol1 = sqrt_eps * std::abs(x) + xatol / 3;
    tol2 = 2 * tol1;
    if (evaluations >= max_evaluations) return {x, fx, evaluations, false};
  }
  return {x, fx, evaluations, true};
}

/// The clamped cubic B-spline of the natural cubic spline with values g_k and second
/// derivatives gamma_k at the breakpoints t_k (gamma zero at both ends). The Bézier inner
/// points of span k are b1 = g_k + (g_(k+1) - g_k) / 3 - h_k^2 (2 gamma_k + gamma_(k+1)) / 18
/// and b2 = g_(k+1) - (g_(k+1) - g_k) / 3 - h_k^2 (gamma_k + 2 gamma_(k+1)) / 18; they divide
/// the leg from control point k + 1 to k + 2 in the ratio h_(k-1) : h_k : h_(k+1) (h_(-1) =
/// h_(n-1) = 0) [Farin02, §8.2], so control point k + 1 is b1 - (h_(k-1) / h_k)(b2 - b1) of
/// span k, or b2 + (h_k / h_(k-1))(b2 - b1) of span k - 1: the one with the ratio <= 1 is
/// taken (no amplification of rounding where neighbouring steps differ widely).
template <class T, int D>
BSpline<T, D> natural_cubic_bspline(const std::vector<T>& t, const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>& g,
                                    const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>& gamma_interior) {
  const std::size_t n = t.size();
  const auto I = [](std::size_t i) { return static_cast<Eigen::Index>(i); };
  std::vector<T> h(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) h[k] = t[k + 1] - t[k];
  const auto gamma = [&](std::size_t k, int c) -> T { return k == 0 || k + 1 == n ? T(0) : gamma_interior(I(k - 1), c); };
  std::vector<Point<T, D>> b1(n - 1), b2(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    for (int c = 0; c < D; ++c) {
      const T g0 = g(I(k), c), g1 = g(I(k + 1), c), third = (g1 - g0) / 3, hh = h[k] * h[k] / 18;
      b1[k][c] = g0 + third - hh * (2 * gamma(k, c) + gamma(k + 1, c));
      b2[k][c] = g1 - third - hh * (gamma(k, c) + 2 * gamma(k + 1, c));
    }
  }
  std::vector<Point<T, D>> P(n + 2);
  for (int c = 0; c < D; ++c) {
    P[0][c] = g(0, c);
    P[n + 1][c] = g(I(n - 1), c);
  }
  P[1] = b1[0];
  P[n] = b2[n - 2];
  for (std::size_t k = 1; k + 1 < n; ++k) {  // control point k + 1, between spans k - 1 and k
    if (h[k - 1] <= h[k]) {
      P[k + 1] = b1[k] - (h[k - 1] / h[k]) * (b2[k] - b1[k]);
    } else {
      P[k + 1] = b2[k - 1] + (h[k] / h[k - 1]) * (b2[k - 1] - b1[k - 1]);
    }
  }
  std::vector<T> U(4, t.front());
  U.insert(U.end(), t.begin() + 1, t.end() - 1);
  U.insert(U.end(), 4, t.back());
  return BSpline<T, D>(3, std::move(U), std::move(P));
}

}  // namespace detail

namespace detail {

/// The smoothing spline's values g (n x d) and interior second derivatives (m x d) at its
/// lambda (given, or chosen by GCV: the criterion's value then in gcv), with the
/// coordinates as columns: the part of smoothing_spline that does not depend on the
/// dimension, compiled once per scalar type.
template <class T>
struct SmoothingSolution {
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> gamma, g;
  T lambda;
  T gcv;
};

/// smoothing_solution on values already in the frame (largest |y| in [0.5, 1), or all 0).
template <class T>
SmoothingSolution<T> smoothing_solution_unit(const std::vector<T>& t, const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>& y,
                                             std::optional<T> lambda, int max_evaluations) {
  ReinschSystem<T> sys(t, y);
  SmoothingSolution<T> out{{}, {}, T(0), std::numeric_limits<T>::quiet_NaN()};
  if (!lambda) {
    const auto criterion = [&](double l) { return static_cast<double>(gcv_criterion<T>(sys, static_cast<T>(l), y)); };
    const BrentMinimum best = brent_bounded(criterion, 0.0, static_cast<double>(y.rows()), 1e-5, max_evaluations);
    if (!best.converged || !std::isfinite(best.fx)) {
      throw NumericalError("the minimisation of the GCV criterion did not converge in " + std::to_string(best.evaluations) +
                           " evaluations (the limit for this many points): give smoothing as a number");
    }
    lambda = static_cast<T>(best.x);
    out.gcv = static_cast<T>(best.fx);
  }
  out.lambda = *lambda;
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> r;
  sys.solve(out.lambda, out.gamma, r, out.g);
  return out;
}

/// The solution for values y of any size: they are first scaled by 2^-e, e the exponent that brings the largest |y| into
/// [0.5, 1) (exact: a power of two), and g, gamma scaled back by 2^e, the criterion by
/// 2^(2e) (which may overflow or underflow there: it is reported, not used). Both terms of
/// the objective are quadratic in y, so lambda and GCV's minimiser do not depend on the
/// scale; without the frame the squared residuals underflowed at 1e-200 (GCV then chose
/// an almost straight fit) and overflowed at 1e160 (refused).
template <class T>
SmoothingSolution<T> smoothing_solution(const std::vector<T>& t, const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>& y_given,
                                        std::optional<T> lambda, int max_evaluations) {
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  const int e = y_given.size() > 0 ? detail::abs_exponent(T(y_given.cwiseAbs().maxCoeff())) : 0;
  const Matrix y = e == 0 ? y_given : Matrix(y_given.unaryExpr([e](T v) { return detail::times_pow2(v, -e); }));
  SmoothingSolution<T> out = smoothing_solution_unit<T>(t, y, lambda, max_evaluations);
  if (e != 0) {
    out.g = out.g.unaryExpr([e](T v) { return detail::times_pow2(v, e); });
    out.gamma = out.gamma.unaryExpr([e](T v) { return detail::times_pow2(v, e); });
    out.gcv = detail::times_pow2(out.gcv, 2 * e);
  }
  return out;
}

}  // namespace detail

/// The smoothing spline through the points Q at the parameters t (strictly increasing, at
/// least 2): the cubic spline minimising sum_k |Q_k - C(t_k)|^2 + lambda * integral over
/// [t_0, t_last] of |C''(t)|^2, knots at every parameter, which is the natural cubic spline
/// of Reinsch's system (detail::ReinschSystem) — scipy's make_smoothing_spline(t, y,
/// lam=lambda) for each coordinate, unit weights. lambda = 0 is natural cubic
/// interpolation; as lambda grows the curve tends to the least-squares line. With lambda
/// absent it is chosen by generalised cross-validation (detail::gcv_criterion, on the
/// stacked coordinates for d > 1) minimised by Brent's method over (0, n) as scipy does
/// (needs at least 3 points). Cost O(n d) per lambda (a banded QR), at most
/// max_evaluations lambdas for GCV (scipy's 500; typically 20 to 40). Errors: NumericalError when the
/// system is not numerically positive definite, or GCV's minimisation does not converge.
template <class T, int D>
SmoothingSpline<T, D> smoothing_spline(const std::vector<Point<T, D>>& Q, const std::vector<T>& t, std::optional<T> lambda,
                                       int max_evaluations = 500) {
  const std::size_t n = Q.size();
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> y(static_cast<Eigen::Index>(n), D);
  for (std::size_t k = 0; k < n; ++k)
    for (int c = 0; c < D; ++c) y(static_cast<Eigen::Index>(k), c) = Q[k][c];
  const detail::SmoothingSolution<T> s = detail::smoothing_solution<T>(t, y, lambda, max_evaluations);
  return {detail::natural_cubic_bspline<T, D>(t, s.g, s.gamma), s.lambda, s.gcv};
}

}  // namespace casteljau
