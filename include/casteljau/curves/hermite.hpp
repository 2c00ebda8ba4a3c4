// Piecewise cubic Hermite curves: points and derivatives given at parameters u_0 < ... <
// u_n, one cubic per interval, and their exact Bézier pieces.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/basis/hermite_basis.hpp"
#include "casteljau/curves/hermite_kernels.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

namespace detail {
/// Whether every coordinate of v is finite: the cheap test, so that the message (and its
/// string) is built only for the element that fails.
template <class V>
bool all_coordinates_finite(const V& v) {
  for (int d = 0; d < V::dimension; ++d)
    if (!std::isfinite(v[d])) return false;
  return true;
}
/// Tag of the constructors that skip the invariant checks (the caller has made them).
struct Unchecked {};

/// (b - a) / h (h > 0) without overflow in the difference: when b - a overflows (points
/// near the largest double, of opposite signs) it is formed at half scale, ((b/2 - a/2) /
/// h) 2. Non-finite only when the slope itself overflows.
template <class T, int D>
Vector<T, D> slope(const Point<T, D>& a, const Point<T, D>& b, T h) {
  const Vector<T, D> v = b - a;
  if (all_coordinates_finite(v)) [[likely]]
    return v / h;
  return ((T(0.5) * b.to_vector() - T(0.5) * a.to_vector()) / h) * T(2);
}
}  // namespace detail

/// The piecewise cubic Hermite curve through P_0..P_n at the parameters u_0 < ... < u_n
/// (n >= 1): on [u_i, u_(i+1)], with h = u_(i+1) - u_i and t = (u - u_i) / h,
///   C(u) = h00(t) P_i + h01(t) P_(i+1) + h (h10(t) m_i + h11(t) m'_(i+1))
/// (basis/hermite_basis.hpp), so that C(u_i) = P_i, C'(u_i) = m_i (the outgoing tangent)
/// and C'(u_(i+1)-) = m'_(i+1) (the incoming tangent at the piece's end). Tangents are
/// derivatives with respect to the parameter u. Usually m' = m (one tangent per point,
/// the curve is C^1); Kochanek-Bartels continuity gives one-sided tangents (a corner).
/// Its exact Bézier form on each interval is P_i, P_i + h m_i / 3, P_(i+1) - h m'_(i+1) / 3,
/// P_(i+1) [Farin02, 7.5]. At a parameter inside the domain the right piece answers
/// (points and derivatives), at u_n the last one; outside the domain the first or last
/// cubic is extrapolated. Invariants (checked in the constructors, naming the field):
/// n + 1 >= 2 finite, strictly increasing params with a finite domain length, one finite
/// point and one finite tangent (of each side) per param.
template <class T, int D>
class Hermite {
 public:
  using Scalar = T;
  using PointType = Point<T, D>;
  using VectorType = Vector<T, D>;
  static constexpr int dimension = D;

  /// One tangent per point. Throws InvalidArgument naming "params", "params[i]",
  /// "points", "points[i][j]", "tangents", "tangents[i][j]".
  Hermite(std::vector<T> params, std::vector<PointType> points, std::vector<VectorType> tangents)
      : u_(std::move(params)), P_(std::move(points)), out_(std::move(tangents)) {
    validate(false);
    index_params();
  }

  /// One tangent per point, without the checks: for constructions (CubicSpline) that have
  /// already established every invariant above while computing the tangents, so that a
  /// spline through 10^6 points is not scanned twice.
  Hermite(detail::Unchecked, std::vector<T> params, std::vector<PointType> points, std::vector<VectorType> tangents)
      : u_(std::move(params)), P_(std::move(points)), out_(std::move(tangents)) {
    index_params();
  }

  /// One-sided tangents: `incoming[i]` is the derivative at u_i from the left (the end of
  /// piece i - 1), `outgoing[i]` the one from the right (the start of piece i).
  /// incoming[0] and outgoing[n] belong to no piece: they are kept as given (and must be
  /// finite). Throws as the other constructor, naming "incoming_tangents" and
  /// "tangents" (the outgoing ones).
  Hermite(std::vector<T> params, std::vector<PointType> points, std::vector<VectorType> incoming, std::vector<VectorType> outgoing)
      : u_(std::move(params)), P_(std::move(points)), in_(std::move(incoming)), out_(std::move(outgoing)) {
    validate(true);
    index_params();
    if (in_ == out_) in_.clear();  // one tangent per point after all: one representation
  }

  [[nodiscard]] const std::vector<T>& params() const { return u_; }
  [[nodiscard]] const std::vector<PointType>& points() const { return P_; }
  /// The outgoing tangents m_i (the only tangents unless one_sided()).
  [[nodiscard]] const std::vector<VectorType>& tangents() const { return out_; }
  /// The incoming tangents m'_i.
  [[nodiscard]] const std::vector<VectorType>& incoming_tangents() const { return in_.empty() ? out_ : in_; }
  /// Whether some interior point has different incoming and outgoing tangents (a corner
  /// unless they are parallel). The pieces use the outgoing tangents at u_0..u_(n-1) and
  /// the incoming ones at u_1..u_n; incoming[0] and outgoing[n] play no part.
  [[nodiscard]] bool one_sided() const {
    if (in_.empty()) return false;
    for (std::size_t i = 1; i + 1 < P_.size(); ++i)
      if (!(in_[i] == out_[i])) return true;
    return false;
  }
  /// The number of cubic pieces, n.
  [[nodiscard]] std::size_t size() const { return u_.size() - 1; }
  [[nodiscard]] Interval<T> domain() const { return {u_.front(), u_.back()}; }

  /// The piece that answers at u: i with u_i <= u < u_(i+1), the last piece at u_n and
  /// beyond, the first one before u_0. O(log n), in two branch-free binary searches: over
  /// every 64th param (a copy of 1/64 of them, made by the constructors, which stays in
  /// the cache), then over the 63 params of the block found, whose cache lines are all
  /// requested at once. The comparisons select by conditional moves, not jumps, so that
  /// no mispredicted branch stalls a step [KhuongMorin17]; on 10^6 params this takes
  /// one wait for memory instead of one for each of the last 6 to 10 halvings. NaN gives 0.
  [[nodiscard]] std::size_t segment_index(T u) const {
    if constexpr (detail::hermite_compiled<T, D>) {
      return detail::hermite_segment_index(arrays(), u);
    } else {
      const Block b = coarse_block(u);
      return b.start + count_at_most(u_.data() + b.start + 1, b.len, u);
    }
  }

  /// C(u) for any finite u: the Hermite form of the piece (exact at the params: h00, h01
  /// are exactly 0 or 1 there), written about the nearer end so that the point
  /// differences, not the coordinates, carry the rounding. Error a few eps of max(|P|,
  /// h |m|) inside the domain. Throws InvalidArgument("t", ...) for a non-finite u or a
  /// value that overflows. Cost O(log n).
  [[nodiscard]] PointType operator()(T u) const {
    if (!std::isfinite(u)) require_finite(u, "t");  // the call (and its string) only to throw
    if constexpr (detail::hermite_compiled<T, D>) {  // the search and the point in one call
      PointType p;
      std::size_t i = 0;
      if (!detail::hermite_point(arrays(), u, reinterpret_cast<double*>(&p), &i)) [[unlikely]]
        repair(u_.data(), P_.data(), out_.data(), in_.empty() ? out_.data() : in_.data(), &i, &u, &p, 1);
      return p;
    } else {
      return point_on(segment_index(u), u);
    }
  }

  /// The k-th derivative (k >= 0) with respect to u: the point for k = 0, zero for k > 3;
  /// the right piece answers at an interior param, the last at u_n. For k >= 1,
  /// ((P_(i+1) - P_i) / h h01^(k)(t) + m_i h10^(k)(t) + m'_(i+1) h11^(k)(t)) / h^(k-1).
  [[nodiscard]] VectorType derivative_at(T u, int k = 1) const {
    require_finite(u, "t");
    if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
    if (k == 0) return (*this)(u).to_vector();
    if (k > 3) return VectorType{};
    return derivative_on(segment_index(u), u, k);
  }

  /// The points at the parameters u (any finite values), found by a linear merge: when u
  /// is sorted the cost is O(n + len(u)) instead of O(len(u) log n); an unsorted value
  /// falls back to the binary search (correct for any order). Throws as operator().
  [[nodiscard]] std::vector<PointType> evaluate_sorted(std::span<const T> u) const {
    std::vector<PointType> out(u.size());
    evaluate_sorted(u, std::span<PointType>(out));
    return out;
  }

  /// The same into caller storage (out.size() == u.size(), else InvalidArgument("out")),
  /// so that repeated batches allocate nothing; out's content is unspecified after a
  /// throw. The batch is cut into four consecutive runs merged side by side, one cursor
  /// each, so that the processor overlaps four independent merge chains. The runs go by
  /// chunks of 64 queries, in three passes per chunk: a check that the 4 x 64 queries are
  /// finite (one vectorisable pass over data about to be used anyway); the merge, which
  /// finds the pieces; the Hermite forms, independent of one another and four at a time
  /// (the kernel of operator(), so the same values bit for bit), so that their divisions
  /// and products do not wait behind the merge chains. A merge step advances
  /// the cursor by counting: the params are sorted, so the number of u_(i+1..i+4) that are
  /// <= x is the step when it is below 4, computed from four independent comparisons
  /// without a jump (the step between sorted queries is data-dependent, 0 to 3 pieces on
  /// W4, where a loop's exit was mispredicted); only a step of 4 or more continues in a
  /// loop (3.5% of the steps on W4, about one query per piece). A non-finite query throws
  /// InvalidArgument("t") for the first one of the batch, before any merge step uses it.
  void evaluate_sorted(std::span<const T> u, std::span<PointType> out) const {
    check_out_size(u.size(), out.size());
    const std::size_t last = size() - 1;
    const T* const uu = u_.data();
    const PointType* const P = P_.data();
    const VectorType* const mo = out_.data();
    const VectorType* const mi = in_.empty() ? mo : in_.data();
    constexpr std::size_t look = 4;  // params compared per merge step
    // One merge step from the cursor i for a finite x: a binary search when x is behind it
    // (an unsorted query, or the first of a run), else the count of the next params <= x.
    const auto advance = [&](T x, std::size_t i) {
      if (x < uu[i]) [[unlikely]] {
        i = segment_index(x);
      } else if (i + look <= last) [[likely]] {
        std::size_t step = 0;
        for (std::size_t j = 1; j <= look; ++j) step += static_cast<std::size_t>(x >= uu[i + j]);
        i += step;
        if (step == look) [[unlikely]]
          while (i < last && x >= uu[i + 1]) ++i;
      } else {
        while (i < last && x >= uu[i + 1]) ++i;
      }
      return i;
    };
    const auto evaluate = [&](const std::size_t* pieces, std::size_t first, std::size_t count) {
      if (!points_of(uu, P, mo, mi, pieces, u.data() + first, out.data() + first, count)) [[unlikely]]
        repair(uu, P, mo, mi, pieces, u.data() + first, out.data() + first, count);
    };
    const auto require_all_finite = [&](std::size_t first, std::size_t count) {
      bool finite = true;
      for (std::size_t k = first; k < first + count; ++k) finite &= std::abs(u[k]) <= std::numeric_limits<T>::max();
      if (!finite) [[unlikely]] {
        for (std::size_t k = 0; k < u.size(); ++k) require_finite(u[k], "t");  // throws at the first one
      }
    };
    constexpr std::size_t chunk = 64;
    std::size_t piece[4][chunk];
    const std::size_t len = u.size() / 4;
    const auto start = [&](std::size_t k) { return k < u.size() && std::isfinite(u[k]) ? segment_index(u[k]) : 0; };
    // The four cursors in locals, not an array: the merge chains then do not pass through
    // memory (store-to-load forwarding added about 4% on W4).
    std::size_t c0 = start(0), c1 = start(len), c2 = start(2 * len), c3 = start(3 * len);
    const T* const x0 = u.data();
    const T* const x1 = x0 + len;
    const T* const x2 = x1 + len;
    const T* const x3 = x2 + len;
    for (std::size_t k0 = 0; k0 < len; k0 += chunk) {
      const std::size_t c = std::min(chunk, len - k0);
      for (std::size_t r = 0; r < 4; ++r) require_all_finite(r * len + k0, c);
      for (std::size_t k = k0; k < k0 + c; ++k) {
        piece[0][k - k0] = c0 = advance(x0[k], c0);
        piece[1][k - k0] = c1 = advance(x1[k], c1);
        piece[2][k - k0] = c2 = advance(x2[k], c2);
        piece[3][k - k0] = c3 = advance(x3[k], c3);
      }
      for (std::size_t r = 0; r < 4; ++r) evaluate(piece[r], r * len + k0, c);
    }
    const std::size_t tail = u.size() - 4 * len;  // 0 to 3 queries
    require_all_finite(4 * len, tail);
    for (std::size_t k = 0; k < tail; ++k) piece[0][k] = c3 = advance(u[4 * len + k], c3);
    evaluate(piece[0], 4 * len, tail);
  }

  /// The points at the parameters u in any order (random queries), into caller storage
  /// (out.size() == u.size(), else InvalidArgument("out")); the same values as operator()
  /// at each u, bit for bit. For 10^6 params a lone query waits for memory twice in a row
  /// (the block of params, then the piece's point and tangents); here the queries go in
  /// groups of 16 through three stages, each stage issuing the prefetches the next one
  /// needs for all 16 before using any: the coarse search (cache-resident) and a prefetch
  /// of the block, the search in the block and a prefetch of the piece, the Hermite form.
  /// So the misses of 16 queries overlap instead of queuing (software pipelining of
  /// independent searches, the batch form of [KhuongMorin17]'s prefetching; compiled in
  /// src/hermite for double at dimensions 1..4, the other scalars search one query at a
  /// time). Throws as operator(); out's content is unspecified after a throw.
  void evaluate(std::span<const T> u, std::span<PointType> out) const {
    check_out_size(u.size(), out.size());
    constexpr std::size_t group = 16;
    const T* const uu = u_.data();
    const PointType* const P = P_.data();
    const VectorType* const mo = out_.data();
    const VectorType* const mi = in_.empty() ? mo : in_.data();
    std::size_t piece[group];
    for (std::size_t k0 = 0; k0 < u.size(); k0 += group) {
      const std::size_t g = std::min(group, u.size() - k0);
      const T* const x = u.data() + k0;
      for (std::size_t j = 0; j < g; ++j)
        if (!std::isfinite(x[j])) require_finite(x[j], "t");  // the call (and its string) only to throw
      if constexpr (detail::hermite_compiled<T, D>) {
        detail::hermite_locate(arrays(), x, g, piece);
      } else {
        for (std::size_t j = 0; j < g; ++j) piece[j] = segment_index(x[j]);
      }
      if (!points_of(uu, P, mo, mi, piece, x, out.data() + k0, g)) [[unlikely]]
        repair(uu, P, mo, mi, piece, x, out.data() + k0, g);
    }
  }

  /// Piece i (0 <= i < n) as a cubic Bézier curve on [0, 1] (its own parameter t).
  [[nodiscard]] Bezier<T, D> piece(std::size_t i) const {
    const T h3 = (u_[i + 1] - u_[i]) / 3;
    return Bezier<T, D>({P_[i], P_[i] + h3 * out_[i], P_[i + 1] - h3 * incoming(i + 1), P_[i + 1]});
  }

  /// The same curve traversed backwards on the same domain: u -> u_0 + u_n - u; params
  /// reflected, points reversed, tangents reversed and negated (incoming and outgoing
  /// swap roles).
  [[nodiscard]] Hermite reverse() const {
    const std::size_t m = u_.size();
    std::vector<T> v(m);
    std::vector<PointType> Q(P_.rbegin(), P_.rend());
    std::vector<VectorType> in(in_.empty() ? 0 : m), out(m);
    for (std::size_t i = 0; i < m; ++i) {
      v[i] = u_.front() + u_.back() - u_[m - 1 - i];
      out[i] = -incoming(m - 1 - i);
      if (!in_.empty()) in[i] = -out_[m - 1 - i];
    }
    v.front() = u_.front();  // exact ends despite rounding
    v.back() = u_.back();
    if (in_.empty()) return Hermite(std::move(v), std::move(Q), std::move(out));
    return Hermite(std::move(v), std::move(Q), std::move(in), std::move(out));
  }

  /// The image under an affine map: points mapped, tangents mapped by the linear part.
  [[nodiscard]] Hermite transform(const Affine<T, D>& m) const {
    std::vector<VectorType> in(in_.size()), out(out_.size());
    for (std::size_t i = 0; i < out_.size(); ++i) out[i] = m(out_[i]);
    for (std::size_t i = 0; i < in_.size(); ++i) in[i] = m(in_[i]);
    if (in_.empty()) return Hermite(u_, mapped_points(m, P_), std::move(out));
    return Hermite(u_, mapped_points(m, P_), std::move(in), std::move(out));
  }

  /// The box of the Bézier control points of every piece: contains the curve over its
  /// domain (convex hull property of each piece).
  [[nodiscard]] Box<T, D> control_bounds() const {
    Box<T, D> b = Box<T, D>::empty_box();
    for (std::size_t i = 0; i < size(); ++i) b.add(box_of<T, D>(piece(i).points()));
    return b;
  }

  friend bool operator==(const Hermite&, const Hermite&) = default;

 private:
  /// The batch calls' size check: one output point per parameter (InvalidArgument "out").
  static void check_out_size(std::size_t params, std::size_t room) {
    if (room != params) {
      throw InvalidArgument("out", "needs one point per parameter: " + std::to_string(params) + " parameters but room for " +
                                       std::to_string(room));
    }
  }
  PointType point_on(std::size_t i, T u) const {
    PointType p;
    const VectorType* mi = in_.empty() ? out_.data() : in_.data();
    if (!points_of(u_.data(), P_.data(), out_.data(), mi, &i, &u, &p, 1)) [[unlikely]]
      repair(u_.data(), P_.data(), out_.data(), mi, &i, &u, &p, 1);
    return p;
  }

  /// points_of's failure: each query of out[0..count) whose point is not finite is
  /// computed again at half scale (P_near / 2 + (w (P_far / 2 - P_near / 2) + h (h10 m /
  /// 2 + h11 m' / 2)), then doubled), which the kernel's differences of coordinates near
  /// the largest double (of opposite signs) overflow although the point does not; the
  /// first one still not finite throws.
  [[gnu::cold, gnu::noinline]] static void repair(const T* uu, const PointType* P, const VectorType* mo, const VectorType* mi,
                                                  const std::size_t* piece, const T* u, PointType* out, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      if (detail::all_coordinates_finite(out[k])) continue;
      const std::size_t i = piece[k];
      const T h = uu[i + 1] - uu[i];
      const T t = (u[k] - uu[i]) / h;
      const HermiteBasis<T> b = hermite_basis(t, 0);
      const bool left = t <= T(0.5);
      const VectorType near = T(0.5) * P[left ? i : i + 1].to_vector(), far = T(0.5) * P[left ? i + 1 : i].to_vector();
      const VectorType half = near + ((left ? b.h01 : b.h00) * (far - near) + h * (b.h10 * (T(0.5) * mo[i]) + b.h11 * (T(0.5) * mi[i + 1])));
      out[k] = PointType::from_vector(T(2) * half);
      if (!detail::all_coordinates_finite(out[k])) overflow_error(u[k], "the curve's point");
    }
  }

  /// The points at u[0..count) of the pieces piece[0..count) into out, from raw arrays
  /// (params, points, outgoing and incoming tangents); returns whether all are finite.
  /// The one kernel of operator() (count 1), evaluate and evaluate_sorted, so that they
  /// agree bit for bit whatever the compiler contracts into fused multiply-adds. For
  /// double at dimensions 1..4 it is compiled in src/hermite (four queries per vector, the
  /// instruction set chosen at run time); otherwise point_of per query, not inlined: one
  /// compiled body, hence one rounding, for every caller.
  static bool points_of(const T* uu, const PointType* P, const VectorType* mo, const VectorType* mi, const std::size_t* piece, const T* u,
                        PointType* out, std::size_t count) {
    if constexpr (detail::hermite_compiled<T, D>) {
      const detail::HermiteArrays c{uu, 0, nullptr, 0, coordinates(P), coordinates(mo), coordinates(mi), D};
      return detail::hermite_points(c, piece, u, reinterpret_cast<double*>(out), count);
    } else {
      return points_of_portable(uu, P, mo, mi, piece, u, out, count);
    }
  }
  [[gnu::noinline]] static bool points_of_portable(const T* uu, const PointType* P, const VectorType* mo, const VectorType* mi,
                                                   const std::size_t* piece, const T* u, PointType* out, std::size_t count) {
    bool ok = true;
    for (std::size_t k = 0; k < count; ++k) {
      out[k] = point_of(uu, P, mo, mi, piece[k], u[k]);
      ok &= detail::all_coordinates_finite(out[k]);
    }
    return ok;
  }

  /// The coordinates of an array of points or vectors as plain doubles (D per entry).
  template <class V>
  static const double* coordinates(const V* v) {
    static_assert(sizeof(V) == D * sizeof(double) && std::is_standard_layout_v<V>);
    return reinterpret_cast<const double*>(v);
  }
  /// The curve's arrays for the compiled kernels (double only).
  detail::HermiteArrays arrays() const {
    const VectorType* mi = in_.empty() ? out_.data() : in_.data();
    return {u_.data(), u_.size(), coarse_.data(), coarse_.size(), coordinates(P_.data()), coordinates(out_.data()), coordinates(mi), D};
  }

  /// The point at u of piece i, one query at a time: points_of's kernel for the scalars and
  /// dimensions that src/hermite does not compile (its lanes take the same expressions).
  static PointType point_of(const T* uu, const PointType* P, const VectorType* mo, const VectorType* mi, std::size_t i, T u) {
    const T h = uu[i + 1] - uu[i];
    const T t = (u - uu[i]) / h;  // exactly 1 at u = u_(i+1): the same rounded h
    const HermiteBasis<T> b = hermite_basis(t, 0);
    const VectorType tangent_part = h * (b.h10 * mo[i] + b.h11 * mi[i + 1]);
    // Selections by index rather than a branch (t <= 1/2 is unpredictable for random or
    // sorted queries; GCC compiled the conditional operator on references into a jump).
    const std::size_t right = static_cast<std::size_t>(!(t <= T(0.5)));
    const PointType& near = P[i + right];
    const PointType& far = P[i + 1 - right];
    const T weight[2] = {b.h01, b.h00};  // of the far point
    return near + (weight[right] * (far - near) + tangent_part);
  }

  VectorType derivative_on(std::size_t i, T u, int k) const {
    const T h = u_[i + 1] - u_[i];
    const T t = (u - u_[i]) / h;
    const HermiteBasis<T> b = hermite_basis(t, k);
    VectorType v = b.h01 * detail::slope(P_[i], P_[i + 1], h) + b.h10 * out_[i] + b.h11 * incoming(i + 1);
    for (int j = 1; j < k; ++j) v /= h;
    check_representable(v, u, "the derivative");
    return v;
  }

  template <class V>
  static void check_representable(const V& v, T u, const char* what) {
    if (!detail::all_coordinates_finite(v)) overflow_error(u, what);
  }

  /// Out of line, so that the evaluation loops carry no string code.
  [[noreturn, gnu::cold, gnu::noinline]] static void overflow_error(T u, const char* what) {
    throw InvalidArgument("t", std::string(what) + " at t = " + detail::format_number(u) + " overflows a double");
  }

  static constexpr std::size_t stride = detail::hermite_stride;  ///< params per entry of coarse_

  /// The answer of segment_index(u) lies in [start, start + len]: start + the number of
  /// u_(start+1..start+len) that are <= u. Found in coarse_ (which stays in the cache).
  /// The portable search of the scalars src/hermite does not compile; the compiled one
  /// also prefetches the block's cache lines, so that its search waits for memory once.
  struct Block {
    std::size_t start, len;
  };
  Block coarse_block(T u) const {
    const std::size_t m = count_at_most(coarse_.data(), coarse_.size(), u);  // coarse_[j] = u_(64 j)
    if (m == 0) return {0, 0};  // before u_0
    const std::size_t start = stride * (m - 1);  // u_start <= u (< u_(start + 64) if sampled)
    const std::size_t stop = std::min(start + stride, u_.size() - 1);  // interior params below stop
    return {start, stop - start - 1};
  }

  /// The number of first[0..len) that are <= x (first sorted): a branch-free binary search
  /// keeping [base, base + len] around the answer (src/hermite's also prefetches the two
  /// possible next probes).
  static std::size_t count_at_most(const T* first, std::size_t len, T x) {
    if (len == 0) return 0;
    const T* base = first;
    while (len > 1) {
      const std::size_t half = len / 2;
      len -= half;
      base = base[half] <= x ? base + half : base;
    }
    return static_cast<std::size_t>(base - first) + (*base <= x ? 1 : 0);
  }

  /// Fills coarse_ with u_0, u_64, u_128, ... up to u_(n-1) (the interior's last param).
  void index_params() {
    coarse_.clear();
    coarse_.reserve((u_.size() - 2) / stride + 1);
    for (std::size_t j = 0; j + 1 < u_.size(); j += stride) coarse_.push_back(u_[j]);
  }

  /// The incoming tangent at u_i (the outgoing one unless one-sided tangents were given).
  const VectorType& incoming(std::size_t i) const { return in_.empty() ? out_[i] : in_[i]; }

  void validate(bool check_incoming) const {
    if (u_.size() < 2) throw InvalidArgument("params", "a Hermite curve needs at least 2 params, got " + std::to_string(u_.size()));
    for (std::size_t i = 0; i < u_.size(); ++i) {
      if (std::isfinite(u_[i]) && (i == 0 || u_[i] > u_[i - 1])) continue;  // no string unless it fails
      const std::string where = "params[" + std::to_string(i) + "]";
      require_finite(u_[i], where);
      throw InvalidArgument(where, "params must be strictly increasing (" + detail::format_number(u_[i]) + " after " +
                                       detail::format_number(u_[i - 1]) + ")");
    }
    if (!std::isfinite(u_.back() - u_.front())) {
      throw InvalidArgument("params", "the domain [" + detail::format_number(u_.front()) + ", " + detail::format_number(u_.back()) +
                                          "] is longer than the largest double");
    }
    const auto count = [&](std::size_t got, const char* field, const char* noun) {
      if (got != u_.size()) {
        throw InvalidArgument(field, "needs one " + std::string(noun) + " per param: " + std::to_string(u_.size()) + " params but " +
                                         std::to_string(got) + " " + noun + "s");
      }
    };
    count(P_.size(), "points", "point");
    count(out_.size(), "tangents", "tangent");
    if (check_incoming) count(in_.size(), "incoming_tangents", "tangent");
    for (std::size_t i = 0; i < P_.size(); ++i)
      if (!detail::all_coordinates_finite(P_[i])) require_finite_point(P_[i], "points[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < out_.size(); ++i)
      if (!detail::all_coordinates_finite(out_[i])) require_finite_point(out_[i], "tangents[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < in_.size(); ++i)
      if (!detail::all_coordinates_finite(in_[i])) require_finite_point(in_[i], "incoming_tangents[" + std::to_string(i) + "]");
    // The Bézier form must exist too: P_i + h m_i / 3 and P_(i+1) - h m'_(i+1) / 3 finite.
    for (std::size_t i = 0; i + 1 < u_.size(); ++i) {
      const T h3 = (u_[i + 1] - u_[i]) / 3;
      const PointType a = P_[i] + h3 * out_[i], b = P_[i + 1] - h3 * incoming(i + 1);
      for (int d = 0; d < D; ++d) {
        if (!std::isfinite(a[d]) || !std::isfinite(b[d])) {
          throw InvalidArgument("tangents[" + std::to_string(std::isfinite(a[d]) ? i + 1 : i) + "]",
                                "the tangent times the param spacing overflows a double");
        }
      }
    }
  }

  std::vector<T> u_;
  std::vector<PointType> P_;
  std::vector<VectorType> in_;  ///< empty when equal to out_ (one tangent per point)
  std::vector<VectorType> out_;
  std::vector<T> coarse_;  ///< u_0, u_64, u_128, ... < u_n: the first level of segment_index
};

/// The exact Bézier pieces: one cubic per interval, breaks at the params.
template <class T, int D>
Pieces<T, D> pieces(const Hermite<T, D>& c) {
  std::vector<BezierPiece<T, D>> segs;
  segs.reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) segs.emplace_back(c.piece(i));
  return Pieces<T, D>(std::move(segs), c.params());
}

static_assert(DifferentiableCurve<Hermite<double, 2>>);
static_assert(Curve<Hermite<double, 1>>);
static_assert(PiecewiseBezierCurve<Hermite<double, 2>>);

}  // namespace casteljau
