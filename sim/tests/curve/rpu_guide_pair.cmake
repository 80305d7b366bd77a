# rpu_guide_pair: defaults with h² from the caller (HhIn = 1, as every candidate evaluator uses
# it; the texture unit's HhIn = 0 is covered by its own test and by the opt-in _hh0 run with junk
# on the h² ports), the radicand limit SqrtW = 40, and the parameter extremes (widest: CoordW 40
# with TFrac 43, L2·w = 126 bits; narrowest: CoordW 12, TFrac 8, SqrtW 16, a 3-bit tag). The
# default run's 40-bit tag waits in the unit's rpu_tag_queue (32 bits or more), the others ride.
rpu_verilated_test(tb_rpu_guide_pair TOP rpu_guide_pair TB tb/curve/tb_rpu_guide_pair.cpp
                   PARAMS -GHhIn=1 -GTagW=40 DEFS VECTORS=100000)
rpu_verilated_test(tb_rpu_guide_pair_hh0 EXTRA TOP rpu_guide_pair TB tb/curve/tb_rpu_guide_pair.cpp
                   PARAMS -GHhIn=0 DEFS VECTORS=50000)
rpu_verilated_test(tb_rpu_guide_pair_s40 EXTRA TOP rpu_guide_pair TB tb/curve/tb_rpu_guide_pair.cpp
                   PARAMS -GHhIn=1 -GSqrtW=40 DEFS VECTORS=20000)
rpu_verilated_test(tb_rpu_guide_pair_w40 EXTRA TOP rpu_guide_pair TB tb/curve/tb_rpu_guide_pair.cpp
                   PARAMS -GHhIn=1 -GCoordW=40 -GTFrac=43
                   DEFS VECTORS=20000)
rpu_verilated_test(tb_rpu_guide_pair_w12 EXTRA TOP rpu_guide_pair TB tb/curve/tb_rpu_guide_pair.cpp
                   PARAMS -GHhIn=1 -GCoordW=12 -GTFrac=8 -GSqrtW=16 -GTagW=3
                   DEFS VECTORS=20000)
