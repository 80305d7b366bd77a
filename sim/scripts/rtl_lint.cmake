# CTest rtl_lint: `verilator --lint-only -Wall` is clean on every module of rtl/rpu.f, each as
# the top at its default parameters, with the one waiver file (rtl/lint/verilator_waiver.vlt).
# Usage: cmake -DPROJECT_SOURCE_DIR=<checkout> -DVERILATOR=<verilator_bin> -P rtl_lint.cmake
cmake_minimum_required(VERSION 3.25)
include(${PROJECT_SOURCE_DIR}/sim/rtl_files.cmake)
set(modules "")
foreach(f IN LISTS RPU_RTL_SOURCES)
  file(STRINGS ${f} decls REGEX "^[ \t]*module[ \t]+[A-Za-z_][A-Za-z0-9_]*")
  foreach(d IN LISTS decls)
    string(REGEX MATCH "module[ \t]+([A-Za-z_][A-Za-z0-9_]*)" m "${d}")
    list(APPEND modules ${CMAKE_MATCH_1})
  endforeach()
endforeach()
set(failed "")
foreach(m IN LISTS modules)
  execute_process(COMMAND ${VERILATOR} --lint-only -Wall -F ${RPU_RTL_LIST} ${RPU_VERILATOR_WAIVER}
                          --top-module ${m}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "")
    string(APPEND failed "---- ${m} (exit ${rc}):\n${out}\n")
  endif()
endforeach()
list(LENGTH modules n)
if(failed)
  message(FATAL_ERROR "verilator --lint-only -Wall is not clean:\n${failed}")
endif()
message(STATUS "verilator --lint-only -Wall: ${n} modules clean")
