# The build's identity for `vitrine --version`: the project's version and the commit the sources are at,
# written into a source file on every build (by cmake/build_info_script.cmake) and rewritten only when
# it changed, so an unchanged commit relinks nothing.
set(VITRINE_BUILD_INFO_CPP ${CMAKE_BINARY_DIR}/generated/build_info.cpp)
add_custom_target(vitrine_build_info
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${VITRINE_BUILD_INFO_CPP}
          -DVERSION=${PROJECT_VERSION} -P ${CMAKE_SOURCE_DIR}/cmake/build_info_script.cmake
  BYPRODUCTS ${VITRINE_BUILD_INFO_CPP}
  COMMENT "The commit the build is made from"
  VERBATIM)
# Compiled on its own, not in a unity batch with main.cpp, so a commit recompiles this one file.
set_source_files_properties(${VITRINE_BUILD_INFO_CPP} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
