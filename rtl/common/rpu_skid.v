// rpu_skid: a valid/ready register slice with a spill slot (Forencich's axis_register SKID, PULP's
// spill_register): an output register plus one extra slot, so valid_o, data_o and ready_o all
// come from flip-flops and no combinational path runs from ready_i to ready_o. Throughput one
// word per cycle while the consumer keeps up; ready_o is low only while the spill slot is full.
// Words leave in arrival order, each exactly once. A shared block, verified through the units
// that use it (rpu_top's work-item input and its formal properties).
`default_nettype none

module rpu_skid #(
  parameter integer W = 1  // data width (>= 1)
) (
  input  wire         clk_i,
  input  wire         rst_ni,
  input  wire         valid_i,
  output wire         ready_o,
  input  wire [W-1:0] data_i,
  output wire         valid_o,
  input  wire         ready_i,
  output wire [W-1:0] data_o
`ifdef FORMAL
  ,
  // Formal only (rpu_top's invariants): the words held (the spill slot is only full behind a
  // full output register) and the words, {spill, output} (the output register's is the older).
  output wire [1:0]     f_count_o,
  output wire [2*W-1:0] f_entries_o
`endif
);
  initial begin
    if (W < 1) $fatal(1, "rpu_skid: W must be >= 1");
  end

  reg         out_valid_q, spill_valid_q;
  reg [W-1:0] out_q, spill_q;
  wire        take_in  = valid_i && !spill_valid_q;
  wire        out_free = ready_i || !out_valid_q;  // the output register can load this cycle

  assign ready_o = !spill_valid_q;
  assign valid_o = out_valid_q;
  assign data_o  = out_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_valid_q   <= 1'b0;
      spill_valid_q <= 1'b0;
    end else if (spill_valid_q) begin
      // Nothing is taken in: the spill slot drains into the output register.
      if (ready_i) begin
        out_valid_q   <= 1'b1;
        spill_valid_q <= 1'b0;
      end
    end else if (out_free) begin
      out_valid_q <= take_in;
    end else if (take_in) begin
      spill_valid_q <= 1'b1;  // the output is held: park the new word
    end
  end
  always @(posedge clk_i) begin
    if (spill_valid_q) begin
      if (ready_i) out_q <= spill_q;
    end else if (out_free) begin
      if (take_in) out_q <= data_i;
    end else if (take_in) begin
      spill_q <= data_i;
    end
  end
`ifdef FORMAL
  assign f_count_o   = {1'b0, out_valid_q} + {1'b0, spill_valid_q};
  assign f_entries_o = {spill_q, out_q};
  always @(*) if (rst_ni) assert(!spill_valid_q || out_valid_q);
`endif
endmodule

`default_nettype wire
