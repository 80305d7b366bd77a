// One guide descriptor (GuideDesc, ref/model/descriptors.h; formats: docs/fixed-point.md), packed
// LSB first: {shape, u} = {mode, h, a, b, u}, the shape laid out by rpu_guide_shape.vh. The
// guide travels as this one word between rpu_top, rpu_ip, rpu_ip_step, rpu_candidate and
// rpu_texture; rpu_guide_pair takes its shape. Included inside a module that defines CoordW,
// TFrac and UnitFrac. A shape field of the descriptor is read at GdShapeO + Gs<Field>O (every
// localparam here is read by the next, so none is left unused). Its total, GdWords, equals
// `RPU_GDW (rpu_widths.vh), a module's derived parameter GdW for its ports.
`include "rpu_guide_shape.vh"
  localparam integer GdUO     = 0;                         // u_k, 3 × Q(2.FU), {z, y, x}
  localparam integer GdUW     = 3 * `RPU_UW(UnitFrac);
  localparam integer GdShapeO = GdUO + GdUW;               // {mode, h, a, b}
  localparam integer GdWords  = GdShapeO + GsWords;
