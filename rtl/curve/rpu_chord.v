// rpu_chord: the chord parameter of a segment (the model's `chord_parameter`):
//   t_o = sat(floor(dot_i · inv_m_i · 2^-(inv_s_i − TFrac)), TFrac + 3 bits signed)
// inv_m · 2^-inv_s ≈ 1/L² is the segment's block-floating-point reciprocal; inv_s is a per-operand
// input, so the shift by inv_s − TFrac runs either way (negative: an exact left shift, as
// fixed::truncate does). Both directions are one arithmetic right shift of dot·inv_m·2^TFrac by
// inv_s. ovf_o is set when the saturation clamps (the pair's sticky overflow bit).
// Pipeline (one operand per cycle, no stall; `tag_i` rides along unchanged):
//   LatM     dot · inv_m                 rpu_mul (InvW+1)×DotW signed (rpu_mul_latency.vh),
//                                        inv_s in its tag (tag_i in a delay line of its own)
//   1        the shift by the high bits of inv_s (multiples of 8)
//   1        the shift by its low three bits; whether coarse's bits from TW+6 up are all sign
//   1        the saturation
// Latency = LatM + 3 cycles (7 at the defaults: 19 × 52 bits, three tiles, LatM = 4).
// No backpressure inside (rpu_top reserves room).
`default_nettype none
`include "rpu_widths.vh"

module rpu_chord #(
  parameter integer DotW  = 52,  // signed width of the dot product (2..126, DotW + InvW <= 127)
  parameter integer InvW  = 18,  // unsigned width of the mantissa inv_m (8..40)
  parameter integer TFrac = 24,  // fraction bits of t, Q(3.TFrac) (8..48)
  parameter integer ShW   = 7,   // unsigned width of the exponent inv_s (1..8)
  parameter integer TagW  = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer TW = `RPU_TW(TFrac)  // t: Q(3.TFrac)
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            valid_i,
  input  wire [DotW-1:0] dot_i,    // (x − p1)·d, LSB², signed
  input  wire [InvW-1:0] inv_m_i,  // unsigned mantissa
  input  wire [ShW-1:0]  inv_s_i,  // unsigned exponent
  input  wire [TagW-1:0] tag_i,
  output reg             valid_o,
  output reg  [TW-1:0]   t_o,      // Q(3.TFrac), signed
  output reg             ovf_o,
  output reg  [TagW-1:0] tag_o
);
  localparam integer PW  = DotW + InvW;  // |dot · inv_m| < 2^(DotW−1) · 2^InvW: exact, signed
  localparam integer SW  = PW + TFrac;   // dot · inv_m · 2^TFrac, exact
  localparam integer MW  = InvW + 1;     // inv_m as a signed multiplier operand
  localparam integer MTW = ShW;          // the multiplier's tag: inv_s
  // The coarse shift: inv_s's bits above the low three, in multiples of 8.
  localparam integer HiW = ShW > 3 ? ShW - 3 : 1;

  initial begin
    if (DotW < 2 || DotW > 126) $fatal(1, "rpu_chord: DotW must be in 2..126");
    if (InvW < 8 || InvW > 40) $fatal(1, "rpu_chord: InvW must be in 8..40");
    if (DotW + InvW > 127) $fatal(1, "rpu_chord: DotW + InvW must be <= 127");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_chord: TFrac must be in 8..48");
    if (ShW < 1 || ShW > 8) $fatal(1, "rpu_chord: ShW must be in 1..8");
    if (TagW < 1) $fatal(1, "rpu_chord: TagW must be >= 1");
  end

`include "rpu_mul_latency.vh"
  localparam integer LatM = `RPU_MUL_LAT(MW, DotW, 1);
  // The unit's latency (what the enclosing units count on; ref::chord_latency).
  localparam integer Latency = LatM + 3;

  // ---- the product dot · inv_m (exact: its top bit is a copy of the sign) ----
  wire            m_valid;
  wire [MW+DotW-1:0] m_p;
  wire [MTW-1:0]  m_tag;
  rpu_mul #(.AW(MW), .BW(DotW), .Signed(1), .TagW(MTW)) u_mul (
    .clk_i, .rst_ni, .valid_i, .a_i({1'b0, inv_m_i}), .b_i(dot_i), .tag_i(inv_s_i),
    .valid_o(m_valid), .p_o(m_p), .tag_o(m_tag));
  wire signed [PW-1:0] prod  = m_p[PW-1:0];
  wire [ShW-1:0]       inv_s = m_tag[ShW-1:0];
  wire unused_prod = m_p[MW+DotW-1];

  // ---- floor(prod · 2^TFrac / 2^inv_s) in two steps of the arithmetic right shift ----
  // A shift by >= SW leaves the sign in every bit (0 or −1), as the model's >> does; the coarse
  // step keeps SW bits, so the fine step's result is exactly the whole shift's.
  wire signed [SW-1:0] scaled = {prod, {TFrac{1'b0}}};
  wire [HiW-1:0]       s_hi;
  wire [2:0]           s_lo;
  generate
    if (ShW > 3) begin : g_hi
      assign s_hi = inv_s[ShW-1:3];
      assign s_lo = inv_s[2:0];
    end else begin : g_lo
      assign s_hi = 1'b0;
      assign s_lo = {{(3 - ShW){1'b0}}, inv_s};
    end
  endgenerate
  wire signed [SW-1:0] coarse = scaled >>> {s_hi, 3'b000};

  reg signed [SW-1:0] coarse_q;
  reg [2:0]           lo_q;
  reg                 valid1_q;
  always @(posedge clk_i) begin
    coarse_q <= coarse;
    lo_q     <= s_lo;
  end

  // ---- the fine shift; beside it, whether coarse's bits from TW+6 up all equal its sign ----
  // The shifted value fits TW bits when its bits TW−1 .. SW−1 all equal the sign, i.e. coarse's
  // bits TW−1+lo .. SW−1. hi_eq covers coarse's bits TW+6 .. SW−1 (independent of lo); the others,
  // TW−1+lo .. TW+5, are the shifted value's bits TW−1 .. TW+5−lo, and its bits from there up to
  // TW+6 are coarse's bits from TW+6 up. So fits = hi_eq ∧ the shifted bits TW−1 .. TW+6 equal.
  wire signed [SW-1:0] shifted = coarse_q >>> lo_q;
  wire                 hi_eq   = (&coarse_q[SW-1:TW+6]) | ~(|coarse_q[SW-1:TW+6]);

  reg [TW+6:0]   sh_q;     // the shifted value's bits 0 .. TW+6
  reg            hi_eq_q;
  reg            sign_q;   // its sign (coarse's top bit)
  reg            valid2_q;
  always @(posedge clk_i) begin
    sh_q    <= shifted[TW+6:0];
    hi_eq_q <= hi_eq;
    sign_q  <= coarse_q[SW-1];
  end
  generate
    if (SW - 1 > TW + 6) begin : g_unused
      wire unused_shifted = ^shifted[SW-1:TW+7];
    end
  endgenerate

  // ---- saturate to TW bits ----
  wire          fits  = hi_eq_q & ((&sh_q[TW+6:TW-1]) | ~(|sh_q[TW+6:TW-1]));
  wire [TW-1:0] t_sat = fits ? sh_q[TW-1:0] : {sign_q, {(TW-1){~sign_q}}};
  always @(posedge clk_i) begin
    t_o   <= t_sat;
    ovf_o <= ~fits;
  end
  // The tag: Latency − 1 plain stages (shift-register LUTs), then one loaded only with a valid
  // operand (a clock enable the others do not have), so it leaves a flip-flop; tag_o holds the
  // last valid item's tag.
  reg [(Latency-1)*TagW-1:0] tag_q;
  always @(posedge clk_i) tag_q <= {tag_q[(Latency-2)*TagW-1:0], tag_i};
  always @(posedge clk_i) if (valid2_q) tag_o <= tag_q[(Latency-1)*TagW-1 -: TagW];

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid1_q <= 1'b0;
      valid2_q <= 1'b0;
      valid_o  <= 1'b0;
    end else begin
      valid1_q <= m_valid;
      valid2_q <= valid1_q;
      valid_o  <= valid2_q;
    end
  end
endmodule

`default_nettype wire
