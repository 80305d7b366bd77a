# rpu_curve_point: the demo scenes' segments at the defaults, and at the widest and a narrow
# parameter set (the scenes quantised with those parameters; a 3-bit tag in the narrow one).
rpu_verilated_test(tb_rpu_curve_point TOP rpu_curve_point TB tb/curve/tb_rpu_curve_point.cpp
                   DEFS VECTORS=100000)
rpu_verilated_test(tb_rpu_curve_point_w40 EXTRA TOP rpu_curve_point
                   TB tb/curve/tb_rpu_curve_point.cpp
                   PARAMS -GCoordW=40 -GTFrac=43 -GUnitFrac=40
                   DEFS VECTORS=20000)
rpu_verilated_test(tb_rpu_curve_point_w16 EXTRA TOP rpu_curve_point
                   TB tb/curve/tb_rpu_curve_point.cpp
                   PARAMS -GCoordW=16 -GTFrac=12 -GUnitFrac=8 -GTagW=3
                   DEFS VECTORS=20000)
