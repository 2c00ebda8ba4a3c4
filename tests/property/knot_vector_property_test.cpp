// Properties of KnotVector's span search (basis/knot_vector.hpp): the hinted search gives
// the binary search's answer for every hint, on random knot vectors (degrees 1..5,
// clamped or not, knots on a grid of 1/16 so repeated knots are frequent) and random
// sorted batches walked with the previous answer as the hint, as batch evaluation does.
#include <algorithm>
#include <vector>

#include "generators.hpp"

namespace {

using namespace casteljau;

// Parameters on a grid of 1/64 over [-1/4, 5/4]: knots, points between them and points
// outside the domain all occur.
double random_parameter() { return *rc::gen::inRange(-16, 81) / 64.0; }

RC_GTEST_PROP(KnotVectorProperty, HintsNeverChangeTheSpan, ()) {
  const KnotVector<double> U = prop::knot_vector(24);
  const int count = *rc::gen::inRange(1, 200);
  std::vector<double> us;
  for (int i = 0; i < count; ++i) us.push_back(random_parameter());
  std::sort(us.begin(), us.end());
  std::size_t previous = *rc::gen::inRange<std::size_t>(0, U.size() + 2);
  for (const double u : us) {
    const std::size_t s = U.find_span(u);
    RC_ASSERT(s == find_span(U.span(), U.degree(), u));
    // The sorted walk: the previous answer as the hint.
    RC_ASSERT(U.find_span(u, previous) == s);
    // Any hint at all.
    RC_ASSERT(U.find_span(u, *rc::gen::inRange<std::size_t>(0, U.size() + 2)) == s);
    // The span holds u (right limits inside, the end spans outside the domain).
    const Interval<double> d = U.domain();
    if (u > d.lo && u < d.hi) RC_ASSERT(U[s] <= u && u < U[s + 1]);
    previous = s;
  }
}

}  // namespace
