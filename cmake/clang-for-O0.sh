#!/bin/sh
# The compiler launcher of the test targets built at -O0 (cmake/ClangForO0.cmake): CMake
# calls it as `clang-for-O0.sh <the project's C++ compiler> <arguments>`; it compiles with
# clang++ instead, with the same arguments. Flags that only g++ knows (-Wno-restrict) are
# accepted silently.
shift
exec clang++ -Wno-unknown-warning-option "$@"
