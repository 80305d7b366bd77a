# CTest rtl_file_list: rtl/rpu.f is the list of every RTL file. Checks that every entry exists
# (sim/rtl_files.cmake, which every build reads, stops at the first missing one), that no entry
# is listed twice, that every rtl/**/*.v is a source line and every rtl/**/*.vh a "// header:"
# line whose directory is an +incdir+ of the list, and, with -DVERILATOR=<verilator_bin>, that
# Verilator reads the list as is (-F rtl/rpu.f): it parses every file, so every `include must
# resolve (the top, rpu_fifo, keeps the check under a second; the builds lint the real tops).
# Usage: cmake -DPROJECT_SOURCE_DIR=<checkout> [-DVERILATOR=<bin>] -P rtl_file_list.cmake
cmake_minimum_required(VERSION 3.25)
include(${PROJECT_SOURCE_DIR}/sim/rtl_files.cmake)

set(errors "")
foreach(kind SOURCES HEADERS INCDIRS)
  set(seen "")
  foreach(f IN LISTS RPU_RTL_${kind})
    if(f IN_LIST seen)
      string(APPEND errors "  listed twice: ${f}\n")
    endif()
    list(APPEND seen ${f})
  endforeach()
endforeach()

file(GLOB_RECURSE rtl_v RELATIVE ${RPU_RTL_DIR} ${RPU_RTL_DIR}/*.v)
file(GLOB_RECURSE rtl_vh RELATIVE ${RPU_RTL_DIR} ${RPU_RTL_DIR}/*.vh)
foreach(f IN LISTS rtl_v)
  if(NOT ${RPU_RTL_DIR}/${f} IN_LIST RPU_RTL_SOURCES)
    string(APPEND errors "  rtl/${f} is not in rtl/rpu.f (add a line: ${f})\n")
  endif()
endforeach()
foreach(f IN LISTS rtl_vh)
  if(NOT ${RPU_RTL_DIR}/${f} IN_LIST RPU_RTL_HEADERS)
    string(APPEND errors "  rtl/${f} is not in rtl/rpu.f (add a line: // header: ${f})\n")
  endif()
endforeach()
foreach(f IN LISTS RPU_RTL_SOURCES)
  if(NOT f MATCHES "\\.v$")
    string(APPEND errors "  ${f}: a source line must name a .v file\n")
  endif()
endforeach()
foreach(f IN LISTS RPU_RTL_HEADERS)
  get_filename_component(dir ${f} DIRECTORY)
  if(NOT f MATCHES "\\.vh$")
    string(APPEND errors "  ${f}: a header line must name a .vh file\n")
  elseif(NOT dir IN_LIST RPU_RTL_INCDIRS)
    string(APPEND errors "  ${f}: its directory is no +incdir+ of rtl/rpu.f\n")
  endif()
endforeach()
if(errors)
  message(FATAL_ERROR "rtl/rpu.f does not match rtl/:\n${errors}")
endif()
list(LENGTH RPU_RTL_SOURCES ns)
list(LENGTH RPU_RTL_HEADERS nh)
message(STATUS "rtl/rpu.f: ${ns} sources and ${nh} headers, every rtl/ file listed")

if(VERILATOR)
  execute_process(COMMAND ${VERILATOR} --lint-only -Wall -F ${RPU_RTL_LIST} --top-module rpu_fifo
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "")
    message(FATAL_ERROR "verilator --lint-only -Wall -F rtl/rpu.f --top-module rpu_fifo "
                        "(exit ${rc}):\n${out}")
  endif()
  message(STATUS "verilator -F rtl/rpu.f: every file parses")
endif()
