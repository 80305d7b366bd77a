// rpu_axi's formal properties (scripts/formal.sh axi; docs/verification.md): the AXI4-Stream
// handshake rules on its two master ports, proved by k-induction with rpu_top abstracted
// (rpu_axi_formal_top.vh). The AXI4-Lite rules are rpu_axil_port's (rpu_axil_port_props.vh).
// Assumed: the host keeps to the AXI rules on the item stream (a beat offered and not taken is
// offered again, unchanged) and the whole design starts in reset. Included inside rpu_axi under
// `ifdef FORMAL.
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @(*) if (!f_past) assume (!rst_ni);

  reg               f_item_held = 1'b0, f_pix_held2 = 1'b0, f_res_held2 = 1'b0;
  reg [AxisW-1:0]    f_item_d, f_pix_d;
  reg [ResAxisW-1:0] f_res_d;
  reg               f_item_l, f_pix_l, f_res_l;
  always @(posedge clk_i) begin
    f_item_held <= rst_ni && s_item_tvalid_i && !s_item_tready_o;
    f_pix_held2 <= rst_ni && m_pix_tvalid_o && !m_pix_tready_i;
    f_res_held2 <= rst_ni && m_res_tvalid_o && !m_res_tready_i;
    {f_item_l, f_item_d} <= {s_item_tlast_i, s_item_tdata_i};
    {f_pix_l, f_pix_d}   <= {m_pix_tlast_o, m_pix_tdata_o};
    {f_res_l, f_res_d}   <= {m_res_tlast_o, m_res_tdata_o};
  end
  always @(*) begin
    // The host's rule on the item stream.
    if (f_past && rst_ni && f_item_held)
      assume (s_item_tvalid_i && s_item_tdata_i == f_item_d && s_item_tlast_i == f_item_l);
    // Reset: no beat offered on a master port.
    if (!rst_ni) begin
      assert (!m_pix_tvalid_o);
      assert (!m_res_tvalid_o);
    end
    // A master's beat offered and not taken is offered again, TDATA and TLAST unchanged.
    if (f_past && rst_ni && f_pix_held2) begin
      assert (m_pix_tvalid_o);
      assert (m_pix_tdata_o == f_pix_d && m_pix_tlast_o == f_pix_l);
    end
    if (f_past && rst_ni && f_res_held2) begin
      assert (m_res_tvalid_o);
      assert (m_res_tdata_o == f_res_d && m_res_tlast_o == f_res_l);
    end
    // Reachable (the assumptions are not vacuous): a frame's last pixel handed out, and DONE.
    if (rst_ni) begin
      cover (m_pix_tvalid_o && m_pix_tready_i && m_pix_tlast_o);
      cover (irq_o);
    end
  end
