# rpu_guide: defaults (exact square root), the radicand limit SqrtW = 40, and the parameter
# extremes (widest: CoordW 40 with TFrac 43, L2·w = 126 bits; narrowest: CoordW 12, TFrac 8,
# SqrtW 16, a 3-bit tag).
set(RPU_GUIDE_SOURCES ${RPU_RTL_DIR}/rpu_sqrt.v ${RPU_RTL_DIR}/rpu_guide.v)
rpu_verilated_test(tb_rpu_guide TOP rpu_guide TB tb/tb_rpu_guide.cpp
                   SOURCES ${RPU_GUIDE_SOURCES}
                   DEFS VECTORS=100000)
rpu_verilated_test(tb_rpu_guide_s40 EXTRA TOP rpu_guide TB tb/tb_rpu_guide.cpp
                   SOURCES ${RPU_GUIDE_SOURCES}
                   PARAMS -GSqrtW=40 DEFS SQRT_W=40 VECTORS=20000)
rpu_verilated_test(tb_rpu_guide_w40 EXTRA TOP rpu_guide TB tb/tb_rpu_guide.cpp
                   SOURCES ${RPU_GUIDE_SOURCES}
                   PARAMS -GCoordW=40 -GTFrac=43 DEFS COORD_W=40 T_FRAC=43 VECTORS=20000)
rpu_verilated_test(tb_rpu_guide_w12 EXTRA TOP rpu_guide TB tb/tb_rpu_guide.cpp
                   SOURCES ${RPU_GUIDE_SOURCES}
                   PARAMS -GCoordW=12 -GTFrac=8 -GSqrtW=16 -GTagW=3
                   DEFS COORD_W=12 T_FRAC=8 SQRT_W=16 TAG_W=3 VECTORS=20000)
