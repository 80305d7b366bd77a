# CTest axi_regmap_catches_drift: scripts/axi_regmap.py --check on a copy of the register map's
# source and its three generated files (rtl/axi/rpu_axi_regs.vh, include/rpu_axi_regs.h, the
# tables of docs/axi.md): the copy passes; a hand edit of one generated file fails and names it;
# an edit of the source fails and names all three; a source with two registers at one offset is
# refused with its reason (exit 2).
# Usage: cmake -DPYTHON=<python3> -DSRC=<checkout> -DWORK=<scratch dir> -P axi_regmap.cmake
cmake_minimum_required(VERSION 3.25)
set(files rtl/axi/rpu_axi_regmap.json rtl/axi/rpu_axi_regs.vh include/rpu_axi_regs.h docs/axi.md)
function(fresh_copy)
  file(REMOVE_RECURSE ${WORK})
  foreach(f IN LISTS files)
    get_filename_component(d ${f} DIRECTORY)
    file(MAKE_DIRECTORY ${WORK}/${d})
    file(COPY_FILE ${SRC}/${f} ${WORK}/${f})
  endforeach()
endfunction()
function(check want_rc want_text what)
  execute_process(COMMAND ${PYTHON} ${SRC}/scripts/axi_regmap.py --check --root ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL want_rc)
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${want_rc}\n${out}${err}")
  endif()
  foreach(t IN LISTS want_text)
    string(FIND "${out}${err}" "${t}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${what}: the message does not name '${t}':\n${out}${err}")
    endif()
  endforeach()
  message(STATUS "${what}: exit ${rc} as expected")
endfunction()

fresh_copy()
check(0 "" "the committed files")

file(READ ${WORK}/include/rpu_axi_regs.h h)
string(REPLACE "#define RPU_AXI_CTRL 0x040u" "#define RPU_AXI_CTRL 0x044u" h2 "${h}")
if(h2 STREQUAL h)
  message(FATAL_ERROR "the fixture edit did not apply to include/rpu_axi_regs.h")
endif()
file(WRITE ${WORK}/include/rpu_axi_regs.h "${h2}")
check(1 "include/rpu_axi_regs.h" "a hand-edited C header")

fresh_copy()
file(READ ${WORK}/rtl/axi/rpu_axi_regmap.json j)
string(REPLACE "\"name\": \"CTRL\", \"offset\": \"0x040\"" "\"name\": \"CTRL\", \"offset\": \"0x030\"" j2 "${j}")
if(j2 STREQUAL j)
  message(FATAL_ERROR "the fixture edit did not apply to the register map's source")
endif()
file(WRITE ${WORK}/rtl/axi/rpu_axi_regmap.json "${j2}")
check(1 "rtl/axi/rpu_axi_regs.vh;include/rpu_axi_regs.h;docs/axi.md" "a moved register")

string(REPLACE "\"name\": \"CTRL\", \"offset\": \"0x040\"" "\"name\": \"CTRL\", \"offset\": \"0x044\"" j3 "${j}")
file(WRITE ${WORK}/rtl/axi/rpu_axi_regmap.json "${j3}")
check(2 "share offset 0x044" "two registers at one offset")
file(REMOVE_RECURSE ${WORK})
