// rpu_test_point: once per pair after the K steps, the test point of the selected τ for the
// capture unit; twin of rpu::ref::test_point_unit (docs/fixed-point.md, "Signals between units"):
//   t = sat(α + floor(β·τ / 2^N)), Q(3.FT)
//   g1, g2 = rpu_guide_pair(t)            (h² from the caller, once per pair)
//   X = rpu_curve_point(t, g1, g2)        s(t), LSB
// Fixed latency; the tag rides along.
`default_nettype none
`include "rpu_widths.vh"

module rpu_test_point #(
`include "rpu_ip_params.vh"
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
`include "rpu_ip_derived.vh"
  parameter integer TauW = N
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [TauW-1:0]     tau_i,      // τ index, 0 .. 2^N − 1
  input  wire [TW-1:0]       alpha_i,
  input  wire [TW-1:0]       beta_i,
  input  wire [3*CoordW-1:0] p1_i,
  input  wire [3*DW-1:0]     d_i,
  input  wire [L2W-1:0]      l2_i,
  input  wire [GdW-1:0]      g1_i,       // guide of end 1 (rpu_guide_desc.vh)
  input  wire [RadW-1:0]     hh1_i,      // h1², computed once per pair by the caller
  input  wire [GdW-1:0]      g2_i,
  input  wire [RadW-1:0]     hh2_i,
  input  wire [TagW-1:0]     tag_i,
  output wire                valid_o,
  output wire [TW-1:0]       t_o,
  output wire [3*XW-1:0]     x_o,
  output wire                ovf_o,      // t or a guide saturated
  output wire [TagW-1:0]     tag_o
);
  localparam integer GW = `RPU_PRW(CoordW);  // rpu_guide_pair's g
`include "rpu_guide_desc.vh"
  localparam integer GsW = `RPU_GSW(CoordW, TFrac);

  initial begin
    if (N < 1 || N > 40) $fatal(1, "rpu_test_point: N must be in 1..40");
    if (GdW != GdWords) $fatal(1, "rpu_test_point: GdW is derived; do not override it");
  end

`include "rpu_mul_latency.vh"
  // ---- t = sat(α + floor(β·τ / 2^N)) ----
  localparam integer MW   = N + 1;  // τ as a signed value
  localparam integer LatM = `RPU_MUL_LAT(TW, MW, 1);
  localparam integer InW  = TW + 3*CoordW + 3*DW + L2W + 2 * (GdW + RadW) + TagW;
  wire             mt_valid;
  wire [TW+MW-1:0] bm;
  wire [InW-1:0]   in_m;
  rpu_mul #(.AW(TW), .BW(MW), .Signed(1), .TagW(InW), .Latency(LatM)) u_bm (
    .clk_i, .rst_ni, .valid_i, .a_i(beta_i), .b_i({1'b0, tau_i}),
    .tag_i({alpha_i, p1_i, d_i, l2_i, g1_i, hh1_i, g2_i, hh2_i, tag_i}),
    .valid_o(mt_valid), .p_o(bm), .tag_o(in_m));
  wire [TW-1:0]       alpha_m;
  wire [3*CoordW-1:0] p1_m;
  wire [3*DW-1:0]     d_m;
  wire [L2W-1:0]      l2_m;
  wire [GdW-1:0]      g1_m, g2_m;
  wire [RadW-1:0]     hh1_m, hh2_m;
  wire [TagW-1:0]     tag_m;
  assign {alpha_m, p1_m, d_m, l2_m, g1_m, hh1_m, g2_m, hh2_m, tag_m} = in_m;
  wire signed [TW-1:0]    alpha = alpha_m;
  wire signed [TW+MW-1:0] bstep = $signed(bm) >>> N;
  wire signed [TW+MW:0]   tsum  = {{(MW+1){alpha[TW-1]}}, alpha} + {bstep[TW+MW-1], bstep};
  wire signed [TW+MW:0]   tmax  = {{(MW+1){1'b0}}, 1'b0, {(TW-1){1'b1}}};
  wire signed [TW+MW:0]   tmin  = {{(MW+1){1'b1}}, 1'b1, {(TW-1){1'b0}}};
  wire                    t_hi  = tsum > tmax;
  wire                    t_lo  = tsum < tmin;
  wire [TW-1:0]           t_m   = t_hi ? tmax[TW-1:0] : t_lo ? tmin[TW-1:0] : tsum[TW-1:0];

  // ---- the two guides; the segment fields the curve point needs ride in the guide pair's tag ----
  localparam integer SegW   = 3*CoordW + 3*DW + 2*GdUW;  // p1, d, u1, u2
  localparam integer G1TagW = SegW + TW + 1 + TagW;
  localparam integer SegDO  = 2*GdUW;
  localparam integer GdInW  = GsW + RadW;
  wire                  valid_q1;
  wire [TW-1:0]         t_q1;
  wire                  ovf_q1;
  wire [TagW-1:0]       tag_q1;
  wire [SegW-1:0]       seg_q1;
  wire [L2W-1:0]        l2_q1;
  wire [GsW-1:0]        gs1_q1, gs2_q1;
  wire [RadW-1:0]       hh1_q1, hh2_q1;
  rpu_stage #(.W(TW + 1 + TagW + SegW + L2W + 2*GdInW)) u_q1 (
    .clk_i, .rst_ni, .valid_i(mt_valid),
    .d_i({t_m, t_hi | t_lo, tag_m, p1_m, d_m, g1_m[GdUO +: GdUW], g2_m[GdUO +: GdUW], l2_m,
          g1_m[GdShapeO +: GsW], hh1_m, g2_m[GdShapeO +: GsW], hh2_m}),
    .valid_o(valid_q1),
    .q_o({t_q1, ovf_q1, tag_q1, seg_q1, l2_q1, gs1_q1, hh1_q1, gs2_q1, hh2_q1}));
  wire [G1TagW-1:0] g_tag;
  wire              g_valid, g_ovf;
  wire [GW-1:0]     g1, g2;
  wire [TFrac-2:0]  w_unused;
  rpu_guide_pair #(.CoordW(CoordW), .TFrac(TFrac), .SqrtW(SqrtW), .HhIn(1), .TagW(G1TagW))
    u_guides (
    .clk_i, .rst_ni, .valid_i(valid_q1), .t_i(t_q1), .l2_i(l2_q1),
    .g1_i(gs1_q1), .hh1_i(hh1_q1), .g2_i(gs2_q1), .hh2_i(hh2_q1),
    .tag_i({seg_q1, t_q1, ovf_q1, tag_q1}),
    .valid_o(g_valid), .g1_o(g1), .g2_o(g2), .w_o(w_unused), .ovf_o(g_ovf), .tag_o(g_tag));
  wire [SegW-1:0]     seg_g = g_tag[G1TagW-1 -: SegW];
  wire [3*CoordW-1:0] p1_g  = seg_g[SegW-1 -: 3*CoordW];
  wire [3*DW-1:0]     d_g   = seg_g[SegDO +: 3*DW];
  wire [GdUW-1:0]     u1_g  = seg_g[GdUW +: GdUW];
  wire [GdUW-1:0]     u2_g  = seg_g[0 +: GdUW];
  wire [TW-1:0]       t_g   = g_tag[TW+1+TagW-1 -: TW];
  wire                ovf_g = g_tag[TagW] | g_ovf;
  wire [TagW-1:0]     tag_g = g_tag[TagW-1:0];

  // ---- the curve point ----
  localparam integer CpTagW = TW + 1 + TagW;
  wire [CpTagW-1:0] cp_tag;
  rpu_curve_point #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .TagW(CpTagW)) u_cp (
    .clk_i, .rst_ni, .valid_i(g_valid), .p1_i(p1_g), .d_i(d_g), .u1_i(u1_g), .u2_i(u2_g),
    .t_i(t_g), .g1_i(g1), .g2_i(g2), .tag_i({t_g, ovf_g, tag_g}),
    .valid_o(valid_o), .x_o(x_o), .tag_o(cp_tag));
  assign {t_o, ovf_o, tag_o} = cp_tag;
  wire unused = ^{w_unused, g1_m[GdW-1:0], g2_m[GdW-1:0]};
endmodule

`default_nettype wire
