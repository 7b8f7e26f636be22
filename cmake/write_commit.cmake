# Run at every build (cli/CMakeLists.txt): writes the checkout's commit, with "+changes" when a tracked file differs
# from it (untracked files do not count), into OUT as a C++ header. The file is rewritten only when that text changes, so nothing rebuilds otherwise.
execute_process(COMMAND git rev-parse --short HEAD WORKING_DIRECTORY "${SOURCE_DIR}"
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed)
  set(commit "")
else()
  execute_process(COMMAND git diff --quiet HEAD WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE dirty ERROR_QUIET)
  if(dirty)
    set(commit "${commit}+changes")
  endif()
endif()
set(text "#pragma once\n// Written by cmake/write_commit.cmake at build time.\n#define VSSW_GIT_COMMIT \"${commit}\"\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE "${OUT}" "${text}")
endif()
