// rpu_ip: the K-step iterative process (docs/algorithms.md §1.2 step 3) in the chord's frame,
// twin of rpu::ref::frame_unit + ip_process + test_point_unit (docs/fixed-point.md, "The
// candidate in the chord's frame"). The frame unit forms the pair's polynomials, an input stage
// squares the guide heights once per pair (h1², h2²: the test point's guide radicands need them),
// a start unit evaluates the candidates τ = 0 and τ = 1 (Fo = md_frac(0)); then
//   Unrolled = 1: K rpu_ip_step units in a pipeline, each with its k wired in: one pair per
//                 cycle, fixed latency, ready_o = 1;
//   Unrolled = 0: one rpu_ip_step unit reused K times: items circulate through it, a returning
//                 item has priority over a new one, so it accepts about one pair per K cycles.
//                 New pairs wait in a FIFO after the start unit; ready_o is credit-counted so
//                 that FIFO never overflows.
// Last, the test point (t and X = s(t) of τ_K, rpu_test_point). Results leave in input order.
//
// Only the arithmetic's operands ride the stages. What the end alone needs waits in block-RAM
// FIFOs (rpu_fifo) and meets its item there, since items leave in the order they came:
//   u_q_tp:  {α, β, p1, d, L², g1, g2}, written as the item enters, read at the test point;
//   u_q_hh:  {h1², h2²}, written after the squares, read at the test point;
//   u_q_ctx: the caller's context, written as the item enters, read as the result leaves.
// Each holds 2^QLog2 entries, more than the items that can be between its write and its read:
// unrolled, the frame (11), the squares, the start candidates and K steps (at most 64 cycles
// each) and the test point (under 256 at every width): (K + 1)·64 + 256; iterative, the start
// FIFO's 2^FifoLog2 credits, one step's 64 and the test point: 2^FifoLog2 + 64 + 256. A write to
// a full queue or a read of an empty one stops a simulation.
`default_nettype none
`include "rpu_widths.vh"

module rpu_ip #(
`include "rpu_ip_params.vh"
  parameter integer N1       = 2,   // bits per step (1..8), N % N1 == 0
  parameter integer Metric   = 0,   // 0: md = |o|, 1: |o|²
  parameter integer Unrolled = 1,   // 1: K step units, 0: one step unit reused K times
  parameter integer FifoLog2 = 8,   // iterative form: log2 of the start FIFO depth (2..12)
  parameter integer CtxW     = 1,   // caller's context passed through
  // Derived (do not override).
  parameter integer K    = N / N1,
`include "rpu_ip_derived.vh"
  parameter integer MdW  = Metric == 0 ? `RPU_FOMAX + 3 : 2 * `RPU_FOMAX + 3,
  parameter integer StW  = N + TW + 3*XW + MdW + MdW,
  parameter integer FrW  = `RPU_FRDW,
  parameter integer FgdW = `RPU_FGDW
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  output wire                ready_o,
  input  wire [3*CoordW-1:0] a_i,
  input  wire [3*DW-1:0]     ab_i,
  input  wire [TW-1:0]       alpha_i,
  input  wire [TW-1:0]       beta_i,
  input  wire [3*CoordW-1:0] p1_i,
  input  wire [3*DW-1:0]     d_i,
  input  wire [L2W-1:0]      l2_i,
  input  wire [GdW-1:0]      g1_i,       // guide of end 1 (rpu_guide_desc.vh)
  input  wire [GdW-1:0]      g2_i,       // guide of end 2
  input  wire [FrW-1:0]      fr_i,       // the frame descriptor (rpu_frame)
  input  wire [2*FgdW-1:0]   fg_i,       // the frame guides {g1, g2}
  input  wire [CtxW-1:0]     ctx_i,
  output wire                valid_o,
  output wire [StW-1:0]      state_o,    // {τ_K, t, X, lo.md, hi.md}
  output wire                ovf_o,
  output wire [CtxW-1:0]     ctx_o
);
  localparam integer KW = 8;
`include "rpu_guide_desc.vh"
  localparam integer HW = GsHW;
  localparam integer GdHO = GdShapeO + GsHO;
  localparam integer FP = `RPU_FP, FC = `RPU_FC;
  localparam integer CXW = `RPU_CXW, CTW = `RPU_CTW, CWW = `RPU_CWW, CAW = `RPU_CAW;
  // rpu_frame's and rpu_ip_step's field widths (their derived parameters)
  localparam integer CaW = `RPU_FCAW(TFrac);
  localparam integer W0W = `RPU_FW0W(N), W1W = `RPU_FW1W(N), W2W = `RPU_FW2W;
  localparam integer A0W = W0W - (`RPU_FW - `RPU_FG), A1W = W1W - (`RPU_FW - `RPU_FG);
  localparam integer A2W = W2W - (`RPU_FW - `RPU_FG);
  localparam integer XSW = CXW + N + 1, TSW = TW + N + 1, CSW = CaW + N + 1;
  localparam integer WSW = W1W + N + 2, SSW = W1W + 2, ASW = A1W + N + 2, SAW = A1W + 2;
  localparam integer FsW = 2*XSW + TSW + 2*CSW + WSW + SSW + 2*(ASW + SAW);
  localparam integer PcW = 2*CXW + TW + 2*CaW + W2W + 2*A2W;
  localparam integer FaW = A0W + A1W + A2W;
  // The queues: depth, and the fields of u_q_tp (MSB first).
  localparam integer QLog2 = $clog2(Unrolled != 0 ? (K + 1) * 64 + 256
                                                  : (1 << FifoLog2) + 64 + 256);
  localparam integer TqW = 2*TW + 3*CoordW + 3*DW + L2W + 2*GdW;

  initial begin
    if (K > 255) $fatal(1, "rpu_ip: N/N1 must be below 256");
    if (FifoLog2 < 2 || FifoLog2 > 12) $fatal(1, "rpu_ip: FifoLog2 must be in 2..12");
    if (GdW != GdWords) $fatal(1, "rpu_ip: GdW is derived; do not override it");
  end

  // ---- the queues' writes, as the item enters ----
  wire accept_in = valid_i && ready_o;
  wire q_tp_wr_ready, q_ctx_wr_ready, q_hh_wr_ready;
  wire q_tp_valid, q_ctx_valid, q_hh_valid;
  wire [TqW-1:0]    q_tp;
  wire [2*RadW-1:0] q_hh;
  wire              tp_valid;  // the test point takes an item (reads u_q_tp and u_q_hh)
  rpu_fifo #(.Width(TqW), .Log2Depth(QLog2)) u_q_tp (
    .clk_i, .rst_ni, .wr_valid_i(accept_in), .wr_ready_o(q_tp_wr_ready),
    .wr_data_i({alpha_i, beta_i, p1_i, d_i, l2_i, g1_i, g2_i}), .rd_valid_o(q_tp_valid),
    .rd_ready_i(tp_valid), .rd_data_o(q_tp));
  rpu_fifo #(.Width(CtxW), .Log2Depth(QLog2)) u_q_ctx (
    .clk_i, .rst_ni, .wr_valid_i(accept_in), .wr_ready_o(q_ctx_wr_ready), .wr_data_i(ctx_i),
    .rd_valid_o(q_ctx_valid), .rd_ready_i(valid_o), .rd_data_o(ctx_o));

  // ---- the frame unit (the guides' heights and the frame guides in its tag) ----
  localparam integer FTagW = 2*HW + 2*FgdW;
  wire               valid_f;
  wire [4*CXW-1:0]   xy_f;                 // {x0, x1, y0, y1}
  wire [4*CaW-1:0]   cs_f;                 // {c2a, c2b, s2a, s2b}
  wire [W0W+W1W+W2W-1:0] w_f;              // {w0, w1, w2}
  wire [2*FaW-1:0]   fa_f;                 // {a1,0..2, a2,0..2}
  wire [TW-1:0]      al_f, be_f;
  wire               ovf_f;
  wire [FTagW-1:0]   tag_f;
  rpu_frame #(.CoordW(CoordW), .TFrac(TFrac), .N(N), .TagW(FTagW)) u_frame (
    .clk_i, .rst_ni, .valid_i(valid_i && ready_o), .a_i, .ab_i, .alpha_i, .beta_i, .p1_i,
    .fr_i, .tag_i({g1_i[GdHO +: HW], g2_i[GdHO +: HW], fg_i}),
    .valid_o(valid_f), .xy_o(xy_f), .cs_o(cs_f), .w_o(w_f), .fa_o(fa_f), .alpha_o(al_f),
    .beta_o(be_f), .ovf_o(ovf_f), .tag_o(tag_f));
  wire [HW-1:0] h1_f = tag_f[2*FgdW + HW +: HW], h2_f = tag_f[2*FgdW +: HW];

  // ---- h1², h2² (exact, unsigned) and the start values: the candidates τ = 0 and τ = 1 ----
  // (inputs at m = 0: x0, floor(α/2^(FT−FP)), …, floor(w0/2^2N); at m = 2^N: x0 + x1,
  //  floor((α + β)/2^(FT−FP)), …, floor((w0 + w1·2^N + w2·2^2N)/2^2N); saturated like
  //  candidate_inputs)
  localparam integer PairW = 2*4*CXW + 4*CaW + W0W + W1W + W2W + 2*FaW + 2*TW + 1 + FTagW;
  wire              valid_h;
  wire [2*RadW-1:0] hh;
  wire [PairW-1:0]  pair_h;
  rpu_mul_vec #(.Count(2), .AW(HW), .BW(HW), .Signed(0), .TagW(PairW)) u_hh (
    .clk_i, .rst_ni, .valid_i(valid_f), .a_i({h2_f, h1_f}), .b_i({h2_f, h1_f}),
    .tag_i({xy_f, xy_f, cs_f, w_f, fa_f, al_f, be_f, ovf_f, tag_f}),
    .valid_o(valid_h), .p_o(hh), .tag_o(pair_h));
  wire [4*CXW-1:0] xy_h;
  wire [4*CXW-1:0] xy_unused;
  wire [4*CaW-1:0] cs_h;
  wire [W0W+W1W+W2W-1:0] w_h;
  wire [2*FaW-1:0] fa_h;
  wire [TW-1:0]    al_h, be_h;
  wire             ovf_h;
  wire [FTagW-1:0] tag_h;
  assign {xy_h, xy_unused, cs_h, w_h, fa_h, al_h, be_h, ovf_h, tag_h} = pair_h;
  wire [2*HW-1:0]     h_unused;
  wire [2*FgdW-1:0]   fg_h;
  assign {h_unused, fg_h} = tag_h;
  rpu_fifo #(.Width(2*RadW), .Log2Depth(QLog2)) u_q_hh (
    .clk_i, .rst_ni, .wr_valid_i(valid_h), .wr_ready_o(q_hh_wr_ready), .wr_data_i(hh),
    .rd_valid_o(q_hh_valid), .rd_ready_i(tp_valid), .rd_data_o(q_hh));

`include "rpu_frame_fn.vh"
  wire [CXW-1:0] x0 = xy_h[3*CXW +: CXW], x1 = xy_h[2*CXW +: CXW];
  wire [CXW-1:0] y0 = xy_h[CXW +: CXW],   y1 = xy_h[0 +: CXW];
  wire [CaW-1:0] c2a = cs_h[3*CaW +: CaW], c2b = cs_h[2*CaW +: CaW];
  wire [CaW-1:0] s2a = cs_h[CaW +: CaW],   s2b = cs_h[0 +: CaW];
  wire [W0W-1:0] w0 = w_h[W1W+W2W +: W0W];
  wire [W1W-1:0] w1 = w_h[W2W +: W1W];
  wire [W2W-1:0] w2 = w_h[0 +: W2W];
  wire [A0W-1:0] a10 = fa_h[FaW+A1W+A2W +: A0W], a20 = fa_h[A1W+A2W +: A0W];
  wire [A1W-1:0] a11 = fa_h[FaW+A2W +: A1W],     a21 = fa_h[A2W +: A1W];
  wire [A2W-1:0] a12 = fa_h[FaW +: A2W],         a22 = fa_h[0 +: A2W];
  wire [127:0] X0 = `RPU_SX(x0, CXW), X1 = `RPU_SX(x1, CXW), Y0 = `RPU_SX(y0, CXW);
  wire [127:0] Y1 = `RPU_SX(y1, CXW), AL = `RPU_SX(al_h, TW), BE = `RPU_SX(be_h, TW);
  wire [127:0] C2A = `RPU_SX(c2a, CaW), C2B = `RPU_SX(c2b, CaW), S2A = `RPU_SX(s2a, CaW);
  wire [127:0] S2B = `RPU_SX(s2b, CaW), W0 = `RPU_SX(w0, W0W), W1 = `RPU_SX(w1, W1W);
  wire [127:0] W2 = `RPU_SX(w2, W2W), A10 = `RPU_SX(a10, A0W), A11 = `RPU_SX(a11, A1W);
  wire [127:0] A12 = `RPU_SX(a12, A2W), A20 = `RPU_SX(a20, A0W), A21 = `RPU_SX(a21, A1W);
  wire [127:0] A22 = `RPU_SX(a22, A2W);
  localparam integer ET = TFrac - FP, EC = FC + TFrac - FP;
  // m = 0 and m = 2^N: the polynomials' values divided by 2^N (linear) or 2^2N (quadratic)
  wire [127:0] vx0 = X0, vy0 = Y0, vt0 = fl(AL, ET), vc0 = fl(C2A, EC), vs0 = fl(S2A, EC);
  wire [127:0] vw0 = fl(W0, 2*N), va10 = fl(A10, 2*N), va20 = fl(A20, 2*N);
  wire [127:0] vx1 = X0 + X1, vy1 = Y0 + Y1, vt1 = fl(AL + BE, ET);
  wire [127:0] vc1 = fl(C2A + C2B, EC), vs1 = fl(S2A + S2B, EC);
  wire [127:0] vw1 = fl(W0 + (W1 << N) + (W2 << (2*N)), 2*N);
  wire [127:0] va11 = fl(A10 + (A11 << N) + (A12 << (2*N)), 2*N);
  wire [127:0] va21 = fl(A20 + (A21 << N) + (A22 << (2*N)), 2*N);
  localparam integer InW = 2*CXW + 3*CTW + CWW + 2*CAW;
  wire [127:0] sx0 = sat(vx0, CXW), sy0 = sat(vy0, CXW), st0 = sat(vt0, CTW);
  wire [127:0] sc0 = sat(vc0, CTW), ss0 = sat(vs0, CTW), sw0 = sat(vw0, CWW);
  wire [127:0] sa10 = sat(va10, CAW), sa20 = sat(va20, CAW);
  wire [127:0] sx1 = sat(vx1, CXW), sy1 = sat(vy1, CXW), st1 = sat(vt1, CTW);
  wire [127:0] sc1 = sat(vc1, CTW), ss1 = sat(vs1, CTW), sw1 = sat(vw1, CWW);
  wire [127:0] sa11 = sat(va11, CAW), sa21 = sat(va21, CAW);
  wire [InW-1:0] in0 = {sx0[CXW-1:0], sy0[CXW-1:0], st0[CTW-1:0], sc0[CTW-1:0], ss0[CTW-1:0],
                        sw0[CWW-1:0], sa20[CAW-1:0], sa10[CAW-1:0]};
  wire [InW-1:0] in1 = {sx1[CXW-1:0], sy1[CXW-1:0], st1[CTW-1:0], sc1[CTW-1:0], ss1[CTW-1:0],
                        sw1[CWW-1:0], sa21[CAW-1:0], sa11[CAW-1:0]};
  wire isat = issat(vx0, CXW) | issat(vy0, CXW) | issat(vt0, CTW) | issat(vc0, CTW) |
              issat(vs0, CTW) | issat(vw0, CWW) | issat(va10, CAW) | issat(va20, CAW) |
              issat(vx1, CXW) | issat(vy1, CXW) | issat(vt1, CTW) | issat(vc1, CTW) |
              issat(vs1, CTW) | issat(vw1, CWW) | issat(va11, CAW) | issat(va21, CAW);
  // The frame state at τ = 0 and the pair's constants.
  wire [127:0] fX = X0 << N, fY = Y0 << N, fT = AL << N, fC2 = C2A << N, fS2 = S2A << N;
  wire [FsW-1:0] fs0 = {fX[XSW-1:0], fY[XSW-1:0], fT[TSW-1:0], fC2[CSW-1:0], fS2[CSW-1:0],
                        W0[WSW-1:0], W1[SSW-1:0], A10[ASW-1:0], A11[SAW-1:0], A20[ASW-1:0],
                        A21[SAW-1:0]};
  wire [PcW-1:0] pc0 = {x1, y1, be_h, c2b, s2b, w2, a12, a22};
  // Beside the carried word, one bit rides to the end: an overflow so far.
  localparam integer SideW = FsW + PcW + 2*FgdW + 1;
  wire             valid_s;
  wire [2*InW-1:0] in_s;
  wire [SideW-1:0] side_s;
  rpu_stage #(.W(2*InW + SideW)) u_sin (
    .clk_i, .rst_ni, .valid_i(valid_h), .d_i({in0, in1, fs0, pc0, fg_h, ovf_h | isat}),
    .valid_o(valid_s), .q_o({in_s, side_s}));
  localparam integer Fo0 = `RPU_MDFRAC(N1, 0);
  // a candidate input's fields, LSB first: a, w, s2t, c2t, t, y, x
  localparam integer oCw = 2*CAW, oCs2 = oCw + CWW, oCc2 = oCs2 + CTW, oCt = oCc2 + CTW;
  localparam integer oCy = oCt + CTW, oCx = oCy + CXW;
  `define RPU_CAND_IN(V) .x_i(V[oCx +: CXW]), .y_i(V[oCy +: CXW]), \
    .t_i(V[oCt +: CTW]), .c2t_i(V[oCc2 +: CTW]), \
    .s2t_i(V[oCs2 +: CTW]), .w_i(V[oCw +: CWW]), .a_i(V[0 +: 2*CAW])
  wire [InW-1:0]   ci0 = in_s[InW +: InW], ci1 = in_s[0 +: InW];
  wire [2*FgdW-1:0] fg_s = side_s[1 +: 2*FgdW];
  wire             s_valid, s_ovf0, s_ovf1, s_v1_unused, s_t1_unused;
  wire [MdW-1:0]   s_md0, s_md1;
  wire [SideW-1:0] s_side;
  // The carried word waits in a queue while the start candidates run (rpu_tag_queue; a bound of
  // 64 cycles on the candidate's latency, 56 at most: rpu_ip_step's side-band slots count on it
  // too), so only the queue's constant bit rides candidate 0's stages.
  localparam integer SPTagW = `RPU_PTAGW(SideW);
  wire [SPTagW-1:0] s_ptag_in, s_ptag_out;
  rpu_tag_queue #(.TagW(SideW), .Latency(64)) u_start_tagq (
    .clk_i, .rst_ni, .valid_i(valid_s), .tag_i(side_s), .ptag_o(s_ptag_in), .out_valid_i(s_valid),
    .ptag_i(s_ptag_out), .tag_o(s_side));
  rpu_candidate #(.SqrtW(SqrtW), .Fo(Fo0), .Metric(Metric), .TagW(SPTagW)) u_start0 (
    .clk_i, .rst_ni, .valid_i(valid_s), .fo_i(5'd0), `RPU_CAND_IN(ci0),
    .g1_i(fg_s[FgdW +: FgdW]), .g2_i(fg_s[0 +: FgdW]), .tag_i(s_ptag_in),
    .valid_o(s_valid), .md_o(s_md0), .ovf_o(s_ovf0), .tag_o(s_ptag_out));
  rpu_candidate #(.SqrtW(SqrtW), .Fo(Fo0), .Metric(Metric), .TagW(1)) u_start1 (
    .clk_i, .rst_ni, .valid_i(valid_s), .fo_i(5'd0), `RPU_CAND_IN(ci1),
    .g1_i(fg_s[FgdW +: FgdW]), .g2_i(fg_s[0 +: FgdW]), .tag_i(1'b0),
    .valid_o(s_v1_unused), .md_o(s_md1), .ovf_o(s_ovf1), .tag_o(s_t1_unused));
  `undef RPU_CAND_IN
  // The steps' carried word: {state {τ, lo.md, hi.md}, fs, pc, fg} and the bundle as context.
  localparam integer SStW = N + 2*MdW;
  localparam integer CarW = SStW + FsW + PcW + 2*FgdW;
  wire [CarW-1:0] s_car = {{N{1'b0}}, s_md0, s_md1, s_side[SideW-1 -: FsW + PcW + 2*FgdW]};
  wire           s_bun = s_side[0] | s_ovf0 | s_ovf1;  // the overflow so far

  // The test point's τ, md's and overflow so far.
  wire            tp_ovf_in;
  wire [N-1:0]    tp_tau;
  wire [2*MdW-1:0] tp_mds;
  generate
    if (Unrolled != 0) begin : g_unrolled
      assign ready_o = 1'b1;
      wire [K:0]             v   /* verilator split_var */;
      wire [(K+1)*CarW-1:0]  car /* verilator split_var */;
      wire [K:0]             bun /* verilator split_var */;
      assign v[0] = s_valid;
      assign car[0 +: CarW] = s_car;
      assign bun[0] = s_bun;
      genvar k;
      for (k = 1; k <= K; k = k + 1) begin : g_step
        wire [CarW-1:0] c = car[(k-1)*CarW +: CarW];
        wire [KW-1:0]   k_unused;
        wire            step_ovf, tag_unused;
        wire            b_out;
        wire [SStW-1:0] st_o;
        wire [FsW-1:0]  fs_o;
        wire [PcW-1:0]  pc_o;
        wire [2*FgdW-1:0] fg_o;
        rpu_ip_step #(.TFrac(TFrac), .SqrtW(SqrtW), .N(N), .N1(N1), .Metric(Metric), .Step(k),
                      .CtxW(1), .TagW(1)) u_step (
          .clk_i, .rst_ni, .valid_i(v[k-1]), .k_i({KW{1'b0}}),
          .state_i(c[CarW-1 -: SStW]), .fs_i(c[PcW+2*FgdW +: FsW]), .pc_i(c[2*FgdW +: PcW]),
          .fg_i(c[0 +: 2*FgdW]), .ctx_i(bun[k-1]), .tag_i(1'b0),
          .valid_o(v[k]), .k_o(k_unused), .state_o(st_o), .fs_o(fs_o), .pc_o(pc_o), .fg_o(fg_o),
          .ovf_o(step_ovf), .ctx_o(b_out), .tag_o(tag_unused));
        assign car[k*CarW +: CarW] = {st_o, fs_o, pc_o, fg_o};
        assign bun[k] = b_out | step_ovf;
        wire unused_k = ^{k_unused, tag_unused};
      end
      wire [CarW-1:0] last = car[K*CarW +: CarW];
      assign tp_valid = v[K];
      assign tp_tau   = last[CarW-1 -: N];
      localparam integer oMds = CarW - N - 2*MdW;  // below τ
      assign tp_mds   = last[oMds +: 2*MdW];
      assign tp_ovf_in = bun[K];
      wire unused_last = ^last[0 +: FsW + PcW + 2*FgdW];
    end else begin : g_iterative
      localparam integer Depth = 1 << FifoLog2;
      localparam integer QW = CarW + 1;
      reg [FifoLog2:0]   owed_q;
      wire               loop_valid;
      wire [KW-1:0]      loop_k;
      wire [CarW-1:0]    loop_car;
      wire               loop_bun;
      wire               loop_ovf;
      wire               tag_unused;
      wire               recirc = loop_valid && (loop_k != K[KW-1:0]);
      wire               fifo_any;
      wire               fifo_wr_ready_unused;
      wire [QW-1:0]      head;
      wire               pop    = fifo_any && !recirc;
      wire               accept = valid_i && ready_o;
      assign ready_o = owed_q < Depth[FifoLog2:0];
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) owed_q <= {(FifoLog2+1){1'b0}};
        else owed_q <= owed_q + {{FifoLog2{1'b0}}, accept} - {{FifoLog2{1'b0}}, pop};
      end
      rpu_fifo #(.Width(QW), .Log2Depth(FifoLog2)) u_start_fifo (
        .clk_i, .rst_ni, .wr_valid_i(s_valid), .wr_ready_o(fifo_wr_ready_unused),
        .wr_data_i({s_car, s_bun}), .rd_valid_o(fifo_any), .rd_ready_i(!recirc),
        .rd_data_o(head));
      wire            in_v   = recirc || pop;
      wire [KW-1:0]   in_k   = recirc ? loop_k + 1'b1 : {{(KW-1){1'b0}}, 1'b1};
      wire [CarW-1:0] in_car = recirc ? loop_car : head[QW-1 -: CarW];
      wire            in_bun = recirc ? loop_bun | loop_ovf : head[0];
      wire [SStW-1:0] st_o;
      wire [FsW-1:0]  fs_o;
      wire [PcW-1:0]  pc_o;
      wire [2*FgdW-1:0] fg_o;
      rpu_ip_step #(.TFrac(TFrac), .SqrtW(SqrtW), .N(N), .N1(N1), .Metric(Metric), .Step(0),
                    .CtxW(1), .TagW(1)) u_step (
        .clk_i, .rst_ni, .valid_i(in_v), .k_i(in_k), .state_i(in_car[CarW-1 -: SStW]),
        .fs_i(in_car[PcW+2*FgdW +: FsW]), .pc_i(in_car[2*FgdW +: PcW]),
        .fg_i(in_car[0 +: 2*FgdW]), .ctx_i(in_bun), .tag_i(1'b0),
        .valid_o(loop_valid), .k_o(loop_k), .state_o(st_o), .fs_o(fs_o), .pc_o(pc_o),
        .fg_o(fg_o), .ovf_o(loop_ovf), .ctx_o(loop_bun), .tag_o(tag_unused));
      assign loop_car = {st_o, fs_o, pc_o, fg_o};
      assign tp_valid = loop_valid && (loop_k == K[KW-1:0]);
      assign tp_tau   = st_o[SStW-1 -: N];
      assign tp_mds   = st_o[0 +: 2*MdW];
      assign tp_ovf_in = loop_bun | loop_ovf;
      wire unused_iter = ^{tag_unused, fifo_wr_ready_unused};
    end
  endgenerate

  // ---- the test point of τ_K, its other inputs from the queues ----
  localparam integer oG2 = 0, oG1 = GdW, oL2 = 2*GdW, oD = oL2 + L2W;  // fields of q_tp
  localparam integer oP1 = oD + 3*DW, oBe = oP1 + 3*CoordW, oAl = oBe + TW;
  localparam integer TpTagW = 2*MdW + 1;
  wire [TW-1:0]   tp_t;
  wire [3*XW-1:0] tp_x;
  wire            tp_ovf;
  wire [TpTagW-1:0] tp_tag;
  wire [N-1:0]    tau_unused;
  rpu_test_point #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                   .TagW(TpTagW + N)) u_tp (
    .clk_i, .rst_ni, .valid_i(tp_valid), .tau_i(tp_tau), .alpha_i(q_tp[oAl +: TW]),
    .beta_i(q_tp[oBe +: TW]), .p1_i(q_tp[oP1 +: 3*CoordW]), .d_i(q_tp[oD +: 3*DW]),
    .l2_i(q_tp[oL2 +: L2W]), .g1_i(q_tp[oG1 +: GdW]), .hh1_i(q_hh[0 +: RadW]),
    .g2_i(q_tp[oG2 +: GdW]), .hh2_i(q_hh[RadW +: RadW]),
    .tag_i({tp_tau, tp_mds, tp_ovf_in}),
    .valid_o(valid_o), .t_o(tp_t), .x_o(tp_x), .ovf_o(tp_ovf), .tag_o({tau_unused, tp_tag}));
  wire [N-1:0] tau_o = tau_unused;
  assign state_o = {tau_o, tp_t, tp_x, tp_tag[TpTagW-1 -: 2*MdW]};
  assign ovf_o   = tp_tag[0] | tp_ovf;
`ifndef SYNTHESIS
`ifndef FORMAL
  // The queues' depth bound (above): a write to a full queue or a read of an empty one is a
  // design error, not a load the unit may meet.
  // (checked from the first reset on: before it, the valid bits hold arbitrary start values)
  reg seen_reset = 1'b0;
  always @(posedge clk_i or negedge rst_ni) if (!rst_ni) seen_reset <= 1'b1;
  always @(posedge clk_i) begin
    if (seen_reset && ((accept_in && !(q_tp_wr_ready && q_ctx_wr_ready)) ||
                       (valid_h && !q_hh_wr_ready)))
      $fatal(1, "rpu_ip: a context queue of %0d entries is full", 1 << QLog2);
    if (seen_reset && ((tp_valid && !(q_tp_valid && q_hh_valid)) || (valid_o && !q_ctx_valid)))
      $fatal(1, "rpu_ip: a context queue is empty when its item arrives");
  end
`endif
`endif
  wire unused = ^{xy_unused, vx0[127:CXW], sx0, sy0, st0, sc0, ss0, sw0, sa10, sa20, sx1, sy1,
                  st1, sc1, ss1, sw1, sa11, sa21, fX, fY, fT, fC2, fS2, W0, W1, A10, A11, A20,
                  A21, X1, Y1, BE, C2B, S2B, W2, A12, A22, vy0, vt0, vc0, vs0, vw0, va10, va20,
                  vx1, vy1, vt1, vc1, vs1, vw1, va11, va21, s_v1_unused, s_t1_unused,
                  h_unused, q_tp_wr_ready, q_ctx_wr_ready, q_hh_wr_ready, q_tp_valid,
                  q_ctx_valid, q_hh_valid};
  `undef RPU_SX
endmodule

`default_nettype wire
