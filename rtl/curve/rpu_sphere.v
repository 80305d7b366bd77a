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
// Pipeline (every product an rpu_mul, rpu_mul_latency.vh; one operand per cycle, no stall; the
// context rides in the multipliers' and the square root's tags, up to the root in a plain delay
// line where no logic reads it; `tag_i` comes out unchanged, a tag of 32 bits or more through
// an rpu_tag_queue beside the stages, whose tags then carry one constant bit):
//   1        q = c0 − h
//   L1       v̂_k·q_k, q_{k+1}·v̂_{k+2}, q_{k+2}·v̂_{k+1}   rpu_mul (CW+1) × (FV+2): 3 at the defaults
//   1        tc (a sum of three: carry-save + one adder), w = q × v̂ floored
//   L2       wt_k²                                      rpu_mul (CW+6)²: 4
//   1        |wt|² (carry-save + one adder)
//   1        disc = R² − perp2, the radicand
//   root     rpu_sqrt                                   27 at the defaults
//   1        tc, hc and the disc sign into flip-flops (the root's tag leaves a shift register)
//   1        t1, t2, pred1
//   L3       v̂_k·t1, v̂_k·t2                             rpu_mul (FV+2) × (CW+5): 4
//   1        A, B saturated
//   1        AB = B − A, A − p1
//   L4       (A − p1)_k·d_k, AB_k·d_k                     rpu_mul (CW+1)²: 3
//   1        the dot products (carry-save + one adder)
//   chord    two rpu_chord                              7
// Latency = root + 9 + L1 + L2 + L3 + L4 + chord cycles (57 at the defaults; ref::sphere_latency).
// No backpressure inside (rpu_top reserves room).
`default_nettype none
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_sphere #(
  parameter integer CoordW  = 24,  // signed width of positions, LSB (12..40)
  parameter integer DirFrac = 24,  // fraction bits of the ray direction v̂, Q(2.DirFrac) (8..40)
  parameter integer TFrac   = 24,  // fraction bits of alpha, beta, Q(3.TFrac) (8..48)
  parameter integer InvW    = 18,  // mantissa bits of 1/L², inv_m unsigned (8..40)
  parameter integer SqrtW   = 0,   // widest radicand of the square root; 0 = exact (16..126)
  parameter integer TagW    = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer DirW  = `RPU_VHATW(DirFrac),  // v̂: Q(2.DirFrac)
  parameter integer DiffW = `RPU_DW(CoordW),      // d, AB: differences of two positions
  parameter integer R2W   = `RPU_R2W(CoordW),  // R² (the compiler's R² < 2^(2CoordW))
  parameter integer TcW   = CoordW + 4,      // tc: |v̂·q| < 3·2^(CoordW+1) for any v̂, q
  parameter integer HcW   = `RPU_XW(CoordW),      // hc = isqrt of a (2CoordW+5)-bit radicand
  parameter integer TW    = `RPU_TW(TFrac)        // alpha, beta: Q(3.TFrac)
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
  localparam integer WDropW = FV - Guard;   // the fraction bits q × v̂ drops
  localparam integer WtW   = PvW + 1 - WDropW;  // q × v̂ floored to Q(.Guard) LSB, signed
  localparam integer WsqW  = 2 * WtW - 1;    // wt_k², unsigned
  localparam integer PsW   = WsqW + 2;       // |wt|², unsigned
  localparam integer PerpW = PsW - 2 * Guard;  // |wt|² floored to LSB²
  localparam integer DiscW = PsW - 2 * Guard + 1;  // R² − perp2, signed (R2W < PsW − 2Guard)
  localparam integer RadW  = 2 * CW + 5;     // the model's sphere_radicand_w()
  localparam integer TpW   = CW + 5;         // t1, t2: |.| < 12·2^CW, signed
  localparam integer PtW   = DirW + TpW;     // v̂_k·t, exact
  localparam integer EndW  = PtW - FV;      // h + floor(v̂·t): |.| < 2^(CW+5) + 2^(CW−1)
  localparam integer DotW  = 2 * DiffW + 2;  // (A − p1)·d and AB·d
  localparam integer SegW  = 3 * CW + 3 * DiffW + InvW + 7;  // {p1, d, inv_m, inv_s}
  // The square-root pipeline depth (rpu_sqrt's derived parameters).
  localparam integer SqShift  = (SqrtW == 0 || RadW <= SqrtW) ? 0 : (RadW - SqrtW + 1) / 2;
  localparam integer SqStages = (RadW - 2 * SqShift + 1) / 2;
  localparam [RadW-1:0] RadMax = {RadW{1'b1}};
`include "rpu_mul_latency.vh"
  localparam integer L1 = `RPU_MUL_LAT(DiffW, DirW, 1);
  localparam integer L2 = `RPU_MUL_LAT(WtW, WtW, 1);
  localparam integer L3 = `RPU_MUL_LAT(DirW, TpW, 1);
  localparam integer L4 = `RPU_MUL_LAT(DiffW, DiffW, 1);
  localparam integer LCh = `RPU_MUL_LAT(InvW + 1, DotW, 1) + 3;  // rpu_chord's
  // The unit's latency (what the enclosing units count on).
  localparam integer Latency = SqStages + 9 + L1 + L2 + L3 + L4 + LCh;
  // The caller's tag: a wide one waits in a queue (rpu_tag_queue), the stages carry PTagW bits.
  localparam integer PTagW = `RPU_PTAGW(TagW);

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_sphere: CoordW must be in 12..40");
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_sphere: DirFrac must be in 8..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_sphere: TFrac must be in 8..48");
    if (InvW < 8 || InvW > 40) $fatal(1, "rpu_sphere: InvW must be in 8..40");
    if (SqrtW != 0 && (SqrtW < 16 || SqrtW > 126))
      $fatal(1, "rpu_sphere: SqrtW must be 0 or 16..126");
    if (TagW < 1) $fatal(1, "rpu_sphere: TagW must be >= 1");
    if (DirW != `RPU_VHATW(DirFrac) || DiffW != `RPU_DW(CoordW) || R2W != `RPU_R2W(CoordW) ||
        TcW != CoordW + 4 || HcW != `RPU_XW(CoordW) || TW != `RPU_TW(TFrac))
      $fatal(1, "rpu_sphere: derived parameters must not be overridden");
    if (SqStages < 1) $fatal(1, "rpu_sphere: bad square-root depth");
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

  // R² rides in the products' tags to stage 6; the rest of the context {tag, seg, v̂, h}, which
  // no logic reads before the square root, in a plain delay line (shift-register LUTs) of
  // L1 + L2 + 4 stages from the inputs to the root's tag.
  localparam integer C1W = R2W;
  localparam integer DcW = PTagW + SegW + 3 * DirW + 3 * CW;
  wire [PTagW-1:0] ptag_in, ptag_out;
  rpu_tag_queue #(.TagW(TagW), .Latency(Latency)) u_tagq (
    .clk_i, .rst_ni, .valid_i, .tag_i, .ptag_o(ptag_in), .out_valid_i(valid_o), .ptag_i(ptag_out),
    .tag_o);
  localparam integer Dc  = L1 + L2 + 4;
  reg [Dc*DcW-1:0] dc_q;
  always @(posedge clk_i) dc_q <= {dc_q[(Dc-1)*DcW-1:0], ptag_in, p1_i, d_i, inv_m_i, inv_s_i, vhat_i, eye_i};
  wire [DcW-1:0] dc_out = dc_q[Dc*DcW-1 -: DcW];
  reg [3*DiffW-1:0] q1_q;
  reg [3*DirW-1:0]  v1_q;
  reg [C1W-1:0]     c1_q;
  reg               valid1_q;
  always @(posedge clk_i) begin
    q1_q <= q;
    v1_q <= vhat_i;
    c1_q <= r2_i;
  end

  // ---------------------------------------------------------------------------------------------
  // The products v̂_k·q_k and the cross-product terms q_{k+1}·v̂_{k+2}, q_{k+2}·v̂_{k+1} (exact).
  // ---------------------------------------------------------------------------------------------
  wire [3*PvW-1:0] pv;
  wire [3*PvW-1:0] pca;
  wire [3*PvW-1:0] pcb;
  wire             m1_valid;
  wire [C1W-1:0]   c2;
  wire [3*DiffW-1:0] qa1, qb1;  // q rotated: {q_{k+1}}, {q_{k+2}}
  wire [3*DirW-1:0]  va1, vb1;  // v̂ rotated: {v̂_{k+2}}, {v̂_{k+1}}
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_rot
      assign qa1[k*DiffW +: DiffW] = q1_q[((k+1)%3)*DiffW +: DiffW];
      assign qb1[k*DiffW +: DiffW] = q1_q[((k+2)%3)*DiffW +: DiffW];
      assign va1[k*DirW +: DirW]   = v1_q[((k+2)%3)*DirW +: DirW];
      assign vb1[k*DirW +: DirW]   = v1_q[((k+1)%3)*DirW +: DirW];
    end
  endgenerate
  rpu_mul_vec #(.Count(9), .AW(DiffW), .BW(DirW), .Signed(1), .TagW(C1W)) u_pv (
    .clk_i, .rst_ni, .valid_i(valid1_q), .a_i({qb1, qa1, q1_q}), .b_i({vb1, va1, v1_q}),
    .tag_i(c1_q), .valid_o(m1_valid), .p_o({pcb, pca, pv}), .tag_o(c2));

  // ---------------------------------------------------------------------------------------------
  // Stage 3: tc = floor(v̂·q · 2^-FV) (the sum cannot wrap in VqW bits; one carry-save step and
  // one adder); the cross product w = q × v̂ (exact), each component floored to Guard fraction
  // bits of an LSB.
  // ---------------------------------------------------------------------------------------------
  wire [VqW-1:0] pv_x = {{(VqW-PvW){pv[1*PvW-1]}}, pv[0*PvW +: PvW]};
  wire [VqW-1:0] pv_y = {{(VqW-PvW){pv[2*PvW-1]}}, pv[1*PvW +: PvW]};
  wire [VqW-1:0] pv_z = {{(VqW-PvW){pv[3*PvW-1]}}, pv[2*PvW +: PvW]};
  wire [VqW-1:0] vq;
  rpu_add3 #(.W(VqW)) u_vq (.a_i(pv_x), .b_i(pv_y), .c_i(pv_z), .s_o(vq));
  wire [TcW-1:0] tc   = vq[VqW-1:FV];  // arithmetic shift right by FV (floor)
  wire unused_vq = ^vq[FV-1:0];
  wire [3*WtW-1:0] wt;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_w
      wire signed [PvW-1:0] a = pca[k*PvW +: PvW];
      wire signed [PvW-1:0] b = pcb[k*PvW +: PvW];
      wire signed [PvW:0]   w = {a[PvW-1], a} - {b[PvW-1], b};
      assign wt[k*WtW +: WtW] = w[PvW:WDropW];  // floor(w · 2^-(FV−Guard))
      wire unused_w = ^w[WDropW-1:0];
    end
  endgenerate

  reg [3*WtW-1:0]  wt3_q;
  reg [TcW+C1W-1:0] c3_q;
  reg              valid3_q;
  always @(posedge clk_i) begin
    wt3_q <= wt;
    c3_q  <= {c2, tc};
  end

  // ---------------------------------------------------------------------------------------------
  // The squares wt_k² (exact, non-negative).
  // ---------------------------------------------------------------------------------------------
  localparam integer C4W = TcW + C1W;
  wire [3*WsqW-1:0] wsq;
  wire              m2_valid;
  wire [C4W-1:0]    c4;
  wire [6*WtW-1:0] sq2;
  rpu_mul_vec #(.Count(3), .AW(WtW), .BW(WtW), .Signed(1), .TagW(C4W)) u_sq (
    .clk_i, .rst_ni, .valid_i(valid3_q), .a_i(wt3_q), .b_i(wt3_q), .tag_i(c3_q),
    .valid_o(m2_valid), .p_o(sq2), .tag_o(c4));
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_wsq
      wire [2*WtW-1:0] sq = sq2[k*2*WtW +: 2*WtW];
      // |wt_k| <= 2^(WtW−1), so wt_k² <= 2^(2WtW−2) < 2^WsqW: the top bit is zero.
      assign wsq[k*WsqW +: WsqW] = sq[WsqW-1:0];
      wire unused_sq = sq[2*WtW-1];
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Stage 5: perp2 = floor(|wt|² · 2^-2Guard) (the squared distance of c0 from the ray, LSB²;
  // one carry-save step and one adder, exact: the sum fits PsW bits).
  // ---------------------------------------------------------------------------------------------
  wire [PsW-1:0] sq_x = {2'b00, wsq[0*WsqW +: WsqW]};
  wire [PsW-1:0] sq_y = {2'b00, wsq[1*WsqW +: WsqW]};
  wire [PsW-1:0] sq_z = {2'b00, wsq[2*WsqW +: WsqW]};
  wire [PsW-1:0] wsum;
  rpu_add3 #(.W(PsW)) u_ws (.a_i(sq_x), .b_i(sq_y), .c_i(sq_z), .s_o(wsum));
  wire unused_wsum = ^wsum[2*Guard-1:0];

  reg [PerpW-1:0]       perp5_q;
  reg [C4W-1:0]         c5_q;
  reg                   valid5_q;
  always @(posedge clk_i) begin
    perp5_q <= wsum[PsW-1:2*Guard];
    c5_q    <= c4;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 6: disc = R² − perp2; the radicand: 0 when disc < 0 (no root taken: hc = 0 as in the
  // model), saturated to RadW bits and flagged when wider (fixed::saturate_unsigned; disc <= R²
  // never is, but the flag mirrors the model's rule rather than relying on that bound).
  // ---------------------------------------------------------------------------------------------
  // c5 = {R², tc}
  wire [TcW-1:0]    tc5   = c5_q[0 +: TcW];
  wire [R2W-1:0]    r2_5  = c5_q[TcW +: R2W];
  wire signed [DiscW-1:0] disc = {{(DiscW-R2W){1'b0}}, r2_5} -
                                 {{(DiscW-(PsW-2*Guard)){1'b0}}, perp5_q};
  wire disc_neg = disc[DiscW-1];
  wire disc_big = ~disc_neg & (|disc[DiscW-2:RadW]);  // disc >= 2^RadW
  wire [RadW-1:0] rad = disc_neg ? {RadW{1'b0}} : disc_big ? RadMax : disc[RadW-1:0];

  reg [RadW-1:0]   rad6_q;
  reg              neg6_q;
  reg              sovf6_q;
  reg [TcW-1:0]    tc6_q;
  reg              valid6_q;
  always @(posedge clk_i) begin
    rad6_q  <= rad;
    neg6_q  <= disc_neg;
    sovf6_q <= disc_big;
    tc6_q   <= tc5;
  end
  // dc = {tag, seg, v̂, h}, aligned with stage 6's registers.
  wire [3*CW-1:0]   h6_q   = dc_out[0 +: 3*CW];
  wire [3*DirW-1:0] v6_q   = dc_out[3*CW +: 3*DirW];
  wire [SegW-1:0]   seg6_q = dc_out[3*CW+3*DirW +: SegW];
  wire [PTagW-1:0]  tag6_q = dc_out[DcW-1 -: PTagW];

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid1_q <= 1'b0;
      valid3_q <= 1'b0;
      valid5_q <= 1'b0;
      valid6_q <= 1'b0;
    end else begin
      valid1_q <= valid_i;
      valid3_q <= m1_valid;
      valid5_q <= m2_valid;
      valid6_q <= valid5_q;
    end
  end

  // ---------------------------------------------------------------------------------------------
  // The square root; the context rides in its tag.
  // ---------------------------------------------------------------------------------------------
  localparam integer CtxW   = PTagW + SegW + 3 * DirW + 3 * CW + 1;  // {tag, seg, v̂, h, sovf}
  localparam integer SqTagW = CtxW + TcW + 1;
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
    .valid_i(valid6_q),
    .rad_i  (rad6_q),
    .tag_i  ({tag6_q, seg6_q, v6_q, h6_q, sovf6_q, tc6_q, neg6_q}),
    .valid_o(sq_valid),
    .root_o (sq_root),
    .tag_o  (sq_tag)
  );

  // ---------------------------------------------------------------------------------------------
  // Stage 7: tc, hc and the disc sign into flip-flops (the root's tag leaves a shift register);
  // the rest of the context follows two plain stages behind.
  // ---------------------------------------------------------------------------------------------
  reg [HcW-1:0]  hc7_q;
  reg [TcW-1:0]  tc7_q;
  reg            neg7_q;
  reg [CtxW-1:0] ctx7_q;
  reg            valid7_q;
  // Loaded only with a valid operand: a clock enable the square root's registers do not have, so
  // Yosys cannot pack these into the shift registers before them.
  always @(posedge clk_i) begin
    if (sq_valid) begin
      hc7_q  <= sq_root;
      tc7_q  <= sq_tag[1 +: TcW];
      neg7_q <= sq_tag[0];
    end
    ctx7_q <= sq_tag[SqTagW-1 -: CtxW];
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 8: t2 = tc + hc, t1 = max(0, tc − hc), pred1 = disc >= 0 ∧ t2 > 0.
  // ---------------------------------------------------------------------------------------------
  wire signed [TpW-1:0] tc_w = {{(TpW-TcW){tc7_q[TcW-1]}}, tc7_q};
  wire signed [TpW-1:0] hc_w = {{(TpW-HcW){1'b0}}, hc7_q};
  wire signed [TpW-1:0] t2   = tc_w + hc_w;
  wire signed [TpW-1:0] t1d  = tc_w - hc_w;
  wire [TpW-1:0]        t1   = t1d[TpW-1] ? {TpW{1'b0}} : t1d;
  wire                  pred1 = ~neg7_q & ~t2[TpW-1] & (|t2);

  // The outputs that ride along to the end: {tag, tc, hc, pred1}.
  localparam integer OutW = PTagW + TcW + HcW + 1;

  reg [TpW-1:0]    t1_8_q;
  reg [TpW-1:0]    t2_8_q;
  reg [3*DirW-1:0] v8_q;
  reg [3*CW-1:0]   h8_q;
  reg              sovf8_q;
  reg [OutW-1:0]   out8_q;
  reg [SegW-1:0]   seg8_q;
  reg              valid8_q;
  // ctx7 = {tag, seg, v̂, h, sovf}
  always @(posedge clk_i) begin
    t1_8_q  <= t1;
    t2_8_q  <= t2;
    v8_q    <= ctx7_q[1+3*CW +: 3*DirW];
    h8_q    <= ctx7_q[1 +: 3*CW];
    sovf8_q <= ctx7_q[0];
    out8_q  <= {ctx7_q[CtxW-1 -: PTagW], tc7_q, hc7_q, pred1};
    seg8_q  <= ctx7_q[1+3*CW+3*DirW +: SegW];
  end

  // ---------------------------------------------------------------------------------------------
  // The products v̂_k·t1, v̂_k·t2 (exact).
  // ---------------------------------------------------------------------------------------------
  localparam integer C9W = SegW + OutW + 1 + 3 * CW;  // {seg, out, sovf, h}
  wire [3*PtW-1:0] pa;
  wire [3*PtW-1:0] pb;
  wire             m3_valid;
  wire [C9W-1:0]   c9;
  rpu_mul_vec #(.Count(6), .AW(DirW), .BW(TpW), .Signed(1), .TagW(C9W)) u_pt (
    .clk_i, .rst_ni, .valid_i(valid8_q), .a_i({v8_q, v8_q}), .b_i({{3{t2_8_q}}, {3{t1_8_q}}}),
    .tag_i({seg8_q, out8_q, sovf8_q, h8_q}), .valid_o(m3_valid), .p_o({pb, pa}), .tag_o(c9));
  wire [3*CW-1:0] h9    = c9[0 +: 3*CW];
  wire            sovf9 = c9[3*CW];
  wire [OutW-1:0] out9  = c9[3*CW+1 +: OutW];
  wire [SegW-1:0] seg9  = c9[C9W-1 -: SegW];

  // ---------------------------------------------------------------------------------------------
  // Stage 10: A = sat(h + floor(v̂·t1 · 2^-FV)), B likewise, to CW bits (flagged under pred1 in
  // stage 11).
  // ---------------------------------------------------------------------------------------------
  wire [3*CW-1:0] a_sat;
  wire [3*CW-1:0] b_sat;
  wire [5:0]      clamped;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_end
      wire signed [PtW-1:0]  pak = pa[k*PtW +: PtW];
      wire signed [PtW-1:0]  pbk = pb[k*PtW +: PtW];
      wire signed [CW-1:0]   hk  = h9[k*CW +: CW];
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

  reg [3*CW-1:0] a10_q;
  reg [3*CW-1:0] b10_q;
  reg [5:0]      clamped10_q;
  reg            sovf10_q;
  reg [OutW-1:0] out10_q;
  reg [SegW-1:0] seg10_q;
  reg            valid10_q;
  always @(posedge clk_i) begin
    a10_q   <= a_sat;
    b10_q   <= b_sat;
    clamped10_q <= clamped;
    sovf10_q    <= sovf9;
    out10_q <= out9;
    seg10_q <= seg9;
  end

  // ---------------------------------------------------------------------------------------------
  // Stage 11: AB = B − A, A − p1 (exact, DiffW bits); the overflow flag.
  // ---------------------------------------------------------------------------------------------
  // seg = {p1, d, inv_m, inv_s}
  wire [3*CW-1:0]    p1_10  = seg10_q[SegW-1 -: 3*CW];
  wire [3*DiffW-1:0] d_10   = seg10_q[InvW+7 +: 3*DiffW];
  wire [InvW+6:0]    inv_10 = seg10_q[0 +: InvW+7];
  wire [3*DiffW-1:0] ab;
  wire [3*DiffW-1:0] ap;
  generate
    for (k = 0; k < 3; k = k + 1) begin : g_ab
      wire signed [DiffW-1:0] ak = {a10_q[k*CW+CW-1], a10_q[k*CW +: CW]};
      wire signed [DiffW-1:0] bk = {b10_q[k*CW+CW-1], b10_q[k*CW +: CW]};
      wire signed [DiffW-1:0] pk = {p1_10[k*CW+CW-1], p1_10[k*CW +: CW]};
      assign ab[k*DiffW +: DiffW] = bk - ak;
      assign ap[k*DiffW +: DiffW] = ak - pk;
    end
  endgenerate

  // Everything the outputs need besides alpha and beta, then {inv_m, inv_s}.
  localparam integer ResW = OutW + 1 + 6 * CW + 3 * DiffW;  // {out, ovf, A, B, AB}
  // res = {tag, tc, hc, pred1, ovf, A, B, AB}: the offsets of tc and hc from the LSB.
  localparam integer ResHcO = ResW - OutW + 1;
  localparam integer ResTcO = ResHcO + HcW;
  reg [3*DiffW-1:0] ab11_q;
  reg [3*DiffW-1:0] ap11_q;
  reg [3*DiffW-1:0] d11_q;
  reg [ResW+InvW+6:0] res11_q;
  reg               valid11_q;
  always @(posedge clk_i) begin
    ab11_q  <= ab;
    ap11_q  <= ap;
    d11_q   <= d_10;
    res11_q <= {out10_q, sovf10_q | (out10_q[0] & (|clamped10_q)), a10_q, b10_q, ab, inv_10};
  end

  // ---------------------------------------------------------------------------------------------
  // The products (A − p1)_k·d_k and AB_k·d_k (exact).
  // ---------------------------------------------------------------------------------------------
  localparam integer PdW = 2 * DiffW;
  wire [3*PdW-1:0]     prod_a;
  wire [3*PdW-1:0]     prod_b;
  wire                 m4_valid;
  wire [ResW+InvW+6:0] res12;
  rpu_mul_vec #(.Count(6), .AW(DiffW), .BW(DiffW), .Signed(1), .TagW(ResW + InvW + 7)) u_dp (
    .clk_i, .rst_ni, .valid_i(valid11_q), .a_i({ab11_q, ap11_q}), .b_i({d11_q, d11_q}),
    .tag_i(res11_q), .valid_o(m4_valid), .p_o({prod_b, prod_a}), .tag_o(res12));

  // ---------------------------------------------------------------------------------------------
  // Stage 13: the dot products (sums of three exact products, DotW bits: one carry-save step
  // and one adder, exact).
  // ---------------------------------------------------------------------------------------------
  wire [DotW-1:0] pa_x = {{2{prod_a[1*PdW-1]}}, prod_a[0*PdW +: PdW]};
  wire [DotW-1:0] pa_y = {{2{prod_a[2*PdW-1]}}, prod_a[1*PdW +: PdW]};
  wire [DotW-1:0] pa_z = {{2{prod_a[3*PdW-1]}}, prod_a[2*PdW +: PdW]};
  wire [DotW-1:0] pb_x = {{2{prod_b[1*PdW-1]}}, prod_b[0*PdW +: PdW]};
  wire [DotW-1:0] pb_y = {{2{prod_b[2*PdW-1]}}, prod_b[1*PdW +: PdW]};
  wire [DotW-1:0] pb_z = {{2{prod_b[3*PdW-1]}}, prod_b[2*PdW +: PdW]};
  wire [DotW-1:0] dot_a, dot_b;
  rpu_add3 #(.W(DotW)) u_dot_a (.a_i(pa_x), .b_i(pa_y), .c_i(pa_z), .s_o(dot_a));
  rpu_add3 #(.W(DotW)) u_dot_b (.a_i(pb_x), .b_i(pb_y), .c_i(pb_z), .s_o(dot_b));

  reg [DotW-1:0] dot_a13_q;
  reg [DotW-1:0] dot_b13_q;
  reg [ResW-1:0] res13_q;
  reg [InvW+6:0] inv13_q;
  reg            valid13_q;
  always @(posedge clk_i) begin
    dot_a13_q <= dot_a;
    dot_b13_q <= dot_b;
    res13_q   <= res12[ResW+InvW+6 -: ResW];
    inv13_q   <= res12[InvW+6:0];
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid7_q  <= 1'b0;
      valid8_q  <= 1'b0;
      valid10_q <= 1'b0;
      valid11_q <= 1'b0;
      valid13_q <= 1'b0;
    end else begin
      valid7_q  <= sq_valid;
      valid8_q  <= valid7_q;
      valid10_q <= m3_valid;
      valid11_q <= valid10_q;
      valid13_q <= m4_valid;
    end
  end

  // ---------------------------------------------------------------------------------------------
  // alpha = chord((A − p1)·d), beta = chord(AB·d).
  // ---------------------------------------------------------------------------------------------
  wire [InvW-1:0] inv_m = inv13_q[InvW+6:7];
  wire [6:0]      inv_s = inv13_q[6:0];

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
    .valid_i(valid13_q),
    .dot_i  (dot_a13_q),
    .inv_m_i(inv_m),
    .inv_s_i(inv_s),
    .tag_i  (res13_q),
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
    .valid_i(valid13_q),
    .dot_i  (dot_b13_q),
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
  assign ptag_out     = res[ResW-1 -: PTagW];
  assign tc_o         = res[ResTcO +: TcW];
  assign half_chord_o = res[ResHcO +: HcW];
  assign pred1_o      = pred1_r;
  assign a_o          = res[3*DiffW+3*CW +: 3*CW];
  assign b_o          = res[3*DiffW +: 3*CW];
  assign ab_o         = res[0 +: 3*DiffW];
  assign alpha_o      = alpha;
  assign beta_o       = beta;
  assign ovf_o        = ovf_r | (pred1_r & (alpha_ovf | beta_ovf));
  `RPU_LATENCY_CHECK(Latency, "rpu_sphere")
endmodule

`default_nettype wire
