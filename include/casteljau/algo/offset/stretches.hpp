// The offset's stretches (phase of algo/offset.hpp): one exact piece's point and
// derivatives without allocation (PieceForm), its cusps (zeros of the speed) and the
// offset's cusps (where 1 - d kappa changes sign or touches zero) that cut it into
// stretches on which the offset is smooth (stretches(), with the curve's limit tangents at
// their ends: limit_tangent), and the Source of the offset over one stretch or a run of
// them across the offset's cusps (offset_source, stretch_source). Depends on common.hpp
// and curves/ (the pieces' own evaluation for rational pieces).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/offset/common.hpp"
#include "casteljau/curves/bezier.hpp"

namespace casteljau::detail::offset {

/// A piece's point and first two derivatives: for a polynomial piece from its control
/// points and its first two hodographs, computed once (form_point, no allocation); for a
/// rational piece through the curve's own evaluation.
template <class T, class Piece>
struct PieceForm {
  static constexpr bool polynomial = std::is_same_v<Piece, Bezier<T, 2>>;
  std::conditional_t<polynomial, std::monostate, std::optional<Piece>> c;  ///< a rational piece itself
  std::vector<Point<T, 2>> P, H1, H2;  ///< a polynomial piece above degree 3: its points and hodographs
  bool cubic = false;                  ///< degree <= 3: Horner in the power basis (CubicForm's), no vectors
  std::array<Vector<T, 2>, 4> pc{};
  explicit PieceForm(const Piece& piece) {
    if constexpr (polynomial) {
      const auto& Q = piece.points();
      if (Q.size() <= 4) {
        cubic = true, pc = power_cubic(Q.data(), Q.size());
        return;
      }
      P = Q;
      const std::size_t n = P.size() - 1;
      for (std::size_t k = 0; k < n; ++k) H1.push_back(Point<T, 2>::from_vector(T(n) * (P[k + 1] - P[k])));
      for (std::size_t k = 0; k + 1 < n; ++k) H2.push_back(Point<T, 2>::from_vector(T(n - 1) * (H1[k + 1] - H1[k])));
    } else {
      c = piece;
    }
  }
  /// An upper bound of |C''| on [0, 1] (polynomial pieces: the second hodograph's control
  /// points, its convex hull; for degree <= 3 the line 2 c2 + 6 c3 t at its ends).
  T second_bound() const {
    T b = 0;
    if (cubic) return std::max(length(pc[2] * T(2)), length(pc[2] * T(2) + pc[3] * T(6)));
    for (const auto& q : H2) b = std::max(b, length(q.to_vector()));
    return b;
  }
  Point<T, 2> at(T t) const {
    if constexpr (polynomial) {
      if (cubic) {
        Point<T, 2> out;
        for (int k = 0; k < 2; ++k) out[k] = pc[0][k] + t * (pc[1][k] + t * (pc[2][k] + t * pc[3][k]));
        return out;
      }
      return form_point(P, t);
    } else {
      return (*c)(t);
    }
  }
  Vector<T, 2> d1(T t) const {
    if constexpr (polynomial) {
      if (cubic) {
        Vector<T, 2> v;
        for (int k = 0; k < 2; ++k) v[k] = pc[1][k] + t * (2 * pc[2][k] + 3 * t * pc[3][k]);
        return v;
      }
      return form_point(H1, t).to_vector();
    } else {
      return c->derivative_at(t, 1);
    }
  }
  Vector<T, 2> d2(T t) const {
    if constexpr (polynomial) {
      if (cubic) {
        Vector<T, 2> v;
        for (int k = 0; k < 2; ++k) v[k] = 2 * pc[2][k] + 6 * t * pc[3][k];
        return v;
      }
      return H2.empty() ? Vector<T, 2>{} : form_point(H2, t).to_vector();
    } else {
      return c->derivative_at(t, 2);
    }
  }
};

/// The unit tangent of a piece at its own parameter t, the limit from inside [lo, hi]
/// where the first derivative vanishes: the first non-zero derivative of order k (up to
/// 6), signed (-1)^(k-1) at the right end of the stretch (C'(t) ~ C^(k)(t0) (t - t0)^(k-1)
/// / (k-1)!). `tiny`: the size below which a derivative counts as zero.
template <class T, class Piece>
Vector<T, 2> limit_tangent(const Piece& c, T t, bool from_left, T tiny) {
  for (int k = 1; k <= 6; ++k) {
    const Vector<T, 2> v = c.derivative_at(t, k);
    if (length(v) > tiny) return unit(v) * ((from_left && k % 2 == 0) ? T(-1) : T(1));
  }
  return {};
}

/// The offset's stretches of one piece (own parameter [0, 1]) split at the piece's cusps
/// (zero speed) and the offset's cusps (1 - d kappa = 0, or a touch of it), each with the
/// curve's tangents at its ends.
template <class T>
struct Stretch {
  T lo, hi;
  bool reversed;
  Vector<T, 2> t_lo, t_hi;  // the curve's unit tangents (limits) at the ends
};

/// n values on the stack up to N, on the heap beyond (the grids of stretches()).
template <class T, std::size_t N>
struct Scratch {
  std::array<T, N> small;
  std::vector<T> large;
  T* p = nullptr;
  explicit Scratch(std::size_t n) {
    if (n > N) large.resize(n), p = large.data();
    else p = small.data();
  }
  T& operator[](int i) { return p[i]; }
  const T& operator[](int i) const { return p[i]; }
};

template <class T, class Piece>
std::vector<Stretch<T>> stretches(const Piece& c, T d, T tiny) {
  const int n = c.degree();
  const int M = std::max(64, 16 * (n + 1));
  const PieceForm<T, Piece> form(c);
  const auto speed = [&](T t) { return length(form.d1(t)); };
  const auto g = [&](T t) {  // 1 - d kappa
    const Vector<T, 2> d1 = form.d1(t), d2 = form.d2(t);
    const T s = length(d1);
    return 1 - d * cross(d1, d2) / (s * s * s);
  };
  Scratch<T, 129> grid(static_cast<std::size_t>(M) + 1), sp(static_cast<std::size_t>(M) + 1);
  T top = 0;
  for (int j = 0; j <= M; ++j) grid[j] = T(j) / M, sp[j] = speed(grid[j]), top = std::max(top, sp[j]);
  // A zero of the speed within one grid step of t makes |C'(t)| at most the step times
  // max |C''|, which the second hodograph's control points bound (convex hull): a local
  // minimum of the sampled speed above that is no cusp and is not refined (polynomial
  // pieces; a rational piece's every minimum is refined).
  T near_zero = std::numeric_limits<T>::infinity();
  if constexpr (PieceForm<T, Piece>::polynomial) {
    const T b2 = form.second_bound();
    near_zero = (b2 / T(M)) * (1 + T(1e-6)) + tiny;
  }
  // The piece's interior cusps: local minima of the speed below 1e-6 of its largest.
  std::vector<T> cusps{T(0)};
  for (int j = 1; j < M; ++j) {
    if (sp[j] <= sp[j - 1] && sp[j] <= sp[j + 1] && sp[j] <= near_zero) {
      T lo = grid[j - 1], hi = grid[j + 1];
      const T rr = T(0.6180339887498948482045868343656381L);
      for (int k = 0; k < 60; ++k) {
        const T x1 = hi - rr * (hi - lo), x2 = lo + rr * (hi - lo);
        if (speed(x1) <= speed(x2)) hi = x2; else lo = x1;
      }
      const T t = (lo + hi) / 2;
      if (speed(t) <= T(1e-6) * top && t > grid[1] / 4 && t < 1 - grid[1] / 4) cusps.push_back(t);
    }
  }
  cusps.push_back(T(1));
  // A cubic piece (or one of lower degree) whose 1 - d kappa is surely positive has no
  // cusp of the offset, and its grid of 1 - d kappa is not needed (most pieces: on the
  // convex side of the curve d kappa <= 0; elsewhere, mostly, |d| is well under the
  // radius of curvature). d kappa = d cross(C', C'') / |C'|^3, whose numerator is the
  // quadratic 2 cross(c1, c2) + 6 cross(c1, c3) t + 6 cross(c2, c3) t^2 in the power basis
  // (its largest value on [0, 1] exactly: the ends and the vertex), whose denominator is
  // at least the cube of a lower bound of the speed: the grid's smallest speed less half a
  // step times max |C''| (the speed is Lipschitz with that constant).
  bool positive = false;
  if constexpr (PieceForm<T, Piece>::polynomial) {
    if (form.cubic && d != 0) {
      const auto& pc = form.pc;
      const T k0 = 2 * cross(pc[1], pc[2]), k1 = 6 * cross(pc[1], pc[3]), k2 = 6 * cross(pc[2], pc[3]);
      const auto num = [&](T t) { return d * (k0 + t * (k1 + t * k2)); };
      T top_num = std::max(num(0), num(1));
      if (k2 != 0) {
        const T tv = -k1 / (2 * k2);
        if (tv > 0 && tv < 1) top_num = std::max(top_num, num(tv));
      }
      T low = std::numeric_limits<T>::infinity();
      for (int j = 0; j <= M; ++j) low = std::min(low, sp[j]);
      low -= form.second_bound() / (2 * T(M));
      positive = top_num <= 0 || (low > 0 && top_num < T(0.5) * low * low * low);
    }
  }
  std::vector<Stretch<T>> out;
  for (std::size_t i = 0; i + 1 < cusps.size(); ++i) {
    const T a = cusps[i], b = cusps[i + 1];
    // The offset's cusps on (a, b): sign changes of g on a grid, and near-zero minima of |g|.
    std::vector<T> cuts{a};
    if (d != 0 && !positive) {
      const int K = M;
      const T h = (b - a) / K;
      Scratch<T, 129> gv(static_cast<std::size_t>(K) + 1);
      for (int j = 0; j <= K; ++j) {
        const T t = a + h * T(j) + (j == 0 ? h / 1024 : j == K ? -h / 1024 : T(0));  // off the cusps, where g is undefined
        gv[j] = g(t);
      }
      for (int j = 0; j < K; ++j) {
        const T t0 = a + h * T(j), t1 = j + 1 == K ? b : a + h * T(j + 1);
        if ((gv[j] < 0) != (gv[j + 1] < 0) && std::isfinite(gv[j]) && std::isfinite(gv[j + 1])) {
          T lo = std::max(t0, a + h / 1024), hi = std::min(t1, b - h / 1024);
          const bool neg_lo = g(lo) < 0;
          for (int k = 0; k < 80 && lo < hi; ++k) {
            const T mid = (lo + hi) / 2;
            if (!(mid > lo && mid < hi)) break;  // adjacent doubles: done
            if ((g(mid) < 0) == neg_lo) lo = mid; else hi = mid;
          }
          cuts.push_back((lo + hi) / 2);
        } else if (j > 0 && std::abs(gv[j]) <= std::abs(gv[j - 1]) && std::abs(gv[j]) <= std::abs(gv[j + 1]) &&
                   std::abs(gv[j]) <= 2 * std::max(std::abs(gv[j - 1] - gv[j]), std::abs(gv[j + 1] - gv[j])) + T(1e-9)) {
          // A touch of zero (a double root t* within half a step of the sample: g about
          // c (t - t*)^2) leaves |g| at the sample at most a quarter of its rise to either
          // neighbour; minima far above that (most minima of |1 - d kappa|) are not refined.
          T lo = a + h * T(j - 1), hi = a + h * T(j + 1);
          const T rr = T(0.6180339887498948482045868343656381L);
          for (int k = 0; k < 60; ++k) {
            const T x1 = hi - rr * (hi - lo), x2 = lo + rr * (hi - lo);
            if (std::abs(g(x1)) <= std::abs(g(x2))) hi = x2; else lo = x1;
          }
          const T t = (lo + hi) / 2;
          if (std::abs(g(t)) <= T(1e-9)) cuts.push_back(t);  // |d| touches the radius of curvature
        }
      }
      std::sort(cuts.begin(), cuts.end());
    }
    cuts.push_back(b);
    // One cusp found twice (a sign change and a touch of 1 - d kappa a rounding apart):
    // cuts within 64 ulps of 1 merged (a stretch of no length, which only the projections
    // of the fallback measure could measure, at length).
    {
      std::vector<T> merged{cuts.front()};
      for (std::size_t k = 1; k < cuts.size(); ++k) {
        if (cuts[k] - merged.back() > tiny) merged.push_back(cuts[k]);
        else if (k + 1 == cuts.size()) merged.back() = cuts[k];
      }
      if (merged.size() == 1) merged.push_back(b);
      cuts = std::move(merged);
    }
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const T lo = cuts[k], hi = cuts[k + 1];
      if (!(hi > lo)) continue;
      const T mid = (lo + hi) / 2;
      // At a cusp of the piece the speed is zero only to the accuracy of its minimisation:
      // derivatives below 1e-5 of the largest speed count as zero there.
      const T zero_lo = (k == 0 && i > 0) ? T(1e-5) * top : tiny;
      const T zero_hi = (k + 2 == cuts.size() && i + 2 < cusps.size()) ? T(1e-5) * top : tiny;
      // The tangent from the first derivative where it is not zero (the piece's form, no
      // allocation), else its limit from the higher derivatives.
      const auto tangent_at = [&](T t, bool from_left, T zero) {
        const Vector<T, 2> v = form.d1(t);
        return length(v) > zero ? unit(v) : limit_tangent<T>(c, t, from_left, zero);
      };
      Stretch<T> s{lo, hi, d != 0 && g(mid) < 0, tangent_at(lo, false, zero_lo), tangent_at(hi, true, zero_hi)};
      out.push_back(s);
    }
  }
  return out;
}

/// The Source of the offset of piece c over the stretches first..last (one, or a run of
/// them) as one smooth curve across the offset's cusps between them (where 1 - d kappa
/// changes sign or touches zero): O(t) = C(t) + d N(t) is as smooth in t as C there (its
/// velocity (1 - d kappa) C' only passes through zero), so a cubic can follow it across a
/// cusp (near one it is a semicubical cusp, (t^2, t^3) to leading order, which a cubic
/// represents). The direction of travel is sign(1 - d kappa) T (constant over one
/// stretch); the cusps are the stretches' ends between them (Source::cusps: parts across
/// them are measured by parametric and partner_distance).
template <class T, class Piece>
Source<T> offset_source(const Piece& c, const Stretch<T>* first, const Stretch<T>* last, T d) {
  // One shared state, so that each std::function holds a pointer only (no allocation of
  // its own: the small-object buffer).
  struct State {
    PieceForm<T, Piece> form;
    T lo, hi, d;
    Vector<T, 2> t_lo, t_hi;
    T sign_lo, sign_hi;
    bool varying;  // a run across cusps: the sign of 1 - d kappa at each t
    Vector<T, 2> tan(T t) const {
      if (t == lo) return t_lo;
      if (t == hi) return t_hi;
      const Vector<T, 2> v = unit(form.d1(t));
      return length(v) > 0 ? v : (t - lo < hi - t ? t_lo : t_hi);
    }
    T sign(T t) const {
      if (!varying || t == lo) return sign_lo;
      if (t == hi) return sign_hi;
      const Vector<T, 2> d1 = form.d1(t), d2 = form.d2(t);
      const T sp = length(d1);
      return sp > 0 && 1 - d * cross(d1, d2) / (sp * sp * sp) < 0 ? T(-1) : T(1);
    }
  };
  const auto st = std::make_shared<const State>(State{PieceForm<T, Piece>(c), first->lo, last->hi, d, first->t_lo, last->t_hi,
                                                      first->reversed ? T(-1) : T(1), last->reversed ? T(-1) : T(1), first != last});
  Source<T> src;
  src.point = [st](T t) { return st->form.at(t) + left(st->tan(t)) * st->d; };
  src.velocity = [st](T t) {
    const Vector<T, 2> d1 = st->form.d1(t), d2 = st->form.d2(t);
    const T sp = length(d1);
    if (!(sp > 0)) return Vector<T, 2>{};
    return d1 * (1 - st->d * cross(d1, d2) / (sp * sp * sp));
  };
  src.tangent = [st](T t) { return st->tan(t) * st->sign(t); };
  src.frame = [st](T t) {
    const Vector<T, 2> u = st->tan(t);
    return std::pair{st->form.at(t) + left(u) * st->d, u * st->sign(t)};
  };
  src.lo = st->lo, src.hi = st->hi;
  src.reversed = first->reversed;
  for (const Stretch<T>* k = first; k != last; ++k) src.cusps.push_back(k->hi);
  return src;
}

/// The Source of the offset of piece c over one stretch.
template <class T, class Piece>
Source<T> stretch_source(const Piece& c, const Stretch<T>& s, T d) {
  return offset_source<T>(c, &s, &s, d);
}

}  // namespace casteljau::detail::offset
