# rpu_fifo: 200,000 cycles of random writes and reads in traffic phases (fill, drain, free flow)
# against ref::Fifo cycle for cycle and an order scoreboard; a narrow configuration (4 entries,
# 1 bit: full and empty every few cycles) and a wide one (100-bit entries, 64 entries).
rpu_verilated_test(tb_rpu_fifo_narrow TOP rpu_fifo TB tb/common/tb_rpu_fifo.cpp
                   PARAMS -GWidth=1 -GLog2Depth=2)
rpu_verilated_test(tb_rpu_fifo_wide TOP rpu_fifo TB tb/common/tb_rpu_fifo.cpp
                   PARAMS -GWidth=100 -GLog2Depth=6)
# Coverage smoke test (docs/verification.md, section 6): the narrow configuration once more,
# Verilated with line and toggle coverage (the default build's only coverage model: a small one),
# its data written and read by scripts/coverage_report.py, rpu_fifo at ≥ 95 % of its line points
# and ≥ 90 % of its toggle bits (sim/scripts/coverage_smoke.cmake). The full measurement:
# scripts/coverage.sh.
rpu_verilated_test(tb_rpu_fifo_cov COVERAGE NOTEST TOP rpu_fifo TB tb/common/tb_rpu_fifo.cpp
                   PARAMS -GWidth=1 -GLog2Depth=2)
if(TARGET tb_rpu_fifo_cov)
  find_program(RPU_VERILATOR_COVERAGE verilator_coverage)
  add_test(NAME coverage_smoke
           COMMAND ${CMAKE_COMMAND} -DTB=$<TARGET_FILE:tb_rpu_fifo_cov> -DPYTHON=${Python3_EXECUTABLE}
                   -DSRC=${PROJECT_SOURCE_DIR} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/coverage_smoke
                   -DVERILATOR_COVERAGE=${RPU_VERILATOR_COVERAGE}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/coverage_smoke.cmake)
  set_tests_properties(coverage_smoke PROPERTIES LABELS rtl)
endif()
