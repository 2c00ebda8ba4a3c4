// Properties of the algorithms across curve types: flattening within tolerance, C^r joins
// built by cr_join_points pass is_cr, curvature under rigid motions and scaling, path
// bounds, and the piecewise algebra (for_each_piece tiles a range, portion keeps the curve).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "../unit/test_support.hpp"
#include "generators.hpp"

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using casteljau::prop::eps;

// Every point of the curve is within tolerance of the polyline (guaranteed by the flatness
// test on control points); checked at 1000 samples; vertices run from start to end.
RC_GTEST_PROP(AlgoProperty, FlattenWithinTolerance, ()) {
  const int n = *rc::gen::inRange(1, 11);
  const Bezier<double, 2> c(prop::control_points<2>(n));
  const double tol = std::pow(10.0, -*rc::gen::inRange(1, 5));
  const auto poly = flatten(c, tol);
  RC_ASSERT(poly.front() == c.points().front());
  RC_ASSERT(poly.back() == c.points().back());
  for (int i = 0; i <= 1000; ++i) RC_ASSERT(test::polyline_distance(c(i / 1000.0), poly) <= tol);
  // Rational curves likewise.
  const RationalBezier<double, 2> r(c.points(), prop::weights(n));
  const auto rp = flatten(r, tol);
  for (int i = 0; i <= 1000; ++i) RC_ASSERT(test::polyline_distance(r(i / 1000.0), rp) <= tol);
}

// Scaling a curve and its tolerance by 2^k scales the polyline by exactly 2^k with the
// same vertices (flatten works on a power-of-two-normalised copy), for k from tiny to
// huge coordinates; the coordinates stay normal numbers (|x| >= 2^-1022) unless 0, since
// the generator's nonzero coordinates are far above 2^-120.
RC_GTEST_PROP(AlgoProperty, FlattenScalesExactlyByPowersOfTwo, ()) {
  const int n = *rc::gen::inRange(1, 9);
  const auto P = prop::control_points<2>(n);
  const int k = *rc::gen::inRange(-900, 900);
  const double tol = std::pow(10.0, -*rc::gen::inRange(1, 5));
  std::vector<P2> Q(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) Q[i] = P2(std::ldexp(P[i][0], k), std::ldexp(P[i][1], k));
  const auto a = flatten(Bezier<double, 2>(P), tol), b = flatten(Bezier<double, 2>(Q), std::ldexp(tol, k));
  RC_ASSERT(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    RC_ASSERT(b[i][0] == std::ldexp(a[i][0], k));
    RC_ASSERT(b[i][1] == std::ldexp(a[i][1], k));
  }
  const auto w = prop::weights(n);
  const auto ra = flatten(RationalBezier<double, 2>(P, w), tol), rb = flatten(RationalBezier<double, 2>(Q, w), std::ldexp(tol, k));
  RC_ASSERT(ra.size() == rb.size());
}

// cr_join_points for random degrees, interval lengths and orders: the joined path is C^r
// at the joint. Derivative k (w.r.t. the path parameter) has size up to
// D_max = max_k |c^(k)| / h^k; the construction's rounding is relative to it, so the
// tolerance is 1e-10 (1 + D_max).
RC_GTEST_PROP(AlgoProperty, CrJoinPointsMakeCrJoins, ()) {
  const int n = *rc::gen::inRange(1, 7), m = *rc::gen::inRange(1, 7);
  const int r = *rc::gen::inRange(0, m + 1);
  const double h = *prop::coordinate(0.25, 4), g = *prop::coordinate(0.25, 4);
  const Bezier<double, 2> prev(prop::control_points<2>(n));
  auto Q = cr_join_points(prev, h, m, g, r);
  RC_ASSERT(Q.size() == static_cast<std::size_t>(r) + 1);
  while (Q.size() < static_cast<std::size_t>(m) + 1) Q.push_back(*prop::point<2>());
  const Path<double, 2> p({prev, Bezier<double, 2>(Q)}, {0.0, h, h + g});
  double dmax = 0;
  for (int k = 0; k <= r; ++k) dmax = std::max(dmax, norm(joint_derivatives(p, 1, k).left));
  // Re-differentiating the new segment amplifies the rounding of its points (size qmax)
  // by m!/(m-k)! 2^k / g^k (k-th differences, scaled to the path parameter): with g = 1/4
  // and k = 6 that is ~3e6, so this term, not the construction, dominates at high order.
  double qmax = 0, amplify = 0;
  for (const auto& q : Q) qmax = std::max(qmax, norm(q.to_vector()));
  for (int k = 0; k <= r; ++k) {
    double a = 1;
    for (int j = 0; j < k; ++j) a *= 2.0 * (m - j) / g;
    amplify = std::max(amplify, a);
  }
  const double tol = 1e-10 * (1 + dmax) + 16 * eps * qmax * amplify;
  RC_ASSERT(is_cr(p, 1, r, tol));
  RC_ASSERT(parametric_continuity(p, 1, r, tol) == r);
  // C1 with a first derivative that is not small relative to tol is G1: the unit tangents
  // differ by at most about tol / |c'| <= 1e-7.
  if (r >= 1 && norm(joint_derivatives(p, 1, 1).left) > 1e-3 * (1 + dmax)) RC_ASSERT(is_g1(p, 1, tol, 1e-6));
}

// Curvature is invariant under rotations and translations, flips sign under a reflection,
// and scales as 1/s under scaling by s. Away from points of near-zero speed the quotient
// is well conditioned: relative 1e-9 (the speed enters cubed, and the map rounds the
// control points once).
RC_GTEST_PROP(AlgoProperty, CurvatureUnderSimilarities, ()) {
  const int n = *rc::gen::inRange(2, 9);
  const Bezier<double, 2> c(prop::control_points<2>(n));
  const double t = *prop::parameter();
  const double speed = norm(c.derivative_at(t));
  RC_PRE(speed > 1e-3);
  const double angle = *prop::coordinate(-3, 3), s = std::pow(2.0, *rc::gen::inRange(-20, 21)) * 1.5;
  const auto rigid = rotation(angle) * Affine<double, 2>::translate({0.3, -0.7});
  Affine<double, 2> mirror = Affine<double, 2>::identity();
  mirror.linear[1][1] = -1;
  const double k = *curvature(c, t);
  const double scale = 1e-9 * (std::abs(k) + 1e-6 * std::pow(2.0 * n, 3) / (speed * speed * speed));
  RC_ASSERT(std::abs(*curvature(c.transform(rigid), t) - k) <= scale);
  RC_ASSERT(std::abs(*curvature(c.transform(mirror), t) + k) <= scale);
  RC_ASSERT(std::abs(*curvature(c.transform(Affine<double, 2>::scale(s)), t) * s - k) <= scale);
}

// The tight box of a path is the union of its segments' tight boxes and contains samples.
RC_GTEST_PROP(AlgoProperty, PathBounds, ()) {
  const int k = *rc::gen::inRange(1, 5);
  std::vector<Path<double, 2>::SegmentType> segs;
  Box<double, 2> expected = Box<double, 2>::empty_box();
  for (int i = 0; i < k; ++i) {
    const int n = *rc::gen::inRange(1, 8);
    if (*rc::gen::arbitrary<bool>()) {
      const Bezier<double, 2> b(prop::control_points<2>(n));
      expected.add(bounds(b));
      segs.emplace_back(b);
    } else {
      const RationalBezier<double, 2> r(prop::control_points<2>(n), prop::weights(n));
      expected.add(bounds(r));
      segs.emplace_back(r);
    }
  }
  const Path<double, 2> p(segs);
  const auto b = bounds(p);
  RC_ASSERT(b.lo == expected.lo);
  RC_ASSERT(b.hi == expected.hi);
  for (int i = 0; i <= 400; ++i) RC_ASSERT(b.contains(p(k * i / 400.0), 1e-13));
}

// The piecewise algebra on random pieces with random breaks (on a grid of 1/16, from -4):
// the parts for_each_piece visits, lifted back, tile the range (consecutive parts meet
// exactly at a break, or where the pieces jump the earlier ends at the double below it; the range's ends come back to within the rounding of one map,
// 4 eps of the domain's size), each part within its piece's own domain; locate then lift
// returns u (the same rounding); and portion(range) is the curve on the range (at its end,
// the last piece's end: random pieces need not meet at their breaks). Its
// tolerance: the two evaluations map u through different breaks (a against u_i), each
// rounding to about eps |u| (|u| <= 28) over a break interval of at least 1/16, so the
// own parameters differ by up to about 450 eps, times the speed in the own parameter, at
// most n (w_max / w_min)^2 max |P_(i+1) - P_i| <= 7 * 256 * 2 sqrt(2) ~ 5100: 5e-10;
// 1e-9 with margin (the portions' own rounding, a few eps, is far below).
RC_GTEST_PROP(AlgoProperty, PiecewiseAlgebraTilesRangesAndKeepsTheCurve, ()) {
  const int k = *rc::gen::inRange(1, 6);
  std::vector<BezierPiece<double, 2>> segs;
  std::vector<double> breaks{-4 + *rc::gen::inRange(0, 16) / 16.0};
  for (int i = 0; i < k; ++i) {
    const int n = *rc::gen::inRange(1, 8);
    if (*rc::gen::arbitrary<bool>())
      segs.emplace_back(Bezier<double, 2>(prop::control_points<2>(n)));
    else
      segs.emplace_back(RationalBezier<double, 2>(prop::control_points<2>(n), prop::weights(n)));
    breaks.push_back(breaks.back() + *rc::gen::inRange(1, 64) / 16.0);
  }
  const Pieces<double, 2> p(segs, breaks);
  const Interval<double> dom = p.domain();
  double a = dom.at(*prop::parameter()), b = dom.at(*prop::parameter());
  if (*rc::gen::arbitrary<bool>()) a = breaks[static_cast<std::size_t>(*rc::gen::inRange(0, k + 1))];  // on a break
  if (a > b) std::swap(a, b);
  const double slack = 4 * eps * std::max(std::abs(dom.lo), std::abs(dom.hi));
  std::vector<Interval<double>> lifted;
  std::vector<std::size_t> visited;
  Point<double, 2> end;  // the range's end on the last piece visited (its left limit at a break)
  p.for_each_piece({a, b}, [&](std::size_t i, const auto& piece, const Interval<double>& own) {
    RC_ASSERT(own.lo >= piece.domain().lo);
    RC_ASSERT(own.hi <= piece.domain().hi);
    lifted.push_back(p.lift(i, own));
    visited.push_back(i);
    end = piece(own.hi);
  });
  RC_ASSERT(!lifted.empty());
  RC_ASSERT(std::abs(lifted.front().lo - a) <= slack);
  RC_ASSERT(std::abs(lifted.back().hi - b) <= slack);
  // Where the pieces do not meet (a jump), the part before the break ends at the double
  // below it (the one rule at a jump: a reported t is where eval gives the point).
  for (std::size_t j = 1; j < lifted.size(); ++j) {
    // A jump read off the control points (the pieces' own end points differ), not from
    // the library's jumps_after: random pieces meet only where their points are equal.
    const auto ends = [&](std::size_t i, bool last) {
      return std::visit([last](const auto& s) { return last ? s.points().back() : s.points().front(); }, segs[i]);
    };
    if (!(ends(visited[j - 1], true) == ends(visited[j], false)))
      RC_ASSERT(lifted[j - 1].hi == std::nextafter(lifted[j].lo, -std::numeric_limits<double>::infinity()));
    else
      RC_ASSERT(lifted[j].lo == lifted[j - 1].hi);
  }
  const auto at = p.locate(a);
  RC_ASSERT(std::abs(p.lift(at.index, at.t) - a) <= slack);
  if (a < b) {
    const auto q = p.portion({a, b});
    RC_ASSERT(q.domain() == Interval<double>(a, b));
    for (int j = 0; j < 50; ++j) {
      const double u = a + (b - a) * j / 50;
      RC_ASSERT(prop::diff(q(u), p(u)) <= 1e-9);
    }
    // At b the portion ends on the piece before b; p itself, at a break, on the next one
    // (the pieces need not meet).
    RC_ASSERT(prop::diff(q(b), end) <= 1e-9);
  }
}

}  // namespace
