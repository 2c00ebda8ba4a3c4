// Curve JSON reading and writing: a strict SAX parser with field paths, typed field
// readers, and the conversion between curve objects and AnyCurve.
#include "casteljau/io/json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace casteljau::io {

namespace {

std::string index_path(std::string_view where, std::size_t i) {
  return std::string(where) + "[" + std::to_string(i) + "]";
}

/// A name in single quotes for a message, escaped as in a JSON string (so that a key
/// holding a newline cannot break the one-line error contract).
std::string quote_name(std::string_view s) {
  const std::string j = Json(std::string(s)).dump(-1, ' ', false, nlohmann::detail::error_handler_t::replace);
  return "'" + j.substr(1, j.size() - 2) + "'";
}

template <class Names>
std::string join(const Names& names) {
  std::string s;
  for (auto n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

// ---------------------------------------------------------------------------------------
// Strict parsing: nlohmann's SAX interface, building the same DOM as json::parse while
// tracking the path of the value being read, so that errors can name it.

class StrictBuilder : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return add(Json(nullptr)); }
  bool boolean(bool v) override { return add(Json(v)); }
  bool number_integer(number_integer_t v) override { return add(Json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return add(Json(v)); }
  bool number_float(number_float_t v, const string_t&) override { return add(Json(v)); }
  bool string(string_t& v) override { return add(Json(std::move(v))); }
  bool binary(binary_t&) override { return fail(path(), "binary values are not JSON"); }

  bool start_object(std::size_t) override { return open(Json::object()); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    Frame& f = stack_.back();
    f.key = k;
    if (f.node->contains(k)) return fail(path(), "duplicate field (each field may appear only once in an object)");
    return true;
  }

  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& ex) override {
    if (ex.id == 406) {
      // out_of_range.406: a number too large for a double. The token is the number.
      std::string msg = ex.what();
      const auto q = msg.find('\'');
      const std::string token = q == std::string::npos ? std::string() : msg.substr(q);
      return fail(path(), "number overflows a double: " + token);
    }
    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..."
    std::string msg = ex.what();
    const std::string marker = "parse error at ";
    const auto at = msg.find(marker);
    msg = at == std::string::npos ? msg : msg.substr(at + marker.size());
    return fail("request", "malformed JSON at " + msg);
  }

  Json take_result() {
    if (error_) throw *error_;
    return std::move(root_);
  }

 private:
  struct Frame {
    Json* node;
    std::string key;  // the key being read, for objects
  };

  /// The path of the value about to be read (or of the key just read).
  [[nodiscard]] std::string path() const {
    std::string p;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      if (f.node->is_object()) {
        if (!p.empty()) p += '.';
        p += f.key;
      } else {
        // Containers below the top hold their open child as their last element.
        const std::size_t n = f.node->size();
        p += "[" + std::to_string(i + 1 < stack_.size() ? n - 1 : n) + "]";
      }
    }
    return p;
  }

  bool fail(std::string where, std::string problem) {
    if (!error_) error_ = InvalidArgument(std::move(where), std::move(problem));
    return false;
  }

  /// Stores v where the parser is and returns its address.
  Json* place(Json v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = stack_.back();
    if (f.node->is_array()) {
      f.node->push_back(std::move(v));
      return &f.node->back();
    }
    Json& slot = (*f.node)[f.key];
    slot = std::move(v);
    return &slot;
  }

  bool add(Json v) {
    place(std::move(v));
    return true;
  }
  bool open(Json container) {
    Json* p = place(std::move(container));
    stack_.push_back({p, {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  Json root_;
  std::vector<Frame> stack_;
  std::optional<InvalidArgument> error_;
};

template <class Names>
bool one_of(std::string_view s, const Names& list) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

void find_non_finite_rec(const OrderedJson& j, std::string& path, std::optional<std::string>& found) {
  if (found) return;
  if (j.is_number_float()) {
    if (!std::isfinite(j.get<double>())) found = path;
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size() && !found; ++i) {
      const std::size_t len = path.size();
      path += "[" + std::to_string(i) + "]";
      find_non_finite_rec(j[i], path, found);
      path.resize(len);
    }
  } else if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      const std::size_t len = path.size();
      if (!path.empty()) path += '.';
      path += k;
      find_non_finite_rec(v, path, found);
      path.resize(len);
      if (found) return;
    }
  }
}

}  // namespace

// -----------------------------------------------------------------------------------------
// Public functions.

std::string quoted(std::string_view s) { return quote_name(s); }

Json parse_json(std::string_view text) {
  StrictBuilder b;
  // strict = true: nothing but whitespace may follow the value.
  Json::sax_parse(text.begin(), text.end(), &b, nlohmann::json::input_format_t::json, true);
  return b.take_result();
}

std::string_view kind_of(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "number";
    case Json::value_t::string: return "string";
    case Json::value_t::array: return "array";
    case Json::value_t::object: return "object";
    default: return "binary";
  }
}

double number_from_json(const Json& j, std::string_view where, std::string_view what) {
  if (!j.is_number()) throw InvalidArgument(std::string(where), std::string(what) + " must be a number, got " + std::string(kind_of(j)));
  const double v = j.get<double>();
  if (!std::isfinite(v)) {
    throw InvalidArgument(std::string(where), std::string(what) + " must be finite, got " + casteljau::detail::format_number(v));
  }
  return v;
}

int integer_from_json(const Json& j, std::string_view where) {
  const std::string w(where);
  if (j.is_number_unsigned()) {
    const auto v = j.get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) throw InvalidArgument(w, "integer out of range, got " + j.dump());
    return static_cast<int>(v);
  }
  if (j.is_number_integer()) {
    const auto v = j.get<std::int64_t>();
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
      throw InvalidArgument(w, "integer out of range, got " + j.dump());
    }
    return static_cast<int>(v);
  }
  if (j.is_number_float()) {
    const double v = number_from_json(j, where);
    if (std::trunc(v) != v) throw InvalidArgument(w, "must be an integer, got " + casteljau::detail::format_number(v));
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
      throw InvalidArgument(w, "integer out of range, got " + casteljau::detail::format_number(v));
    }
    return static_cast<int>(v);
  }
  throw InvalidArgument(w, "must be an integer, got " + std::string(kind_of(j)));
}

std::vector<double> numbers_from_json(const Json& j, std::string_view where) {
  if (!j.is_array()) throw InvalidArgument(std::string(where), "must be an array of numbers, got " + std::string(kind_of(j)));
  std::vector<double> v(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) v[i] = number_from_json(j[i], index_path(where, i));
  return v;
}

bool boolean_from_json(const Json& j, std::string_view where) {
  if (!j.is_boolean()) throw InvalidArgument(std::string(where), "must be true or false, got " + std::string(kind_of(j)));
  return j.get<bool>();
}

std::string string_from_json(const Json& j, std::string_view where) {
  if (!j.is_string()) throw InvalidArgument(std::string(where), "must be a string, got " + std::string(kind_of(j)));
  return j.get<std::string>();
}

Fields::Fields(const Json& j, std::string_view what) : j_(j) {
  if (!j.is_object()) throw InvalidArgument("", std::string(what) + " must be a JSON object, got " + std::string(kind_of(j)));
}

const Json& Fields::required(std::string_view name) const {
  if (const Json* p = optional(name)) return *p;
  throw InvalidArgument(std::string(name), "required field is missing");
}

const Json* Fields::optional(std::string_view name) const {
  const auto it = j_.find(std::string(name));
  return it == j_.end() ? nullptr : &*it;
}

void Fields::allow_only(std::initializer_list<std::string_view> allowed, std::string_view owner) const {
  for (const auto& [k, v] : j_.items()) {
    if (!one_of(k, allowed)) {
      throw InvalidArgument(k, "unknown field " + quote_name(k) + " (" + std::string(owner) + " has: " + join(allowed) + ")");
    }
  }
}

std::optional<std::string> find_non_finite(const OrderedJson& j) {
  std::string path;
  std::optional<std::string> found;
  find_non_finite_rec(j, path, found);
  return found;
}

}  // namespace casteljau::io