// Formal only (scripts/formal.sh axi, RPU_FORMAL_AXI): rpu_top abstracted, as the top's own
// proof abstracts its pipelines. Its item ready, its result and pixel streams and their records
// are free inputs, constrained only by the valid/ready rule rpu_top's proof establishes for its
// ports (a record offered and not taken is offered again, unchanged; nothing offered in reset).
// The shell's handshake properties (rpu_axi_props.vh) hold against any such rpu_top. Included
// inside rpu_axi in place of the rpu_top instance.
  (* anyseq *) reg                f_top_ready, f_res_valid, f_pix_valid;
  (* anyseq *) reg [RResultW-1:0] f_res;
  (* anyseq *) reg [RPixelW-1:0]  f_pix;
  assign top_ready  = f_top_ready;
  assign res_valid  = f_res_valid;
  assign pix_valid  = f_pix_valid;
  assign res_id     = f_res[ResultIdO +: ResultIdW];
  assign res_i      = f_res[ResultIO +: ResultIW];
  assign res_j      = f_res[ResultJO +: ResultJW];
  assign res_seg    = f_res[ResultSegO +: ResultSegW];
  assign res_last   = f_res[ResultLastO];
  assign res_surf   = f_res[ResultSurfO];
  assign res_piece  = f_res[ResultPieceO +: ResultPieceW];
  assign res_tex    = f_res[ResultTexO];
  assign res_pieces = f_res[ResultPiecesO +: ResultPiecesW];
  assign res_prim   = f_res[ResultPrimO +: ResultPrimW];
  assign res_pred1  = f_res[ResultPred1O];
  assign res_hit    = f_res[ResultHitO];
  assign res_depth  = f_res[ResultDepthO +: ResultDepthW];
  assign res_tau    = f_res[ResultTauO +: ResultTauW];
  assign res_t      = f_res[ResultTO +: ResultTW];
  assign res_x      = f_res[ResultXO +: ResultXW];
  assign res_ovf    = f_res[ResultOvfO];
  assign pix_i      = f_pix[PixelIO +: PixelIW];
  assign pix_j      = f_pix[PixelJO +: PixelJW];
  assign pix_hit    = f_pix[PixelHitO];
  assign pix_depth  = f_pix[PixelDepthO +: PixelDepthW];
  assign pix_prim   = f_pix[PixelPrimO +: PixelPrimW];
  wire unused_f_top = ^{cam_we_q, seg_we_q, surf_we_q, it_last, it_surf, g_rec};
  reg f_top_past = 1'b0;
  reg f_res_held = 1'b0, f_pix_held = 1'b0;
  reg [RResultW-1:0] f_res_q;
  reg [RPixelW-1:0]  f_pix_q;
  always @(posedge clk_i) begin
    f_top_past <= 1'b1;
    f_res_held <= top_rst_nq && res_valid && !res_ready;
    f_pix_held <= top_rst_nq && pix_valid && !pix_ready;
    f_res_q    <= f_res;
    f_pix_q    <= f_pix;
  end
  always @(*) begin
    if (!top_rst_nq) assume (!f_res_valid && !f_pix_valid);
    if (f_top_past && top_rst_nq && f_res_held) assume (f_res_valid && f_res == f_res_q);
    if (f_top_past && top_rst_nq && f_pix_held) assume (f_pix_valid && f_pix == f_pix_q);
  end
