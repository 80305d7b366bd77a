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
// Pipeline (Latency = CoordW + 5 cycles, 29 at the defaults; one ray per cycle, no stall):
//   1        |h_z|, |v̂_z|, the sign and quotient-fit tests, −h_z     (all inputs sampled here)
//   CW+1     rpu_div: t0                   (h, v̂_x, v̂_y, W, −h_z, the tests, tag_i in its tag)
//   1        v̂_x·t0, v̂_y·t0, −h_z·W_z (exact products)
//   1        p0 = h + floor(v̂·t0 / 2^FV), the range test; (p0 − h)_x·W_x, (p0 − h)_y·W_y
//   1        depth = the sum of the three products; outputs registered (zero when not valid)
//
// Widths: t0 < 2^(CW+1) and |v̂_k| ≤ 2^(FV+1) give |floor(v̂_k·t0 / 2^FV)| ≤ 2^(CW+2) (CW+3 bits
// signed) and h + that within CW+4 bits: the range test sees the exact sum for every port value.
// For a valid point p0 − h (and −h_z) fit CW+1 bits signed, so the depth products use those low
// bits (exact whenever the result is used) and the sum is exact in DepthW bits.
`default_nettype none

module rpu_ray_plane #(
  parameter integer CoordW   = 24,  // CW: signed width of positions, LSB (12..40)
  parameter integer DirFrac  = 24,  // FV: fraction bits of the ray direction v̂, Q(2.FV) (8..40)
  parameter integer EdgeFrac = 16,  // FE: fraction bits of W, Q(4.FE+14) (8..40)
  parameter integer TagW     = 1,   // side-band bits carried with each ray (>= 1)
  // Derived (do not override).
  parameter integer DirW   = DirFrac + 2,              // v̂: Q(2.FV)
  parameter integer EdgeW  = 4 + EdgeFrac + 14,        // W: Q(4.FE+14)
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
  localparam integer SbW   = TagW + 1 + DqW + 3 * EdgeW + 2 * DirW + 2 * CW;

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_ray_plane: CoordW must be in 12..40");
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_ray_plane: DirFrac must be in 8..40");
    if (EdgeFrac < 8 || EdgeFrac > 40) $fatal(1, "rpu_ray_plane: EdgeFrac must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_ray_plane: TagW must be >= 1");
    if (DirW != DirFrac + 2 || EdgeW != 4 + EdgeFrac + 14 || DepthW != CoordW + 4 + EdgeW + 2)
      $fatal(1, "rpu_ray_plane: derived parameters must not be overridden");
  end

  // ---- stage 1: |h_z|, |v̂_z|, the tests; −h_z ----
  wire signed [CW-1:0]   hx = eye_i[0*CW +: CW];
  wire signed [CW-1:0]   hy = eye_i[1*CW +: CW];
  wire signed [CW-1:0]   hz = eye_i[2*CW +: CW];
  wire signed [DirW-1:0] vz = vhat_i[2*DirW +: DirW];
  wire                   hz_neg = hz[CW-1];
  wire                   vz_neg = vz[DirW-1];
  // |h_z| ≤ 2^(CW−1) and |v̂_z| ≤ 2^(FV+1) fit their widths unsigned (the minimum negates to
  // itself read as unsigned).
  wire [CW-1:0]          hz_abs = hz_neg ? -hz : hz;
  wire [DirW-1:0]        vz_abs = vz_neg ? -vz : vz;
  wire [NumW-1:0]        num    = {hz_abs, {FV{1'b0}}};
  wire [HiW-1:0]         num_hi = num[NumW-1:QuotW];
  // Opposite signs, neither zero: t0 = −h_z / v̂_z > 0. The quotient fits CW+1 bits iff
  // num >> (CW+1) < |v̂_z| (then rpu_div's precondition holds; otherwise its result is unused).
  wire                   sign_ok = (|hz) & (|vz) & (hz_neg ^ vz_neg);
  wire                   quot_ok = {{(DirW - HiW){1'b0}}, num_hi} < vz_abs;
  wire signed [DqW-1:0]  nhz     = -{hz[CW-1], hz};

  reg              s1_valid_q;
  reg [NumW-1:0]   s1_num_q;
  reg [DirW-1:0]   s1_den_q;
  reg [SbW-1:0]    s1_sb_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) s1_valid_q <= 1'b0;
    else         s1_valid_q <= valid_i;
  end
  always @(posedge clk_i) begin
    s1_num_q <= num;
    s1_den_q <= vz_abs;
    s1_sb_q  <= {tag_i, sign_ok & quot_ok, nhz, w_i, vhat_i[0 +: 2*DirW], hy, hx};
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

  // ---- stage A: v̂_x·t0, v̂_y·t0, −h_z·W_z (exact) ----
  wire signed [PtW-1:0] t0_s  = $signed({{(PtW - QuotW){1'b0}}, t0});
  wire signed [PtW-1:0] ptx   = $signed({{(PtW - DirW){dv_vx[DirW-1]}}, dv_vx}) * t0_s;
  wire signed [PtW-1:0] pty   = $signed({{(PtW - DirW){dv_vy[DirW-1]}}, dv_vy}) * t0_s;
  wire signed [PW-1:0]  pz    = $signed({{EdgeW{dv_nhz[DqW-1]}}, dv_nhz}) *
                                $signed({{DqW{dv_wz[EdgeW-1]}}, dv_wz});

  reg              sa_valid_q;
  reg [PtW-1:0]    sa_ptx_q, sa_pty_q;
  reg [PW-1:0]     sa_pz_q;
  reg [EdgeW-1:0]  sa_wy_q, sa_wx_q;
  reg [CW-1:0]     sa_hy_q, sa_hx_q;
  reg              sa_ok_q;
  reg [TagW-1:0]   sa_tag_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) sa_valid_q <= 1'b0;
    else         sa_valid_q <= dv_valid;
  end
  always @(posedge clk_i) begin
    sa_ptx_q <= ptx;
    sa_pty_q <= pty;
    sa_pz_q  <= pz;
    sa_wy_q  <= dv_wy;
    sa_wx_q  <= dv_wx;
    sa_hy_q  <= dv_hy;
    sa_hx_q  <= dv_hx;
    sa_ok_q  <= dv_ok;
    sa_tag_q <= dv_tag;
  end

  // ---- stage B: p0 = h + floor(v̂·t0 / 2^FV) and its range test; the x and y depth products ----
  // |v̂_k·t0| < 2^(FV+CW+2): the product's top bit is a sign copy; the floor is FxW bits.
  wire signed [FxW-1:0]  fx   = sa_ptx_q[PtW-2:FV];
  wire signed [FxW-1:0]  fy   = sa_pty_q[PtW-2:FV];
  wire signed [SumW-1:0] p0x  = {{(SumW - CW){sa_hx_q[CW-1]}}, sa_hx_q} +
                                {{(SumW - FxW){fx[FxW-1]}}, fx};
  wire signed [SumW-1:0] p0y  = {{(SumW - CW){sa_hy_q[CW-1]}}, sa_hy_q} +
                                {{(SumW - FxW){fy[FxW-1]}}, fy};
  wire                   fits_x = (&p0x[SumW-1:CW-1]) | ~(|p0x[SumW-1:CW-1]);
  wire                   fits_y = (&p0y[SumW-1:CW-1]) | ~(|p0y[SumW-1:CW-1]);
  // p0 − h = floor(v̂·t0 / 2^FV); its low DqW bits are exact when p0 fits (|p0 − h| < 2^CW).
  wire signed [DqW-1:0]  dqx  = fx[DqW-1:0];
  wire signed [DqW-1:0]  dqy  = fy[DqW-1:0];
  wire signed [PW-1:0]   px   = $signed({{EdgeW{dqx[DqW-1]}}, dqx}) *
                                $signed({{DqW{sa_wx_q[EdgeW-1]}}, sa_wx_q});
  wire signed [PW-1:0]   py   = $signed({{EdgeW{dqy[DqW-1]}}, dqy}) *
                                $signed({{DqW{sa_wy_q[EdgeW-1]}}, sa_wy_q});

  reg              sb_valid_q;
  reg              sb_ok_q;
  reg [CW-1:0]     sb_p0x_q, sb_p0y_q;
  reg [PW-1:0]     sb_px_q, sb_py_q, sb_pz_q;
  reg [TagW-1:0]   sb_tag_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) sb_valid_q <= 1'b0;
    else         sb_valid_q <= sa_valid_q;
  end
  always @(posedge clk_i) begin
    sb_ok_q  <= sa_ok_q & fits_x & fits_y;
    sb_p0x_q <= p0x[CW-1:0];
    sb_p0y_q <= p0y[CW-1:0];
    sb_px_q  <= px;
    sb_py_q  <= py;
    sb_pz_q  <= sa_pz_q;
    sb_tag_q <= sa_tag_q;
  end

  // ---- stage C: depth = the sum of the three products (exact); outputs zero when not valid ----
  wire signed [SW-1:0] dsum = {{2{sb_px_q[PW-1]}}, sb_px_q} + {{2{sb_py_q[PW-1]}}, sb_py_q} +
                              {{2{sb_pz_q[PW-1]}}, sb_pz_q};
  wire [DepthW-1:0]    depth = {{(DepthW - SW){dsum[SW-1]}}, dsum};
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_o <= 1'b0;
    else         valid_o <= sb_valid_q;
  end
  always @(posedge clk_i) begin
    p0_valid_o <= sb_ok_q;
    p0_o       <= sb_ok_q ? {{CW{1'b0}}, sb_p0y_q, sb_p0x_q} : {3*CW{1'b0}};
    depth_o    <= sb_ok_q ? depth : {DepthW{1'b0}};
    tag_o      <= sb_tag_q;
  end

  // The products' top bits are sign copies, their low FV bits the floor's dropped fraction; the
  // bits of p0 − h above DqW only matter for an invalid point (caught by the range test).
  wire unused_bits = ^{sa_ptx_q[PtW-1], sa_ptx_q[FV-1:0], sa_pty_q[PtW-1], sa_pty_q[FV-1:0],
                       fx[FxW-1:DqW], fy[FxW-1:DqW]};
endmodule

`default_nettype wire
