# rpu_top: a whole frame's work items, throughput, backpressure, X seeds; unrolled and iterative.
set(RPU_TOP_RTL ${RPU_RTL_DIR}/rpu_top.v ${RPU_RTL_DIR}/rpu_ray_gen.v ${RPU_RTL_DIR}/rpu_div.v
    ${RPU_RTL_DIR}/rpu_sqrt.v ${RPU_RTL_DIR}/rpu_sphere.v ${RPU_RTL_DIR}/rpu_chord.v
    ${RPU_RTL_DIR}/rpu_ip.v ${RPU_RTL_DIR}/rpu_ip_step.v ${RPU_RTL_DIR}/rpu_candidate.v
    ${RPU_RTL_DIR}/rpu_guide.v ${RPU_RTL_DIR}/rpu_curve_point.v ${RPU_RTL_DIR}/rpu_capture.v)
rpu_verilated_test(tb_rpu_top TOP rpu_top TB tb/tb_rpu_top.cpp SOURCES ${RPU_TOP_RTL}
                   DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_test(NAME tb_rpu_top_throughput COMMAND tb_rpu_top throughput)
add_test(NAME tb_rpu_top_backpressure COMMAND tb_rpu_top backpressure --size 32)
add_test(NAME tb_rpu_top_xseeds COMMAND ${CMAKE_COMMAND} -DTB=$<TARGET_FILE:tb_rpu_top>
         -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/x_seeds.cmake)
set_tests_properties(tb_rpu_top_throughput tb_rpu_top_backpressure tb_rpu_top_xseeds
                     PROPERTIES LABELS rtl)
rpu_verilated_test(tb_rpu_top_iter EXTRA TOP rpu_top TB tb/tb_rpu_top.cpp SOURCES ${RPU_TOP_RTL}
                   PARAMS -GUnrolled=0 DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}" TOP_UNROLLED=0
                   ARGS frame --size 24)
