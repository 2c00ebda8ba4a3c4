// The offset's trim (phase of algo/offset.hpp): the raw offset cut at its self-crossings
// (raw_crossings: the pairs whose control boxes meet, by intersect()), at the round caps
// of an open curve's ends (cap_crossings), at its cusps and join ends; each part judged by
// the distance of samples to the curve (near.hpp) and kept where it is at least |d| - tol
// away (trimmed_intervals); the kept intervals made into parts of cubics, a gap between
// parts that do not meet (trimmed_cubics). Depends on common.hpp, near.hpp and
// algo/intersect.hpp (intersect(), isect::boxes_meet).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "casteljau/algo/intersect.hpp"
#include "casteljau/algo/intersect/prepare.hpp"
#include "casteljau/algo/offset/common.hpp"
#include "casteljau/algo/offset/near.hpp"
#include "casteljau/core/error.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/curves/piecewise.hpp"

namespace casteljau::detail::offset {

/// Where the raw cubic Q crosses the circle of radius r about e (an end of an open curve:
/// its round cap, which the raw offset does not hold): sign changes of |Q(u) - e| - r on 32
/// equal parts (values within eps of zero skipped: the offset starts on the circle), each
/// narrowed by bisection. Appends the raw parameters i + u.
template <class T>
void cap_crossings(const Quad<T>& Q, std::size_t i, const Point<T, 2>& e, T r, T eps, std::vector<T>& out) {
  const Box<T, 2> box = box_of<T, 2>(Q);
  const Point<T, 2> lo = box.lo, hi = box.hi;
  const T dx = std::max({lo[0] - e[0], T(0), e[0] - hi[0]}), dy = std::max({lo[1] - e[1], T(0), e[1] - hi[1]});
  if (std::sqrt(dx * dx + dy * dy) > r + eps) return;  // the box outside the circle
  const T fx = std::max(std::abs(lo[0] - e[0]), std::abs(hi[0] - e[0])), fy = std::max(std::abs(lo[1] - e[1]), std::abs(hi[1] - e[1]));
  if (std::sqrt(fx * fx + fy * fy) < r - eps) return;  // inside it
  const CubicForm<T> F(Q[0], Q[1], Q[2], Q[3]);
  const auto f = [&](T u) { return length(F.at(u) - e) - r; };
  T last_u = 0;
  int last_sign = 0;
  for (int j = 0; j <= 32; ++j) {
    const T u = T(j) / 32, v = f(u);
    const int sign = v > eps ? 1 : (v < -eps ? -1 : 0);
    if (sign == 0) continue;
    if (last_sign != 0 && sign != last_sign) {
      T a = last_u, b = u;
      for (int k = 0; k < 60 && b - a > T(1e-15); ++k) {
        const T m = (a + b) / 2;
        ((f(m) > 0) == (last_sign > 0) ? a : b) = m;
      }
      out.push_back(static_cast<T>(i) + (a + b) / 2);
    }
    last_u = u, last_sign = sign;
  }
}

/// The crossings of the raw offset's cubics with each other (consecutive ones too: a join
/// arc meets the stretch before it away from their shared end), appended to `out` as raw
/// parameters (cubic i on [i, i + 1]), both parameters of each, and the ends of overlaps.
/// Pairs whose control boxes meet, found by a sweep over the boxes sorted by their left
/// side (sweep and prune: the pairs of a path without interference are its neighbours'),
/// each intersected as two cubics (intersect(), its fast path for degree <= 3). A point
/// at the shared end of neighbours comes too; an extra cut only splits a part whose
/// pieces are judged alike.
template <class T>
void raw_crossings(const Raw<T>& raw, std::vector<T>& out) {
  const std::size_t n = raw.cubics.size();
  std::vector<Box<T, 2>> box(n);
  for (std::size_t i = 0; i < n; ++i) box[i] = box_of<T, 2>(raw.cubics[i]);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return box[a].lo[0] < box[b].lo[0]; });
  const T slack = 64 * std::numeric_limits<T>::epsilon();  // in the unit frame
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t i = order[a];
    for (std::size_t b = a + 1; b < n && box[order[b]].lo[0] <= box[i].hi[0] + slack; ++b) {
      const std::size_t j = order[b];
      if (!isect::boxes_meet(box[j], box[i], slack)) continue;  // (in x they meet: the sweep)
      const Quad<T>& P = raw.cubics[i];
      const Quad<T>& Q = raw.cubics[j];
      // Neighbours that lie on either side of a line through their shared end (every other
      // control point strictly) meet only there: the common case of a smooth stretch.
      if (j == i + 1 || i == j + 1) {
        const Quad<T>& A = j == i + 1 ? P : Q;  // the first of the two
        const Quad<T>& B = j == i + 1 ? Q : P;
        const auto apart = [&](const Vector<T, 2>& v) {
          for (int k = 0; k < 3; ++k) {
            if (!(dot(A[static_cast<std::size_t>(k)] - A[3], v) < 0)) return false;
          }
          for (int k = 1; k < 4; ++k) {
            if (!(dot(B[static_cast<std::size_t>(k)] - B[0], v) > 0)) return false;
          }
          return true;
        };
        if (apart(B[3] - A[0]) || apart(B[1] - B[0]) || apart(A[3] - A[2])) continue;
      }
      const Intersections<T> x = intersect(Bezier<T, 2>({P[0], P[1], P[2], P[3]}), Bezier<T, 2>({Q[0], Q[1], Q[2], Q[3]}));
      for (const auto& p : x.points) {
        // Not the shared end of neighbours (found there as a touch or a crossing).
        if (j == i + 1 && length(p.point - P[3]) <= T(1e-9)) continue;
        if (i == j + 1 && length(p.point - P[0]) <= T(1e-9)) continue;
        out.push_back(static_cast<T>(i) + p.ta), out.push_back(static_cast<T>(j) + p.tb);
      }
      for (const auto& v : x.overlaps) {
        out.insert(out.end(), {static_cast<T>(i) + v.a.lo, static_cast<T>(i) + v.a.hi, static_cast<T>(j) + v.b_start, static_cast<T>(j) + v.b_end});
      }
    }
  }
}

/// The trim (see offset()): the raw path (cubic i on [i, i + 1]) cut at its
/// self-intersections, at the ends of its reversed runs and joins (the cusps of the offset,
/// the corners) and, for an open curve, where it crosses the round caps of the curve's
/// ends; each part between cuts judged on samples in its share of each raw cubic (8 to 32
/// parts, at most |d| apart): kept
/// where they are at least |d| - tol from the curve (for an outer join, the point moved
/// radially onto the arc of radius |d| about the corner, so that a miter or bevel is
/// judged as the round join it replaces); where the samples disagree (the offset of the
/// other side of the curve passes there, which is not in the raw path) the change is found
/// by bisection. Returns the
/// kept parameter intervals in order; `dropped` counts the runs cut away.
template <class T>
std::vector<Interval<T>> trimmed_intervals(const Pieces<T, 2>& path, const Raw<T>& raw, const Nearness<T>& near, T d, T tol,
                                           const std::optional<std::array<Point<T, 2>, 2>>& open_ends, std::size_t& dropped) {
  const std::size_t n = raw.cubics.size();
  const T r = std::abs(d);
  std::vector<T> cut{T(0), static_cast<T>(n)};
  for (std::size_t i = 1; i < n; ++i) {
    if (raw.reversed[i] != raw.reversed[i - 1] || raw.kind[i] != raw.kind[i - 1]) cut.push_back(static_cast<T>(i));
  }
  std::sort(cut.begin(), cut.end());
  const std::vector<T> structural = cut;  // not crossings: their points are judged too
  raw_crossings(raw, cut);
  if (open_ends) {
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& e : *open_ends) cap_crossings(raw.cubics[i], i, e, r, T(1e-3) * tol, cut);
    }
  }
  // A crossing at a joint that is a cut already (the shared end of neighbours, rounded):
  // that joint, so that no sliver part lies between them.
  for (std::size_t k = structural.size(); k < cut.size(); ++k) {
    const T j = std::round(cut[k]);
    if (std::abs(cut[k] - j) <= T(1e-9) && std::binary_search(structural.begin(), structural.end(), j)) cut[k] = j;
  }
  std::sort(cut.begin(), cut.end());
  cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
  // The point of the raw offset at parameter t as judged (an outer join's moved onto the arc).
  const auto judged = [&](T t) {
    const std::size_t i = std::min(static_cast<std::size_t>(t), n - 1);
    const Quad<T>& Q = raw.cubics[i];
    Point<T, 2> p = CubicForm<T>(Q[0], Q[1], Q[2], Q[3]).at(t - static_cast<T>(i));
    if (raw.kind[i] == RawKind::outer_join) {  // a miter or bevel (a round arc's cubic is itself judged)
      const Vector<T, 2> v = p - raw.corner[i];
      const T lv = length(v);
      if (lv > 0 && std::abs(lv - r) > tol) p = raw.corner[i] + v * (r / lv);
    }
    return p;
  };
  // A point is judged on |d| - tol (a point of the offset is that far, the fit's error
  // allowing); a change between two samples is placed where the distance passes it.
  const auto valid = [&](T t) { return !near.within(judged(t), r - tol); };
  std::vector<Interval<T>> kept;
  const auto keep = [&](T lo, T hi, bool ok, bool& last_ok) {
    if (!ok) {
      if (last_ok) ++dropped;
    } else if (!kept.empty() && kept.back().hi == lo) {
      kept.back().hi = hi;
    } else {
      kept.push_back({lo, hi});
    }
    last_ok = ok;
  };
  bool last_ok = true;
  std::vector<std::pair<T, bool>> samples;
  struct Run {
    Interval<T> iv;
    bool ok;
    bool deep;
  };
  std::vector<Run> all;
  for (std::size_t k = 0; k + 1 < cut.size(); ++k) {
    const T a = std::max(cut[k], T(0)), b = std::min(cut[k + 1], static_cast<T>(n));
    if (!(b - a > T(1e-12))) continue;
    // Samples inside the part: 7 or more in its share of each raw cubic, the joints between, and
    // its ends where they are not crossings (at a crossing the point is |d| from the curve
    // on both sides: judging it would keep a sliver of the part cut away).
    samples.clear();
    const auto is_structural = [&](T t) { return std::binary_search(structural.begin(), structural.end(), t); };
    if (is_structural(a)) samples.emplace_back(a, valid(a));
    for (std::size_t i = std::min(static_cast<std::size_t>(a), n - 1); i < n && static_cast<T>(i) < b; ++i) {
      const T lo = std::max(a, static_cast<T>(i)), hi = std::min(b, static_cast<T>(i + 1));
      if (!(hi > lo)) continue;
      // At most |d| apart along the cubic (its control polygon's length): the stretch of an
      // offset within |d| of a part of the curve that crosses it is at least 2 |d| long.
      // 8 to 32 parts.
      const Quad<T>& Q = raw.cubics[i];
      const T poly = length(Q[1] - Q[0]) + length(Q[2] - Q[1]) + length(Q[3] - Q[2]);
      const T want = std::ceil(poly * (hi - lo) / r);
      const int m = want > 32 ? 32 : (want < 8 ? 8 : static_cast<int>(want));
      for (int j = lo > a ? 0 : 1; j < m; ++j) {
        const T t = lo + (hi - lo) * T(j) / T(m);
        samples.emplace_back(t, valid(t));
      }
    }
    if (is_structural(b)) samples.emplace_back(b, valid(b));
    // Where the samples disagree, the change (the offset of another part of the curve, a
    // cap, passes there without crossing this side's offset) narrowed by bisection.
    std::vector<std::pair<Interval<T>, bool>> runs;
    T at = a;
    for (std::size_t j = 1; j < samples.size(); ++j) {
      if (samples[j].second == samples[j - 1].second) continue;
      T lo = samples[j - 1].first, hi = samples[j].first;
      for (int it = 0; it < 48 && hi - lo > T(1e-13) && length(path(hi) - path(lo)) > tol / 16; ++it) {
        const T m = (lo + hi) / 2;
        (valid(m) == samples[j - 1].second ? lo : hi) = m;
      }
      const T c = samples[j - 1].second ? lo : hi;  // the end on the kept side
      if (c > at) runs.push_back({{at, c}, samples[j - 1].second});
      at = std::max(at, c);
    }
    if (b > at) runs.push_back({{at, b}, samples.empty() || samples.back().second});
    // A kept run between a crossing and a change is the spur of a part cut away there when
    // it is short, all within 8 tol of the crossing (the raw offset is up to tol off the
    // exact one, so the distance passes |d| - tol a little past the crossing, farther
    // where the two offsets cross at a small angle, as near a cusp of the offset): cut
    // away with it.
    if (runs.size() > 1) {
      const auto spur = [&](const Interval<T>& iv, T end) {
        const Point<T, 2> x = path(end);
        for (int j = 0; j <= 8; ++j) {
          if (length(path(iv.lo + (iv.hi - iv.lo) * T(j) / 8) - x) > 8 * tol) return false;
        }
        return true;
      };
      if (runs.front().second && !is_structural(a) && spur(runs.front().first, a)) runs.front().second = false;
      if (runs.back().second && !is_structural(b) && spur(runs.back().first, b)) runs.back().second = false;
    }
    for (const auto& [iv, ok] : runs) {
      bool deep = false;  // some sample of a run cut away nearer than |d| - 2 tol
      for (const auto& q : samples) {
        if (!ok && !q.second && q.first >= iv.lo && q.first <= iv.hi && near.within(judged(q.first), r - 2 * tol)) {
          deep = true;
          break;
        }
      }
      all.push_back({iv, ok, deep});
    }
  }
  // A stretch of consecutive runs to cut away is cut only where it goes deeper than 2 tol
  // somewhere: shallower, it is the raw offset's own error (a measured error of the fit a
  // little over the tolerance, the line at a corner that turns by very little), kept whole
  // (judged as one, so that the parts on either side still meet).
  for (std::size_t k = 0; k < all.size();) {
    if (all[k].ok) {
      ++k;
      continue;
    }
    std::size_t e = k;
    bool deep = all[k].deep;
    while (e + 1 < all.size() && !all[e + 1].ok && all[e + 1].iv.lo == all[e].iv.hi) {
      ++e;
      deep = deep || all[e].deep;
    }
    if (!deep) {
      for (std::size_t j = k; j <= e; ++j) all[j].ok = true;
    }
    k = e + 1;
  }
  for (const auto& x : all) keep(x.iv.lo, x.iv.hi, x.ok, last_ok);
  return kept;
}

/// The trim of the raw offset (see offset()): the kept intervals (trimmed_intervals) made
/// into parts, each a run of cubics of the raw path (portions of its cubics, a point left
/// out: `tiny`); consecutive intervals whose ends meet within the tolerance continue one
/// part, and for a closed curve the last part continues into the first when its end
/// meets the first's start. Returns the parts' cubics in order (a gap between parts that
/// do not meet); `dropped` counts the runs cut away. `near` gets its grid here (more than 8
/// pieces). Throws InvalidArgument("distance") when nothing is kept.
template <class T>
std::vector<Quad<T>> trimmed_cubics(const Raw<T>& raw, Nearness<T>& near, T d, T tol, bool closed, const Point<T, 2>& first_at,
                                    const Point<T, 2>& last_at, T tiny, std::size_t& dropped) {
  std::vector<BezierPiece<T, 2>> segs;
  segs.reserve(raw.cubics.size());
  for (const auto& Q : raw.cubics) segs.emplace_back(Bezier<T, 2>({Q[0], Q[1], Q[2], Q[3]}));
  const Pieces<T, 2> path(std::move(segs));
  std::optional<std::array<Point<T, 2>, 2>> open_ends;
  if (!closed) open_ends = std::array<Point<T, 2>, 2>{first_at, last_at};
  if (near.pieces.size() > 8) near.build_grid(std::abs(d));
  const auto keep = trimmed_intervals(path, raw, near, d, tol, open_ends, dropped);
  // The kept parts in order, each a run of cubics; consecutive intervals whose ends meet
  // (the two parameters of one crossing) within the tolerance continue one part.
  std::vector<std::vector<Quad<T>>> parts;
  for (const auto& iv : keep) {
    std::vector<Quad<T>> cubics;
    const Pieces<T, 2> portion = path.portion(iv);
    for (const auto& seg : portion.segments()) {
      const auto& P = std::get<Bezier<T, 2>>(seg).points();  // a portion of a cubic: a cubic
      if (std::all_of(P.begin(), P.end(), [&](const auto& p) { return norm(p - P.front()) <= tiny; })) continue;
      cubics.push_back(Quad<T>{P[0], P[1], P[2], P[3]});
    }
    if (cubics.empty()) continue;
    if (!parts.empty() && norm(cubics.front()[0] - parts.back().back()[3]) <= tol) {
      cubics.front()[0] = parts.back().back()[3];
      parts.back().insert(parts.back().end(), cubics.begin(), cubics.end());
    } else {
      parts.push_back(std::move(cubics));
    }
  }
  if (parts.empty()) throw InvalidArgument("distance", "the trimmed offset is empty: every point of the offset is nearer than |distance| to the curve");
  // A closed curve: the last part continues into the first across the closing point (or
  // a crossing) when its end meets the first's start; it is then put before it.
  if (closed && parts.size() > 1 && norm(parts.back().back()[3] - parts.front().front()[0]) <= tol) {
    parts.front().front()[0] = parts.back().back()[3];
    parts.back().insert(parts.back().end(), parts.front().begin(), parts.front().end());
    parts.erase(parts.begin());
  }
  std::vector<Quad<T>> kept;
  for (auto& part : parts) kept.insert(kept.end(), part.begin(), part.end());
  return kept;
}

}  // namespace casteljau::detail::offset
