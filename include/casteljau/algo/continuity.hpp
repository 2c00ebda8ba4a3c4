// Continuity of composite curves at their joints (C0, C1, G1, C2, ..., Cr), and the
// construction of a next Bézier segment that joins the previous one with Cr.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/curves/path.hpp"

namespace casteljau {

/// The k-th derivative (k = 0: position) with respect to the path parameter on both
/// sides of interior break `joint` (1 <= joint <= k - 1 for k segments).
template <class T, int D>
struct JointDerivatives {
  Vector<T, D> left;   ///< from segment joint - 1 at its end
  Vector<T, D> right;  ///< from segment joint at its start
};

namespace detail {
template <class T, int D>
void require_joint(const Path<T, D>& p, std::size_t joint) {
  if (joint < 1 || joint >= p.size()) {
    throw InvalidArgument("joint", "must name an interior break 1.." + std::to_string(p.size() - 1) + ", got " +
                                       std::to_string(joint));
  }
}
}  // namespace detail

template <class T, int D>
JointDerivatives<T, D> joint_derivatives(const Path<T, D>& p, std::size_t joint, int k) {
  detail::require_joint(p, joint);
  if (k < 0) throw InvalidArgument("k", "derivative order must be >= 0, got " + std::to_string(k));
  return {p.one_sided_derivative(joint - 1, T(1), k), p.one_sided_derivative(joint, T(0), k)};
}

namespace detail {
template <class T>
void require_tolerance_nonnegative(T tolerance) {
  require_finite(tolerance, "tolerance");
  if (tolerance < 0) throw InvalidArgument("tolerance", "must be >= 0, got " + format_number(tolerance));
}
/// Whether the k-th derivatives on both sides of the joint agree within tolerance.
template <class T, int D>
bool order_matches(const Path<T, D>& p, std::size_t joint, int k, T tolerance) {
  const auto d = joint_derivatives(p, joint, k);
  return norm(d.left - d.right) <= tolerance;
}
}  // namespace detail

/// Whether the path is C^r at the joint: |left^(k) - right^(k)| <= tolerance for every
/// k = 0..r, the derivatives taken with respect to the path parameter (so for Bézier
/// segments of degrees n, m on intervals h, g: n!/(n-k)! Delta^k P_{n-k} / h^k against
/// m!/(m-k)! Delta^k Q_0 / g^k [Farin02, 7.1]). `tolerance` is absolute, in model units per
/// parameter unit^k.
template <class T, int D>
bool is_cr(const Path<T, D>& p, std::size_t joint, int r, T tolerance) {
  detail::require_tolerance_nonnegative(tolerance);
  if (r < 0) throw InvalidArgument("r", "continuity order must be >= 0, got " + std::to_string(r));
  for (int k = 0; k <= r; ++k) {
    if (!detail::order_matches(p, joint, k, tolerance)) return false;
  }
  return true;
}

/// The unit tangent at an end of a segment as the limit of c'/|c'|: the first non-zero
/// derivative c^(k) gives it, with sign (-1)^(k-1) when approaching from the left
/// (c'(t) ~ c^(k)(1) (t-1)^(k-1) / (k-1)!). nullopt for a segment that is a single point.
template <class T, int D>
std::optional<Vector<T, D>> end_tangent(const Path<T, D>& p, std::size_t segment, bool at_end) {
  for (int k = 1; k <= 64; ++k) {
    Vector<T, D> v = p.one_sided_derivative(segment, at_end ? T(1) : T(0), k);
    const T len = norm(v);
    if (len > 0) {
      v /= len;
      return (at_end && k % 2 == 0) ? -v : v;
    }
  }
  return std::nullopt;
}

/// Whether the path is G1 at the joint: positions within `tolerance` (model units) and
/// unit tangents within `angle_tolerance` of each other (|t_left - t_right|, about the
/// angle in radians for small angles). A segment collapsed to a point has no tangent and
/// fails the test.
template <class T, int D>
bool is_g1(const Path<T, D>& p, std::size_t joint, T tolerance, T angle_tolerance) {
  require_finite(angle_tolerance, "angle_tolerance");
  if (angle_tolerance < 0) {
    throw InvalidArgument("angle_tolerance", "must be >= 0, got " + detail::format_number(angle_tolerance));
  }
  if (!is_cr(p, joint, 0, tolerance)) return false;
  const auto a = end_tangent(p, joint - 1, true), b = end_tangent(p, joint, false);
  return a && b && norm(*a - *b) <= angle_tolerance;
}

/// The highest r <= max_order for which the joint is C^r (see is_cr), or -1 when even
/// the positions differ by more than tolerance.
template <class T, int D>
int parametric_continuity(const Path<T, D>& p, std::size_t joint, int max_order, T tolerance) {
  if (max_order < 0) throw InvalidArgument("max_order", "must be >= 0, got " + std::to_string(max_order));
  detail::require_tolerance_nonnegative(tolerance);
  int r = -1;  // each order compared once, lowest first
  while (r < max_order && detail::order_matches(p, joint, r + 1, tolerance)) ++r;
  return r;
}

/// The continuity found at one interior break of a path.
template <class T>
struct JointContinuity {
  std::size_t joint;  ///< index of the break, 1..k-1
  T parameter;        ///< the break t_joint
  int parametric;     ///< highest r <= max_order with C^r (see is_cr); -1 for a gap
  bool g1;            ///< G1 (see is_g1); true whenever parametric >= 1 and the tangent is defined
};

/// The continuity at every interior break of the path, in order: parametric_continuity up
/// to max_order and is_g1, with the same tolerances. Empty for a single segment.
template <class T, int D>
std::vector<JointContinuity<T>> joint_continuity(const Path<T, D>& p, int max_order, T tolerance, T angle_tolerance) {
  std::vector<JointContinuity<T>> out;
  for (std::size_t j = 1; j < p.size(); ++j) {
    out.push_back({j, p.breaks()[j], parametric_continuity(p, j, max_order, tolerance),
                   is_g1(p, j, tolerance, angle_tolerance)});
  }
  return out;
}

/// The first r + 1 control points Q_0..Q_r of a degree-m Bézier segment on an interval of
/// length g that joins `previous` (on an interval of length h) with C^r: derivative k of
/// the new segment at its start equals that of the previous one at its end, so
/// m!/(m-k)! Delta^k Q_0 / g^k = D_k, solved for Q_k one k at a time [Farin02, 7.1].
/// Requires 0 <= r <= m. The remaining m - r points are free.
template <class T, int D>
std::vector<Point<T, D>> cr_join_points(const Bezier<T, D>& previous, T h, int m, T g, int r) {
  require_finite(h, "previous_length");
  require_finite(g, "next_length");
  if (!(h > 0)) throw InvalidArgument("previous_length", "must be > 0, got " + detail::format_number(h));
  if (!(g > 0)) throw InvalidArgument("next_length", "must be > 0, got " + detail::format_number(g));
  if (r < 0 || r > m) {
    throw InvalidArgument("r", "continuity order must lie in [0, degree = " + std::to_string(m) + "], got " + std::to_string(r));
  }
  std::vector<Point<T, D>> Q;
  Q.push_back(previous(T(1)));
  for (int k = 1; k <= r; ++k) {
    // Required: Delta^k Q_0 = D_k (g / h)^k (m-k)!/m!, D_k being the previous segment's
    // derivative in its own parameter (D_k / h^k is the path derivative).
    Vector<T, D> delta = previous.derivative_at(T(1), k);
    for (int j = 0; j < k; ++j) delta *= g / h / static_cast<T>(m - j);
    // Delta^k Q_0 = sum_{i<=k} (-1)^(k-i) C(k,i) Q_i. The coefficients sum to 0 for k >= 1,
    // so offsets e_i = Q_i - Q_0 may replace the points (e_0 = 0):
    // e_k = Delta^k Q_0 - sum_{i<k} (-1)^(k-i) C(k,i) e_i.
    Vector<T, D> rest{};
    for (int i = 0; i < k; ++i) {
      const T coef = binomial<T>(k, i) * (((k - i) % 2 == 0) ? T(1) : T(-1));
      rest += coef * (Q[static_cast<std::size_t>(i)] - Q[0]);
    }
    Q.push_back(Q[0] + (delta - rest));
  }
  return Q;
}

}  // namespace casteljau
