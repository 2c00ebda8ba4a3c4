// The fonts module (casteljau-fonts.so): src/io/glyph.cpp with FreeType and HarfBuzz,
// loaded by the program when `casteljau glyph` runs (modules.cpp). Linked with
// -Bsymbolic: the call below reaches this module's glyph_outlines, never the program's.
#include <optional>
#include <string>

#include "casteljau/io/glyph.hpp"

/// The module's entry point (modules.cpp finds it by this unmangled name). The result is
/// written to `out` (a C linkage function does not return a C++ class); errors propagate
/// as the library's exceptions (one libstdc++ for the program and its modules).
extern "C" [[gnu::visibility("default")]] void casteljau_fonts_module(const std::string& font_path, const std::string& text,
                                                                     std::optional<double> size,
                                                                     casteljau::io::GlyphRun& out) {
  out = casteljau::io::glyph_outlines(font_path, text, size);
}
