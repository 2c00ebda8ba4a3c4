// Loads the server module (casteljau-serve.so: serve.cpp and cpp-httplib) when
// `casteljau serve` runs. Linked into the program directly, cpp-httplib brings OpenSSL,
// zlib and Brotli into every process start: about 9 ms of CPU each at load 10, half of a
// start of `casteljau eval` (measured in session 12), and the command-line tests start the
// program thousands of times.
#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <stdexcept>
#include <string>

#include "serve.hpp"

#ifndef CASTELJAU_SERVE_MODULE
#error "CASTELJAU_SERVE_MODULE: the module's installed path relative to the program's folder (apps/cli/CMakeLists.txt)"
#endif

namespace casteljau::cli {

namespace {

/// The folder of the running program (/proc/self/exe), with a trailing '/'.
std::string program_folder() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) throw std::runtime_error("cannot find the program's own path (/proc/self/exe)");
  std::string path(buf, static_cast<std::size_t>(n));
  return path.substr(0, path.rfind('/') + 1);
}

}  // namespace

int serve_through_module(const ServeOptions& options) {
  const std::string folder = program_folder();
  std::string tried;
  for (const std::string candidate : {folder + "casteljau-serve.so", folder + CASTELJAU_SERVE_MODULE}) {
    if (access(candidate.c_str(), F_OK) != 0) {
      tried += (tried.empty() ? "" : ", ") + candidate;
      continue;
    }
    void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) throw std::runtime_error("cannot load the server module " + candidate + ": " + dlerror());
    using Entry = int (*)(const ServeOptions&);
    auto entry = reinterpret_cast<Entry>(dlsym(module, "casteljau_serve_module"));
    if (!entry) throw std::runtime_error("the server module " + candidate + " has no entry point");
    return entry(options);
  }
  throw std::runtime_error("the server module casteljau-serve.so is missing (looked for " + tried + ")");
}

}  // namespace casteljau::cli
