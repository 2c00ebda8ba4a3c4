// Properties of the Bernstein basis and the basis-level algorithms: partition of unity,
// non-negativity, symmetry, derivatives, products, roots and the power form round trip.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "generators.hpp"

namespace {

using namespace casteljau;
using casteljau::prop::eps;

// sum_i B(i,n)(t) = 1 and B(i,n)(t) >= 0 on [0, 1] [Farin02, 5.1]. Each value carries a
// relative error of about (n + 2) eps (products of n factors and a binomial) and the
// values sum to 1, so the sum is 1 within 2 (n + 2) eps.
RC_GTEST_PROP(BernsteinProperty, PartitionOfUnityAndNonNegative, ()) {
  const int n = *rc::gen::inRange(0, 31);
  const double t = *prop::parameter();
  const auto b = bernstein_all(n, t);
  double sum = 0;
  for (double v : b) {
    RC_ASSERT(v >= 0.0);
    sum += v;
  }
  RC_ASSERT(std::abs(sum - 1) <= 2 * (n + 2) * eps);
}

// B(i,n)(1-t) = B(n-i,n)(t): the same three factors multiplied in another order (1 - t is
// exact on the 2^-20 grid), so they agree to a relative 2 (n + 2) eps. bernstein_all
// agrees with the single-value bernstein to the same relative accuracy.
RC_GTEST_PROP(BernsteinProperty, SymmetryAndAllMatchesSingle, ()) {
  const int n = *rc::gen::inRange(0, 31);
  const double t = *prop::parameter();
  const auto all = bernstein_all(n, t);
  for (int i = 0; i <= n; ++i) {
    const double a = bernstein(i, n, 1 - t), b = bernstein(n - i, n, t);
    RC_ASSERT(std::abs(a - b) <= 2 * (n + 2) * eps * std::abs(b));
    const double single = bernstein(i, n, t);
    RC_ASSERT(std::abs(all[static_cast<std::size_t>(i)] - single) <= 4 * (n + 2) * eps * single);
  }
}

// The derivative against a central difference of the values with h = 1e-4: truncation
// h^2 |B'''| / 6 with |B'''| <= 8 n^3 (three forward differences of values in [0, 1],
// times n(n-1)(n-2)), rounding 2 eps / (2h) per difference.
RC_GTEST_PROP(BernsteinProperty, DerivativeMatchesFiniteDifference, ()) {
  const int n = *rc::gen::inRange(1, 31);
  const int i = *rc::gen::inRange(0, n + 1);
  const double t = 0.01 + 0.98 * *prop::parameter();
  const double h = 1e-4;
  const double fd = (bernstein(i, n, t + h) - bernstein(i, n, t - h)) / (2 * h);
  const double tol = h * h * 8.0 * n * n * n / 6 + 4 * eps / h;
  RC_ASSERT(std::abs(bernstein_derivative(i, n, 1, t) - fd) <= tol);
  std::vector<double> all(static_cast<std::size_t>(n) + 1);
  bernstein_all_derivatives(n, 1, t, std::span<double>(all));
  RC_ASSERT(std::abs(all[static_cast<std::size_t>(i)] - fd) <= tol);
}

// The Bernstein product evaluates to the product of the values: all three evaluations are
// convex combinations of coefficients in [-1, 1], so errors are a few (m + n) eps.
RC_GTEST_PROP(BernsteinProperty, ProductEvaluatesToProductOfValues, ()) {
  const int m = *rc::gen::inRange(0, 16), n = *rc::gen::inRange(0, 16);
  const auto f = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(m) + 1, prop::coordinate());
  const auto g = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(n) + 1, prop::coordinate());
  const auto h = bernstein_product<double>(f, g);
  RC_ASSERT(h.size() == static_cast<std::size_t>(m + n) + 1);
  const double t = *prop::parameter();
  const double fv = de_casteljau<double, double>(f, t), gv = de_casteljau<double, double>(g, t);
  RC_ASSERT(std::abs(de_casteljau<double, double>(h, t) - fv * gv) <= 8 * (m + n + 2) * eps);
}

// Polynomials built from 1 to 5 known roots in (0, 1), at least 0.05 apart: every root is
// found once, to 1e-10 (the Bernstein coefficients carry rounding of a few eps, and these
// root separations keep the condition number below ~1e5).
RC_GTEST_PROP(BernsteinProperty, RootsOfKnownRootsAreFound, ()) {
  std::vector<int> slots = *rc::gen::unique<std::vector<int>>(rc::gen::inRange(1, 20));
  if (slots.size() > 5) slots.resize(5);
  if (slots.empty()) slots.push_back(*rc::gen::inRange(1, 20));
  std::sort(slots.begin(), slots.end());
  std::vector<double> roots;
  for (int s : slots) roots.push_back(s * 0.05);
  // Bernstein coefficients of prod (t - r): multiply linear factors (-r, 1 - r) in
  // Bernstein form by hand: degree elevation of the product one factor at a time, in long
  // double, independent of bernstein_product.
  std::vector<long double> c{1.0L};
  for (double r : roots) {
    const int d = static_cast<int>(c.size()) - 1;  // current degree
    std::vector<long double> next(c.size() + 1, 0.0L);
    for (int i = 0; i <= d + 1; ++i) {
      // (t - r) p(t) with p in degree d: coefficient i of degree d + 1 is
      // (i/(d+1)) (1 - r) c_{i-1} + ((d+1-i)/(d+1)) (-r) c_i.
      long double v = 0;
      if (i >= 1) v += static_cast<long double>(i) / (d + 1) * (1 - r) * c[static_cast<std::size_t>(i - 1)];
      if (i <= d) v += static_cast<long double>(d + 1 - i) / (d + 1) * (-r) * c[static_cast<std::size_t>(i)];
      next[static_cast<std::size_t>(i)] = v;
    }
    c = next;
  }
  std::vector<double> cd(c.begin(), c.end());
  const auto found = bernstein_roots<double>(cd);
  RC_ASSERT(found.size() == roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) RC_ASSERT(std::abs(found[i] - roots[i]) <= 1e-10);
}

// Random Bernstein coefficients: every reported root is in [0, 1], ascending, and the
// polynomial is small there (|p(r)| <= |p'| * (root error) + rounding; 1e-9 covers simple
// roots; multiple roots are flat so p is tiny too).
RC_GTEST_PROP(BernsteinProperty, ReportedRootsAreRoots, ()) {
  const int n = *rc::gen::inRange(1, 21);
  const auto c = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(n) + 1, prop::coordinate());
  const auto r = bernstein_roots<double>(c);
  for (std::size_t i = 0; i < r.size(); ++i) {
    RC_ASSERT(r[i] >= 0.0);
    RC_ASSERT(r[i] <= 1.0);
    if (i > 0) RC_ASSERT(r[i] > r[i - 1]);
    RC_ASSERT(std::abs(de_casteljau<double, double>(c, r[i])) <= 1e-9);
  }
  // Conversely, a sign change between samples means a root was reported in between.
  for (int j = 0; j < 200; ++j) {
    const double a = j / 200.0, b = (j + 1) / 200.0;
    const double fa = de_casteljau<double, double>(c, a), fb = de_casteljau<double, double>(c, b);
    if (fa * fb < 0 && std::abs(fa) > 1e-12 && std::abs(fb) > 1e-12) {
      bool any = false;
      for (double x : r) any = any || (x >= a - 1e-9 && x <= b + 1e-9);
      RC_ASSERT(any);
    }
  }
}

// from_power(to_power(c)) = c at low degree: M then M^-1 amplify rounding by at most
// ~3^n (the row sums of |M|), so 8 * 3^n eps of the coordinates (<= 1).
RC_GTEST_PROP(BernsteinProperty, PowerFormRoundTrip, ()) {
  const int n = *rc::gen::inRange(0, 7);
  const Bezier<double, 2> c(prop::control_points<2>(n));
  const auto a = c.to_power();
  const auto back = Bezier<double, 2>::from_power(a);
  RC_ASSERT(back.degree() == n);
  for (int i = 0; i <= n; ++i) {
    for (int d = 0; d < 2; ++d) {
      RC_ASSERT(std::abs(back.points()[static_cast<std::size_t>(i)][d] - c.points()[static_cast<std::size_t>(i)][d]) <=
                8 * std::pow(3.0, n) * eps);
    }
  }
}

}  // namespace
