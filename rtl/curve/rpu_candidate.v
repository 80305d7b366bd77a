// rpu_candidate: the candidate evaluator of one IP step in the chord's 2-D frame, twin of
// rpu::ref::candidate_unit (docs/fixed-point.md, "The candidate in the chord's frame"). From the
// candidate's polynomial values (formed by the step unit from the pair's frame):
//   t' = clamp(t, 0, 1), c2t' = clamp(c2·t, −1, 1), s2t' likewise, w' = clamp(w, 0, 1/4)
//   ĝ_k = isqrt(η_k² + w'·2^(2FG−FW)) − η_k  (arc),  clamp(a_k, 0, 1 − 2^-FG)  (flat),  0
//   gx  = floor(ĝ1·(1 − t') / 2^FP) + floor(ĝ2·c2t' / 2^FP),  gy = floor(ĝ2·s2t' / 2^FP)
//   o   = sat(floor((x, y) − (gx, gy)·2^(FX−FG)) / 2^(FX−Fo)), Fo + 2 bits)
//   md  = isqrt(ox² + oy²) · 2^(FOMAX−Fo)  or  (ox² + oy²) · 2^(2·(FOMAX−Fo))   (Metric)
// Fo is a parameter (an unrolled step's md_frac(k)), or 0: it comes with the item on fo_i (the
// iterative form's step unit; widths then as for FOMAX).
// Three products of ≤ 25 × 18 bits (one DSP48E1 each) and two squares of Fo + 2 bits. Fixed
// latency; the candidate's context rides in the sub-units' tags.
`default_nettype none
`include "rpu_widths.vh"

module rpu_candidate #(
  parameter integer SqrtW  = 0,   // widest square-root radicand; 0 = exact
  parameter integer Fo     = 20,  // fraction bits of the offsets: md_frac(k) of the step, or 0
  parameter integer Metric = 0,   // 0: md = |o| (seed), 1: md = |o|²
  parameter integer TagW   = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer XW  = `RPU_CXW,
  parameter integer TW  = `RPU_CTW,
  parameter integer WW  = `RPU_CWW,
  parameter integer AW  = `RPU_CAW,
  parameter integer GdW = `RPU_FGDW,
  parameter integer MdW = Metric == 0 ? `RPU_FOMAX + 3 : 2 * `RPU_FOMAX + 3
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              valid_i,
  input  wire [4:0]        fo_i,    // the offsets' fraction bits when Fo == 0 (8..FOMAX)
  input  wire [XW-1:0]     x_i,     // FX
  input  wire [XW-1:0]     y_i,
  input  wire [TW-1:0]     t_i,     // FP
  input  wire [TW-1:0]     c2t_i,
  input  wire [TW-1:0]     s2t_i,
  input  wire [WW-1:0]     w_i,     // FW
  input  wire [2*AW-1:0]   a_i,     // {a2, a1}: flat guides' offsets, FG
  input  wire [GdW-1:0]    g1_i,    // frame guide 1 {mode, η, η²}
  input  wire [GdW-1:0]    g2_i,
  input  wire [TagW-1:0]   tag_i,
  output wire              valid_o,
  output wire [MdW-1:0]    md_o,    // at FOMAX fraction bits (2·FOMAX squared)
  output wire              ovf_o,   // an offset saturated
  output wire [TagW-1:0]   tag_o
);
  localparam integer FX = `RPU_FX, FG = `RPU_FG, FW = `RPU_FW, FP = `RPU_FP;
  localparam integer FOMAX = `RPU_FOMAX;
  localparam integer RadW = `RPU_FRADW, EtaW = `RPU_ETAW;
  localparam integer GW  = FG + 1;   // ĝ, signed: 0 ≤ ĝ < 1
  localparam integer FoW = Fo == 0 ? FOMAX : Fo;  // the widths' Fo
  localparam integer OW  = FoW + 2;  // offsets, signed: |o| < 2
  localparam integer M2W = 2 * FoW + 3;
  // The item's tag inside: {fo, tag}.
  localparam integer ITW = TagW + 5;
  localparam [4:0] FoC = Fo[4:0], FxC = `RPU_FX, FomaxC = `RPU_FOMAX;
  wire [ITW-1:0] itag_i = {Fo == 0 ? fo_i : FoC, tag_i};

  initial begin
    if (Metric != 0 && Metric != 1) $fatal(1, "rpu_candidate: Metric must be 0 or 1");
    if (Fo != 0 && (Fo < 8 || Fo > FOMAX)) $fatal(1, "rpu_candidate: Fo must be 0 or in 8..FOMAX");
    if (GdW != 2 + EtaW + RadW) $fatal(1, "rpu_candidate: GdW is derived; do not override it");
  end

  // ---- stage 1: clamps and the arc radicands ----
  localparam [1:0] ModeArc = 2'd1, ModeFlat = 2'd2;
  wire [1:0]      mode1 = g1_i[GdW-1 -: 2], mode2 = g2_i[GdW-1 -: 2];
  wire [EtaW-1:0] eta1 = g1_i[RadW +: EtaW], eta2 = g2_i[RadW +: EtaW];
  wire [RadW-1:0] ee1 = g1_i[RadW-1:0], ee2 = g2_i[RadW-1:0];
  wire signed [TW-1:0] t_s = t_i, c2_s = c2t_i, s2_s = s2t_i;
  localparam signed [TW-1:0] One = 1 <<< FP, MinusOne = -(1 <<< FP);
  wire [FP:0] t_c  = t_s < 0 ? {(FP+1){1'b0}} : t_s > One ? One[FP:0] : t_s[FP:0];
  wire [FP+1:0] c2_c = c2_s < MinusOne ? MinusOne[FP+1:0] : c2_s > One ? One[FP+1:0] : c2_s[FP+1:0];
  wire [FP+1:0] s2_c = s2_s < MinusOne ? MinusOne[FP+1:0] : s2_s > One ? One[FP+1:0] : s2_s[FP+1:0];
  wire signed [WW-1:0] w_s = w_i;
  localparam signed [WW-1:0] Quarter = 1 <<< (FW - 2);
  // The radicands η² + w'·2^(2FG−FW) for the three cases of the clamp, summed in parallel with
  // the compares and then selected (one adder after the clamp's compare would be 4.06 ns).
  wire w_neg = w_s < 0, w_big = w_s > Quarter;
  wire [RadW-1:0] wsh = {{(RadW+1-2*FG){1'b0}}, w_s[FW-2:0], {(2*FG-FW){1'b0}}};
  localparam [RadW-1:0] QSh = {{(RadW+1-2*FG){1'b0}}, Quarter[FW-2:0], {(2*FG-FW){1'b0}}};
  wire [RadW-1:0] ra1 = ee1 + wsh, rq1 = ee1 + QSh, ra2 = ee2 + wsh, rq2 = ee2 + QSh;
  wire [RadW-1:0] rad1 = w_neg ? ee1 : w_big ? rq1 : ra1;
  wire [RadW-1:0] rad2 = w_neg ? ee2 : w_big ? rq2 : ra2;
  wire signed [AW-1:0] a1_s = a_i[0 +: AW], a2_s = a_i[AW +: AW];
  localparam signed [AW-1:0] GMax = (1 <<< FG) - 1;
  wire [GW-1:0] fl1 = a1_s < 0 ? {GW{1'b0}} : a1_s > GMax ? GMax[GW-1:0] : a1_s[GW-1:0];
  wire [GW-1:0] fl2 = a2_s < 0 ? {GW{1'b0}} : a2_s > GMax ? GMax[GW-1:0] : a2_s[GW-1:0];
  // Context to the guide products: x, y, t', c2t', s2t', the flat offsets, modes, η's, tag.
  localparam integer CtxW = 2*XW + (FP+1) + 2*(FP+2) + 2*GW + 4 + 2*EtaW + ITW;
  wire                valid_1;
  wire [RadW-1:0]     r1_1, r2_1;
  wire [CtxW-1:0]     ctx_1;
  rpu_stage #(.W(2*RadW + CtxW)) u_s1 (
    .clk_i, .rst_ni, .valid_i,
    .d_i({rad1, rad2, x_i, y_i, t_c, c2_c, s2_c, fl1, fl2, mode1, mode2, eta1, eta2,
          itag_i}),
    .valid_o(valid_1), .q_o({r1_1, r2_1, ctx_1}));

  // ---- the two arc roots (the first carries the context) ----
  localparam integer RShift = (SqrtW == 0 || RadW <= SqrtW) ? 0 : (RadW - SqrtW + 1) / 2;
  localparam integer RootW  = (RadW - 2 * RShift + 1) / 2 + RShift;  // rpu_sqrt's root_o
  wire              valid_r;
  wire [CtxW-1:0]   ctx_r;
  wire [RootW-1:0]  root1, root2;
  wire              v_unused, t_unused;
  rpu_sqrt #(.RadW(RadW), .SqrtW(SqrtW), .TagW(CtxW)) u_root1 (
    .clk_i, .rst_ni, .valid_i(valid_1), .rad_i(r1_1), .tag_i(ctx_1),
    .valid_o(valid_r), .root_o(root1), .tag_o(ctx_r));
  rpu_sqrt #(.RadW(RadW), .SqrtW(SqrtW), .TagW(1)) u_root2 (
    .clk_i, .rst_ni, .valid_i(valid_1), .rad_i(r2_1), .tag_i(1'b0),
    .valid_o(v_unused), .root_o(root2), .tag_o(t_unused));
  wire [XW-1:0]   x_r, y_r;
  wire [FP:0]     t_r;
  wire [FP+1:0]   c2_r, s2_r;
  wire [GW-1:0]   fl1_r, fl2_r;
  wire [1:0]      mode1_r, mode2_r;
  wire [EtaW-1:0] eta1_r, eta2_r;
  wire [ITW-1:0] tag_r;
  assign {x_r, y_r, t_r, c2_r, s2_r, fl1_r, fl2_r, mode1_r, mode2_r, eta1_r, eta2_r, tag_r} = ctx_r;

  // ---- stage 2: the guides' offsets, 1 − t' ----
  wire [RootW-1:0] arc1 = root1 - {{(RootW-EtaW){1'b0}}, eta1_r};
  wire [RootW-1:0] arc2 = root2 - {{(RootW-EtaW){1'b0}}, eta2_r};
  wire [GW-1:0] gh1 = mode1_r == ModeArc ? arc1[GW-1:0] : mode1_r == ModeFlat ? fl1_r : {GW{1'b0}};
  wire [GW-1:0] gh2 = mode2_r == ModeArc ? arc2[GW-1:0] : mode2_r == ModeFlat ? fl2_r : {GW{1'b0}};
  localparam [FP:0] OneU = 1 << FP;
  wire [FP+1:0] omt = {1'b0, OneU - t_r};
  localparam integer Ctx2W = 2*XW + ITW;
  wire             valid_2;
  wire [GW-1:0]    gh1_2, gh2_2;
  wire [FP+1:0]    omt_2, c2_2, s2_2;
  wire [Ctx2W-1:0] ctx_2;
  rpu_stage #(.W(2*GW + 3*(FP+2) + Ctx2W)) u_s2 (
    .clk_i, .rst_ni, .valid_i(valid_r),
    .d_i({gh1, gh2, omt, c2_r, s2_r, x_r, y_r, tag_r}),
    .valid_o(valid_2), .q_o({gh1_2, gh2_2, omt_2, c2_2, s2_2, ctx_2}));

  // ---- the three guide products (25 × 18 signed: one DSP48E1 each) ----
  localparam integer PW = FP + 2 + GW;
  wire             valid_p;
  wire [PW-1:0]    p1, p2, p3;
  wire [Ctx2W-1:0] ctx_p;
  wire             vp2_unused, tp2_unused, vp3_unused, tp3_unused;
  rpu_mul #(.AW(FP+2), .BW(GW), .Signed(1), .TagW(Ctx2W)) u_p1 (
    .clk_i, .rst_ni, .valid_i(valid_2), .a_i(omt_2), .b_i(gh1_2), .tag_i(ctx_2),
    .valid_o(valid_p), .p_o(p1), .tag_o(ctx_p));
  rpu_mul #(.AW(FP+2), .BW(GW), .Signed(1), .TagW(1)) u_p2 (
    .clk_i, .rst_ni, .valid_i(valid_2), .a_i(c2_2), .b_i(gh2_2), .tag_i(1'b0),
    .valid_o(vp2_unused), .p_o(p2), .tag_o(tp2_unused));
  rpu_mul #(.AW(FP+2), .BW(GW), .Signed(1), .TagW(1)) u_p3 (
    .clk_i, .rst_ni, .valid_i(valid_2), .a_i(s2_2), .b_i(gh2_2), .tag_i(1'b0),
    .valid_o(vp3_unused), .p_o(p3), .tag_o(tp3_unused));

  // ---- stage 3: the curve's offset in the frame (FG) ----
  wire signed [PW-1:0] p1_s = p1, p2_s = p2, p3_s = p3;
  wire signed [PW-1:0] q1 = p1_s >>> FP, q2 = p2_s >>> FP, q3 = p3_s >>> FP;
  localparam integer GxW = GW + 3;  // |gx| < 2, signed, with room
  wire signed [GxW-1:0] gx = q1[GxW-1:0] + q2[GxW-1:0];
  wire [XW-1:0] x_p, y_p;
  wire [ITW-1:0] tag_p;
  assign {x_p, y_p, tag_p} = ctx_p;
  wire             valid_3;
  wire [GxW-1:0]   gx_3, gy_3;
  wire [XW-1:0]    x_3, y_3;
  wire [ITW-1:0]  tag_3;
  rpu_stage #(.W(2*GxW + 2*XW + ITW)) u_s3 (
    .clk_i, .rst_ni, .valid_i(valid_p), .d_i({gx, q3[GxW-1:0], x_p, y_p, tag_p}),
    .valid_o(valid_3), .q_o({gx_3, gy_3, x_3, y_3, tag_3}));

  // ---- stage 4: (x, y) − g·2^(FX−FG) ----
  localparam integer DfW = XW + 2;
  wire signed [XW-1:0]  x3_s = x_3, y3_s = y_3;
  wire signed [GxW-1:0] gx3_s = gx_3, gy3_s = gy_3;
  wire signed [DfW-1:0] xe = {{(DfW-XW){x3_s[XW-1]}}, x3_s};
  wire signed [DfW-1:0] ye = {{(DfW-XW){y3_s[XW-1]}}, y3_s};
  wire signed [DfW-1:0] gxe = {{(DfW-GxW){gx3_s[GxW-1]}}, gx3_s};
  wire signed [DfW-1:0] gye = {{(DfW-GxW){gy3_s[GxW-1]}}, gy3_s};
  wire signed [DfW-1:0] dx = xe - (gxe <<< (FX - FG));
  wire signed [DfW-1:0] dy = ye - (gye <<< (FX - FG));
  wire             valid_4;
  wire [DfW-1:0]   dx_4, dy_4;
  wire [ITW-1:0]  tag_4;
  rpu_stage #(.W(2*DfW + ITW)) u_s4 (
    .clk_i, .rst_ni, .valid_i(valid_3), .d_i({dx, dy, tag_3}),
    .valid_o(valid_4), .q_o({dx_4, dy_4, tag_4}));

  // ---- stage 5: floor to Fo fraction bits (a shift by FX − Fo); stage 6: saturate to Fo + 2
  //      bits (two stages: with Fo at run time the shift and the compare do not fit one) ----
  wire signed [DfW-1:0] dx4_s = dx_4, dy4_s = dy_4;
  wire [4:0] fo_4 = tag_4[ITW-1 -: 5];
  wire [4:0] drop = FxC - fo_4;  // FX − Fo
  // The bounds ±(2^(Fo+1) − 1) (symmetric), registered beside the shifted values.
  wire [DfW-1:0] one_d = {{(DfW-1){1'b0}}, 1'b1};
  wire [DfW-1:0] omax_4 = (one_d << (fo_4 + 5'd1)) - one_d;
  wire             valid_e;
  wire [DfW-1:0]   ex_e, ey_e, omax_e, omin_e;
  wire [ITW-1:0]   tag_e;
  rpu_stage #(.W(4*DfW + ITW)) u_s5e (
    .clk_i, .rst_ni, .valid_i(valid_4),
    .d_i({dx4_s >>> drop, dy4_s >>> drop, omax_4, ~omax_4 + one_d, tag_4}),
    .valid_o(valid_e), .q_o({ex_e, ey_e, omax_e, omin_e, tag_e}));
  wire signed [DfW-1:0] ex = ex_e, ey = ey_e;
  wire signed [DfW-1:0] OMax = omax_e, OMin = omin_e;
  wire sat_x = ex > OMax || ex < OMin, sat_y = ey > OMax || ey < OMin;
  wire [OW-1:0] ox = ex > OMax ? OMax[OW-1:0] : ex < OMin ? OMin[OW-1:0] : ex[OW-1:0];
  wire [OW-1:0] oy = ey > OMax ? OMax[OW-1:0] : ey < OMin ? OMin[OW-1:0] : ey[OW-1:0];
  wire             valid_5;
  wire [OW-1:0]    ox_5, oy_5;
  wire             ovf_5;
  wire [ITW-1:0]  tag_5;
  rpu_stage #(.W(2*OW + 1 + ITW)) u_s5 (
    .clk_i, .rst_ni, .valid_i(valid_e), .d_i({ox, oy, sat_x | sat_y, tag_e}),
    .valid_o(valid_5), .q_o({ox_5, oy_5, ovf_5, tag_5}));

  // ---- the two squares, their sum ----
  wire              valid_q;
  wire [2*OW-1:0]   sqx, sqy;
  wire [ITW:0]     ctx_q;
  wire              vq_unused, tq_unused;
  rpu_mul #(.AW(OW), .BW(OW), .Signed(1), .TagW(ITW + 1)) u_sqx (
    .clk_i, .rst_ni, .valid_i(valid_5), .a_i(ox_5), .b_i(ox_5), .tag_i({ovf_5, tag_5}),
    .valid_o(valid_q), .p_o(sqx), .tag_o(ctx_q));
  rpu_mul #(.AW(OW), .BW(OW), .Signed(1), .TagW(1)) u_sqy (
    .clk_i, .rst_ni, .valid_i(valid_5), .a_i(oy_5), .b_i(oy_5), .tag_i(1'b0),
    .valid_o(vq_unused), .p_o(sqy), .tag_o(tq_unused));
  wire             valid_6;
  wire [M2W-1:0]   md2_6;
  wire [ITW:0]    ctx_6;
  rpu_stage #(.W(M2W + ITW + 1)) u_s6 (
    .clk_i, .rst_ni, .valid_i(valid_q),
    .d_i({{1'b0, sqx[M2W-2:0]} + {1'b0, sqy[M2W-2:0]}, ctx_q}),
    .valid_o(valid_6), .q_o({md2_6, ctx_6}));

  // ---- md, scaled to FOMAX fraction bits ----
  generate
    if (Metric == 0) begin : g_abs
      localparam integer MShift = (SqrtW == 0 || M2W <= SqrtW) ? 0 : (M2W - SqrtW + 1) / 2;
      localparam integer MRootW = (M2W - 2 * MShift + 1) / 2 + MShift;
      wire [MRootW-1:0] root;
      wire [ITW:0]     ctx_o;
      rpu_sqrt #(.RadW(M2W), .SqrtW(SqrtW), .TagW(ITW + 1)) u_md (
        .clk_i, .rst_ni, .valid_i(valid_6), .rad_i(md2_6), .tag_i(ctx_6),
        .valid_o(valid_o), .root_o(root), .tag_o(ctx_o));
      wire [MdW-1:0] root_w = {{(MdW - MRootW){1'b0}}, root};  // MdW > MRootW
      wire [4:0]     up = FomaxC - ctx_o[ITW-1 -: 5];
      assign md_o = root_w << up;
      assign {ovf_o, tag_o} = {ctx_o[ITW], ctx_o[TagW-1:0]};
    end else begin : g_squared
      wire [MdW:0] md2_w = {{(MdW + 1 - M2W){1'b0}}, md2_6};  // MdW + 1 > M2W
      assign valid_o = valid_6;
      wire [4:0]   up = FomaxC - ctx_6[ITW-1 -: 5];
      assign md_o = md2_w[MdW-1:0] << {up, 1'b0};
      assign {ovf_o, tag_o} = {ctx_6[ITW], ctx_6[TagW-1:0]};
      wire unused_top = md2_w[MdW];
    end
  endgenerate

  wire unused = ^{v_unused, t_unused, vp2_unused, tp2_unused, vp3_unused, tp3_unused, vq_unused,
                  tq_unused, arc1[RootW-1:GW], arc2[RootW-1:GW], q1[PW-1:GxW], q2[PW-1:GxW],
                  q3[PW-1:GxW], sqx[2*OW-1:M2W-1], sqy[2*OW-1:M2W-1]};
endmodule

`default_nettype wire
