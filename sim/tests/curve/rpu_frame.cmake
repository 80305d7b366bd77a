# rpu_frame: real curve12 pairs with their frame descriptors, drawn flat-guide constants, and
# random inputs over the port widths (x0 … y1 saturate).
rpu_verilated_test(tb_rpu_frame TOP rpu_frame TB tb/curve/tb_rpu_frame.cpp)
