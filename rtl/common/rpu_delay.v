// rpu_delay: a D-cycle delay line for context that rides beside a unit's arithmetic (a shared
// block, verified through the units that use it). The first D − 1 stages are plain registers (Yosys packs
// them into shift-register LUTs); the last is loaded only with a valid item, a clock enable the
// others lack, so it stays a flip-flop and the logic it feeds does not start at a slow SRL
// output. d_o holds the last valid item's value while no item arrives. valid_i is the item's
// valid bit at the line's input; its copy inside the line is not reset (it only gates data).
`default_nettype none

module rpu_delay #(
  parameter integer W = 1,  // width (>= 1)
  parameter integer D = 1   // delay in cycles (>= 0; 0 is a wire)
) (
  input  wire         clk_i,
  input  wire         valid_i,
  input  wire [W-1:0] d_i,
  output wire [W-1:0] d_o
);
  initial begin
    if (W < 1) $fatal(1, "rpu_delay: W must be >= 1");
    if (D < 0) $fatal(1, "rpu_delay: D must be >= 0");
  end

  generate
    if (D == 0) begin : g_wire
      assign d_o = d_i;
      wire unused_wire = ^{clk_i, valid_i};
    end else if (D == 1) begin : g_one
      reg [W-1:0] q;
      always @(posedge clk_i) if (valid_i) q <= d_i;
      assign d_o = q;
    end else begin : g_line
      reg [(D-1)*(W+1)-1:0] line_q;  // {valid, data} per stage, oldest at the top
      reg [W-1:0]           q;
      if (D == 2) begin : g_two
        always @(posedge clk_i) line_q <= {valid_i, d_i};
      end else begin : g_more
        always @(posedge clk_i) line_q <= {line_q[(D-2)*(W+1)-1:0], valid_i, d_i};
      end
      wire [W:0] last = line_q[(D-1)*(W+1)-1 -: W+1];
      always @(posedge clk_i) if (last[W]) q <= last[W-1:0];
      assign d_o = q;
    end
  endgenerate
endmodule

`default_nettype wire
