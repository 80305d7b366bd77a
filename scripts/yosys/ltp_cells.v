// Timing-graph stand-ins used only by scripts/yosys_report.sh for its longest-path count (`ltp`),
// after synthesis and after `stat`; never part of a synthesised design.
//
// `ltp` sees an edge from every input bit of a cell to every output bit, and takes a port's
// direction from the module of the cell's type: a port the module does not declare is invisible
// to it. A DSP48E1 whose A and/or B operand is registered inside the DSP (AREG/BREG >= 1, how
// synth_xilinx absorbs operand registers) and whose M and P registers are off is retyped to one
// of these boxes, which leave out the registered operand's ports: the paths into that operand
// end there (as at a flip-flop's D input), and the paths from its internal register through the
// multiplier to P/PCOUT still start at the DSP, counting it as one level. (A DSP with M or P
// registered is a plain path break; see the script.) The C input, cascades and control inputs
// stay combinational.
(* blackbox *)
module RPU_LTP_DSP48E1_AB (  // A and B registered
  input  wire [47:0] C,
  input  wire [47:0] PCIN,
  input  wire        CARRYCASCIN,
  input  wire        MULTSIGNIN,
  input  wire        CARRYIN,
  input  wire [2:0]  CARRYINSEL,
  input  wire [3:0]  ALUMODE,
  input  wire [6:0]  OPMODE,
  output wire [47:0] P,
  output wire [47:0] PCOUT,
  output wire        CARRYCASCOUT,
  output wire        MULTSIGNOUT,
  output wire [3:0]  CARRYOUT,
  output wire        OVERFLOW,
  output wire        UNDERFLOW,
  output wire        PATTERNDETECT,
  output wire        PATTERNBDETECT
);
endmodule

(* blackbox *)
module RPU_LTP_DSP48E1_A (  // A registered, B combinational
  input  wire [17:0] B,
  input  wire [17:0] BCIN,
  input  wire [47:0] C,
  input  wire [47:0] PCIN,
  input  wire        CARRYCASCIN,
  input  wire        MULTSIGNIN,
  input  wire        CARRYIN,
  input  wire [2:0]  CARRYINSEL,
  input  wire [3:0]  ALUMODE,
  input  wire [6:0]  OPMODE,
  output wire [17:0] BCOUT,
  output wire [47:0] P,
  output wire [47:0] PCOUT,
  output wire        CARRYCASCOUT,
  output wire        MULTSIGNOUT,
  output wire [3:0]  CARRYOUT,
  output wire        OVERFLOW,
  output wire        UNDERFLOW,
  output wire        PATTERNDETECT,
  output wire        PATTERNBDETECT
);
endmodule

(* blackbox *)
module RPU_LTP_DSP48E1_B (  // B registered, A (and the pre-adder's D) combinational
  input  wire [29:0] A,
  input  wire [29:0] ACIN,
  input  wire [24:0] D,
  input  wire [4:0]  INMODE,
  input  wire [47:0] C,
  input  wire [47:0] PCIN,
  input  wire        CARRYCASCIN,
  input  wire        MULTSIGNIN,
  input  wire        CARRYIN,
  input  wire [2:0]  CARRYINSEL,
  input  wire [3:0]  ALUMODE,
  input  wire [6:0]  OPMODE,
  output wire [29:0] ACOUT,
  output wire [47:0] P,
  output wire [47:0] PCOUT,
  output wire        CARRYCASCOUT,
  output wire        MULTSIGNOUT,
  output wire [3:0]  CARRYOUT,
  output wire        OVERFLOW,
  output wire        UNDERFLOW,
  output wire        PATTERNDETECT,
  output wire        PATTERNBDETECT
);
endmodule
