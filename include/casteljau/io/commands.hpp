// The command registry: every command of the run-time interfaces (the `casteljau` command
// line, later `casteljau serve` and the Python bindings), each declared once with its
// name, summary, description and example, its request fields and the function that runs
// it. The field list drives request validation (unknown, missing and mistyped fields),
// which request field a library error is reported under, `casteljau NAME --help` and the
// listing a server publishes (`GET /api`). Command definitions: src/io/commands_*.cpp,
// one file per family; the machinery: src/io/commands.cpp.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/io/any_curve.hpp"
#include "casteljau/io/json.hpp"

namespace casteljau::io {

struct AnySurface;

/// What a request field holds, as checked before the command runs.
enum class FieldType {
  number,   ///< a finite number
  integer,  ///< an integer in int range (2.0 counts)
  boolean,  ///< true or false
  string,   ///< a string; with `choices`, one of them
  numbers,  ///< an array of finite numbers
  point,    ///< a point: an array of finite numbers (its dimension is checked by the command)
  vector,   ///< a vector: as point
  points,   ///< a polygon: an array of points of one dimension 1..max_dimension, at least one
  curve,    ///< a curve object (curve JSON)
  curves,   ///< an array of curve objects, between min_count and max_count of them
  number_or_choice,  ///< a finite number, or a string among `choices` (read by Args::choice)
  surface,  ///< a surface object (surface JSON, io/surfaces.hpp)
  json,     ///< any JSON value, checked by the command (fields whose shape depends on another)
};

/// The name of a field type in the API listing and in help: "number", "integer",
/// "boolean", "string", "number[]", "point", "vector", "point[]", "curve", "curve[]",
/// "number|string", "surface", "json".
[[nodiscard]] std::string_view field_type_name(FieldType t);

/// One field of a request.
struct Field {
  std::string_view name;
  FieldType type;
  bool required = false;
  /// The default as JSON text ("1e-12", "false", "\"optimal\""), empty for none. An absent
  /// field reads as its default, so the listing and the behaviour cannot disagree.
  std::string_view default_json = {};
  /// One line for help and the API listing (the rules beyond the type, the meaning).
  std::string_view help = {};
  /// string: the accepted values ("unknown <name> '<value>' (a, b, c)" otherwise).
  std::span<const std::string_view> choices = {};
  /// number: how a type error names the value ("split parameter must be a number, ...");
  /// empty: the field's name.
  std::string_view noun = {};
  /// curves: how many curves the array holds (max_count 0: no limit).
  std::size_t min_count = 0;
  std::size_t max_count = 0;
  /// curve: the capability its type needs (help and the listing name the types that
  /// have it, from the registry).
  std::optional<Capability> needs = {};
};

/// A request whose fields have been checked against the command's field list: every field
/// present has its declared type, every required one is present. Reading a field the
/// command did not declare is a programming error (std::logic_error).
class Args {
 public:
  /// Whether the request gave the field (a default does not count).
  [[nodiscard]] bool has(std::string_view name) const;

  /// The field's value, or its default when absent; a field without either is a
  /// programming error (read optional fields with has() first or the optional_ forms).
  [[nodiscard]] double number(std::string_view name) const;
  [[nodiscard]] std::optional<double> optional_number(std::string_view name) const;
  [[nodiscard]] int integer(std::string_view name) const;
  [[nodiscard]] bool boolean(std::string_view name) const;
  [[nodiscard]] const std::string& string(std::string_view name) const;
  /// number_or_choice: the string given, or empty when a number was (read it by number()).
  [[nodiscard]] const std::string& choice(std::string_view name) const;
  /// number[], point, vector.
  [[nodiscard]] const std::vector<double>& numbers(std::string_view name) const;
  [[nodiscard]] std::optional<std::vector<double>> optional_numbers(std::string_view name) const;
  [[nodiscard]] const PointList& points(std::string_view name) const;
  [[nodiscard]] const AnyCurve& curve(std::string_view name) const;
  [[nodiscard]] std::span<const AnyCurve> curves(std::string_view name) const;
  [[nodiscard]] const AnySurface& surface(std::string_view name) const;
  /// json: the value as given (or the default).
  [[nodiscard]] const Json& json(std::string_view name) const;

  struct Value {
    const Field* field = nullptr;
    bool given = false;   ///< in the request (else: the default, or nothing)
    bool filled = false;  ///< given or defaulted
    double number = 0;
    int integer = 0;
    bool boolean = false;
    std::string string;
    std::vector<double> numbers;
    PointList points;
    std::vector<AnyCurve> curves;  ///< curve: one
    std::shared_ptr<const AnySurface> surface;
    Json json;
  };

 private:
  friend Args read_args(std::span<const Field> fields, const Json& request, std::string_view owner);
  [[nodiscard]] const Value& at(std::string_view name) const;
  [[nodiscard]] const Value& filled(std::string_view name) const;
  std::vector<Value> values_;
};

/// What a command answers: a JSON object, or for `render` an SVG document (`json` then
/// holds {"svg": ...} for line-oriented front-ends).
struct Response {
  OrderedJson json;
  std::string svg = {};
  bool is_svg = false;
};

/// One command.
struct Command {
  std::string_view name;
  std::string_view summary;  ///< one line, for `casteljau --help` and the API listing
  std::string_view details;   ///< what it does, for `casteljau NAME --help`
  std::string_view response;  ///< what it answers, for `casteljau NAME --help`
  /// Example requests and their responses: lines "  echo '<request>' | casteljau NAME",
  /// each followed by the response line (checked by tests/cli).
  std::string_view example;
  std::span<const Field> fields;
  Response (*run)(const Args& args);
  /// Where an error about an intermediate value is reported: a library error whose path
  /// does not start at one of the command's fields is reported against this field as
  /// "the computation failed on this curve: ..." (empty: passed through as it is).
  std::string_view subject = "curve";
  /// The field a NumericalError (a limit of an algorithm reached on this input) is
  /// reported against as bad input (empty: it escapes, an internal error).
  std::string_view numerical_field = "curve";
};

/// Every command, grouped by family (curve operations, queries, point sets, surfaces).
[[nodiscard]] std::span<const Command> commands();

/// The surface form of a command that `cli.md` defines for curves (eval, split, elevate,
/// insert_knot, to_bezier, bounds, area): the same name, `surface` instead of `curve`; nullptr when the
/// command has none. run() takes a request holding `surface` to it.
[[nodiscard]] const Command* surface_form(std::string_view name);

/// The command called name, or nullptr.
[[nodiscard]] const Command* find_command(std::string_view name);

/// Checks the request against the field list: a JSON object ("<owner> must be a JSON
/// object"), no unknown field ("unknown field 'x' (<owner> has: ...)"), then each field in
/// the list's order: required ones present ("required field is missing"), each of its
/// type (the messages of io/json.hpp, paths inside the field: "curve.points[2][1]").
[[nodiscard]] Args read_args(std::span<const Field> fields, const Json& request, std::string_view owner);

/// "an eval request", "a split request": how messages name the command's request.
[[nodiscard]] std::string request_noun(const Command& command);

/// Runs the command on one parsed request (a request with a `surface` field, to a command
/// that does not declare one, runs the command's surface form). Bad input throws InvalidArgument whose where()
/// is a path in the request ("curve.points[2][1]", "t[3]", "" for the request itself); a
/// result that is not finite is refused ("request"). Anything else that escapes is an
/// internal error.
[[nodiscard]] Response run(const Command& command, const Json& request);

/// The command's help: details, the request fields (type, required or default, help),
/// the response, the example; then the same for its surface form when it has one.
[[nodiscard]] std::string help(const Command& command);

/// The listing of `GET /api`: {"commands": [{"name", "summary", "fields": [{"name",
/// "type", "required", "default" (when there is one), "choices" (strings with a fixed
/// set), "types" (curves of some types only), "min_count", "max_count" (curve arrays),
/// "help"}, ...]}, ...]}, and "surface_forms": the surface forms of the commands that have
/// one (eval, split, ..., project, intersect), each entry as in "commands".
[[nodiscard]] OrderedJson api_listing();

}  // namespace casteljau::io
