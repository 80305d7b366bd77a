// rpu_top's proof: the curve and texture paths as in-order queues of free delay.
// Formal only: included by rtl/top/rpu_top.v under `ifdef RPU_FORMAL_TOP (scripts/formal.sh top,
// docs/verification.md); it refers to rpu_top's own signals.
  // The curve path (sphere unit, IP, capture) and the texture path (ray/plane point, coverage
  // test) as the proof's in-order queues of free delay (above, at the ray generator): the item
  // word comes back, every datapath value is 0.
  (* anyseq *) wire f_cv_go, f_tx_go;
  wire             f_cv_v, f_tx_v, f_cv_wr_unused, f_tx_wr_unused;
  wire [ItBW-1:0]  f_cv_d, f_tx_d;
  wire [FifoLog2+1:0] f_cv_cnt, f_tx_cnt;
  wire [((1<<FifoLog2)+1)*ItBW-1:0] f_cv_ent, f_tx_ent;
  rpu_fifo #(.Width(ItBW), .Log2Depth(FifoLog2)) u_f_cv (
    .clk_i, .rst_ni, .wr_valid_i(rg_valid && !rg_surf && !sd_tex), .wr_ready_o(f_cv_wr_unused),
    .wr_data_i(rg_itb), .rd_valid_o(f_cv_v), .rd_ready_i(f_cv_go), .rd_data_o(f_cv_d),
    .f_count_o(f_cv_cnt), .f_entries_o(f_cv_ent));
  rpu_fifo #(.Width(ItBW), .Log2Depth(FifoLog2)) u_f_tx (
    .clk_i, .rst_ni, .wr_valid_i(rg_valid && sd_tex), .wr_ready_o(f_tx_wr_unused),
    .wr_data_i(rg_itb), .rd_valid_o(f_tx_v), .rd_ready_i(f_tx_go), .rd_data_o(f_tx_d),
    .f_count_o(f_tx_cnt), .f_entries_o(f_tx_ent));
  wire              cp_valid = f_cv_v && f_cv_go;
  wire              cp_hit   = 1'b0;
  wire [DepthW-1:0] cp_depth = {DepthW{1'b0}};
  wire [CapTagW-1:0] cp_tag  = {f_cv_d, {CtItO{1'b0}}};
  wire              c_pred1  = 1'b0;
  wire              tx_valid = f_tx_v && f_tx_go;
  wire              tx_covers = 1'b0, tx_ovf = 1'b0;
  wire [TW-1:0]     tx_t     = {TW{1'b0}};
  wire [3*XW-1:0]   tx_x     = {3*XW{1'b0}};
  wire [ItBW-1:0]   tx_it    = f_tx_d;
  wire [PrimW-1:0]  tx_prim  = {PrimW{1'b0}};
  wire              tx_p0ok  = 1'b0;
  wire [DepthW-1:0] tx_depth = {DepthW{1'b0}};
  wire unused_f_paths = ^{f_cv_wr_unused, f_tx_wr_unused, sd_prim, sd_p1, sd_d, sd_c0, sd_r2,
                          sd_l2, sd_invm, sd_invs, sd_g, sd_fr, sd_fg, rg_edges, cam_eye, cam_w};
