# rpu_capture: model test points of curve12, random points, t edge values.
rpu_verilated_test(tb_rpu_capture TOP rpu_capture TB tb/tb_rpu_capture.cpp
                   SOURCES ${RPU_RTL_DIR}/rpu_capture.v ${RPU_RTL_DIR}/rpu_mul.v
                   DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
