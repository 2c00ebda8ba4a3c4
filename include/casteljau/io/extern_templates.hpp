// The library's queries at double, compiled once in casteljau::io (src/io/extern_templates.cpp)
// and declared here as explicit instantiation declarations (`extern template`), so that a
// translation unit that includes this header calls that compiled code instead of
// instantiating and compiling the queries again.
//
// Opt-in: include it only in code that links casteljau::io (the project's tests do, through
// tests/unit/test_support.hpp). The header-only library (casteljau/casteljau.hpp) never
// includes it, so a user without casteljau::io instantiates every template as before.
//
// What is listed: the queries written once on the pieces (docs/architecture.md), on
// Pieces<double, D> for D = 1..4, and the step to the pieces of every registered curve type.
// The overloads for the other curve types are one line that calls the Pieces version, so
// they stay implicit and cheap. A query whose return type is deduced (auto) cannot be
// declared extern (its body is needed for the type) and is left out; so are the algorithms
// other helpers own this session (offset, to_quadratic). See docs/architecture.md, "Adding
// a query", for where a new query's lines go.
#pragma once

#include <type_traits>

#include "casteljau/casteljau.hpp"

// The registry's curve types (curves/path.hpp, SegmentTypes) as an X-macro: X(Type, D) for
// each. The static_assert below fails when the registry gains a type this list lacks.
#define CASTELJAU_SEGMENT_TYPES(X, D) \
  X(Bezier, D) X(RationalBezier, D) X(BSpline, D) X(Nurbs, D) X(Polyline, D) X(Lagrange, D) X(CatmullRom, D) X(CubicSpline, D) X(Hermite, D)

// pieces(c) of one curve type (CatmullRom returns a reference to its own pieces).
#define CASTELJAU_PIECES_OF(Type, D) \
  EXTERN_OR_NOT template std::conditional_t<std::is_same_v<Type<double, D>, CatmullRom<double, D>>, const Pieces<double, D>&, Pieces<double, D>> pieces(const Type<double, D>&);

// Every query at one dimension D, on Pieces<double, D>. EXTERN_OR_NOT is `extern` for the
// declarations (below) and empty for the definitions (src/io/extern_templates.cpp).
#define CASTELJAU_QUERIES_AT(D)                                                                              \
  CASTELJAU_SEGMENT_TYPES(CASTELJAU_PIECES_OF, D)                                                            \
  EXTERN_OR_NOT template Box<double, D> bounds(const Bezier<double, D>&);                                    \
  EXTERN_OR_NOT template Box<double, D> bounds(const Bezier<double, D>&, double, double);                    \
  EXTERN_OR_NOT template Box<double, D> bounds(const RationalBezier<double, D>&);                            \
  EXTERN_OR_NOT template Box<double, D> bounds(const RationalBezier<double, D>&, double, double);            \
  EXTERN_OR_NOT template Box<double, D> bounds(const Pieces<double, D>&);                                    \
  EXTERN_OR_NOT template Box<double, D> bounds(const Pieces<double, D>&, double, double);                    \
  EXTERN_OR_NOT template double arc_length(const Pieces<double, D>&, double, double);                        \
  EXTERN_OR_NOT template double arc_length(const Pieces<double, D>&);                                        \
  EXTERN_OR_NOT template Projection<double, D> project(const Pieces<double, D>&, const Point<double, D>&, bool); \
  EXTERN_OR_NOT template Features<double, D> features(const Pieces<double, D>&);                             \
  EXTERN_OR_NOT template CurveDistance<double, D> distance(const Pieces<double, D>&, const Pieces<double, D>&); \
  EXTERN_OR_NOT template std::optional<Frame<double, D>> frame(const Pieces<double, D>&, double);            \
  EXTERN_OR_NOT template LevelSet<double> solve(const Pieces<double, D>&, const Vector<double, D>&, double); \
  EXTERN_OR_NOT template BSplineForm<double, D> to_bspline(const Pieces<double, D>&);                        \
  EXTERN_OR_NOT template double flatten_count_estimate(const Pieces<double, D>&, double);                    \
  EXTERN_OR_NOT template void flatten(const Pieces<double, D>&, double, FlattenMethod, std::vector<Point<double, D>>&); \
  EXTERN_OR_NOT template std::vector<Point<double, D>> flatten(const Pieces<double, D>&, double, FlattenMethod); \
  EXTERN_OR_NOT template void flatten(const Bezier<double, D>&, double, FlattenMethod, std::vector<Point<double, D>>&); \
  EXTERN_OR_NOT template std::vector<Point<double, D>> flatten(const Bezier<double, D>&, double, FlattenMethod); \
  EXTERN_OR_NOT template void flatten(const RationalBezier<double, D>&, double, FlattenMethod, std::vector<Point<double, D>>&); \
  EXTERN_OR_NOT template std::vector<Point<double, D>> flatten(const RationalBezier<double, D>&, double, FlattenMethod);

// The queries of plane curves only (D = 2).
#define CASTELJAU_PLANE_QUERIES                                                                               \
  CASTELJAU_QUERIES_AT(2)                                                                                     \
  EXTERN_OR_NOT template double area(const Pieces<double, 2>&);                                              \
  EXTERN_OR_NOT template Intersections<double> intersect(const Pieces<double, 2>&, const Pieces<double, 2>&); \
  EXTERN_OR_NOT template Intersections<double> self_intersect(const Pieces<double, 2>&);                     \
  EXTERN_OR_NOT template Intersections<double> detail::isect::solve_extreme(const Pieces<double, 2>&, const Pieces<double, 2>*);

// Every line of the list.
#define CASTELJAU_EXTERN_TEMPLATE_LIST \
  CASTELJAU_QUERIES_AT(1) CASTELJAU_PLANE_QUERIES CASTELJAU_QUERIES_AT(3) CASTELJAU_QUERIES_AT(4)

namespace casteljau {
static_assert(std::is_same_v<SegmentTypes, CurveTypeList<Bezier, RationalBezier, BSpline, Nurbs, Polyline, Lagrange, CatmullRom, CubicSpline, Hermite>>,
              "a curve type joined SegmentTypes (curves/path.hpp): add it to CASTELJAU_SEGMENT_TYPES in io/extern_templates.hpp");

// CASTELJAU_NO_EXTERN_TEMPLATES: compile the queries in this translation unit again (to
// step through them at -O0 in a debugger, or to measure what the declarations save).
#ifndef CASTELJAU_NO_EXTERN_TEMPLATES
#define EXTERN_OR_NOT extern
CASTELJAU_EXTERN_TEMPLATE_LIST
#undef EXTERN_OR_NOT
#endif
}  // namespace casteljau
