# docs/throughput.md holds exactly what scripts/throughput_projection.py prints (which reads the
# rpu_top rows of docs/resources.md): the projection cannot drift from the resource table.
#   cmake -DPYTHON=python3 -DSRC=<source dir> -P throughput_table.cmake
execute_process(COMMAND ${PYTHON} ${SRC}/scripts/throughput_projection.py
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAILED: throughput_projection.py exited ${rc}: ${err}")
endif()
file(READ ${SRC}/docs/throughput.md doc)
string(FIND "${doc}" "${out}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "FAILED: docs/throughput.md does not hold the projection's current output; "
                      "regenerate it: python3 scripts/throughput_projection.py\n${out}")
endif()
message(STATUS "docs/throughput.md holds the current projection")
