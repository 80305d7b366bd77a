# rpu_frame: real curve12 pairs with their frame descriptors, drawn flat-guide constants, and
# random inputs over the port widths (x0 … y1 saturate).
rpu_verilated_test(tb_rpu_frame TOP rpu_frame TB tb/curve/tb_rpu_frame.cpp)
# At n = 24 the flat guides' w needs a third tile in its high half (rtl/curve/rpu_frame.v,
# "Both halves run at the slower one's latency"); below n = 24 the two halves have two each.
rpu_verilated_test(tb_rpu_frame_n24 TOP rpu_frame TB tb/curve/tb_rpu_frame.cpp
                   PARAMS -GN=24)
