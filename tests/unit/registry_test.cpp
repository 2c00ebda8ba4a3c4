// The curve-type registry (io::CurveTypes) and the piecewise Bézier form: a JSON round
// trip (write, read, compare) for every registered type at every run-time dimension,
// polylines and paths of any segment type, and the queries written once on the pieces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/io/json.hpp"
#include "test_support.hpp"

namespace {

using namespace casteljau;

// ---------------------------------------------------------------------------------------
// One sample per registered type and dimension. A type added to the registry without a
// sample here does not compile (the static_assert of Samples<C> says so), so the round
// trip below covers every type.

template <int D>
Point<double, D> pt(double a, double b) {
  Point<double, D> p;
  for (int k = 0; k < D; ++k) p[k] = a + (k + 1) * b + 0.1 * k * k;
  return p;
}

template <template <class, int> class>
inline constexpr bool no_round_trip_samples = false;

template <template <class, int> class C>
struct Samples {
  static_assert(no_round_trip_samples<C>, "a registered curve type (casteljau::CurveTypes) has no JSON round-trip samples: "
                                          "specialise Samples<C> in tests/unit/registry_test.cpp (docs/architecture.md, "
                                          "Adding a curve type)");
};

template <>
struct Samples<Bezier> {
  template <int D>
  static std::vector<Bezier<double, D>> make() {
    return {Bezier<double, D>({pt<D>(0, 0)}), Bezier<double, D>({pt<D>(0.1, 1), pt<D>(1.0 / 3, -2), pt<D>(1e300, 1e-300)})};
  }
};

template <>
struct Samples<RationalBezier> {
  template <int D>
  static std::vector<RationalBezier<double, D>> make() {
    return {RationalBezier<double, D>({pt<D>(1, 0), pt<D>(1, 1), pt<D>(0, 1)}, {1, std::sqrt(0.5), 1e-300})};
  }
};

template <>
struct Samples<BSpline> {
  template <int D>
  static std::vector<BSpline<double, D>> make() {
    return {BSpline<double, D>(1, {0, 0, 1, 1}, {pt<D>(0, 0), pt<D>(1, 1)}),
            BSpline<double, D>(2, {-1, 0.1, 0.1, 2, 3, 7}, {pt<D>(0, 0), pt<D>(1, 1), pt<D>(2, -1)})};
  }
};

template <>
struct Samples<Nurbs> {
  template <int D>
  static std::vector<Nurbs<double, D>> make() {
    return {Nurbs<double, D>(2, {0, 0, 0, 1, 1, 1}, {pt<D>(1, 0), pt<D>(1, 1), pt<D>(0, 1)}, {1, std::sqrt(0.5), 3e-7})};
  }
};

template <>
struct Samples<Polyline> {
  template <int D>
  static std::vector<Polyline<double, D>> make() {
    return {Polyline<double, D>({pt<D>(0, 0), pt<D>(0, 0), pt<D>(-1.5, 0.7)})};
  }
};

template <>
struct Samples<Lagrange> {
  template <int D>
  static std::vector<Lagrange<double, D>> make() {
    // Params in any order, uneven; a straight line through many points; Chebyshev nodes.
    return {Lagrange<double, D>({0.5, -1.25, 3}, {pt<D>(0, 0), pt<D>(1, 1), pt<D>(-0.3, 2.5)}),
            Lagrange<double, D>({0, 1, 2, 3, 4}, {pt<D>(0, 0), pt<D>(0, 1), pt<D>(0, 2), pt<D>(0, 3), pt<D>(0, 4)}),
            Lagrange<double, D>(interpolation_nodes<double>(Nodes::chebyshev1, 4, -1, 1),
                                {pt<D>(1, 0), pt<D>(1.0 / 3, 2), pt<D>(0, 0), pt<D>(-1, 1e-3)})};
  }
};

template <>
struct Samples<Hermite> {
  template <int D>
  static std::vector<Hermite<double, D>> make() {
    const auto v = [](double a) { return pt<D>(a, 0.5 * a).to_vector(); };
    return {Hermite<double, D>({0, 1}, {pt<D>(0, 0), pt<D>(1, 1)}, {v(1), v(-2)}),
            Hermite<double, D>({-1.5, 0.1, 1e-3 + 0.1, 7}, {pt<D>(0, 0), pt<D>(1, 1), pt<D>(2, -1), pt<D>(1.0 / 3, 3)},
                               {v(0.3), v(0), v(-1e5), v(1.0 / 7)})};
  }
};

template <>
struct Samples<CatmullRom> {
  template <int D>
  static std::vector<CatmullRom<double, D>> make() {
    const std::vector<Point<double, D>> P{pt<D>(0, 0), pt<D>(1, 1), pt<D>(-0.3, 2.5), pt<D>(2, 0.1), pt<D>(3, 3)};
    return {CatmullRom<double, D>(P), CatmullRom<double, D>(P, 0.0, true), CatmullRom<double, D>(P, 1.0 / 3, false),
            CatmullRom<double, D>({P[0], P[0], P[0], P[0]}, 0.0),
            CatmullRom<double, D>(P, 0.5, false, CatmullRomEnds::reflect),  // `ends` written and read back
            CatmullRom<double, D>({P[1], P[2]}, 0.0, false, CatmullRomEnds::reflect)};
  }
};

template <>
struct Samples<CubicSpline> {
  template <int D>
  static std::vector<CubicSpline<double, D>> make() {
    using B = SplineBoundary<double, D>;
    const std::vector<double> u = {-1, 0.25, 0.3, 2};
    const std::vector<Point<double, D>> P = {pt<D>(0, 0), pt<D>(1, 1), pt<D>(2, -1), pt<D>(0.1, 3)};
    const std::vector<Point<double, D>> closed = {pt<D>(0, 0), pt<D>(1, 1), pt<D>(2, -1), pt<D>(0, 0)};
    const auto v = [](double a) { return pt<D>(a, 1.0 / 3).to_vector(); };
    return {CubicSpline<double, D>(u, P), CubicSpline<double, D>(u, P, B::clamped(v(1), v(-2))),
            CubicSpline<double, D>(u, P, B::not_a_knot()), CubicSpline<double, D>(u, closed, B::periodic()),
            CubicSpline<double, D>(u, P, B::general({1, v(0.5)}, {2, v(-7)})), CubicSpline<double, D>({0, 1}, {P[0], P[1]})};
  }
};

template <>
struct Samples<Path> {
  template <int D>
  static std::vector<Path<double, D>> make() {
    using S = Segment<double, D>;
    return {Path<double, D>({S(Bezier<double, D>({pt<D>(0, 0), pt<D>(1, 1)}))}),
            Path<double, D>({S(Polyline<double, D>({pt<D>(1, 1), pt<D>(2, 0), pt<D>(3, 3)})),
                             S(RationalBezier<double, D>({pt<D>(3, 3), pt<D>(4, 0)}, {2, 0.5})),
                             S(Bezier<double, D>({pt<D>(9, 9), pt<D>(4, 0), pt<D>(0.3, 0.7)}))},
                            {-2.5, 0.1, 1e-3 + 0.1, 7})};
  }
};

template <template <class, int> class... C>
void round_trip_all(CurveTypeList<C...>) {
  (
      [] {
        const auto one_dim = [&]<int D>() {
          for (const auto& c : Samples<C>::template make<D>()) {
            const io::AnyCurve any(c);
            const std::string text = io::to_json(any).dump();
            const io::AnyCurve back = io::curve_from_json(io::parse_json(text));
            ASSERT_TRUE(std::holds_alternative<std::decay_t<decltype(c)>>(back)) << text;
            // Numbers are written in shortest round-trip form: the read curve is equal.
            EXPECT_EQ(std::get<std::decay_t<decltype(c)>>(back), c) << text;
            EXPECT_EQ(io::type_name(back), io::type_name(any));
            EXPECT_EQ(io::dimension(back), D);
          }
        };
        one_dim.template operator()<1>();
        one_dim.template operator()<2>();
        one_dim.template operator()<3>();
        one_dim.template operator()<4>();
      }(),
      ...);
}

TEST(Registry, JsonRoundTripOfEveryType) { round_trip_all(io::CurveTypes{}); }

TEST(Registry, TypeNames) {
  EXPECT_EQ(io::type_name(io::AnyCurve(Polyline<double, 2>({{0, 0}, {1, 1}}))), "polyline");
  EXPECT_EQ(io::type_name(io::AnyCurve(Bezier<double, 1>({Point<double, 1>(0.0)}))), "bezier");
  EXPECT_EQ(io::type_name(io::AnyCurve(RationalBezier<double, 3>({{0, 0, 0}}, {1}))), "rational_bezier");
  EXPECT_EQ(io::type_name(io::AnyCurve(Path<double, 4>({Bezier<double, 4>({{0, 0, 0, 0}})}))), "path");
}

/// Parses a curve object given as JSON text.
io::AnyCurve curve(const std::string& text) { return io::curve_from_json(io::parse_json(text)); }

// A nested path is spliced: its segments land on its break interval, mapped affinely.
TEST(Registry, NestedPathIsSpliced) {
  const auto any = curve(R"({"type": "path", "breaks": [0, 1, 5], "segments": [
      {"type": "bezier", "points": [[0, 0], [1, 0]]},
      {"type": "path", "breaks": [10, 11, 12], "segments": [
          {"type": "polyline", "points": [[1, 0], [2, 0], [2, 2]]},
          {"type": "bezier", "points": [[2, 2], [0, 2]]}]}]})");
  const auto& p = std::get<Path<double, 2>>(any);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.breaks(), (std::vector<double>{0, 1, 3, 5}));
  EXPECT_TRUE((std::holds_alternative<Polyline<double, 2>>(p.segments()[1])));
  // The polyline's own [0, 2] on [1, 3]: its vertex 1 at u = 2, derivative halved.
  EXPECT_EQ(p(2.0), (Point<double, 2>{2, 0}));
  EXPECT_EQ(p.derivative_at(1.5), (Vector<double, 2>{1, 0}));
  EXPECT_EQ(p(4.0), (Point<double, 2>{1, 2}));
}

TEST(Registry, ReaderErrors) {
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "polyline", "points": [[0, 0]]})"), "points", "at least 2 points");
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "polyline", "points": [[0, 0], [1, 1]], "degree": 1})"), "degree", "unknown field");
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "polyline", "points": [[0, 0], [1, 1]], "dim": 3})"), "dim", "dim is 3");
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "path", "segments": [{"type": "polyline", "points": [[0], [1]]},
                                   {"type": "bezier", "points": [[0, 1]]}]})"),
                          "segments[1]", "dimension 2");
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "path", "segments": [{"type": "polyline", "points": [[0], [1]]}], "breaks": [1, 1]})"),
                          "breaks[1]", "strictly increasing");
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "path", "segments": [{"type": "polyline", "points": [[0], [1]]}], "breaks": [0, 1, 2]})"),
                          "breaks", "one more break");
  EXPECT_INVALID_ARGUMENT(curve(R"({"type": "path", "segments": [{"type": "lagrangian"}]})"), "segments[0].type", "unknown curve type");
  // Input degree above the cap of the run-time interfaces.
  std::string big = R"({"type": "bezier", "points": [)";
  for (int i = 0; i <= io::max_degree + 1; ++i) big += std::string(i ? "," : "") + "[" + std::to_string(i) + "]";
  EXPECT_INVALID_ARGUMENT(curve(big + "]}"), "points", "highest supported degree 1000");
  // Nesting is bounded (the reader recurses).
  std::string deep = R"({"type": "bezier", "points": [[0]]})";
  for (int i = 0; i < 40; ++i) deep = R"({"type": "path", "segments": [)" + deep + "]}";
  EXPECT_THROW(curve(deep), InvalidArgument);
}

// ---------------------------------------------------------------------------------------
// Polylines and the queries on pieces.

using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;

TEST(Polyline, EvaluationAndDerivatives) {
  const Polyline<double, 2> c{{0, 0}, {2, 0}, {2, 4}};
  EXPECT_EQ(c.domain(), (Interval<double>{0, 2}));
  EXPECT_EQ(c(0.0), P2(0, 0));
  EXPECT_EQ(c(0.25), P2(0.5, 0));
  EXPECT_EQ(c(1.0), P2(2, 0));
  EXPECT_EQ(c(1.5), P2(2, 2));
  EXPECT_EQ(c(2.0), P2(2, 4));
  // Extrapolation extends the first and last segments.
  EXPECT_EQ(c(-1.0), P2(-2, 0));
  EXPECT_EQ(c(3.0), P2(2, 8));
  // The right segment answers at a vertex, the last one at the end.
  EXPECT_EQ(c.derivative_at(1.0), V2(0, 4));
  EXPECT_EQ(c.derivative_at(0.999), V2(2, 0));
  EXPECT_EQ(c.derivative_at(2.0), V2(0, 4));
  EXPECT_EQ(c.derivative_at(0.5, 2), V2(0, 0));
  EXPECT_EQ(c.derivative_at(1.5, 0), V2(2, 2));
  EXPECT_INVALID_ARGUMENT(c.derivative_at(0.5, -1), "k", ">= 0");
  EXPECT_INVALID_ARGUMENT(c(1e308), "t", "overflows");
  EXPECT_INVALID_ARGUMENT((Polyline<double, 2>({P2(0, 0)})), "points", "at least 2");
  EXPECT_INVALID_ARGUMENT((Polyline<double, 2>({P2(0, 0), P2(0, NAN)})), "points[1][1]", "finite");
  EXPECT_EQ(bounds(c).lo, P2(0, 0));
  EXPECT_EQ(bounds(c).hi, P2(2, 4));
}

TEST(Pieces, PolylinePiecesAreItsSegments) {
  const Polyline<double, 3> c{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}};
  const auto p = pieces(c);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.breaks(), (std::vector<double>{0, 1, 2, 3}));
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& b = std::get<Bezier<double, 3>>(p.segments()[i]);
    EXPECT_EQ(b.points(), (std::vector<Point<double, 3>>{c.points()[i], c.points()[i + 1]}));
  }
}

// flatten on pieces: the polyline of a polyline is its vertices; a path whose segments
// do not meet is refused when the gap exceeds the tolerance, bridged when it does not.
TEST(Pieces, FlattenJoinsPiecesAndRefusesGaps) {
  const Polyline<double, 2> c{{0, 0}, {2, 0}, {2, 4}};
  EXPECT_EQ(flatten(c, 0.1), c.points());
  using S = Segment<double, 2>;
  const Path<double, 2> gap({S(c), S(Bezier<double, 2>({P2(2, 4.5), P2(3, 5)}))});
  EXPECT_INVALID_ARGUMENT(flatten(gap, 0.1), "curve", "not connected at t = 1");
  const auto bridged = flatten(gap, 0.5);
  EXPECT_EQ(bridged, (std::vector<P2>{{0, 0}, {2, 0}, {2, 4}, {2, 4.5}, {3, 5}}));
  // A path that meets exactly writes the joint once.
  const Path<double, 2> joined({S(c), S(Bezier<double, 2>({P2(2, 4), P2(3, 5)}))}, {-1, 0.5, 2});
  EXPECT_EQ(flatten(joined, 0.1), (std::vector<P2>{{0, 0}, {2, 0}, {2, 4}, {3, 5}}));
  // Gaps of huge curves are measured without overflow: 1e200 apart is a gap, not inf.
  const Path<double, 2> far({S(Bezier<double, 2>({P2(0, 0), P2(1e300, 0)})), S(Bezier<double, 2>({P2(1e300, 1e299), P2(0, 0)}))});
  EXPECT_INVALID_ARGUMENT(flatten(far, 1e298), "curve", "apart");
}

TEST(Pieces, BoundsOnPiecesUseTheDomainNotTheUnitInterval) {
  // A quadratic on [2, 6] and a polyline on [6, 7]: the tight box comes from the pieces.
  using S = Segment<double, 2>;
  const Path<double, 2> p({S(Bezier<double, 2>({P2(0, 0), P2(1, 2), P2(2, 0)})), S(Polyline<double, 2>({P2(2, 0), P2(3, -1)}))},
                          {2, 6, 7});
  const auto b = bounds(p);
  EXPECT_EQ(b.lo, P2(0, -1));
  EXPECT_EQ(b.hi, P2(3, 1));  // the quadratic's peak y = 1 at its t = 1/2 (u = 4)
  EXPECT_EQ(start_point(p), P2(0, 0));
  EXPECT_EQ(end_point(p), P2(3, -1));
}

}  // namespace

// The shorthands are read as the nurbs of conics.hpp (the construction itself is tested in
// knots_test.cpp against the NURBS Book): the same curve, and a nurbs is what is written.
TEST(Registry, ShorthandsAreReadAsNurbs) {
  const auto read = [](const char* text) { return io::curve_from_json(io::parse_json(text)); };
  const io::AnyCurve c = read(R"({"type": "circle", "center": [1, 2], "radius": 3})");
  using N2 = Nurbs<double, 2>;
  ASSERT_TRUE(std::holds_alternative<N2>(c));
  EXPECT_EQ(std::get<N2>(c), nurbs_circle(P2(1.0, 2.0), 3.0));
  EXPECT_EQ(io::type_name(c), "nurbs");
  EXPECT_EQ(io::to_json(c)["type"], "nurbs");
  const io::AnyCurve a = read(R"({"type": "arc", "center": [0, 0], "radius": 2, "start_angle": -1, "end_angle": 2})");
  EXPECT_EQ(std::get<N2>(a), nurbs_arc(P2(0.0, 0.0), 2.0, -1.0, 2.0));
  const io::AnyCurve e = read(R"({"type": "ellipse", "center": [0, 0], "radii": [2, 1], "dim": 2})");
  EXPECT_EQ(std::get<N2>(e), nurbs_ellipse(P2(0.0, 0.0), V2(2.0, 0.0), V2(0.0, 1.0)));
  // 3-D with a normal along z: the plane circle lifted to the center's height.
  const io::AnyCurve s = read(R"({"type": "circle", "center": [0, 0, 5], "radius": 1, "normal": [0, 0, 2]})");
  const auto& n = std::get<Nurbs<double, 3>>(s);
  for (double t : {0.0, 0.1, 0.3, 0.5, 0.9}) {
    const Point<double, 3> q = n(t);
    EXPECT_EQ(q[2], 5.0);
    EXPECT_NEAR(std::hypot(q[0], q[1]), 1.0, 4e-16);  // on the circle to rounding
  }
  EXPECT_INVALID_ARGUMENT(read(R"({"type": "circle", "center": [0, 0], "radius": 0})"), "radius", "> 0");
  EXPECT_INVALID_ARGUMENT(read(R"({"type": "arc", "center": [0, 0], "radius": 1, "start_angle": 0, "end_angle": 7})"), "end_angle", "2 pi");
  EXPECT_INVALID_ARGUMENT(read(R"({"type": "ellipse", "center": [0, 0], "radii": [1, 2], "weights": [1]})"), "weights", "unknown field");
}
