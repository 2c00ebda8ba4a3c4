// Rotation-minimizing frames of a space curve sampled at increasing parameters, by the
// double reflection method [WangJuttlerZhengLiu08]. Plain arrays in, plain arrays out:
// not templated on curve types (the samples come from any curve's evaluation); templated
// on the scalar T (deduced from r0).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/core/error.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau {

namespace detail {

/// One double-reflection step [WangJuttlerZhengLiu08]: the normal r at (x0, t0) carried to
/// (x1, t1), re-projected onto the plane normal to t1 and normalised.
template <class T>
Vector<T, 3> double_reflection(const Vector<T, 3>& x0, const Vector<T, 3>& x1, const Vector<T, 3>& t0,
                               const Vector<T, 3>& t1, const Vector<T, 3>& r) {
  const Vector<T, 3> v1 = x1 - x0;
  const T c1 = dot(v1, v1);
  Vector<T, 3> rl = r, tl = t0;
  if (c1 > 0) {
    rl = rl - (2 / c1 * dot(v1, rl)) * v1;
    tl = tl - (2 / c1 * dot(v1, tl)) * v1;
  }
  const Vector<T, 3> v2 = t1 - tl;
  const T c2 = dot(v2, v2);
  Vector<T, 3> next = rl;
  if (c2 > 0) next = next - (2 / c2 * dot(v2, rl)) * v2;
  next = next - dot(next, t1) * t1;
  const T len = norm(next);
  return len > 0 ? next / len : next;
}

/// The normal r at a tangent t0 turned by the smallest rotation that takes t0 to t1 (both
/// unit; about t0 x t1), re-projected onto the plane normal to t1 and normalised: the
/// frame carried across a break of a curve, where the point or the tangent may jump. For
/// opposite tangents (no smallest rotation) r is kept.
template <class T>
Vector<T, 3> turn_at_break(const Vector<T, 3>& t0, const Vector<T, 3>& t1, const Vector<T, 3>& r) {
  const Vector<T, 3> k(t0[1] * t1[2] - t0[2] * t1[1], t0[2] * t1[0] - t0[0] * t1[2], t0[0] * t1[1] - t0[1] * t1[0]);
  const T c = dot(t0, t1);
  Vector<T, 3> next = r;
  if (c > T(-1) + T(1e-12)) {  // Rodrigues with the unnormalised axis k = t0 x t1, |k| = sin
    const Vector<T, 3> kr(k[1] * r[2] - k[2] * r[1], k[2] * r[0] - k[0] * r[2], k[0] * r[1] - k[1] * r[0]);
    next = c * r + kr + (dot(k, r) / (1 + c)) * k;
  }
  next = next - dot(next, t1) * t1;
  const T len = norm(next);
  return len > 0 ? next / len : next;
}

}  // namespace detail

/// The rotation-minimizing normals r_0..r_(n-1) at n samples of a curve: points x_i and
/// unit tangents t_i, in the order of increasing parameter, from r0 (a unit vector normal
/// to t_0). Each step is the double reflection of [WangJuttlerZhengLiu08]: reflect r_i and
/// t_i in the plane bisecting x_i x_(i+1) (v1 = x_(i+1) - x_i), then reflect in the plane
/// that takes the reflected tangent to t_(i+1) (v2 = t_(i+1) - t_i^L); a reflection whose
/// vector is zero is skipped (two equal samples, or a tangent already in place). The
/// global error is O(h^4) in the step h (fourth order: halving the step divides it by
/// about 16). Each r_(i+1) is then projected onto the plane normal to t_(i+1) and
/// normalised, so rounding does not accumulate out of the normal plane. Cost O(n).
/// Throws InvalidArgument("tangents", ...) when the sizes differ.
template <class T>
std::vector<Vector<T, 3>> rotation_minimizing_normals(std::type_identity_t<std::span<const Vector<T, 3>>> x,
                                                      std::type_identity_t<std::span<const Vector<T, 3>>> tangents,
                                                      const Vector<T, 3>& r0) {
  if (x.size() != tangents.size()) {
    throw InvalidArgument("tangents", "needs one tangent per point: " + std::to_string(x.size()) + " points, " +
                                          std::to_string(tangents.size()) + " tangents");
  }
  std::vector<Vector<T, 3>> r;
  if (x.empty()) return r;
  r.reserve(x.size());
  r.push_back(r0);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    r.push_back(detail::double_reflection(x[i], x[i + 1], tangents[i], tangents[i + 1], r[i]));
  }
  return r;
}

/// The rotation-minimizing normals at the increasing parameters t of a curve, from r0 (a
/// unit vector normal to the tangent at t[0]), carried by double reflection along an
/// internal grid that depends on the curve, not on t: breaks b_0 < ... < b_k cut the
/// parameter line into segments (a curve's piece breaks, the first and last extended to
/// cover t); each segment overlapping [t[0], t[n-1]] gets m uniform steps, m = 8, 16,
/// ... doubled until the normal carried across the whole segment by m and by m / 2 steps
/// differ by less than `tolerance` (an angle, radians), at most max_steps (a cusp or a
/// jump inside a segment need not converge). The method is fourth order, so the m-step
/// transport across a segment is then within about tolerance / 15 of the exact one. The
/// grid points inside (t[0], t[n-1]) and the t themselves are then marched in one pass.
/// A requested t adds a grid point, which changes the frames by less than the tolerance,
/// so the frame at a parameter does not depend on which other t are asked (beyond that).
/// sample(u, x, tangents) fills the points and unit tangents at the increasing
/// parameters u (a std::vector<T>). Cost: O(sum of m) samples.
template <class T, class Sample>
std::vector<Vector<T, 3>> rotation_minimizing_normals_at(Sample&& sample, std::type_identity_t<std::span<const T>> breaks,
                                                         std::type_identity_t<std::span<const T>> t,
                                                         const Vector<T, 3>& r0, T tolerance, std::size_t max_steps) {
  using V = Vector<T, 3>;
  std::vector<V> out;
  if (t.empty()) return out;
  if (t.size() == 1) return {r0};
  const T lo = t.front(), hi = t.back();
  std::vector<T> b(breaks.begin(), breaks.end());
  if (b.empty()) b = {lo, hi};
  b.front() = std::min(b.front(), lo);
  b.back() = std::max(b.back(), hi);
  std::vector<T> grid(t.begin(), t.end());
  std::vector<T> u;
  std::vector<V> x, tan;
  // The normal carried across [a, c] by m uniform steps from a normal q to tan[0].
  auto carry = [&](T a, T c, std::size_t m) {
    u.resize(m + 1);
    for (std::size_t i = 0; i <= m; ++i) u[i] = i == m ? c : a + (c - a) * static_cast<T>(i) / static_cast<T>(m);
    x.clear();
    tan.clear();
    sample(u, x, tan);
    const V& t0 = tan[0];
    const std::size_t k = std::abs(t0[0]) <= std::abs(t0[1]) && std::abs(t0[0]) <= std::abs(t0[2]) ? 0
                          : std::abs(t0[1]) <= std::abs(t0[2])                                    ? 1
                                                                                                  : 2;
    V e(T(0), T(0), T(0));
    e[k] = T(1);
    V q = e - dot(e, t0) * t0;
    q = q / norm(q);
    for (std::size_t i = 0; i < m; ++i) q = detail::double_reflection(x[i], x[i + 1], tan[i], tan[i + 1], q);
    return q;
  };
  for (std::size_t j = 0; j + 1 < b.size(); ++j) {
    const T a = b[j], c = b[j + 1];
    if (!(c > lo) || !(a < hi)) continue;
    // Up to the left limit at an interior break (the sample just before it).
    const T cl = j + 2 < b.size() ? std::nextafter(c, a) : c;
    std::size_t m = 8;
    V prev = carry(a, cl, m / 2);
    while (m < max_steps) {
      const V next = carry(a, cl, m);
      if (norm(next - prev) < tolerance) break;
      prev = next;
      m *= 2;
    }
    for (std::size_t i = 1; i < m; ++i) {
      const T v = a + (c - a) * static_cast<T>(i) / static_cast<T>(m);
      if (v > lo && v < hi) grid.push_back(v);
    }
    if (c > lo && c < hi) grid.push_back(c);
    if (cl > lo && cl < hi) grid.push_back(cl);
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  x.clear();
  tan.clear();
  sample(grid, x, tan);
  V r = r0;
  out.reserve(t.size());
  out.push_back(r0);
  std::size_t k = 1;
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    const bool at_break = grid[i] == std::nextafter(grid[i + 1], grid[i]) &&
                          std::binary_search(b.begin() + 1, b.end() - 1, grid[i + 1]);
    r = at_break ? detail::turn_at_break(tan[i], tan[i + 1], r)
                 : detail::double_reflection(x[i], x[i + 1], tan[i], tan[i + 1], r);
    if (k < t.size() && grid[i + 1] == t[k]) {
      out.push_back(r);
      ++k;
    }
  }
  return out;
}

}  // namespace casteljau
