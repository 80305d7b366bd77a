// One guide descriptor (GuideDesc, ref/model/descriptors.h; formats: docs/fixed-point.md), packed
// LSB first: {mode, h, a, b, u}. Included inside a module that defines CoordW, TFrac and
// UnitFrac; each offset is defined from the previous one. GdW = 2 + (CW + 5) + CW + FT + 3(FU + 2).
  localparam integer GdUO    = 0;                          // u_k, 3 × Q(2.FU), {z, y, x}
  localparam integer GdUW    = 3 * `RPU_UW(UnitFrac);
  localparam integer GdBO    = GdUO + GdUW;                // b = L²/(4h²), Q(0.FT) (flat)
  localparam integer GdBW    = TFrac;
  localparam integer GdAO    = GdBO + GdBW;                // a = L²/(2h), LSB (flat)
  localparam integer GdAW    = CoordW;
  localparam integer GdHO    = GdAO + GdAW;                // h, LSB (arc)
  localparam integer GdHW    = `RPU_HW(CoordW);
  localparam integer GdModeO = GdHO + GdHW;                // 0 straight, 1 arc, 2 flat
  localparam integer GdModeW = 2;
  localparam integer GdW     = GdModeO + GdModeW;
