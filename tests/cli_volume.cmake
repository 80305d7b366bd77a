# `rpu volume` (issue 13, item 5): the three volume estimates of a closed Bézier model, and one
# line "rpu: error: <where>: <problem>" with exit status 1 for every scene it cannot measure. Run as
#   cmake -DRPU=path/to/rpu -DSCENES=tests/scenes -P cli_volume.cmake
set(failures 0)

function(run_rpu)
  execute_process(COMMAND ${RPU} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 60)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  string(STRIP "${err}" err)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(fail label detail)
  message(STATUS "FAIL ${label}: ${detail}")
  math(EXPR n "${failures} + 1")
  set(failures ${n} PARENT_SCOPE)
endfunction()

# Output: each listed regex must match stdout, exit 0.
function(expect_output label regexes)
  run_rpu(${ARGN})
  set(ok TRUE)
  if(NOT rc STREQUAL "0")
    set(ok FALSE)
  endif()
  foreach(re IN LISTS regexes)
    if(NOT out MATCHES "${re}")
      set(ok FALSE)
      message(STATUS "     missing: ${re}")
    endif()
  endforeach()
  if(ok)
    message(STATUS "ok   ${label}")
  else()
    fail("${label}" "exit ${rc}, stdout:\n${out}\nstderr:\n${err}")
    set(failures ${failures} PARENT_SCOPE)
  endif()
endfunction()

function(expect_error label parts)
  run_rpu(${ARGN})
  set(ok TRUE)
  if(NOT rc STREQUAL "1" OR NOT err MATCHES "^rpu: error: " OR err MATCHES "\n")
    set(ok FALSE)
  endif()
  foreach(part IN LISTS parts)
    string(FIND "${err}" "${part}" pos)
    if(pos EQUAL -1)
      set(ok FALSE)
    endif()
  endforeach()
  if(ok)
    message(STATUS "ok   ${label}: ${err}")
  else()
    fail("${label}" "exit ${rc}, stderr:\n${err}\nexpected to contain: ${parts}")
    set(failures ${failures} PARENT_SCOPE)
  endif()
endfunction()

# The Bézier sphere: its exact volume (5168·√2 − 5108)/525 = 4.191725124465..., the second exact
# route agreeing to rounding, graphical integration and slices with their errors.
expect_output("sphere" "closed, normals outward;exact, Bernstein integrals \\(eqs 21, 25-27\\) +4\\.19172512446[45] +\\(reference\\);exact check, Gauss-Legendre[^\n]* 4\\.19172512446[45] +[-+][0-9.]+e-1[0-9] %;graphical 10x10 \\(eq 23, midpoint nodes\\) +4\\.18[0-9]+ +-[0-9.]+e-02 %;graphical 100x100 \\(eq 23, midpoint nodes\\) +4\\.1916[0-9]+ +-[0-9.]+e-04 %;slices: trapezoid, 10 intervals along z +4\\.1[0-9]+ +-[0-9.]+e\\+00 %;slices: Cavalieri, 10 slabs"
              volume builtin:bezier_sphere)
expect_output("sphere --slices 40" "slices: trapezoid, 40 intervals along z +4\\.1[0-9]+ +-[0-9.]+e-02 %"
              volume builtin:bezier_sphere --slices 40)
# Inward normals: the same cube, signs flipped and said so.
expect_output("inward cube" "normals inward;exact, Bernstein[^\n]* 1\\.000000000000 +\\(reference\\)"
              volume ${SCENES}/volume_cube_inward.json)
# An open model prints with --no-closure-check (and a warning), is refused without it.
run_rpu(volume ${SCENES}/volume_open.json --no-closure-check)
if(NOT rc STREQUAL "0" OR NOT err MATCHES "^rpu: warning: .*do not close a volume" OR
   NOT out MATCHES "NOT closed")
  fail("open --no-closure-check" "exit ${rc}, stdout:\n${out}\nstderr:\n${err}")
else()
  message(STATUS "ok   open --no-closure-check")
endif()

# The teapot without handle and spout: the flat gap between lid and rim is capped by its plane.
expect_output("teapot body" "closed \\(capped by planes z = const at 8 open edges\\), normals inward;exact, Bernstein[^\n]* 25\\.25114594342[89] +\\(reference\\);Gauss-Legendre of \\(1/3\\) S\\.n \\+ caps +25\\.25114594342[89] "
              volume ${SCENES}/volume_teapot_body.json --planar-openings)
expect_error("teapot body without --planar-openings" "volume_teapot_body.json: patches;do not close a volume;--planar-openings"
             volume ${SCENES}/volume_teapot_body.json)
expect_error("whole teapot" "builtin:teapot: patches[12];does not lie in a plane z = const"
             volume builtin:teapot --planar-openings)
expect_error("open model" "volume_open.json: patches;meets no other patch edge;do not close a volume"
             volume ${SCENES}/volume_open.json)
expect_error("flipped face" "volume_cube_flipped_face.json: patches;patches[3];oriented inconsistently"
             volume ${SCENES}/volume_cube_flipped_face.json)
expect_error("b-spline" "volume_bspline.json: patches[0];B-spline;Bézier patches only"
             volume ${SCENES}/volume_bspline.json)
expect_error("no patches" "builtin:curve12;has no patches" volume builtin:curve12)
expect_error("missing file" "no_such_scene.json" volume ${SCENES}/no_such_scene.json)
expect_error("slices 0" "--slices;out of range" volume builtin:bezier_sphere --slices 0)
expect_error("slice grid" "--slice-grid;out of range" volume builtin:bezier_sphere --slice-grid 0)
expect_error("no scene" "command line" volume)

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} rpu volume check(s) failed")
endif()
