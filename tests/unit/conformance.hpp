// The shared curve contract, checked for every curve type (a typed, type-parameterised
// suite): domain end points, finite values, derivative_at against finite differences,
// reverse, transform, bounds, pieces, and rejection of non-finite parameters.
//
// The suite runs on every type of the library's list casteljau::CurveTypes
// (conformance_test.cpp): a curve template C of that list names the instances the suite
// runs in Samples<C>, and each instance has its Sample. A registered type without them
// does not compile (the static_asserts below say what to add).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "test_support.hpp"

namespace casteljau::test {

template <class>
inline constexpr bool no_sample = false;
template <template <class, int> class>
inline constexpr bool no_samples = false;

/// A non-trivial sample of a curve type: make(), and its expected start() and end() points.
template <class C>
struct Sample {
  static_assert(no_sample<C>, "this curve type has no conformance sample: specialise casteljau::test::Sample<C> "
                              "in tests/unit/conformance_test.cpp (docs/architecture.md, Adding a curve type)");
};

/// The instances of a curve template that the suite runs (types: a SampleList).
template <class... C>
struct SampleList {
  using types = SampleList;
};
template <template <class, int> class C>
struct Samples {
  static_assert(no_samples<C>, "a registered curve type (casteljau::CurveTypes) has no conformance samples: specialise "
                               "casteljau::test::Samples<C> and Sample<C<double, D>> in tests/unit/conformance_test.cpp "
                               "(docs/architecture.md, Adding a curve type)");
  using types = SampleList<>;
};

namespace detail {
template <class... Lists>
struct Concat;
template <class... A>
struct Concat<SampleList<A...>> {
  using type = ::testing::Types<A...>;
};
template <class... A, class... B, class... Rest>
struct Concat<SampleList<A...>, SampleList<B...>, Rest...> : Concat<SampleList<A..., B...>, Rest...> {};
template <class List, class... Extra>
struct SuiteTypes;
template <template <class, int> class... C, class... Extra>
struct SuiteTypes<CurveTypeList<C...>, Extra...> : Concat<typename Samples<C>::types..., SampleList<Extra...>> {};
}  // namespace detail

/// The samples of every curve template of the list (a CurveTypeList), then Extra..., as
/// the ::testing::Types of an INSTANTIATE_TYPED_TEST_SUITE_P.
template <class List, class... Extra>
using SuiteTypes = typename detail::SuiteTypes<List, Extra...>::type;

template <class C>
class Conformance : public ::testing::Test {};

TYPED_TEST_SUITE_P(Conformance);

/// n + 1 parameters spread over the domain, including both ends.
template <class C>
std::vector<double> params(const C& c, int n = 64) {
  std::vector<double> ts;
  const auto dom = c.domain();
  for (int i = 0; i <= n; ++i) ts.push_back(dom.at(static_cast<double>(i) / n));
  ts.back() = dom.hi;
  return ts;
}

TYPED_TEST_P(Conformance, ModelsTheConcepts) {
  static_assert(Curve<TypeParam>);
  static_assert(DifferentiableCurve<TypeParam>);
  static_assert(PiecewiseBezierCurve<TypeParam>);
}

// The exact Bézier form traces the same curve with the same parametrisation, so queries
// on the pieces never disagree with evaluation: points and derivatives (orders 1..3) at
// parameters across the domain and beyond it (extrapolation of the first and last
// piece). Both sides evaluate the same polynomials after one affine parameter map:
// a few ulps of the coordinates (<= 6) times the derivative's size (<= ~50 for k <= 3
// here, with the polyline's factor 6 per order): 1e-11.
TYPED_TEST_P(Conformance, PiecesTraceTheCurve) {
  const auto c = Sample<TypeParam>::make();
  const auto p = pieces(c);
  const auto dom = c.domain();
  EXPECT_EQ(p.domain(), dom);
  std::vector<double> ts = params(c, 97);
  ts.push_back(dom.lo - 0.1 * dom.length());
  ts.push_back(dom.hi + 0.1 * dom.length());
  if constexpr (requires { c.breaks(); }) ts.insert(ts.end(), c.breaks().begin(), c.breaks().end());
  for (double t : ts) {
    EXPECT_EQ(test::max_coord_diff(p(t), c(t)) <= 1e-13 * (1 + norm(c(t).to_vector())), true) << "t=" << t;
    for (int k = 1; k <= 3; ++k) {
      const auto a = p.derivative_at(t, k), b = c.derivative_at(t, k);
      EXPECT_LE(test::max_coord_diff(a, b), 1e-11 * (1 + norm(b))) << "t=" << t << " k=" << k;
    }
  }
  // Every piece's parameter lifts back to the curve's: the piece's ends are the breaks.
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.lift(i, 0.0), p.breaks()[i]);
    EXPECT_EQ(p.lift(i, 1.0), p.breaks()[i + 1]);
  }
}

// The domain's ends map to the first and last control points. Bézier forms interpolate
// exactly; a path maps its ends through Interval::fraction, exact at the break values.
TYPED_TEST_P(Conformance, DomainEndPoints) {
  const auto c = Sample<TypeParam>::make();
  const auto dom = c.domain();
  EXPECT_LT(dom.lo, dom.hi);
  EXPECT_EQ(c(dom.lo), Sample<TypeParam>::start());
  EXPECT_EQ(c(dom.hi), Sample<TypeParam>::end());
}

// Finite values everywhere in the domain, and inside the control box (convex hull).
TYPED_TEST_P(Conformance, FiniteAndInsideControlBounds) {
  const auto c = Sample<TypeParam>::make();
  const auto box = c.control_bounds();
  for (double t : params(c, 200)) {
    const auto p = c(t);
    EXPECT_TRUE(test::all_finite(p));
    EXPECT_TRUE(box.contains(p, 1e-14)) << "t=" << t;
    EXPECT_TRUE(test::all_finite(c.derivative_at(t, 1)));
    EXPECT_TRUE(test::all_finite(c.derivative_at(t, 2)));
  }
}

// derivative_at against central differences (c(t+h) - c(t-h)) / 2h: truncation error
// h^2 |c'''| / 6 and rounding eps |c| / h; with h = 1e-5 and |c'''|, |c| <= ~1e3 for these
// samples both are <= 1e-7, so 1e-6 is a safe bound. Second derivatives from differences
// of first derivatives, same step: error h^2 |c''''| / 6 + eps |c'| / h.
TYPED_TEST_P(Conformance, DerivativesMatchFiniteDifferences) {
  const auto c = Sample<TypeParam>::make();
  const auto dom = c.domain();
  const double h = 1e-5 * dom.length();
  const std::vector<double> joints = pieces(c).breaks();
  for (double t : params(c, 40)) {
    // Stay inside one segment of a path (breaks are at multiples of 1/40 of the domain
    // only for the Path sample's 0.5 = -1 + 1.5 * 40/40; avoid them and the domain ends).
    if (t - h <= dom.lo || t + h >= dom.hi) continue;
    // Nor straddle a joint of the pieces (a polyline's vertex, a path's break), where
    // derivatives jump.
    bool near_break = false;
    for (double b : joints) near_break = near_break || std::abs(t - b) <= 2 * h;
    if (near_break) continue;
    const auto fd = test::central_difference(c, t, h);
    EXPECT_LE(test::max_coord_diff(fd, c.derivative_at(t, 1)), 1e-6 * (1 + norm(fd))) << "t=" << t;
    const auto fd2 = (c.derivative_at(t + h, 1) - c.derivative_at(t - h, 1)) / (2 * h);
    EXPECT_LE(test::max_coord_diff(fd2, c.derivative_at(t, 2)), 1e-5 * (1 + norm(fd2))) << "t=" << t;
  }
}

// Reversing swaps the ends and traverses backwards: r(lo + hi - t) = c(t), and derivatives
// change sign. Reverse twice is the identity exactly (the same numbers, reordered twice).
TYPED_TEST_P(Conformance, Reverse) {
  const auto c = Sample<TypeParam>::make();
  const auto r = c.reverse();
  const auto dom = c.domain();
  EXPECT_EQ(r.domain(), dom);
  EXPECT_EQ(r.reverse(), c);
  for (double t : params(c, 50)) {
    const double u = dom.lo + dom.hi - t;
    // Both sides are evaluations at parameters related by one rounding: a few ulps of the
    // coordinates (<= 5) times |c'| (<= ~20).
    EXPECT_LE(test::max_coord_diff(r(u), c(t)), 1e-13) << "t=" << t;
  }
  // Away from breaks, derivatives flip sign.
  const double t = dom.at(0.3);
  EXPECT_LE(test::max_coord_diff(r.derivative_at(dom.lo + dom.hi - t), -c.derivative_at(t)), 1e-12);
}

// Affine invariance: the transformed curve is the transformed curve's image, to rounding
// of the map (entries <= 2, coordinates <= 5: 1e-13 absolute).
TYPED_TEST_P(Conformance, Transform) {
  const auto c = Sample<TypeParam>::make();
  constexpr int D = TypeParam::dimension;
  Affine<double, D> m = Affine<double, D>::identity();
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) m.linear[i][j] = (i == j ? 1.5 : 0.0) + 0.25 * (i - j);
  for (int i = 0; i < D; ++i) m.translation[i] = 0.5 * (i + 1);
  const auto tc = c.transform(m);
  for (double t : params(c, 50)) EXPECT_LE(test::max_coord_diff(tc(t), m(c(t))), 1e-13) << "t=" << t;
  // The identity map changes nothing.
  EXPECT_EQ(c.transform(Affine<double, D>::identity()), c);
  // Derivatives are mapped by the linear part only.
  const double t = c.domain().at(0.4);
  EXPECT_LE(test::max_coord_diff(tc.derivative_at(t), m(c.derivative_at(t))), 1e-12);
}

// Non-finite parameters throw InvalidArgument naming "t"; extrapolation outside the domain
// is finite.
TYPED_TEST_P(Conformance, NonFiniteParameterThrows) {
  const auto c = Sample<TypeParam>::make();
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    EXPECT_INVALID_ARGUMENT(c(bad), "t", "finite");
    EXPECT_INVALID_ARGUMENT(c.derivative_at(bad, 1), "t", "finite");
  }
  const auto dom = c.domain();
  EXPECT_TRUE(test::all_finite(c(dom.lo - 0.25)));
  EXPECT_TRUE(test::all_finite(c(dom.hi + 0.25)));
}

// Tight bounds of each type contain every sample and lie inside the control box.
TYPED_TEST_P(Conformance, TightBounds) {
  const auto c = Sample<TypeParam>::make();
  const auto b = bounds(c), cb = c.control_bounds();
  for (double t : params(c, 500)) EXPECT_TRUE(b.contains(c(t), 1e-14)) << "t=" << t;
  for (int d = 0; d < TypeParam::dimension; ++d) {
    EXPECT_GE(b.lo[d], cb.lo[d]);
    EXPECT_LE(b.hi[d], cb.hi[d]);
  }
}

REGISTER_TYPED_TEST_SUITE_P(Conformance, ModelsTheConcepts, PiecesTraceTheCurve, DomainEndPoints, FiniteAndInsideControlBounds, DerivativesMatchFiniteDifferences, Reverse, Transform, NonFiniteParameterThrows, TightBounds);

}  // namespace casteljau::test
