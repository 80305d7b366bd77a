# The parameter-table check (scripts/check_params_docs.py, issue 21 item 2) on a fixture whose
# tables drifted from the table of hardware parameters: it must fail and name each drift. Run as
#   cmake -DPYTHON=python3 -DRPU=<rpu> -DSRC=<source dir> -P docs_params.cmake
set(fixture ${SRC}/tests/docs_check/drifted_params.md)
execute_process(COMMAND ${PYTHON} ${SRC}/scripts/check_params_docs.py --rpu ${RPU}
                        --fixed-point ${fixture} --readme ${fixture}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit ${rc}\n${err}")
set(bad "")
if(NOT rc EQUAL 1)
  string(APPEND bad "exit ${rc}, expected 1; ")
endif()
# The drifted n1 default is on line 6 of the fixture; the other rows are named by their text.
foreach(text "drifted_params.md:6: the parameter table differs from `rpu config --markdown`: '| n1 | `--n1` | 3 |"
             ": the parameter table lacks the row '| AW | `--angle-w` | 20 |"
             ": the parameter row differs from `rpu config --markdown=readme`: '| coord_w | `--coord-w` | 24 | signed width of positions |'"
             ": the parameter table lacks the row '| ip | `--ip` | unrolled |")
  string(FIND "${err}" "${text}" at)
  if(at EQUAL -1)
    string(APPEND bad "missing '${text}'; ")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "FAILED: ${bad}")
endif()
