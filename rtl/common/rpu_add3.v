// rpu_add3: s = a ± b ± c + Cin modulo 2^W in one carry chain (combinational; a shared block,
// verified through the units that use it): one 3:2 carry-save step (one LUT level) and one
// adder, so a stage that sums three terms still has a single wide carry chain. NegB / NegC invert b / c;
// −b = ~b + 1, so a subtraction asks for one unit of Cin (the carry vector's free low bit takes
// the first, the adder's carry-in the second).
`default_nettype none

module rpu_add3 #(
  parameter integer W    = 8,  // operand and sum width (2..128)
  parameter integer NegB = 0,  // 1: b enters inverted (~b)
  parameter integer NegC = 0,  // 1: c enters inverted (~c)
  parameter integer Cin  = 0   // constant added, 0..2
) (
  input  wire [W-1:0] a_i,
  input  wire [W-1:0] b_i,
  input  wire [W-1:0] c_i,
  output wire [W-1:0] s_o
);
  initial begin
    if (W < 2 || W > 128) $fatal(1, "rpu_add3: W must be in 2..128");
    if (Cin < 0 || Cin > 2) $fatal(1, "rpu_add3: Cin must be in 0..2");
  end

  wire [W-1:0] b     = NegB != 0 ? ~b_i : b_i;
  wire [W-1:0] c     = NegC != 0 ? ~c_i : c_i;
  wire [W-1:0] sum   = a_i ^ b ^ c;
  wire [W-1:0] maj   = (a_i & b) | (a_i & c) | (b & c);
  wire         cin0  = Cin >= 1;
  wire         cin1  = Cin >= 2;
  assign s_o = sum + {maj[W-2:0], cin0} + {{(W - 1){1'b0}}, cin1};
  wire unused_maj = maj[W-1];  // the carry out of the top bit: the sum is modulo 2^W
endmodule

`default_nettype wire
