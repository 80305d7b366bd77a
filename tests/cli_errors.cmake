# CLI contract for bad input (docs/scene-format.md, README "Command line", issue 11): exactly one
# line "rpu: error: <where>: <problem>" on stderr naming the file, the JSON path and the problem,
# and exit status 1; never a crash, never CLI11's own exit codes. Run as
#   cmake -DRPU=path/to/rpu -DBAD=tests/bad_scenes -DOUT=dir -P cli_errors.cmake
file(MAKE_DIRECTORY ${OUT})
set(failures 0)

function(expect_error label expected_list)
  # ARGN: the rpu command line.
  execute_process(COMMAND ${RPU} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 60)
  string(STRIP "${err}" err)
  set(ok TRUE)
  if(NOT rc STREQUAL "1")
    set(ok FALSE)  # 1 = user error, usage errors included; anything else fails
  endif()
  if(NOT err MATCHES "^rpu: error: ")
    set(ok FALSE)
  endif()
  foreach(part IN LISTS expected_list)
    string(FIND "${err}" "${part}" pos)
    if(pos EQUAL -1)
      set(ok FALSE)
    endif()
  endforeach()
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines nl)
  if(nl GREATER 0)
    set(ok FALSE)  # exactly one line
  endif()
  if(ok)
    message(STATUS "ok   ${label}: exit ${rc}: ${err}")
  else()
    message(STATUS "FAIL ${label}: exit ${rc}, stderr:\n${err}\nexpected to contain: ${expected_list}")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  endif()
endfunction()

file(STRINGS ${BAD}/expected.txt lines)
set(count 0)
foreach(line IN LISTS lines)
  string(REPLACE "\t" ";" fields "${line}")
  list(GET fields 0 name)
  list(GET fields 1 path)
  list(GET fields 2 problem)
  foreach(backend float float-ip)
    expect_error("${name} (${backend})" "${name};${path};${problem}"
                 render ${BAD}/${name} --backend ${backend} -o ${OUT}/bad.png)
  endforeach()
  math(EXPR count "${count} + 1")
endforeach()

expect_error("missing file" "no_such_scene.json" render ${BAD}/no_such_scene.json -o ${OUT}/x.png)
expect_error("unknown builtin" "builtin:nope;no such built-in scene" render builtin:nope -o ${OUT}/x.png)
expect_error("n not a multiple of n1" "--n;not a multiple of n1"
             render builtin:ellipse6 --n 16 --n1 3 -o ${OUT}/x.png)
expect_error("n1 too large" "--n1;bits per step" config --n 18 --n1 9)
expect_error("surfaces' first step not a name or number" "--surf-n1-first;must be seed or an integer, got 'wide'"
             config --surf-n1-first wide)
expect_error("surfaces' first step too wide" "--surf-n1-first;first-step bits must be in [1, 10], got 11"
             render builtin:surf_ellipsoid --backend float-ip --surf-n1-first 11 -o ${OUT}/x.png)
expect_error("sqrt width name unknown" "--sqrt-w;must be exact or an integer, got 'tight'"
             config --sqrt-w tight)
expect_error("unknown backend" "--backend;warp" render builtin:ellipse6 --backend warp -o ${OUT}/x.png)
# Patches (docs/algorithms.md §4): the fixed-point model and the RTL have no path for them; bad
# patch flags.
# A build without the surface path refuses a scene with surfaces (never an image without them).
expect_error("surfaces off, ref" "builtin:surf_mix: surfaces;2 surfaces;no surface path (--surfaces off)"
             render builtin:surf_mix --backend ref --surfaces off -o ${OUT}/x.png)
expect_error("patches on ref" "builtin:column: patches;the ref backend has no fixed-point path"
             render builtin:column --backend ref --size 16x16 -o ${OUT}/x.png)
expect_error("patches on rtl" "builtin:column: patches;the rtl backend has no fixed-point path"
             render builtin:column --backend rtl --size 16x16 -o ${OUT}/x.png)
# A scene with surfaces and patches: ref renders surfaces, so the patches are named.
expect_error("surfaces and patches on ref" "surface_and_patch.json: patches;the ref backend has no fixed-point path"
             render ${BAD}/../scenes/surface_and_patch.json --backend ref --size 16x16 -o ${OUT}/x.png)
expect_error("unknown patch method" "--patch-method;unknown patch method 'bisection'"
             render builtin:teapot --patch-method bisection -o ${OUT}/x.png)
expect_error("bad patch start" "--patch-start;must be map or random"
             render builtin:teapot --patch-start grid -o ${OUT}/x.png)
expect_error("bad patch map size" "--patch-map-size;must be WxH"
             render builtin:teapot --patch-map-size 512 -o ${OUT}/x.png)
expect_error("bad patch tolerance" "--patch-tolerance;must be in (0, 1] pixels"
             render builtin:teapot --patch-tolerance 0 -o ${OUT}/x.png)
expect_error("unknown image format" "x.nosuchformat;image format"
             render builtin:ellipse6 -o ${OUT}/x.nosuchformat)
expect_error("unwritable output" "no_dir/x.png;does not exist"
             render builtin:ellipse6 -o ${OUT}/no_dir/x.png)
expect_error("usage: missing output" "command line: ;--output is required" render builtin:ellipse6)
expect_error("usage: unknown flag" "command line: ;--frobnicate" render builtin:ellipse6 --frobnicate -o ${OUT}/x.png)
expect_error("usage: not a number" "command line: ;--n" config --n sixteen)
expect_error("bad metric" "--metric;abs or squared" render builtin:ellipse6 --backend ref --metric cube -o ${OUT}/x.png)
expect_error("bad ip mode" "--ip;unrolled or iterative" config --ip sideways)
expect_error("coord_w too small for the scene" "builtin:airfield: textures;coord_w = 12 is too small"
             render builtin:airfield --backend ref --coord-w 12 -o ${OUT}/x.png)
expect_error("product too wide" "--t-frac;limit 126" config --coord-w 40 --t-frac 48)

# And the good paths: every backend renders, `config` prints the parameter set.
foreach(backend float float-ip ref)
  execute_process(COMMAND ${RPU} render builtin:polyline9 --backend ${backend} -q -o ${OUT}/ok_${backend}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/ok_${backend}.png)
    message(STATUS "FAIL render --backend ${backend}: exit ${rc}: ${err}")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
execute_process(COMMAND ${RPU} config --n 12 --n1 3 --ip iterative RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "K          = 4" OR NOT out MATCHES "iterative")
  message(STATUS "FAIL config: exit ${rc}: ${out}")
  math(EXPR failures "${failures} + 1")
endif()

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} CLI error case(s) failed")
endif()
message(STATUS "${count} bad scene files and 14 bad command lines rejected cleanly; every backend renders")
