// Rotation-minimizing frames of a space curve sampled at increasing parameters, by the
// double reflection method [WangJuttlerZhengLiu08]. Plain arrays in, plain arrays out:
// not templated on curve types (the samples come from any curve's evaluation); templated
// on the scalar T (deduced from r0).
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "casteljau/core/error.hpp"
#include "casteljau/core/point.hpp"

namespace casteljau {

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
    const Vector<T, 3> v1 = x[i + 1] - x[i];
    const T c1 = dot(v1, v1);
    Vector<T, 3> rl = r[i], tl = tangents[i];
    if (c1 > 0) {
      rl = rl - (2 / c1 * dot(v1, rl)) * v1;
      tl = tl - (2 / c1 * dot(v1, tl)) * v1;
    }
    const Vector<T, 3> v2 = tangents[i + 1] - tl;
    const T c2 = dot(v2, v2);
    Vector<T, 3> next = rl;
    if (c2 > 0) next = next - (2 / c2 * dot(v2, rl)) * v2;
    next = next - dot(next, tangents[i + 1]) * tangents[i + 1];
    const T len = norm(next);
    r.push_back(len > 0 ? next / len : next);
  }
  return r;
}

}  // namespace casteljau
