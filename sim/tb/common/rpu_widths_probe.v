// rpu_widths_probe: the width formulas of rtl/common/rpu_widths.vh evaluated by the Verilog
// compiler at run-time inputs, for tb_rpu_widths (sim/tb/common/tb_rpu_widths.cpp), which checks
// each against its C++ twin (ref/model/hw_params.h) over the parameters' whole ranges. A macro is
// text: applied to a 32-bit input it gives the value a module's parameter declaration gets.
// Simulation only (not in rtl/rpu.f).
`default_nettype none
`include "rpu_widths.vh"

module rpu_widths_probe (
  input  wire [31:0] coord_w_i,
  input  wire [31:0] dir_frac_i,
  input  wire [31:0] t_frac_i,
  input  wire [31:0] unit_frac_i,
  input  wire [31:0] edge_frac_i,
  input  wire [31:0] surf_w_i,
  input  wire [31:0] n1_i,
  input  wire [31:0] k_i,
  input  wire [31:0] ind_i,
  // One output per formula, in rpu_widths.vh's order.
  output wire [31:0] tw_o,
  output wire [31:0] dw_o,
  output wire [31:0] uw_o,
  output wire [31:0] hw_o,
  output wire [31:0] l2w_o,
  output wire [31:0] r2w_o,
  output wire [31:0] xw_o,
  output wire [31:0] prw_o,
  output wire [31:0] vw_o,
  output wire [31:0] vhatw_o,
  output wire [31:0] vgw_o,
  output wire [31:0] egw_o,
  output wire [31:0] gradw_o,
  output wire [31:0] md2w_o,
  output wire [31:0] depthw_o,
  output wire [31:0] gsw_o,
  output wire [31:0] gdw_o,
  output wire [31:0] sdw_o,
  output wire [31:0] mdfrac_o,
  output wire [31:0] cxw_o,
  output wire [31:0] ctw_o,
  output wire [31:0] cww_o,
  output wire [31:0] caw_o,
  output wire [31:0] fradw_o,
  output wire [31:0] fgdw_o,
  output wire [31:0] frdw_o,
  output wire [31:0] slanes_o
);
  assign tw_o     = `RPU_TW(t_frac_i);
  assign dw_o     = `RPU_DW(coord_w_i);
  assign uw_o     = `RPU_UW(unit_frac_i);
  assign hw_o     = `RPU_HW(coord_w_i);
  assign l2w_o    = `RPU_L2W(coord_w_i);
  assign r2w_o    = `RPU_R2W(coord_w_i);
  assign xw_o     = `RPU_XW(coord_w_i);
  assign prw_o    = `RPU_PRW(coord_w_i);
  assign vw_o     = `RPU_VW(dir_frac_i);
  assign vhatw_o  = `RPU_VHATW(dir_frac_i);
  assign vgw_o    = `RPU_VGW(dir_frac_i);
  assign egw_o    = `RPU_EGW(edge_frac_i);
  assign gradw_o  = `RPU_GRADW(coord_w_i);
  assign md2w_o   = `RPU_MD2W(coord_w_i);
  assign depthw_o = `RPU_DEPTHW(coord_w_i, edge_frac_i);
  assign gsw_o    = `RPU_GSW(coord_w_i, t_frac_i);
  assign gdw_o    = `RPU_GDW(coord_w_i, t_frac_i, unit_frac_i);
  assign sdw_o    = `RPU_SDW(surf_w_i);
  assign mdfrac_o = `RPU_MDFRAC(n1_i, k_i);
  assign cxw_o    = `RPU_CXW;
  assign ctw_o    = `RPU_CTW;
  assign cww_o    = `RPU_CWW;
  assign caw_o    = `RPU_CAW;
  assign fradw_o  = `RPU_FRADW;
  assign fgdw_o   = `RPU_FGDW;
  assign frdw_o   = `RPU_FRDW;
  assign slanes_o = `RPU_SLANES(n1_i, ind_i);
endmodule

`default_nettype wire
