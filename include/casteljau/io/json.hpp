// Curve JSON (docs/cli.md): strict parsing with field-path errors, typed field
// readers, and writing curves, points and vectors.
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "casteljau/core/error.hpp"
#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

/// Parsed requests. Objects are std::maps: their nodes never move, so parsing never
/// copies a value (nlohmann::ordered_json's vector of pairs with const keys copies every
/// earlier value, recursively, each time it grows: quadratic, and a stack overflow on
/// deeply nested input).
using Json = nlohmann::json;

/// Responses: fields in the order written, so that they read naturally (`type` first).
using OrderedJson = nlohmann::ordered_json;

/// Error paths. Every function below throws casteljau::InvalidArgument whose where() is a
/// path relative to the value it was given ("points[2][1]", "weights", "" for the value
/// itself); callers add their own context with InvalidArgument::within, so an error deep
/// in a request reads "curve.segments[1].points[0][2]".

/// Parses one JSON text (RFC 8259), more strictly than plain nlohmann::json::parse:
/// - malformed text: where "request", problem "malformed JSON at line L, column C: ...";
/// - a number that overflows a double (1e999): where is its path, e.g. "t[3]";
/// - an object key given twice: where is the key's path (the JSON RFC leaves duplicates
///   undefined; silently keeping one would hide a user's mistake);
/// - a NUL byte anywhere outside what a failed parse read first (nlohmann would take it
///   for the end of the text and ignore what follows): malformed JSON at its position.
/// Long keys in paths, deep paths and long tokens in messages are cut (see quoted).
[[nodiscard]] Json parse_json(std::string_view text);

/// The JSON type of j for messages: "null", "boolean", "number", "string", "array", "object".
[[nodiscard]] std::string_view kind_of(const Json& j);

/// s in single quotes for an error message, escaped as in a JSON string (so that user
/// input holding a newline cannot break the one-line error contract). Text longer than 64
/// characters is cut there and its length given: 'aaaa…' (1048576 bytes), so that a
/// message stays short whatever the input.
[[nodiscard]] std::string quoted(std::string_view s);

/// j as a finite double; JSON integers and floats are numbers, booleans are not.
/// `what` names the value in the message ("coordinate must be a number, got string").
[[nodiscard]] double number_from_json(const Json& j, std::string_view where, std::string_view what = "value");

/// j as an int: a JSON integer, or a float with an integral value (2.0), within int range.
/// An out-of-range value is echoed only when its digits are exact (a JSON integer that
/// fits 64 bits); otherwise (beyond 64 bits, or 3e9) it is "a number above/below ...".
[[nodiscard]] int integer_from_json(const Json& j, std::string_view where);

/// j as an array of finite numbers; element errors name "where[i]".
[[nodiscard]] std::vector<double> numbers_from_json(const Json& j, std::string_view where);

[[nodiscard]] bool boolean_from_json(const Json& j, std::string_view where);
[[nodiscard]] std::string string_from_json(const Json& j, std::string_view where);

/// Read access to the fields of one JSON object, with unknown-field detection.
class Fields {
 public:
  /// Throws InvalidArgument("", "<what> must be a JSON object, got <kind>") unless j is one.
  Fields(const Json& j, std::string_view what);

  /// The field, or InvalidArgument(name, "required field is missing").
  [[nodiscard]] const Json& required(std::string_view name) const;
  /// The field, or nullptr when absent.
  [[nodiscard]] const Json* optional(std::string_view name) const;
  [[nodiscard]] bool has(std::string_view name) const { return optional(name) != nullptr; }

  /// Throws InvalidArgument(field, "unknown field (<owner> has: a, b, c)") for the first
  /// field not in `allowed`.
  void allow_only(std::initializer_list<std::string_view> allowed, std::string_view owner) const;
  void allow_only(std::span<const std::string_view> allowed, std::string_view owner) const;

 private:
  const Json& j_;
};

/// A curve object of any registered type (docs/cli.md, "Curve objects"), dimension
/// 1..max_dimension. Checks everything docs/cli.md asks: known type, required fields, no
/// unknown fields, JSON types, finite numbers, one dimension for all points, `dim` and
/// `degree` agreeing with the data; the curve constructors check the rest (weights > 0,
/// counts, breaks). An unknown type gives where "type" and "unknown curve type '...'
/// (known: ...)".
[[nodiscard]] AnyCurve curve_from_json(const Json& j);

/// One registered type as the bindings see it: its curve-JSON name, the library's class
/// name ("BSpline": the Python class) and the fields of its curve-JSON object ("type"
/// first, then in the order its reader lists them: the Python constructor's arguments).
struct CurveTypeInfo {
  std::string_view name;
  std::string_view class_name;
  std::span<const std::string_view> fields;
};

/// Every registered type, in the order of CurveTypes (from the Format entries of
/// src/io/curve_json.cpp, which check curve JSON against the same field lists).
[[nodiscard]] std::span<const CurveTypeInfo> curve_types();

/// The curve as curve JSON: {"type", "points"[, "weights"]} or {"type": "path",
/// "segments", "breaks"} (breaks always written). Numbers are written by nlohmann::json
/// in shortest round-trip form.
[[nodiscard]] OrderedJson to_json(const AnyCurve& c);

template <class T, int D>
[[nodiscard]] OrderedJson to_json(const Point<T, D>& p) {
  OrderedJson a = OrderedJson::array();
  for (int i = 0; i < D; ++i) a.push_back(static_cast<double>(p[i]));
  return a;
}

template <class T, int D>
[[nodiscard]] OrderedJson to_json(const Vector<T, D>& v) {
  OrderedJson a = OrderedJson::array();
  for (int i = 0; i < D; ++i) a.push_back(static_cast<double>(v[i]));
  return a;
}

/// The first number in j (depth first) that is not finite, as a path relative to j
/// ("curves[0].points[2][1]"), or nullopt. JSON cannot carry NaN or infinities
/// (nlohmann::json would write them as null), so writers check with this before output.
[[nodiscard]] std::optional<std::string> find_non_finite(const OrderedJson& j);

}  // namespace casteljau::io
