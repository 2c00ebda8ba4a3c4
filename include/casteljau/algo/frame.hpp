// The moving frame of a curve: unit tangent, normal (the left normal in the plane, the
// principal normal in space), the binormal and torsion in 3-D, with the curvature.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <variant>

#include "casteljau/algo/curvature.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau {

/// The Frenet frame at one parameter [Farin02, ch. 10; doCarmo76, 1-5]:
/// - tangent: the unit tangent T = c' / |c'|;
/// - normal (D >= 2): in the plane the left normal (T turned by +90 degrees), defined
///   wherever T is, with the signed curvature saying which way the curve bends; for
///   D >= 3 the principal normal N, the unit component of c'' normal to T, which exists
///   only where the curvature is not zero (std::nullopt on a straight stretch or at a
///   point of zero curvature);
/// - binormal (D == 3, with normal): B = T x N;
/// - curvature: signed in 2-D (positive turning left), >= 0 otherwise, 0 in 1-D;
/// - torsion (D == 3, with normal): det(c', c'', c''') / |c' x c''|^2.
/// In 4-D only T, N and the curvature (the further Frenet vectors are not computed).
template <class T, int D>
struct Frame {
  Vector<T, D> tangent;
  std::optional<Vector<T, D>> normal;
  std::optional<Vector<T, D>> binormal;
  T curvature = 0;
  std::optional<T> torsion;
};

namespace detail {

template <class T>
Vector<T, 3> cross3(const Vector<T, 3>& a, const Vector<T, 3>& b) {
  return Vector<T, 3>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

}  // namespace detail

/// The frame from the first three derivatives d1, d2, d3 at one parameter (see Frame),
/// given bounds noise1, noise2 of the rounding errors of d1 and d2: std::nullopt where
/// |d1| <= noise1 (the velocity vanishes: a cusp or a stop, where the tangent has no
/// direction we can compute); in D >= 3 no normal where the component of d2 normal to T
/// is <= noise2 (the curvature is zero as far as the data tell). Every quantity is
/// formed from unit vectors and one division at a time (kappa = |d2_perp| / |d1| / |d1|,
/// torsion = (B . d3) / |d1| / |d2_perp|), so coordinates near 1e+-150 neither overflow
/// nor underflow. Accuracy: directions to about noise / |d1| (T) and noise2 / |d2_perp|
/// (N, B) radians; curvature and torsion to a few eps relative beyond that.
template <class T, int D>
std::optional<Frame<T, D>> frame_of(const Vector<T, D>& d1, const Vector<T, D>& d2, const Vector<T, D>& d3, T noise1 = T(0),
                                    T noise2 = T(0)) {
  const T speed = norm(d1);
  if (!(speed > noise1) || !std::isfinite(speed)) return std::nullopt;
  Frame<T, D> f;
  f.tangent = d1 / speed;
  if constexpr (D == 1) {
    return f;
  } else if constexpr (D == 2) {
    f.normal = Vector<T, 2>(-f.tangent[1], f.tangent[0]);
    f.curvature = cross(f.tangent, d2) / speed / speed;
    return f;
  } else {
    const Vector<T, D> perp = d2 - dot(f.tangent, d2) * f.tangent;
    const T bend = norm(perp);
    f.curvature = bend / speed / speed;
    if (!(bend > noise2)) return f;
    f.normal = perp / bend;
    if constexpr (D == 3) {
      f.binormal = detail::cross3(f.tangent, *f.normal);
      f.torsion = dot(*f.binormal, d3) / speed / bend;
    }
    return f;
  }
}

namespace detail {

/// Bounds of the rounding errors of the first and second derivatives of a Bézier piece
/// (in its own parameter), as computed by derivative_at: the k-th differences of
/// coordinates of size up to Pmax = max |P_i|, times n^k, evaluated by de Casteljau
/// (error a few (n + 1) eps of the coefficients' size [Farin02, 3.1]): 32 (n + 1) eps
/// (2 n)^k Pmax, the factor 32 a margin over the few. For a rational piece the quotient
/// rule divides by w and mixes in lower derivatives: the bound is multiplied by
/// rho^(k + 1), rho = max w / min w (w(t) >= min w). An estimate, not a proof; it only
/// decides when a derivative is indistinguishable from zero.
template <class T, int D, class Piece>
std::array<T, 2> derivative_noise(const Piece& c) {
  const auto& P = c.points();
  const T n = static_cast<T>(P.size() - 1);
  T pmax = 0;
  for (const auto& p : P) pmax = std::max(pmax, norm(p.to_vector()));
  T rho = 1;
  if constexpr (std::is_same_v<Piece, RationalBezier<T, D>>) {
    const auto [lo, hi] = std::minmax_element(c.weights().begin(), c.weights().end());
    rho = *hi / *lo;
  }
  const T base = 32 * (n + 1) * std::numeric_limits<T>::epsilon() * pmax;
  return {base * 2 * n * rho * rho, base * 4 * n * n * rho * rho * rho};
}

}  // namespace detail

/// The frame of a curve at the parameter u (any finite u, as evaluation; at an interior
/// break the right-hand piece answers, at the domain's end the last piece), from its
/// exact Bézier pieces: frame_of(c'(u), c''(u), c'''(u)) with the noise bounds of the
/// piece (detail::derivative_noise, scaled by the chain rule). std::nullopt where the
/// velocity vanishes (a cusp or a stop); no normal in D >= 3 where the curvature does
/// (a straight piece, a point of zero curvature). Cost: three derivative evaluations,
/// O(n^2) each. Throws InvalidArgument("t", ...) for a non-finite u or a derivative that
/// is not representable.
template <class C>
  requires detail::is_pieces<C>
std::optional<Frame<typename C::Scalar, C::dimension>> frame(const C& c, typename C::Scalar u) {
  using T = typename C::Scalar;
  constexpr int D = C::dimension;
  require_finite(u, "t");
  const auto& p = pieces(c);  // a reference when c is Pieces; else the local owns them
  const PieceParameter<T> at = p.locate(u);  // not a structured binding: clang 14 cannot capture one
  const T t = at.t;
  const std::size_t i = at.index;
  // The frame, curvature and torsion are unchanged by an increasing affine change of
  // parameter: the piece's own derivatives (in t on [0, 1]) give them without the chain
  // rule's powers of the break length, which under- or overflow for a domain of length
  // 1e200 or 1e-200.
  return std::visit(
      [&](const auto& piece) {
        const auto noise = detail::derivative_noise<T, D>(piece);
        return frame_of<T, D>(piece.derivative_at(t, 1), piece.derivative_at(t, 2), piece.derivative_at(t, 3), noise[0], noise[1]);
      },
      p.segments()[i]);
}

/// Every other curve type: the same, on its exact pieces (see detail::is_pieces).
template <class C>
  requires PiecewiseBezierCurve<C> && (!detail::is_pieces<C>)
std::optional<Frame<typename C::Scalar, C::dimension>> frame(const C& c, typename C::Scalar u) {
  return frame(pieces(c), u);
}

}  // namespace casteljau
