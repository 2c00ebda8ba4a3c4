// Intersections of plane curves for the run-time interfaces (the `intersect` command):
// compiled once in src/io/intersect.cpp.
#pragma once

#include "casteljau/algo/intersect.hpp"
#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// The highest piece degree `intersect` accepts: a pair of random degree-500 curves (160
/// crossings) takes about 0.7 s of CPU (degree 200: 45 ms, 300: 0.18 s; measured on the
/// shared 2-core machine under load), about what degree 200 took before fat-line
/// rejection (0.73 s). Arcs, subdivision and refinement all grow with the degree.
inline constexpr int max_intersect_degree = 500;

/// The result is the library's Intersections<double> (algo/intersect.hpp; its JSON:
/// io/results.hpp).

/// The intersections of two 2-D curves (algo/intersect.hpp). Throws
/// InvalidArgument("curves[i]", ...) for a curve that is not 2-D or has a piece above
/// max_intersect_degree, NumericalError when the subdivision limit is reached.
[[nodiscard]] Intersections<double> intersect(const AnyCurve& a, const AnyCurve& b);

/// The self-intersections of one 2-D curve (ta < tb).
[[nodiscard]] Intersections<double> self_intersect(const AnyCurve& a);

}  // namespace casteljau::io
