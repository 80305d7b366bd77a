// rpu_curve_point: the curve point s(t) from the chord and the two guide offsets (the model's
// `curve_point_unit`), per component:
//   X = p1 + floor(d·t / 2^FT) + floor(u1·G1 / 2^FU) + floor(u2·G2 / 2^FU)
//   G1 = floor(g1·(2^FT − t) / 2^FT),  G2 = floor(g2·t / 2^FT)
// Fixed latency of 3 cycles (products of t; products of u; the sum), one operand per cycle, no
// stall; `tag_i` comes out unchanged with the result.
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

module rpu_curve_point #(
  parameter integer CoordW   = 24,  // CW: signed width of positions (12..40)
  parameter integer TFrac    = 24,  // FT: fraction bits of t (8..48)
  parameter integer UnitFrac = 16,  // FU: fraction bits of the guide unit vectors (8..40)
  parameter integer TagW     = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer TW = TFrac + 3,     // t: Q(3.FT)
  parameter integer DW = CoordW + 1,    // d = p2 − p1
  parameter integer UW = UnitFrac + 2,  // u: Q(2.FU)
  parameter integer GW = CoordW + 2,    // g1, g2 (rpu_guide's g_o)
  parameter integer XW = CoordW + 3     // X
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
  output reg               valid_o,
  output reg  [3*XW-1:0]   x_o,     // {z, y, x}, LSB, signed each
  output reg  [TagW-1:0]   tag_o
);
  localparam integer OmW = TW + 1;       // 2^FT − t ∈ (−3, 5]·2^FT
  localparam integer GkW = CoordW + 5;   // G1 ∈ [−10, 10)·2^CW, G2 ∈ [−8, 8]·2^CW
  localparam integer DtW = CoordW + 4;   // floor(d·t) ∈ [−4, 4]·2^CW

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_curve_point: CoordW must be in 12..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_curve_point: TFrac must be in 8..48");
    if (UnitFrac < 8 || UnitFrac > 40) $fatal(1, "rpu_curve_point: UnitFrac must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_curve_point: TagW must be >= 1");
  end

  // ---- stage 1: G1, G2 and floor(d·t) (signed products, explicitly sign-extended) ----
  wire [OmW-1:0]      one = {{(OmW - TFrac - 1){1'b0}}, 1'b1, {TFrac{1'b0}}};
  wire [OmW-1:0]      omt = one - {t_i[TW-1], t_i};  // 2^FT − t, exact
  wire signed [GW+OmW-1:0] g1omt = $signed({{OmW{g1_i[GW-1]}}, g1_i}) *
                                   $signed({{GW{omt[OmW-1]}}, omt});
  wire signed [GW+TW-1:0]  g2t   = $signed({{TW{g2_i[GW-1]}}, g2_i}) *
                                   $signed({{GW{t_i[TW-1]}}, t_i});
  // |g1·(2^FT − t)| ≤ 5·2^(CW+1+FT): the floor fits GkW bits, the product's top bit is a sign copy.
  wire [GkW-1:0]      G1 = g1omt[TFrac+GkW-1:TFrac];
  wire [GkW-1:0]      G2 = g2t[TFrac+GkW-1:TFrac];

  reg               valid_1q;
  reg [3*CoordW-1:0] p1_1q;
  reg [3*DtW-1:0]   dt_1q;
  reg [3*UW-1:0]    u1_1q, u2_1q;
  reg [GkW-1:0]     G1_1q, G2_1q;
  reg [TagW-1:0]    tag_1q;

  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_dt
      wire [DW-1:0] d = d_i[c*DW +: DW];
      wire signed [DW+TW-1:0] dt_p = $signed({{TW{d[DW-1]}}, d}) * $signed({{DW{t_i[TW-1]}}, t_i});
      always @(posedge clk_i) dt_1q[c*DtW +: DtW] <= dt_p[TFrac+DtW-1:TFrac];
      wire unused_dt = ^dt_p[TFrac-1:0];
    end
  endgenerate

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_1q <= 1'b0;
    else         valid_1q <= valid_i;
  end
  always @(posedge clk_i) begin
    p1_1q  <= p1_i;
    u1_1q  <= u1_i;
    u2_1q  <= u2_i;
    G1_1q  <= G1;
    G2_1q  <= G2;
    tag_1q <= tag_i;
  end

  // ---- stage 2: p(t) = p1 + floor(d·t), floor(u1·G1), floor(u2·G2), each modulo 2^XW ----
  reg               valid_2q;
  reg [3*XW-1:0]    pt_2q, ug1_2q, ug2_2q;
  reg [TagW-1:0]    tag_2q;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_term
      wire [CoordW-1:0] p1 = p1_1q[c*CoordW +: CoordW];
      wire [DtW-1:0]    dt = dt_1q[c*DtW +: DtW];
      wire [UW-1:0]     u1 = u1_1q[c*UW +: UW];
      wire [UW-1:0]     u2 = u2_1q[c*UW +: UW];
      // The sum's low XW bits: the terms' low XW bits (sign extension of p1, truncation of dt).
      wire [XW-1:0]     pt = {{(XW - CoordW){p1[CoordW-1]}}, p1} + dt[XW-1:0];
      wire signed [UW+GkW-1:0] ug1_p = $signed({{GkW{u1[UW-1]}}, u1}) *
                                       $signed({{UW{G1_1q[GkW-1]}}, G1_1q});
      wire signed [UW+GkW-1:0] ug2_p = $signed({{GkW{u2[UW-1]}}, u2}) *
                                       $signed({{UW{G2_1q[GkW-1]}}, G2_1q});
      always @(posedge clk_i) begin
        pt_2q[c*XW +: XW]  <= pt;
        ug1_2q[c*XW +: XW] <= ug1_p[UnitFrac+XW-1:UnitFrac];
        ug2_2q[c*XW +: XW] <= ug2_p[UnitFrac+XW-1:UnitFrac];
      end
      wire unused_term = ^{dt[DtW-1:XW], ug1_p[UW+GkW-1:UnitFrac+XW], ug1_p[UnitFrac-1:0],
                           ug2_p[UW+GkW-1:UnitFrac+XW], ug2_p[UnitFrac-1:0]};
    end
  endgenerate

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_2q <= 1'b0;
    else         valid_2q <= valid_1q;
  end
  always @(posedge clk_i) tag_2q <= tag_1q;

  // ---- stage 3: X = p(t) + floor(u1·G1) + floor(u2·G2) (modulo 2^XW, exact in range) ----
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_sum
      always @(posedge clk_i)
        x_o[c*XW +: XW] <= pt_2q[c*XW +: XW] + ug1_2q[c*XW +: XW] + ug2_2q[c*XW +: XW];
    end
  endgenerate

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_o <= 1'b0;
    else         valid_o <= valid_2q;
  end
  always @(posedge clk_i) tag_o <= tag_2q;

  wire unused_products = ^{g1omt[GW+OmW-1:TFrac+GkW], g1omt[TFrac-1:0], g2t[TFrac-1:0]};
endmodule

`default_nettype wire
