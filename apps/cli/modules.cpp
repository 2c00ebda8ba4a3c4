// The program's two modules, loaded when a command needs them, so that every other
// command starts without their shared libraries (the command-line tests start the program
// thousands of times):
// - casteljau-serve.so (serve.cpp and cpp-httplib, with OpenSSL, zlib and Brotli: about
//   9 ms of CPU of a 23 ms start at load 10, session 12), for `casteljau serve`;
// - casteljau-fonts.so (src/io/glyph.cpp with FreeType and HarfBuzz, and through them
//   libpng, Brotli, glib and graphite2: about 8 ms of CPU of a 15 ms start, session 13),
//   for `casteljau glyph`. This file defines io::glyph_outlines for the program, so the
//   linker never takes the library's own definition (and FreeType) from casteljau_io.
// Both are inside the program (module_images.cpp): a module is copied to an anonymous
// memory file (memfd_create) and loaded from there, so the program is one file to run.
#include <dlfcn.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include "casteljau/io/glyph.hpp"
#include "serve.hpp"

extern "C" {
extern const unsigned char casteljau_serve_image_begin[], casteljau_serve_image_end[];
extern const unsigned char casteljau_fonts_image_begin[], casteljau_fonts_image_end[];
}

namespace casteljau::cli {

namespace {

/// The entry point `entry` of the module whose image is [begin, end), loaded by each call
/// (serve once per process; glyph_outlines keeps the pointer). Throws std::runtime_error with the system's or
/// the loader's message.
void* module_entry(const char* name, const unsigned char* begin, const unsigned char* end, const char* entry) {
  const int fd = memfd_create(name, MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::string("cannot create a memory file for ") + name + ": " + std::strerror(errno));
  for (const unsigned char* p = begin; p < end;) {
    const ssize_t n = write(fd, p, static_cast<std::size_t>(end - p));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(errno);
      close(fd);
      throw std::runtime_error(std::string("cannot write ") + name + " to a memory file: " + why);
    }
    p += n;
  }
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  close(fd);  // the loader keeps its own mapping
  if (!module) throw std::runtime_error(std::string("cannot load ") + name + ": " + dlerror());
  void* function = dlsym(module, entry);
  if (!function) throw std::runtime_error(std::string(name) + " has no entry point " + entry);
  return function;
}

}  // namespace

int serve_through_module(const ServeOptions& options) {
  using Entry = int (*)(const ServeOptions&);
  return reinterpret_cast<Entry>(module_entry("casteljau-serve.so", casteljau_serve_image_begin, casteljau_serve_image_end,
                                              "casteljau_serve_module"))(options);
}

}  // namespace casteljau::cli

namespace casteljau::io {

GlyphRun glyph_outlines(const std::string& font_path, const std::string& text, std::optional<double> size) {
  using Entry = void (*)(const std::string&, const std::string&, std::optional<double>, GlyphRun&);
  static const Entry entry =
      reinterpret_cast<Entry>(cli::module_entry("casteljau-fonts.so", casteljau_fonts_image_begin, casteljau_fonts_image_end,
                                                "casteljau_fonts_module"));
  GlyphRun run;
  entry(font_path, text, size, run);
  return run;
}

}  // namespace casteljau::io
