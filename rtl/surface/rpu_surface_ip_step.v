// rpu_surface_ip_step: one pass of the surface sign search (docs/surfaces.md, "The iterative
// process on a piece"), twin of rpu::ref::surface_ip_start (pass 0) and surface_ip_step (pass k,
// k = 1..K). τ is an N-bit dyadic index m (τ = m·2^-N); the candidate at m is
//   pr_local(m) = lA' + floor(lAB'·m·2^-N)          (llsb; every product an rpu_mul)
// and its inside bit comes from an rpu_indicator, one per candidate lane.
//   pass 0    lanes 0, 1 evaluate m = 0 and m = 2^N: lo = s(0), hi = s(2^N), τ = 0.
//   pass k    lanes e = 0 .. J−2 evaluate m = τ + (e + 1)·2^(N − N1·k) (the bits are disjoint
//             from τ's, so an OR); with s_0 = lo, s_J = hi the change bits c_j = s_j ^ s_{j+1}
//             (j = 0 .. J−1) are registered, then the lowest set one as a one-hot vector selects
//             η: τ' = τ | η·2^(N − N1·k), lo' = s_η, hi' = s_{η+1} (an AND-OR over the
//             one-hot). No change bit: the piece misses (live' = 0; only possible at k = 1).
// Pass = k wired in (the unrolled form), or Pass = −1: k and its shift N − N1·k come with the
// item (the iterative form, one unit used K + 1 times); the unit hands out the next pass's k + 1
// and N − N1·(k + 1), each one carry chain in the change-bit stage, so the ring's input (a mux)
// feeds the multipliers through the shift of j only, no adder.
//
// State {τ, lo, hi, live, ovf} (StW = N + 4 bits, τ on top): live = the piece is searched and has
// not missed; ovf = the sticky overflow of the twin (some indicator of a live pass saturated).
// A pass on an item that is not live changes nothing and flags nothing (the twin stops
// evaluating after a miss, and never runs a piece that does not exist).
//
// Lanes: 2 for pass 0, J − 1 for pass k, max(J − 1, 2) at Pass = −1; a lane a pass does not use
// evaluates a don't-care point and its overflow is masked.
//
// Pipeline (one item per cycle, no stall; context: the lane-0 units' tags):
//   Lm     lAB'_c · m_e: 3 rpu_mul per lane, (LW + 1) × (N + 2) signed (one DSP48E1 at the
//          defaults); m_e = τ | j·2^shift in front of the multipliers' input registers
//   1      l = lA' + (p >>> N), exact in LW bits (between lA' and lB'), registered
//   Lind   rpu_indicator per lane
//   1      change bits, lane overflow (masked) registered
//   1      one-hot select, next state registered
// Latency = Lm + 1 + Lind + 2 (rpu_surface_pass_latency, rpu_surface_latency.vh;
// ref::surface_ip_pass_latency; 80 at the defaults).
// The descriptor, lA' and the branch bits ride the lane-0 x product's tag to the indicators
// (Lm + 1 cycles); ctx_i rides the whole pass.
`default_nettype none
`include "rpu_widths.vh"

module rpu_surface_ip_step #(
`include "rpu_surface_ip_params.vh"
  parameter integer Pass   = -1,  // this unit's pass 0..N/N1, or −1: k_i at run time
  parameter integer CtxW   = 1,   // caller's context passed through (>= 1)
  // Derived (do not override).
  parameter integer K      = N / N1,
  parameter integer KW     = 8,                   // pass counter width
  parameter integer ShW    = 8,                   // the step's shift N − N1·k
  parameter integer StW    = N + 4,               // state {τ, lo, hi, live, ovf}
  parameter integer LabW   = SurfW + 1,           // lB' − lA'
  parameter integer DescW  = `RPU_SDW(SurfW)       // the packed descriptor (rpu_surface_desc.vh)
) (
  input  wire               clk_i,
  input  wire               rst_ni,
  input  wire               valid_i,
  input  wire [KW-1:0]      k_i,           // this pass (used when Pass == −1)
  input  wire [ShW-1:0]     shift_i,       // N − N1·k_i (used when Pass == −1 and k_i > 0)
  input  wire [StW-1:0]     state_i,
  input  wire [3*SurfW-1:0] la_i,          // lA', llsb, {z, y, x}
  input  wire [3*LabW-1:0]  lab_i,         // lB' − lA', llsb, {z, y, x}
  input  wire               x_negative_i,  // the piece's azimuth branch (rpu_indicator)
  input  wire               last_turn_i,
  input  wire [DescW-1:0]   desc_i,        // the indicator's descriptor (rpu_surface_desc.vh)
  input  wire [CtxW-1:0]    ctx_i,
  output wire               valid_o,
  output wire [KW-1:0]      k_o,           // the next pass: k + 1
  output wire [ShW-1:0]     shift_o,       // its shift N − N1·(k + 1)
  output wire [StW-1:0]     state_o,
  output wire [CtxW-1:0]    ctx_o
);
`include "rpu_mul_latency.vh"
`include "rpu_surface_latency.vh"
`include "rpu_surface_desc.vh"
  localparam integer LW    = SurfW;
  localparam integer J     = 1 << N1;
  localparam integer NStep = J - 1;                       // new candidates of a step
  localparam integer NC    = Pass == 0 ? 2 : Pass > 0 ? NStep : (NStep > 2 ? NStep : 2);
  localparam integer MW_   = N + 2;                       // m as a non-negative signed operand
  localparam integer PW    = LabW + MW_;                  // lAB'_c · m, exact
  localparam integer FW    = PW - N;                      // p >>> N: LW + 3 bits
  localparam integer LInd  = rpu_surface_indicator_latency(SurfW, AngleW);
  // The lane-0 x product's tag: {k, shift, state, ctx, la, x_negative, last_turn, desc}.
  localparam integer SbW   = KW + ShW + StW + CtxW + 3 * LW + 2 + DescW;
  // The lane-0 indicator's tag: {k, shift, state, ctx}, LSB first.
  localparam integer ItStO = CtxW;
  localparam integer ItShO = ItStO + StW;
  localparam integer ItKO  = ItShO + ShW;
  localparam integer ItW   = ItKO + KW;

  initial begin
    if (SurfW < 16 || SurfW > 36) $fatal(1, "rpu_surface_ip_step: SurfW must be in 16..36");
    if (N < 1 || N > 40) $fatal(1, "rpu_surface_ip_step: N must be in 1..40");
    if (N1 < 1 || N1 > 8) $fatal(1, "rpu_surface_ip_step: N1 must be in 1..8");
    if (N % N1 != 0) $fatal(1, "rpu_surface_ip_step: N must be a multiple of N1");
    if (Pass < -1 || Pass > K) $fatal(1, "rpu_surface_ip_step: Pass must be in -1..N/N1");
    if (CtxW < 1) $fatal(1, "rpu_surface_ip_step: CtxW must be >= 1");
    if (K != N / N1 || KW != 8 || ShW != 8 || StW != N + 4 || LabW != SurfW + 1 ||
        DescW != SdW)
      $fatal(1, "rpu_surface_ip_step: derived parameters must not be overridden");
  end

  genvar e, c;

  // ---- the candidates' m and the products lAB'_c · m_e ----
  wire [KW-1:0]  k_in    = Pass < 0 ? k_i : Pass[KW-1:0];
  wire           start   = k_in == {KW{1'b0}};
  wire [N-1:0]   tau_in  = state_i[StW-1 -: N];
  localparam integer ShPass = N - N1 * (Pass < 0 ? 0 : Pass);
  wire [ShW-1:0] shift   = Pass < 0 ? shift_i : ShPass[ShW-1:0];      // N − N1·k (k >= 1)
  wire [SbW-1:0] sb_in   = {k_in, shift, state_i, ctx_i, la_i, x_negative_i, last_turn_i, desc_i};

  wire [NC*3*MW_-1:0] m_op;  // lane e: {3{m_e}}, each as a non-negative signed operand
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_lane_m
      localparam [N:0] JE = e + 1;                      // the lane's j in a step
      localparam [N:0] M0 = e == 1 ? {1'b1, {N{1'b0}}}   // pass 0: m = 0 (lane 0), 2^N (lane 1)
                                   : {(N+1){1'b0}};
      wire [N:0] m_step = {1'b0, tau_in} | (JE << shift);
      wire [N:0] m      = start ? M0 : m_step;
      assign m_op[e*3*MW_ +: 3*MW_] = {3{1'b0, m}};
    end
  endgenerate
  wire [NC*3*PW-1:0] prod;  // lane e, component c at index 3e + c
  wire               p_valid;
  wire [SbW-1:0]     p_sb;
  rpu_mul_vec #(.Count(3*NC), .AW(LabW), .BW(MW_), .Signed(1), .TagW(SbW)) u_mul (
    .clk_i, .rst_ni, .valid_i, .a_i({NC{lab_i}}), .b_i(m_op), .tag_i(sb_in),
    .valid_o(p_valid), .p_o(prod), .tag_o(p_sb));

  // ---- l = lA' + floor(lAB'·m·2^-N): exact in LW bits (a point of the piece lA' .. lB') ----
  wire [3*LW-1:0]    p_la = p_sb[2 + DescW +: 3*LW];
  wire [NC*3*LW-1:0] l;
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_lane_l
      for (c = 0; c < 3; c = c + 1) begin : g_comp
        wire [PW-1:0] p   = prod[(3*e + c)*PW +: PW];
        wire [FW-1:0] f   = p[PW-1:N];                              // p >>> N (floor)
        wire [LW-1:0] la  = p_la[c*LW +: LW];
        wire [FW-1:0] sum = {{(FW-LW){la[LW-1]}}, la} + f;
        assign l[(3*e + c)*LW +: LW] = sum[LW-1:0];  // exact (above)
        wire unused_sum = ^{sum[FW-1:LW], p[N-1:0]};  // the bits the floor drops
      end
    end
  endgenerate
  wire               s1_valid_q;
  wire [NC*3*LW-1:0] s1_l_q;
  wire [ItW-1:0]     s1_it_q;       // {k, shift, state, ctx}
  wire [1:0]         s1_branch_q;   // {x_negative, last_turn}
  wire [DescW-1:0]   s1_desc_q;
  rpu_stage #(.W(NC*3*LW + ItW + 2 + DescW)) u_s1 (
    .clk_i, .rst_ni, .valid_i(p_valid), .d_i({l, p_sb[SbW-1 -: ItW], p_sb[0 +: DescW + 2]}),
    .valid_o(s1_valid_q), .q_o({s1_l_q, s1_it_q, s1_branch_q, s1_desc_q}));

  // ---- the indicators ----
  wire [NC-1:0]  ind_inside, ind_ovf;
  wire           ind_valid;
  wire [ItW-1:0] ind_it;
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_ind
      wire [Turns-1:0]  turns_unused;
      wire [AngleW-1:0] angle_unused;
      wire [LW+5:0]     rho_unused;
      if (e == 0) begin : g_carry
        rpu_indicator #(.SurfW(SurfW), .AngleW(AngleW), .Lanes(Turns), .TagW(ItW)) u_ind (
          .clk_i, .rst_ni, .valid_i(s1_valid_q), .l_i(s1_l_q[e*3*LW +: 3*LW]),
          .x_negative_i(s1_branch_q[1]), .last_turn_i(s1_branch_q[0]),
          .desc_i(s1_desc_q), .tag_i(s1_it_q),
          .valid_o(ind_valid), .inside_o(ind_inside[e]), .turn_inside_o(turns_unused),
          .angle_o(angle_unused), .rho_o(rho_unused), .ovf_o(ind_ovf[e]), .tag_o(ind_it));
      end else begin : g_plain
        wire v_unused, t_unused;
        rpu_indicator #(.SurfW(SurfW), .AngleW(AngleW), .Lanes(Turns), .TagW(1)) u_ind (
          .clk_i, .rst_ni, .valid_i(s1_valid_q), .l_i(s1_l_q[e*3*LW +: 3*LW]),
          .x_negative_i(s1_branch_q[1]), .last_turn_i(s1_branch_q[0]),
          .desc_i(s1_desc_q), .tag_i(1'b0),
          .valid_o(v_unused), .inside_o(ind_inside[e]), .turn_inside_o(turns_unused),
          .angle_o(angle_unused), .rho_o(rho_unused), .ovf_o(ind_ovf[e]), .tag_o(t_unused));
        wire unused_plain = ^{v_unused, t_unused};
      end
      wire unused_trace = ^{turns_unused, angle_unused, rho_unused};
    end
  endgenerate

`ifndef SYNTHESIS
  // The ring period and the top's admission count on LInd (rpu_surface_latency.vh): check it
  // against the instance, so that a change of rpu_indicator's schedule stops the simulation.
  reg [LInd-1:0] chk_valid_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) chk_valid_q <= {LInd{1'b0}};
    else begin
      chk_valid_q <= {chk_valid_q[LInd-2:0], s1_valid_q};
      if (ind_valid != chk_valid_q[LInd-1])
        $fatal(1, "rpu_surface_ip_step: rpu_indicator's latency is not %0d (rpu_surface_latency.vh)",
               LInd);
    end
  end
`endif

  // ---- registered change bits (pass k) and the lanes' overflow, masked to the lanes used ----
  wire [KW-1:0]   a_k     = ind_it[ItKO +: KW];
  wire [ShW-1:0]  a_shift = ind_it[ItShO +: ShW];
  wire [StW-1:0]  a_st    = ind_it[ItStO +: StW];
  wire            a_start = a_k == {KW{1'b0}};
  wire [J:0]      s_in;                    // s_0 = lo, s_1 .. s_{J−1} the lanes, s_J = hi
  assign s_in[0] = a_st[3];
  assign s_in[J] = a_st[2];
  generate
    for (e = 1; e < J; e = e + 1) begin : g_s
      if (e - 1 < NC) begin : g_lane
        assign s_in[e] = ind_inside[e-1];
      end else begin : g_none          // Pass = 0 with J − 1 > 2: no step here
        assign s_in[e] = 1'b0;
      end
    end
  endgenerate
  wire [NC-1:0] use_step, use_start;      // the lanes a step / pass 0 uses
  wire [1:0]    ends;                     // pass 0: {s(0), s(2^N)}
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_use
      assign use_step[e]  = e < NStep;
      assign use_start[e] = e < 2;
    end
    if (NC >= 2) begin : g_ends
      assign ends = {ind_inside[0], ind_inside[1]};
    end else begin : g_no_ends            // Pass = k > 0 with N1 = 1: never pass 0
      assign ends = 2'b00;
    end
  endgenerate
  wire          lanes_ovf = |(ind_ovf & (a_start ? use_start : use_step));
  // The next pass: k + 1 and N − N1·(k + 1), N1 below this pass's shift (N at k = 0).
  wire [KW-1:0]  a_knext  = a_k + 1'b1;
  wire [ShW-1:0] a_shnext = (a_start ? N[ShW-1:0] : a_shift) - N1[ShW-1:0];

  wire            b_valid_q;
  wire [KW-1:0]   b_k_q, b_knext_q;
  wire [ShW-1:0]  b_shift_q, b_shnext_q;
  wire [StW-1:0]  b_st_q;
  wire [CtxW-1:0] b_ctx_q;
  wire [J:0]      b_s_q;
  wire [J-1:0]    b_chg_q;
  wire [1:0]      b_ends_q;                // pass 0: {s(0), s(2^N)}
  wire            b_ovf_q;
  rpu_stage #(.W(2*KW + 2*ShW + StW + CtxW + 2*J + 4)) u_b (
    .clk_i, .rst_ni, .valid_i(ind_valid),
    .d_i({a_k, a_knext, a_shift, a_shnext, a_st, ind_it[CtxW-1:0], s_in, s_in[J-1:0] ^ s_in[J:1],
          ends, lanes_ovf}),
    .valid_o(b_valid_q),
    .q_o({b_k_q, b_knext_q, b_shift_q, b_shnext_q, b_st_q, b_ctx_q, b_s_q, b_chg_q, b_ends_q,
          b_ovf_q}));

  // ---- the one-hot of the lowest change bit, the AND-OR select, the next state ----
  wire [N-1:0]   b_tau   = b_st_q[StW-1 -: N];
  wire           b_live  = b_st_q[1];
  wire           b_sovf  = b_st_q[0];
  wire           b_start = b_k_q == {KW{1'b0}};
  wire [ShW-1:0] b_shift = b_shift_q;
  reg [J-1:0]    onehot;
  reg            lower;
  integer q;
  always @(*) begin
    lower = 1'b0;
    for (q = 0; q < J; q = q + 1) begin
      onehot[q] = b_chg_q[q] & ~lower;
      lower     = lower | b_chg_q[q];
    end
  end
  wire [J*N-1:0] tau_terms;               // η·2^shift for η = q, where selected
  generate
    for (e = 0; e < J; e = e + 1) begin : g_eta
      localparam [N-1:0] Eta = e;
      assign tau_terms[e*N +: N] = onehot[e] ? Eta << b_shift : {N{1'b0}};
    end
  endgenerate
  reg [N-1:0] tau_sel;
  always @(*) begin
    tau_sel = {N{1'b0}};
    for (q = 0; q < J; q = q + 1) tau_sel = tau_sel | tau_terms[q*N +: N];
  end
  wire lo_sel = |(onehot & b_s_q[J-1:0]);
  wire hi_sel = |(onehot & b_s_q[J:1]);
  wire           found = |b_chg_q;
  reg [StW-1:0]  st_next;
  always @(*) begin
    if (b_start)
      st_next = {{N{1'b0}}, b_ends_q, b_live, b_sovf | (b_live & b_ovf_q)};
    else if (!b_live)
      st_next = b_st_q;
    else if (!found)                                    // step 1 without a change: a miss
      st_next = {b_tau, b_st_q[3:2], 1'b0, b_sovf | b_ovf_q};
    else
      st_next = {b_tau | tau_sel, lo_sel, hi_sel, 1'b1, b_sovf | b_ovf_q};
  end

  rpu_stage #(.W(KW + ShW + StW + CtxW)) u_out (
    .clk_i, .rst_ni, .valid_i(b_valid_q), .d_i({b_knext_q, b_shnext_q, st_next, b_ctx_q}),
    .valid_o, .q_o({k_o, shift_o, state_o, ctx_o}));
endmodule

`default_nettype wire
