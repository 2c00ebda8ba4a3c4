// Catmull-Rom splines: the C1 piecewise cubic through points with knot intervals
// |P_(i+1) - P_i|^alpha (uniform, centripetal, chordal and any alpha in [0, 1]), open or
// closed, held as its exact Bézier pieces [CatmullRom74; BarryGoldman88; Yuksel11].
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// How an open Catmull-Rom curve treats its end points: `inner` (the contract's default)
/// runs from P_1 to P_(N-2), the end points only shaping the end tangents; `reflect` first
/// adds the phantom points 2 P_0 - P_1 before and 2 P_(N-1) - P_(N-2) after, so that the
/// curve runs through every point, from P_0 to P_(N-1).
enum class CatmullRomEnds { inner, reflect };

/// The Catmull-Rom spline through points P_0..P_(N-1) with the parametrisation of
/// docs/cli.md: knot intervals d_i = |P_(i+1) - P_i|^alpha (1 for alpha = 0), knots
/// s_0 = 0, s_(i+1) = s_i + d_i.
/// - Open (N >= 4): segment j = 0..N-4 runs from P_(j+1) to P_(j+2) on [s_(j+1), s_(j+2)]
///   shifted by -s_1, so the domain is [0, s_(N-2) - s_1]; P_0 and P_(N-1) only shape the
///   end tangents.
/// - Closed (N >= 3): the points wrap (P_N = P_0); segment j runs from P_j to P_(j+1) on
///   [s_j, s_(j+1)], domain [0, s_N]; the curve closes with C1 continuity.
/// - Open with ends `reflect` (N >= 2): the open curve of the N + 2 points P_(-1) =
///   2 P_0 - P_1, P_0, ..., P_(N-1), P_N = 2 P_(N-1) - P_(N-2) (knots of those, s_0 at the
///   phantom P_(-1)): N - 1 segments from P_0 to P_(N-1), the parameter starting at P_0.
///   Its end tangents are those of the parabola through the reflected triple (for alpha 0,
///   P_1 - P_0 at the start).
/// Each segment is the cubic Hermite interpolant of its end points with the tangent of the
/// non-uniform Catmull-Rom spline, which is the derivative of the Barry-Goldman pyramid:
/// m_i = (P_i - P_(i-1)) / d_(i-1) - (P_(i+1) - P_(i-1)) / (d_(i-1) + d_i) + (P_(i+1) - P_i) / d_i,
/// equal to d_i / (d_(i-1) (d_(i-1) + d_i)) (P_i - P_(i-1)) + d_(i-1) / (d_i (d_(i-1) +
/// d_i)) (P_(i+1) - P_i) (the same, without cancellation); for alpha = 0 it is
/// (P_(i+1) - P_(i-1)) / 2. Its Bézier points are P_i, P_i + d_i m_i / 3, P_(i+1) -
/// d_i m_(i+1) / 3, P_(i+1), the products d m formed from ratios of intervals (build), so
/// that coordinates from 1e-300 to 1e300 give the same curve up to scale; built once in
/// the constructor (O(N)); evaluation and
/// derivatives (with respect to the parameter s) run on those pieces, so the right
/// segment answers at a joint and the end segments extrapolate.
/// Invariants (checked in the constructor): alpha finite in [0, 1] ("alpha"), enough points
/// ("points"), ends `reflect` only when open ("ends"), finite coordinates ("points[i][d]"), for alpha > 0 no two consecutive
/// points equal (a zero knot interval, "points[i]"), and a representable parameter: every
/// interval a normal double, the knots finite, the Bézier points finite ("points").
template <class T, int D>
class CatmullRom {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  explicit CatmullRom(std::vector<PointType> points, T alpha = T(0.5), bool closed = false, CatmullRomEnds ends = CatmullRomEnds::inner)
      : P_(std::move(points)),
        alpha_(alpha),
        closed_(closed),
        ends_(ends),
        d_(intervals_of(P_, alpha_, closed_, ends_)),
        pieces_(build(P_, d_, closed_, ends_)) {}

  /// The points given (without the phantom points of ends `reflect`).
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  [[nodiscard]] T alpha() const { return alpha_; }
  [[nodiscard]] bool closed() const { return closed_; }
  [[nodiscard]] CatmullRomEnds ends() const { return ends_; }
  /// The knot intervals d_i: N - 1 of them when open, N when closed (d_(N-1) from P_(N-1)
  /// back to P_0), N + 1 with ends `reflect` (the first and last to the phantom points).
  [[nodiscard]] const std::vector<T>& intervals() const { return d_; }
  /// Whether the intervals are |P_(i+1) - P_i|^alpha of the points, to 8 eps relative (true
  /// unless the curve is the image under a map that is not a similarity: transform keeps
  /// the knots).
  [[nodiscard]] bool knots_follow_points() const { return follow_; }
  /// The exact Bézier pieces (one cubic per segment; breaks at the segments' knots).
  [[nodiscard]] const Pieces<T, D>& bezier_pieces() const { return pieces_; }
  [[nodiscard]] const std::vector<T>& breaks() const { return pieces_.breaks(); }
  [[nodiscard]] Interval<T> domain() const { return pieces_.domain(); }

  /// The point at parameter s (de Casteljau on the segment's cubic). O(log N). Throws
  /// InvalidArgument("t", ...) for a non-finite s or a point that overflows (far
  /// extrapolation), quoting s (not the segment's own parameter).
  [[nodiscard]] PointType operator()(T s) const {
    try {
      return pieces_(s);
    } catch (const InvalidArgument& e) {
      rethrow_for(e, s, "the curve's point");
    }
  }
  /// The k-th derivative (k >= 0; zero above 3) with respect to s. O(log N). Throws as
  /// operator(), and InvalidArgument("k", ...) for k < 0.
  [[nodiscard]] VectorType derivative_at(T s, int k = 1) const {
    try {
      return pieces_.derivative_at(s, k);
    } catch (const InvalidArgument& e) {
      rethrow_for(e, s, k == 0 ? "the curve's point" : "the derivative");
    }
  }

  /// The same curve backwards on the same domain (up to the rounding of the knot sums):
  /// the points reversed (closed: P_0, P_(N-1), ..., P_1, so that it starts where the curve
  /// ends) with their intervals. Reversing twice gives the same curve exactly.
  [[nodiscard]] CatmullRom reverse() const {
    std::vector<PointType> Q;
    std::vector<T> e;
    const std::size_t N = P_.size();
    if (closed_) {
      Q.push_back(P_[0]);
      for (std::size_t i = N - 1; i >= 1; --i) Q.push_back(P_[i]);
      for (std::size_t i = N; i-- > 0;) e.push_back(d_[i]);
    } else {
      Q.assign(P_.rbegin(), P_.rend());
      e.assign(d_.rbegin(), d_.rend());
    }
    return CatmullRom(std::move(Q), alpha_, closed_, ends_, std::move(e), follow_);
  }

  /// The exact image under an affine map: the mapped points with the same knot intervals
  /// (with fixed knots the spline is linear in its points). Unless the map is a
  /// similarity, the intervals then differ from those the mapped points would give
  /// (knots_follow_points() is false): chordal and centripetal parametrisations commute
  /// only with similarities.
  [[nodiscard]] CatmullRom transform(const Affine<T, D>& m) const {
    return CatmullRom(mapped_points(m, P_), alpha_, closed_, ends_, d_, follow_);
  }

  /// The box of the Bézier control points: it contains the curve over its domain.
  [[nodiscard]] Box<T, D> control_bounds() const { return pieces_.control_bounds(); }

  friend bool operator==(const CatmullRom& a, const CatmullRom& b) {
    return a.P_ == b.P_ && a.alpha_ == b.alpha_ && a.closed_ == b.closed_ && a.ends_ == b.ends_ && a.d_ == b.d_ && a.follow_ == b.follow_;
  }

 private:
  CatmullRom(std::vector<PointType> points, T alpha, bool closed, CatmullRomEnds ends, std::vector<T> intervals, bool follow)
      : P_(std::move(points)),
        alpha_(alpha),
        closed_(closed),
        ends_(ends),
        d_(std::move(intervals)),
        follow_(follow),
        pieces_(build(P_, d_, closed_, ends_)) {
    if (follow_) {
      // Whether the points still give these intervals, to rounding (8 eps relative: a
      // rotation or uniform scaling moves each distance by a few ulps); not when the mapped
      // points' own intervals are not doubles (the kept ones are).
      try {
        const std::vector<T> e = intervals_of(P_, alpha_, closed_, ends_);
        for (std::size_t i = 0; i < e.size(); ++i)
          follow_ = follow_ && std::abs(e[i] - d_[i]) <= 8 * std::numeric_limits<T>::epsilon() * d_[i];
      } catch (const InvalidArgument&) {
        follow_ = false;
      }
    }
  }

  /// A segment's error about its own parameter, restated for the curve's parameter s that
  /// the caller gave (issue 15: a message quoted 4.47e148 where the user sent 0.1).
  [[noreturn]] static void rethrow_for(const InvalidArgument& e, T s, const char* what) {
    if (e.where() != "t" || !std::isfinite(s)) throw e;
    throw InvalidArgument("t", std::string(what) + " at t = " + detail::format_number(s) +
                                   " is not representable (a coordinate exceeds the largest finite number)");
  }

  /// |P[b] - P[a]| as scale * root with root in [1, sqrt(D)]: scale = max |coordinate
  /// difference| (exact), or half of it (halved = true) when a difference overflows.
  struct Length {
    T scale, root;
    bool halved;
  };
  static Length length_of(const PointType& a, const PointType& b) {
    VectorType v = b - a;
    bool halved = false;
    if (!detail::all_finite_point(v)) {
      v = T(0.5) * b.to_vector() - T(0.5) * a.to_vector();  // exact: the coordinates are far above the subnormals
      halved = true;
    }
    T scale = 0;
    for (int k = 0; k < D; ++k) scale = std::max(scale, std::abs(v[k]));
    if (scale == 0) return {T(0), T(1), false};
    T sum = 0;
    for (int k = 0; k < D; ++k) sum += (v[k] / scale) * (v[k] / scale);
    return {scale, std::sqrt(sum), halved};
  }

  /// The knot intervals d_i = |P_(i+1) - P_i|^alpha of the contract, each rounded once from
  /// its exact value wherever that is a normal double: the length is formed without
  /// overflow or underflow (length_of) and the power taken of its factors when the
  /// length itself is not a normal double. An interval that overflows, or falls below
  /// the normal range (where it keeps fewer than the double's 53 bits, and its ratios to
  /// the others, which shape the curve, are no longer exact) is refused naming "points".
  /// The name of point i of the working list (working_points) in messages: with ends
  /// `reflect` index i is the given point i - 1, or a phantom point.
  static std::string point_name(std::size_t i, std::size_t count, CatmullRomEnds ends) {
    if (ends == CatmullRomEnds::inner) return "points[" + std::to_string(i) + "]";
    if (i == 0) return "the phantom point 2 points[0] - points[1]";
    if (i + 1 == count) {
      return "the phantom point 2 points[" + std::to_string(count - 3) + "] - points[" + std::to_string(count - 4) + "]";
    }
    return "points[" + std::to_string(i - 1) + "]";
  }

  /// The points the pieces are built on: the given ones, with the phantom end points
  /// 2 P_0 - P_1 and 2 P_(N-1) - P_(N-2) around them for ends `reflect` (needs N >= 2).
  /// Throws InvalidArgument("points") when a phantom point overflows.
  static std::vector<PointType> working_points(const std::vector<PointType>& P, CatmullRomEnds ends) {
    if (ends == CatmullRomEnds::inner) return P;
    const std::size_t N = P.size();
    std::vector<PointType> E;
    E.reserve(N + 2);
    E.push_back(P[0] + (P[0] - P[1]));
    E.insert(E.end(), P.begin(), P.end());
    E.push_back(P[N - 1] + (P[N - 1] - P[N - 2]));
    for (const std::size_t i : {std::size_t(0), N + 1}) {
      if (!detail::all_finite_point(E[i])) {
        throw InvalidArgument("points", point_name(i, N + 2, ends) + " overflows a double: scale the points, or use ends 'inner'");
      }
    }
    return E;
  }

  static std::vector<T> intervals_of(const std::vector<PointType>& given, T alpha, bool closed, CatmullRomEnds ends) {
    require_finite(alpha, "alpha");
    if (!(alpha >= 0 && alpha <= 1)) throw InvalidArgument("alpha", "alpha must lie in [0, 1], got " + detail::format_number(alpha));
    const bool reflect = ends == CatmullRomEnds::reflect;
    if (closed && reflect) throw InvalidArgument("ends", "'reflect' is for open curves: a closed catmull_rom has no end points");
    const std::size_t need = closed ? 3 : reflect ? 2 : 4;
    if (given.size() < need) {
      throw InvalidArgument("points", std::string("a") + (closed ? " closed" : "n open") + " catmull_rom curve" +
                                          (reflect ? " with ends 'reflect'" : "") + " needs at least " + std::to_string(need) +
                                          " points, got " + std::to_string(given.size()));
    }
    require_finite_points(given, "points");
    if (reflect && alpha > 0) {  // the given points first: a phantom point equals its neighbour only when they do
      for (std::size_t i = 1; i < given.size(); ++i) {
        if (given[i] == given[i - 1]) {
          throw InvalidArgument("points[" + std::to_string(i) + "]", "equals points[" + std::to_string(i - 1) +
                                                                         "]: with alpha > 0 consecutive points must differ (a zero knot interval)");
        }
      }
    }
    const std::vector<PointType> P = working_points(given, ends);
    const auto name = [&](std::size_t i) { return point_name(i, P.size(), ends); };
    const std::size_t N = P.size(), m = closed ? N : N - 1;
    std::vector<T> d(m);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t next = (i + 1) % N;
      const Length len = length_of(P[i], P[next]);
      if (len.scale == 0 && alpha > 0) {
        throw InvalidArgument(reflect ? std::string("points") : "points[" + std::to_string(next) + "]",
                              (reflect ? name(next) + " equals " : std::string("equals ")) + name(i) +
                                  ": with alpha > 0 consecutive points must differ (a zero knot interval)" +
                                  std::string(closed && next == 0 ? " (the curve is closed: the last point is followed by the first)" : ""));
      }
      if (alpha == 0) {
        d[i] = 1;
        continue;
      }
      const T whole = len.halved ? std::numeric_limits<T>::infinity() : len.scale * len.root;
      if (std::isfinite(whole) && whole >= std::numeric_limits<T>::min()) {
        d[i] = alpha == 1 ? whole : std::pow(whole, alpha);  // the common case: as the contract writes it
      } else {
        // |dP|^alpha = scale^alpha root^alpha (2^alpha when halved): no intermediate overflow
        // or underflow, a few ulps.
        d[i] = std::pow(len.scale, alpha) * std::pow(len.root, alpha) * (len.halved ? std::exp2(alpha) : T(1));
      }
      if (!std::isfinite(d[i]) || d[i] < std::numeric_limits<T>::min()) {
        const bool over = !std::isfinite(d[i]) || d[i] > 1;
        throw InvalidArgument("points", "the knot interval |" + name(next) + " - " + name(i) + "|^alpha (alpha " + detail::format_number(alpha) + ") " +
                                            (over ? "overflows a double (above " + detail::format_number(std::numeric_limits<T>::max()) + ")"
                                                  : "= " + detail::format_number(d[i]) + " underflows a double (below the normal range, " +
                                                        detail::format_number(std::numeric_limits<T>::min()) +
                                                        ", where it would lose precision)") +
                                            ": the curve's parameter cannot be represented; scale the points, or use a smaller alpha");
      }
    }
    return d;
  }

  /// (P[b] - P[a]) / 2 when any difference of the segment overflows (sigma = 1/2), else
  /// P[b] - P[a] (sigma = 1): the control vectors are formed at that scale.
  static VectorType difference(const PointType& a, const PointType& b, T sigma) {
    return sigma == 1 ? b - a : T(0.5) * b.to_vector() - T(0.5) * a.to_vector();
  }

  /// The Bézier pieces. Segment a (P_a to P_b, interval d_a) has the inner control points
  /// P_a + d_a m_a / 3 and P_b - d_a m_b / 3, with the Catmull-Rom tangents m written
  /// through ratios of intervals only (no product of two intervals, which overflows or
  /// underflows for intervals beyond 1e154 or below 1e-154):
  ///   d_a m_a = w d_a (P_a - P_p) / d_p + (1 - w) (P_b - P_a), w = d_a / (d_p + d_a),
  ///   d_a m_b = (1 - v) (P_b - P_a) + v d_a (P_n - P_b) / d_n, v = d_a / (d_a + d_n),
  /// (p, n the neighbours), w = 1 / (1 + d_p / d_a) and v likewise. For alpha = 0 these are
  /// (P_b - P_p) / 2 and (P_n - P_a) / 2. Throws InvalidArgument("points") when the knots
  /// sum beyond the largest double or a control point overflows.
  static Pieces<T, D> build(const std::vector<PointType>& given, const std::vector<T>& d, bool closed, CatmullRomEnds ends) {
    const std::vector<PointType> P = working_points(given, ends);
    const auto name = [&](std::size_t i) { return point_name(i, P.size(), ends); };
    const std::size_t N = P.size();
    std::vector<BezierPiece<T, D>> segs;
    std::vector<T> breaks{T(0)};
    // Segment from P_a to P_b (indices mod N) with interval d_a, neighbours P_p, P_n.
    const auto add = [&](std::size_t p, std::size_t a, std::size_t b, std::size_t n) {
      const T dp = d[p], da = d[a], dn = d[b];  // the intervals before, of and after the segment
      const T w = 1 / (1 + dp / da), v = 1 / (1 + dn / da);
      T sigma = 1;
      for (const auto& [x, y] : {std::pair{p, a}, std::pair{a, b}, std::pair{b, n}})
        if (!detail::all_finite_point(P[y] - P[x])) sigma = T(0.5);
      const VectorType pa = difference(P[p], P[a], sigma), ab = difference(P[a], P[b], sigma), bn = difference(P[b], P[n], sigma);
      const VectorType out = (w * da) * (pa / dp) + (1 - w) * ab;  // d_a m_a (times sigma)
      const VectorType in = (1 - v) * ab + (v * da) * (bn / dn);   // d_a m_b (times sigma)
      const T third = 1 / (3 * sigma);
      const PointType c1 = P[a] + third * out, c2 = P[b] - third * in;
      if (!detail::all_finite_point(c1) || !detail::all_finite_point(c2)) {
        throw InvalidArgument("points", "the Bézier control points of the segment from " + name(a) + " to " + name(b) + " overflow a double");
      }
      segs.emplace_back(Bezier<T, D>({P[a], c1, c2, P[b]}));
      const T next = breaks.back() + da;
      if (!std::isfinite(next)) {
        throw InvalidArgument("points", "the knots s_i (sums of |P_(i+1) - P_i|^alpha) exceed the largest double at " + name(b) +
                                            ": the curve's parameter cannot be represented");
      }
      if (!(next > breaks.back())) {
        throw InvalidArgument(ends == CatmullRomEnds::reflect ? std::string("points") : name(b),
                              (ends == CatmullRomEnds::reflect ? "at " + name(b) + ", " : std::string()) + "the knot interval " +
                                  detail::format_number(da) + " vanishes next to the knot " + detail::format_number(breaks.back()));
      }
      breaks.push_back(next);
    };
    if (closed) {
      for (std::size_t j = 0; j < N; ++j) add((j + N - 1) % N, j, (j + 1) % N, (j + 2) % N);
    } else {
      for (std::size_t j = 1; j + 2 < N; ++j) add(j - 1, j, j + 1, j + 2);
    }
    return Pieces<T, D>(std::move(segs), std::move(breaks));
  }

  std::vector<PointType> P_;
  T alpha_;
  bool closed_;
  CatmullRomEnds ends_;
  std::vector<T> d_;
  bool follow_ = true;
  Pieces<T, D> pieces_;
};

/// The exact Bézier form: the cubic pieces built in the constructor.
template <class T, int D>
const Pieces<T, D>& pieces(const CatmullRom<T, D>& c) {
  return c.bezier_pieces();
}

static_assert(DifferentiableCurve<CatmullRom<double, 2>>);
static_assert(Curve<CatmullRom<double, 1>>);
static_assert(PiecewiseBezierCurve<CatmullRom<double, 2>>);

}  // namespace casteljau
