// The run-time fitting entry of io/fit.hpp: the only translation unit that instantiates
// algo/fit.hpp (Eigen's sparse solvers), once per dimension.
#include "casteljau/io/fit.hpp"

#include <algorithm>
#include <string>

#include "casteljau/algo/fit.hpp"
#include "casteljau/algo/smoothing.hpp"

namespace casteljau::io {

namespace {

template <int D>
std::optional<Vector<double, D>> vector_of(const std::optional<std::vector<double>>& v, const char* where) {
  if (!v) return std::nullopt;
  if (v->size() != static_cast<std::size_t>(D)) {
    throw InvalidArgument(where, "needs " + std::to_string(D) + " coordinates (the points' dimension), got " + std::to_string(v->size()));
  }
  Vector<double, D> x;
  for (int d = 0; d < D; ++d) x[d] = (*v)[static_cast<std::size_t>(d)];
  return x;
}

/// The smoothing fit: parameters by the fit's rule on [0, 1], then the smoothing spline.
template <int D>
AnyFit smoothing_fit(const std::vector<Point<double, D>>& Q, const AnyFitRequest& r) {
  for (std::size_t i = 0; i < Q.size(); ++i) require_finite_point(Q[i], "points[" + std::to_string(i) + "]");
  const std::size_t least = r.smoothing_gcv ? 3 : 2;
  if (Q.size() < least) {
    throw InvalidArgument("points", std::string("a smoothing fit") + (r.smoothing_gcv ? " with gcv" : "") + " needs at least " +
                                        std::to_string(least) + " points, got " + std::to_string(Q.size()));
  }
  // Work: one lambda costs about 0.3 us per point (measured, x86-64, one core: 1e5 points
  // in 27 ms); gcv's search usually takes 20 to 40 of them. At most smoothing_evaluation_limit
  // point-evaluations (about 2 s) per request: above it the search stops and is refused,
  // and a count of points that cannot afford 20 evaluations is refused up front.
  constexpr double smoothing_evaluation_limit = 6e6;
  const double n = static_cast<double>(Q.size());
  if (r.smoothing_gcv && n * 20 > smoothing_evaluation_limit) {
    throw InvalidArgument("points", "a gcv smoothing fit of " + std::to_string(Q.size()) +
                                        " points is above the work limit (about 20 or more evaluations of " +
                                        casteljau::detail::format_number(n) + " points; at most " +
                                        casteljau::detail::format_number(smoothing_evaluation_limit / 20) +
                                        " points): give smoothing as a number");
  }
  const int evaluations = static_cast<int>(std::min(500.0, smoothing_evaluation_limit / n));
  const std::vector<double> t = unit_parameters(Q, r.parametrization, false);
  SmoothingSpline<double, D> s = [&] {
    try {
      return smoothing_spline<double, D>(Q, t, r.smoothing_gcv ? std::nullopt : r.smoothing, evaluations);
    } catch (const NumericalError& e) {
      throw InvalidArgument("smoothing", e.what());
    }
  }();
  double e = 0;
  for (std::size_t k = 0; k < Q.size(); ++k) e = std::max(e, distance(s.curve(t[k]), Q[k]));
  return {AnyCurve(s.curve), e, s.lambda};
}

template <int D>
AnyFit fit_in(const PointList& L, const AnyFitRequest& r) {
  std::vector<Point<double, D>> Q(L.size());
  for (std::size_t i = 0; i < L.size(); ++i)
    for (int d = 0; d < D; ++d) Q[i][d] = L[i][static_cast<std::size_t>(d)];
  if (r.smoothing || r.smoothing_gcv) return smoothing_fit<D>(Q, r);
  FitRequest<double, D> req;
  req.degree = r.degree;
  req.control_points = r.control_points;
  req.tolerance = r.tolerance;
  req.parametrization = r.parametrization;
  req.start_derivative = vector_of<D>(r.start_derivative, "start_derivative");
  req.end_derivative = vector_of<D>(r.end_derivative, "end_derivative");
  req.closed = r.closed;
  FitResult<double, D> f = casteljau::fit(std::move(Q), req);
  return {AnyCurve(std::move(f.curve)), f.max_error, std::nullopt};
}

}  // namespace

AnyFit fit(const PointList& P, const AnyFitRequest& r) {
  return dispatch_dimension(P.dim, [&]<int D>() { return fit_in<D>(P, r); });
}

}  // namespace casteljau::io
