// The run-time operations of io/ops.hpp: solve and to_bspline on Pieces<double, D> (one
// instantiation per dimension), refine and reduce on the Bézier, B-spline and NURBS types.
#include "casteljau/io/ops.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
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
#include "casteljau/basis/quadrature.hpp"
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

namespace {

/// The distinct knots of a B-spline or NURBS inside its domain (its pieces' breaks), or
/// {0, 1} for a Bézier curve.
template <class C>
std::vector<double> breaks_of(const C& x) {
  const Interval<double> dom = x.domain();
  if constexpr (requires { x.knot_vector(); }) {
    std::vector<double> b;
    for (const auto& run : x.knot_vector().distinct())
      if (run.value >= dom.lo && run.value <= dom.hi) b.push_back(run.value);
    return b;
  } else {
    return {dom.lo, dom.hi};
  }
}

/// The mean of the curve over its domain, (1 / |domain|) times the integral of C (the
/// best constant in L2), by adaptive Gauss-Kronrod per knot interval to 1e-14 relative.
template <class C>
Point<double, C::dimension> mean_of(const C& x, const std::vector<double>& breaks) {
  constexpr int D = C::dimension;
  const Interval<double> dom = x.domain();
  Point<double, D> m;
  for (int k = 0; k < D; ++k) {
    double s = 0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      s += integrate_adaptive<double>([&](double u) { return x(u)[k]; }, breaks[i], breaks[i + 1], 1e-14, 1e-300).value;
    }
    m[k] = s / (dom.hi - dom.lo);
  }
  return m;
}

/// The largest |a(u) - b(u)| at samples + 1 equally spaced u per interval of `breaks`
/// (a value from below of max_deviation's), stopping at the first above stop_above.
template <class A, class B>
double sampled_deviation(const A& a, const B& b, const std::vector<double>& breaks, int samples, double stop_above) {
  double top = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    for (int j = 0; j <= samples; ++j) {
      const double u = j == samples ? breaks[i + 1] : breaks[i] + (breaks[i + 1] - breaks[i]) * j / samples;
      top = std::max(top, norm(a(u) - b(u)));
      if (top > stop_above) return top;
    }
  }
  return top;
}

/// The centre of the control points' box: the fits work about it, so that translating
/// the curve changes nothing but rounding.
template <int D>
Point<double, D> control_centre(const std::vector<Point<double, D>>& P) {
  Point<double, D> lo = P.front(), hi = P.front();
  for (const auto& q : P)
    for (int d = 0; d < D; ++d) {
      lo[d] = std::min(lo[d], q[d]);
      hi[d] = std::max(hi[d], q[d]);
    }
  Point<double, D> c;
  for (int d = 0; d < D; ++d) c[d] = lo[d] / 2 + hi[d] / 2;
  return c;
}

/// A B-spline's points about c, or a NURBS' homogeneous points (w (P - c), w), flat.
template <int D>
casteljau::detail::FlatSpline<double> flat_about(const BSpline<double, D>& x, const Point<double, D>& c) {
  casteljau::detail::FlatSpline<double> f{x.degree(), D, x.knots(), {}};
  for (const auto& q : x.points())
    for (int d = 0; d < D; ++d) f.P.push_back(q[d] - c[d]);
  return f;
}
template <int D>
casteljau::detail::FlatSpline<double> flat_about(const Nurbs<double, D>& x, const Point<double, D>& c) {
  casteljau::detail::FlatSpline<double> f{x.degree(), D + 1, x.knots(), {}};
  for (const auto& h : x.homogeneous().points()) {
    for (int d = 0; d < D; ++d) f.P.push_back(h[d] - h[D] * c[d]);
    f.P.push_back(h[D]);
  }
  return f;
}

/// The fitting problem of the reduction by r of the degree-p spline f: the knots of
/// detail::reduced_knots, the pieces of f's domain, K = 2 p + 4 samples a piece, and
/// the fixed control points (the domain's ends, both limits at a jump) with the values
/// value(s, u, out) gives: f's piece on its span s at u, as the fit's E numbers.
template <class Value>
casteljau::detail::SplineFit<double> spline_fit_problem(const casteljau::detail::FlatSpline<double>& f, int r, int E, Value&& value) {
  const std::span<const double> U(f.U);
  casteljau::detail::SplineFit<double> g;
  g.q = f.p - r;
  g.E = E;
  g.K = 2 * f.p + 4;
  g.W = casteljau::detail::reduced_knots<double>(U, f.p, r);
  for (const std::size_t s : casteljau::detail::nonempty_spans<double>(U, f.p)) {
    g.lo.push_back(U[s]);
    g.hi.push_back(U[s + 1]);
    g.source_span.push_back(s);
    g.fit_span.push_back(find_span<double>(std::span<const double>(g.W), g.q, U[s] / 2 + U[s + 1] / 2));
  }
  const std::size_t n = g.W.size() - static_cast<std::size_t>(g.q) - 1, e = static_cast<std::size_t>(E);
  g.fixed.assign(n, 0);
  g.C0.assign(n * e, 0.0);
  const auto fix = [&](std::size_t i, std::size_t s, double u) {
    g.fixed[i] = 1;
    value(s, u, std::span<double>(g.C0).subspan(i * e, e));
  };
  fix(0, g.source_span.front(), g.lo.front());
  fix(n - 1, g.source_span.back(), g.hi.back());
  for (std::size_t j = 1; j < g.lo.size(); ++j) {
    const double x = g.lo[j];
    if (knot_multiplicity<double>(U, x) != static_cast<std::size_t>(f.p) + 1) continue;
    const std::size_t k = static_cast<std::size_t>(std::lower_bound(g.W.begin(), g.W.end(), x) - g.W.begin());
    fix(k - 1, g.source_span[j - 1], x);  // the left limit ends the piece before the jump
    fix(k, g.source_span[j], x);          // the right limit starts the next
  }
  return g;
}

/// The curve's values at the fit's samples, E numbers each, when they take at most 4e6
/// numbers (else none: the fit evaluates the curve at each use).
template <class Value>
std::vector<double> sample_values(const casteljau::detail::SplineFit<double>& g, Value&& value) {
  std::vector<double> Y;
  const std::size_t E = static_cast<std::size_t>(g.E);
  if (static_cast<double>(g.samples()) * static_cast<double>(E) > 4e6) return Y;
  Y.resize(g.samples() * E);
  for (std::size_t i = 0; i < g.samples(); ++i) value(g.source_span[g.piece(i)], g.sample(i), std::span<double>(Y).subspan(i * E, E));
  return Y;
}

/// How many Lawson steps the fit may take: about 3e7 operations in all, none
/// past 2e6 samples (the weights and errors are kept per sample), at most 30.
inline int lawson_steps(const casteljau::detail::SplineFit<double>& g, int p, int source_coordinates, bool cached) {
  const double N = static_cast<double>(g.samples());
  if (N > 2e6) return 0;
  const double per_step =
      N * ((g.q + 1.0) * (g.q + 1.0) * (g.E + 2.0) + (cached ? 0.0 : 2.0 * (p + 1.0) * (p + 1.0) * source_coordinates));
  return static_cast<int>(std::min(30.0, std::floor(3e7 / per_step)));
}

/// The candidate reductions of a bspline or nurbs x by r (p - r >= 1). The fits of
/// detail::lawson_fits on the knots of detail::reduced_knots, the end points (and both
/// limits at a jump) kept: for a bspline of its points; for a nurbs of the Cartesian curve
/// by a polynomial spline (weights 1: always possible, whatever the weights) and of the
/// homogeneous points (kept when every fitted weight is > 0). Then r steps of [PT97] A5.11
/// (reduce_degree with no tolerance to meet: every knot removal taken; left out where it
/// fails, e.g. a NURBS weight <= 0), and the fits' first (least-squares) solves. In this
/// order, the likely best first; none depends on a tolerance. Each with a value from
/// below of its max_error (the fits' largest sampled error; 0 for A5.11).
template <class C>
std::vector<std::pair<C, double>> spline_reductions(const C& x, int r) {
  constexpr int D = C::dimension;
  constexpr bool rational = std::is_same_v<C, Nurbs<double, D>>;
  std::vector<std::pair<C, double>> out, rest;  // the fits' best, then A5.11 and the fits' first solves
  std::optional<C> steps;
  try {
    C y = x;
    for (int j = 0; j < r; ++j) y = y.reduce_degree(std::numeric_limits<double>::max()).curve;
    steps = std::move(y);
  } catch (const InvalidArgument&) {
  } catch (const NumericalError&) {
  }
  const int p = x.degree(), q = p - r;
  const Point<double, D> c = control_centre<D>(x.points());
  const casteljau::detail::FlatSpline<double> f = flat_about<D>(x, c);
  const std::size_t S = static_cast<std::size_t>(f.E);
  std::vector<double> N(static_cast<std::size_t>(p) + 1), h(S), y(S);
  // The curve's value on a piece, as f holds it (points, or homogeneous points)...
  const auto source = [&](std::size_t s, double u, std::span<double> v) {
    casteljau::detail::piece_value<double>(f, s, u, std::span<double>(N), v);
  };
  // ... and as a Cartesian point about c.
  const auto cartesian = [&](std::size_t s, double u, std::span<double> v) {
    source(s, u, std::span<double>(h));
    for (int d = 0; d < D; ++d) v[static_cast<std::size_t>(d)] = rational ? h[static_cast<std::size_t>(d)] / h[D] : h[static_cast<std::size_t>(d)];
  };
  // |a - b| over the first D numbers (the Cartesian coordinates; b / b[D] and a / a[D]
  // when `projective`), scaled by the largest difference so that no square under- or
  // overflows at any scale.
  const auto distance_to = [&](std::span<const double> a, std::span<const double> b, bool projective = false) {
    Vector<double, D> diff;
    for (std::size_t d = 0; d < static_cast<std::size_t>(D); ++d) {
      diff[static_cast<int>(d)] = projective ? a[d] / a[D] - b[d] / b[D] : a[d] - b[d];
    }
    return norm(diff);
  };
  std::vector<double> point(static_cast<std::size_t>(D));
  // A clamped end's point is the curve's end exactly (the fits' fixed values are that
  // point about c, which adding c back may round; A5.11 divides by the weight again).
  const std::vector<double>& U = x.knots();
  const std::size_t n = x.points().size();
  const auto exact_ends = [&](std::vector<Point<double, D>>& Q) {
    if (U.front() == U[static_cast<std::size_t>(p)]) Q.front() = x.points().front();
    if (U.back() == U[n]) Q.back() = x.points().back();
  };
  // The polynomial fit (a bspline's, or a nurbs' with weights 1).
  {
    const casteljau::detail::SplineFit<double> g = spline_fit_problem(f, r, D, cartesian);
    const std::vector<double> Y = sample_values(g, cartesian);
    const auto target = [&](std::size_t i, std::span<double> v) {
      if (Y.empty()) return cartesian(g.source_span[g.piece(i)], g.sample(i), v);
      std::copy_n(Y.begin() + static_cast<std::ptrdiff_t>(i * D), D, v.begin());
    };
    const auto error = [&](std::size_t i, std::span<const double> v) {
      target(i, std::span<double>(point));
      return distance_to(v, point);
    };
    const auto fits = casteljau::detail::lawson_fits<double>(g, target, error, lawson_steps(g, p, static_cast<int>(S), !Y.empty()));
    for (std::size_t k = 0; k < fits.size(); ++k) {
      std::vector<Point<double, D>> Q(g.fixed.size());
      for (std::size_t i = 0; i < Q.size(); ++i)
        for (int d = 0; d < D; ++d) Q[i][d] = fits[k].C[i * D + static_cast<std::size_t>(d)] + c[d];
      exact_ends(Q);
      if constexpr (rational) {
        (k == 0 ? out : rest).emplace_back(C(q, g.W, std::move(Q), std::vector<double>(g.fixed.size(), 1.0)), fits[k].sampled_error);
      } else {
        (k == 0 ? out : rest).emplace_back(C(q, g.W, std::move(Q)), fits[k].sampled_error);
      }
    }
  }
  if constexpr (rational) {
    // The homogeneous fit, its error the Cartesian distance (infinite where the fitted
    // weight is <= 0).
    const casteljau::detail::SplineFit<double> g = spline_fit_problem(f, r, D + 1, source);
    const std::vector<double> Y = sample_values(g, source);
    const auto target = [&](std::size_t i, std::span<double> v) {
      if (Y.empty()) return source(g.source_span[g.piece(i)], g.sample(i), v);
      std::copy_n(Y.begin() + static_cast<std::ptrdiff_t>(i * S), S, v.begin());
    };
    const auto error = [&](std::size_t i, std::span<const double> v) {
      if (!(v[D] > 0)) return std::numeric_limits<double>::infinity();
      target(i, std::span<double>(y));
      return distance_to(v, y, true);
    };
    const auto fits = casteljau::detail::lawson_fits<double>(g, target, error, lawson_steps(g, p, static_cast<int>(S), !Y.empty()));
    for (std::size_t k = 0; k < fits.size(); ++k) {
      const std::vector<double>& P = fits[k].C;
      std::vector<Point<double, D>> Q(g.fixed.size());
      std::vector<double> w(g.fixed.size());
      bool positive = true;
      for (std::size_t i = 0; i < Q.size(); ++i) {
        w[i] = P[i * S + D];
        positive = positive && w[i] > 0 && std::isfinite(w[i]);
        for (int d = 0; d < D; ++d) Q[i][d] = P[i * S + static_cast<std::size_t>(d)] / w[i] + c[d];
      }
      if (!positive) continue;
      exact_ends(Q);
      bool finite = true;
      for (const auto& pt : Q) finite = finite && casteljau::detail::all_finite_point(pt);
      if (finite) (k == 0 ? out : rest).emplace_back(C(q, g.W, std::move(Q), std::move(w)), fits[k].sampled_error);
    }
  }
  if (steps) {
    std::vector<Point<double, D>> Q = steps->points();
    exact_ends(Q);
    if constexpr (rational) {
      out.emplace_back(C(steps->degree(), steps->knots(), std::move(Q), steps->weights()), 0.0);
    } else {
      out.emplace_back(C(steps->degree(), steps->knots(), std::move(Q)), 0.0);
    }
  }
  for (auto& y : rest) out.push_back(std::move(y));
  return out;
}

}  // namespace

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
        constexpr int D = C::dimension;
        constexpr bool bezier = std::is_same_v<C, Bezier<double, D>>;
        if constexpr (DegreeReducibleCurve<C>) {
          const int p = x.degree();
          if (times < 1 || times > p) {
            throw InvalidArgument("times", "must be in 1..p = " + std::to_string(p) + " (the curve's degree), got " + std::to_string(times));
          }
          const int m = p - times;
          const std::vector<double> breaks = breaks_of(x);
          // Measuring max_error evaluates both curves 32 (p + 1) times per piece at O(p^2)
          // each, and the candidates' fits cost about as much: (p + 1)^3 units a piece, four
          // times that for a NURBS (its rational fit: measured 3.4x at degree 200, 4.8x at
          // 300), plus 1000 a piece for the per-piece work of the measure (its local
          // searches: 65 us a quadratic piece). Calibrated on this machine's user CPU
          // (session 17): about 0.065 us a unit, so the limit 3e7 is about 2 s (B-spline
          // degree 300 in one piece 1.8 s; 20,000 quadratic pieces 1.3 s).
          constexpr bool rational = std::is_same_v<C, Nurbs<double, D>>;
          const double work = static_cast<double>(breaks.size() - 1) * ((rational ? 4 : 1) * std::pow(p + 1.0, 3) + 1000);
          if (work > 3e7) {
            throw InvalidArgument("curve", "the reduction would take about " + format_number(work) +
                                               " units of work (pieces x ((degree + 1)^3, four times that for a nurbs, "
                                               "+ 1000)), more than the limit of 3e7: use fewer pieces or a lower degree");
          }
          C reduced = x;
          if constexpr (bezier) {
            reduced = casteljau::reduce_degree(x, m, m >= 1 ? Endpoints::keep : Endpoints::free).curve;
          } else if (m == 0) {
            const Interval<double> dom = x.domain();
            const Point<double, D> mean = mean_of(x, breaks);
            if constexpr (rational) {
              reduced = C(0, {dom.lo, dom.hi}, {mean}, {1.0});
            } else {
              reduced = C(0, {dom.lo, dom.hi}, {mean});
            }
          }
          // 32 (p + 1) samples per knot interval: a peak of the difference of two degree-p
          // polynomials is wider than that spacing.
          double err = std::numeric_limits<double>::infinity();
          if constexpr (!bezier) {
            // The candidates ranked by their largest distance at 4 (p + 1) + 1 equally
            // spaced parameters per interval (the ends included: a fit's error often
            // peaks at a break), the least kept (the first of equals) and measured as
            // below. The answer does not depend on the tolerance, which only accepts or
            // refuses it.
            if (m >= 1) {
              double coarse = std::numeric_limits<double>::infinity();
              for (auto& [y, below] : spline_reductions(x, times)) {
                if (below > coarse) continue;  // a sampled error above the best's already
                const double e = sampled_deviation(x, y, breaks, 4 * (p + 1), coarse);
                if (e < coarse) {
                  coarse = e;
                  reduced = std::move(y);
                }
              }
              if (coarse < std::numeric_limits<double>::infinity()) err = 0;  // measured below
            }
          }
          if (bezier || m == 0 || err == 0) err = max_deviation<double>(x, reduced, breaks, 32 * (p + 1));
          if (!std::isfinite(err)) {
            throw InvalidArgument("curve", "no reduction from degree " + std::to_string(p) + " to " + std::to_string(m) +
                                               " with a finite distance to the curve was found (coordinates near the largest double?)");
          }
          if (!(err <= tolerance)) {
            throw InvalidArgument("tolerance", "reducing the degree from " + std::to_string(p) + " to " + std::to_string(m) +
                                                   " moves the curve by " + format_number(err) +
                                                   " (measured: the largest distance at equal parameters, of the best reduction "
                                                   "found), more than the tolerance " + format_number(tolerance));
          }
          return {AnyCurve(std::move(reduced)), err};
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
