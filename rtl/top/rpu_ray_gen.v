// rpu_ray_gen: the ray generator, twin of `rpu::ref::ray_generator(params, camera, i, j)`.
// For pixel (i, j) of the camera descriptor (docs/fixed-point.md, "Signals between units"):
//   v      = floor((v0 + i·dx + j·dy) / 2^G)               Q(4.FV)   (exact sum, G = 14 guard bits)
//   |v|    = isqrt(v·v)                                    Q(4.FV)   (rpu_sqrt, exact radicand)
//   1/|v|  = floor(2^(2FV+2) / |v|), FV+3 quotient bits    Q(1.FV+2) (rpu_div)
//   v̂      = floor(v · (1/|v|) / 2^(FV+2))                 Q(2.FV)
//   E_left = el0 − i·σW,  E_right = el0 − (i+1)·σW         Q(4.FE+14), exact
//   E_top  = et0 − j·σW,  E_bottom = et0 − (j+1)·σW        Q(4.FE+14), exact
// E_right and E_bottom are formed as E_left − σW and E_top − σW: the same integers, so
// E_right(i) = E_left(i+1) and E_bottom(j) = E_top(j+1) bit for bit (pixels tile exactly).
//
// Pipeline (Latency = 2·DirFrac + 10 + L1 + L2 + L3 cycles, 69 at the defaults, one pixel per
// cycle, no stall; every product an rpu_mul, rpu_mul_latency.vh; ref::ray_gen_latency):
//   L1       i·dx, j·dy, i·σW, j·σW        rpu_mul (FV+18) × (IdxW+1), (FE+18) × (IdxW+1): 3
//                                          (v0, el0, et0, σW and tag_i in i·dx's tag)
//   1        v = v0 + i·dx + j·dy (carry-save + one adder, guard bits dropped); E_left, E_top
//   L2       v_k² (three squares)          rpu_mul (FV+4)²: 4   (the side band in a delay line)
//   1        v·v (carry-save + one adder)
//   FV+4     rpu_sqrt: |v|                       (v, E_left, E_top, σW and tag_i in its tag)
//   FV+3     rpu_div:  1/|v|                     (the same side band in its tag)
//   L3       v·(1/|v|)                     rpu_mul (FV+4) × (FV+4): 4 (the side band in its tag)
//   1        v̂; E_right, E_bottom; outputs registered
// Every input is sampled with valid_i (the camera ports may change between pixels). A tag_i of 32
// bits or more waits in an rpu_tag_queue beside the stages instead ("tag_i" above is then one
// constant bit).
//
// Preconditions (checked by the scene compiler, as the model assumes): every pixel's direction
// v0 + i·dx + j·dy fits Q(4.FV+14) (the model checks the image corners: |component| < 8), and
// |v| > 1/2 so that 1/|v| fits FV+3 bits (|v| >= ~1 for any camera: v = W + in-plane offsets).
// Under them the sum is computed modulo 2^(4+FV+14), which gives the exact value's low bits and
// hence exactly the twin's v. The edge vectors are exact for every input (EdgeOutW bits).
`default_nettype none
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_ray_gen #(
  parameter integer DirFrac  = 24,  // FV: fraction bits of the ray direction (8..40)
  parameter integer EdgeFrac = 16,  // FE: fraction bits of the edge vectors (8..40)
  parameter integer IdxW     = 14,  // pixel index width; image sides < 2^14 (guard bits) (1..14)
  parameter integer TagW     = 1,   // side-band bits carried with each pixel (>= 1)
  // Derived (do not override). 4 integer bits (kDirInt, kEdgeInt), 14 guard bits (kRayGuard).
  parameter integer VgW      = `RPU_VGW(DirFrac),   // v0, dx, dy: Q(4.FV+14)
  parameter integer EgW      = `RPU_EGW(EdgeFrac),  // el0, et0, σW: Q(4.FE+14)
  parameter integer VW       = `RPU_VW(DirFrac),        // v: Q(4.FV)
  parameter integer VhW      = `RPU_VHATW(DirFrac),        // v̂: Q(2.FV)
  parameter integer EdgeOutW = EgW + IdxW + 1      // E_*: el0 − k·σW for 0 <= k <= 2^IdxW, exact
) (
  input  wire                  clk_i,
  input  wire                  rst_ni,
  input  wire                  valid_i,
  input  wire [IdxW-1:0]       i_i,       // column, unsigned
  input  wire [IdxW-1:0]       j_i,       // row, unsigned
  input  wire [3*VgW-1:0]      v0_i,      // {z, y, x}, signed components
  input  wire [3*VgW-1:0]      dx_i,
  input  wire [3*VgW-1:0]      dy_i,
  input  wire [3*EgW-1:0]      el0_i,
  input  wire [3*EgW-1:0]      et0_i,
  input  wire [3*EgW-1:0]      sw_i,
  input  wire [TagW-1:0]       tag_i,
  output wire                  valid_o,
  output wire [3*VW-1:0]       v_o,       // {z, y, x}, Q(4.FV)
  output wire [3*VhW-1:0]      vhat_o,    // {z, y, x}, Q(2.FV)
  output wire [3*EdgeOutW-1:0] e_left_o,  // {z, y, x}, Q(4.FE+14)
  output wire [3*EdgeOutW-1:0] e_right_o,
  output wire [3*EdgeOutW-1:0] e_top_o,
  output wire [3*EdgeOutW-1:0] e_bottom_o,
  output wire [TagW-1:0]       tag_o
);
  localparam integer Guard = 14;                  // kRayGuard
  localparam integer RadW  = 2 * VW;              // v·v: 2·dir_w + 4 bits (3·2^(2VW−2) < 2^RadW)
  localparam integer RootW = VW;                  // |v| = rpu_sqrt root: (RadW + 1) / 2 bits
  localparam integer QuotW = DirFrac + 3;         // 1/|v|: Q(1.FV+2)
  localparam integer NumW  = 2 * DirFrac + 3;     // 2^(2FV+2)
  localparam integer PrdW  = VW + QuotW + 1;      // v·(1/|v|), signed × unsigned
  // Side band through rpu_sqrt and rpu_div: {tag, σW, E_top, E_left, v}.
  localparam integer SbV   = 0;
  localparam integer SbEl  = SbV + 3 * VW;
  localparam integer SbEt  = SbEl + 3 * EdgeOutW;
  localparam integer SbSw  = SbEt + 3 * EdgeOutW;
  localparam integer SbTag = SbSw + 3 * EgW;
  // The caller's tag: a wide one waits in a queue (rpu_tag_queue), the stages carry PTagW bits.
  localparam integer PTagW = `RPU_PTAGW(TagW);
  localparam integer SbW   = SbTag + PTagW;

  initial begin
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_ray_gen: DirFrac must be in 8..40");
    if (EdgeFrac < 8 || EdgeFrac > 40) $fatal(1, "rpu_ray_gen: EdgeFrac must be in 8..40");
    if (IdxW < 1 || IdxW > 14) $fatal(1, "rpu_ray_gen: IdxW must be in 1..14");
    if (TagW < 1) $fatal(1, "rpu_ray_gen: TagW must be >= 1");
    if (VgW != 4 + DirFrac + Guard || EgW != 4 + EdgeFrac + Guard || VW != 4 + DirFrac ||
        VhW != 2 + DirFrac || EdgeOutW != EgW + IdxW + 1)
      $fatal(1, "rpu_ray_gen: derived parameters must not be overridden");
  end

`include "rpu_mul_latency.vh"
  localparam integer L1v = `RPU_MUL_LAT(VgW, IdxW + 1, 1);
  localparam integer L1e = `RPU_MUL_LAT(EgW, IdxW + 1, 1);
  localparam integer L1 = L1v > L1e ? L1v : L1e;
  localparam integer L2 = `RPU_MUL_LAT(VW, VW, 1);
  localparam integer L3 = `RPU_MUL_LAT(QuotW + 1, VW, 1);
  // The unit's latency (what the enclosing units count on).
  localparam integer Latency = 2 * DirFrac + 10 + L1 + L2 + L3;
  wire [PTagW-1:0] ptag_in, ptag_out;
  rpu_tag_queue #(.TagW(TagW), .Latency(Latency)) u_tagq (
    .clk_i, .rst_ni, .valid_i, .tag_i, .ptag_o(ptag_in), .out_valid_i(valid_o), .ptag_i(ptag_out),
    .tag_o);

  // ---- the products i·dx, j·dy, i·σW, j·σW (pixel indices as non-negative signed operands) ----
  localparam integer C1W = PTagW + 3 * EgW + 6 * EgW + 3 * VgW;  // {tag, σW, et0, el0, v0}
  localparam integer IW  = IdxW + 1;
  wire [IW-1:0]       i_s = {1'b0, i_i};
  wire [IW-1:0]       j_s = {1'b0, j_i};
  wire [3*VgW-1:0]    dxi, dyj;           // modulo 2^VgW
  wire [3*EdgeOutW-1:0] swi, swj;         // exact
  wire                m1_valid;
  wire [C1W-1:0]      c1;
  localparam integer PvW = VgW + IW;
  wire [6*PvW-1:0]    p_v;                // {j·dy, i·dx}, lanes 0..2 and 3..5
  wire                m1b_valid;
  wire                m1b_tag;
  rpu_mul_vec #(.Count(6), .AW(VgW), .BW(IW), .Signed(1), .TagW(C1W), .Latency(L1)) u_dir (
    .clk_i, .rst_ni, .valid_i, .a_i({dy_i, dx_i}), .b_i({{3{j_s}}, {3{i_s}}}),
    .tag_i({ptag_in, sw_i, et0_i, el0_i, v0_i}), .valid_o(m1_valid), .p_o(p_v), .tag_o(c1));
  rpu_mul_vec #(.Count(6), .AW(EgW), .BW(IW), .Signed(1), .TagW(1), .Latency(L1)) u_edge (
    .clk_i, .rst_ni, .valid_i, .a_i({sw_i, sw_i}), .b_i({{3{j_s}}, {3{i_s}}}), .tag_i(1'b0),
    .valid_o(m1b_valid), .p_o({swj, swi}), .tag_o(m1b_tag));
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_m1
      // Wrapping VgW-bit arithmetic: the low VgW bits of the exact values.
      wire [PvW-1:0] p_dx = p_v[c*PvW +: PvW];
      wire [PvW-1:0] p_dy = p_v[(c + 3)*PvW +: PvW];
      assign dxi[c*VgW +: VgW] = p_dx[VgW-1:0];
      assign dyj[c*VgW +: VgW] = p_dy[VgW-1:0];
      wire unused_m1 = ^{p_dx[PvW-1:VgW], p_dy[PvW-1:VgW]};
    end
  endgenerate
  wire unused_m1b = ^{m1b_valid, m1b_tag};
  wire [3*VgW-1:0] v0_1  = c1[0 +: 3*VgW];
  wire [3*EgW-1:0] el0_1 = c1[3*VgW +: 3*EgW];
  wire [3*EgW-1:0] et0_1 = c1[3*VgW+3*EgW +: 3*EgW];
  wire [3*EgW-1:0] sw_1  = c1[3*VgW+6*EgW +: 3*EgW];
  wire [PTagW-1:0] tag_1 = c1[C1W-1 -: PTagW];

  // ---- stage 2: v = floor((v0 + i·dx + j·dy) / 2^G) (a sum of three modulo 2^VgW, rpu_add3),
  // the named truncation to Q(4.FV); E_left, E_top (exact) ----
  wire [3*VW-1:0]       s2_v;
  wire [3*EdgeOutW-1:0] s2_el, s2_et;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s2
      wire [VgW-1:0] vg;
      rpu_add3 #(.W(VgW)) u_vg (
        .a_i(v0_1[c*VgW +: VgW]), .b_i(dxi[c*VgW +: VgW]), .c_i(dyj[c*VgW +: VgW]), .s_o(vg));
      wire signed [EgW-1:0] el0 = el0_1[c*EgW +: EgW];
      wire signed [EgW-1:0] et0 = et0_1[c*EgW +: EgW];
      wire signed [EdgeOutW-1:0] el0_x = {{(EdgeOutW - EgW){el0[EgW-1]}}, el0};
      wire signed [EdgeOutW-1:0] et0_x = {{(EdgeOutW - EgW){et0[EgW-1]}}, et0};
      // vg >>> G is VW bits wide exactly (VgW − G = VW): the floor, no further narrowing.
      assign s2_v[c*VW +: VW] = vg[VgW-1:Guard];
      // |el0 − k·σW| < 2^(EdgeOutW−1) for k <= 2^IdxW: exact in EdgeOutW bits.
      assign s2_el[c*EdgeOutW +: EdgeOutW] = el0_x - swi[c*EdgeOutW +: EdgeOutW];
      assign s2_et[c*EdgeOutW +: EdgeOutW] = et0_x - swj[c*EdgeOutW +: EdgeOutW];
      wire unused_guard = ^vg[Guard-1:0];
    end
  endgenerate
  wire                  s2_valid_q;
  wire [SbW-1:0]        s2_sb_q;   // {tag, σW, E_top, E_left, v}
  rpu_stage #(.W(SbW)) u_s2 (
    .clk_i, .rst_ni, .valid_i(m1_valid), .d_i({tag_1, sw_1, s2_et, s2_el, s2_v}),
    .valid_o(s2_valid_q), .q_o(s2_sb_q));

  // ---- the squares v_k² (exact) ----
  // The side band, which no logic reads before the output stage, takes a plain delay line
  // (shift-register LUTs) of L2 + 1 stages to the square root's tag.
  wire [3*RadW-1:0] sq;
  wire              m2_valid;
  wire              m2_tag;
  reg [(L2+1)*SbW-1:0] sb_dl_q;
  always @(posedge clk_i) sb_dl_q <= {sb_dl_q[L2*SbW-1:0], s2_sb_q};
  rpu_mul_vec #(.Count(3), .AW(VW), .BW(VW), .Signed(1), .TagW(1)) u_sq (
    .clk_i, .rst_ni, .valid_i(s2_valid_q), .a_i(s2_sb_q[SbV +: 3*VW]),
    .b_i(s2_sb_q[SbV +: 3*VW]), .tag_i(1'b0), .valid_o(m2_valid), .p_o(sq), .tag_o(m2_tag));
  wire unused_m2 = m2_tag;

  // ---- stage 3: the radicand v·v (exact: three squares of VW-bit values < 2^RadW) ----
  wire [RadW-1:0] vv;
  rpu_add3 #(.W(RadW)) u_vv (
    .a_i(sq[0*RadW +: RadW]), .b_i(sq[1*RadW +: RadW]), .c_i(sq[2*RadW +: RadW]), .s_o(vv));
  wire [RadW-1:0] s3_rad_q;
  wire [SbW-1:0]  s3_sb_q = sb_dl_q[L2*SbW +: SbW];
  wire            s3_valid_q;
  rpu_stage #(.W(RadW)) u_s3 (
    .clk_i, .rst_ni, .valid_i(m2_valid), .d_i(vv), .valid_o(s3_valid_q), .q_o(s3_rad_q));

  // ---- |v| = isqrt(v·v) ----
  wire             sq_valid;
  wire [RootW-1:0] sq_root;
  wire [SbW-1:0]   sq_sb;
  rpu_sqrt #(.RadW(RadW), .SqrtW(0), .TagW(SbW)) u_sqrt (
    .clk_i, .rst_ni, .valid_i(s3_valid_q), .rad_i(s3_rad_q), .tag_i(s3_sb_q),
    .valid_o(sq_valid), .root_o(sq_root), .tag_o(sq_sb));

  // ---- 1/|v| = floor(2^(2FV+2) / |v|) ----
  wire             dv_valid;
  wire [QuotW-1:0] dv_recip;
  wire [SbW-1:0]   dv_sb;
  rpu_div #(.NumW(NumW), .DenW(RootW), .QuotW(QuotW), .TagW(SbW)) u_div (
    .clk_i, .rst_ni, .valid_i(sq_valid), .num_i({1'b1, {(NumW - 1){1'b0}}}), .den_i(sq_root),
    .tag_i(sq_sb), .valid_o(dv_valid), .quot_o(dv_recip), .tag_o(dv_sb));

  // ---- v·(1/|v|) (exact; 1/|v| as a non-negative signed operand); the side band in its tag ----
  wire [3*PrdW-1:0] prd;
  wire              m3_valid;
  wire [SbW-1:0]    c3;
  rpu_mul_vec #(.Count(3), .AW(QuotW + 1), .BW(VW), .Signed(1), .ShareA(1), .TagW(SbW)) u_vh (
    .clk_i, .rst_ni, .valid_i(dv_valid), .a_i({1'b0, dv_recip}), .b_i(dv_sb[SbV +: 3*VW]),
    .tag_i(dv_sb), .valid_o(m3_valid), .p_o(prd), .tag_o(c3));

  // ---- output stage: v̂ = floor(v·(1/|v|) / 2^(FV+2)); E_right, E_bottom ----
  wire [3*EdgeOutW-1:0] o_el = c3[SbEl +: 3 * EdgeOutW];
  wire [3*EdgeOutW-1:0] o_et = c3[SbEt +: 3 * EdgeOutW];
  wire [3*EgW-1:0]      o_sw = c3[SbSw +: 3 * EgW];
  wire [3*VhW-1:0]      o_vhat;
  wire [3*EdgeOutW-1:0] o_er, o_eb;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_out
      wire [PrdW-1:0]            pc   = prd[c*PrdW +: PrdW];
      wire signed [EgW-1:0]      sw   = o_sw[c*EgW +: EgW];
      wire signed [EdgeOutW-1:0] sw_x = {{(EdgeOutW - EgW){sw[EgW-1]}}, sw};
      // prd >>> (FV+2), truncated to Q(2.FV): |v_c| <= |v| gives |v̂_c| <= 2^FV, so the
      // dropped high bits are copies of the sign.
      assign o_vhat[c*VhW +: VhW] = pc[DirFrac+2 +: VhW];
      // E_left(i) − σW = E_left(i+1), |·| < 2^(EdgeOutW−1): exact in EdgeOutW bits.
      assign o_er[c*EdgeOutW +: EdgeOutW] = o_el[c*EdgeOutW +: EdgeOutW] - sw_x;
      assign o_eb[c*EdgeOutW +: EdgeOutW] = o_et[c*EdgeOutW +: EdgeOutW] - sw_x;
      wire unused_prd = ^{pc[PrdW-1:DirFrac+2+VhW], pc[DirFrac+1:0]};
    end
  endgenerate
  rpu_stage #(.W(3*VW + 3*VhW + 4*3*EdgeOutW + PTagW)) u_out (
    .clk_i, .rst_ni, .valid_i(m3_valid),
    .d_i({c3[SbV +: 3*VW], o_vhat, o_el, o_er, o_et, o_eb, c3[SbTag +: PTagW]}),
    .valid_o, .q_o({v_o, vhat_o, e_left_o, e_right_o, e_top_o, e_bottom_o, ptag_out}));
  `RPU_LATENCY_CHECK(Latency, "rpu_ray_gen")
endmodule

`default_nettype wire
