# One fuzz CTest (fuzz/CMakeLists.txt): FUZZER, MODE (smoke | regressions), CORPUS, REGRESSIONS,
# WORK (a directory of the build tree), DICT (optional).
#   smoke:       WORK/corpus = a fresh copy of CORPUS, then 60 s of fuzzing on it (the repository
#                is never written); crash files land in WORK.
#   regressions: every file of CORPUS and REGRESSIONS run once.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(dict_arg "")
if(DICT)
  set(dict_arg -dict=${DICT})
endif()
if(MODE STREQUAL "smoke")
  file(COPY ${CORPUS}/ DESTINATION ${WORK}/corpus)
  execute_process(COMMAND ${FUZZER} -max_total_time=60 -timeout=10 -rss_limit_mb=2048
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
  execute_process(COMMAND ${FUZZER} -timeout=10 -rss_limit_mb=2048 -artifact_prefix=${WORK}/ ${inputs}
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
else()
  message(FATAL_ERROR "MODE must be smoke or regressions, got '${MODE}'")
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} (${MODE}) exited with ${rc}")
endif()
