# Mutation testing's kill path (scripts/mutate.py --smoke, docs/verification.md): two Yosys
# mutants of each of five small modules, elaborated as their testbenches build them, Verilated
# in a build of their own and run; every one must be killed, the unmutated design must pass.
# The full run (over 1,000 mutants) is opt-in: scripts/mutate.py.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME mutation_smoke
         COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/mutate.py --smoke --fresh
                 --build-dir ${PROJECT_BINARY_DIR}/mutation-smoke --jobs 2)
set_tests_properties(mutation_smoke PROPERTIES LABELS "rtl;mutation" TIMEOUT 1200)
