// rpu_chord: the chord parameter of a segment (the model's `chord_parameter`):
//   t_o = sat(floor(dot_i · inv_m_i · 2^-(inv_s_i − TFrac)), TFrac + 3 bits signed)
// inv_m · 2^-inv_s ≈ 1/L² is the segment's block-floating-point reciprocal; inv_s is a per-operand
// input, so the shift by inv_s − TFrac runs either way (negative: an exact left shift, as
// fixed::truncate does). Both directions are one arithmetic right shift of dot·inv_m·2^TFrac by
// inv_s. ovf_o is set when the saturation clamps (the pair's sticky overflow bit).
// Fixed latency of 2 cycles (the product registered, then shifted and saturated), one operand per
// cycle; `tag_i` rides along unchanged. No backpressure inside (rpu_top reserves room).
`default_nettype none

module rpu_chord #(
  parameter integer DotW  = 52,  // signed width of the dot product (2..126)
  parameter integer InvW  = 18,  // unsigned width of the mantissa inv_m (8..40)
  parameter integer TFrac = 24,  // fraction bits of t, Q(3.TFrac) (8..48)
  parameter integer ShW   = 7,   // unsigned width of the exponent inv_s (1..8)
  parameter integer TagW  = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer TW = TFrac + 3  // t: Q(3.TFrac)
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            valid_i,
  input  wire [DotW-1:0] dot_i,    // (x − p1)·d, LSB², signed
  input  wire [InvW-1:0] inv_m_i,  // unsigned mantissa
  input  wire [ShW-1:0]  inv_s_i,  // unsigned exponent
  input  wire [TagW-1:0] tag_i,
  output wire            valid_o,
  output wire [TW-1:0]   t_o,      // Q(3.TFrac), signed
  output wire            ovf_o,
  output wire [TagW-1:0] tag_o
);
  localparam integer PW = DotW + InvW;  // |dot · inv_m| < 2^(DotW−1) · 2^InvW: exact, signed
  localparam integer SW = PW + TFrac;   // dot · inv_m · 2^TFrac, exact

  initial begin
    if (DotW < 2 || DotW > 126) $fatal(1, "rpu_chord: DotW must be in 2..126");
    if (InvW < 8 || InvW > 40) $fatal(1, "rpu_chord: InvW must be in 8..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_chord: TFrac must be in 8..48");
    if (ShW < 1 || ShW > 8) $fatal(1, "rpu_chord: ShW must be in 1..8");
    if (TagW < 1) $fatal(1, "rpu_chord: TagW must be >= 1");
  end

  // ---- stage 1: the product, both operands widened to PW bits (sign / zero extension) ----
  wire signed [PW-1:0] dot_x  = {{InvW{dot_i[DotW-1]}}, dot_i};
  wire signed [PW-1:0] inv_x  = {{DotW{1'b0}}, inv_m_i};
  wire signed [PW-1:0] prod   = dot_x * inv_x;  // fits PW bits: no bit lost

  reg signed [PW-1:0] prod_q;
  reg [ShW-1:0]       inv_s_q;
  reg [TagW-1:0]      tag1_q;
  reg                 valid1_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid1_q <= 1'b0;
    else         valid1_q <= valid_i;
  end
  always @(posedge clk_i) begin
    prod_q  <= prod;
    inv_s_q <= inv_s_i;
    tag1_q  <= tag_i;
  end

  // ---- stage 2: floor(prod · 2^TFrac / 2^inv_s), then saturate to TW bits ----
  // A shift by >= SW leaves the sign in every bit (0 or −1), as the model's >> does.
  wire signed [SW-1:0] scaled  = {prod_q, {TFrac{1'b0}}};
  wire signed [SW-1:0] shifted = scaled >>> inv_s_q;
  wire                 fits    = (&shifted[SW-1:TW-1]) | ~(|shifted[SW-1:TW-1]);
  wire [TW-1:0]        t_sat   = fits ? shifted[TW-1:0]
                                      : {shifted[SW-1], {(TW-1){~shifted[SW-1]}}};

  reg [TW-1:0]   t_q;
  reg            ovf_q;
  reg [TagW-1:0] tag2_q;
  reg            valid2_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid2_q <= 1'b0;
    else         valid2_q <= valid1_q;
  end
  always @(posedge clk_i) begin
    t_q    <= t_sat;
    ovf_q  <= ~fits;
    tag2_q <= tag1_q;
  end

  assign valid_o = valid2_q;
  assign t_o     = t_q;
  assign ovf_o   = ovf_q;
  assign tag_o   = tag2_q;
endmodule

`default_nettype wire
