// A module that breaks the RTL house rules (fixture of the CTest rtl_style_catches).
module bad #(parameter integer W = 16, parameter integer T = 4) (
  input  wire [W-1:0] x_i,
  output wire [3:0]   y_o
);
  /* verilator lint_off UNUSEDSIGNAL */
  assign y_o = x_i[W-T-1 -: 4];
endmodule
