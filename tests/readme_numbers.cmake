# The README-number check (scripts/check_readme_numbers.py, issue 20 item 3) on a fixture whose
# figures drifted: it must fail and name each drifted figure. Run as
#   cmake -DPYTHON=python3 -DSRC=<source dir> -P readme_numbers.cmake
execute_process(COMMAND ${PYTHON} ${SRC}/scripts/check_readme_numbers.py --root ${SRC}
                        --readme ${SRC}/tests/docs_check/drifted_readme.md
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit ${rc}\n${err}")
set(bad "")
if(NOT rc EQUAL 1)
  string(APPEND bad "exit ${rc}, expected 1; ")
endif()
foreach(re "drifted_readme.md:3: '15 s' names no docs table"
           "drifted_readme.md:5: '940 cycles' is in no table of docs/rtl.md"
           "drifted_readme.md:7: docs/no-such-file.md does not exist"
           "parameter table: --n1 default '3', docs/fixed-point.md says '2'")
  string(FIND "${err}" "${re}" pos)
  if(pos EQUAL -1)
    string(APPEND bad "missing '${re}'; ")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "FAILED: ${bad}")
endif()
