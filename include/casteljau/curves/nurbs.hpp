// NURBS curves: a B-spline in homogeneous coordinates (w P, w), evaluated, differentiated
// and cut into exact rational Bézier pieces through it [PT97, chapter 4].
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/curves/bspline.hpp"
#include "casteljau/curves/rational_bezier.hpp"

namespace casteljau {

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
  /// A^(j), w^(j): C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w [PT97, A4.2];
  /// k = 1 inside the domain over pairs of control points (first_derivative), k >= 2 there
  /// too where the span's weights spread beyond 2^20 (pair_derivative).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 1 && u >= domain().lo && u <= domain().hi) return first_derivative(u);
    if (k >= 2 && u >= domain().lo && u <= domain().hi) {
      if (const auto v = pair_derivative(u, k)) return *v;
    }
    std::vector<Point<T, D + 1>> hd(static_cast<std::size_t>(k) + 1);
    for (int j = 0; j <= k; ++j) hd[static_cast<std::size_t>(j)] = Point<T, D + 1>::from_vector(h_.derivative_at(u, j));
    project(hd[0].to_vector(), u);  // the pole check
    std::vector<VectorType> r(static_cast<std::size_t>(k) + 1);
    detail::quotient_rule<T, D>(hd, k, r.data());
    detail::require_representable(r[static_cast<std::size_t>(k)], static_cast<double>(u), "the derivative");
    return r[static_cast<std::size_t>(k)];
  }

  /// C'(u) for u in the domain as sum_(i<j) w_i w_j (N_i N_j' - N_i' N_j) (P_j - P_i) / W^2
  /// over the span's p + 1 basis functions (the quotient rule's numerator A'W - AW'
  /// antisymmetrised; as detail::rational_jet for a Bézier piece): each pair's weights
  /// multiply its basis Wronskian, so a large weight does not swamp the others' share
  /// (weights 1, 1e30, 1: C'(1/2) ~ 1e-30, from terms of size 1 in the quotient rule). Each
  /// factor is divided by W first (no overflow), the points halved (no overflow of their
  /// differences). Cost O(p^2 D).
  [[nodiscard]] VectorType first_derivative(T u) const {
    const auto& kv = h_.knot_vector();
    const int p = kv.degree();
    const std::size_t s = kv.find_span(u), first = s - static_cast<std::size_t>(p);
    const auto ders = basis_function_derivatives<T>(kv.knots(), p, s, u, 1);
    const auto np = static_cast<std::size_t>(p) + 1;
    std::vector<T> a(np), b(np);
    T W = 0;
    for (std::size_t j = 0; j < np; ++j) {
      const T wj = h_.points()[first + j][D];
      a[j] = wj * ders[0][j];
      b[j] = wj * ders[1][j];
      W += a[j];
    }
    for (std::size_t j = 0; j < np; ++j) {
      a[j] /= W;
      b[j] /= W;
    }
    VectorType v{};
    for (std::size_t i = 0; i < np; ++i)
      for (std::size_t j = i + 1; j < np; ++j) {
        VectorType d;
        for (int c = 0; c < D; ++c) d[c] = P_[first + j][c] / 2 - P_[first + i][c] / 2;
        v += (a[i] * b[j] - b[i] * a[j]) * d;
      }
    v = T(2) * v;
    detail::require_representable(v, static_cast<double>(u), "the derivative");
    return v;
  }

  /// C^(k)(u), k >= 2, for u in the domain over pairs of control points
  /// (detail::pair_derivative on the span's p + 1 weighted basis functions and their
  /// derivatives, each divided by W first) where the span's weights spread by more than
  /// 2^20 (detail::extreme_weight_spread: the quotient rule loses C^(k) where the curve
  /// hugs its control polygon); nothing elsewhere, or where the result is not finite.
  /// Cost O(k^2 p^2 + p^2 D).
  [[nodiscard]] std::optional<VectorType> pair_derivative(T u, int k) const {
    const auto& kv = h_.knot_vector();
    const int p = kv.degree();
    const std::size_t s = kv.find_span(u), first = s - static_cast<std::size_t>(p);
    const auto np = static_cast<std::size_t>(p) + 1;
    std::vector<T> ws(np);
    for (std::size_t j = 0; j < np; ++j) ws[j] = h_.points()[first + j][D];
    if (!detail::extreme_weight_spread(std::span<const T>(ws))) return std::nullopt;
    auto rows = basis_function_derivatives<T>(kv.knots(), p, s, u, k);  // rows beyond p are zero
    T W = 0;
    for (std::size_t j = 0; j < np; ++j) W += ws[j] * rows[0][j];
    for (auto& r : rows)
      for (std::size_t j = 0; j < np; ++j) r[j] = ws[j] * r[j] / W;
    const VectorType v = detail::pair_derivative<T, D>(std::span<const PointType>(P_.data() + first, np), std::span<const std::vector<T>>(rows), k);
    if (!detail::all_finite(v)) return std::nullopt;
    return v;
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
    KnotForm<T, Point<T, D + 1>> g = detail::elevate(h_.form(), r);
    for (const auto& q : g.P) {
      // The outer points of an unclamped end can need a weight <= 0, which a Nurbs cannot
      // hold: then the ends are clamped (the same curve on the domain, and the same end
      // pieces beyond it).
      if (!(q[D] > 0)) return from_homogeneous(detail::elevate(h_.form(), r, false));
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
    auto [f, c, wmin, radius] = centred_form();
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
    auto [f, c, wmin, radius] = centred_form();
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
  /// The homogeneous form taken relative to the centre c of the control box (points
  /// w (P - c), which the curve does not notice), with the smallest weight and the radius
  /// max |P_i - c|: the setting of the Cartesian error bounds of reduce_degree and
  /// remove_knot [PT97, eq. 5.30].
  struct CentredForm {
    KnotForm<T, Point<T, D + 1>> form;
    PointType centre;
    T wmin;
    T radius;
  };
  [[nodiscard]] CentredForm centred_form() const {
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
    return {std::move(f), c, wmin, radius};
  }

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
    require_finite_points(P, "points");
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
static_assert(Curve<Nurbs<double, 1>>);
static_assert(PiecewiseBezierCurve<Nurbs<double, 2>>);
static_assert(SplittableCurve<Nurbs<double, 2>>);

}  // namespace casteljau
