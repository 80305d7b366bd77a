# CTest rtl_params_catches: scripts/check_rtl_params.py on a copy of rtl/ and the parameter table:
# the copy passes; a module with a wrong default of a table parameter (rpu_chord's TFrac) fails
# naming the file, the line and the table's value, as does a wrong default in rpu_top's own
# parameter list (rpu_top_params.vh's TFrac); a module that declares one of rpu_top's parameters
# with another default (rpu_resolve's PrimW) fails naming rpu_top's; an AXI shell that declares
# its own list instead of including rpu_top's fails; a module that writes a width formula of
# rpu_widths.vh out by hand (rpu_capture's DepthW) fails naming the macro; a testbench default
# that is not the table's (tb_common.h's COORD_W) fails.
# Usage: cmake -DPYTHON=<python3> -DSRC=<checkout> -DWORK=<scratch dir> -P rtl_params.cmake
cmake_minimum_required(VERSION 3.25)
function(fresh_copy)
  file(REMOVE_RECURSE ${WORK})
  file(MAKE_DIRECTORY ${WORK}/ref/model)
  file(COPY ${SRC}/rtl DESTINATION ${WORK})
  file(COPY_FILE ${SRC}/ref/model/hw_params.def ${WORK}/ref/model/hw_params.def)
  file(MAKE_DIRECTORY ${WORK}/sim/tb)
  file(COPY_FILE ${SRC}/sim/tb/tb_common.h ${WORK}/sim/tb/tb_common.h)
endfunction()
function(check want_rc want_text what)
  execute_process(COMMAND ${PYTHON} ${SRC}/scripts/check_rtl_params.py --root ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL want_rc)
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${want_rc}\n${out}${err}")
  endif()
  string(FIND "${out}${err}" "${want_text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${what}: the output does not say '${want_text}':\n${out}${err}")
  endif()
  message(STATUS "${what}: exit ${rc}: ${out}")
endfunction()
function(edit file from to)
  file(READ ${WORK}/${file} text)
  string(REPLACE "${from}" "${to}" changed "${text}")
  if(changed STREQUAL text)
    message(FATAL_ERROR "the fixture edit '${from}' did not apply to ${file}")
  endif()
  file(WRITE ${WORK}/${file} "${changed}")
endfunction()

# One fixture: a fresh copy with one edit must fail, saying `want`.
function(must_fail what file from to want)
  fresh_copy()
  edit(${file} "${from}" "${to}")
  check(1 "${want}" "${what}")
endfunction()

fresh_copy()
check(0 "agree with the table" "the committed RTL")
must_fail("a wrong default of a table parameter" rtl/curve/rpu_chord.v
          "parameter integer TFrac = 24" "parameter integer TFrac = 20" "rtl/curve/rpu_chord.v:")
must_fail("a wrong default in rpu_top's parameter list" rtl/top/rpu_top_params.vh
          "parameter integer TFrac    = 24" "parameter integer TFrac    = 22"
          "rtl/top/rpu_top_params.vh:")
must_fail("a wrong default of one of rpu_top's parameters" rtl/top/rpu_resolve.v
          "parameter integer PrimW  = 16" "parameter integer PrimW  = 12"
          "PrimW = 12, rpu_top_params.vh declares 16")
must_fail("an AXI shell with a parameter list of its own" rtl/axi/rpu_axi.v
          "`include \"rpu_top_params.vh\"" "parameter integer IdxW = 14"
          "does not include rpu_top_params.vh")
must_fail("a width formula written out by hand" rtl/curve/rpu_capture.v
          "DepthW = `RPU_DEPTHW(CoordW, EdgeFrac)" "DepthW = CoordW + 4 + EdgeW + 2"
          "rpu_capture.v:26: DepthW = CoordW + 4 + EdgeW + 2 repeats `RPU_DEPTHW(CoordW, EdgeFrac)")
must_fail("a testbench default" sim/tb/tb_common.h "#define COORD_W 24" "#define COORD_W 20"
          "COORD_W = 20, the table (ref/model/hw_params.def) says 24")
file(REMOVE_RECURSE ${WORK})
