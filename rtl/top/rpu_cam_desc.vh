// The camera register of rpu_top (CameraDesc, ref/model/descriptors.h; formats:
// docs/fixed-point.md; packed by sim/harness/rtl_types.cpp), LSB first:
// {v0, dx, dy, el0, et0, sw, w, eye}. Each offset is defined from the previous one.
  localparam integer CamEyeO = 0;                          // eye h, 3 × LSB
  localparam integer CamEyeW = 3 * CoordW;
  localparam integer CamWO   = CamEyeO + CamEyeW;          // W, 3 × Q(4.FE+14)
  localparam integer CamEW   = 3 * `RPU_EGW(EdgeFrac);     // one edge-format vector
  localparam integer CamSwO  = CamWO + CamEW;              // σ·W
  localparam integer CamEt0O = CamSwO + CamEW;             // top edge of row 0
  localparam integer CamEl0O = CamEt0O + CamEW;            // left edge of column 0
  localparam integer CamVW   = 3 * `RPU_VGW(DirFrac);      // one direction vector, Q(4.FV+14)
  localparam integer CamDyO  = CamEl0O + CamEW;            // per-row increment of v
  localparam integer CamDxO  = CamDyO + CamVW;             // per-column increment of v
  localparam integer CamV0O  = CamDxO + CamVW;             // v of pixel (0, 0)
  localparam integer CamWords = CamV0O + CamVW;
