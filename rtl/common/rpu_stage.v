// rpu_stage: one pipeline register: the valid bit (reset to 0 by rst_ni) and a W-bit data word
// (not reset) that loads every cycle, or with Hold = 1 only with a valid item (a clock enable:
// the word then holds the last valid item's value and Yosys keeps it a flip-flop rather than a
// shift-register LUT, so the logic it feeds does not start at a slow SRL output). A shared
// block, verified through the units that use it; a unit lists its stage's fields once, as the
// concatenation on d_i and on q_o.
`default_nettype none

module rpu_stage #(
  parameter integer W    = 1,  // data width (>= 1)
  parameter integer Hold = 0   // 1: d loads only with valid_i
) (
  input  wire         clk_i,
  input  wire         rst_ni,
  input  wire         valid_i,
  input  wire [W-1:0] d_i,
  output reg          valid_o,
  output reg  [W-1:0] q_o
);
  initial begin
    if (W < 1) $fatal(1, "rpu_stage: W must be >= 1");
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_o <= 1'b0;
    else         valid_o <= valid_i;
  end
  generate
    if (Hold != 0) begin : g_hold
      always @(posedge clk_i) if (valid_i) q_o <= d_i;
    end else begin : g_load
      always @(posedge clk_i) q_o <= d_i;
    end
  endgenerate
endmodule

`default_nettype wire
