# The surface indicator (rpu_indicator with rpu_cordic, rpu_mul and its helpers): every surface
# of the demo scenes scenes/surf_*.json against the twin (ref::indicator_unit), points in the
# bounding sphere, on and near the seed's parametric surface, edge points and edited descriptors
# (tb/surface/tb_rpu_indicator.cpp). Two configurations: the defaults (LW 24, AW 20, 8 lanes,
# 8-bit tag) and, opt-in (RPU_SIM_EXTRA, to keep the default build's Verilated C++ small), a
# narrow one (LW 18, AW 14, 6 lanes, 3-bit tag).
rpu_verilated_test(tb_rpu_indicator TOP rpu_indicator TB tb/surface/tb_rpu_indicator.cpp
                   PARAMS -GTagW=8)
rpu_verilated_test(tb_rpu_indicator_lw18 EXTRA TOP rpu_indicator TB tb/surface/tb_rpu_indicator.cpp
                   PARAMS -GSurfW=18 -GAngleW=14 -GLanes=6 -GTagW=3)
