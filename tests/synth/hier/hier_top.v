// The top: three units of width 12 (one derived module, three instances), one of width 20, and
// logic of its own.
module hier_top (
  input  wire        clk_i,
  input  wire [19:0] a_i,
  input  wire [19:0] b_i,
  input  wire [3:0]  sel_i,
  output reg  [41:0] y_o,
  output reg  [3:0]  gt_o
);
  wire [25:0] y0, y1, y2;
  wire [41:0] y3;
  wire [3:0]  gt;
  hier_unit #(.W(12)) u0 (.clk_i(clk_i), .a_i(a_i[11:0]), .b_i(b_i[11:0]), .sel_i(sel_i),
                          .y_o(y0), .gt_o(gt[0]));
  hier_unit #(.W(12)) u1 (.clk_i(clk_i), .a_i(a_i[19:8]), .b_i(b_i[19:8]), .sel_i(sel_i),
                          .y_o(y1), .gt_o(gt[1]));
  hier_unit #(.W(12)) u2 (.clk_i(clk_i), .a_i(a_i[15:4]), .b_i(b_i[11:0]), .sel_i(~sel_i),
                          .y_o(y2), .gt_o(gt[2]));
  hier_unit #(.W(20)) u3 (.clk_i(clk_i), .a_i(a_i), .b_i(b_i), .sel_i(sel_i), .y_o(y3),
                          .gt_o(gt[3]));
  always @(posedge clk_i) begin
    y_o  <= y3 ^ {16'd0, y0} ^ {16'd0, y1 + y2};
    gt_o <= gt;
  end
endmodule
