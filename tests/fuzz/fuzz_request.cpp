// Fuzz target `request`: the JSON request reader and the command that reads the request.
// An input is
//
//   COMMAND '\n' REQUEST
//
// where COMMAND is a command's name in the registry (io/commands.hpp: "eval", "render", ...)
// and REQUEST its JSON request, as `echo REQUEST | casteljau COMMAND` would get them: the
// input chooses one command by name (the mapping cannot shift as commands are added), and
// libFuzzer's dictionary (tests/fuzz/request.dict) holds every command's "COMMAND\n".
// Under libFuzzer an input without such a first line is parsed as a request and goes no
// further (the reader alone). The corpus replay (Mode::replay) gives every input, its
// first line stripped when it names a command, to every command: a regression input keeps
// reaching the commands it reached when it was found, and a request from anywhere (a bug
// report) is a corpus file as it is.
//
// Bad input must end as InvalidArgument (or NumericalError for a tolerance below the
// coordinates' resolution); any other exception, a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

#include "casteljau/core/error.hpp"
#include "casteljau/io/commands.hpp"
#include "fuzz_target.hpp"

namespace {

void run_command(const casteljau::io::Command& command, const casteljau::io::Json& request) {
  try {
    (void)casteljau::io::run(command, request);
  } catch (const casteljau::InvalidArgument&) {
  } catch (const casteljau::NumericalError&) {
  }
}

}  // namespace

CASTELJAU_FUZZ_TARGET(request) {
  std::string_view text(reinterpret_cast<const char*>(input.data()), input.size());
  const casteljau::io::Command* command = nullptr;
  if (const auto newline = text.find('\n'); newline != std::string_view::npos) {
    command = casteljau::io::find_command(text.substr(0, newline));
    if (command != nullptr) text.remove_prefix(newline + 1);
  }
  casteljau::io::Json request;
  try {
    request = casteljau::io::parse_json(text);
  } catch (const casteljau::InvalidArgument&) {
    return 0;
  }
  if (mode == casteljau::fuzz::Mode::replay) {
    for (const auto& c : casteljau::io::commands()) run_command(c, request);
  } else if (command != nullptr) {
    run_command(*command, request);
  }
  return 0;
}

#ifdef CASTELJAU_FUZZ_REPLAY
// The request target's seeds and dictionary against the registry (ctest fuzz_request_seeds):
// every command has a seed input in the corpus, and the dictionary has every command's
// first line and every name a request can hold (field names, string choices, curve types),
// so neither goes stale as commands and fields are added.
namespace casteljau::fuzz {

namespace {

// The values of a libFuzzer dictionary: lines [name=]"value" with \\, \" and \xNN escapes;
// # comments and blank lines skipped.
std::set<std::string> dictionary_values(const std::filesystem::path& path) {
  std::set<std::string> values;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto open = line.find('"');
    if (line.empty() || line[0] == '#' || open == std::string::npos) continue;
    std::string value;
    for (std::size_t i = open + 1; i < line.size() && line[i] != '"'; ++i) {
      if (line[i] == '\\' && i + 1 < line.size()) {
        ++i;
        if (line[i] == 'x' && i + 2 < line.size()) {
          value += static_cast<char>(std::stoi(line.substr(i + 1, 2), nullptr, 16));
          i += 2;
          continue;
        }
      }
      value += line[i];
    }
    values.insert(value);
  }
  return values;
}

}  // namespace

int check_request_seeds(const std::filesystem::path& dictionary, const std::filesystem::path& corpus) {
  const auto values = dictionary_values(dictionary);
  std::set<std::string> missing;
  auto need = [&](std::string value) {
    if (!values.contains(value)) missing.insert(std::move(value));
  };
  auto quoted = [](std::string_view s) { return "\"" + std::string(s) + "\""; };
  std::set<std::string> seeded;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::string first;
    std::getline(in, first);
    seeded.insert(first);
  }
  int failures = 0;
  for (const auto& command : io::commands()) {
    need(std::string(command.name) + "\n");
    for (const auto& field : command.fields) {
      need(quoted(field.name));
      for (const auto& choice : field.choices) need(quoted(choice));
    }
    if (!seeded.contains(std::string(command.name))) {
      std::fprintf(stderr, "%s: no seed input for command %.*s (a file starting \"%.*s\\n\")\n", corpus.c_str(),
                   static_cast<int>(command.name.size()), command.name.data(), static_cast<int>(command.name.size()),
                   command.name.data());
      ++failures;
    }
  }
  for (const auto& type : io::curve_type_names()) need(quoted(type));
  for (const auto& value : missing) {
    std::string escaped;
    for (const char c : value) escaped += c == '\n' ? std::string("\\x0a") : c == '"' ? std::string("\\\"") : std::string(1, c);
    std::fprintf(stderr, "%s: missing \"%s\"\n", dictionary.c_str(), escaped.c_str());
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace casteljau::fuzz
#endif
