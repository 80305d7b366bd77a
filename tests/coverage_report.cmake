# The coverage report (scripts/coverage_report.py, docs/verification.md section 6) on hand-written
# Verilator data with known counts (tests/docs_check/coverage/, its README says what each point
# tests): the table and the gaps must be exactly the expected ones; --check must catch a drifted
# docs table and pass once --update-docs rewrote it; --require must fail below the thresholds and
# for a module without points. Run as
#   cmake -DPYTHON=python3 -DSRC=<source dir> -DOUT=<scratch dir> -P coverage_report.cmake
set(fx ${SRC}/tests/docs_check/coverage)
set(report ${PYTHON} ${SRC}/scripts/coverage_report.py ${fx}/final.dat --base ${fx}/base.dat
           --root ${fx})
set(bad "")

execute_process(COMMAND ${report} --print --gaps RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
file(READ ${fx}/expected.txt want)
message(STATUS "--print --gaps: exit ${rc}\n${out}${err}")
if(NOT rc EQUAL 0 OR NOT out STREQUAL want)
  string(APPEND bad "--print --gaps: exit ${rc} or not tests/docs_check/coverage/expected.txt; ")
endif()

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(COPY ${fx}/doc.md DESTINATION ${OUT})
execute_process(COMMAND ${report} --check --docs ${OUT}/doc.md RESULT_VARIABLE rc ERROR_VARIABLE err)
message(STATUS "--check (drifted): exit ${rc}\n${err}")
if(NOT rc EQUAL 1 OR NOT err MATCHES "the coverage table differs from the data.*-\\| `rpu_a` \\| 4 \\| 75.0 %.*\\+\\| `rpu_a` \\| 4 \\| 50.0 %")
  string(APPEND bad "--check did not report the drifted row; ")
endif()
execute_process(COMMAND ${report} --update-docs --docs ${OUT}/doc.md RESULT_VARIABLE rc)
execute_process(COMMAND ${report} --check --docs ${OUT}/doc.md RESULT_VARIABLE rc2 ERROR_VARIABLE err)
file(READ ${OUT}/doc.md doc)
if(NOT rc EQUAL 0 OR NOT rc2 EQUAL 0 OR NOT doc MATCHES "\\| `rpu_a` \\| 4 \\| 50.0 %"
   OR NOT doc MATCHES "Text after the table stays.")
  string(APPEND bad "--update-docs then --check: exit ${rc}, ${rc2} ${err}; ")
endif()

# module|min line|min toggle|exit status|stderr ('-': none)
foreach(case "rpu_b|60|90|0|-" "rpu_b|95|90|1|rpu_b: line 66.6 % of 3, toggle 100.0 % of 10: below 95/90"
             "rpu_a|0|0|0|-" "rpu_zzz|0|0|1|rpu_zzz: no line or toggle points")
  string(REPLACE "|" ";" c "${case}")
  list(GET c 0 m)
  list(GET c 1 ml)
  list(GET c 2 mt)
  list(GET c 3 want_rc)
  list(GET c 4 want_err)
  execute_process(COMMAND ${report} --require ${m} --min-line ${ml} --min-toggle ${mt}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  message(STATUS "--require ${m} --min-line ${ml} --min-toggle ${mt}: exit ${rc} ${err}")
  if(NOT rc EQUAL want_rc)
    string(APPEND bad "--require ${m} ${ml}/${mt}: exit ${rc}, expected ${want_rc}; ")
  endif()
  if(NOT want_err STREQUAL "-")
    string(FIND "${err}" "${want_err}" at)
    if(at EQUAL -1)
      string(APPEND bad "--require ${m}: stderr lacks '${want_err}'; ")
    endif()
  endif()
endforeach()

if(bad)
  message(FATAL_ERROR "FAILED: ${bad}")
endif()
