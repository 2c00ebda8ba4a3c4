// The first derivative of a rational Bézier curve and the bivector R' ^ R'' (its
// curvature's numerator) on [0, 1] in forms that do not cancel, for weights of any spread;
// the derivatives of order >= 2 over pairs of control points (differences only).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "casteljau/basis/binomial.hpp"
#include "casteljau/basis/extrapolate.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau::detail {

/// The largest degree that rational_jet serves (its cost is O(n^2) pairs and O(n^3)
/// triples per call); above it the callers keep the homogeneous quotient rule.
inline constexpr int rational_jet_max_degree = 24;

/// A parameter t in [0, 1] as m 2^e (m in [0.5, 1), or m = 0 for t = 0), so that t may be
/// far below the smallest double (the arc length integrates in log t down to 2^-1200),
/// with s = 1 - t (rounded; 1 when t < 2^-60).
template <class T>
struct JetParameter {
  T m = 0;
  int e = 0;
  T s = 1;
  static JetParameter of(T t) {
    JetParameter p;
    p.m = std::frexp(t, &p.e);
    p.s = 1 - t;
    return p;
  }
};

/// R' = r 2^er and the components of R' ^ R'' (pairs a < b of coordinates in
/// lexicographic order; in the plane the one component x'y'' - y'x'') = b 2^eb, in the
/// units of the points as given. r and b are of moderate size (no overflow), the
/// exponents carry the scale.
template <class T, int D>
struct RationalJet {
  Vector<T, D> r{};
  int er = 0;
  std::array<T, static_cast<std::size_t>(D * (D - 1) / 2)> b{};
  int eb = 0;
};

/// R'(t) and, with `second`, R' ^ R'' of the rational Bézier curve with points P and
/// weights w > 0 (degree n <= rational_jet_max_degree) at t in [0, 1], from
///   R' = sum_(i<j) (j-i) C(n,i) C(n,j) w_i w_j t^(i+j-1) s^(2n-i-j-1) (P_j - P_i) / W^2,
///   R' ^ R'' = sum_(i<j<k) (j-i)(k-i)(k-j) C(n,i) C(n,j) C(n,k) w_i w_j w_k
///              t^(i+j+k-3) s^(3n-i-j-k-3) (P_j - P_i) ^ (P_k - P_i) / W^3,
/// s = 1 - t, W = sum_i C(n,i) w_i t^i s^(n-i): the homogeneous numerators A'W - AW' and
/// det(H, H', H'') expanded over pairs and triples of control points, whose coefficients
/// are the Wronskians of the Bernstein polynomials (positive on [0, 1]; [Floater92] for
/// the first). Every coefficient is a positive product, so nothing cancels but the
/// control points' own differences: the quotient rule on the homogeneous derivatives
/// loses R' entirely where the curve hugs its control polygon (weights 1, 1e30, 1: R'(1/2)
/// ~ 1e-30 from terms of size 1), and the part of R'' normal to the curve where it hugs
/// its chord (weights 1, 1e-100, 1: curvature 1e-100 from terms of size 1). Every product
/// is kept as a mantissa and an exponent, so that weights spanning the whole range of T
/// and t down to 2^-1200 neither over- nor underflow. Error: a few eps (n^2 terms) of the
/// sum of the terms' sizes. Cost O(n^2 D) (O(n^3 D^2) with `second`).
template <class T, int D>
RationalJet<T, D> rational_jet(std::span<const Point<T, D>> P, std::span<const T> w, const JetParameter<T>& t, bool second) {
  const int n = static_cast<int>(P.size()) - 1;
  RationalJet<T, D> out;
  if (n < 1) return out;
  const int e0 = scale_exponent<Point<T, D>>(P);
  // Powers of t and s up to 3n, as mantissa (in [0.5, 1), or 0) and exponent.
  const int K = 3 * n;
  std::vector<T> mt(static_cast<std::size_t>(K) + 1), ms(mt.size());
  std::vector<int> et(mt.size()), es(mt.size());
  int es1 = 0;
  const T ms1 = std::frexp(t.s, &es1);
  mt[0] = ms[0] = 1;
  et[0] = es[0] = 0;
  for (std::size_t k = 1; k < mt.size(); ++k) {
    int x = 0;
    mt[k] = std::frexp(mt[k - 1] * t.m, &x);
    et[k] = et[k - 1] + t.e + x;
    ms[k] = std::frexp(ms[k - 1] * ms1, &x);
    es[k] = es[k - 1] + es1 + x;
  }
  std::vector<T> mw(P.size()), C(P.size());
  std::vector<int> ew(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    mw[i] = std::frexp(w[i], &ew[i]);
    C[i] = binomial<T>(n, static_cast<int>(i));
  }
  // A product as a normalised mantissa and an exponent; exponent INT_MIN for zero.
  constexpr int none = std::numeric_limits<int>::min();
  auto norm_term = [&](T m, int e, int& x) {
    if (m == 0) {
      x = none;
      return T(0);
    }
    int y = 0;
    const T r = std::frexp(m, &y);
    x = e + y;
    return r;
  };
  // W = What 2^E.
  std::vector<T> wm(P.size());
  std::vector<int> wx(P.size());
  int E = none;
  for (int i = 0; i <= n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    wm[u] = norm_term(C[u] * mw[u] * mt[u] * ms[static_cast<std::size_t>(n - i)], ew[u] + et[u] + es[static_cast<std::size_t>(n - i)], wx[u]);
    E = std::max(E, wx[u]);
  }
  T What = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (wx[i] != none) What += std::ldexp(wm[i], wx[i] - E);
  // Points scaled by 2^-e0 (largest coordinate in [0.5, 1)): their differences never overflow.
  std::vector<Point<T, D>> Q(P.size());
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int d = 0; d < D; ++d) Q[i][d] = std::ldexp(P[i][d], -e0);
  // Pairs.
  {
    std::vector<T> m;
    std::vector<int> x;
    int M = none;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j <= n; ++j) {
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
        const auto kt = static_cast<std::size_t>(i + j - 1), ks = static_cast<std::size_t>(2 * n - i - j - 1);
        int y = 0;
        m.push_back(norm_term(static_cast<T>(j - i) * C[a] * C[b] * mw[a] * mw[b] * mt[kt] * ms[ks], ew[a] + ew[b] + et[kt] + es[ks], y));
        x.push_back(y);
        M = std::max(M, y);
      }
    std::size_t q = 0;
    Vector<T, D> acc{};
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j <= n; ++j, ++q)
        if (x[q] != none) acc += std::ldexp(m[q], x[q] - M) * (Q[static_cast<std::size_t>(j)] - Q[static_cast<std::size_t>(i)]);
    out.r = acc / (What * What);
    out.er = M == none ? 0 : M - 2 * E + e0;
  }
  if (!second || n < 2 || D < 2) return out;
  // Triples.
  std::vector<T> m;
  std::vector<int> x;
  int M = none;
  for (int i = 0; i < n - 1; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k <= n; ++k) {
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j), c = static_cast<std::size_t>(k);
        const auto kt = static_cast<std::size_t>(i + j + k - 3), ks = static_cast<std::size_t>(3 * n - i - j - k - 3);
        int y = 0;
        m.push_back(norm_term(static_cast<T>((j - i) * (k - i) * (k - j)) * C[a] * C[b] * C[c] * mw[a] * mw[b] * mw[c] * mt[kt] * ms[ks],
                              ew[a] + ew[b] + ew[c] + et[kt] + es[ks], y));
        x.push_back(y);
        M = std::max(M, y);
      }
  std::size_t q = 0;
  for (int i = 0; i < n - 1; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k <= n; ++k, ++q) {
        if (x[q] == none) continue;
        const T f = std::ldexp(m[q], x[q] - M);
        const auto u = Q[static_cast<std::size_t>(j)] - Q[static_cast<std::size_t>(i)];
        const auto v = Q[static_cast<std::size_t>(k)] - Q[static_cast<std::size_t>(i)];
        std::size_t c = 0;
        for (int a = 0; a < D; ++a)
          for (int b = a + 1; b < D; ++b, ++c) out.b[c] += f * (u[a] * v[b] - u[b] * v[a]);
      }
  for (T& v : out.b) v /= What * What * What;
  out.eb = M == none ? 0 : M - 3 * E + 2 * e0;
  return out;
}

/// R^(k) (k >= 1) of a rational curve R = sum_i w_i N_i P_i / W from its weighted basis
/// at a parameter: rows[m][i] = w_i N_i^(m) / W for m = 0..k (W = sum_i w_i N_i; rows[0]
/// is rho_i = w_i N_i / W, which sums to 1), and the control points P_i, as
///   R^(k) = sum_(i<j) g_ij^(k) (P_j - P_i),   g_ij^(k) = rho_i rho_j^(k) - rho_j rho_i^(k)
/// (sum_i rho_i = 1 and sum_i rho_i^(k) = 0 antisymmetrise sum_i rho_i^(k) P_i over pairs,
/// so that only the points' differences appear). Leibniz on rho_i W = w_i N_i gives
/// rho^(k) = rows[k] - sum_(m=1..k) C(k,m) omega_m rho^(k-m), omega_m = W^(m) / W =
/// sum_i rows[m][i]; in the pairs' combinations the m = k term cancels exactly, leaving
///   g^(k) = (rho_i rows[k]_j - rho_j rows[k]_i) - sum_(m=1..k-1) C(k,m) omega_m g^(k-m),
/// a recursion on the pairs' scalars alone: g^(1) = rho_i rows[1]_j - rho_j rows[1]_i,
/// g^(2) = (rho_i rows[2]_j - rho_j rows[2]_i) - 2 omega_1 g^(1) (the quotient rule's
/// (A'' W - A W'') / W^2 - 2 W' (A' W - A W') / W^3 over pairs). Where the curve hugs its
/// control polygon (weights 1, 1e30, 1) R^(k)(1/2) is of size 1/w and so are these
/// terms, where the quotient rule subtracts terms of size 1 (it gave 0 for R'' and R''').
/// The points are halved before their differences (no overflow). Cost O(k^2 n^2 + n^2 D)
/// for n + 1 basis functions.
template <class T, int D>
Vector<T, D> pair_derivative(std::span<const Point<T, D>> P, std::span<const std::vector<T>> rows, int k) {
  const std::size_t n = P.size(), K = static_cast<std::size_t>(k);
  const std::size_t pairs = n * (n - 1) / 2;
  std::vector<T> omega(K + 1, T(0));
  for (std::size_t m = 1; m <= K; ++m)
    for (T x : rows[m]) omega[m] += x;
  // g[l * pairs + q]: g^(l) of the q-th pair (i < j, lexicographic).
  std::vector<T> g((K + 1) * pairs, T(0));
  const std::vector<T>& a = rows[0];
  for (std::size_t l = 1; l <= K; ++l) {
    const std::vector<T>& r = rows[l];
    std::size_t q = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j, ++q) {
        T f = a[i] * r[j] - r[i] * a[j];
        for (std::size_t m = 1; m < l; ++m) f -= binomial<T>(static_cast<int>(l), static_cast<int>(m)) * omega[m] * g[(l - m) * pairs + q];
        g[l * pairs + q] = f;
      }
  }
  Vector<T, D> v{};
  std::size_t q = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j, ++q) {
      const T f = g[K * pairs + q];
      if (f == 0) continue;
      Vector<T, D> d;
      for (int c = 0; c < D; ++c) d[c] = P[j][c] / 2 - P[i][c] / 2;
      v += f * d;
    }
  return T(2) * v;
}

/// Whether positive weights spread by more than 2^20 (largest over smallest): where the
/// quotient rule starts to lose the second derivative of a curve hugging its control
/// polygon. Below it the quotient rule is kept, so that ordinary rational curves (circles,
/// conics) give the values they always gave.
template <class T>
bool extreme_weight_spread(std::span<const T> w) {
  if (w.empty()) return false;
  const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
  return *hi > T(1048576) * *lo;
}

/// R^(k)(t) (k >= 1) of the rational Bézier curve with points P and weights w > 0 at t in
/// [0, 1] (pair_derivative on the Bernstein basis: B_i^(m) = n! / (n - m)!
/// sum_(l=0..m) (-1)^l C(m, l) B^(n-m)_(i-m+l), zero for m > n). Weights as normalised
/// (the largest in [0.5, 1)). Cost O(k^2 n^2 + k n^2).
template <class T, int D>
Vector<T, D> rational_pair_derivative(std::span<const Point<T, D>> P, std::span<const T> w, T t, int k) {
  const int n = static_cast<int>(P.size()) - 1;
  const T s = 1 - t;
  auto bern = [&](int m, int i) -> T {
    if (i < 0 || i > m) return 0;
    return binomial<T>(m, i) * std::pow(t, i) * std::pow(s, m - i);
  };
  std::vector<std::vector<T>> rows(static_cast<std::size_t>(k) + 1, std::vector<T>(P.size(), T(0)));
  T W = 0;
  for (int i = 0; i <= n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    rows[0][u] = w[u] * bern(n, i);
    W += rows[0][u];
  }
  T fall = 1;  // n! / (n - m)!
  for (int m = 1; m <= std::min(k, n); ++m) {
    fall *= static_cast<T>(n - m + 1);
    for (int i = 0; i <= n; ++i) {
      T sum = bern(n - m, i - m);
      for (int l = 1; l <= m; ++l) {
        const T c = binomial<T>(m, l);
        sum += (l % 2 ? -c : c) * bern(n - m, i - m + l);
      }
      rows[static_cast<std::size_t>(m)][static_cast<std::size_t>(i)] = w[static_cast<std::size_t>(i)] * (fall * sum);
    }
  }
  for (auto& r : rows)
    for (T& x : r) x /= W;
  return pair_derivative<T, D>(P, std::span<const std::vector<T>>(rows), k);
}

/// Curvature from a jet: (x'y'' - y'x'') / |R'|^3 in the plane (signed), |R' ^ R''| /
/// |R'|^3 otherwise (0 in R^1); std::nullopt where R' = 0. Infinity when it overflows.
template <class T, int D>
std::optional<T> jet_curvature(const RationalJet<T, D>& j) {
  const T speed = norm(j.r);
  if (!(speed > 0)) return std::nullopt;
  if constexpr (D == 1) {
    return T(0);
  } else {
    T num = 0;
    if constexpr (D == 2) {
      num = j.b[0];
    } else {
      for (T v : j.b) num = std::hypot(num, v);
    }
    return std::ldexp(num / speed / speed / speed, j.eb - 3 * j.er);
  }
}

}  // namespace casteljau::detail
