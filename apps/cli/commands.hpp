// The commands of the `casteljau` program: their descriptions, and request -> response.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "casteljau/io/json.hpp"

namespace casteljau::cli {

/// One command of shared/spec/cli.md.
struct Command {
  std::string_view name;
  std::string_view summary;  ///< one line, for `casteljau --help`
  std::string_view details;  ///< request, response and an example, for `casteljau NAME --help`
  bool supported;            ///< false: the spec defines it, this build does not run it yet
};

/// Every command of the spec, supported ones first.
std::span<const Command> commands();

/// The command called name, or nullptr.
const Command* find_command(std::string_view name);

/// What a command answers: a JSON object, or for `render` an SVG document.
struct Response {
  io::OrderedJson json;
  std::string svg;
  bool is_svg = false;
};

/// Runs a supported command on one parsed request. Bad input throws InvalidArgument whose
/// where() is a path in the request ("curve.points[2][1]", "t[3]", "" for the request
/// itself). Anything else that escapes is an internal error.
Response run(const Command& command, const io::Json& request);

}  // namespace casteljau::cli
