// rpu_mul's latency for given operand widths: 2 (the tile input and product registers) +
// ceil(log2(tiles)) adder-tree levels, tiles = ceil((aw − s)/ca) · ceil((bw − s)/cb) for a
// signed (s = 1) or unsigned (s = 0) product in tiles of ca × cb unsigned bits. One formula for
// rpu_mul and every module that must know when a product arrives; the C++ side is
// ref::mul_latency (ref/model/common/rpu_mul.h). Macros rather than a constant function, so that
// a header included in nested modules declares nothing.
`define RPU_MUL_LATENCY(aw, bw, s, ca, cb) \
  (2 + $clog2((((aw) - (s) + (ca) - 1) / (ca)) * (((bw) - (s) + (cb) - 1) / (cb))))
// At the tile size every datapath product uses (rpu_mul's default chunks, 24 × 17 bits).
`define RPU_MUL_LAT(aw, bw, s) `RPU_MUL_LATENCY(aw, bw, s, 24, 17)

