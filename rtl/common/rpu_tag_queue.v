// rpu_tag_queue: where a unit with a fixed latency keeps its caller's tag (the context the unit
// passes through untouched). A narrow tag rides the unit's stages. A tag of RPU_TAGQ_MINW bits
// (rpu_widths.vh: 32) or more waits in a queue instead (rpu_fifo: distributed or block RAM, as
// Yosys maps its depth), written as the item enters and read as it leaves: the unit is in order and every item takes
// exactly Latency cycles, so the queue's head is always the leaving item's tag. The stages then
// carry one constant bit, not TagW bits through every register, product and root of the unit.
// A shared block, verified through the units that use it (their testbenches check every tag).
//
// The unit wires it as: ptag_o → its stages (in place of tag_i), what its stages return → ptag_i,
// tag_o → its own tag_o. The queue holds 2^⌈log2 Latency⌉ entries besides its output register:
// at most Latency items are between the write and the read. A write to a full queue or a read
// of an empty one stops a simulation (the unit's Latency parameter is wrong).
`default_nettype none
`include "rpu_widths.vh"

module rpu_tag_queue #(
  parameter integer TagW    = 1,   // the caller's tag (>= 1)
  parameter integer Latency = 2,   // the unit's latency, valid_i to out_valid_i, or a bound
                                   // above it (2..65536)
  // Derived (do not override): what the unit's stages carry (rpu_widths.vh).
  parameter integer PTagW   = `RPU_PTAGW(TagW)
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             valid_i,      // an item enters the unit
  input  wire [TagW-1:0]  tag_i,
  output wire [PTagW-1:0] ptag_o,       // into the unit's stages
  input  wire             out_valid_i,  // an item leaves the unit
  input  wire [PTagW-1:0] ptag_i,       // out of the unit's stages
  output wire [TagW-1:0]  tag_o
);
  initial begin
    if (TagW < 1) $fatal(1, "rpu_tag_queue: TagW must be >= 1");
    if (Latency < 2 || Latency > 65536) $fatal(1, "rpu_tag_queue: Latency must be in 2..65536");
    if (PTagW != `RPU_PTAGW(TagW))
      $fatal(1, "rpu_tag_queue: derived parameters must not be overridden");
  end

  generate
    if (PTagW != TagW) begin : g_queue
      localparam integer Log2Depth = $clog2(Latency);
      wire wr_ready, rd_valid;
      rpu_fifo #(.Width(TagW), .Log2Depth(Log2Depth)) u_fifo (
        .clk_i, .rst_ni, .wr_valid_i(valid_i), .wr_ready_o(wr_ready), .wr_data_i(tag_i),
        .rd_valid_o(rd_valid), .rd_ready_i(out_valid_i), .rd_data_o(tag_o));
      assign ptag_o = 1'b0;
`ifndef SYNTHESIS
`ifndef FORMAL
      // Checked from the first reset on (before it, the valid bits hold arbitrary values).
      reg seen_reset = 1'b0;
      always @(posedge clk_i or negedge rst_ni) if (!rst_ni) seen_reset <= 1'b1;
      always @(posedge clk_i) begin
        if (seen_reset && valid_i && !wr_ready)
          $fatal(1, "rpu_tag_queue: the queue of %0d entries is full (Latency %0d)",
                 1 << Log2Depth, Latency);
        if (seen_reset && out_valid_i && !rd_valid)
          $fatal(1, "rpu_tag_queue: no tag for a leaving item (Latency %0d)", Latency);
      end
`endif
`endif
      wire unused = ^{ptag_i, wr_ready, rd_valid};
    end else begin : g_ride
      assign ptag_o = tag_i;
      assign tag_o  = ptag_i;
      wire unused = ^{clk_i, rst_ni, valid_i, out_valid_i};
    end
  endgenerate
endmodule

`default_nettype wire
