# Run by ctest (see GTestSuites.cmake) with exe, target, labels and timeout set: lists the
# executable's suites and adds one test per suite.
if(NOT EXISTS "${exe}")
  add_test("${target}_NOT_BUILT" "${exe}")
  return()
endif()
execute_process(COMMAND "${exe}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE rc
                TIMEOUT 120)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${exe} --gtest_list_tests failed (${rc}):\n${listing}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  # "Suite." or "Prefix/Suite/0.  # TypeParam = ..." start a suite; test names are indented.
  if(line MATCHES "^([^ #][^ ]*)\\.")
    set(suite "${CMAKE_MATCH_1}")
    add_test("${suite}" "${exe}" "--gtest_filter=${suite}.*")
    set_tests_properties("${suite}" PROPERTIES LABELS "${labels}" TIMEOUT "${timeout}")
  endif()
endforeach()
