# rpu_fifo: 200,000 cycles of random writes and reads in traffic phases (fill, drain, free flow)
# against ref::Fifo cycle for cycle and an order scoreboard; a narrow configuration (4 entries,
# 1 bit: full and empty every few cycles) and a wide one (100-bit entries, 64 entries).
rpu_verilated_test(tb_rpu_fifo_narrow TOP rpu_fifo TB tb/common/tb_rpu_fifo.cpp
                   PARAMS -GWidth=1 -GLog2Depth=2 DEFS WIDTH=1 LOG2_DEPTH=2)
rpu_verilated_test(tb_rpu_fifo_wide TOP rpu_fifo TB tb/common/tb_rpu_fifo.cpp
                   PARAMS -GWidth=100 -GLog2Depth=6 DEFS WIDTH=100 LOG2_DEPTH=6)
