# rpu_sqrt: exhaustive at 16 bits, edges + random at the guide's default width, radicand limit.
rpu_verilated_test(tb_rpu_sqrt_w16 TOP rpu_sqrt TB tb/tb_rpu_sqrt.cpp
                   PARAMS -GRadW=16 DEFS RAD_W=16)
rpu_verilated_test(tb_rpu_sqrt_w58 TOP rpu_sqrt TB tb/tb_rpu_sqrt.cpp
                   PARAMS -GRadW=58 DEFS RAD_W=58)
rpu_verilated_test(tb_rpu_sqrt_w58_s40 TOP rpu_sqrt TB tb/tb_rpu_sqrt.cpp
                   PARAMS -GRadW=58 -GSqrtW=40 DEFS RAD_W=58 SQRT_W=40)
