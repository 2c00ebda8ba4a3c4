// The run-time operations of io/ops.hpp: solve and to_bspline on Pieces<double, D> (one
// instantiation per dimension), refine and reduce on the Bézier, B-spline and NURBS types.
#include "casteljau/io/ops.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "casteljau/algo/deviation.hpp"
#include "casteljau/algo/reduce.hpp"
#include "casteljau/algo/reduce_spline.hpp"
#include "casteljau/algo/scalar_forms.hpp"
#include "casteljau/algo/solve.hpp"
#include "casteljau/algo/to_bspline.hpp"
#include "casteljau/algo/to_quadratic.hpp"
#include "work_limits.hpp"

namespace casteljau::io {

namespace {

using casteljau::detail::format_number;

/// The queries' work limit, on the curve as given and then on its pieces.
void check_solve_work(const AnyCurve& c, const std::string& what = "solving") { limits::check_curve_work(c, "curve", what); }

}  // namespace

LevelSet<double> solve(const AnyCurve& c, std::optional<int> axis, std::optional<std::span<const double>> direction, double value) {
  const int d = dimension(c);
  if (axis && direction) throw InvalidArgument("direction", "give axis or direction, not both");
  if (!axis && !direction) throw InvalidArgument("axis", "give axis (a coordinate index) or direction (a vector)");
  if (axis && (*axis < 0 || *axis >= d)) {
    throw InvalidArgument("axis", "must be a coordinate index 0.." + std::to_string(d - 1) + " of this " + std::to_string(d) +
                                      "-D curve, got " + std::to_string(*axis));
  }
  if (direction && direction->size() != static_cast<std::size_t>(d)) {
    throw InvalidArgument("direction", "needs " + std::to_string(d) + " coordinates (the curve's dimension), got " +
                                           std::to_string(direction->size()));
  }
  if (direction && std::all_of(direction->begin(), direction->end(), [](double x) { return x == 0; })) {
    throw InvalidArgument("direction", "must not be the zero vector");
  }
  check_solve_work(c);
  // How the pieces were made bounds their rounding (none for Bézier curves, polylines).
  const AnyPieces any = pieces(c);
  return std::visit(
      [&]<class C>(const C& x) {
        constexpr int D = C::dimension;
        const auto& p = std::get<Pieces<double, D>>(any);
        limits::check_work(p, "curve", "solving");
        const auto errors = casteljau::detail::piece_errors(x, p);
        Vector<double, D> a{};
        for (int k = 0; k < D; ++k) a[k] = axis ? (k == *axis ? 1.0 : 0.0) : (*direction)[static_cast<std::size_t>(k)];
        return casteljau::solve(p, a, value, std::span<const casteljau::detail::PieceError<double, D>>(errors));
      },
      c);
}

AnyCurve refine(const AnyCurve& c, std::span<const double> X) {
  return std::visit(
      [&]<class C>(const C& x) -> AnyCurve {
        if constexpr (requires { x.refine_knots(X); }) {
          const Interval<double> dom = x.domain();
          for (std::size_t j = 0; j < X.size(); ++j) {
            const std::string where = "knots[" + std::to_string(j) + "]";
            if (j > 0 && X[j] < X[j - 1]) {
              throw InvalidArgument(where, "knots must be non-decreasing (" + format_number(X[j]) + " after " + format_number(X[j - 1]) + ")");
            }
            if (X[j] < dom.lo || X[j] > dom.hi) {
              throw InvalidArgument(where, "a knot to insert must lie in the domain [" + format_number(dom.lo) + ", " +
                                               format_number(dom.hi) + "], got " + format_number(X[j]));
            }
          }
          return AnyCurve(x.refine_knots(X));  // multiplicities past the degree: "knots[j]"
        } else {
          throw InvalidArgument("curve.type", "refine needs " + types_phrase(Capability::knot_insertion) + ", got a " +
                                                  std::string(type_name(c)));
        }
      },
      c);
}

AnyCurve to_bspline(const AnyCurve& c) {
  check_solve_work(c, "the conversion");
  return std::visit(
      [&](const auto& p) {
        limits::check_work(p, "curve", "the conversion");
        return std::visit([](auto&& b) { return AnyCurve(std::move(b)); }, casteljau::to_bspline(p));
      },
      pieces(c));
}

AnyReduction reduce(const AnyCurve& c, int times, double tolerance) {
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(tolerance));
  check_solve_work(c, "the reduction");
  return std::visit(
      [&]<class C>(const C& x) -> AnyReduction {
        if constexpr (DegreeReducibleCurve<C>) {
          const int p = x.degree();
          if (times < 1 || times > p) {
            throw InvalidArgument("times", "must be in 1..p = " + std::to_string(p) + " (the curve's degree), got " + std::to_string(times));
          }
          const int m = p - times;
          // The work limit: reduce_spline_work's units (a bezier is one piece), about 2 s at 3e7.
          double work = 0;
          if constexpr (SplineCurveType<C>) {
            work = reduce_spline_work(x);
          } else {
            work = std::pow(p + 1.0, 3) + 1000;
          }
          if (work > 3e7) {
            throw InvalidArgument("curve", "the reduction would take about " + format_number(work) +
                                               " units of work (pieces x ((degree + 1)^3, four times that for a nurbs, "
                                               "+ 1000)), more than the limit of 3e7: use fewer pieces or a lower degree");
          }
          double err = 0;
          std::optional<C> reduced;
          if constexpr (SplineCurveType<C>) {
            try {
              auto r = reduce_spline(x, times);
              reduced = std::move(r.curve);
              err = r.max_error;
            } catch (const NumericalError& e) {
              throw InvalidArgument("curve", e.what());
            }
          } else {
            // Least squares with the ends kept (free for a constant: the mean), measured at
            // 32 (p + 1) samples: a peak of the difference of two degree-p polynomials is
            // wider than that spacing.
            reduced = casteljau::reduce_degree(x, m, m >= 1 ? Endpoints::keep : Endpoints::free).curve;
            const Interval<double> dom = x.domain();
            err = max_deviation<double>(x, *reduced, std::vector<double>{dom.lo, dom.hi}, 32 * (p + 1));
            if (!std::isfinite(err)) {
              throw InvalidArgument("curve", "no reduction from degree " + std::to_string(p) + " to " + std::to_string(m) +
                                                 " with a finite distance to the curve was found (coordinates near the largest double?)");
            }
          }
          if (!(err <= tolerance)) {
            throw InvalidArgument("tolerance", "reducing the degree from " + std::to_string(p) + " to " + std::to_string(m) +
                                                   " moves the curve by " + format_number(err) +
                                                   " (measured: the largest distance at equal parameters, of the best reduction "
                                                   "found), more than the tolerance " + format_number(tolerance));
          }
          return {AnyCurve(std::move(*reduced)), err};
        } else {
          throw InvalidArgument("curve.type", "reduce needs " + types_phrase(Capability::degree_reduction) + ", got a " +
                                                  std::string(type_name(c)));
        }
      },
      c);
}

AnyCurve to_quadratic(const AnyCurve& c, double tolerance) {
  require_finite(tolerance, "tolerance");
  if (!(tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(tolerance));
  check_solve_work(c, "the approximation");
  return std::visit(
      [&]<class P>(const P& p) {
        constexpr int D = P::dimension;
        limits::check_work(p, "curve", "the approximation");
        // The count beforehand: a piece of degree n >= 3 whose third differences reach M3
        // (third derivative at most n (n - 1) (n - 2) M3 = d3) needs about
        // (d3 / (24 tol))^(1/3) quadratics for a parametric error of tol, more than the
        // geometric fit needs (its error falls as the fourth power of the step). On the
        // points divided by 8 (exact for normal numbers; no difference overflows near the
        // largest double) and divided by the tolerance before the degree factor, so that
        // the estimate is the same at every scale.
        double estimate = 0;
        for (const auto& piece : p.segments()) {
          estimate += std::visit(
              [&](const auto& b) {
                const auto& P3 = b.points();
                const std::size_t n = P3.size() - 1;
                if (n < 3) return 1.0;
                double m3 = 0;
                for (std::size_t k = 0; k + 3 <= n; ++k) {
                  Vector<double, D> v;
                  for (int d = 0; d < D; ++d) v[d] = (P3[k + 3][d] / 8 - P3[k][d] / 8) - 3.0 * (P3[k + 2][d] / 8 - P3[k + 1][d] / 8);
                  m3 = std::max(m3, norm(v));
                }
                const double degree_factor = static_cast<double>(n) * static_cast<double>(n - 1) * static_cast<double>(n - 2);
                return std::ceil(std::cbrt(m3 / (3 * tolerance) * degree_factor));  // d3 / (24 tol), d3 = 8 m3 n (n-1) (n-2)
              },
              piece);
        }
        if (!(estimate <= static_cast<double>(max_quadratic_segments))) {
          throw InvalidArgument("tolerance", "the approximation would need about " + format_number(estimate) +
                                                 " quadratic segments, more than the limit of " +
                                                 std::to_string(max_quadratic_segments) + ": use a larger tolerance");
        }
        const QuadraticChain<double, D> r = casteljau::to_quadratic(p, tolerance, max_quadratic_segments);
        std::vector<Segment<double, D>> segs;
        segs.reserve(r.segments.size());
        for (const auto& q : r.segments) segs.emplace_back(q);
        return AnyCurve(Path<double, D>(std::move(segs), r.breaks));
      },
      pieces(c));
}

}  // namespace casteljau::io
