// to_quadratic (issue 20) in the library. Its checks sample the curves densely (a brute-force
// two-sided distance between polylines of thousands of points), so this source is one of
// the unit executable's own, built at -O1 (at -O0 the suite took 48 s).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "test_support.hpp"  // the whole library (casteljau.hpp: to_quadratic)

namespace {

using namespace casteljau;
using P2 = Point<double, 2>;
using B2 = Bezier<double, 2>;
using R2 = RationalBezier<double, 2>;

// to_quadratic: closed forms (exact low degrees, an elevated quadratic), and on random and
// special curves an independent check written here: dense samples of both curves, the
// two-sided distance (each sample to the other's dense polyline) within the tolerance,
// joints tangent-continuous.

/// The largest distance from the points a to the polyline b (brute force).
template <int D>
double to_polyline(const std::vector<Point<double, D>>& a, const std::vector<Point<double, D>>& b) {
  double worst = 0;  // squared distances (moderate coordinates: no overflow)
  for (const auto& p : a) {
    double best = INFINITY;
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      const Vector<double, D> e = b[j + 1] - b[j];
      const double ee = dot(e, e);
      const double u = ee > 0 ? std::clamp(dot(p - b[j], e) / ee, 0.0, 1.0) : 0.0;
      const Vector<double, D> r = p - (b[j] + u * e);
      best = std::min(best, dot(r, r));
    }
    worst = std::max(worst, best);
  }
  return std::sqrt(worst);
}

/// Checks a chain against the curve: breaks, two-sided distance within tol plus `slack`,
/// joints where the curve is tangent-continuous (its one-sided derivatives at the joint's
/// parameter) within 1e-9 rad; returns the segment count.
template <class C>
std::size_t check_chain(const C& c, const QuadraticChain<double, C::dimension>& r, double tol, double slack, const char* what) {
  constexpr int D = C::dimension;
  SCOPED_TRACE(what);
  EXPECT_EQ(r.breaks.size(), r.segments.size() + 1);
  EXPECT_EQ(r.breaks.front(), c.domain().lo);
  EXPECT_EQ(r.breaks.back(), c.domain().hi);
  std::vector<Point<double, D>> curve, quads;
  const int per = 400;
  const auto dom = c.domain();
  for (int j = 0; j <= per * 8; ++j) curve.push_back(c(dom.lo + (dom.hi - dom.lo) * j / (per * 8.0)));
  for (const auto& q : r.segments) {
    EXPECT_EQ(q.degree(), 2);
    for (int j = 0; j <= per; ++j) {
      const double s = j / double(per);
      const auto& P = q.points();
      Point<double, D> x;
      for (int k = 0; k < D; ++k) x[k] = (1 - s) * (1 - s) * P[0][k] + 2 * s * (1 - s) * P[1][k] + s * s * P[2][k];
      quads.push_back(x);
    }
  }
  EXPECT_LE(to_polyline(curve, quads), tol + slack);
  EXPECT_LE(to_polyline(quads, curve), tol + slack);
  for (std::size_t i = 0; i + 1 < r.segments.size(); ++i) {
    const double u = r.breaks[i + 1];
    // The curve's one-sided tangents at the joint, by differences a little to each side.
    const double h = 1e-7 * (dom.hi - dom.lo);
    const auto before = c(u) - c(u - h), after = c(u + h) - c(u);
    if (dot(before, after) <= 0.999 * norm(before) * norm(after)) continue;  // a corner or a cusp of the curve
    const auto& A = r.segments[i].points();
    const auto& B = r.segments[i + 1].points();
    const auto ta = A[2] - A[1], tb = B[1] - B[0];
    const double angle = std::atan2(norm(ta - dot(ta, tb) / dot(tb, tb) * tb), dot(ta, tb) / norm(tb));
    EXPECT_LE(angle, 1e-9) << "joint " << i << " at t = " << u;
    EXPECT_EQ(A[2], B[0]);
  }
  return r.segments.size();
}

/// The part of c over [a, b] and its tangent quadratic (none where the tangent lines do not
/// meet ahead), as to_quadratic's attempts make them.
struct TangentPart {
  detail::quadratic::Part<B2> part;
  std::optional<detail::quadratic::Chain<double, 2>> q;
  TangentPart(const B2& c, double a, double b) {
    part.make(c, a, b);
    const auto d0 = detail::quadratic::end_direction(part.points, true), d1 = detail::quadratic::end_direction(part.points, false);
    q = detail::quadratic::tangent_chain(part.points.front(), d0, part.points.back(), d1, part.end_speed(true), part.end_speed(false));
  }
};

TEST(ToQuadratic, LowDegreesAreExactInOneSegment) {
  const B2 quad({P2(0, 0), P2(1, 2), P2(3, -1)});
  const auto r = to_quadratic(quad, 1e-9);
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_EQ(r.segments[0], quad);  // the quadratic itself
  const auto l = to_quadratic(B2({P2(1, 1), P2(3, 5)}), 1e-9);
  ASSERT_EQ(l.segments.size(), 1u);
  EXPECT_EQ(l.segments[0], B2({P2(1, 1), P2(2, 3), P2(3, 5)}));  // the line, its midpoint in the middle
}

TEST(ToQuadratic, ElevatedQuadraticIsOneSegment) {
  const B2 quad({P2(0, 0), P2(2, 3), P2(5, 1)});
  const auto r = to_quadratic(quad.elevate(1), 1e-9);
  ASSERT_EQ(r.segments.size(), 1u);
  for (int k = 0; k < 3; ++k) {
    // The tangent lines of the cubic meet at the quadratic's middle point (rounding of
    // the elevation and of the intersection: a few eps of the size 5).
    EXPECT_NEAR(r.segments[0].points()[k][0], quad.points()[k][0], 1e-14);
    EXPECT_NEAR(r.segments[0].points()[k][1], quad.points()[k][1], 1e-14);
  }
}

TEST(ToQuadratic, StraightCubicIsOneSegment) {
  // Straight cubics (control points on one line, unevenly spaced): a quadratic with its
  // middle point on the line is exact, so one segment at any tolerance. The first is a line
  // of DejaVuSans stored as a quadratic, elevated (W11's glyphs), whose tangent lines'
  // crossing is lost in rounding: it took 20 segments at 1e-3 of the em before session 18.
  const B2 quad({P2(855, 733), P2(865, 729), P2(870, 727)});
  const B2 glyph_line = quad.elevate(1);
  const B2 uneven({P2(0, 0), P2(1, 0.5), P2(7, 3.5), P2(10, 5)});
  for (const B2* c : {&glyph_line, &uneven}) {
    for (const double tol : {1e-9, 2.048, 204.8}) {
      const auto r = to_quadratic(*c, tol);
      ASSERT_EQ(r.segments.size(), 1u) << "tolerance " << tol;
      const auto& q = r.segments[0].points();
      EXPECT_EQ(q[0], c->points().front());
      EXPECT_EQ(q[2], c->points().back());
      const Vector<double, 2> chord = q[2] - q[0], m = q[1] - q[0];
      EXPECT_LE(std::abs(chord[0] * m[1] - chord[1] * m[0]), 1e-9 * dot(chord, chord));  // on the line
      EXPECT_GT(dot(m, chord), 0.0);  // between the ends
      EXPECT_LT(dot(m, chord), dot(chord, chord));
    }
  }
}

TEST(ToQuadratic, RandomCubicsWithinToleranceAndTangentContinuous) {
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> u(0, 100);
  std::size_t total = 0;
  for (int i = 0; i < 8; ++i) {  // 8: the brute-force distance check costs O(samples^2) per curve
    const B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    const double tol = i % 2 ? 0.1 : 1.0;
    const auto r = to_quadratic(c, tol);
    EXPECT_LE(r.max_error, tol);
    // Slack: polylines of 3200 and 400 points a segment: chords within (arc length /
    // count)^2 curvature / 8 of the curves, far below 1e-3 here.
    total += check_chain(c, r, tol, 1e-3, "random cubic");
  }
  EXPECT_GT(total, 8u);
}

TEST(ToQuadratic, ReparametrisedBoundHoldsOnRandomParts) {
  // Part::reparametrised_bound4_at (the Bernstein polygon of c(s) - q(sigma(s)), sigma a
  // quartic whose middle is fitted to the foot of c(1/2)) against the two-sided distance of
  // dense samples of the part and its tangent quadratic, measured here; parts of random
  // cubics that turn little (where the bound accepts parts).
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 100), w(0, 1);
  int finite = 0;
  for (int i = 0; i < 24; ++i) {
    const B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    const double a = 0.8 * w(rng), b = a + 0.05 + 0.15 * w(rng);
    const TangentPart tp(c, a, b);
    const auto& part = tp.part;
    const auto& q = tp.q;
    if (!q || q->size != 1) continue;
    double foot = 0;
    if (!std::isfinite(part.middle_foot(*q, foot))) continue;
    const double bound4 = part.reparametrised_bound4_at(*q, foot, 0.0, 3);
    if (!std::isfinite(bound4)) continue;
    ++finite;
    std::vector<P2> cs, qs;
    const int n = 1500;
    const auto& Q = q->front();
    for (int j = 0; j <= n; ++j) {
      const double s = j / double(n);
      cs.push_back(c(a + (b - a) * s));
      qs.push_back(P2((1 - s) * (1 - s) * Q[0][0] + 2 * s * (1 - s) * Q[1][0] + s * s * Q[2][0],
                      (1 - s) * (1 - s) * Q[0][1] + 2 * s * (1 - s) * Q[1][1] + s * s * Q[2][1]));
    }
    // Slack: chords of 1/1500 of parts a few tens long, sag far below 1e-6.
    const double dense = std::max(to_polyline(cs, qs), to_polyline(qs, cs));
    EXPECT_LE(dense, bound4 + 1e-6) << "cubic " << i;
  }
  EXPECT_GE(finite, 12);
}

TEST(ToQuadratic, PlaneCuspPretestNeverHidesACusp) {
  // plane_cubic_without_cusp (the cross product A x c'(t), linear in t) may only say "no
  // cusp" where there is none: on cubics built from a hodograph through 0 at a known t
  // (a cusp there), and on those with P1 moved off by 1e-13 to 1e-2, whenever it says so
  // the closed form (cubic_cusps, which refines the minima of |c'|) finds none and the speed
  // sampled densely here stays above 1e-9 of the largest |H_k|. On random cubics it decides
  // nearly all (the fast path is used).
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-1, 1), w(0.05, 0.95);
  const auto hodograph = [](const B2& c) {
    const auto& P = c.points();
    return std::array<P2, 3>{P2::from_vector(3.0 * (P[1] - P[0])), P2::from_vector(3.0 * (P[2] - P[1])), P2::from_vector(3.0 * (P[3] - P[2]))};
  };
  int decided = 0, cusped = 0, checked = 0;
  for (int i = 0; i < 3000; ++i) {
    B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    if (i % 3 != 0) {
      // A hodograph H(t) = (t - tc) v + (t - tc)^2 g: zero at tc, where it changes sign
      // along v (the direction turns back: a cusp).
      const double tc = w(rng);
      const Vector<double, 2> v(u(rng), u(rng)), g(u(rng), u(rng));
      const auto H = [&](double t) { return (t - tc) * v + (t - tc) * (t - tc) * g; };
      // Its Bernstein control points from the values at 0, 1/2, 1 (a quadratic).
      const Vector<double, 2> h0 = H(0), h2 = H(1), h1 = 2.0 * H(0.5) - 0.5 * (h0 + h2);
      const P2 p0(u(rng), u(rng));
      const P2 p1 = p0 + h0 / 3.0, p2 = p1 + h1 / 3.0, p3 = p2 + h2 / 3.0;
      const double off = i % 3 == 1 ? 0.0 : std::pow(10.0, -13.0 + 11.0 * w(rng));
      c = B2({p0, p1 + Vector<double, 2>(off, -off), p2, p3});
    }
    const auto Hc = hodograph(c);
    const bool none = detail::quadratic::plane_cubic_without_cusp(Hc);
    const auto closed = detail::quadratic::cubic_cusps(c, Hc);
    if (i % 3 == 0) decided += none;
    if (!closed.empty()) ++cusped;
    if (!none) continue;
    ++checked;
    EXPECT_TRUE(closed.empty()) << "cubic " << i;
    double big = 0, low = INFINITY;
    for (const auto& h : Hc) big = std::max(big, norm(h.to_vector()));
    for (int j = 0; j <= 20000; ++j) {
      const double t = j / 20000.0, s = 1 - t;
      low = std::min(low, norm(s * s * Hc[0].to_vector() + 2 * s * t * Hc[1].to_vector() + t * t * Hc[2].to_vector()));
    }
    EXPECT_GT(low, 1e-9 * big) << "cubic " << i;
  }
  EXPECT_GE(decided, 990);  // of 1000 random cubics
  EXPECT_GE(cusped, 900);   // the built cusps are found (the test reaches them)
  EXPECT_GE(checked, 1200);  // the random cubics and the moved cusps it decides (1,283)
}

TEST(ToQuadratic, InflectionsWhereTheCurvatureChangesSign) {
  // cubic_inflections against a sign scan of c' x c'' written here from the hodograph (the
  // cross product at 100,001 parameters; each change of sign bracketed to 1e-5): the same
  // count, each within the bracket.
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(0, 100);
  int with = 0;
  for (int i = 0; i < 300; ++i) {
    const B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    const auto& P = c.points();
    const auto cross_at = [&](double t) {
      const double s = 1 - t;
      const auto d1 = 3.0 * (s * s * (P[1] - P[0]) + 2 * s * t * (P[2] - P[1]) + t * t * (P[3] - P[2]));
      const auto d2 = 6.0 * (s * ((P[2] - P[1]) - (P[1] - P[0])) + t * ((P[3] - P[2]) - (P[2] - P[1])));
      return d1[0] * d2[1] - d1[1] * d2[0];
    };
    std::vector<double> scan;
    const int n = 100000;
    double prev = cross_at(0);
    for (int j = 1; j <= n; ++j) {
      const double cur = cross_at(j / double(n));
      if ((prev < 0) != (cur < 0) && prev != 0) scan.push_back((j - 0.5) / n);
      prev = cur;
    }
    std::array<double, 2> got{};
    const int k = detail::quadratic::cubic_inflections(c, 0.0, 1.0, got);
    ASSERT_EQ(static_cast<std::size_t>(k), scan.size()) << "cubic " << i;
    for (int j = 0; j < k; ++j) EXPECT_NEAR(got[static_cast<std::size_t>(j)], scan[static_cast<std::size_t>(j)], 1e-5) << "cubic " << i;
    with += k > 0;
  }
  EXPECT_GE(with, 50);
}

TEST(ToQuadratic, MiddleFootIsTheNearestPoint) {
  // Part::middle_foot (the search's measure): the distance from c(1/2) to the tangent
  // quadratic, against the nearest of 200,001 points of the quadratic computed here. It is a
  // distance to a point of q (the foot returned), so never below the nearest; it is the
  // nearest (within 1%: Newton stops after a step of 1e-2) on at least 98% of random parts
  // (from the affine guess Newton can end at a farther foot, mostly on quadratics far
  // longer than their part).
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> u(0, 100), w(0, 1);
  int finite = 0, nearest = 0;
  for (int i = 0; i < 300; ++i) {
    const B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    const double a = 0.7 * w(rng), b = a + 0.02 + 0.28 * w(rng);
    const TangentPart tp(c, a, b);
    const auto& part = tp.part;
    const auto& q = tp.q;
    if (!q) continue;
    double x = -1;
    const double mid = part.middle_foot(*q, x);
    ASSERT_TRUE(std::isfinite(mid));
    ++finite;
    const auto& Q = q->front();
    const P2 m = c(a + 0.5 * (b - a));
    const auto at = [&](double s) {
      return P2((1 - s) * (1 - s) * Q[0][0] + 2 * s * (1 - s) * Q[1][0] + s * s * Q[2][0],
                (1 - s) * (1 - s) * Q[0][1] + 2 * s * (1 - s) * Q[1][1] + s * s * Q[2][1]);
    };
    double best = INFINITY;
    for (int j = 0; j <= 200000; ++j) best = std::min(best, norm(at(j / 200000.0) - m));
    const double size = norm(Q[2] - Q[1]) + norm(Q[1] - Q[0]);
    // The grid's nearest point exceeds the true distance by at most its spacing (5e-6 of
    // the parameter, within 1e-5 of the size).
    EXPECT_GE(mid, best - 1e-5 * size) << "part " << i;
    EXPECT_NEAR(norm(at(x) - m), mid, 1e-12 * size) << "part " << i;
    nearest += mid <= 1.01 * best + 1e-12 * size;
    // With the recheck at 0: the nearest, unless the foot kept lies outside the part's
    // control box (then farther than the distance found from every point of the part).
    double y = -1, first = -1;
    const double mid0 = part.middle_foot(*q, y, 0.0, &first);
    double out2 = 0;
    for (int k = 0; k < 2; ++k) {
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& P : part.points) lo = std::min(lo, P[k]), hi = std::max(hi, P[k]);
      const double o = std::max({0.0, lo - at(y)[k], at(y)[k] - hi});
      out2 += o * o;
    }
    EXPECT_TRUE(mid0 <= 1.01 * best + 1e-12 * size || out2 > 0) << "part " << i << ": " << mid0 / best << " times the nearest";
    EXPECT_LE(mid0, mid) << "part " << i;
  }
  EXPECT_GE(finite, 200);
  EXPECT_GE(nearest, 0.98 * finite);
}

TEST(ToQuadratic, PartBoundsHoldAndAgree) {
  // On random parts of random cubics, against measurements written here (the parametric
  // difference c(s) - q(s) at 20,001 parameters; the two-sided distance of dense samples):
  // elevated_bound, halved or not, is at least the parametric distance, and halving (4
  // levels, the limit 1% above it) brings it there on most parts; reparametrised_bound4_at
  // bounds the two-sided distance at any middle parameter, not only the foot's;
  // distance_from is at least the distance to the part's dense polyline and within 1e-9
  // of it for points near the part; the plane branch of tangent_chain agrees with the
  // general one (the same curve in 3-D, z = 0) to 1e-12 of the chord.
  std::mt19937_64 rng(53);
  std::uniform_real_distribution<double> u(0, 100), w(0, 1);
  using P3 = Point<double, 3>;
  int rb_checked = 0, halved_close = 0, parts = 0;
  for (int i = 0; i < 120; ++i) {
    const B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    const double a = 0.8 * w(rng), b = a + 0.02 + 0.18 * w(rng);
    const TangentPart tp(c, a, b);
    const auto& part = tp.part;
    const auto& q = tp.q;
    const auto d0 = detail::quadratic::end_direction(part.points, true), d1 = detail::quadratic::end_direction(part.points, false);
    // The same part in 3-D: the general branch of tangent_chain.
    std::vector<P3> P3s;
    for (const auto& p : part.points) P3s.push_back(P3(p[0], p[1], 0));
    const auto e0 = detail::quadratic::end_direction(P3s, true), e1 = detail::quadratic::end_direction(P3s, false);
    const auto q3 = detail::quadratic::tangent_chain(P3s.front(), e0, P3s.back(), e1, 1.0, 1.0);
    ASSERT_EQ(q.has_value(), q3.has_value()) << "part " << i;
    if (!q) continue;
    ++parts;
    const double chord = norm(part.points.back() - part.points.front());
    ASSERT_EQ(q3->size, 1) << "part " << i;
    // The crossing's rounding grows as 1 / sin of the angle between the directions.
    const double sine = std::abs(d0[0] * d1[1] - d0[1] * d1[0]);
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(q->front()[1][k], q3->front()[1][k], 1e-13 * (chord + norm(q->front()[1] - q->front()[0])) / sine) << "part " << i;
    const auto& Q = q->front();
    const auto qat = [&](double s) {
      return P2((1 - s) * (1 - s) * Q[0][0] + 2 * s * (1 - s) * Q[1][0] + s * s * Q[2][0],
                (1 - s) * (1 - s) * Q[0][1] + 2 * s * (1 - s) * Q[1][1] + s * s * Q[2][1]);
    };
    double parametric = 0;
    std::vector<P2> cs, qs;
    for (int j = 0; j <= 20000; ++j) {
      const double s = j / 20000.0;
      parametric = std::max(parametric, norm(part(s) - qat(s)));
      if (j % 10 == 0) cs.push_back(part(s)), qs.push_back(qat(s));
    }
    const double plain = part.elevated_bound(*q), halved = part.elevated_bound(*q, 1.01 * parametric, 4);
    EXPECT_GE(plain, parametric * (1 - 1e-12)) << "part " << i;
    EXPECT_GE(halved, parametric * (1 - 1e-12)) << "part " << i;
    EXPECT_LE(halved, plain * (1 + 1e-12)) << "part " << i;
    halved_close += halved <= 1.01 * parametric;
    // Slack: polylines of 2,001 points on parts a few tens long: chords of about 0.02,
    // their sag (length^2 curvature / 8) below 1e-3 for radii above 0.05.
    const double dense = std::max(to_polyline(cs, qs), to_polyline(qs, cs));
    for (const double x : {0.2, 0.5, 0.8}) {
      const double rb = part.reparametrised_bound4_at(*q, x, 0.0, 3);
      if (!std::isfinite(rb)) continue;
      ++rb_checked;
      EXPECT_GE(rb, dense - 1e-3) << "part " << i << " x " << x;
    }
    // distance_from: a point near the part (its middle, moved off by 1e-3 of the chord)
    // and one of q's.
    const P2 m = part(0.5);
    const Vector<double, 2> off(-1e-3 * chord, 1e-3 * chord);
    const double near = part.distance_from(m + off, 0.5);
    EXPECT_GE(near, to_polyline(std::vector<P2>{m + off}, cs) - 1e-3) << "part " << i;
    EXPECT_LE(near, norm(off) * (1 + 1e-9)) << "part " << i;
    const double far = part.distance_from(qat(0.5), 0.5);
    EXPECT_GE(far, to_polyline(std::vector<P2>{qat(0.5)}, cs) - 1e-3) << "part " << i;
  }
  EXPECT_GE(parts, 80);
  EXPECT_GE(rb_checked, 60);
  EXPECT_GE(halved_close, parts * 9 / 10);
}

TEST(ToQuadratic, FlatHairpinKeepsTwoSegments) {
  // A cubic that runs left and back right within 1e-6 of a line (a hairpin, not a cusp):
  // it does not fit one segment (its tangent quadratic is a spike), and two suffice. From
  // the affine guess Newton found the spike's foot of the middle point (7 times the
  // Hausdorff distance of the part [0, 0.6]), which rejected the parts across the turn:
  // three segments, before the recheck from q's ends and middle.
  const B2 c({P2(0.834323442, 7.75695857e-07), P2(0.673325704, 8.68642536e-07), P2(0.233072742, 6.04811804e-07),
              P2(0.927076599, 2.8530731e-08)});
  const double tol = 0.0135196;
  const auto r = to_quadratic(c, tol);
  EXPECT_EQ(r.segments.size(), 2u);
  check_chain(c, r, tol, 1e-6, "flat hairpin");
}

TEST(ToQuadratic, PathKeepsCornersAndSmoothJoints) {
  // A smooth joint (collinear handles) and a corner.
  Pieces<double, 2> p({B2({P2(0, 0), P2(1, 2), P2(2, 2), P2(3, 0)}), B2({P2(3, 0), P2(4, -2), P2(5, -2), P2(6, 0)}),
                       B2({P2(6, 0), P2(6, 3), P2(8, 3), P2(9, 1)})});
  const auto r = to_quadratic(p, 1e-3);
  check_chain(p, r, 1e-3, 1e-4, "path");
  // The joint at t = 1 is smooth, the one at t = 2 a corner: both are breaks.
  EXPECT_NE(std::find(r.breaks.begin(), r.breaks.end(), 1.0), r.breaks.end());
  EXPECT_NE(std::find(r.breaks.begin(), r.breaks.end(), 2.0), r.breaks.end());
}

TEST(ToQuadratic, CuspZeroHandlesSpaceCurvesAndConics) {
  // A cusp at t = 1/2 (P3 + P2 - P1 - P0 = 0), handles of zero length, a twisted cubic
  // (tangent lines skew: pairs of quadratics), a rational quarter circle.
  const B2 cusp({P2(0, 0), P2(1, 1), P2(0, 1), P2(1, 0)});
  const auto rc = to_quadratic(cusp, 1e-3);
  for (const auto& q : rc.segments)
    for (const auto& x : q.points()) EXPECT_TRUE(std::isfinite(x[0]) && std::isfinite(x[1]));
  check_chain(cusp, rc, 1e-3, 1e-4, "cusp");
  // The cusp (c'(1/2) = 3/4 (P3 + P2 - P1 - P0) = 0) is a break, found in closed form.
  EXPECT_TRUE(std::any_of(rc.breaks.begin(), rc.breaks.end(), [](double t) { return std::abs(t - 0.5) <= 1e-12; }));
  const B2 zero({P2(0, 0), P2(0, 0), P2(1, 1), P2(1, 1)});
  check_chain(zero, to_quadratic(zero, 1e-4), 1e-4, 1e-5, "zero-length handles");
  using P3 = Point<double, 3>;
  const Bezier<double, 3> twisted({P3(0, 0, 0), P3(1, 0, 0), P3(1, 1, 0), P3(1, 1, 1)});
  const auto rt = to_quadratic(twisted, 1e-4);
  check_chain(twisted, rt, 1e-4, 1e-5, "twisted cubic");
  const R2 quarter({P2(1, 0), P2(1, 1), P2(0, 1)}, {1.0, std::sqrt(0.5), 1.0});
  const auto rq = to_quadratic(quarter, 1e-6);
  check_chain(quarter, rq, 1e-6, 1e-7, "quarter circle");
  // The circle's radial error at the segments' midpoints, a closed form: |Q(1/2)| - 1.
  for (const auto& q : rq.segments) {
    const auto& P = q.points();
    EXPECT_LE(std::abs(norm((0.25 * (P[0].to_vector() + P[2].to_vector())) + 0.5 * P[1].to_vector()) - 1), 1e-6);
  }
}

TEST(ToQuadratic, BezierOverloadMatchesPieces) {
  // A Bézier (or rational Bézier) is approximated as its one piece without building
  // pieces(c): the same chain either way.
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0, 100);
  for (int i = 0; i < 20; ++i) {
    const B2 c({P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng)), P2(u(rng), u(rng))});
    const auto a = to_quadratic(c, 0.1), b = to_quadratic(pieces(c), 0.1);
    EXPECT_EQ(a.segments, b.segments);
    EXPECT_EQ(a.breaks, b.breaks);
    EXPECT_EQ(a.max_error, b.max_error);
  }
  const R2 quarter({P2(1, 0), P2(1, 1), P2(0, 1)}, {1.0, std::sqrt(0.5), 1.0});
  EXPECT_EQ(to_quadratic(quarter, 1e-4).breaks, to_quadratic(pieces(quarter), 1e-4).breaks);
}

TEST(ToQuadratic, BadTolerance) {
  const B2 c({P2(0, 0), P2(1, 2), P2(3, 2), P2(4, 0)});
  for (const double tol : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    try {
      (void)to_quadratic(c, tol);
      ADD_FAILURE() << "accepted tolerance " << tol;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.where(), "tolerance");
    }
  }
  try {
    (void)to_quadratic(c, 1e-12, 10);
    ADD_FAILURE() << "more than 10 segments accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.where(), "tolerance");
  }
}

}  // namespace
