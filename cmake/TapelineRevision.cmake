# Writes tapeline_build_info.h with the project version, the git revision (refreshed at every build,
# rewritten only when it changes) and the compiler flags, so that every benchmark line and
# `tapeline --version` can say what produced them.
set(TAPELINE_BUILD_INFO_DIR ${CMAKE_BINARY_DIR}/generated)
string(TOUPPER "${CMAKE_BUILD_TYPE}" _tapeline_bt)
set(TAPELINE_COMPILER_FLAGS
    "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_tapeline_bt}}")
string(STRIP "${TAPELINE_COMPILER_FLAGS}" TAPELINE_COMPILER_FLAGS)
add_custom_target(tapeline_build_info
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUT_DIR=${TAPELINE_BUILD_INFO_DIR}
          "-DFLAGS=${TAPELINE_COMPILER_FLAGS}" -DVERSION=${PROJECT_VERSION} -P ${CMAKE_SOURCE_DIR}/cmake/write_build_info.cmake
  BYPRODUCTS ${TAPELINE_BUILD_INFO_DIR}/tapeline_build_info.h
  COMMENT "Recording git revision")
