// rpu_mul_vec: Count exact products p_k = a_k × b_k in lockstep, one rpu_mul per lane (twin
// rpu::ref::mul_unit per lane). Lane k's operands are a_i[k*AW +: AW] and b_i[k*BW +: BW]; with
// ShareA = 1 (ShareB = 1) every lane takes the same a_i[AW-1:0] (b_i[BW-1:0]). One valid and one tag travel with lane
// 0; the other lanes' copies are not used. A shared block, verified through the units that use
// it. Latency: `RPU_MUL_LAT(AW, BW, Signed), or Latency when larger (rpu_mul).
`default_nettype none

module rpu_mul_vec #(
  parameter integer Count   = 3,   // lanes (>= 1)
  parameter integer AW      = 25,  // width of each a (2..126)
  parameter integer BW      = 18,  // width of each b (2..126), AW + BW <= 128
  parameter integer Signed  = 1,   // 1: two's complement; 0: unsigned
  parameter integer ShareA  = 0,   // 1: one a for every lane
  parameter integer ShareB  = 0,   // 1: one b for every lane
  parameter integer TagW    = 1,   // side-band bits (>= 1)
  parameter integer Latency = 0,   // 0: the natural latency; more: extra output registers
  // Derived (do not override).
  parameter integer PW      = AW + BW,
  parameter integer AInW    = ShareA != 0 ? AW : Count * AW,
  parameter integer BInW    = ShareB != 0 ? BW : Count * BW
) (
  input  wire               clk_i,
  input  wire               rst_ni,
  input  wire               valid_i,
  input  wire [AInW-1:0]    a_i,
  input  wire [BInW-1:0]    b_i,
  input  wire [TagW-1:0]    tag_i,
  output wire               valid_o,
  output wire [Count*PW-1:0] p_o,
  output wire [TagW-1:0]    tag_o
);
  initial begin
    if (Count < 1) $fatal(1, "rpu_mul_vec: Count must be >= 1");
  end

  genvar k;
  generate
    for (k = 0; k < Count; k = k + 1) begin : g_lane
      wire [AW-1:0] ak = a_i[(ShareA != 0 ? 0 : k) * AW +: AW];
      wire [BW-1:0] bk = b_i[(ShareB != 0 ? 0 : k) * BW +: BW];
      if (k == 0) begin : g_ctl
        rpu_mul #(.AW(AW), .BW(BW), .Signed(Signed), .TagW(TagW), .Latency(Latency)) u_mul (
          .clk_i, .rst_ni, .valid_i, .a_i(ak), .b_i(bk), .tag_i,
          .valid_o, .p_o(p_o[k*PW +: PW]), .tag_o);
      end else begin : g_data
        wire lane_valid, lane_tag;
        rpu_mul #(.AW(AW), .BW(BW), .Signed(Signed), .TagW(1), .Latency(Latency)) u_mul (
          .clk_i, .rst_ni, .valid_i, .a_i(ak), .b_i(bk), .tag_i(1'b0),
          .valid_o(lane_valid), .p_o(p_o[k*PW +: PW]), .tag_o(lane_tag));
        wire unused_lane = ^{lane_valid, lane_tag};
      end
    end
  endgenerate
endmodule

`default_nettype wire
