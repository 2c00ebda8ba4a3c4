# casteljau_clang_for_O0(target...): compiles the targets' sources with clang++ when the
# project's compiler is g++ (through cmake/clang-for-O0.sh as their compiler launcher).
#
# Why: the test sources built at -O0 (the batched unit and property tests, the SVG tests,
# the examples) spend their time instantiating templates, and clang 14 does that at -O0 in
# about 40% less CPU time than g++ 12 (the batched unit tests: 61 s against 99 s of CPU;
# docs/testing.md). At -O1 and above the two take about the same time, so the library,
# the program and the densely sampling tests stay with g++. Both compilers use libstdc++
# and the Itanium C++ ABI, so the objects link together; the sanitizer build compiles
# every test with clang anyway.
find_program(CASTELJAU_CLANGXX clang++)
function(casteljau_clang_for_O0)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CASTELJAU_CLANGXX)
    foreach(target ${ARGN})
      set_target_properties(${target} PROPERTIES CXX_COMPILER_LAUNCHER ${PROJECT_SOURCE_DIR}/cmake/clang-for-O0.sh)
    endforeach()
  endif()
endfunction()
