# No compiler- or instruction-set-specific code in the public headers (issue 15): every
# file under INCLUDE_DIR is scanned for GCC/Clang extensions (__attribute__, __builtin_*,
# vector_size, #pragma GCC / clang) and intrinsics headers (<immintrin.h> and the other
# <*intrin.h>, <arm_neon.h>); such code belongs in src/ (compiled once per instruction set
# and chosen at run time, docs/decisions/0004, 0006). A user's translation unit that
# includes casteljau.hpp then sees portable C++ only.
# usage: cmake -DINCLUDE_DIR=<dir> -P portable.cmake
if(NOT INCLUDE_DIR)
  message(FATAL_ERROR "portable.cmake: pass -DINCLUDE_DIR=<dir>")
endif()
file(GLOB_RECURSE _files LIST_DIRECTORIES false "${INCLUDE_DIR}/*")
list(LENGTH _files _count)
if(_count EQUAL 0)
  message(FATAL_ERROR "portable.cmake: no files under ${INCLUDE_DIR}")
endif()
set(_pattern "__attribute__|__builtin_|vector_size|#[ \t]*pragma[ \t]+(GCC|clang)|[a-z0-9_]*intrin\\.h|arm_neon\\.h|arm_sve\\.h")
set(_found 0)
foreach(_f IN LISTS _files)
  file(STRINGS "${_f}" _lines REGEX "${_pattern}")
  foreach(_line IN LISTS _lines)
    file(RELATIVE_PATH _rel "${INCLUDE_DIR}" "${_f}")
    string(STRIP "${_line}" _line)
    message("${_rel}: ${_line}")
    math(EXPR _found "${_found} + 1")
  endforeach()
endforeach()
if(_found GREATER 0)
  message(FATAL_ERROR "${_found} line(s) of compiler- or instruction-set-specific code in public headers: move it to src/ "
                      "(docs/testing.md, \"Portable public headers\")")
endif()
message(STATUS "${_count} files under ${INCLUDE_DIR}: no compiler- or instruction-set-specific code")

# The umbrella header reaches every public header but io/'s (the compiled casteljau::io's
# interface, included one by one): the #include "casteljau/..." lines followed from
# casteljau/casteljau.hpp (issue 15: intersect was not reachable from it). A text scan too.
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST) in script mode
set(_reached "casteljau/casteljau.hpp")
set(_queue "casteljau/casteljau.hpp")
while(_queue)
  list(POP_FRONT _queue _h)
  file(STRINGS "${INCLUDE_DIR}/${_h}" _includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"casteljau/")
  foreach(_line IN LISTS _includes)
    string(REGEX REPLACE ".*\"(casteljau/[^\"]+)\".*" "\\1" _inc "${_line}")
    if(NOT _inc IN_LIST _reached AND EXISTS "${INCLUDE_DIR}/${_inc}")
      list(APPEND _reached "${_inc}")
      list(APPEND _queue "${_inc}")
    endif()
  endforeach()
endwhile()
file(GLOB_RECURSE _headers RELATIVE "${INCLUDE_DIR}" "${INCLUDE_DIR}/casteljau/*.hpp")
list(FILTER _headers EXCLUDE REGEX "^casteljau/io/")
set(_missing)
foreach(_h IN LISTS _headers)
  if(NOT _h IN_LIST _reached)
    list(APPEND _missing "${_h}")
  endif()
endforeach()
if(_missing)
  list(JOIN _missing "\n  " _missing)
  message(FATAL_ERROR "casteljau/casteljau.hpp does not reach:\n  ${_missing}")
endif()
list(LENGTH _headers _count)
message(STATUS "casteljau/casteljau.hpp reaches the ${_count} headers outside io/ (itself among them)")
