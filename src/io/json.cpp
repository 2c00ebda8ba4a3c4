// Curve JSON reading and writing: a strict SAX parser with field paths, typed field
// readers, and the conversion between curve objects and AnyCurve.
#include "casteljau/io/json.hpp"

#include "text.hpp"

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

using detail::index_path;
using detail::join;

/// How much user text a message quotes: the first 64 characters (code points), enough
/// to recognise a name or a value; a longer text is cut there, with its length stated, so
/// that a 1 MB key cannot make a 2 MB error line.
constexpr std::size_t quote_limit = 64;

/// The byte offset after the first n characters of s (UTF-8: a character starts at every
/// byte that is not a continuation byte 10xxxxxx, so the cut never splits a sequence), or
/// s.size() when s is no longer.
std::size_t after_characters(std::string_view s, std::size_t n) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xc0) != 0x80) {
      if (count == n) return i;
      ++count;
    }
  }
  return s.size();
}

/// The byte offset before the last n characters of s, or 0 when s is no longer.
std::size_t before_last_characters(std::string_view s, std::size_t n) {
  std::size_t count = 0;
  for (std::size_t i = s.size(); i-- > 0;) {
    if ((static_cast<unsigned char>(s[i]) & 0xc0) != 0x80 && ++count == n) return i;
  }
  return 0;
}

/// s escaped as the inside of a JSON string (control characters, quotes, backslashes;
/// bytes that are not UTF-8 become U+FFFD), so that user text holding a newline cannot
/// break the one-line error contract.
std::string escaped(std::string_view s) {
  const std::string j = Json(std::string(s)).dump(-1, ' ', false, nlohmann::detail::error_handler_t::replace);
  return j.substr(1, j.size() - 2);
}

/// A name in single quotes for a message: see quoted().
std::string quote_name(std::string_view s) {
  const std::size_t cut = after_characters(s, quote_limit);
  if (cut == s.size()) return "'" + escaped(s) + "'";
  return "'" + escaped(s.substr(0, cut)) + "\u2026' (" + std::to_string(s.size()) + " bytes)";
}

/// As quote_name, but keeping the end of s: for the text a parser read up to an error
/// (the error is at its end).
std::string quote_tail(std::string_view s) {
  const std::size_t cut = before_last_characters(s, quote_limit);
  if (cut == 0) return "'" + std::string(s) + "'";
  return "'\u2026" + std::string(s.substr(cut)) + "' (" + std::to_string(s.size()) + " bytes)";
}

/// An object key as a path component: cut to quote_limit characters (marked with an
/// ellipsis; the message says how long it was).
std::string key_in_path(std::string_view k) {
  const std::size_t cut = after_characters(k, quote_limit);
  return cut == k.size() ? std::string(k) : std::string(k.substr(0, cut)) + "\u2026";
}

/// A path of at most about 256 bytes: a longer one (nesting 100000 levels deep) keeps its
/// start and its end, an ellipsis standing for the middle.
std::string clip_path(std::string p) {
  constexpr std::size_t head_bytes = 160, tail_bytes = 80;
  if (p.size() <= head_bytes + tail_bytes + 16) return p;
  const auto continuation = [&](std::size_t i) { return (static_cast<unsigned char>(p[i]) & 0xc0) == 0x80; };
  std::size_t head = head_bytes, tail = p.size() - tail_bytes;
  while (head > 0 && continuation(head)) --head;  // whole characters only
  while (tail < p.size() && continuation(tail)) ++tail;
  return p.substr(0, head) + "\u2026" + p.substr(tail);
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
    if (f.node->contains(k)) {
      return fail(path(), "duplicate field " + quote_name(k) + " (each field may appear only once in an object)");
    }
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& ex) override {
    syntax_error_at_ = position;
    if (ex.id == 406) {
      // out_of_range.406: "number overflow parsing '<token>'", the token being the number
      // (quoted here again, cut if it is long).
      return fail(path(), "number overflows a double: " + quote_name(last_token));
    }
    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ...
    // - invalid literal; last read: '<token>'; expected ...": the token is what the lexer
    // read of the bad value, which may be a whole string; its end is kept.
    std::string msg = ex.what();
    const std::string marker = "parse error at ";
    const auto at = msg.find(marker);
    msg = at == std::string::npos ? msg : msg.substr(at + marker.size());
    const std::string read = "last read: '" + last_token + "'";
    if (const auto r = msg.find(read); r != std::string::npos) {
      msg.replace(r, read.size(), "last read: " + quote_tail(last_token));
    }
    return fail("request", "malformed JSON at " + msg);
  }

  /// The byte count read when the parser reported a syntax error (the offending byte is
  /// the last one read), or nullopt.
  [[nodiscard]] std::optional<std::size_t> syntax_error_at() const { return syntax_error_at_; }
  [[nodiscard]] bool failed() const { return error_.has_value(); }

  Json take_result() {
    if (error_) throw *error_;
    return std::move(root_);
  }

 private:
  struct Frame {
    Json* node;
    std::string key;  // the key being read, for objects
  };

  /// The path of the value about to be read (or of the key just read); long keys and deep
  /// paths are cut (key_in_path, clip_path).
  [[nodiscard]] std::string path() const {
    std::string p;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      if (f.node->is_object()) {
        if (!p.empty()) p += '.';
        p += key_in_path(f.key);
      } else {
        // Containers below the top hold their open child as their last element.
        const std::size_t n = f.node->size();
        p += "[" + std::to_string(i + 1 < stack_.size() ? n - 1 : n) + "]";
      }
    }
    return clip_path(std::move(p));
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
  std::optional<std::size_t> syntax_error_at_;
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
  // nlohmann's lexer takes a NUL byte for the end of the input (as at the end of a C
  // string), so "{...}\0garbage" would parse and the garbage be ignored. A NUL is not
  // JSON text anywhere (in a string it must be written \u0000): unless the parser failed
  // before reaching it, the NUL is the error.
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    const bool failed_before = b.failed() && !(b.syntax_error_at() && *b.syntax_error_at() > nul);
    if (!failed_before) {
      const std::size_t line_start = text.rfind('\n', nul) == std::string_view::npos ? 0 : text.rfind('\n', nul) + 1;
      const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
      throw InvalidArgument("request", "malformed JSON at line " + std::to_string(line) + ", column " +
                                           std::to_string(nul - line_start + 1) +
                                           ": NUL byte (U+0000); JSON text may hold it only in a string, escaped as \\u0000");
    }
  }
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
  constexpr auto lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
  const std::string range = "integer out of range (" + std::to_string(lo) + " to " + std::to_string(hi) + "), got ";
  if (j.is_number_unsigned()) {
    const auto v = j.get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(hi)) throw InvalidArgument(w, range + std::to_string(v));
    return static_cast<int>(v);
  }
  if (j.is_number_integer()) {
    const auto v = j.get<std::int64_t>();
    if (v < lo || v > hi) throw InvalidArgument(w, range + std::to_string(v));
    return static_cast<int>(v);
  }
  if (j.is_number_float()) {
    const double v = number_from_json(j, where);
    if (std::trunc(v) != v) throw InvalidArgument(w, "must be an integer, got " + casteljau::detail::format_number(v));
    if (v < lo || v > hi) {
      // A JSON integer beyond 64 bits (-9223372036854775809), or a float token, arrives as
      // the nearest double, whose digits may differ from the ones written (it printed as
      // -9223372036854775808): echoing them would misquote the request, so say where it is.
      throw InvalidArgument(w, range + (v < 0 ? "a number below " + std::to_string(lo) : "a number above " + std::to_string(hi)));
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
  allow_only(std::span<const std::string_view>(allowed.begin(), allowed.size()), owner);
}

void Fields::allow_only(std::span<const std::string_view> allowed, std::string_view owner) const {
  for (const auto& [k, v] : j_.items()) {
    if (!one_of(k, allowed)) {
      throw InvalidArgument(key_in_path(k), "unknown field " + quote_name(k) + " (" + std::string(owner) + " has: " + join(allowed) + ")");
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