// Real roots of a polynomial in Bernstein form on [0, 1], by subdivision with the
// variation-diminishing property and a bracketed solve where one root is isolated.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/basis/de_casteljau.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

namespace detail {

template <class T>
int sign_of(T v) {
  return (v > 0) - (v < 0);
}

/// Sign changes in the coefficient sequence, zeros skipped. By Descartes' rule for the
/// Bernstein basis it bounds the number of roots in the open interval and has the same
/// parity [Farin02, 5.5; LaneRiesenfeld81].
template <class T>
int sign_variations(std::span<const T> c) {
  int v = 0, last = 0;
  for (T x : c) {
    const int s = sign_of(x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

/// The value at t in [0, 1] of the Bernstein form c in O(n) where that matters: past
/// degree 32 the Bernstein-Horner scheme [Farin02, 5.8; SchumakerVolk86], p(t) =
/// (..((c_0 u + C(n,1) x c_1) u + C(n,2) x^2 c_2) u + ...) with x = t, u = 1 - t, run on
/// the reversed form for t > 1/2 (so x <= 1/2). The term C(n,i) x^i comes from its own
/// recurrence (times x (n-i+1)/i) and is rescaled together with the sum by 2^-600 whenever
/// it passes 2^600, so nothing overflows at any degree (the result, a convex combination
/// of the c_i, is scaled back). Relative error about n eps of max |c|, against a few eps
/// for de Casteljau; up to degree 32, where O(n^2) is cheap, de Casteljau. Used to
/// locate roots, where only the sign of the value near the root matters.
template <class T>
T bernstein_value_fast(std::span<const T> c, T t) {
  const std::size_t m = c.size();
  if (m <= 33) return de_casteljau<T, T>(c, t);
  const bool rev = t > T(0.5);
  const T x = rev ? 1 - t : t, u = 1 - x;
  const std::size_t n = m - 1;
  auto at = [&](std::size_t i) { return rev ? c[n - i] : c[i]; };
  T term = 1, acc = at(0) * u;
  int scale = 0;  // acc and term are stored times 2^-scale
  for (std::size_t i = 1; i < n; ++i) {
    term *= x * static_cast<T>(n - i + 1) / static_cast<T>(i);
    acc = (acc + term * at(i)) * u;
    if (term > T(0x1p600)) {
      term = std::ldexp(term, -600);
      acc = std::ldexp(acc, -600);
      scale += 600;
    }
  }
  term *= x / static_cast<T>(n);
  return std::ldexp(acc + term * at(n), scale);
}

/// The single root of the Bernstein form c on (0, 1) given c[0] and c[n] of opposite
/// signs: the Illinois variant of regula falsi, with values from de Casteljau, ending at
/// a bracket of width <= 4 eps or a zero value. Converges superlinearly on simple roots.
/// Safeguard: when four steps have not halved the bracket, the next step bisects, so the
/// bracket halves at least every 5 steps and 50 halvings (1 -> 4 eps) take at most 250
/// steps; the limit of 256 is nearly tight (a root within 1e-30 of an end reached it), so
/// the bracket is then finished by plain bisection (at most 60 steps more): the result is
/// always a converged bracket. Cost O(n) per step past degree 32
/// (bernstein_value_fast), O(n^2) below.
template <class T>
T isolated_root(std::span<const T> c) {
  T a = 0, b = 1;
  T fa = c.front(), fb = c.back();
  int side = 0;
  T width_ref = 1;  // bracket width at the last checkpoint
  int since = 0;    // steps since the last checkpoint
  for (int it = 0; it < 256; ++it) {
    T x = (a * fb - b * fa) / (fb - fa);
    bool bisect = false;
    if (++since == 5) {
      bisect = b - a > width_ref / 2;
      width_ref = b - a;
      since = 0;
    }
    if (bisect || !(x > a && x < b)) x = a + (b - a) / 2;
    const T fx = bernstein_value_fast<T>(c, x);
    if (fx == 0) return x;
    if (sign_of(fx) == sign_of(fa)) {
      a = x;
      fa = fx;
      if (side == -1) fb /= 2;
      side = -1;
    } else {
      b = x;
      fb = fx;
      if (side == 1) fa /= 2;
      side = 1;
    }
    if (b - a <= 4 * std::numeric_limits<T>::epsilon()) return (a + b) / 2;
  }
  // The safeguard's count is tight (a root within 1e-30 of an end, approached by
  // Illinois steps that creep from the far side, took all 256): finish by bisection,
  // which halves the bracket every step and ends within 60 more.
  for (int it = 0; it < 64 && b - a > 4 * std::numeric_limits<T>::epsilon(); ++it) {
    const T x = a + (b - a) / 2;
    const T fx = bernstein_value_fast<T>(c, x);
    if (fx == 0) return x;
    if (sign_of(fx) == sign_of(fa)) {
      a = x;
    } else {
      b = x;
    }
  }
  return (a + b) / 2;
}

template <class T>
void bernstein_roots_rec(std::span<const T> c, T lo, T hi, int depth, std::vector<T>& out) {
  const int v = sign_variations(c);
  if (v == 0) return;
  const std::size_t n = c.size() - 1;
  if (v == 1 && c.front() != 0 && c.back() != 0) {
    out.push_back(lo + (hi - lo) * isolated_root(c));
    return;
  }
  // Several roots, or a root at an end of this piece: halve. The depth cap (2^-60 of the
  // original width) stops the subdivision at multiple roots, which are reported once: a
  // result, not a silent limit (roots closer than 2^-60 < merge are merged anyway).
  if (depth >= 60) {
    out.push_back((lo + hi) / 2);
    return;
  }
  std::vector<T> left(n + 1), right(n + 1);
  de_casteljau_split<T, T>(c, T(0.5), left, right);
  const T mid = (lo + hi) / 2;
  bernstein_roots_rec<T>(left, lo, mid, depth + 1, out);
  if (right.front() == 0) out.push_back(mid);
  bernstein_roots_rec<T>(right, mid, hi, depth + 1, out);
}

}  // namespace detail

/// The distinct real roots in [0, 1] of the polynomial with Bernstein coefficients c,
/// ascending. An identically zero polynomial (all coefficients 0) gives no roots: callers
/// that care test for it. Roots closer than `merge` (default 1e-10, well above the
/// solver's accuracy of a few eps on simple roots) are reported once: a multiple root
/// appears once, located to about eps^(1/m) for multiplicity m, as for any floating
/// point solver. A root of even multiplicity whose coefficients are rounded may vanish
/// altogether (the rounded polynomial need not touch zero); odd multiplicities keep their
/// sign change and are always found. Cost O(n^2) per isolated root plus O(n^2) per subdivision step.
/// Throws InvalidArgument("c[i]", ...) for a non-finite coefficient and NumericalError if
/// a bracketed solve does not converge (never observed; see detail::isolated_root).
template <class T>
std::vector<T> bernstein_roots(std::span<const T> c, T merge = T(1e-10)) {
  std::vector<T> out;
  require_finite_values(c, "c");
  // Identically zero (or empty): no roots, as documented (every t would be one).
  if (std::all_of(c.begin(), c.end(), [](T x) { return x == 0; })) return out;
  if (c.front() == 0) out.push_back(T(0));
  detail::bernstein_roots_rec<T>(c, T(0), T(1), 0, out);
  if (c.size() > 1 && c.back() == 0) out.push_back(T(1));
  std::sort(out.begin(), out.end());
  std::vector<T> merged;
  for (T r : out) {
    if (merged.empty() || r - merged.back() > merge) merged.push_back(r);
  }
  return merged;
}

/// A real root of a polynomial and its multiplicity m >= 1 (see bernstein_roots_with_multiplicity).
template <class T>
struct BernsteinRoot {
  T t;
  int multiplicity;
  friend bool operator==(const BernsteinRoot&, const BernsteinRoot&) = default;
};

/// The highest multiplicity bernstein_roots_with_multiplicity resolves: a root of
/// multiplicity above it is reported with this multiplicity (meaning "at least"). Each
/// level costs one more root isolation on a derivative.
inline constexpr int max_root_multiplicity = 4;

namespace detail {

/// |c|_inf, the scale of a Bernstein form (its values on [0, 1] are convex combinations).
template <class T>
T max_abs(std::span<const T> c) {
  T m = 0;
  for (T x : c) m = std::max(m, std::abs(x));
  return m;
}

template <class T>
std::vector<BernsteinRoot<T>> roots_with_multiplicity_rec(std::span<const T> c, T noise, int level) {
  std::vector<BernsteinRoot<T>> out;
  for (T r : bernstein_roots<T>(c)) out.push_back({r, 1});
  const std::size_t n = c.size() - 1;
  if (n < 2 || level + 1 >= max_root_multiplicity) return out;
  // The derivative n (c_{i+1} - c_i): a root of p of multiplicity m >= 2 is a root of p'
  // of multiplicity m - 1 at which p vanishes. Each coefficient adds 2 n noise.
  std::vector<T> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<T>(n) * (c[i + 1] - c[i]);
  const T dnoise = 2 * static_cast<T>(n) * (noise + std::numeric_limits<T>::epsilon() * max_abs<T>(c));
  if (max_abs<T>(d) <= dnoise) return out;  // p constant within its noise
  // de Casteljau's value error is below 2 n eps max|c| [Farin02, 3.1]; with the
  // coefficients' own noise, a smaller value is zero within what the data determine.
  const T bound = noise + 2 * static_cast<T>(n + 1) * std::numeric_limits<T>::epsilon() * max_abs<T>(c);
  // Past degree 32 an O(n) estimate first (bernstein_value_fast, error below 16 (n + 1)
  // eps max|c|): a value clearly above the bound is not a multiple root, and the O(n^2)
  // de Casteljau check runs only on the few that may be (at degree 2000 it was most of
  // the time of features()).
  const T margin = 32 * static_cast<T>(n + 1) * std::numeric_limits<T>::epsilon() * max_abs<T>(c);
  for (const auto& dr : roots_with_multiplicity_rec<T>(d, dnoise, level + 1)) {
    if (std::abs(bernstein_value_fast<T>(c, dr.t)) > bound + margin) continue;  // (a NaN estimate is checked)
    if (!(std::abs(de_casteljau<T, T>(c, dr.t)) <= bound)) continue;
    const int m = std::min(dr.multiplicity + 1, max_root_multiplicity);
    // The cluster radius: near a root of multiplicity m, p ~ p^(m)(r) (t - r)^m / m!, so
    // p stays below its bound within (m! bound / |p^(m)(r)|)^(1/m) of r; rounding can put
    // sign changes anywhere in there (about eps^(1/m): 6e-6 for a triple root). Twice
    // that, at least 1e-9 and at most 1e-3 (of the interval).
    std::vector<T> dm(c.begin(), c.end());
    T factorial = 1;
    for (int j = 0; j < m && dm.size() > 1; ++j) {
      const std::size_t k = dm.size() - 1;
      for (std::size_t i = 0; i < k; ++i) dm[i] = static_cast<T>(k) * (dm[i + 1] - dm[i]);
      dm.pop_back();
      factorial *= static_cast<T>(j + 1);
    }
    const T pm = std::abs(de_casteljau<T, T>(std::span<const T>(dm), dr.t));
    const T radius = pm > 0 ? std::clamp(2 * std::pow(factorial * bound / pm, T(1) / static_cast<T>(m)), T(1e-9), T(1e-3)) : T(1e-3);
    // Merge the cluster of sign-change roots around it (a rounded multiple root splits
    // into nearby simple ones) into one root at the derivative's root, which is located
    // better: at the deepest level the root is simple and found to a few eps.
    std::erase_if(out, [&](const BernsteinRoot<T>& r) { return std::abs(r.t - dr.t) <= radius; });
    out.push_back({dr.t, m});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  return out;
}

}  // namespace detail

/// The real roots in [a, b] of the polynomial whose Bernstein coefficients c are given
/// on [a, b] (p(x) = sum c_i B(i,n)((x - a)/(b - a))), ascending, each with its
/// multiplicity: all real roots, including those of even multiplicity that have no sign
/// change (which bernstein_roots alone can miss once the coefficients are rounded).
///
/// Method: the sign-change roots of bernstein_roots (subdivision with Descartes' rule
/// for the Bernstein basis, then a safeguarded Illinois solve [Farin02, 5.5;
/// LaneRiesenfeld81]); then, recursively, the roots of the derivative at which p is zero
/// within its evaluation error bound (noise + 2 (n+1) eps |c|_inf) are roots of p of
/// multiplicity one more than in p'. The sign-change roots of p near such a root (within
/// twice the radius where the Taylor term p^(m)(r) (t - r)^m / m! stays below the bound,
/// clamped to [1e-9, 1e-3]) are the split images of the same rounded multiple root and
/// are replaced by it.
///
/// `noise` is the absolute error of the coefficients themselves (0 when they are exact,
/// the default); values of p below the bound are treated as zero.
///
/// Accuracy (in units of b - a): a simple root to a few eps (the bracket ends at 4 eps)
/// times the condition number 1 / |p'|; a root of multiplicity m is located as the
/// simple root of p^(m-1), so to a few eps times the conditioning of that root.
/// Multiplicity is a statement about the rounded data: distinct roots so close that p
/// stays within its noise of 0 between them are reported as one multiple root, and a
/// near-touch within the noise as a double root. Multiplicities above
/// max_root_multiplicity are reported as max_root_multiplicity. An identically zero p
/// (all |c_i| <= noise) has no isolated roots: the result is empty (callers test for it
/// with bernstein_negligible). Cost: up to max_root_multiplicity root isolations (p and
/// its derivatives). Throws InvalidArgument("c[i]", ...) for a non-finite coefficient,
/// ("interval", ...) unless a < b are finite, NumericalError if a solve does not converge.
template <class T>
std::vector<BernsteinRoot<T>> bernstein_roots_with_multiplicity(std::span<const T> c, Interval<T> ab = {T(0), T(1)},
                                                                T noise = T(0)) {
  require_finite_values(c, "c");
  require_finite(ab.lo, "interval.lo");
  require_finite(ab.hi, "interval.hi");
  if (!(ab.lo < ab.hi)) throw InvalidArgument("interval", "needs lo < hi");
  std::vector<BernsteinRoot<T>> out;
  if (c.empty() || detail::max_abs<T>(c) <= noise) return out;
  out = detail::roots_with_multiplicity_rec<T>(c, noise, 0);
  for (auto& r : out) r.t = (r.t == 0) ? ab.lo : (r.t == 1) ? ab.hi : ab.lo + (ab.hi - ab.lo) * r.t;
  return out;
}

/// Whether the Bernstein form c is zero within `noise` (every |c_i| <= noise): then the
/// polynomial is identically zero as far as the data determine (|p| <= |c|_inf on [0, 1]).
template <class T>
bool bernstein_negligible(std::span<const T> c, T noise) {
  return detail::max_abs<T>(c) <= noise;
}

/// The product of two Bernstein forms f (degree m) and g (degree n) as one of degree m+n:
/// h_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) f_i g_j [Farin02, 5.7]. The bracketed
/// factors are hypergeometric weights (they sum to 1 over i for each k), computed by
/// detail::hypergeometric_row without forming binomials, which would overflow a double
/// past m + n = 1029. Each h_k is a convex combination of the products f_i g_j: its
/// error is a few (min(m, n) + 2) eps of max |f_i g_j|. Throws InvalidArgument("f" /
/// "g", ...) for an empty form. Cost O((m + n) min(m, n)).
template <class T>
std::vector<T> bernstein_product(std::span<const T> f, std::span<const T> g) {
  if (f.empty()) throw InvalidArgument("f", "needs at least one coefficient");
  if (g.empty()) throw InvalidArgument("g", "needs at least one coefficient");
  const int m = static_cast<int>(f.size()) - 1, n = static_cast<int>(g.size()) - 1;
  std::vector<T> h(static_cast<std::size_t>(m + n) + 1, T(0));
  std::vector<T> weights(static_cast<std::size_t>(std::min(m, n)) + 1);
  for (int k = 0; k <= m + n; ++k) {
    const int lo = std::max(0, k - n), hi = std::min(m, k);
    detail::hypergeometric_row<T>(m + n, m, k, std::span<T>(weights.data(), static_cast<std::size_t>(hi - lo + 1)));
    T s = 0;
    for (int i = lo; i <= hi; ++i)
      s += weights[static_cast<std::size_t>(i - lo)] * f[static_cast<std::size_t>(i)] * g[static_cast<std::size_t>(k - i)];
    h[static_cast<std::size_t>(k)] = s;
  }
  return h;
}

}  // namespace casteljau
