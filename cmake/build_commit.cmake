# cmake -DSOURCE_DIR=... -DOUTPUT=... [-DGIT_EXECUTABLE=...] -P build_commit.cmake
#
# Writes OUTPUT, a C++ source defining blockfrag::build_commit(): `git rev-parse --short HEAD` of
# SOURCE_DIR when SOURCE_DIR is the top of a git checkout, else "unknown" (a source archive, or one
# unpacked inside some other repository, or no git). mpi_driver/CMakeLists.txt runs it at every
# build, so a new commit needs no re-configure; OUTPUT is rewritten only when the commit changed,
# so a build on the same commit recompiles nothing.
cmake_minimum_required(VERSION 3.25)
set(commit unknown)
if(GIT_EXECUTABLE)
  execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse --show-toplevel --short HEAD
                  OUTPUT_VARIABLE answer RESULT_VARIABLE result ERROR_QUIET
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(result EQUAL 0)
    string(REPLACE "\n" ";" answer "${answer}")
    list(GET answer 0 top)
    list(GET answer -1 head)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
    if(top STREQUAL source AND head MATCHES "^[0-9a-f]+$")
      set(commit "${head}")
    endif()
  endif()
endif()
file(CONFIGURE OUTPUT "${OUTPUT}" CONTENT
"// Generated at build time by cmake/build_commit.cmake.
#include \"blockfrag/version.hpp\"

const char* blockfrag::build_commit() { return \"@commit@\"; }
" @ONLY)
