// Degree reduction of B-splines and NURBS (reduce_spline): the lower-degree spline on the
// same breaks fitted to the curve by weighted least squares, then refined towards the
// min-max fit by Lawson's reweighting, measured next to [PT97] A5.11 and the least kept.
// The fits use flat coordinates (a run-time count E per point) so that one instantiation
// per scalar serves every dimension and both the Cartesian and the homogeneous fits.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "casteljau/algo/deviation.hpp"
#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/knot_form.hpp"
#include "casteljau/basis/quadrature.hpp"
#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/nurbs.hpp"

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

/// A degree-q spline on knots W fitted to a curve on its pieces: the problem
/// reduce_spline poses. Pieces j = 0.. of the curve's domain: [lo_j, hi_j], the original's span
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
  std::vector<T> nodes;  // the K Chebyshev points on [-1, 1] (set_samples), computed once

  /// K samples per piece at the Chebyshev points of the first kind.
  void set_samples(int k) {
    K = k;
    nodes.resize(static_cast<std::size_t>(K));
    for (std::size_t j = 0; j < nodes.size(); ++j)
      nodes[j] = std::cos(std::numbers::pi_v<T> * static_cast<T>(2 * j + 1) / static_cast<T>(2 * K));
  }

  [[nodiscard]] std::size_t samples() const { return lo.size() * static_cast<std::size_t>(K); }
  [[nodiscard]] std::size_t piece(std::size_t i) const { return i / static_cast<std::size_t>(K); }
  [[nodiscard]] T sample(std::size_t i) const {
    const std::size_t j = i / static_cast<std::size_t>(K), k = i % static_cast<std::size_t>(K);
    const T mid = (lo[j] + hi[j]) / 2, half = (hi[j] - lo[j]) / 2;
    return mid + half * nodes[k];
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

namespace casteljau {

/// A curve type reduce_spline takes: a BSpline or a Nurbs (any scalar, any dimension).
template <class C>
concept SplineCurveType = std::is_same_v<C, BSpline<typename C::Scalar, C::dimension>> ||
                          std::is_same_v<C, Nurbs<typename C::Scalar, C::dimension>>;

/// The result of reduce_spline: the curve of degree p - r and its largest distance from
/// the original at equal parameters over the domain, measured (max_deviation: dense
/// samples and a local search, to about 1e-9 relative at double; a value from below).
template <class C>
struct SplineReduction {
  C curve;
  typename C::Scalar max_error = 0;
};

namespace detail {

/// The distinct knots of a B-spline or NURBS inside its domain: its pieces' breaks.
template <SplineCurveType C>
std::vector<typename C::Scalar> spline_breaks(const C& x) {
  const auto dom = x.domain();
  std::vector<typename C::Scalar> b;
  for (const auto& run : x.knot_vector().distinct())
    if (run.value >= dom.lo && run.value <= dom.hi) b.push_back(run.value);
  return b;
}

/// The mean of the curve over its domain, (1 / |domain|) times the integral of C (the
/// best constant in L2), by adaptive Gauss-Kronrod per knot interval to 1e-14 relative at
/// double (target_at: the same number of digits at other scalars).
template <class C>
Point<typename C::Scalar, C::dimension> spline_mean(const C& x, const std::vector<typename C::Scalar>& breaks) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  const Interval<T> dom = x.domain();
  const T rel = target_at<T>(1e-14), abs = std::max(static_cast<T>(1e-300), std::numeric_limits<T>::min());
  Point<T, D> m;
  for (int k = 0; k < D; ++k) {
    T s = 0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      s += integrate_adaptive<T>([&](T u) { return x(u)[k]; }, breaks[i], breaks[i + 1], rel, abs).value;
    }
    m[k] = s / (dom.hi - dom.lo);
  }
  return m;
}

/// The largest |a(u) - b(u)| at samples + 1 equally spaced u per interval of `breaks`
/// (a value from below of max_deviation's), stopping at the first above stop_above.
template <class T, class A, class B>
T sampled_deviation(const A& a, const B& b, const std::vector<T>& breaks, int samples, T stop_above) {
  T top = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    for (int j = 0; j <= samples; ++j) {
      const T u = j == samples ? breaks[i + 1] : breaks[i] + (breaks[i + 1] - breaks[i]) * static_cast<T>(j) / static_cast<T>(samples);
      top = std::max(top, norm(a(u) - b(u)));
      if (top > stop_above) return top;
    }
  }
  return top;
}

/// The centre of the control points' box: the fits work about it, so that translating
/// the curve changes nothing but rounding.
template <class T, int D>
Point<T, D> control_centre(const std::vector<Point<T, D>>& P) {
  Point<T, D> lo = P.front(), hi = P.front();
  for (const auto& q : P)
    for (int d = 0; d < D; ++d) {
      lo[d] = std::min(lo[d], q[d]);
      hi[d] = std::max(hi[d], q[d]);
    }
  Point<T, D> c;
  for (int d = 0; d < D; ++d) c[d] = lo[d] / 2 + hi[d] / 2;
  return c;
}

/// A B-spline's points about c, or a NURBS' homogeneous points (w (P - c), w), flat.
template <class T, int D>
FlatSpline<T> flat_about(const BSpline<T, D>& x, const Point<T, D>& c) {
  FlatSpline<T> f{x.degree(), D, x.knots(), {}};
  for (const auto& q : x.points())
    for (int d = 0; d < D; ++d) f.P.push_back(q[d] - c[d]);
  return f;
}
template <class T, int D>
FlatSpline<T> flat_about(const Nurbs<T, D>& x, const Point<T, D>& c) {
  FlatSpline<T> f{x.degree(), D + 1, x.knots(), {}};
  for (const auto& h : x.homogeneous().points()) {
    for (int d = 0; d < D; ++d) f.P.push_back(h[d] - h[D] * c[d]);
    f.P.push_back(h[D]);
  }
  return f;
}

/// The fitting problem of the reduction by r of the degree-p spline f: the knots of
/// reduced_knots, the pieces of f's domain, K = 2 p + 4 samples a piece, and the fixed
/// control points (the domain's ends, both limits at a jump) with the values
/// value(s, u, out) gives: f's piece on its span s at u, as the fit's E numbers.
template <class T, class Value>
SplineFit<T> spline_fit_problem(const FlatSpline<T>& f, int r, int E, Value&& value) {
  const std::span<const T> U(f.U);
  SplineFit<T> g;
  g.q = f.p - r;
  g.E = E;
  g.set_samples(2 * f.p + 4);
  g.W = reduced_knots<T>(U, f.p, r);
  for (const std::size_t s : nonempty_spans<T>(U, f.p)) {
    g.lo.push_back(U[s]);
    g.hi.push_back(U[s + 1]);
    g.source_span.push_back(s);
    g.fit_span.push_back(find_span<T>(std::span<const T>(g.W), g.q, U[s] / 2 + U[s + 1] / 2));
  }
  const std::size_t n = g.W.size() - static_cast<std::size_t>(g.q) - 1, e = static_cast<std::size_t>(E);
  g.fixed.assign(n, 0);
  g.C0.assign(n * e, T(0));
  const auto fix = [&](std::size_t i, std::size_t s, T u) {
    g.fixed[i] = 1;
    value(s, u, std::span<T>(g.C0).subspan(i * e, e));
  };
  fix(0, g.source_span.front(), g.lo.front());
  fix(n - 1, g.source_span.back(), g.hi.back());
  for (std::size_t j = 1; j < g.lo.size(); ++j) {
    const T x = g.lo[j];
    if (knot_multiplicity<T>(U, x) != static_cast<std::size_t>(f.p) + 1) continue;
    const std::size_t k = static_cast<std::size_t>(std::lower_bound(g.W.begin(), g.W.end(), x) - g.W.begin());
    fix(k - 1, g.source_span[j - 1], x);  // the left limit ends the piece before the jump
    fix(k, g.source_span[j], x);          // the right limit starts the next
  }
  return g;
}

/// The curve's values at the fit's samples, E numbers each, when they take at most 4e6
/// numbers (else none: the fit evaluates the curve at each use).
template <class T, class Value>
std::vector<T> sample_values(const SplineFit<T>& g, Value&& value) {
  std::vector<T> Y;
  const std::size_t E = static_cast<std::size_t>(g.E);
  if (static_cast<double>(g.samples()) * static_cast<double>(E) > 4e6) return Y;
  Y.resize(g.samples() * E);
  for (std::size_t i = 0; i < g.samples(); ++i) value(g.source_span[g.piece(i)], g.sample(i), std::span<T>(Y).subspan(i * E, E));
  return Y;
}

/// How many Lawson steps the fit may take: about 3e7 operations in all, none past 2e6
/// samples (the weights and errors are kept per sample), at most 30.
template <class T>
int lawson_steps(const SplineFit<T>& g, int p, int source_coordinates, bool cached) {
  const double N = static_cast<double>(g.samples());
  if (N > 2e6) return 0;
  const double per_step =
      N * ((g.q + 1.0) * (g.q + 1.0) * (g.E + 2.0) + (cached ? 0.0 : 2.0 * (p + 1.0) * (p + 1.0) * source_coordinates));
  return static_cast<int>(std::min(30.0, std::floor(3e7 / per_step)));
}

/// The candidate reductions of a bspline or nurbs x by r (p - r >= 1). The fits of
/// lawson_fits on the knots of reduced_knots, the end points (and both limits at a jump)
/// kept: for a bspline of its points; for a nurbs of the Cartesian curve by a polynomial
/// spline (weights 1: always possible, whatever the weights) and of the homogeneous points
/// (kept when every fitted weight is > 0). Then r steps of [PT97] A5.11 (reduce_degree
/// with no tolerance to meet: every knot removal taken; left out where it fails, e.g. a
/// NURBS weight <= 0), and the fits' first (least-squares) solves. In this order, the
/// likely best first; none depends on a tolerance. Each with a value from below of its
/// max error (the fits' largest sampled error; 0 for A5.11).
template <SplineCurveType C>
std::vector<std::pair<C, typename C::Scalar>> spline_reductions(const C& x, int r) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  constexpr bool rational = std::is_same_v<C, Nurbs<T, D>>;
  std::vector<std::pair<C, T>> out, rest;  // the fits' best, then A5.11 and the fits' first solves
  std::optional<C> steps;
  try {
    C y = x;
    for (int j = 0; j < r; ++j) y = y.reduce_degree(std::numeric_limits<T>::max()).curve;
    steps = std::move(y);
  } catch (const InvalidArgument&) {
  } catch (const NumericalError&) {
  }
  const int p = x.degree(), q = p - r;
  const Point<T, D> c = control_centre<T, D>(x.points());
  const FlatSpline<T> f = flat_about<T, D>(x, c);
  const std::size_t S = static_cast<std::size_t>(f.E);
  std::vector<T> N(static_cast<std::size_t>(p) + 1), h(S), y(S);
  // The curve's value on a piece, as f holds it (points, or homogeneous points)...
  const auto source = [&](std::size_t s, T u, std::span<T> v) { piece_value<T>(f, s, u, std::span<T>(N), v); };
  // ... and as a Cartesian point about c.
  const auto cartesian = [&](std::size_t s, T u, std::span<T> v) {
    source(s, u, std::span<T>(h));
    for (int d = 0; d < D; ++d) v[static_cast<std::size_t>(d)] = rational ? h[static_cast<std::size_t>(d)] / h[D] : h[static_cast<std::size_t>(d)];
  };
  // |a - b| over the first D numbers (the Cartesian coordinates; b / b[D] and a / a[D]
  // when `projective`), scaled by the largest difference so that no square under- or
  // overflows at any scale.
  const auto distance_to = [&](std::span<const T> a, std::span<const T> b, bool projective = false) {
    Vector<T, D> diff;
    for (std::size_t d = 0; d < static_cast<std::size_t>(D); ++d) {
      diff[static_cast<int>(d)] = projective ? a[d] / a[D] - b[d] / b[D] : a[d] - b[d];
    }
    return norm(diff);
  };
  std::vector<T> point(static_cast<std::size_t>(D));
  // A clamped end's point is the curve's end exactly (the fits' fixed values are that
  // point about c, which adding c back may round; A5.11 divides by the weight again).
  const std::vector<T>& U = x.knots();
  const std::size_t n = x.points().size();
  const auto exact_ends = [&](std::vector<Point<T, D>>& Q) {
    if (U.front() == U[static_cast<std::size_t>(p)]) Q.front() = x.points().front();
    if (U.back() == U[n]) Q.back() = x.points().back();
  };
  // The polynomial fit (a bspline's, or a nurbs' with weights 1).
  {
    const SplineFit<T> g = spline_fit_problem<T>(f, r, D, cartesian);
    const std::vector<T> Y = sample_values<T>(g, cartesian);
    const auto target = [&](std::size_t i, std::span<T> v) {
      if (Y.empty()) return cartesian(g.source_span[g.piece(i)], g.sample(i), v);
      std::copy_n(Y.begin() + static_cast<std::ptrdiff_t>(i * D), D, v.begin());
    };
    const auto error = [&](std::size_t i, std::span<const T> v) {
      target(i, std::span<T>(point));
      return distance_to(v, point);
    };
    const auto fits = lawson_fits<T>(g, target, error, lawson_steps<T>(g, p, static_cast<int>(S), !Y.empty()));
    for (std::size_t k = 0; k < fits.size(); ++k) {
      std::vector<Point<T, D>> Q(g.fixed.size());
      for (std::size_t i = 0; i < Q.size(); ++i)
        for (int d = 0; d < D; ++d) Q[i][d] = fits[k].C[i * D + static_cast<std::size_t>(d)] + c[d];
      exact_ends(Q);
      if constexpr (rational) {
        (k == 0 ? out : rest).emplace_back(C(q, g.W, std::move(Q), std::vector<T>(g.fixed.size(), T(1))), fits[k].sampled_error);
      } else {
        (k == 0 ? out : rest).emplace_back(C(q, g.W, std::move(Q)), fits[k].sampled_error);
      }
    }
  }
  if constexpr (rational) {
    // The homogeneous fit, its error the Cartesian distance (infinite where the fitted
    // weight is <= 0).
    const SplineFit<T> g = spline_fit_problem<T>(f, r, D + 1, source);
    const std::vector<T> Y = sample_values<T>(g, source);
    const auto target = [&](std::size_t i, std::span<T> v) {
      if (Y.empty()) return source(g.source_span[g.piece(i)], g.sample(i), v);
      std::copy_n(Y.begin() + static_cast<std::ptrdiff_t>(i * S), S, v.begin());
    };
    const auto error = [&](std::size_t i, std::span<const T> v) {
      if (!(v[D] > 0)) return std::numeric_limits<T>::infinity();
      target(i, std::span<T>(y));
      return distance_to(v, y, true);
    };
    const auto fits = lawson_fits<T>(g, target, error, lawson_steps<T>(g, p, static_cast<int>(S), !Y.empty()));
    for (std::size_t k = 0; k < fits.size(); ++k) {
      const std::vector<T>& P = fits[k].C;
      std::vector<Point<T, D>> Q(g.fixed.size());
      std::vector<T> w(g.fixed.size());
      bool positive = true;
      for (std::size_t i = 0; i < Q.size(); ++i) {
        w[i] = P[i * S + D];
        positive = positive && w[i] > 0 && std::isfinite(w[i]);
        for (int d = 0; d < D; ++d) Q[i][d] = P[i * S + static_cast<std::size_t>(d)] / w[i] + c[d];
      }
      if (!positive) continue;
      exact_ends(Q);
      bool finite = true;
      for (const auto& pt : Q) finite = finite && all_finite_point(pt);
      if (finite) (k == 0 ? out : rest).emplace_back(C(q, g.W, std::move(Q), std::move(w)), fits[k].sampled_error);
    }
  }
  if (steps) {
    std::vector<Point<T, D>> Q = steps->points();
    exact_ends(Q);
    if constexpr (rational) {
      out.emplace_back(C(steps->degree(), steps->knots(), std::move(Q), steps->weights()), T(0));
    } else {
      out.emplace_back(C(steps->degree(), steps->knots(), std::move(Q)), T(0));
    }
  }
  for (auto& z : rest) out.push_back(std::move(z));
  return out;
}

}  // namespace detail

/// The cost of reduce_spline(x, r) in units of about 0.065 us (user CPU of the machine it
/// was calibrated on): pieces x ((p + 1)^3, four times that for a NURBS, + 1000). Measuring
/// the answer evaluates both curves 32 (p + 1) times per piece at O(p^2) each, and the
/// candidates' fits cost about as much: (p + 1)^3 a piece, four times that for a NURBS
/// (its rational fit: measured 3.4x at degree 200, 4.8x at 300); the 1000 a piece is the
/// measure's local searches (65 us a quadratic piece). It does not depend on r. The
/// command line refuses above 3e7 (about 2 s: a B-spline of degree 300 in one piece
/// 1.8 s, 20,000 quadratic pieces 1.3 s).
template <SplineCurveType C>
double reduce_spline_work(const C& x) {
  constexpr bool rational = std::is_same_v<C, Nurbs<typename C::Scalar, C::dimension>>;
  const double pieces = static_cast<double>(detail::spline_breaks(x).size() - 1);
  return pieces * ((rational ? 4 : 1) * std::pow(x.degree() + 1.0, 3) + 1000);
}

/// The degree reduction of a B-spline or NURBS x of degree p by r (1 <= r <= p): the best
/// of several candidates, with its measured error. None of them depends on a tolerance:
/// the caller accepts or refuses the answer on its max_error.
/// - To degree q = p - r >= 1 the answer keeps the domain and its breaks: clamped at both
///   ends, each break inside the domain of multiplicity m with multiplicity max(m - r, 1)
///   (detail::reduced_knots; the original continuity where degree q allows it), a jump
///   (m = p + 1) q + 1 times; the domain's end points (and both limits at a jump) kept.
///   The candidates: the fit of the degree-q spline on those knots at 2 p + 4 Chebyshev
///   points per knot interval, weighted least squares then up to 30 Lawson steps towards
///   the min-max fit (detail::lawson_fits; the step of least sampled error, and the
///   first); for a NURBS that fit twice, of the Cartesian curve by a polynomial spline
///   (weights 1: always possible) and of the homogeneous points (kept when every fitted
///   weight is > 0); r steps of [PT97] A5.11 (x.reduce_degree; left out where it fails).
///   They are ranked by their largest distance at 4 (p + 1) + 1 equally spaced parameters
///   per knot interval (the breaks included), the least kept (the first of equals).
/// - To degree 0: the constant mean of the curve over its domain (the L2 best constant,
///   one constant also for a curve that jumps).
/// The answer's max_error is then measured by max_deviation at 32 (p + 1) samples per
/// knot interval. An elevated curve comes back with its own knots, up to rounding.
/// Throws InvalidArgument("times", ...) for r outside 1..p, NumericalError when no
/// candidate lies at a finite distance from x (coordinates near the overflow threshold)
/// or the mean's integral fails. Cost: reduce_spline_work(x) units.
template <SplineCurveType C>
SplineReduction<C> reduce_spline(const C& x, int times) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  constexpr bool rational = std::is_same_v<C, Nurbs<T, D>>;
  const int p = x.degree();
  if (times < 1 || times > p) {
    throw InvalidArgument("times", "must be in 1..p = " + std::to_string(p) + " (the curve's degree), got " + std::to_string(times));
  }
  const int m = p - times;
  const std::vector<T> breaks = detail::spline_breaks(x);
  C reduced = x;
  bool measure = true;
  if (m == 0) {
    const Interval<T> dom = x.domain();
    const Point<T, D> mean = detail::spline_mean(x, breaks);
    if constexpr (rational) {
      reduced = C(0, {dom.lo, dom.hi}, {mean}, {T(1)});
    } else {
      reduced = C(0, {dom.lo, dom.hi}, {mean});
    }
  } else {
    T coarse = std::numeric_limits<T>::infinity();
    for (auto& [y, below] : detail::spline_reductions(x, times)) {
      if (below > coarse) continue;  // a sampled error above the best's already
      const T e = detail::sampled_deviation<T>(x, y, breaks, 4 * (p + 1), coarse);
      if (e < coarse) {
        coarse = e;
        reduced = std::move(y);
      }
    }
    measure = coarse < std::numeric_limits<T>::infinity();
  }
  // 32 (p + 1) samples per knot interval: a peak of the difference of two degree-p
  // polynomials is wider than that spacing.
  const T err = measure ? max_deviation<T>(x, reduced, breaks, 32 * (p + 1)) : std::numeric_limits<T>::infinity();
  if (!std::isfinite(err)) {
    throw NumericalError("no reduction from degree " + std::to_string(p) + " to " + std::to_string(m) +
                         " with a finite distance to the curve was found (coordinates near the largest " +
                         (std::is_same_v<T, double> ? "double" : "value of the scalar type") + "?)");
  }
  return {std::move(reduced), err};
}

}  // namespace casteljau
