# One fuzz CTest (fuzz/CMakeLists.txt): FUZZER, MODE (smoke | regressions), CORPUS, REGRESSIONS,
# WORK (a directory of the build tree), DICT (optional), SEED and RUNS (smoke).
#   smoke:       WORK/corpus = a fresh copy of CORPUS, then RUNS inputs of libFuzzer from SEED on
#                it (the repository is never written); crash files land in WORK. The environment
#                variables RPU_FUZZ_SEED and RPU_FUZZ_RUNS override SEED and RUNS.
#   regressions: every file of CORPUS and REGRESSIONS run once.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(dict_arg "")
if(DICT)
  set(dict_arg -dict=${DICT})
endif()
if(MODE STREQUAL "smoke")
  if(DEFINED ENV{RPU_FUZZ_SEED})
    set(SEED $ENV{RPU_FUZZ_SEED})
  endif()
  if(DEFINED ENV{RPU_FUZZ_RUNS})
    set(RUNS $ENV{RPU_FUZZ_RUNS})
  endif()
  if(NOT SEED MATCHES "^[1-9][0-9]*$" OR NOT RUNS MATCHES "^[1-9][0-9]*$")
    message(FATAL_ERROR "seed '${SEED}' and runs '${RUNS}' must be positive whole numbers")
  endif()
  message(STATUS "libFuzzer seed ${SEED}, ${RUNS} runs (override: RPU_FUZZ_SEED, RPU_FUZZ_RUNS)")
  file(COPY ${CORPUS}/ DESTINATION ${WORK}/corpus)
  # One input may take up to 60 s before it counts as a hang: a loaded CI machine must not turn a
  # slow input into a finding (scripts/fuzz.sh keeps libFuzzer's usual 10 s).
  execute_process(COMMAND ${FUZZER} -seed=${SEED} -runs=${RUNS} -timeout=60 -rss_limit_mb=2048
                          -print_final_stats=1 ${dict_arg} -artifact_prefix=${WORK}/ ${WORK}/corpus
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
elseif(MODE STREQUAL "regressions")
  file(GLOB inputs ${CORPUS}/* ${REGRESSIONS}/*)
  list(FILTER inputs EXCLUDE REGEX "/README[^/]*$")
  list(LENGTH inputs count)
  if(count EQUAL 0)
    message(FATAL_ERROR "no inputs in ${CORPUS} or ${REGRESSIONS}")
  endif()
  message(STATUS "running ${count} inputs once")
  execute_process(COMMAND ${FUZZER} -seed=${SEED} -timeout=60 -rss_limit_mb=2048 -artifact_prefix=${WORK}/ ${inputs}
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
else()
  message(FATAL_ERROR "MODE must be smoke or regressions, got '${MODE}'")
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} (${MODE}) exited with ${rc}")
endif()
