// rpu_cordic: pipelined CORDIC, twin rpu::ref::cordic_vectoring / cordic_rotation
// (ref/model/common/rpu_cordic.h; formats and error bounds: docs/fixed-point.md, "CORDIC").
//   Mode 0, vectoring: (x_i, y_i) → x_o = |(x, y)| (unsigned), angle_o = atan2(y, x) as an
//                      AW-bit binary angle in [0, 2^AW) (2^AW = one turn); atan2(0, 0) = 0;
//                      y_o = 0.
//   Mode 1, rotation:  (x_i, y_i, angle_i) → (x_o, y_o) = (x, y) rotated counter-clockwise by
//                      angle_i / 2^AW turn; angle_o = 0.
// Inputs are W-bit two's complement with |x|, |y| <= 2^(W-2) (outside it the result wraps:
// meaningless, but bit-exact with the twin). Fixed latency
//   Latency = 1 + Iters + rpu_mul latency + 1 cycles
// (pre-rotation, one micro-rotation per stage, the gain product, the rounding stage), one
// operand per cycle, no stall; `tag_i` rides along unchanged (enclosing pipelines reserve room
// before they issue, as for every arithmetic unit).
//
// Datapath (every stage one add/sub carry chain, registers between stages):
// - Stage 0, pre-rotation by a half turn, x and y negated modulo 2^W:
//     vectoring when x < 0 (then x >= 0: the angle to resolve is within ±1/4 turn), the angle
//     register z starting at 1/2 turn plus half an output LSB (the rounding of the result);
//     rotation when the angle's top two bits differ (angle in [1/4, 3/4) turn), z = the angle
//     with its top bit flipped, a signed F-bit value in [−1/4, 1/4) turn.
//   x, y are widened to XW = W + 1 + G bits, G guard bits below the input LSB; z has F = AW + GA
//   bits, GA guard bits below the output LSB.
// - Stage 1 + i (i = 0 .. Iters−1), a rotation by d·atan(2^−i), d = +1 counter-clockwise:
//     x' = x − d·(y >>> i),  y' = y + d·(x >>> i),  z' = z − d·α_i
//   d = +1 when y < 0 (vectoring: drive y to 0) or z >= 0 (rotation: drive z to 0). The shifts
//   are sign-extended slices (floor); x, y wrap at XW bits, z at F bits (a full turn).
// - The gain K = Π √(1 + 2^−2i) is compensated by one constant product with
//   GainInv = round(2^KF / K), KF = W + 2 (rpu_mul; rotation: one per coordinate), and the last
//   stage rounds: out = floor(p / 2^(G+KF)) + bit G+KF−1 of p (to nearest, ties up), modulo 2^W.
// The constants α_i (round(atan(2^−i) · 2^F / 2π)) and GainInv are computed at elaboration by
// integer constant functions below (atan series, Machin's π, integer square root): the twin's
// cordic_tables does the same integer arithmetic.
`default_nettype none
`include "rpu_latency_check.vh"

module rpu_cordic #(
  parameter integer W     = 32,  // coordinate width in and out, two's complement (6..48)
  parameter integer AW    = 24,  // binary angle width: 2^AW is one turn (4..48)
  parameter integer Iters = 24,  // micro-rotations, one pipeline stage each (4..min(48, W + 4))
  parameter integer Mode  = 0,   // 0: vectoring (magnitude, atan2); 1: rotation
  parameter integer TagW  = 1    // side-band bits carried with each operand (>= 1)
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            valid_i,
  input  wire [W-1:0]    x_i,
  input  wire [W-1:0]    y_i,
  input  wire [AW-1:0]   angle_i,  // rotation: the angle; vectoring: unused
  input  wire [TagW-1:0] tag_i,
  output wire            valid_o,
  output wire [W-1:0]    x_o,      // vectoring: the magnitude (unsigned); rotation: x'
  output wire [W-1:0]    y_o,      // vectoring: 0; rotation: y'
  output wire [AW-1:0]   angle_o,  // vectoring: atan2(y, x); rotation: 0
  output wire [TagW-1:0] tag_o
);
`include "rpu_mul_latency.vh"
  localparam integer G   = $clog2(Iters) + 2;  // guard bits of x, y below the input LSB
  localparam integer GA  = $clog2(Iters) + 2;  // guard bits of z below the output angle LSB
  localparam integer XW  = W + 1 + G;          // x, y registers (signed)
  localparam integer F   = AW + GA;            // z register (a turn is 2^F)
  localparam integer KF  = W + 2;              // fraction bits of GainInv
  localparam integer S   = G + KF;             // product bits below the output LSB
  localparam integer SBW = Mode == 0 ? TagW + 1 : TagW;  // side band: {zero input, tag} | tag
  // The gain product: vectoring x (>= 0, W + G bits) unsigned × KF bits; rotation x or y
  // (signed, XW bits) × {0, GainInv} (signed, KF + 1 bits).
  localparam integer MA  = Mode == 0 ? W + G : XW;
  localparam integer MB  = Mode == 0 ? KF : KF + 1;
  localparam integer MP  = MA + MB;
  // Tiles of 13 × 17 bits instead of rpu_mul's 24 × 17: its first adder-tree level (a DSP's
  // slow P output into a carry chain about ChunkA + 17 bits long) then fits 3.5 ns (Yosys sta
  // 3.46 ns at the defaults, 3.80 with 24-bit tiles) for 6 DSP48E1 per product instead of 4.
  localparam integer MulChunkA  = 13;
  localparam integer MulLatency = `RPU_MUL_LATENCY(MA, MB, Mode == 0 ? 0 : 1, MulChunkA, 17);
  // The unit's latency (what the enclosing units count on; the twin's cordic_latency).
  localparam integer Latency = 1 + Iters + MulLatency + 1;

  initial begin
    if (W < 6 || W > 48) $fatal(1, "rpu_cordic: W must be in 6..48");
    if (AW < 4 || AW > 48) $fatal(1, "rpu_cordic: AW must be in 4..48");
    if (Iters < 4 || Iters > 48 || Iters > W + 4)
      $fatal(1, "rpu_cordic: Iters must be in 4..min(48, W + 4)");
    if (Mode != 0 && Mode != 1) $fatal(1, "rpu_cordic: Mode must be 0 or 1");
    if (TagW < 1) $fatal(1, "rpu_cordic: TagW must be >= 1");
  end

  // ---- constants: integer arithmetic at elaboration, 128-bit (twin: cordic_tables) ----
  localparam integer AtanFrac = 70;  // atan and 2π in radians · 2^70
  localparam integer GainFrac = 62;  // K² and K · 2^62

  // atan(2^−i) · 2^70 for i >= 1: Σ_k (−1)^k 2^(70 − i(2k+1)) / (2k+1), each term floored.
  function [127:0] atan_pow2(input integer i);
    reg [127:0] t, sum, odd;
    reg         sub;
    begin
      sum = 128'd0;
      odd = 128'd1;
      sub = 1'b0;
      t   = 128'd1 << (AtanFrac - i);
      while (t != 128'd0) begin
        if (sub) sum = sum - t / odd;
        else     sum = sum + t / odd;
        sub = ~sub;
        odd = odd + 128'd2;
        t   = t >> (2 * i);
      end
      atan_pow2 = sum;
    end
  endfunction

  // atan(1/m) · 2^70: the same series with x^(2k+1) = floor(2^70 / m^(2k+1)).
  function [127:0] atan_inv(input [127:0] atan_m);
    reg [127:0] t, sum, odd;
    reg         sub;
    begin
      sum = 128'd0;
      odd = 128'd1;
      sub = 1'b0;
      t   = (128'd1 << AtanFrac) / atan_m;
      while (t != 128'd0) begin
        if (sub) sum = sum - t / odd;
        else     sum = sum + t / odd;
        sub = ~sub;
        odd = odd + 128'd2;
        t   = t / (atan_m * atan_m);
      end
      atan_inv = sum;
    end
  endfunction

  // α_i = round(atan(2^−i) · 2^F / 2π), ties up; α_0 = 2^F / 8 exactly (below 2^F: the
  // caller keeps the low F bits). 2π · 2^70 = 8 (4 atan(1/5) − atan(1/239)) · 2^70 (Machin).
  function [127:0] atan_entry(input integer i);
    reg [127:0] two_pi, a, q;
    begin
      if (i == 0) begin
        q = 128'd1 << (F - 3);
      end else begin
        two_pi = 128'd8 * (128'd4 * atan_inv(128'd5) - atan_inv(128'd239));
        a      = atan_pow2(i) << F;
        q      = (a * 128'd2 + two_pi) / (two_pi * 128'd2);
      end
      atan_entry = q;
    end
  endfunction

  // floor(√v), one root bit per step.
  function [127:0] isqrt(input [127:0] v);
    reg [127:0] rem, root, one;
    begin
      rem  = v;
      root = 128'd0;
      one  = 128'd1 << 126;
      while (one > rem) one = one >> 2;
      while (one != 128'd0) begin
        if (rem >= root + one) begin
          rem  = rem - (root + one);
          root = (root >> 1) + one;
        end else begin
          root = root >> 1;
        end
        one = one >> 2;
      end
      isqrt = root;
    end
  endfunction

  // GainInv = round(2^KF / K), ties up: K² = Π_{i<n} (1 + 2^−2i) at 62 fraction bits (each
  // step floored), K · 2^62 = isqrt(K² · 2^62). Below 2^KF (1/K < 0.71).
  function [127:0] gain_inv(input integer n);
    reg [127:0] ksq, k, q;
    integer     i;
    begin
      ksq = 128'd1 << GainFrac;
      for (i = 0; i < n; i = i + 1) ksq = ksq + (ksq >> (2 * i));
      k = isqrt(ksq << GainFrac);
      q = ((128'd1 << (GainFrac + KF + 1)) + k) / (k * 128'd2);
      gain_inv = q;
    end
  endfunction

  localparam [127:0]  GainInvWide = gain_inv(Iters);
  localparam [KF-1:0] GainInv     = GainInvWide[KF-1:0];

  // ---- stage 0: pre-rotation and widening ----
  wire            flip;    // rotate by a half turn: negate x and y
  wire [F-1:0]    z_pre;
  wire [SBW-1:0]  side_pre;
  generate
    if (Mode == 0) begin : g_pre_vectoring
      assign flip     = x_i[W-1];
      // z = 1/2 turn if flipped, plus half an output LSB (rounds the final truncation).
      assign z_pre    = {flip, {(AW - 1){1'b0}}, 1'b1, {(GA - 1){1'b0}}};
      assign side_pre = {~|{x_i, y_i}, tag_i};  // atan2(0, 0) := 0
      wire unused_angle = ^angle_i;
    end else begin : g_pre_rotation
      // Angle in [1/4, 3/4) turn: its top two bits differ. Flipping the top bit leaves it equal
      // to the second bit: z = {a[AW-2], a[AW-2:0]} · 2^GA, signed, in [−1/4, 1/4) turn.
      assign flip     = angle_i[AW-1] ^ angle_i[AW-2];
      assign z_pre    = {angle_i[AW-2], angle_i[AW-2:0], {GA{1'b0}}};
      assign side_pre = tag_i;
    end
  endgenerate
  // ±x, ±y modulo 2^W (exact in range: −(−2^(W−2)) fits).
  wire [W-1:0] x_pre = (x_i ^ {W{flip}}) + {{(W - 1){1'b0}}, flip};
  wire [W-1:0] y_pre = (y_i ^ {W{flip}}) + {{(W - 1){1'b0}}, flip};

  // Stage registers: index k holds the state after stage k (0: pre-rotation, 1 + i: after
  // micro-rotation i).
  wire [XW-1:0]  xs    [0:Iters];
  wire [XW-1:0]  ys    [0:Iters];
  wire [F-1:0]   zs    [0:Iters];
  wire [SBW-1:0] sides [0:Iters];
  wire [Iters:0] valids;

  reg [XW-1:0]  x0_q, y0_q;
  reg [F-1:0]   z0_q;
  reg [SBW-1:0] side0_q;
  reg           valid0_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid0_q <= 1'b0;
    else         valid0_q <= valid_i;
  end
  always @(posedge clk_i) begin
    x0_q    <= {x_pre[W-1], x_pre, {G{1'b0}}};  // sign-extended, times 2^G
    y0_q    <= {y_pre[W-1], y_pre, {G{1'b0}}};
    z0_q    <= z_pre;
    side0_q <= side_pre;
  end
  assign xs[0]     = x0_q;
  assign ys[0]     = y0_q;
  assign zs[0]     = z0_q;
  assign sides[0]  = side0_q;
  assign valids[0] = valid0_q;

  // ---- stages 1 .. Iters: one micro-rotation each ----
  genvar s;
  generate
    for (s = 0; s < Iters; s = s + 1) begin : g_stage
      localparam [127:0] AtanWide = atan_entry(s);
      localparam [F-1:0] Atan    = AtanWide[F-1:0];  // α_s
      localparam [F-1:0] AtanNeg = ~Atan + 1'b1;    // −α_s modulo 2^F
      wire [XW-1:0] x = xs[s];
      wire [XW-1:0] y = ys[s];
      wire [F-1:0]  z = zs[s];
      wire [XW-1:0] x_sh;  // floor(x · 2^−s)
      wire [XW-1:0] y_sh;  // floor(y · 2^−s)
      if (s == 0) begin : g_noshift
        assign x_sh = x;
        assign y_sh = y;
      end else begin : g_shift
        assign x_sh = {{s{x[XW-1]}}, x[XW-1:s]};
        assign y_sh = {{s{y[XW-1]}}, y[XW-1:s]};
      end
      // Counter-clockwise (d = +1): vectoring when y < 0, rotation when z >= 0.
      wire ccw = Mode == 0 ? y[XW-1] : ~z[F-1];
      reg [XW-1:0]  x_q, y_q;
      reg           x_c, y_c;  // the sums' low bits (1 − carry-in)
      wire          unused_c = ^{x_c, y_c};
      reg [F-1:0]   z_q;
      reg [SBW-1:0] side_q;
      reg           valid_q;
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) valid_q <= 1'b0;
        else         valid_q <= valids[s];
      end
      always @(posedge clk_i) begin
        // x − d·y_sh, y + d·x_sh: one adder each, the operand inverted with carry-in 1 to subtract.
        // The carry-in rides as the low bit of one XW+1-bit sum ({a, 1} + {b, c} = 2(a + b + c)
        // + 1 − c), so the synthesis sees one carry chain whatever else it maps (two chained adds
        // were mapped as one or as two chains, 2.1k or 3.1k LUTs a unit, by Yosys' cell order).
        {x_q, x_c} <= {x, 1'b1} + {y_sh ^ {XW{ccw}}, ccw};
        {y_q, y_c} <= {y, 1'b1} + {x_sh ^ {XW{~ccw}}, ~ccw};
        z_q    <= z + (ccw ? AtanNeg : Atan);
        side_q <= sides[s];
      end
      assign xs[s+1]     = x_q;
      assign ys[s+1]     = y_q;
      assign zs[s+1]     = z_q;
      assign sides[s+1]  = side_q;
      assign valids[s+1] = valid_q;
    end
  endgenerate

  // ---- gain compensation (rpu_mul) and rounding ----
  wire [XW-1:0]  x_last    = xs[Iters];
  wire [XW-1:0]  y_last    = ys[Iters];
  wire [F-1:0]   z_last    = zs[Iters];
  wire [SBW-1:0] side_last = sides[Iters];
  reg            valid_q;
  reg [W-1:0]    xo_q, yo_q;
  reg [AW-1:0]   angle_q;
  reg [TagW-1:0] tag_q;
  wire           mul_valid;
  generate
    if (Mode == 0) begin : g_vectoring
      // x_last >= 0 (it only grows from the pre-rotated x >= 0) and below 2^(W+G) in range.
      localparam integer MTW = 1 + AW + TagW;  // {zero, angle, tag}
      wire [MP-1:0]  p;
      wire [MTW-1:0] mtag;
      rpu_mul #(.AW(MA), .BW(MB), .Signed(0), .ChunkA(MulChunkA), .TagW(MTW)) u_gain (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(valids[Iters]),
        .a_i    (x_last[MA-1:0]),
        .b_i    (GainInv),
        .tag_i  ({side_last[TagW], z_last[F-1:GA], side_last[TagW-1:0]}),
        .valid_o(mul_valid),
        .p_o    (p),
        .tag_o  (mtag)
      );
      always @(posedge clk_i) begin
        // round(p / 2^S), ties up; p / 2^S < 2^(W−1) in range: the top W bits of p.
        xo_q    <= p[S +: W] + {{(W - 1){1'b0}}, p[S-1]};
        yo_q    <= {W{1'b0}};
        angle_q <= mtag[MTW-1] ? {AW{1'b0}} : mtag[TagW +: AW];
        tag_q   <= mtag[TagW-1:0];
      end
      // Dropped: x's sign bit (0), y (driven to 0), z's guard bits (the rounding is in z's
      // start value), the product bits below the rounding bit.
      wire unused_vectoring = ^{x_last[XW-1], y_last, z_last[GA-1:0], p[S-2:0]};
    end else begin : g_rotation
      wire [MP-1:0]   px, py;
      wire [TagW-1:0] mtag;
      wire            unused_valid_y;
      wire            unused_tag_y;
      rpu_mul #(.AW(MA), .BW(MB), .Signed(1), .ChunkA(MulChunkA), .TagW(TagW)) u_gain_x (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(valids[Iters]),
        .a_i    (x_last),
        .b_i    ({1'b0, GainInv}),
        .tag_i  (side_last),
        .valid_o(mul_valid),
        .p_o    (px),
        .tag_o  (mtag)
      );
      rpu_mul #(.AW(MA), .BW(MB), .Signed(1), .ChunkA(MulChunkA), .TagW(1)) u_gain_y (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(valids[Iters]),
        .a_i    (y_last),
        .b_i    ({1'b0, GainInv}),
        .tag_i  (1'b0),
        .valid_o(unused_valid_y),
        .p_o    (py),
        .tag_o  (unused_tag_y)
      );
      always @(posedge clk_i) begin
        // round(p / 2^S), ties up, modulo 2^W (|result| < 2^(W−1) in range).
        xo_q    <= px[S +: W] + {{(W - 1){1'b0}}, px[S-1]};
        yo_q    <= py[S +: W] + {{(W - 1){1'b0}}, py[S-1]};
        angle_q <= {AW{1'b0}};
        tag_q   <= mtag;
      end
      // Dropped: the remaining angle, the product's two top (sign) bits and the bits below the
      // rounding bit, the second multiplier's valid and tag (the same as the first's).
      wire unused_rotation = ^{z_last, px[MP-1:S+W], px[S-2:0], py[MP-1:S+W], py[S-2:0],
                               unused_valid_y, unused_tag_y};
    end
  endgenerate
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= 1'b0;
    else         valid_q <= mul_valid;
  end

  assign valid_o = valid_q;
  assign x_o     = xo_q;
  assign y_o     = yo_q;
  assign angle_o = angle_q;
  assign tag_o   = tag_q;
  `RPU_LATENCY_CHECK(Latency, "rpu_cordic")
endmodule

`default_nettype wire
