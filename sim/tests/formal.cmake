# Formal checks (scripts/formal.sh, docs/verification.md), label `formal`:
#   formal_smoke  BMC + k-induction + covers of rpu_fifo, rpu_resolve, rpu_surface_admit (at
#                 periods 3, 5 and 7), rpu_axi
#                 (the AXI4-Lite and AXI4-Stream handshake rules, rpu_top abstracted), and
#                 rpu_top at the reduced parameter set: its BMC to a short depth, its stream
#                 properties proved by k-induction (the deeper BMC and the covers:
#                 `scripts/formal.sh top`);
#   formal_faults two mutated rpu_fifo copies, a mutated rpu_top, a mutated rpu_axis_scatter
#                 (TDATA changing while TVALID is held) and a mutated rpu_axil_port (a write
#                 answered before its W) that must yield a
#                 counterexample (the proofs can fail).
# Needs yosys-smtbmc, z3 and cvc5 (scripts/setup.sh); without them the tests are not registered.
find_program(RPU_SMTBMC yosys-smtbmc)
find_program(RPU_Z3 z3)
find_program(RPU_CVC5 cvc5)
if(RPU_SMTBMC AND RPU_Z3 AND RPU_CVC5)
  add_test(NAME formal_smoke
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/formal.sh --smoke
                   --out ${CMAKE_BINARY_DIR}/formal-smoke fifo resolve admit admit_p5 admit_p7
                   top axi)
  add_test(NAME formal_faults
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/formal.sh
                   --out ${CMAKE_BINARY_DIR}/formal-faults fifo_bug_full fifo_bug_stale top_bug_lost
                   axi_bug_payload axi_bug_early_b)
  set_tests_properties(formal_smoke formal_faults PROPERTIES LABELS formal)
  set_tests_properties(formal_smoke PROPERTIES TIMEOUT 900)
else()
  message(STATUS "yosys-smtbmc, z3 or cvc5 not found: formal tests not registered")
endif()
