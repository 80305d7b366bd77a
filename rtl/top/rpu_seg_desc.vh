// A segment descriptor in rpu_top's segment RAM (SegmentDesc, ref/model/descriptors.h; formats:
// docs/fixed-point.md; the harness packs it in sim/harness/rtl_types.cpp), LSB first:
// {tex, prim, p1, d, c0, R2 | w0², L², inv_m, inv_s, g1, g2, frame, fg1, fg2}. A texture's frame
// and frame guides are unused (0), its R2 field holds w0² and its c0 field its join: bit 0 is 1
// for a round join, the rest 0. Included inside rpu_top
// after rpu_guide_desc.vh; each offset is defined from the previous one.
  localparam integer SegFgO   = 0;                         // frame guides {fg1, fg2} (rpu_ip)
  localparam integer SegFgW   = 2 * `RPU_FGDW;
  localparam integer SegFrO   = SegFgO + SegFgW;           // frame descriptor (rpu_frame)
  localparam integer SegFrW   = `RPU_FRDW;
  localparam integer SegG2O   = SegFrO + SegFrW;           // guide of end 2 (rpu_guide_desc.vh)
  localparam integer SegG1O   = SegG2O + GdW;              // guide of end 1
  localparam integer SegInvSO = SegG1O + GdW;              // inv_s: 1/L² = inv_m · 2^-inv_s
  localparam integer SegInvSW = 7;
  localparam integer SegInvMO = SegInvSO + SegInvSW;       // inv_m, IW bits
  localparam integer SegInvMW = InvW;
  localparam integer SegL2O   = SegInvMO + SegInvMW;       // L², LSB²
  localparam integer SegL2W   = `RPU_L2W(CoordW);
  localparam integer SegR2O   = SegL2O + SegL2W;           // R², LSB² (texture: w0²)
  localparam integer SegR2W   = `RPU_R2W(CoordW);
  localparam integer SegC0O   = SegR2O + SegR2W;           // c0, 3 × LSB
  localparam integer SegC0W   = 3 * CoordW;
  localparam integer SegDO    = SegC0O + SegC0W;           // d = p2 − p1, 3 × LSB
  localparam integer SegDW    = 3 * `RPU_DW(CoordW);
  localparam integer SegP1O   = SegDO + SegDW;             // p1, 3 × LSB
  localparam integer SegP1W   = 3 * CoordW;
  localparam integer SegPrimO = SegP1O + SegP1W;           // primitive id
  localparam integer SegPrimW = PrimW;
  localparam integer SegTexO  = SegPrimO + SegPrimW;       // 1: texture segment, 0: curve
  localparam integer SegWords = SegTexO + 1;               // the descriptor's width
