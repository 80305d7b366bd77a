# rpu_sqrt: exhaustive at 16 bits, edges + random at the guide's default width, radicand limit.
rpu_verilated_test(tb_rpu_sqrt_w16 TOP rpu_sqrt TB tb/common/tb_rpu_sqrt.cpp PARAMS -GRadW=16)
rpu_verilated_test(tb_rpu_sqrt_w58 TOP rpu_sqrt TB tb/common/tb_rpu_sqrt.cpp PARAMS -GRadW=58)
rpu_verilated_test(tb_rpu_sqrt_w58_s40 TOP rpu_sqrt TB tb/common/tb_rpu_sqrt.cpp
                   PARAMS -GRadW=58 -GSqrtW=40)
# Odd radicand widths (a zero-padded top digit): exhaustive at 15 bits; the sphere's 53 bits with
# a radicand limit (39 bits after the pre-shift); and the widest radicand, 126 bits (63 stages).
rpu_verilated_test(tb_rpu_sqrt_w15 TOP rpu_sqrt TB tb/common/tb_rpu_sqrt.cpp PARAMS -GRadW=15)
rpu_verilated_test(tb_rpu_sqrt_w53_s40 TOP rpu_sqrt TB tb/common/tb_rpu_sqrt.cpp
                   PARAMS -GRadW=53 -GSqrtW=40)
rpu_verilated_test(tb_rpu_sqrt_w126 TOP rpu_sqrt TB tb/common/tb_rpu_sqrt.cpp PARAMS -GRadW=126)
