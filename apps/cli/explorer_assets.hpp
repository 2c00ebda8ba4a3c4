// The explorer page's files (apps/explorer), embedded in the program at build time
// (apps/explorer/embed.cmake writes their definition): the server reads no file.
#pragma once

#include <span>
#include <string_view>

namespace casteljau::cli {

struct Asset {
  std::string_view path;  ///< file name under apps/explorer ("index.html" is served at /)
  std::string_view type;  ///< its media type
  std::string_view body;
};

[[nodiscard]] std::span<const Asset> explorer_assets();

}  // namespace casteljau::cli
