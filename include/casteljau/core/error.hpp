// Error types of casteljau and the checks that every public entry runs on its input.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace casteljau {

/// Thrown for bad input: names where the problem is (`where`, e.g. "weights[2]") and what
/// is wrong (`problem`, e.g. "weight must be > 0, got -1"). what() is "where: problem".
/// Interfaces prefix `where` with their own context (the CLI writes "curve.weights[2]").
class InvalidArgument : public std::invalid_argument {
 public:
  InvalidArgument(std::string where, std::string problem)
      : std::invalid_argument(where.empty() ? problem : where + ": " + problem),
        where_(std::move(where)),
        problem_(std::move(problem)) {}

  [[nodiscard]] const std::string& where() const noexcept { return where_; }
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

  /// The same error seen from an enclosing context: "points[1]" inside "curve" becomes
  /// "curve.points[1]"; an index path ("[3]") is appended without a dot.
  [[nodiscard]] InvalidArgument within(std::string_view context) const {
    return {join_where(context, where_), problem_};
  }

  static std::string join_where(std::string_view outer, std::string_view inner) {
    if (outer.empty()) return std::string(inner);
    if (inner.empty()) return std::string(outer);
    std::string s(outer);
    if (inner.front() != '[') s += '.';
    s += inner;
    return s;
  }

 private:
  std::string where_;
  std::string problem_;
};

/// Thrown when an algorithm cannot return a result it can guarantee: an iteration or
/// depth limit would be hit (flatten below the coordinates' resolution, a root solve
/// that does not converge). Distinct from InvalidArgument: the input is valid, the
/// algorithm gives up and says so rather than returning an unverified answer.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {

/// Formats a number for a message in the shortest form that reads back as the same
/// value (1.1 prints as 1.1, not 1.1000000000000001), as the CLI writes numbers.
template <class T>
std::string format_number(T v) {
  if constexpr (std::is_floating_point_v<T>) {
    std::array<char, 64> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    if (r.ec == std::errc()) return std::string(buf.data(), r.ptr);
  }
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace detail

/// Throws InvalidArgument(where, ...) unless v is finite.
template <class T>
void require_finite(T v, std::string_view where) {
  if (!std::isfinite(v)) {
    throw InvalidArgument(std::string(where), "value must be finite, got " + detail::format_number(v));
  }
}

/// Throws InvalidArgument naming `name[i]` for the first non-finite value i of `values`
/// (require_finite's message), building the name only then.
template <class Range>
void require_finite_values(const Range& values, std::string_view name) {
  std::size_t i = 0;
  for (const auto& v : values) {
    if (!std::isfinite(v)) require_finite(v, std::string(name) + "[" + std::to_string(i) + "]");
    ++i;
  }
}

}  // namespace casteljau
