// rpu_top: the ray-processing unit for spatial curves, vector textures and vector-described
// surfaces. Twins, per work item: rpu::ref::process_curve_pair (curve segment), ray_plane_unit +
// texture_unit (texture segment) or process_surface_piece (surface piece); per pixel:
// rpu::ref::Resolve.
// Ports (docs/rtl.md, "rpu_top"): the descriptor RAMs, written before a frame; work items on a
// valid/ready stream, one per cycle, a pixel's items consecutive, `last` on its last one, a
// surface item naming one piece of a surface; the results of the items in input order; one
// pixel per pixel from rpu_resolve, fed by the result stream (a result leaves when both take it).
// Inside: input skid register → segment RAM read → rpu_ray_gen → curve: rpu_sphere → rpu_ip →
// rpu_capture → curve FIFO; texture: rpu_ray_plane → rpu_texture → texture FIFO; surface: the
// same rpu_sphere on the bounding sphere → surface RAM read → rpu_surface_top (Sphere = 0, its
// iterative search ring) → surface FIFO; Surfaces = 0 builds no surface path. An order FIFO
// of two bits per item (the kind) merges the three in input order; the merged stream feeds the
// result port and rpu_resolve, which orders the hits of all kinds by the one depth format.
// The arithmetic pipelines never stall: a work item is only taken from the input register while
// fewer than 2^FifoLog2 items are in flight or waiting in the output FIFOs (a credit count of
// registers) and, for a surface piece, while the search ring has a slot for it when it arrives
// (rpu_surface_admit here mirrors the ring's occupancy at a fixed distance ahead of it), so no
// FIFO can overflow and no combinational ready path crosses the pipeline; item_ready_o is the
// input skid register's own flip-flop.
`default_nettype none
`include "rpu_widths.vh"
`include "rpu_formal_ports.vh"

module rpu_top #(
`include "rpu_top_params.vh"
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  // Descriptor load.
  input  wire                cam_we_i,
  input  wire [CamW-1:0]     cam_data_i,   // {v0, dx, dy, el0, et0, sw, w, eye}
  input  wire                seg_we_i,
  input  wire [SegAddrW-1:0] seg_addr_i,
  input  wire [SegW-1:0]     seg_data_i,   // {tex, prim, p1, d, c0, R2 | w0_2, L2, inv_m, inv_s,
                                           //  g1, g2}; a texture's R2 holds w0_2, its c0 bit 0
                                           //  the join (1: round)
  input  wire                 surf_we_i,
  input  wire [SurfAddrW-1:0] surf_addr_i,
  input  wire [SurfDW-1:0]    surf_data_i, // {prim, c0, R2, origin, M, M's shift, y_min, y_max,
                                           //  end angle, end cos, end sin, indicator word}
  // Work items.
  input  wire                item_valid_i,
  output wire                item_ready_o,
  input  wire [IdW-1:0]      item_id_i,
  input  wire [IdxW-1:0]     item_i_i,
  input  wire [IdxW-1:0]     item_j_i,
  input  wire [SegAddrW-1:0] item_seg_i,
  input  wire                item_last_i,  // the last work item of its pixel
  input  wire                item_surf_i,  // a surface piece: item_seg_i addresses the surface RAM
  input  wire [1:0]          item_piece_i, // the piece (surfaces), 0..2
  // Results.
  output wire                res_valid_o,
  input  wire                res_ready_i,
  output wire [IdW-1:0]      res_id_o,
  output wire [IdxW-1:0]     res_i_o,
  output wire [IdxW-1:0]     res_j_o,
  output wire [SegAddrW-1:0] res_seg_o,
  output wire                res_last_o,
  output wire                res_surf_o,   // a surface piece (pred_1: the piece exists)
  output wire [1:0]          res_piece_o,
  output wire                res_tex_o,    // a texture item (pred_1: the ray meets the plane)
  output wire [1:0]          res_pieces_o, // a surface pair's non-empty pieces (0 otherwise)
  output wire [PrimW-1:0]    res_prim_o,
  output wire                res_pred1_o,
  output wire                res_hit_o,
  output wire [DepthW-1:0]   res_depth_o,
  output wire [N-1:0]        res_tau_o,
  output wire [TW-1:0]       res_t_o,
  output wire [3*XW-1:0]     res_x_o,
  output wire                res_ovf_o,
  // Pixels.
  output wire                pix_valid_o,
  input  wire                pix_ready_i,
  output wire [IdxW-1:0]     pix_i_o,
  output wire [IdxW-1:0]     pix_j_o,
  output wire                pix_hit_o,
  output wire [DepthW-1:0]   pix_depth_o,  // 0 without a hit
  output wire [PrimW-1:0]    pix_prim_o    // 0 without a hit
);
  localparam integer EgW  = `RPU_EGW(EdgeFrac);
  localparam integer EoW  = EgW + IdxW + 1;           // rpu_ray_gen's edge outputs
  localparam integer MdW  = Metric == 0 ? `RPU_FOMAX + 3 : 2 * `RPU_FOMAX + 3;  // rpu_ip's md
`include "rpu_guide_desc.vh"
  localparam integer GdW = GdWords;  // one guide (the segment descriptor holds two)
`include "rpu_seg_desc.vh"
`include "rpu_cam_desc.vh"
`include "rpu_top_words.vh"
`include "rpu_surf_desc.vh"
`include "rpu_mul_latency.vh"
`include "rpu_surface_latency.vh"
  // The search ring of the surface path: its period and the passes of an item.
`ifndef RPU_FORMAL_TOP
  localparam integer SfPeriod = rpu_surface_pass_latency(SurfW, AngleW, N);
  localparam integer SfPasses = rpu_surface_passes(N, N1, N1First, Indicators);
`endif
`ifdef FORMAL
`include "rpu_top_formal_decl.vh"
`endif

  initial begin
    if (SegAddrW < 1 || SegAddrW > 16) $fatal(1, "rpu_top: SegAddrW must be in 1..16");
    if (IdxW < 1 || IdxW > 14) $fatal(1, "rpu_top: IdxW must be in 1..14");
    if (FifoLog2 < 2 || FifoLog2 > 12) $fatal(1, "rpu_top: FifoLog2 must be in 2..12");
    if (PrimW < 1 || PrimW > 31) $fatal(1, "rpu_top: PrimW must be in 1..31");
    if (Surfaces < 0 || Surfaces > 1) $fatal(1, "rpu_top: Surfaces must be 0 or 1");
    if (SurfAddrW < 1 || SurfAddrW > SegAddrW)
      $fatal(1, "rpu_top: SurfAddrW must be in 1..SegAddrW");
    if (SegW != SegWords || CamW != CamWords || SurfDW != SfWords)
      $fatal(1, "rpu_top: SegW/CamW/SurfDW are derived; do not override them");
  end

  // ---- descriptor storage ----
  reg [CamW-1:0] cam_q;
  reg [SegW-1:0] seg_mem [0:(1<<SegAddrW)-1];
  reg [SurfDW-1:0] surf_mem [0:(1<<SurfAddrW)-1];
  always @(posedge clk_i) begin
    if (cam_we_i) cam_q <= cam_data_i;
    if (seg_we_i) seg_mem[seg_addr_i] <= seg_data_i;
    if (surf_we_i) surf_mem[surf_addr_i] <= surf_data_i;
  end
  wire [CamVW-1:0]   cam_v0  = cam_q[CamV0O +: CamVW];
  wire [CamVW-1:0]   cam_dx  = cam_q[CamDxO +: CamVW];
  wire [CamVW-1:0]   cam_dy  = cam_q[CamDyO +: CamVW];
  wire [CamEW-1:0]   cam_el0 = cam_q[CamEl0O +: CamEW];
  wire [CamEW-1:0]   cam_et0 = cam_q[CamEt0O +: CamEW];
  wire [CamEW-1:0]   cam_sw  = cam_q[CamSwO +: CamEW];
  wire [CamEW-1:0]   cam_w   = cam_q[CamWO +: CamEW];
  wire [CamEyeW-1:0] cam_eye = cam_q[CamEyeO +: CamEyeW];

  // ---- input: a skid register, so item_ready_o is a flip-flop ----
  wire           in_valid, in_ready;
  wire [ItW-1:0] in_item;
  rpu_skid #(.W(ItW)) u_in (
    .clk_i, .rst_ni, .valid_i(item_valid_i), .ready_o(item_ready_o),
    .data_i({item_piece_i, item_surf_i, item_last_i, item_id_i, item_i_i, item_j_i, item_seg_i}),
    .valid_o(in_valid), .ready_i(in_ready), .data_o(in_item) `RPU_F_QUEUE(f_in_cnt, f_in_ent));
  wire in_surf = in_item[ItSurfO];

  // ---- admission: credits for every item in flight or waiting in an output FIFO, and a slot of
  // the surface search ring for a surface piece ----
  localparam integer Depth = 1 << FifoLog2;
  reg  [FifoLog2:0] used_q;
  wire              credit = used_q < Depth[FifoLog2:0];
  wire              ring_ready;
  wire              accept = in_valid && in_ready;
  wire              pop    = res_valid_o && res_ready_i;
  assign in_ready = credit && (!in_surf || ring_ready);
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) used_q <= {(FifoLog2+1){1'b0}};
    else         used_q <= used_q + {{FifoLog2{1'b0}}, accept} - {{FifoLog2{1'b0}}, pop};
  end
  // The ring's occupancy, mirrored here at the fixed distance (stage 0, the ray generator, the
  // sphere unit, the surface RAM read, the setup) ahead of the ring (rpu_surface_admit: any
  // fixed distance).
  generate
    if (Surfaces != 0) begin : g_ring
      rpu_surface_admit #(.Period(SfPeriod), .Returns(SfPasses - 1)) u_ring_admit (
        .clk_i, .rst_ni, .valid_i(in_valid && in_surf && credit), .ready_o(ring_ready));
    end else begin : g_no_ring
      assign ring_ready = 1'b1;  // no ring: a surface item only waits for a credit
    end
  endgenerate

  // ---- stage 0: read the segment descriptor ----
  wire           v0_q;
  wire [ItW-1:0] item_q;
  reg [SegW-1:0] seg_q;
  rpu_stage #(.W(ItW)) u_stage0 (
    .clk_i, .rst_ni, .valid_i(accept), .d_i(in_item), .valid_o(v0_q), .q_o(item_q));
  always @(posedge clk_i) seg_q <= seg_mem[in_item[ItSegO +: SegAddrW]];

  // ---- ray generator; the item and its descriptor ride along ----
  wire [IdxW-1:0] it_i = item_q[ItIO +: IdxW];
  wire [IdxW-1:0] it_j = item_q[ItJO +: IdxW];
  wire            rg_valid;
  wire [3*`RPU_VW(DirFrac)-1:0] rg_v_unused;
  wire [3*`RPU_VHATW(DirFrac)-1:0] rg_vhat;
  wire [3*EoW-1:0] rg_el, rg_er, rg_et, rg_eb;
  wire [ItW+SegW-1:0] rg_tag;
`ifdef RPU_FORMAL_TOP
`include "rpu_top_formal_ray.vh"
`else
  rpu_ray_gen #(.DirFrac(DirFrac), .EdgeFrac(EdgeFrac), .IdxW(IdxW), .TagW(ItW + SegW)) u_ray (
    .clk_i, .rst_ni, .valid_i(v0_q), .i_i(it_i), .j_i(it_j), .v0_i(cam_v0), .dx_i(cam_dx),
    .dy_i(cam_dy), .el0_i(cam_el0), .et0_i(cam_et0), .sw_i(cam_sw), .tag_i({item_q, seg_q}),
    .valid_o(rg_valid), .v_o(rg_v_unused), .vhat_o(rg_vhat), .e_left_o(rg_el),
    .e_right_o(rg_er), .e_top_o(rg_et), .e_bottom_o(rg_eb), .tag_o(rg_tag));
`endif

  // Edge vectors: the compiler guarantees every pixel's fit Q(4.FE+14) (EgW bits), so the
  // generator's wider outputs are narrowed losslessly.
  wire [EdgW-1:0] rg_edges;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_narrow
      assign rg_edges[EdLeftO + c*EgW +: EgW]   = rg_el[c*EoW +: EgW];
      assign rg_edges[EdRightO + c*EgW +: EgW]  = rg_er[c*EoW +: EgW];
      assign rg_edges[EdTopO + c*EgW +: EgW]    = rg_et[c*EoW +: EgW];
      assign rg_edges[EdBottomO + c*EgW +: EgW] = rg_eb[c*EoW +: EgW];
      wire unused_high = ^{rg_el[c*EoW+EgW +: EoW-EgW], rg_er[c*EoW+EgW +: EoW-EgW],
                           rg_et[c*EoW+EgW +: EoW-EgW], rg_eb[c*EoW+EgW +: EoW-EgW]};
    end
  endgenerate

  // Segment descriptor fields (rpu_seg_desc.vh).
  wire [SegW-1:0]     sd      = rg_tag[0 +: SegW];
  wire [ItW-1:0]      rg_it   = rg_tag[SegW +: ItW];
  wire                rg_surf = rg_it[ItSurfO];
  wire [ItBW-1:0]     rg_itb  = rg_it[0 +: ItBW];          // what the curve and texture paths carry
  wire                sd_tex  = sd[SegTexO] && !rg_surf;
  wire [PrimW-1:0]    sd_prim = sd[SegPrimO +: SegPrimW];
  wire [SegP1W-1:0]   sd_p1   = sd[SegP1O +: SegP1W];
  wire [SegDW-1:0]    sd_d    = sd[SegDO +: SegDW];
  wire [SegC0W-1:0]   sd_c0   = sd[SegC0O +: SegC0W];
  wire [SegR2W-1:0]   sd_r2   = sd[SegR2O +: SegR2W];
  wire [SegL2W-1:0]   sd_l2   = sd[SegL2O +: SegL2W];
  wire [SegInvMW-1:0] sd_invm = sd[SegInvMO +: SegInvMW];
  wire [SegInvSW-1:0] sd_invs = sd[SegInvSO +: SegInvSW];
  wire [2*GdW-1:0]    sd_g    = sd[SegG2O +: 2 * GdW];     // {g1, g2}
  wire [SegFrW-1:0]   sd_fr   = sd[SegFrO +: SegFrW];
  wire [SegFgW-1:0]   sd_fg   = sd[SegFgO +: SegFgW];      // {fg1, fg2}

`ifndef RPU_FORMAL_TOP
  // ---- sphere unit: a curve item's interpolation sphere, or a surface piece's bounding sphere
  // (with p1 = d = 0 and no 1/L², as rpu_surface_setup's own unit would take it: the surface path
  // shares this unit, each work item being of one kind) ----
  // The bounding spheres {R², c0}, a copy of those fields of the surface RAM read beside the ray
  // generator's output (distributed RAM, read without a register).
  localparam integer SbW = SfR2W + 3 * CoordW;
  wire            sp_surf = Surfaces != 0 && rg_surf;
  wire [SbW-1:0]  rg_sb;
  generate
    if (Surfaces != 0) begin : g_bound_ram
      reg [SbW-1:0] sb_mem [0:(1<<SurfAddrW)-1];
      always @(posedge clk_i) if (surf_we_i) sb_mem[surf_addr_i] <= surf_data_i[SfR2O +: SbW];
      assign rg_sb = sb_mem[rg_it[ItSegO +: SurfAddrW]];
    end else begin : g_no_bound_ram
      assign rg_sb = {SbW{1'b0}};
    end
  endgenerate
  wire             sp_valid, sp_pred1, sp_ovf;
  wire [CoordW+3:0] sp_tc_unused;
  wire [CoordW+2:0] sp_hc_unused;
  wire [3*CoordW-1:0] sp_a, sp_b;
  wire [SegDW-1:0] sp_ab;
  wire [TW-1:0]    sp_alpha, sp_beta;
  wire [SphTagW-1:0] sp_tag;
  rpu_sphere #(.CoordW(CoordW), .DirFrac(DirFrac), .TFrac(TFrac), .InvW(InvW), .SqrtW(SqrtW),
               .TagW(SphTagW)) u_sphere (
    .clk_i, .rst_ni, .valid_i(rg_valid && !sd_tex && (!rg_surf || sp_surf)), .eye_i(cam_eye),
    .vhat_i(rg_vhat),
    .c0_i(sp_surf ? rg_sb[SfR2W +: 3*CoordW] : sd_c0),
    .r2_i(sp_surf ? rg_sb[0 +: SfR2W] : sd_r2), .p1_i(sp_surf ? {SegP1W{1'b0}} : sd_p1),
    .d_i(sp_surf ? {SegDW{1'b0}} : sd_d), .inv_m_i(sp_surf ? {SegInvMW{1'b0}} : sd_invm),
    .inv_s_i(sp_surf ? {SegInvSW{1'b0}} : sd_invs),
    .tag_i({rg_it, sd_prim, sd_p1, sd_d, sd_l2, sd_g, sd_fr, sd_fg, rg_edges}),
    .valid_o(sp_valid), .pred1_o(sp_pred1), .tc_o(sp_tc_unused), .half_chord_o(sp_hc_unused),
    .a_o(sp_a), .b_o(sp_b), .ab_o(sp_ab), .alpha_o(sp_alpha), .beta_o(sp_beta),
    .ovf_o(sp_ovf), .tag_o(sp_tag));
  wire [ItW-1:0] sp_it     = sp_tag[SpItO +: ItW];
  wire           sp_is_sf  = sp_it[ItSurfO];

  // ---- the K-step process ----
  wire             ip_ready, ip_valid, ip_ovf;
  wire [StW-1:0]   ip_state;
  wire [IpCtxW-1:0] ip_ctx;
  rpu_ip #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .SqrtW(SqrtW), .N(N), .N1(N1),
           .Metric(Metric), .Unrolled(Unrolled), .FifoLog2(FifoLog2), .CtxW(IpCtxW)) u_ip (
    .clk_i, .rst_ni, .valid_i(sp_valid && !sp_is_sf), .ready_o(ip_ready), .a_i(sp_a),
    .ab_i(sp_ab),
    .alpha_i(sp_alpha), .beta_i(sp_beta), .p1_i(sp_tag[SpP1O +: SegP1W]),
    .d_i(sp_tag[SpDO +: SegDW]), .l2_i(sp_tag[SpL2O +: SegL2W]),
    .g1_i(sp_tag[SpGO + GdW +: GdW]), .g2_i(sp_tag[SpGO +: GdW]),
    .fr_i(sp_tag[SpFrO +: SegFrW]), .fg_i(sp_tag[SpFgO +: SegFgW]),
    .ctx_i({sp_tag[SpItO +: ItBW], sp_tag[SpPrimO +: PrimW], sp_pred1, sp_ovf,
            sp_tag[SpEdgesO +: EdgW]}),
    .valid_o(ip_valid), .state_o(ip_state), .ovf_o(ip_ovf), .ctx_o(ip_ctx));
  // The credit count keeps rpu_ip's start FIFO (same depth) from filling: ready_o is high when an
  // item comes (the iterative rpu_ip drops one offered while it is low), checked in simulation.
`ifndef SYNTHESIS
  always @(posedge clk_i or negedge rst_ni)
    if (rst_ni && sp_valid && !sp_is_sf && !ip_ready)
      $fatal(1, "rpu_top: a curve item offered to rpu_ip while its ready_o is low");
`endif
  wire unused_md = ^ip_state[IsMdO +: 2 * MdW];
  wire unused_ip = ^{ip_ready, sp_tc_unused, sp_hc_unused, rg_v_unused};

  wire [ItBW-1:0]  i_it    = ip_ctx[IcItO +: ItBW];
  wire [PrimW-1:0] i_prim  = ip_ctx[IcPrimO +: PrimW];
  wire             i_pred1 = ip_ctx[IcPred1O];
  wire             i_sovf  = ip_ctx[IcOvfO];
  wire [EdgW-1:0]  i_edges = ip_ctx[IcEdgesO +: EdgW];
  wire [N-1:0]     i_tau   = ip_state[IsTauO +: N];
  wire [TW-1:0]    i_t     = ip_state[IsTO +: TW];
  wire [3*XW-1:0]  i_x     = ip_state[IsXO +: 3 * XW];
  // As the model: without pred_1 the pair is background and τ, t, X are zero; overflow counts
  // the sphere unit always and the IP only for pairs that ran it.
  wire             r_ovf   = i_sovf | (i_pred1 & ip_ovf);
  wire [N-1:0]     r_tau   = i_pred1 ? i_tau : {N{1'b0}};
  wire [TW-1:0]    r_t     = i_pred1 ? i_t : {TW{1'b0}};
  wire [3*XW-1:0]  r_x     = i_pred1 ? i_x : {3*XW{1'b0}};

  // ---- capture ----
  wire              cp_valid, cp_hit, cp_tok_unused;
  wire [3:0]        cp_signs_unused;
  wire [DepthW-1:0] cp_depth;
  wire [CapTagW-1:0] cp_tag;
  rpu_capture #(.CoordW(CoordW), .TFrac(TFrac), .EdgeFrac(EdgeFrac), .TagW(CapTagW)) u_capture (
    .clk_i, .rst_ni, .valid_i(ip_valid), .x_i(r_x), .t_i(r_t), .eye_i(cam_eye),
    .e_left_i(i_edges[EdLeftO +: CamEW]), .e_right_i(i_edges[EdRightO +: CamEW]),
    .e_top_i(i_edges[EdTopO +: CamEW]), .e_bottom_i(i_edges[EdBottomO +: CamEW]), .w_i(cam_w),
    .tag_i({i_it, i_prim, i_pred1, r_ovf, r_tau, r_t, r_x}),
    .valid_o(cp_valid), .hit_o(cp_hit), .t_in_range_o(cp_tok_unused), .signs_o(cp_signs_unused),
    .depth_o(cp_depth), .tag_o(cp_tag));
  wire unused_cp = ^{cp_tok_unused, cp_signs_unused};
  wire c_pred1 = cp_tag[CtPred1O];

  // ---- texture path: ray/plane point, then the coverage test ----
  wire             rp_valid, rp_p0_valid;
  wire [3*CoordW-1:0] rp_p0;
  wire [DepthW-1:0] rp_depth;
  wire [RpTagW-1:0] rp_tag;
  rpu_ray_plane #(.CoordW(CoordW), .DirFrac(DirFrac), .EdgeFrac(EdgeFrac),
                  .TagW(RpTagW)) u_ray_plane (
    .clk_i, .rst_ni, .valid_i(rg_valid && sd_tex), .eye_i(cam_eye), .vhat_i(rg_vhat),
    .w_i(cam_w), .tag_i({rg_itb, sd_prim, sd_p1, sd_d, sd_l2, sd_invm, sd_invs, sd_g, sd_r2,
                         sd_c0[0]}),
    .valid_o(rp_valid), .p0_valid_o(rp_p0_valid), .p0_o(rp_p0), .depth_o(rp_depth),
    .tag_o(rp_tag));

  wire             tx_valid, tx_covers, tx_ovf, tx_pr1_unused, tx_pr2_unused, tx_pr3_unused;
  wire [TW-1:0]    tx_t;
  wire [3*XW-1:0]  tx_x;
  wire [TxTagW-1:0] tx_tag;
  rpu_texture #(.CoordW(CoordW), .TFrac(TFrac), .UnitFrac(UnitFrac), .InvW(InvW),
                .SqrtW(SqrtW), .TagW(TxTagW)) u_texture (
    .clk_i, .rst_ni, .valid_i(rp_valid), .p0_i(rp_p0), .p1_i(rp_tag[RpP1O +: SegP1W]),
    .d_i(rp_tag[RpDO +: SegDW]), .l2_i(rp_tag[RpL2O +: SegL2W]),
    .inv_m_i(rp_tag[RpInvMO +: SegInvMW]), .inv_s_i(rp_tag[RpInvSO +: SegInvSW]),
    .g1_i(rp_tag[RpGO + GdW +: GdW]), .g2_i(rp_tag[RpGO +: GdW]),
    .w0_2_i(rp_tag[RpW02O +: SegR2W]), .round_join_i(rp_tag[RpJoinO]),
    .tag_i({rp_tag[RpItO +: ItBW], rp_tag[RpPrimO +: PrimW], rp_p0_valid, rp_depth}),
    .valid_o(tx_valid), .pr1_o(tx_pr1_unused), .pr2_o(tx_pr2_unused), .pr3_o(tx_pr3_unused),
    .covers_o(tx_covers), .t_o(tx_t), .x_o(tx_x), .ovf_o(tx_ovf), .tag_o(tx_tag));
  wire unused_tx = ^{tx_pr1_unused, tx_pr2_unused, tx_pr3_unused};
  wire [ItBW-1:0]   tx_it    = tx_tag[TtItO +: ItBW];
  wire [PrimW-1:0]  tx_prim  = tx_tag[TtPrimO +: PrimW];
  wire              tx_p0ok  = tx_tag[TtP0OkO];
  wire [DepthW-1:0] tx_depth = tx_tag[TtDepthO +: DepthW];
`else
`include "rpu_top_formal_paths.vh"
`endif

  // ---- surface path: the sphere unit's result for the piece (above) and the descriptor read
  // beside it, then rpu_surface_top; without the surface path (Surfaces = 0), and in the top's
  // proof, the piece branches off at the ray generator instead ----
  wire           sf_src_v;
  wire [ItW-1:0] sf_src_it;
`ifdef RPU_FORMAL_TOP
  assign sf_src_v  = rg_valid && rg_surf;
  assign sf_src_it = rg_it;
`else
  assign sf_src_v  = Surfaces != 0 ? sp_valid && sp_is_sf : rg_valid && rg_surf;
  assign sf_src_it = Surfaces != 0 ? sp_it : rg_it;
  // The sphere unit's result for the piece: {pred1, A, B, B − A, overflow}.
  localparam integer SfSpW = 2 + 6 * CoordW + SegDW;
  reg [SfSpW-1:0] sf_sp_q;
  always @(posedge clk_i) sf_sp_q <= {sp_pred1, sp_a, sp_b, sp_ab, sp_ovf};
`endif
  wire             sf_v_q;
  wire [ItW-1:0]   sf_it_q;
  reg [SurfDW-1:0] sf_q;
  rpu_stage #(.W(ItW)) u_sf_stage (
    .clk_i, .rst_ni, .valid_i(sf_src_v), .d_i(sf_src_it), .valid_o(sf_v_q), .q_o(sf_it_q));
  always @(posedge clk_i) sf_q <= surf_mem[sf_src_it[ItSegO +: SurfAddrW]];
  wire             sf_valid, sf_ready_unused, sf_pv, sf_hit, sf_ovf;
  wire [1:0]       sf_pcs;
  wire [N-1:0]     sf_tau;
  wire [3*CoordW-1:0] sf_x;
  wire [DepthW-1:0] sf_depth;
  wire [ItW+PrimW-1:0] sf_tag;
`ifdef RPU_FORMAL_TOP
`include "rpu_top_formal_surface.vh"
`else
  generate
    if (Surfaces != 0) begin : g_surface
    rpu_surface_top #(.CoordW(CoordW), .DirFrac(DirFrac), .TFrac(TFrac), .InvW(InvW),
                      .SqrtW(SqrtW), .EdgeFrac(EdgeFrac), .SurfW(SurfW), .AngleW(AngleW),
                      .Turns(Turns), .N(N), .N1(N1), .N1First(N1First), .Indicators(Indicators),
                      .Unrolled(0), .Admit(0), .TagW(ItW + PrimW), .Sphere(0)) u_surface (
      .clk_i, .rst_ni, .eye_i(cam_eye), .w_i(cam_w), .valid_i(sf_v_q), .ready_o(sf_ready_unused),
      .vhat_i({3*(2+DirFrac){1'b0}}), .bound_c0_i({3*CoordW{1'b0}}), .bound_r2_i({SfR2W{1'b0}}),
      .origin_i(sf_q[SfOriginO +: 3*CoordW]), .to_local_i(sf_q[SfToLocO +: 9*SfMantW]),
      .to_local_s_i(sf_q[SfToLocSO +: 7]), .y_min_i(sf_q[SfYMinO +: SurfW]),
      .y_max_i(sf_q[SfYMaxO +: SurfW]), .end_angle_i(sf_q[SfEndAngO +: AngleW]),
      .end_cos_i(sf_q[SfEndCosO +: SfConstW]), .end_sin_i(sf_q[SfEndSinO +: SfConstW]),
      .desc_i(sf_q[SfDescO +: SfDescW]), .piece_i(sf_it_q[ItPcO +: 2]),
      .tag_i({sf_it_q, sf_q[SfPrimO +: PrimW]}),
      .sp_pred1_i(sf_sp_q[SfSpW-1]), .sp_a_i(sf_sp_q[1 + 3*CoordW + SegDW +: 3*CoordW]),
      .sp_b_i(sf_sp_q[1 + SegDW +: 3*CoordW]), .sp_ab_i(sf_sp_q[1 +: SegDW]),
      .sp_ovf_i(sf_sp_q[0]), .valid_o(sf_valid), .piece_valid_o(sf_pv), .hit_o(sf_hit), .ovf_o(sf_ovf),
      .pieces_o(sf_pcs), .tau_o(sf_tau), .x_o(sf_x), .depth_o(sf_depth), .tag_o(sf_tag));
      wire unused_sf_bound = ^sf_q[SfR2O +: SbW];  // the sphere unit took them (sb_mem)
    end else begin : g_no_surface
      // Not built: a surface item's word comes back one cycle after its descriptor stage with
      // no piece, no hit and the overflow bit (the model's unbuilt_surface_result; the host
      // refuses scenes with surfaces for such a build, docs/rtl.md).
      assign sf_valid = sf_v_q;
      assign sf_tag   = {sf_it_q, {PrimW{1'b0}}};
      assign {sf_ready_unused, sf_pv, sf_hit, sf_pcs, sf_tau, sf_x, sf_depth} =
          {(5 + N + 3*CoordW + DepthW){1'b0}};
      assign sf_ovf   = 1'b1;
      wire unused_sf_off = ^{sf_q, sf_sp_q};
    end
  endgenerate
`endif
  // X in the result's width (the curve point's): each component sign-extended.
  wire [3*XW-1:0] sf_xw = {{(XW-CoordW){sf_x[3*CoordW-1]}}, sf_x[2*CoordW +: CoordW],
                           {(XW-CoordW){sf_x[2*CoordW-1]}}, sf_x[CoordW +: CoordW],
                           {(XW-CoordW){sf_x[CoordW-1]}}, sf_x[0 +: CoordW]};

  // ---- output FIFOs: curve, texture and surface results, merged in input order ----
  // Result record: {item, texture, pieces, primitive, pred_1, ovf, τ, t, X, hit, depth}.
  // A curve's or texture's item word: piece 0, not a surface.
  wire [ResW-1:0] cres = {3'b000, cp_tag[CtItO +: ItBW], 1'b0, 2'b00, cp_tag[0 +: RsCtxW],
                          c_pred1 & cp_hit, c_pred1 ? cp_depth : {DepthW{1'b0}}};
  // As the model: a ray that misses the plane (or leaves the range) tests nothing: the result
  // is all zero; otherwise covers, t̂, X, the unit's overflow bit, and the ray/plane depth.
  wire [ResW-1:0] tres = {3'b000, tx_it, 1'b1, 2'b00, tx_prim, tx_p0ok, tx_p0ok & tx_ovf, {N{1'b0}},
                        tx_p0ok ? tx_t : {TW{1'b0}}, tx_p0ok ? tx_x : {3*XW{1'b0}},
                        tx_p0ok & tx_covers, tx_depth};
  // As the model: τ, X and depth are 0 without a hit (rpu_surface_top zeroes them), t is 0.
  wire [ResW-1:0] sres = {sf_tag[PrimW +: ItW], 1'b0, sf_pcs, sf_tag[0 +: PrimW], sf_pv, sf_ovf,
                          sf_tau, {TW{1'b0}}, sf_xw, sf_hit, sf_depth};

  // Four FIFOs in block RAM (rpu_fifo: registered read, data out of a register): curve, texture
  // and surface results, and two bits per accepted item saying which of the three holds its
  // result (00 curve, 01 texture, 10 surface). The credit count bounds every FIFO's fill by
  // Depth, so no write is ever refused.
  wire              c_valid, tx_fifo_valid, sf_fifo_valid, o_valid;
  wire [1:0]        head_kind;
  wire              head_surf = head_kind[1];
  wire              head_tex  = head_kind[0];
  wire [ResW-1:0]   c_data, tx_data, sf_data;
  wire              c_wr_ready_unused, tx_wr_ready_unused, sf_wr_ready_unused, o_wr_ready_unused;
  wire              head_valid = o_valid && (head_surf ? sf_fifo_valid
                                           : head_tex ? tx_fifo_valid : c_valid);
  wire              rs_ready;
  rpu_fifo #(.Width(ResW), .Log2Depth(FifoLog2)) u_curve_fifo (
    .clk_i, .rst_ni, .wr_valid_i(cp_valid), .wr_ready_o(c_wr_ready_unused), .wr_data_i(cres),
    .rd_valid_o(c_valid), .rd_ready_i(pop && !head_surf && !head_tex), .rd_data_o(c_data)
    `RPU_F_QUEUE(f_c_cnt, f_c_ent));
  rpu_fifo #(.Width(ResW), .Log2Depth(FifoLog2)) u_texture_fifo (
    .clk_i, .rst_ni, .wr_valid_i(tx_valid), .wr_ready_o(tx_wr_ready_unused), .wr_data_i(tres),
    .rd_valid_o(tx_fifo_valid), .rd_ready_i(pop && head_tex), .rd_data_o(tx_data)
    `RPU_F_QUEUE(f_t_cnt, f_t_ent));
  rpu_fifo #(.Width(ResW), .Log2Depth(FifoLog2)) u_surface_fifo (
    .clk_i, .rst_ni, .wr_valid_i(sf_valid), .wr_ready_o(sf_wr_ready_unused), .wr_data_i(sres),
    .rd_valid_o(sf_fifo_valid), .rd_ready_i(pop && head_surf), .rd_data_o(sf_data)
    `RPU_F_QUEUE(f_s_cnt, f_s_ent));
  rpu_fifo #(.Width(2), .Log2Depth(FifoLog2)) u_order_fifo (
    .clk_i, .rst_ni, .wr_valid_i(v0_q), .wr_ready_o(o_wr_ready_unused),
    .wr_data_i({item_q[ItSurfO], seg_q[SegTexO] && !item_q[ItSurfO]}), .rd_valid_o(o_valid),
    .rd_ready_i(pop), .rd_data_o(head_kind) `RPU_F_QUEUE(f_o_cnt, f_o_ent));
  wire unused_fifo = ^{c_wr_ready_unused, tx_wr_ready_unused, sf_wr_ready_unused,
                       o_wr_ready_unused, sf_ready_unused};
  wire [ResW-1:0] head = head_surf ? sf_data : head_tex ? tx_data : c_data;
  // A result leaves when the consumer and the pixel resolve both take it.
  assign res_valid_o = head_valid && rs_ready;
  assign {res_piece_o, res_surf_o, res_last_o, res_id_o, res_i_o, res_j_o, res_seg_o, res_tex_o,
          res_pieces_o, res_prim_o, res_pred1_o, res_ovf_o, res_tau_o, res_t_o, res_x_o,
          res_hit_o, res_depth_o} = head;

  // ---- pixel resolve ----
  wire [2*IdxW-1:0] pix_ji;
  rpu_resolve #(.PixW(2 * IdxW), .DepthW(DepthW), .PrimW(PrimW)) u_resolve (
    .clk_i, .rst_ni, .valid_i(pop), .ready_o(rs_ready), .pixel_i({res_j_o, res_i_o}),
    .last_i(res_last_o), .hit_i(res_hit_o), .depth_i(res_depth_o), .primitive_i(res_prim_o),
    .valid_o(pix_valid_o), .ready_i(pix_ready_i), .pixel_o(pix_ji), .any_hit_o(pix_hit_o),
    .depth_o(pix_depth_o), .primitive_o(pix_prim_o));
  assign pix_j_o = pix_ji[IdxW +: IdxW];
  assign pix_i_o = pix_ji[IdxW-1:0];

`ifdef FORMAL
`include "rpu_top_props.vh"
`endif
endmodule

`default_nettype wire
