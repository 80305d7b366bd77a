# Frame-parallel co-simulation (docs/cosim.md, "Frame-parallel co-simulation"): the same frame on
# one Verilated instance, on three at once (--jobs 3), and as three shards run one by one
# (--shard I/3) and merged (--merge-shards) gives the same image byte for byte, every share
# checked against the model; the instances' cycles add up to the work items they took. Then the
# merge's bad input: a missing share, a repeated one, a shard of another frame, a foreign file;
# and --shard, --jobs and --rtl-exe out of range or misplaced.
#   cmake -DRPU=rpu -DOUT=dir "-DARGS=scene;flags..." -P rtl_shards.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
function(rpu_ok name)
  execute_process(COMMAND ${RPU} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err)
  message(STATUS "${name}: exit ${rc}\n${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAILED: ${name} exited ${rc}")
  endif()
  if(err MATCHES "MISMATCH")
    message(FATAL_ERROR "FAILED: ${name} reports a mismatch")
  endif()
  set(err "${err}" PARENT_SCOPE)
endfunction()
function(rpu_refused name regex)
  execute_process(COMMAND ${RPU} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err)
  message(STATUS "${name}: exit ${rc}\n${err}")
  if(NOT rc EQUAL 1 OR NOT err MATCHES "${regex}")
    message(FATAL_ERROR "FAILED: ${name}: exit ${rc}, expected 1 with /${regex}/")
  endif()
  string(REGEX MATCHALL "rpu: error" lines "${err}")
  list(LENGTH lines n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "FAILED: ${name}: ${n} error lines, expected one")
  endif()
endfunction()
function(same a b what)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAILED: ${what}: ${a} and ${b} differ")
  endif()
endfunction()

rpu_ok("one instance" render ${ARGS} --backend rtl --jobs 1 -o ${OUT}/one.png)
if(NOT err MATCHES "rtl \\(c\\+\\+ harness, [^)]*\\): ([0-9]+) cycles")
  message(FATAL_ERROR "FAILED: no cycle count")
endif()
string(REGEX MATCH "([0-9]+) ray/segment pairs" m "${err}")
set(items ${CMAKE_MATCH_1})

rpu_ok("three instances" render ${ARGS} --backend rtl --jobs 3 -o ${OUT}/three.png)
same(${OUT}/one.png ${OUT}/three.png "--jobs 3 against --jobs 1")
if(NOT err MATCHES "; 3 instances \\(cycles \\[([0-9]+),([0-9]+),([0-9]+)\\]\\), the frame ([0-9]+) cycles")
  message(FATAL_ERROR "FAILED: --jobs 3 does not report three instances' cycles")
endif()
set(c0 ${CMAKE_MATCH_1})
set(c1 ${CMAKE_MATCH_2})
set(c2 ${CMAKE_MATCH_3})
set(frame ${CMAKE_MATCH_4})
# Each instance takes about a third of the items at one item per cycle (plus its own latency):
# no instance ran the whole frame, and the frame's cycles are the longest instance's.
foreach(c ${c0} ${c1} ${c2})
  math(EXPR limit "${items} * 2 / 3")
  if(c GREATER limit OR c GREATER frame)
    message(FATAL_ERROR "FAILED: an instance ran ${c} cycles for a third of ${items} items (frame ${frame})")
  endif()
endforeach()

set(shards "")
foreach(i 0 1 2)
  rpu_ok("shard ${i}/3" render ${ARGS} --backend rtl --shard ${i}/3 -o ${OUT}/share${i}.shard)
  if(NOT err MATCHES "share ${i} of 3 of the [0-9]+x[0-9]+ frame, [0-9]+ work items, [0-9]+ cycles [^\n]*checked against the model: equal")
    message(FATAL_ERROR "FAILED: shard ${i}/3 does not report its check")
  endif()
  list(APPEND shards ${OUT}/share${i}.shard)
endforeach()
rpu_ok("merge" render ${ARGS} --backend rtl --merge-shards ${OUT}/share2.shard ${OUT}/share0.shard
       ${OUT}/share1.shard -o ${OUT}/merged.png)
same(${OUT}/one.png ${OUT}/merged.png "three shards merged against one instance")
if(NOT err MATCHES "rtl \\(shards harness, [^)]*\\): [0-9]+ cycles[^\n]*; 3 instances")
  message(FATAL_ERROR "FAILED: the merge does not report the three shards")
endif()

rpu_refused("a missing share" "--merge-shards: share 1 of 3 is missing"
            render ${ARGS} --backend rtl --merge-shards ${OUT}/share0.shard ${OUT}/share2.shard
            -o ${OUT}/bad.png)
rpu_refused("a repeated share" "share1.shard: repeats share 1 of 3"
            render ${ARGS} --backend rtl --merge-shards ${shards} ${OUT}/share1.shard -o ${OUT}/bad.png)
rpu_refused("another frame" "share0.shard: is a shard of another frame"
            render ${ARGS} --backend rtl --n 12 --n1 3 --merge-shards ${shards} -o ${OUT}/bad.png)
rpu_refused("a foreign file" "one.png: not an rpu shard file"
            render ${ARGS} --backend rtl --merge-shards ${OUT}/one.png -o ${OUT}/bad.png)
rpu_refused("a share past the end" "--shard: must be I/N with 0 <= I < N"
            render ${ARGS} --backend rtl --shard 3/3 -o ${OUT}/bad.shard)
rpu_refused("too many instances" "--jobs: must be in \\[0, 64\\]"
            render ${ARGS} --backend rtl --jobs 65 -o ${OUT}/bad.png)
rpu_refused("shards of another backend" "--shard: applies to --backend rtl only"
            render ${ARGS} --backend ref --shard 0/2 -o ${OUT}/bad.shard)
rpu_refused("a missing harness executable" "--rtl-exe: '[^']*/none' is not an executable file"
            render ${ARGS} --backend rtl --rtl-exe ${OUT}/none -o ${OUT}/bad.png)
rpu_refused("two harnesses" "--rtl-exe: cannot be combined with --systemc"
            render ${ARGS} --backend rtl --systemc --rtl-exe ${OUT}/share0.shard -o ${OUT}/bad.png)
message(STATUS "PASS: one instance, three instances and three merged shards give one image")
