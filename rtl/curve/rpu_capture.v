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
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_capture #(
  parameter integer CoordW   = 24,  // position width (12..40)
  parameter integer TFrac    = 24,  // fraction bits of t (8..48)
  parameter integer EdgeFrac = 16,  // fraction bits of edge vectors (8..40), plus 14 guard bits
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer XW     = `RPU_XW(CoordW),              // curve point X
  parameter integer EdgeW  = `RPU_EGW(EdgeFrac),       // Q(4.FE+14)
  parameter integer DepthW = `RPU_DEPTHW(CoordW, EdgeFrac) // q·W
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
  wire signed [TFrac+2:0] t_s = t_i;
  wire signed [TFrac+2:0] one = {{2{1'b0}}, 1'b1, {TFrac{1'b0}}};
  wire [3*QW-1:0] q;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_q
      wire signed [XW-1:0]     xc = x_i[c*XW +: XW];
      wire signed [CoordW-1:0] hc = eye_i[c*CoordW +: CoordW];
      assign q[c*QW +: QW] = {{(QW-XW){xc[XW-1]}}, xc} - {{(QW-CoordW){hc[CoordW-1]}}, hc};
    end
  endgenerate
  wire                valid_q1;
  wire [3*QW-1:0]     q_q1;
  wire                t_ok_q1;
  wire [15*EdgeW-1:0] e_q1;  // vector v (0 left, 1 right, 2 top, 3 bottom, 4 W), component c
  wire [TagW-1:0]     tag_q1;
  rpu_stage #(.W(3*QW + 1 + 15*EdgeW + TagW)) u_s1 (
    .clk_i, .rst_ni, .valid_i,
    .d_i({q, (t_s >= 0) && (t_s <= one), w_i, e_bottom_i, e_top_i, e_right_i, e_left_i, tag_i}),
    .valid_o(valid_q1), .q_o({q_q1, t_ok_q1, e_q1, tag_q1}));

  // ---- the fifteen exact products q_c · E_c; t_ok and the tag beside them ----
  wire [15*PW-1:0] prod;
  wire             m_valid;
  wire [TagW:0]    m_tag;
  rpu_mul_vec #(.Count(15), .AW(EdgeW), .BW(QW), .Signed(1), .TagW(TagW + 1)) u_prod (
    .clk_i, .rst_ni, .valid_i(valid_q1), .a_i(e_q1), .b_i({5{q_q1}}), .tag_i({tag_q1, t_ok_q1}),
    .valid_o(m_valid), .p_o(prod), .tag_o(m_tag));

  // ---- the dot products (a sum of three in one carry chain, rpu_add3), their signs ----
  // The sum fits SW bits, so the modulo-2^SW sum is exact.
  wire [5*SW-1:0] dots;
  genvar v;
  generate
    for (v = 0; v < 5; v = v + 1) begin : g_dot
      wire signed [PW-1:0] p0 = prod[(3*v + 0)*PW +: PW];
      wire signed [PW-1:0] p1 = prod[(3*v + 1)*PW +: PW];
      wire signed [PW-1:0] p2 = prod[(3*v + 2)*PW +: PW];
      rpu_add3 #(.W(SW)) u_dot (
        .a_i({{2{p0[PW-1]}}, p0}), .b_i({{2{p1[PW-1]}}, p1}), .c_i({{2{p2[PW-1]}}, p2}),
        .s_o(dots[v*SW +: SW]));
    end
  endgenerate

  wire              valid_q3;
  wire [3:0]        neg_q3;     // the signs of {bottom, top, right, left}
  wire [SW-1:0]     dot_w_q3;   // q·W
  wire              t_ok_q3;
  wire [TagW-1:0]   tag_q3;
  rpu_stage #(.W(4 + SW + 1 + TagW)) u_s3 (
    .clk_i, .rst_ni, .valid_i(m_valid),
    .d_i({dots[4*SW - 1], dots[3*SW - 1], dots[2*SW - 1], dots[SW - 1], dots[4*SW +: SW],
          m_tag}),
    .valid_o(valid_q3), .q_o({neg_q3, dot_w_q3, tag_q3, t_ok_q3}));

  // ---- the hit: 0 <= t <= 1, depth > 0 and all four signs ----
  wire [3:0] signs_q3 = {neg_q3[3], ~neg_q3[2], neg_q3[1], ~neg_q3[0]};  // {bottom < 0, top >= 0,
                                                                          //  right < 0, left >= 0}
  wire hit_q3 = t_ok_q3 && ~dot_w_q3[SW-1] && (|dot_w_q3) && (&signs_q3);
  wire valid_q4_unused;
  rpu_stage #(.W(2 + 4 + DepthW)) u_s4 (
    .clk_i, .rst_ni, .valid_i(valid_q3),
    .d_i({hit_q3, t_ok_q3, signs_q3, dot_w_q3[DepthW-1:0]}),
    .valid_o(valid_o), .q_o({hit_o, t_in_range_o, signs_o, depth_o}));
  // The tag loads only with a valid operand, so it leaves a flip-flop, not a shift-register LUT.
  rpu_stage #(.W(TagW), .Hold(1)) u_s4_tag (
    .clk_i, .rst_ni, .valid_i(valid_q3), .d_i(tag_q3), .valid_o(valid_q4_unused), .q_o(tag_o));
  `RPU_LATENCY_CHECK(Latency, "rpu_capture")
endmodule

`default_nettype wire
