# Whole frames through the Verilated rpu_top, every work item and pixel checked against the
# model (`rpu compare` / `rpu render --backend rtl`): every demo scene at 64×64 and at a
# non-square size for the defaults, and at 64×64 for the iterative form and two other (n, n1)
# pairs; the SystemC harness against the C++ one; the checker's own test (a fault-injected build
# must be caught and reported with the pixel); --trace-pixel; and the co-simulation's bad input.
set(RPU_RUN ${PROJECT_SOURCE_DIR}/tests/rpu_run.cmake)
set(RPU_CMP_OUT ${CMAKE_CURRENT_BINARY_DIR}/compare)
set(rtl_tests "")
foreach(scene curve12 ellipse6 polyline9 airfield)
  add_test(NAME rtl_compare_${scene}_64 COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
           "-DARGS=compare;builtin:${scene};--size;64x64;--out;${RPU_CMP_OUT}/${scene}_64"
           -DEXPECT_RC=0 "-DEXPECT_ERR=PASS: report"
           "-DFILES=${RPU_CMP_OUT}/${scene}_64/metrics.json;${RPU_CMP_OUT}/${scene}_64/report.html"
           -P ${RPU_RUN})
  add_test(NAME rtl_compare_${scene}_72x40 COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
           "-DARGS=compare;builtin:${scene};--size;72x40;--out;${RPU_CMP_OUT}/${scene}_72x40"
           -DEXPECT_RC=0 "-DEXPECT_ERR=PASS: report" -P ${RPU_RUN})
  list(APPEND rtl_tests rtl_compare_${scene}_64 rtl_compare_${scene}_72x40)
  set(cfgs "iterative|--ip|iterative" "n8_n1_1|--n|8|--n1|1|--surfaces|off")
  if(RPU_SIM_EXTRA)  # the (12, 3) iterative configuration is opt-in (sim/harness/CMakeLists.txt)
    list(APPEND cfgs "n12_n1_3_iterative|--n|12|--n1|3|--ip|iterative")
  endif()
  foreach(c IN LISTS cfgs)
    string(REPLACE "|" ";" cfg "${c}")
    list(POP_FRONT cfg name)
    add_test(NAME rtl_render_${scene}_64_${name} COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
             "-DARGS=render;builtin:${scene};--size;64x64;--backend;rtl;${cfg};-o;${RPU_CMP_OUT}/${scene}_${name}.png"
             -DEXPECT_RC=0 "-DEXPECT_ERR=rtl \\(c\\+\\+ harness" -DNOT_ERR=MISMATCH -P ${RPU_RUN})
    list(APPEND rtl_tests rtl_render_${scene}_64_${name})
  endforeach()
endforeach()

# The texture path at full resolution (64,489 texture work items of the airfield).
add_test(NAME rtl_compare_airfield_full COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;builtin:airfield;--out;${RPU_CMP_OUT}/airfield_full"
         -DEXPECT_RC=0 "-DEXPECT_ERR=PASS: report" -P ${RPU_RUN})
list(APPEND rtl_tests rtl_compare_airfield_full)

# Issue 11, items 9 and 10 through the RTL: a camera 5,000 units from the curve (the model keeps
# its hits and warns, naming the widths) and curves exactly on the centre pixel edges.
add_test(NAME rtl_compare_far_camera COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;${PROJECT_SOURCE_DIR}/tests/scenes/far_camera.json;--out;${RPU_CMP_OUT}/far_camera"
         -DEXPECT_RC=0
         "-DEXPECT_ERR=rpu: warning: [^\n]*far_camera.json: a pixel spans only [0-9]+ position LSBs[^\n]*raise --coord-w 29 and --dir-frac 29;PASS: report"
         -P ${RPU_RUN})
add_test(NAME rtl_compare_pixel_edge COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;${PROJECT_SOURCE_DIR}/tests/scenes/pixel_edge.json;--out;${RPU_CMP_OUT}/pixel_edge"
         -DEXPECT_RC=0 "-DEXPECT_ERR=rtl vs ref 0 px, ref vs float-ip 0 px;PASS: report" -DNOT_ERR=warning
         -P ${RPU_RUN})
# Round texture joins and a straight curve ("join": "round", "smooth": false) through the RTL.
add_test(NAME rtl_compare_star_joins COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;${PROJECT_SOURCE_DIR}/tests/scenes/star_joins.json;--out;${RPU_CMP_OUT}/star_joins"
         -DEXPECT_RC=0 "-DEXPECT_ERR=rtl vs ref 0 px, ref vs float-ip 0 px;PASS: report"
         -P ${RPU_RUN})
# All three kinds through the RTL: surf_mix's curve, texture, relief ellipsoid and rocket, every
# item and pixel equal to the model (iterative form: its smaller model simulates faster; a
# surface piece takes the ring 142 cycles, so the frame is small).
add_test(NAME rtl_compare_surf_mix COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;builtin:surf_mix;--size;20x20;--ip;iterative;--out;${RPU_CMP_OUT}/surf_mix"
         -DEXPECT_RC=0
         "-DEXPECT_ERR=rtl [^\n]*[1-9][0-9]* hit pixels, [0-9]+ pairs\n;rtl vs ref 0 px;PASS: report"
         "-DFILES=${RPU_CMP_OUT}/surf_mix/metrics.json;${RPU_CMP_OUT}/surf_mix/diff_rtl_vs_ref.png"
         -P ${RPU_RUN})
list(APPEND rtl_tests rtl_compare_far_camera rtl_compare_pixel_edge rtl_compare_star_joins
     rtl_compare_surf_mix)

# Frame-parallel co-simulation: --jobs and --shard/--merge-shards give the one-instance image.
add_test(NAME rtl_frame_parallel COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         -DOUT=${RPU_CMP_OUT}/frame_parallel "-DARGS=builtin:curve12;--size;40x40"
         -P ${PROJECT_SOURCE_DIR}/tests/rtl_shards.cmake)
list(APPEND rtl_tests rtl_frame_parallel)

# The main job's command at a small size: every scene compared concurrently, the index written.
add_test(NAME rtl_demo COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=demo;--max-side;40;--surface-max-side;8;--out;${RPU_CMP_OUT}/demo"
         -DEXPECT_RC=0 "-DEXPECT_ERR=builtin:curve12 \\(40x40\\): PASS;builtin:airfield \\(40x30\\): PASS;builtin:surf_snail \\(8x8\\): PASS, rtl == ref"
         "-DFILES=${RPU_CMP_OUT}/demo/index.html;${RPU_CMP_OUT}/demo/summary.md;${RPU_CMP_OUT}/demo/ellipse6/metrics.json"
         -P ${RPU_RUN})
list(APPEND rtl_tests rtl_demo)

# The SystemC harness: same image and cycle count as the C++ harness (iterative defaults).
if(TARGET rpu_sc)
  foreach(scene curve12 airfield)
    add_test(NAME rtl_systemc_${scene} COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
             -DOUT=${RPU_CMP_OUT}/systemc_${scene}
             "-DARGS=builtin:${scene};--size;40x32;--ip;iterative"
             -P ${PROJECT_SOURCE_DIR}/tests/rtl_systemc.cmake)
    list(APPEND rtl_tests rtl_systemc_${scene})
  endforeach()
  # Surfaces through the SystemC harness too (surface RAM writes, surface items and results).
  add_test(NAME rtl_systemc_surf_mix COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
           -DOUT=${RPU_CMP_OUT}/systemc_surf_mix "-DARGS=builtin:surf_mix;--size;8x8;--ip;iterative"
           -P ${PROJECT_SOURCE_DIR}/tests/rtl_systemc.cmake)
  list(APPEND rtl_tests rtl_systemc_surf_mix)
endif()

# The comparison can fail: the argmin tie rule flipped in the RTL (--rtl-fault, argmin-tie) must
# give exit status 2 and a mismatch report naming the pixel, the item and the model's stages.
add_test(NAME rtl_fault_is_caught COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;builtin:curve12;--size;48x48;--n;8;--n1;1;--ip;iterative;--rtl-fault;--out;${RPU_CMP_OUT}/fault"
         -DEXPECT_RC=2
         "-DEXPECT_ERR=MISMATCH: pixel \\([0-9]+,[0-9]+\\) work item [0-9]+;model stages:;IP step 1: sums;FAIL: report"
         "-DFILES=${RPU_CMP_OUT}/fault/report.html" -P ${RPU_RUN})
# A fault that changes the image and no work item: the resolve keeps the farther hit
# (--rtl-fault=far-hit). The image differs from the model's, the pixel is named, exit status 2.
add_test(NAME rtl_fault_pixel_is_caught COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=compare;builtin:curve12;--size;48x48;--n;8;--n1;1;--ip;iterative;--rtl-fault=far-hit;--out;${RPU_CMP_OUT}/fault_pixel"
         -DEXPECT_RC=2
         "-DEXPECT_ERR=rtl vs ref [1-9][0-9]* px;MISMATCH: pixel \\([0-9]+,[0-9]+\\) resolve\n  expected pixel [^\n]* depth [0-9]+ primitive [0-9]+\n  actual ;FAIL: report"
         "-DNOT_ERR=work item" -P ${RPU_RUN})
list(APPEND rtl_tests rtl_fault_pixel_is_caught)
# --trace-pixel writes a waveform of that pixel's work items.
add_test(NAME rtl_trace_pixel COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=render;builtin:curve12;--size;32x32;--backend;rtl;--trace-pixel;16,9;--trace-out;${RPU_CMP_OUT}/p16_9.fst;-o;${RPU_CMP_OUT}/trace.png"
         -DEXPECT_RC=0 "-DEXPECT_ERR=pixel \\(16,9\\): [0-9]+ work items"
         "-DFILES=${RPU_CMP_OUT}/p16_9.fst" -P ${RPU_RUN})
# A surface piece's waveform, with the model's setup and search values of the piece.
add_test(NAME rtl_trace_pixel_surface COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=render;builtin:surf_rocket;--size;6x6;--backend;rtl;--trace-pixel;3,3;--trace-out;${RPU_CMP_OUT}/rocket_3_3.fst;-o;${RPU_CMP_OUT}/rocket_trace.png"
         -DEXPECT_RC=0 "-DEXPECT_ERR=pixel \\(3,3\\): 1 work items, [0-9]+ cycles, 0 item and 0 pixel mismatches;surface piece 0 of 1;surface setup: valid 1;search: hit"
         "-DFILES=${RPU_CMP_OUT}/rocket_3_3.fst" -P ${RPU_RUN})
# Under a file-size limit the FST writer would die of SIGBUS: refused up front, one line.
add_test(NAME rtl_trace_pixel_fsize_limit COMMAND ${CMAKE_COMMAND} -DRPU=sh
         "-DARGS=-c;ulimit -f 1 && exec \"$0\" \"$@\";$<TARGET_FILE:rpu>;render;builtin:curve12;--size;16x16;--backend;rtl;--trace-pixel;8,8;--trace-out;${RPU_CMP_OUT}/limited.fst;-o;${RPU_CMP_OUT}/limited.png"
         -DEXPECT_RC=1 "-DEXPECT_ERR=^rpu: error: --trace-pixel: waveforms need an unlimited file size"
         -P ${RPU_RUN})
list(APPEND rtl_tests rtl_fault_is_caught rtl_trace_pixel rtl_trace_pixel_surface
     rtl_trace_pixel_fsize_limit)

# A build without the surface path refuses a scene with surfaces before any cycle runs.
add_test(NAME rtl_bad_no_surfaces COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=render;builtin:surf_mix;--size;16x16;--backend;rtl;--n;8;--n1;1;--surfaces;off;-o;${RPU_CMP_OUT}/bad.png"
         -DEXPECT_RC=1 "-DEXPECT_ERR=no surface path \\(--surfaces off\\)" -P ${RPU_RUN})
list(APPEND rtl_tests rtl_bad_no_surfaces)

# Bad input to the co-simulation: one line, exit 1 ('~' separates arguments here).
foreach(bad "no_config|--size~16x16~--n~10~--n1~2|no Verilated rpu_top for n 10"
            "trace_syntax|--size~16x16~--trace-pixel~3-4|--trace-pixel: must be X,Y"
            "trace_range|--size~16x16~--trace-pixel~500,2|outside the 16x16 image"
            "systemc_unrolled|--size~16x16~--systemc|--systemc: the SystemC model is built"
            "size_syntax|--size~16by16|--size: must be WxH"
            "fault_name|--size~16x16~--rtl-fault=bogus|--rtl-fault: unknown fault 'bogus' \\(argmin-tie, far-hit\\)"
            "axi_no_config|--size~16x16~--axi|--axi: no Verilated rpu_top in its AXI shell for n 16"
            "axi_systemc|--size~16x16~--ip~iterative~--axi~--systemc|--axi: cannot be combined with --systemc")
  string(REPLACE "|" ";" parts "${bad}")
  list(GET parts 0 name)
  list(GET parts 1 flags)
  list(GET parts 2 msg)
  string(REPLACE "~" ";" flags "${flags}")
  add_test(NAME rtl_bad_${name} COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
           "-DARGS=render;builtin:curve12;--backend;rtl;${flags};-o;${RPU_CMP_OUT}/bad.png"
           -DEXPECT_RC=1 "-DEXPECT_ERR=${msg}" -P ${RPU_RUN})
  list(APPEND rtl_tests rtl_bad_${name})
endforeach()
add_test(NAME rtl_bad_axi_ref COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
         "-DARGS=render;builtin:curve12;--backend;ref;--axi;--size;16x16;-o;${RPU_CMP_OUT}/bad.png"
         -DEXPECT_RC=1 "-DEXPECT_ERR=--axi: applies to --backend rtl only" -P ${RPU_RUN})
list(APPEND rtl_tests rtl_bad_axi_ref)

# Through the AXI shell (--axi): the same image as through rpu_top alone, and the same cycle count
# plus the shell's latency (docs/axi.md), on all three kinds (surf_mix) and on curves.
foreach(scene surf_mix curve12)
  add_test(NAME rtl_axi_render_${scene} COMMAND ${CMAKE_COMMAND} -DRPU=$<TARGET_FILE:rpu>
           -DSCENE=builtin:${scene} -DSIZE=16x16 -DOUT=${RPU_CMP_OUT}/axi_${scene} -DDELTA=1
           -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/axi_render.cmake)
  list(APPEND rtl_tests rtl_axi_render_${scene})
endforeach()
set_tests_properties(${rtl_tests} PROPERTIES LABELS "rtl;cosim")
