// Fuzz target for the command line's request handling: any bytes are parsed as a JSON
// request and given to every command of the registry (io/commands.hpp). Bad input must end as InvalidArgument
// (or NumericalError for a tolerance below the coordinates' resolution); any other
// exception, a crash or a sanitizer report is a bug. Built for libFuzzer by `make fuzz`
// (clang), and replayed over tests/fuzz/corpus by ctest with replay_main.cpp.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "casteljau/core/error.hpp"
#include "casteljau/io/commands.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  casteljau::io::Json request;
  try {
    request = casteljau::io::parse_json(text);
  } catch (const casteljau::InvalidArgument&) {
    return 0;
  }
  for (const auto& command : casteljau::io::commands()) {
    try {
      (void)casteljau::io::run(command, request);
    } catch (const casteljau::InvalidArgument&) {
    } catch (const casteljau::NumericalError&) {
    }
  }
  return 0;
}
