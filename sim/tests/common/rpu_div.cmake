# rpu_div: exhaustive at 10/8/10 bits, and with a wide dividend (num >> QuotW wider than the
# divisor) and a one-bit quotient; edges + random (with the ray generator's reciprocal
# 2^(2FV+2) / |v|) at the ray generator's configuration FV = 24: 51-bit dividend, 28-bit |v|,
# FV + 3 quotient bits.
rpu_verilated_test(tb_rpu_div_n10_d8_q10 TOP rpu_div TB tb/common/tb_rpu_div.cpp
                   PARAMS -GNumW=10 -GDenW=8 -GQuotW=10)
rpu_verilated_test(tb_rpu_div_n16_d4_q8 EXTRA TOP rpu_div TB tb/common/tb_rpu_div.cpp
                   PARAMS -GNumW=16 -GDenW=4 -GQuotW=8)
rpu_verilated_test(tb_rpu_div_n8_d8_q1 EXTRA TOP rpu_div TB tb/common/tb_rpu_div.cpp
                   PARAMS -GNumW=8 -GDenW=8 -GQuotW=1)
rpu_verilated_test(tb_rpu_div_recip24 TOP rpu_div TB tb/common/tb_rpu_div.cpp
                   PARAMS -GNumW=51 -GDenW=28 -GQuotW=27 -GTagW=16
                   DEFS RECIP_FV=24)
