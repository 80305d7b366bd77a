// rpu_axil_port: an AXI4-Lite slave (32-bit data) in front of a register file with one write and
// one read access port. AW and W are taken independently into one-entry registers (AWREADY,
// WREADY: the register is empty); when both are held and no write response is pending, the
// write goes to the register file (wr_o, one cycle; its response wr_resp_i is taken with it)
// and BVALID rises the next cycle; wr_hold_i keeps it waiting (a soft reset in progress). AR is taken into a register (ARREADY: empty); when no read
// response is pending the read goes to the register file (rd_o; rd_data_i and rd_resp_i from
// the registered address) and RVALID rises the next cycle. Every output is a flip-flop or a
// register's emptiness, so B and R hold still until taken; one response per request, none
// without one (proved: scripts/formal.sh axi). AWPROT and ARPROT are not used.
`default_nettype none

module rpu_axil_port #(
  parameter integer AddrW = 12  // byte address bits (>= 3)
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             wr_hold_i,  // hold a write (it goes to the register file after)
  // AXI4-Lite slave
  input  wire [AddrW-1:0] awaddr_i,
  input  wire             awvalid_i,
  output wire             awready_o,
  input  wire [31:0]      wdata_i,
  input  wire [3:0]       wstrb_i,
  input  wire             wvalid_i,
  output wire             wready_o,
  output wire [1:0]       bresp_o,
  output wire             bvalid_o,
  input  wire             bready_i,
  input  wire [AddrW-1:0] araddr_i,
  input  wire             arvalid_i,
  output wire             arready_o,
  output wire [31:0]      rdata_o,
  output wire [1:0]       rresp_o,
  output wire             rvalid_o,
  input  wire             rready_i,
  // register file
  output wire             wr_o,       // a write this cycle
  output wire [AddrW-1:0] wr_addr_o,
  output wire [31:0]      wr_data_o,
  output wire [3:0]       wr_strb_o,
  input  wire [1:0]       wr_resp_i,  // 0 OKAY, 2 SLVERR, 3 DECERR
  output wire             rd_o,       // a read this cycle
  output wire [AddrW-1:0] rd_addr_o,
  input  wire [31:0]      rd_data_i,
  input  wire [1:0]       rd_resp_i
);
  reg             aw_full_q, w_full_q, b_valid_q, ar_full_q, r_valid_q;
  reg [AddrW-1:0] aw_addr_q, ar_addr_q;
  reg [31:0]      w_data_q, r_data_q;
  reg [3:0]       w_strb_q;
  reg [1:0]       b_resp_q, r_resp_q;

  assign awready_o = !aw_full_q;
  assign wready_o  = !w_full_q;
  assign arready_o = !ar_full_q;
  assign bvalid_o  = b_valid_q;
  assign bresp_o   = b_resp_q;
  assign rvalid_o  = r_valid_q;
  assign rdata_o   = r_data_q;
  assign rresp_o   = r_resp_q;

  assign wr_o      = aw_full_q && w_full_q && !b_valid_q && !wr_hold_i;
  assign wr_addr_o = aw_addr_q;
  assign wr_data_o = w_data_q;
  assign wr_strb_o = w_strb_q;
  assign rd_o      = ar_full_q && !r_valid_q;
  assign rd_addr_o = ar_addr_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      aw_full_q <= 1'b0;
      w_full_q  <= 1'b0;
      b_valid_q <= 1'b0;
      ar_full_q <= 1'b0;
      r_valid_q <= 1'b0;
    end else begin
      if (wr_o) begin
        aw_full_q <= 1'b0;
        w_full_q  <= 1'b0;
        b_valid_q <= 1'b1;
      end else begin
        if (awvalid_i && !aw_full_q) aw_full_q <= 1'b1;
        if (wvalid_i && !w_full_q) w_full_q <= 1'b1;
        if (b_valid_q && bready_i) b_valid_q <= 1'b0;
      end
      if (rd_o) begin
        ar_full_q <= 1'b0;
        r_valid_q <= 1'b1;
      end else begin
        if (arvalid_i && !ar_full_q) ar_full_q <= 1'b1;
        if (r_valid_q && rready_i) r_valid_q <= 1'b0;
      end
    end
  end
  always @(posedge clk_i) begin
    if (awvalid_i && !aw_full_q) aw_addr_q <= awaddr_i;
    if (wvalid_i && !w_full_q) begin
      w_data_q <= wdata_i;
      w_strb_q <= wstrb_i;
    end
    if (arvalid_i && !ar_full_q) ar_addr_q <= araddr_i;
    if (wr_o) b_resp_q <= wr_resp_i;
    if (rd_o) begin
      r_data_q <= rd_data_i;
      r_resp_q <= rd_resp_i;
    end
  end

`ifdef FORMAL
`include "rpu_axil_port_props.vh"
`endif
endmodule

`default_nettype wire
