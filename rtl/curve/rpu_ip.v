// rpu_ip: the K-step iterative process (docs/algorithms.md §1.2 step 3), twin of
// rpu::ref::ip_process. An input stage squares the guide heights once per pair (h1², h2², rpu_mul:
// the candidates' guide radicands h² + L²w need them; no candidate multiplies h); a start unit
// evaluates the candidates τ = 0 and τ = 1; then
//   Unrolled = 1: K rpu_ip_step units in a pipeline, each with its k wired in: one pair per
//                 cycle, fixed latency, ready_o = 1;
//   Unrolled = 0: one rpu_ip_step unit reused K times: items circulate through it, a returning
//                 item has priority over a new one, so it accepts about one pair per K cycles.
//                 New pairs wait in a FIFO after the start unit; ready_o is credit-counted so
//                 that FIFO never overflows.
// Results leave in completion order, which is the input order (both forms keep order: the ring
// never lets a younger item overtake, see the FIFO and the fixed loop latency).
`default_nettype none
`include "rpu_widths.vh"

module rpu_ip #(
`include "rpu_ip_params.vh"
  parameter integer N1       = 2,   // bits per step (1..8), N % N1 == 0
  parameter integer Metric   = 0,   // 0: |pr − X|, 1: |pr − X|²
  parameter integer Unrolled = 1,   // 1: K step units, 0: one step unit reused K times
  parameter integer FifoLog2 = 8,   // iterative form: log2 of the start FIFO depth (2..12)
  parameter integer CtxW     = 1,   // caller's context passed through
  // Derived (do not override).
  parameter integer K    = N / N1,
`include "rpu_ip_derived.vh"
  parameter integer MdW  = Metric == 0 ? CoordW + 4 : 2 * CoordW + 8,
  parameter integer StW  = N + TW + 3*XW + MdW + MdW
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
  input  wire [CtxW-1:0]     ctx_i,
  output wire                valid_o,
  output wire [StW-1:0]      state_o,    // {τ_K, lo.t, lo.X, lo.md, hi.md}
  output wire                ovf_o,
  output wire [CtxW-1:0]     ctx_o
);
  localparam integer KW = 8;
`include "rpu_guide_desc.vh"
  localparam integer HW = GsHW;              // guide height h
  localparam integer GdHO = GdShapeO + GsHO;  // h within the descriptor
  // Everything a step needs, as one bundle {pair, caller's context, overflow}; the pair's fields
  // from the top: A, AB, α, β, p1, d, L², then per guide its descriptor and h², {g, h²}.
  localparam integer GhW   = GdW + RadW;
  localparam integer PairW = 3*CoordW + 3*DW + 2*TW + 3*CoordW + 3*DW + L2W + 2 * GhW;
  localparam integer BunW  = PairW + CtxW + 1;
  // Field offsets in a bundle (LSB of each field), from the overflow bit up.
  localparam integer OffG2    = CtxW + 1;
  localparam integer OffG1    = OffG2 + GhW;
  localparam integer OffL2    = OffG1 + GhW;
  localparam integer OffD     = OffL2 + L2W;
  localparam integer OffP1    = OffD + 3*DW;
  localparam integer OffBeta  = OffP1 + 3*CoordW;
  localparam integer OffAlpha = OffBeta + TW;
  localparam integer OffAB    = OffAlpha + TW;
  localparam integer OffA     = OffAB + 3*DW;

  initial begin
    if (K > 255) $fatal(1, "rpu_ip: N/N1 must be below 256");
    if (FifoLog2 < 2 || FifoLog2 > 12) $fatal(1, "rpu_ip: FifoLog2 must be in 2..12");
    if (OffA + 3*CoordW != BunW) $fatal(1, "rpu_ip: internal: bundle offsets");
    if (GdW != GdWords) $fatal(1, "rpu_ip: GdW is derived; do not override it");
  end

  // ---- input stage: h1², h2² (exact, RadW = 2·HW bits: one rpu_mul_vec), the pair and the
  //      caller's context riding in its tag ----
  localparam integer InTagW = PairW - 2 * RadW + CtxW;
  localparam integer HeadW  = PairW - 2 * GhW;             // A .. L²
  wire               valid_0q;
  wire [2*RadW-1:0]  hh;                                   // {h2², h1²}
  wire [InTagW-1:0]  in_0q;                                // {head, g1, g2, ctx}
  rpu_mul_vec #(.Count(2), .AW(HW), .BW(HW), .Signed(0), .TagW(InTagW)) u_hh (
    .clk_i, .rst_ni, .valid_i(valid_i && ready_o), .a_i({g2_i[GdHO +: HW], g1_i[GdHO +: HW]}),
    .b_i({g2_i[GdHO +: HW], g1_i[GdHO +: HW]}),
    .tag_i({a_i, ab_i, alpha_i, beta_i, p1_i, d_i, l2_i, g1_i, g2_i, ctx_i}),
    .valid_o(valid_0q), .p_o(hh), .tag_o(in_0q));
  // h² after each guide: {head, g1, h1², g2, h2²}.
  wire [PairW-1:0]  pair_0q = {in_0q[InTagW-1 -: HeadW], in_0q[CtxW + GdW +: GdW], hh[0 +: RadW],
                               in_0q[CtxW +: GdW], hh[RadW +: RadW]};
  wire [CtxW-1:0]   ctx_0q  = in_0q[CtxW-1:0];

  // Unpacking a bundle {pair, ctx, ovf} into a step's or a candidate's ports.
  `define RPU_IP_STEP_PORTS(B) \
    .a_i(B[OffA +: 3*CoordW]), \
    .ab_i(B[OffAB +: 3*DW]), \
    .alpha_i(B[OffAlpha +: TW]), \
    .beta_i(B[OffBeta +: TW]), \
    .p1_i(B[OffP1 +: 3*CoordW]), \
    .d_i(B[OffD +: 3*DW]), \
    .l2_i(B[OffL2 +: L2W]), \
    .g1_i(B[OffG1 + RadW +: GdW]), \
    .hh1_i(B[OffG1 +: RadW]), \
    .g2_i(B[OffG2 + RadW +: GdW]), \
    .hh2_i(B[OffG2 +: RadW])

  wire [BunW-1:0] bun_0 = {pair_0q, ctx_0q, 1'b0};

  // ---- start unit: candidates τ = 0 (carries the bundle) and τ = 1 ----
  wire            s_valid, s_ovf0, s_ovf1;
  wire [TW-1:0]   s_t0, s_t1_unused;
  wire [3*XW-1:0] s_x0, s_x1_unused;
  wire [MdW-1:0]  s_md0, s_md1;
  wire [BunW-1:0] s_bun;
  wire            s_valid1_unused;
  wire [BunW-1:0] s_tag1_unused;
  wire [3*(CoordW+2)-1:0] s_pr0_unused, s_pr1_unused;
  rpu_candidate #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                  .Metric(Metric), .TagW(BunW)) u_start0 (
    .clk_i, .rst_ni, .valid_i(valid_0q), .m_i({(N+1){1'b0}}), `RPU_IP_STEP_PORTS(bun_0),
    .tag_i(bun_0), .valid_o(s_valid), .t_o(s_t0), .x_o(s_x0),
    .pr_o(s_pr0_unused), .md_o(s_md0), .ovf_o(s_ovf0), .tag_o(s_bun));
  rpu_candidate #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                  .Metric(Metric), .TagW(1)) u_start1 (
    .clk_i, .rst_ni, .valid_i(valid_0q), .m_i({1'b1, {N{1'b0}}}), `RPU_IP_STEP_PORTS(bun_0),
    .tag_i(1'b0), .valid_o(s_valid1_unused), .t_o(s_t1_unused), .x_o(s_x1_unused),
    .pr_o(s_pr1_unused), .md_o(s_md1), .ovf_o(s_ovf1), .tag_o(s_tag1_unused[0]));
  assign s_tag1_unused[BunW-1:1] = {(BunW-1){1'b0}};
  wire unused_start = ^{s_valid1_unused, s_t1_unused, s_x1_unused, s_tag1_unused, s_pr0_unused,
                        s_pr1_unused, s_bun[0]};
  wire [StW-1:0]  s_state = {{N{1'b0}}, s_t0, s_x0, s_md0, s_md1};
  wire [BunW-1:0] s_bundle = {s_bun[BunW-1:1], s_ovf0 | s_ovf1};

  generate
    if (Unrolled != 0) begin : g_unrolled
      assign ready_o = 1'b1;
      // split_var: one Verilator variable per stage's slice (see rpu_sqrt).
      wire [K:0]          v   /* verilator split_var */;
      wire [(K+1)*StW-1:0] st  /* verilator split_var */;
      wire [(K+1)*BunW-1:0] bun /* verilator split_var */;
      assign v[0] = s_valid;
      assign st[0 +: StW] = s_state;
      assign bun[0 +: BunW] = s_bundle;
      genvar k;
      for (k = 1; k <= K; k = k + 1) begin : g_step
        wire [BunW-1:0] b = bun[(k-1)*BunW +: BunW];
        wire [KW-1:0]   k_unused;
        wire            step_ovf;
        wire [BunW-1:0] b_out;
        wire            tag_unused;
        rpu_ip_step #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                      .N1(N1), .Metric(Metric), .Step(k), .CtxW(BunW), .TagW(1)) u_step (
          .clk_i, .rst_ni, .valid_i(v[k-1]), .k_i({KW{1'b0}}), .state_i(st[(k-1)*StW +: StW]),
          `RPU_IP_STEP_PORTS(b), .ctx_i(b), .tag_i(1'b0),
          .valid_o(v[k]), .k_o(k_unused), .state_o(st[k*StW +: StW]), .ovf_o(step_ovf),
          .ctx_o(b_out), .tag_o(tag_unused));
        assign bun[k*BunW +: BunW] = {b_out[BunW-1:1], b_out[0] | step_ovf};
        wire unused_k = ^{k_unused, tag_unused};
      end
      assign valid_o = v[K];
      assign state_o = st[K*StW +: StW];
      assign ovf_o   = bun[K*BunW];
      assign ctx_o   = bun[K*BunW+1 +: CtxW];
      wire unused_pair = ^bun[K*BunW+CtxW+1 +: PairW];
    end else begin : g_iterative
      // Start FIFO: pairs leaving the start unit wait for a free slot of the step unit. Block
      // RAM with a registered read (rpu_fifo); its output register adds one entry of room.
      localparam integer Depth = 1 << FifoLog2;
      localparam integer FW = StW + BunW;
      // Credits: pairs accepted and not yet taken by the step unit never exceed the FIFO depth.
      reg [FifoLog2:0]   owed_q;  // accepted, not yet popped into the ring
      wire               loop_valid;
      wire [KW-1:0]      loop_k;
      wire [StW-1:0]     loop_st;
      wire [BunW-1:0]    loop_bun;
      wire               loop_ovf;
      wire               tag_unused;
      wire               recirc   = loop_valid && (loop_k != K[KW-1:0]);
      wire               fifo_any;
      wire               fifo_wr_ready_unused;
      wire [FW-1:0]      head;
      wire               pop      = fifo_any && !recirc;
      wire               accept   = valid_i && ready_o;
      assign ready_o = owed_q < Depth[FifoLog2:0];
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) owed_q <= {(FifoLog2+1){1'b0}};
        else owed_q <= owed_q + {{FifoLog2{1'b0}}, accept} - {{FifoLog2{1'b0}}, pop};
      end
      rpu_fifo #(.Width(FW), .Log2Depth(FifoLog2)) u_start_fifo (
        .clk_i, .rst_ni, .wr_valid_i(s_valid), .wr_ready_o(fifo_wr_ready_unused),
        .wr_data_i({s_state, s_bundle}), .rd_valid_o(fifo_any), .rd_ready_i(!recirc),
        .rd_data_o(head));
      // The step unit's input: a returning item (its next k), else the FIFO head (k = 1).
      wire            in_v   = recirc || pop;
      wire [KW-1:0]   in_k   = recirc ? loop_k + 1'b1 : {{(KW-1){1'b0}}, 1'b1};
      wire [StW-1:0]  in_st  = recirc ? loop_st : head[FW-1 -: StW];
      wire [BunW-1:0] in_bun = recirc ? {loop_bun[BunW-1:1], loop_bun[0] | loop_ovf}
                                      : head[BunW-1:0];
      wire [BunW-1:0] out_bun;
      rpu_ip_step #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                    .N1(N1), .Metric(Metric), .Step(0), .CtxW(BunW), .TagW(1)) u_step (
        .clk_i, .rst_ni, .valid_i(in_v), .k_i(in_k), .state_i(in_st),
        `RPU_IP_STEP_PORTS(in_bun), .ctx_i(in_bun), .tag_i(1'b0),
        .valid_o(loop_valid), .k_o(loop_k), .state_o(loop_st), .ovf_o(loop_ovf),
        .ctx_o(out_bun), .tag_o(tag_unused));
      assign loop_bun = out_bun;
      assign valid_o  = loop_valid && (loop_k == K[KW-1:0]);
      assign state_o  = loop_st;
      assign ovf_o    = loop_bun[0] | loop_ovf;
      assign ctx_o    = loop_bun[1 +: CtxW];
      wire unused_iter = ^{tag_unused, fifo_wr_ready_unused, loop_bun[BunW-1 -: PairW]};
    end
  endgenerate
  `undef RPU_IP_STEP_PORTS
endmodule

`default_nettype wire
