// rpu_top's proof: the ray generator as an in-order queue of free delay.
// Formal only: included by rtl/top/rpu_top.v under `ifdef RPU_FORMAL_TOP (scripts/formal.sh top,
// docs/verification.md); it refers to rpu_top's own signals.
  // The top's proof (scripts/formal.sh, docs/verification.md) replaces each pipeline by what
  // rpu_top relies on: an in-order queue that returns every item's tag once, after any delay
  // (an rpu_fifo read at free times, f_*_go). That covers every fixed latency, and the
  // iterative IP's varying one; the units' own fixed latency and tags have proofs of their own
  // (formal.sh pipe targets). The datapath values are cut from the proof anyway.
  (* anyseq *) wire f_rg_go;
  wire             f_rg_v, f_rg_wr_unused;
  wire [ItW:0]     f_rg_d;
  wire [FifoLog2+1:0] f_rg_cnt;
  wire [((1<<FifoLog2)+1)*(ItW+1)-1:0] f_rg_ent;
  reg  [SegW-1:0]  f_rg_sd;
  rpu_fifo #(.Width(ItW + 1), .Log2Depth(FifoLog2)) u_f_rg (
    .clk_i, .rst_ni, .wr_valid_i(v0_q), .wr_ready_o(f_rg_wr_unused),
    .wr_data_i({item_q, seg_q[SegTexO]}), .rd_valid_o(f_rg_v), .rd_ready_i(f_rg_go),
    .rd_data_o(f_rg_d), .f_count_o(f_rg_cnt), .f_entries_o(f_rg_ent));
  always @(*) begin
    f_rg_sd          = {SegW{1'b0}};
    f_rg_sd[SegTexO] = f_rg_d[0];
  end
  assign rg_valid = f_rg_v && f_rg_go;
  assign rg_tag   = {f_rg_d[1 +: ItW], f_rg_sd};
  assign {rg_v_unused, rg_vhat, rg_el, rg_er, rg_et, rg_eb} =
      {(3*(4+DirFrac) + 3*(2+DirFrac) + 12*EoW){1'b0}};
  wire unused_f_rg = ^{f_rg_wr_unused, it_i, it_j, cam_v0, cam_dx, cam_dy, cam_el0, cam_et0,
                       cam_sw};
