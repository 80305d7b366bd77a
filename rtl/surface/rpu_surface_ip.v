// rpu_surface_ip: the sign search of one surface piece (docs/surfaces.md, "The search on a
// piece"), twin of rpu::ref::surface_ip (ref/model/surface/rpu_surface_ip.{h,cpp}). The search
// runs as P passes of rpu_surface_ip_step (NC = Indicators indicators each, 0 meaning 2^N1 − 1):
// step k (b_k bits: N1First for step 1, 0 meaning N1; N1 for each later step, the last what
// remains of N) takes ⌈(2^b_1 + 1)/NC⌉ passes for step 1's candidates, the ends τ = 0 and τ = 1
// among them, and ⌈(2^b_k − 1)/NC⌉ for the new candidates of each later step; a step 1 without a
// sign change is a miss. P = rpu_surface_passes (rpu_surface_latency.vh;
// ref::surface_ip_passes): 48 at the defaults (N 16, N1 2, N1First 7, 3 indicators: steps of 7,
// 2, 2, 2, 2, 1 bits, 142 candidates), K + 1 with N1First = 0; 142 with one indicator.
//   Unrolled = 1: P pass units in a pipeline (P·NC indicators), one item per cycle, ready_o = 1;
//                 the item's data rides the pass units' tags.
//   Unrolled = 0: one pass unit, used P times by each item (the default: 3 indicators). An item
//                 enters the unit's ring when the slot passing the ring's input is free and goes
//                 round P times without waiting; ready_o = that slot is free (no item returning
//                 for another pass this cycle), a compare of the unit's output registers.
//                 At full load one item per P cycles; bursts of up to one ring period (L items)
//                 are taken back to back.
// Both forms have the same fixed latency P·L + 1, L = one pass (rpu_surface_pass_latency,
// rpu_surface_latency.vh; ref::surface_ip_latency: 3,841 at the defaults), and keep the input
// order. The item's search state (rpu_surface_state.vh) carries its schedule: the pass unit reads
// from it what to evaluate, and sets done after the last pass.
//
// Iterative form, context: an item's data (lA', lB' − lA', the branch bits, the descriptor and
// ctx_i: 571 bits at the defaults with a 1-bit ctx_i, 722 in rpu_surface_top) does not ride the
// ring (that would be L × 571 flip-flops or SRL bits per ring slot, 45,680 at the defaults). Every item
// in the ring has its own ring phase (the cycle it entered, modulo L), so a RAM of L entries
// indexed by the phase holds it: written when the item enters (its first pass takes the input ports
// directly), read one cycle before each return (a registered read: block RAM), and for the exit
// (ctx_o). The phase counter runs modulo L whether or not items flow. Yosys maps the RAM to
// ⌈571 / 72⌉ = 8 RAMB36E1 (512 × 72) at the defaults.
//
// run_i = 0 (the setup found no such piece): the item still takes its slot and its passes but is
// not searched: hit_o = 0, tau_o = 0, ovf_o = 0 (the twin does not run the IP then).
// Outputs: hit_o = the piece has a sign change (the twin's !miss), tau_o = τ_K (0 without a hit),
// ovf_o = some indicator of the search saturated (the twin's flag), ctx_o = ctx_i.
`default_nettype none
`include "rpu_widths.vh"

module rpu_surface_ip #(
`include "rpu_surface_ip_params.vh"
  parameter integer Unrolled = 0,   // 1: P pass units, 0: one pass unit used P times
  parameter integer CtxW     = 1,   // caller's context passed through (>= 1)
  // Derived (do not override).
  parameter integer DescW    = `RPU_SDW(SurfW), // the descriptor word (rpu_surface_desc.vh)
  parameter integer LabW     = SurfW + 1        // lB' − lA'
) (
  input  wire               clk_i,
  input  wire               rst_ni,
  input  wire               valid_i,
  output wire               ready_o,
  input  wire               run_i,         // the piece exists (the setup's piece_valid)
  input  wire [3*SurfW-1:0] la_i,          // lA', llsb, {z, y, x}
  input  wire [3*LabW-1:0]  lab_i,         // lB' − lA', llsb, {z, y, x}
  input  wire               x_negative_i,  // the piece's azimuth branch (spiral, snail)
  input  wire               last_turn_i,
  input  wire [DescW-1:0]   desc_i,        // the surface's indicator fields (rpu_surface_desc.vh)
  input  wire [CtxW-1:0]    ctx_i,
  output wire               valid_o,
  output wire               hit_o,
  output wire [N-1:0]       tau_o,
  output wire               ovf_o,
  output wire [CtxW-1:0]    ctx_o
);
`include "rpu_mul_latency.vh"
`include "rpu_surface_latency.vh"
`include "rpu_surface_desc.vh"
  localparam integer LW  = SurfW;
`include "rpu_surface_state.vh"
  localparam integer StW = SsW;
  localparam integer L   = rpu_surface_pass_latency(SurfW, AngleW, N);
  localparam integer P   = rpu_surface_passes(N, N1, N1First, Indicators);
  localparam integer B1  = rpu_surface_first_bits(N, N1, N1First);
  // An item's data, {ctx, desc, la, lab, x_negative, last_turn}; offsets from the bottom.
  localparam integer DBranchO = 0;
  localparam integer DLabO    = DBranchO + 2;
  localparam integer DLaO     = DLabO + 3 * LabW;
  localparam integer DDescO   = DLaO + 3 * LW;
  localparam integer DCtxO    = DDescO + SdW;
  localparam integer DW       = DCtxO + CtxW;

  initial begin
    if (SurfW < 16 || SurfW > 36) $fatal(1, "rpu_surface_ip: SurfW must be in 16..36");
    if (N < 1 || N > 40) $fatal(1, "rpu_surface_ip: N must be in 1..40");
    if (N1 < 1 || N1 > 8 || N % N1 != 0)
      $fatal(1, "rpu_surface_ip: N1 must be in 1..8 and divide N");
    if (N1First < 0 || N1First > 10) $fatal(1, "rpu_surface_ip: N1First must be in 0..10");
    if (Indicators < 0 || Indicators > 64) $fatal(1, "rpu_surface_ip: Indicators must be in 0..64");
    if (Unrolled != 0 && Unrolled != 1) $fatal(1, "rpu_surface_ip: Unrolled must be 0 or 1");
    if (CtxW < 1) $fatal(1, "rpu_surface_ip: CtxW must be >= 1");
    if (DescW != SdW || LabW != SurfW + 1)
      $fatal(1, "rpu_surface_ip: derived parameters must not be overridden");
  end

  wire [DW-1:0]  data_in = {ctx_i, desc_i, la_i, lab_i, x_negative_i, last_turn_i};
  // The state an item starts with: step 1's first pass next (lane e at m = e·2^shift), step 1's
  // bits and shift, live = run_i; everything else 0.
  localparam integer     Shift1I = N - B1;
  localparam [SsBW-1:0]  Bits1  = B1[SsBW-1:0];
  localparam [SsShW-1:0] Shift1 = Shift1I[SsShW-1:0];
  wire [SsLanes*SsMW-1:0] m_in;
  genvar g;
  generate
    for (g = 0; g < SsLanes; g = g + 1) begin : g_m_in
      localparam [SsMW-1:0] Lane = g;
      assign m_in[g*SsMW +: SsMW] = Lane << Shift1I;
    end
  endgenerate
  reg [StW-1:0] st_in;
  always @(*) begin
    st_in = {StW{1'b0}};
    st_in[SsLiveO]                  = run_i;
    st_in[SsStartO]                 = 1'b1;
    st_in[SsFirstO]                 = 1'b1;
    st_in[SsBitsO +: SsBW]          = Bits1;
    st_in[SsShiftO +: SsShW]        = Shift1;
    st_in[SsMO +: SsLanes*SsMW]     = m_in;
  end

  `define RPU_SURFACE_PASS_DATA(D) \
    .la_i(D[DLaO +: 3*LW]), .lab_i(D[DLabO +: 3*LabW]), .x_negative_i(D[DBranchO + 1]), \
    .last_turn_i(D[DBranchO]), .desc_i(D[DDescO +: SdW])

  // Both forms' output: the item leaving after pass K, its state and its ctx.
  wire            out_valid;
  wire [StW-1:0]  out_st;
  wire [CtxW-1:0] out_ctx;
  generate
    if (Unrolled != 0) begin : g_unrolled
      assign ready_o = 1'b1;
      // split_var: one Verilator variable per pass's slice (see rpu_sqrt).
      wire [P:0]         v  /* verilator split_var */;
      wire [(P+1)*StW-1:0] st /* verilator split_var */;
      wire [(P+1)*DW-1:0]  dt /* verilator split_var */;
      assign {v[0], st[0 +: StW], dt[0 +: DW]} = {valid_i, st_in, data_in};
      genvar k;
      for (k = 0; k < P; k = k + 1) begin : g_pass
        wire [DW-1:0] d = dt[k*DW +: DW];
        rpu_surface_ip_step #(.SurfW(SurfW), .AngleW(AngleW), .Turns(Turns), .N(N), .N1(N1),
                              .N1First(N1First), .Indicators(Indicators), .CtxW(DW)) u_pass (
          .clk_i, .rst_ni, .valid_i(v[k]), .state_i(st[k*StW +: StW]), `RPU_SURFACE_PASS_DATA(d),
          .ctx_i(d), .valid_o(v[k+1]), .state_o(st[(k+1)*StW +: StW]), .ctx_o(dt[(k+1)*DW +: DW]));
      end
      assign out_valid = v[P];
      assign out_st    = st[P*StW +: StW];
      assign out_ctx   = dt[P*DW + DCtxO +: CtxW];
      wire unused_out = ^dt[P*DW +: DCtxO];
    end else begin : g_iterative
      localparam integer PhW = $clog2(L);
      localparam integer   LastI  = L - 1;
      localparam [PhW-1:0] PhLast = LastI[PhW-1:0];
      // The ring phase: the cycle modulo L. An item keeps its phase for all its passes.
      reg  [PhW-1:0] ph_q;
      wire [PhW-1:0] ph_next = ph_q == PhLast ? {PhW{1'b0}} : ph_q + 1'b1;
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) ph_q <= {PhW{1'b0}};
        else         ph_q <= ph_next;
      end
      // The pass unit's output: an item returning for its next pass, or leaving after its last.
      wire           ret_valid;
      wire [StW-1:0] ret_st;
      wire           ret_ctx_unused;
      wire           recirc = ret_valid && !ret_st[SsDoneO];
      wire           leave  = ret_valid && ret_st[SsDoneO];
      assign ready_o = !recirc;
      wire           accept = valid_i && !recirc;
      // The context RAM (block RAM: one write port, one registered read port). Entry ph holds
      // the data of the item of phase ph; the read of the next phase's entry is registered, so
      // rd_q is the data of the item returning (or leaving) this cycle.
      reg [DW-1:0] mem_q [0:L-1];
      reg [DW-1:0] rd_q;
      always @(posedge clk_i) begin
        if (accept) mem_q[ph_q] <= data_in;
        rd_q <= mem_q[ph_next];
      end
      // The pass unit's input: the returning item (its next pass, its data from the RAM), else
      // a new item (its first pass, its data from the ports).
      wire           in_valid = recirc || accept;
      wire [StW-1:0] in_st    = recirc ? ret_st : st_in;
      wire [DW-1:0]  in_d     = recirc ? rd_q : data_in;
      rpu_surface_ip_step #(.SurfW(SurfW), .AngleW(AngleW), .Turns(Turns), .N(N), .N1(N1),
                            .N1First(N1First), .Indicators(Indicators), .CtxW(1)) u_pass (
        .clk_i, .rst_ni, .valid_i(in_valid), .state_i(in_st), `RPU_SURFACE_PASS_DATA(in_d),
        .ctx_i(1'b0), .valid_o(ret_valid), .state_o(ret_st), .ctx_o(ret_ctx_unused));
      assign out_valid = leave;
      assign out_st    = ret_st;
      assign out_ctx   = rd_q[DCtxO +: CtxW];
      wire unused_iter = ret_ctx_unused;
    end
  endgenerate
  `undef RPU_SURFACE_PASS_DATA
  rpu_stage #(.W(1 + N + 1 + CtxW)) u_out (
    .clk_i, .rst_ni, .valid_i(out_valid),
    .d_i({out_st[SsLiveO], out_st[SsTauO +: N], out_st[SsOvfO], out_ctx}),
    .valid_o, .q_o({hit_o, tau_o, ovf_o, ctx_o}));
  // The rest of the final state: the interval's end bits and the search's bookkeeping.
  wire unused_st = ^{out_st[StW-1:SsFoundO], out_st[SsLoO], out_st[SsHiO]};
endmodule

`default_nettype wire
