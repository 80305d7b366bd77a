# The CLI's contract for hostile input and failing disks (issue 11): every failure is one line
# "rpu: error: <where>: <problem>" with exit 1; outputs are never partial, never written through
# a symlink or over the input. Run as
#   cmake -DRPU=path/to/rpu -DOUT=dir -DMODE=inputs|limits|outputs|compare|scale -P cli_io.cmake
# (needs sh, mkfifo and ln, as every Linux build host has).
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(failures 0)
include(${CMAKE_CURRENT_LIST_DIR}/cli_verdict.cmake)

# run(label rc regex...) -- ARGN after "--": the rpu command line. rc is the exit status wanted;
# every regex must match stderr. For rc 1, stderr must be exactly one "rpu: error: " line.
function(run label want_rc)
  rpu_cli_split(regexes args ${ARGN})
  execute_process(COMMAND ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 60)
  rpu_cli_verdict("${label}" "${want_rc}" "${rc}" "${err}" ${regexes})
  set(failures ${failures} PARENT_SCOPE)
endfunction()

# expect(label "condition"): the condition is evaluated as if(condition) in the caller's scope.
function(expect label condition)
  cmake_language(EVAL CODE "if(${condition})\n set(holds TRUE)\nelse()\n set(holds FALSE)\nendif()")
  if(holds)
    message(STATUS "ok   ${label}")
  else()
    message(STATUS "FAIL ${label}")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  endif()
endfunction()

# The names in a directory (hidden ones included), sorted, as a ;-list in `var`.
function(list_dir dir var)
  file(GLOB names RELATIVE ${dir} LIST_DIRECTORIES true ${dir}/* ${dir}/.*)
  list(SORT names)
  set(${var} "${names}" PARENT_SCOPE)
endfunction()

set(SCENE ${SRC}/scenes/polyline9.json)
# sh -c 'ulimit -f BLOCKS; exec rpu ...': a file-size limit, as on a quota'd cluster.
set(LIMITED sh -c "ulimit -f 1 && exec \"$0\" \"$@\"" ${RPU})

if(MODE STREQUAL "inputs")
  # Item 3: only regular files are read; nothing blocks or grows without bound.
  execute_process(COMMAND mkfifo ${OUT}/fifo.json)
  file(MAKE_DIRECTORY ${OUT}/dir.json)
  run("/dev/zero" 1 "/dev/zero: is not a regular file" -- ${RPU} render /dev/zero -o ${OUT}/x.png)
  run("fifo" 1 "fifo.json: is not a regular file" -- ${RPU} render ${OUT}/fifo.json -o ${OUT}/x.png)
  run("directory" 1 "dir.json: is a directory" -- ${RPU} render ${OUT}/dir.json -o ${OUT}/x.png)
  run("/proc/self/mem" 1 "/proc/self/mem: cannot read the scene file" -- ${RPU} render /proc/self/mem -o ${OUT}/x.png)
  # Item 12: command-line errors are one line, exit 1; --help still prints help, exit 0.
  run("unknown flag" 1 "rpu: error: command line: .*--bogus" -- ${RPU} render builtin:curve12 --bogus -o ${OUT}/x.png)
  run("bad number" 1 "rpu: error: command line: .*--n" -- ${RPU} render builtin:curve12 --n abc -o ${OUT}/x.png)
  run("missing -o" 1 "rpu: error: command line: .*required" -- ${RPU} render builtin:curve12)
  run("no subcommand" 1 "rpu: error: command line: " -- ${RPU})
  execute_process(COMMAND ${RPU} render --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect("--help exits 0 with the usage" "rc EQUAL 0 AND out MATCHES \"Usage\"")
  # Item 12: a scene named with invalid UTF-8 is compared, not an internal error.
  execute_process(COMMAND sh -c "cp \"$1\" \"$2/$(printf 'sc\\377ne.json')\"" sh ${SCENE} ${OUT})
  file(GLOB odd ${OUT}/sc*ne.json)
  run("non-UTF-8 scene name" 0 "report" -- ${RPU} compare ${odd} --no-rtl --max-side 32 --out ${OUT}/odd)
  expect("non-UTF-8 scene name: metrics.json written" "EXISTS ${OUT}/odd/metrics.json")
elseif(MODE STREQUAL "limits")
  # Items 4 and 5: one image-size limit for scene files, --size and --max-side; bounded threads.
  run("--size too many pixels" 1 "--size: image size 16384x16384 is too large" -- ${RPU} render builtin:curve12 --size 16384x16384 -o ${OUT}/x.png)
  run("--size huge" 1 "--size: .*out of range" -- ${RPU} render builtin:curve12 --size 99999999999999999999x2 -o ${OUT}/x.png)
  run("--size zero" 1 "--size: image size 0x4 is out of range" -- ${RPU} render builtin:curve12 --size 0x4 -o ${OUT}/x.png)
  run("--size syntax" 1 "--size: must be WxH" -- ${RPU} render builtin:curve12 --size 4x4x4 -o ${OUT}/x.png)
  run("--max-side negative" 1 "--max-side: must be at least 1" -- ${RPU} render builtin:curve12 --max-side -2 -o ${OUT}/x.png)
  run("--threads huge" 1 "--threads: must be in \\[0, 1024\\]" -- ${RPU} render builtin:curve12 --threads 2147483647 -o ${OUT}/x.png)
  run("--threads negative" 1 "--threads: must be in \\[0, 1024\\]" -- ${RPU} render builtin:curve12 --threads -1 -o ${OUT}/x.png)
  run("config --threads" 1 "--threads: must be in" -- ${RPU} config --threads 5000)
  run("--threads 1024 renders" 0 "" -- ${RPU} render builtin:curve12 --size 8x8 --threads 1024 -q -o ${OUT}/ok.png)
elseif(MODE STREQUAL "outputs")
  # Item 6: outputs are regular files, written whole or not at all.
  file(MAKE_DIRECTORY ${OUT}/d.png)
  file(CREATE_LINK /dev/full ${OUT}/full.png SYMBOLIC)
  run("-o directory" 1 "d.png: is a directory" -- ${RPU} render builtin:curve12 -o ${OUT}/d.png)
  run("-o symlink to /dev/full" 1 "full.png: is not a regular file" -- ${RPU} render builtin:curve12 -o ${OUT}/full.png)
  # The device itself: named as a device, not as an unknown image format.
  run("-o /dev/full" 1 "/dev/full: is not a regular file" -- ${RPU} render builtin:curve12 -o /dev/full)
  file(MAKE_DIRECTORY ${OUT}/limited)
  foreach(ext png exr ppm)
    run("file-size limit .${ext}" 1 "x.${ext}: cannot write the file: File too large"
        -- ${LIMITED} render builtin:curve12 -o ${OUT}/limited/x.${ext})
  endforeach()
  list_dir(${OUT}/limited left)
  expect("file-size limit: no partial file or temporary (${left})" "\"${left}\" STREQUAL \"\"")
  # The input is never the output.
  file(COPY_FILE ${SCENE} ${OUT}/scene.ppm)
  run("-o the scene file" 1 "scene.ppm: is the scene file" -- ${RPU} render ${OUT}/scene.ppm -o ${OUT}/scene.ppm)
  file(SHA256 ${SCENE} want)
  file(SHA256 ${OUT}/scene.ppm got)
  expect("-o the scene file: scene intact" "want STREQUAL got")
  # Item 8: the waveform's place is checked before the (long) co-simulation.
  foreach(case "missing/p.fst|does not exist" "d.png|is a directory" "full.png|is not a regular file")
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 target)
    list(GET parts 1 msg)
    run("--trace-out ${target}" 1 "${msg}" -- ${RPU} render builtin:curve12 --backend rtl --size 16x16
        --trace-pixel 8,8 --trace-out ${OUT}/${target} -o ${OUT}/t.png)
  endforeach()
elseif(MODE STREQUAL "compare")
  set(common --no-rtl --max-side 32 -q)
  # Item 7: the scene file as DIR/metrics.json is refused, untouched.
  file(MAKE_DIRECTORY ${OUT}/self)
  file(COPY_FILE ${SCENE} ${OUT}/self/metrics.json)
  run("scene is DIR/metrics.json" 1 "metrics.json: is the scene file being compared"
      -- ${RPU} compare ${OUT}/self/metrics.json --out ${OUT}/self ${common})
  file(SHA256 ${SCENE} want)
  file(SHA256 ${OUT}/self/metrics.json got)
  expect("scene intact" "want STREQUAL got")
  # A symlink named ref.png is replaced, its target outside untouched; stale rtl outputs go;
  # --no-rtl exits 0 (item 12).
  file(MAKE_DIRECTORY ${OUT}/cmp)
  file(WRITE ${OUT}/outside.png "outside\n")
  file(CREATE_LINK ${OUT}/outside.png ${OUT}/cmp/ref.png SYMBOLIC)
  file(WRITE ${OUT}/cmp/rtl.png "stale")
  file(WRITE ${OUT}/cmp/rtl_x8.png "stale")
  file(WRITE ${OUT}/cmp/diff_rtl_vs_ref.png "stale")
  file(WRITE ${OUT}/cmp/notes.txt "mine")
  run("--no-rtl rerun" 0 "" -- ${RPU} compare builtin:polyline9 --out ${OUT}/cmp ${common})
  file(READ ${OUT}/outside.png outside)
  expect("symlink target untouched" "outside STREQUAL \"outside\n\"")
  expect("ref.png replaced" "NOT IS_SYMLINK ${OUT}/cmp/ref.png AND EXISTS ${OUT}/cmp/ref.png")
  expect("stale rtl outputs removed" "NOT EXISTS ${OUT}/cmp/rtl.png AND NOT EXISTS ${OUT}/cmp/rtl_x8.png AND NOT EXISTS ${OUT}/cmp/diff_rtl_vs_ref.png")
  expect("other files kept" "EXISTS ${OUT}/cmp/notes.txt")
  # (an empty argument cannot pass through a CMake list: sh supplies it)
  run("--out empty" 1 "rpu: error: --out: " -- sh -c "exec \"$0\" compare builtin:polyline9 --out '' --no-rtl" ${RPU})
  run("--out a file" 1 "outside.png: exists and is not a directory" -- ${RPU} compare builtin:polyline9 --out ${OUT}/outside.png ${common})
  # Item 6: a failed compare leaves nothing behind.
  run("compare under a file-size limit" 1 "File too large" -- ${LIMITED} compare builtin:curve12 --out ${OUT}/limited ${common})
  list_dir(${OUT}/limited left)
  expect("failed compare: no partial outputs (${left})" "\"${left}\" STREQUAL \"\"")
  # demo --out: one line, exit 1.
  run("demo --out FILE" 1 "outside.png: exists and is not a directory" -- ${RPU} demo --out ${OUT}/outside.png --no-rtl)
  run("demo --out empty" 1 "--out: " -- sh -c "exec \"$0\" demo --out '' --no-rtl" ${RPU})
  # Item 9: ref vs float-ip beyond the documented bound: a warning line, the metric, exit 0.
  run("ref vs float-ip beyond the bound" 0
      "rpu: warning: builtin:curve12: ref differs from float-ip on [0-9]+ of [0-9]+ hit pixels \\([0-9.]+ %\\), beyond the documented bound of 0.1 %"
      -- ${RPU} compare builtin:curve12 --inv-w 8 --no-rtl --max-side 64 -q --out ${OUT}/bound)
  file(READ ${OUT}/bound/metrics.json metrics)
  expect("metrics.json: ref_vs_float_ip_beyond_bound" "metrics MATCHES \"\\\"ref_vs_float_ip_beyond_bound\\\": true\"")
  file(READ ${OUT}/bound/report.html html)
  expect("report.html: warning banner" "html MATCHES \"banner warn\"")
  run("ref vs float-ip within the bound: no warning" 0 "" -- ${RPU} compare builtin:curve12 --no-rtl --max-side 64 -q --out ${OUT}/bound_ok)
elseif(MODE STREQUAL "flags")
  # Flags that do not apply are refused with one line naming the flag (issue 20, item 4).
  set(img ${OUT}/f.png)
  run("--shade with ref" 1 "rpu: error: --shade: applies to --backend float and float-ip only"
      -- ${RPU} render builtin:surf_rocket --backend ref --size 8x8 --shade -o ${img})
  run("--shade with rtl" 1 "rpu: error: --shade: applies to --backend float and float-ip only"
      -- ${RPU} render builtin:curve12 --backend rtl --size 8x8 --shade -o ${img})
  run("--shade without surfaces or patches" 1
      "rpu: error: --shade: changes nothing: builtin:curve12 has no surfaces or patches"
      -- ${RPU} render builtin:curve12 --size 8x8 --shade -o ${img})
  run("--shade on surfaces, float" 0 "" -- ${RPU} render builtin:surf_rocket --size 8x8 --shade -q -o ${img})
  foreach(flag "--size;8x8" "--max-side;8" "--trace-pixel;1,1" "--trace-out;t.fst" "--systemc"
               "--rtl-fault" "--patch-method;martin" "--patch-map-size;8x8" "--patch-map-full"
               "--patch-start;random" "--patch-tolerance;0.5" "--patch-iterations;9")
    list(GET flag 0 name)
    run("config ${name}" 1 "rpu: error: ${name}: does not apply to rpu config: it prints the parameter set"
        -- ${RPU} config ${flag})
  endforeach()
  run("config with hardware flags" 0 "" -- ${RPU} config --n 12 --n1 3 --threads 2 --no-binning)
  # The candidate count is stated one way (docs/algorithms.md §1.2).
  execute_process(COMMAND ${RPU} config --n 12 --n1 3 OUTPUT_VARIABLE cfg)
  expect("config: 8 sub-intervals, 9 candidate points, 7 new"
         "cfg MATCHES \"per step   = 8 sub-intervals, 9 candidate points \\\\(7 new after the first step\\\\)\"")
  # The surfaces' schedule: the default first step, and the seed's by name (docs/surfaces.md).
  execute_process(COMMAND ${RPU} config OUTPUT_VARIABLE cfg)
  expect("config: the default surface search"
         "cfg MATCHES \"surf steps = 7,2,2,2,2,1 \\\\(bits per step\\\\), 142 indicator evaluations\"")
  execute_process(COMMAND ${RPU} config --surf-n1-first seed OUTPUT_VARIABLE cfg)
  expect("config: the seed's surface search by name"
         "cfg MATCHES \"surf steps = 2,2,2,2,2,2,2,2 \\\\(bits per step\\\\), 26 indicator evaluations\"")
  foreach(flag "--trace-pixel;1,1" "--trace-out;t.fst" "--rtl-fault" "--rtl-fault=far-hit")
    list(GET flag 0 name)
    string(REGEX REPLACE "=.*" "" name "${name}")
    run("demo ${name}" 1 "rpu: error: ${name}: does not apply to rpu demo: it compares every built-in scene"
        -- ${RPU} demo --no-rtl --out ${OUT}/demo ${flag})
  endforeach()
  expect("a refused demo wrote nothing" "NOT EXISTS ${OUT}/demo")
  # Lossy image formats cannot hold the exact colours.
  foreach(ext jpg JPEG webp gif hdr)
    run("-o x.${ext}" 1 "rpu: error: ${OUT}/x.${ext}: .* cannot hold the image's exact colours"
        -- ${RPU} render builtin:curve12 --size 8x8 -o ${OUT}/x.${ext})
  endforeach()
  foreach(ext png exr ppm tif)
    run("-o x.${ext}" 0 "" -- ${RPU} render builtin:curve12 --size 8x8 -q -o ${OUT}/x.${ext})
  endforeach()
  # A comparison that did not run says n/a, never null.
  run("compare --no-rtl: rtl vs ref n/a" 0 "rtl vs ref n/a, ref vs float-ip [0-9]+ px"
      -- ${RPU} compare builtin:polyline9 --no-rtl --max-side 16 --out ${OUT}/cmp)
  run("compare of a patch scene: n/a" 0 "rtl vs ref n/a, ref vs float-ip n/a, ref vs float n/a, float-ip vs float [0-9]+ px"
      -- ${RPU} compare builtin:torus --no-rtl --max-side 16 --out ${OUT}/cmp_patch)
elseif(MODE STREQUAL "scale")
  # Item 2: a million empty objects (3 MB) parse in linear time (the test's TIMEOUT bounds it).
  string(REPEAT "{}," 999999 objects)
  file(WRITE ${OUT}/million.json "{\"camera\": {\"eye\": [0, -12, 6], \"target\": [0, 0, 0], \"up\": [0, 0, 1], \"fov_deg\": 40, \"width\": 8, \"height\": 8}, \"curves\": [${objects}{}]}")
  string(TIMESTAMP t0 "%s")
  run("1e6 {} in curves" 1 "million.json: curves\\[0\\]: missing required key 'points'" -- ${RPU} render ${OUT}/million.json -o ${OUT}/x.png)
  string(TIMESTAMP t1 "%s")
  math(EXPR dt "${t1} - ${t0}")
  message(STATUS "1e6 {} refused in about ${dt} s (rpu's start-up included)")
  string(REPEAT "[" 1000000 deep)
  file(WRITE ${OUT}/deep.json "{\"about\": ${deep}")
  run("1e6 nested arrays" 1 "deep.json: about.*nested too deeply" -- ${RPU} render ${OUT}/deep.json -o ${OUT}/x.png)
else()
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} case(s) failed")
endif()
