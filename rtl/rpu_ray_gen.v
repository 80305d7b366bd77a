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
// Pipeline (Latency = 2·DirFrac + 11 cycles, one pixel per cycle, no stall):
//   1        v0 + i·dx, j·dy; E_left, E_top (products and edge vectors)
//   2        v (sum, guard bits dropped)
//   3        v·v (three squares)
//   FV+4     rpu_sqrt: |v|                       (v, E_left, E_top, σW and tag_i in its tag)
//   FV+3     rpu_div:  1/|v|                     (the same side band in its tag)
//   1        v̂ = v·(1/|v|); E_right, E_bottom; outputs registered
// Every input is sampled with valid_i (the camera ports may change between pixels).
//
// Preconditions (checked by the scene compiler, as the model assumes): every pixel's direction
// v0 + i·dx + j·dy fits Q(4.FV+14) (the model checks the image corners: |component| < 8), and
// |v| > 1/2 so that 1/|v| fits FV+3 bits (|v| >= ~1 for any camera: v = W + in-plane offsets).
// Under them the sum is computed modulo 2^(4+FV+14), which gives the exact value's low bits and
// hence exactly the twin's v. The edge vectors are exact for every input (EdgeOutW bits).
`default_nettype none

module rpu_ray_gen #(
  parameter integer DirFrac  = 24,  // FV: fraction bits of the ray direction (8..40)
  parameter integer EdgeFrac = 16,  // FE: fraction bits of the edge vectors (8..40)
  parameter integer IdxW     = 14,  // pixel index width; image sides < 2^14 (guard bits) (1..14)
  parameter integer TagW     = 1,   // side-band bits carried with each pixel (>= 1)
  // Derived (do not override). 4 integer bits (kDirInt, kEdgeInt), 14 guard bits (kRayGuard).
  parameter integer VgW      = 4 + DirFrac + 14,   // v0, dx, dy: Q(4.FV+14)
  parameter integer EgW      = 4 + EdgeFrac + 14,  // el0, et0, σW: Q(4.FE+14)
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

  // ---- stage 1: products (pixel indices as non-negative signed operands) ----
  wire signed [VgW-1:0]      i_v = $signed({{(VgW - IdxW){1'b0}}, i_i});
  wire signed [VgW-1:0]      j_v = $signed({{(VgW - IdxW){1'b0}}, j_i});
  wire signed [EdgeOutW-1:0] i_e = $signed({{(EdgeOutW - IdxW){1'b0}}, i_i});
  wire signed [EdgeOutW-1:0] j_e = $signed({{(EdgeOutW - IdxW){1'b0}}, j_i});

  reg  [3*VgW-1:0]      s1_a_q;   // v0 + i·dx, modulo 2^VgW
  reg  [3*VgW-1:0]      s1_b_q;   // j·dy, modulo 2^VgW
  reg  [3*EdgeOutW-1:0] s1_el_q;  // E_left(i), exact
  reg  [3*EdgeOutW-1:0] s1_et_q;  // E_top(j), exact
  reg  [3*EgW-1:0]      s1_sw_q;
  reg  [TagW-1:0]       s1_tag_q;
  reg                   s1_valid_q;

  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s1
      wire signed [VgW-1:0] v0 = v0_i[c*VgW +: VgW];
      wire signed [VgW-1:0] dx = dx_i[c*VgW +: VgW];
      wire signed [VgW-1:0] dy = dy_i[c*VgW +: VgW];
      wire signed [EgW-1:0] el0 = el0_i[c*EgW +: EgW];
      wire signed [EgW-1:0] et0 = et0_i[c*EgW +: EgW];
      wire signed [EgW-1:0] sw = sw_i[c*EgW +: EgW];
      wire signed [EdgeOutW-1:0] el0_x = {{(EdgeOutW - EgW){el0[EgW-1]}}, el0};
      wire signed [EdgeOutW-1:0] et0_x = {{(EdgeOutW - EgW){et0[EgW-1]}}, et0};
      wire signed [EdgeOutW-1:0] sw_x  = {{(EdgeOutW - EgW){sw[EgW-1]}}, sw};
      // Wrapping VgW-bit arithmetic: the low VgW bits of the exact values.
      wire signed [VgW-1:0] a = v0 + dx * i_v;
      wire signed [VgW-1:0] b = dy * j_v;
      // |el0 − k·σW| < 2^(EdgeOutW−1) for k <= 2^IdxW: exact in EdgeOutW bits.
      wire signed [EdgeOutW-1:0] el = el0_x - sw_x * i_e;
      wire signed [EdgeOutW-1:0] et = et0_x - sw_x * j_e;
      always @(posedge clk_i) begin
        s1_a_q[c*VgW +: VgW]           <= a;
        s1_b_q[c*VgW +: VgW]           <= b;
        s1_el_q[c*EdgeOutW +: EdgeOutW] <= el;
        s1_et_q[c*EdgeOutW +: EdgeOutW] <= et;
      end
    end
  endgenerate

  always @(posedge clk_i) begin
    s1_sw_q  <= sw_i;
    s1_tag_q <= tag_i;
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) s1_valid_q <= 1'b0;
    else         s1_valid_q <= valid_i;
  end

  // ---- stage 2: v = floor((v0 + i·dx + j·dy) / 2^G), the named truncation to Q(4.FV) ----
  reg [3*VW-1:0]        s2_v_q;
  reg [3*EdgeOutW-1:0]  s2_el_q;
  reg [3*EdgeOutW-1:0]  s2_et_q;
  reg [3*EgW-1:0]       s2_sw_q;
  reg [TagW-1:0]        s2_tag_q;
  reg                   s2_valid_q;

  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s2
      wire [VgW-1:0] vg = s1_a_q[c*VgW +: VgW] + s1_b_q[c*VgW +: VgW];
      // vg >>> G is VW bits wide exactly (VgW − G = VW): the floor, no further narrowing.
      always @(posedge clk_i) s2_v_q[c*VW +: VW] <= vg[VgW-1:Guard];
      wire unused_guard = ^vg[Guard-1:0];
    end
  endgenerate

  always @(posedge clk_i) begin
    s2_el_q  <= s1_el_q;
    s2_et_q  <= s1_et_q;
    s2_sw_q  <= s1_sw_q;
    s2_tag_q <= s1_tag_q;
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) s2_valid_q <= 1'b0;
    else         s2_valid_q <= s1_valid_q;
  end

  // ---- stage 3: the radicand v·v (exact: three squares of VW-bit values < 2^RadW) ----
  wire signed [VW-1:0] vx = s2_v_q[0*VW +: VW];
  wire signed [VW-1:0] vy = s2_v_q[1*VW +: VW];
  wire signed [VW-1:0] vz = s2_v_q[2*VW +: VW];
  wire signed [RadW-1:0] vx_x = {{VW{vx[VW-1]}}, vx};
  wire signed [RadW-1:0] vy_x = {{VW{vy[VW-1]}}, vy};
  wire signed [RadW-1:0] vz_x = {{VW{vz[VW-1]}}, vz};
  wire signed [RadW-1:0] vv = vx_x * vx_x + vy_x * vy_x + vz_x * vz_x;

  reg [RadW-1:0] s3_rad_q;
  reg [SbW-1:0]  s3_sb_q;
  reg            s3_valid_q;
  always @(posedge clk_i) begin
    s3_rad_q <= vv;
    s3_sb_q  <= {s2_tag_q, s2_sw_q, s2_et_q, s2_el_q, s2_v_q};
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) s3_valid_q <= 1'b0;
    else         s3_valid_q <= s2_valid_q;
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

  // ---- output stage: v̂ = floor(v·(1/|v|) / 2^(FV+2)); E_right, E_bottom ----
  wire [3*VW-1:0]       o_v  = dv_sb[SbV +: 3 * VW];
  wire [3*EdgeOutW-1:0] o_el = dv_sb[SbEl +: 3 * EdgeOutW];
  wire [3*EdgeOutW-1:0] o_et = dv_sb[SbEt +: 3 * EdgeOutW];
  wire [3*EgW-1:0]      o_sw = dv_sb[SbSw +: 3 * EgW];
  wire signed [PrdW-1:0] recip_x = $signed({{(PrdW - QuotW){1'b0}}, dv_recip});

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
      wire signed [VW-1:0]       v   = o_v[c*VW +: VW];
      wire signed [PrdW-1:0]     v_x = {{(PrdW - VW){v[VW-1]}}, v};
      wire signed [PrdW-1:0]     prd = v_x * recip_x;
      wire signed [EgW-1:0]      sw  = o_sw[c*EgW +: EgW];
      wire signed [EdgeOutW-1:0] sw_x = {{(EdgeOutW - EgW){sw[EgW-1]}}, sw};
      wire signed [EdgeOutW-1:0] el  = o_el[c*EdgeOutW +: EdgeOutW];
      wire signed [EdgeOutW-1:0] et  = o_et[c*EdgeOutW +: EdgeOutW];
      // E_left(i) − σW = E_left(i+1), |·| < 2^(EdgeOutW−1): exact in EdgeOutW bits.
      wire signed [EdgeOutW-1:0] er  = el - sw_x;
      wire signed [EdgeOutW-1:0] eb  = et - sw_x;
      always @(posedge clk_i) begin
        // prd >>> (FV+2), truncated to Q(2.FV): |v_c| <= |v| gives |v̂_c| <= 2^FV, so the
        // dropped high bits are copies of the sign.
        out_vhat_q[c*VhW +: VhW]          <= prd[DirFrac+2 +: VhW];
        out_er_q[c*EdgeOutW +: EdgeOutW]  <= er;
        out_eb_q[c*EdgeOutW +: EdgeOutW]  <= eb;
      end
      wire unused_prd = ^{prd[PrdW-1:DirFrac+2+VhW], prd[DirFrac+1:0]};
    end
  endgenerate

  always @(posedge clk_i) begin
    out_v_q   <= o_v;
    out_el_q  <= o_el;
    out_et_q  <= o_et;
    out_tag_q <= dv_sb[SbTag +: TagW];
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) out_valid_q <= 1'b0;
    else         out_valid_q <= dv_valid;
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
