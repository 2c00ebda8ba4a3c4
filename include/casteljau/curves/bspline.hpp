// B-spline curves of any degree p >= 0 and dimension: evaluation by de Boor's algorithm,
// derivatives from the basis-function derivatives, and the exact Bézier pieces by
// blossoming [PT97, chapters 2-4; Ramshaw87]. The algorithms on plain knot data are in
// basis/knot_form.hpp; NURBS in curves/nurbs.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/basis/bspline_basis.hpp"
#include "casteljau/basis/knot_form.hpp"
#include "casteljau/basis/knot_ops.hpp"
#include "casteljau/basis/knot_vector.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

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

/// A B-spline curve C(u) = sum_i N_{i,p}(u) P_i with degree p >= 0, knots U_0..U_{n+p}
/// and control points P_0..P_{n-1}, on the domain [U_p, U_n]. Invariants (checked in the
/// constructor, naming "degree", "knots", "knots[i]", "points[i][j]"): the knot rules of
/// check_knots, n + p + 1 knots, finite points. Clamped or not: nothing assumes the end
/// knots are repeated. An interior knot of multiplicity p + 1 is a break where the curve
/// may jump (degree 0: piecewise constant, a jump at every knot). At a knot inside the
/// domain the right limit answers (derivatives too), at U_n the left one (the last
/// non-empty span); outside the domain the first or last piece is extrapolated.
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
  /// most p + 1 ("times"; p + 1 makes a break, the way a B-spline is cut in two). New
  /// points are convex combinations: the curve moves by a few eps.
  [[nodiscard]] BSpline insert_knot(T u, int times = 1) const { return from_form(detail::insert_knot<T, PointType>(form(), u, times)); }

  /// The same curve with the sorted knots X inserted at once [PT97, A5.4].
  [[nodiscard]] BSpline refine_knots(std::span<const T> X) const { return from_form(detail::refine<T, PointType>(form(), X)); }

  /// Removes the interior knot u up to `times` times while the curve moves by at most
  /// `tolerance` (an absolute distance, over the whole domain): each extra removal is
  /// computed from the previous one [PT97, eq. 5.28-5.29, A5.8], and accepted only if the
  /// bound of removal_deviation (re-insert the knot, compare the control points: a
  /// guaranteed bound, not an estimate) against the original curve is within tolerance.
  /// At a break of multiplicity p + 1 the first removal joins the two limits at their
  /// midpoint: it is accepted only where the curve jumps by at most twice the tolerance.
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
  /// [U_p, u], right on [u, U_n]), by knot insertion up to multiplicity p (at a break of
  /// multiplicity p + 1 the halves end and start at the left and right limits).
  [[nodiscard]] Split<BSpline> split(T u) const {
    auto [l, r] = detail::split<T, PointType>(form(), u);
    return {from_form(std::move(l)), from_form(std::move(r))};
  }

  /// The same curve at degree p + r (r >= 0; InvalidArgument "r" otherwise), every
  /// interior knot r more times (continuity kept, a jump too); see detail::elevate.
  [[nodiscard]] BSpline elevate(int r = 1) const {
    if (r < 0) throw InvalidArgument("r", "degree elevation count must be >= 0, got " + std::to_string(r));
    if (r == 0) return *this;
    return from_form(detail::elevate(form(), r));
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
    require_finite_points(P_, "points");
  }

  KnotVector<T> kv_;
  std::vector<PointType> P_;
};

/// The exact Bézier pieces of a B-spline: one degree-p piece per non-empty knot span of
/// the domain, breaks at the distinct knots U_p .. U_n (detail::span_bezier_points: two
/// de Boor triangles, cost O(p^2) a span). At a break of multiplicity p + 1 consecutive
/// pieces need not meet (a path with a gap); a degree-0 piece is a one-point Bézier curve.
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
static_assert(Curve<BSpline<double, 1>>);
static_assert(PiecewiseBezierCurve<BSpline<double, 2>>);
static_assert(SplittableCurve<BSpline<double, 2>>);

}  // namespace casteljau
