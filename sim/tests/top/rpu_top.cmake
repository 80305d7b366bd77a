# rpu_top through the co-simulation harness (sim/harness, its Verilated configurations):
# frames of curves, textures and surfaces, throughput, backpressure, X seeds; unrolled and
# iterative.
add_executable(tb_rpu_top tb/top/tb_rpu_top.cpp)
target_include_directories(tb_rpu_top PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/tb)
target_link_libraries(tb_rpu_top PRIVATE rpu_rtl)
target_compile_options(tb_rpu_top PRIVATE -Wno-unused-parameter)
target_compile_definitions(tb_rpu_top PRIVATE RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_test(NAME tb_rpu_top COMMAND tb_rpu_top frame)
add_test(NAME tb_rpu_top_airfield COMMAND tb_rpu_top frame --scene airfield --size 48)
add_test(NAME tb_rpu_top_throughput COMMAND tb_rpu_top throughput)
add_test(NAME tb_rpu_top_backpressure COMMAND tb_rpu_top backpressure --size 32)
add_test(NAME tb_rpu_top_xseeds COMMAND ${CMAKE_COMMAND} -DTB=$<TARGET_FILE:tb_rpu_top>
         -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/x_seeds.cmake)
add_test(NAME tb_rpu_top_iter COMMAND tb_rpu_top frame --size 24 --config n16_n1_2_iterative)
# Curves and textures in one frame: the order FIFO merges the two paths' results (the frame
# mutation testing runs rpu_top's mutants on).
add_test(NAME tb_rpu_top_mixed COMMAND tb_rpu_top frame --scene curve12+ellipse6 --size 24
         --config n16_n1_2_iterative)
add_test(NAME tb_rpu_top_iter_throughput COMMAND tb_rpu_top throughput --config n16_n1_2_iterative)
# All three kinds in one frame (surf_mix: a curve, a texture, a relief ellipsoid and a rocket):
# the surface path, its ring admission at the input, and the order FIFO's three-way merge; the
# pixel resolve orders hits across kinds. Unrolled curves, and the iterative form with
# backpressure.
add_test(NAME tb_rpu_top_surf_mix COMMAND tb_rpu_top frame --scene surf_mix --size 16)
add_test(NAME tb_rpu_top_surf_backpressure COMMAND tb_rpu_top backpressure --scene surf_mix
         --size 12 --config n16_n1_2_iterative)
# A build without the surface path (Surfaces = 0) answers surf_mix's surface pieces with no
# piece, no hit and the overflow bit, in order between the curve and texture results.
add_test(NAME tb_rpu_top_no_surfaces COMMAND tb_rpu_top frame --scene surf_mix --size 16
         --config n8_n1_1_no_surfaces)
set_tests_properties(tb_rpu_top tb_rpu_top_airfield tb_rpu_top_throughput tb_rpu_top_backpressure
                     tb_rpu_top_xseeds tb_rpu_top_iter tb_rpu_top_iter_throughput tb_rpu_top_mixed
                     tb_rpu_top_surf_mix tb_rpu_top_surf_backpressure tb_rpu_top_no_surfaces
                     PROPERTIES LABELS rtl)

# rpu_top in its AXI shell rpu_axi (docs/axi.md), through the bus-functional models of
# sim/harness/axi_ports.h with random TVALID gaps and TREADY back-pressure: a curve, a texture
# and a surface demo frame on the iterative defaults with 128-bit streams, and all three kinds on
# (8, 1) without surfaces on 32-bit streams (multi-beat records; the surface items answered with
# the overflow bit and the UNBUILT_KIND cause); the bad host's session (tb_rpu_axi host).
add_executable(tb_rpu_axi tb/top/tb_rpu_axi.cpp)
target_include_directories(tb_rpu_axi PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/tb)
target_link_libraries(tb_rpu_axi PRIVATE rpu_rtl)
target_compile_options(tb_rpu_axi PRIVATE -Wno-unused-parameter)
target_compile_definitions(tb_rpu_axi PRIVATE RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_test(NAME tb_rpu_axi_curve COMMAND tb_rpu_axi frame --scene curve12 --size 16)
add_test(NAME tb_rpu_axi_texture COMMAND tb_rpu_axi frame --scene ellipse6 --size 32)
add_test(NAME tb_rpu_axi_surface COMMAND tb_rpu_axi frame --scene surf_ellipsoid --size 8)
add_test(NAME tb_rpu_axi_narrow COMMAND tb_rpu_axi frame --scene surf_mix --size 12
         --config n8_n1_1_no_surfaces_axi32)
add_test(NAME tb_rpu_axi_host COMMAND tb_rpu_axi host --scene curve12 --size 16)
add_test(NAME tb_rpu_axi_host_narrow COMMAND tb_rpu_axi host --scene curve12 --size 16
         --config n8_n1_1_no_surfaces_axi32)
set_tests_properties(tb_rpu_axi_curve tb_rpu_axi_texture tb_rpu_axi_surface tb_rpu_axi_narrow
                     tb_rpu_axi_host tb_rpu_axi_host_narrow PROPERTIES LABELS rtl)
