// The request handling shared by the command line (main.cpp) and the server (serve.cpp):
// both answer a request through answer(), so the same request gets the same bytes from
// either. Light on purpose: serve.cpp includes it and not the io headers (request.cpp and
// main.cpp, which do, compile as one unit: apps/cli/CMakeLists.txt).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace casteljau {
class InvalidArgument;
namespace io {
struct Command;
}
}  // namespace casteljau

namespace casteljau::cli {

constexpr int exit_ok = 0;
constexpr int exit_internal = 1;
constexpr int exit_bad_input = 2;

/// Longest `<where>` and whole message written (bytes): far above any message the program
/// composes, far below what hostile input could make of one.
constexpr std::size_t max_where = 300;
constexpr std::size_t max_message = 800;

/// The message with control characters and bytes that are not UTF-8 escaped, so that it
/// stays one line of text (user input may appear in it).
[[nodiscard]] std::string one_line(std::string_view s);

/// s cut to about `limit` bytes: its start and its end (whole UTF-8 characters) around an
/// ellipsis and the length. The io layer already cuts the user text it quotes; this keeps
/// every message bounded whatever its source (CLI11's messages echo arguments).
[[nodiscard]] std::string clipped(std::string_view s, std::size_t limit);

/// "<where>: <what>" of a bad-input error ("request" when it has no place).
[[nodiscard]] std::string where_what(const InvalidArgument& e);

/// The outcome of one request: the text to write, or an error.
struct Answer {
  std::string text;   ///< response (JSON line or SVG), on success
  std::string error;  ///< "<where>: <what>", on failure
  int status = exit_ok;
  bool is_svg = false;  ///< text is an SVG document (render, outside --jsonl)
};

/// Parses the request text and runs the command: the response as the command line writes
/// it (JSON and a newline, or render's SVG document unless jsonl), or the error with
/// exit_bad_input (InvalidArgument) or exit_internal (anything else).
[[nodiscard]] Answer answer(const io::Command& command, std::string_view text, bool jsonl);

// For the server.

/// Whether a command of that name exists.
[[nodiscard]] bool command_exists(std::string_view name);

/// The request answered by the command called name, as answer() does outside --jsonl; for
/// glyph, `font` must be a file name inside font_dir (no '/', not starting with '.'), read
/// there. Never throws: every failure is in the Answer.
[[nodiscard]] Answer answer_named(std::string_view name, std::string_view body, const std::string& font_dir);

/// The server's batch (`POST /batch`): one line {"command": NAME, "request": {...}} per
/// request, answered by one line each, in order: the response as `casteljau NAME --jsonl`
/// writes it, or {"error": "<where>: <what>"} (a bad line does not stop the others). glyph
/// as answer_named serves it (refused when font_dir is empty). Never throws.
[[nodiscard]] std::string answer_batch(std::string_view body, const std::string& font_dir);

/// The `GET /api` listing as JSON text (and a newline), without glyph unless with_glyph.
[[nodiscard]] std::string api_listing_text(bool with_glyph);

/// {"error": message} as JSON text and a newline.
[[nodiscard]] std::string error_json(std::string_view message);

/// s between quotes as messages quote user text (io::quoted).
[[nodiscard]] std::string quoted_text(std::string_view s);

}  // namespace casteljau::cli
