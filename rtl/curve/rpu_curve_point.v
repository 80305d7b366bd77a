// rpu_curve_point: the curve point s(t) from the chord and the two guide offsets (the model's
// `curve_point_unit`), per component:
//   X = p1 + floor(d·t / 2^FT) + floor(u1·G1 / 2^FU) + floor(u2·G2 / 2^FU)
//   G1 = floor(g1·(2^FT − t) / 2^FT),  G2 = floor(g2·t / 2^FT)
// Every product is an rpu_mul (DSP-sized tiles, registered; rpu_mul_latency.vh). Pipeline:
//   G1 = g1·(2^FT − t), G2 = g2·t, d·t          rpu_mul 26×28, 26×27, 25×27: LatG (4)
//   u1·G1, u2·G2 | p1 + floor(d·t)              rpu_mul 18×29: LatU (3) | d·t padded, one add
//   X = p(t) + the two guide terms              1
// Latency = LatG + LatU + 1 cycles (8 at the defaults), one operand per cycle, no stall;
// `tag_i` comes out unchanged with the result.
//
// Widths: the products and the floors are exact for every port value (G1, G2: CW+5 bits). X is
// CW+3 bits signed (docs/fixed-point.md) and the sum is taken modulo 2^(CW+3), which is the
// exact value whenever it fits. It does for the descriptor formats: |p1|, |p2| ≤ 7/16·2^CW per
// component (the normalisation), so |p1 + d·t| ≤ (|1−t| + |t|)·7/16·2^CW ≤ 9·7/16·2^CW for
// t ∈ [−4, 4) (Q(3.FT)), leaving 2^(CW−4) − 8 LSB for the guide terms; for t ∈ [0, 1] those are
// ≤ L < 2^(CW+1) while |p(t)| ≤ 7/16·2^CW, and outside [0, 1] w = 0, so g is 0 (exact root,
// flat, straight) or in (−2^S, 0] (pre-shifted root), |u1·G1 + u2·G2| ≤ 9·2^S + 2: it fits for
// S ≤ CW − 8, i.e. every SqrtW ≥ 26 or 0 (in practice t stays within a few LSB of [0, 1]).
`default_nettype none
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_curve_point #(
  parameter integer CoordW   = 24,  // CW: signed width of positions (12..40)
  parameter integer TFrac    = 24,  // FT: fraction bits of t (8..48)
  parameter integer UnitFrac = 16,  // FU: fraction bits of the guide unit vectors (8..40)
  parameter integer TagW     = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer TW = `RPU_TW(TFrac),     // t: Q(3.FT)
  parameter integer DW = `RPU_DW(CoordW),    // d = p2 − p1
  parameter integer UW = `RPU_UW(UnitFrac),  // u: Q(2.FU)
  parameter integer GW = `RPU_PRW(CoordW),    // g1, g2 (rpu_guide_pair's g1_o, g2_o)
  parameter integer XW = `RPU_XW(CoordW)     // X
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              valid_i,
  input  wire [3*CoordW-1:0] p1_i,  // {z, y, x}, LSB, signed each
  input  wire [3*DW-1:0]   d_i,     // {z, y, x}, LSB, signed each
  input  wire [3*UW-1:0]   u1_i,    // {z, y, x}, Q(2.FU), signed each
  input  wire [3*UW-1:0]   u2_i,    // {z, y, x}, Q(2.FU), signed each
  input  wire [TW-1:0]     t_i,     // Q(3.FT), signed
  input  wire [GW-1:0]     g1_i,    // LSB, signed
  input  wire [GW-1:0]     g2_i,    // LSB, signed
  input  wire [TagW-1:0]   tag_i,
  output wire              valid_o,
  output wire [3*XW-1:0]   x_o,     // {z, y, x}, LSB, signed each
  output wire [TagW-1:0]   tag_o
);
  localparam integer OmW = TW + 1;       // 2^FT − t ∈ (−3, 5]·2^FT
  localparam integer GkW = `RPU_HW(CoordW);   // G1 ∈ [−10, 10)·2^CW, G2 ∈ [−8, 8]·2^CW

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_curve_point: CoordW must be in 12..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_curve_point: TFrac must be in 8..48");
    if (UnitFrac < 8 || UnitFrac > 40) $fatal(1, "rpu_curve_point: UnitFrac must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_curve_point: TagW must be >= 1");
  end

`include "rpu_mul_latency.vh"
  localparam integer LatG = `RPU_MUL_LAT(GW, OmW, 1) > `RPU_MUL_LAT(GW, TW, 1)
                          ? `RPU_MUL_LAT(GW, OmW, 1) : `RPU_MUL_LAT(GW, TW, 1);
  localparam integer LatU = `RPU_MUL_LAT(UW, GkW, 1);
  localparam integer LatD = `RPU_MUL_LAT(DW, TW, 1);
  // The unit's latency (what the enclosing units count on).
  localparam integer Latency = LatG + LatU + 1;

  initial begin
    if (LatD > LatG + LatU - 1) $fatal(1, "rpu_curve_point: internal: d·t slower than the guides");
  end

  // ---- G1 = floor(g1·(2^FT − t) / 2^FT), G2 = floor(g2·t / 2^FT); u1, u2 and the tag ride along ----
  wire [OmW-1:0] one = {{(OmW - TFrac - 1){1'b0}}, 1'b1, {TFrac{1'b0}}};
  wire [OmW-1:0] omt = one - {t_i[TW-1], t_i};  // 2^FT − t, exact
  localparam integer GTagW = TagW + 6 * UW;
  wire                 g_valid, g2_valid_unused, g2_tag_unused;
  wire [GW+OmW-1:0]    g1omt;
  wire [GW+TW-1:0]     g2t;
  wire [GTagW-1:0]     g_tag;
  rpu_mul #(.AW(GW), .BW(OmW), .Signed(1), .TagW(GTagW), .Latency(LatG)) u_g1 (
    .clk_i, .rst_ni, .valid_i, .a_i(g1_i), .b_i(omt), .tag_i({tag_i, u1_i, u2_i}),
    .valid_o(g_valid), .p_o(g1omt), .tag_o(g_tag));
  rpu_mul #(.AW(GW), .BW(TW), .Signed(1), .TagW(1), .Latency(LatG)) u_g2 (
    .clk_i, .rst_ni, .valid_i, .a_i(g2_i), .b_i(t_i), .tag_i(1'b0),
    .valid_o(g2_valid_unused), .p_o(g2t), .tag_o(g2_tag_unused));
  // |g1·(2^FT − t)| ≤ 5·2^(CW+1+FT): the floor fits GkW bits, the product's top bit is a sign copy.
  wire [GkW-1:0]   G1 = g1omt[TFrac+GkW-1:TFrac];
  wire [GkW-1:0]   G2 = g2t[TFrac+GkW-1:TFrac];
  wire [TagW-1:0]  tag_g = g_tag[GTagW-1 -: TagW];
  wire [3*UW-1:0]  u1_g  = g_tag[6*UW-1 -: 3*UW];
  wire [3*UW-1:0]  u2_g  = g_tag[3*UW-1:0];

  // ---- floor(u1·G1), floor(u2·G2) and p(t) = p1 + floor(d·t), each modulo 2^XW ----
  localparam integer UgW = UW + GkW;
  wire [6*UgW-1:0] ug_p;  // {u2·G2, u1·G1}, three lanes each
  wire [TagW-1:0]  tag_u;
  wire             u_valid;
  rpu_mul_vec #(.Count(6), .AW(UW), .BW(GkW), .Signed(1), .TagW(TagW)) u_ug (
    .clk_i, .rst_ni, .valid_i(g_valid), .a_i({u2_g, u1_g}), .b_i({{3{G2}}, {3{G1}}}),
    .tag_i(tag_g), .valid_o(u_valid), .p_o(ug_p), .tag_o(tag_u));
  wire [3*XW-1:0] x_next;
  reg  [3*XW-1:0] pt_q;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_term
      // d·t, padded so that p(t) is registered when the guide terms arrive; p1 rides along.
      wire [DW+TW-1:0]  dt_p;
      wire [CoordW-1:0] p1;
      wire              dt_v_unused;
      rpu_mul #(.AW(DW), .BW(TW), .Signed(1), .TagW(CoordW), .Latency(LatG + LatU - 1)) u_dt (
        .clk_i, .rst_ni, .valid_i, .a_i(d_i[c*DW +: DW]), .b_i(t_i),
        .tag_i(p1_i[c*CoordW +: CoordW]), .valid_o(dt_v_unused), .p_o(dt_p), .tag_o(p1));
      // The sum's low XW bits: the terms' low XW bits (sign extension of p1, floor(d·t) mod 2^XW).
      always @(posedge clk_i)
        pt_q[c*XW +: XW] <= {{(XW - CoordW){p1[CoordW-1]}}, p1} + dt_p[TFrac +: XW];
      wire [UgW-1:0] ug1_p = ug_p[c*UgW +: UgW];
      wire [UgW-1:0] ug2_p = ug_p[(c + 3)*UgW +: UgW];
      // X = p(t) + floor(u1·G1) + floor(u2·G2) (modulo 2^XW, exact in range)
      assign x_next[c*XW +: XW] = pt_q[c*XW +: XW] + ug1_p[UnitFrac +: XW] + ug2_p[UnitFrac +: XW];
      wire unused_term = ^{dt_v_unused, dt_p[DW+TW-1:TFrac+XW], dt_p[TFrac-1:0],
                           ug1_p[UgW-1:UnitFrac+XW], ug1_p[UnitFrac-1:0],
                           ug2_p[UgW-1:UnitFrac+XW], ug2_p[UnitFrac-1:0]};
    end
  endgenerate
  rpu_stage #(.W(3*XW + TagW)) u_out (
    .clk_i, .rst_ni, .valid_i(u_valid), .d_i({x_next, tag_u}), .valid_o, .q_o({x_o, tag_o}));

  wire unused_products = ^{g1omt[GW+OmW-1:TFrac+GkW], g1omt[TFrac-1:0], g2t[TFrac-1:0]};
  `RPU_LATENCY_CHECK(Latency, "rpu_curve_point")
endmodule

`default_nettype wire
