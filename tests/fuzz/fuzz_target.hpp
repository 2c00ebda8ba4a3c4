// A fuzz target: one reader of outside bytes (the JSON request reader today; SVG path data
// and HTTP requests as they arrive), written once as
//
//   CASTELJAU_FUZZ_TARGET(request) { ... input ... mode ... return 0; }
//
// and built two ways (tests/fuzz/CMakeLists.txt, casteljau_fuzz_target()): for libFuzzer
// (`make fuzz`, executable casteljau_fuzz_NAME, the macro defines LLVMFuzzerTestOneInput)
// and into casteljau_fuzz_replay, which replays tests/fuzz/corpus/NAME/ in every build
// (CASTELJAU_FUZZ_REPLAY: the macro registers the target under its name).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace casteljau::fuzz {

/// How the target is run: by libFuzzer (each input on the narrowest path it names, as many
/// inputs a second as possible) or by the corpus replay (each regression input on every
/// path it applies to).
enum class Mode { fuzz, replay };

using Entry = int (*)(std::span<const std::uint8_t> input, Mode mode);

struct Target {
  std::string_view name;
  Entry run;
};

/// The targets built into the replay (defined in replay_main.cpp).
std::vector<Target>& targets();

struct Registrar {
  Registrar(std::string_view name, Entry run) { targets().push_back({name, run}); }
};

}  // namespace casteljau::fuzz

#ifdef CASTELJAU_FUZZ_REPLAY
#define CASTELJAU_FUZZ_TARGET(name)                                                                 \
  static int casteljau_fuzz_##name(std::span<const std::uint8_t> input, casteljau::fuzz::Mode mode); \
  static const casteljau::fuzz::Registrar casteljau_fuzz_registrar_##name(#name, casteljau_fuzz_##name); \
  static int casteljau_fuzz_##name(std::span<const std::uint8_t> input, casteljau::fuzz::Mode mode)
#else
#define CASTELJAU_FUZZ_TARGET(name)                                                                 \
  static int casteljau_fuzz_##name(std::span<const std::uint8_t> input, casteljau::fuzz::Mode mode); \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {               \
    return casteljau_fuzz_##name(std::span<const std::uint8_t>(data, size), casteljau::fuzz::Mode::fuzz); \
  }                                                                                                 \
  static int casteljau_fuzz_##name(std::span<const std::uint8_t> input, casteljau::fuzz::Mode mode)
#endif
