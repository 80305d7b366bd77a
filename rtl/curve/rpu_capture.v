// rpu_capture: the plane-sign capture unit (seed 000 eqs 24–26 in the camera basis), twin of
// rpu::ref::capture_unit. With q = X − h:
//   left  = q·E_left(i)  ≥ 0     right  = q·E_left(i+1) < 0
//   top   = q·E_top(j)   ≥ 0     bottom = q·E_top(j+1)  < 0
//   depth = q·W,  hit = (0 ≤ t ≤ 1) ∧ depth > 0 ∧ all four signs.
// All products are exact (no bits dropped). Pipeline (one operand per cycle, no stall; `tag_i`
// rides along unchanged):
//   1        q = X − h, t in [0, 1]
//   LatM     the fifteen products q_c·E_c        rpu_mul EdgeW × (CoordW+4) signed
//                                                 (rpu_mul_latency.vh; 34 × 28: 4 tiles, 4)
//   1        the five dot products (carry-save + one adder) and the four signs
//   1        depth > 0, the hit
// Latency = LatM + 3 cycles (7 at the defaults).
`default_nettype none
`include "rpu_widths.vh"

module rpu_capture #(
  parameter integer CoordW   = 24,  // position width (12..40)
  parameter integer TFrac    = 24,  // fraction bits of t (8..48)
  parameter integer EdgeFrac = 16,  // fraction bits of edge vectors (8..40), plus 14 guard bits
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer XW     = `RPU_XW(CoordW),              // curve point X
  parameter integer EdgeW  = `RPU_EGW(EdgeFrac),       // Q(4.FE+14)
  parameter integer DepthW = CoordW + 4 + EdgeW + 2   // q·W
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                valid_i,
  input  wire [3*XW-1:0]     x_i,        // {z, y, x}
  input  wire [TFrac+2:0]    t_i,        // Q(3.FT)
  input  wire [3*CoordW-1:0] eye_i,
  input  wire [3*EdgeW-1:0]  e_left_i,
  input  wire [3*EdgeW-1:0]  e_right_i,
  input  wire [3*EdgeW-1:0]  e_top_i,
  input  wire [3*EdgeW-1:0]  e_bottom_i,
  input  wire [3*EdgeW-1:0]  w_i,
  input  wire [TagW-1:0]     tag_i,
  output wire                valid_o,
  output wire                hit_o,
  output wire                t_in_range_o,
  output wire [3:0]          signs_o,    // {bottom, top, right, left}
  output wire [DepthW-1:0]   depth_o,
  output wire [TagW-1:0]     tag_o
);
  localparam integer QW = CoordW + 4;  // X − h
  localparam integer PW = QW + EdgeW;  // one product
  localparam integer SW = PW + 2;      // a sum of three

`include "rpu_mul_latency.vh"
  localparam integer LatM = `RPU_MUL_LAT(EdgeW, QW, 1);
  // The unit's latency (what the enclosing units count on).
  localparam integer Latency = LatM + 3;

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_capture: CoordW must be in 12..40");
    if (EdgeFrac < 8 || EdgeFrac > 40) $fatal(1, "rpu_capture: EdgeFrac must be in 8..40");
  end

  // ---- stage 1: q = X − h, t in [0, 2^FT] ----
  reg              valid_q1;
  reg [3*QW-1:0]   q_q1;
  reg              t_ok_q1;
  reg [5*3*EdgeW-1:0] e_q1;
  reg [TagW-1:0]   tag_q1;
  wire signed [TFrac+2:0] t_s = t_i;
  wire signed [TFrac+2:0] one = {{2{1'b0}}, 1'b1, {TFrac{1'b0}}};
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_q
      wire signed [XW-1:0]     xc = x_i[c*XW +: XW];
      wire signed [CoordW-1:0] hc = eye_i[c*CoordW +: CoordW];
      wire signed [QW-1:0]     qc = {{(QW-XW){xc[XW-1]}}, xc} - {{(QW-CoordW){hc[CoordW-1]}}, hc};
      always @(posedge clk_i) q_q1[c*QW +: QW] <= qc;
    end
  endgenerate
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q1 <= 1'b0;
    else         valid_q1 <= valid_i;
  end
  always @(posedge clk_i) begin
    t_ok_q1 <= (t_s >= 0) && (t_s <= one);
    e_q1    <= {w_i, e_bottom_i, e_top_i, e_right_i, e_left_i};
    tag_q1  <= tag_i;
  end

  // ---- the fifteen exact products q_c · E_c (rpu_mul); t_ok and the tag in one's tag ----
  // Vector v (0 left, 1 right, 2 top, 3 bottom, 4 W), component c.
  wire [15*PW-1:0] prod;
  wire             m_valid;
  wire [TagW:0]    m_tag;
  genvar v;
  generate
    for (v = 0; v < 5; v = v + 1) begin : g_vec
      for (c = 0; c < 3; c = c + 1) begin : g_comp
        wire            mv;
        wire [TagW:0]   mt;
        rpu_mul #(.AW(EdgeW), .BW(QW), .Signed(1), .TagW(TagW + 1)) u_mul (
          .clk_i, .rst_ni, .valid_i(valid_q1), .a_i(e_q1[(3*v + c)*EdgeW +: EdgeW]),
          .b_i(q_q1[c*QW +: QW]), .tag_i({tag_q1, t_ok_q1}),
          .valid_o(mv), .p_o(prod[(3*v + c)*PW +: PW]), .tag_o(mt));
        if (v == 0 && c == 0) begin : g_ctl
          assign m_valid = mv;
          assign m_tag   = mt;
        end else begin : g_no_ctl
          wire unused_ctl = ^{mv, mt};
        end
      end
    end
  endgenerate

  // ---- the dot products (a sum of three as one carry-save step and one adder), their signs ----
  // a + b + c = (a ^ b ^ c) + 2·maj(a, b, c), exact modulo 2^SW (the sum fits SW bits).
  wire signed [SW-1:0] dots [0:4];
  generate
    for (v = 0; v < 5; v = v + 1) begin : g_dot
      wire signed [PW-1:0] p0 = prod[(3*v + 0)*PW +: PW];
      wire signed [PW-1:0] p1 = prod[(3*v + 1)*PW +: PW];
      wire signed [PW-1:0] p2 = prod[(3*v + 2)*PW +: PW];
      wire [SW-1:0] x0 = {{2{p0[PW-1]}}, p0};
      wire [SW-1:0] x1 = {{2{p1[PW-1]}}, p1};
      wire [SW-1:0] x2 = {{2{p2[PW-1]}}, p2};
      wire [SW-1:0] cs_s = x0 ^ x1 ^ x2;
      wire [SW-2:0] cs_c = (x0[SW-2:0] & x1[SW-2:0]) | (x0[SW-2:0] & x2[SW-2:0]) |
                           (x1[SW-2:0] & x2[SW-2:0]);
      assign dots[v] = cs_s + {cs_c, 1'b0};
    end
  endgenerate

  reg              valid_q3;
  reg [3:0]        neg_q3;     // the signs of {bottom, top, right, left}
  reg [SW-1:0]     dot_w_q3;   // q·W
  reg              t_ok_q3;
  reg [TagW-1:0]   tag_q3;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q3 <= 1'b0;
    else         valid_q3 <= m_valid;
  end
  always @(posedge clk_i) begin
    neg_q3   <= {dots[3][SW-1], dots[2][SW-1], dots[1][SW-1], dots[0][SW-1]};
    dot_w_q3 <= dots[4];
    t_ok_q3  <= m_tag[0];
    tag_q3   <= m_tag[TagW:1];
  end

  // ---- the hit: 0 <= t <= 1, depth > 0 and all four signs ----
  wire [3:0] signs_q3 = {neg_q3[3], ~neg_q3[2], neg_q3[1], ~neg_q3[0]};  // {bottom < 0, top >= 0,
                                                                          //  right < 0, left >= 0}
  reg              valid_q4;
  reg              hit_q4, t_ok_q4;
  reg [3:0]        signs_q4;
  reg [DepthW-1:0] depth_q4;
  reg [TagW-1:0]   tag_q4;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q4 <= 1'b0;
    else         valid_q4 <= valid_q3;
  end
  always @(posedge clk_i) begin
    signs_q4 <= signs_q3;
    t_ok_q4  <= t_ok_q3;
    hit_q4   <= t_ok_q3 && ~dot_w_q3[SW-1] && (|dot_w_q3) && (&signs_q3);
    depth_q4 <= dot_w_q3[DepthW-1:0];
  end
  // Loaded only with a valid operand, so the tag leaves a flip-flop, not a shift-register LUT.
  always @(posedge clk_i) if (valid_q3) tag_q4 <= tag_q3;

  assign valid_o      = valid_q4;
  assign hit_o        = hit_q4;
  assign t_in_range_o = t_ok_q4;
  assign signs_o      = signs_q4;
  assign depth_o      = depth_q4;
  assign tag_o        = tag_q4;
endmodule

`default_nettype wire
