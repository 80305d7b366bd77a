// A surface descriptor in rpu_top's surface RAM (SurfaceDesc, ref/model/descriptors.h; formats:
// docs/fixed-point.md, "Surfaces"; the harness packs it in sim/harness/frame_schedule.cpp), LSB
// first: {desc, end_sin, end_cos, end_angle, y_max, y_min, to_local_s, to_local, origin, R2, c0,
// prim}. desc is the indicator's word (rtl/surface/rpu_surface_desc.vh, the type at its bit 0);
// the rest are rpu_surface_top's setup ports (rpu_surface_setup_ports.vh) and the primitive id.
// Included inside rpu_top; each offset is defined from the previous one.
  localparam integer SfDescO   = 0;                          // the indicator's fields
  localparam integer SfDescW   = `RPU_SDW(SurfW);
  localparam integer SfEndSinO = SfDescO + SfDescW;          // sin of the end angle, Q(1.KF)
  localparam integer SfConstW  = SurfW + 2;
  localparam integer SfEndCosO = SfEndSinO + SfConstW;       // cos of the end angle, Q(1.KF)
  localparam integer SfEndAngO = SfEndCosO + SfConstW;       // the end angle, binary angle
  localparam integer SfYMaxO   = SfEndAngO + AngleW;         // slab top, llsb
  localparam integer SfYMinO   = SfYMaxO + SurfW;            // slab bottom, llsb
  localparam integer SfToLocSO = SfYMinO + SurfW;            // M's shift
  localparam integer SfToLocO  = SfToLocSO + 7;              // M, 9 entries, row-major, LSB first
  localparam integer SfMantW   = SurfW + 2;
  localparam integer SfOriginO = SfToLocO + 9 * SfMantW;     // origin, 3 × LSB
  localparam integer SfR2O     = SfOriginO + 3 * CoordW;     // bounding-sphere R², LSB²
  localparam integer SfR2W     = `RPU_R2W(CoordW);
  localparam integer SfC0O     = SfR2O + SfR2W;              // bounding-sphere centre, 3 × LSB
  localparam integer SfPrimO   = SfC0O + 3 * CoordW;         // primitive id
  localparam integer SfWords   = SfPrimO + PrimW;            // the descriptor's width
