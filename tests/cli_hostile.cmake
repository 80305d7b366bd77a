# Hostile input, second round (issue 24): patches, surfaces and `rpu volume` end in one error line
# and exit 1, or in the right image, within bounded time and memory. Run as
#   cmake -DRPU=path/to/rpu -DPYTHON=python3 -DSRC=source-dir -DOUT=dir -DMODE=<mode>
#         [-DSANITIZE=ON] -P cli_hostile.cmake
# Every command runs under `ulimit -v` (1 GiB of address space: a case that needs more dies of
# std::bad_alloc, which rpu reports as "out of memory", and the expected line is then missing)
# and a timeout, so a regression cannot take the suite down. Under the sanitizers (SANITIZE=ON)
# the address-space limit is left out (ASan reserves terabytes of shadow memory) and the timeouts
# are longer. The scenes are written by tests/hostile_scenes.py into OUT.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(failures 0)
if(SANITIZE)
  set(VMEM unlimited)
  set(TIMEOUT 120)
else()
  set(VMEM 1048576)  # KiB: 1 GiB
  set(TIMEOUT 20)
endif()
execute_process(COMMAND ${PYTHON} ${SRC}/tests/hostile_scenes.py ${OUT} ${SRC} ${MODE}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hostile_scenes.py failed: ${err}")
endif()
set(S ${OUT})
set(IMG ${OUT}/x.png)

# run(label rc regex... -- args...): runs `rpu args...` under the limits. rc is the exit status
# wanted; every regex must match stderr. For rc 1, stderr must be exactly one "rpu: error: " line.
# The stderr is left in LAST_ERR (parent scope), stdout in LAST_OUT; with RUN_STDOUT set, stdout
# goes to that file instead.
function(run label want_rc)
  set(regexes "")
  set(args "")
  set(in_args FALSE)
  foreach(a IN LISTS ARGN)
    if(in_args)
      list(APPEND args "${a}")
    elseif(a STREQUAL "--")
      set(in_args TRUE)
    else()
      list(APPEND regexes "${a}")
    endif()
  endforeach()
  set(redirect "")
  if(RUN_STDOUT)
    set(redirect " >${RUN_STDOUT}")
  endif()
  execute_process(COMMAND sh -c "ulimit -v ${VMEM} && exec \"$0\" \"$@\"${redirect}" ${RPU} ${args}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${TIMEOUT})
  string(STRIP "${err}" err_stripped)
  set(bad "")
  if(NOT "${rc}" STREQUAL "${want_rc}")
    string(APPEND bad "exit ${rc}, expected ${want_rc}; ")
  endif()
  if(want_rc EQUAL 1)
    string(REGEX MATCHALL "\n" newlines "${err_stripped}")
    list(LENGTH newlines nl)
    if(nl GREATER 0 OR NOT err_stripped MATCHES "^rpu: error: ")
      string(APPEND bad "stderr is not one 'rpu: error: ' line; ")
    endif()
  endif()
  foreach(re IN LISTS regexes)
    if(NOT err MATCHES "${re}")
      string(APPEND bad "stderr lacks /${re}/; ")
    endif()
  endforeach()
  if(bad)
    message(STATUS "FAIL ${label}: ${bad}\n${err}")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  else()
    message(STATUS "ok   ${label}: exit ${rc}: ${err_stripped}")
  endif()
  set(LAST_ERR "${err}" PARENT_SCOPE)
  set(LAST_OUT "${out}" PARENT_SCOPE)
endfunction()

# hits(label want -- args...): `rpu render args... -o IMG` must exit 0 and report exactly `want`
# hit pixels (the exact count, or that of the unscaled scene).
function(hits label want)
  list(REMOVE_AT ARGN 0)  # the "--"
  run("${label}" 0 "hit pixels" -- render ${ARGN} -o ${IMG})
  set(f ${failures})
  if(LAST_ERR MATCHES "float(-ip)? in [0-9.]+ s, ([0-9]+) hit pixels")
    set(got ${CMAKE_MATCH_2})
  else()
    set(got "none")
  endif()
  if(NOT got STREQUAL "${want}")
    message(STATUS "FAIL ${label}: ${got} hit pixels, expected ${want}")
    math(EXPR f "${f} + 1")
  endif()
  set(failures ${f} PARENT_SCOPE)
endfunction()

if(MODE STREQUAL "output")
  # Item 4: a resource failure of --threads is one line, exit 1 (1,024 thread stacks do not fit in
  # 1 GiB of address space; rows = 1,100, so all 1,024 workers are wanted).
  if(NOT SANITIZE)
    run("--threads 1024 under ulimit -v" 1 "--threads: cannot start worker thread [0-9]+ of 1024"
        -- render builtin:curve12 --size 8x1100 --threads 1024 -q -o ${IMG})
  endif()
  # Item 3: stdout is checked like every other output (rpu volume, rpu scenes, rpu config).
  set(RUN_STDOUT /dev/full)
  foreach(cmd "volume;builtin:bezier_sphere" "scenes" "config")
    run("rpu ${cmd} > /dev/full" 1 "standard output: cannot write: No space left on device"
        -- ${cmd})
  endforeach()
  unset(RUN_STDOUT)
else()
  message(FATAL_ERROR "unknown MODE ${MODE}")
endif()

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} case(s) failed")
endif()
