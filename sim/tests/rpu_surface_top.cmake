# The surface path: rpu_surface_top (rpu_surface_setup → rpu_surface_ip → X and depth) against
# process_surface_piece on every surface of the scenes/surf_*.json demo scenes (camera pixels,
# image-border pixels, grazing rays, range-plane rays, eyes inside the bounding sphere; every
# piece), the latency of every item and the full-load rate; at the defaults: the iterative IP
# (one pass unit with 3 indicators, n = 16, n1 = 2). rpu_surface_ip alone: rpu_surface_ip.cmake.
# Opt-in (-DRPU_SIM_EXTRA=ON): its Verilated C++ takes about 8 CPU-minutes to compile.
set(RPU_SURFACE_IP_SOURCES
    ${RPU_RTL_DIR}/rpu_surface_ip.v ${RPU_RTL_DIR}/rpu_surface_ip_step.v
    ${RPU_RTL_DIR}/rpu_indicator.v ${RPU_RTL_DIR}/rpu_indicator_add3.v
    ${RPU_RTL_DIR}/rpu_indicator_delay.v ${RPU_RTL_DIR}/rpu_cordic.v ${RPU_RTL_DIR}/rpu_mul.v)
set(RPU_SURFACE_TOP_SOURCES
    ${RPU_RTL_DIR}/rpu_surface_top.v ${RPU_RTL_DIR}/rpu_surface_admit.v
    ${RPU_RTL_DIR}/rpu_surface_setup.v ${RPU_RTL_DIR}/rpu_sphere.v ${RPU_RTL_DIR}/rpu_chord.v
    ${RPU_RTL_DIR}/rpu_sqrt.v ${RPU_RTL_DIR}/rpu_div.v ${RPU_RTL_DIR}/rpu_fifo.v
    ${RPU_SURFACE_IP_SOURCES})
rpu_verilated_test(tb_rpu_surface_top EXTRA TOP rpu_surface_top TB tb/tb_rpu_surface_top.cpp
                   SOURCES ${RPU_SURFACE_TOP_SOURCES} PARAMS -GTagW=16
                   DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}" TAG_W=16)
