// Replays the fuzz targets' corpora without libFuzzer, so that every build, the sanitizer
// build included, runs every regression input (ctest fuzz_corpus_replay).
//
//   casteljau_fuzz_replay CORPUS_ROOT
//       gives each file of CORPUS_ROOT/NAME/ to the target NAME (fuzz_target.hpp), in
//       Mode::replay; every target needs its directory and every directory its target.
//   casteljau_fuzz_replay NAME FILE|DIR...
//       gives the files (a crash libFuzzer wrote, say) to the target NAME.
//   casteljau_fuzz_replay --check-request-seeds DICTIONARY CORPUS_DIR
//       the request target's dictionary and seeds against the command registry
//       (fuzz_request.cpp).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_target.hpp"

namespace casteljau::fuzz {

std::vector<Target>& targets() {
  static std::vector<Target> all;
  return all;
}

int check_request_seeds(const std::filesystem::path& dictionary, const std::filesystem::path& corpus);

}  // namespace casteljau::fuzz

namespace {

namespace fs = std::filesystem;
using casteljau::fuzz::Target;

const Target* find_target(std::string_view name) {
  for (const auto& t : casteljau::fuzz::targets())
    if (t.name == name) return &t;
  return nullptr;
}

// The files named (a directory: its regular files), in a stable order.
std::vector<fs::path> files_of(const std::vector<fs::path>& paths) {
  std::vector<fs::path> files;
  for (const auto& p : paths) {
    if (fs::is_directory(p)) {
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::size_t replay(const Target& target, const std::vector<fs::path>& files) {
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    target.run(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
               casteljau::fuzz::Mode::replay);
  }
  return files.size();
}

int usage() {
  std::fprintf(stderr,
               "usage: casteljau_fuzz_replay [--elsewhere=NAME]... CORPUS_ROOT | NAME FILE|DIR... | "
               "--check-request-seeds DICTIONARY CORPUS_DIR\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  // --elsewhere=NAME (repeatable): a corpus directory of a target that this program does not
  // hold and that another test replays (corpus/http: the server's test sends it to the server).
  std::vector<std::string> elsewhere;
  while (!args.empty() && args[0].starts_with("--elsewhere=")) {
    elsewhere.push_back(args[0].substr(std::string_view("--elsewhere=").size()));
    args.erase(args.begin());
  }
  if (args.size() == 3 && args[0] == "--check-request-seeds")
    return casteljau::fuzz::check_request_seeds(args[1], args[2]);
  if (args.size() >= 2) {
    const Target* target = find_target(args[0]);
    if (target == nullptr) {
      std::fprintf(stderr, "casteljau_fuzz_replay: no fuzz target '%s'\n", args[0].c_str());
      return 2;
    }
    const auto files = files_of(std::vector<fs::path>(args.begin() + 1, args.end()));
    std::printf("%.*s: replayed %zu inputs\n", static_cast<int>(target->name.size()), target->name.data(),
                replay(*target, files));
    return 0;
  }
  if (args.size() != 1 || !fs::is_directory(args[0])) return usage();
  int failures = 0;
  for (const auto& e : fs::directory_iterator(args[0])) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && find_target(name) == nullptr && std::ranges::find(elsewhere, name) == elsewhere.end()) {
      std::fprintf(stderr, "casteljau_fuzz_replay: %s names no fuzz target\n", e.path().c_str());
      ++failures;
    }
  }
  for (const auto& target : casteljau::fuzz::targets()) {
    const auto dir = fs::path(args[0]) / target.name;
    const auto files = fs::is_directory(dir) ? files_of({dir}) : std::vector<fs::path>{};
    if (files.empty()) {
      std::fprintf(stderr, "casteljau_fuzz_replay: no corpus for target %.*s\n", static_cast<int>(target.name.size()),
                   target.name.data());
      ++failures;
      continue;
    }
    std::printf("%.*s: replayed %zu inputs\n", static_cast<int>(target.name.size()), target.name.data(),
                replay(target, files));
  }
  return failures == 0 ? 0 : 1;
}
