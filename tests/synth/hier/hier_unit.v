// A unit: two multipliers of one width, one of another, a delay line, a RAM, and logic of its
// own (an adder chain, a comparison and a wide multiplexer).
module hier_unit #(
  parameter integer W = 16
) (
  input  wire           clk_i,
  input  wire [W-1:0]   a_i,
  input  wire [W-1:0]   b_i,
  input  wire [3:0]     sel_i,
  output reg  [2*W+1:0] y_o,
  output reg            gt_o
);
  wire [2*W-1:0] p0, p1;
  wire [2*W+1:0] p2;
  wire [W-1:0]   a_d, r;
  hier_mul #(.AW(W), .BW(W)) u_m0 (.clk_i(clk_i), .a_i(a_i), .b_i(b_i), .p_o(p0));
  hier_mul #(.AW(W), .BW(W)) u_m1 (.clk_i(clk_i), .a_i(b_i), .b_i(a_d), .p_o(p1));
  hier_mul #(.AW(W + 1), .BW(W + 1)) u_m2 (.clk_i(clk_i), .a_i({1'b0, a_d}), .b_i({1'b1, r}),
                                           .p_o(p2));
  hier_delay #(.W(W), .D(W)) u_d (.clk_i(clk_i), .d_i(a_i), .q_o(a_d));
  hier_ram #(.W(W), .AW(5)) u_r (.clk_i(clk_i), .we_i(sel_i[0]), .wa_i(a_i[4:0]), .wd_i(b_i),
                                 .ra_i(b_i[4:0]), .rd_o(r));
  reg [W-1:0] m;
  always @(*) begin
    case (sel_i)
      4'd0: m = a_i;  4'd1: m = b_i;  4'd2: m = a_d;  4'd3: m = r;
      4'd4: m = a_i ^ b_i;  4'd5: m = a_i & r;  4'd6: m = a_d | b_i;  4'd7: m = ~r;
      4'd8: m = p0[W-1:0];  4'd9: m = p1[2*W-1:W];  4'd10: m = p2[W:1];  4'd11: m = p0[2*W-1:W];
      default: m = {W{sel_i[1]}};
    endcase
  end
  always @(posedge clk_i) begin
    y_o  <= {2'b00, p0} + {2'b00, p1} + p2 + {{(W+2){1'b0}}, m};
    gt_o <= p0 > p1;
  end
endmodule
