# The surface path: rpu_surface_top (rpu_surface_setup → rpu_surface_ip → X and depth) against
# process_surface_piece on every surface of the scenes/surf_*.json demo scenes (camera pixels,
# image-border pixels, grazing rays, range-plane rays, eyes inside the bounding sphere; every
# piece), the latency of every item and the full-load rate; at the defaults: the iterative IP
# (one pass unit with 3 indicators, n = 16, n1 = 2, first step 7 bits: 48 passes per item).
# rpu_surface_ip alone: rpu_surface_ip.cmake. Opt-in (-DRPU_SIM_EXTRA=ON): about 1.5 CPU-minutes
# of Verilated C++ and a minute of run.
rpu_verilated_test(tb_rpu_surface_top EXTRA TOP rpu_surface_top TB tb/surface/tb_rpu_surface_top.cpp
                   PARAMS -GTagW=16 -GUnrolled=0)
# In the default suite: the whole surface path at narrow widths, iterative (LW 18, AW 14,
# n = 6, n1 = 3, first step 4 bits, 2 indicators: 9 + 2 = 11 passes per item).
rpu_verilated_test(tb_rpu_surface_top_lw18 TOP rpu_surface_top TB tb/surface/tb_rpu_surface_top.cpp
                   PARAMS -GTagW=16 -GUnrolled=0 -GSurfW=18 -GAngleW=14 -GN=6 -GN1=3 -GN1First=4
                          -GIndicators=2)
