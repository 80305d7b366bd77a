// rpu_indicator: the inside bit of one point in a surface's local frame, for every primitive type,
// twin of `rpu::ref::indicator_unit(params, surface, l, x_negative, last_turn, ovf, trace)`
// (ref/model/surface/rpu_indicator.h; the indicators: docs/surfaces.md; formats: docs/fixed-point.md,
// "Surfaces"). One configurable unit: the descriptor's type selects the primitive per point, so
// one pipeline serves a scene that mixes them; the spiral's and snail's turns m = 0 .. Lanes−1
// are parallel lanes. Every type takes the same number of cycles (the longest, the relief's).
//
// Ports (LW = SurfW, AW = AngleW, KF = LW, MW = LW + 2, CorW = LW + 6 the CORDIC width):
//   l_i           the point {z, y, x}, llsb, LW bits signed each
//   x_negative_i, last_turn_i   the piece's azimuth branch (spiral, snail; unused otherwise)
//   desc_i        the SurfaceDesc's indicator fields as one word (rpu_surface_desc.vh, DescW =
//                 15·LW + 61 bits); a type does not read the fields it has no use for:
//     type        SurfaceType: 0 ellipsoid, 1 relief ellipsoid, 2 spiral, 3 snail, 4 rocket
//                 (5..7: inside 0, every output 0)
//     full_turns  4 bits                       sx, sy, sz   Q(1.KF), KF+1 bits unsigned
//     r2          2LW+1 bits unsigned, ≤ 2^(2LW) (the descriptor's round(m·2^(F+G))² with
//                 m·2^F ≤ 2^(LW−2): its local box fills at most a quarter of the LW range)
//     kd, ke2     Q(1.KF), KF+2 bits signed    rho0, rocket_a, rocket_b   llsb, LW signed
//     a_turn, k_turn   llsb per turn, LW+8 bits signed
//     y_angle, fin, cone   ScaledConst m · 2^-s: m MW bits signed, s 8 bits unsigned (s ≥ 0)
// Contract beyond the port widths: r2 ≤ 2^(2LW) and full_turns + last_turn ≤ Lanes. Within it the
// outputs equal the twin's for every port value.
// Outputs: inside_o; turn_inside_o (spiral, snail: the enabled lanes whose turn holds the point,
// the trace's turn_inside); angle_o (ψ, or the relief's φ; 0 for the ellipsoid) and rho_o (ρ for
// the spiral, snail and rocket; else 0), the trace's angle and rho; ovf_o, the sticky overflow
// bit the twin sets (a CORDIC input saturated: the spiral's first-turn offset with turn 0 enabled,
// its per-turn step with turn 1 enabled, the rocket's fin term).
//
// Latency = 1 + LF + Tv + LT + 3 + Tr + LB cycles (ref::indicator_latency; 75 at the defaults),
//   LF = the front products, Tv / Tr = rpu_cordic's vectoring / rotation latency, LT = ψ·a_turn,
//   LB = the back end after the rotation (the longest type's, every type padded to it).
// One point per cycle, no stall; `tag_i` comes out unchanged with the result.
//
// Pipeline (every product an rpu_mul; every stage at most one wide carry chain, three-term sums as
// one carry-save step and an adder, rpu_add3; every stage register an rpu_stage; context in the
// units' tags and in rpu_delay lines):
//   E1       inputs registered; the rocket's region (y ≤ 0 fins, y > b cone, else cylinder); the
//            constant product's operand y or y − b, mantissa and shift (relief: y_angle; rocket:
//            fin or cone), the shift clamped to PW − 1; lane enables m < full_turns + last_turn
//   LF       x·sx, y·sy, z·sz and the constant product P (exact; padded to the slowest)
//   Tv       rpu_cordic vectoring of (z·sz, x·sx) (relief) or (z, x): φ or ψ, ρ
//   LT       ψ_u·a_turn, ψ_u·k_turn (ψ unwrapped on the piece's branch: two bits, no adder)
//   T1       spiral: D0 = ρ − rho0 − r0, E0 = y − y0 (r0, y0 the products ≫ AW); P ≫ 8·(s ≫ 3)
//   T2       the fine shift P ≫ (s mod 8); D0, E0 and the spiral's step (a_turn, k_turn) on
//   T3       the CORDIC inputs saturated to CorW − 1 bits; the rotation angles 4ψ (spiral),
//            10φ ± 9y (relief: rotations of (ke2, 0)), 5ψ (rocket: a rotation of (Y, 0)); Y
//            saturated to CorW + 1 bits (exact for ρ < r, see below)
//   Tr       two rpu_cordic rotations: 0 takes the spiral's (D0, E0), the relief's 10φ + 9y and
//            the rocket; 1 the spiral's step (a_turn, k_turn) and the relief's 10φ − 9y. The
//            section rotation is linear and its angle 4φ_m ≡ 4ψ is the same in every turn, so
//            turn m's rotated offset is rotation 0 − m·rotation 1, and no lane has a CORDIC.
//   back end, in parallel:
//     spiral   the two rotations scaled by (sx, sy) (4 products, exact); lane m: the first's
//              minus m times the second (m·X as at most two shifted terms: 3 = 2 + 1, 5 = 4 + 1,
//              6 = 4 + 2, 7 = 8 − 1), ≫ (KF − G); each clamped (|·| ≥ 2^LW: outside, as
//              r2 ≤ 2^(2LW)); squared; r2 − 1 − A² − B² ≥ 0
//     snail    (ρ − R_m)² − r_m² = (ρ − G_m)(ρ − G_{m+1}) with G_j = R_j − r_j = j·h_{j−1},
//              h_j = 2r0 + j·a_turn (the turns' inner and outer edges), exact. Inside ⇔ the
//              factors P_m, P_{m+1} have opposite signs and |P_m|·|P_{m+1}| > y². The smaller
//              factor is capped at 2^LW − 1 (at ≥ 2^(LW−1) + 1 the product beats y² ≤ 2^(2LW−2)
//              anyway), so the product is LW × (LW+15) bits.
//     relief   k' = kd + y1 + y2; floor(k'²·2^-KF)·s²m² ≫ KF against (x·sx)² + (z·sz)², where
//              s²m² = r2 − (y·sy)² > 0 (|y·sy| ≥ 2^LW: outside, as r2 ≤ 2^(2LW))
//     ellipsoid r2 − 1 − (x·sx)² − (y·sy)² − (z·sz)² ≥ 0
//     rocket   r = a − Y + (fins ? (rotation of (Y, 0) by 5ψ).y : 0) (Y = 0 on the cylinder,
//              the cone's (y − b)·cone on the cone); ρ < r
//   output   the type's bit, lanes, angle, ρ, overflow; registered
//
// Y = floor(y·m·2^-s) is exact in PW bits; the unit keeps it saturated to CorW + 1 bits. That
// leaves ρ < r unchanged: with |Y| ≥ 2^CorW − 1, r is below 0 (Y > 0) or above 2^(CorW−1) > ρ
// (Y < 0) either way, since |a| < 2^(LW−1) and the rotated fin term is at most 2^(CorW−2)·(1 + ε).
`default_nettype none
`include "rpu_widths.vh"

module rpu_indicator #(
  parameter integer SurfW  = 24,  // LW: signed width of surface-local coordinates (16..36)
  parameter integer AngleW = 20,  // AW: binary-angle bits, 2^AW = one turn (12..32, <= LW + 10)
  parameter integer Lanes  = 8,   // spiral / snail turn lanes (2..8)
  parameter integer TagW   = 1,   // side-band bits carried with each point (>= 1)
  // Derived (do not override).
  parameter integer KF     = SurfW,          // fraction bits of the Q(1.KF) constants
  parameter integer MW     = SurfW + 2,      // mantissa bits of the ScaledConst constants
  parameter integer TurnW  = SurfW + 8,      // a_turn, k_turn
  parameter integer CorW   = SurfW + 6,      // the CORDIC width LW + G + 4 (rho_o)
  parameter integer R2W    = 2 * SurfW + 1,  // r2, unsigned
  parameter integer DescW  = `RPU_SDW(SurfW) // the descriptor word (rpu_surface_desc.vh)
) (
  input  wire                 clk_i,
  input  wire                 rst_ni,
  input  wire                 valid_i,
  input  wire [3*SurfW-1:0]   l_i,
  input  wire                 x_negative_i,
  input  wire                 last_turn_i,
  input  wire [DescW-1:0]     desc_i,
  input  wire [TagW-1:0]      tag_i,
  output wire                 valid_o,
  output wire                 inside_o,
  output wire [Lanes-1:0]     turn_inside_o,
  output wire [AngleW-1:0]    angle_o,
  output wire [CorW-1:0]      rho_o,
  output wire                 ovf_o,
  output wire [TagW-1:0]      tag_o
);
`include "rpu_mul_latency.vh"
`include "rpu_surface_desc.vh"
  localparam integer LW   = SurfW;
  localparam integer AW   = AngleW;
  localparam integer G    = 2;             // guard bits of the scaled coordinates (kSurfGuard)
  localparam integer KfDropW = KF - G;     // fraction bits a scaled coordinate x·s drops
  localparam integer XSW  = LW + 3;        // x·sx ≫ (KF − G): |·| ≤ 2^(LW+2)
  localparam integer OPW  = LW + 1;        // the constant product's operand: y or y − b
  localparam integer PW   = OPW + MW;      // the constant product P, exact
  localparam integer SCW  = $clog2(PW);    // its shift, clamped to PW − 1
  localparam integer YW   = CorW + 1;      // Y = P ≫ s, saturated (rocket)
  localparam integer PSW  = AW + 2;        // ψ unwrapped: [−¼, 1¼) turn
  localparam integer R0W  = TurnW + 2;     // r0 = ψ_u·a_turn ≫ AW, y0 = ψ_u·k_turn ≫ AW
  localparam integer SPW  = TurnW + 4;     // spiral lane offsets ρ − ρ_a, y − y_a (< 2^(TurnW+3))
  localparam integer HW   = TurnW + 4;     // snail h_j = 2r0 + j·a_turn (< 2^(TurnW+3))
  localparam integer PJW  = TurnW + 8;     // snail P_j = ρ − j·h_{j−1} (< 2^(TurnW+7))
  localparam integer HIW  = PJW - 1;       // |P_j|
  localparam integer XsHiW  = XSW - LW;     // x·sx's bits from LW up
  localparam integer KpW  = CorW + 2;      // relief k' = kd + y1 + y2 (|k'| < 2^(CorW+1))
  localparam integer K2W  = 2 * KpW - 2 - KF;  // floor(k'²·2^-KF)
  localparam integer D2W  = 2 * LW + 1;    // s²m² = r2 − (y·sy)², 0 < · ≤ 2^(2LW) where used
  localparam integer RHW  = K2W + D2W - KF;   // the relief's right-hand side
  localparam integer LHW  = 2 * XSW;      // (x·sx)² + (z·sz)² < 2^(2LW+5)
  localparam integer SQW  = 2 * LW + 1;    // a clamped square: ≤ 2^(2LW)
  localparam integer RW   = YW + 2;        // the rocket's radius r
  localparam integer RotN = 2;             // rotation CORDICs

  initial begin
    if (SurfW < 16 || SurfW > 36) $fatal(1, "rpu_indicator: SurfW must be in 16..36");
    if (AngleW < 12 || AngleW > 32) $fatal(1, "rpu_indicator: AngleW must be in 12..32");
    if (AngleW > SurfW + 10)
      $fatal(1, "rpu_indicator: AngleW must be <= SurfW + 10 (CORDIC stages <= its width + 4)");
    if (Lanes < 2 || Lanes > 8) $fatal(1, "rpu_indicator: Lanes must be in 2..8");
    if (TagW < 1) $fatal(1, "rpu_indicator: TagW must be >= 1");
    if (KF != SurfW || MW != SurfW + 2 || TurnW != SurfW + 8 || CorW != SurfW + 6 ||
        R2W != 2 * SurfW + 1 || DescW != SdW)
      $fatal(1, "rpu_indicator: derived parameters must not be overridden");
  end

  // ---- latencies of the products (rpu_mul_latency.vh) ----
  localparam integer LSx  = `RPU_MUL_LAT(LW, KF + 2, 1);   // x·sx
  localparam integer LCp  = `RPU_MUL_LAT(OPW, MW, 1);      // y·m
  localparam integer LF   = LSx > LCp ? LSx : LCp;
  localparam integer LSc  = `RPU_MUL_LAT(CorW, KF + 2, 1); // spiral u·sx
  localparam integer LQ   = `RPU_MUL_LAT(LW + 1, LW + 1, 1);  // clamped squares
  localparam integer LX   = `RPU_MUL_LAT(XSW, XSW, 1);     // (x·sx)²
  localparam integer LXY  = LX > 1 + LQ ? LX : 1 + LQ;                 // all three squares
  localparam integer LK   = `RPU_MUL_LAT(KpW, KpW, 1);     // k'²
  localparam integer LKD  = `RPU_MUL_LAT(K2W, D2W, 0);     // k2·s²m²
  localparam integer LN   = `RPU_MUL_LAT(LW, HIW, 0);      // snail |P|·|P|
  // The back end, in cycles after the rotations (the registered bit of each type):
  localparam integer BSp  = LSc + LQ + 3;  // spiral
  localparam integer BEl  = LXY + 2;       // ellipsoid
  localparam integer BSn  = LN + 5;        // snail
  localparam integer BRo  = 2;             // rocket
  localparam integer TKD  = 1 + LK > LXY + 1 ? 1 + LK : LXY + 1;  // the relief's k2·s²m² starts
  localparam integer BRe  = TKD + LKD;     // relief: rhs ready (the compare is the output stage)
  localparam integer BM1  = BSp > BEl ? BSp : BEl;
  localparam integer BM2  = BSn > BRo ? BSn : BRo;
  localparam integer BM3  = BM1 > BM2 ? BM1 : BM2;
  localparam integer BLast = BM3 > BRe ? BM3 : BRe;  // the last registered bit
  localparam integer LB   = BLast + 1;     // the output register
  // The unit's latency without the two CORDICs (ref::indicator_latency adds them).
  localparam integer LatencyOwn = 1 + LF + `RPU_MUL_LAT(PSW, TurnW, 1) + 3 + LB;

  // m·X = X·2^T1S(m) ± X·2^T2S(m), m = 1..8 (1, 2, 2 + 1, 4, 4 + 1, 4 + 2, 8 − 1, 8).
  function integer t1_shift(input integer k);
    t1_shift = k >= 7 ? 3 : k >= 4 ? 2 : k >= 2 ? 1 : 0;
  endfunction
  function integer t2_used(input integer k);
    t2_used = (k == 3 || k == 5 || k == 6 || k == 7) ? 1 : 0;
  endfunction
  function integer t2_shift(input integer k);
    t2_shift = k == 6 ? 1 : 0;
  endfunction
  function integer t2_neg(input integer k);
    t2_neg = k == 7 ? 1 : 0;
  endfunction

  genvar m;

  // ===============================================================================================
  // E1: inputs registered; the constant product's operand; the rocket's region; lane enables.
  // ===============================================================================================
  // The descriptor's fields (rpu_surface_desc.vh; formats in the header above).
  wire [2:0] sd_type = desc_i[SdTypeO +: 3];
  wire [3:0] sd_full_turns = desc_i[SdFullO +: 4];
  wire [KF:0]     sd_sx = desc_i[SdSxO +: KF + 1];
  wire [KF:0]     sd_sy = desc_i[SdSyO +: KF + 1];
  wire [KF:0]     sd_sz = desc_i[SdSzO +: KF + 1];
  wire [R2W-1:0] sd_r2 = desc_i[SdR2O +: R2W];
  wire [KF+1:0]   sd_kd = desc_i[SdKdO +: KF + 2];
  wire [KF+1:0]   sd_ke2 = desc_i[SdKe2O +: KF + 2];
  wire [MW-1:0] sd_y_angle_m = desc_i[SdYamO +: MW];
  wire [7:0] sd_y_angle_s = desc_i[SdYasO +: 8];
  wire [LW-1:0] sd_rho0 = desc_i[SdRho0O +: LW];
  wire [TurnW-1:0] sd_a_turn = desc_i[SdAturnO +: TurnW];
  wire [TurnW-1:0] sd_k_turn = desc_i[SdKturnO +: TurnW];
  wire [LW-1:0] sd_rocket_a = desc_i[SdRaO +: LW];
  wire [LW-1:0] sd_rocket_b = desc_i[SdRbO +: LW];
  wire [MW-1:0] sd_fin_m = desc_i[SdFinmO +: MW];
  wire [7:0] sd_fin_s = desc_i[SdFinsO +: 8];
  wire [MW-1:0] sd_cone_m = desc_i[SdConemO +: MW];
  wire [7:0] sd_cone_s = desc_i[SdConesO +: 8];
  wire [LW-1:0] lx = l_i[0*LW +: LW];
  wire [LW-1:0] ly = l_i[1*LW +: LW];
  wire [LW-1:0] lz = l_i[2*LW +: LW];
  wire [4:0]    typ = {sd_type == 3'd4, sd_type == 3'd3, sd_type == 3'd2, sd_type == 3'd1,
                       sd_type == 3'd0};  // one-hot {rocket, snail, spiral, relief, ellipsoid}
  wire [OPW-1:0] ly_x  = {ly[LW-1], ly};
  wire [OPW-1:0] rb_x  = {sd_rocket_b[LW-1], sd_rocket_b};
  wire [OPW-1:0] ymb   = ly_x - rb_x;  // y − b, exact
  wire [OPW-1:0] bmy   = rb_x - ly_x;  // b − y: negative ⇔ y > b
  wire           fins  = ly[LW-1] | ~|ly;          // y ≤ 0
  wire           cone  = ~fins & bmy[OPW-1];       // y > b (> 0)
  wire           cyl   = ~fins & ~bmy[OPW-1];      // 0 < y ≤ b
  wire [OPW-1:0] op    = typ[4] && cone ? ymb : ly_x;
  wire [MW-1:0]  cm    = typ[1] ? sd_y_angle_m : fins ? sd_fin_m : sd_cone_m;
  wire [7:0]     cs    = typ[1] ? sd_y_angle_s : fins ? sd_fin_s : sd_cone_s;
  // A shift by PW − 1 or more leaves the sign in every bit, as by PW − 1.
  localparam integer   ScMaxI = PW - 1;
  localparam [7:0]     ScMax8 = ScMaxI[7:0];
  localparam [SCW-1:0] ScMax  = ScMaxI[SCW-1:0];
  wire [SCW-1:0] sc    = cs >= ScMax8 ? ScMax : cs[SCW-1:0];
  wire [Lanes-1:0] en;
  generate
    for (m = 0; m < Lanes; m = m + 1) begin : g_en
      localparam [3:0] M4 = m;
      assign en[m] = (sd_full_turns > M4) | (last_turn_i & (sd_full_turns == M4));
    end
  endgenerate

  // The context after E1: {tag, type, x_negative, en, x, y, z, rho0, a_turn, k_turn, sx, sy, r2,
  // kd, ke2, a, shift, fins, cylinder}.
  // Beside it the product operands: the point {z, y, x}, the scales {sz, sy, sx}, op and m.
  localparam integer C1W = TagW + 5 + 1 + Lanes + 4 * LW + 2 * TurnW + 2 * (KF + 1) + R2W +
                           2 * (KF + 2) + LW + SCW + 2;
  localparam integer SkW = KF + 1;  // a scale sx, sy, sz
  wire             s1_valid_q;
  wire [C1W-1:0]   s1_ctx_q;
  wire [3*LW-1:0]  s1_l_q;
  wire [3*SkW-1:0] s1_s_q;
  wire [OPW-1:0]   s1_op_q;
  wire [MW-1:0]    s1_cm_q;
  rpu_stage #(.W(C1W + 3*LW + 3*SkW + OPW + MW)) u_e1 (
    .clk_i, .rst_ni, .valid_i,
    .d_i({tag_i, typ, x_negative_i, en, lx, ly, lz, sd_rho0, sd_a_turn, sd_k_turn, sd_sx, sd_sy,
          sd_r2, sd_kd, sd_ke2, sd_rocket_a, sc, fins, cyl, l_i, sd_sz, sd_sy, sd_sx, op, cm}),
    .valid_o(s1_valid_q), .q_o({s1_ctx_q, s1_l_q, s1_s_q, s1_op_q, s1_cm_q}));
  wire unused_e1 = ^cs[7:SCW];

  // ===============================================================================================
  // LF: the scaled coordinates x·sx, y·sy, z·sz (floor to G bits below the llsb) and P = op·m.
  // ===============================================================================================
  localparam integer SxPW = LW + KF + 2;
  wire [SxPW-1:0] pxs, pys, pzs;
  wire [PW-1:0]   pcp;
  wire            f_valid;
  wire [C1W-1:0]  f_ctx;
  wire            mv_cp, mt_cp;
  // The scales as non-negative signed operands; the context rides in the x product's tag.
  rpu_mul_vec #(.Count(3), .AW(LW), .BW(KF + 2), .Signed(1), .TagW(C1W), .Latency(LF)) u_xyz (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .a_i(s1_l_q),
    .b_i({1'b0, s1_s_q[2*SkW +: SkW], 1'b0, s1_s_q[SkW +: SkW], 1'b0, s1_s_q[0 +: SkW]}),
    .tag_i(s1_ctx_q), .valid_o(f_valid), .p_o({pzs, pys, pxs}), .tag_o(f_ctx));
  rpu_mul #(.AW(OPW), .BW(MW), .Signed(1), .TagW(1), .Latency(LF)) u_cp (
    .clk_i, .rst_ni, .valid_i(s1_valid_q), .a_i(s1_op_q), .b_i(s1_cm_q),
    .tag_i(1'b0), .valid_o(mv_cp), .p_o(pcp), .tag_o(mt_cp));
  // x·k < 2^(LW+KF) in magnitude (k < 2^(KF+1)): bits KF − G .. LW + KF of the product.
  wire [XSW-1:0] xs = pxs[KF-G +: XSW];
  wire [XSW-1:0] ys = pys[KF-G +: XSW];
  wire [XSW-1:0] zs = pzs[KF-G +: XSW];
  wire unused_f = ^{mv_cp, mt_cp, pxs[KfDropW-1:0], pys[KfDropW-1:0], pzs[KfDropW-1:0],
                    pxs[SxPW-1], pys[SxPW-1], pzs[SxPW-1]};

  wire [TagW-1:0]  f_tag;
  wire [4:0]       f_typ;
  wire             f_xneg, f_fins, f_cyl;
  wire [Lanes-1:0] f_en;
  wire [LW-1:0]    f_x, f_y, f_z, f_rho0, f_ra;
  wire [TurnW-1:0] f_at, f_kt;
  wire [KF:0]      f_sx, f_sy;
  wire [R2W-1:0]   f_r2;
  wire [KF+1:0]    f_kd, f_ke2;
  wire [SCW-1:0]   f_sc;
  assign {f_tag, f_typ, f_xneg, f_en, f_x, f_y, f_z, f_rho0, f_at, f_kt, f_sx, f_sy, f_r2, f_kd,
          f_ke2, f_ra, f_sc, f_fins, f_cyl} = f_ctx;

  // ===============================================================================================
  // Tv: vectoring of (z·sz, x·sx) (relief: φ = atan2(x/a, z/c)) or (z, x): ψ, ρ. Never saturated:
  // |x·sx| < 2^(LW+2) ≤ 2^(CorW−2).
  // ===============================================================================================
  localparam integer C2W = TagW + 5 + 1 + Lanes + 3 * LW + 2 * TurnW + 2 * (KF + 1) + R2W +
                           2 * (KF + 2) + SCW + 2 + 3 * XSW + PW;
  wire [CorW-1:0] vx_in = f_typ[1] ? {{(CorW - XSW){zs[XSW-1]}}, zs}
                                   : {{(CorW - LW){f_z[LW-1]}}, f_z};
  wire [CorW-1:0] vy_in = f_typ[1] ? {{(CorW - XSW){xs[XSW-1]}}, xs}
                                   : {{(CorW - LW){f_x[LW-1]}}, f_x};
  wire          v_valid;
  wire [CorW-1:0] v_mag, v_y_unused;
  wire [AW-1:0] v_angle;
  wire [C2W-1:0] v_ctx;
  rpu_cordic #(.W(CorW), .AW(AW), .Iters(AW), .Mode(0), .TagW(C2W)) u_vec (
    .clk_i, .rst_ni, .valid_i(f_valid), .x_i(vx_in), .y_i(vy_in), .angle_i({AW{1'b0}}),
    .tag_i({f_tag, f_typ, f_en, f_y, f_rho0, f_sx, f_sy, f_r2, f_kd, f_ke2, f_ra, f_sc, f_fins,
            f_cyl, xs, ys, zs, pcp, f_at, f_kt, f_xneg}),
    .valid_o(v_valid), .x_o(v_mag), .y_o(v_y_unused), .angle_o(v_angle), .tag_o(v_ctx));
  // What LT reads of the context is at its bottom: {..., a_turn, k_turn, x_negative}.
  wire             v_xneg = v_ctx[0];
  wire [TurnW-1:0] v_kt   = v_ctx[1 +: TurnW];
  wire [TurnW-1:0] v_at   = v_ctx[1 + TurnW +: TurnW];

  // ψ unwrapped on the piece's branch (unwrap_azimuth): x ≥ 0 and ψ ≥ ¾ turn → ψ − 2^AW;
  // x < 0 and ψ < ¼ turn → ψ + 2^AW. Only the two bits above ψ change.
  wire [1:0]     v_top = v_angle[AW-1:AW-2];
  wire [PSW-1:0] psi   = {(!v_xneg && v_top == 2'b11) ? 2'b11 :
                          (v_xneg && v_top == 2'b00) ? 2'b01 : 2'b00, v_angle};

  // ===============================================================================================
  // LT: ψ_u·a_turn and ψ_u·k_turn (exact); the context rides in the first product's tag.
  // ===============================================================================================
  localparam integer C3W = C2W - 1 + AW + CorW;
  localparam integer TPW = PSW + TurnW;
  wire [TPW-1:0] pat, pkt;
  wire           t_valid;
  wire [C3W-1:0] t_ctx;
  rpu_mul_vec #(.Count(2), .AW(PSW), .BW(TurnW), .Signed(1), .ShareA(1), .TagW(C3W)) u_turn (
    .clk_i, .rst_ni, .valid_i(v_valid), .a_i(psi), .b_i({v_kt, v_at}),
    .tag_i({v_ctx[C2W-1:1], v_angle, v_mag}),
    .valid_o(t_valid), .p_o({pkt, pat}), .tag_o(t_ctx));
  wire unused_v = ^{v_y_unused, pat[AW-1:0], pkt[AW-1:0]};

  wire [TagW-1:0]  t_tag;
  wire [4:0]       t_typ;
  wire             t_fins, t_cyl;
  wire [Lanes-1:0] t_en;
  wire [LW-1:0]    t_y, t_rho0, t_ra;
  wire [TurnW-1:0] t_at, t_kt;
  wire [KF:0]      t_sx, t_sy;
  wire [R2W-1:0]   t_r2;
  wire [KF+1:0]    t_kd, t_ke2;
  wire [SCW-1:0]   t_sc;
  wire [XSW-1:0]   t_xs, t_ys, t_zs;
  wire [PW-1:0]    t_p;
  wire [AW-1:0]    t_angle;
  wire [CorW-1:0]    t_rho;
  assign {t_tag, t_typ, t_en, t_y, t_rho0, t_sx, t_sy, t_r2, t_kd, t_ke2, t_ra, t_sc, t_fins, t_cyl,
          t_xs, t_ys, t_zs, t_p, t_at, t_kt, t_angle, t_rho} = t_ctx;
  // r0 = floor(a_turn·ψ_u·2^-AW) (= a·ψ), y0 = floor(k_turn·ψ_u·2^-AW): the products' top bits.
  wire [R0W-1:0] t_r0 = pat[AW +: R0W];
  wire [R0W-1:0] t_y0 = pkt[AW +: R0W];

  // ===============================================================================================
  // T1: D0 = ρ − rho0 − r0, E0 = y − y0 (spiral); the coarse shift of P.
  // ===============================================================================================
  wire [SPW-1:0] d0, e0;
  rpu_add3 #(.W(SPW), .NegB(1), .NegC(1), .Cin(2)) u_d0 (
    .a_i({{(SPW - CorW){1'b0}}, t_rho}), .b_i({{(SPW - LW){t_rho0[LW-1]}}, t_rho0}),
    .c_i({{(SPW - R0W){t_r0[R0W-1]}}, t_r0}), .s_o(d0));
  assign e0 = {{(SPW - LW){t_y[LW-1]}}, t_y} - {{(SPW - R0W){t_y0[R0W-1]}}, t_y0};
  wire signed [PW-1:0] coarse = $signed(t_p) >>> {t_sc[SCW-1:3], 3'b000};

  wire             t1_valid_q;
  wire [SPW-1:0]   t1_d0_q, t1_e0_q;
  wire [PW-1:0]    t1_coarse_q;
  wire [2:0]       t1_scl_q;
  wire [TurnW-1:0] t1_at_q, t1_kt_q;
  wire [R0W-1:0]   t1_r0_q;
  rpu_stage #(.W(2*SPW + PW + 3 + 2*TurnW + R0W)) u_t1 (
    .clk_i, .rst_ni, .valid_i(t_valid), .d_i({d0, e0, coarse, t_sc[2:0], t_at, t_kt, t_r0}),
    .valid_o(t1_valid_q),
    .q_o({t1_d0_q, t1_e0_q, t1_coarse_q, t1_scl_q, t1_at_q, t1_kt_q, t1_r0_q}));

  // The context for after the rotations: {tag, type, en, y, sx, sy, r2, kd, a, x·sx, y·sy, z·sz,
  // angle, ρ, fins, cylinder} three cycles on; what T3 reads two cycles on; a_turn and r0 two
  // cycles on from T1.
  localparam integer CDW = TagW + 5 + Lanes + LW + 2 * (KF + 1) + R2W + (KF + 2) + LW + 3 * XSW +
                           AW + CorW + 2;
  wire [CDW-1:0] t3_ctx;
  rpu_delay #(.W(CDW), .D(3)) u_dl_t3 (
    .clk_i, .valid_i(t_valid),
    .d_i({t_tag, t_typ, t_en, t_y, t_sx, t_sy, t_r2, t_kd, t_ra, t_xs, t_ys, t_zs, t_angle, t_rho,
          t_fins, t_cyl}),
    .d_o(t3_ctx));
  localparam integer CEW = 5 + Lanes + AW + KF + 2 + 1;
  wire [4:0]       t2_typ;
  wire [Lanes-1:0] t2_en;
  wire [AW-1:0]    t2_angle;
  wire [KF+1:0]    t2_ke2;
  wire             t2_fins;
  rpu_delay #(.W(CEW), .D(2)) u_dl_t2 (
    .clk_i, .valid_i(t_valid), .d_i({t_typ, t_en, t_angle, t_ke2, t_fins}),
    .d_o({t2_typ, t2_en, t2_angle, t2_ke2, t2_fins}));
  wire [TurnW-1:0] t3_at;
  wire [R0W-1:0]   t3_r0;
  rpu_delay #(.W(TurnW + R0W), .D(2)) u_dl_t3b (
    .clk_i, .valid_i(t1_valid_q), .d_i({t1_at_q, t1_r0_q}), .d_o({t3_at, t3_r0}));

  // ===============================================================================================
  // T2: the fine shift of P; the spiral's first-turn offset (D0, E0) and step (a_turn, k_turn) on.
  // ===============================================================================================
  wire [PW-1:0]    t2_r = $signed(t1_coarse_q) >>> t1_scl_q;  // Y = floor(P·2^-s), exact
  wire             t2_valid_q;
  wire [SPW-1:0]   t2_d0_q, t2_e0_q;
  wire [TurnW-1:0] t2_at_q, t2_kt_q;
  wire [PW-1:0]    t2_r_q;
  rpu_stage #(.W(2*SPW + 2*TurnW + PW)) u_t2 (
    .clk_i, .rst_ni, .valid_i(t1_valid_q), .d_i({t1_d0_q, t1_e0_q, t1_at_q, t1_kt_q, t2_r}),
    .valid_o(t2_valid_q), .q_o({t2_d0_q, t2_e0_q, t2_at_q, t2_kt_q, t2_r_q}));

  // ===============================================================================================
  // T3: the rotation inputs. Saturation to CorW − 1 bits (cordic_in): |v| ≤ 2^(CorW−2) passes.
  // ===============================================================================================
  localparam integer SatTop = CorW - 2;  // bits SatTop and up must equal the sign
  localparam integer RHiW   = PW - SatTop;   // the product bits from SatTop up
  localparam integer SpHiW  = SPW - SatTop;  // the spiral offset's bits from SatTop up
  localparam integer StHiW  = TurnW - SatTop;  // the step's bits from SatTop up
  wire [CorW-2:0] sat_max = {1'b0, {(CorW - 2){1'b1}}};
  wire [CorW-2:0] sat_min = {1'b1, {(CorW - 2){1'b0}}};
  wire [RotN*CorW-1:0] t3_rx, t3_ry;
  wire [RotN*AW-1:0]   t3_ra;
  wire [RotN-1:0]      t3_sat;
  // Y (rocket): saturated to YW bits (exact for ρ < r) and to CorW − 1 bits (the CORDIC input).
  wire [PW-YW:0]   r_hi_y = t2_r_q[PW-1:YW-1];
  wire [RHiW-1:0] r_hi_c = t2_r_q[PW-1:SatTop];
  wire             r_neg  = t2_r_q[PW-1];
  wire             fit_y  = &r_hi_y | ~|r_hi_y;
  wire             fit_c  = &r_hi_c | ~|r_hi_c;
  wire [YW-1:0]    ysat   = fit_y ? t2_r_q[YW-1:0] : {r_neg, {(YW - 1){~r_neg}}};
  wire [CorW-2:0]    ycin   = fit_c ? t2_r_q[CorW-2:0] : r_neg ? sat_min : sat_max;
  // The angles: 4ψ (spiral), 5ψ (rocket), 10φ ± 9y (relief), modulo a turn.
  wire [AW-1:0] a9  = t2_r_q[AW-1:0];
  wire [AW-1:0] a4  = {t2_angle[AW-3:0], 2'b00};
  wire [AW-1:0] a5  = a4 + t2_angle;
  wire [AW-1:0] a8  = {t2_angle[AW-4:0], 3'b000};
  wire [AW-1:0] a2  = {t2_angle[AW-2:0], 1'b0};
  wire [AW-1:0] ang_p, ang_m;
  rpu_add3 #(.W(AW), .NegB(0), .NegC(0), .Cin(0)) u_angp (
    .a_i(a8), .b_i(a2), .c_i(a9), .s_o(ang_p));
  rpu_add3 #(.W(AW), .NegB(0), .NegC(1), .Cin(1)) u_angm (
    .a_i(a8), .b_i(a2), .c_i(a9), .s_o(ang_m));
  wire [CorW-1:0] ke2_x  = {{(CorW - KF - 2){t2_ke2[KF+1]}}, t2_ke2};
  wire [CorW-1:0] ycin_x = {ycin[CorW-2], ycin};
  wire          rel2   = t2_typ[1];
  wire          roc2   = t2_typ[4];
  // The spiral's two rotation operands, saturated: (D0, E0) (SPW bits) and the step
  // (a_turn, k_turn) (TurnW bits).
  wire [SpHiW-1:0] h_d0 = t2_d0_q[SPW-1:SatTop];
  wire [SpHiW-1:0] h_e0 = t2_e0_q[SPW-1:SatTop];
  wire [StHiW-1:0] h_at = t2_at_q[TurnW-1:SatTop];
  wire [StHiW-1:0] h_kt = t2_kt_q[TurnW-1:SatTop];
  wire ok_d0 = &h_d0 | ~|h_d0;
  wire ok_e0 = &h_e0 | ~|h_e0;
  wire ok_at = &h_at | ~|h_at;
  wire ok_kt = &h_kt | ~|h_kt;
  wire [CorW-2:0] s_d0 = ok_d0 ? t2_d0_q[CorW-2:0] : t2_d0_q[SPW-1] ? sat_min : sat_max;
  wire [CorW-2:0] s_e0 = ok_e0 ? t2_e0_q[CorW-2:0] : t2_e0_q[SPW-1] ? sat_min : sat_max;
  wire [CorW-2:0] s_at = ok_at ? t2_at_q[CorW-2:0] : t2_at_q[TurnW-1] ? sat_min : sat_max;
  wire [CorW-2:0] s_kt = ok_kt ? t2_kt_q[CorW-2:0] : t2_kt_q[TurnW-1] ? sat_min : sat_max;
  // Rotation 0: relief (ke2, 0) by 10φ + 9y; rocket (Y, 0) by 5ψ; spiral (D0, E0) by 4ψ.
  assign t3_rx[0 +: CorW] = rel2 ? ke2_x : roc2 ? ycin_x : {s_d0[CorW-2], s_d0};
  assign t3_ry[0 +: CorW] = rel2 || roc2 ? {CorW{1'b0}} : {s_e0[CorW-2], s_e0};
  assign t3_ra[0 +: AW]   = rel2 ? ang_p : roc2 ? a5 : a4;
  // Rotation 1: relief (ke2, 0) by 10φ − 9y; spiral (a_turn, k_turn) by 4ψ.
  assign t3_rx[CorW +: CorW] = rel2 ? ke2_x : {s_at[CorW-2], s_at};
  assign t3_ry[CorW +: CorW] = rel2 ? {CorW{1'b0}} : {s_kt[CorW-2], s_kt};
  assign t3_ra[AW +: AW]     = rel2 ? ang_m : a4;
  // The offset's saturation counts with turn 0 enabled, the step's with turn 1.
  assign t3_sat = {t2_en[1] & ~(ok_at & ok_kt), t2_en[0] & ~(ok_d0 & ok_e0)};
  wire unused_t2 = ^{t2_typ[0], t2_typ[3:2], t2_en[Lanes-1:2]};
  wire                 t3_valid_q;
  wire [RotN*CorW-1:0] t3_rx_q, t3_ry_q;
  wire [RotN*AW-1:0]   t3_ra_q;
  wire [RotN-1:0]      t3_sat_q;
  wire [YW-1:0]        t3_ysat_q;
  wire                 t3_ovf_roc_q;
  // The twin saturates Y on the fins only.
  rpu_stage #(.W(RotN*(2*CorW + AW + 1) + YW + 1)) u_t3 (
    .clk_i, .rst_ni, .valid_i(t2_valid_q),
    .d_i({t3_rx, t3_ry, t3_ra, t3_sat, ysat, roc2 & t2_fins & ~fit_c}),
    .valid_o(t3_valid_q), .q_o({t3_rx_q, t3_ry_q, t3_ra_q, t3_sat_q, t3_ysat_q, t3_ovf_roc_q}));

  // The overflow so far: a spiral lane's offset saturated, or the rocket's fin term.
  localparam integer CdSpiralO = CDW - TagW - 3;  // the type's spiral bit in t3_ctx
  wire q_ovf = (t3_ctx[CdSpiralO] & |t3_sat_q) | t3_ovf_roc_q;

  // ===============================================================================================
  // Tr: the two rotations; the context rides in rotation 0's tag.
  // ===============================================================================================
  localparam integer C4W = CDW + R0W + TurnW + YW + 1;
  wire [RotN*CorW-1:0] rot_x, rot_y;
  wire                 r_valid;
  wire [C4W-1:0]       r_ctx;
  wire                 r1_valid, r1_tag;
  wire [AW-1:0]        r0_ao, r1_ao;
  rpu_cordic #(.W(CorW), .AW(AW), .Iters(AW), .Mode(1), .TagW(C4W)) u_rot0 (
    .clk_i, .rst_ni, .valid_i(t3_valid_q), .x_i(t3_rx_q[0 +: CorW]), .y_i(t3_ry_q[0 +: CorW]),
    .angle_i(t3_ra_q[0 +: AW]), .tag_i({t3_ctx, t3_r0, t3_at, t3_ysat_q, q_ovf}),
    .valid_o(r_valid), .x_o(rot_x[0 +: CorW]), .y_o(rot_y[0 +: CorW]), .angle_o(r0_ao),
    .tag_o(r_ctx));
  rpu_cordic #(.W(CorW), .AW(AW), .Iters(AW), .Mode(1), .TagW(1)) u_rot1 (
    .clk_i, .rst_ni, .valid_i(t3_valid_q), .x_i(t3_rx_q[CorW +: CorW]),
    .y_i(t3_ry_q[CorW +: CorW]), .angle_i(t3_ra_q[AW +: AW]), .tag_i(1'b0),
    .valid_o(r1_valid), .x_o(rot_x[CorW +: CorW]), .y_o(rot_y[CorW +: CorW]), .angle_o(r1_ao),
    .tag_o(r1_tag));
  wire unused_rot = ^{r1_valid, r1_tag, r0_ao, r1_ao};

  wire [TagW-1:0]  r_tag;
  wire [4:0]       r_typ;
  wire [Lanes-1:0] r_en;
  wire [LW-1:0]    r_y, r_ra;
  wire [KF:0]      r_sx, r_sy;
  wire [R2W-1:0]   r_r2;
  wire [KF+1:0]    r_kd;
  wire [XSW-1:0]   r_xs, r_ys, r_zs;
  wire [AW-1:0]    r_angle;
  wire [CorW-1:0]    r_rho;
  wire             r_fins, r_cyl, r_ovf;
  wire [R0W-1:0]   r_r0;
  wire [TurnW-1:0] r_at;
  wire [YW-1:0]    r_ysat;
  assign {r_tag, r_typ, r_en, r_y, r_sx, r_sy, r_r2, r_kd, r_ra, r_xs, r_ys, r_zs, r_angle, r_rho,
          r_fins, r_cyl, r_r0, r_at, r_ysat, r_ovf} = r_ctx;

  // The valid bit after the rotations: vr[k] at k cycles past them.
  wire [LB-1:0] vr;
  reg  [LB-1:1] vr_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) vr_q <= {(LB - 1){1'b0}};
    else         vr_q <= {vr[LB-2:0]};
  end
  assign vr = {vr_q, r_valid};

  // ===============================================================================================
  // Back end: spiral lanes. The rotated offset (u0, w0) and step (ua, wa) scaled by (sx, sy),
  // exact; lane m: (u0·sx − m·ua·sx, w0·sy − m·wa·sy) ≫ (KF − G) (m·X as at most two shifted terms:
  // 3 = 2 + 1, 5 = 4 + 1, 6 = 4 + 2, 7 = 8 − 1); clamped; squared; r2 − 1 − A² − B² ≥ 0.
  // ===============================================================================================
  localparam integer ScPW = CorW + KF + 2;  // a scaled rotation output, exact
  localparam integer LPW  = ScPW + 2;       // a lane's u0·sx − m·ua·sx: |·| < 2^(CorW+KF+3)
  localparam integer LAW  = LPW - KfDropW;  // the same ≫ (KF − G)
  localparam integer LaHiW = LAW - LW;      // its bits from LW up
  wire [Lanes-1:0] sp_bit;
  wire [Lanes-1:0] sp_en;
  wire [R2W-1:0]   sp_r2;
  rpu_delay #(.W(Lanes + R2W), .D(LSc + 2 + LQ)) u_dl_sp (
    .clk_i, .valid_i(vr[0]), .d_i({r_en, r_r2}), .d_o({sp_en, sp_r2}));
  wire [ScPW-1:0] pu0, pw0, pua, pwa;
  wire            vs, ts;
  rpu_mul_vec #(.Count(4), .AW(CorW), .BW(KF + 2), .Signed(1), .TagW(1)) u_sc (
    .clk_i, .rst_ni, .valid_i(vr[0]),
    .a_i({rot_y[CorW +: CorW], rot_x[CorW +: CorW], rot_y[0 +: CorW], rot_x[0 +: CorW]}),
    .b_i({1'b0, r_sy, 1'b0, r_sx, 1'b0, r_sy, 1'b0, r_sx}), .tag_i(1'b0),
    .valid_o(vs), .p_o({pwa, pua, pw0, pu0}), .tag_o(ts));
  wire [LPW-1:0] pu0_x = {{2{pu0[ScPW-1]}}, pu0};
  wire [LPW-1:0] pw0_x = {{2{pw0[ScPW-1]}}, pw0};
  wire [LPW-1:0] pua_x = {{2{pua[ScPW-1]}}, pua};
  wire [LPW-1:0] pwa_x = {{2{pwa[ScPW-1]}}, pwa};
  generate
    for (m = 0; m < Lanes; m = m + 1) begin : g_sp
      localparam integer U1 = m != 0 ? 1 : 0;
      localparam integer U2 = t2_used(m);
      localparam integer N2 = t2_neg(m);
      // X0 − t1 − (±t2): t1 subtracted, t2 subtracted unless it is the "− X" of 7 = 8 − 1.
      localparam integer SubC = (U2 != 0 && N2 == 0) ? 1 : 0;
      wire [LPW-1:0] ua1 = U1 != 0 ? pua_x << t1_shift(m) : {LPW{1'b0}};
      wire [LPW-1:0] ua2 = U2 != 0 ? pua_x << t2_shift(m) : {LPW{1'b0}};
      wire [LPW-1:0] wa1 = U1 != 0 ? pwa_x << t1_shift(m) : {LPW{1'b0}};
      wire [LPW-1:0] wa2 = U2 != 0 ? pwa_x << t2_shift(m) : {LPW{1'b0}};
      wire [LPW-1:0] lu, lw;
      rpu_add3 #(.W(LPW), .NegB(U1), .NegC(SubC), .Cin(U1 + SubC)) u_lu (
        .a_i(pu0_x), .b_i(ua1), .c_i(ua2), .s_o(lu));
      rpu_add3 #(.W(LPW), .NegB(U1), .NegC(SubC), .Cin(U1 + SubC)) u_lw (
        .a_i(pw0_x), .b_i(wa1), .c_i(wa2), .s_o(lw));
      reg [LAW-1:0] lu_q, lw_q;
      always @(posedge clk_i) begin
        lu_q <= lu[LPW-1:KfDropW];
        lw_q <= lw[LPW-1:KfDropW];
      end
      // The lane's scaled u squares to ≥ 2^(2LW) ≥ r2 (outside) unless it fits LW + 1 bits
      // signed, so only those are squared.
      wire [LaHiW-1:0] hu = lu_q[LAW-1:LW];
      wire [LaHiW-1:0] hw = lw_q[LAW-1:LW];
      reg  [LW:0] qu_q, qw_q;
      reg         big_q;
      always @(posedge clk_i) begin
        qu_q  <= (&hu | ~|hu) ? lu_q[LW:0] : {(LW + 1){1'b0}};
        qw_q  <= (&hw | ~|hw) ? lw_q[LW:0] : {(LW + 1){1'b0}};
        big_q <= ~((&hu | ~|hu) & (&hw | ~|hw));
      end
      wire [2*LW+1:0] uu, ww;
      wire            v3, v4, big, t4;
      rpu_mul #(.AW(LW + 1), .BW(LW + 1), .Signed(1), .TagW(1)) u_uu (
        .clk_i, .rst_ni, .valid_i(vr[LSc+2]), .a_i(qu_q), .b_i(qu_q),
        .tag_i(big_q), .valid_o(v3), .p_o(uu), .tag_o(big));
      rpu_mul #(.AW(LW + 1), .BW(LW + 1), .Signed(1), .TagW(1)) u_ww (
        .clk_i, .rst_ni, .valid_i(vr[LSc+2]), .a_i(qw_q), .b_i(qw_q),
        .tag_i(1'b0), .valid_o(v4), .p_o(ww), .tag_o(t4));
      // r2 − 1 − u² − w² ≥ 0 (each square ≤ 2^(2LW): its low SQW bits).
      wire [2*LW+2:0] diff;
      rpu_add3 #(.W(2 * LW + 3), .NegB(1), .NegC(1), .Cin(1)) u_cmp (
        .a_i({2'b00, sp_r2}), .b_i({2'b00, uu[SQW-1:0]}), .c_i({2'b00, ww[SQW-1:0]}), .s_o(diff));
      reg bit_q;
      always @(posedge clk_i) bit_q <= sp_en[m] & ~big & ~diff[2*LW+2];
      assign sp_bit[m] = bit_q;
      wire unused_sp = ^{v3, v4, t4, lu[KfDropW-1:0], lw[KfDropW-1:0], uu[2*LW+1:SQW],
                         ww[2*LW+1:SQW]};
    end
  endgenerate
  wire unused_sc = ^{vs, ts};

  // ===============================================================================================
  // Back end: snail lanes. P_j = ρ − G_j, G_0 = 0, G_j = j·h_{j−1}, h_j = 2r0 + j·a_turn;
  // turn m holds the point ⇔ P_m·P_{m+1} + y² < 0.
  // ===============================================================================================
  wire [HW-1:0] r0_2 = {{(HW - R0W - 1){r_r0[R0W-1]}}, r_r0, 1'b0};
  wire [HW-1:0] at_h = {{(HW - TurnW){r_at[TurnW-1]}}, r_at};
  reg  [Lanes*HW-1:0] sn_h_q;  // h_0 .. h_{Lanes−1}
  generate
    for (m = 0; m < Lanes; m = m + 1) begin : g_h
      localparam integer U1 = m != 0 ? 1 : 0;
      localparam integer U2 = t2_used(m);
      localparam integer N2 = t2_neg(m);
      wire [HW-1:0] ha1 = U1 != 0 ? at_h << t1_shift(m) : {HW{1'b0}};
      wire [HW-1:0] ha2 = U2 != 0 ? at_h << t2_shift(m) : {HW{1'b0}};
      wire [HW-1:0] h;
      rpu_add3 #(.W(HW), .NegB(0), .NegC(N2), .Cin(N2)) u_h (
        .a_i(r0_2), .b_i(ha1), .c_i(ha2), .s_o(h));
      always @(posedge clk_i) sn_h_q[m*HW +: HW] <= h;
    end
  endgenerate
  wire [CorW-1:0] sn_rho1;
  rpu_delay #(.W(CorW), .D(1)) u_dl_rho1 (
    .clk_i, .valid_i(vr[0]), .d_i(r_rho), .d_o(sn_rho1));
  wire [PJW-1:0] rho_p = {{(PJW - CorW){1'b0}}, sn_rho1};
  reg  [(Lanes+1)*PJW-1:0] sn_p_q;  // P_0 .. P_Lanes
  generate
    for (m = 0; m <= Lanes; m = m + 1) begin : g_p
      if (m == 0) begin : g_p0
        always @(posedge clk_i) sn_p_q[0 +: PJW] <= rho_p;
      end else begin : g_pj
        localparam integer U2 = t2_used(m);
        localparam integer N2 = t2_neg(m);
        localparam integer SubC = (U2 != 0 && N2 == 0) ? 1 : 0;
        wire [HW-1:0]  hp = sn_h_q[(m-1)*HW +: HW];
        wire [PJW-1:0] hx = {{(PJW - HW){hp[HW-1]}}, hp};
        wire [PJW-1:0] b1 = hx << t1_shift(m);
        wire [PJW-1:0] b2 = U2 != 0 ? hx << t2_shift(m) : {PJW{1'b0}};
        wire [PJW-1:0] pj;
        rpu_add3 #(.W(PJW), .NegB(1), .NegC(SubC), .Cin(1 + SubC)) u_p (
          .a_i(rho_p), .b_i(b1), .c_i(b2), .s_o(pj));
        always @(posedge clk_i) sn_p_q[m*PJW +: PJW] <= pj;
      end
    end
  endgenerate
  // ER+3: |P_j|, its sign, P_j ≠ 0.
  reg [(Lanes+1)*HIW-1:0] sn_u_q;
  reg [Lanes:0]           sn_neg_q, sn_nz_q;
  generate
    for (m = 0; m <= Lanes; m = m + 1) begin : g_abs
      wire [PJW-1:0] pj  = sn_p_q[m*PJW +: PJW];
      wire           neg = pj[PJW-1];
      wire [PJW-1:0] mag = (pj ^ {PJW{neg}}) + {{(PJW - 1){1'b0}}, neg};
      always @(posedge clk_i) begin
        sn_u_q[m*HIW +: HIW] <= mag[HIW-1:0];  // |P_j| < 2^(PJW−1)
        sn_neg_q[m]          <= neg;
        sn_nz_q[m]           <= |pj;
      end
      wire unused_mag = mag[PJW-1];
    end
  endgenerate
  // ER+4: per lane the order of |P_m|, |P_{m+1}| and whether P_m, P_{m+1} differ in sign (both
  // nonzero); per factor the capped value min(|P|, 2^LW − 1).
  reg [(Lanes+1)*LW-1:0] sn_cl_q;
  reg [(Lanes+1)*HIW-1:0] sn_hi_q;
  reg [Lanes-1:0] sn_lt_q, sn_opp_q;
  generate
    for (m = 0; m <= Lanes; m = m + 1) begin : g_cap
      wire [HIW-1:0] u = sn_u_q[m*HIW +: HIW];
      always @(posedge clk_i) begin
        sn_cl_q[m*LW +: LW]   <= |u[HIW-1:LW] ? {LW{1'b1}} : u[LW-1:0];
        sn_hi_q[m*HIW +: HIW] <= u;
      end
      if (m < Lanes) begin : g_ord
        wire [HIW-1:0] un = sn_u_q[(m+1)*HIW +: HIW];
        always @(posedge clk_i) begin
          sn_lt_q[m]  <= u < un;
          sn_opp_q[m] <= (sn_neg_q[m] ^ sn_neg_q[m+1]) & sn_nz_q[m] & sn_nz_q[m+1];
        end
      end
    end
  endgenerate
  // The products min·max (exact after the cap) and y², compared at ER+5+LN.
  localparam integer NPW = LW + HIW;
  wire [2*LW-1:0] yy;
  wire            v_yy, t_yy;
  rpu_mul #(.AW(LW), .BW(LW), .Signed(1), .TagW(1), .Latency(4 + LN)) u_yy (
    .clk_i, .rst_ni, .valid_i(vr[0]), .a_i(r_y), .b_i(r_y), .tag_i(1'b0),
    .valid_o(v_yy), .p_o(yy), .tag_o(t_yy));
  wire [Lanes-1:0] sn_en;
  rpu_delay #(.W(Lanes), .D(4 + LN)) u_dl_sn (
    .clk_i, .valid_i(vr[0]), .d_i(r_en), .d_o(sn_en));
  wire [Lanes-1:0] sn_bit;
  generate
    for (m = 0; m < Lanes; m = m + 1) begin : g_sn
      wire [LW-1:0]  lo = sn_lt_q[m] ? sn_cl_q[m*LW +: LW] : sn_cl_q[(m+1)*LW +: LW];
      wire [HIW-1:0] hi = sn_lt_q[m] ? sn_hi_q[(m+1)*HIW +: HIW] : sn_hi_q[m*HIW +: HIW];
      wire [NPW-1:0] pr;
      wire           v5, opp;
      rpu_mul #(.AW(LW), .BW(HIW), .Signed(0), .TagW(1)) u_pp (
        .clk_i, .rst_ni, .valid_i(vr[4]), .a_i(lo), .b_i(hi), .tag_i(sn_opp_q[m]),
        .valid_o(v5), .p_o(pr), .tag_o(opp));
      // y² ≤ 2^(2LW−2) < 2^NPW: y² < product.
      reg bit_q;
      always @(posedge clk_i) bit_q <= sn_en[m] & opp & ({{(NPW - 2 * LW){1'b0}}, yy} < pr);
      assign sn_bit[m] = bit_q;
      wire unused_sn = v5;
    end
  endgenerate
  wire unused_yy = ^{v_yy, t_yy};

  // ===============================================================================================
  // Back end: the ellipsoid and the relief's sums. (x·sx)², (z·sz)² exact; (y·sy)² clamped
  // (|y·sy| ≥ 2^LW: outside for both, as r2 ≤ 2^(2LW)).
  // ===============================================================================================
  reg  [LW:0] ey_q;
  reg         ey_big_q;
  wire [XsHiW-1:0] ys_hi = r_ys[XSW-1:LW];
  always @(posedge clk_i) begin
    ey_q     <= (&ys_hi | ~|ys_hi) ? r_ys[LW:0] : {(LW + 1){1'b0}};
    ey_big_q <= ~(&ys_hi | ~|ys_hi);
  end
  wire [2*XSW-1:0] exx, ezz;
  wire [2*LW+1:0]  eyy;
  wire             v6, v7, v8, t6, t7, ey_big;
  rpu_mul #(.AW(XSW), .BW(XSW), .Signed(1), .TagW(1), .Latency(LXY)) u_exx (
    .clk_i, .rst_ni, .valid_i(vr[0]), .a_i(r_xs), .b_i(r_xs), .tag_i(1'b0),
    .valid_o(v6), .p_o(exx), .tag_o(t6));
  rpu_mul #(.AW(XSW), .BW(XSW), .Signed(1), .TagW(1), .Latency(LXY)) u_ezz (
    .clk_i, .rst_ni, .valid_i(vr[0]), .a_i(r_zs), .b_i(r_zs), .tag_i(1'b0),
    .valid_o(v7), .p_o(ezz), .tag_o(t7));
  rpu_mul #(.AW(LW + 1), .BW(LW + 1), .Signed(1), .TagW(1), .Latency(LXY - 1)) u_eyy (
    .clk_i, .rst_ni, .valid_i(vr[1]), .a_i(ey_q), .b_i(ey_q), .tag_i(ey_big_q),
    .valid_o(v8), .p_o(eyy), .tag_o(ey_big));
  wire [R2W-1:0] e_r2;
  rpu_delay #(.W(R2W), .D(LXY)) u_dl_er2 (
    .clk_i, .valid_i(vr[0]), .d_i(r_r2), .d_o(e_r2));
  // ER+LXY+1: (x·sx)² + (z·sz)²; s²m² = r2 − (y·sy)² and whether it is > 0.
  wire [LHW-1:0]  lhs   = {1'b0, exx[LHW-2:0]} + {1'b0, ezz[LHW-2:0]};  // each < 2^(2LW+4)
  wire [SQW:0]    d2s   = {1'b0, e_r2} - {1'b0, eyy[SQW-1:0]};
  wire [SQW:0]    d2m1  = {1'b0, e_r2} + ~{1'b0, eyy[SQW-1:0]};     // r2 − (y·sy)² − 1
  reg  [LHW-1:0]  e_lhs_q;
  reg  [D2W-1:0]  e_d2_q;
  reg             e_d2pos_q, e_big_q;
  reg  [R2W-1:0]  e_r2_q;
  reg  [SQW-1:0]  e_yy_q;
  always @(posedge clk_i) begin
    e_lhs_q   <= lhs;
    e_d2_q    <= d2s[D2W-1:0];  // only used when 0 < s²m² ≤ 2^(2LW)
    e_d2pos_q <= ~ey_big & ~d2m1[SQW];
    e_big_q   <= ey_big;
    e_r2_q    <= e_r2;
    e_yy_q    <= eyy[SQW-1:0];
  end
  // ER+LXY+2: the ellipsoid: r2 − 1 − lhs − (y·sy)² ≥ 0.
  localparam integer EDW = LHW + 2;
  wire [EDW-1:0] ediff;
  rpu_add3 #(.W(EDW), .NegB(1), .NegC(1), .Cin(1)) u_ell (
    .a_i({{(EDW - R2W){1'b0}}, e_r2_q}), .b_i({2'b00, e_lhs_q}),
    .c_i({{(EDW - SQW){1'b0}}, e_yy_q}), .s_o(ediff));
  reg el_bit_q;
  always @(posedge clk_i) el_bit_q <= ~e_big_q & ~ediff[EDW-1];
  wire unused_e = ^{v6, v7, v8, t6, t7, exx[2*XSW-1:LHW-1], ezz[2*XSW-1:LHW-1], eyy[2*LW+1:SQW],
                    d2s[SQW:D2W]};

  // ===============================================================================================
  // Back end: the relief. k' = kd + y1 + y2 (lanes 0 and 1); k2 = floor(k'²·2^-KF);
  // rhs = floor(k2·s²m²·2^-KF) against lhs = (x·sx)² + (z·sz)² (in the output stage).
  // ===============================================================================================
  wire [KpW-1:0] kk;
  rpu_add3 #(.W(KpW), .NegB(0), .NegC(0), .Cin(0)) u_k (
    .a_i({{(KpW - KF - 2){r_kd[KF+1]}}, r_kd}),
    .b_i({{(KpW - CorW){rot_y[0*CorW + CorW-1]}}, rot_y[0*CorW +: CorW]}),
    .c_i({{(KpW - CorW){rot_y[1*CorW + CorW-1]}}, rot_y[1*CorW +: CorW]}), .s_o(kk));
  reg [KpW-1:0] re_k_q;
  always @(posedge clk_i) re_k_q <= kk;
  wire [2*KpW-1:0] k2p;
  wire            v9, t9;
  rpu_mul #(.AW(KpW), .BW(KpW), .Signed(1), .TagW(1), .Latency(TKD - 1)) u_kk (
    .clk_i, .rst_ni, .valid_i(vr[1]), .a_i(re_k_q), .b_i(re_k_q), .tag_i(1'b0),
    .valid_o(v9), .p_o(k2p), .tag_o(t9));
  wire [K2W-1:0] k2 = k2p[KF +: K2W];  // k'² < 2^(2KW−2)
  wire [D2W-1:0] re_d2;
  rpu_delay #(.W(D2W), .D(TKD - LXY - 1)) u_dl_d2 (
    .clk_i, .valid_i(vr[LXY+1]), .d_i(e_d2_q), .d_o(re_d2));
  wire [K2W+D2W-1:0] rhp;
  wire               v10, t10;
  rpu_mul #(.AW(K2W), .BW(D2W), .Signed(0), .TagW(1), .Latency(BLast - TKD)) u_kd2 (
    .clk_i, .rst_ni, .valid_i(vr[TKD]), .a_i(k2), .b_i(re_d2), .tag_i(1'b0),
    .valid_o(v10), .p_o(rhp), .tag_o(t10));
  wire [RHW-1:0] rhs = rhp[KF +: RHW];
  wire [LHW-1:0] re_lhs;
  wire           re_d2pos;
  rpu_delay #(.W(LHW + 1), .D(BLast - LXY - 1)) u_dl_lhs (
    .clk_i, .valid_i(vr[LXY+1]), .d_i({e_lhs_q, e_d2pos_q}), .d_o({re_lhs, re_d2pos}));
  localparam integer CmpW = (RHW > LHW ? RHW : LHW) + 1;
  wire re_in = re_d2pos & ({{(CmpW - LHW){1'b0}}, re_lhs} < {{(CmpW - RHW){1'b0}}, rhs});
  wire unused_re = ^{v9, t9, v10, t10, k2p[KF-1:0], k2p[2*KpW-1:KF+K2W], rhp[KF-1:0]};

  // ===============================================================================================
  // Back end: the rocket. r = a − Y + (fins ? (Y rotated by 5ψ).y : 0); ρ < r.
  // ===============================================================================================
  wire [RW-1:0] ro_y  = r_cyl ? {RW{1'b0}} : {{(RW - YW){r_ysat[YW-1]}}, r_ysat};
  wire [RW-1:0] ro_ys = r_fins ? {{(RW - CorW){rot_y[CorW-1]}}, rot_y[0 +: CorW]} : {RW{1'b0}};
  wire [RW-1:0] ro_r;
  rpu_add3 #(.W(RW), .NegB(1), .NegC(0), .Cin(1)) u_ro (
    .a_i({{(RW - LW){r_ra[LW-1]}}, r_ra}), .b_i(ro_y), .c_i(ro_ys), .s_o(ro_r));
  reg [RW-1:0] ro_r_q;
  always @(posedge clk_i) ro_r_q <= ro_r;
  wire [RW:0] ro_d = {{(RW + 1 - CorW){1'b0}}, sn_rho1} - {ro_r_q[RW-1], ro_r_q};
  reg ro_bit_q;
  always @(posedge clk_i) ro_bit_q <= ro_d[RW];

  // ===============================================================================================
  // Output: each type's bit delayed to the last stage; the trace fields; registered.
  // ===============================================================================================
  wire             o_el, o_ro;
  wire [Lanes-1:0] o_sp, o_sn;
  rpu_delay #(.W(1), .D(BLast - BEl)) u_dl_oel (
    .clk_i, .valid_i(vr[BEl]), .d_i(el_bit_q), .d_o(o_el));
  rpu_delay #(.W(Lanes), .D(BLast - BSp)) u_dl_osp (
    .clk_i, .valid_i(vr[BSp]), .d_i(sp_bit), .d_o(o_sp));
  rpu_delay #(.W(Lanes), .D(BLast - BSn)) u_dl_osn (
    .clk_i, .valid_i(vr[BSn]), .d_i(sn_bit), .d_o(o_sn));
  rpu_delay #(.W(1), .D(BLast - BRo)) u_dl_oro (
    .clk_i, .valid_i(vr[BRo]), .d_i(ro_bit_q), .d_o(o_ro));
  localparam integer COW = TagW + 5 + AW + CorW + 1;
  wire [TagW-1:0] o_tag;
  wire [4:0]      o_typ;
  wire [AW-1:0]   o_angle;
  wire [CorW-1:0]   o_rho;
  wire            o_ovf;
  rpu_delay #(.W(COW), .D(BLast)) u_dl_out (
    .clk_i, .valid_i(vr[0]), .d_i({r_tag, r_typ, r_angle, r_rho, r_ovf}),
    .d_o({o_tag, o_typ, o_angle, o_rho, o_ovf}));

  wire             o_inside = (o_typ[0] & o_el) | (o_typ[1] & re_in) | (o_typ[2] & |o_sp) |
                              (o_typ[3] & |o_sn) | (o_typ[4] & o_ro);
  wire [Lanes-1:0] o_turns  = ({Lanes{o_typ[2]}} & o_sp) | ({Lanes{o_typ[3]}} & o_sn);
  wire [AW-1:0]    o_ang    = o_typ[0] || o_typ == 5'b0 ? {AW{1'b0}} : o_angle;
  wire [CorW-1:0]    o_rh     = o_typ[2] || o_typ[3] || o_typ[4] ? o_rho : {CorW{1'b0}};
  // Loaded only with a valid point.
  rpu_stage #(.W(1 + Lanes + AW + CorW + 1 + TagW), .Hold(1)) u_out (
    .clk_i, .rst_ni, .valid_i(vr[BLast]), .d_i({o_inside, o_turns, o_ang, o_rh, o_ovf, o_tag}),
    .valid_o, .q_o({inside_o, turn_inside_o, angle_o, rho_o, ovf_o, tag_o}));
`ifndef SYNTHESIS
  // The declared latency is the schedule (rtl/common/rpu_latency_check.v).
  rpu_latency_check #(.Latency(LatencyOwn), .Segments(3),
                     .Name("rpu_indicator (without its CORDICs)")) u_latency_check (
    .clk_i, .rst_ni, .in_i({valid_i, v_valid, r_valid}), .out_i({f_valid, t3_valid_q, valid_o}));
`endif
endmodule

`default_nettype wire
