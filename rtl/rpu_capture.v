// rpu_capture: the plane-sign capture unit (seed 000 eqs 24–26 in the camera basis), twin of
// rpu::ref::capture_unit. With q = X − h:
//   left  = q·E_left(i)  ≥ 0     right  = q·E_left(i+1) < 0
//   top   = q·E_top(j)   ≥ 0     bottom = q·E_top(j+1)  < 0
//   depth = q·W,  hit = (0 ≤ t ≤ 1) ∧ depth > 0 ∧ all four signs.
// All products are exact (no bits dropped). Latency 3: q, products, sums and signs.
`default_nettype none

module rpu_capture #(
  parameter integer CoordW   = 24,  // position width (12..40)
  parameter integer TFrac    = 24,  // fraction bits of t (8..48)
  parameter integer EdgeFrac = 16,  // fraction bits of edge vectors (8..40), plus 14 guard bits
  parameter integer TagW     = 1,   // side-band bits (>= 1)
  // Derived (do not override).
  parameter integer XW     = CoordW + 3,              // curve point X
  parameter integer EdgeW  = 4 + EdgeFrac + 14,       // Q(4.FE+14)
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

  // ---- stage 2: the fifteen exact products ----
  reg            valid_q2;
  reg [15*PW-1:0] prod_q2;   // vector v (0 left, 1 right, 2 top, 3 bottom, 4 W), component c
  reg            t_ok_q2;
  reg [TagW-1:0] tag_q2;
  genvar v;
  generate
    for (v = 0; v < 5; v = v + 1) begin : g_vec
      for (c = 0; c < 3; c = c + 1) begin : g_comp
        wire signed [QW-1:0]    qc = q_q1[c*QW +: QW];
        wire signed [EdgeW-1:0] ec = e_q1[(3*v + c)*EdgeW +: EdgeW];
        wire signed [PW-1:0]    p  = qc * ec;
        always @(posedge clk_i) prod_q2[(3*v + c)*PW +: PW] <= p;
      end
    end
  endgenerate
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q2 <= 1'b0;
    else         valid_q2 <= valid_q1;
  end
  always @(posedge clk_i) begin
    t_ok_q2 <= t_ok_q1;
    tag_q2  <= tag_q1;
  end

  // ---- stage 3: the dot products, their signs, the hit ----
  wire signed [SW-1:0] dots [0:4];
  generate
    for (v = 0; v < 5; v = v + 1) begin : g_dot
      wire signed [PW-1:0] p0 = prod_q2[(3*v + 0)*PW +: PW];
      wire signed [PW-1:0] p1 = prod_q2[(3*v + 1)*PW +: PW];
      wire signed [PW-1:0] p2 = prod_q2[(3*v + 2)*PW +: PW];
      assign dots[v] = {{2{p0[PW-1]}}, p0} + {{2{p1[PW-1]}}, p1} + {{2{p2[PW-1]}}, p2};
    end
  endgenerate
  wire [3:0] signs = {dots[3] < 0, dots[2] >= 0, dots[1] < 0, dots[0] >= 0};

  reg              valid_q3;
  reg              hit_q3, t_ok_q3;
  reg [3:0]        signs_q3;
  reg [DepthW-1:0] depth_q3;
  reg [TagW-1:0]   tag_q3;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q3 <= 1'b0;
    else         valid_q3 <= valid_q2;
  end
  always @(posedge clk_i) begin
    signs_q3 <= signs;
    t_ok_q3  <= t_ok_q2;
    hit_q3   <= t_ok_q2 && (dots[4] > 0) && (&signs);
    depth_q3 <= dots[4][DepthW-1:0];
    tag_q3   <= tag_q2;
  end

  assign valid_o      = valid_q3;
  assign hit_o        = hit_q3;
  assign t_in_range_o = t_ok_q3;
  assign signs_o      = signs_q3;
  assign depth_o      = depth_q3;
  assign tag_o        = tag_q3;
endmodule

`default_nettype wire
