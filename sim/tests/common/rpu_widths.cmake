# rtl/common/rpu_widths.vh: every width formula against its C++ twin in ref/model/hw_params.h over
# each parameter's whole range (a simulation-only probe module evaluates the macros,
# sim/tb/common/rpu_widths_probe.v). tb_rpu_widths_catches: the same check on a copy of
# rpu_widths.vh with one formula changed must fail.
rpu_verilated_test(tb_rpu_widths TOP rpu_widths_probe TB tb/common/tb_rpu_widths.cpp
                   SOURCES tb/common/rpu_widths_probe.v)
set(fault_dir ${CMAKE_CURRENT_BINARY_DIR}/widths_fault)
file(READ ${PROJECT_SOURCE_DIR}/rtl/common/rpu_widths.vh widths)
string(REPLACE "`define RPU_XW(coordw)       ((coordw) + 3)" "`define RPU_XW(coordw)       ((coordw) + 4)"
       widths_bad "${widths}")
file(READ ${CMAKE_CURRENT_SOURCE_DIR}/tb/common/rpu_widths_probe.v probe)
string(REPLACE "`include \"rpu_widths.vh\"" "`include \"${fault_dir}/rpu_widths_fault.vh\""
       probe_bad "${probe}")
if(widths_bad STREQUAL widths OR probe_bad STREQUAL probe)
  message(FATAL_ERROR "tb_rpu_widths_catches: the fault edit no longer applies to rpu_widths.vh "
                      "or rpu_widths_probe.v; update sim/tests/common/rpu_widths.cmake")
endif()
file(CONFIGURE OUTPUT ${fault_dir}/rpu_widths_fault.vh CONTENT "${widths_bad}" @ONLY)
file(CONFIGURE OUTPUT ${fault_dir}/rpu_widths_probe.v CONTENT "${probe_bad}" @ONLY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${PROJECT_SOURCE_DIR}/rtl/common/rpu_widths.vh
             ${CMAKE_CURRENT_SOURCE_DIR}/tb/common/rpu_widths_probe.v)
rpu_verilated_test(tb_rpu_widths_catches NOTEST TOP rpu_widths_probe TB tb/common/tb_rpu_widths.cpp
                   SOURCES ${fault_dir}/rpu_widths_probe.v)
if(TARGET tb_rpu_widths_catches)
  add_test(NAME tb_rpu_widths_catches COMMAND tb_rpu_widths_catches)
  set_tests_properties(tb_rpu_widths_catches PROPERTIES LABELS rtl PASS_REGULAR_EXPRESSION
                       "FAILURE RPU_XW at CoordW 12: rpu_widths.vh gives 16, hw_params.h 15")
endif()
