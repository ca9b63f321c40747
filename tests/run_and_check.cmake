# Runs a command and checks its exit status, its output and the files it
# writes. Used by ctest for the program's command-line behaviour.
#   -DCOMMAND=<;-list>      the command
#   -DWORKDIR=<dir>         working folder (emptied first)
#   -DEXPECT_EXIT=<n>       expected exit status
#   -DEXPECT_OUTPUT=<regex> must match stdout + stderr (optional)
#   -DEXPECT_ONCE=<text>    must occur exactly once in the output (optional)
#   -DEXPECT_FILES=<;-list> files that must exist afterwards, relative to WORKDIR
#   -DCSV=<file> -DCSV_LAST_ROW=<regex>  the last line of a CSV file (optional)
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
execute_process(COMMAND ${COMMAND}
  WORKING_DIRECTORY "${WORKDIR}"
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 240)
set(all "${out}${err}")
message("${all}")
if(NOT "${status}" STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_EXIT}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT all MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}'")
endif()
if(DEFINED EXPECT_ONCE)
  string(REPLACE "${EXPECT_ONCE}" "" without "${all}")
  string(LENGTH "${all}" n_all)
  string(LENGTH "${without}" n_without)
  string(LENGTH "${EXPECT_ONCE}" n_text)
  math(EXPR count "(${n_all} - ${n_without}) / ${n_text}")
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "'${EXPECT_ONCE}' printed ${count} times, expected once")
  endif()
endif()
foreach(f ${EXPECT_FILES})
  if(NOT EXISTS "${WORKDIR}/${f}")
    message(FATAL_ERROR "missing output file ${f}")
  endif()
endforeach()
if(DEFINED CSV)
  file(STRINGS "${WORKDIR}/${CSV}" rows)
  list(GET rows -1 last)
  if(NOT last MATCHES "${CSV_LAST_ROW}")
    message(FATAL_ERROR "last CSV row '${last}' does not match '${CSV_LAST_ROW}'")
  endif()
endif()
message("run_and_check: all checks passed")
