// The geometric queries on AnyCurve, compiled once: every query is instantiated on
// Pieces<double, D> for D = 1..4 only (a curve reaches it through its exact pieces).
#include "casteljau/io/queries.hpp"

#include "casteljau/io/frames.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "casteljau/algo/area.hpp"
#include "casteljau/algo/bounds.hpp"
#include "casteljau/algo/curvature.hpp"
#include "casteljau/algo/distance.hpp"
#include "casteljau/algo/features.hpp"
#include "casteljau/algo/frame.hpp"
#include "casteljau/algo/length.hpp"
#include "casteljau/algo/project.hpp"
#include "work_limits.hpp"

namespace casteljau::io {

namespace {

using casteljau::detail::format_number;

using limits::check_curve_work;
using limits::check_work;

}  // namespace

std::unique_ptr<const ProjectionPieces> projection_pieces(const AnyCurve& c) {
  check_curve_work(c, "curve");
  // new from the prvalues (elided): the variant of pieces is not moved.
  std::unique_ptr<const ProjectionPieces> out(new ProjectionPieces{pieces(c), domain(c)});
  std::visit([](const auto& p) { check_work(p, "curve"); }, out->pieces);
  return out;
}

AnyProjection project(const ProjectionPieces& pp, std::span<const double> point, bool farthest) {
  return std::visit(
      [&]<class P>(const P& p) {
        constexpr int D = P::dimension;
        if (point.size() != static_cast<std::size_t>(D)) {
          throw InvalidArgument("point", "needs " + std::to_string(D) + " coordinates (the curve's dimension), got " +
                                             std::to_string(point.size()));
        }
        Point<double, D> q;
        for (int k = 0; k < D; ++k) {
          require_finite(point[static_cast<std::size_t>(k)], "point[" + std::to_string(k) + "]");
          q[k] = point[static_cast<std::size_t>(k)];
        }
        auto r = casteljau::project(p, q, farthest);
        // A curve on a single parameter (a one-point lagrange: its pieces run to the next
        // double) answers that parameter, and its domain as the interval.
        const Interval<double> dom = pp.domain;
        if (dom.lo == dom.hi) {
          r.t = dom.lo;
          for (auto& u : r.all_t) u = dom.lo;
          for (auto& i : r.intervals) i = dom;
        }
        return AnyProjection(std::move(r));
      },
      pp.pieces);
}

AnyProjection project(const AnyCurve& c, std::span<const double> point, bool farthest) {
  return project(*projection_pieces(c), point, farthest);
}

void project_rows(const ProjectionPieces& pp, std::span<const double> points, bool farthest, std::span<double> t,
                  std::span<double> point, std::span<double> distance) {
  const Interval<double> dom = pp.domain;
  std::visit(
      [&]<class P>(const P& p) {
        constexpr int D = P::dimension;
        for (std::size_t i = 0; i < t.size(); ++i) {
          Point<double, D> q;
          for (int k = 0; k < D; ++k) {
            const double v = points[i * D + static_cast<std::size_t>(k)];
            if (!std::isfinite(v)) require_finite(v, "points[" + std::to_string(i) + "][" + std::to_string(k) + "]");
            q[k] = v;
          }
          const auto r = casteljau::project(p, q, farthest);
          // A curve on a single parameter answers that parameter (as project).
          t[i] = dom.lo == dom.hi ? dom.lo : r.t;
          for (int k = 0; k < D; ++k) point[i * D + static_cast<std::size_t>(k)] = r.point[k];
          distance[i] = r.distance;
        }
      },
      pp.pieces);
}

void project_rows(const AnyCurve& c, std::span<const double> points, bool farthest, std::span<double> t,
                  std::span<double> point, std::span<double> distance) {
  project_rows(*projection_pieces(c), points, farthest, t, point, distance);
}

double length(const AnyCurve& c, std::optional<double> from, std::optional<double> to) {
  check_curve_work(c, "curve");
  return std::visit(
      [&](const auto& p) {
        check_work(p, "curve");
        const auto dom = p.domain();
        return casteljau::arc_length(p, from.value_or(dom.lo), to.value_or(dom.hi));
      },
      pieces(c));
}

AnyBox bounds(const AnyCurve& c, std::optional<double> from, std::optional<double> to) {
  check_curve_work(c, "curve");
  return std::visit(
      [&]<class P>(const P& p) {
        const auto dom = p.domain();
        return AnyBox(casteljau::bounds(p, from.value_or(dom.lo), to.value_or(dom.hi)));
      },
      pieces(c));
}

std::vector<double> param_at_length(const AnyCurve& c, std::span<const double> lengths) {
  check_curve_work(c, "curve");
  return std::visit(
      [&]<class P>(const P& p) {
        check_work(p, "curve");
        const ArcLengthTable<double, P::dimension> table(p);
        std::vector<double> out;
        for (std::size_t i = 0; i < lengths.size(); ++i) {
          try {
            out.push_back(table.parameter_at(lengths[i]));
          } catch (const InvalidArgument& e) {
            throw InvalidArgument("lengths[" + std::to_string(i) + "]", e.problem());
          }
        }
        return out;
      },
      pieces(c));
}

std::vector<double> curvature(const AnyCurve& c, std::span<const double> t) {
  check_curve_work(c, "curve");
  return std::visit(
      [&](const auto& p) {
        std::vector<double> out;
        for (std::size_t j = 0; j < t.size(); ++j) {
          std::optional<double> kappa;
          try {
            kappa = casteljau::curvature(p, t[j]);  // scale-free: in each piece's own parameter
          } catch (const InvalidArgument& e) {
            throw InvalidArgument("t[" + std::to_string(j) + "]", e.problem());
          }
          if (!kappa || !std::isfinite(*kappa)) {
            throw InvalidArgument("t[" + std::to_string(j) + "]",
                                  "curvature is undefined at t = " + format_number(t[j]) +
                                      (kappa ? " (it is not representable)" : ": the velocity is zero (a cusp or a stop)"));
          }
          out.push_back(*kappa);
        }
        return out;
      },
      pieces(c));
}

namespace {

// `stopped` (frenet_frames only): where the velocity vanishes, a flag 1 and a frame with a
// zero tangent in its place, not an error.
AnyFrames frames_of(const AnyCurve& c, std::span<const double> t, bool require_normal, std::vector<char>* stopped = nullptr) {
  check_curve_work(c, "curve");
  return std::visit(
      [&]<class P>(const P& p) -> AnyFrames {
        constexpr int D = P::dimension;
        Frames<double, D> out;
        for (std::size_t j = 0; j < t.size(); ++j) {
          const std::string where = "t[" + std::to_string(j) + "]";
          std::optional<Frame<double, D>> f;
          try {
            f = casteljau::frame(p, t[j]);
          } catch (const InvalidArgument& e) {
            throw InvalidArgument(where, e.problem());
          }
          if (stopped) stopped->push_back(f ? 0 : 1);
          if (!f && stopped) {
            out.push_back(Frame<double, D>{Vector<double, D>{}, std::nullopt, std::nullopt, 0.0, std::nullopt});
            continue;
          }
          if (!f) {
            throw InvalidArgument(where, "the frame is undefined at t = " + format_number(t[j]) +
                                             ": the velocity is zero (a cusp or a stop), the tangent has no direction");
          }
          if (D >= 3 && !f->normal && require_normal) {
            throw InvalidArgument(where, "the principal normal is undefined at t = " + format_number(t[j]) +
                                             ": the curvature is zero (a straight stretch or a point of zero curvature)");
          }
          const auto finite = [](const std::optional<Vector<double, D>>& v) {
            if (!v) return true;
            for (int k = 0; k < D; ++k) {
              if (!std::isfinite((*v)[k])) return false;
            }
            return true;
          };
          if (!finite(f->tangent) || !finite(f->normal) || !finite(f->binormal) || !std::isfinite(f->curvature) ||
              (f->torsion && !std::isfinite(*f->torsion))) {
            throw InvalidArgument(where, "the frame at t = " + format_number(t[j]) + " is not representable");
          }
          out.push_back(std::move(*f));
        }
        return out;
      },
      pieces(c));
}

}  // namespace

AnyFrames frames(const AnyCurve& c, std::span<const double> t) { return frames_of(c, t, true); }

AnyFrames frenet_frames(const AnyCurve& c, std::span<const double> t, std::vector<char>* stopped) {
  return frames_of(c, t, false, stopped);
}

double area(const AnyCurve& c) {
  // Closedness is judged on the pieces (1e-9 of their extent), so it follows the check.
  check_curve_work(c, "curve");
  return std::visit(
      [&]<class P>(const P& p) -> double {
        if constexpr (P::dimension == 2) {
          return casteljau::area(p);
        } else {
          throw InvalidArgument("curve", "area needs a plane curve (dimension 2), got dimension " + std::to_string(P::dimension));
        }
      },
      pieces(c));
}

AnyFeatures features(const AnyCurve& c) {
  check_curve_work(c, "curve");
  return std::visit(
      [&](const auto& p) {
        check_work(p, "curve");
        return AnyFeatures(casteljau::features(p));
      },
      pieces(c));
}

AnyDistance distance(const AnyCurve& a, const AnyCurve& b) {
  check_curve_work(a, "curves[0]");
  check_curve_work(b, "curves[1]");
  const AnyPieces pa = pieces(a), pb = pieces(b);
  return std::visit(
      [&]<class PA, class PB>(const PA& x, const PB& y) -> AnyDistance {
        if constexpr (PA::dimension == PB::dimension) {
          check_work(x, "curves[0]");
          check_work(y, "curves[1]");
          return AnyDistance(casteljau::distance(x, y));
        } else {
          throw InvalidArgument("curves[1]", "must have the dimension of curves[0] (" + std::to_string(PA::dimension) + "), got " +
                                                 std::to_string(PB::dimension));
        }
      },
      pa, pb);
}

}  // namespace casteljau::io
