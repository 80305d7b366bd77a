// rpu_top's parameters, the one declaration of them: the parameter list of rpu_top and of the
// AXI shell rpu_axi (included inside `module ... #(`, after any parameters of the module's own),
// so both take the same names, ranges and defaults. The defaults are the table's
// (ref/model/hw_params.def; CTest rtl_params checks them). Needs rpu_widths.vh.
  parameter integer CoordW   = 24,  // position width (12..40)
  parameter integer DirFrac  = 24,  // ray direction fraction bits (8..40)
  parameter integer TFrac    = 24,  // chord parameter fraction bits (8..48)
  parameter integer UnitFrac = 16,  // guide direction fraction bits (8..40)
  parameter integer EdgeFrac = 16,  // PVP edge vector fraction bits (8..40)
  parameter integer InvW     = 18,  // 1/L² mantissa bits (8..40)
  parameter integer SqrtW    = 0,   // widest square-root radicand; 0 = exact
  parameter integer N        = 16,  // result bits of τ (1..40)
  parameter integer N1       = 2,   // bits per step (1..8), N % N1 == 0
  parameter integer Metric   = 0,   // 0: |pr − X| (seed), 1: |pr − X|²
  parameter integer Unrolled = 1,   // 1: K step units (one item per cycle), 0: one reused K times
  parameter integer SegAddrW = 12,  // log2 of the segment descriptor capacity (1..16)
  parameter integer IdxW     = 14,  // pixel index width (1..14)
  parameter integer IdW      = 32,  // width of the caller's work-item id (1..64)
  parameter integer PrimW    = 16,  // primitive id width (1..31)
  parameter integer FifoLog2 = 10,  // log2 of the items in flight + waiting (2..12)
  // Surfaces (the surface path, rpu_surface_top, always in its iterative form).
  parameter integer Surfaces = 1,   // 1: the surface path is built; 0: curves and textures only
                                    // (a surface item is answered with no piece, no hit and
                                    // the overflow bit; its descriptor write is ignored)
  parameter integer SurfW    = 24,  // LW: signed width of surface-local coordinates (16..36)
  parameter integer AngleW   = 20,  // AW: binary-angle bits (12..32, <= LW + 10)
  parameter integer Turns    = 8,   // rpu_indicator's spiral / snail turn lanes (2..8)
  parameter integer N1First  = 7,   // bits of the search's step 1 (0: N1; 1..10, at most N used)
  parameter integer Indicators = 1, // indicators of the search's pass unit (1..64; 0: 2^N1 − 1)
  parameter integer SurfAddrW = 4,  // log2 of the surface descriptor capacity (1..SegAddrW)
  // Derived (do not override): the port widths; the layouts themselves are in
  // rpu_cam_desc.vh and rpu_seg_desc.vh, which check these totals.
  parameter integer TW     = `RPU_TW(TFrac),
  parameter integer XW     = `RPU_XW(CoordW),
  parameter integer CamW   = 9 * `RPU_VGW(DirFrac) + 12 * `RPU_EGW(EdgeFrac) + 3 * CoordW,
  parameter integer SegW   = 1 + PrimW + 9 * CoordW + 3 + `RPU_R2W(CoordW) + `RPU_L2W(CoordW)
                           + InvW + 7 + 2 * (2 + `RPU_HW(CoordW) + CoordW + TFrac
                                             + 3 * `RPU_UW(UnitFrac))
                           + `RPU_FRDW + 2 * `RPU_FGDW,
  parameter integer SurfDW = PrimW + 6 * CoordW + `RPU_R2W(CoordW) + 9 * (SurfW + 2) + 7
                           + 2 * SurfW + AngleW + 2 * (SurfW + 2) + `RPU_SDW(SurfW),
  parameter integer DepthW = `RPU_DEPTHW(CoordW, EdgeFrac)
