// The shape of one guide (GuideDesc's mode, h, a, b: ref/model/descriptors.h; formats:
// docs/fixed-point.md), the fields rpu_guide_pair reads, packed LSB first: {mode, h, a, b}.
// Included inside a module that defines CoordW and TFrac; each offset is defined from the
// previous one. Its total, GsWords, equals `RPU_GSW (rpu_widths.vh), which a module declares as
// its derived parameter GsW for its ports. rpu_guide_desc.vh puts the shape above the guide's u.
  localparam integer GsBO    = 0;                          // b = L²/(4h²), Q(0.FT) (flat)
  localparam integer GsBW    = TFrac;
  localparam integer GsAO    = GsBO + GsBW;                // a = L²/(2h), LSB (flat)
  localparam integer GsAW    = CoordW;
  localparam integer GsHO    = GsAO + GsAW;                // h, LSB (arc)
  localparam integer GsHW    = `RPU_HW(CoordW);
  localparam integer GsModeO = GsHO + GsHW;                // 0 straight, 1 arc, 2 flat
  localparam integer GsModeW = 2;
  localparam integer GsWords = GsModeO + GsModeW;
