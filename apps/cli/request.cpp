// The request handling shared by the command line (apps/cli/main.cpp) and the server
// (apps/cli/serve.cpp): one request's text in, the response text or the error out, so that
// both front-ends answer the same bytes.
#include "request.hpp"

#include <cstdio>
#include <exception>

#include "casteljau/io/commands.hpp"

namespace casteljau::cli {

using casteljau::InvalidArgument;
using casteljau::io::Command;
using casteljau::io::Json;
using casteljau::io::OrderedJson;

namespace {

/// The length of the well-formed UTF-8 sequence starting at s[i] (RFC 3629), or 0.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n;
  unsigned char lo = 0x80, hi = 0xbf;  // range of the second byte
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3;
    if (c == 0xe0) lo = 0xa0;  // no overlong forms
    if (c == 0xed) hi = 0x9f;  // no surrogates
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4;
    if (c == 0xf0) lo = 0x90;
    if (c == 0xf4) hi = 0x8f;  // <= U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (b(i + k) < 0x80 || b(i + k) > 0xbf) return 0;
  }
  return n;
}

}  // namespace

/// The message with control characters and bytes that are not UTF-8 escaped, so that it
/// stays one line of text (user input may appear in it).
std::string one_line(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char ch = s[i];
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x80) {
      if (const std::size_t n = utf8_length(s, i)) {
        out.append(s.substr(i, n));
        i += n - 1;
      } else {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\x%02x", c);
        out += buf;
      }
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out;
}

/// s cut to about `limit` bytes: its start and its end (whole UTF-8 characters) around an
/// ellipsis and the length. The io layer already cuts the user text it quotes; this keeps
/// every message bounded whatever its source (CLI11's messages echo arguments).
std::string clipped(std::string_view s, std::size_t limit) {
  if (s.size() <= limit) return std::string(s);
  const auto continuation = [&](std::size_t i) { return (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80; };
  std::size_t head = limit * 2 / 3, tail = s.size() - limit / 3;
  while (head > 0 && continuation(head)) --head;
  while (tail < s.size() && continuation(tail)) ++tail;
  return std::string(s.substr(0, head)) + "\u2026 (" + std::to_string(s.size()) + " bytes) \u2026" + std::string(s.substr(tail));
}

std::string where_what(const InvalidArgument& e) {
  return clipped(e.where().empty() ? std::string("request") : e.where(), max_where) + ": " + e.problem();
}

/// Runs f, which returns the answer; the library's bad input becomes status 2 with its
/// "<where>: <what>", anything else that escapes status 1 ("internal: ...").
template <class F>
Answer guarded(F&& f) {
  Answer a;
  try {
    return f();
  } catch (const InvalidArgument& e) {
    a.error = where_what(e);
    a.status = exit_bad_input;
  } catch (const std::exception& e) {
    a.error = std::string("internal: ") + e.what();
    a.status = exit_internal;
  }
  return a;
}

Answer answer(const Command& command, std::string_view text, bool jsonl) {
  return guarded([&] {
    Answer a;
    // A blank line is not silently skipped: responses pair with input lines by position.
    if (jsonl && text.find_first_not_of(" \t") == std::string_view::npos) {
      throw InvalidArgument("request", "empty line (every line must hold one JSON request object)");
    }
    const Json request = casteljau::io::parse_json(text);
    const auto response = casteljau::io::run(command, request);
    if (response.is_svg && !jsonl) {
      a.text = response.svg;
      a.is_svg = true;
    } else {
      a.text = response.json.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
    }
    return a;
  });
}

bool command_exists(std::string_view name) { return io::find_command(name) != nullptr; }

namespace {

/// glyph's font on a server: a file name inside the font directory, nothing else (no path,
/// no "..": the request never names a file outside it). Rewrites request's `font` to the
/// file's path.
void serve_glyph_font(Json& request, const std::string& font_dir) {
  if (request.is_object() && request.contains("font") && request["font"].is_string()) {
    const std::string name = request["font"].get<std::string>();
    const bool plain = !name.empty() && name.front() != '.' && name.find_first_of("/\\") == std::string::npos &&
                       name.find('\0') == std::string::npos && name.size() <= 255;
    if (font_dir.empty() || !plain) {
      throw InvalidArgument("font", "the server reads fonts by file name from its font directory (no '/', not starting with '.'): " +
                                        io::quoted(name));
    }
    request["font"] = font_dir + "/" + name;
  }
}

std::string glyph_request(std::string_view body, const std::string& font_dir) {
  Json request = io::parse_json(body);
  serve_glyph_font(request, font_dir);
  return request.dump();
}

/// One line of a batch: {"command": NAME, "request": {...}} answered as `--jsonl` answers
/// a line (render's response as JSON).
Answer answer_batch_line(std::string_view line, const std::string& font_dir) {
  return guarded([&] {
    if (line.find_first_not_of(" \t") == std::string_view::npos) {
      throw InvalidArgument("batch line", "empty line (every line must hold one {\"command\", \"request\"} object)");
    }
    Json item = io::parse_json(line);
    if (!item.is_object()) throw InvalidArgument("batch line", "a batch line must be a JSON object, got " + std::string(io::kind_of(item)));
    for (const auto& [key, value] : item.items()) {
      if (key != "command" && key != "request") {
        throw InvalidArgument(key, "unknown field (a batch line has: command, request)");
      }
    }
    if (!item.contains("command")) throw InvalidArgument("command", "required field is missing");
    if (!item.contains("request")) throw InvalidArgument("request", "required field is missing");
    const std::string name = io::string_from_json(item["command"], "command");
    const Command* command = io::find_command(name);
    if (!command) throw InvalidArgument("command", "unknown command " + io::quoted(name));
    Json& request = item["request"];
    if (name == "glyph") {
      if (font_dir.empty()) {
        throw InvalidArgument("command", "glyph is not served: its font is a file on the server (start the server with --font-dir DIR)");
      }
      serve_glyph_font(request, font_dir);
    }
    const auto response = io::run(*command, request);
    Answer a;
    a.text = response.json.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
    return a;
  });
}

}  // namespace

Answer answer_named(std::string_view name, std::string_view body, const std::string& font_dir) {
  return guarded([&] {
    const Command* command = io::find_command(name);
    if (!command) throw InvalidArgument("command", "unknown command " + io::quoted(name));
    if (name == "glyph") return answer(*command, glyph_request(body, font_dir), false);
    return answer(*command, body, false);
  });
}

std::string answer_batch(std::string_view body, const std::string& font_dir) {
  std::string out;
  std::size_t start = 0;
  while (start < body.size()) {
    std::size_t end = body.find('\n', start);
    if (end == std::string_view::npos) end = body.size();
    std::string_view line = body.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const Answer a = answer_batch_line(line, font_dir);
    out += a.status == exit_ok ? a.text : error_json(a.error);
    start = end + 1;
  }
  return out;
}

std::string api_listing_text(bool with_glyph) {
  OrderedJson listing = io::api_listing();
  if (!with_glyph) {
    auto& list = listing["commands"];
    for (auto it = list.begin(); it != list.end(); ++it) {
      if ((*it)["name"] == "glyph") {
        list.erase(it);
        break;
      }
    }
  }
  return listing.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
}

std::string error_json(std::string_view message) {
  return OrderedJson{{"error", clipped(message, max_message)}}.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
}

std::string quoted_text(std::string_view s) { return io::quoted(s); }

}  // namespace casteljau::cli
