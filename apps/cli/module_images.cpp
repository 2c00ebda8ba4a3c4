// The program's modules (modules.cpp), built first and carried inside the program as bytes
// (.incbin): `casteljau` is one file to run, and a start of any command still maps none of
// their libraries. The paths are the build tree's (apps/cli/CMakeLists.txt); ccache does not
// cache a source with .incbin, so an image is never stale.
#ifndef CASTELJAU_SERVE_IMAGE
#error "CASTELJAU_SERVE_IMAGE and CASTELJAU_FONTS_IMAGE: the modules' paths (apps/cli/CMakeLists.txt)"
#endif

#define CASTELJAU_IMAGE(name, path)                                  \
  ".section .rodata." name ",\"a\"\n"                                \
  ".balign 64\n"                                                     \
  ".global " name "_begin\n.hidden " name "_begin\n" name "_begin:\n" \
  ".incbin \"" path "\"\n"                                           \
  ".global " name "_end\n.hidden " name "_end\n" name "_end:\n"       \
  ".previous\n"

__asm__(CASTELJAU_IMAGE("casteljau_serve_image", CASTELJAU_SERVE_IMAGE));
__asm__(CASTELJAU_IMAGE("casteljau_fonts_image", CASTELJAU_FONTS_IMAGE));
