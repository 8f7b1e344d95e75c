# Run at every build (target aliaslab_version): writes OUT, the header with
# the git revision of SRC and the build type, and touches it only when its
# text changes, so only lib/core/version.cpp recompiles after a commit.
execute_process(COMMAND git -C "${SRC}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE rev OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR rev STREQUAL "")
  set(rev "unknown")
endif()
if(BUILD_TYPE STREQUAL "")
  set(BUILD_TYPE "none")
endif()
set(text "// Generated at build time by cmake/version.cmake.\n#pragma once\n#define ALIASLAB_GIT_REVISION \"${rev}\"\n#define ALIASLAB_BUILD_TYPE \"${BUILD_TYPE}\"\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE "${OUT}" "${text}")
endif()
