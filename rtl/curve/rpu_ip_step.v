// rpu_ip_step: one step of the iterative process (docs/algorithms.md §1.2 step 3), twin of
// rpu::ref::ip_step. The J − 1 new candidates m_j = τ + j·2^(N − N1·k), j = 1..J−1, are
// evaluated in parallel; with md_0 = lo.md and md_J = hi.md the pair sums sd_j = md_j + md_{j+1}
// go through a lowest-index argmin η, and the next state is
//   τ' = τ + η·2^(N − N1·k),  lo' = candidate η (or lo),  hi'.md = md_{η+1} (or hi.md).
// Step = k wired in (unrolled pipeline), or Step = 0: k comes with the item (iterative form).
// The segment and interval context rides in candidate 1's tag. Fixed latency: the candidate's,
// then the pair sums (registered), then the compares and the select (registered).
`default_nettype none
`include "rpu_widths.vh"

module rpu_ip_step #(
`include "rpu_ip_params.vh"
  parameter integer N1       = 2,   // bits per step (1..8), N % N1 == 0
  parameter integer Metric   = 0,   // 0: |pr − X|, 1: |pr − X|²
  parameter integer Step     = 1,   // k of this unit (1..N/N1), or 0: taken from k_i
  parameter integer CtxW     = 1,   // width of the segment/interval context passed through
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer K    = N / N1,
  parameter integer J    = 1 << N1,
  parameter integer KW   = 8,                     // step counter width
`include "rpu_ip_derived.vh"
  parameter integer MdW  = Metric == 0 ? CoordW + 4 : 2 * CoordW + 8,
  parameter integer StW  = N + TW + 3*XW + MdW + MdW  // {tau, lo.t, lo.X, lo.md, hi.md}
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [KW-1:0]       k_i,        // this step's k (used when Step == 0)
  input  wire [StW-1:0]      state_i,
  input  wire [3*CoordW-1:0] a_i,
  input  wire [3*DW-1:0]     ab_i,
  input  wire [TW-1:0]       alpha_i,
  input  wire [TW-1:0]       beta_i,
  input  wire [3*CoordW-1:0] p1_i,
  input  wire [3*DW-1:0]     d_i,
  input  wire [L2W-1:0]      l2_i,
  input  wire [GdW-1:0]      g1_i,       // guide of end 1 (rpu_guide_desc.vh)
  input  wire [RadW-1:0]     hh1_i,      // h1² (the caller computes it once per pair)
  input  wire [GdW-1:0]      g2_i,       // guide of end 2
  input  wire [RadW-1:0]     hh2_i,      // h2²
  input  wire [CtxW-1:0]     ctx_i,      // passed through unchanged (the caller's descriptors)
  input  wire [TagW-1:0]     tag_i,
  output wire                valid_o,
  output wire [KW-1:0]       k_o,        // this step's k
  output wire [StW-1:0]      state_o,
  output wire                ovf_o,      // a candidate of this step saturated
  output wire [CtxW-1:0]     ctx_o,
  output wire [TagW-1:0]     tag_o
);
  initial begin
    if (N1 < 1 || N1 > 8) $fatal(1, "rpu_ip_step: N1 must be in 1..8");
    if (N % N1 != 0) $fatal(1, "rpu_ip_step: N must be a multiple of N1");
    if (Step < 0 || Step > K) $fatal(1, "rpu_ip_step: Step must be in 0..N/N1");
  end

  // State fields.
  wire [N-1:0]   tau_in = state_i[StW-1 -: N];
  wire [KW-1:0]  k_in   = Step == 0 ? k_i : Step[KW-1:0];
  // Shift of this step: N − N1·k (k ≥ 1).
  wire [KW+7:0]  shift  = N[KW+7:0] - N1[KW+7:0] * {8'd0, k_in};

  // The side band carried by candidate 1: everything the step needs after the candidates.
  localparam integer SbW = KW + StW + CtxW + TagW;
  localparam integer SbStO = CtxW + TagW;              // {k, state, ctx, tag}, LSB first
  localparam integer StTO  = StW - N - TW;             // state: {τ, t, X, md_lo, md_hi}
  localparam integer StXO  = StTO - 3*XW;
  wire [SbW-1:0] sb_in = {k_in, state_i, ctx_i, tag_i};

  wire [J-2:0]      c_valid;
  wire [(J-1)*TW-1:0]   c_t;
  wire [(J-1)*3*XW-1:0] c_x;
  wire [(J-1)*MdW-1:0]  c_md;
  wire [J-2:0]      c_ovf;
  wire [SbW-1:0]    sb_out;
  genvar j;
  generate
    for (j = 1; j < J; j = j + 1) begin : g_cand
      wire [N:0] m = {1'b0, tau_in} + ({{N{1'b0}}, 1'b1} * j << shift);
      wire [3*(CoordW+2)-1:0] pr_unused;
      if (j == 1) begin : g_carry
        rpu_candidate #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                        .Metric(Metric), .TagW(SbW)) u_cand (
          .clk_i, .rst_ni, .valid_i, .m_i(m), .a_i, .ab_i, .alpha_i, .beta_i, .p1_i, .d_i, .l2_i,
          .g1_i, .hh1_i, .g2_i, .hh2_i,
          .tag_i(sb_in), .valid_o(c_valid[j-1]), .t_o(c_t[(j-1)*TW +: TW]),
          .x_o(c_x[(j-1)*3*XW +: 3*XW]), .pr_o(pr_unused), .md_o(c_md[(j-1)*MdW +: MdW]),
          .ovf_o(c_ovf[j-1]), .tag_o(sb_out));
      end else begin : g_plain
        wire tag_unused;
        rpu_candidate #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N),
                        .Metric(Metric), .TagW(1)) u_cand (
          .clk_i, .rst_ni, .valid_i, .m_i(m), .a_i, .ab_i, .alpha_i, .beta_i, .p1_i, .d_i, .l2_i,
          .g1_i, .hh1_i, .g2_i, .hh2_i,
          .tag_i(1'b0), .valid_o(c_valid[j-1]), .t_o(c_t[(j-1)*TW +: TW]),
          .x_o(c_x[(j-1)*3*XW +: 3*XW]), .pr_o(pr_unused), .md_o(c_md[(j-1)*MdW +: MdW]),
          .ovf_o(c_ovf[j-1]), .tag_o(tag_unused));
        wire unused_plain = tag_unused;
      end
      wire unused_pr = ^pr_unused;
    end
  endgenerate

  // ---- after the candidates: the pair sums sd_j = md_j + md_{j+1} (md_0 = lo.md, md_J = hi.md),
  //      registered with everything the select needs, so the compares start from flip-flops ----
  localparam integer StA = SbW - KW - 1;  // the state's top bit in the side band
  wire [MdW-1:0] md_a [0:J];
  assign md_a[0] = sb_out[StA-StW+2*MdW -: MdW];
  assign md_a[J] = sb_out[StA-StW+MdW -: MdW];
  generate
    for (j = 1; j < J; j = j + 1) begin : g_md_a
      assign md_a[j] = c_md[(j-1)*MdW +: MdW];
    end
  endgenerate
  reg                    valid_r;
  reg [SbW-1:0]          sb_r;
  reg [(J-1)*TW-1:0]     c_t_r;
  reg [(J-1)*3*XW-1:0]   c_x_r;
  reg [(J-1)*MdW-1:0]    c_md_r;
  reg [J-2:0]            c_ovf_r;
  reg [MdW:0]            sd [0:J-1];
  integer q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_r <= 1'b0;
    else         valid_r <= c_valid[0];
  end
  always @(posedge clk_i) begin
    sb_r    <= sb_out;
    c_t_r   <= c_t;
    c_x_r   <= c_x;
    c_md_r  <= c_md;
    c_ovf_r <= c_ovf;
    for (q = 0; q < J; q = q + 1) sd[q] <= {1'b0, md_a[q]} + {1'b0, md_a[q+1]};
  end

  // Unpack the registered side band.
  wire [KW-1:0]   k_c     = sb_r[SbW-1 -: KW];
  wire [StW-1:0]  st_c    = sb_r[SbStO +: StW];
  wire [CtxW-1:0] ctx_c   = sb_r[CtxW+TagW-1 -: CtxW];
  wire [TagW-1:0] tag_c   = sb_r[TagW-1:0];
  wire [N-1:0]    tau_c   = st_c[StW-1 -: N];
  wire [TW-1:0]   lo_t_c  = st_c[StTO +: TW];
  wire [3*XW-1:0] lo_x_c  = st_c[StXO +: 3*XW];
  wire [MdW-1:0]  lo_md_c = st_c[2*MdW-1 -: MdW];
  wire [MdW-1:0]  hi_md_c = st_c[MdW-1:0];
  wire [KW+7:0]   shift_c = N[KW+7:0] - N1[KW+7:0] * {8'd0, k_c};

  // The lowest-index argmin as a one-hot vector: j wins when sd_j < sd_i for every i < j and
  // sd_j ≤ sd_i for every i > j (exactly one j does). All J·(J−1)/2 compares run in parallel
  // (one carry chain after the sums' register) instead of a serial chain; the next state is an
  // AND-OR select by the one-hot.
  wire [MdW-1:0] md [0:J];
  assign md[0] = lo_md_c;
  assign md[J] = hi_md_c;
  generate
    for (j = 1; j < J; j = j + 1) begin : g_md
      assign md[j] = c_md_r[(j-1)*MdW +: MdW];
    end
  endgenerate
  reg [J-1:0] win;
  integer a, b;
`ifdef RPU_FAULT
  // The fault-injected build: which fault is on comes from the harness at time zero (DPI,
  // sim/harness/rtl_backend.cpp; 0 none, 1 the argmin tie rule, 2 rpu_resolve's depth order).
  import "DPI-C" function int rpu_fault();
  integer fault_sel;
  initial fault_sel = rpu_fault();
  wire fault_tie = fault_sel == 1;
`endif
  always @(*) begin
    for (a = 0; a < J; a = a + 1) begin
      win[a] = 1'b1;
      for (b = 0; b < J; b = b + 1) begin
`ifdef RPU_FAULT
        // Deliberate fault for the co-simulation checker's own tests (the fault-injected build
        // only, fault 1 selected at run time): the last minimum wins.
        if (fault_tie) begin
          if (b < a && sd[a] > sd[b]) win[a] = 1'b0;
          if (b > a && sd[a] >= sd[b]) win[a] = 1'b0;
        end else begin
          if (b < a && sd[a] >= sd[b]) win[a] = 1'b0;
          if (b > a && sd[a] > sd[b]) win[a] = 1'b0;
        end
`else
        if (b < a && sd[a] >= sd[b]) win[a] = 1'b0;
        if (b > a && sd[a] > sd[b]) win[a] = 1'b0;
`endif
      end
    end
  end

  // The next state: τ' = τ + η·2^shift (the bits η lands on are zero in τ, so τ | that), and
  // the winner's lo and hi fields, each an AND-OR over the one-hot.
  reg [N-1:0]     tau_next;
  reg [TW-1:0]    lo_t_n;
  reg [3*XW-1:0]  lo_x_n;
  reg [MdW-1:0]   lo_md_n, hi_md_n;
  integer e;
  always @(*) begin
    tau_next = {N{1'b0}};
    lo_t_n   = {TW{1'b0}};
    lo_x_n   = {3*XW{1'b0}};
    lo_md_n  = {MdW{1'b0}};
    hi_md_n  = {MdW{1'b0}};
    for (e = 0; e < J; e = e + 1) begin
      if (win[e]) begin
        tau_next = tau_next | (tau_c + ({{(N-N1){1'b0}}, e[N1-1:0]} << shift_c));
        lo_md_n  = lo_md_n | md[e];
        hi_md_n  = hi_md_n | md[e+1];
        if (e == 0) begin
          lo_t_n = lo_t_n | lo_t_c;
          lo_x_n = lo_x_n | lo_x_c;
        end else begin
          lo_t_n = lo_t_n | c_t_r[(e-1)*TW +: TW];
          lo_x_n = lo_x_n | c_x_r[(e-1)*3*XW +: 3*XW];
        end
      end
    end
  end

  rpu_stage #(.W(KW + StW + 1 + CtxW + TagW)) u_out (
    .clk_i, .rst_ni, .valid_i(valid_r),
    .d_i({k_c, tau_next, lo_t_n, lo_x_n, lo_md_n, hi_md_n, |c_ovf_r, ctx_c, tag_c}),
    .valid_o, .q_o({k_o, state_o, ovf_o, ctx_o, tag_o}));
  wire unused_step = ^c_valid;
endmodule

`default_nettype wire
