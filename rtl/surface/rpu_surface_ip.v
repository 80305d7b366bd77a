// rpu_surface_ip: the K-step sign search of one surface piece (docs/surfaces.md, "The iterative
// process on a piece"), twin of rpu::ref::surface_ip (ref/model/surface/rpu_surface_ip.{h,cpp}). The
// search runs as K + 1 passes of rpu_surface_ip_step: pass 0 evaluates the ends τ = 0 and τ = 1,
// pass k = 1..K the J − 1 new candidates of step k and the first sign change; a step 1 without
// one is a miss.
//   Unrolled = 1: K + 1 pass units in a pipeline (2 + K·(J − 1) indicators), one item per cycle,
//                 ready_o = 1; the item's data rides the pass units' tags.
//   Unrolled = 0: one pass unit with max(J − 1, 2) indicators, used K + 1 times by each item
//                 (the default: 3 indicators instead of 26 at n = 16, n1 = 2). An item enters
//                 the unit's ring when the slot passing the ring's input is free and goes round
//                 K + 1 times without waiting; ready_o = that slot is free (no item returning
//                 for another pass this cycle), a compare of the unit's output registers.
//                 At full load one item per K + 1 cycles; bursts of up to one ring period (L
//                 items) are taken back to back.
// Both forms have the same fixed latency (K + 1)·L + 1, L = one pass
// (rpu_surface_pass_latency, rpu_surface_latency.vh; ref::surface_ip_latency: 721 at the
// defaults), and keep the input order.
//
// Iterative form, context: an item's data (lA', lB' − lA', the branch bits, the descriptor and
// ctx_i: 571 bits at the defaults with a 1-bit ctx_i, 722 in rpu_surface_top) does not ride the
// ring (that would be L × 571 flip-flops or SRL bits per ring slot, 45,680 at the defaults). Every item
// in the ring has its own ring phase (the cycle it entered, modulo L), so a RAM of L entries
// indexed by the phase holds it: written when the item enters (its pass 0 takes the input ports
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
  parameter integer Unrolled = 0,   // 1: K + 1 pass units, 0: one pass unit used K + 1 times
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
  localparam integer K   = N / N1;
  localparam integer KW  = 8;
  localparam integer ShW = 8;
  localparam integer StW = N + 4;                 // {τ, lo, hi, live, ovf}
  localparam integer L   = rpu_surface_pass_latency(SurfW, AngleW, N);
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
    if (Unrolled != 0 && Unrolled != 1) $fatal(1, "rpu_surface_ip: Unrolled must be 0 or 1");
    if (CtxW < 1) $fatal(1, "rpu_surface_ip: CtxW must be >= 1");
    if (DescW != SdW || LabW != SurfW + 1)
      $fatal(1, "rpu_surface_ip: derived parameters must not be overridden");
  end

  wire [DW-1:0]  data_in = {ctx_i, desc_i, la_i, lab_i, x_negative_i, last_turn_i};
  // The state an item starts with: τ = 0, lo = hi = 0 (pass 0 sets them), live = run_i, no ovf.
  wire [StW-1:0] st_in   = {{(N + 2){1'b0}}, run_i, 1'b0};

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
      wire [K+1:0]         v  /* verilator split_var */;
      wire [(K+2)*StW-1:0] st /* verilator split_var */;
      wire [(K+2)*DW-1:0]  dt /* verilator split_var */;
      assign {v[0], st[0 +: StW], dt[0 +: DW]} = {valid_i, st_in, data_in};
      genvar k;
      for (k = 0; k <= K; k = k + 1) begin : g_pass
        wire [DW-1:0] d = dt[k*DW +: DW];
        wire [KW-1:0] k_unused;
        wire [ShW-1:0] sh_unused;
        rpu_surface_ip_step #(.SurfW(SurfW), .AngleW(AngleW), .Turns(Turns), .N(N), .N1(N1),
                              .Pass(k), .CtxW(DW)) u_pass (
          .clk_i, .rst_ni, .valid_i(v[k]), .k_i({KW{1'b0}}), .shift_i({ShW{1'b0}}),
          .state_i(st[k*StW +: StW]), `RPU_SURFACE_PASS_DATA(d), .ctx_i(d),
          .valid_o(v[k+1]), .k_o(k_unused), .shift_o(sh_unused), .state_o(st[(k+1)*StW +: StW]),
          .ctx_o(dt[(k+1)*DW +: DW]));
        wire unused_k = ^{k_unused, sh_unused};
      end
      assign out_valid = v[K+1];
      assign out_st    = st[(K+1)*StW +: StW];
      assign out_ctx   = dt[(K+1)*DW + DCtxO +: CtxW];
      wire unused_out = ^dt[(K+1)*DW +: DCtxO];
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
      // The pass unit's output: an item returning for its next pass, or leaving after pass K.
      wire           ret_valid;
      wire [KW-1:0]  ret_k;                    // the item's next pass
      wire [ShW-1:0] ret_shift;                // and its shift
      wire [StW-1:0] ret_st;
      wire           ret_ctx_unused;
      localparam integer   Done  = K + 1;
      wire           recirc = ret_valid && (ret_k != Done[KW-1:0]);
      wire           leave  = ret_valid && (ret_k == Done[KW-1:0]);
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
      // a new item (pass 0, its data from the ports).
      wire           in_valid = recirc || accept;
      wire [KW-1:0]  in_k     = recirc ? ret_k : {KW{1'b0}};
      wire [ShW-1:0] in_shift = recirc ? ret_shift : N[ShW-1:0];
      wire [StW-1:0] in_st    = recirc ? ret_st : st_in;
      wire [DW-1:0]  in_d     = recirc ? rd_q : data_in;
      rpu_surface_ip_step #(.SurfW(SurfW), .AngleW(AngleW), .Turns(Turns), .N(N), .N1(N1),
                            .Pass(-1), .CtxW(1)) u_pass (
        .clk_i, .rst_ni, .valid_i(in_valid), .k_i(in_k), .shift_i(in_shift), .state_i(in_st),
        `RPU_SURFACE_PASS_DATA(in_d), .ctx_i(1'b0),
        .valid_o(ret_valid), .k_o(ret_k), .shift_o(ret_shift), .state_o(ret_st),
        .ctx_o(ret_ctx_unused));
      assign out_valid = leave;
      assign out_st    = ret_st;
      assign out_ctx   = rd_q[DCtxO +: CtxW];
      wire unused_iter = ret_ctx_unused;
    end
  endgenerate
  `undef RPU_SURFACE_PASS_DATA
  rpu_stage #(.W(1 + N + 1 + CtxW)) u_out (
    .clk_i, .rst_ni, .valid_i(out_valid),
    .d_i({out_st[1], out_st[StW-1 -: N], out_st[0], out_ctx}),
    .valid_o, .q_o({hit_o, tau_o, ovf_o, ctx_o}));
  wire unused_st = ^out_st[3:2];  // lo, hi
endmodule

`default_nettype wire
