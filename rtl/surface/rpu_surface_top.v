// rpu_surface_top: one surface work item (pixel ray, surface, piece) through the surface path,
// twin of rpu::ref::process_surface_piece (ref/model/surface/rpu_surface_top.{h,cpp}):
//   rpu_surface_setup   bounding sphere, local frame, the requested piece (A', B' − A' in world
//                       LSB, lA', lB' − lA' in llsb, the azimuth branch)
//   rpu_surface_ip      the sign search on the piece: hit, τ_K
//   X     = A' + floor((B' − A')·τ_K·2^-N)      world LSB, exact in CoordW bits (a point of
//                                               the piece A' .. B')
//   depth = (X − h)·W                           exact, rpu_capture's depth format and width, so
//                                               rpu_resolve orders surfaces, curves and textures
//                                               alike
// Outputs, one per accepted item in input order after a fixed latency: piece_valid_o (the
// twin's valid: the piece exists), hit_o, ovf_o (the twin's sticky flag: setup or search
// saturated), pieces_o (the pair's non-empty pieces), tau_o, x_o, depth_o (τ, X and depth are 0
// without a hit, as the twin's), tag_o = tag_i.
//
// Ports: the camera eye_i (h, LSB) and w_i (W, Q(4.FE+14)) are constants while items are in
// flight (rpu_top's camera register). Per item, sampled with valid_i: vhat_i (the ray generator's
// v̂), the surface descriptor (SurfaceDesc: the setup's fields, bound_c0_i, bound_r2_i, origin_i,
// to_local_i, to_local_s_i, y_min_i, y_max_i, end_angle_i, end_cos_i, end_sin_i as
// rpu_surface_setup's ports; the indicator's fields, the type among them, as one word desc_i,
// rpu_surface_desc.vh), piece_i, tag_i.
//
// Flow: no stall inside. Unrolled = 1: ready_o = 1, one item per cycle. Unrolled = 0 (the
// default): the IP's ring takes an item only into a free slot, so the items are admitted here,
// a setup latency ahead, by rpu_surface_admit (the ring's occupancy mirrored: ready_o is a
// compare of a register); every admitted item finds its slot, so the latency stays fixed. At full
// load one item per P cycles, P the search's passes (rpu_surface_passes: 48 at the defaults),
// bursts of up to one ring period back to back.
// The indicator fields wait for the setup in a FIFO (rpu_fifo, block RAM, first-word
// fall-through: the head is at its output when the setup delivers that item); the setup's
// results the tail needs ride the IP as its context (in the iterative form, the IP's context
// RAM).
//
// Pipeline after the IP (every product an rpu_mul, one carry chain per stage):
//   Lx    AB'_c · τ, (CoordW + 1) × (N + 1) signed; A' − h beside it (in the tag)
//   1     X = A' + (p >>> N), X − h = (A' − h) + (p >>> N), both exact
//   Ld    (X − h)_c · W_c, (CoordW + 1) × EdgeW signed (in this order: 2 DSP tiles, not 4)
//   1     depth = the sum of the three (one carry-save step and one adder); outputs registered
// Latency = setup + IP + Lx + 1 + Ld + 1 (ref::surface_top_latency; 105 + 3,841 + 2 + 1 + 3 + 1 =
// 3,953 at the defaults).
`default_nettype none
`include "rpu_widths.vh"

module rpu_surface_top #(
  parameter integer CoordW   = 24,  // CW: signed width of positions, LSB (12..40)
  parameter integer DirFrac  = 24,  // FV: fraction bits of v̂ (8..40)
  parameter integer TFrac    = 24,  // the sphere unit's α, β format (8..48; d = 0: unused values)
  parameter integer InvW     = 18,  // the sphere unit's 1/L² mantissa width (8..40)
  parameter integer SqrtW    = 0,   // widest radicand of the sphere unit's root; 0 = exact
  parameter integer EdgeFrac = 16,  // FE: fraction bits of the camera axis W (8..40)
`include "rpu_surface_ip_params.vh"
  parameter integer Unrolled = 0,   // 1: P pass units, 0: one pass unit used P times
  parameter integer Admit    = 1,   // iterative form: 1 admits here; 0: the caller admits with
                                    // an rpu_surface_admit of this Period and Returns at any
                                    // fixed distance ahead (rpu_top), ready_o is 1
  parameter integer TagW     = 1,   // side-band bits carried with each item (>= 1)
  parameter integer Sphere   = 1,   // 1: the setup's own sphere unit; 0: the caller's, whose
                                    // results come with the item on sp_*_i (rpu_surface_setup)
  // Derived (do not override).
  parameter integer DirW   = `RPU_VHATW(DirFrac),              // v̂: Q(2.FV)
  parameter integer DiffW  = `RPU_DW(CoordW),               // B' − A', X − h
  parameter integer BR2W   = `RPU_R2W(CoordW),           // the bounding sphere's R²
  parameter integer MantW  = SurfW + 2,                // M's entries, ScaledConst mantissas
  parameter integer ConstW = SurfW + 2,                // end_cos, end_sin, kd, ke2: Q(1.KF)
  parameter integer DescW  = `RPU_SDW(SurfW),          // the indicator's fields (rpu_surface_desc.vh)
  parameter integer EdgeW  = `RPU_EGW(EdgeFrac),        // W: Q(4.FE+14)
  parameter integer DepthW = `RPU_DEPTHW(CoordW, EdgeFrac)    // rpu_capture's depth
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire [3*CoordW-1:0] eye_i,          // h, LSB (constant while items are in flight)
  input  wire [3*EdgeW-1:0]  w_i,            // W, Q(4.FE+14) (constant likewise)
  input  wire                valid_i,
  output wire                ready_o,
  input  wire [3*DirW-1:0]   vhat_i,         // v̂, Q(2.FV)
  // SurfaceDesc: the setup's fields.
  input  wire [3*CoordW-1:0] bound_c0_i,     // bounding-sphere centre, LSB
  input  wire [BR2W-1:0]     bound_r2_i,     // bounding-sphere radius², LSB², unsigned
`include "rpu_surface_setup_ports.vh"
  input  wire [DescW-1:0]    desc_i,         // SurfaceDesc: the indicator's fields, one word
  input  wire [1:0]          piece_i,        // 0..2
  input  wire [TagW-1:0]     tag_i,
  input  wire                sp_pred1_i,     // Sphere = 0: the caller's sphere unit's pred1, A,
  input  wire [3*CoordW-1:0] sp_a_i,         //   B, B − A and overflow for this item (p1 = d = 0);
  input  wire [3*CoordW-1:0] sp_b_i,         //   with Sphere = 0, eye_i is still the camera's
  input  wire [3*DiffW-1:0]  sp_ab_i,        //   (the depth) but vhat_i, bound_c0_i and
  input  wire                sp_ovf_i,       //   bound_r2_i are unused
  output wire                valid_o,
  output wire                piece_valid_o,
  output wire                hit_o,
  output wire                ovf_o,
  output wire [1:0]          pieces_o,
  output wire [N-1:0]        tau_o,
  output wire [3*CoordW-1:0] x_o,            // X, LSB
  output wire [DepthW-1:0]   depth_o,        // (X − h)·W, Q(.FE+14) in LSB
  output wire [TagW-1:0]     tag_o
);
`include "rpu_mul_latency.vh"
`include "rpu_surface_latency.vh"
`include "rpu_surface_desc.vh"
  localparam integer CW   = CoordW;
  localparam integer LW   = SurfW;
  localparam integer P    = rpu_surface_passes(N, N1, N1First, Indicators);  // the search's passes
  localparam integer LabW = SurfW + 1;
  localparam integer L    = rpu_surface_pass_latency(SurfW, AngleW, N);
  // The IP's context (the setup's results the tail needs), offsets from the bottom:
  // {tag, A', B' − A', pieces, setup overflow, piece valid}.
  localparam integer CValidO  = 0;
  localparam integer COvfO    = CValidO + 1;
  localparam integer CPiecesO = COvfO + 1;
  localparam integer CAbO     = CPiecesO + 2;
  localparam integer CAO      = CAbO + 3 * DiffW;
  localparam integer CTagO    = CAO + 3 * CW;
  localparam integer CtxW     = CTagO + TagW;
  // The indicator fields' FIFO: every item in the setup waits there (the setup's latency is
  // below 512 for every legal parameter set; simulation checks it never fills).
  localparam integer DescFifoLog2 = 9;
  // The tail.
  localparam integer XPW = DiffW + N + 1;     // AB'_c · τ, exact
  localparam integer XFW = XPW - N;           // p >>> N: CW + 2 bits
  localparam integer DPW = EdgeW + DiffW;     // (X − h)_c · W_c, exact
  localparam integer DSW = DPW + 2;           // their sum, exact

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_surface_top: CoordW must be in 12..40");
    if (EdgeFrac < 8 || EdgeFrac > 40) $fatal(1, "rpu_surface_top: EdgeFrac must be in 8..40");
    if (TagW < 1) $fatal(1, "rpu_surface_top: TagW must be >= 1");
    if (Sphere != 0 && Sphere != 1) $fatal(1, "rpu_surface_top: Sphere must be 0 or 1");
    if (DirW != `RPU_VHATW(DirFrac) || DiffW != `RPU_DW(CoordW) || BR2W != `RPU_R2W(CoordW) ||
        MantW != SurfW + 2 || ConstW != SurfW + 2 || DescW != SdW || EdgeW != 4 + EdgeFrac + 14 || DepthW != CoordW + 4 + EdgeW + 2)
      $fatal(1, "rpu_surface_top: derived parameters must not be overridden");
    if (DSW > DepthW) $fatal(1, "rpu_surface_top: internal: depth width");
  end

  // ---- admission ----
  generate
    if (Unrolled != 0 || Admit == 0) begin : g_admit_all
      assign ready_o = 1'b1;
    end else begin : g_admit_ring
      rpu_surface_admit #(.Period(L), .Returns(P - 1)) u_admit (
        .clk_i, .rst_ni, .valid_i, .ready_o);
    end
  endgenerate
  wire accept = valid_i && ready_o;

  // ---- the indicator fields wait for the setup ----
  wire           su_valid;
  wire           df_wr_ready, df_rd_valid;
  wire [SdW-1:0] df_desc;
  rpu_fifo #(.Width(SdW), .Log2Depth(DescFifoLog2)) u_desc_fifo (
    .clk_i, .rst_ni, .wr_valid_i(accept), .wr_ready_o(df_wr_ready), .wr_data_i(desc_i),
    .rd_valid_o(df_rd_valid), .rd_ready_i(su_valid), .rd_data_o(df_desc));

  // ---- setup ----
  wire                su_pred1_unused, su_piece_valid, su_xneg, su_last, su_ovf;
  wire [1:0]          su_pieces;
  wire [LW+2:0]       su_slo_unused, su_shi_unused;
  wire [3*CW-1:0]     su_a;
  wire [3*DiffW-1:0]  su_ab;
  wire [3*LW-1:0]     su_la;
  wire [3*LabW-1:0]   su_lab;
  wire [TagW-1:0]     su_tag;
  rpu_surface_setup #(.CoordW(CoordW), .DirFrac(DirFrac), .TFrac(TFrac), .InvW(InvW),
                      .SqrtW(SqrtW), .SurfW(SurfW), .AngleW(AngleW), .TagW(TagW),
                      .Sphere(Sphere)) u_setup (
    .clk_i, .rst_ni, .valid_i(accept), .eye_i, .vhat_i, .c0_i(bound_c0_i), .r2_i(bound_r2_i),
    .origin_i, .to_local_i, .to_local_s_i, .type_i(desc_i[SdTypeO +: 3]), .y_min_i, .y_max_i,
    .end_angle_i, .end_cos_i, .end_sin_i, .piece_i, .tag_i, .sp_pred1_i, .sp_a_i, .sp_b_i,
    .sp_ab_i, .sp_ovf_i, .valid_o(su_valid), .pred1_o(su_pred1_unused), .piece_valid_o(su_piece_valid),
    .pieces_o(su_pieces), .s_lo_o(su_slo_unused), .s_hi_o(su_shi_unused), .a_o(su_a),
    .ab_o(su_ab), .la_o(su_la), .lab_o(su_lab), .x_negative_o(su_xneg), .last_turn_o(su_last),
    .ovf_o(su_ovf), .tag_o(su_tag));
  wire unused_su = ^{su_pred1_unused, su_slo_unused, su_shi_unused};

  // ---- the sign search ----
  wire            ip_ready, ip_valid, ip_hit, ip_ovf;
  wire [N-1:0]    ip_tau;
  wire [CtxW-1:0] ip_ctx;
  rpu_surface_ip #(.SurfW(SurfW), .AngleW(AngleW), .Turns(Turns), .N(N), .N1(N1),
                   .N1First(N1First), .Indicators(Indicators), .Unrolled(Unrolled), .CtxW(CtxW))
      u_ip (
    .clk_i, .rst_ni, .valid_i(su_valid), .ready_o(ip_ready), .run_i(su_piece_valid),
    .la_i(su_la), .lab_i(su_lab), .x_negative_i(su_xneg), .last_turn_i(su_last),
    .desc_i(df_desc),
    .ctx_i({su_tag, su_a, su_ab, su_pieces, su_ovf, su_piece_valid}),
    .valid_o(ip_valid), .hit_o(ip_hit), .tau_o(ip_tau), .ovf_o(ip_ovf), .ctx_o(ip_ctx));

  // The admission's promise: every item the setup delivers finds the IP ready and its indicator
  // fields at the FIFO's head; the FIFO never fills. Simulation stops on a broken promise; the
  // formal proofs assert it (Yosys's formal front end has no $fatal in an always block).
`ifdef FORMAL
  always @(*) begin
    if (rst_ni && su_valid) assert(ip_ready && df_rd_valid);
    if (rst_ni && accept) assert(df_wr_ready);
  end
`elsif SYNTHESIS
`else
  always @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni && su_valid && (!ip_ready || !df_rd_valid))
      $fatal(1, "rpu_surface_top: an item reached the IP without a ring slot or descriptor");
    if (rst_ni && accept && !df_wr_ready)
      $fatal(1, "rpu_surface_top: the descriptor FIFO is full");
  end
`endif

  // ---- X = A' + floor(AB'·τ·2^-N) and X − h ----
  genvar c;
  wire [3*CW-1:0]    ip_a  = ip_ctx[CAO +: 3*CW];
  wire [3*DiffW-1:0] ip_ab = ip_ctx[CAbO +: 3*DiffW];
  wire [3*DiffW-1:0] amh;                      // A' − h, exact
  rpu_surface_vsub #(.Count(3), .InW(CW)) u_amh (.a_i(ip_a), .b_i(eye_i), .d_o(amh));
  // The first product's tag: {tag, hit, ovf, pieces, piece valid, τ, A', A' − h}.
  localparam integer XtW = TagW + 1 + 1 + 2 + 1 + N + 3 * CW + 3 * DiffW;
  wire [3*XPW-1:0] xp;
  wire             xp_valid;
  wire [XtW-1:0]   xp_tag;
  rpu_mul_vec #(.Count(3), .AW(DiffW), .BW(N + 1), .Signed(1), .ShareB(1), .TagW(XtW)) u_xmul (
    .clk_i, .rst_ni, .valid_i(ip_valid), .a_i(ip_ab), .b_i({1'b0, ip_tau}),
    .tag_i({ip_ctx[CTagO +: TagW], ip_hit, ip_ovf | ip_ctx[COvfO], ip_ctx[CPiecesO +: 2],
            ip_ctx[CValidO], ip_tau, ip_a, amh}),
    .valid_o(xp_valid), .p_o(xp), .tag_o(xp_tag));

  localparam integer XsW = TagW + 5 + N;       // {tag, hit, ovf, pieces, piece valid, τ}
  wire [3*CW-1:0]    xt_a   = xp_tag[3*DiffW +: 3*CW];
  wire [3*DiffW-1:0] xt_amh = xp_tag[0 +: 3*DiffW];
  wire [3*CW-1:0]    x;
  wire [3*DiffW-1:0] q;                        // X − h
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_x
      wire [XPW-1:0]   p  = xp[c*XPW +: XPW];
      wire [XFW-1:0]   f  = p[XPW-1:N];                       // floor(AB'_c·τ·2^-N)
      wire [CW-1:0]    ac = xt_a[c*CW +: CW];
      wire [DiffW-1:0] mc = xt_amh[c*DiffW +: DiffW];
      wire [XFW-1:0]   xs = {ac[CW-1], ac[CW-1], ac} + f;      // exact in CW bits (A' .. B')
      wire [XFW-1:0]   qs = {mc[DiffW-1], mc} + f;            // exact in CW + 1 bits (X − h)
      assign x[c*CW +: CW]       = xs[CW-1:0];
      assign q[c*DiffW +: DiffW] = qs[DiffW-1:0];
      wire unused_x = ^{p[N-1:0], xs[XFW-1:CW], qs[XFW-1:DiffW]};
    end
  endgenerate
  wire               xs_valid_q;
  wire [XsW-1:0]     xs_q;
  wire [3*CW-1:0]    x_q;
  wire [3*DiffW-1:0] q_q;
  rpu_stage #(.W(XsW + 3*CW + 3*DiffW)) u_xs (
    .clk_i, .rst_ni, .valid_i(xp_valid), .d_i({xp_tag[XtW-1 -: XsW], x, q}),
    .valid_o(xs_valid_q), .q_o({xs_q, x_q, q_q}));

  // ---- depth = (X − h)·W ----
  localparam integer DtW = XsW + 3 * CW;       // {tag, hit, ovf, pieces, piece valid, τ, X}
  wire [3*DPW-1:0] dp;
  wire             dp_valid;
  wire [DtW-1:0]   dp_tag;
  rpu_mul_vec #(.Count(3), .AW(DiffW), .BW(EdgeW), .Signed(1), .TagW(DtW)) u_dmul (
    .clk_i, .rst_ni, .valid_i(xs_valid_q), .a_i(q_q), .b_i(w_i), .tag_i({xs_q, x_q}),
    .valid_o(dp_valid), .p_o(dp), .tag_o(dp_tag));
  // A sum of three in one carry chain (rpu_add3), exact modulo 2^DSW (the sum fits DSW bits).
  wire [DPW-1:0] d0 = dp[0*DPW +: DPW];
  wire [DPW-1:0] d1 = dp[1*DPW +: DPW];
  wire [DPW-1:0] d2 = dp[2*DPW +: DPW];
  wire [DSW-1:0] depth;
  rpu_add3 #(.W(DSW)) u_depth (
    .a_i({{2{d0[DPW-1]}}, d0}), .b_i({{2{d1[DPW-1]}}, d1}), .c_i({{2{d2[DPW-1]}}, d2}),
    .s_o(depth));

  // ---- outputs (τ, X and depth zero without a hit, as the twin's) ----
  wire [3*CW-1:0] o_x     = dp_tag[3*CW-1:0];
  wire [N-1:0]    o_tau   = dp_tag[3*CW +: N];
  wire            o_pv    = dp_tag[3*CW + N];
  wire [1:0]      o_pcs   = dp_tag[3*CW + N + 1 +: 2];
  wire            o_ovf   = dp_tag[3*CW + N + 3];
  wire            o_hit   = dp_tag[3*CW + N + 4];
  wire [TagW-1:0] o_tag   = dp_tag[DtW-1 -: TagW];
  wire [DepthW-1:0] o_depth = o_hit ? {{(DepthW-DSW){depth[DSW-1]}}, depth} : {DepthW{1'b0}};
  rpu_stage #(.W(5 + N + 3*CW + DepthW + TagW)) u_out (
    .clk_i, .rst_ni, .valid_i(dp_valid),
    .d_i({o_pv, o_hit, o_ovf, o_pcs, o_hit ? o_tau : {N{1'b0}}, o_hit ? o_x : {(3*CW){1'b0}},
          o_depth, o_tag}),
    .valid_o, .q_o({piece_valid_o, hit_o, ovf_o, pieces_o, tau_o, x_o, depth_o, tag_o}));
endmodule

`default_nettype wire
