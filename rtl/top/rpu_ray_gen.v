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
// Every input is sampled with valid_i (the camera ports may change between pixels).
//
// Preconditions (checked by the scene compiler, as the model assumes): every pixel's direction
// v0 + i·dx + j·dy fits Q(4.FV+14) (the model checks the image corners: |component| < 8), and
// |v| > 1/2 so that 1/|v| fits FV+3 bits (|v| >= ~1 for any camera: v = W + in-plane offsets).
// Under them the sum is computed modulo 2^(4+FV+14), which gives the exact value's low bits and
// hence exactly the twin's v. The edge vectors are exact for every input (EdgeOutW bits).
`default_nettype none
`include "rpu_widths.vh"

module rpu_ray_gen #(
  parameter integer DirFrac  = 24,  // FV: fraction bits of the ray direction (8..40)
  parameter integer EdgeFrac = 16,  // FE: fraction bits of the edge vectors (8..40)
  parameter integer IdxW     = 14,  // pixel index width; image sides < 2^14 (guard bits) (1..14)
  parameter integer TagW     = 1,   // side-band bits carried with each pixel (>= 1)
  // Derived (do not override). 4 integer bits (kDirInt, kEdgeInt), 14 guard bits (kRayGuard).
  parameter integer VgW      = `RPU_VGW(DirFrac),   // v0, dx, dy: Q(4.FV+14)
  parameter integer EgW      = `RPU_EGW(EdgeFrac),  // el0, et0, σW: Q(4.FE+14)
  parameter integer VW       = 4 + DirFrac,        // v: Q(4.FV)
  parameter integer VhW      = 2 + DirFrac,        // v̂: Q(2.FV)
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
  localparam integer SbW   = SbTag + TagW;

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

  // ---- the products i·dx, j·dy, i·σW, j·σW (pixel indices as non-negative signed operands) ----
  localparam integer C1W = TagW + 3 * EgW + 6 * EgW + 3 * VgW;  // {tag, σW, et0, el0, v0}
  localparam integer IW  = IdxW + 1;
  wire [IW-1:0]       i_s = {1'b0, i_i};
  wire [IW-1:0]       j_s = {1'b0, j_i};
  wire [3*VgW-1:0]    dxi, dyj;           // modulo 2^VgW
  wire [3*EdgeOutW-1:0] swi, swj;         // exact
  wire                m1_valid;
  wire [C1W-1:0]      c1;

  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_m1
      wire [VgW+IW-1:0] p_dx, p_dy;
      wire              v_dx, v_dy, v_si, v_sj, t_dy, t_si, t_sj;
      if (c == 0) begin : g_ctl
        rpu_mul #(.AW(VgW), .BW(IW), .Signed(1), .TagW(C1W), .Latency(L1)) u_dx (
          .clk_i, .rst_ni, .valid_i, .a_i(dx_i[c*VgW +: VgW]), .b_i(i_s),
          .tag_i({tag_i, sw_i, et0_i, el0_i, v0_i}), .valid_o(v_dx), .p_o(p_dx), .tag_o(c1));
        assign m1_valid = v_dx;
      end else begin : g_no_ctl
        wire t_dx;
        rpu_mul #(.AW(VgW), .BW(IW), .Signed(1), .TagW(1), .Latency(L1)) u_dx (
          .clk_i, .rst_ni, .valid_i, .a_i(dx_i[c*VgW +: VgW]), .b_i(i_s), .tag_i(1'b0),
          .valid_o(v_dx), .p_o(p_dx), .tag_o(t_dx));
        wire unused_ctl = ^{v_dx, t_dx};
      end
      rpu_mul #(.AW(VgW), .BW(IW), .Signed(1), .TagW(1), .Latency(L1)) u_dy (
        .clk_i, .rst_ni, .valid_i, .a_i(dy_i[c*VgW +: VgW]), .b_i(j_s), .tag_i(1'b0),
        .valid_o(v_dy), .p_o(p_dy), .tag_o(t_dy));
      rpu_mul #(.AW(EgW), .BW(IW), .Signed(1), .TagW(1), .Latency(L1)) u_si (
        .clk_i, .rst_ni, .valid_i, .a_i(sw_i[c*EgW +: EgW]), .b_i(i_s), .tag_i(1'b0),
        .valid_o(v_si), .p_o(swi[c*EdgeOutW +: EdgeOutW]), .tag_o(t_si));
      rpu_mul #(.AW(EgW), .BW(IW), .Signed(1), .TagW(1), .Latency(L1)) u_sj (
        .clk_i, .rst_ni, .valid_i, .a_i(sw_i[c*EgW +: EgW]), .b_i(j_s), .tag_i(1'b0),
        .valid_o(v_sj), .p_o(swj[c*EdgeOutW +: EdgeOutW]), .tag_o(t_sj));
      // Wrapping VgW-bit arithmetic: the low VgW bits of the exact values.
      assign dxi[c*VgW +: VgW] = p_dx[VgW-1:0];
      assign dyj[c*VgW +: VgW] = p_dy[VgW-1:0];
      wire unused_m1 = ^{v_dy, v_si, v_sj, t_dy, t_si, t_sj, p_dx[VgW+IW-1:VgW],
                         p_dy[VgW+IW-1:VgW]};
    end
  endgenerate
  wire [3*VgW-1:0] v0_1  = c1[0 +: 3*VgW];
  wire [3*EgW-1:0] el0_1 = c1[3*VgW +: 3*EgW];
  wire [3*EgW-1:0] et0_1 = c1[3*VgW+3*EgW +: 3*EgW];
  wire [3*EgW-1:0] sw_1  = c1[3*VgW+6*EgW +: 3*EgW];
  wire [TagW-1:0]  tag_1 = c1[C1W-1 -: TagW];

  // ---- stage 2: v = floor((v0 + i·dx + j·dy) / 2^G) (a sum of three modulo 2^VgW: one
  // carry-save step and one adder), the named truncation to Q(4.FV); E_left, E_top (exact) ----
  reg [3*VW-1:0]        s2_v_q;
  reg [3*EdgeOutW-1:0]  s2_el_q;
  reg [3*EdgeOutW-1:0]  s2_et_q;
  reg [3*EgW-1:0]       s2_sw_q;
  reg [TagW-1:0]        s2_tag_q;
  reg                   s2_valid_q;

  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s2
      wire [VgW-1:0] x0 = v0_1[c*VgW +: VgW];
      wire [VgW-1:0] x1 = dxi[c*VgW +: VgW];
      wire [VgW-1:0] x2 = dyj[c*VgW +: VgW];
      wire [VgW-1:0] cs_s = x0 ^ x1 ^ x2;
      wire [VgW-2:0] cs_c = (x0[VgW-2:0] & x1[VgW-2:0]) | (x0[VgW-2:0] & x2[VgW-2:0]) |
                            (x1[VgW-2:0] & x2[VgW-2:0]);
      wire [VgW-1:0] vg = cs_s + {cs_c, 1'b0};
      wire signed [EgW-1:0] el0 = el0_1[c*EgW +: EgW];
      wire signed [EgW-1:0] et0 = et0_1[c*EgW +: EgW];
      wire signed [EdgeOutW-1:0] el0_x = {{(EdgeOutW - EgW){el0[EgW-1]}}, el0};
      wire signed [EdgeOutW-1:0] et0_x = {{(EdgeOutW - EgW){et0[EgW-1]}}, et0};
      // |el0 − k·σW| < 2^(EdgeOutW−1) for k <= 2^IdxW: exact in EdgeOutW bits.
      always @(posedge clk_i) begin
        // vg >>> G is VW bits wide exactly (VgW − G = VW): the floor, no further narrowing.
        s2_v_q[c*VW +: VW]             <= vg[VgW-1:Guard];
        s2_el_q[c*EdgeOutW +: EdgeOutW] <= el0_x - swi[c*EdgeOutW +: EdgeOutW];
        s2_et_q[c*EdgeOutW +: EdgeOutW] <= et0_x - swj[c*EdgeOutW +: EdgeOutW];
      end
      wire unused_guard = ^vg[Guard-1:0];
    end
  endgenerate

  always @(posedge clk_i) begin
    s2_sw_q  <= sw_1;
    s2_tag_q <= tag_1;
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) s2_valid_q <= 1'b0;
    else         s2_valid_q <= m1_valid;
  end

  // ---- the squares v_k² (exact) ----
  // The side band {tag, σW, E_top, E_left, v}, which no logic reads before the output stage,
  // takes a plain delay line (shift-register LUTs) of L2 + 1 stages to the square root's tag.
  wire [3*RadW-1:0] sq;
  wire              m2_valid;
  reg [(L2+1)*SbW-1:0] sb_dl_q;
  always @(posedge clk_i)
    sb_dl_q <= {sb_dl_q[L2*SbW-1:0], s2_tag_q, s2_sw_q, s2_et_q, s2_el_q, s2_v_q};
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_sq
      wire [VW-1:0] vk = s2_v_q[c*VW +: VW];
      wire          v_sq, t_sq;
      rpu_mul #(.AW(VW), .BW(VW), .Signed(1), .TagW(1)) u_sq (
        .clk_i, .rst_ni, .valid_i(s2_valid_q), .a_i(vk), .b_i(vk), .tag_i(1'b0),
        .valid_o(v_sq), .p_o(sq[c*RadW +: RadW]), .tag_o(t_sq));
      if (c == 0) begin : g_ctl
        assign m2_valid = v_sq;
        wire unused_ctl = t_sq;
      end else begin : g_no_ctl
        wire unused_ctl = ^{v_sq, t_sq};
      end
    end
  endgenerate

  // ---- stage 3: the radicand v·v (exact: three squares of VW-bit values < 2^RadW; one
  // carry-save step and one adder) ----
  wire [RadW-1:0] q0 = sq[0*RadW +: RadW];
  wire [RadW-1:0] q1 = sq[1*RadW +: RadW];
  wire [RadW-1:0] q2 = sq[2*RadW +: RadW];
  wire [RadW-1:0] vv_s = q0 ^ q1 ^ q2;
  wire [RadW-2:0] vv_c = (q0[RadW-2:0] & q1[RadW-2:0]) | (q0[RadW-2:0] & q2[RadW-2:0]) |
                         (q1[RadW-2:0] & q2[RadW-2:0]);
  wire [RadW-1:0] vv = vv_s + {vv_c, 1'b0};

  reg [RadW-1:0] s3_rad_q;
  wire [SbW-1:0] s3_sb_q = sb_dl_q[(L2+1)*SbW-1 -: SbW];
  reg            s3_valid_q;
  always @(posedge clk_i) s3_rad_q <= vv;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) s3_valid_q <= 1'b0;
    else         s3_valid_q <= m2_valid;
  end

  // ---- |v| = isqrt(v·v) ----
  wire             sq_valid;
  wire [RootW-1:0] sq_root;
  wire [SbW-1:0]   sq_sb;
  rpu_sqrt #(
    .RadW (RadW),
    .SqrtW(0),
    .TagW (SbW)
  ) u_sqrt (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(s3_valid_q),
    .rad_i  (s3_rad_q),
    .tag_i  (s3_sb_q),
    .valid_o(sq_valid),
    .root_o (sq_root),
    .tag_o  (sq_sb)
  );

  // ---- 1/|v| = floor(2^(2FV+2) / |v|) ----
  wire             dv_valid;
  wire [QuotW-1:0] dv_recip;
  wire [SbW-1:0]   dv_sb;
  rpu_div #(
    .NumW (NumW),
    .DenW (RootW),
    .QuotW(QuotW),
    .TagW (SbW)
  ) u_div (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(sq_valid),
    .num_i  ({1'b1, {(NumW - 1){1'b0}}}),
    .den_i  (sq_root),
    .tag_i  (sq_sb),
    .valid_o(dv_valid),
    .quot_o (dv_recip),
    .tag_o  (dv_sb)
  );

  // ---- v·(1/|v|) (exact; 1/|v| as a non-negative signed operand); the side band in x's tag ----
  wire [QuotW:0]    recip_s = {1'b0, dv_recip};
  wire [3*PrdW-1:0] prd;
  wire              m3_valid;
  wire [SbW-1:0]    c3;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_m3
      wire [VW-1:0] v = dv_sb[SbV + c*VW +: VW];
      wire          v_p;
      if (c == 0) begin : g_ctl
        rpu_mul #(.AW(QuotW + 1), .BW(VW), .Signed(1), .TagW(SbW)) u_vh (
          .clk_i, .rst_ni, .valid_i(dv_valid), .a_i(recip_s), .b_i(v), .tag_i(dv_sb),
          .valid_o(v_p), .p_o(prd[c*PrdW +: PrdW]), .tag_o(c3));
        assign m3_valid = v_p;
      end else begin : g_no_ctl
        wire t_p;
        rpu_mul #(.AW(QuotW + 1), .BW(VW), .Signed(1), .TagW(1)) u_vh (
          .clk_i, .rst_ni, .valid_i(dv_valid), .a_i(recip_s), .b_i(v), .tag_i(1'b0),
          .valid_o(v_p), .p_o(prd[c*PrdW +: PrdW]), .tag_o(t_p));
        wire unused_ctl = ^{v_p, t_p};
      end
    end
  endgenerate

  // ---- output stage: v̂ = floor(v·(1/|v|) / 2^(FV+2)); E_right, E_bottom ----
  wire [3*VW-1:0]       o_v  = c3[SbV +: 3 * VW];
  wire [3*EdgeOutW-1:0] o_el = c3[SbEl +: 3 * EdgeOutW];
  wire [3*EdgeOutW-1:0] o_et = c3[SbEt +: 3 * EdgeOutW];
  wire [3*EgW-1:0]      o_sw = c3[SbSw +: 3 * EgW];

  reg [3*VW-1:0]        out_v_q;
  reg [3*VhW-1:0]       out_vhat_q;
  reg [3*EdgeOutW-1:0]  out_el_q;
  reg [3*EdgeOutW-1:0]  out_er_q;
  reg [3*EdgeOutW-1:0]  out_et_q;
  reg [3*EdgeOutW-1:0]  out_eb_q;
  reg [TagW-1:0]        out_tag_q;
  reg                   out_valid_q;

  generate
    for (c = 0; c < 3; c = c + 1) begin : g_out
      wire [PrdW-1:0]            pc   = prd[c*PrdW +: PrdW];
      wire signed [EgW-1:0]      sw   = o_sw[c*EgW +: EgW];
      wire signed [EdgeOutW-1:0] sw_x = {{(EdgeOutW - EgW){sw[EgW-1]}}, sw};
      wire signed [EdgeOutW-1:0] el   = o_el[c*EdgeOutW +: EdgeOutW];
      wire signed [EdgeOutW-1:0] et   = o_et[c*EdgeOutW +: EdgeOutW];
      // E_left(i) − σW = E_left(i+1), |·| < 2^(EdgeOutW−1): exact in EdgeOutW bits.
      wire signed [EdgeOutW-1:0] er   = el - sw_x;
      wire signed [EdgeOutW-1:0] eb   = et - sw_x;
      always @(posedge clk_i) begin
        // prd >>> (FV+2), truncated to Q(2.FV): |v_c| <= |v| gives |v̂_c| <= 2^FV, so the
        // dropped high bits are copies of the sign.
        out_vhat_q[c*VhW +: VhW]          <= pc[DirFrac+2 +: VhW];
        out_er_q[c*EdgeOutW +: EdgeOutW]  <= er;
        out_eb_q[c*EdgeOutW +: EdgeOutW]  <= eb;
      end
      wire unused_prd = ^{pc[PrdW-1:DirFrac+2+VhW], pc[DirFrac+1:0]};
    end
  endgenerate

  always @(posedge clk_i) begin
    out_v_q   <= o_v;
    out_el_q  <= o_el;
    out_et_q  <= o_et;
    out_tag_q <= c3[SbTag +: TagW];
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) out_valid_q <= 1'b0;
    else         out_valid_q <= m3_valid;
  end

  assign valid_o    = out_valid_q;
  assign v_o        = out_v_q;
  assign vhat_o     = out_vhat_q;
  assign e_left_o   = out_el_q;
  assign e_right_o  = out_er_q;
  assign e_top_o    = out_et_q;
  assign e_bottom_o = out_eb_q;
  assign tag_o      = out_tag_q;
endmodule

`default_nettype wire
