// rpu_surface_setup: the surface setup unit, twin of `rpu::ref::surface_setup(p, eye, v̂, s, piece)`
// (ref/model/surface/rpu_surface_setup.{h,cpp}; formats: docs/fixed-point.md, "Surfaces"; the contract:
// docs/surfaces.md, "Ranges"). One work item is (pixel ray, surface, piece index):
//   sphere      pred1, A, B = rpu_sphere on the bounding sphere (c0, R²), d = 0 (α = β = 0)
//   la, lb      floor(M·(X − origin)·2^-s) for X = A, B: exact products (rpu_mul), one
//               arithmetic shift by s = to_local_s, saturated to LW bits (flagged under pred1)
//   slab        (ellipsoid, relief ellipsoid, rocket) lo, hi = the entry and exit of
//               y_min ≤ y ≤ y_max along la → lb, each clamped to [0, 1]: 0 when num ≤ 0, 1 when
//               num ≥ den = |lb.y − la.y|, else udiv(num·2^SF, den), SF + 1 quotient bits
//               (the twin's SF bits give the same floor: num < den); dy = 0: [0, 1] or [0, 0]
//   cuts        (spiral, snail) where f_x = x and f_e = x·end_cos − z·end_sin (exact) change
//               their sign bit from la to lb: udiv(|fA|·2^SF, |fA| + |fB|), SF + 1 bits; f_e
//               only when end_angle ≠ 0
//   pieces      the non-empty intervals between 0, the sorted cuts and 1 (slab: [lo, hi]);
//               piece_i selects one; pieces_o counts them (0 without pred1)
//   A', B' − A' A + floor((B − A)·s_lo·2^-SF), the same at s_hi, the difference; likewise on
//               la → lb (lA', lB' − lA')
//   branch      x_negative: the piece's side of x = 0 (A's side if the piece ends at or before
//               the cut, else B's); last_turn = end ≠ 0 ∧ (end < ½ turn ? x ≥ 0 ∧ f_e < 0 :
//               x ≥ 0 ∨ f_e < 0) with f_e's side chosen the same way; 0 for the slab types.
// The two dividers are shared by type: divider 1 takes the slab's lo or the x = 0 cut, divider 2
// the slab's hi or the end-plane cut (the widest denominator, LW + KF + 3 bits).
// ovf_o mirrors the twin's sticky flag: the sphere unit's flag, and the saturation of la or lb
// when pred1 holds. When piece_valid_o is 0, s_lo_o, s_hi_o, a_o, ab_o, la_o, lab_o,
// x_negative_o and last_turn_o are don't-care (the twin leaves them zero).
//
// Ports. Vectors are flattened {z, y, x}, each component two's complement. The descriptor fields
// are SurfaceDesc's (ref/model/descriptors.h), all sampled with valid_i:
//   c0_i, r2_i      bound.c0 (LSB), bound.R2 (LSB², unsigned)
//   origin_i        LSB
//   to_local_i      M, row-major: entry M[r][c] (k = 3r + c) at bits [k·MantW +: MantW], signed
//   to_local_s_i    the block shift s, unsigned 0..127 (the compiler's is 4..CW+8)
//   type_i          scene::SurfaceType: 0 ellipsoid, 1 relief, 2 spiral, 3 snail, 4 rocket
//   y_min_i, y_max_i  llsb, signed LW bits (slab types)
//   end_angle_i     binary angle, AW bits; end_cos_i, end_sin_i Q(1.KF) signed KF + 2 bits
//   piece_i         the requested piece, 0..2 (3 is never valid)
// Outputs: s_lo_o, s_hi_o Q(1.SF) unsigned SF + 1 bits; a_o LSB; ab_o B' − A' (CW + 1 bits);
// la_o lA' (LW bits); lab_o lB' − lA' (LW + 1 bits). KF = LW, SF = MantW = LW + 2.
//
// Sphere = 0 (rpu_top, which shares its curve path's sphere unit: a surface item takes that
// unit's slot, as every work item is of one kind): the sphere's results come with the item, the
// stage Ls and the descriptor FIFO below are not built, and the latency is Latency − Ls.
// The descriptor waits in a FIFO (rpu_fifo, 2^FifoLog2 ≥ Ls entries: 64, which Yosys puts in
// LUT RAM; first-word fall-through, so the head is at its output when the sphere unit delivers
// that item) instead of riding the sphere unit's 57 stages in shift registers; from there the
// context rides in the multipliers' and dividers' tags. The sphere unit's α, β tail (its
// (A − p1)·d products and two rpu_chord, 11 of its cycles) still runs: with d = 0 its products
// fold to zero in synthesis, but its stages and latency remain.
// Pipeline (one item per cycle, no stall; every product an rpu_mul, rpu_mul_latency.vh):
//   Ls       rpu_sphere (d = 0)                             57 at the defaults
//   1        q = X − origin for A and B
//   L1       q_c · M[r][c]                   rpu_mul (CW+1) × MW: 18, 3 cycles at the defaults
//   1        the row sums (carry-save + one adder)
//   1        shift by 8·s[6:3]
//   1        shift by s[2:0]
//   1        saturation to LW bits: la, lb
//   L2       la.x·cos, la.z·sin, lb.x·cos, lb.z·sin   rpu_mul LW × (KF+2): 4, 3 cycles
//   1        f_e = x·cos − z·sin; slab differences; |la.x|, |lb.x|; lb − la
//   1        |f_e|; the slab's numerators and denominator chosen by the sign of dy;
//            |la.x| + |lb.x|
//   1        the divider operands (by type); |feA| + |feB|; the slab's clamp tests
//   SF+1     two rpu_div                                    27 at the defaults
//   1        the clamped bounds; their order and equality tests
//   1        the pieces, the selected one
//   L3       (B − A)_k·s, (lb − la)_k·s at s_lo and s_hi  rpu_mul: 12, 3 cycles (the branch
//            bits in a parallel delay line)
//   1        A', B', lA', lB'
//   1        B' − A', lB' − lA'; outputs registered
// Latency = Ls + 1 + L1 + 4 + L2 + 3 + (SF + 1) + 2 + L3 + 2 cycles (105 at the defaults;
// ref::surface_setup_latency). No stage has two wide carry chains in series.
// No backpressure inside (the enclosing top reserves room).
`default_nettype none
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_surface_setup #(
  parameter integer CoordW  = 24,  // CW: signed width of positions, LSB (12..40)
  parameter integer DirFrac = 24,  // FV: fraction bits of the ray direction v̂, Q(2.FV) (8..40)
  parameter integer TFrac   = 24,  // the sphere unit's α, β format (8..48; unused values, d = 0)
  parameter integer InvW    = 18,  // the sphere unit's 1/L² mantissa width (8..40; sets its latency)
  parameter integer SqrtW   = 0,   // widest radicand of the sphere unit's root; 0 = exact (16..126)
  parameter integer SurfW   = 24,  // LW: signed width of surface-local coordinates, llsb (16..36)
  parameter integer AngleW  = 20,  // AW: bits of a binary angle (12..32)
  parameter integer TagW    = 1,   // side-band bits carried with each item (>= 1)
  parameter integer Sphere  = 1,   // 1: the unit's own sphere unit; 0: the caller's (rpu_top's
                                   // curve-path rpu_sphere at these parameters, d = 0): its
                                   // results come with the item on sp_*_i, and eye_i, vhat_i,
                                   // c0_i, r2_i are unused
  // Derived (do not override).
  parameter integer DirW   = `RPU_VHATW(DirFrac),     // v̂: Q(2.FV)
  parameter integer DiffW  = `RPU_DW(CoordW),      // B − A, X − origin
  parameter integer R2W    = `RPU_R2W(CoordW),  // R²
  parameter integer MantW  = SurfW + 2,       // MW: the entries of M, signed
  parameter integer ConstW = SurfW + 2,       // end_cos, end_sin: Q(1.KF), KF = LW, signed
  parameter integer SW     = SurfW + 3,       // s: Q(1.SF), SF = LW + 2, unsigned
  parameter integer LDiffW = SurfW + 1        // lb − la
) (
  input  wire                 clk_i,
  input  wire                 rst_ni,
  input  wire                 valid_i,
  input  wire [3*CoordW-1:0]  eye_i,         // h, LSB
  input  wire [3*DirW-1:0]    vhat_i,        // v̂, Q(2.FV)
  input  wire [3*CoordW-1:0]  c0_i,          // bounding-sphere centre, LSB
  input  wire [R2W-1:0]       r2_i,          // bounding-sphere radius², LSB², unsigned
  input  wire [2:0]           type_i,        // scene::SurfaceType
`include "rpu_surface_setup_ports.vh"
  input  wire [1:0]           piece_i,       // 0..2
  input  wire [TagW-1:0]      tag_i,
  input  wire                 sp_pred1_i,    // Sphere = 0: the sphere unit's pred1, A, B and
  input  wire [3*CoordW-1:0]  sp_a_i,        //   overflow for this item (rpu_sphere's outputs
  input  wire [3*CoordW-1:0]  sp_b_i,        //   with p1 = d = 0, inv_m = inv_s = 0), and its
  input  wire [3*DiffW-1:0]   sp_ab_i,       //   B − A
  input  wire                 sp_ovf_i,
  output wire                 valid_o,
  output wire                 pred1_o,       // the bounding sphere is met in front of the eye
  output wire                 piece_valid_o, // ... and piece_i exists (the twin's `valid`)
  output wire [1:0]           pieces_o,      // non-empty pieces of the pair (0..3)
  output wire [SW-1:0]        s_lo_o,        // Q(1.SF)
  output wire [SW-1:0]        s_hi_o,        // Q(1.SF)
  output wire [3*CoordW-1:0]  a_o,           // A', LSB
  output wire [3*DiffW-1:0]   ab_o,          // B' − A', LSB
  output wire [3*SurfW-1:0]   la_o,          // lA', llsb
  output wire [3*LDiffW-1:0]  lab_o,         // lB' − lA', llsb
  output wire                 x_negative_o,  // spiral, snail: the piece lies in x < 0
  output wire                 last_turn_o,   // spiral, snail: turn full_turns is in range
  output wire                 ovf_o,
  output wire [TagW-1:0]      tag_o
);
  localparam integer CW   = CoordW;
  localparam integer LW   = SurfW;
  localparam integer MW   = MantW;
  localparam integer SF   = SurfW + 2;
  localparam integer ShW  = 7;                 // to_local_s
  localparam integer PmW  = DiffW + MW;        // q_c · M[r][c], exact
  localparam integer SumW = PmW + 1;           // a row: |.| < 3 · 2^(CW+MW−1)
  localparam integer PeW  = LW + ConstW;       // x·cos, z·sin, exact
  localparam integer FeW  = PeW + 1;           // f_e: |.| ≤ 2^(LW+ConstW−1); |feA| + |feB|
                                               // unsigned
  localparam integer FaW  = FeW - 1;           // |f_e|, unsigned
  localparam integer Den1W = LW + 1;           // |dy| < 2^LW, |la.x| + |lb.x| ≤ 2^LW
  localparam integer Den2W = FeW;              // |feA| + |feB| ≤ 2^(FeW−1), or |dy|
  localparam integer PsW  = DiffW + SW + 1;    // (B − A)_k · s (s as a non-negative signed operand)
  localparam integer PlW  = LDiffW + SW + 1;   // (lb − la)_k · s

`include "rpu_mul_latency.vh"
  // rpu_sphere's latency (its header's formula; the FIFO depth below must cover it).
  localparam integer SpRadW   = 2 * CW + 5;
  localparam integer SpShift  = (SqrtW == 0 || SpRadW <= SqrtW) ? 0 : (SpRadW - SqrtW + 1) / 2;
  localparam integer SpStages = (SpRadW - 2 * SpShift + 1) / 2;
  localparam integer SpL1  = `RPU_MUL_LAT(DiffW, DirW, 1);
  localparam integer SpL2  = `RPU_MUL_LAT(CW + 6, CW + 6, 1);
  localparam integer SpL3  = `RPU_MUL_LAT(DirW, CW + 5, 1);
  localparam integer SpL4  = `RPU_MUL_LAT(DiffW, DiffW, 1);
  localparam integer SpLCh = `RPU_MUL_LAT(InvW + 1, 2 * DiffW + 2, 1) + 3;
  localparam integer Ls    = Sphere == 0 ? 0 : SpStages + 9 + SpL1 + SpL2 + SpL3 + SpL4 + SpLCh;
  localparam integer L1 = `RPU_MUL_LAT(DiffW, MW, 1);
  localparam integer L2 = `RPU_MUL_LAT(LW, ConstW, 1);
  localparam integer L3W = `RPU_MUL_LAT(DiffW, SW + 1, 1);
  localparam integer L3L = `RPU_MUL_LAT(LDiffW, SW + 1, 1);
  localparam integer L3 = L3W > L3L ? L3W : L3L;  // both groups run at this latency
  // The unit's latency (what the enclosing units count on; ref::surface_setup_latency).
  localparam integer Latency = Ls + 1 + L1 + 4 + L2 + 3 + SW + 2 + L3 + 2;
  // The descriptor FIFO holds every item the sphere unit has in flight (at most Ls).
  localparam integer FifoLog2 = Ls < 16 ? 4 : Ls < 32 ? 5 : Ls < 64 ? 6 : Ls < 128 ? 7 : 8;

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_surface_setup: CoordW must be in 12..40");
    if (DirFrac < 8 || DirFrac > 40) $fatal(1, "rpu_surface_setup: DirFrac must be in 8..40");
    if (SurfW < 16 || SurfW > 36) $fatal(1, "rpu_surface_setup: SurfW must be in 16..36");
    if (AngleW < 12 || AngleW > 32) $fatal(1, "rpu_surface_setup: AngleW must be in 12..32");
    if (TagW < 1) $fatal(1, "rpu_surface_setup: TagW must be >= 1");
    if (Sphere != 0 && Sphere != 1) $fatal(1, "rpu_surface_setup: Sphere must be 0 or 1");
    if (DirW != `RPU_VHATW(DirFrac) || DiffW != `RPU_DW(CoordW) || R2W != `RPU_R2W(CoordW) ||
        MantW != SurfW + 2 || ConstW != SurfW + 2 || SW != SurfW + 3 || LDiffW != SurfW + 1)
      $fatal(1, "rpu_surface_setup: derived parameters must not be overridden");
  end

  genvar k, r, e;

  // =============================================================================================
  // The sphere unit (d = 0: p1, d, inv_m, inv_s tied to zero, so α = β = 0 and never flagged)
  // and the descriptor FIFO; with Sphere = 0 the caller's sphere unit, and neither.
  // =============================================================================================
  // The descriptor word, field by field.
  localparam integer OffOrigin = 0;
  localparam integer OffM      = OffOrigin + 3 * CW;
  localparam integer OffS      = OffM + 9 * MW;
  localparam integer OffYMin   = OffS + ShW;
  localparam integer OffYMax   = OffYMin + LW;
  localparam integer OffSin    = OffYMax + LW;
  localparam integer OffCos    = OffSin + ConstW;
  localparam integer OffEnd    = OffCos + ConstW;
  localparam integer OffType   = OffEnd + AngleW;
  localparam integer OffPiece  = OffType + 3;
  localparam integer OffTag    = OffPiece + 2;
  localparam integer DescW     = OffTag + TagW;
  // The fields in the offsets' order, MSB first.
  wire [DescW-1:0] desc_in = {tag_i, piece_i, type_i, end_angle_i, end_cos_i, end_sin_i, y_max_i,
                              y_min_i, to_local_s_i, to_local_i, origin_i};

  wire               sp_valid;
  wire               sp_pred1;
  wire [3*CW-1:0]    sp_a;
  wire [3*CW-1:0]    sp_b;
  wire [3*DiffW-1:0] sp_ab;
  wire               sp_ovf;
  wire [DescW-1:0]   desc;
  generate
    if (Sphere != 0) begin : g_sphere
      wire [CW+3:0]      sp_tc;
      wire [CW+2:0]      sp_hc;
      wire [TFrac+2:0]   sp_alpha;
      wire [TFrac+2:0]   sp_beta;
      wire               sp_tag;
      rpu_sphere #(.CoordW(CoordW), .DirFrac(DirFrac), .TFrac(TFrac), .InvW(InvW), .SqrtW(SqrtW),
                   .TagW(1)) u_sphere (
        .clk_i, .rst_ni, .valid_i, .eye_i, .vhat_i, .c0_i, .r2_i, .p1_i({3*CW{1'b0}}),
        .d_i({3*DiffW{1'b0}}), .inv_m_i({InvW{1'b0}}), .inv_s_i(7'd0), .tag_i(1'b0),
        .valid_o(sp_valid), .pred1_o(sp_pred1), .tc_o(sp_tc), .half_chord_o(sp_hc), .a_o(sp_a),
        .b_o(sp_b), .ab_o(sp_ab), .alpha_o(sp_alpha), .beta_o(sp_beta), .ovf_o(sp_ovf),
        .tag_o(sp_tag));
      wire unused_sp = ^{sp_tc, sp_hc, sp_alpha, sp_beta, sp_tag, sp_pred1_i, sp_a_i, sp_b_i,
                         sp_ab_i, sp_ovf_i};

      wire             desc_wr_ready;
      wire             desc_valid;
      rpu_fifo #(.Width(DescW), .Log2Depth(FifoLog2)) u_desc (
        .clk_i, .rst_ni, .wr_valid_i(valid_i), .wr_ready_o(desc_wr_ready), .wr_data_i(desc_in),
        .rd_valid_o(desc_valid), .rd_ready_i(sp_valid), .rd_data_o(desc));
`ifdef FORMAL
      // The same promise, asserted (Yosys's formal front end has no $fatal in an always block).
      always @(*) if (rst_ni) begin
        if (valid_i) assert(desc_wr_ready);
        if (sp_valid) assert(desc_valid);
      end
`elsif SYNTHESIS
      wire unused_fifo = ^{desc_wr_ready, desc_valid};
`else
      // The FIFO never fills (it holds at most Ls items) and always has the item the sphere unit
      // delivers. Checked only out of reset: at an edge inside the reset the registers still hold
      // their power-up values (live_q included), which an X-seeded simulation makes random.
      reg live_q;  // out of reset
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) live_q <= 1'b0;
        else begin
          live_q <= 1'b1;
          if (live_q && valid_i && !desc_wr_ready)
            $fatal(1, "rpu_surface_setup: descriptor FIFO full");
          if (live_q && sp_valid && !desc_valid)
            $fatal(1, "rpu_surface_setup: descriptor FIFO empty at the sphere unit's output");
        end
      end
`endif

    end else begin : g_ext_sphere
      // The caller's sphere unit: its results and the descriptor arrive together.
      assign sp_valid = valid_i;
      assign sp_pred1 = sp_pred1_i;
      assign sp_a     = sp_a_i;
      assign sp_b     = sp_b_i;
      assign sp_ab    = sp_ab_i;
      assign sp_ovf   = sp_ovf_i;
      assign desc     = desc_in;
      wire unused_ext = ^{eye_i, vhat_i, c0_i, r2_i};
    end
  endgenerate

  // =============================================================================================
  // Stage 1: q = X − origin for X = A, B (exact, DiffW bits); the type decoded.
  // =============================================================================================
  wire [3*CW-1:0] origin = desc[OffOrigin +: 3*CW];
  wire [AngleW-1:0] end_angle = desc[OffEnd +: AngleW];
  wire [2:0]      stype  = desc[OffType +: 3];
  wire            az     = stype == 3'd2 || stype == 3'd3;  // spiral, snail: azimuth cuts
  wire            end_nz = |end_angle;
  wire            end_lo = ~end_angle[AngleW-1];             // end angle below half a turn
  wire [6*DiffW-1:0] q;  // {B − origin, A − origin}
  rpu_surface_vsub #(.Count(6), .InW(CW)) u_q (.a_i({sp_b, sp_a}), .b_i({2{origin}}), .d_o(q));

  // The context from here to the local transform's sums:
  // {tag, piece, az, end_nz, end_lo, cos, sin, y_max, y_min, s, A, AB, pred1, sovf}.
  localparam integer C1W  = TagW + 2 + 3 + 2 * ConstW + 2 * LW + ShW + 3 * CW + 3 * DiffW + 2;
  localparam integer C1SO = 2 + 3 * DiffW + 3 * CW;  // s in the context
  wire               valid1_q;
  wire [6*DiffW-1:0] q1_q;
  wire [9*MW-1:0]    m1_q;
  wire [C1W-1:0]     c1_q;
  rpu_stage #(.W(6*DiffW + 9*MW + C1W)) u_s1 (
    .clk_i, .rst_ni, .valid_i(sp_valid),
    .d_i({q, desc[OffM +: 9*MW], desc[OffTag +: TagW], desc[OffPiece +: 2], az, end_nz, end_lo,
          desc[OffCos +: ConstW], desc[OffSin +: ConstW], desc[OffYMax +: LW], desc[OffYMin +: LW],
          desc[OffS +: ShW], sp_a, sp_ab, sp_pred1, sp_ovf}),
    .valid_o(valid1_q), .q_o({q1_q, m1_q, c1_q}));

  // =============================================================================================
  // The products q_c · M[r][c] for A (e = 0) and B (e = 1), exact.
  // =============================================================================================
  wire [18*PmW-1:0] pm;  // product (e, r, c) at index 9e + 3r + c
  wire              m1_valid;
  wire [C1W-1:0]    c2;
  rpu_mul_vec #(.Count(18), .AW(DiffW), .BW(MW), .Signed(1), .TagW(C1W)) u_pm (
    .clk_i, .rst_ni, .valid_i(valid1_q),
    .a_i({{3{q1_q[3*DiffW +: 3*DiffW]}}, {3{q1_q[0 +: 3*DiffW]}}}), .b_i({2{m1_q}}),
    .tag_i(c1_q), .valid_o(m1_valid), .p_o(pm), .tag_o(c2));

  // =============================================================================================
  // Stage 2: the row sums (exact in SumW bits, rpu_add3). Stages 3, 4: the arithmetic right
  // shift by s (fixed::truncate), by 8·s[6:3] then by s[2:0] (a shift of SumW or more leaves the
  // sign). The context rides beside them.
  // =============================================================================================
  wire [6*SumW-1:0] rs, v3, v4;      // row (e, r) at index 3e + r
  wire [6*SumW-1:0] v2_q, v3_q, v4_q;
  wire [C1W-1:0]    c2_q, c3_q, c4_q;
  wire              valid2_q, valid3_q, valid4_q;
  wire [ShW-1:0]    sh2 = c2_q[C1SO +: ShW];
  wire [ShW-1:0]    sh3 = c3_q[C1SO +: ShW];
  generate
    for (r = 0; r < 6; r = r + 1) begin : g_row
      wire [3*PmW-1:0]       p  = pm[3*r*PmW +: 3*PmW];
      wire signed [SumW-1:0] x2 = v2_q[r*SumW +: SumW];
      wire signed [SumW-1:0] x3 = v3_q[r*SumW +: SumW];
      rpu_add3 #(.W(SumW)) u_sum (
        .a_i({p[PmW-1], p[0 +: PmW]}), .b_i({p[2*PmW-1], p[PmW +: PmW]}),
        .c_i({p[3*PmW-1], p[2*PmW +: PmW]}), .s_o(rs[r*SumW +: SumW]));
      assign v3[r*SumW +: SumW] = x2 >>> {sh2[ShW-1:3], 3'b000};
      assign v4[r*SumW +: SumW] = x3 >>> sh3[2:0];
    end
  endgenerate
  wire unused_sh = ^{sh2[2:0], sh3[ShW-1:3]};
  rpu_stage #(.W(6*SumW + C1W)) u_s2 (
    .clk_i, .rst_ni, .valid_i(m1_valid), .d_i({rs, c2}), .valid_o(valid2_q), .q_o({v2_q, c2_q}));
  rpu_stage #(.W(6*SumW + C1W)) u_s3 (
    .clk_i, .rst_ni, .valid_i(valid2_q), .d_i({v3, c2_q}), .valid_o(valid3_q), .q_o({v3_q, c3_q}));
  rpu_stage #(.W(6*SumW + C1W)) u_s4 (
    .clk_i, .rst_ni, .valid_i(valid3_q), .d_i({v4, c3_q}), .valid_o(valid4_q), .q_o({v4_q, c4_q}));

  // =============================================================================================
  // Stage 5: saturation to LW bits (fixed::saturate), flagged under pred1: la, lb.
  // =============================================================================================
  wire [6*LW-1:0] lsat;  // {lb, la}
  wire [5:0]      clamped;
  generate
    for (k = 0; k < 6; k = k + 1) begin : g_sat
      wire [SumW-1:0] v   = v4_q[k*SumW +: SumW];
      wire            fit = (&v[SumW-1:LW-1]) | ~(|v[SumW-1:LW-1]);
      assign lsat[k*LW +: LW] = fit ? v[LW-1:0] : {v[SumW-1], {(LW-1){~v[SumW-1]}}};
      assign clamped[k] = ~fit;
    end
  endgenerate
  wire unused_sh4 = ^c4_q[C1SO +: ShW];  // s is spent

  // The context from here to the end-plane products' outputs:
  // {tag, piece, az, end_nz, end_lo, y_max, y_min, A, AB, pred1, ovf}, then {lb, la}.
  localparam integer C5W = TagW + 2 + 3 + 2 * LW + 3 * CW + 3 * DiffW + 2;
  localparam integer C6W = C5W + 6 * LW;
  wire        pred1_4 = c4_q[1];
  wire [C5W-1:0] c5 = {c4_q[C1W-1 -: TagW + 5], c4_q[C1SO + ShW +: 2*LW], c4_q[2 +: C1SO - 2],
                       pred1_4, c4_q[0] | (pred1_4 & (|clamped))};
  wire [2*ConstW-1:0] cs4 = c4_q[C1SO + ShW + 2*LW +: 2*ConstW];  // {cos, sin}
  wire            valid5_q;
  wire [6*LW-1:0] l5_q;
  wire [2*ConstW-1:0] cs5_q;
  wire [C5W-1:0]  c5_q;
  rpu_stage #(.W(6*LW + 2*ConstW + C5W)) u_s5 (
    .clk_i, .rst_ni, .valid_i(valid4_q), .d_i({lsat, cs4, c5}), .valid_o(valid5_q),
    .q_o({l5_q, cs5_q, c5_q}));

  // =============================================================================================
  // The end-plane products la.x·cos, la.z·sin, lb.x·cos, lb.z·sin (exact), index 2e + {0, 1}.
  // =============================================================================================
  wire [ConstW-1:0]    sin5 = cs5_q[0 +: ConstW];
  wire [ConstW-1:0]    cos5 = cs5_q[ConstW +: ConstW];
  wire [4*PeW-1:0] pe;
  wire             m2_valid;
  wire [C6W-1:0]   c6;
  rpu_mul_vec #(.Count(4), .AW(LW), .BW(ConstW), .Signed(1), .TagW(C6W)) u_pe (
    .clk_i, .rst_ni, .valid_i(valid5_q),
    .a_i({l5_q[5*LW +: LW], l5_q[3*LW +: LW], l5_q[2*LW +: LW], l5_q[0 +: LW]}),
    .b_i({sin5, cos5, sin5, cos5}), .tag_i({c5_q, l5_q}), .valid_o(m2_valid), .p_o(pe),
    .tag_o(c6));

  // =============================================================================================
  // Stage E1: f_e = x·cos − z·sin at la and lb; the slab differences; |la.x|, |lb.x|; lb − la.
  // =============================================================================================
  // c6 = {tag, piece, az, end_nz, end_lo, y_max, y_min, A, AB, pred1, ovf, lb, la}
  wire [3*LW-1:0] la6   = c6[0 +: 3*LW];
  wire [3*LW-1:0] lb6   = c6[3*LW +: 3*LW];
  wire [C5W-1:0]  ctx6  = c6[6*LW +: C5W];
  wire [LW-1:0]   ymin6 = ctx6[2 + 3*DiffW + 3*CW +: LW];
  wire [LW-1:0]   ymax6 = ctx6[2 + 3*DiffW + 3*CW + LW +: LW];
  wire [2*FeW-1:0] fe;
  rpu_surface_vsub #(.Count(2), .InW(PeW)) u_fe (
    .a_i({pe[2*PeW +: PeW], pe[0 +: PeW]}), .b_i({pe[3*PeW +: PeW], pe[PeW +: PeW]}), .d_o(fe));
  wire signed [LW:0] ya   = {la6[2*LW-1], la6[LW +: LW]};
  wire signed [LW:0] yb   = {lb6[2*LW-1], lb6[LW +: LW]};
  wire signed [LW:0] ylo  = {ymin6[LW-1], ymin6};
  wire signed [LW:0] yhi  = {ymax6[LW-1], ymax6};
  // {dyp, dyn, n_min, n_max, m_max, m_min}: lb.y − la.y, la.y − lb.y, y_min − la.y, y_max − la.y,
  // la.y − y_max, la.y − y_min (exact, LW + 1 bits each).
  wire [6*(LW+1)-1:0] slab = {yb - ya, ya - yb, ylo - ya, yhi - ya, ya - yhi, ya - ylo};
  wire signed [LW-1:0] xa = la6[0 +: LW];
  wire signed [LW-1:0] xb = lb6[0 +: LW];
  // |x| ≤ 2^(LW−1) fits LW bits unsigned (the minimum negates to itself read as unsigned).
  wire [LW-1:0] xa_abs = xa[LW-1] ? -xa : xa;
  wire [LW-1:0] xb_abs = xb[LW-1] ? -xb : xb;
  wire [3*LDiffW-1:0] lab;
  rpu_surface_vsub #(.Count(3), .InW(LW)) u_lab (.a_i(lb6), .b_i(la6), .d_o(lab));

  // The context from here to the dividers' inputs:
  // {tag, piece, az, end_nz, end_lo, A, AB, pred1, ovf}, then {la, lb − la}.
  localparam integer C7W = TagW + 2 + 3 + 3 * CW + 3 * DiffW + 2;
  localparam integer CeW = C7W + 3 * LW + 3 * LDiffW;
  wire [C7W-1:0] c7 = {ctx6[C5W-1 -: TagW + 5], ctx6[0 +: 3*CW + 3*DiffW + 2]};
  wire unused_y6 = ^{ymin6, ymax6, lb6[2*LW +: LW], la6[2*LW +: LW]};

  wire                valid7_q;
  wire [2*FeW-1:0]    fe7_q;
  wire [6*(LW+1)-1:0] slab7_q;
  wire [LW-1:0]       xa7_q, xb7_q;
  wire                xan7_q, xbn7_q;
  wire [CeW-1:0]      c7_q;
  rpu_stage #(.W(2*FeW + 6*(LW+1) + 2*LW + 2 + CeW)) u_e1 (
    .clk_i, .rst_ni, .valid_i(m2_valid),
    .d_i({fe, slab, xa_abs, xb_abs, xa[LW-1], xb[LW-1], c7, la6, lab}),
    .valid_o(valid7_q), .q_o({fe7_q, slab7_q, xa7_q, xb7_q, xan7_q, xbn7_q, c7_q}));

  // =============================================================================================
  // Stage E2: |f_e|; the slab's operands chosen by the sign of dy; |la.x| + |lb.x|.
  // =============================================================================================
  wire signed [FeW-1:0] fea = fe7_q[0 +: FeW];
  wire signed [FeW-1:0] feb = fe7_q[FeW +: FeW];
  wire [FeW-1:0] fea_neg_v = -fea;
  wire [FeW-1:0] feb_neg_v = -feb;
  // |f_e| ≤ 2^(FeW−2): FaW bits unsigned.
  wire [FaW-1:0] fea_abs = fea[FeW-1] ? fea_neg_v[FaW-1:0] : fea[FaW-1:0];
  wire [FaW-1:0] feb_abs = feb[FeW-1] ? feb_neg_v[FaW-1:0] : feb[FaW-1:0];
  wire unused_fe = ^{fea_neg_v[FeW-1], feb_neg_v[FeW-1]};
  wire [LW:0] m_min = slab7_q[0*(LW+1) +: LW+1];
  wire [LW:0] m_max = slab7_q[1*(LW+1) +: LW+1];
  wire [LW:0] n_max = slab7_q[2*(LW+1) +: LW+1];
  wire [LW:0] n_min = slab7_q[3*(LW+1) +: LW+1];
  wire [LW:0] dyn   = slab7_q[4*(LW+1) +: LW+1];
  wire [LW:0] dyp   = slab7_q[5*(LW+1) +: LW+1];
  wire        dy_neg = dyp[LW];
  wire [LW:0] den_s  = dy_neg ? dyn : dyp;     // |dy|, non-negative
  wire [LW:0] num_lo = dy_neg ? m_max : n_min;  // y_min − y or y − y_max along the ray
  wire [LW:0] num_hi = dy_neg ? m_min : n_max;
  wire        dy_zero = ~(|dyp);
  wire        in_slab = (n_min[LW] | ~(|n_min)) & ~n_max[LW];  // y_min ≤ la.y ≤ y_max
  wire [LW:0] den_x  = {1'b0, xa7_q} + {1'b0, xb7_q};          // ≤ 2^LW

  wire          valid8_q;
  wire [FaW-1:0] fea8_q, feb8_q;
  wire          fean8_q, febn8_q;
  wire [LW:0]   dens8_q, numlo8_q, numhi8_q;
  wire          dyz8_q, ins8_q;
  wire [LW:0]   denx8_q;
  wire [LW-1:0] xa8_q;
  wire          xan8_q, xbn8_q;
  wire [CeW-1:0] c8_q;
  rpu_stage #(.W(2*FaW + 2 + 3*(LW+1) + 2 + (LW+1) + LW + 2 + CeW)) u_e2 (
    .clk_i, .rst_ni, .valid_i(valid7_q),
    .d_i({fea_abs, feb_abs, fea[FeW-1], feb[FeW-1], den_s, num_lo, num_hi, dy_zero, in_slab,
          den_x, xa7_q, xan7_q, xbn7_q, c7_q}),
    .valid_o(valid8_q),
    .q_o({fea8_q, feb8_q, fean8_q, febn8_q, dens8_q, numlo8_q, numhi8_q, dyz8_q, ins8_q, denx8_q,
          xa8_q, xan8_q, xbn8_q, c8_q}));

  // =============================================================================================
  // Stage E3: the divider operands by type; |feA| + |feB|; the slab's clamp tests
  // (clamped_ratio: 0 when num ≤ 0, 1 when num ≥ den; dy = 0: lo = 0, hi = in_slab).
  // =============================================================================================
  // c8 = {tag, piece, az, end_nz, end_lo, A, AB, pred1, ovf, la, lab}
  wire       az8     = c8_q[CeW-TagW-3];
  wire       endnz8  = c8_q[CeW-TagW-4];
  wire [FeW-1:0] den_e = {1'b0, fea8_q} + {1'b0, feb8_q};
  wire signed [LW+1:0] lo_d = {numlo8_q[LW], numlo8_q} - {1'b0, dens8_q};
  wire signed [LW+1:0] hi_d = {numhi8_q[LW], numhi8_q} - {1'b0, dens8_q};
  wire le0_lo = numlo8_q[LW] | ~(|numlo8_q);
  wire le0_hi = numhi8_q[LW] | ~(|numhi8_q);
  wire z_lo   = dyz8_q | le0_lo;
  wire o_lo   = ~z_lo & ~lo_d[LW+1];
  wire z_hi   = dyz8_q ? ~ins8_q : le0_hi;
  wire o_hi   = dyz8_q ? ins8_q : ~le0_hi & ~hi_d[LW+1];
  wire has_x  = xan8_q ^ xbn8_q;
  wire has_e  = endnz8 & (fean8_q ^ febn8_q);
  // Operands (when used: 0 < num < den for the slab; |fA| ≤ |fA| + |fB| for a cut).
  wire [Den1W-1:0] num1 = az8 ? {1'b0, xa8_q} : numlo8_q;
  wire [Den1W-1:0] den1 = az8 ? denx8_q : dens8_q;
  wire [Den2W-1:0] num2 = az8 ? {1'b0, fea8_q} : {{(Den2W-LW-1){1'b0}}, numhi8_q};
  wire [Den2W-1:0] den2 = az8 ? den_e : {{(Den2W-LW-1){1'b0}}, dens8_q};

  // The context through the dividers: {tag, piece, az, end_nz, end_lo, has_x, has_e, x_a < 0,
  // x_b < 0, f_eA < 0, f_eB < 0, z_lo, o_lo, z_hi, o_hi, A, AB, pred1, ovf, la, lab}.
  localparam integer CdW = CeW + 10;
  wire             valid9_q;
  wire [Den1W-1:0] num1_9_q, den1_9_q;
  wire [Den2W-1:0] num2_9_q, den2_9_q;
  wire [CdW-1:0]   c9_q;
  rpu_stage #(.W(2*Den1W + 2*Den2W + CdW)) u_e3 (
    .clk_i, .rst_ni, .valid_i(valid8_q),
    .d_i({num1, den1, num2, den2, c8_q[CeW-1 -: TagW + 5], has_x, has_e, xan8_q, xbn8_q, fean8_q,
          febn8_q, z_lo, o_lo, z_hi, o_hi, c8_q[0 +: CeW - TagW - 5]}),
    .valid_o(valid9_q), .q_o({num1_9_q, den1_9_q, num2_9_q, den2_9_q, c9_q}));

  // =============================================================================================
  // The dividers: 1 takes the slab's lo or the x = 0 cut, 2 the slab's hi or the end-plane cut.
  // =============================================================================================
  wire           d1_valid, d2_valid;
  wire [SW-1:0]  q1, q2;
  wire [CdW-1:0] cd;
  wire           d2_tag;
  rpu_div #(.NumW(Den1W + SF), .DenW(Den1W), .QuotW(SW), .TagW(CdW)) u_div1 (
    .clk_i, .rst_ni, .valid_i(valid9_q), .num_i({num1_9_q, {SF{1'b0}}}), .den_i(den1_9_q),
    .tag_i(c9_q), .valid_o(d1_valid), .quot_o(q1), .tag_o(cd));
  rpu_div #(.NumW(Den2W + SF), .DenW(Den2W), .QuotW(SW), .TagW(1)) u_div2 (
    .clk_i, .rst_ni, .valid_i(valid9_q), .num_i({num2_9_q, {SF{1'b0}}}), .den_i(den2_9_q),
    .tag_i(1'b0), .valid_o(d2_valid), .quot_o(q2), .tag_o(d2_tag));
  wire unused_d2 = ^{d2_valid, d2_tag};  // the same pipeline as u_div1

  // =============================================================================================
  // Stage D1: the bounds: the slab's clamped lo, hi, or the raw cuts; their order and tests.
  // =============================================================================================
  // cd = {tag, piece, az, end_nz, end_lo, has_x, has_e, xan, xbn, fean, febn, z_lo, o_lo, z_hi,
  //       o_hi, A, AB, pred1, ovf, la, lab}
  localparam integer CxW = CeW - TagW - 5;  // {A, AB, pred1, ovf, la, lab}
  localparam integer CdAzO = CdW - TagW - 3;  // az in cd
  localparam [SW-1:0] One = {1'b1, {SF{1'b0}}};
  wire       azd  = cd[CdAzO];
  wire       zlod = cd[CxW + 3];
  wire       olod = cd[CxW + 2];
  wire       zhid = cd[CxW + 1];
  wire       ohid = cd[CxW + 0];
  wire [SW-1:0] v1 = azd | ~(zlod | olod) ? q1 : zlod ? {SW{1'b0}} : One;
  wire [SW-1:0] v2 = azd | ~(zhid | ohid) ? q2 : zhid ? {SW{1'b0}} : One;

  wire          valid10_q;
  wire [SW-1:0] v1_10_q, v2_10_q;
  wire          lt10_q, eq10_q, z1_10_q, z2_10_q, o1_10_q, o2_10_q;
  wire [CdW-5:0] c10_q;  // the flags z_lo .. o_hi are spent
  rpu_stage #(.W(2*SW + 6 + CdW - 4)) u_d1 (
    .clk_i, .rst_ni, .valid_i(d1_valid),
    .d_i({v1, v2, v1 < v2, v1 == v2, ~(|v1), ~(|v2), v1 == One, v2 == One,
          cd[CdW-1 -: TagW + 11], cd[0 +: CxW]}),
    .valid_o(valid10_q),
    .q_o({v1_10_q, v2_10_q, lt10_q, eq10_q, z1_10_q, z2_10_q, o1_10_q, o2_10_q, c10_q}));

  // =============================================================================================
  // Stage D2: the pieces. Four bounds b0 ≤ b1 ≤ b2 ≤ b3 with empty intervals where the twin has
  // fewer: slab [lo, hi, hi, hi]; both cuts [0, min, max, 1]; one cut [0, c, 1, 1]; none
  // [0, 1, 1, 1]. Interval k is a piece iff b_k < b_{k+1}; piece_i selects the piece_i-th one.
  // =============================================================================================
  // c10 = {tag, piece, az, end_nz, end_lo, has_x, has_e, xan, xbn, fean, febn, A, AB, pred1,
  //        ovf, la, lab}
  localparam integer OffPred = 3 * LW + 3 * LDiffW + 1;  // pred1 in the {A .. lab} block
  localparam integer C10AzO    = CdAzO - 4;  // c10 drops the four flags z_lo .. o_hi below az
  localparam integer C10PieceO = C10AzO + 1;
  wire [1:0] piece10 = c10_q[C10PieceO +: 2];
  wire       az10    = c10_q[C10AzO];
  wire       hx10    = c10_q[CxW + 5];
  wire       he10    = c10_q[CxW + 4];
  wire       pred10  = c10_q[OffPred];
  reg [SW-1:0] b0;
  reg [SW-1:0] b1;
  reg [SW-1:0] b2;
  reg [SW-1:0] b3;
  reg [2:0]    ne;  // ne[k]: b_k < b_{k+1}
  always @* begin
    if (!az10) begin
      b0 = v1_10_q;
      b1 = v2_10_q;
      b2 = v2_10_q;
      b3 = v2_10_q;
      ne = {2'b00, lt10_q};
    end else if (hx10 && he10) begin
      b0 = {SW{1'b0}};
      b1 = lt10_q ? v1_10_q : v2_10_q;
      b2 = lt10_q ? v2_10_q : v1_10_q;
      b3 = One;
      ne = {lt10_q ? ~o2_10_q : ~o1_10_q, ~eq10_q, lt10_q ? ~z1_10_q : ~z2_10_q};
    end else if (hx10 || he10) begin  // one cut: the x = 0 cut, else the end-plane cut
      b0 = {SW{1'b0}};
      b1 = hx10 ? v1_10_q : v2_10_q;
      b2 = One;
      b3 = One;
      ne = {1'b0, hx10 ? ~o1_10_q : ~o2_10_q, hx10 ? ~z1_10_q : ~z2_10_q};
    end else begin
      b0 = {SW{1'b0}};
      b1 = One;
      b2 = One;
      b3 = One;
      ne = 3'b001;
    end
  end
  wire [1:0] before1 = {1'b0, ne[0]};
  wire [1:0] before2 = {1'b0, ne[0]} + {1'b0, ne[1]};
  wire       sel0 = ne[0] & (piece10 == 2'd0);
  wire       sel1 = ne[1] & (piece10 == before1);
  wire       sel2 = ne[2] & (piece10 == before2);
  wire [1:0] count = before2 + {1'b0, ne[2]};
  wire [SW-1:0] s_lo = sel0 ? b0 : sel1 ? b1 : b2;
  wire [SW-1:0] s_hi = sel0 ? b1 : sel1 ? b2 : b3;

  // The context from here to the piece products' outputs: {tag, pred1, piece_valid, pieces, s_lo,
  // s_hi, A, ovf, la}; the branch inputs {az, end_nz, end_lo, has_x, has_e, xan, xbn, fean, febn,
  // cut_x, cut_e} for stage D3; the products' operands AB, lab.
  localparam integer CpW = TagW + 4 + 2 * SW + 3 * CW + 1 + 3 * LW;
  wire [3*CW-1:0]    a10   = c10_q[OffPred + 1 + 3*DiffW +: 3*CW];
  wire [3*DiffW-1:0] ab10  = c10_q[OffPred + 1 +: 3*DiffW];
  wire               ovf10 = c10_q[OffPred - 1];
  wire [3*LW-1:0]    la10  = c10_q[3*LDiffW +: 3*LW];
  wire [3*LDiffW-1:0] lab10 = c10_q[0 +: 3*LDiffW];

  wire                valid11_q;
  wire [SW-1:0]       slo11_q, shi11_q;
  wire [3*DiffW-1:0]  ab11_q;
  wire [3*LDiffW-1:0] lab11_q;
  wire [CpW-1:0]      c11_q;
  wire [8:0]          br11_q;
  wire [SW-1:0]       cx11_q, ce11_q;
  // br: {az, end_nz, end_lo, has_x, has_e, xan, xbn, fean, febn}; cx, ce: the cuts.
  rpu_stage #(.W(2*SW + 3*DiffW + 3*LDiffW + CpW + 9 + 2*SW)) u_d2 (
    .clk_i, .rst_ni, .valid_i(valid10_q),
    .d_i({s_lo, s_hi, ab10, lab10, c10_q[CdW-5 -: TagW], pred10, pred10 & (sel0 | sel1 | sel2),
          pred10 ? count : 2'd0, s_lo, s_hi, a10, ovf10, la10, c10_q[CxW +: 9], v1_10_q,
          v2_10_q}),
    .valid_o(valid11_q),
    .q_o({slo11_q, shi11_q, ab11_q, lab11_q, c11_q, br11_q, cx11_q, ce11_q}));

  // =============================================================================================
  // Stage D3 (beside the piece products): the piece's azimuth branch. A piece ending at or before
  // a cut lies on A's side of that plane, any other on B's.
  // =============================================================================================
  wire az11   = br11_q[8];
  wire endnz11 = br11_q[7];
  wire endlo11 = br11_q[6];
  wire hx11   = br11_q[5];
  wire he11   = br11_q[4];
  wire xan11  = br11_q[3];
  wire xbn11  = br11_q[2];
  wire fean11 = br11_q[1];
  wire febn11 = br11_q[0];
  wire x_neg  = hx11 && shi11_q > cx11_q ? xbn11 : xan11;
  wire e_neg  = he11 && shi11_q > ce11_q ? febn11 : fean11;
  wire last   = endnz11 & (endlo11 ? ~x_neg & e_neg : ~x_neg | e_neg);

  // The two branch bits wait L3 cycles for the products (L3 >= 2).
  reg [2*L3-1:0] br_q;
  always @(posedge clk_i) br_q <= {br_q[2*L3-3:0], az11 & x_neg, az11 & last};
  wire [1:0] br_out = br_q[2*L3-1 -: 2];

  // =============================================================================================
  // The piece products (B − A)_k·s and (lb − la)_k·s at s_lo (f = 0) and s_hi (f = 1), exact.
  // =============================================================================================
  wire [6*PsW-1:0] ps;   // index 3f + k
  wire [6*PlW-1:0] pl;
  wire             m3_valid;
  wire [CpW-1:0]   c12;
  wire             m3l_valid, m3l_tag;
  wire [SW:0]      slo_s = {1'b0, slo11_q};  // s as a non-negative signed operand
  wire [SW:0]      shi_s = {1'b0, shi11_q};
  rpu_mul_vec #(.Count(6), .AW(DiffW), .BW(SW + 1), .Signed(1), .TagW(CpW), .Latency(L3)) u_ps (
    .clk_i, .rst_ni, .valid_i(valid11_q), .a_i({2{ab11_q}}), .b_i({{3{shi_s}}, {3{slo_s}}}),
    .tag_i(c11_q), .valid_o(m3_valid), .p_o(ps), .tag_o(c12));
  rpu_mul_vec #(.Count(6), .AW(LDiffW), .BW(SW + 1), .Signed(1), .TagW(1), .Latency(L3)) u_pl (
    .clk_i, .rst_ni, .valid_i(valid11_q), .a_i({2{lab11_q}}), .b_i({{3{shi_s}}, {3{slo_s}}}),
    .tag_i(1'b0), .valid_o(m3l_valid), .p_o(pl), .tag_o(m3l_tag));
  wire unused_pl = ^{m3l_valid, m3l_tag};  // the same pipeline as u_ps

  // =============================================================================================
  // Stage P1: A' = A + floor((B − A)·s_lo·2^-SF), B' likewise at s_hi; lA', lB' on la → lb.
  // s ∈ [0, 1], so each end lies between A and B (la and lb): CW (LW) bits hold it exactly.
  // =============================================================================================
  // c12 = {tag, pred1, piece_valid, pieces, s_lo, s_hi, A, ovf, la}
  wire [3*LW-1:0] la12 = c12[0 +: 3*LW];
  wire [3*CW-1:0] a12  = c12[3*LW + 1 +: 3*CW];
  wire [6*CW-1:0] wend;  // {B', A'}
  wire [6*LW-1:0] lend;  // {lB', lA'}
  generate
    for (e = 0; e < 2; e = e + 1) begin : g_end
      for (k = 0; k < 3; k = k + 1) begin : g_endk
        wire signed [PsW-1:0]  pw  = ps[(3*e+k)*PsW +: PsW];
        wire signed [PlW-1:0]  plk = pl[(3*e+k)*PlW +: PlW];
        wire signed [CW-1:0]   ak  = a12[k*CW +: CW];
        wire signed [LW-1:0]   lk  = la12[k*LW +: LW];
        // floor(p·2^-SF) has DiffW + 2 (LDiffW + 2) bits; the sums one more.
        wire signed [DiffW+2:0]  sw = {pw[PsW-1], pw[PsW-1:SF]} + {{(DiffW+3-CW){ak[CW-1]}}, ak};
        wire signed [LDiffW+2:0] sl = {plk[PlW-1], plk[PlW-1:SF]} +
                                      {{(LDiffW+3-LW){lk[LW-1]}}, lk};
        assign wend[(3*e+k)*CW +: CW] = sw[CW-1:0];
        assign lend[(3*e+k)*LW +: LW] = sl[LW-1:0];
        wire unused_p = ^{pw[SF-1:0], plk[SF-1:0], sw[DiffW+2:CW], sl[LDiffW+2:LW]};
      end
    end
  endgenerate

  // {tag, pred1, piece_valid, pieces, s_lo, s_hi, ovf, x_negative, last_turn}
  localparam integer CoW = TagW + 4 + 2 * SW + 1 + 2;
  // c14, LSB first: last_turn, x_negative, ovf, s_hi, s_lo, pieces, piece_valid, pred1, tag.
  localparam integer C14PiecesO = 3 + 2 * SW;
  localparam integer C14TagO    = C14PiecesO + 4;
  wire [6*CW-1:0] wend13_q;
  wire [6*LW-1:0] lend13_q;
  wire [CoW-1:0]  c13_q;
  wire            valid13_q;
  rpu_stage #(.W(6*CW + 6*LW + CoW)) u_p1 (
    .clk_i, .rst_ni, .valid_i(m3_valid),
    .d_i({wend, lend, c12[CpW-1 -: TagW + 4 + 2*SW], c12[3*LW], br_out}),
    .valid_o(valid13_q), .q_o({wend13_q, lend13_q, c13_q}));

  // =============================================================================================
  // Stage P2: B' − A', lB' − lA' (exact); the outputs registered.
  // =============================================================================================
  wire [3*DiffW-1:0]  wd;
  wire [3*LDiffW-1:0] ld;
  rpu_surface_vsub #(.Count(3), .InW(CW)) u_wd (
    .a_i(wend13_q[3*CW +: 3*CW]), .b_i(wend13_q[0 +: 3*CW]), .d_o(wd));
  rpu_surface_vsub #(.Count(3), .InW(LW)) u_ld (
    .a_i(lend13_q[3*LW +: 3*LW]), .b_i(lend13_q[0 +: 3*LW]), .d_o(ld));

  // c14 = {tag, pred1, piece_valid, pieces, s_lo, s_hi, ovf, x_negative, last_turn}
  wire [CoW-1:0] c14_q;
  rpu_stage #(.W(3*CW + 3*DiffW + 3*LW + 3*LDiffW + CoW)) u_p2 (
    .clk_i, .rst_ni, .valid_i(valid13_q),
    .d_i({wend13_q[0 +: 3*CW], wd, lend13_q[0 +: 3*LW], ld, c13_q}),
    .valid_o, .q_o({a_o, ab_o, la_o, lab_o, c14_q}));
  assign tag_o         = c14_q[C14TagO +: TagW];
  assign pred1_o       = c14_q[C14TagO - 1];
  assign piece_valid_o = c14_q[C14PiecesO + 2];
  assign pieces_o      = c14_q[C14PiecesO +: 2];
  assign s_lo_o        = c14_q[3 + SW +: SW];
  assign s_hi_o        = c14_q[3 +: SW];
  assign ovf_o         = c14_q[2];
  assign x_negative_o  = c14_q[1];
  assign last_turn_o   = c14_q[0];
  `RPU_LATENCY_CHECK(Latency, "rpu_surface_setup")
endmodule

`default_nettype wire
