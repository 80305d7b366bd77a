# CTest rtl_axi_render_*: a frame co-simulated through rpu_top and through its AXI shell rpu_axi
# (`rpu render --backend rtl` without and with --axi, the same parameters): the two images are
# the same file, every item and pixel of both equal to the model (no MISMATCH), and the frame
# through the shell takes exactly DELTA cycles more (the shell's latency, docs/axi.md).
# Usage: cmake -DRPU=<rpu> -DSCENE=<scene> -DSIZE=WxH -DOUT=<dir> -DDELTA=<cycles> -P axi_render.cmake
cmake_minimum_required(VERSION 3.25)
file(MAKE_DIRECTORY ${OUT})
set(cycles "")
foreach(mode plain axi)
  set(extra "")
  if(mode STREQUAL "axi")
    set(extra --axi)
  endif()
  execute_process(COMMAND ${RPU} render ${SCENE} --backend rtl --ip iterative --size ${SIZE}
                          --jobs 1 ${extra} -o ${OUT}/${mode}.png
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT rc EQUAL 0 OR "${out}${err}" MATCHES "MISMATCH")
    message(FATAL_ERROR "${mode}: exit ${rc}\n${out}${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "rtl \\(c\\+\\+ harness, ([a-z0-9_]+)\\): ([0-9]+) cycles")
    message(FATAL_ERROR "${mode}: no cycle count in the output:\n${out}${err}")
  endif()
  message(STATUS "${mode}: configuration ${CMAKE_MATCH_1}, ${CMAKE_MATCH_2} cycles")
  list(APPEND cycles ${CMAKE_MATCH_2})
endforeach()
file(SHA256 ${OUT}/plain.png a)
file(SHA256 ${OUT}/axi.png b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "the image through rpu_axi differs from the one through rpu_top")
endif()
list(GET cycles 0 plain)
list(GET cycles 1 axi)
math(EXPR delta "${axi} - ${plain}")
if(NOT delta EQUAL DELTA)
  message(FATAL_ERROR "through rpu_axi: ${axi} cycles, ${delta} more than rpu_top's ${plain} "
                      "(expected ${DELTA}: the shell's latency)")
endif()
message(STATUS "the same image; ${axi} cycles = ${plain} + ${delta} (the shell's latency)")
