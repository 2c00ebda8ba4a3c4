// The run-time fitting entry of io/fit.hpp: the only translation unit that instantiates
// algo/fit.hpp (Eigen's sparse solvers), once per dimension.
#include "casteljau/io/fit.hpp"

#include <string>

#include "casteljau/algo/fit.hpp"

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

template <int D>
AnyFit fit_in(const PointList& L, const AnyFitRequest& r) {
  std::vector<Point<double, D>> Q(L.size());
  for (std::size_t i = 0; i < L.size(); ++i)
    for (int d = 0; d < D; ++d) Q[i][d] = L[i][static_cast<std::size_t>(d)];
  FitRequest<double, D> req;
  req.degree = r.degree;
  req.control_points = r.control_points;
  req.tolerance = r.tolerance;
  req.parametrization = r.parametrization;
  req.start_derivative = vector_of<D>(r.start_derivative, "start_derivative");
  req.end_derivative = vector_of<D>(r.end_derivative, "end_derivative");
  req.closed = r.closed;
  FitResult<double, D> f = casteljau::fit(std::move(Q), req);
  return {AnyCurve(std::move(f.curve)), f.max_error};
}

}  // namespace

AnyFit fit(const PointList& P, const AnyFitRequest& r) {
  return dispatch_dimension(P.dim, [&]<int D>() { return fit_in<D>(P, r); });
}

}  // namespace casteljau::io
