// The program's two modules, loaded when a command needs them, so that every other
// command starts without their shared libraries (the command-line tests start the program
// thousands of times):
// - casteljau-serve.so (serve.cpp and cpp-httplib, with OpenSSL, zlib and Brotli: about
//   9 ms of CPU of a 23 ms start at load 10, session 12), for `casteljau serve`;
// - casteljau-fonts.so (src/io/glyph.cpp with FreeType and HarfBuzz, and through them
//   libpng, Brotli, glib and graphite2: about 8 ms of CPU of a 15 ms start, session 13),
//   for `casteljau glyph`. This file defines io::glyph_outlines for the program, so the
//   linker never takes the library's own definition (and FreeType) from casteljau_io.
// Each is looked for beside the program (the build tree), then at its installed place
// relative to the program (CASTELJAU_MODULE_DIR).
#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <optional>
#include <stdexcept>
#include <string>

#include "casteljau/io/glyph.hpp"
#include "serve.hpp"

#ifndef CASTELJAU_MODULE_DIR
#error "CASTELJAU_MODULE_DIR: the modules' installed folder relative to the program's folder (apps/cli/CMakeLists.txt)"
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

/// The entry point `entry` of the module `file` (loaded once; dlopen counts references).
/// Throws std::runtime_error naming the places tried, or the loader's message.
void* module_entry(const std::string& file, const char* entry, const char* what) {
  const std::string folder = program_folder();
  std::string tried;
  for (const std::string candidate : {folder + file, folder + CASTELJAU_MODULE_DIR + file}) {
    if (access(candidate.c_str(), F_OK) != 0) {
      tried += (tried.empty() ? "" : ", ") + candidate;
      continue;
    }
    void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) throw std::runtime_error(std::string("cannot load the ") + what + " module " + candidate + ": " + dlerror());
    void* function = dlsym(module, entry);
    if (!function) throw std::runtime_error(std::string("the ") + what + " module " + candidate + " has no entry point " + entry);
    return function;
  }
  throw std::runtime_error(std::string("the ") + what + " module " + file + " is missing (looked for " + tried + ")");
}

}  // namespace

int serve_through_module(const ServeOptions& options) {
  using Entry = int (*)(const ServeOptions&);
  return reinterpret_cast<Entry>(module_entry("casteljau-serve.so", "casteljau_serve_module", "server"))(options);
}

}  // namespace casteljau::cli

namespace casteljau::io {

GlyphRun glyph_outlines(const std::string& font_path, const std::string& text, std::optional<double> size) {
  using Entry = void (*)(const std::string&, const std::string&, std::optional<double>, GlyphRun&);
  static const Entry entry =
      reinterpret_cast<Entry>(cli::module_entry("casteljau-fonts.so", "casteljau_fonts_module", "fonts"));
  GlyphRun run;
  entry(font_path, text, size, run);
  return run;
}

}  // namespace casteljau::io
