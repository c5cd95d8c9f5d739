# Writes OUT (a C++ string literal: the source tree's `git describe --always --dirty`, empty outside a git
# checkout) when it changes: run at every build (src/CMakeLists.txt), so a build names the commit it was built
# from, not the one CMake configured at.
execute_process(COMMAND git describe --always --dirty WORKING_DIRECTORY ${SRC}
  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  set(commit "")
endif()
set(text "\"${commit}\"\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUT} "${text}")
endif()
