# Run after a build by vitrine_gtest_suites (GTestSuites.cmake): lists TEST_EXECUTABLE's suites and
# writes CTEST_FILE, one add_test per suite, each with TEST_ENVIRONMENT (a list of VAR=VALUE) if given.
execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE result
                TIMEOUT 60)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${result}):\n${listing}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(content "")
foreach(line IN LISTS lines)
  # A suite's line starts in the first column and ends its name with a dot ("Suite." or
  # "Prefix/Suite.  # TypeParam = ..."); its cases follow, indented.
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.")
    set(suite "${CMAKE_MATCH_1}")
    string(APPEND content "add_test([=[${suite}]=] [=[${TEST_EXECUTABLE}]=] [=[--gtest_filter=${suite}.*]=])\n")
    if(TEST_ENVIRONMENT)
      string(APPEND content "set_tests_properties([=[${suite}]=] PROPERTIES ENVIRONMENT [=[${TEST_ENVIRONMENT}]=])\n")
    endif()
  endif()
endforeach()
file(WRITE "${CTEST_FILE}" "${content}")
