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
// A tag_i of 32 bits or more waits in an rpu_tag_queue beside the stages instead ("tag_i" above is
// then one constant bit).
//
// Widths: t0 < 2^(CW+1) and |v̂_k| ≤ 2^(FV+1) give |floor(v̂_k·t0 / 2^FV)| ≤ 2^(CW+2) (CW+3 bits
// signed) and h + that within CW+4 bits: the range test sees the exact sum for every port value.
// For a valid point p0 − h (and −h_z) fit CW+1 bits signed, so the depth products use those low
// bits (exact whenever the result is used) and the sum is exact in DepthW bits. For an invalid
// point the depth products' operands are zeroed, so the depth is zero as the twin's.
`default_nettype none
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_ray_plane #(
  parameter integer CoordW   = 24,  // CW: signed width of positions, LSB (12..40)
  parameter integer DirFrac  = 24,  // FV: fraction bits of the ray direction v̂, Q(2.FV) (8..40)
  parameter integer EdgeFrac = 16,  // FE: fraction bits of W, Q(4.FE+14) (8..40)
  parameter integer TagW     = 1,   // side-band bits carried with each ray (>= 1)
  // Derived (do not override).
  parameter integer DirW   = `RPU_VHATW(DirFrac),              // v̂: Q(2.FV)
  parameter integer EdgeW  = `RPU_EGW(EdgeFrac),        // W: Q(4.FE+14)
  parameter integer DepthW = `RPU_DEPTHW(CoordW, EdgeFrac)    // depth: rpu_capture's depth_o width
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [3*CoordW-1:0] eye_i,       // h, {z, y, x}, LSB, signed each
  input  wire [3*DirW-1:0]   vhat_i,      // v̂, {z, y, x}, Q(2.FV), signed each
  input  wire [3*EdgeW-1:0]  w_i,         // camera axis W, {z, y, x}, Q(4.FE+14), signed each
  input  wire [TagW-1:0]     tag_i,
  output wire                valid_o,
  output wire                p0_valid_o,  // the ray meets z = 0 in front of the eye, in range
  output wire [3*CoordW-1:0] p0_o,        // {z = 0, y, x}, LSB, signed each (0 when not valid)
  output wire [DepthW-1:0]   depth_o,     // (p0 − h)·W, signed (0 when not valid)
  output wire [TagW-1:0]     tag_o
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
  localparam integer PTagW   = `RPU_PTAGW(TagW);  // the tag the stages carry (rpu_tag_queue)
  localparam integer SbW     = PTagW + 1 + SbDataW;

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_ray_plane: CoordW must be in 12..40");
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_ray_plane: DirFrac must be in 8..40");
    if (EdgeFrac < 8 || EdgeFrac > 40) $fatal(1, "rpu_ray_plane: EdgeFrac must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_ray_plane: TagW must be >= 1");
    if (DirW != `RPU_VHATW(DirFrac) || EdgeW != `RPU_EGW(EdgeFrac)
        || DepthW != `RPU_DEPTHW(CoordW, EdgeFrac))
      $fatal(1, "rpu_ray_plane: derived parameters must not be overridden");
  end

`include "rpu_mul_latency.vh"
  localparam integer LatPt = `RPU_MUL_LAT(QuotW + 1, DirW, 1);
  localparam integer LatD  = `RPU_MUL_LAT(DqW, EdgeW, 1);
  // The unit's latency (what the enclosing units count on; ref::ray_plane_latency).
  localparam integer Latency = CoordW + 5 + LatPt + LatD;
  // The caller's tag: a wide one waits in a queue (rpu_tag_queue), the stages carry PTagW bits.
  wire [PTagW-1:0] ptag_in, ptag_out;
  rpu_tag_queue #(.TagW(TagW), .Latency(Latency)) u_tagq (
    .clk_i, .rst_ni, .valid_i, .tag_i, .ptag_o(ptag_in), .out_valid_i(valid_o), .ptag_i(ptag_out),
    .tag_o);

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

  wire              s0_valid_q;
  wire [CW-1:0]     s0_hz_abs_q;
  wire [DirW-1:0]   s0_vz_abs_q;
  wire              s0_sign_ok_q;
  wire [SbDataW-1:0] s0_sb_q;
  wire [PTagW-1:0]  s0_tag_q;
  rpu_stage #(.W(CW + DirW + 1 + SbDataW + PTagW)) u_s0 (
    .clk_i, .rst_ni, .valid_i, .d_i({hz_abs, vz_abs, sign_ok, sb_data, ptag_in}),
    .valid_o(s0_valid_q), .q_o({s0_hz_abs_q, s0_vz_abs_q, s0_sign_ok_q, s0_sb_q, s0_tag_q}));

  // ---- stage 1: the quotient fits CW+1 bits iff num >> (CW+1) < |v̂_z| (then rpu_div's
  // precondition holds; otherwise its result is unused) ----
  wire [NumW-1:0]  num     = {s0_hz_abs_q, {FV{1'b0}}};
  wire [HiW-1:0]   num_hi  = num[NumW-1:QuotW];
  wire             quot_ok = {{(DirW - HiW){1'b0}}, num_hi} < s0_vz_abs_q;

  wire              s1_valid_q;
  wire [NumW-1:0]   s1_num_q;
  wire [DirW-1:0]   s1_den_q;
  wire [SbW-1:0]    s1_sb_q;
  rpu_stage #(.W(NumW + DirW + SbW)) u_s1 (
    .clk_i, .rst_ni, .valid_i(s0_valid_q),
    .d_i({num, s0_vz_abs_q, s0_tag_q, s0_sign_ok_q & quot_ok, s0_sb_q}),
    .valid_o(s1_valid_q), .q_o({s1_num_q, s1_den_q, s1_sb_q}));

  // ---- t0 = floor(|h_z|·2^FV / |v̂_z|), the context in the divider's tag ----
  wire             dv_valid;
  wire [QuotW-1:0] t0;
  wire [SbW-1:0]   dv_sb;
  rpu_div #(.NumW(NumW), .DenW(DirW), .QuotW(QuotW), .TagW(SbW)) u_div (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .num_i(s1_num_q), .den_i(s1_den_q),
    .tag_i(s1_sb_q), .valid_o(dv_valid), .quot_o(t0), .tag_o(dv_sb));
  wire [PTagW-1:0]       dv_tag;
  wire                   dv_ok;
  wire signed [DqW-1:0]  dv_nhz;
  wire [EdgeW-1:0]       dv_wz, dv_wy, dv_wx;
  wire signed [DirW-1:0] dv_vy, dv_vx;
  wire [CW-1:0]          dv_hy, dv_hx;
  assign {dv_tag, dv_ok, dv_nhz, dv_wz, dv_wy, dv_wx, dv_vy, dv_vx, dv_hy, dv_hx} = dv_sb;

  // ---- v̂_x·t0, v̂_y·t0 (exact; t0 as a non-negative signed operand); the rest in x's tag ----
  localparam integer PtTagW = PTagW + 1 + DqW + 3 * EdgeW + 2 * CW;
  wire [QuotW:0]      t0_s = {1'b0, t0};
  wire [PtW-1:0]      ptx, pty;
  wire                pt_valid;
  wire [PtTagW-1:0]   pt_tag;
  rpu_mul_vec #(.Count(2), .AW(QuotW + 1), .BW(DirW), .Signed(1), .ShareA(1), .TagW(PtTagW))
    u_pt (
    .clk_i, .rst_ni, .valid_i(dv_valid), .a_i(t0_s), .b_i({dv_vy, dv_vx}),
    .tag_i({dv_tag, dv_ok, dv_nhz, dv_wz, dv_wy, dv_wx, dv_hy, dv_hx}),
    .valid_o(pt_valid), .p_o({pty, ptx}), .tag_o(pt_tag));
  wire [PTagW-1:0]      pt_tg;
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
  wire              sb_valid_q;
  wire              sb_ok_q;
  wire [2*CW-1:0]   sb_p0_q;   // {p0_y, p0_x}
  wire [3*DqW-1:0]  sb_dq_q;   // {−h_z, p0_y − h_y, p0_x − h_x}
  wire [3*EdgeW-1:0] sb_w_q;   // {W_z, W_y, W_x}
  wire [PTagW-1:0]  sb_tag_q;
  rpu_stage #(.W(1 + 2*CW + 3*DqW + 3*EdgeW + PTagW)) u_sb (
    .clk_i, .rst_ni, .valid_i(pt_valid),
    .d_i({ok, ok ? {p0y[CW-1:0], p0x[CW-1:0]} : {2*CW{1'b0}},
          ok ? {pt_nhz, fy[DqW-1:0], fx[DqW-1:0]} : {3*DqW{1'b0}}, pt_wz, pt_wy, pt_wx, pt_tg}),
    .valid_o(sb_valid_q), .q_o({sb_ok_q, sb_p0_q, sb_dq_q, sb_w_q, sb_tag_q}));

  // ---- the three depth products (exact); {tag, ok, p0} in x's tag ----
  localparam integer DTagW = PTagW + 1 + 2 * CW;
  wire [PW-1:0]      px, py, pz;
  wire               d_valid;
  wire [DTagW-1:0]   d_tag;
  rpu_mul_vec #(.Count(3), .AW(DqW), .BW(EdgeW), .Signed(1), .TagW(DTagW)) u_pd (
    .clk_i, .rst_ni, .valid_i(sb_valid_q), .a_i(sb_dq_q), .b_i(sb_w_q),
    .tag_i({sb_tag_q, sb_ok_q, sb_p0_q}), .valid_o(d_valid), .p_o({pz, py, px}), .tag_o(d_tag));

  // ---- stage C: depth = the sum of the three products (one carry-save step and one adder,
  // exact modulo 2^SW: the sum fits) ----
  wire [SW-1:0] dsum;
  rpu_add3 #(.W(SW)) u_dsum (
    .a_i({{2{px[PW-1]}}, px}), .b_i({{2{py[PW-1]}}, py}), .c_i({{2{pz[PW-1]}}, pz}), .s_o(dsum));
  wire [DepthW-1:0] depth = {{(DepthW - SW){dsum[SW-1]}}, dsum};
  rpu_stage #(.W(1 + 3*CW + DepthW + PTagW)) u_out (
    .clk_i, .rst_ni, .valid_i(d_valid),
    .d_i({d_tag[2*CW], {CW{1'b0}}, d_tag[2*CW-1:0], depth, d_tag[DTagW-1 -: PTagW]}),
    .valid_o, .q_o({p0_valid_o, p0_o, depth_o, ptag_out}));

  // The products' top bits are sign copies, their low FV bits the floor's dropped fraction; the
  // bits of p0 − h above DqW only matter for an invalid point (caught by the range test).
  wire unused_bits = ^{ptx[PtW-1], ptx[FV-1:0], pty[PtW-1], pty[FV-1:0],
                       fx[FxW-1:DqW], fy[FxW-1:DqW]};
  `RPU_LATENCY_CHECK(Latency, "rpu_ray_plane")
endmodule

`default_nettype wire
