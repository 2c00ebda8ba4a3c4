// The work limit shared by the run-time queries and operations (private to src/io): a
// request is refused, naming its field and the figures, before work that would take more
// than seconds (casteljau::detail::max_query_work units).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <variant>

#include "casteljau/algo/scalar_forms.hpp"  // query_work, max_query_work
#include "casteljau/io/any_curve.hpp"

namespace casteljau::io::limits {

/// An estimated amount for a refusal message: the integer below 2^53 ("1234567"), three
/// significant digits above ("4.79e+49"), "more than 1e308" when it overflowed. A plain
/// cast to an integer type is undefined past its range (an estimate can reach 1e49).
inline std::string amount_text(double x) {
  if (!std::isfinite(x)) return "more than 1e308";
  if (std::abs(x) < 9007199254740992.0) return std::to_string(static_cast<long long>(x));
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

/// Refuses work on pieces p (see casteljau::detail::query_work) past the limit; `what` is
/// the subject of the message ("the query", "solving", ...).
template <class P>
void check_work(const P& p, const std::string& field, const std::string& what = "the query") {
  const double work = casteljau::detail::query_work(p);
  if (work > casteljau::detail::max_query_work) {
    throw InvalidArgument(field, what + " would take about " + amount_text(work) + " units of work (" +
                                     std::to_string(p.size()) + " Bézier pieces, (degree + 1)^2 summed over them), more than the limit of " +
                                     amount_text(casteljau::detail::max_query_work) +
                                     ": use fewer pieces or a lower degree");
  }
}

/// The same limit checked on the curve as given, before its Bézier pieces are made (for a
/// B-spline of degree p on n control points that conversion alone costs about n p^2
/// combinations of points: 0.7 s at n = 3000, p = 300, and a minute before it was made
/// O(p^2) a span): at most n - p pieces of degree p, (n - p) (p + 1)^2 (a Bézier curve:
/// one piece). Types without a single degree (paths, interpolating splines) are checked
/// on their pieces. The commands that make a curve's pieces call it first.
inline void check_curve_work(const AnyCurve& c, const std::string& field, const std::string& what = "the query") {
  const double work = std::visit(
      [](const auto& x) -> double {
        if constexpr (requires { x.degree(); x.points(); }) {
          const double n = static_cast<double>(x.points().size()), d = static_cast<double>(x.degree()) + 1;
          return std::max(1.0, n - d + 1) * d * d;
        } else {
          return 0;
        }
      },
      c);
  if (work > casteljau::detail::max_query_work) {
    throw InvalidArgument(field, what + " would take about " + amount_text(work) +
                                     " units of work (pieces x (degree + 1)^2), more than the limit of " +
                                     amount_text(casteljau::detail::max_query_work) +
                                     ": use fewer control points or a lower degree");
  }
}

}  // namespace casteljau::io::limits
