// B-spline and NURBS curves of any degree p >= 1 and dimension: evaluation by de Boor's
// algorithm, derivatives from the basis-function derivatives, and the exact Bézier pieces
// by blossoming [PT97, chapters 2-4; Ramshaw87].
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/knot_ops.hpp"
#include "casteljau/basis/knot_vector.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

namespace detail {

/// The Bézier control points of span s: the blossom at (a^(p-j), b^j), j = 0..p, with
/// [a, b] = [U_s, U_{s+1}] [Ramshaw87; Farin02, 8.4]. Exact up to rounding: the piece is
/// the same polynomial.
template <class V, class T>
std::vector<V> span_bezier_points(std::span<const T> U, int p, std::size_t s, std::span<const V> P) {
  std::vector<V> Q(static_cast<std::size_t>(p) + 1);
  std::vector<T> args(static_cast<std::size_t>(p));
  for (int j = 0; j <= p; ++j) {
    std::fill(args.begin(), args.end() - j, U[s]);
    std::fill(args.end() - j, args.end(), U[s + 1]);
    Q[static_cast<std::size_t>(j)] = de_boor_blossom<V, T>(U, p, s, P, args);
  }
  return Q;
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
bool all_finite_point(const V& v) {
  for (int d = 0; d < V::dimension; ++d) {
    if (!std::isfinite(v[d])) return false;
  }
  return true;
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
/// multiplicity afterwards at most p (InvalidArgument "times").
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
  if (s + static_cast<std::size_t>(times) > static_cast<std::size_t>(p)) {
    throw InvalidArgument("times", "knot " + format_number(u) + " has multiplicity " + std::to_string(s) + "; inserting it " +
                                       std::to_string(times) + " more times would exceed the degree " + std::to_string(p));
  }
}

/// f with u inserted `times` times (checked as check_insertion says).
template <class T, class V>
KnotForm<T, V> insert_knot(KnotForm<T, V> f, T u, int times) {
  check_insertion<T>(f.U, f.p, u, times);
  for (int j = 0; j < times; ++j) f = insert_knot_once(f, u);
  return f;
}

/// f with the sorted knots X inserted (each in the domain, multiplicities at most p after;
/// InvalidArgument naming "knots[j]" of X otherwise).
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
    const std::size_t s = knot_multiplicity<T>(f.U, X[j]) + knot_multiplicity<T>(X, X[j]);
    if (s > static_cast<std::size_t>(f.p)) {
      throw InvalidArgument(where, "knot " + format_number(X[j]) + " would have multiplicity " + std::to_string(s) +
                                       ", more than the degree " + std::to_string(f.p));
    }
  }
  return refine_knots<T, V>(f, X);
}

/// The halves of f at u strictly inside the domain (InvalidArgument "t" otherwise): u is
/// inserted up to multiplicity p [PT97, §5.3: splitting by knot insertion], the left half
/// keeps the knots up to u plus one more u (clamped at u), the right half one u plus the
/// rest. Both keep their parameter: left on [U_p, u], right on [u, U_n].
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
  KnotForm<T, V> g = f;
  for (std::size_t j = s; j < static_cast<std::size_t>(f.p); ++j) g = insert_knot_once(g, u);
  const std::size_t j0 = static_cast<std::size_t>(std::lower_bound(g.U.begin(), g.U.end(), u) - g.U.begin());
  const std::size_t p = static_cast<std::size_t>(f.p);
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

/// Degree elevation by r >= 1, by decomposition, elevation and recomposition [PT97, §5.5
/// and A5.9, which interleaves the same three steps]: the exact Bézier pieces of the
/// domain's spans are elevated (Bezier::elevate, Forrest's equations), joined into the
/// C^0 B-spline of degree q = p + r (every interior knot q times), and each interior knot
/// of multiplicity m in U is removed q - (m + r) = p - m times (remove_knot_once: exact,
/// since the elevated curve is still C^(p-m) there). Ends: a clamped end stays clamped;
/// an unclamped one gets the outer knots U_0 (r + 1 times), U_1, .., U_{p-1} and its end
/// points by blossoming (with_outer_knots), unless keep_unclamped_ends is false, the new
/// degree is above 100 or a blossom value overflows (then both ends are clamped). Cost O(spans (p + r) p + p^3) plus, for an
/// unclamped end, O((p + r)^3).
template <class T, int E>
KnotForm<T, Point<T, E>> elevate(const KnotForm<T, Point<T, E>>& f, int r, bool keep_unclamped_ends = true) {
  using V = Point<T, E>;
  const int p = f.p, q = p + r;
  const std::span<const T> U(f.U);
  const std::size_t n = f.P.size(), m = f.U.size() - 1;
  const T a = U[static_cast<std::size_t>(p)], b = U[n];
  const std::vector<std::size_t> spans = nonempty_spans(U, p);
  // The C^0 form: every piece elevated, joined at the breaks (q copies of each).
  std::vector<T> U0(static_cast<std::size_t>(q) + 1, a);
  std::vector<V> P0;
  for (std::size_t k = 0; k < spans.size(); ++k) {
    const Bezier<T, E> piece(span_bezier_points<V, T>(U, p, spans[k], f.P));
    const std::vector<V> Q = piece.elevate(r).points();
    if (k == 0) {
      P0.insert(P0.end(), Q.begin(), Q.end());
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
                                       std::to_string(times) + " times");
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

}  // namespace detail

/// The result of a degree reduction: the curve of degree one less, a guaranteed bound on
/// its distance from the original over the domain (the same parameter on both), and how
/// many knot copies were kept beyond those the original continuity needs (0 normally; see
/// detail::reduce_degree_form).
template <class C>
struct DegreeReduction {
  C curve;
  typename C::Scalar error_bound = 0;
  int kept_knots = 0;
};

/// The result of a knot removal: the curve and how many times the knot was removed.
template <class C>
struct KnotRemoval {
  C curve;
  int removed = 0;
};

/// A B-spline curve C(u) = sum_i N_{i,p}(u) P_i with degree p >= 1, knots U_0..U_{n+p}
/// and control points P_0..P_{n-1}, on the domain [U_p, U_n]. Invariants (checked in the
/// constructor, naming "degree", "knots", "knots[i]", "points[i][j]"): the knot rules of
/// check_knots, n + p + 1 knots, finite points. Clamped or not: nothing assumes the end
/// knots are repeated. At a knot inside the domain the right limit answers, at U_n the
/// left one; outside the domain the first or last piece is extrapolated.
template <class T, int D>
class BSpline {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  BSpline(int degree, std::vector<T> knots, std::vector<PointType> points)
      : kv_(degree, std::move(knots), points.size()), P_(std::move(points)) {
    check_points();
  }

  /// The curve on validated knots: only the point count (check_knot_count) and the
  /// points are checked.
  BSpline(KnotVector<T> knots, std::vector<PointType> points) : kv_(std::move(knots)), P_(std::move(points)) {
    check_knot_count(kv_.degree(), kv_.size(), P_.size());
    check_points();
  }

  [[nodiscard]] int degree() const { return kv_.degree(); }
  [[nodiscard]] const std::vector<T>& knots() const { return kv_.knots(); }
  /// The validated knot vector (a reference: no copy), with its span search and
  /// multiplicities.
  [[nodiscard]] const KnotVector<T>& knot_vector() const { return kv_; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] Interval<T> domain() const { return kv_.domain(); }

  /// C(u) by de Boor's algorithm [PT97, A3.1 in its de Boor form]: convex combinations
  /// inside the domain, error a few eps of max |P|. Throws InvalidArgument("t", ...) for
  /// a non-finite u or an extrapolated point that overflows. Cost O(log n + p^2).
  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    const std::size_t s = kv_.find_span(u);
    detail::Scratch<T> args(static_cast<std::size_t>(kv_.degree()));
    std::fill(args.data(), args.data() + kv_.degree(), u);
    const PointType c = detail::de_boor_blossom<PointType, T>(kv_.knots(), kv_.degree(), s, P_, std::span<const T>(args.data(), static_cast<std::size_t>(kv_.degree())));
    detail::require_representable(c, static_cast<double>(u), "the curve's point");
    return c;
  }

  /// C(ts[j]) for every parameter into out[j], bit for bit as operator() gives them, with
  /// each span searched from the previous one (KnotVector::find_span(u, hint)): O(p^2) a
  /// point for sorted parameters, O(log n + p^2) for scattered ones. Throws
  /// InvalidArgument "out" for a size mismatch, "t[j]" for a non-finite parameter or an
  /// extrapolated point that overflows. (algo/span_table.hpp's table is faster for many
  /// parameters at low degree; evaluate_pieces falls back to this above its degrees.)
  void evaluate(std::span<const T> ts, std::span<PointType> out) const {
    if (out.size() != ts.size()) {
      throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                       std::to_string(out.size()) + " points");
    }
    const int p = kv_.degree();
    detail::Scratch<T> args(static_cast<std::size_t>(p));
    const std::span<const T> arg(args.data(), static_cast<std::size_t>(p));
    std::size_t s = kv_.first_span();
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const T u = ts[j];
      if (!std::isfinite(u)) require_finite(u, "t[" + std::to_string(j) + "]");
      s = kv_.find_span(u, s);
      std::fill(args.data(), args.data() + p, u);
      out[j] = detail::de_boor_blossom<PointType, T>(kv_.knots(), p, s, P_, arg);
      if (!detail::all_finite_point(out[j])) {
        throw InvalidArgument("t[" + std::to_string(j) + "]",
                              "the curve's point at t = " + detail::format_number(u) + " is not representable (overflow)");
      }
    }
  }

  /// The k-th derivative (k >= 0; zero for k > p) at u: sum_j N^(k)_{s-p+j,p}(u) P_{s-p+j}
  /// [PT97, A3.2], with the same span rule as evaluation. Cost O(p^2 + k p).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 0) return (*this)(u).to_vector();
    if (k > kv_.degree()) return VectorType{};
    const std::size_t s = kv_.find_span(u);
    const auto ders = basis_function_derivatives<T>(kv_.knots(), kv_.degree(), s, u, k);
    // Differences from the span's first point: the derivative weights sum to 0, so the
    // origin cancels and translations do not cost accuracy.
    const PointType& base = P_[s - static_cast<std::size_t>(kv_.degree())];
    VectorType v{};
    for (int j = 1; j <= kv_.degree(); ++j) {
      v += ders[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] * (P_[s - static_cast<std::size_t>(kv_.degree()) + static_cast<std::size_t>(j)] - base);
    }
    detail::require_representable(v, static_cast<double>(u), "the derivative");
    return v;
  }

  /// The same curve traversed backwards on the same domain: u -> U_p + U_n - u, knots
  /// reflected and reversed, points reversed.
  [[nodiscard]] BSpline reverse() const {
    const T a = domain().lo, b = domain().hi;
    std::vector<T> V(kv_.knots().size());
    for (std::size_t i = 0; i < kv_.knots().size(); ++i) V[i] = a + b - kv_.knots()[kv_.knots().size() - 1 - i];
    V[static_cast<std::size_t>(kv_.degree())] = a;  // exact domain ends despite rounding
    V[P_.size()] = b;
    return BSpline(kv_.degree(), std::move(V), std::vector<PointType>(P_.rbegin(), P_.rend()));
  }

  /// The image under an affine map (affine invariance: map the control points).
  [[nodiscard]] BSpline transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    return BSpline(kv_, std::move(Q));
  }

  /// The box of the control points: contains the curve over its domain.
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }

  /// The degree, knots and points as plain data (basis/knot_ops.hpp).
  [[nodiscard]] KnotForm<T, PointType> form() const { return {kv_.degree(), kv_.knots(), P_}; }
  /// The curve of plain data, validated as by the constructor.
  [[nodiscard]] static BSpline from_form(KnotForm<T, PointType> f) { return BSpline(f.p, std::move(f.U), std::move(f.P)); }

  /// The same curve with u inserted `times` times (Boehm's algorithm, [PT97, A5.1] one
  /// copy at a time): u in the domain (InvalidArgument "knot"), multiplicity afterwards at
  /// most p ("times"). New points are convex combinations: the curve moves by a few eps.
  [[nodiscard]] BSpline insert_knot(T u, int times = 1) const { return from_form(detail::insert_knot<T, PointType>(form(), u, times)); }

  /// The same curve with the sorted knots X inserted at once [PT97, A5.4].
  [[nodiscard]] BSpline refine_knots(std::span<const T> X) const { return from_form(detail::refine<T, PointType>(form(), X)); }

  /// Removes the interior knot u up to `times` times while the curve moves by at most
  /// `tolerance` (an absolute distance, over the whole domain): each extra removal is
  /// computed from the previous one [PT97, eq. 5.28-5.29, A5.8], and accepted only if the
  /// bound of removal_deviation (re-insert the knot, compare the control points: a
  /// guaranteed bound, not an estimate) against the original curve is within tolerance.
  /// Stops at the first removal refused. Errors: see detail::check_removal.
  [[nodiscard]] KnotRemoval<BSpline> remove_knot(T u, int times = 1, T tolerance = T(1e-12)) const {
    detail::check_removal<T>(kv_.knots(), kv_.degree(), u, times, tolerance);
    const KnotForm<T, PointType> f = form();
    KnotForm<T, PointType> best = f, g = f;
    int removed = 0;
    for (int j = 1; j <= times; ++j) {
      g = remove_knot_once(g, u);
      bool finite = true;
      for (const auto& q : g.P) finite = finite && detail::all_finite_point(q);
      if (!finite || !(removal_deviation(f, g, u, j) <= tolerance)) break;
      best = g;
      removed = j;
    }
    return {from_form(std::move(best)), removed};
  }

  /// The halves at u strictly inside the domain, each keeping its parameter (left on
  /// [U_p, u], right on [u, U_n]), by knot insertion up to multiplicity p.
  [[nodiscard]] Split<BSpline> split(T u) const {
    auto [l, r] = detail::split<T, PointType>(form(), u);
    return {from_form(std::move(l)), from_form(std::move(r))};
  }

  /// The same curve at degree p + r (r >= 0; InvalidArgument "r" otherwise), every
  /// interior knot one r more times (continuity kept); see detail::elevate for the method.
  [[nodiscard]] BSpline elevate(int r = 1) const {
    if (r < 0) throw InvalidArgument("r", "degree elevation count must be >= 0, got " + std::to_string(r));
    if (r == 0) return *this;
    return from_form(detail::elevate<T, D>(form(), r));
  }

  /// The curve at degree p - 1 within `tolerance` (an absolute distance over the domain,
  /// at equal parameters) [PT97, A5.11]: the Bézier pieces reduced by one degree, joined
  /// and their knots removed back to the original continuity, the error bound accumulated
  /// per span (detail::reduce_degree_form). The result is clamped on the same domain and
  /// keeps the end points of the domain exactly (up to rounding); an elevated curve comes
  /// back exactly (error bound ~ eps). Errors: "degree" for p < 2, "tolerance" not finite
  /// or <= 0, or when a piece cannot be reduced within it (the message gives the bound
  /// and the span). A knot removal that would exceed the tolerance is skipped (the knot
  /// keeps one more copy: kept_knots > 0). Cost O(k p^3) for k spans.
  [[nodiscard]] DegreeReduction<BSpline> reduce_degree(T tolerance) const {
    detail::check_reduction<T>(degree(), tolerance);
    detail::FormReduction<T, PointType> r = detail::reduce_degree_form<T, PointType>(form(), tolerance);
    return {from_form(std::move(r.form)), r.error_bound, r.kept_knots};
  }

  /// Clamped at both ends: the end knots repeated p + 1 times, so the curve starts at the
  /// first control point and ends at the last. The same curve on the same domain.
  [[nodiscard]] BSpline clamp() const {
    const Interval<T> d = domain();
    return from_form(detail::with_outer_knots<T, PointType>(form(), std::vector<T>(static_cast<std::size_t>(kv_.degree()), d.lo),
                                                            std::vector<T>(static_cast<std::size_t>(kv_.degree()), d.hi)));
  }

  /// Unclamped: the outer knots of detail::unclamped_outer_knots (spaced by the end spans),
  /// the same curve on the same domain. Blossoming beyond the domain can amplify rounding
  /// by the ratio of those spacings; the end points become ordinary control points.
  [[nodiscard]] BSpline unclamp() const {
    const auto [L, R] = detail::unclamped_outer_knots<T>(kv_.knots(), kv_.degree());
    return from_form(detail::with_outer_knots<T, PointType>(form(), L, R));
  }

  /// True when both end knots are repeated p + 1 times.
  [[nodiscard]] bool is_clamped() const { return kv_.is_clamped(); }

  /// The Bézier curve as a B-spline: degree n, knots 0 (n + 1 times) and 1 (n + 1 times).
  [[nodiscard]] static BSpline from_bezier(const Bezier<T, D>& c) {
    const std::size_t k = c.points().size();
    std::vector<T> U(k, T(0));
    U.insert(U.end(), k, T(1));
    return BSpline(c.degree(), std::move(U), c.points());
  }

  /// Bézier pieces back to a B-spline: piece i on [breaks[i], breaks[i+1]] (breaks
  /// strictly increasing, one more than the pieces; InvalidArgument "breaks"), each
  /// elevated to the highest degree p among them, joined with every interior break p
  /// times (C^0 form; the join point is the mean of the two pieces' end points, which
  /// should agree). remove_knot then restores any continuity the pieces have.
  [[nodiscard]] static BSpline from_pieces(const std::vector<Bezier<T, D>>& segs, const std::vector<T>& breaks) {
    if (segs.empty()) throw InvalidArgument("pieces", "needs at least one piece");
    if (breaks.size() != segs.size() + 1) throw InvalidArgument("breaks", "needs one more break than pieces");
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      require_finite(breaks[i + 1], "breaks[" + std::to_string(i + 1) + "]");
      if (!(breaks[i] < breaks[i + 1])) throw InvalidArgument("breaks[" + std::to_string(i + 1) + "]", "breaks must increase");
    }
    int p = 1;
    for (const auto& b : segs) p = std::max(p, b.degree());
    std::vector<T> U(static_cast<std::size_t>(p) + 1, breaks.front());
    std::vector<PointType> P;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const std::vector<PointType> Q = segs[i].elevate(p - segs[i].degree()).points();
      if (i == 0) {
        P.insert(P.end(), Q.begin(), Q.end());
      } else {
        P.back() = lerp(P.back(), Q.front(), T(0.5));
        P.insert(P.end(), Q.begin() + 1, Q.end());
        U.insert(U.end(), static_cast<std::size_t>(p), breaks[i]);
      }
    }
    U.insert(U.end(), static_cast<std::size_t>(p) + 1, breaks.back());
    return BSpline(p, std::move(U), std::move(P));
  }

  friend bool operator==(const BSpline&, const BSpline&) = default;

 private:
  void check_points() const {
    for (std::size_t i = 0; i < P_.size(); ++i) require_finite_point(P_[i], "points[" + std::to_string(i) + "]");
  }

  KnotVector<T> kv_;
  std::vector<PointType> P_;
};

/// The exact Bézier pieces of a B-spline: one degree-p piece per non-empty knot span of
/// the domain, breaks at the distinct knots U_p .. U_n (blossoming; cost O(p^3) a span).
template <class T, int D>
Pieces<T, D> pieces(const BSpline<T, D>& c) {
  const std::span<const T> U(c.knots());
  std::vector<BezierPiece<T, D>> segs;
  std::vector<T> breaks;
  for (const std::size_t s : detail::nonempty_spans(U, c.degree())) {
    segs.emplace_back(Bezier<T, D>(detail::span_bezier_points<Point<T, D>, T>(U, c.degree(), s, c.points())));
    breaks.push_back(U[s]);
  }
  breaks.push_back(c.domain().hi);
  return Pieces<T, D>(std::move(segs), std::move(breaks));
}

static_assert(DifferentiableCurve<BSpline<double, 2>>);
static_assert(ControlPolygonCurve<BSpline<double, 3>>);

/// A NURBS curve: C(u) = sum N_{i,p}(u) w_i P_i / sum N_{i,p}(u) w_i with Cartesian
/// control points P_i and weights w_i > 0, evaluated in homogeneous coordinates
/// (w_i P_i, w_i) [PT97, chapter 4]. The knots, degree and domain rules are those of
/// BSpline. Computations use the weights scaled by one power of two so that the largest
/// lies in [0.5, 1) (exact, and the same curve), so that w_i P_i cannot overflow.
template <class T, int D>
class Nurbs {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  using Homogeneous = BSpline<T, D + 1>;
  static constexpr int dimension = D;

  Nurbs(int degree, std::vector<T> knots, std::vector<PointType> points, std::vector<T> weights)
      : P_(std::move(points)), w_(std::move(weights)), h_(degree, std::move(knots), homogeneous_points(P_, w_)) {}

  /// The curve on validated knots (the weights and points are checked as above).
  Nurbs(KnotVector<T> knots, std::vector<PointType> points, std::vector<T> weights)
      : P_(std::move(points)), w_(std::move(weights)), h_(std::move(knots), homogeneous_points(P_, w_)) {}

  [[nodiscard]] int degree() const { return h_.degree(); }
  [[nodiscard]] const std::vector<T>& knots() const { return h_.knots(); }
  [[nodiscard]] const KnotVector<T>& knot_vector() const { return h_.knot_vector(); }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] const std::vector<T>& weights() const { return w_; }
  [[nodiscard]] Interval<T> domain() const { return h_.domain(); }
  /// The homogeneous B-spline (w_i P_i, w_i), weights scaled as the class comment says.
  [[nodiscard]] const Homogeneous& homogeneous() const { return h_; }

  /// C(u): de Boor on the homogeneous points, then the projection. Inside the domain the
  /// weight sum is >= min w_i > 0 (convex combination), so there is no pole there.
  [[nodiscard]] PointType operator()(T u) const {
    require_finite(u, "t");
    return project(h_(u).to_vector(), u);
  }

  /// C(ts[j]) for every parameter into out[j], as operator() gives them: the homogeneous
  /// points by BSpline::evaluate (spans searched from the previous one), then projected.
  /// Errors as BSpline::evaluate, and "t[j]" at a pole.
  void evaluate(std::span<const T> ts, std::span<PointType> out) const {
    if (out.size() != ts.size()) {
      throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(ts.size()) + " parameters, " +
                                       std::to_string(out.size()) + " points");
    }
    std::vector<Point<T, D + 1>> h(ts.size());
    h_.evaluate(ts, h);
    for (std::size_t j = 0; j < ts.size(); ++j) {
      try {
        out[j] = project(h[j].to_vector(), ts[j]);
      } catch (const InvalidArgument& e) {
        throw InvalidArgument("t[" + std::to_string(j) + "]", e.problem());
      }
    }
  }

  /// The k-th derivative (k >= 0) by the quotient rule on the homogeneous derivatives
  /// A^(j), w^(j): C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w [PT97, A4.2].
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    std::vector<Point<T, D + 1>> hd(static_cast<std::size_t>(k) + 1);
    for (int j = 0; j <= k; ++j) hd[static_cast<std::size_t>(j)] = Point<T, D + 1>::from_vector(h_.derivative_at(u, j));
    project(hd[0].to_vector(), u);  // the pole check
    std::vector<VectorType> r(static_cast<std::size_t>(k) + 1);
    detail::quotient_rule<T, D>(hd, k, r.data());
    detail::require_representable(r[static_cast<std::size_t>(k)], static_cast<double>(u), "the derivative");
    return r[static_cast<std::size_t>(k)];
  }

  [[nodiscard]] Nurbs reverse() const {
    const Homogeneous r = h_.reverse();
    return Nurbs(degree(), r.knots(), std::vector<PointType>(P_.rbegin(), P_.rend()), std::vector<T>(w_.rbegin(), w_.rend()));
  }

  /// Affine maps act on the Cartesian control points; weights are unchanged.
  [[nodiscard]] Nurbs transform(const Affine<T, D>& m) const {
    std::vector<PointType> Q = mapped_points(m, P_);
    return Nurbs(degree(), knots(), std::move(Q), w_);
  }

  /// The box of the control points: contains the curve over its domain (weights > 0).
  [[nodiscard]] Box<T, D> control_bounds() const { return box_of<T, D>(P_); }

  /// Every knot operation acts on the homogeneous B-spline (w_i P_i, w_i) and projects
  /// back [PT97, §5.2-5.5: "apply the nonrational algorithm to the P_i^w"]. Weights are
  /// returned at the scale of this curve's weights (the internal power of two undone).
  [[nodiscard]] Nurbs insert_knot(T u, int times = 1) const {
    return from_homogeneous(detail::insert_knot<T, Point<T, D + 1>>(h_.form(), u, times));
  }
  [[nodiscard]] Nurbs refine_knots(std::span<const T> X) const {
    return from_homogeneous(detail::refine<T, Point<T, D + 1>>(h_.form(), X));
  }
  [[nodiscard]] Split<Nurbs> split(T u) const {
    auto [l, r] = detail::split<T, Point<T, D + 1>>(h_.form(), u);
    return {from_homogeneous(std::move(l)), from_homogeneous(std::move(r))};
  }
  [[nodiscard]] Nurbs elevate(int r = 1) const {
    if (r < 0) throw InvalidArgument("r", "degree elevation count must be >= 0, got " + std::to_string(r));
    if (r == 0) return *this;
    KnotForm<T, Point<T, D + 1>> g = detail::elevate<T, D + 1>(h_.form(), r);
    for (const auto& q : g.P) {
      // The outer points of an unclamped end can need a weight <= 0, which a Nurbs cannot
      // hold: then the ends are clamped (the same curve on the domain, and the same end
      // pieces beyond it).
      if (!(q[D] > 0)) return from_homogeneous(detail::elevate<T, D + 1>(h_.form(), r, false));
    }
    return from_homogeneous(std::move(g));
  }

  /// Degree reduction as BSpline::reduce_degree, on the homogeneous points (taken about
  /// the centre c of the control box, which the curve does not notice). Error measure:
  /// the Cartesian distance at equal parameters, bounded from the homogeneous bound d
  /// by d sqrt(1 + R^2) / w_min as remove_knot does ([PT97, eq. 5.30]; R bounds |C - c|
  /// on both curves, w_min is the smallest original weight): the per-span acceptance uses
  /// R of the original points, the reported bound R of both, and a result whose bound then
  /// exceeds the tolerance, or that needs a weight <= 0, is refused ("tolerance").
  [[nodiscard]] DegreeReduction<Nurbs> reduce_degree(T tolerance) const {
    detail::check_reduction<T>(degree(), tolerance);
    const Box<T, D> box = control_bounds();
    PointType c;
    for (int d = 0; d < D; ++d) c[d] = box.lo[d] / 2 + box.hi[d] / 2;
    KnotForm<T, Point<T, D + 1>> f = h_.form();
    for (auto& q : f.P)
      for (int d = 0; d < D; ++d) q[d] -= q[D] * c[d];  // w (P - c)
    T wmin = f.P.front()[D], radius = 0;
    for (std::size_t i = 0; i < f.P.size(); ++i) {
      wmin = std::min(wmin, f.P[i][D]);
      radius = std::max(radius, norm(P_[i] - c));
    }
    const T scale = std::sqrt(1 + radius * radius) / wmin;
    detail::FormReduction<T, Point<T, D + 1>> r = detail::reduce_degree_form<T, Point<T, D + 1>>(f, tolerance, scale);
    T reach = radius;
    for (const auto& q : r.form.P) {
      if (!(q[D] > 0)) {
        throw InvalidArgument("tolerance", "the reduced curve would need a weight <= 0: this NURBS has no reduced form here");
      }
      T s2 = 0;
      for (int d = 0; d < D; ++d) s2 += (q[d] / q[D]) * (q[d] / q[D]);
      reach = std::max(reach, std::sqrt(s2));
    }
    const T bound = r.error_bound / scale * std::sqrt(1 + reach * reach) / wmin;
    if (!(bound <= tolerance)) {
      throw InvalidArgument("tolerance", "reducing the degree moves the curve by up to " + detail::format_number(bound) +
                                             ", more than the tolerance " + detail::format_number(tolerance));
    }
    for (auto& q : r.form.P)
      for (int d = 0; d < D; ++d) q[d] += q[D] * c[d];
    return {from_homogeneous(std::move(r.form)), bound, r.kept_knots};
  }
  [[nodiscard]] Nurbs clamp() const { return from_homogeneous(h_.clamp().form()); }
  /// Unclamping may make a weight non-positive (InvalidArgument "weights[i]").
  [[nodiscard]] Nurbs unclamp() const { return from_homogeneous(h_.unclamp().form()); }
  [[nodiscard]] bool is_clamped() const { return h_.is_clamped(); }

  /// Knot removal as BSpline::remove_knot, on the homogeneous points, with the bound of
  /// [PT97, eq. 5.30]: a homogeneous deviation d moves the Cartesian curve by at most
  /// d sqrt(1 + R^2) / w_min, where R bounds |C - c| for the centre c of the control box
  /// (the homogeneous points are taken relative to c, which the curve does not notice) and
  /// w_min is the smallest weight. A removal that makes a weight non-positive is refused.
  [[nodiscard]] KnotRemoval<Nurbs> remove_knot(T u, int times = 1, T tolerance = T(1e-12)) const {
    detail::check_removal<T>(knots(), degree(), u, times, tolerance);
    const Box<T, D> box = control_bounds();
    PointType c;
    for (int d = 0; d < D; ++d) c[d] = box.lo[d] / 2 + box.hi[d] / 2;
    KnotForm<T, Point<T, D + 1>> f = h_.form();
    for (auto& q : f.P)
      for (int d = 0; d < D; ++d) q[d] -= q[D] * c[d];  // w (P - c)
    T wmin = f.P.front()[D];
    T radius = 0;
    for (std::size_t i = 0; i < f.P.size(); ++i) {
      wmin = std::min(wmin, f.P[i][D]);
      radius = std::max(radius, norm(P_[i] - c));
    }
    KnotForm<T, Point<T, D + 1>> best = f, g = f;
    int removed = 0;
    for (int j = 1; j <= times; ++j) {
      g = remove_knot_once(g, u);
      bool ok = true;
      T r = radius;
      for (const auto& q : g.P) {
        ok = ok && detail::all_finite_point(q) && q[D] > 0;
        if (ok) {
          T s2 = 0;
          for (int d = 0; d < D; ++d) s2 += (q[d] / q[D]) * (q[d] / q[D]);
          r = std::max(r, std::sqrt(s2));
        }
      }
      if (!ok) break;
      const T bound = removal_deviation(f, g, u, j) * std::sqrt(1 + r * r) / wmin;
      if (!(bound <= tolerance)) break;
      best = g;
      removed = j;
    }
    for (auto& q : best.P)
      for (int d = 0; d < D; ++d) q[d] += q[D] * c[d];
    return {from_homogeneous(std::move(best)), removed};
  }

  /// The NURBS of a homogeneous B-spline (w_i P_i, w_i) at this curve's weight scale:
  /// P_i = (w_i P_i) / w_i. Throws InvalidArgument naming "weights[i]" for a weight <= 0.
  [[nodiscard]] Nurbs from_homogeneous(KnotForm<T, Point<T, D + 1>> f) const {
    const T scale = w_.front() / h_.points().front()[D];  // a power of two
    std::vector<PointType> P(f.P.size());
    std::vector<T> w(f.P.size());
    for (std::size_t i = 0; i < f.P.size(); ++i) {
      const T wi = f.P[i][D];
      if (!(wi > 0)) {
        throw InvalidArgument("weights[" + std::to_string(i) + "]", "the operation gives a weight <= 0 (" + detail::format_number(wi * scale) + ")");
      }
      for (int d = 0; d < D; ++d) P[i][d] = f.P[i][d] / wi;
      w[i] = wi * scale;
    }
    return Nurbs(f.p, std::move(f.U), std::move(P), std::move(w));
  }

  /// Rational and polynomial Bézier pieces back to a NURBS [PT97, A5.6 read backwards; the
  /// rational form of BSpline::from_pieces]: piece i on [breaks[i], breaks[i+1]]
  /// (breaks finite, strictly increasing, one more than the pieces; InvalidArgument
  /// "pieces" / "breaks" / "breaks[i]"), a polynomial piece with weights 1, each elevated
  /// to the highest degree p among them (p >= 1), joined with every interior break p
  /// times: the C^0 form. A rational piece is unchanged when all its weights are scaled,
  /// so piece i + 1 is scaled by w_end(i) / w_start(i + 1): the homogeneous curve is then
  /// continuous too and the join is one control point (the mean of the two end points and
  /// weights, which agree up to rounding). The scale factors chain along the pieces and
  /// are carried as (mantissa, exponent) so that they cannot overflow; at the end all
  /// weights are divided by a power of two so that the largest is in [0.5, 1). Weights
  /// spanning more than the floating point range are an InvalidArgument ("pieces").
  /// With removal_tolerance, each interior break is then removed up to p times with
  /// remove_knot(x, p, tolerance) (the [PT97, eq. 5.30] bound, within the tolerance of
  /// the curve before that break's removal, so at most the tolerance per break and
  /// (breaks - 1) times it in all), restoring the continuity the pieces have. The pieces
  /// are exact: the result traces them up to rounding. Cost O(pieces p^2) plus the
  /// removals, O(pieces (n + p^2)) each of n control points.
  [[nodiscard]] static Nurbs from_pieces(const std::vector<BezierPiece<T, D>>& segs, const std::vector<T>& breaks,
                                         std::optional<T> removal_tolerance = std::nullopt) {
    if (segs.empty()) throw InvalidArgument("pieces", "needs at least one piece");
    if (breaks.size() != segs.size() + 1) throw InvalidArgument("breaks", "needs one more break than pieces");
    require_finite(breaks.front(), "breaks[0]");
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      require_finite(breaks[i + 1], "breaks[" + std::to_string(i + 1) + "]");
      if (!(breaks[i] < breaks[i + 1])) throw InvalidArgument("breaks[" + std::to_string(i + 1) + "]", "breaks must increase");
    }
    int p = 1;
    for (const auto& s : segs) p = std::max(p, std::visit([](const auto& b) { return b.degree(); }, s));
    std::vector<T> U(static_cast<std::size_t>(p) + 1, breaks.front());
    std::vector<PointType> P;
    std::vector<T> mant;   // weight = mant[i] 2^expo[i], mant in [0.5, 1)
    std::vector<int> expo;
    T scale_m = 1;  // the current piece's scale factor, scale_m 2^scale_e
    int scale_e = 0;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      std::vector<PointType> Q;
      std::vector<T> W;
      if (const auto* b = std::get_if<Bezier<T, D>>(&segs[i])) {
        Q = b->elevate(p - b->degree()).points();
        W.assign(Q.size(), T(1));
      } else {
        const auto& r = std::get<RationalBezier<T, D>>(segs[i]);
        const RationalBezier<T, D> e = r.elevate(p - r.degree());
        Q = e.points();
        W = e.weights();
      }
      if (i > 0) {
        // Scale so that this piece's first weight equals the previous piece's last one.
        int ea = 0, eb = 0;
        const T ma = std::frexp(mant.back(), &ea), mb = std::frexp(W.front(), &eb);
        scale_m = std::frexp(ma / mb, &scale_e);
        scale_e += ea + expo.back() - eb;
      }
      for (std::size_t j = 0; j < Q.size(); ++j) {
        int e = 0;
        const T m = std::frexp(W[j] * scale_m, &e);
        if (i > 0 && j == 0) {
          // The join: one point and one weight for both pieces.
          P.back() = lerp(P.back(), Q.front(), T(0.5));
          mant.back() = mant.back() / 2 + std::ldexp(m, e + scale_e - expo.back()) / 2;
          continue;
        }
        P.push_back(Q[j]);
        mant.push_back(m);
        expo.push_back(e + scale_e);
      }
      if (i > 0) U.insert(U.end(), static_cast<std::size_t>(p), breaks[i]);
    }
    U.insert(U.end(), static_cast<std::size_t>(p) + 1, breaks.back());
    int top = expo.front();
    for (std::size_t j = 0; j < mant.size(); ++j) {
      int e = 0;
      (void)std::frexp(mant[j], &e);
      top = std::max(top, expo[j] + e);
    }
    std::vector<T> w(mant.size());
    for (std::size_t j = 0; j < mant.size(); ++j) {
      w[j] = std::ldexp(mant[j], expo[j] - top);
      if (!(w[j] > 0)) throw InvalidArgument("pieces", "the weights of the joined pieces span more than the floating point range");
    }
    Nurbs c(p, std::move(U), std::move(P), std::move(w));
    if (removal_tolerance) {
      for (std::size_t i = 1; i + 1 < breaks.size(); ++i) c = c.remove_knot(breaks[i], p, *removal_tolerance).curve;
    }
    return c;
  }
  [[nodiscard]] static Nurbs from_pieces(const std::vector<RationalBezier<T, D>>& segs, const std::vector<T>& breaks,
                                         std::optional<T> removal_tolerance = std::nullopt) {
    return from_pieces(std::vector<BezierPiece<T, D>>(segs.begin(), segs.end()), breaks, removal_tolerance);
  }
  /// The NURBS of exact pieces (pieces(c) of any curve), as from_pieces above.
  [[nodiscard]] static Nurbs from_pieces(const Pieces<T, D>& pc, std::optional<T> removal_tolerance = std::nullopt) {
    return from_pieces(pc.segments(), pc.breaks(), removal_tolerance);
  }

  friend bool operator==(const Nurbs&, const Nurbs&) = default;

 private:
  /// (w_i P_i, w_i) with the weights scaled as the class comment says; checks the weights
  /// and points (the knots are checked by the B-spline made of them).
  static std::vector<Point<T, D + 1>> homogeneous_points(const std::vector<PointType>& P, const std::vector<T>& w) {
    if (w.size() != P.size()) {
      throw InvalidArgument("weights", "needs one weight per control point: " + std::to_string(P.size()) + " points but " +
                                           std::to_string(w.size()) + " weights");
    }
    T wmax = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      const std::string where = "weights[" + std::to_string(i) + "]";
      require_finite(w[i], where);
      if (!(w[i] > 0)) throw InvalidArgument(where, "weight must be > 0, got " + detail::format_number(w[i]));
      wmax = std::max(wmax, w[i]);
    }
    for (std::size_t i = 0; i < P.size(); ++i) require_finite_point(P[i], "points[" + std::to_string(i) + "]");
    int e = 0;
    if (wmax > 0) std::frexp(wmax, &e);
    std::vector<Point<T, D + 1>> H(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
      const T wi = std::ldexp(w[i], -e);
      if (!(wi > 0)) {
        throw InvalidArgument("weights[" + std::to_string(i) + "]",
                              "weight " + detail::format_number(w[i]) + " is too small next to the largest weight " +
                                  detail::format_number(wmax) + " (their ratio underflows)");
      }
      for (int d = 0; d < D; ++d) H[i][d] = wi * P[i][d];
      H[i][D] = wi;
    }
    // The homogeneous points are finite products of finite values: only the degree and
    // knot errors can come from the B-spline, and they name the fields as they are.
    return H;
  }

  /// The Cartesian point of a homogeneous one. Outside the domain the weight function may
  /// change sign (extrapolation, as for RationalBezier): only a zero weight is a pole; a
  /// quotient that overflows is refused by require_representable.
  PointType project(const Vector<T, D + 1>& h, T u) const {
    PointType c;
    if (h[D] == 0 || !std::isfinite(h[D])) {
      throw InvalidArgument("t", "the curve has a pole at t = " + detail::format_number(u) + " (its weight function vanishes there)");
    }
    for (int d = 0; d < D; ++d) c[d] = h[d] / h[D];
    detail::require_representable(c, static_cast<double>(u), "the curve's point");
    return c;
  }

  std::vector<PointType> P_;
  std::vector<T> w_;
  Homogeneous h_;
};

/// The exact rational Bézier pieces of a NURBS curve (the pieces of its homogeneous
/// B-spline, projected).
template <class T, int D>
Pieces<T, D> pieces(const Nurbs<T, D>& c) {
  const auto& h = c.homogeneous();
  const std::span<const T> U(h.knots());
  std::vector<BezierPiece<T, D>> segs;
  std::vector<T> breaks;
  for (const std::size_t s : detail::nonempty_spans(U, h.degree())) {
    const Bezier<T, D + 1> hb(detail::span_bezier_points<Point<T, D + 1>, T>(U, h.degree(), s, h.points()));
    segs.emplace_back(RationalBezier<T, D>::from_homogeneous(hb));
    breaks.push_back(U[s]);
  }
  breaks.push_back(c.domain().hi);
  return Pieces<T, D>(std::move(segs), std::move(breaks));
}

static_assert(DifferentiableCurve<Nurbs<double, 2>>);
static_assert(ControlPolygonCurve<Nurbs<double, 3>>);

}  // namespace casteljau
