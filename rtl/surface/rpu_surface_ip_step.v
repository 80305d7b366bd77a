// rpu_surface_ip_step: one pass of the surface sign search (docs/surfaces.md, "The search on a
// piece"), twin of the steps of rpu::ref::surface_ip (step 1's passes: surface_ip_start and
// surface_ip_step; the passes of step k: surface_ip_step). τ is an N-bit dyadic index m (τ = m·2^-N); the candidate at m is
//   pr_local(m) = lA' + floor(lAB'·m·2^-N)          (llsb; every product an rpu_mul)
// and its inside bit comes from an rpu_indicator, one per lane: NC = Indicators lanes (0: 2^N1 − 1,
// so that every step after the first takes one pass; 3 at the defaults).
// The item's search state (rpu_surface_state.vh) says what a pass does, so one unit serves every
// pass: the iterative form uses one unit for all of an item's passes, the unrolled form chains
// one unit per pass.
//   step k     b_k bits (N1First for step 1, 0 meaning N1; N1 for each later step, the last
//              what remains of N), J = 2^b_k sub-intervals, candidates at m = τ + j·2^shift,
//              shift = N − (b_1 + … + b_k). Step 1 evaluates j = 0 .. J, the ends τ = 0 and
//              τ = 1 among them, in ⌈(J + 1)/NC⌉ passes, lane e of the pass with j0 candidates
//              before it evaluating j = j0 + e; each later step the J − 1 new candidates
//              j = 1 .. J − 1 in ⌈(J − 1)/NC⌉ passes, lane e evaluating j = j0 + e + 1, with
//              s_0 = lo and s_J = hi from the step before. Lanes past the step's candidates idle,
//              their overflow masked. The change bits c_j = s_j ^ s_{j+1} are taken pass by pass,
//              the previous pass's last candidate (prev) joining the next pass's first; the first
//              change of the step (the lowest j) is kept (found, its interval's start m and end
//              bits). After the step's last pass τ' = that start, lo' = s_η, hi' = s_{η+1}; no
//              change: the piece misses (live' = 0; only possible at step 1). Each pass's lanes'
//              m come with the state (the next pass's computed here), so the multipliers see
//              register outputs.
// With N1First = 0 (the seed's schedule) and NC = 2^N1 − 1: K + 1 passes.
//
// State: rpu_surface_state.vh. A pass on an item that is not live changes no result and flags
// nothing (the twin stops evaluating after a miss, and never runs a piece that does not exist),
// but its schedule advances, so every item takes the same passes and the latency is fixed.
//
// Pipeline (one item per cycle, no stall; context: the lane-0 units' tags):
//   Lm     lAB'_c · m_e: 3 rpu_mul per lane, (LW + 1) × (N + 2) signed (one DSP48E1 at the
//          defaults); m_e from the state
//   1      l = lA' + (p >>> N), exact in LW bits (between lA' and lB'), registered
//   Lind   rpu_indicator per lane
//   1      the lanes used, the change bits, the pass's last candidate, the lanes' overflow
//          (masked), j0 + NC, m_e + NC·2^shift, the next step's bits and shift, (e + 1)·2^shift'
//          registered
//   1      one-hot of the lowest change bit, the AND-OR select, the next state registered
// Latency = Lm + 1 + Lind + 2 (rpu_surface_pass_latency, rpu_surface_latency.vh;
// ref::surface_ip_pass_latency; 80 at the defaults).
// The descriptor, lA' and the branch bits ride the lane-0 x product's tag to the indicators
// (Lm + 1 cycles); the state and ctx_i ride the whole pass.
`default_nettype none
`include "rpu_widths.vh"

module rpu_surface_ip_step #(
`include "rpu_surface_ip_params.vh"
  parameter integer CtxW   = 1,   // caller's context passed through (>= 1)
  // Derived (do not override).
  parameter integer StW    = `RPU_SSTW(N, N1, Indicators),  // the search state (rpu_surface_state.vh)
  parameter integer LabW   = SurfW + 1,           // lB' − lA'
  parameter integer DescW  = `RPU_SDW(SurfW)       // the packed descriptor (rpu_surface_desc.vh)
) (
  input  wire               clk_i,
  input  wire               rst_ni,
  input  wire               valid_i,
  input  wire [StW-1:0]     state_i,
  input  wire [3*SurfW-1:0] la_i,          // lA', llsb, {z, y, x}
  input  wire [3*LabW-1:0]  lab_i,         // lB' − lA', llsb, {z, y, x}
  input  wire               x_negative_i,  // the piece's azimuth branch (rpu_indicator)
  input  wire               last_turn_i,
  input  wire [DescW-1:0]   desc_i,        // the indicator's descriptor (rpu_surface_desc.vh)
  input  wire [CtxW-1:0]    ctx_i,
  output wire               valid_o,
  output wire [StW-1:0]     state_o,
  output wire [CtxW-1:0]    ctx_o
);
`include "rpu_mul_latency.vh"
`include "rpu_surface_latency.vh"
`include "rpu_surface_desc.vh"
`include "rpu_surface_state.vh"
  localparam integer LW    = SurfW;
  localparam integer NC    = SsLanes;                     // lanes: Indicators, or 2^N1 − 1
  localparam integer MW_   = N + 2;                       // m as a non-negative signed operand
  localparam integer PW    = LabW + MW_;                  // lAB'_c · m, exact
  localparam integer FW    = PW - N;                      // p >>> N: LW + 3 bits
  localparam integer LInd  = rpu_surface_indicator_latency(SurfW, AngleW);
  // The lane-0 x product's tag: {state, ctx, la, x_negative, last_turn, desc}.
  localparam integer SbW   = StW + CtxW + 3 * LW + 2 + DescW;
  // The lane-0 indicator's tag: {state, ctx}.
  localparam integer ItW   = StW + CtxW;

  initial begin
    if (SurfW < 16 || SurfW > 36) $fatal(1, "rpu_surface_ip_step: SurfW must be in 16..36");
    if (N < 1 || N > 40) $fatal(1, "rpu_surface_ip_step: N must be in 1..40");
    if (N1 < 1 || N1 > 8) $fatal(1, "rpu_surface_ip_step: N1 must be in 1..8");
    if (N % N1 != 0) $fatal(1, "rpu_surface_ip_step: N must be a multiple of N1");
    if (N1First < 0 || N1First > 10) $fatal(1, "rpu_surface_ip_step: N1First must be in 0..10");
    if (Indicators < 0 || Indicators > 64)
      $fatal(1, "rpu_surface_ip_step: Indicators must be in 0..64");
    if (CtxW < 1) $fatal(1, "rpu_surface_ip_step: CtxW must be >= 1");
    if (StW != SsW || LabW != SurfW + 1 || DescW != SdW)
      $fatal(1, "rpu_surface_ip_step: derived parameters must not be overridden");
  end

  genvar e, c;

  // ---- the candidates' m (from the state) and the products lAB'_c · m_e ----
  wire [SbW-1:0] sb_in = {state_i, ctx_i, la_i, x_negative_i, last_turn_i, desc_i};
  wire [NC*3*MW_-1:0] m_op;  // lane e: {3{m_e}}, each as a non-negative signed operand
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_lane_m
      wire [SsMW-1:0] m = state_i[SsMO + e*SsMW +: SsMW];
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
`ifndef FORMAL
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
`endif

  // ---- stage A: the lanes used, the change bits, the pass's last candidate; the next pass's
  // ---- schedule and candidates, precomputed ----
  wire [StW-1:0]   a_st    = ind_it[CtxW +: StW];
  wire             a_start = a_st[SsStartO];   // step 1's first pass: no prev
  wire             a_first = a_st[SsFirstO];   // step 1: the ends are candidates, no hi
  wire [SsBW-1:0]  a_bits  = a_st[SsBitsO +: SsBW];
  wire [SsShW-1:0] a_shift = a_st[SsShiftO +: SsShW];
  wire [SsJW-1:0]  a_j0    = a_st[SsJ0O +: SsJW];
  // The step's candidates not yet evaluated before this pass: J + 1 − j0 in step 1, J − 1 − j0
  // later (≥ 1).
  wire [SsJW-1:0]  a_jj    = ({{(SsJW - 1){1'b0}}, 1'b1} << a_bits);
  wire [SsJW-1:0]  a_jpm   = a_first ? a_jj + 1'b1 : a_jj - 1'b1;
  wire [SsJW-1:0]  a_cnt   = a_jpm - a_j0;
  localparam [SsJW-1:0] NcJ = NC[SsJW-1:0];
  wire             a_last  = a_cnt <= NcJ;               // the step's last pass
  wire [NC-1:0]    used, lastlane;
  wire [NC:0]      x;                                    // x_0 = prev, x_{e+1} = lane e
  assign x[0] = a_st[SsPrevO];
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_use
      localparam integer    E1I = e + 1;
      localparam [SsJW-1:0] E1 = E1I[SsJW-1:0];
      assign x[e+1]      = ind_inside[e];
      assign used[e]     = a_cnt >= E1;
      assign lastlane[e] = a_last ? (a_cnt == E1) : (e == NC - 1);
    end
  endgenerate
  wire         s_last = |(lastlane & ind_inside);
  reg  [N-1:0] m_last;
  integer q;
  always @(*) begin
    m_last = {N{1'b0}};
    for (q = 0; q < NC; q = q + 1)
      m_last = m_last | ({N{lastlane[q]}} & a_st[SsMO + q*SsMW +: N]);
  end
  // Change bits: c_e between x_e and x_{e+1} (lanes used; c_0 not in step 1's first pass), c_NC
  // between the step's last candidate and hi (the last pass of a step after the first).
  wire [NC:0] chg;
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_chg
      if (e == 0) begin : g_c0
        assign chg[e] = ~a_start & used[e] & (x[e] ^ x[e+1]);
      end else begin : g_ce
        assign chg[e] = used[e] & (x[e] ^ x[e+1]);
      end
    end
  endgenerate
  assign chg[NC] = a_last & ~a_first & (s_last ^ a_st[SsHiO]);
  wire lanes_ovf = |(ind_ovf & used);
  // The next step's bits min(N1, shift) and shift.
  localparam [SsShW-1:0] N1S = N1[SsShW-1:0];
  wire [SsShW-1:0] nb8     = a_shift < N1S ? a_shift : N1S;
  wire [SsShW-1:0] n_shift = a_shift - nb8;
  wire [SsBW-1:0]  n_bits  = nb8[SsBW-1:0];
  wire             n_done  = a_last & (a_shift == {SsShW{1'b0}});
  wire [SsJW-1:0]  j0_next = a_j0 + NcJ;
  localparam [SsMW-1:0] NcM = NC[SsMW-1:0];
  wire [NC*SsMW-1:0] pre, madd;  // (e + 1)·2^shift' (a new step), m_e + NC·2^shift (this step)
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_next_m
      localparam integer    E1MI = e + 1;
      localparam [SsMW-1:0] E1M = E1MI[SsMW-1:0];
      assign pre[e*SsMW +: SsMW]  = E1M << n_shift;
      assign madd[e*SsMW +: SsMW] = a_st[SsMO + e*SsMW +: SsMW] + (NcM << a_shift);
    end
  endgenerate
  wire unused_a = ^{nb8[SsShW-1:SsBW]};

  wire              b_valid_q;
  wire [StW-1:0]    b_st_q;
  wire [CtxW-1:0]   b_ctx_q;
  wire [NC:0]       b_x_q, b_chg_q;
  wire              b_slast_q, b_last_q, b_ovf_q, b_done_q;
  wire [N-1:0]      b_mlast_q;
  wire [SsShW-1:0]  b_nshift_q;
  wire [SsBW-1:0]   b_nbits_q;
  wire [SsJW-1:0]   b_j0n_q;
  wire [NC*SsMW-1:0] b_pre_q, b_madd_q;
  rpu_stage #(.W(StW + CtxW + 2*(NC + 1) + 4 + N + SsShW + SsBW + SsJW + 2*NC*SsMW)) u_b (
    .clk_i, .rst_ni, .valid_i(ind_valid),
    .d_i({a_st, ind_it[CtxW-1:0], x, chg, s_last, a_last, lanes_ovf, n_done, m_last, n_shift,
          n_bits, j0_next, pre, madd}),
    .valid_o(b_valid_q),
    .q_o({b_st_q, b_ctx_q, b_x_q, b_chg_q, b_slast_q, b_last_q, b_ovf_q, b_done_q, b_mlast_q,
          b_nshift_q, b_nbits_q, b_j0n_q, b_pre_q, b_madd_q}));

  // ---- stage B: the one-hot of the lowest change bit, the AND-OR select, the next state ----
  wire         b_live  = b_st_q[SsLiveO];
  wire         b_found = b_st_q[SsFoundO];
  reg  [NC:0]  onehot;
  reg          lower;
  always @(*) begin
    lower = 1'b0;
    for (q = 0; q <= NC; q = q + 1) begin
      onehot[q] = b_chg_q[q] & ~lower;
      lower     = lower | b_chg_q[q];
    end
  end
  // Change bit q's interval: its lower candidate's m and the bits of its ends.
  wire [NC:0] xl = {b_slast_q, b_x_q[NC-1:0]};
  wire [NC:0] xu = {b_st_q[SsHiO], b_x_q[NC:1]};
  reg  [N-1:0] ml_sel;
  always @(*) begin
    ml_sel = {N{onehot[0]}} & b_st_q[SsMprevO +: N];
    for (q = 1; q < NC; q = q + 1)
      ml_sel = ml_sel | ({N{onehot[q]}} & b_st_q[SsMO + (q-1)*SsMW +: N]);
    ml_sel = ml_sel | ({N{onehot[NC]}} & b_mlast_q);
  end
  wire any     = |b_chg_q;
  wire take    = b_live & ~b_found & any;            // this pass has the step's first change
  wire found1  = b_found | (b_live & any);
  wire [N-1:0] stau = take ? ml_sel : b_st_q[SsStauO +: N];
  wire         slo  = take ? |(onehot & xl) : b_st_q[SsSloO];
  wire         shi  = take ? |(onehot & xu) : b_st_q[SsShiO];
  // The step's end: the selected interval, or a miss.
  wire         hit_end = b_live & found1;
  wire [N-1:0] tau_e   = hit_end ? stau : b_st_q[SsTauO +: N];
  wire         lo_e    = hit_end ? slo : b_st_q[SsLoO];
  wire         hi_e    = hit_end ? shi : b_st_q[SsHiO];
  wire         ovf1    = b_st_q[SsOvfO] | (b_live & b_ovf_q);
  // The next step's lanes start at its τ.
  wire [NC*SsMW-1:0] m_new;
  generate
    for (e = 0; e < NC; e = e + 1) begin : g_m_new
      assign m_new[e*SsMW +: SsMW] = {1'b0, tau_e} | b_pre_q[e*SsMW +: SsMW];
    end
  endgenerate
  reg [StW-1:0] st_next;
  always @(*) begin
    st_next = b_st_q;
    st_next[SsStartO] = 1'b0;
    if (b_last_q) begin                                  // the step's last pass
      st_next[SsTauO +: N]     = tau_e;
      st_next[SsLoO]           = lo_e;
      st_next[SsHiO]           = hi_e;
      st_next[SsLiveO]         = b_live & found1;        // no change at step 1: a miss
      st_next[SsOvfO]          = ovf1;
      st_next[SsFoundO]        = 1'b0;
      st_next[SsFirstO]        = 1'b0;
      st_next[SsPrevO]         = lo_e;
      st_next[SsMprevO +: N]   = tau_e;
      st_next[SsDoneO]         = b_done_q;
      st_next[SsBitsO +: SsBW] = b_nbits_q;
      st_next[SsShiftO +: SsShW] = b_nshift_q;
      st_next[SsJ0O +: SsJW]   = {SsJW{1'b0}};
      st_next[SsMO +: NC*SsMW] = m_new;
    end else begin                                       // more passes of this step
      st_next[SsOvfO]          = ovf1;
      st_next[SsFoundO]        = found1;
      st_next[SsStauO +: N]    = stau;
      st_next[SsSloO]          = slo;
      st_next[SsShiO]          = shi;
      st_next[SsPrevO]         = b_slast_q;
      st_next[SsMprevO +: N]   = b_mlast_q;
      st_next[SsJ0O +: SsJW]   = b_j0n_q;
      st_next[SsMO +: NC*SsMW] = b_madd_q;
    end
  end
  wire unused_b = b_x_q[NC];

  rpu_stage #(.W(StW + CtxW)) u_out (
    .clk_i, .rst_ni, .valid_i(b_valid_q), .d_i({st_next, b_ctx_q}),
    .valid_o, .q_o({state_o, ctx_o}));
endmodule

`default_nettype wire
