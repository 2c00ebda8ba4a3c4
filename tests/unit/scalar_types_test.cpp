// Every curve type of the library (casteljau::CurveTypes) at float and at long double, and
// every query on it, against closed forms: the conventions promise the templates at these
// scalars (docs/architecture.md), and this is where that promise is run. A registered type
// without its Parabola below does not compile.
//
// Every sample traces the parabola y = x^2 for x in [-1, 1] (the polyline: its chords
// through x = -1, -1/2, 0, 1/2, 1), with x an affine function of the curve's parameter
// over its domain, so that each query has one closed-form answer for all the types, and
// with dyadic control data, so that the float, double and long double curves are the same
// curve. The reference values are exact or were computed with mpmath at 40 digits (the
// derivations are next to them); each is written with 21 significant digits, more than
// long double's 19.
//
// Tolerances are in units of the scalar's own epsilon e (float 1.2e-7, long double
// 1.1e-19), each with its reason. Where a query computed anything in double, a long double
// result would be off by about 1e-16 = 1000 e: every long double tolerance below is under
// that, so the check tells a long double computation from a double one.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "test_support.hpp"

// A named namespace: in a unity batch the other sources' anonymous namespaces are the same
// one as this file's.
namespace scalar_types {

using namespace casteljau;

template <template <class, int> class>
inline constexpr bool no_parabola = false;

/// The parabola y = x^2, x in [-1, 1], as the curve type C at scalar T (see the file's
/// comment): make<T>(), and whether it is the polyline of chords.
template <template <class, int> class C>
struct Parabola {
  static_assert(no_parabola<C>, "a registered curve type (casteljau::CurveTypes) has no float / long double sample: "
                                "specialise Parabola<C> in tests/unit/scalar_types_test.cpp (docs/architecture.md, "
                                "Adding a curve type)");
};

template <class T>
Point<T, 2> on(T x) {
  return {x, x * x};
}
template <class T>
Vector<T, 2> slope(T x) {
  return {T(1), 2 * x};
}

template <>
struct Parabola<Bezier> {
  static constexpr const char* name = "bezier";
  static constexpr bool chords = false;
  // B(t) = (2t - 1, (2t - 1)^2) on [0, 1].
  template <class T>
  static Bezier<T, 2> make() {
    return {{-1, 1}, {0, -1}, {1, 1}};
  }
};

template <>
struct Parabola<RationalBezier> {
  static constexpr const char* name = "rational_bezier";
  static constexpr bool chords = false;
  // Equal weights: the polynomial curve, through the rational code.
  template <class T>
  static RationalBezier<T, 2> make() {
    return RationalBezier<T, 2>({{-1, 1}, {0, -1}, {1, 1}}, {2, 2, 2});
  }
};

template <>
struct Parabola<BSpline> {
  static constexpr const char* name = "bspline";
  static constexpr bool chords = false;
  // The Bézier above with the knot 1 inserted on [0, 2]: control points P0, (P0 + P1) / 2,
  // (P1 + P2) / 2, P2; x = t - 1.
  template <class T>
  static BSpline<T, 2> make() {
    return BSpline<T, 2>(2, {0, 0, 0, 1, 2, 2, 2}, {{-1, 1}, {-0.5, 0}, {0.5, 0}, {1, 1}});
  }
};

template <>
struct Parabola<Nurbs> {
  static constexpr const char* name = "nurbs";
  static constexpr bool chords = false;
  template <class T>
  static Nurbs<T, 2> make() {
    return Nurbs<T, 2>(2, {0, 0, 0, 1, 2, 2, 2}, {{-1, 1}, {-0.5, 0}, {0.5, 0}, {1, 1}}, {0.75, 0.75, 0.75, 0.75});
  }
};

template <>
struct Parabola<Polyline> {
  static constexpr const char* name = "polyline";
  static constexpr bool chords = true;
  // Vertex i at t = i: x = t / 2 - 1.
  template <class T>
  static Polyline<T, 2> make() {
    return {on<T>(-1), on<T>(-0.5), on<T>(0), on<T>(0.5), on<T>(1)};
  }
};

template <>
struct Parabola<Lagrange> {
  static constexpr const char* name = "lagrange";
  static constexpr bool chords = false;
  // A quadratic through three points of the parabola at params x (uneven): the parabola.
  template <class T>
  static Lagrange<T, 2> make() {
    return Lagrange<T, 2>({-1, 0.5, 1}, {on<T>(-1), on<T>(0.5), on<T>(1)});
  }
};

template <>
struct Parabola<CatmullRom> {
  static constexpr const char* name = "catmull_rom";
  static constexpr bool chords = false;
  // Uniform Catmull-Rom through x = -2..2: its tangents (P_{i+1} - P_{i-1}) / 2 are the
  // parabola's at uniform params, and a cubic Hermite with exact tangents reproduces a
  // quadratic. The curve runs from P_1 to P_3.
  template <class T>
  static CatmullRom<T, 2> make() {
    return CatmullRom<T, 2>({on<T>(-2), on<T>(-1), on<T>(0), on<T>(1), on<T>(2)}, T(0));
  }
};

template <>
struct Parabola<CubicSpline> {
  static constexpr const char* name = "cubic_spline";
  static constexpr bool chords = false;
  // Clamped with the parabola's own end tangents at params x: the spline is the parabola.
  template <class T>
  static CubicSpline<T, 2> make() {
    return CubicSpline<T, 2>({-1, -0.25, 0.5, 1}, {on<T>(-1), on<T>(-0.25), on<T>(0.5), on<T>(1)},
                             SplineBoundary<T, 2>::clamped(slope<T>(-1), slope<T>(1)));
  }
};

template <>
struct Parabola<Hermite> {
  static constexpr const char* name = "hermite";
  static constexpr bool chords = false;
  template <class T>
  static Hermite<T, 2> make() {
    return Hermite<T, 2>({-1, 0, 1}, {on<T>(-1), on<T>(0), on<T>(1)}, {slope<T>(-1), slope<T>(0), slope<T>(1)});
  }
};

template <>
struct Parabola<Path> {
  static constexpr const char* name = "path";
  static constexpr bool chords = false;
  // The left half as a Bézier on [-1, 0], the right half as a Hermite on [0, 1]: x = t.
  template <class T>
  static Path<T, 2> make() {
    return Path<T, 2>({Bezier<T, 2>{{-1, 1}, {-0.5, 0}, {0, 0}}, Hermite<T, 2>({0, 1}, {on<T>(0), on<T>(1)}, {slope<T>(0), slope<T>(1)})},
                      {-1, 0, 1});
  }
};

/// The closed-form answers, for the parabola and for the polyline of chords.
struct Expected {
  long double length;   // arc length over the domain
  long double x_at_quarter;  // x where the arc length from the start is length / 4
  long double x_closest, closest_distance;  // projection of (1/4, 1)
  long double y_closest;
  long double curvature;  // at x = 1/4
  long double x_crossing;  // the line y = 1/2 meets the curve at x = -+x_crossing
  long double area;        // of the curve closed by its chord from (1, 1) to (-1, 1)
};

// The parabola. Length: the antiderivative of sqrt(1 + 4x^2) is F(x) = x sqrt(1 + 4x^2) / 2
// + asinh(2x) / 4, so L = F(1) - F(-1) = sqrt(5) + asinh(2) / 2. x at L / 4: the root of
// F(x) - F(-1) = L / 4 (mpmath findroot, 40 digits). Closest point to q = (1/4, 1): the
// roots of d/dx |(x, x^2) - q|^2 / 2 = 2x^3 - x - 1/4 are -1/2, (1 -+ sqrt 5) / 4; the
// smallest distance is at x = (1 + sqrt 5) / 4 = cos 36 degrees, where y = (3 + sqrt 5) / 8 and
// the distance is sqrt(50 - 10 sqrt 5) / 8. Curvature 2 / (1 + 4x^2)^(3/2) at x = 1/4:
// 2 / 1.25^1.5. Crossing of y = 1/2: x = 1/sqrt(2). Area between the chord y = 1 and the
// parabola: the integral of 1 - x^2 over [-1, 1] = 4/3 (counter-clockwise: positive).
constexpr Expected parabola{2.95788571508919486766L, -0.610738682958059886042L, 0.809016994374947424102L,
                            0.657163890148917007532L, 0.654508497187473712051L, 1.43108350559986540570L,
                            0.707106781186547524401L, 4.0L / 3};

// The chords. Length: 2 (sqrt(13) + sqrt(5)) / 4. x at L / 4: inside the first chord
// (length sqrt(13) / 4 > L / 4), x = -1 + (L / 4) / (sqrt(13) / 4) / 2. Closest point to
// (1/4, 1): on the chord from (1/2, 1/4) to (1, 1) at (10/13, 17/26) (the foot of the
// perpendicular; the other chords are farther, checked with mpmath), distance
// sqrt((27/52)^2 + (9/26)^2) = 9 sqrt(13) / 52. Curvature 0 inside a chord. Crossing of
// y = 1/2 on the chord from (1/2, 1/4) to (1, 1): x = 1/2 + (1/4) / (3/4) / 2 = 2/3. Area:
// 2 minus the trapezoids under the chords, 2 - 2 (1/16 + 5/16) = 5/4.
constexpr Expected chords{2.92080962648188949476L, -0.594956581763489429762L, 10.0L / 13, 0.624037720753382762271L,
                          17.0L / 26, 0.0L, 2.0L / 3, 1.25L};

template <class T>
constexpr T eps = std::numeric_limits<T>::epsilon();

// The checks below are plain functions, called from the templates: each assertion is
// compiled once, not once per curve type and scalar (GoogleTest's macros are most of a
// test's code at -O0).

/// Expects |a - b| <= tol; the message gives the error in units of the scalar's epsilon e
/// (`at`: the index of a vertex, when >= 0).
void expect_close(long double a, long double b, long double tol, long double e, const char* what, long at = -1) {
  const long double err = std::abs(a - b);
  EXPECT_LE(err, tol) << std::setprecision(21) << what << (at >= 0 ? " at " + std::to_string(at) : std::string()) << ": " << a
                      << " against " << b << ", error " << err / e << " e, tolerance " << tol / e << " e";
}
#define EXPECT_CLOSE(a, b, tol) expect_close(static_cast<long double>(a), (b), (tol), eps<T>, #a)
#define EXPECT_CLOSE_AT(a, b, tol, at) expect_close(static_cast<long double>(a), (b), (tol), eps<T>, #a, static_cast<long>(at))

/// Expects the condition; returns it (for the checks that guard what follows).
bool check(bool ok, const char* what, long at = -1) {
  EXPECT_TRUE(ok) << what << (at >= 0 ? " at " + std::to_string(at) : std::string());
  return ok;
}
#define CHECK(cond) check((cond), #cond)
#define REQUIRE(cond) \
  if (!check((cond), #cond)) return

/// The curve closed by its chord from its end back to its start, as a path.
template <class C>
auto closed_by_chord(const C& c) {
  using T = typename C::Scalar;
  std::vector<Segment<T, 2>> segs;
  std::vector<T> breaks;
  if constexpr (std::is_same_v<C, Path<T, 2>>) {
    segs = c.segments();
    breaks = c.breaks();
  } else {
    segs = {c};
    breaks = {c.domain().lo, c.domain().hi};
  }
  segs.push_back(Bezier<T, 2>{c(c.domain().hi), c(c.domain().lo)});
  breaks.push_back(breaks.back() + 1);
  return Path<T, 2>(std::move(segs), std::move(breaks));
}

template <template <class, int> class C, class T>
void every_query() {
  using S = Parabola<C>;
  SCOPED_TRACE(std::string(S::name) + (std::is_same_v<T, float> ? " at float" : " at long double"));
  const C<T, 2> c = S::template make<T>();
  const Expected& ex = S::chords ? chords : parabola;
  const T e = eps<T>;
  const auto dom = c.domain();
  const T width = dom.hi - dom.lo;
  // The parameter of abscissa x, and dx/dt.
  const auto t_of = [&](long double x) { return static_cast<long double>(dom.lo) + (x + 1) / 2 * width; };
  const long double dxdt = 2 / static_cast<long double>(width);
  // The curve's ordinate at x (chords: the polyline's interpolant).
  const auto y_of = [&](long double x) {
    if (!S::chords) return x * x;
    const long double i = std::min(std::floor((x + 1) * 2), 3.0L), x0 = -1 + i / 2, x1 = x0 + 0.5L;
    return x0 * x0 + (x - x0) / (x1 - x0) * (x1 * x1 - x0 * x0);
  };

  // Points and derivatives at x = 3/8 (dyadic: the point is exact). Evaluation of a
  // piece of degree <= 3 with control points <= 4 after one parameter map: a few e of
  // the coordinates (<= 4) per step; the derivative a few more (differences of the
  // control points over piece widths >= 1/2): 64 e.
  {
    const T x = T(0.375), t = static_cast<T>(t_of(x));
    const auto p = c(t);
    EXPECT_CLOSE(p[0], x, 64 * e);
    EXPECT_CLOSE(p[1], y_of(x), 64 * e);
    const auto d = c.derivative_at(t, 1);
    EXPECT_CLOSE(d[0], dxdt, 64 * e * dxdt);
    EXPECT_CLOSE(d[1], (S::chords ? 0.5L : 2 * 0.375L) * dxdt, 64 * e * dxdt);
    const auto r = c.reverse();
    EXPECT_CLOSE(r(dom.lo + dom.hi - t)[1], y_of(x), 64 * e);
    // Affine map: x -> 2x + 1, y -> y / 2 (exact in binary).
    Affine<T, 2> m = Affine<T, 2>::identity();
    m.linear[0][0] = 2, m.linear[1][1] = 0.5, m.translation[0] = 1;
    EXPECT_CLOSE(c.transform(m)(t)[0], 2 * 0.375L + 1, 64 * e);
    std::vector<T> ts{dom.lo, t, dom.hi};
    std::vector<Point<T, 2>> out(3);
    evaluate(c, std::span<const T>(ts), std::span<Point<T, 2>>(out));
    EXPECT_CLOSE(out[1][1], y_of(x), 64 * e);
    EXPECT_CLOSE(out[2][0], 1.0L, 64 * e);
  }

  // Tight bounds [-1, 1] x [0, 1]: the corners are control points or the vertex (0, 0),
  // located at a simple root of y'(t) to a few e, where y is flat: 16 e.
  {
    const auto b = bounds(c);
    EXPECT_CLOSE(b.lo[0], -1.0L, 16 * e);
    EXPECT_CLOSE(b.hi[0], 1.0L, 16 * e);
    EXPECT_CLOSE(b.lo[1], 0.0L, 16 * e);
    EXPECT_CLOSE(b.hi[1], 1.0L, 16 * e);
  }

  // Arc length and its inverse. The quadrature's target is 1e-13 at double, the
  // equivalent 450 e at every scalar (arc_length_tolerance<T>); its error estimate
  // overestimates by orders of magnitude on a smooth speed, the sum of a few hundred
  // rounded terms is a few e: 64 e relative. The parameter at a quarter of the length is
  // the root of length(t) = L / 4 with speed >= 1: the length's error over the speed.
  {
    const T L = arc_length(c);
    EXPECT_CLOSE(L, ex.length, 64 * e * ex.length);
    const T t = parameter_at_length(c, static_cast<T>(ex.length / 4));
    EXPECT_CLOSE(t, t_of(ex.x_at_quarter), 64 * e * ex.length * width);
    EXPECT_CLOSE(arc_length(c, dom.lo, static_cast<T>(t_of(0))), ex.length / 2, 64 * e * ex.length);
  }

  // Projection of (1/4, 1): a simple minimum of the distance; the parameter is a root of
  // a cubic to a few e over its slope, the distance to a few e.
  {
    const auto pr = project(c, Point<T, 2>{0.25, 1});
    EXPECT_CLOSE(pr.distance, ex.closest_distance, 16 * e);
    EXPECT_CLOSE(pr.t, t_of(ex.x_closest), 64 * e * width);
    EXPECT_CLOSE(pr.point[0], ex.x_closest, 64 * e);
    EXPECT_CLOSE(pr.point[1], ex.y_closest, 64 * e);
  }

  // Curvature and frame at x = 1/4: c', c'' to a few e (see points), the curvature
  // |c' x c''| / |c'|^3 to a few e more: 64 e relative.
  {
    const T t = static_cast<T>(t_of(0.25L));
    const auto k = curvature(c, t);
    REQUIRE(k.has_value());
    EXPECT_CLOSE(*k, ex.curvature, 64 * e * (1 + ex.curvature));
    const auto f = frame(c, t);
    REQUIRE(f.has_value());
    // Tangent (1, 1/2) / sqrt(5/4) (the chord from (0, 0) to (1/2, 1/4) has the same
    // slope), left normal (-1/2, 1) / sqrt(5/4).
    const long double s = 1 / std::sqrt(1.25L);
    EXPECT_CLOSE(f->tangent[0], s, 16 * e);
    EXPECT_CLOSE(f->tangent[1], s / 2, 16 * e);
    REQUIRE(f->normal.has_value());
    EXPECT_CLOSE((*f->normal)[0], -s / 2, 16 * e);
    EXPECT_CLOSE(f->curvature, ex.curvature, 64 * e * (1 + ex.curvature));
  }

  // Features: the ordinate's minimum at x = 0 (the parabola's vertex: a simple root of
  // y', to a few e of the parameter range; the polyline's corner: the vertex exactly),
  // nothing else.
  {
    const auto fe = features(c);
    CHECK(fe.inflections.empty());
    CHECK(fe.cusps.empty());
    CHECK(fe.extrema[0].empty());
    REQUIRE(fe.extrema[1].size() == 1u);
    EXPECT_CLOSE(fe.extrema[1][0], t_of(0), 16 * e * width);
  }

  // Distance to the segment y = -1 (x in [-2, 2]): 1, at the vertex. A flat minimum: the
  // parameter is found to about sqrt(e), the distance to a few e.
  {
    const Bezier<T, 2> line{{-2, -1}, {2, -1}};
    const auto d = distance(c, line);
    EXPECT_CLOSE(d.distance, 1.0L, 16 * e);
    EXPECT_CLOSE(d.points[0][1], 0.0L, 16 * e);
  }

  // Intersections with the segment y = 1/2: two transversal crossings at x = -+x_crossing
  // (slopes >= 4/3 against the line): the parameters to a few e of the range.
  {
    const Bezier<T, 2> line{{-2, 0.5}, {2, 0.5}};
    const auto is = intersect(c, line);
    CHECK(is.overlaps.empty());
    REQUIRE(is.points.size() == 2u);
    EXPECT_CLOSE(is.points[0].ta, t_of(-ex.x_crossing), 64 * e * width);
    EXPECT_CLOSE(is.points[1].ta, t_of(ex.x_crossing), 64 * e * width);
    EXPECT_CLOSE(is.points[1].point[0], ex.x_crossing, 64 * e);
    CHECK(self_intersect(c).points.empty());
  }

  // Area closed by the chord: exact polynomial integrals (the equal-weight rational pieces
  // by quadrature to its target) summed over a few pieces: 64 e relative.
  EXPECT_CLOSE(area(closed_by_chord(c)), ex.area, 64 * e * ex.area);

  // The members the type has (split, elevate, knot insertion and removal, degree
  // reduction) keep the curve: points at x = 3/8 as evaluation (64 e); a removal of the
  // knot just inserted is exact up to the rounding of the insertion (its tolerance 1e-3
  // is far above it, the check is that it runs and removes it).
  {
    const T t = static_cast<T>(t_of(0.375L));
    if constexpr (requires { c.split(t); }) {
      const auto halves = c.split(t);
      EXPECT_CLOSE(halves.left(halves.left.domain().hi)[1], y_of(0.375L), 64 * e);
      EXPECT_CLOSE(halves.right(halves.right.domain().lo)[1], y_of(0.375L), 64 * e);
    }
    if constexpr (requires { c.elevate(1); }) {
      EXPECT_CLOSE(c.elevate(1)(t)[1], y_of(0.375L), 64 * e);
    }
    if constexpr (requires { c.insert_knot(t, 1); }) {
      const auto k = c.insert_knot(t, 1);
      EXPECT_CLOSE(k(t)[1], y_of(0.375L), 64 * e);
      const auto r = k.remove_knot(t, 1, T(1e-3));
      CHECK(r.removed == 1);
      EXPECT_CLOSE(r.curve(static_cast<T>(t_of(-0.5L)))[1], 0.25L, 64 * e);
    }
    if constexpr (requires { c.reduce_degree(T(1)); }) {
      const auto r = c.elevate(1).reduce_degree(T(1e-3));
      CHECK(r.curve.degree() == 2);
      EXPECT_CLOSE(r.curve(t)[1], y_of(0.375L), 64 * e);
    }
  }

  // Flattening within 1e-3: the vertices are points of the curve (64 e, as evaluation)
  // from its start to its end; for the parabola each chord within the tolerance (the
  // curve's farthest point from the chord from x0 to x1 is where the tangent is parallel
  // to it, at x = (x0 + x1) / 2, at distance (x1 - x0)^2 / 4 / sqrt(1 + (x0 + x1)^2)).
  {
    const T tol = T(1e-3);
    const auto poly = flatten(c, tol);
    REQUIRE(poly.size() >= 3u);
    EXPECT_CLOSE(poly.front()[0], -1.0L, 64 * e);
    EXPECT_CLOSE(poly.back()[0], 1.0L, 64 * e);
    for (std::size_t i = 0; i < poly.size(); ++i) {
      EXPECT_CLOSE_AT(poly[i][1], y_of(poly[i][0]), 64 * e, i);
      if (!S::chords && i + 1 < poly.size()) {
        const long double x0 = poly[i][0], x1 = poly[i + 1][0];
        check((x1 - x0) * (x1 - x0) / 4 / std::sqrt(1 + (x0 + x1) * (x0 + x1)) <= tol, "chord within the tolerance", static_cast<long>(i));
      }
    }
  }
}

template <template <class, int> class... C>
void every_type(CurveTypeList<C...>) {
  (every_query<C, float>(), ...);
  (every_query<C, long double>(), ...);
}

TEST(ScalarTypes, EveryTypeEveryQueryAtFloatAndLongDouble) { every_type(CurveTypes{}); }

// The queries that take points or a path rather than one curve.
template <class T>
void point_queries() {
  SCOPED_TRACE((std::is_same_v<T, float> ? "float" : "long double"));
  const T e = eps<T>;
  // A least-squares quadratic B-spline (5 control points) through 9 points of the parabola
  // at uniform parameters, x affine in t: the parabola is in the spline space, so the fit
  // is the parabola; Eigen's solve of a small well-conditioned system at T: 256 e.
  std::vector<Point<T, 2>> Q;
  for (int i = 0; i <= 8; ++i) Q.push_back(on<T>(T(i - 4) / 4));
  FitRequest<T, 2> req;
  req.degree = 2;
  req.control_points = 5;
  req.parametrization = Parametrization::uniform;
  const auto f = fit(Q, req);
  CHECK(f.max_error <= 256 * e);
  const auto p = f.curve(f.curve.domain().at(T(0.3)));
  EXPECT_CLOSE(p[1], static_cast<long double>(p[0]) * p[0], 256 * e);

  // Degree reduction of the parabola elevated to a cubic gives it back (exact up to the
  // least-squares solve: 64 e).
  const Bezier<T, 2> b{{-1, 1}, {0, -1}, {1, 1}};
  const auto red = reduce_degree(b.elevate(1), 2);
  CHECK(red.error_bound <= 64 * e);
  EXPECT_CLOSE(red.curve.points()[1][1], -1.0L, 64 * e);

  // Subdivision of the unit square (closed): Chaikin cuts each edge at 1/4 and 3/4, the
  // 4-point scheme (w = 1/16) puts (9/16)(P_1 + P_2) - (1/16)(P_0 + P_3) on each edge:
  // (1/2, -1/8) on the first. Dyadic arithmetic: exact.
  const std::vector<Point<T, 2>> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto ch = chaikin(square, 1, true);
  REQUIRE(ch.size() == 8u);
  CHECK((ch[0] == Point<T, 2>{0.25, 0}));
  CHECK((ch[1] == Point<T, 2>{0.75, 0}));
  const auto fp = four_point(square, 1, true);
  REQUIRE(fp.size() == 8u);
  CHECK((fp[1] == Point<T, 2>{0.5, -0.125}));
  CHECK(lane_riesenfeld_limit(square, 2, true).degree() == 2);

  // Continuity of the path sample at its joint x = 0: on both sides the first derivative
  // is (1, 0), the second (0, 2), the third 0 (exact in dyadic arithmetic): C^3 and G1
  // with tolerances of 64 e.
  const auto path = Parabola<Path>::template make<T>();
  const auto jc = joint_continuity(path, 3, 64 * e, 64 * e);
  REQUIRE(jc.size() == 1u);
  CHECK(jc[0].parametric == 3);
  CHECK(jc[0].g1);

  // The length of a degree-7 Bézier curve with control points up to 12 (the speed's
  // Bernstein coefficients up to 100 against speeds down to about 1): 15.5343025607747124039
  // (mpmath quad of the speed at 30 digits on 64 subintervals). Before the quadrature's
  // target was stated in units of T's epsilon, float threw here (its target 1e-13 was
  // below the integrand's rounding). The speed's rounding is up to 100 e relative where
  // it is small: 1024 e.
  const Bezier<T, 2> wiggly{{0, 0}, {10, 3}, {-4, 7}, {12, -5}, {3, 9}, {-8, 2}, {5, 5}, {1, -3}};
  EXPECT_CLOSE(arc_length(wiggly), 15.5343025607747124039L, 1024 * e * 15.6L);

  // A cusp off the dyadic grid: the cubic (0, 0), (1, 1), (0, 1), (1, 0) has its cusp at
  // t = 1/2 (both derivative coordinates 3/4 - 3/2 + 3/4 = 0 and 3/4 - 3/4 = 0); its
  // portion over [1/8, 3/4] has it at (1/2 - 1/8) / (5/8) = 3/5, with control points
  // rounded at T. Its velocity there is a few e of the hodograph, which in float is more
  // than the double threshold 1e-8 (cusp_tolerance is now 64 e in float). The cusp's
  // parameter: a common root of the two derivative coordinates, each simple: 64 e.
  const Bezier<T, 2> loop{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  const auto cusp = features(loop.portion(T(0.125), T(0.75)));
  REQUIRE(cusp.cusps.size() == 1u);
  EXPECT_CLOSE(cusp.cusps[0], 0.6L, 64 * e);

  // Equal arc lengths on the symmetric parabola: the middle parameter is the vertex,
  // t = 1/2 (as parameter_at_length: 64 e of the range).
  const auto ts = equal_length_parameters(b, 3);
  REQUIRE(ts.size() == 3u);
  EXPECT_CLOSE(ts[1], 0.5L, 64 * e);
}

TEST(ScalarTypes, PointQueriesAtFloatAndLongDouble) {
  point_queries<float>();
  point_queries<long double>();
}

// The twisted cubic (t, t^2, t^3), t in [0, 1], as a Bézier curve (control points (0, 0,
// 0), (1/3, 0, 0), (2/3, 1/3, 0), (1, 1, 1)): the 3-D frame at t = 1/2. Its derivatives
// are (1, 2t, 3t^2), (0, 2, 6t) and (0, 0, 6), the cross product of the first two
// (6t^2, -6t, 2) = (3/2, -3, 2) at t = 1/2, of length sqrt(61) / 2: the torsion
// 12 / (36t^4 + 36t^2 + 4) = 48/61, the curvature (sqrt(61) / 2) / (41/16)^(3/2) =
// 32 sqrt(61) / (41 sqrt(41)) = 0.952004740039499345894 (mpmath, 30 digits), the
// binormal's last coordinate 2 / (sqrt(61) / 2) = 4 / sqrt(61). The control points 1/3
// and 2/3 are rounded at T (half an e): the derivatives to a few e, the curvature and
// torsion (ratios of products of them) to 64 e.
template <class T>
void twisted_cubic() {
  SCOPED_TRACE((std::is_same_v<T, float> ? "float" : "long double"));
  const T e = eps<T>;
  const Bezier<T, 3> c{{0, 0, 0}, {T(1) / 3, 0, 0}, {T(2) / 3, T(1) / 3, 0}, {1, 1, 1}};
  const auto f = frame(c, T(0.5));
  REQUIRE(f.has_value());
  EXPECT_CLOSE(f->curvature, 0.952004740039499345894L, 64 * e);
  REQUIRE(f->torsion.has_value());
  EXPECT_CLOSE(*f->torsion, 48.0L / 61, 64 * e);
  REQUIRE(f->binormal.has_value());
  EXPECT_CLOSE((*f->binormal)[2], 4 / std::sqrt(61.0L), 64 * e);
  EXPECT_CLOSE(*curvature(c, T(0.5)), 0.952004740039499345894L, 64 * e);
}

TEST(ScalarTypes, FrameInSpaceAtFloatAndLongDouble) {
  twisted_cubic<float>();
  twisted_cubic<long double>();
}

#undef EXPECT_CLOSE
#undef EXPECT_CLOSE_AT
#undef CHECK
#undef REQUIRE

}  // namespace scalar_types
