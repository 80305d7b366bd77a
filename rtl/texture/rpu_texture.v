// rpu_texture: the vector-texture coverage test of one (p0, segment) pair, twin of
// `rpu::ref::texture_unit(params, segment, p0, ovf)`. With r1 = p0 − p1 and r2 = r1 − d
// (= p0 − p2):
//   pr1    = r1·d ≥ 0 ∧ r2·d ≤ 0                               between the end planes, exact
//   pr2    = |r1|² ≤ w0_2 ∨ |r2|² ≤ w0_2                        round end caps, exact
//   t̂      = chord(clamp(r1·d, 0, L2))                          rpu_chord, Q(3.FT)
//   X      = s(t̂) = curve_point(t̂, g1(t̂), g2(t̂))               rpu_guide_pair, rpu_curve_point
//   pr3    = |X − p0|² ≤ w0_2                                    exact
//   covers = pr1 ∧ (pr2 ∨ pr3)           the seed's join (eq 25), round_join_i = 0
//          = (pr1 ∧ pr3) ∨ pr2           a round join, round_join_i = 1
// ovf_o is the pair's sticky overflow bit as the twin sets it: the chord parameter saturated
// (never for a descriptor: the clamped dot gives t̂ ∈ [0, 1]) or an arc guide's radicand did.
// Every output is computed for every operand, as in the twin (t̂, X and pr3 also where pr1 fails).
//
// Pipeline (Latency = 6 + LF + LE + rpu_chord's + rpu_guide_pair's + rpu_curve_point's latency,
// 4 + 4 + 7 + 6 = 21 + 40 + 8 = 69 at the defaults; every product an rpu_mul, rpu_mul_latency.vh;
// one pair per cycle, no stall):
//   1        r1, r2                                  (every input is sampled here)
//   LF       the twelve products r1_k·d_k, r2_k·d_k, r1_k², r2_k² (exact; 4)
//                                                    (the context in a plain delay line)
//   1        their sums (carry-save + one adder each)
//   1        pr1, pr2; clamp(r1·d, 0, L2)
//   chord    rpu_chord: t̂                                            (context in its tag)
//   guides   rpu_guide_pair: g1, g2                      (context in its tag)
//   cp       rpu_curve_point: X                          (context in its tag)
//   1        e = X − p0
//   LE       e_k² (exact; 4)                             (context in a tag)
//   1        |e|² (carry-save + one adder)
//   1        pr3, covers; outputs registered
//
// Widths hold every port value exactly: |r1_k| < 2^CW, |r2_k| < 2^(CW+1) (CW+2 bits), r1·d in
// 2CW+3 bits and r2·d in 2CW+4 bits signed, |r1|² < 3·2^(2CW), |r2|² < 3·2^(2CW+2), and
// |X − p0| < 2^(CW+3) per component (CW+4 bits), |X − p0|² < 2^(2CW+6). w0_2 is 2CW+1 bits
// unsigned: it holds round((w0·S)²) for a half width w0·S up to 2^CW LSB, the whole coordinate
// range (the normalisation keeps w0·S < 7/16·2^CW).
`default_nettype none
`include "rpu_widths.vh"

module rpu_texture #(
  parameter integer CoordW   = 24,  // CW: signed width of positions (12..40)
  parameter integer TFrac    = 24,  // FT: fraction bits of t̂ (8..48, 2·CW+3+FT <= 126)
  parameter integer UnitFrac = 16,  // FU: fraction bits of the guide unit vectors (8..40)
  parameter integer InvW     = 18,  // IW: mantissa bits of 1/L² (8..40)
  parameter integer SqrtW    = 0,   // widest guide square-root radicand; 0 = exact (16..126)
  parameter integer TagW     = 1,   // side-band bits carried with each pair (>= 1)
  // Derived (do not override).
  parameter integer TW   = `RPU_TW(TFrac),       // t̂: Q(3.FT)
  parameter integer DW   = `RPU_DW(CoordW),      // d = p2 − p1
  parameter integer UW   = `RPU_UW(UnitFrac),    // u: Q(2.FU)
  parameter integer GdW  = `RPU_GDW(CoordW, TFrac, UnitFrac),  // a guide (rpu_guide_desc.vh)
  parameter integer L2W  = `RPU_L2W(CoordW),  // L² = |d|²
  parameter integer XW   = `RPU_XW(CoordW),      // X (rpu_curve_point)
  parameter integer W02W = `RPU_R2W(CoordW)   // w0_2, unsigned
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [3*CoordW-1:0] p0_i,      // ray/plane point, {z, y, x}, LSB (z = 0 from rpu_ray_plane;
                                        // any z is taken, as by the twin)
  input  wire [3*CoordW-1:0] p1_i,      // segment start, {z, y, x}, LSB
  input  wire [3*DW-1:0]     d_i,       // p2 − p1, {z, y, x}, LSB
  input  wire [L2W-1:0]      l2_i,      // |d|², LSB², unsigned
  input  wire [InvW-1:0]     inv_m_i,   // 1/L² = inv_m · 2^-inv_s
  input  wire [6:0]          inv_s_i,
  input  wire [GdW-1:0]      g1_i,      // guide of end 1 (rpu_guide_desc.vh)
  input  wire [GdW-1:0]      g2_i,      // guide of end 2
  input  wire [W02W-1:0]     w0_2_i,    // texture half-width², LSB², unsigned
  input  wire                round_join_i,  // 1: the caps count outside the slab too
  input  wire [TagW-1:0]     tag_i,
  output wire                valid_o,
  output wire                pr1_o,
  output wire                pr2_o,
  output wire                pr3_o,
  output wire                covers_o,  // pr1 ∧ (pr2 ∨ pr3), or (pr1 ∧ pr3) ∨ pr2 (round join)
  output wire [TW-1:0]       t_o,       // t̂, Q(3.FT), signed
  output wire [3*XW-1:0]     x_o,       // X = s(t̂), {z, y, x}, LSB, signed each
  output wire                ovf_o,     // sticky overflow bit of the pair
  output wire [TagW-1:0]     tag_o
);
  localparam integer CW   = CoordW;
  localparam integer TgW  = TagW + 1;        // the side band inside: {round join, tag}
  localparam integer R1W  = CW + 1;          // r1 = p0 − p1
  localparam integer R2W  = CW + 2;          // r2 = r1 − d
  localparam integer F1PW = R1W + DW;        // r1_k·d_k
  localparam integer F2PW = R2W + DW;        // r2_k·d_k
  localparam integer S1PW = 2 * R1W;         // r1_k²
  localparam integer S2PW = 2 * R2W;         // r2_k²
  localparam integer DotW = 2 * CW + 4;      // r1·d (2CW+3 bits suffice), the chord's dot
  localparam integer F2W  = 2 * CW + 5;      // r2·d
  localparam integer S1W  = 2 * CW + 3;      // |r1|² (< 2^(2CW+2)) with w0_2, signed compare
  localparam integer S2W  = 2 * CW + 5;      // |r2|² (< 2^(2CW+4)) with w0_2, signed compare
  localparam integer EW   = CW + 4;          // e = X − p0
  localparam integer EPW  = 2 * EW;          // e_k²
  localparam integer ESW  = 2 * EW + 2;      // |e|² with w0_2, signed compare
  localparam integer GW   = `RPU_PRW(CW);          // rpu_guide_pair's g
`include "rpu_guide_desc.vh"
  localparam integer GsW  = GsWords;          // one guide's shape {mode, h, a, b}

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_texture: CoordW must be in 12..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_texture: TFrac must be in 8..48");
    if (2 * CoordW + 3 + TFrac > 126) $fatal(1, "rpu_texture: 2*CoordW+3+TFrac must be <= 126");
    if (UnitFrac < 8 || UnitFrac > 40) $fatal(1, "rpu_texture: UnitFrac must be in 8..40");
    if (InvW < 8 || InvW > 40) $fatal(1, "rpu_texture: InvW must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_texture: TagW must be >= 1");
    if (TW != `RPU_TW(TFrac) || DW != `RPU_DW(CoordW) || UW != `RPU_UW(UnitFrac) || GdW != GdWords ||
        L2W != `RPU_L2W(CoordW) || XW != `RPU_XW(CoordW) || W02W != `RPU_R2W(CoordW))
      $fatal(1, "rpu_texture: derived parameters must not be overridden");
  end

`include "rpu_mul_latency.vh"
  // The front products, all padded to the slowest (LF), and the squares e_k² (LE).
  localparam integer LF1 = `RPU_MUL_LAT(R1W, DW, 1);
  localparam integer LF2 = `RPU_MUL_LAT(DW, R2W, 1);
  localparam integer LF3 = `RPU_MUL_LAT(R1W, R1W, 1);
  localparam integer LF4 = `RPU_MUL_LAT(R2W, R2W, 1);
  localparam integer LFa = LF1 > LF2 ? LF1 : LF2;
  localparam integer LFb = LF3 > LF4 ? LF3 : LF4;
  localparam integer LF  = LFa > LFb ? LFa : LFb;
  localparam integer LE  = `RPU_MUL_LAT(EW, EW, 1);
  localparam integer LCh = `RPU_MUL_LAT(InvW + 1, DotW, 1) + 3;  // rpu_chord's
  // The unit's latency (what the enclosing units count on; ref::texture_latency), with the guide
  // pair's and the curve point's (their headers).
  localparam integer LatOwn = 6 + LF + LE + LCh;

  genvar c;

  // ---------------------------------------------------------------------------------------------
  // Stage 1: r1 = p0 − p1, r2 = p0 − p1 − d (exact).
  // ---------------------------------------------------------------------------------------------
  // The segment context used after the front end: {w0_2, p0, p1, d, u1, u2, l2, guide 1, guide 2}.
  localparam integer CtxW = W02W + 6 * CW + 3 * DW + 6 * UW + L2W + 2 * GsW;
  wire [3*R1W-1:0] r1v;
  wire [3*R2W-1:0] r2v;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_r
      wire [CW-1:0]  p0 = p0_i[c*CW +: CW];
      wire [CW-1:0]  p1 = p1_i[c*CW +: CW];
      wire [DW-1:0]  d  = d_i[c*DW +: DW];
      wire [R2W-1:0] p0x = {{(R2W - CW){p0[CW-1]}}, p0};
      wire [R2W-1:0] p1x = {{(R2W - CW){p1[CW-1]}}, p1};
      wire [R2W-1:0] dx  = {{(R2W - DW){d[DW-1]}}, d};
      wire [R2W-1:0] r1  = p0x - p1x;  // |r1| < 2^CW: its low R1W bits are exact
      assign r1v[c*R1W +: R1W] = r1[R1W-1:0];
      assign r2v[c*R2W +: R2W] = r1 - dx;
      wire unused_r1 = r1[R2W-1];
    end
  endgenerate
  wire [3*R1W-1:0]  s1_r1_q;
  wire [3*R2W-1:0]  s1_r2_q;
  wire [CtxW-1:0]   s1_ctx_q;
  wire [InvW+6:0]   s1_inv_q;
  wire [TgW-1:0]   s1_tag_q;
  wire              s1_valid_q;
  rpu_stage #(.W(3*R1W + 3*R2W + CtxW + InvW + 7 + TgW)) u_s1 (
    .clk_i, .rst_ni, .valid_i,
    .d_i({r1v, r2v, w0_2_i, p0_i, p1_i, d_i, g1_i[GdUO +: GdUW], g2_i[GdUO +: GdUW], l2_i,
          g1_i[GdShapeO +: GsW], g2_i[GdShapeO +: GsW], inv_s_i, inv_m_i, round_join_i, tag_i}),
    .valid_o(s1_valid_q), .q_o({s1_r1_q, s1_r2_q, s1_ctx_q, s1_inv_q, s1_tag_q}));
  wire [3*DW-1:0] s1_d = s1_ctx_q[6*UW + L2W + 2*GsW +: 3*DW];

  // ---------------------------------------------------------------------------------------------
  // The products (exact): r1_k·d_k, r2_k·d_k, r1_k², r2_k², all padded to LF cycles; w0_2 and L2
  // (used by the next two stages' logic) ride in r1_x·d_x's tag, the rest of the context in a
  // plain delay line to the chord (shift registers: no logic reads it before the chord's tag).
  // ---------------------------------------------------------------------------------------------
  wire [3*F1PW-1:0] f1p;
  wire [3*F2PW-1:0] f2p;
  wire [3*S1PW-1:0] s1p;
  wire [3*S2PW-1:0] s2p;
  wire              m_valid;
  wire [W02W+L2W-1:0] m_tag;
  wire f2_valid, s1_valid, s2_valid, f2_tag, s1_tag, s2_tag;
  rpu_mul_vec #(.Count(3), .AW(R1W), .BW(DW), .Signed(1), .TagW(W02W + L2W), .Latency(LF)) u_f1 (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .a_i(s1_r1_q), .b_i(s1_d),
    .tag_i({s1_ctx_q[CtxW-1 -: W02W], s1_ctx_q[2*GsW +: L2W]}),
    .valid_o(m_valid), .p_o(f1p), .tag_o(m_tag));
  rpu_mul_vec #(.Count(3), .AW(DW), .BW(R2W), .Signed(1), .TagW(1), .Latency(LF)) u_f2 (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .a_i(s1_d), .b_i(s1_r2_q), .tag_i(1'b0),
    .valid_o(f2_valid), .p_o(f2p), .tag_o(f2_tag));
  rpu_mul_vec #(.Count(3), .AW(R1W), .BW(R1W), .Signed(1), .TagW(1), .Latency(LF)) u_s1sq (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .a_i(s1_r1_q), .b_i(s1_r1_q), .tag_i(1'b0),
    .valid_o(s1_valid), .p_o(s1p), .tag_o(s1_tag));
  rpu_mul_vec #(.Count(3), .AW(R2W), .BW(R2W), .Signed(1), .TagW(1), .Latency(LF)) u_s2sq (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .a_i(s1_r2_q), .b_i(s1_r2_q), .tag_i(1'b0),
    .valid_o(s2_valid), .p_o(s2p), .tag_o(s2_tag));
  wire unused_prod = ^{f2_valid, s1_valid, s2_valid, f2_tag, s1_tag, s2_tag};

  // The context's delay lines (plain stages: shift-register LUTs, no logic reads them): the
  // chord's operand inv and the guide operands {L2, guide 1, guide 2} for LF + 2 stages to the
  // chord (whose tag carries the guide operands on, ending in a flip-flop), the rest
  // {tag, w0_2, p0, p1, d, u1, u2} for LF + 2 + the chord's latency, straight to the guides' tag.
  localparam integer LoW = L2W + 2 * GsW;
  localparam integer HiW = CtxW - LoW;
  localparam integer DlW = InvW + 7 + LoW;      // {inv, ctx_lo}
  localparam integer Dl  = LF + 2;
  localparam integer D2W = TgW + HiW;          // {tag, ctx_hi}
  localparam integer D2  = LF + 2 + LCh;
  reg [Dl*DlW-1:0] dl_q;
  reg [D2*D2W-1:0] d2_q;
  always @(posedge clk_i) begin
    dl_q <= {dl_q[(Dl-1)*DlW-1:0], s1_inv_q, s1_ctx_q[LoW-1:0]};
    d2_q <= {d2_q[(D2-1)*D2W-1:0], s1_tag_q, s1_ctx_q[CtxW-1:LoW]};
  end
  wire [DlW-1:0] dl_out = dl_q[Dl*DlW-1 -: DlW];
  wire [D2W-1:0] d2_out = d2_q[D2*D2W-1 -: D2W];

  // ---------------------------------------------------------------------------------------------
  // Stage T1: r1·d, r2·d, |r1|², |r2|² (sums of three: one carry-save step and one adder each,
  // exact modulo the width, which holds the sum).
  // ---------------------------------------------------------------------------------------------
  wire [DotW-1:0] f1x0 = {{(DotW-F1PW){f1p[1*F1PW-1]}}, f1p[0*F1PW +: F1PW]};
  wire [DotW-1:0] f1x1 = {{(DotW-F1PW){f1p[2*F1PW-1]}}, f1p[1*F1PW +: F1PW]};
  wire [DotW-1:0] f1x2 = {{(DotW-F1PW){f1p[3*F1PW-1]}}, f1p[2*F1PW +: F1PW]};
  wire [F2W-1:0]  f2x0 = {{(F2W-F2PW){f2p[1*F2PW-1]}}, f2p[0*F2PW +: F2PW]};
  wire [F2W-1:0]  f2x1 = {{(F2W-F2PW){f2p[2*F2PW-1]}}, f2p[1*F2PW +: F2PW]};
  wire [F2W-1:0]  f2x2 = {{(F2W-F2PW){f2p[3*F2PW-1]}}, f2p[2*F2PW +: F2PW]};
  // The squares are non-negative (zero-extended).
  wire [S1W-1:0]  s1x0 = {{(S1W-S1PW){1'b0}}, s1p[0*S1PW +: S1PW]};
  wire [S1W-1:0]  s1x1 = {{(S1W-S1PW){1'b0}}, s1p[1*S1PW +: S1PW]};
  wire [S1W-1:0]  s1x2 = {{(S1W-S1PW){1'b0}}, s1p[2*S1PW +: S1PW]};
  wire [S2W-1:0]  s2x0 = {{(S2W-S2PW){1'b0}}, s2p[0*S2PW +: S2PW]};
  wire [S2W-1:0]  s2x1 = {{(S2W-S2PW){1'b0}}, s2p[1*S2PW +: S2PW]};
  wire [S2W-1:0]  s2x2 = {{(S2W-S2PW){1'b0}}, s2p[2*S2PW +: S2PW]};
  wire [DotW-1:0] f1sum;
  wire [F2W-1:0]  f2sum;
  wire [S1W-1:0]  s1sum;
  wire [S2W-1:0]  s2sum;
  rpu_add3 #(.W(DotW)) u_f1sum (.a_i(f1x0), .b_i(f1x1), .c_i(f1x2), .s_o(f1sum));
  rpu_add3 #(.W(F2W))  u_f2sum (.a_i(f2x0), .b_i(f2x1), .c_i(f2x2), .s_o(f2sum));
  rpu_add3 #(.W(S1W))  u_s1sum (.a_i(s1x0), .b_i(s1x1), .c_i(s1x2), .s_o(s1sum));
  rpu_add3 #(.W(S2W))  u_s2sum (.a_i(s2x0), .b_i(s2x1), .c_i(s2x2), .s_o(s2sum));

  wire [DotW-1:0]   t1_f1_q;
  wire [F2W-1:0]    t1_f2_q;
  wire [S1W-1:0]    t1_s1_q;
  wire [S2W-1:0]    t1_s2_q;
  wire [W02W-1:0]   t1_w02_q;
  wire [L2W-1:0]    t1_l2_q;
  wire              t1_valid_q;
  rpu_stage #(.W(DotW + F2W + S1W + S2W + W02W + L2W)) u_t1 (
    .clk_i, .rst_ni, .valid_i(m_valid), .d_i({f1sum, f2sum, s1sum, s2sum, m_tag}),
    .valid_o(t1_valid_q), .q_o({t1_f1_q, t1_f2_q, t1_s1_q, t1_s2_q, t1_w02_q, t1_l2_q}));

  // ---------------------------------------------------------------------------------------------
  // Stage T2: pr1, pr2; the chord's dot clamp(r1·d, 0, L2).
  // ---------------------------------------------------------------------------------------------
  // w0_2 − Σ r_k² ≥ 0 is the exact test Σ r_k² ≤ w0_2.
  wire signed [S1W-1:0]  m1 = {{(S1W-W02W){1'b0}}, t1_w02_q} - t1_s1_q;
  wire signed [S2W-1:0]  m2 = {{(S2W-W02W){1'b0}}, t1_w02_q} - t1_s2_q;
  // L2 − r1·d < 0 is r1·d > L2 (one bit wider than the dot: exact for every r1·d).
  wire signed [DotW:0]   l2d = $signed({2'b00, t1_l2_q}) - $signed({t1_f1_q[DotW-1], t1_f1_q});
  wire                   f1_neg = t1_f1_q[DotW-1];
  wire                   f1_big = l2d[DotW];
  wire [DotW-1:0]        dot    = f1_neg ? {DotW{1'b0}} : f1_big ? {1'b0, t1_l2_q} : t1_f1_q;
  wire                   pr1    = ~f1_neg & (t1_f2_q[F2W-1] | ~(|t1_f2_q));
  wire                   pr2    = ~m1[S1W-1] | ~m2[S2W-1];

  wire [DotW-1:0]   s3_dot_q;
  wire              s3_pr1_q, s3_pr2_q;
  wire              s3_valid_q;
  rpu_stage #(.W(DotW + 2)) u_s3 (
    .clk_i, .rst_ni, .valid_i(t1_valid_q), .d_i({dot, pr1, pr2}), .valid_o(s3_valid_q),
    .q_o({s3_dot_q, s3_pr1_q, s3_pr2_q}));
  wire [InvW+6:0] s3_inv_q = dl_out[LoW +: InvW + 7];
  wire [LoW-1:0]  s3_lo_q  = dl_out[LoW-1:0];

  // ---------------------------------------------------------------------------------------------
  // The chord parameter t̂; the pair's context rides in the chord's tag.
  // ---------------------------------------------------------------------------------------------
  localparam integer ChTagW = 2 + LoW;
  wire              ch_valid, ch_ovf;
  wire [TW-1:0]     ch_t;
  wire [ChTagW-1:0] ch_tag_out;
  rpu_chord #(.DotW(DotW), .InvW(InvW), .TFrac(TFrac), .ShW(7), .TagW(ChTagW)) u_chord (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(s3_valid_q),
    .dot_i  (s3_dot_q),
    .inv_m_i(s3_inv_q[InvW-1:0]),
    .inv_s_i(s3_inv_q[InvW +: 7]),
    .tag_i  ({s3_pr1_q, s3_pr2_q, s3_lo_q}),
    .valid_o(ch_valid),
    .t_o    (ch_t),
    .ovf_o  (ch_ovf),
    .tag_o  (ch_tag_out)
  );
  wire [TgW-1:0]     ch_tag;
  wire                ch_pr1, ch_pr2;
  wire [W02W-1:0]     ch_w02;
  wire [3*CW-1:0]     ch_p0, ch_p1;
  wire [3*DW-1:0]     ch_d;
  wire [3*UW-1:0]     ch_u1, ch_u2;
  wire [L2W-1:0]      ch_l2;
  wire [GsW-1:0]      ch_g1, ch_g2;  // the guides' shapes
  assign {ch_pr1, ch_pr2, ch_l2, ch_g1, ch_g2} =
      ch_tag_out;
  assign {ch_tag, ch_w02, ch_p0, ch_p1, ch_d, ch_u1, ch_u2} = d2_out;

  // ---------------------------------------------------------------------------------------------
  // The two guides at t̂; what the curve point and the end need rides in guide 1's tag.
  // ---------------------------------------------------------------------------------------------
  localparam integer G1TagW = TgW + 2 + W02W + 6 * CW + 3 * DW + 6 * UW + TW + 1;
  localparam integer RadW   = `RPU_GRADW(CW);
  wire              g1_valid, g1_ovf;
  wire [GW-1:0]     g1, g2;
  wire [TFrac-2:0]  w_unused;
  wire [G1TagW-1:0] g1_tag_out;
  // One texture item per cycle: the pair squares h itself (HhIn = 0).
  rpu_guide_pair #(.CoordW(CW), .TFrac(TFrac), .SqrtW(SqrtW), .HhIn(0), .TagW(G1TagW)) u_guides (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(ch_valid),
    .t_i    (ch_t),
    .l2_i   (ch_l2),
    .g1_i   (ch_g1),
    .hh1_i  ({RadW{1'b0}}),
    .g2_i   (ch_g2),
    .hh2_i  ({RadW{1'b0}}),
    .tag_i  ({ch_tag, ch_pr1, ch_pr2, ch_w02, ch_p0, ch_p1, ch_d, ch_u1, ch_u2, ch_t, ch_ovf}),
    .valid_o(g1_valid),
    .g1_o   (g1),
    .g2_o   (g2),
    .w_o    (w_unused),
    .ovf_o  (g1_ovf),
    .tag_o  (g1_tag_out)
  );
  wire [TgW-1:0]  gd_tag;
  wire             gd_pr1, gd_pr2;
  wire [W02W-1:0]  gd_w02;
  wire [3*CW-1:0]  gd_p0, gd_p1;
  wire [3*DW-1:0]  gd_d;
  wire [3*UW-1:0]  gd_u1, gd_u2;
  wire [TW-1:0]    gd_t;
  wire             gd_covf;
  assign {gd_tag, gd_pr1, gd_pr2, gd_w02, gd_p0, gd_p1, gd_d, gd_u1, gd_u2, gd_t, gd_covf} =
      g1_tag_out;

  // ---------------------------------------------------------------------------------------------
  // The curve point X = s(t̂).
  // ---------------------------------------------------------------------------------------------
  localparam integer CpTagW = TgW + 2 + W02W + 3 * CW + TW + 1;
  wire              cp_valid;
  wire [3*XW-1:0]   cp_x;
  wire [CpTagW-1:0] cp_tag_out;
  rpu_curve_point #(.CoordW(CW), .TFrac(TFrac), .UnitFrac(UnitFrac), .TagW(CpTagW)) u_cp (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(g1_valid),
    .p1_i   (gd_p1),
    .d_i    (gd_d),
    .u1_i   (gd_u1),
    .u2_i   (gd_u2),
    .t_i    (gd_t),
    .g1_i   (g1),
    .g2_i   (g2),
    .tag_i  ({gd_tag, gd_pr1, gd_pr2, gd_w02, gd_p0, gd_t, gd_covf | g1_ovf}),
    .valid_o(cp_valid),
    .x_o    (cp_x),
    .tag_o  (cp_tag_out)
  );
  wire [TgW-1:0]  cp_tag;
  wire             cp_pr1, cp_pr2;
  wire [W02W-1:0]  cp_w02;
  wire [3*CW-1:0]  cp_p0;
  wire [TW-1:0]    cp_t;
  wire             cp_ovf;
  assign {cp_tag, cp_pr1, cp_pr2, cp_w02, cp_p0, cp_t, cp_ovf} = cp_tag_out;

  // ---------------------------------------------------------------------------------------------
  // Stage E1: e = X − p0 (exact: |X| < 2^(CW+2), |p0| ≤ 2^(CW−1)).
  // ---------------------------------------------------------------------------------------------
  // The result fields that ride to the end: {tag, pr1, pr2, w0_2, t̂, X, ovf}.
  localparam integer ResW = TgW + 2 + W02W + TW + 3 * XW + 1;
  wire [3*EW-1:0] e_v;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_e
      wire [XW-1:0] xk = cp_x[c*XW +: XW];
      wire [CW-1:0] pk = cp_p0[c*CW +: CW];
      assign e_v[c*EW +: EW] = {{(EW-XW){xk[XW-1]}}, xk} - {{(EW-CW){pk[CW-1]}}, pk};
    end
  endgenerate
  wire [3*EW-1:0]   e1_e_q;
  wire [ResW-1:0]   e1_res_q;
  wire              e1_valid_q;
  rpu_stage #(.W(3*EW + ResW)) u_e1 (
    .clk_i, .rst_ni, .valid_i(cp_valid),
    .d_i({e_v, cp_tag, cp_pr1, cp_pr2, cp_w02, cp_t, cp_x, cp_ovf}),
    .valid_o(e1_valid_q), .q_o({e1_e_q, e1_res_q}));

  // ---------------------------------------------------------------------------------------------
  // The squares e_k² (exact); the result fields in x's tag.
  // ---------------------------------------------------------------------------------------------
  wire [3*EPW-1:0] esq;
  wire             e2_valid;
  wire [ResW-1:0]  e2_res;
  rpu_mul_vec #(.Count(3), .AW(EW), .BW(EW), .Signed(1), .TagW(ResW)) u_sq (
    .clk_i, .rst_ni, .valid_i(e1_valid_q), .a_i(e1_e_q), .b_i(e1_e_q), .tag_i(e1_res_q),
    .valid_o(e2_valid), .p_o(esq), .tag_o(e2_res));

  // ---------------------------------------------------------------------------------------------
  // Stage E3: |e|² (one carry-save step and one adder, exact in ESW bits).
  // ---------------------------------------------------------------------------------------------
  wire [ESW-1:0] ex0 = {2'b00, esq[0*EPW +: EPW]};
  wire [ESW-1:0] ex1 = {2'b00, esq[1*EPW +: EPW]};
  wire [ESW-1:0] ex2 = {2'b00, esq[2*EPW +: EPW]};
  wire [ESW-1:0]  esum;
  rpu_add3 #(.W(ESW)) u_esum (.a_i(ex0), .b_i(ex1), .c_i(ex2), .s_o(esum));
  wire [ESW-1:0]  e3_sum_q;
  wire [ResW-1:0] e3_res_q;
  wire            e3_valid_q;
  rpu_stage #(.W(ESW + ResW)) u_e3 (
    .clk_i, .rst_ni, .valid_i(e2_valid), .d_i({esum, e2_res}), .valid_o(e3_valid_q),
    .q_o({e3_sum_q, e3_res_q}));

  // ---------------------------------------------------------------------------------------------
  // Stage E4: pr3 = |e|² ≤ w0_2 (exact), covers; the outputs.
  // ---------------------------------------------------------------------------------------------
  wire [TgW-1:0]  r_tag;
  wire             r_pr1, r_pr2;
  wire [W02W-1:0]  r_w02;
  wire [TW-1:0]    r_t;
  wire [3*XW-1:0]  r_x;
  wire             r_ovf;
  assign {r_tag, r_pr1, r_pr2, r_w02, r_t, r_x, r_ovf} = e3_res_q;
  wire signed [ESW-1:0] m3 = {{(ESW-W02W){1'b0}}, r_w02} - e3_sum_q;
  wire pr3 = ~m3[ESW-1];
  // Loaded only with a valid pair: the fields that only ride along leave flip-flops, not the
  // shift-register LUTs Yosys would pack their plain stages into.
  wire r_round = r_tag[TgW-1];  // the join: {round join, tag}
  wire covers  = r_round ? (r_pr1 & pr3) | r_pr2 : r_pr1 & (r_pr2 | pr3);
  rpu_stage #(.W(4 + TW + 3*XW + 1 + TagW), .Hold(1)) u_out (
    .clk_i, .rst_ni, .valid_i(e3_valid_q),
    .d_i({r_pr1, r_pr2, pr3, covers, r_t, r_x, r_ovf, r_tag[TagW-1:0]}),
    .valid_o, .q_o({pr1_o, pr2_o, pr3_o, covers_o, t_o, x_o, ovf_o, tag_o}));

  wire unused_bits = ^w_unused;
`ifndef SYNTHESIS
  // The declared latency is the schedule (rtl/common/rpu_latency_check.v).
  rpu_latency_check #(.Latency(LatOwn), .Segments(2),
                     .Name("rpu_texture (without its guide pair and curve point)")) u_latency_check (
    .clk_i, .rst_ni, .in_i({valid_i, cp_valid}), .out_i({ch_valid, valid_o}));
`endif
endmodule

`default_nettype wire
