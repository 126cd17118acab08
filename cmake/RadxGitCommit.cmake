# Script mode (cmake -DSOURCE_DIR=... -DOUTPUT=... -P RadxGitCommit.cmake), run at every build by the target
# radx_commit (apps/CMakeLists.txt): writes OUTPUT, the C++ source of radx::app::build_commit(), which
# returns the commit the sources are at:
#   the short hash of HEAD ("abc1234"), with "-dirty" when a tracked file differs from HEAD (untracked files
#   do not count, as for git describe --dirty);
#   "unknown" when SOURCE_DIR is not the top of a git work tree (a source tarball, even one unpacked inside
#   another repository) or git cannot be run.
# OUTPUT is rewritten only when its text changes, so a build at the same commit compiles and links nothing
# more, and a new HEAD (a commit, a checkout) recompiles that one file and relinks the executables, without
# a new configure.
if(NOT SOURCE_DIR OR NOT OUTPUT)
  message(FATAL_ERROR "RadxGitCommit.cmake: give -DSOURCE_DIR=<repository> -DOUTPUT=<file.cpp>")
endif()

set(commit "unknown")
find_program(RADX_GIT git)
if(RADX_GIT)
  # --no-optional-locks: status refreshes no index file in the repository it only reads.
  execute_process(COMMAND "${RADX_GIT}" -C "${SOURCE_DIR}" rev-parse --show-toplevel
                  OUTPUT_VARIABLE top RESULT_VARIABLE top_rc OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(top_rc EQUAL 0)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
  endif()
  if(top_rc EQUAL 0 AND top STREQUAL source)
    execute_process(COMMAND "${RADX_GIT}" -C "${SOURCE_DIR}" rev-parse --short HEAD
                    OUTPUT_VARIABLE hash RESULT_VARIABLE hash_rc OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    execute_process(COMMAND "${RADX_GIT}" --no-optional-locks -C "${SOURCE_DIR}" status --porcelain
                            --untracked-files=no
                    OUTPUT_VARIABLE changes RESULT_VARIABLE status_rc OUTPUT_STRIP_TRAILING_WHITESPACE
                    ERROR_QUIET)
    if(hash_rc EQUAL 0 AND status_rc EQUAL 0 AND hash MATCHES "^[0-9a-f]+$")
      set(commit "${hash}")
      if(NOT changes STREQUAL "")
        string(APPEND commit "-dirty")
      endif()
    endif()
  endif()
endif()

file(CONFIGURE OUTPUT "${OUTPUT}" CONTENT [[
// Generated at each build by cmake/RadxGitCommit.cmake: do not edit.
#include "apps/build_info.hpp"

namespace radx::app {

std::string_view build_commit() { return "@commit@"; }

}  // namespace radx::app
]] @ONLY)
