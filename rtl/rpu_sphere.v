// rpu_sphere: the sphere unit (the model's `sphere_unit`): does the ray h + v̂·t meet the
// segment's interpolation sphere (c0, R²) in front of the eye, and the search interval [A, B]:
//   q = c0 − h (exact), tc = floor(v̂·q), w = q × v̂ (exact) floored to Guard fraction bits,
//   disc = R² − floor(|w|²) (the squared ray distance of c0; well conditioned however far the eye),
//   hc = sqrt_unit(disc) (rpu_sqrt, 2CoordW+5-bit radicand; saturated, flagged when wider),
//   pred1 = disc >= 0 ∧ tc + hc > 0, t1 = max(0, tc − hc), t2 = tc + hc,
//   A = sat(h + floor(v̂·t1)), B = sat(h + floor(v̂·t2)) to CoordW bits (flagged), AB = B − A,
//   alpha = chord((A − p1)·d), beta = chord(AB·d) (two rpu_chord, flagged when saturated).
// ovf_o mirrors the model's sticky flag exactly: the radicand saturation counts whenever
// disc >= 0 (the model takes the root before it tests t2), every later saturation only when
// pred1 holds (the model returns before A and B otherwise). half_chord_o is 0 when disc < 0, as
// in the model. When pred1_o is 0, a_o, b_o, ab_o, alpha_o and beta_o are don't-care.
// Vectors are flattened {z, y, x}, each component two's complement.
// Fixed latency of Latency = SqrtStages + 13 cycles (40 at the defaults): 5 stages up to the
// radicand, the rpu_sqrt pipeline, 6 stages to the dot products, 2 in rpu_chord. One operand per
// cycle; `tag_i` rides along unchanged. No backpressure inside (rpu_top reserves room).
`default_nettype none

module rpu_sphere #(
  parameter integer CoordW  = 24,  // signed width of positions, LSB (12..40)
  parameter integer DirFrac = 24,  // fraction bits of the ray direction v̂, Q(2.DirFrac) (8..40)
  parameter integer TFrac   = 24,  // fraction bits of alpha, beta, Q(3.TFrac) (8..48)
  parameter integer InvW    = 18,  // mantissa bits of 1/L², inv_m unsigned (8..40)
  parameter integer SqrtW   = 0,   // widest radicand of the square root; 0 = exact (16..126)
  parameter integer TagW    = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer DirW  = DirFrac + 2,     // v̂: Q(2.DirFrac)
  parameter integer DiffW = CoordW + 1,      // d, AB: differences of two positions
  parameter integer R2W   = 2 * CoordW + 1,  // R² (the compiler's R² < 2^(2CoordW))
  parameter integer TcW   = CoordW + 4,      // tc: |v̂·q| < 3·2^(CoordW+1) for any v̂, q
  parameter integer HcW   = CoordW + 3,      // hc = isqrt of a (2CoordW+5)-bit radicand
  parameter integer TW    = TFrac + 3        // alpha, beta: Q(3.TFrac)
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              valid_i,
  input  wire [3*CoordW-1:0] eye_i,    // h, LSB
  input  wire [3*DirW-1:0]   vhat_i,   // v̂, Q(2.DirFrac)
  input  wire [3*CoordW-1:0] c0_i,     // sphere centre, LSB
  input  wire [R2W-1:0]      r2_i,     // sphere radius², LSB², unsigned
  input  wire [3*CoordW-1:0] p1_i,     // segment start, LSB
  input  wire [3*DiffW-1:0]  d_i,      // p2 − p1, LSB
  input  wire [InvW-1:0]     inv_m_i,  // 1/L² = inv_m · 2^-inv_s
  input  wire [6:0]          inv_s_i,
  input  wire [TagW-1:0]     tag_i,
  output wire              valid_o,
  output wire              pred1_o,
  output wire [TcW-1:0]      tc_o,          // LSB, signed
  output wire [HcW-1:0]      half_chord_o,  // LSB, unsigned
  output wire [3*CoordW-1:0] a_o,           // LSB, saturated
  output wire [3*CoordW-1:0] b_o,           // LSB, saturated
  output wire [3*DiffW-1:0]  ab_o,          // B − A, LSB
  output wire [TW-1:0]       alpha_o,       // Q(3.TFrac)
  output wire [TW-1:0]       beta_o,        // Q(3.TFrac)
  output wire              ovf_o,
  output wire [TagW-1:0]     tag_o
);
  localparam integer CW    = CoordW;
  localparam integer FV    = DirFrac;
  localparam integer PvW   = DirW + DiffW;   // v̂_k·q_k, exact
  localparam integer VqW   = FV + CW + 4;    // v̂·q: |.| < 3·2^(FV+CW+1)
  localparam integer Guard = 2;             // HwParams::kSphereGuard
  localparam integer WtW   = PvW + 1 - (FV - Guard);  // q × v̂ floored to Q(.Guard) LSB, signed
  localparam integer WsqW  = 2 * WtW - 1;    // wt_k², unsigned
  localparam integer PsW   = WsqW + 2;       // |wt|², unsigned
  localparam integer DiscW = PsW - 2 * Guard + 1;  // R² − perp2, signed (R2W < PsW − 2Guard)
  localparam integer RadW  = 2 * CW + 5;     // the model's sphere_radicand_w()
  localparam integer TpW   = CW + 5;         // t1, t2: |.| < 12·2^CW, signed
  localparam integer PtW   = DirW + TpW;     // v̂_k·t, exact
  localparam integer EndW  = PtW - FV;      // h + floor(v̂·t): |.| < 2^(CW+5) + 2^(CW−1)
  localparam integer DotW  = 2 * DiffW + 2;  // (A − p1)·d and AB·d
  localparam integer SegW  = 3 * CW + 3 * DiffW + InvW + 7;  // {inv_s, inv_m, d, p1}
  localparam integer ChW   = 3 * DiffW + InvW + 7;           // {inv_s, inv_m, d}
  // The square-root pipeline depth (rpu_sqrt's derived parameters).
  localparam integer SqShift  = (SqrtW == 0 || RadW <= SqrtW) ? 0 : (RadW - SqrtW + 1) / 2;
  localparam integer SqStages = (RadW - 2 * SqShift + 1) / 2;
  localparam integer Latency  = SqStages + 13;
  localparam [RadW-1:0] RadMax = {RadW{1'b1}};

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_sphere: CoordW must be in 12..40");
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_sphere: DirFrac must be in 8..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_sphere: TFrac must be in 8..48");
    if (InvW < 8 || InvW > 40) $fatal(1, "rpu_sphere: InvW must be in 8..40");
    if (SqrtW != 0 && (SqrtW < 16 || SqrtW > 126))
      $fatal(1, "rpu_sphere: SqrtW must be 0 or 16..126");
    if (TagW < 1) $fatal(1, "rpu_sphere: TagW must be >= 1");
    if (DirW != DirFrac + 2 || DiffW != CoordW + 1 || R2W != 2 * CoordW + 1 ||
        TcW != CoordW + 4 || HcW != CoordW + 3 || TW != TFrac + 3)
      $fatal(1, "rpu_sphere: derived parameters must not be overridden");
    if (Latency < 14) $fatal(1, "rpu_sphere: bad square-root depth");
  end

  genvar k;

  // ---------------------------------------------------------------------------------------------
  // Stage 1: q = c0 − h (exact, DiffW bits).
  // ---------------------------------------------------------------------------------------------
  wire [3*DiffW-1:0] q;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_q
      wire signed [DiffW-1:0] c0x = {c0_i[k*CW+CW-1], c0_i[k*CW +: CW]};
      wire signed [DiffW-1:0] hx  = {eye_i[k*CW+CW-1], eye_i[k*CW +: CW]};
      assign q[k*DiffW +: DiffW] = c0x - hx;
    end
  endgenerate

  reg [3*DiffW-1:0] q1_q;
  reg [3*CW-1:0]    h1_q;
  reg [3*DirW-1:0]  v1_q;
  reg [R2W-1:0]     r2_1_q;
  reg [SegW-1:0]    seg1_q;
  reg [TagW-1:0]    tag1_q;
  reg               valid1_q;
  always @(posedge clk_i) begin
    q1_q   <= q;
    h1_q   <= eye_i;
    v1_q   <= vhat_i;
    r2_1_q <= r2_i;
    seg1_q <= {inv_s_i, inv_m_i, d_i, p1_i};
    tag1_q <= tag_i;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 2: the products v̂_k·q_k and the cross-product terms q_{k+1}·v̂_{k+2}, q_{k+2}·v̂_{k+1}
  // (all exact).
  // ---------------------------------------------------------------------------------------------
  wire [3*PvW-1:0] pv;
  wire [3*PvW-1:0] pca;
  wire [3*PvW-1:0] pcb;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_pv
      wire signed [DirW-1:0]  vk  = v1_q[k*DirW +: DirW];
      wire signed [DiffW-1:0] qk  = q1_q[k*DiffW +: DiffW];
      wire signed [DirW-1:0]  va  = v1_q[((k+2)%3)*DirW +: DirW];
      wire signed [DiffW-1:0] qa  = q1_q[((k+1)%3)*DiffW +: DiffW];
      wire signed [DirW-1:0]  vb  = v1_q[((k+1)%3)*DirW +: DirW];
      wire signed [DiffW-1:0] qb  = q1_q[((k+2)%3)*DiffW +: DiffW];
      wire signed [PvW-1:0]   vx  = {{DiffW{vk[DirW-1]}}, vk};
      wire signed [PvW-1:0]   qx  = {{DirW{qk[DiffW-1]}}, qk};
      wire signed [PvW-1:0]   vax = {{DiffW{va[DirW-1]}}, va};
      wire signed [PvW-1:0]   qax = {{DirW{qa[DiffW-1]}}, qa};
      wire signed [PvW-1:0]   vbx = {{DiffW{vb[DirW-1]}}, vb};
      wire signed [PvW-1:0]   qbx = {{DirW{qb[DiffW-1]}}, qb};
      assign pv[k*PvW +: PvW]  = vx * qx;
      assign pca[k*PvW +: PvW] = qax * vax;
      assign pcb[k*PvW +: PvW] = qbx * vbx;
    end
  endgenerate

  reg [3*PvW-1:0]  pv2_q;
  reg [3*PvW-1:0]  pca2_q;
  reg [3*PvW-1:0]  pcb2_q;
  reg [3*CW-1:0]   h2_q;
  reg [3*DirW-1:0] v2_q;
  reg [R2W-1:0]    r2_2_q;
  reg [SegW-1:0]   seg2_q;
  reg [TagW-1:0]   tag2_q;
  reg              valid2_q;
  always @(posedge clk_i) begin
    pv2_q  <= pv;
    pca2_q <= pca;
    pcb2_q <= pcb;
    h2_q   <= h1_q;
    v2_q   <= v1_q;
    r2_2_q <= r2_1_q;
    seg2_q <= seg1_q;
    tag2_q <= tag1_q;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 3: tc = floor(v̂·q · 2^-FV) (the sum cannot wrap in VqW bits); the cross product
  // w = q × v̂ (exact), each component floored to Guard fraction bits of an LSB.
  // ---------------------------------------------------------------------------------------------
  wire signed [PvW-1:0] pv_x = pv2_q[0*PvW +: PvW];
  wire signed [PvW-1:0] pv_y = pv2_q[1*PvW +: PvW];
  wire signed [PvW-1:0] pv_z = pv2_q[2*PvW +: PvW];
  wire signed [VqW-1:0] vq = {{(VqW-PvW){pv_x[PvW-1]}}, pv_x} +
                             {{(VqW-PvW){pv_y[PvW-1]}}, pv_y} +
                             {{(VqW-PvW){pv_z[PvW-1]}}, pv_z};
  wire [TcW-1:0] tc = vq[VqW-1:FV];  // arithmetic shift right by FV (floor)
  wire unused_vq = ^vq[FV-1:0];
  wire [3*WtW-1:0] wt;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_w
      wire signed [PvW-1:0] a = pca2_q[k*PvW +: PvW];
      wire signed [PvW-1:0] b = pcb2_q[k*PvW +: PvW];
      wire signed [PvW:0]   w = {a[PvW-1], a} - {b[PvW-1], b};
      assign wt[k*WtW +: WtW] = w[PvW:FV-Guard];  // floor(w · 2^-(FV−Guard))
      wire unused_w = ^w[FV-Guard-1:0];
    end
  endgenerate

  reg [TcW-1:0]    tc3_q;
  reg [3*WtW-1:0]  wt3_q;
  reg [3*CW-1:0]   h3_q;
  reg [3*DirW-1:0] v3_q;
  reg [R2W-1:0]    r2_3_q;
  reg [SegW-1:0]   seg3_q;
  reg [TagW-1:0]   tag3_q;
  reg              valid3_q;
  always @(posedge clk_i) begin
    tc3_q  <= tc;
    wt3_q  <= wt;
    h3_q   <= h2_q;
    v3_q   <= v2_q;
    r2_3_q <= r2_2_q;
    seg3_q <= seg2_q;
    tag3_q <= tag2_q;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 4: the squares wt_k² (exact, non-negative).
  // ---------------------------------------------------------------------------------------------
  wire [3*WsqW-1:0] wsq;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_wsq
      wire signed [WtW-1:0]   wk = wt3_q[k*WtW +: WtW];
      wire signed [2*WtW-1:0] wx = {{WtW{wk[WtW-1]}}, wk};
      wire signed [2*WtW-1:0] sq = wx * wx;
      // |wt_k| <= 2^(WtW−1), so wt_k² <= 2^(2WtW−2) < 2^WsqW: the top bit is zero.
      assign wsq[k*WsqW +: WsqW] = sq[WsqW-1:0];
      wire unused_sq = sq[2*WtW-1];
    end
  endgenerate

  reg [3*WsqW-1:0] wsq4_q;
  reg [R2W-1:0]    r2_4_q;
  reg [TcW-1:0]    tc4_q;
  reg [3*CW-1:0]   h4_q;
  reg [3*DirW-1:0] v4_q;
  reg [SegW-1:0]   seg4_q;
  reg [TagW-1:0]   tag4_q;
  reg              valid4_q;
  always @(posedge clk_i) begin
    wsq4_q  <= wsq;
    r2_4_q  <= r2_3_q;
    tc4_q   <= tc3_q;
    h4_q    <= h3_q;
    v4_q    <= v3_q;
    seg4_q  <= seg3_q;
    tag4_q  <= tag3_q;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 5: perp2 = floor(|wt|² · 2^-2Guard) (the squared distance of c0 from the ray, LSB²),
  // disc = R² − perp2; the radicand: 0 when disc < 0 (no root taken: hc = 0 as in the model),
  // saturated to RadW bits and flagged when wider (fixed::saturate_unsigned; disc <= R² never
  // is, but the flag mirrors the model's rule rather than relying on that bound).
  // ---------------------------------------------------------------------------------------------
  wire [PsW-1:0] wsum = {2'b00, wsq4_q[0*WsqW +: WsqW]} + {2'b00, wsq4_q[1*WsqW +: WsqW]} +
                        {2'b00, wsq4_q[2*WsqW +: WsqW]};
  wire [PsW-2*Guard-1:0] perp2 = wsum[PsW-1:2*Guard];
  wire unused_wsum = ^wsum[2*Guard-1:0];
  wire signed [DiscW-1:0] disc = {{(DiscW-R2W){1'b0}}, r2_4_q} -
                                 {{(DiscW-(PsW-2*Guard)){1'b0}}, perp2};
  wire disc_neg = disc[DiscW-1];
  wire disc_big = ~disc_neg & (|disc[DiscW-2:RadW]);  // disc >= 2^RadW
  wire [RadW-1:0] rad = disc_neg ? {RadW{1'b0}} : disc_big ? RadMax : disc[RadW-1:0];

  reg [RadW-1:0]   rad5_q;
  reg              neg5_q;
  reg              sovf5_q;
  reg [TcW-1:0]    tc5_q;
  reg [3*CW-1:0]   h5_q;
  reg [3*DirW-1:0] v5_q;
  reg [SegW-1:0]   seg5_q;
  reg [TagW-1:0]   tag5_q;
  reg              valid5_q;
  always @(posedge clk_i) begin
    rad5_q  <= rad;
    neg5_q  <= disc_neg;
    sovf5_q <= disc_big;
    tc5_q   <= tc4_q;
    h5_q    <= h4_q;
    v5_q    <= v4_q;
    seg5_q  <= seg4_q;
    tag5_q  <= tag4_q;
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid1_q <= 1'b0;
      valid2_q <= 1'b0;
      valid3_q <= 1'b0;
      valid4_q <= 1'b0;
      valid5_q <= 1'b0;
    end else begin
      valid1_q <= valid_i;
      valid2_q <= valid1_q;
      valid3_q <= valid2_q;
      valid4_q <= valid3_q;
      valid5_q <= valid4_q;
    end
  end

  // ---------------------------------------------------------------------------------------------
  // The square root; the context rides in its tag.
  // ---------------------------------------------------------------------------------------------
  localparam integer SqTagW = TagW + SegW + 3 * DirW + 3 * CW + TcW + 2;
  wire              sq_valid;
  wire [HcW-1:0]    sq_root;
  wire [SqTagW-1:0] sq_tag;
  rpu_sqrt #(
    .RadW (RadW),
    .SqrtW(SqrtW),
    .TagW (SqTagW)
  ) u_sqrt (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(valid5_q),
    .rad_i  (rad5_q),
    .tag_i  ({tag5_q, seg5_q, v5_q, h5_q, tc5_q, neg5_q, sovf5_q}),
    .valid_o(sq_valid),
    .root_o (sq_root),
    .tag_o  (sq_tag)
  );
  wire [TagW-1:0]   tag_s  = sq_tag[SqTagW-1 -: TagW];
  wire [SegW-1:0]   seg_s  = sq_tag[SqTagW-TagW-1 -: SegW];
  wire [3*DirW-1:0] v_s    = sq_tag[2+TcW+3*CW +: 3*DirW];
  wire [3*CW-1:0]   h_s    = sq_tag[2+TcW +: 3*CW];
  wire [TcW-1:0]    tc_s   = sq_tag[2 +: TcW];
  wire              neg_s  = sq_tag[1];
  wire              sovf_s = sq_tag[0];

  // ---------------------------------------------------------------------------------------------
  // Stage 6: t2 = tc + hc, t1 = max(0, tc − hc), pred1 = disc >= 0 ∧ t2 > 0.
  // ---------------------------------------------------------------------------------------------
  wire signed [TpW-1:0] tc_w = {{(TpW-TcW){tc_s[TcW-1]}}, tc_s};
  wire signed [TpW-1:0] hc_w = {{(TpW-HcW){1'b0}}, sq_root};
  wire signed [TpW-1:0] t2   = tc_w + hc_w;
  wire signed [TpW-1:0] t1d  = tc_w - hc_w;
  wire [TpW-1:0]        t1   = t1d[TpW-1] ? {TpW{1'b0}} : t1d;
  wire                  pred1 = ~neg_s & ~t2[TpW-1] & (|t2);

  reg [TpW-1:0]    t1_6_q;
  reg [TpW-1:0]    t2_6_q;
  reg              pred1_6_q;
  reg              sovf6_q;
  reg [HcW-1:0]    hc6_q;
  reg [TcW-1:0]    tc6_q;
  reg [3*CW-1:0]   h6_q;
  reg [3*DirW-1:0] v6_q;
  reg [SegW-1:0]   seg6_q;
  reg [TagW-1:0]   tag6_q;
  reg              valid6_q;
  always @(posedge clk_i) begin
    t1_6_q    <= t1;
    t2_6_q    <= t2;
    pred1_6_q <= pred1;
    sovf6_q   <= sovf_s;
    hc6_q     <= sq_root;
    tc6_q     <= tc_s;
    h6_q      <= h_s;
    v6_q      <= v_s;
    seg6_q    <= seg_s;
    tag6_q    <= tag_s;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 7: the products v̂_k·t1, v̂_k·t2 (exact).
  // ---------------------------------------------------------------------------------------------
  wire [3*PtW-1:0] pa;
  wire [3*PtW-1:0] pb;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_pt
      wire signed [DirW-1:0] vk  = v6_q[k*DirW +: DirW];
      wire signed [PtW-1:0]  vx  = {{TpW{vk[DirW-1]}}, vk};
      wire signed [PtW-1:0]  t1x = {{DirW{t1_6_q[TpW-1]}}, t1_6_q};
      wire signed [PtW-1:0]  t2x = {{DirW{t2_6_q[TpW-1]}}, t2_6_q};
      assign pa[k*PtW +: PtW] = vx * t1x;
      assign pb[k*PtW +: PtW] = vx * t2x;
    end
  endgenerate

  // The outputs that ride along to the end: {tag, tc, hc, pred1}.
  localparam integer OutW = TagW + TcW + HcW + 1;

  reg [3*PtW-1:0] pa7_q;
  reg [3*PtW-1:0] pb7_q;
  reg [3*CW-1:0]  h7_q;
  reg             sovf7_q;
  reg [OutW-1:0]  out7_q;
  reg [SegW-1:0]  seg7_q;
  reg             valid7_q;
  always @(posedge clk_i) begin
    pa7_q   <= pa;
    pb7_q   <= pb;
    h7_q    <= h6_q;
    sovf7_q <= sovf6_q;
    out7_q  <= {tag6_q, tc6_q, hc6_q, pred1_6_q};
    seg7_q  <= seg6_q;
  end
  wire pred1_7 = out7_q[0];

  // ---------------------------------------------------------------------------------------------
  // Stage 8: A = sat(h + floor(v̂·t1 · 2^-FV)), B likewise, to CW bits; flagged under pred1.
  // ---------------------------------------------------------------------------------------------
  wire [3*CW-1:0] a_sat;
  wire [3*CW-1:0] b_sat;
  wire [5:0]      clamped;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_end
      wire signed [PtW-1:0]  pak = pa7_q[k*PtW +: PtW];
      wire signed [PtW-1:0]  pbk = pb7_q[k*PtW +: PtW];
      wire signed [CW-1:0]   hk  = h7_q[k*CW +: CW];
      // |floor(v̂·t · 2^-FV)| <= 2^(CW+5) (|v̂_k| <= 2^(FV+1), |t| <= 2^(CW+4)): with h the sum
      // fits EndW = CW + 7 bits, the width of the shifted product; the addition cannot wrap.
      wire signed [EndW-1:0] ea  = pak[PtW-1:FV] + {{(EndW-CW){hk[CW-1]}}, hk};
      wire signed [EndW-1:0] eb  = pbk[PtW-1:FV] + {{(EndW-CW){hk[CW-1]}}, hk};
      wire fa = (&ea[EndW-1:CW-1]) | ~(|ea[EndW-1:CW-1]);
      wire fb = (&eb[EndW-1:CW-1]) | ~(|eb[EndW-1:CW-1]);
      assign a_sat[k*CW +: CW] = fa ? ea[CW-1:0] : {ea[EndW-1], {(CW-1){~ea[EndW-1]}}};
      assign b_sat[k*CW +: CW] = fb ? eb[CW-1:0] : {eb[EndW-1], {(CW-1){~eb[EndW-1]}}};
      assign clamped[2*k]   = ~fa;
      assign clamped[2*k+1] = ~fb;
      wire unused_frac = ^{pak[FV-1:0], pbk[FV-1:0]};
    end
  endgenerate

  reg [3*CW-1:0] a8_q;
  reg [3*CW-1:0] b8_q;
  reg            ovf8_q;
  reg [OutW-1:0] out8_q;
  reg [SegW-1:0] seg8_q;
  reg            valid8_q;
  always @(posedge clk_i) begin
    a8_q   <= a_sat;
    b8_q   <= b_sat;
    ovf8_q <= sovf7_q | (pred1_7 & (|clamped));
    out8_q <= out7_q;
    seg8_q <= seg7_q;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 9: AB = B − A, A − p1 (exact, DiffW bits).
  // ---------------------------------------------------------------------------------------------
  wire [3*DiffW-1:0] ab;
  wire [3*DiffW-1:0] ap;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_ab
      wire signed [DiffW-1:0] ak = {a8_q[k*CW+CW-1], a8_q[k*CW +: CW]};
      wire signed [DiffW-1:0] bk = {b8_q[k*CW+CW-1], b8_q[k*CW +: CW]};
      wire signed [DiffW-1:0] pk = {seg8_q[k*CW+CW-1], seg8_q[k*CW +: CW]};
      assign ab[k*DiffW +: DiffW] = bk - ak;
      assign ap[k*DiffW +: DiffW] = ak - pk;
    end
  endgenerate

  reg [3*CW-1:0]    a9_q;
  reg [3*CW-1:0]    b9_q;
  reg [3*DiffW-1:0] ab9_q;
  reg [3*DiffW-1:0] ap9_q;
  reg               ovf9_q;
  reg [OutW-1:0]    out9_q;
  reg [ChW-1:0]     ch9_q;
  reg               valid9_q;
  always @(posedge clk_i) begin
    a9_q   <= a8_q;
    b9_q   <= b8_q;
    ab9_q  <= ab;
    ap9_q  <= ap;
    ovf9_q <= ovf8_q;
    out9_q <= out8_q;
    ch9_q  <= seg8_q[SegW-1:3*CW];  // {inv_s, inv_m, d}; p1 is no longer needed
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 10: the products (A − p1)_k·d_k and AB_k·d_k (exact).
  // ---------------------------------------------------------------------------------------------
  wire [3*2*DiffW-1:0] prod_a;
  wire [3*2*DiffW-1:0] prod_b;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_dp
      wire signed [DiffW-1:0]   dk  = ch9_q[k*DiffW +: DiffW];
      wire signed [DiffW-1:0]   apk = ap9_q[k*DiffW +: DiffW];
      wire signed [DiffW-1:0]   abk = ab9_q[k*DiffW +: DiffW];
      wire signed [2*DiffW-1:0] dx  = {{DiffW{dk[DiffW-1]}}, dk};
      wire signed [2*DiffW-1:0] apx = {{DiffW{apk[DiffW-1]}}, apk};
      wire signed [2*DiffW-1:0] abx = {{DiffW{abk[DiffW-1]}}, abk};
      assign prod_a[k*2*DiffW +: 2*DiffW] = apx * dx;
      assign prod_b[k*2*DiffW +: 2*DiffW] = abx * dx;
    end
  endgenerate

  reg [3*2*DiffW-1:0] prod_a10_q;
  reg [3*2*DiffW-1:0] prod_b10_q;
  reg [3*CW-1:0]      a10_q;
  reg [3*CW-1:0]      b10_q;
  reg [3*DiffW-1:0]   ab10_q;
  reg                 ovf10_q;
  reg [OutW-1:0]      out10_q;
  reg [InvW+6:0]      inv10_q;
  reg                 valid10_q;
  always @(posedge clk_i) begin
    prod_a10_q <= prod_a;
    prod_b10_q <= prod_b;
    a10_q      <= a9_q;
    b10_q      <= b9_q;
    ab10_q     <= ab9_q;
    ovf10_q    <= ovf9_q;
    out10_q    <= out9_q;
    inv10_q    <= ch9_q[ChW-1:3*DiffW];  // {inv_s, inv_m}
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 11: the dot products (sums of three exact products, DotW bits).
  // ---------------------------------------------------------------------------------------------
  localparam integer PdW = 2 * DiffW;
  wire signed [PdW-1:0] pa_x = prod_a10_q[0*PdW +: PdW];
  wire signed [PdW-1:0] pa_y = prod_a10_q[1*PdW +: PdW];
  wire signed [PdW-1:0] pa_z = prod_a10_q[2*PdW +: PdW];
  wire signed [PdW-1:0] pb_x = prod_b10_q[0*PdW +: PdW];
  wire signed [PdW-1:0] pb_y = prod_b10_q[1*PdW +: PdW];
  wire signed [PdW-1:0] pb_z = prod_b10_q[2*PdW +: PdW];
  wire signed [DotW-1:0] dot_a = {{2{pa_x[PdW-1]}}, pa_x} + {{2{pa_y[PdW-1]}}, pa_y} +
                                 {{2{pa_z[PdW-1]}}, pa_z};
  wire signed [DotW-1:0] dot_b = {{2{pb_x[PdW-1]}}, pb_x} + {{2{pb_y[PdW-1]}}, pb_y} +
                                 {{2{pb_z[PdW-1]}}, pb_z};

  // Everything the outputs need besides alpha and beta rides in chord A's tag.
  localparam integer ResW = OutW + 1 + 6 * CW + 3 * DiffW;  // {out, ovf, A, B, AB}

  reg [DotW-1:0] dot_a11_q;
  reg [DotW-1:0] dot_b11_q;
  reg [ResW-1:0] res11_q;
  reg [InvW+6:0] inv11_q;
  reg            valid11_q;
  always @(posedge clk_i) begin
    dot_a11_q <= dot_a;
    dot_b11_q <= dot_b;
    res11_q   <= {out10_q, ovf10_q, a10_q, b10_q, ab10_q};
    inv11_q   <= inv10_q;
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid6_q  <= 1'b0;
      valid7_q  <= 1'b0;
      valid8_q  <= 1'b0;
      valid9_q  <= 1'b0;
      valid10_q <= 1'b0;
      valid11_q <= 1'b0;
    end else begin
      valid6_q  <= sq_valid;
      valid7_q  <= valid6_q;
      valid8_q  <= valid7_q;
      valid9_q  <= valid8_q;
      valid10_q <= valid9_q;
      valid11_q <= valid10_q;
    end
  end

  // ---------------------------------------------------------------------------------------------
  // Stages 12–13: alpha = chord((A − p1)·d), beta = chord(AB·d).
  // ---------------------------------------------------------------------------------------------
  wire [InvW-1:0] inv_m = inv11_q[InvW-1:0];
  wire [6:0]      inv_s = inv11_q[InvW+6:InvW];

  wire            alpha_valid;
  wire [TW-1:0]   alpha;
  wire            alpha_ovf;
  wire [ResW-1:0] res;
  rpu_chord #(
    .DotW (DotW),
    .InvW (InvW),
    .TFrac(TFrac),
    .ShW  (7),
    .TagW (ResW)
  ) u_alpha (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(valid11_q),
    .dot_i  (dot_a11_q),
    .inv_m_i(inv_m),
    .inv_s_i(inv_s),
    .tag_i  (res11_q),
    .valid_o(alpha_valid),
    .t_o    (alpha),
    .ovf_o  (alpha_ovf),
    .tag_o  (res)
  );

  wire          beta_valid;
  wire [TW-1:0] beta;
  wire          beta_ovf;
  wire          beta_tag;
  rpu_chord #(
    .DotW (DotW),
    .InvW (InvW),
    .TFrac(TFrac),
    .ShW  (7),
    .TagW (1)
  ) u_beta (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(valid11_q),
    .dot_i  (dot_b11_q),
    .inv_m_i(inv_m),
    .inv_s_i(inv_s),
    .tag_i  (1'b0),
    .valid_o(beta_valid),
    .t_o    (beta),
    .ovf_o  (beta_ovf),
    .tag_o  (beta_tag)
  );
  wire unused_beta = ^{beta_valid, beta_tag};  // same pipeline as u_alpha

  // res = {tag, tc, hc, pred1, ovf, A, B, AB}
  wire pred1_r = res[ResW-OutW];
  wire ovf_r   = res[ResW-OutW-1];

  assign valid_o      = alpha_valid;
  assign tag_o        = res[ResW-1 -: TagW];
  assign tc_o         = res[ResW-TagW-1 -: TcW];
  assign half_chord_o = res[ResW-TagW-TcW-1 -: HcW];
  assign pred1_o      = pred1_r;
  assign a_o          = res[3*DiffW+3*CW +: 3*CW];
  assign b_o          = res[3*DiffW +: 3*CW];
  assign ab_o         = res[0 +: 3*DiffW];
  assign alpha_o      = alpha;
  assign beta_o       = beta;
  assign ovf_o        = ovf_r | (pred1_r & (alpha_ovf | beta_ovf));
endmodule

`default_nettype wire
