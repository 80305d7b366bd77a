# rpu_ip: the K-step process, unrolled and iterative, against ip_process.
# (The unrolled default is opt-in here: rpu_top contains exactly that rpu_ip and its test covers it.)
set(RPU_IP_RTL ${RPU_RTL_DIR}/rpu_ip.v ${RPU_RTL_DIR}/rpu_ip_step.v ${RPU_RTL_DIR}/rpu_candidate.v
    ${RPU_RTL_DIR}/rpu_guide_pair.v ${RPU_RTL_DIR}/rpu_curve_point.v ${RPU_RTL_DIR}/rpu_sqrt.v
    ${RPU_RTL_DIR}/rpu_fifo.v ${RPU_RTL_DIR}/rpu_mul.v)
rpu_verilated_test(tb_rpu_ip EXTRA TOP rpu_ip TB tb/tb_rpu_ip.cpp SOURCES ${RPU_IP_RTL}
                   PARAMS -GCtxW=32 DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
rpu_verilated_test(tb_rpu_ip_iter_n8_n1_4 TOP rpu_ip TB tb/tb_rpu_ip.cpp SOURCES ${RPU_IP_RTL}
                   PARAMS -GCtxW=32 -GUnrolled=0 -GN=8 -GN1=4
                   DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}" UNROLLED=0 IP_N=8 IP_N1=4)
set(RPU_IP_STEP_RTL ${RPU_RTL_DIR}/rpu_ip_step.v ${RPU_RTL_DIR}/rpu_candidate.v
    ${RPU_RTL_DIR}/rpu_guide_pair.v ${RPU_RTL_DIR}/rpu_curve_point.v ${RPU_RTL_DIR}/rpu_sqrt.v
    ${RPU_RTL_DIR}/rpu_mul.v)
rpu_verilated_test(tb_rpu_ip_step TOP rpu_ip_step TB tb/tb_rpu_ip.cpp SOURCES ${RPU_IP_STEP_RTL}
                   PARAMS -GCtxW=32 -GStep=0 DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}" IP_STEP=1)
