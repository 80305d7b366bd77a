# rpu_ip: the K-step process, unrolled and iterative, against ip_process.
# (The unrolled default is opt-in here: rpu_top contains exactly that rpu_ip and its test covers it.)
rpu_verilated_test(tb_rpu_ip EXTRA TOP rpu_ip TB tb/curve/tb_rpu_ip.cpp
                   PARAMS -GCtxW=32)
rpu_verilated_test(tb_rpu_ip_iter_n8_n1_4 TOP rpu_ip TB tb/curve/tb_rpu_ip.cpp
                   PARAMS -GCtxW=32 -GUnrolled=0 -GN=8 -GN1=4)
# rpu_ip_step (forward differences in the chord's frame) on the model's intermediate states: the
# iterative form (k per item) in the default suite, an unrolled step (k = 5) opt-in.
rpu_verilated_test(tb_rpu_ip_step TOP rpu_ip_step TB tb/curve/tb_rpu_ip_step.cpp
                   PARAMS -GStep=0)
rpu_verilated_test(tb_rpu_ip_step_k5 EXTRA TOP rpu_ip_step TB tb/curve/tb_rpu_ip_step.cpp
                   PARAMS -GStep=5)
