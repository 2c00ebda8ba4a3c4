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

/// The limit of intersect_work that a request may ask for, checked before any work.
/// Measured on the shared 2-core machine (CPU time; wall time was 10 times more under
/// load): a pair of line segments is a box test, about 1.5 ns for 8 units (two
/// random-walk 20,000-point polylines, 3.2e9 units, 0.5 s), a pair of random degree-500
/// pieces about 0.4 s for 1.3e8 units. The largest accepted requests: seven degree-500
/// pieces against a degree-500 curve (8.8e8 units) 2.8 s, two 11,180-point random walks
/// 0.07 s, a 15,800-point walk's self-intersections 0.4 s. Refused: two 20,000-point
/// polylines, a 16,000-point polyline's self-intersections, eight degree-500 pieces
/// against one.
inline constexpr double max_intersect_work = 1e9;

/// The up-front estimate of intersect's work on two curves' Bézier pieces (b null: the
/// self-intersections of a, its pairs of distinct pieces): for each pair of pieces of
/// degrees n and m, (n + 1)(m + 1)(n + m + 2) / 2. The engine compares the pieces' monotone
/// arcs pairwise (about n m pairs) and subdivides a meeting pair at O(n + m) per step per
/// control point: 8 units for two line segments, 1.3e8 for two degree-500 pieces.
[[nodiscard]] double intersect_work(const Pieces<double, 2>& a, const Pieces<double, 2>* b);

/// The result is the library's Intersections<double> (algo/intersect.hpp; its JSON:
/// io/results.hpp).

/// The intersections of two 2-D curves (algo/intersect.hpp). Throws
/// InvalidArgument("curves[i]", ...) for a curve that is not 2-D or has a piece above
/// max_intersect_degree, InvalidArgument("curves", ...) when intersect_work is above
/// max_intersect_work, NumericalError when the subdivision limit is reached.
[[nodiscard]] Intersections<double> intersect(const AnyCurve& a, const AnyCurve& b);

/// The self-intersections of one 2-D curve (ta < tb). Throws as intersect(), naming
/// curves[0] (also for the work limit).
[[nodiscard]] Intersections<double> self_intersect(const AnyCurve& a);

}  // namespace casteljau::io
