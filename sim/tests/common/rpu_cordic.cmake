# rpu_cordic: both modes at a narrow configuration (W = 8, AW = 10, Iters = 8; vectoring every
# (x, y) of the ports, rotation every (x, y) in [−32, 32]² × every angle plus every (x, y) × 8
# angles; TagW = 3) and at the default (W = 32, AW = 24, Iters = 24; edges + 100,000 random).
# The default-width runs are opt-in (RPU_SIM_EXTRA, CI build time): in the default suite the
# CORDICs at their product widths are checked inside rpu_indicator's testbench.
rpu_verilated_test(tb_rpu_cordic_w8_vec TOP rpu_cordic TB tb/common/tb_rpu_cordic.cpp
                   PARAMS -GW=8 -GAW=10 -GIters=8 -GMode=0 -GTagW=3)
rpu_verilated_test(tb_rpu_cordic_w8_rot TOP rpu_cordic TB tb/common/tb_rpu_cordic.cpp
                   PARAMS -GW=8 -GAW=10 -GIters=8 -GMode=1 -GTagW=3)
rpu_verilated_test(tb_rpu_cordic_w32_vec EXTRA TOP rpu_cordic TB tb/common/tb_rpu_cordic.cpp
                   PARAMS -GW=32 -GAW=24 -GIters=24 -GMode=0)
rpu_verilated_test(tb_rpu_cordic_w32_rot EXTRA TOP rpu_cordic TB tb/common/tb_rpu_cordic.cpp
                   PARAMS -GW=32 -GAW=24 -GIters=24 -GMode=1)
