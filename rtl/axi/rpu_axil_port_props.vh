// rpu_axil_port's formal properties (scripts/formal.sh axi, with rpu_axi around it): the AXI4-
// Lite rules on the slave's side. Assumed: the host keeps to them (AWVALID, WVALID and ARVALID
// with their payloads held until taken). Proved by k-induction: BVALID and RVALID held until
// taken with BRESP, RDATA and RRESP unchanged; one response per request and none without one
// (the requests taken and not yet answered, per channel, are what the port holds: at most two
// writes, a held one and one answered in B, and two reads likewise); nothing offered in reset.
// Included inside rpu_axil_port under `ifdef FORMAL.
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;

  reg f_aw_held = 1'b0, f_w_held = 1'b0, f_ar_held = 1'b0, f_b_held = 1'b0, f_r_held = 1'b0;
  reg [AddrW-1:0] f_awaddr, f_araddr;
  reg [31:0]      f_wdata, f_rdata;
  reg [3:0]       f_wstrb;
  reg [1:0]       f_bresp, f_rresp;
  always @(posedge clk_i) begin
    f_aw_held <= rst_ni && awvalid_i && !awready_o;
    f_w_held  <= rst_ni && wvalid_i && !wready_o;
    f_ar_held <= rst_ni && arvalid_i && !arready_o;
    f_b_held  <= rst_ni && bvalid_o && !bready_i;
    f_r_held  <= rst_ni && rvalid_o && !rready_i;
    f_awaddr  <= awaddr_i;
    f_araddr  <= araddr_i;
    f_wdata   <= wdata_i;
    f_wstrb   <= wstrb_i;
    f_bresp   <= bresp_o;
    f_rdata   <= rdata_o;
    f_rresp   <= rresp_o;
  end
  // Requests taken and not yet answered, per channel.
  reg [1:0] f_aw_open, f_w_open, f_ar_open;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_aw_open <= 2'd0;
      f_w_open  <= 2'd0;
      f_ar_open <= 2'd0;
    end else begin
      f_aw_open <= f_aw_open + {1'b0, awvalid_i && awready_o} - {1'b0, bvalid_o && bready_i};
      f_w_open  <= f_w_open + {1'b0, wvalid_i && wready_o} - {1'b0, bvalid_o && bready_i};
      f_ar_open <= f_ar_open + {1'b0, arvalid_i && arready_o} - {1'b0, rvalid_o && rready_i};
    end
  end
  always @(*) begin
    if (f_past && rst_ni) begin
      if (f_aw_held) assume (awvalid_i && awaddr_i == f_awaddr);
      if (f_w_held) assume (wvalid_i && wdata_i == f_wdata && wstrb_i == f_wstrb);
      if (f_ar_held) assume (arvalid_i && araddr_i == f_araddr);
      if (f_b_held) begin
        assert (bvalid_o);
        assert (bresp_o == f_bresp);
      end
      if (f_r_held) begin
        assert (rvalid_o);
        assert (rdata_o == f_rdata && rresp_o == f_rresp);
      end
    end
    if (!rst_ni) begin
      assert (!bvalid_o);
      assert (!rvalid_o);
    end else begin
      // What the port holds is exactly what is open: no request lost, none answered twice,
      // no response without a request.
      assert (f_aw_open == {1'b0, aw_full_q} + {1'b0, b_valid_q});
      assert (f_w_open == {1'b0, w_full_q} + {1'b0, b_valid_q});
      assert (f_ar_open == {1'b0, ar_full_q} + {1'b0, r_valid_q});
      cover (bvalid_o && bready_i && bresp_o == 2'b10);
      cover (rvalid_o && rready_i && rresp_o == 2'b00);
    end
  end
