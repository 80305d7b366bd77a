# rpu_surface_ip alone against surface_ip: pieces of the scenes/surf_*.json surfaces from the
# setup twin (camera pixels, border pixels, grazing and range-plane rays, eyes inside the sphere),
# edited indicator fields (overflowing lanes), empty pieces with junk (run_i = 0) and random
# pieces; the latency of every item.
# - In the default suite (and the mutation plan's testbench of rpu_surface_ip_step): iterative,
#   narrow (LW 18, AW 14, 6 turn lanes, n = 8, n1 = 2, first step 5 bits, 2 indicators): step 1's
#   33 candidates in 17 passes (the last with an idle lane), step 2's 3 new ones in 2 passes (the
#   end compare after a pass of its own), step 3 the remaining 1 bit: 20 passes, shifts 3, 1, 0.
# - Opt-in (-DRPU_SIM_EXTRA=ON): unrolled, narrow (LW 18, AW 14, 6 turn lanes, n = 6, n1 = 3,
#   first step 4 bits: 4 pass units of 7 indicators); iterative at n = 8, n1 = 1 with the default
#   first step and one indicator (7 bits: 129 passes for step 1, 130 in all); iterative at the
#   defaults with the seed's schedule (N1First = 0: K + 1 = 9 passes). The iterative form at the
#   defaults is in tb_rpu_surface_top.
rpu_verilated_test(tb_rpu_surface_ip_iter_lw18 TOP rpu_surface_ip
                   TB tb/surface/tb_rpu_surface_ip.cpp
                   PARAMS -GUnrolled=0 -GSurfW=18 -GAngleW=14 -GTurns=6 -GN=8 -GN1=2 -GN1First=5
                          -GIndicators=2 -GCtxW=24)
rpu_verilated_test(tb_rpu_surface_ip_unrolled_lw18 EXTRA TOP rpu_surface_ip
                   TB tb/surface/tb_rpu_surface_ip.cpp
                   PARAMS -GUnrolled=1 -GSurfW=18 -GAngleW=14 -GTurns=6 -GN=6 -GN1=3 -GN1First=4
                          -GCtxW=24)
rpu_verilated_test(tb_rpu_surface_ip_iter_n8_n1_1 EXTRA TOP rpu_surface_ip
                   TB tb/surface/tb_rpu_surface_ip.cpp
                   PARAMS -GUnrolled=0 -GN=8 -GN1=1 -GCtxW=24)
rpu_verilated_test(tb_rpu_surface_ip_iter_seed EXTRA TOP rpu_surface_ip
                   TB tb/surface/tb_rpu_surface_ip.cpp
                   PARAMS -GUnrolled=0 -GN1First=0 -GCtxW=24)
