// A small synchronous-write, asynchronous-read RAM (distributed RAM: LUTRAM).
module hier_ram #(
  parameter integer W = 16,
  parameter integer AW = 5
) (
  input  wire          clk_i,
  input  wire          we_i,
  input  wire [AW-1:0] wa_i,
  input  wire [W-1:0]  wd_i,
  input  wire [AW-1:0] ra_i,
  output wire [W-1:0]  rd_o
);
  reg [W-1:0] mem [0:(1<<AW)-1];
  always @(posedge clk_i) if (we_i) mem[wa_i] <= wd_i;
  assign rd_o = mem[ra_i];
endmodule
