# The table of hardware parameters (hw_params.def) as CMake reads it, at configure time: each
# entry's first line by a regular expression, so no CMake file keeps a list of its own.
#
# rpu_read_hw_params(PREFIX) sets, in the caller's scope, one list element per entry in table
# order: PREFIX_FIELDS (HwParams members), PREFIX_KEYS (sweep/JSON keys), PREFIX_FLAGS (CLI
# flags) and PREFIX_VERILOG (Verilog parameter names, "-" for none). Editing the table
# reconfigures the build.
set(RPU_HW_PARAMS_DEF ${CMAKE_CURRENT_LIST_DIR}/hw_params.def)

function(rpu_read_hw_params prefix)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${RPU_HW_PARAMS_DEF})
  file(STRINGS ${RPU_HW_PARAMS_DEF} lines REGEX "^RPU_HW_PARAM\\(")
  set(fields "")
  set(keys "")
  set(flags "")
  set(verilog "")
  set(q "\"")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^RPU_HW_PARAM\\(([a-z0-9_]+), *[A-Za-z:]+, *${q}([a-z0-9_]+)${q}, *${q}(--[a-z0-9-]+)${q}, *${q}([A-Za-z0-9_]*)${q},")
      message(FATAL_ERROR "${RPU_HW_PARAMS_DEF}: cannot read the entry '${line}' (field, type, "
                          "\"key\", \"--flag\", \"Verilog\", ... on its first line)")
    endif()
    list(APPEND fields ${CMAKE_MATCH_1})
    list(APPEND keys ${CMAKE_MATCH_2})
    list(APPEND flags ${CMAKE_MATCH_3})
    if(CMAKE_MATCH_4 STREQUAL "")
      list(APPEND verilog -)
    else()
      list(APPEND verilog ${CMAKE_MATCH_4})
    endif()
  endforeach()
  if(NOT fields)
    message(FATAL_ERROR "${RPU_HW_PARAMS_DEF}: no RPU_HW_PARAM entries")
  endif()
  set(${prefix}_FIELDS ${fields} PARENT_SCOPE)
  set(${prefix}_KEYS ${keys} PARENT_SCOPE)
  set(${prefix}_FLAGS ${flags} PARENT_SCOPE)
  set(${prefix}_VERILOG ${verilog} PARENT_SCOPE)
endfunction()
