# rpu_capture: model test points of curve12, random points, t edge values.
rpu_verilated_test(tb_rpu_capture TOP rpu_capture TB tb/curve/tb_rpu_capture.cpp)
