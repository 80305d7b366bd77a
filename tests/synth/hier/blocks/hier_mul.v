// A registered multiplier (one DSP48E1 when AW <= 25 and BW <= 18).
module hier_mul #(
  parameter integer AW = 16,
  parameter integer BW = 16
) (
  input  wire                 clk_i,
  input  wire [AW-1:0]        a_i,
  input  wire [BW-1:0]        b_i,
  output reg  [AW+BW-1:0]     p_o
);
  reg [AW-1:0] a_q;
  reg [BW-1:0] b_q;
  always @(posedge clk_i) begin
    a_q <= a_i;
    b_q <= b_i;
    p_o <= a_q * b_q;
  end
endmodule
