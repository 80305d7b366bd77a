# The coverage smoke test of the default suite (docs/verification.md, section 6): tb_rpu_fifo_cov
# (rpu_fifo's narrow configuration, Verilated with line and toggle coverage) runs with
# RPU_COVERAGE_DIR set to a fresh directory and must write one base file (the counts after the
# first reset) and one end file (harness/coverage_file.h); scripts/coverage_report.py must read
# them, find rpu_fifo's line and toggle points, and rpu_fifo must be at ≥ 95 % of its line points
# and ≥ 90 % of its toggle points. The annotated source goes to OUT/annotate when
# verilator_coverage is given. Run as
#   cmake -DTB=tb_rpu_fifo_cov -DPYTHON=python3 -DSRC=<source dir> -DOUT=<scratch dir>
#         [-DVERILATOR_COVERAGE=verilator_coverage] -P coverage_smoke.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/data)
execute_process(COMMAND ${CMAKE_COMMAND} -E env RPU_COVERAGE_DIR=${OUT}/data ${TB}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${TB}: exit ${rc}\n${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAILED: the testbench failed")
endif()
file(GLOB base ${OUT}/data/*.base.dat)
file(GLOB all ${OUT}/data/*.dat)
set(final ${all})
list(REMOVE_ITEM final ${base})
list(LENGTH base nb)
list(LENGTH final nf)
if(NOT nb EQUAL 1 OR NOT nf EQUAL 1)
  message(FATAL_ERROR "FAILED: expected one base and one end file in ${OUT}/data, found ${all}")
endif()
execute_process(COMMAND ${PYTHON} ${SRC}/scripts/coverage_report.py ${final} --base ${base}
                        --root ${SRC} --print --gaps --write-dat ${OUT}/judged.dat
                        --require rpu_fifo --min-line 95 --min-toggle 90
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "coverage_report.py: exit ${rc}\n${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "\n\\| `rpu_fifo` \\| [1-9][0-9]* \\| [0-9.]+ % \\| [1-9][0-9]* \\| [0-9.]+ % \\| yes \\|\n")
  message(FATAL_ERROR "FAILED: rpu_fifo's row is missing or below 95/90")
endif()
if(VERILATOR_COVERAGE)
  execute_process(COMMAND ${VERILATOR_COVERAGE} --annotate ${OUT}/annotate ${OUT}/judged.dat
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "verilator_coverage --annotate: exit ${rc}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAILED: verilator_coverage cannot read the judged data")
  endif()
endif()
