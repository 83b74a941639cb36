# One ctest test per GoogleTest suite (`Suite.*` in one process) instead of one per case, for binaries
# whose cases take milliseconds but whose process takes a good part of a second to start (the core
# library's image and video dependencies are ~260 shared libraries to load and relocate): 508 unit cases
# as 508 processes were ~300 s of CPU on the 2-core CI machine; as their 145 suites, ~90 s. A failing
# case is named in the test's output (ctest --output-on-failure). The suites are listed from the binary
# after each build, as gtest_discover_tests lists cases. ENVIRONMENT VAR=VALUE... is set for each suite.
function(vitrine_gtest_suites target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "ENVIRONMENT")
  set(base "${CMAKE_CURRENT_BINARY_DIR}/${target}_suites")
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -D "TEST_EXECUTABLE=$<TARGET_FILE:${target}>" -D "CTEST_FILE=${base}.cmake"
            -D "TEST_ENVIRONMENT=${arg_ENVIRONMENT}" -P "${CMAKE_SOURCE_DIR}/cmake/gtest_suites_script.cmake"
    BYPRODUCTS "${base}.cmake" VERBATIM)
  file(WRITE "${base}_include.cmake"
       "if(EXISTS \"${base}.cmake\")\n  include(\"${base}.cmake\")\nelse()\n"
       "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${base}_include.cmake")
endfunction()
