// rpu_candidate: the candidate evaluator of one IP step, twin of rpu::ref::candidate_evaluator.
// For the candidate m (τ = m·2^-n):
//   pr = A + floor(AB·m / 2^n)                        ray point
//   t  = sat(α + floor(β·m / 2^n))                     chord parameter, Q(3.FT)
//   g1, g2 = rpu_guide_pair(t)                         both guides, w and L²·w shared, h²
//                                                      from the caller (once per pair)
//   X  = rpu_curve_point(t, g1, g2)                    curve point s(t)
//   md = isqrt(sat(|pr − X|²)) or sat(|pr − X|²)       by Metric
// Fixed latency; the candidate's context rides in the sub-units' tags.
`default_nettype none
`include "rpu_widths.vh"

module rpu_candidate #(
`include "rpu_ip_params.vh"
  parameter integer Metric   = 0,   // 0: md = |pr − X| (seed), 1: md = |pr − X|²
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
`include "rpu_ip_derived.vh"
  parameter integer PrW  = `RPU_PRW(CoordW),          // pr
  parameter integer Md2W = `RPU_MD2W(CoordW),      // |pr − X|² format (dist_radicand_w)
  parameter integer MdW  = Metric == 0 ? CoordW + 4 : Md2W
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [N:0]          m_i,        // τ index, 0..2^N
  input  wire [3*CoordW-1:0] a_i,        // A, {z, y, x}
  input  wire [3*DW-1:0]     ab_i,       // B − A
  input  wire [TW-1:0]       alpha_i,
  input  wire [TW-1:0]       beta_i,
  input  wire [3*CoordW-1:0] p1_i,
  input  wire [3*DW-1:0]     d_i,
  input  wire [L2W-1:0]      l2_i,
  input  wire [GdW-1:0]      g1_i,       // guide of end 1 (rpu_guide_desc.vh)
  input  wire [RadW-1:0]     hh1_i,      // h1², computed once per pair by the caller
  input  wire [GdW-1:0]      g2_i,       // guide of end 2
  input  wire [RadW-1:0]     hh2_i,      // h2²
  input  wire [TagW-1:0]     tag_i,
  output wire                valid_o,
  output wire [TW-1:0]       t_o,
  output wire [3*XW-1:0]     x_o,
  output wire [3*PrW-1:0]    pr_o,
  output wire [MdW-1:0]      md_o,
  output wire                ovf_o,      // some value of this candidate saturated
  output wire [TagW-1:0]     tag_o
);
  localparam integer GW = `RPU_PRW(CoordW);  // rpu_guide_pair's g
`include "rpu_guide_desc.vh"
  localparam integer GsW = `RPU_GSW(CoordW, TFrac);  // a guide's shape (rpu_guide_pair's g1_i)

  initial begin
    if (Metric != 0 && Metric != 1) $fatal(1, "rpu_candidate: Metric must be 0 or 1");
    if (N < 1 || N > 40) $fatal(1, "rpu_candidate: N must be in 1..40");
    if (GdW != GdWords) $fatal(1, "rpu_candidate: GdW is derived; do not override it");
  end

`include "rpu_mul_latency.vh"
  // ---- pr(m) and t(m): the products (rpu_mul), then the sums, registered ----
  localparam integer MW   = N + 2;  // m as a signed value
  localparam integer LatM = `RPU_MUL_LAT(TW, MW, 1) > `RPU_MUL_LAT(DW, MW, 1)
                          ? `RPU_MUL_LAT(TW, MW, 1) : `RPU_MUL_LAT(DW, MW, 1);
  wire [MW-1:0] m_s = {1'b0, m_i};
  // Everything the guides, the curve point and the end need rides in the t product's tag.
  localparam integer InW = 3*CoordW + TW + 3*CoordW + 3*DW + L2W + 2 * (GdW + RadW) + TagW;
  wire          mt_valid;
  wire [TW+MW-1:0] bm;
  wire [InW-1:0]   in_m;
  rpu_mul #(.AW(TW), .BW(MW), .Signed(1), .TagW(InW), .Latency(LatM)) u_bm (
    .clk_i, .rst_ni, .valid_i, .a_i(beta_i), .b_i(m_s),
    .tag_i({a_i, alpha_i, p1_i, d_i, l2_i, g1_i, hh1_i, g2_i, hh2_i, tag_i}),
    .valid_o(mt_valid), .p_o(bm), .tag_o(in_m));
  wire [3*CoordW-1:0] a_m;
  wire [TW-1:0]       alpha_m;
  wire [3*CoordW-1:0] p1_m;
  wire [3*DW-1:0]     d_m;
  wire [L2W-1:0]      l2_m;
  wire [GdW-1:0]      g1_m, g2_m;
  wire [RadW-1:0]     hh1_m, hh2_m;
  wire [TagW-1:0]     tag_m;
  assign {a_m, alpha_m, p1_m, d_m, l2_m, g1_m, hh1_m, g2_m, hh2_m, tag_m} = in_m;

  wire [3*PrW-1:0] pr_m;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_pr
      wire [DW+MW-1:0] prod;
      wire             v_unused, t_unused;
      rpu_mul #(.AW(DW), .BW(MW), .Signed(1), .TagW(1), .Latency(LatM)) u_abm (
        .clk_i, .rst_ni, .valid_i, .a_i(ab_i[c*DW +: DW]), .b_i(m_s), .tag_i(1'b0),
        .valid_o(v_unused), .p_o(prod), .tag_o(t_unused));
      wire signed [CoordW-1:0] ac   = a_m[c*CoordW +: CoordW];
      wire signed [DW+MW-1:0]  step = $signed(prod) >>> N;  // floor
      assign pr_m[c*PrW +: PrW] = {{(PrW-CoordW){ac[CoordW-1]}}, ac} + step[PrW-1:0];
      wire unused_step = ^{step[DW+MW-1:PrW], v_unused, t_unused};
    end
  endgenerate
  wire signed [TW-1:0]    alpha = alpha_m;
  wire signed [TW+MW-1:0] bstep = $signed(bm) >>> N;
  wire signed [TW+MW:0]   tsum  = {{(MW+1){alpha[TW-1]}}, alpha} + {bstep[TW+MW-1], bstep};
  wire signed [TW+MW:0]   tmax  = {{(MW+1){1'b0}}, 1'b0, {(TW-1){1'b1}}};
  wire signed [TW+MW:0]   tmin  = {{(MW+1){1'b1}}, 1'b1, {(TW-1){1'b0}}};
  wire                    t_hi  = tsum > tmax;
  wire                    t_lo  = tsum < tmin;
  wire [TW-1:0]           t_m   = t_hi ? tmax[TW-1:0] : t_lo ? tmin[TW-1:0] : tsum[TW-1:0];

  // ---- the two guides; the candidate's context (and the segment fields the curve point needs
  //      later) ride in the guide pair's tag ----
  localparam integer SegW   = 3*CoordW + 3*DW + 2*GdUW;  // p1, d, u1, u2
  localparam integer G1TagW = SegW + 3*PrW + TW + 1 + TagW;
  // The guide pair's tag, LSB first: {seg, pr, t, ovf, tag}; seg = {p1, d, u1, u2}.
  localparam integer GtPrO   = G1TagW - SegW - 3*PrW;
  localparam integer SegDO   = 2*GdUW;
  localparam integer GdInW   = GsW + RadW;  // one guide's shape and h²
  wire                  valid_q1;
  wire [3*PrW-1:0]      pr_q1;
  wire [TW-1:0]         t_q1;
  wire                  ovf_q1;
  wire [TagW-1:0]       tag_q1;
  wire [SegW-1:0]       seg_q1;
  wire [L2W-1:0]        l2_q1;
  wire [GsW-1:0]        gs1_q1, gs2_q1;  // the guides' shapes
  wire [RadW-1:0]       hh1_q1, hh2_q1;
  rpu_stage #(.W(3*PrW + TW + 1 + TagW + SegW + L2W + 2*GdInW)) u_q1 (
    .clk_i, .rst_ni, .valid_i(mt_valid),
    .d_i({pr_m, t_m, t_hi | t_lo, tag_m, p1_m, d_m, g1_m[GdUO +: GdUW], g2_m[GdUO +: GdUW], l2_m,
          g1_m[GdShapeO +: GsW], hh1_m, g2_m[GdShapeO +: GsW], hh2_m}),
    .valid_o(valid_q1),
    .q_o({pr_q1, t_q1, ovf_q1, tag_q1, seg_q1, l2_q1, gs1_q1, hh1_q1, gs2_q1, hh2_q1}));
  wire [G1TagW-1:0] g1_tag_out;
  wire              g1_valid, g_ovf;
  wire [GW-1:0]     g1, g2;
  wire [TFrac-2:0]  w_unused;
  rpu_guide_pair #(.CoordW(CoordW), .TFrac(TFrac), .SqrtW(SqrtW), .HhIn(1), .TagW(G1TagW))
    u_guides (
    .clk_i, .rst_ni, .valid_i(valid_q1), .t_i(t_q1), .l2_i(l2_q1),
    .g1_i(gs1_q1), .hh1_i(hh1_q1), .g2_i(gs2_q1), .hh2_i(hh2_q1),
    .tag_i({seg_q1, pr_q1, t_q1, ovf_q1, tag_q1}),
    .valid_o(g1_valid), .g1_o(g1), .g2_o(g2), .w_o(w_unused), .ovf_o(g_ovf),
    .tag_o(g1_tag_out));
  wire [SegW-1:0]  seg_g = g1_tag_out[G1TagW-1 -: SegW];
  wire [3*PrW-1:0] pr_g = g1_tag_out[GtPrO +: 3*PrW];
  wire [3*CoordW-1:0] p1_g = seg_g[SegW-1 -: 3*CoordW];
  wire [3*DW-1:0]     d_g  = seg_g[SegDO +: 3*DW];
  wire [GdUW-1:0]     u1_g = seg_g[GdUW +: GdUW];
  wire [GdUW-1:0]     u2_g = seg_g[0 +: GdUW];
  wire [TW-1:0]    t_g  = g1_tag_out[TW+1+TagW-1 -: TW];
  wire             ovf_g = g1_tag_out[TagW] | g_ovf;
  wire [TagW-1:0]  tag_g = g1_tag_out[TagW-1:0];
  wire unused_guide = ^w_unused;

  // ---- curve point ----
  localparam integer CpTagW = 3*PrW + TW + 1 + TagW;
  wire              cp_valid;
  wire [3*XW-1:0]   x_cp;
  wire [CpTagW-1:0] cp_tag;
  rpu_curve_point #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .TagW(CpTagW)) u_cp (
    .clk_i, .rst_ni, .valid_i(g1_valid), .p1_i(p1_g), .d_i(d_g), .u1_i(u1_g), .u2_i(u2_g),
    .t_i(t_g), .g1_i(g1), .g2_i(g2), .tag_i({pr_g, t_g, ovf_g, tag_g}),
    .valid_o(cp_valid), .x_o(x_cp), .tag_o(cp_tag));
  wire [3*PrW-1:0] pr_c  = cp_tag[CpTagW-1 -: 3*PrW];
  wire [TW-1:0]    t_c   = cp_tag[TW+1+TagW-1 -: TW];
  wire             ovf_c = cp_tag[TagW];
  wire [TagW-1:0]  tag_c = cp_tag[TagW-1:0];

  // ---- |pr − X|²: three squares (rpu_mul), then two sums, saturated to Md2W bits ----
  localparam integer DfW = CoordW + 4;      // pr − X
  localparam integer SqW = 2 * DfW + 2;     // sum of three squares
  localparam integer ExW = 3*XW + 3*PrW + TW + 1 + TagW;
  wire [2*DfW-1:0] sq [0:2];
  wire             sq_valid;
  wire [ExW-1:0]   sq_tag;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_diff
      wire signed [PrW-1:0] prc = pr_c[c*PrW +: PrW];
      wire signed [XW-1:0]  xc  = x_cp[c*XW +: XW];
      wire signed [DfW-1:0] df  = {{(DfW-PrW){prc[PrW-1]}}, prc} - {{(DfW-XW){xc[XW-1]}}, xc};
      if (c == 0) begin : g_carry
        rpu_mul #(.AW(DfW), .BW(DfW), .Signed(1), .TagW(ExW)) u_sq (
          .clk_i, .rst_ni, .valid_i(cp_valid), .a_i(df), .b_i(df),
          .tag_i({x_cp, pr_c, t_c, ovf_c, tag_c}), .valid_o(sq_valid), .p_o(sq[c]),
          .tag_o(sq_tag));
      end else begin : g_plain
        // The third square arrives one cycle later, when the first two are summed (its extra
        // cycle is an operand delay inside rpu_mul, so the sum starts from its flip-flops).
        wire v_unused, t_unused;
        rpu_mul #(.AW(DfW), .BW(DfW), .Signed(1), .TagW(1),
                  .Latency(c == 2 ? `RPU_MUL_LAT(DfW, DfW, 1) + 1 : 0)) u_sq (
          .clk_i, .rst_ni, .valid_i(cp_valid), .a_i(df), .b_i(df), .tag_i(1'b0),
          .valid_o(v_unused), .p_o(sq[c]), .tag_o(t_unused));
        wire unused_sq_ctl = ^{v_unused, t_unused};
      end
    end
  endgenerate
  // Two adds, one register after each (a square is ≥ 0: its top bit is 0).
  wire            valid_s;
  wire [SqW-1:0]  s01_s;
  wire [ExW-1:0]  ex_s;
  rpu_stage #(.W(SqW + ExW)) u_sum01 (
    .clk_i, .rst_ni, .valid_i(sq_valid), .d_i({{2'b00, sq[0]} + {2'b00, sq[1]}, sq_tag}),
    .valid_o(valid_s), .q_o({s01_s, ex_s}));
  // The full sum, registered; then the saturation to Md2W bits in a stage of its own (a 58-bit
  // carry chain and the saturating mux do not fit one 4 ns stage together).
  wire            valid_f;
  wire [SqW-1:0]  md2_f;
  wire [ExW-1:0]  ex_f;
  rpu_stage #(.W(SqW + ExW)) u_sum (
    .clk_i, .rst_ni, .valid_i(valid_s), .d_i({s01_s + {2'b00, sq[2]}, ex_s}),
    .valid_o(valid_f), .q_o({md2_f, ex_f}));
  wire            md2_big  = |md2_f[SqW-1:Md2W];
  wire            valid_q2;
  wire [Md2W-1:0] md2_q2;
  wire            ovf_q2;
  wire [3*XW-1:0] x_q2;
  wire [3*PrW-1:0] pr_q2;
  wire [TW-1:0]   t_q2;
  wire [TagW-1:0] tag_q2;
  // ex = {X, pr, t, ovf, tag}
  rpu_stage #(.W(Md2W + ExW)) u_sat (
    .clk_i, .rst_ni, .valid_i(valid_f),
    .d_i({md2_big ? {Md2W{1'b1}} : md2_f[Md2W-1:0], ex_f[ExW-1:TagW+1], ex_f[TagW] | md2_big,
          ex_f[TagW-1:0]}),
    .valid_o(valid_q2), .q_o({md2_q2, x_q2, pr_q2, t_q2, ovf_q2, tag_q2}));

  // ---- md: the square root (seed metric) or the square itself ----
  generate
    if (Metric == 0) begin : g_abs
      localparam integer OutTagW = 3*XW + 3*PrW + TW + 1 + TagW;
      wire [OutTagW-1:0] out_tag;
      wire [CoordW+3:0]  root;
      rpu_sqrt #(.RadW(Md2W), .SqrtW(SqrtW), .TagW(OutTagW)) u_md (
        .clk_i, .rst_ni, .valid_i(valid_q2), .rad_i(md2_q2),
        .tag_i({x_q2, pr_q2, t_q2, ovf_q2, tag_q2}),
        .valid_o(valid_o), .root_o(root), .tag_o(out_tag));
      assign md_o  = root;
      assign x_o   = out_tag[OutTagW-1 -: 3*XW];
      localparam integer OtPrO = OutTagW - 3*XW - 3*PrW;  // {X, pr, t, ovf, tag}
      assign pr_o  = out_tag[OtPrO +: 3*PrW];
      assign t_o   = out_tag[TW+1+TagW-1 -: TW];
      assign ovf_o = out_tag[TagW];
      assign tag_o = out_tag[TagW-1:0];
    end else begin : g_squared
      assign {valid_o, md_o, x_o, pr_o, t_o, ovf_o, tag_o} =
             {valid_q2, md2_q2, x_q2, pr_q2, t_q2, ovf_q2, tag_q2};
    end
  endgenerate
endmodule

`default_nettype wire
