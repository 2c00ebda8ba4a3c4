// Small text helpers for messages, shared by the io sources (internal: not installed).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace casteljau::io::detail {

/// "where[i]": the path of element i of an array field.
inline std::string index_path(std::string_view where, std::size_t i) { return std::string(where) + "[" + std::to_string(i) + "]"; }

/// The names separated by ", ", for "(known: a, b, c)" lists.
template <class Names>
std::string join(const Names& names) {
  std::string s;
  for (auto n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

}  // namespace casteljau::io::detail
