// A delay line of D cycles (shift registers: SRL16E/SRLC32E).
module hier_delay #(
  parameter integer W = 8,
  parameter integer D = 12
) (
  input  wire         clk_i,
  input  wire [W-1:0] d_i,
  output wire [W-1:0] q_o
);
  reg [W-1:0] sr [0:D-1];
  integer k;
  always @(posedge clk_i) begin
    sr[0] <= d_i;
    for (k = 1; k < D; k = k + 1) sr[k] <= sr[k-1];
  end
  assign q_o = sr[D-1];
endmodule
