// Algorithms on B-splines as plain data (KnotForm: degree, knots, points of any point
// type, e.g. homogeneous ones), beside the knot operations of knot_ops.hpp: the Bézier
// points of a span by blossoming, insertion checks, refinement, splitting, re-knotting of
// the ends, knot removal on a sliding window, the outer knots for unclamping, and degree
// reduction [PT97, chapter 5; Ramshaw87]. BSpline and Nurbs (curves/bspline.hpp,
// curves/nurbs.hpp) and the surfaces (per row) wrap them with validation; and degree
// elevation (the spans' Bézier points elevated, joined, knots removed back).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/basis/bernstein.hpp"
#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/knot_ops.hpp"
#include "casteljau/basis/knot_vector.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau::detail {

/// The Bézier control points of span s: the blossoms b(a^(p-j), b^j), j = 0..p, with
/// [a, b] = [U_s, U_{s+1}] [Ramshaw87; Farin02, 8.4], by two de Boor triangles instead of
/// p + 1 separate blossoms: de Boor's algorithm at a on the p + 1 local points gives, as
/// the last point of each level r, g_{p-r} = b(a^r, U_{s+1}..U_{s+p-r}) (the points of the
/// knots a^p, U_{s+1}..U_{s+p}: a inserted up to multiplicity p); de Boor's algorithm at b
/// on those gives b(a^(p-j), b^j) as the first point of level j. Each step is a convex
/// combination as in evaluation; exact up to rounding (the same polynomial). Cost p^2 + p
/// combinations of points (O(p^3) as separate blossoms: a minute for 2,700 spans of degree
/// 300).
template <class V, class T>
std::vector<V> span_bezier_points(std::span<const T> U, int p, std::size_t s, std::span<const V> P) {
  const auto n = static_cast<std::size_t>(p) + 1;
  const std::size_t first = s - static_cast<std::size_t>(p);  // P_first..P_s act on the span
  std::vector<V> d(P.begin() + static_cast<std::ptrdiff_t>(first), P.begin() + static_cast<std::ptrdiff_t>(s) + 1);
  std::vector<V> g(n);
  g[n - 1] = d[n - 1];
  const T a = U[s], b = U[s + 1];
  for (int r = 1; r <= p; ++r) {  // de Boor at a (de_boor_blossom's loop), keeping d[p]
    for (int j = p; j >= r; --j) {
      const std::size_t i = first + static_cast<std::size_t>(j);
      const T alpha = (a - U[i]) / (U[i + static_cast<std::size_t>(p + 1 - r)] - U[i]);
      d[static_cast<std::size_t>(j)] = lerp(d[static_cast<std::size_t>(j) - 1], d[static_cast<std::size_t>(j)], alpha);
    }
    g[static_cast<std::size_t>(p - r)] = d[n - 1];
  }
  // g_m on the knots w = (a^p, U_{s+1}..U_{s+p}): de Boor at b on [w_p, w_{p+1}] = [a, b],
  // w_m = a for m <= p, w_{m+p+1-r} = U_{s+m+1-r}; after level r, g[r] is final.
  for (int r = 1; r <= p; ++r) {
    for (int m = p; m > r; --m) {  // m = r has alpha 1 (U_{s+1} = b): g[r] stays
      const T alpha = (b - a) / (U[s + static_cast<std::size_t>(m + 1 - r)] - a);
      g[static_cast<std::size_t>(m)] = lerp(g[static_cast<std::size_t>(m) - 1], g[static_cast<std::size_t>(m)], alpha);
    }
  }
  return g;
}

/// The non-empty spans s = p..n-1 (U_s < U_{s+1}) of a valid knot vector.
template <class T>
std::vector<std::size_t> nonempty_spans(std::span<const T> U, int p) {
  std::vector<std::size_t> spans;
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  for (std::size_t s = static_cast<std::size_t>(p); s < n; ++s) {
    if (U[s] < U[s + 1]) spans.push_back(s);
  }
  return spans;
}

template <class V>
void require_representable(const V& v, double u, const char* what) {
  for (int d = 0; d < V::dimension; ++d) {
    if (!std::isfinite(v[d])) {
      throw InvalidArgument("t", std::string(what) + " at t = " + format_number(u) + " is not representable (overflow)");
    }
  }
}

/// Checks that u may be inserted `times` more times into the knots U of degree p: u
/// finite and in the domain [U_p, U_n] (InvalidArgument "knot"), times >= 1 and the
/// multiplicity afterwards at most p + 1 (InvalidArgument "times"): insertion up to p + 1
/// makes a break, where the curve may jump afterwards (it does not: the same curve).
template <class T>
void check_insertion(std::span<const T> U, int p, T u, int times) {
  require_finite(u, "knot");
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  const T a = U[static_cast<std::size_t>(p)], b = U[n];
  if (u < a || u > b) {
    throw InvalidArgument("knot", "a knot to insert must lie in the domain [" + format_number(a) + ", " + format_number(b) +
                                      "], got " + format_number(u));
  }
  if (times < 1) throw InvalidArgument("times", "insertion count must be >= 1, got " + std::to_string(times));
  const std::size_t s = knot_multiplicity<T>(U, u);
  if (s + static_cast<std::size_t>(times) > static_cast<std::size_t>(p) + 1) {
    throw InvalidArgument("times", "knot " + format_number(u) + " has multiplicity " + std::to_string(s) + "; inserting it " +
                                       (times == 1 ? std::string("once more") : std::to_string(times) + " more times") +
                                       " would exceed p + 1 = " + std::to_string(p + 1) + " (the degree plus one)");
  }
}

/// f with u inserted `times` times (checked as check_insertion says).
template <class T, class V>
KnotForm<T, V> insert_knot(KnotForm<T, V> f, T u, int times) {
  check_insertion<T>(f.U, f.p, u, times);
  for (int j = 0; j < times; ++j) f = insert_knot_once(f, u);
  return f;
}

/// f with the sorted knots X inserted (each in the domain, multiplicities at most p + 1
/// after; InvalidArgument naming "knots[j]" of X otherwise, for a multiplicity the first
/// copy that goes over p + 1).
template <class T, class V>
KnotForm<T, V> refine(const KnotForm<T, V>& f, std::span<const T> X) {
  const std::size_t n = f.U.size() - static_cast<std::size_t>(f.p) - 1;
  for (std::size_t j = 0; j < X.size(); ++j) {
    const std::string where = "knots[" + std::to_string(j) + "]";
    require_finite(X[j], where);
    if (j > 0 && X[j] < X[j - 1]) throw InvalidArgument(where, "knots to insert must be sorted");
    if (X[j] < f.U[static_cast<std::size_t>(f.p)] || X[j] > f.U[n]) {
      throw InvalidArgument(where, "a knot to insert must lie in the domain, got " + format_number(X[j]));
    }
    // The copies of X[j] so far (X is sorted): the error names the copy that goes over.
    std::size_t before = 0;
    while (before < j && X[j - 1 - before] == X[j]) ++before;
    if (knot_multiplicity<T>(f.U, X[j]) + before + 1 > static_cast<std::size_t>(f.p) + 1) {
      const std::size_t s = knot_multiplicity<T>(f.U, X[j]) + knot_multiplicity<T>(X, X[j]);
      throw InvalidArgument(where, "knot " + format_number(X[j]) + " would have multiplicity " + std::to_string(s) +
                                       ", more than p + 1 = " + std::to_string(f.p + 1) + " (the degree plus one)");
    }
  }
  return refine_knots<T, V>(f, X);
}

/// The halves of f at u strictly inside the domain (InvalidArgument "t" otherwise): u is
/// inserted up to multiplicity p [PT97, §5.3: splitting by knot insertion], the left half
/// keeps the knots up to u plus one more u (clamped at u), the right half one u plus the
/// rest. Both keep their parameter: left on [U_p, u], right on [u, U_n]. At a break of
/// multiplicity p + 1 (where the curve may jump) the knots and points part there as they
/// are: the left half ends at the left limit, the right half starts at the right one.
template <class T, class V>
std::pair<KnotForm<T, V>, KnotForm<T, V>> split(const KnotForm<T, V>& f, T u) {
  require_finite(u, "t");
  const std::size_t n = f.U.size() - static_cast<std::size_t>(f.p) - 1;
  const T a = f.U[static_cast<std::size_t>(f.p)], b = f.U[n];
  if (!(u > a && u < b)) {
    throw InvalidArgument("t", "a B-spline splits at a parameter strictly inside its domain (" + format_number(a) + ", " +
                                   format_number(b) + "), got " + format_number(u));
  }
  const std::size_t s = knot_multiplicity<T>(f.U, u);
  const std::size_t p = static_cast<std::size_t>(f.p);
  if (s == p + 1) {
    const std::size_t j0 = static_cast<std::size_t>(std::lower_bound(f.U.begin(), f.U.end(), u) - f.U.begin());
    const auto J = static_cast<std::ptrdiff_t>(j0);
    return {KnotForm<T, V>{f.p, std::vector<T>(f.U.begin(), f.U.begin() + J + f.p + 1), std::vector<V>(f.P.begin(), f.P.begin() + J)},
            KnotForm<T, V>{f.p, std::vector<T>(f.U.begin() + J, f.U.end()), std::vector<V>(f.P.begin() + J, f.P.end())}};
  }
  KnotForm<T, V> g = f;
  for (std::size_t j = s; j < p; ++j) g = insert_knot_once(g, u);
  const std::size_t j0 = static_cast<std::size_t>(std::lower_bound(g.U.begin(), g.U.end(), u) - g.U.begin());
  KnotForm<T, V> left{f.p, std::vector<T>(g.U.begin(), g.U.begin() + static_cast<std::ptrdiff_t>(j0 + p)),
                      std::vector<V>(g.P.begin(), g.P.begin() + static_cast<std::ptrdiff_t>(j0))};
  left.U.push_back(u);
  KnotForm<T, V> right{f.p, {u}, std::vector<V>(g.P.begin() + static_cast<std::ptrdiff_t>(j0 - 1), g.P.end())};
  right.U.insert(right.U.end(), g.U.begin() + static_cast<std::ptrdiff_t>(j0), g.U.end());
  return {std::move(left), std::move(right)};
}

/// The same curve with new outer knots: L (p knots <= U_p) before the domain knots
/// U_p..U_n and R (p knots >= U_n) after them; the p - 1 points at each end whose knot
/// windows change are the blossoms of the end pieces (reblossom_ends). Clamping
/// (L = U_p repeated) and unclamping use it [PT97, §12.2 does the same by knot insertion
/// and its inverse]. The caller validates the result (a BSpline constructor).
template <class T, class V>
KnotForm<T, V> with_outer_knots(const KnotForm<T, V>& f, const std::vector<T>& L, const std::vector<T>& R) {
  const std::size_t p = static_cast<std::size_t>(f.p);
  if (p == 0) return f;  // degree 0: no outer knots (U_0 = U_p, U_n = U_(n+p))
  const std::size_t n = f.P.size();
  std::vector<T> Ub(L);
  Ub.insert(Ub.end(), f.U.begin() + static_cast<std::ptrdiff_t>(p), f.U.begin() + static_cast<std::ptrdiff_t>(n) + 1);
  Ub.insert(Ub.end(), R.begin(), R.end());
  std::vector<V> Q = reblossom_ends<T, V>(f, Ub, p - 1, p - 1, f.P);
  return {f.p, std::move(Ub), std::move(Q)};
}

/// Knot removal, left to right, on a window W of a C^0 form (knots U0, points P0, degree
/// q) that slides along (elevate, reduce_degree_form): a removal at x reads and changes
/// only knots and points within q + 1 indices of the run of x (and q removals there reach
/// q further), so what lies more than 2 q + 2 left of the run is final and moves to the
/// result. W keeps the pairing of the whole form (knot i with point i, q + 1 more knots
/// than points), so remove_knot_once and insert_knot_once work on it as on a whole curve.
/// Cost O(N q) instead of O(N removals).
template <class T, class V>
class SlidingWindow {
 public:
  SlidingWindow(const std::vector<T>& U0, const std::vector<V>& P0, int q) : W{q, {}, {}}, U0_(U0), P0_(P0), q_(q) {
    extend_to(1);
  }

  /// Brings x's run and q + 1 knots after it into W (as far as the form goes).
  void reach(T x) {
    std::size_t after = run_end(x);
    while (after == W.U.size() || W.U.size() < after + sz(q_) + 1) {
      const std::size_t before = W.U.size();
      extend_to(before + 1);
      if (W.U.size() == before) break;
      after = run_end(x);
    }
  }

  /// Moves what lies more than 2 q + 2 left of x's run, final now, to the result.
  void settle(T x) {
    const std::size_t end = run_end(x), reach = 2 * sz(q_) + 2;
    if (end <= reach) return;
    const auto c = static_cast<std::ptrdiff_t>(std::min(end - reach, W.P.size()));
    done_.U.insert(done_.U.end(), W.U.begin(), W.U.begin() + c);
    done_.P.insert(done_.P.end(), W.P.begin(), W.P.begin() + c);
    W.U.erase(W.U.begin(), W.U.begin() + c);
    W.P.erase(W.P.begin(), W.P.begin() + c);
  }

  /// The whole form after the removals: the settled part and the rest of the form.
  KnotForm<T, V> finish() {
    extend_to(U0_.size() + 1);
    done_.U.insert(done_.U.end(), W.U.begin(), W.U.end());
    done_.P.insert(done_.P.end(), W.P.begin(), W.P.end());
    return std::move(done_);
  }

  KnotForm<T, V> W;  ///< the window: removals work on it directly

 private:
  std::size_t run_end(T x) const { return static_cast<std::size_t>(std::upper_bound(W.U.begin(), W.U.end(), x) - W.U.begin()); }

  void extend_to(std::size_t knots_needed) {
    while (W.U.size() < knots_needed && next_ + sz(q_) < U0_.size()) {
      if (next_ < P0_.size()) W.P.push_back(P0_[next_]);
      if (next_ == 0) {  // the first q + 1 knots come with the first point
        W.U.insert(W.U.end(), U0_.begin(), U0_.begin() + q_ + 1);
        next_ = 1;
        continue;
      }
      W.U.push_back(U0_[next_ + sz(q_)]);
      ++next_;
    }
  }

  const std::vector<T>& U0_;
  const std::vector<V>& P0_;
  int q_;
  std::size_t next_ = 0;  // the next point (and knot) of the form to move into W
  KnotForm<T, V> done_{q_, {}, {}};
};


/// Outer knots for unclamping: p knots spaced by the length h of the end span, a - p h ..
/// a - h on the left and b + h .. b + p h on the right.
template <class T>
std::pair<std::vector<T>, std::vector<T>> unclamped_outer_knots(std::span<const T> U, int p) {
  const std::vector<std::size_t> spans = nonempty_spans(U, p);
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  const T a = U[static_cast<std::size_t>(p)], b = U[n];
  const T ha = U[spans.front() + 1] - U[spans.front()], hb = U[spans.back() + 1] - U[spans.back()];
  std::vector<T> L(static_cast<std::size_t>(p)), R(static_cast<std::size_t>(p));
  for (int k = 1; k <= p; ++k) {
    L[static_cast<std::size_t>(p - k)] = a - static_cast<T>(k) * ha;
    R[static_cast<std::size_t>(k - 1)] = b + static_cast<T>(k) * hb;
  }
  return {std::move(L), std::move(R)};
}

/// Validates a knot to remove: finite, a knot strictly inside the domain (InvalidArgument
/// "knot"), times >= 1 and at most its multiplicity ("times"), tolerance > 0 and finite
/// ("tolerance").
template <class T>
void check_removal(std::span<const T> U, int p, T u, int times, T tolerance) {
  require_finite(u, "knot");
  const std::size_t n = U.size() - static_cast<std::size_t>(p) - 1;
  const T a = U[static_cast<std::size_t>(p)], b = U[n];
  const std::size_t s = knot_multiplicity<T>(U, u);
  if (!(u > a && u < b) || s == 0) {
    throw InvalidArgument("knot", format_number(u) + " is not a knot strictly inside the domain [" + format_number(a) + ", " +
                                      format_number(b) + "]");
  }
  if (times < 1) throw InvalidArgument("times", "removal count must be >= 1, got " + std::to_string(times));
  if (static_cast<std::size_t>(times) > s) {
    throw InvalidArgument("times", "knot " + format_number(u) + " has multiplicity " + std::to_string(s) + ", cannot remove it " +
                                       std::to_string(times) + " times");  // times > s >= 1 here: never "1 times"
  }
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "tolerance must be > 0, got " + format_number(tolerance));
}

/// Validates a degree reduction: degree >= 2 ("degree"), tolerance finite and > 0
/// ("tolerance").
template <class T>
void check_reduction(int p, T tolerance) {
  if (p < 2) throw InvalidArgument("degree", "degree reduction needs degree >= 2 (the result has degree >= 1), got " + std::to_string(p));
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "tolerance must be > 0, got " + format_number(tolerance));
}

/// One degree less for the Bézier points P_0..P_p (p >= 2) [PT97, eq. 5.41-5.44, the
/// reduction step of A5.11]: with alpha_i = i / p, the forward recurrence
/// Q_i = (P_i - alpha_i Q_(i-1)) / (1 - alpha_i) from Q_0 = P_0 and the backward one
/// Q_(i-1) = (P_i - (1 - alpha_i) Q_i) / alpha_i from Q_(p-1) = P_p, each used on its
/// half (r = (p - 1) / 2: forward up to Q_r for even p, up to Q_(r-1) for odd p, where
/// Q_r is the mean of both). Both are exact when P is an elevated degree-(p-1) curve.
/// The end points are kept, and for even p also the end tangents. Returns the points and
/// the bound max_i |P_i - R_i|, R the reduced curve elevated back (Forrest's equations):
/// the difference of the two curves is a Bézier curve with those control point
/// differences, so the bound holds at every parameter (guaranteed, up to rounding).
template <class V, class T>
std::pair<std::vector<V>, T> reduce_bezier_once(const std::vector<V>& P) {
  const int p = static_cast<int>(P.size()) - 1;
  const int r = (p - 1) / 2;
  const auto alpha = [&](int i) { return static_cast<T>(i) / static_cast<T>(p); };
  std::vector<V> Q(static_cast<std::size_t>(p));
  const auto forward = [&](int i) {  // Q_i from P_i and Q_(i-1)
    if (i == 0) return P[0];
    const T a = alpha(i);
    return P[sz(i)] + (a / (1 - a)) * (P[sz(i)] - Q[sz(i - 1)]);
  };
  const auto backward = [&](int i) {  // Q_(i-1) from P_i and Q_i
    if (i == p) return P[sz(p)];
    const T a = alpha(i);
    return P[sz(i)] + ((1 - a) / a) * (P[sz(i)] - Q[sz(i)]);
  };
  const bool even = p % 2 == 0;
  const int forward_last = even ? r : r - 1;
  for (int i = 0; i <= forward_last; ++i) Q[sz(i)] = forward(i);
  for (int i = p; i - 1 > r; --i) Q[sz(i - 1)] = backward(i);
  if (!even) {
    const V left = forward(r);
    const V right = backward(r + 1);
    Q[sz(r)] = lerp(left, right, T(0.5));
  }
  T bound = 0;
  for (int i = 0; i <= p; ++i) {
    const V R = i == 0 ? Q[0] : i == p ? Q[sz(p - 1)] : lerp(Q[sz(i)], Q[sz(i - 1)], alpha(i));
    bound = std::max(bound, norm(P[sz(i)] - R));
  }
  return {std::move(Q), bound};
}

/// What reduce_degree_form returns: the reduced form, the largest per-span error bound and
/// how many knot copies were kept beyond the target multiplicities (0: the original
/// continuity, C^(p-1-m) at a knot of multiplicity m, except C^(p-2) at simple knots).
template <class T, class V>
struct FormReduction {
  KnotForm<T, V> form;
  T error_bound = 0;
  int kept_knots = 0;
};

/// Degree reduction p -> p - 1 of the B-spline f (p >= 2) within `tolerance`, an error e
/// in V's norm counting as `scale` e (1 for a B-spline; NURBS pass the factor that turns
/// a homogeneous deviation into a Cartesian bound) [PT97, A5.11]: (1) the exact Bézier pieces of the domain's spans, (2) each
/// reduced by one degree (reduce_bezier_once, its bound e_j), refused with InvalidArgument
/// "tolerance" if some e_j > tolerance, (3) joined as the C^0 B-spline of degree q = p - 1,
/// (4) each interior knot of multiplicity m in f removed from q copies down to max(m - 1, 1)
/// (a break of multiplicity p + 1, where f may jump, keeps q + 1 copies and both points)
/// (the multiplicity the reduced curve needs for f's continuity; a simple knot stays),
/// one copy at a time (remove_knot_once), each removal accepted only if the per-span
/// error stays within tolerance. The error is accumulated per span as A5.11 does: a removal
/// changes the control points by d_i (measured by re-inserting the knot), which moves the
/// curve on a span by at most the largest d_i of the points whose support covers it
/// (basis functions >= 0 summing to 1); the sum of the span's bounds bounds its error
/// (triangle inequality). A refused removal keeps that copy (kept_knots counts them). The
/// result is clamped on f's domain. Cost O(k p^3): the pieces, then the removals on a
/// sliding window of O(p) knots (k spans).
template <class T, class V>
FormReduction<T, V> reduce_degree_form(const KnotForm<T, V>& f, T tolerance, T scale = T(1)) {
  const std::span<const T> U(f.U);
  const int p = f.p, q = p - 1;
  const std::vector<std::size_t> spans = nonempty_spans(U, p);
  const std::size_t k = spans.size();
  std::vector<T> breaks;
  for (const std::size_t s : spans) breaks.push_back(U[s]);
  breaks.push_back(U[f.P.size()]);
  std::vector<T> err(k);
  KnotForm<T, V> cur{q, std::vector<T>(sz(q) + 1, breaks.front()), {}};
  for (std::size_t j = 0; j < k; ++j) {
    auto [Q, e] = reduce_bezier_once<V, T>(span_bezier_points<V, T>(U, p, spans[j], f.P));
    if (!(e * scale <= tolerance)) {
      throw InvalidArgument("tolerance", "reducing the degree from " + std::to_string(p) + " to " + std::to_string(q) +
                                             " moves the curve by up to " + format_number(e * scale) + " on [" + format_number(breaks[j]) +
                                             ", " + format_number(breaks[j + 1]) + "], more than the tolerance " +
                                             format_number(tolerance));
    }
    err[j] = e;
    if (j == 0) {
      cur.P.insert(cur.P.end(), Q.begin(), Q.end());
    } else if (knot_multiplicity<T>(U, breaks[j]) == sz(p) + 1) {
      // A break where f may jump: both pieces' end points kept, q + 1 copies of the knot.
      cur.P.insert(cur.P.end(), Q.begin(), Q.end());
      cur.U.insert(cur.U.end(), sz(q) + 1, breaks[j]);
    } else {
      cur.P.back() = lerp(cur.P.back(), Q.front(), T(0.5));  // the same point from both pieces, up to rounding
      cur.P.insert(cur.P.end(), Q.begin() + 1, Q.end());
      cur.U.insert(cur.U.end(), sz(q), breaks[j]);
    }
  }
  cur.U.insert(cur.U.end(), sz(q) + 1, breaks.back());
  // Knot removal on a sliding window (SlidingWindow), as in elevate, each removal kept
  // only while the spans it moves stay within the tolerance.
  const std::size_t Q1 = sz(q) + 1;
  SlidingWindow<T, V> win(cur.U, cur.P, q);
  KnotForm<T, V>& W = win.W;
  int kept = 0;
  std::vector<T> add(k, T(0));
  for (std::size_t j = 1; j < k; ++j) {
    const T x = breaks[j];
    win.reach(x);
    const int m = static_cast<int>(knot_multiplicity<T>(U, x));
    const int wanted = q - std::max(m - 1, 1);
    for (int c = 0; c < wanted; ++c) {
      KnotForm<T, V> g = remove_knot_once(W, x);
      bool ok = true;
      for (const auto& pt : g.P) ok = ok && all_finite_point(pt);
      std::size_t s_lo = k, s_hi = 0;  // the spans the removal moves
      if (ok) {
        const KnotForm<T, V> back = insert_knot_once(g, x);
        for (std::size_t i = 0; i < W.P.size() && i + Q1 < W.U.size(); ++i) {
          const T d = norm(W.P[i] - back.P[i]);
          if (!(d > 0)) continue;
          // N_i is supported on [U_i, U_(i+q+1)]: the spans inside it.
          const T lo = W.U[i], hi = W.U[i + Q1];
          for (std::size_t s = static_cast<std::size_t>(std::lower_bound(breaks.begin(), breaks.end(), lo) - breaks.begin());
               s < k && breaks[s + 1] <= hi; ++s) {
            add[s] = std::max(add[s], d);
            s_lo = std::min(s_lo, s);
            s_hi = std::max(s_hi, s);
          }
        }
        for (std::size_t s = s_lo; s <= s_hi && s < k && ok; ++s) ok = (err[s] + add[s]) * scale <= tolerance;
      }
      for (std::size_t s = s_lo; s <= s_hi && s < k; ++s) {
        if (ok) err[s] += add[s];
        add[s] = 0;
      }
      if (!ok) {
        kept += wanted - c;
        break;
      }
      W = std::move(g);
    }
    win.settle(x);
  }
  return {win.finish(), *std::max_element(err.begin(), err.end()) * scale, kept};
}

/// Degree elevation by r >= 1 of a B-spline of any point type (the curves' points, the
/// NURBS' homogeneous points, a surface's rows), by decomposition, elevation and recomposition [PT97, §5.5
/// and A5.9, which interleaves the same three steps]: the exact Bézier pieces of the
/// domain's spans are elevated (elevate_bezier_points, Forrest's equations), joined into the
/// C^0 B-spline of degree q = p + r (every interior knot q times), and each interior knot
/// of multiplicity m in U is removed q - (m + r) = p - m times (remove_knot_once: exact,
/// since the elevated curve is still C^(p-m) there; a break of multiplicity p + 1, where
/// the curve may jump, keeps both pieces' end points and q + 1 copies, as [PT97, A5.9]
/// raises every multiplicity by r). Ends: a clamped end stays clamped;
/// an unclamped one gets the outer knots U_0 (r + 1 times), U_1, .., U_{p-1} and its end
/// points by blossoming (with_outer_knots), unless keep_unclamped_ends is false, the new
/// degree is above 100 or a blossom value overflows (then both ends are clamped). Cost O(spans (p + r) p + p^3) plus, for an
/// unclamped end, O((p + r)^3).
template <class T, class V>
KnotForm<T, V> elevate(const KnotForm<T, V>& f, int r, bool keep_unclamped_ends = true) {
  const int p = f.p, q = p + r;
  const std::span<const T> U(f.U);
  const std::size_t n = f.P.size(), m = f.U.size() - 1;
  const T a = U[static_cast<std::size_t>(p)], b = U[n];
  const std::vector<std::size_t> spans = nonempty_spans(U, p);
  // The C^0 form: every piece elevated, joined at the breaks (q copies of each).
  std::vector<T> U0(static_cast<std::size_t>(q) + 1, a);
  std::vector<V> P0;
  for (std::size_t k = 0; k < spans.size(); ++k) {
    const std::vector<V> B = span_bezier_points<V, T>(U, p, spans[k], f.P);
    const std::vector<V> Q = elevate_bezier_points<T, V>(std::span<const V>(B), r);
    if (k == 0) {
      P0.insert(P0.end(), Q.begin(), Q.end());
    } else if (knot_multiplicity<T>(U, U[spans[k]]) == static_cast<std::size_t>(p) + 1) {
      P0.insert(P0.end(), Q.begin(), Q.end());  // a break where the curve may jump: both limits
      U0.insert(U0.end(), static_cast<std::size_t>(q) + 1, U[spans[k]]);
    } else {
      P0.back() = lerp(P0.back(), Q.front(), T(0.5));  // the same point from both sides, up to rounding
      P0.insert(P0.end(), Q.begin() + 1, Q.end());
      U0.insert(U0.end(), static_cast<std::size_t>(q), U[spans[k]]);
    }
  }
  U0.insert(U0.end(), static_cast<std::size_t>(q) + 1, b);
  // Knot removal down to the original continuity, on a sliding window (SlidingWindow).
  SlidingWindow<T, V> win(U0, P0, q);
  for (std::size_t k = 1; k < spans.size(); ++k) {
    const T x = U[spans[k]];
    const int mult = static_cast<int>(knot_multiplicity<T>(U, x));
    win.reach(x);
    for (int j = 0; j < p - mult; ++j) win.W = remove_knot_once(win.W, x);
    win.settle(x);
  }
  KnotForm<T, V> g = win.finish();
  // Re-blossoming an unclamped end evaluates the end piece beyond the domain: O(q^3), and
  // at high degree the blossom values overflow. Above degree max_unclamped_elevation, or
  // when a value is not finite, the ends are clamped instead (the same curve on the
  // domain, the same end pieces beyond it).
  constexpr int max_unclamped_elevation = 100;
  const bool keep = keep_unclamped_ends && q <= max_unclamped_elevation;
  const bool clamped_left = U[0] == a || !keep, clamped_right = U[m] == b || !keep;
  if (clamped_left && clamped_right) return g;
  std::vector<T> L(static_cast<std::size_t>(q), a), R(static_cast<std::size_t>(q), b);
  if (!clamped_left) {
    for (int j = 0; j < r; ++j) L[static_cast<std::size_t>(j)] = U[0];
    for (int j = 0; j < p; ++j) L[static_cast<std::size_t>(r + j)] = U[static_cast<std::size_t>(j)];
  }
  if (!clamped_right) {
    for (int j = 0; j < p; ++j) R[static_cast<std::size_t>(j)] = U[n + 1 + static_cast<std::size_t>(j)];
    for (int j = 0; j < r; ++j) R[static_cast<std::size_t>(p + j)] = U[m];
  }
  KnotForm<T, V> h = with_outer_knots<T, V>(g, L, R);
  for (const auto& pt : h.P)
    if (!all_finite_point(pt)) return g;
  return h;
}

}  // namespace casteljau::detail
