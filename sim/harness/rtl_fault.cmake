# The fault-injected build's RTL (rpu_rtl_config FAULT, docs/cosim.md): copies of two units with
# a deliberate fault each, chosen at run time through DPI (`rpu_fault()`, sim/harness/
# rtl_backend.cpp, set by `--rtl-fault`: 0 none, 1 argmin-tie, 2 far-hit). The synthesizable
# sources carry no fault code; the faults are edits of their text, made here at configure time,
# and an edit that no longer applies stops the configure.
#   rpu_ip_step: the argmin keeps the last minimum on a tie (fault 1);
#   rpu_resolve: the farther hit wins (fault 2), so pixels change while every work item is right.
# rpu_fault_sources(OUT): RPU_TOP_RTL with those two files replaced by their faulted copies.
function(rpu_fault_edit text_var from to file)
  string(REPLACE "${from}" "${to}" changed "${${text_var}}")
  if(changed STREQUAL ${text_var})
    message(FATAL_ERROR "sim/harness/rtl_fault.cmake: the fault edit no longer applies to ${file}")
  endif()
  set(${text_var} "${changed}" PARENT_SCOPE)
endfunction()

function(rpu_fault_sources out)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/rtl_fault)
  set(dpi "  import \"DPI-C\" function int rpu_fault();\n  integer fault_sel;\n  initial fault_sel = rpu_fault();\n")
  set(sources "")
  foreach(src IN LISTS RPU_TOP_RTL)
    get_filename_component(name ${src} NAME)
    if(name STREQUAL "rpu_ip_step.v")
      file(READ ${src} text)
      rpu_fault_edit(text "  reg [J-1:0] win;\n"
        "  reg [J-1:0] win;\n${dpi}  wire fault_tie = fault_sel == 1;\n" ${name})
      rpu_fault_edit(text
        "        if (b < a && sd[a] >= sd[b]) win[a] = 1'b0;\n        if (b > a && sd[a] > sd[b]) win[a] = 1'b0;\n"
        "        if (b < a && (fault_tie ? sd[a] > sd[b] : sd[a] >= sd[b])) win[a] = 1'b0;\n        if (b > a && (fault_tie ? sd[a] >= sd[b] : sd[a] > sd[b])) win[a] = 1'b0;\n"
        ${name})
    elseif(name STREQUAL "rpu_resolve.v")
      file(READ ${src} text)
      rpu_fault_edit(text "  wire nearer = d_new < d_old;\n"
        "${dpi}  wire nearer = fault_sel == 2 ? d_new > d_old : d_new < d_old;\n" ${name})
    else()
      list(APPEND sources ${src})
      continue()
    endif()
    file(CONFIGURE OUTPUT ${dir}/${name} CONTENT "${text}" @ONLY)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${src})
    list(APPEND sources ${dir}/${name})
  endforeach()
  set(${out} ${sources} PARENT_SCOPE)
endfunction()
