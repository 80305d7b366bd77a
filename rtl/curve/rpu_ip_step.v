// rpu_ip_step: one step of the iterative process (docs/algorithms.md §1.2 step 3) in the chord's
// frame, twin of rpu::ref::ip_step (docs/fixed-point.md, "The candidate in the chord's frame").
// The step carries the frame's polynomials at its interval start m0 = τ (fs_i: X, Y, T, C2, S2
// at full precision, W and each flat guide's A with their slopes) beside the pair's constants
// (pc_i: x1, y1, β, c2b, s2b, w2, a1,2, a2,2). With D = 2^(N − N1·k), candidate j = 1..J−1 gets
//   Q_j = Q + (j·q1)·D            (X, Y, T, C2, S2)
//   Q_j = Q + (j·S)·D + (j²·q2)·D²  (W, A1, A2)
// floored and saturated to rpu_candidate's ports; with md_0 = lo.md and md_J = hi.md the pair
// sums sd_j = md_j + md_{j+1} go through a lowest-index argmin η, and the next state is
//   τ' = τ + η·D,  lo'.md = md_η,  hi'.md = md_{η+1},  Q' = Q_η,  S' = S + (2η·q2)·D.
// Step = k wired in (unrolled pipeline), or Step = 0: k comes with the item (iterative form:
// variable shifts, rpu_candidate with Fo = 0). The state, constants and context wait in two
// slot-indexed RAMs while the candidates run (candidate 1 carries the slot): side band A, read as
// the candidates leave, and side band B, read after the multiples of η. Fixed latency: three
// input stages, the candidate's, the pair sums, the compares and η, the η multiples, the moved
// state (two stages).
`default_nettype none
`include "rpu_widths.vh"

module rpu_ip_step #(
  parameter integer TFrac    = 24,  // fraction bits of t (8..48)
  parameter integer SqrtW    = 0,   // widest square-root radicand; 0 = exact
  parameter integer N        = 16,  // result bits of τ (1..40)
  parameter integer N1       = 2,   // bits per step (1..8), N % N1 == 0
  parameter integer Metric   = 0,   // 0: md = |o|, 1: |o|²
  parameter integer Step     = 1,   // k of this unit (1..N/N1), or 0: taken from k_i
  parameter integer CtxW     = 1,   // width of the context passed through
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer K    = N / N1,
  parameter integer J    = 1 << N1,
  parameter integer KW   = 8,
  parameter integer MdW  = Metric == 0 ? `RPU_FOMAX + 3 : 2 * `RPU_FOMAX + 3,
  parameter integer StW  = N + 2 * MdW,                    // {τ, lo.md, hi.md}
  parameter integer XW   = `RPU_CXW,
  parameter integer TW   = `RPU_TW(TFrac),
  parameter integer CaW  = `RPU_FCAW(TFrac),
  parameter integer W1W  = `RPU_FW1W(N),
  parameter integer W2W  = `RPU_FW2W,
  parameter integer A1W  = W1W - (`RPU_FW - `RPU_FG),
  parameter integer A2W  = W2W - (`RPU_FW - `RPU_FG),
  // The frame state at m0 (FsW) and the pair's constants (PcW).
  parameter integer XSW  = XW + N + 1,
  parameter integer TSW  = TW + N + 1,
  parameter integer CSW  = CaW + N + 1,
  parameter integer WSW  = W1W + N + 2,
  parameter integer SSW  = W1W + 2,
  parameter integer ASW  = A1W + N + 2,
  parameter integer SAW  = A1W + 2,
  parameter integer FsW  = 2*XSW + TSW + 2*CSW + WSW + SSW + 2*(ASW + SAW),
  parameter integer PcW  = 2*XW + TW + 2*CaW + W2W + 2*A2W,
  parameter integer FgW  = 2 * `RPU_FGDW
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             valid_i,
  input  wire [KW-1:0]    k_i,     // this step's k (used when Step == 0)
  input  wire [StW-1:0]   state_i,
  input  wire [FsW-1:0]   fs_i,    // {X, Y, T, C2, S2, W, SW, A1, SA1, A2, SA2} at τ
  input  wire [PcW-1:0]   pc_i,    // {x1, y1, β, c2b, s2b, w2, a1,2, a2,2}
  input  wire [FgW-1:0]   fg_i,    // {g1, g2}: frame guides {mode, η, η²}
  input  wire [CtxW-1:0]  ctx_i,
  input  wire [TagW-1:0]  tag_i,
  output wire             valid_o,
  output wire [KW-1:0]    k_o,
  output wire [StW-1:0]   state_o,
  output wire [FsW-1:0]   fs_o,
  output wire [PcW-1:0]   pc_o,
  output wire [FgW-1:0]   fg_o,
  output wire             ovf_o,   // a candidate of this step saturated
  output wire [CtxW-1:0]  ctx_o,
  output wire [TagW-1:0]  tag_o
);
  localparam integer FP = `RPU_FP, FC = `RPU_FC;
  localparam integer CTW = `RPU_CTW, CWW = `RPU_CWW, CAW = `RPU_CAW, GdW = `RPU_FGDW;
  // fs fields, LSB of each (MSB first: X, Y, T, C2, S2, W, SW, A1, SA1, A2, SA2)
  localparam integer oSA2 = 0, oA2 = SAW, oSA1 = oA2 + ASW, oA1 = oSA1 + SAW, oSW = oA1 + ASW;
  localparam integer oW = oSW + SSW, oS2 = oW + WSW, oC2 = oS2 + CSW, oT = oC2 + CSW;
  localparam integer oY = oT + TSW, oX = oY + XSW;
  // pc fields (MSB first: x1, y1, β, c2b, s2b, w2, a1,2, a2,2)
  localparam integer pA22 = 0, pA12 = A2W, pW2 = 2*A2W, pS2B = pW2 + W2W, pC2B = pS2B + CaW;
  localparam integer pB = pC2B + CaW, pY1 = pB + TW, pX1 = pY1 + XW;

  initial begin
    if (N1 < 1 || N1 > 8) $fatal(1, "rpu_ip_step: N1 must be in 1..8");
    if (N % N1 != 0) $fatal(1, "rpu_ip_step: N must be a multiple of N1");
    if (Step < 0 || Step > K) $fatal(1, "rpu_ip_step: Step must be in 0..N/N1");
    if (oX + XSW != FsW || pX1 + XW != PcW) $fatal(1, "rpu_ip_step: internal: field offsets");
  end

  // c·q for a constant c ≥ 0 (shifts and adds), and e·q for a variable e (a mux per bit), in
  // 128-bit two's complement (the callers keep what fits).
  function automatic [127:0] cmul(input [127:0] q, input integer c);
    integer b;
    begin
      cmul = 128'd0;
      for (b = 0; b < 20; b = b + 1)
        if (((c >> b) & 1) != 0) cmul = cmul + (q << b);
    end
  endfunction
  // q·e for a run-time e < 2^16 (η, η²): the partial products summed in a balanced tree, so
  // an e of b set-able bits costs ceil(log2 b) adder levels, not b − 1 (zero bits fold away).
  function automatic [127:0] vmul(input [127:0] q, input [15:0] e);
    reg [127:0] p0, p1, p2, p3, p4, p5, p6, p7;
    begin
      p0 = (e[0] ? q : 128'd0) + (e[1] ? q << 1 : 128'd0);
      p1 = (e[2] ? q << 2 : 128'd0) + (e[3] ? q << 3 : 128'd0);
      p2 = (e[4] ? q << 4 : 128'd0) + (e[5] ? q << 5 : 128'd0);
      p3 = (e[6] ? q << 6 : 128'd0) + (e[7] ? q << 7 : 128'd0);
      p4 = (e[8] ? q << 8 : 128'd0) + (e[9] ? q << 9 : 128'd0);
      p5 = (e[10] ? q << 10 : 128'd0) + (e[11] ? q << 11 : 128'd0);
      p6 = (e[12] ? q << 12 : 128'd0) + (e[13] ? q << 13 : 128'd0);
      p7 = (e[14] ? q << 14 : 128'd0) + (e[15] ? q << 15 : 128'd0);
      vmul = ((p0 + p1) + (p2 + p3)) + ((p4 + p5) + (p6 + p7));
    end
  endfunction
`include "rpu_frame_fn.vh"
  wire [KW-1:0] k_in = Step == 0 ? k_i : Step[KW-1:0];
  wire [7:0]    sh_in = N[7:0] - N1[7:0] * k_in[7:0];          // log2 D
  // The offsets' fraction bits of this step (the iterative form's candidates take them per item).
  wire [7:0]    fo_raw = `RPU_FOB + N1[7:0] * k_in[7:0];
  wire [4:0]    fo_in = fo_raw > `RPU_FOMAX ? 5'd`RPU_FOMAX : fo_raw[4:0];

  // The side band: the state, constants and context the step's end needs, in two parts by
  // where they are needed (named layouts, LSB first):
  //   A, read as the candidates leave: {SA2, SA1, SW, pc, state, shift}: the md's for the pair
  //     sums, τ, and what the multiples of η take;
  //   B, read after the multiples: {tag, ctx, fg, fs, k}: what the moves add to and the output.
  localparam integer AsA2O = 0, AsA1O = AsA2O + SAW, AsSwO = AsA1O + SAW, AsPcO = AsSwO + SSW;
  localparam integer AsStO = AsPcO + PcW, AsShO = AsStO + StW, SaW = AsShO + 8;
  localparam integer BsTagO = 0, BsCtxO = BsTagO + TagW, BsFgO = BsCtxO + CtxW;
  localparam integer BsFsO = BsFgO + FgW, BsKO = BsFsO + FsW, SbW = BsKO + KW;
  wire [SaW-1:0] sa_in = {sh_in, state_i, pc_i, fs_i[oSW +: SSW], fs_i[oSA1 +: SAW],
                          fs_i[oSA2 +: SAW]};
  wire [SbW-1:0] sb_in = {k_in, fs_i, fg_i, ctx_i, tag_i};
  // Both wait in RAMs of 2^SlotW slots (distributed RAM), written as the item enters, read by
  // the slot candidate 1 brings back (A) and that slot two stages later (B). The path is in order
  // and at most one item enters per cycle, so a slot is read before it is written again while at
  // most 2^SlotW items are between the write and the last read: the three input stages, the
  // candidate, whose latency is largest at Fo = 0, Metric = 0, SqrtW = 0 (56 cycles; its widths
  // are otherwise fixed), and three stages, so at most 62 items (checked in simulation below).
  // Nothing of them rides the candidates' stages; after the candidates only what the next stage
  // computes with rides (the slot, the shift, τ, the md's, pc).
  localparam integer SlotW = 6;
  reg [SlotW-1:0] slot_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)      slot_q <= {SlotW{1'b0}};
    else if (valid_i) slot_q <= slot_q + 1'b1;
  end
  reg [SaW-1:0] sa_ram [0:(1 << SlotW) - 1];
  reg [SbW-1:0] sb_ram [0:(1 << SlotW) - 1];
  always @(posedge clk_i) if (valid_i) sa_ram[slot_q] <= sa_in;
  always @(posedge clk_i) if (valid_i) sb_ram[slot_q] <= sb_in;

  // ---- input stages 1–3: the candidates' polynomial values ----
  wire [XSW-1:0] fX = fs_i[oX +: XSW], fY = fs_i[oY +: XSW];
  wire [TSW-1:0] fT = fs_i[oT +: TSW];
  wire [CSW-1:0] fC2 = fs_i[oC2 +: CSW], fS2 = fs_i[oS2 +: CSW];
  wire [WSW-1:0] fW = fs_i[oW +: WSW];
  wire [SSW-1:0] fSW = fs_i[oSW +: SSW];
  wire [ASW-1:0] fA1 = fs_i[oA1 +: ASW], fA2 = fs_i[oA2 +: ASW];
  wire [SAW-1:0] fSA1 = fs_i[oSA1 +: SAW], fSA2 = fs_i[oSA2 +: SAW];
  wire [XW-1:0]  px1 = pc_i[pX1 +: XW], py1 = pc_i[pY1 +: XW];
  wire [TW-1:0]  pbe = pc_i[pB +: TW];
  wire [CaW-1:0] pc2b = pc_i[pC2B +: CaW], ps2b = pc_i[pS2B +: CaW];
  wire [W2W-1:0] pw2 = pc_i[pW2 +: W2W];
  wire [A2W-1:0] pa12 = pc_i[pA12 +: A2W], pa22 = pc_i[pA22 +: A2W];
  wire [127:0] X = `RPU_SX(fX, XSW), Y = `RPU_SX(fY, XSW), T = `RPU_SX(fT, TSW);
  wire [127:0] C2 = `RPU_SX(fC2, CSW), S2 = `RPU_SX(fS2, CSW), W = `RPU_SX(fW, WSW);
  wire [127:0] SW = `RPU_SX(fSW, SSW), A1 = `RPU_SX(fA1, ASW), A2 = `RPU_SX(fA2, ASW);
  wire [127:0] SA1 = `RPU_SX(fSA1, SAW), SA2 = `RPU_SX(fSA2, SAW);
  wire [127:0] x1 = `RPU_SX(px1, XW), y1 = `RPU_SX(py1, XW), be = `RPU_SX(pbe, TW);
  wire [127:0] c2b = `RPU_SX(pc2b, CaW), s2b = `RPU_SX(ps2b, CaW), w2 = `RPU_SX(pw2, W2W);
  wire [127:0] a12 = `RPU_SX(pa12, A2W), a22 = `RPU_SX(pa22, A2W);
  // Per candidate: stage 1 the linear values and the quadratic ones' first two terms; stage 2
  // the quadratic sums; stage 3 the floors and saturations (the candidate's input register).
  localparam integer LinW = 2*XSW + TSW + 2*CSW;     // X, Y, T, C2, S2 at m
  localparam integer QW   = WSW + 2*ASW;              // W, A1, A2 partial sums
  localparam integer InW  = 2*XW + 3*CTW + CWW + 2*CAW + 1;  // the candidate's inputs + sat flag
  wire [(J-1)*InW-1:0] cin;
  wire                 valid_3;
  wire [SlotW-1:0]     slot_3;
  genvar j;
  generate
    for (j = 1; j < J; j = j + 1) begin : g_in
      wire [127:0] dx  = cmul(x1, j) << sh_in,  dy  = cmul(y1, j) << sh_in;
      wire [127:0] dt  = cmul(be, j) << sh_in,  dc  = cmul(c2b, j) << sh_in;
      wire [127:0] ds  = cmul(s2b, j) << sh_in;
      wire [127:0] dw1 = cmul(SW, j) << sh_in,  dw2 = cmul(w2, j * j) << {sh_in, 1'b0};
      wire [127:0] da1 = cmul(SA1, j) << sh_in, db1 = cmul(a12, j * j) << {sh_in, 1'b0};
      wire [127:0] da2 = cmul(SA2, j) << sh_in, db2 = cmul(a22, j * j) << {sh_in, 1'b0};
      wire [127:0] xm = X + dx, ym = Y + dy, tm = T + dt, cm = C2 + dc, sm = S2 + ds;
      wire [127:0] wp = W + dw1, a1p = A1 + da1, a2p = A2 + da2;
      reg [LinW-1:0] lin_1;
      reg [QW-1:0]   qp_1, qd_1;
      always @(posedge clk_i) begin
        lin_1 <= {xm[XSW-1:0], ym[XSW-1:0], tm[TSW-1:0], cm[CSW-1:0], sm[CSW-1:0]};
        qp_1  <= {wp[WSW-1:0], a1p[ASW-1:0], a2p[ASW-1:0]};
        qd_1  <= {dw2[WSW-1:0], db1[ASW-1:0], db2[ASW-1:0]};
      end
      wire [WSW-1:0] qpw = qp_1[2*ASW +: WSW], qdw = qd_1[2*ASW +: WSW];
      wire [ASW-1:0] qpa1 = qp_1[ASW +: ASW], qda1 = qd_1[ASW +: ASW];
      wire [ASW-1:0] qpa2 = qp_1[0 +: ASW], qda2 = qd_1[0 +: ASW];
      wire [127:0] w_s  = `RPU_SX(qpw, WSW) + `RPU_SX(qdw, WSW);
      wire [127:0] a1_s = `RPU_SX(qpa1, ASW) + `RPU_SX(qda1, ASW);
      wire [127:0] a2_s = `RPU_SX(qpa2, ASW) + `RPU_SX(qda2, ASW);
      reg [LinW-1:0] lin_2;
      reg [QW-1:0]   q_2;
      always @(posedge clk_i) begin
        lin_2 <= lin_1;
        q_2   <= {w_s[WSW-1:0], a1_s[ASW-1:0], a2_s[ASW-1:0]};
      end
      // floors and saturations: x = floor(X/2^N), t = floor(T/2^(FT+N−FP)), c2t = floor(C2 /
      // 2^(FC+FT+N−FP)), w = floor(W/2^2N), a = floor(A/2^2N)
      wire [XSW-1:0] lx = lin_2[XSW + TSW + 2*CSW +: XSW], ly = lin_2[TSW + 2*CSW +: XSW];
      wire [TSW-1:0] lt = lin_2[2*CSW +: TSW];
      wire [CSW-1:0] lc = lin_2[CSW +: CSW], ls = lin_2[0 +: CSW];
      wire [WSW-1:0] lw = q_2[2*ASW +: WSW];
      wire [ASW-1:0] la1 = q_2[ASW +: ASW], la2 = q_2[0 +: ASW];
      wire [127:0] vx = fl(`RPU_SX(lx, XSW), N), vy = fl(`RPU_SX(ly, XSW), N);
      wire [127:0] vt = fl(`RPU_SX(lt, TSW), TFrac + N - FP);
      wire [127:0] vc = fl(`RPU_SX(lc, CSW), FC + TFrac + N - FP);
      wire [127:0] vs = fl(`RPU_SX(ls, CSW), FC + TFrac + N - FP);
      wire [127:0] vw = fl(`RPU_SX(lw, WSW), 2 * N);
      wire [127:0] va1 = fl(`RPU_SX(la1, ASW), 2 * N), va2 = fl(`RPU_SX(la2, ASW), 2 * N);
      wire s3 = issat(vx, XW) | issat(vy, XW) | issat(vt, CTW) | issat(vc, CTW) | issat(vs, CTW) |
                issat(vw, CWW) | issat(va1, CAW) | issat(va2, CAW);
      wire [127:0] ox = sat(vx, XW), oy = sat(vy, XW), ot = sat(vt, CTW), oc = sat(vc, CTW);
      wire [127:0] os = sat(vs, CTW), ow = sat(vw, CWW), oa1 = sat(va1, CAW), oa2 = sat(va2, CAW);
      reg [InW-1:0] in_3;
      always @(posedge clk_i)
        in_3 <= {ox[XW-1:0], oy[XW-1:0], ot[CTW-1:0], oc[CTW-1:0], os[CTW-1:0], ow[CWW-1:0],
                 oa2[CAW-1:0], oa1[CAW-1:0], s3};
      assign cin[(j-1)*InW +: InW] = in_3;
      wire unused_in = ^{dx[127:XSW], dy[127:XSW], dt[127:TSW], dc[127:CSW], ds[127:CSW],
                         xm[127:XSW], ym[127:XSW], tm[127:TSW], cm[127:CSW], sm[127:CSW],
                         wp[127:WSW], a1p[127:ASW], a2p[127:ASW], dw1[127:WSW], dw2[127:WSW],
                         da1[127:ASW], db1[127:ASW], da2[127:ASW], db2[127:ASW], w_s[127:WSW],
                         a1_s[127:ASW], a2_s[127:ASW], vx[127:XW], vy[127:XW], vt[127:CTW],
                         vc[127:CTW], vs[127:CTW], vw[127:CWW], va1[127:CAW], va2[127:CAW],
                         ox[127:XW], oy[127:XW], ot[127:CTW], oc[127:CTW], os[127:CTW],
                         ow[127:CWW], oa1[127:CAW], oa2[127:CAW]};
    end
  endgenerate
  // The slot through the three input stages, the guides and Fo through two (and u_i3g).
  wire valid_1, valid_2;
  localparam integer IbW = SlotW + FgW + 5;
  wire [IbW-1:0] sbf_1, sbf_2;
  rpu_stage #(.W(IbW)) u_i1 (.clk_i, .rst_ni, .valid_i, .d_i({slot_q, fg_i, fo_in}),
                             .valid_o(valid_1), .q_o(sbf_1));
  rpu_stage #(.W(IbW)) u_i2 (.clk_i, .rst_ni, .valid_i(valid_1), .d_i(sbf_1),
                             .valid_o(valid_2), .q_o(sbf_2));
  rpu_stage #(.W(SlotW)) u_i3 (.clk_i, .rst_ni, .valid_i(valid_2), .d_i(sbf_2[IbW-1 -: SlotW]),
                               .valid_o(valid_3), .q_o(slot_3));
  // The guides and Fo, which the candidates' first stage adds and shifts with, again in a held
  // stage of flip-flops beside u_i3 (a flat synthesis would otherwise make the three stages one
  // shift-register LUT, whose output is slow: 4.06 ns).
  localparam integer oFg2 = 5;  // the guides' offset in sbf_2
  wire           valid_3h_unused;
  wire [4:0]     fo_3;
  wire [FgW-1:0] fg_3;
  rpu_stage #(.W(FgW + 5), .Hold(1)) u_i3g (
    .clk_i, .rst_ni, .valid_i(valid_2), .d_i({sbf_2[oFg2 +: FgW], sbf_2[4:0]}),
    .valid_o(valid_3h_unused), .q_o({fg_3, fo_3}));

  // ---- the candidates ----
  localparam integer FoP = Step == 0 ? 0 : `RPU_MDFRAC(N1, Step);
  wire [J-2:0]         c_valid;
  wire [(J-1)*MdW-1:0] c_md;
  wire [J-2:0]         c_ovf;
  wire [SlotW:0]       slot_out;  // {in-sat, slot}
  wire [J-2:0]         c_isat;   // a candidate input saturated
  localparam integer oIs = 1 + 2*CAW + CWW, oIy = oIs + 3*CTW;  // s2t's and y's offsets in ci
  generate
    for (j = 1; j < J; j = j + 1) begin : g_cand
      wire [InW-1:0] ci = cin[(j-1)*InW +: InW];
      // fields, LSB first: the sat flag, a, w, s2t, c2t, t, y, x
      wire [XW-1:0]  cx = ci[oIy + XW +: XW], cy = ci[oIy +: XW];
      wire [CTW-1:0] ct = ci[oIs + 2*CTW +: CTW], cc = ci[oIs + CTW +: CTW];
      wire [CTW-1:0] cs = ci[oIs +: CTW];
      wire [CWW-1:0] cw = ci[2*CAW+1 +: CWW];
      wire [2*CAW-1:0] ca = ci[1 +: 2*CAW];
      if (j == 1) begin : g_carry
        rpu_candidate #(.SqrtW(SqrtW), .Fo(FoP), .Metric(Metric), .TagW(SlotW + 1)) u_cand (
          .clk_i, .rst_ni, .valid_i(valid_3), .fo_i(fo_3), .x_i(cx), .y_i(cy), .t_i(ct),
          .c2t_i(cc), .s2t_i(cs), .w_i(cw), .a_i(ca), .g1_i(fg_3[GdW +: GdW]),
          .g2_i(fg_3[0 +: GdW]), .tag_i({ci[0], slot_3}), .valid_o(c_valid[j-1]),
          .md_o(c_md[(j-1)*MdW +: MdW]), .ovf_o(c_ovf[j-1]), .tag_o(slot_out));
        assign c_isat[j-1] = slot_out[SlotW];
      end else begin : g_plain
        wire tag_unused;
        assign c_isat[j-1] = tag_unused;
        rpu_candidate #(.SqrtW(SqrtW), .Fo(FoP), .Metric(Metric), .TagW(1)) u_cand (
          .clk_i, .rst_ni, .valid_i(valid_3), .fo_i(fo_3), .x_i(cx), .y_i(cy), .t_i(ct),
          .c2t_i(cc), .s2t_i(cs), .w_i(cw), .a_i(ca), .g1_i(fg_3[GdW +: GdW]),
          .g2_i(fg_3[0 +: GdW]), .tag_i(ci[0]), .valid_o(c_valid[j-1]),
          .md_o(c_md[(j-1)*MdW +: MdW]), .ovf_o(c_ovf[j-1]), .tag_o(tag_unused));
      end
    end
  endgenerate
  // ---- the pair sums sd_j = md_j + md_{j+1} (md_0 = lo.md, md_J = hi.md), registered ----
  // With Step wired in, k and the shift are constants: taken as such, not from the RAMs (through
  // which no synthesis propagates a constant), so the moves below shift by constants.
  wire [SaW-1:0] sa_q = sa_ram[slot_out[SlotW-1:0]];
  wire [SaW-1:0] sa_c = {Step == 0 ? sa_q[AsShO +: 8] : sh_in, sa_q[0 +: AsShO]};
  wire           valid_p;      // the multiples' stage (below): side band B is read there
  wire [SlotW-1:0] slot_p;
`ifndef SYNTHESIS
`ifndef FORMAL
  // Items between the RAMs' write and their last read: never more than their slots.
  integer in_flight = 0;
  always @(posedge clk_i) begin
    in_flight <= in_flight + (valid_i ? 1 : 0) - (valid_p ? 1 : 0);
    if (in_flight > (1 << SlotW))
      $fatal(1, "rpu_ip_step: %0d items in flight over %0d side-band slots", in_flight,
             1 << SlotW);
  end
`endif
`endif
  wire [StW-1:0] st_c = sa_c[AsStO +: StW];
  wire [MdW-1:0] md_a [0:J];
  assign md_a[0] = st_c[MdW +: MdW];
  assign md_a[J] = st_c[0 +: MdW];
  generate
    for (j = 1; j < J; j = j + 1) begin : g_md_a
      assign md_a[j] = c_md[(j-1)*MdW +: MdW];
    end
  endgenerate
  reg                    valid_r;
  reg [SaW-1:0]          sa_r;
  reg [SlotW-1:0]        slot_r;
  reg [(J-1)*MdW-1:0]    c_md_r;
  reg                    ovf_r;
  reg [MdW:0]            sd [0:J-1];
  integer q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_r <= 1'b0;
    else         valid_r <= c_valid[0];
  end
  // (sa_r loads only with a valid item: a clock enable keeps it a flip-flop, so the pair sums'
  // compares and η's stage do not start at a slow shift-register LUT output)
  always @(posedge clk_i) if (c_valid[0]) {slot_r, sa_r} <= {slot_out[SlotW-1:0], sa_c};
  always @(posedge clk_i) begin
    c_md_r <= c_md;
    ovf_r  <= |{c_ovf, c_isat};
    for (q = 0; q < J; q = q + 1) sd[q] <= {1'b0, md_a[q]} + {1'b0, md_a[q+1]};
  end
  wire [StW-1:0] st_r = sa_r[AsStO +: StW];
  wire [MdW-1:0] md [0:J];
  assign md[0] = st_r[MdW +: MdW];
  assign md[J] = st_r[0 +: MdW];
  generate
    for (j = 1; j < J; j = j + 1) begin : g_md
      assign md[j] = c_md_r[(j-1)*MdW +: MdW];
    end
  endgenerate

  // ---- the lowest-index argmin (one-hot: j wins when sd_j < sd_i for every i < j and
  //      sd_j ≤ sd_i for every i > j), η and the selected md's, registered ----
  reg [J-1:0] win;
  integer a, b;
  always @(*) begin
    for (a = 0; a < J; a = a + 1) begin
      win[a] = 1'b1;
      for (b = 0; b < J; b = b + 1) begin
        if (b < a && sd[a] >= sd[b]) win[a] = 1'b0;
        if (b > a && sd[a] > sd[b]) win[a] = 1'b0;
      end
    end
  end
  reg [N1-1:0]  eta;
  reg [15:0]    eta_sq;  // η² (< 2^16): the winner's constant, like η, no squarer
  reg [MdW-1:0] lo_md_n, hi_md_n;
  integer e;
  reg [15:0] sq;
  always @(*) begin
    eta     = {N1{1'b0}};
    eta_sq  = 16'd0;
    sq      = 16'd0;
    lo_md_n = {MdW{1'b0}};
    hi_md_n = {MdW{1'b0}};
    for (e = 0; e < J; e = e + 1)
      if (win[e]) begin
        eta     = eta | e[N1-1:0];
        sq      = e[15:0] * e[15:0];  // a constant per e
        eta_sq  = eta_sq | sq;
        lo_md_n = lo_md_n | md[e];
        hi_md_n = hi_md_n | md[e+1];
      end
  end
  wire             valid_h;
  wire [N1-1:0]    eta_h;
  wire [2*N1-1:0]  eta_sq_h;  // η² < J² = 2^(2·N1): only its real bits cross the stage
  wire [2*MdW-1:0] mds_h;
  wire             ovf_h;
  wire [SlotW-1:0] slot_h;
  wire [SaW-1:0]   sa_h;
  // (Hold: flip-flops, so the η multiples below do not start at the slow output of the
  // shift-register LUTs the side band's delay line becomes)
  rpu_stage #(.W(N1 + 2*N1 + 2*MdW + 1 + SlotW + SaW), .Hold(1)) u_eta (
    .clk_i, .rst_ni, .valid_i(valid_r),
    .d_i({eta, eta_sq[2*N1-1:0], lo_md_n, hi_md_n, ovf_r, slot_r, sa_r}),
    .valid_o(valid_h), .q_o({eta_h, eta_sq_h, mds_h, ovf_h, slot_h, sa_h}));

  // ---- the state moved by η: three stages (the multiples of η and η², the shifted terms, the
  //      sums) ----
  wire [StW-1:0] st_h = sa_h[AsStO +: StW];
  wire [PcW-1:0] pc_h = sa_h[AsPcO +: PcW];
  wire [15:0] e1 = {{(16-N1){1'b0}}, eta_h};
  wire [15+2*N1:0] e2x = {16'd0, eta_sq_h};  // zero-extended (no zero-width replication)
  wire [15:0] e2 = e2x[15:0];
  wire [XW-1:0]  hpx1 = pc_h[pX1 +: XW], hpy1 = pc_h[pY1 +: XW];
  wire [TW-1:0]  hpbe = pc_h[pB +: TW];
  wire [CaW-1:0] hpc2b = pc_h[pC2B +: CaW], hps2b = pc_h[pS2B +: CaW];
  wire [W2W-1:0] hpw2 = pc_h[pW2 +: W2W];
  wire [A2W-1:0] hpa12 = pc_h[pA12 +: A2W], hpa22 = pc_h[pA22 +: A2W];
  wire [SSW-1:0] hfSW = sa_h[AsSwO +: SSW];
  wire [SAW-1:0] hfSA1 = sa_h[AsA1O +: SAW], hfSA2 = sa_h[AsA2O +: SAW];
  wire [127:0] hx1 = `RPU_SX(hpx1, XW), hy1 = `RPU_SX(hpy1, XW), hbe = `RPU_SX(hpbe, TW);
  wire [127:0] hc2b = `RPU_SX(hpc2b, CaW), hs2b = `RPU_SX(hps2b, CaW), hw2 = `RPU_SX(hpw2, W2W);
  wire [127:0] ha12 = `RPU_SX(hpa12, A2W), ha22 = `RPU_SX(hpa22, A2W);
  wire [127:0] hSW = `RPU_SX(hfSW, SSW), hSA1 = `RPU_SX(hfSA1, SAW), hSA2 = `RPU_SX(hfSA2, SAW);
  // The multiples, each kept to the width of the field it moves (the shifts below only move
  // bits up, and every field wraps within its width).
  wire [127:0] mX = vmul(hx1, e1), mY = vmul(hy1, e1), mT = vmul(hbe, e1);
  wire [127:0] mC = vmul(hc2b, e1), mS = vmul(hs2b, e1);
  wire [127:0] mSW = vmul(hSW, e1), mW2 = vmul(hw2, e2), mW1 = vmul(hw2, e1);
  wire [127:0] mSA1 = vmul(hSA1, e1), mA12 = vmul(ha12, e2), mA11 = vmul(ha12, e1);
  wire [127:0] mSA2 = vmul(hSA2, e1), mA22 = vmul(ha22, e2), mA21 = vmul(ha22, e1);
  localparam integer MW = 2*XSW + TSW + 2*CSW + 2*WSW + SSW + 2*(2*ASW + SAW);
  wire [MW-1:0] mult = {mX[XSW-1:0], mY[XSW-1:0], mT[TSW-1:0], mC[CSW-1:0], mS[CSW-1:0],
                        mSW[WSW-1:0], mW2[WSW-1:0], mW1[SSW-1:0],
                        mSA1[ASW-1:0], mA12[ASW-1:0], mA11[SAW-1:0],
                        mSA2[ASW-1:0], mA22[ASW-1:0], mA21[SAW-1:0]};
  // τ' = τ + η·D (the bits η lands on are zero in τ)
  // (with Step wired in, the shift is a constant, not the value the stages carried: a hierarchical
  // synthesis cannot see through the stages, and a carried shift would be a barrel shifter)
  wire [7:0]   sh_h = Step == 0 ? sa_h[AsShO +: 8] : sh_in;
  wire [N-1:0] tau_h = st_h[StW-1 -: N];
  wire [N+15:0] tau_n = {16'd0, tau_h} + ({{N{1'b0}}, e1} << sh_h);
  wire [MW-1:0]    mult_p;
  wire [N-1:0]     tau_p;
  wire [2*MdW-1:0] mds_p;
  wire             ovf_p;
  wire [7:0]       shc_p;
  wire [PcW-1:0]   pc_p;
  rpu_stage #(.W(MW + N + 2*MdW + 1 + SlotW + 8 + PcW)) u_mult (
    .clk_i, .rst_ni, .valid_i(valid_h),
    .d_i({mult, tau_n[N-1:0], mds_h, ovf_h, slot_h, sa_h[AsShO +: 8], pc_h}),
    .valid_o(valid_p), .q_o({mult_p, tau_p, mds_p, ovf_p, slot_p, shc_p, pc_p}));
  // Side band B, read by the slot beside the terms.
  wire [SbW-1:0] sb_q = sb_ram[slot_p];
  wire [SbW-1:0] sb_c = {Step == 0 ? sb_q[BsKO +: KW] : k_in, sb_q[0 +: BsKO]};
  // Terms of the move, in the fields' order and widths: a multiple times D = 2^sh, η² ones
  // times D².
  wire [7:0] sh_p = Step == 0 ? shc_p : sh_in;
  wire [XSW-1:0] uX, uY;
  wire [TSW-1:0] uT;
  wire [CSW-1:0] uC, uS;
  wire [WSW-1:0] uSW, uW2;
  wire [SSW-1:0] uW1;
  wire [ASW-1:0] uSA1, uA12, uSA2, uA22;
  wire [SAW-1:0] uA11, uA21;
  assign {uX, uY, uT, uC, uS, uSW, uW2, uW1, uSA1, uA12, uA11, uSA2, uA22, uA21} = mult_p;
  `define RPU_ZX(v, w) {{(128-(w)){1'b0}}, v}
  wire [127:0] tX = `RPU_ZX(uX, XSW) << sh_p, tY = `RPU_ZX(uY, XSW) << sh_p;
  wire [127:0] tT = `RPU_ZX(uT, TSW) << sh_p;
  wire [127:0] tC = `RPU_ZX(uC, CSW) << sh_p, tS = `RPU_ZX(uS, CSW) << sh_p;
  wire [127:0] tW = (`RPU_ZX(uSW, WSW) << sh_p) + (`RPU_ZX(uW2, WSW) << {sh_p, 1'b0});
  wire [127:0] tSW = `RPU_ZX(uW1, SSW) << (sh_p + 8'd1);
  wire [127:0] tA1 = (`RPU_ZX(uSA1, ASW) << sh_p) + (`RPU_ZX(uA12, ASW) << {sh_p, 1'b0});
  wire [127:0] tSA1 = `RPU_ZX(uA11, SAW) << (sh_p + 8'd1);
  wire [127:0] tA2 = (`RPU_ZX(uSA2, ASW) << sh_p) + (`RPU_ZX(uA22, ASW) << {sh_p, 1'b0});
  wire [127:0] tSA2 = `RPU_ZX(uA21, SAW) << (sh_p + 8'd1);
  `undef RPU_ZX
  wire [FsW-1:0] terms = {tX[XSW-1:0], tY[XSW-1:0], tT[TSW-1:0], tC[CSW-1:0], tS[CSW-1:0],
                          tW[WSW-1:0], tSW[SSW-1:0], tA1[ASW-1:0], tSA1[SAW-1:0], tA2[ASW-1:0],
                          tSA2[SAW-1:0]};
  wire             valid_m;
  wire [FsW-1:0]   terms_m;
  wire [N-1:0]     tau_m;
  wire [2*MdW-1:0] mds_m;
  wire             ovf_m;
  wire [PcW-1:0]   pc_m;
  wire [SbW-1:0]   sb_m;
  rpu_stage #(.W(FsW + N + 2*MdW + 1 + PcW + SbW)) u_terms (
    .clk_i, .rst_ni, .valid_i(valid_p), .d_i({terms, tau_p, mds_p, ovf_p, pc_p, sb_c}),
    .valid_o(valid_m), .q_o({terms_m, tau_m, mds_m, ovf_m, pc_m, sb_m}));
  wire [FsW-1:0] fs_m = sb_m[BsFsO +: FsW];
  // Field-wise sums (each field wraps within its own width; the values fit).
  wire [FsW-1:0] fs_n;
  `define RPU_STEP_ADD(O, W) assign fs_n[O +: W] = fs_m[O +: W] + terms_m[O +: W];
  `RPU_STEP_ADD(oX, XSW)
  `RPU_STEP_ADD(oY, XSW)
  `RPU_STEP_ADD(oT, TSW)
  `RPU_STEP_ADD(oC2, CSW)
  `RPU_STEP_ADD(oS2, CSW)
  `RPU_STEP_ADD(oW, WSW)
  `RPU_STEP_ADD(oSW, SSW)
  `RPU_STEP_ADD(oA1, ASW)
  `RPU_STEP_ADD(oSA1, SAW)
  `RPU_STEP_ADD(oA2, ASW)
  `RPU_STEP_ADD(oSA2, SAW)
  `undef RPU_STEP_ADD
  rpu_stage #(.W(KW + StW + FsW + PcW + FgW + 1 + CtxW + TagW)) u_out (
    .clk_i, .rst_ni, .valid_i(valid_m),
    .d_i({sb_m[BsKO +: KW], tau_m, mds_m, fs_n, pc_m, sb_m[BsFgO +: FgW], ovf_m,
          sb_m[BsCtxO +: CtxW], sb_m[BsTagO +: TagW]}),
    .valid_o, .q_o({k_o, state_o, fs_o, pc_o, fg_o, ovf_o, ctx_o, tag_o}));

  wire unused = ^{c_valid[J-2:0], valid_3h_unused, st_r[StW-1 -: N],
                  st_c[StW-1 -: N], sa_c, sa_q[AsShO +: 8], sb_q[BsKO +: KW], tau_n[N+15:N],
                  e2[15:0], e2x, mX, mY, mT, mC, mS, mSW, mW2, mW1, mSA1, mA12, mA11, mSA2, mA22,
                  mA21, tX, tY, tT, tC, tS, tW, tSW, tA1, tSA1, tA2, tSA2, hx1, st_h[2*MdW-1:0],
                  sa_r, sa_h, shc_p};
`undef RPU_SX
endmodule

`default_nettype wire
