# rpu_mul: exhaustive at 7 × 6 bits with 3 × 2-bit chunks (9 tiles, a four-level tree), signed
# and unsigned, every tile a Booth shift-and-add (LutTile 4) and, signed, every tile a product
# (LutTile 0); corners and 200,000 random products at 51 × 23 unsigned (6 tiles: L²·w of the
# guide pair; the two tiles of a's 3-bit top chunk in LUTs) and 22 × 22 signed (the candidate's
# squares: one DSP tile and a Booth tile with the sign) and, with SwapSides, 34 × 28 signed (the
# capture's: the operands swap sides, 2 DSP tiles and 2 narrow ones); exhaustive with swapped
# sides at 10 × 6 signed and 7 × 9 unsigned (narrow tiles of 1 bit); opt-in, 28 × 28 signed
# padded to a latency of 6 and one tile (25 × 18 signed).
rpu_verilated_test(tb_rpu_mul_7x6s TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=7 -GBW=6 -GSigned=1 -GChunkA=3 -GChunkB=2)
rpu_verilated_test(tb_rpu_mul_7x6s_dsp TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=7 -GBW=6 -GSigned=1 -GChunkA=3 -GChunkB=2 -GLutTile=0)
rpu_verilated_test(tb_rpu_mul_22x22s TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=22 -GBW=22 -GSigned=1)
rpu_verilated_test(tb_rpu_mul_34x28s TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=34 -GBW=28 -GSigned=1 -GSwapSides=1)
rpu_verilated_test(tb_rpu_mul_10x6s_swap TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=10 -GBW=6 -GSigned=1 -GChunkA=4 -GChunkB=3 -GLutTile=1
                   -GSwapSides=1)
rpu_verilated_test(tb_rpu_mul_7x9u_swap TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=7 -GBW=9 -GSigned=0 -GChunkA=5 -GChunkB=3 -GLutTile=1
                   -GSwapSides=1)
rpu_verilated_test(tb_rpu_mul_7x6u TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=7 -GBW=6 -GSigned=0 -GChunkA=3 -GChunkB=2)
rpu_verilated_test(tb_rpu_mul_51x23u TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=51 -GBW=23 -GSigned=0)
rpu_verilated_test(tb_rpu_mul_28x28s EXTRA TOP rpu_mul TB tb/common/tb_rpu_mul.cpp
                   PARAMS -GAW=28 -GBW=28 -GSigned=1 -GLatency=6)
rpu_verilated_test(tb_rpu_mul_25x18s EXTRA TOP rpu_mul TB tb/common/tb_rpu_mul.cpp)
