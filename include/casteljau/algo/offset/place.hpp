// The placement of the offset's cubics along a Source (phase of algo/offset.hpp): each
// end's candidates (fit.hpp) screened by their normal scans and the best certified by its
// measure (best_screened, certify, best_fit), and approximate(): greedy (the farthest end
// within the tolerance, from a model of the error's growth inside a bracket) or uniform
// (the reference: n equal parts). The cubics go into the raw offset (Raw). Depends on
// common.hpp, measure.hpp, normal_scan.hpp, fit.hpp and options.hpp (OffsetFit).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/algo/offset/common.hpp"
#include "casteljau/algo/offset/fit.hpp"
#include "casteljau/algo/offset/measure.hpp"
#include "casteljau/algo/offset/normal_scan.hpp"
#include "casteljau/algo/offset/options.hpp"
#include "casteljau/core/error.hpp"

namespace casteljau::detail::offset {

/// A candidate cubic over [a, b] with its scan.
template <class T>
struct Screened {
  CubicForm<T> cubic;
  NormalScan<T> scan;
  T error;  ///< the scan's estimate (the choice of the end), or the measure where the scan failed
  bool measured = false;  ///< error is the measure itself (projections: a failed scan, or a part across a cusp)
};

/// A candidate over [a, b] and its scan's estimate (a failed scan measured by
/// projections): the first whose estimate is within stop_above, else the one with the
/// smaller estimate. `hermite_first`: the Hermite cubic is screened first, and the fit is
/// made only where it fails (for the last part of a stretch, which is often a whole glyph
/// piece that the Hermite cubic already follows: a third of the glyphs' time went to fits
/// whose cubic was not needed); otherwise the fit first (the longer reach in the middle of
/// the search, where the Hermite cubic is rarely within the tolerance).
template <class T>
Screened<T>& best_screened(const Source<T>& s, T a, T b, T stop_above, bool hermite_first, std::array<Screened<T>, 2>& work) {
  const Ends<T> E(s, a, b);
  Screened<T>* best = nullptr;  // the scans (a few kB each) stay where they were made
  const bool across = s.spans_cusp(a, b);
  if (across) hermite_first = true;  // the Hermite cubic follows the offset's parametrisation, across cusps too
  const auto screen = [&](const CubicForm<T>& c) {
    Screened<T>& g = best == &work[0] ? work[1] : work[0];
    const T limit = best ? std::min(stop_above, best->error) : stop_above;
    g.cubic = c;
    if (across) {
      // No normal scan (its feet do not run in order about a cusp): the parametric bound
      // (cheap, and met by most Hermite cubics that are within the tolerance), else the
      // projections from partners.
      g.scan.ok = false, g.measured = true;
      g.error = parametric(c, s, a, b, limit);
      if (g.error > limit) g.error = partner_distance(c, s, a, b, limit);
    } else {
      normal_scan(c, s, a, b, limit, g.scan);
      g.measured = !g.scan.ok;
      g.error = g.scan.ok ? g.scan.estimate : hausdorff(c, s, a, b, limit);
    }
    if (!best || g.error < best->error) best = &g;
    return best->error <= stop_above;
  };
  if (hermite_first) {
    if (screen(E.hermite())) return *best;
    // Across a cusp, no fit where the Hermite cubic is more than 8 tolerances off (its
    // first sample over the limit): on W11's glyphs at d = 204.8 such fits saved 2 cubics
    // of 83,463, for 0.7% of the instructions (2.4% on the random cubics, which they never
    // saved one).
    if (across && best->error > 8 * stop_above) return *best;
    if (const auto f = fitted(s, a, b, E, stop_above)) screen(*f);
  } else {
    if (const auto f = fitted(s, a, b, E, stop_above)) {
      if (screen(*f)) return *best;
    }
    screen(E.hermite());
  }
  return *best;
}

/// The measured error of a screened candidate within stop_above: its scan's peaks (or the
/// projections where the scan failed or a peak's foot is not found).
template <class T>
T certify(Screened<T>& g, const Source<T>& s, T a, T b, T stop_above) {
  if (g.measured) return g.error;  // within stop_above: the projections ran to the end
  if (g.scan.ok) {
    const T e = normal_peaks(g.cubic, s, g.scan, stop_above);
    if (g.scan.ok) return e;
  }
  return hausdorff(g.cubic, s, a, b, stop_above);
}

/// The best candidate over [a, b] and its measured error (stop_above as measured's).
template <class T>
std::pair<Quad<T>, T> best_fit(const Source<T>& s, T a, T b, T stop_above, bool hermite_only) {
  const Ends<T> E(s, a, b);
  std::optional<CubicForm<T>> best;
  T err = std::numeric_limits<T>::infinity();
  if (!hermite_only) {
    if (const auto f = fitted(s, a, b, E, stop_above)) err = measured(*f, s, a, b, stop_above), best = *f;
  }
  const CubicForm<T> h = E.hermite();
  const T e = measured(h, s, a, b, std::min(stop_above, err));
  if (!(e >= err)) err = e, best = h;
  if (!best) best = h, err = std::numeric_limits<T>::infinity();
  return {best->P, err};
}

/// Approximates the whole source by cubics within the tolerance into raw.
template <class T>
void approximate(const Source<T>& s, OffsetFit fit, Raw<T>& raw) {
  const T tol = raw.tolerance;
  const T min_step = (s.hi - s.lo) * T(1e-9);
  if (fit == OffsetFit::uniform) {
    for (std::size_t n = 1;; ++n) {
      if (n > raw.max_segments) {
        throw InvalidArgument("tolerance", "the reference subdivision needs more than " + std::to_string(raw.max_segments) + " cubics");
      }
      std::vector<Quad<T>> parts;
      T worst = 0;
      bool ok = true;
      for (std::size_t i = 0; i < n && ok; ++i) {
        const T a = s.lo + (s.hi - s.lo) * T(i) / T(n), b = i + 1 == n ? s.hi : s.lo + (s.hi - s.lo) * T(i + 1) / T(n);
        auto [B, e] = best_fit(s, a, b, tol, true);
        ok = e <= tol;
        worst = std::max(worst, e);
        parts.push_back(std::move(B));
      }
      if (ok) {
        raw.max_error = std::max(raw.max_error, worst);
        for (const auto& B : parts) raw.push(B, s.reversed);
        return;
      }
    }
  }
  // Greedy: the farthest end b whose best candidate is measured within the tolerance,
  // found from a model of the error (growing as about the fifth power of the step on
  // smooth parts: each next end proposed from the last error, the first from the last
  // step) inside a bracket [lo, hi] (within, over; bisection where the model fails), until
  // an end is measured at 70% of the tolerance or more, or the bracket is within 1/16 of
  // the step (90% and 1/64 made 0.7% fewer cubics on W11's random cubics for 1.25 times
  // the instructions: the band [0.9, 1] of the error is 2% of the step). Each end's candidates are compared by their normal scans' estimates (the
  // largest sample and a parabola at its top); the best, when estimated within the
  // tolerance, is measured (its scan's peaks: see NormalScan), so the cubic kept needs no
  // further check.
  T a = s.lo;
  T last_step = s.hi - s.lo;
  const T full_tol = tol;
  while (a < s.hi) {
    const T shift = raw.start_shift;
    const T tol = full_tol - shift;  // the first cubic after a stretch left out: less
    T lo = a, hi = s.hi;
    bool hi_tested = false;
    std::optional<std::pair<CubicForm<T>, T>> B;  // the longest cubic within the tolerance, its error
    std::array<Screened<T>, 2> work;
    T x = std::min(s.hi, a + last_step);
    for (int it = 0; it < 200; ++it) {
      if (x - a < min_step) {
        throw InvalidArgument("tolerance", "cannot be met by cubics near the offset's parameter " + std::to_string(a) +
                                               " of a piece (below the rounding of the computation): use a larger tolerance");
      }
      Screened<T>& g = best_screened(s, a, x, tol, x == s.hi, work);
      T e = g.error;
      if (e <= tol) e = certify(g, s, a, x, tol);
      if (e <= tol) {
        lo = x, B = std::pair{g.cubic, e};
        if (x == s.hi || e >= T(0.7) * tol) break;
      } else {
        hi = x, hi_tested = true;
      }
      if (B && hi_tested && hi - lo <= (lo - a) / 16) break;
      T next = std::numeric_limits<T>::quiet_NaN();
      if (std::isfinite(e) && e > 0) next = a + (x - a) * std::pow(T(0.95) * tol / e, T(0.2));
      if (!(next > lo)) next = lo + (hi - lo) / 2;
      if (next >= hi) next = hi_tested ? lo + (hi - lo) / 2 : s.hi;
      if (!B && next > a + (x - a) / 2 && !(e <= tol)) next = std::min(next, a + (x - a) / 2 + (x - a) / 4);  // failing: shrink surely
      if (next == x) break;
      x = next;
    }
    if (!B) {
      throw InvalidArgument("tolerance", "cannot be met by cubics near the offset's parameter " + std::to_string(a) +
                                             " of a piece (below the rounding of the computation): use a larger tolerance");
    }
    raw.max_error = std::max(raw.max_error, B->second + shift);
    raw.push(B->first.P, s.reversed);
    raw.start_shift = 0;
    last_step = lo - a;
    a = lo;
  }
}

}  // namespace casteljau::detail::offset
