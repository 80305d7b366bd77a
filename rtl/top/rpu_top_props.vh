// rpu_top's formal properties (scripts/formal.sh top at a reduced parameter set,
// docs/verification.md). Formal only: included by rtl/top/rpu_top.v under `ifdef FORMAL; it
// refers to rpu_top's own signals.
  // ---- formal properties (scripts/formal.sh at a reduced parameter set, docs/verification.md)
  // Only control and tag signals are referenced: the script removes the datapath outputs from
  // the ports, so no multiplier or divider stays in the proof. Environment: reset at the first
  // cycle; the work items are numbered 0, 1, 2, … (mod 2^IdW) in item_id_i; every other input
  // is free (any valid/ready pattern, any segment, descriptor writes at any time).
  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
  always @(*) if (!f_past_valid) assume(!rst_ni);
  reg [IdW-1:0]     f_acc_id, f_pop_id;   // items accepted / results delivered, mod 2^IdW
  reg [FifoLog2+1:0] f_out;               // accepted at the port − delivered (exact)
  reg [1:0]          f_in;                // accepted at the port − taken by stage 0 (exact)
  wire f_port = item_valid_i && item_ready_o;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_acc_id <= {IdW{1'b0}};
      f_pop_id <= {IdW{1'b0}};
      f_out    <= {(FifoLog2+2){1'b0}};
      f_in     <= 2'd0;
    end else begin
      if (f_port) f_acc_id <= f_acc_id + 1'b1;
      if (pop)    f_pop_id <= f_pop_id + 1'b1;
      f_out <= f_out + {{(FifoLog2+1){1'b0}}, f_port} - {{(FifoLog2+1){1'b0}}, pop};
      f_in  <= f_in + {1'b0, f_port} - {1'b0, accept};
    end
  end
  always @(*) if (item_valid_i) assume(item_id_i == f_acc_id);
  always @(*) begin
    if (!rst_ni) assert(!res_valid_o && !pix_valid_o);
    if (rst_ni) begin
      // The credit count is the number of items taken and not delivered, never above
      // 2^FifoLog2; the input register holds the rest of those accepted (at most two).
      assert(used_q <= Depth[FifoLog2:0]);
      assert(f_in <= 2'd2);
      assert({1'b0, used_q} + {{FifoLog2{1'b0}}, f_in} == f_out);
      // item_ready_o: exactly while the input register's spill slot is free; an item waits
      // there only while it cannot be taken.
      assert(item_ready_o == (f_in != 2'd2));
      assert(in_valid == (f_in != 2'd0));
      // No result without an accepted item; results in input order, each exactly once (the
      // result's id is the number of results delivered before it).
      if (res_valid_o) begin
        assert(f_out != {(FifoLog2+2){1'b0}});
        assert(res_id_o == f_pop_id);
      end
    end
  end
  // Tracked item: f_pick (free) chooses one accepted item; f_t_ahead counts the items in front
  // of it (accepted, not delivered). It must come back when none is left in front, with its id,
  // pixel, segment, last bit, surface bit and piece (a curve's or texture's result says piece 0).
  (* anyseq *) wire f_pick;
  reg                f_track, f_done;
  reg [IdW-1:0]      f_t_id;
  reg [FifoLog2+1:0] f_t_ahead;
  reg [2*IdxW+SegAddrW+3:0] f_t_tag;   // {piece, surf, last, i, j, seg}
  localparam integer FtW = 2 * IdxW + SegAddrW + 1;   // {last, i, j, seg}
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_track <= 1'b0;
      f_done  <= 1'b0;
    end else if (f_port && f_pick && !f_track && !f_done) begin
      f_track   <= 1'b1;
      f_t_id    <= item_id_i;
      f_t_ahead <= f_out - {{(FifoLog2+1){1'b0}}, pop};
      f_t_tag   <= {item_piece_i, item_surf_i, item_last_i, item_i_i, item_j_i, item_seg_i};
    end else if (f_track && pop) begin
      if (f_t_ahead == {(FifoLog2+2){1'b0}}) begin
        f_track <= 1'b0;
        f_done  <= 1'b1;
      end
      f_t_ahead <= f_t_ahead - 1'b1;
    end
  end
  always @(*) if (rst_ni && f_track) begin
    assert(f_t_ahead < f_out);
    assert(f_t_id == f_pop_id + f_t_ahead[IdW-1:0]);
    if (res_valid_o && f_t_ahead == {(FifoLog2+2){1'b0}}) begin
      assert(res_id_o == f_t_id);
      assert({res_last_o, res_i_o, res_j_o, res_seg_o} == f_t_tag[0 +: FtW]);
      assert(res_surf_o == f_t_tag[FtW]);
      assert(res_piece_o == (res_surf_o ? f_t_tag[FtW+1 +: 2] : 2'b00));
    end
  end
  always @(*) if (rst_ni) assert(!(f_track && f_done));

`ifdef RPU_FORMAL_TOP
  // ---- Induction invariants: every item is in one place, in order, and its kind is known ----
  // The items accepted and not delivered have positions 0, 1, … (0: the next result), and an
  // item's id is f_pop_id + its position. Input register: positions used_q, used_q + 1; stage 0:
  // position f_o_cnt (its kind is written into the order FIFO this cycle); the ray generator's
  // queue: the f_rg_cnt positions below that; every position below f_lim has left the ray
  // generator, and the order FIFO's entry p is the kind of the item at position p. Each path
  // (its queue, then its result FIFO; the surface path's descriptor stage first) holds its items
  // in increasing position, each where the order FIFO says its kind is, and as many as the order
  // FIFO counts of that kind below f_lim: so the paths hold exactly the items below f_lim, each
  // once, and the head of the kind the order FIFO names is position 0 (the id f_pop_id).
  localparam integer FE = Depth + 1;          // entries of an rpu_fifo
  localparam integer CW = FifoLog2 + 2;       // their count's width
  localparam integer QW = ItW + 1;            // the ray generator queue's entry: {item, tex}
  reg [CW-1:0]  f_lim, f_p, f_prev, f_n0, f_n1, f_n2;
  reg           f_have;
  reg [ItW-1:0] f_w;
  reg [1:0]     f_kind, f_at;
  integer       f_k, f_q;
`define RPU_F_POS(w) ({{(CW-IdW){1'b0}}, (w[ItIdO +: IdW]) - f_pop_id})
  // f_at: the order FIFO's entry at position p (constant indices: no multiplier in the proof).
`define RPU_F_KIND_AT(p) \
        f_at = 2'b11; \
        for (f_q = 0; f_q < FE; f_q = f_q + 1) if ((p) == f_q[CW-1:0]) f_at = f_o_ent[2*f_q +: 2];
  // A path's item word w of kind KIND (2'b00 curve, 01 texture, 10 surface), next in its path.
`define RPU_F_PATH(w, KIND) \
      begin \
        f_p = `RPU_F_POS(w); \
        assert(f_p < f_lim); \
        `RPU_F_KIND_AT(f_p) \
        assert(f_at == (KIND)); \
        if ((KIND) == 2'b10) assert(w[ItSurfO]); \
        if (f_have) assert(f_p > f_prev); \
        f_prev = f_p; \
        f_have = 1'b1; \
        if (f_track && f_p == f_t_ahead) begin \
          assert({w[ItLastO], w[0 +: ItIdO]} == f_t_tag[0 +: FtW]); \
          if ((KIND) == 2'b10) assert(w[ItSurfO +: 3] == f_t_tag[FtW +: 3]); \
          else assert(!f_t_tag[FtW]); \
        end \
      end
  always @(*) begin
    f_lim = {CW{1'b0}}; f_p = {CW{1'b0}}; f_prev = {CW{1'b0}}; f_have = 1'b0;
    f_n0 = {CW{1'b0}}; f_n1 = {CW{1'b0}}; f_n2 = {CW{1'b0}}; f_w = {ItW{1'b0}}; f_kind = 2'b00;
    f_at = 2'b00;
    if (rst_ni) begin
      // Counts: the input register holds f_in items, the credit count is stage 0 plus the order
      // FIFO, which counts every item past stage 0 once.
      assert({1'b0, f_in_cnt} == {1'b0, f_in});
      assert({1'b0, used_q} == f_o_cnt + {{(CW-1){1'b0}}, v0_q});
      // (summed in 8 bits: a wrapped sum would let a full set of FIFOs pass for empty ones)
      assert({4'd0, f_o_cnt} == {4'd0, f_rg_cnt} + {4'd0, f_cv_cnt} + {4'd0, f_tx_cnt}
                                + {4'd0, f_sf_cnt} + {4'd0, f_c_cnt} + {4'd0, f_t_cnt}
                                + {4'd0, f_s_cnt} + {{(CW+3){1'b0}}, sf_v_q});
      assert(f_acc_id == f_pop_id + f_out[IdW-1:0]);
      f_lim = f_o_cnt - f_rg_cnt;
      // The input register: positions used_q, used_q + 1 (the output register's item first).
      for (f_k = 0; f_k < 2; f_k = f_k + 1)
        if (f_k < f_in) begin
          f_w = f_in_ent[f_k*ItW +: ItW];
          f_p = {1'b0, used_q} + f_k[CW-1:0];
          assert(f_w[ItIdO +: IdW] == f_pop_id + f_p[IdW-1:0]);
          if (f_track && f_p == f_t_ahead)
            assert({f_w[ItPcO +: 2], f_w[ItSurfO], f_w[ItLastO], f_w[0 +: ItIdO]} == f_t_tag);
        end
      // Stage 0: position f_o_cnt.
      if (v0_q) begin
        assert(item_q[ItIdO +: IdW] == f_pop_id + f_o_cnt[IdW-1:0]);
        if (f_track && f_o_cnt == f_t_ahead)
          assert({item_q[ItPcO +: 2], item_q[ItSurfO], item_q[ItLastO], item_q[0 +: ItIdO]} == f_t_tag);
      end
      // The ray generator's queue: positions f_lim … f_o_cnt − 1, kinds as in the order FIFO.
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_rg_cnt) begin
          f_w    = f_rg_ent[f_k*QW + 1 +: ItW];
          f_kind = {f_w[ItSurfO], f_rg_ent[f_k*QW] && !f_w[ItSurfO]};
          f_p    = f_lim + f_k[CW-1:0];
          assert(f_w[ItIdO +: IdW] == f_pop_id + f_p[IdW-1:0]);
          `RPU_F_KIND_AT(f_p)
          assert(f_at == f_kind);
          if (f_track && f_p == f_t_ahead)
            assert({f_w[ItPcO +: 2], f_w[ItSurfO], f_w[ItLastO], f_w[0 +: ItIdO]} == f_t_tag);
        end
      // The order FIFO: no fourth kind; the kinds below f_lim counted.
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_o_cnt) begin
          assert(f_o_ent[2*f_k +: 2] != 2'b11);
          if (f_k < f_lim) begin
            if (f_o_ent[2*f_k +: 2] == 2'b00) f_n0 = f_n0 + 1'b1;
            if (f_o_ent[2*f_k +: 2] == 2'b01) f_n1 = f_n1 + 1'b1;
            if (f_o_ent[2*f_k +: 2] == 2'b10) f_n2 = f_n2 + 1'b1;
          end
        end
      assert({1'b0, f_n0} == {1'b0, f_c_cnt} + {1'b0, f_cv_cnt});
      assert({1'b0, f_n1} == {1'b0, f_t_cnt} + {1'b0, f_tx_cnt});
      assert({2'b0, f_n2} == {2'b0, f_s_cnt} + {2'b0, f_sf_cnt} + {{(CW+1){1'b0}}, sf_v_q});
      // Curve path: its result FIFO (oldest first), then its queue. A curve or texture
      // record's item says piece 0, no surface.
      f_have = 1'b0;
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_c_cnt) begin
          f_w = f_c_ent[f_k*ResW + RsItO +: ItW];
          assert(f_w[ItSurfO +: 3] == 3'b000);
          `RPU_F_PATH(f_w, 2'b00)
        end
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_cv_cnt) begin
          f_w = {3'b000, f_cv_ent[f_k*ItBW +: ItBW]};
          `RPU_F_PATH(f_w, 2'b00)
        end
      // Texture path.
      f_have = 1'b0;
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_t_cnt) begin
          f_w = f_t_ent[f_k*ResW + RsItO +: ItW];
          assert(f_w[ItSurfO +: 3] == 3'b000);
          `RPU_F_PATH(f_w, 2'b01)
        end
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_tx_cnt) begin
          f_w = {3'b000, f_tx_ent[f_k*ItBW +: ItBW]};
          `RPU_F_PATH(f_w, 2'b01)
        end
      // Surface path: result FIFO, queue, then the descriptor stage.
      f_have = 1'b0;
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_s_cnt) begin
          f_w = f_s_ent[f_k*ResW + RsItO +: ItW];
          `RPU_F_PATH(f_w, 2'b10)
        end
      for (f_k = 0; f_k < FE; f_k = f_k + 1)
        if (f_k < f_sf_cnt) begin
          f_w = f_sf_ent[f_k*(ItW+PrimW) + PrimW +: ItW];
          `RPU_F_PATH(f_w, 2'b10)
        end
      if (sf_v_q) begin
        f_w = sf_it_q;
        `RPU_F_PATH(f_w, 2'b10)
      end
    end
  end
`undef RPU_F_PATH
`undef RPU_F_KIND_AT
`undef RPU_F_POS
`endif
  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_ni) && rst_ni) begin
      // AXI-Stream: a result, or a pixel, stays valid with the same tags until taken.
      if ($past(res_valid_o && !res_ready_i)) begin
        assert(res_valid_o);
        assert(res_id_o == $past(res_id_o) && res_last_o == $past(res_last_o) &&
               res_i_o == $past(res_i_o) && res_j_o == $past(res_j_o) &&
               res_seg_o == $past(res_seg_o) && res_tex_o == $past(res_tex_o) &&
               res_surf_o == $past(res_surf_o) && res_piece_o == $past(res_piece_o));
      end
      if ($past(pix_valid_o && !pix_ready_i)) begin
        assert(pix_valid_o);
        assert(pix_i_o == $past(pix_i_o) && pix_j_o == $past(pix_j_o));
      end
    end
  end
  // Reachability: a curve and a texture result out, the credits exhausted, a pixel out.
  always @(*) if (rst_ni) begin
    cover(res_valid_o && !res_tex_o);
    cover(res_valid_o && res_tex_o);
    cover(!item_ready_o);
    cover(pix_valid_o);
    cover(f_done);
  end
