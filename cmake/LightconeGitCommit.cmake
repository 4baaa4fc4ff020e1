# SPDX-License-Identifier: BSD-3-Clause
# Run at every build (the root CMakeLists' lightcone_git_commit target): writes OUTPUT with the
# commit HEAD names now, only when it changed, so `lightcone --version` and every output's
# provenance name the commit the programs were built from, not the one the build was configured
# from. "unknown" outside git (a source tarball).
#   cmake -DSOURCE_DIR=... -DOUTPUT=.../lightcone_git_commit.hpp -P LightconeGitCommit.cmake
execute_process(COMMAND git rev-parse --short HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
endif()
set(text "// Written at build time by cmake/LightconeGitCommit.cmake: the commit of the sources built.\n#pragma once\n#define LIGHTCONE_GIT_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
