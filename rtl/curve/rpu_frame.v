// rpu_frame: the frame unit, once per (ray, segment) pair; twin of rpu::ref::frame_unit
// (docs/fixed-point.md, "The candidate in the chord's frame"). From the sphere unit's interval
// (A, B − A, α, β), the segment's p1 and its frame descriptor {e1, e2, s, c2, s2, a1, a2}:
//   x0 = sat(floor(((A − p1)·e1) / 2^(s − FX))), y0 with e2, x1, y1 with B − A   (FX + 3 bits)
//   c2a = c2·α, c2b = c2·β, s2a = s2·α, s2b = s2·β                             (exact)
//   w0 = floor(α(2^FT − α) · 2^(FW + 2n − 2FT)), w1 = floor(β(2^FT − 2α) · 2^(FW + n − 2FT)),
//   w2 = floor(−β² · 2^(FW − 2FT))                                             (exact widths)
//   a_k,i = floor(a_k · floor(w_i / 2^(FW − FG)) / 2^FA)                       (flat guides)
// Products: 12 of (CoordW+1) × 18 bits, 4 of (FT+3) × 18, 3 of (FT+5)², then 6 flat ones.
// Fixed latency; α, β and the tag ride along. The descriptor's s is at least 20 (L ≥ 8 LSB).
`default_nettype none
`include "rpu_widths.vh"

module rpu_frame #(
  parameter integer CoordW = 24,  // position width
  parameter integer TFrac  = 24,  // fraction bits of t
  parameter integer N      = 16,  // result bits of τ
  parameter integer TagW   = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer DW   = `RPU_DW(CoordW),
  parameter integer TW   = `RPU_TW(TFrac),
  parameter integer FrW  = `RPU_FRDW,
  parameter integer XW   = `RPU_CXW,
  parameter integer CaW  = `RPU_FCAW(TFrac),
  parameter integer W0W  = `RPU_FW0W(N),
  parameter integer W1W  = `RPU_FW1W(N),
  parameter integer W2W  = `RPU_FW2W,
  parameter integer A0W  = W0W - (`RPU_FW - `RPU_FG),
  parameter integer A1W  = W1W - (`RPU_FW - `RPU_FG),
  parameter integer A2W  = W2W - (`RPU_FW - `RPU_FG)
) (
  input  wire                     clk_i,
  input  wire                     rst_ni,
  input  wire                     valid_i,
  input  wire [3*CoordW-1:0]      a_i,      // A, {z, y, x}
  input  wire [3*DW-1:0]          ab_i,     // B − A
  input  wire [TW-1:0]            alpha_i,
  input  wire [TW-1:0]            beta_i,
  input  wire [3*CoordW-1:0]      p1_i,
  input  wire [FrW-1:0]           fr_i,     // {e1, e2, s, c2, s2, a1, a2} (MSB first)
  input  wire [TagW-1:0]          tag_i,
  output wire                     valid_o,
  output wire [4*XW-1:0]          xy_o,     // {x0, x1, y0, y1}
  output wire [4*CaW-1:0]         cs_o,     // {c2a, c2b, s2a, s2b}
  output wire [W0W+W1W+W2W-1:0]   w_o,      // {w0, w1, w2}
  output wire [2*(A0W+A1W+A2W)-1:0] fa_o,   // {a1,0, a1,1, a1,2, a2,0, a2,1, a2,2}
  output wire [TW-1:0]            alpha_o,
  output wire [TW-1:0]            beta_o,
  output wire                     ovf_o,    // x0, x1, y0 or y1 saturated
  output wire [TagW-1:0]          tag_o
);
  localparam integer FX = `RPU_FX, FW = `RPU_FW, FG = `RPU_FG, FA = `RPU_FA;
  localparam integer EW = `RPU_FEW, SW = `RPU_FSW, CW2 = `RPU_FCW, AW = `RPU_FAW;

  initial begin
    if (FrW != 6*EW + SW + 2*CW2 + 2*AW) $fatal(1, "rpu_frame: FrW is derived; do not override it");
    if (N < 1 || N > 40) $fatal(1, "rpu_frame: N must be in 1..40");
  end

  // ---- stage 0: A − p1, 1 − α, 1 − 2α; the descriptor's fields ----
  localparam integer RestW = SW + 2*CW2 + 2*AW;  // {s, c2, s2, a1, a2}
  wire [3*EW-1:0] e1 = fr_i[RestW + 3*EW +: 3*EW];
  wire [3*EW-1:0] e2 = fr_i[RestW +: 3*EW];
  wire [RestW-1:0] rest = fr_i[RestW-1:0];
  wire [3*DW-1:0] ap;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_ap
      wire signed [CoordW-1:0] ac = a_i[c*CoordW +: CoordW], pc = p1_i[c*CoordW +: CoordW];
      assign ap[c*DW +: DW] = {ac[CoordW-1], ac} - {pc[CoordW-1], pc};
    end
  endgenerate
  localparam integer OW = TW + 2;  // 2^FT − α, 2^FT − 2α, β: signed
  wire signed [OW-1:0] al = {{2{alpha_i[TW-1]}}, alpha_i};
  localparam signed [OW-1:0] OneT = 1 <<< TFrac;
  wire signed [OW-1:0] om1 = OneT - al, om2 = OneT - (al <<< 1);
  wire             valid_0;
  wire [3*DW-1:0]  ap_0, ab_0;
  wire [3*EW-1:0]  e1_0, e2_0;
  wire [RestW-1:0] rest_0;
  wire [TW-1:0]    al_0, be_0;
  wire [OW-1:0]    om1_0, om2_0;
  wire [TagW-1:0]  tag_0;
  rpu_stage #(.W(6*DW + 6*EW + RestW + 2*TW + 2*OW + TagW)) u_s0 (
    .clk_i, .rst_ni, .valid_i,
    .d_i({ap, ab_i, e1, e2, rest, alpha_i, beta_i, om1, om2, tag_i}),
    .valid_o(valid_0), .q_o({ap_0, ab_0, e1_0, e2_0, rest_0, al_0, be_0, om1_0, om2_0, tag_0}));
  wire [SW-1:0]  s_0  = rest_0[RestW-1 -: SW];
  wire [CW2-1:0] c2_0 = rest_0[2*AW+CW2 +: CW2], s2_0 = rest_0[2*AW +: CW2];
  wire [2*AW-1:0] fa_0 = rest_0[2*AW-1:0];  // {a1, a2}

`include "rpu_mul_latency.vh"
  localparam integer LE = `RPU_MUL_LAT(DW, EW, 1), LC = `RPU_MUL_LAT(TW, CW2, 1);
  localparam integer LW = `RPU_MUL_LAT(OW, OW, 1);
  localparam integer L1 = LE > LC ? (LE > LW ? LE : LW) : (LC > LW ? LC : LW);
  // ---- the products: (A − p1)·e, (B − A)·e; c2·α …; α(1 − α), β(1 − 2α), β² ----
  localparam integer PE = DW + EW, PC = TW + CW2, PWW = 2 * OW;
  localparam integer Ctx1W = SW + 2*AW + 2*TW + TagW;
  wire             valid_1;
  wire [12*PE-1:0] pe;
  wire [Ctx1W-1:0] ctx_1;
  rpu_mul_vec #(.Count(12), .AW(DW), .BW(EW), .Signed(1), .TagW(Ctx1W), .Latency(L1)) u_pe (
    .clk_i, .rst_ni, .valid_i(valid_0),
    .a_i({ab_0, ab_0, ap_0, ap_0}), .b_i({e2_0, e1_0, e2_0, e1_0}),
    .tag_i({s_0, fa_0, al_0, be_0, tag_0}), .valid_o(valid_1), .p_o(pe), .tag_o(ctx_1));
  wire [4*PC-1:0] pc;
  wire            vc_unused, tc_unused;
  rpu_mul_vec #(.Count(4), .AW(TW), .BW(CW2), .Signed(1), .TagW(1), .Latency(L1)) u_pc (
    .clk_i, .rst_ni, .valid_i(valid_0),
    .a_i({be_0, al_0, be_0, al_0}), .b_i({s2_0, s2_0, c2_0, c2_0}), .tag_i(1'b0),
    .valid_o(vc_unused), .p_o(pc), .tag_o(tc_unused));
  wire [3*PWW-1:0] pw;
  wire             vw_unused, tw_unused;
  wire [OW-1:0]    al_w = {{2{al_0[TW-1]}}, al_0}, be_w = {{2{be_0[TW-1]}}, be_0};
  rpu_mul_vec #(.Count(3), .AW(OW), .BW(OW), .Signed(1), .TagW(1), .Latency(L1)) u_pw (
    .clk_i, .rst_ni, .valid_i(valid_0),
    .a_i({be_w, be_w, al_w}), .b_i({be_w, om2_0, om1_0}), .tag_i(1'b0),
    .valid_o(vw_unused), .p_o(pw), .tag_o(tw_unused));

  // ---- stage 1: the four dot products' first two terms; W's coefficients (constant shifts) ----
  // (a three-term sum right after the products becomes a chain of three cascaded DSP post-adders,
  // 4.1 ns; two terms per stage stay within the budget)
  localparam integer DotW = PE + 2;
  wire [4*(PE+1)-1:0] d01;
  wire [4*PE-1:0]     d2;
  generate
    for (c = 0; c < 4; c = c + 1) begin : g_dot  // x0, y0, x1, y1 (lanes 3c .. 3c+2)
      wire signed [PE-1:0] q0 = pe[(3*c)*PE +: PE], q1 = pe[(3*c+1)*PE +: PE];
      assign d01[c*(PE+1) +: PE+1] = {q0[PE-1], q0} + {q1[PE-1], q1};
      assign d2[c*PE +: PE]        = pe[(3*c+2)*PE +: PE];
    end
  endgenerate
  // floor(v · 2^k) for a constant k of either sign, to a width Wout (the value fits).
  function automatic [127:0] shift_const(input [127:0] v, input integer k);
    shift_const = k >= 0 ? v << k : $signed(v) >>> (-k);
  endfunction
  wire signed [PWW-1:0] pw0 = pw[0 +: PWW], pw1 = pw[PWW +: PWW], pw2 = pw[2*PWW +: PWW];
  wire [127:0] w0x = shift_const({{(128-PWW){pw0[PWW-1]}}, pw0}, FW + 2*N - 2*TFrac);
  wire [127:0] w1x = shift_const({{(128-PWW){pw1[PWW-1]}}, pw1}, FW + N - 2*TFrac);
  wire [127:0] w2x = shift_const(-{{(128-PWW){pw2[PWW-1]}}, pw2}, FW - 2*TFrac);
  wire             valid_2;
  wire [4*(PE+1)-1:0] d01_2;
  wire [4*PE-1:0]  d2_2;
  wire [4*PC-1:0]  pc_2;
  wire [W0W-1:0]   w0_2;
  wire [W1W-1:0]   w1_2;
  wire [W2W-1:0]   w2_2;
  wire [Ctx1W-1:0] ctx_2;
  rpu_stage #(.W(4*(PE+1) + 4*PE + 4*PC + W0W + W1W + W2W + Ctx1W)) u_s1 (
    .clk_i, .rst_ni, .valid_i(valid_1),
    .d_i({d01, d2, pc, w0x[W0W-1:0], w1x[W1W-1:0], w2x[W2W-1:0], ctx_1}),
    .valid_o(valid_2), .q_o({d01_2, d2_2, pc_2, w0_2, w1_2, w2_2, ctx_2}));
  wire [SW-1:0]   s_2;
  wire [2*AW-1:0] fa_2;
  wire [TW-1:0]   al_2, be_2;
  wire [TagW-1:0] tag_2;
  assign {s_2, fa_2, al_2, be_2, tag_2} = ctx_2;

  // ---- the flat guides: a_k · floor(w_i / 2^(FW − FG)), then / 2^FA ----
  localparam integer FS = FW - FG;
  localparam integer WA = A0W;  // the widest w_i / 2^(FW − FG)
  wire signed [W0W-1:0] w0s = w0_2;
  wire signed [W1W-1:0] w1s = w1_2;
  wire signed [W2W-1:0] w2s = w2_2;
  wire signed [W0W-1:0] w0f = w0s >>> FS;
  wire signed [W1W-1:0] w1f = w1s >>> FS;
  wire signed [W2W-1:0] w2f = w2s >>> FS;
  wire [WA-1:0] w0a = w0f[WA-1:0];
  wire [WA-1:0] w1a = {{(WA-A1W){w1f[W1W-1]}}, w1f[A1W-1:0]};
  wire [WA-1:0] w2a = {{(WA-A2W){w2f[W2W-1]}}, w2f[A2W-1:0]};
  localparam integer PF = AW + WA;
  // The coefficients that only wait ride in the flat products' tag.
  localparam integer WaitW = 4*PC + W0W + W1W + W2W + 2*TW + TagW;
  wire              valid_f;
  wire [6*PF-1:0]   pf;
  wire [WaitW-1:0]  wait_f;
  wire [AW-1:0] fa1 = fa_2[AW +: AW], fa2 = fa_2[0 +: AW];
  wire [6*AW-1:0] fa_l = {fa2, fa2, fa2, fa1, fa1, fa1};
  wire [6*WA-1:0] wa_l = {w2a, w1a, w0a, w2a, w1a, w0a};
  wire [WaitW-1:0] wait_2 = {pc_2, w0_2, w1_2, w2_2, al_2, be_2, tag_2};
  // A w wider than two tiles is split, w = wh·2^WL + wl (wl unsigned): a·wl and a·wh (two tiles
  // each, one adder level), then one registered sum. The same tiles as one a × w product, but no
  // adder chain longer than about 45 bits after a DSP (one 4-tile tree level is a 57-bit chain
  // at n = 16, over the 4 ns budget).
  // Both halves run at the slower one's latency: two tiles each up to n = 23; from n = 24 on,
  // wh needs three tiles and one more adder level.
  localparam integer WL = 34;            // two 17-bit tiles
  localparam integer Split = WA > WL + 2 ? 1 : 0;
  localparam integer LSL = `RPU_MUL_LAT(AW, WL + 1, 1);
  localparam integer LSH = Split != 0 ? `RPU_MUL_LAT(AW, WA - WL, 1) : 0;
  localparam integer LS = LSL > LSH ? LSL : LSH;
  localparam integer LF = Split != 0 ? LS + 1 : `RPU_MUL_LAT(AW, WA, 1);
  generate
    if (Split != 0) begin : g_split
      localparam integer WH = WA - WL;   // wh, signed
      localparam integer PL = AW + WL + 1, PH = AW + WH;
      wire [6*(WL+1)-1:0] wl_l;
      wire [6*WH-1:0]     wh_l;
      for (c = 0; c < 6; c = c + 1) begin : g_cut
        assign wl_l[c*(WL+1) +: WL+1] = {1'b0, wa_l[c*WA +: WL]};
        assign wh_l[c*WH +: WH]       = wa_l[c*WA + WL +: WH];
      end
      wire             valid_l;
      wire [6*PL-1:0]  pl;
      wire [6*PH-1:0]  ph;
      wire [WaitW-1:0] wait_l;
      wire             vh_unused;
      wire             th_unused;
      rpu_mul_vec #(.Count(6), .AW(AW), .BW(WL + 1), .Signed(1), .TagW(WaitW), .Latency(LS)) u_pfl (
        .clk_i, .rst_ni, .valid_i(valid_2), .a_i(fa_l), .b_i(wl_l), .tag_i(wait_2),
        .valid_o(valid_l), .p_o(pl), .tag_o(wait_l));
      rpu_mul_vec #(.Count(6), .AW(AW), .BW(WH), .Signed(1), .TagW(1), .Latency(LS)) u_pfh (
        .clk_i, .rst_ni, .valid_i(valid_2), .a_i(fa_l), .b_i(wh_l), .tag_i(1'b0),
        .valid_o(vh_unused), .p_o(ph), .tag_o(th_unused));
      wire [6*PF-1:0] sum;
      for (c = 0; c < 6; c = c + 1) begin : g_sum
        wire signed [PL-1:0] l = pl[c*PL +: PL];
        wire signed [PH-1:0] h = ph[c*PH +: PH];
        wire [PF-1:0] lx = {{(PF-PL){l[PL-1]}}, l};
        wire [PF-1:0] hx = {h, {WL{1'b0}}};  // PH + WL = PF
        assign sum[c*PF +: PF] = lx + hx;
      end
      rpu_stage #(.W(6*PF + WaitW)) u_pfs (
        .clk_i, .rst_ni, .valid_i(valid_l), .d_i({sum, wait_l}),
        .valid_o(valid_f), .q_o({pf, wait_f}));
    end else begin : g_whole
      rpu_mul_vec #(.Count(6), .AW(AW), .BW(WA), .Signed(1), .TagW(WaitW), .Latency(LF)) u_pf (
        .clk_i, .rst_ni, .valid_i(valid_2), .a_i(fa_l), .b_i(wa_l), .tag_i(wait_2),
        .valid_o(valid_f), .p_o(pf), .tag_o(wait_f));
    end
  endgenerate
  // Lane 3k + i: a_(k+1) · w_i; each floored by 2^FA to its width.
  wire [2*(A0W+A1W+A2W)-1:0] fa_f;
  generate
    for (c = 0; c < 2; c = c + 1) begin : g_fa
      wire signed [PF-1:0] f0 = pf[(3*c)*PF +: PF], f1 = pf[(3*c+1)*PF +: PF];
      wire signed [PF-1:0] f2 = pf[(3*c+2)*PF +: PF];
      wire signed [PF-1:0] g0 = f0 >>> FA, g1 = f1 >>> FA, g2 = f2 >>> FA;
      // {a_k,0, a_k,1, a_k,2} with guide 1 in the upper half
      assign fa_f[(1-c)*(A0W+A1W+A2W) +: A0W+A1W+A2W] = {g0[A0W-1:0], g1[A1W-1:0], g2[A2W-1:0]};
      wire unused_top = ^{g0[PF-1:A0W], g1[PF-1:A1W], g2[PF-1:A2W]};
    end
  endgenerate

  // ---- stage 2: the dot products' third term ----
  wire [4*DotW-1:0] dots;
  generate
    for (c = 0; c < 4; c = c + 1) begin : g_dot2
      wire signed [PE:0]   p01 = d01_2[c*(PE+1) +: PE+1];
      wire signed [PE-1:0] q2  = d2_2[c*PE +: PE];
      assign dots[c*DotW +: DotW] = {p01[PE], p01} + {{2{q2[PE-1]}}, q2};
    end
  endgenerate
  wire              valid_3;
  wire [4*DotW-1:0] dots_2;
  wire [SW-1:0]     s_3;
  rpu_stage #(.W(4*DotW + SW)) u_s2 (
    .clk_i, .rst_ni, .valid_i(valid_2), .d_i({dots, s_2}),
    .valid_o(valid_3), .q_o({dots_2, s_3}));

  // ---- x0, y0, x1, y1: floor(dot / 2^(s − FX)) = floor(dot·2^8 / 2^(s − 16)), two shift
  //      stages (multiples of 8, then 0..7), then the saturation ----
  localparam integer VW = DotW + 8;
  localparam integer ShBaseI = FX - 8;
  localparam [SW-1:0] ShBase = ShBaseI[SW-1:0];
  wire [SW-1:0] sh = s_3 - ShBase;
  wire [4*VW-1:0]  va;
  generate
    for (c = 0; c < 4; c = c + 1) begin : g_coarse
      wire signed [VW-1:0] v = {dots_2[c*DotW +: DotW], 8'b0};
      assign va[c*VW +: VW] = v >>> {sh[SW-1:3], 3'b000};
    end
  endgenerate
  // (the coarse stage's input comes straight from stage 2's registers)
  wire             valid_b;
  wire [4*VW-1:0]  va_b;
  wire [2:0]       sh_b;
  rpu_stage #(.W(4*VW + 3)) u_sa (
    .clk_i, .rst_ni, .valid_i(valid_3), .d_i({va, sh[2:0]}),
    .valid_o(valid_b), .q_o({va_b, sh_b}));
  wire [4*VW-1:0] vb;
  generate
    for (c = 0; c < 4; c = c + 1) begin : g_fine
      wire signed [VW-1:0] v = va_b[c*VW +: VW];
      assign vb[c*VW +: VW] = v >>> sh_b;
    end
  endgenerate
  wire             valid_c;
  wire [4*VW-1:0]  vb_c;
  rpu_stage #(.W(4*VW)) u_sb (
    .clk_i, .rst_ni, .valid_i(valid_b), .d_i(vb), .valid_o(valid_c), .q_o(vb_c));
  wire [4*XW-1:0] xy_c;
  wire [3:0]      sat_c;
  localparam signed [VW-1:0] XMax = (1 <<< (XW - 1)) - 1, XMin = -(1 <<< (XW - 1));
  generate
    for (c = 0; c < 4; c = c + 1) begin : g_sat
      wire signed [VW-1:0] v = vb_c[c*VW +: VW];
      assign sat_c[c] = v > XMax || v < XMin;
      // dots are {x0, y0, x1, y1} (lanes 0..3); the output is {x0, x1, y0, y1}
      localparam integer Pos = c == 0 ? 3 : c == 1 ? 1 : c == 2 ? 2 : 0;
      assign xy_c[Pos*XW +: XW] = v > XMax ? XMax[XW-1:0] : v < XMin ? XMin[XW-1:0] : v[XW-1:0];
    end
  endgenerate
  // Wait for the flat products: LF − 3 more cycles (the last one a flip-flop).
  wire [4*XW:0] xy_d;
  rpu_delay #(.W(4*XW + 1), .D(LF - 3)) u_xy_wait (
    .clk_i, .valid_i(valid_c), .d_i({xy_c, |sat_c}), .d_o(xy_d));
  wire unused_valid = valid_c;

  // ---- the output stage ----
  wire [4*PC-1:0] pc_f;
  wire [W0W-1:0]  w0_f;
  wire [W1W-1:0]  w1_f;
  wire [W2W-1:0]  w2_f;
  wire [TW-1:0]   al_f, be_f;
  wire [TagW-1:0] tag_f;
  assign {pc_f, w0_f, w1_f, w2_f, al_f, be_f, tag_f} = wait_f;
  // pc lanes are {s2·β, s2·α, c2·β, c2·α} (lane 0 lowest); the output is {c2a, c2b, s2a, s2b}
  wire [4*CaW-1:0] cs_f = {pc_f[0 +: CaW], pc_f[PC +: CaW], pc_f[2*PC +: CaW], pc_f[3*PC +: CaW]};
  rpu_stage #(.W(4*XW + 1 + 4*CaW + W0W + W1W + W2W + 2*(A0W+A1W+A2W) + 2*TW + TagW)) u_out (
    .clk_i, .rst_ni, .valid_i(valid_f),
    .d_i({xy_d, cs_f, w0_f, w1_f, w2_f, fa_f, al_f, be_f, tag_f}),
    .valid_o(valid_o), .q_o({xy_o, ovf_o, cs_o, w_o, fa_o, alpha_o, beta_o, tag_o}));

  wire unused = ^{vc_unused, tc_unused, vw_unused, tw_unused, w0x[127:W0W], w1x[127:W1W],
                  w2x[127:W2W], w0f[W0W-1:WA], w1f[W1W-1:A1W], w2f[W2W-1:A2W]};
endmodule

`default_nettype wire
