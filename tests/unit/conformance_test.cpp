// The conformance suite (conformance.hpp) run on every curve type of the library: the
// types come from the library's list (casteljau::CurveTypes) through Samples<C>, so a
// registered type without samples here does not compile. Also Pieces (the scalar types
// and dimensions beyond double 2-D/3-D: instantiations_test.cpp).
#include <numbers>

#include "conformance.hpp"

namespace casteljau::test {

// ---------------------------------------------------------------------------------------
// The Bézier family: Bezier, RationalBezier, Polyline, Path and Pieces.

template <>
struct Sample<Bezier<double, 2>> {
  static Bezier<double, 2> make() { return {{0, 0}, {1, 2.5}, {2.5, -1}, {4, 1.5}, {3, 3}}; }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {3, 3}; }
};

template <>
struct Sample<Bezier<double, 3>> {
  static Bezier<double, 3> make() { return {{0, 0, 1}, {1, 2, -1}, {3, -1, 0.5}, {2, 2, 2}}; }
  static Point<double, 3> start() { return {0, 0, 1}; }
  static Point<double, 3> end() { return {2, 2, 2}; }
};

template <>
struct Sample<RationalBezier<double, 2>> {
  static RationalBezier<double, 2> make() { return {{{1, 0}, {1, 1}, {0.5, 2}, {0, 1}}, {1, 0.6, 2.5, 1.2}}; }
  static Point<double, 2> start() { return {1, 0}; }
  static Point<double, 2> end() { return {0, 1}; }
};

template <>
struct Sample<Path<double, 2>> {
  // A cubic on [-1, 0.5] and a rational quadratic on [0.5, 2], C0 at the joint.
  static Path<double, 2> make() {
    return Path<double, 2>({Bezier<double, 2>{{0, 0}, {1, 1}, {2, -1}, {3, 0}},
                            RationalBezier<double, 2>({{3, 0}, {4, 1}, {5, 0}}, {1, 3, 1})},
                           {-1.0, 0.5, 2.0});
  }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {5, 0}; }
};

template <>
struct Sample<Polyline<double, 2>> {
  static Polyline<double, 2> make() { return {{0, 0}, {1, 2}, {1, 2}, {3, -1}, {4, 0.5}}; }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {4, 0.5}; }
};

/// A path of every segment type, one of them a polyline whose own domain [0, 3] is mapped
/// onto [1, 1.5] (so its derivatives scale by 6).
template <>
struct Sample<Path<double, 3>> {
  static Path<double, 3> make() {
    return Path<double, 3>({Bezier<double, 3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}},
                            Polyline<double, 3>{{2, 0, 1}, {3, 1, 1}, {3, 2, 0}, {4, 2, 2}},
                            RationalBezier<double, 3>({{4, 2, 2}, {5, 3, 2}, {6, 2, 1}}, {1, 0.5, 2})},
                           {0.0, 1.0, 1.5, 4.0});
  }
  static Point<double, 3> start() { return {0, 0, 0}; }
  static Point<double, 3> end() { return {6, 2, 1}; }
};

template <>
struct Sample<Pieces<double, 2>> {
  static Pieces<double, 2> make() { return pieces(Sample<Path<double, 2>>::make()); }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {5, 0}; }
};

// ---------------------------------------------------------------------------------------
// B-splines and NURBS.

/// A non-uniform, unclamped cubic B-spline with a double interior knot.
template <>
struct Sample<BSpline<double, 2>> {
  static BSpline<double, 2> make() {
    return BSpline<double, 2>(3, {-1, -0.5, 0, 0.5, 1.5, 1.5, 2.5, 3, 4, 4.5},
                              {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}, {4, 0.5}, {5, 2}});
  }
  // The domain [0.5, 2.5]; the points there are (5/6, 23/18) and (187/45, 11/15), as
  // scipy.interpolate.BSpline 1.10 rounds them (its own de Boor, bit for bit ours).
  static Point<double, 2> start() { return {0.8333333333333334, 1.277777777777778}; }
  static Point<double, 2> end() { return {4.155555555555556, 0.7333333333333334}; }
};

/// The full NURBS circle of radius 2 about (1, -1): nine points, weights 1 and sqrt(2)/2,
/// double knots at the quarters [PT97, Ex. 7.2].
template <>
struct Sample<Nurbs<double, 2>> {
  static Nurbs<double, 2> make() {
    const double h = std::sqrt(0.5);
    return Nurbs<double, 2>(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                            {{3, -1}, {3, 1}, {1, 1}, {-1, 1}, {-1, -1}, {-1, -3}, {1, -3}, {3, -3}, {3, -1}},
                            {1, h, 1, h, 1, h, 1, h, 1});
  }
  static Point<double, 2> start() { return {3, -1}; }
  static Point<double, 2> end() { return {3, -1}; }
};

// ---------------------------------------------------------------------------------------
// The interpolating polynomial curves: Lagrange and Catmull-Rom (open centripetal, closed
// chordal).

/// A cubic Lagrange curve through four points at uneven params given out of order; the
/// params are dyadic, so that reversing twice gives them back exactly.
template <>
struct Sample<Lagrange<double, 2>> {
  static Lagrange<double, 2> make() {
    return Lagrange<double, 2>({0.75, -0.5, 2, 0.25}, {{1, 2}, {0, 0}, {3, -1}, {0.5, 1.5}});
  }
  // The domain's ends are the params -0.5 and 2: the points there, exactly.
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {3, -1}; }
};

/// A centripetal open Catmull-Rom curve whose distances are perfect squares (16, 9, 25, 4,
/// 1: intervals 4, 3, 5, 2, 1 exactly), so that its knots and the reversed curve's are
/// exact sums. Segments from P_1 to P_4; domain [0, 3 + 5 + 2] = [0, 10].
template <>
struct Sample<CatmullRom<double, 2>> {
  static CatmullRom<double, 2> make() {
    return CatmullRom<double, 2>({{0, 0}, {16, 0}, {16, 9}, {-9, 9}, {-9, 5}, {-8, 5}}, 0.5);
  }
  static Point<double, 2> start() { return {16, 0}; }
  static Point<double, 2> end() { return {-9, 5}; }
};

/// A closed chordal triangle with integer side lengths 3, 4, 3 (exact knot sums): the
/// curve starts and ends at P_0.
template <>
struct Sample<CatmullRom<double, 3>> {
  static CatmullRom<double, 3> make() { return CatmullRom<double, 3>({{0, 0, 0}, {2, 1, 2}, {2, 1, -2}}, 1.0, true); }
  static Point<double, 3> start() { return {0, 0, 0}; }
  static Point<double, 3> end() { return {0, 0, 0}; }
};

// ---------------------------------------------------------------------------------------
// The interpolating cubics: Hermite curves and cubic splines.

/// A Hermite curve on uneven params with tangents of mixed sizes.
template <>
struct Sample<Hermite<double, 2>> {
  static Hermite<double, 2> make() {
    return Hermite<double, 2>({-1, 0.5, 0.75, 2.5}, {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}},
                              {{1, 1}, {2, 0}, {0.5, -3}, {1, 1}});
  }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {3, -1}; }
};

/// Kochanek-Bartels one-sided tangents (continuity -0.5: a corner at every point).
template <>
struct Sample<Hermite<double, 3>> {
  static Hermite<double, 3> make() {
    const std::vector<double> u = {0, 1, 1.5, 3};
    const std::vector<Point<double, 3>> P = {{0, 0, 0}, {1, 2, 1}, {2.5, 1.5, -1}, {3, -1, 0}};
    auto m = kochanek_bartels_tangents(u, P, KochanekBartels<double>{0.25, -0.5, 0.5});
    return Hermite<double, 3>(u, P, m.incoming, m.outgoing);
  }
  static Point<double, 3> start() { return {0, 0, 0}; }
  static Point<double, 3> end() { return {3, -1, 0}; }
};

/// A natural spline on uneven params.
template <>
struct Sample<CubicSpline<double, 2>> {
  static CubicSpline<double, 2> make() {
    return CubicSpline<double, 2>({0, 0.5, 1.25, 2, 4}, {{0, 0}, {1, 2}, {2.5, 1.5}, {3, -1}, {1, -2}});
  }
  static Point<double, 2> start() { return {0, 0}; }
  static Point<double, 2> end() { return {1, -2}; }
};

/// A closed (periodic) spline.
template <>
struct Sample<CubicSpline<double, 3>> {
  static CubicSpline<double, 3> make() {
    return CubicSpline<double, 3>({0, 1, 1.5, 2.25, 3}, {{1, 0, 0}, {0, 1, 0.5}, {-1, 0, 1}, {0, -1, 0.5}, {1, 0, 0}},
                                  SplineBoundary<double, 3>::periodic());
  }
  static Point<double, 3> start() { return {1, 0, 0}; }
  static Point<double, 3> end() { return {1, 0, 0}; }
};

// ---------------------------------------------------------------------------------------
// The instances of each registered type that the suite runs (each has its Sample above).

template <>
struct Samples<Bezier> : SampleList<Bezier<double, 2>, Bezier<double, 3>> {};
template <>
struct Samples<RationalBezier> : SampleList<RationalBezier<double, 2>> {};
template <>
struct Samples<BSpline> : SampleList<BSpline<double, 2>> {};
template <>
struct Samples<Nurbs> : SampleList<Nurbs<double, 2>> {};
template <>
struct Samples<Polyline> : SampleList<Polyline<double, 2>> {};
template <>
struct Samples<Lagrange> : SampleList<Lagrange<double, 2>> {};
template <>
struct Samples<CatmullRom> : SampleList<CatmullRom<double, 2>, CatmullRom<double, 3>> {};
template <>
struct Samples<CubicSpline> : SampleList<CubicSpline<double, 2>, CubicSpline<double, 3>> {};
template <>
struct Samples<Hermite> : SampleList<Hermite<double, 2>, Hermite<double, 3>> {};
template <>
struct Samples<Path> : SampleList<Path<double, 2>, Path<double, 3>> {};

// Every registered type's samples, and the exact pieces (not a registered type).
using EveryType = SuiteTypes<CurveTypes, Pieces<double, 2>>;
INSTANTIATE_TYPED_TEST_SUITE_P(EveryType, Conformance, EveryType);

}  // namespace casteljau::test
