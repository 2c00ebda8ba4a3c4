# casteljau_gtest_suites(TARGET LABELS ... TIMEOUT seconds): one ctest test per GoogleTest
# suite of TARGET (ctest name = the suite's name, run with --gtest_filter=SUITE.*), listed
# when ctest starts, as gtest_discover_tests(... DISCOVERY_MODE PRE_TEST) does per test.
# A suite is the unit of a process: with about 85 suites instead of 526 tests, ctest starts
# 441 fewer processes of a large test executable (about 16 s of CPU in make test).
set(_casteljau_gtest_suites_script "${CMAKE_CURRENT_LIST_DIR}/gtest_suites_list.cmake")

function(casteljau_gtest_suites target)
  cmake_parse_arguments(ARG "" "TIMEOUT" "LABELS" ${ARGN})
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake")
  file(GENERATE OUTPUT "${include_file}" CONTENT
       "set(exe \"$<TARGET_FILE:${target}>\")\nset(labels \"${ARG_LABELS}\")\nset(timeout \"${ARG_TIMEOUT}\")\n\
set(target \"${target}\")\ninclude(\"${_casteljau_gtest_suites_script}\")\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
