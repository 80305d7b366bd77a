// rpu_ray_plane: the ray / texture-plane unit, twin of
// `rpu::ref::ray_plane_unit(params, camera, v̂)`. The ray h + v̂·t meets the plane z = 0 at
//   t0    = udiv(|h_z|·2^FV, |v̂_z|), CW+1 quotient bits (rpu_div)                 LSB, unsigned
//   p0    = h + floor(v̂·t0 / 2^FV), z = 0                                         LSB, CW bits
//   depth = (p0 − h)·W, exact                    Q(4.FE+14)·LSB, rpu_capture's depth_o format
// and p0_valid_o is set iff h_z and v̂_z are non-zero with opposite signs (t0 > 0), the quotient
// fits CW+1 bits (|h_z|·2^FV < |v̂_z|·2^(CW+1)) and p0.x, p0.y fit CW bits signed. When it is
// clear, p0_o and depth_o are zero (the model's PlanePoint{} fields), so every output field
// equals the twin's bit for bit.
//
// Pipeline (Latency = CoordW + 5 + LatPt + LatD cycles, 36 at the defaults; one ray per cycle,
// no stall; every product an rpu_mul, rpu_mul_latency.vh):
//   1        |h_z|, |v̂_z|, the sign test, −h_z                       (all inputs sampled here)
//   1        the quotient-fit test
//   CW+1     rpu_div: t0                   (h, v̂_x, v̂_y, W, −h_z, the tests, tag_i in its tag)
//   LatPt    v̂_x·t0, v̂_y·t0                rpu_mul (CW+2) × (FV+2): 4 at the defaults
//   1        p0 = h + floor(v̂·t0 / 2^FV), the range test; p0 − h, −h_z (zero when not valid)
//   LatD     (p0 − h)_k·W_k, −h_z·W_z       rpu_mul (CW+1) × (FE+18): 3 at the defaults
//   1        depth = the sum of the three products (zero when not valid); outputs registered
//
// Widths: t0 < 2^(CW+1) and |v̂_k| ≤ 2^(FV+1) give |floor(v̂_k·t0 / 2^FV)| ≤ 2^(CW+2) (CW+3 bits
// signed) and h + that within CW+4 bits: the range test sees the exact sum for every port value.
// For a valid point p0 − h (and −h_z) fit CW+1 bits signed, so the depth products use those low
// bits (exact whenever the result is used) and the sum is exact in DepthW bits. For an invalid
// point the depth products' operands are zeroed, so the depth is zero as the twin's.
`default_nettype none
`include "rpu_widths.vh"

module rpu_ray_plane #(
  parameter integer CoordW   = 24,  // CW: signed width of positions, LSB (12..40)
  parameter integer DirFrac  = 24,  // FV: fraction bits of the ray direction v̂, Q(2.FV) (8..40)
  parameter integer EdgeFrac = 16,  // FE: fraction bits of W, Q(4.FE+14) (8..40)
  parameter integer TagW     = 1,   // side-band bits carried with each ray (>= 1)
  // Derived (do not override).
  parameter integer DirW   = DirFrac + 2,              // v̂: Q(2.FV)
  parameter integer EdgeW  = `RPU_EGW(EdgeFrac),        // W: Q(4.FE+14)
  parameter integer DepthW = CoordW + 4 + EdgeW + 2    // depth: rpu_capture's depth_o width
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [3*CoordW-1:0] eye_i,       // h, {z, y, x}, LSB, signed each
  input  wire [3*DirW-1:0]   vhat_i,      // v̂, {z, y, x}, Q(2.FV), signed each
  input  wire [3*EdgeW-1:0]  w_i,         // camera axis W, {z, y, x}, Q(4.FE+14), signed each
  input  wire [TagW-1:0]     tag_i,
  output reg                 valid_o,
  output reg                 p0_valid_o,  // the ray meets z = 0 in front of the eye, in range
  output reg  [3*CoordW-1:0] p0_o,        // {z = 0, y, x}, LSB, signed each (0 when not valid)
  output reg  [DepthW-1:0]   depth_o,     // (p0 − h)·W, signed (0 when not valid)
  output reg  [TagW-1:0]     tag_o
);
  localparam integer CW    = CoordW;
  localparam integer FV    = DirFrac;
  localparam integer NumW  = CW + FV;        // |h_z|·2^FV (|h_z| ≤ 2^(CW−1): CW bits)
  localparam integer QuotW = CW + 1;         // t0
  localparam integer HiW   = NumW - QuotW;   // (|h_z|·2^FV) >> (CW+1): FV−1 bits
  localparam integer DqW   = CW + 1;         // p0 − h, −h_z (of a valid point)
  localparam integer PtW   = DirW + QuotW + 1;  // v̂_k·t0 (t0 as a non-negative signed operand)
  localparam integer FxW   = CW + 3;         // floor(v̂_k·t0 / 2^FV)
  localparam integer SumW  = CW + 4;         // h_k + floor(v̂_k·t0 / 2^FV)
  localparam integer PW    = DqW + EdgeW;    // one depth product
  localparam integer SW    = PW + 2;         // the sum of three
  // Side band through rpu_div: {tag, ok, −h_z, W, v̂_y, v̂_x, h_y, h_x}.
  localparam integer SbDataW = DqW + 3 * EdgeW + 2 * DirW + 2 * CW;  // {−h_z, W, v̂_y, v̂_x, h_y, h_x}
  localparam integer SbW     = TagW + 1 + SbDataW;

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_ray_plane: CoordW must be in 12..40");
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_ray_plane: DirFrac must be in 8..40");
    if (EdgeFrac < 8 || EdgeFrac > 40) $fatal(1, "rpu_ray_plane: EdgeFrac must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_ray_plane: TagW must be >= 1");
    if (DirW != `RPU_VHATW(DirFrac) || EdgeW != 4 + EdgeFrac + 14 || DepthW != CoordW + 4 + EdgeW + 2)
      $fatal(1, "rpu_ray_plane: derived parameters must not be overridden");
  end

`include "rpu_mul_latency.vh"
  localparam integer LatPt = `RPU_MUL_LAT(QuotW + 1, DirW, 1);
  localparam integer LatD  = `RPU_MUL_LAT(DqW, EdgeW, 1);
  // The unit's latency (what the enclosing units count on; ref::ray_plane_latency).
  localparam integer Latency = CoordW + 5 + LatPt + LatD;

  // ---- stage 0: |h_z|, |v̂_z|, the sign test; −h_z ----
  wire signed [CW-1:0]   hz = eye_i[2*CW +: CW];
  wire signed [DirW-1:0] vz = vhat_i[2*DirW +: DirW];
  wire                   hz_neg = hz[CW-1];
  wire                   vz_neg = vz[DirW-1];
  // |h_z| ≤ 2^(CW−1) and |v̂_z| ≤ 2^(FV+1) fit their widths unsigned (the minimum negates to
  // itself read as unsigned).
  wire [CW-1:0]          hz_abs = hz_neg ? -hz : hz;
  wire [DirW-1:0]        vz_abs = vz_neg ? -vz : vz;
  // Opposite signs, neither zero: t0 = −h_z / v̂_z > 0.
  wire                   sign_ok = (|hz) & (|vz) & (hz_neg ^ vz_neg);
  wire signed [DqW-1:0]  nhz     = -{hz[CW-1], hz};
  // Side band from here to the divider's output: {tag, ok, −h_z, W, v̂_y, v̂_x, h_y, h_x}.
  wire [SbDataW-1:0]    sb_data = {nhz, w_i, vhat_i[0 +: 2*DirW], eye_i[0 +: 2*CW]};

  reg              s0_valid_q;
  reg [CW-1:0]     s0_hz_abs_q;
  reg [DirW-1:0]   s0_vz_abs_q;
  reg              s0_sign_ok_q;
  reg [SbDataW-1:0] s0_sb_q;
  reg [TagW-1:0]   s0_tag_q;
  always @(posedge clk_i) begin
    s0_hz_abs_q  <= hz_abs;
    s0_vz_abs_q  <= vz_abs;
    s0_sign_ok_q <= sign_ok;
    s0_sb_q      <= sb_data;
    s0_tag_q     <= tag_i;
  end

  // ---- stage 1: the quotient fits CW+1 bits iff num >> (CW+1) < |v̂_z| (then rpu_div's
  // precondition holds; otherwise its result is unused) ----
  wire [NumW-1:0]  num     = {s0_hz_abs_q, {FV{1'b0}}};
  wire [HiW-1:0]   num_hi  = num[NumW-1:QuotW];
  wire             quot_ok = {{(DirW - HiW){1'b0}}, num_hi} < s0_vz_abs_q;

  reg              s1_valid_q;
  reg [NumW-1:0]   s1_num_q;
  reg [DirW-1:0]   s1_den_q;
  reg [SbW-1:0]    s1_sb_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      s0_valid_q <= 1'b0;
      s1_valid_q <= 1'b0;
    end else begin
      s0_valid_q <= valid_i;
      s1_valid_q <= s0_valid_q;
    end
  end
  always @(posedge clk_i) begin
    s1_num_q <= num;
    s1_den_q <= s0_vz_abs_q;
    s1_sb_q  <= {s0_tag_q, s0_sign_ok_q & quot_ok, s0_sb_q};
  end

  // ---- t0 = floor(|h_z|·2^FV / |v̂_z|), the context in the divider's tag ----
  wire             dv_valid;
  wire [QuotW-1:0] t0;
  wire [SbW-1:0]   dv_sb;
  rpu_div #(
    .NumW (NumW),
    .DenW (DirW),
    .QuotW(QuotW),
    .TagW (SbW)
  ) u_div (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(s1_valid_q),
    .num_i  (s1_num_q),
    .den_i  (s1_den_q),
    .tag_i  (s1_sb_q),
    .valid_o(dv_valid),
    .quot_o (t0),
    .tag_o  (dv_sb)
  );
  wire [TagW-1:0]        dv_tag;
  wire                   dv_ok;
  wire signed [DqW-1:0]  dv_nhz;
  wire [EdgeW-1:0]       dv_wz, dv_wy, dv_wx;
  wire signed [DirW-1:0] dv_vy, dv_vx;
  wire [CW-1:0]          dv_hy, dv_hx;
  assign {dv_tag, dv_ok, dv_nhz, dv_wz, dv_wy, dv_wx, dv_vy, dv_vx, dv_hy, dv_hx} = dv_sb;

  // ---- v̂_x·t0, v̂_y·t0 (exact; t0 as a non-negative signed operand); the rest in x's tag ----
  localparam integer PtTagW = TagW + 1 + DqW + 3 * EdgeW + 2 * CW;
  wire [QuotW:0]      t0_s = {1'b0, t0};
  wire [PtW-1:0]      ptx, pty;
  wire                pt_valid, pty_valid_unused;
  wire [PtTagW-1:0]   pt_tag;
  wire                pty_tag_unused;
  rpu_mul #(.AW(QuotW + 1), .BW(DirW), .Signed(1), .TagW(PtTagW)) u_ptx (
    .clk_i, .rst_ni, .valid_i(dv_valid), .a_i(t0_s), .b_i(dv_vx),
    .tag_i({dv_tag, dv_ok, dv_nhz, dv_wz, dv_wy, dv_wx, dv_hy, dv_hx}),
    .valid_o(pt_valid), .p_o(ptx), .tag_o(pt_tag));
  rpu_mul #(.AW(QuotW + 1), .BW(DirW), .Signed(1), .TagW(1)) u_pty (
    .clk_i, .rst_ni, .valid_i(dv_valid), .a_i(t0_s), .b_i(dv_vy), .tag_i(1'b0),
    .valid_o(pty_valid_unused), .p_o(pty), .tag_o(pty_tag_unused));
  wire [TagW-1:0]       pt_tg;
  wire                  pt_ok;
  wire signed [DqW-1:0] pt_nhz;
  wire [EdgeW-1:0]      pt_wz, pt_wy, pt_wx;
  wire [CW-1:0]         pt_hy, pt_hx;
  assign {pt_tg, pt_ok, pt_nhz, pt_wz, pt_wy, pt_wx, pt_hy, pt_hx} = pt_tag;

  // ---- stage B: p0 = h + floor(v̂·t0 / 2^FV) and its range test; the depth operands ----
  // |v̂_k·t0| < 2^(FV+CW+2): the product's top bit is a sign copy; the floor is FxW bits.
  wire signed [FxW-1:0]  fx   = ptx[PtW-2:FV];
  wire signed [FxW-1:0]  fy   = pty[PtW-2:FV];
  wire signed [SumW-1:0] p0x  = {{(SumW - CW){pt_hx[CW-1]}}, pt_hx} +
                                {{(SumW - FxW){fx[FxW-1]}}, fx};
  wire signed [SumW-1:0] p0y  = {{(SumW - CW){pt_hy[CW-1]}}, pt_hy} +
                                {{(SumW - FxW){fy[FxW-1]}}, fy};
  wire                   fits_x = (&p0x[SumW-1:CW-1]) | ~(|p0x[SumW-1:CW-1]);
  wire                   fits_y = (&p0y[SumW-1:CW-1]) | ~(|p0y[SumW-1:CW-1]);
  wire                   ok     = pt_ok & fits_x & fits_y;
  // p0 − h = floor(v̂·t0 / 2^FV); its low DqW bits are exact when p0 fits (|p0 − h| < 2^CW).
  // Zeroed, with −h_z and p0, when the point is not valid: then the depth and p0 are zero.
  reg              sb_valid_q;
  reg              sb_ok_q;
  reg [CW-1:0]     sb_p0x_q, sb_p0y_q;
  reg [DqW-1:0]    sb_dqx_q, sb_dqy_q, sb_nhz_q;
  reg [EdgeW-1:0]  sb_wx_q, sb_wy_q, sb_wz_q;
  reg [TagW-1:0]   sb_tag_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) sb_valid_q <= 1'b0;
    else         sb_valid_q <= pt_valid;
  end
  always @(posedge clk_i) begin
    sb_ok_q  <= ok;
    sb_p0x_q <= ok ? p0x[CW-1:0] : {CW{1'b0}};
    sb_p0y_q <= ok ? p0y[CW-1:0] : {CW{1'b0}};
    sb_dqx_q <= ok ? fx[DqW-1:0] : {DqW{1'b0}};
    sb_dqy_q <= ok ? fy[DqW-1:0] : {DqW{1'b0}};
    sb_nhz_q <= ok ? pt_nhz : {DqW{1'b0}};
    sb_wx_q  <= pt_wx;
    sb_wy_q  <= pt_wy;
    sb_wz_q  <= pt_wz;
    sb_tag_q <= pt_tg;
  end

  // ---- the three depth products (exact); {tag, ok, p0} in x's tag ----
  localparam integer DTagW = TagW + 1 + 2 * CW;
  wire [PW-1:0]      px, py, pz;
  wire               d_valid, dy_valid_unused, dz_valid_unused, dy_tag_unused, dz_tag_unused;
  wire [DTagW-1:0]   d_tag;
  rpu_mul #(.AW(DqW), .BW(EdgeW), .Signed(1), .TagW(DTagW)) u_px (
    .clk_i, .rst_ni, .valid_i(sb_valid_q), .a_i(sb_dqx_q), .b_i(sb_wx_q),
    .tag_i({sb_tag_q, sb_ok_q, sb_p0y_q, sb_p0x_q}), .valid_o(d_valid), .p_o(px), .tag_o(d_tag));
  rpu_mul #(.AW(DqW), .BW(EdgeW), .Signed(1), .TagW(1)) u_py (
    .clk_i, .rst_ni, .valid_i(sb_valid_q), .a_i(sb_dqy_q), .b_i(sb_wy_q), .tag_i(1'b0),
    .valid_o(dy_valid_unused), .p_o(py), .tag_o(dy_tag_unused));
  rpu_mul #(.AW(DqW), .BW(EdgeW), .Signed(1), .TagW(1)) u_pz (
    .clk_i, .rst_ni, .valid_i(sb_valid_q), .a_i(sb_nhz_q), .b_i(sb_wz_q), .tag_i(1'b0),
    .valid_o(dz_valid_unused), .p_o(pz), .tag_o(dz_tag_unused));

  // ---- stage C: depth = the sum of the three products (one carry-save step and one adder,
  // exact modulo 2^SW: the sum fits) ----
  wire [SW-1:0] x0   = {{2{px[PW-1]}}, px};
  wire [SW-1:0] x1   = {{2{py[PW-1]}}, py};
  wire [SW-1:0] x2   = {{2{pz[PW-1]}}, pz};
  wire [SW-1:0] cs_s = x0 ^ x1 ^ x2;
  wire [SW-2:0] cs_c = (x0[SW-2:0] & x1[SW-2:0]) | (x0[SW-2:0] & x2[SW-2:0]) |
                       (x1[SW-2:0] & x2[SW-2:0]);
  wire [SW-1:0] dsum = cs_s + {cs_c, 1'b0};
  wire [DepthW-1:0] depth = {{(DepthW - SW){dsum[SW-1]}}, dsum};
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_o <= 1'b0;
    else         valid_o <= d_valid;
  end
  always @(posedge clk_i) begin
    p0_valid_o <= d_tag[2*CW];
    p0_o       <= {{CW{1'b0}}, d_tag[2*CW-1:0]};
    depth_o    <= depth;
    tag_o      <= d_tag[DTagW-1 -: TagW];
  end

  // The products' top bits are sign copies, their low FV bits the floor's dropped fraction; the
  // bits of p0 − h above DqW only matter for an invalid point (caught by the range test).
  wire unused_bits = ^{ptx[PtW-1], ptx[FV-1:0], pty[PtW-1], pty[FV-1:0],
                       fx[FxW-1:DqW], fy[FxW-1:DqW]};
endmodule

`default_nettype wire
