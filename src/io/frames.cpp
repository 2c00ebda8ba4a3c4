// The `frames` command's library call (io/frames.hpp).
#include "casteljau/io/frames.hpp"

#include <cmath>
#include <variant>

#include "casteljau/algo/rmf.hpp"

namespace casteljau::io {

namespace {

std::array<double, 3> to_array(const Vector<double, 3>& v) { return {v[0], v[1], v[2]}; }

// Each piece's steps are doubled until the normal carried across it changes by less than
// this (radians); fourth order, so the transport is then within about 1/15 of it.
constexpr double rmf_tolerance = 1e-10;
constexpr std::size_t rmf_max_steps = std::size_t{1} << 14;

Vector<double, 3> cross(const Vector<double, 3>& a, const Vector<double, 3>& b) {
  return Vector<double, 3>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

}  // namespace

MovingFrames moving_frames(const AnyCurve& c, std::span<const double> t, const std::string& method,
                           std::optional<std::span<const double>> initial_normal) {
  using casteljau::detail::format_number;
  if (dimension(c) != 3) throw InvalidArgument("curve", "frames needs a 3-D curve, got dimension " + std::to_string(dimension(c)));
  const bool rmf = method == "rotation_minimizing";
  if (!rmf && method != "frenet") {
    throw InvalidArgument("method", "unknown method '" + method + "' (rotation_minimizing, frenet)");
  }
  if (initial_normal && !rmf) throw InvalidArgument("initial_normal", "belongs to method rotation_minimizing, not frenet");
  if (initial_normal && initial_normal->size() != 3) {
    throw InvalidArgument("initial_normal", "needs 3 coordinates (the curve's dimension), got " + std::to_string(initial_normal->size()));
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    require_finite(t[i], "t[" + std::to_string(i) + "]");
    if (i > 0 && !(t[i] > t[i - 1])) {
      throw InvalidArgument("t[" + std::to_string(i) + "]",
                            "parameters must be increasing (" + format_number(t[i]) + " after " + format_number(t[i - 1]) + ")");
    }
  }
  MovingFrames out;
  if (!rmf) {
    // The contract's "null where undefined": no tangent where the velocity vanishes.
    std::vector<char> stopped;
    const AnyFrames any = frenet_frames(c, t, &stopped);
    const auto& fr = std::get<Frames<double, 3>>(any);
    for (std::size_t i = 0; i < fr.size(); ++i) {
      const auto& f = fr[i];
      out.tangents.push_back(stopped[i] ? std::nullopt : std::optional(to_array(f.tangent)));
      out.normals.push_back(f.normal ? std::optional(to_array(*f.normal)) : std::nullopt);
      out.binormals.push_back(f.normal ? std::optional(to_array(cross(f.tangent, *f.normal))) : std::nullopt);
    }
    return out;
  }
  const AnyFrames any = frenet_frames(c, t);
  const auto& fr = std::get<Frames<double, 3>>(any);
  std::vector<Vector<double, 3>> tangents;
  for (const auto& f : fr) {
    tangents.push_back(f.tangent);
    out.tangents.push_back(to_array(f.tangent));
  }
  if (t.empty()) return out;
  Vector<double, 3> r0;
  if (initial_normal) {
    const Vector<double, 3> n((*initial_normal)[0], (*initial_normal)[1], (*initial_normal)[2]);
    const double len = norm(n);
    const Vector<double, 3> p = n - dot(n, tangents[0]) * tangents[0];
    const double plen = norm(p);
    // Parallel to the tangent (or zero): nothing of it is left in the normal plane beyond
    // the rounding of the projection.
    if (!(len > 0) || !std::isfinite(len) || !(plen > 1e-12 * len)) {
      throw InvalidArgument("initial_normal", "must have a component normal to the tangent at t[0] = " + format_number(t[0]) +
                                                  " (it is zero or parallel to the tangent)");
    }
    r0 = p / plen;
  } else if (fr[0].normal) {
    r0 = *fr[0].normal;
  } else {
    throw InvalidArgument("initial_normal", "the curve has no Frenet normal at t[0] = " + format_number(t[0]) +
                                                " (zero curvature): give initial_normal");
  }
  // The internal grid: the curve's exact Bezier pieces (sampled directly: no dispatch on
  // the curve type per sample), their breaks refined to rmf_tolerance.
  const AnyPieces any_pieces = pieces(c);
  const auto* p = std::get_if<Pieces<double, 3>>(&any_pieces);
  if (p == nullptr) throw InvalidArgument("curve", "frames needs a 3-D curve");
  const std::vector<double>& breaks = p->breaks();
  auto sample = [&](const std::vector<double>& u, std::vector<Vector<double, 3>>& x, std::vector<Vector<double, 3>>& tan) {
    for (const double ui : u) {
      const Point<double, 3> q = (*p)(ui);
      x.emplace_back(q[0], q[1], q[2]);
      Vector<double, 3> v = p->derivative_at(ui, 1);
      // A grid point where the velocity vanishes (a stop between the asked t): the
      // direction of the first non-zero higher derivative, the limit of the tangent.
      for (int k = 2; !(norm(v) > 0) && k <= 3; ++k) v = p->derivative_at(ui, k);
      if (!(norm(v) > 0)) {
        throw InvalidArgument("curve", "the tangent is undefined at t = " + format_number(ui) +
                                           " (the velocity and the next two derivatives are zero)");
      }
      tan.push_back(v / norm(v));
    }
  };
  auto r = rotation_minimizing_normals_at<double>(sample, breaks, t, r0, rmf_tolerance, rmf_max_steps);
  for (std::size_t i = 0; i < r.size(); ++i) {  // onto the plane normal to the reported tangent
    const Vector<double, 3> p = r[i] - dot(r[i], tangents[i]) * tangents[i];
    r[i] = p / norm(p);
  }
  for (std::size_t i = 0; i < r.size(); ++i) {
    out.normals.push_back(to_array(r[i]));
    out.binormals.push_back(to_array(cross(tangents[i], r[i])));
  }
  return out;
}

}  // namespace casteljau::io
