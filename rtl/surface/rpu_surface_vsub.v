// rpu_surface_vsub: Count exact differences d_k = a_k − b_k of InW-bit two's complement operands,
// each sign-extended to InW + 1 bits first (combinational; a shared block of the surface path,
// verified through the units that use it). Lane k is a_i[k*InW +: InW], b_i[k*InW +: InW],
// d_o[k*(InW+1) +: InW + 1]: the vectors B − A, X − origin, X − h of the surface units.
`default_nettype none

module rpu_surface_vsub #(
  parameter integer Count = 3,   // lanes (>= 1)
  parameter integer InW   = 24   // operand width, signed (>= 1); the differences are InW + 1 bits
) (
  input  wire [Count*InW-1:0]     a_i,
  input  wire [Count*InW-1:0]     b_i,
  output wire [Count*(InW+1)-1:0] d_o
);
  initial begin
    if (Count < 1) $fatal(1, "rpu_surface_vsub: Count must be >= 1");
    if (InW < 1) $fatal(1, "rpu_surface_vsub: InW must be >= 1");
  end

  genvar k;
  generate
    for (k = 0; k < Count; k = k + 1) begin : g_lane
      wire [InW-1:0] a = a_i[k*InW +: InW];
      wire [InW-1:0] b = b_i[k*InW +: InW];
      assign d_o[k*(InW+1) +: InW + 1] = {a[InW-1], a} - {b[InW-1], b};
    end
  endgenerate
endmodule

`default_nettype wire
