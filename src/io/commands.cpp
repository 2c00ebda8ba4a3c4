// The command registry's machinery (io/commands.hpp): the list of commands from the
// family files, request validation from the field lists, the error paths, help and the
// API listing. The commands themselves: src/io/commands_*.cpp.
#include "casteljau/io/commands.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/io/surfaces.hpp"
#include "commands_family.hpp"
#include "text.hpp"

namespace casteljau::io {

namespace {

using detail::index_path;

[[noreturn]] void undeclared(std::string_view name) {
  throw std::logic_error("command reads field '" + std::string(name) + "' that it does not declare, or without a value");
}

std::string count_word(std::size_t n) {
  static constexpr std::string_view words[] = {"zero", "one", "two", "three", "four"};
  return n < std::size(words) ? std::string(words[n]) : std::to_string(n);
}

/// The polygon of a points field: an array of points, each 1..max_dimension finite
/// numbers, all of one dimension, at least one.
PointList polygon_from_json(const Json& j, const std::string& where) {
  if (!j.is_array()) throw InvalidArgument(where, "must be an array of points, got " + std::string(kind_of(j)));
  PointList P;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = index_path(where, i);
    const std::vector<double> x = numbers_from_json(j[i], at);
    if (x.empty() || x.size() > static_cast<std::size_t>(max_dimension)) {
      throw InvalidArgument(at, "a point has 1 to " + std::to_string(max_dimension) + " coordinates, got " + std::to_string(x.size()));
    }
    if (i == 0) P.dim = static_cast<int>(x.size());
    if (x.size() != static_cast<std::size_t>(P.dim)) {
      throw InvalidArgument(at, "all points must have the same dimension: " + std::to_string(x.size()) + " coordinates after " +
                                    std::to_string(P.dim));
    }
    P.coords.insert(P.coords.end(), x.begin(), x.end());
  }
  if (P.dim == 0) throw InvalidArgument(where, "needs at least one point");
  return P;
}

/// A curves field: the array, its count, then each curve (errors "curves[i]...").
std::vector<AnyCurve> curves_from_json(const Json& j, const Field& field) {
  const std::string where(field.name);
  const std::size_t lo = field.min_count, hi = field.max_count;
  if (!j.is_array()) {
    std::string count;
    if (hi != 0 && lo == hi) count = count_word(lo) + " ";
    else if (hi != 0) count = count_word(lo) + " or " + count_word(hi) + " ";
    throw InvalidArgument(where, "must be an array of " + count + "curve objects, got " + std::string(kind_of(j)));
  }
  const std::size_t n = j.size();
  const auto plural = [](std::size_t k) { return k == 1 ? std::string(" curve") : std::string(" curves"); };
  if (hi != 0 && lo == hi && n != lo) {
    throw InvalidArgument(where, "needs exactly " + count_word(lo) + plural(lo) + ", got " + std::to_string(n));
  }
  if (hi != 0 && (n < lo || n > hi)) {
    throw InvalidArgument(where, "needs " + count_word(lo) + plural(lo) + " or " + count_word(hi) + ", got " + std::to_string(n));
  }
  if (n < lo) throw InvalidArgument(where, "needs at least " + count_word(lo) + plural(lo));
  std::vector<AnyCurve> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    try {
      out.push_back(curve_from_json(j[i]));
    } catch (const InvalidArgument& e) {
      throw e.within(index_path(where, i));
    }
  }
  return out;
}

/// Reads one field's JSON value into v by the field's type.
void read_value(const Field& field, const Json& j, Args::Value& v) {
  const std::string where(field.name);
  switch (field.type) {
    case FieldType::number:
      v.number = number_from_json(j, where, field.noun.empty() ? field.name : field.noun);
      break;
    case FieldType::integer:
      v.integer = integer_from_json(j, where);
      break;
    case FieldType::boolean:
      v.boolean = boolean_from_json(j, where);
      break;
    case FieldType::string:
      v.string = string_from_json(j, where);
      if (!field.choices.empty() &&
          std::find(field.choices.begin(), field.choices.end(), v.string) == field.choices.end()) {
        throw InvalidArgument(where, "unknown " + where + " " + io::quoted(v.string) + " (" + detail::join(field.choices) + ")");
      }
      break;
    case FieldType::numbers:
    case FieldType::point:
    case FieldType::vector:
      v.numbers = numbers_from_json(j, where);
      break;
    case FieldType::points:
      v.points = polygon_from_json(j, where);
      break;
    case FieldType::curve:
      try {
        v.curves.push_back(curve_from_json(j));
      } catch (const InvalidArgument& e) {
        throw e.within(where);
      }
      break;
    case FieldType::curves:
      v.curves = curves_from_json(j, field);
      break;
    case FieldType::surface:
      try {
        v.surface = std::make_shared<const AnySurface>(surface_from_json(j));
      } catch (const InvalidArgument& e) {
        throw e.within(where);
      }
      break;
    case FieldType::json:
      v.json = j;
      break;
    case FieldType::number_or_choice:
      if (j.is_string()) {
        v.string = j.get<std::string>();
        if (std::find(field.choices.begin(), field.choices.end(), v.string) == field.choices.end()) {
          throw InvalidArgument(where, "unknown " + where + " " + io::quoted(v.string) + " (a number, or " + detail::join(field.choices) + ")");
        }
      } else if (j.is_number()) {
        v.number = number_from_json(j, where, field.noun.empty() ? field.name : field.noun);
      } else {
        throw InvalidArgument(where, "must be a number or one of " + detail::join(field.choices) + ", got " + std::string(kind_of(j)));
      }
      break;
  }
}

/// The first name of a path: "curve" of "curve.points[2]", "t" of "t[3]".
std::string_view path_root(std::string_view where) { return where.substr(0, where.find_first_of(".[")); }

bool declares(const Command& c, std::string_view field) {
  return std::any_of(c.fields.begin(), c.fields.end(), [&](const Field& f) { return f.name == field; });
}

std::vector<Command> collect() {
  std::vector<Command> all;
  for (const auto family : {detail::curve_commands(), detail::query_commands(), detail::point_commands(), detail::ops_commands(),
                            detail::svg_import_commands(), detail::outline_commands(), detail::surface_commands(),
                            detail::surface_mesh_commands()}) {
    all.insert(all.end(), family.begin(), family.end());
  }
  return all;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Args

const Args::Value& Args::at(std::string_view name) const {
  for (const auto& v : values_) {
    if (v.field->name == name) return v;
  }
  undeclared(name);
}

const Args::Value& Args::filled(std::string_view name) const {
  const Value& v = at(name);
  if (!v.filled) undeclared(name);
  return v;
}

bool Args::has(std::string_view name) const { return at(name).given; }
double Args::number(std::string_view name) const { return filled(name).number; }
std::optional<double> Args::optional_number(std::string_view name) const {
  const Value& v = at(name);
  return v.filled ? std::optional<double>(v.number) : std::nullopt;
}
int Args::integer(std::string_view name) const { return filled(name).integer; }
bool Args::boolean(std::string_view name) const { return filled(name).boolean; }
const std::string& Args::string(std::string_view name) const { return filled(name).string; }
const std::string& Args::choice(std::string_view name) const { return filled(name).string; }
const std::vector<double>& Args::numbers(std::string_view name) const { return filled(name).numbers; }
std::optional<std::vector<double>> Args::optional_numbers(std::string_view name) const {
  const Value& v = at(name);
  return v.filled ? std::optional<std::vector<double>>(v.numbers) : std::nullopt;
}
const PointList& Args::points(std::string_view name) const { return filled(name).points; }
const AnyCurve& Args::curve(std::string_view name) const {
  const Value& v = filled(name);
  if (v.curves.size() != 1) undeclared(name);
  return v.curves.front();
}
std::span<const AnyCurve> Args::curves(std::string_view name) const { return filled(name).curves; }
const AnySurface& Args::surface(std::string_view name) const {
  const Value& v = filled(name);
  if (!v.surface) undeclared(name);
  return *v.surface;
}
const Json& Args::json(std::string_view name) const { return filled(name).json; }

Args read_args(std::span<const Field> fields, const Json& request, std::string_view owner) {
  const Fields f(request, owner);
  std::vector<std::string_view> names;
  names.reserve(fields.size());
  for (const auto& field : fields) names.push_back(field.name);
  f.allow_only(names, owner);
  Args args;
  args.values_.reserve(fields.size());
  for (const auto& field : fields) {
    Args::Value& v = args.values_.emplace_back();
    v.field = &field;
    if (const Json* j = f.optional(field.name)) {
      read_value(field, *j, v);
      v.given = v.filled = true;
    } else if (field.required) {
      throw InvalidArgument(std::string(field.name), "required field is missing");
    } else if (!field.default_json.empty()) {
      read_value(field, Json::parse(field.default_json), v);
      v.filled = true;
    }
  }
  return args;
}

// ---------------------------------------------------------------------------------------
// The registry

std::string_view field_type_name(FieldType t) {
  switch (t) {
    case FieldType::number: return "number";
    case FieldType::integer: return "integer";
    case FieldType::boolean: return "boolean";
    case FieldType::string: return "string";
    case FieldType::numbers: return "number[]";
    case FieldType::point: return "point";
    case FieldType::vector: return "vector";
    case FieldType::points: return "point[]";
    case FieldType::curve: return "curve";
    case FieldType::curves: return "curve[]";
    case FieldType::number_or_choice: return "number|string";
    case FieldType::surface: return "surface";
    case FieldType::json: return "json";
  }
  return "";
}

std::span<const Command> commands() {
  static const std::vector<Command> all = collect();
  return all;
}

const Command* surface_form(std::string_view name) {
  for (const auto& c : detail::surface_forms()) {
    if (c.name == name) return &c;
  }
  for (const auto& c : detail::surface_mesh_forms()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

const Command* find_command(std::string_view name) {
  for (const auto& c : commands()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

std::string request_noun(const Command& command) {
  const bool vowel = !command.name.empty() && std::string_view("aeiou").find(command.name.front()) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + std::string(command.name) + " request";
}

Response run(const Command& command, const Json& request) {
  if (request.is_object() && (request.contains("surface") || request.contains("surfaces")) && !declares(command, "surface")) {
    if (const Command* s = surface_form(command.name)) return run(*s, request);
  }
  const Args args = read_args(command.fields, request, request_noun(command));
  Response r;
  try {
    r = command.run(args);
  } catch (const InvalidArgument& e) {
    // An error under one of the request's fields passes through; any other concerns an
    // intermediate value inside an algorithm on valid input (an overflow, say), reported
    // against the command's subject rather than under a name the request does not have.
    if (command.subject.empty() || declares(command, path_root(e.where()))) throw;
    throw InvalidArgument(std::string(command.subject), "the computation failed on this curve: " + std::string(e.what()));
  } catch (const NumericalError& e) {
    if (command.numerical_field.empty()) throw;
    throw InvalidArgument(std::string(command.numerical_field), e.what());
  }
  if (!r.is_svg) {
    // JSON has no NaN or infinity; a result that overflowed is refused, not written as null.
    if (auto where = find_non_finite(r.json)) throw InvalidArgument("request", "the result is not finite at " + *where + " (overflow)");
  }
  return r;
}

namespace {

/// The request fields of a command's help, one line each.
std::string field_lines(const Command& command) {
  std::size_t width = 0;
  for (const auto& f : command.fields) width = std::max(width, f.name.size());
  std::string s;
  for (const auto& f : command.fields) {
    s += "  " + std::string(f.name) + std::string(width + 2 - f.name.size(), ' ') + std::string(field_type_name(f.type));
    if (f.required) s += ", required";
    else if (!f.default_json.empty()) s += ", default " + std::string(f.default_json);
    else s += ", optional";
    std::string rule;
    if (!f.choices.empty()) rule = detail::join(f.choices);
    if (f.needs) rule = types_phrase(*f.needs);
    if (!f.help.empty()) rule += (rule.empty() ? "" : "; ") + std::string(f.help);
    if (!rule.empty()) s += "; " + rule;
    s += "\n";
  }
  return s;
}

/// A command's entry in the API listing: name, summary, fields.
OrderedJson listing_entry(const Command& c) {
  OrderedJson fields = OrderedJson::array();
  for (const auto& f : c.fields) {
    OrderedJson field{{"name", f.name}, {"type", field_type_name(f.type)}, {"required", f.required}};
    if (!f.default_json.empty()) field["default"] = OrderedJson::parse(f.default_json);
    if (!f.choices.empty()) field["choices"] = std::vector<std::string_view>(f.choices.begin(), f.choices.end());
    if (f.needs) field["types"] = types_with(*f.needs);
    if (f.type == FieldType::curves) {
      field["min_count"] = f.min_count;
      if (f.max_count != 0) field["max_count"] = f.max_count;
    }
    field["help"] = f.help;
    fields.push_back(std::move(field));
  }
  return OrderedJson{{"name", c.name}, {"summary", c.summary}, {"fields", std::move(fields)}};
}

}  // namespace

std::string help(const Command& command) {
  std::string s(command.details);
  s += "\n\nRequest:\n" + field_lines(command);
  s += "Response: " + std::string(command.response) + "\n\nExample:\n" + std::string(command.example);
  // The surface form of the command (a request with `surface`), when it has one.
  if (const Command* sf = surface_form(command.name); sf && sf != &command) {
    s += "\n\nSurface form (a request with `surface` instead of `curve`): " + std::string(sf->summary) + "\n" + std::string(sf->details);
    s += "\n\nRequest (surface form):\n" + field_lines(*sf);
    s += "Response (surface form): " + std::string(sf->response) + "\n\nExample (surface form):\n" + std::string(sf->example);
  }
  return s;
}

OrderedJson api_listing() {
  OrderedJson list = OrderedJson::array(), forms = OrderedJson::array();
  for (const auto& c : commands()) list.push_back(listing_entry(c));
  for (const auto& c : detail::surface_forms()) forms.push_back(listing_entry(c));
  return OrderedJson{{"commands", std::move(list)}, {"surface_forms", std::move(forms)}};
}

}  // namespace casteljau::io
