// rpu_top's proof: the surface unit as an in-order queue of free delay.
// Formal only: included by rtl/top/rpu_top.v under `ifdef RPU_FORMAL_TOP (scripts/formal.sh top,
// docs/verification.md); it refers to rpu_top's own signals.
  // The surface unit as the proof's in-order queue of free delay (above, at the ray generator);
  // the input's ring admission stays real (rpu_surface_admit has its own proof, and
  // tb_rpu_surface_top checks the real unit's latency, order and ring slots).
  (* anyseq *) wire f_sf_go;
  wire               f_sf_v, f_sf_wr_unused;
  wire [FifoLog2+1:0] f_sf_cnt;
  wire [((1<<FifoLog2)+1)*(ItW+PrimW)-1:0] f_sf_ent;
  rpu_fifo #(.Width(ItW + PrimW), .Log2Depth(FifoLog2)) u_f_sf (
    .clk_i, .rst_ni, .wr_valid_i(sf_v_q), .wr_ready_o(f_sf_wr_unused),
    .wr_data_i({sf_it_q, sf_q[SfPrimO +: PrimW]}), .rd_valid_o(f_sf_v), .rd_ready_i(f_sf_go),
    .rd_data_o(sf_tag), .f_count_o(f_sf_cnt), .f_entries_o(f_sf_ent));
  assign sf_valid = f_sf_v && f_sf_go;
  assign {sf_ready_unused, sf_pv, sf_hit, sf_ovf, sf_pcs, sf_tau, sf_x, sf_depth} =
      {(6 + N + 3*CoordW + DepthW){1'b0}};
  wire unused_sf_abs = ^{sf_q, f_sf_wr_unused};
