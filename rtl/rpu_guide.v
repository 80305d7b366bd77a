// rpu_guide: one guide's offset g_k(t) of the closed-form curve (the model's `guide_weight`
// followed by `guide_unit`):
//   w = floor(tc·(2^FT − tc) / 2^FT),  tc = clamp(t, 0, 2^FT)                 Q(0.FT), ≤ 1/4
//   arc      (mode 1): g = sqrt_unit(h² + floor(L2·w / 2^FT)) − h   (RadW = 2·CW+10 radicand,
//                      saturated to RadW bits (sets ovf_o), then rpu_sqrt with its SqrtW pre-shift)
//   flat     (mode 2): g = aw − floor(aw·bw / 2^FT),
//                      aw = floor(a·w / 2^FT), bw = floor(b·w / 2^FT)
//   straight (mode 0, and the unused code 3): g = 0
// The arc's h, or the finished flat/straight result, rides through the square root's side band
// (one shared field), so every mode has the same fixed latency: Latency = 3 + Stages(rpu_sqrt)
// + 1 cycles (33 at the defaults, 24 with SqrtW = 40). One operand per cycle, no stall; `tag_i`
// comes out unchanged with the result.
//
// g is signed: with a pre-shifted square root (SqrtW > 0) the root may fall below h, so the arc
// gives g ∈ (−2^S, 0] where the exact g is 0 (S = the pre-shift; docs/fixed-point.md bound).
// Over every port value g ∈ (−2^S, 2^(CW+1)) (g ≤ sqrt(floor(L2·w)) < 2^(CW+1/2)), which fits
// CW+2 signed bits since S ≤ CW−3; within the descriptor formats g ≤ L/2 < 2^CW.
`default_nettype none

module rpu_guide #(
  parameter integer CoordW = 24,  // CW: signed width of positions (12..40)
  parameter integer TFrac  = 24,  // FT: fraction bits of t and w (8..48, 2·CW+3+FT <= 126)
  parameter integer SqrtW  = 0,   // widest radicand of the square root; 0 = exact (16..126)
  parameter integer TagW   = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer TW   = TFrac + 3,       // t: Q(3.FT), signed
  parameter integer WW   = TFrac - 1,       // w ≤ 2^(FT−2): FT−1 bits, unsigned
  parameter integer HW   = CoordW + 5,      // h ≤ 16·L < 16·√3·2^CW < 2^(CW+5), unsigned
  parameter integer AW   = CoordW,          // a = L²/(2h) < L/32, unsigned
  parameter integer L2W  = 2 * CoordW + 3,  // L2 = |d|² ≤ 3·2^(2CW), unsigned
  parameter integer GW   = CoordW + 2       // g, signed (see above)
) (
  input  wire                   clk_i,
  input  wire                   rst_ni,
  input  wire                   valid_i,
  input  wire [TW-1:0]          t_i,     // chord parameter, Q(3.FT) signed
  input  wire [1:0]             mode_i,  // 0 straight, 1 arc, 2 flat (3 acts as straight)
  input  wire [HW-1:0]          h_i,     // guide height, LSB (arc)
  input  wire [AW-1:0]          a_i,     // L²/(2h), LSB (flat)
  input  wire [TFrac-1:0]       b_i,     // L²/(4h²), Q(0.FT) (flat)
  input  wire [L2W-1:0]         l2_i,    // |d|², LSB²
  input  wire [TagW-1:0]        tag_i,
  output reg                    valid_o,
  output reg  signed [GW-1:0]   g_o,     // guide offset, LSB
  output reg  [WW-1:0]          w_o,     // w = tc·(1 − tc), Q(0.FT)
  output reg                    ovf_o,   // the arc's radicand saturated (sticky bit of the pair)
  output reg  [TagW-1:0]        tag_o
);
  localparam integer RadW = 2 * CoordW + 10;  // guide_radicand_w(): h² + L²w with h ≤ 16·L
  // rpu_sqrt's derived widths (the same formulas; RadW is even, so its RootW equals HW).
  localparam integer SqShift  = (SqrtW == 0 || RadW <= SqrtW) ? 0 : (RadW - SqrtW + 1) / 2;
  localparam integer SqStages = (RadW - 2 * SqShift + 1) / 2;
  localparam integer RootW    = SqStages + SqShift;
  localparam integer LwW      = L2W + WW - TFrac;    // floor(L2·w): 2·CW+2 bits (< 2^(2CW+1))
  localparam integer AwW      = AW + WW - TFrac;     // floor(a·w): CW−1 bits (< 2^(CW−2))
  localparam integer AbW      = AwW + WW - TFrac;    // floor(aw·bw): CW−2 bits (< 2^(CW−4))
  // Side band through the square root: tag, w, is-arc, overflow, and one HW-bit field holding
  // h (arc) or the finished non-arc result (flat, straight).
  localparam integer SbW      = TagW + WW + 2 + HW;

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_guide: CoordW must be in 12..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_guide: TFrac must be in 8..48");
    if (2 * CoordW + 3 + TFrac > 126) $fatal(1, "rpu_guide: 2*CoordW+3+TFrac must be <= 126");
    if (TagW < 1) $fatal(1, "rpu_guide: TagW must be >= 1");
    if (RootW != HW) $fatal(1, "rpu_guide: internal: root width differs from h width");
  end

  // ---- stage 1: w = floor(tc·(2^FT − tc) / 2^FT) ----
  // tc = clamp(t, 0, 2^FT). Both ends give w = 0, so only x = tc mod 2^FT matters: x = t for
  // 0 ≤ t < 2^FT, else 0; and (2^FT − tc) mod 2^FT = (−x) mod 2^FT (x = 0 → product 0 either way).
  wire             t_neg  = t_i[TW-1];
  wire             t_big  = ~t_neg & (|t_i[TW-2:TFrac]);  // t ≥ 2^FT
  wire [TFrac-1:0] x      = (t_neg | t_big) ? {TFrac{1'b0}} : t_i[TFrac-1:0];
  wire [TFrac-1:0] x_comp = -x;
  wire [2*TFrac-1:0] ww   = {{TFrac{1'b0}}, x} * {{TFrac{1'b0}}, x_comp};
  // ww ≤ 2^(2FT−2): bit 2FT−1 is zero; the low FT bits are the floor's dropped fraction.
  wire [WW-1:0]    w      = ww[2*TFrac-2:TFrac];

  reg              valid_1q;
  reg [WW-1:0]     w_1q;
  reg [1:0]        mode_1q;
  reg [HW-1:0]     h_1q;
  reg [AW-1:0]     a_1q;
  reg [TFrac-1:0]  b_1q;
  reg [L2W-1:0]    l2_1q;
  reg [TagW-1:0]   tag_1q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_1q <= 1'b0;
    else         valid_1q <= valid_i;
  end
  always @(posedge clk_i) begin
    w_1q    <= w;
    mode_1q <= mode_i;
    h_1q    <= h_i;
    a_1q    <= a_i;
    b_1q    <= b_i;
    l2_1q   <= l2_i;
    tag_1q  <= tag_i;
  end

  // ---- stage 2: h², floor(L2·w), aw = floor(a·w), bw = floor(b·w) (all unsigned) ----
  wire [RadW-1:0]        hh    = {{HW{1'b0}}, h_1q} * {{HW{1'b0}}, h_1q};  // 2·HW = RadW bits
  wire [L2W+WW-1:0]      lw_p  = {{WW{1'b0}}, l2_1q} * {{L2W{1'b0}}, w_1q};
  wire [AW+WW-1:0]       aw_p  = {{WW{1'b0}}, a_1q} * {{AW{1'b0}}, w_1q};
  wire [TFrac+WW-1:0]    bw_p  = {{WW{1'b0}}, b_1q} * {{TFrac{1'b0}}, w_1q};
  wire [LwW-1:0]         lw    = lw_p[L2W+WW-1:TFrac];
  wire [AwW-1:0]         aw    = aw_p[AW+WW-1:TFrac];
  wire [WW-1:0]          bw    = bw_p[TFrac+WW-1:TFrac];  // b < 2^FT: bw < 2^(FT−2)

  reg              valid_2q;
  reg [RadW-1:0]   hh_2q;
  reg [LwW-1:0]    lw_2q;
  reg [AwW-1:0]    aw_2q;
  reg [WW-1:0]     bw_2q;
  reg [WW-1:0]     w_2q;
  reg [1:0]        mode_2q;
  reg [HW-1:0]     h_2q;
  reg [TagW-1:0]   tag_2q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_2q <= 1'b0;
    else         valid_2q <= valid_1q;
  end
  always @(posedge clk_i) begin
    hh_2q   <= hh;
    lw_2q   <= lw;
    aw_2q   <= aw;
    bw_2q   <= bw;
    w_2q    <= w_1q;
    mode_2q <= mode_1q;
    h_2q    <= h_1q;
    tag_2q  <= tag_1q;
  end

  // ---- stage 3: radicand h² + floor(L2·w), saturated to RadW bits; floor(aw·bw) ----
  // The sum is < 2^RadW + 2^(2CW+1) < 2^(RadW+1): its top bit is the overflow.
  wire [RadW:0]          rad_sum = {1'b0, hh_2q} + {{(RadW + 1 - LwW){1'b0}}, lw_2q};
  wire                   rad_ovf = rad_sum[RadW];
  wire [RadW-1:0]        rad_sat = rad_ovf ? {RadW{1'b1}} : rad_sum[RadW-1:0];
  wire [AwW+WW-1:0]      ab_p    = {{WW{1'b0}}, aw_2q} * {{AwW{1'b0}}, bw_2q};
  wire [AbW-1:0]         ab      = ab_p[AwW+WW-1:TFrac];

  reg              valid_3q;
  reg [RadW-1:0]   rad_3q;
  reg              ovf_3q;
  reg [AwW-1:0]    aw_3q;
  reg [AbW-1:0]    ab_3q;
  reg [WW-1:0]     w_3q;
  reg [1:0]        mode_3q;
  reg [HW-1:0]     h_3q;
  reg [TagW-1:0]   tag_3q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_3q <= 1'b0;
    else         valid_3q <= valid_2q;
  end
  always @(posedge clk_i) begin
    rad_3q  <= rad_sat;
    ovf_3q  <= rad_ovf;
    aw_3q   <= aw_2q;
    ab_3q   <= ab;
    w_3q    <= w_2q;
    mode_3q <= mode_2q;
    h_3q    <= h_2q;
    tag_3q  <= tag_2q;
  end

  // ---- stages 4 .. 3+SqStages: the square root; the rest rides in its side band ----
  // Flat: aw − floor(aw·bw) ≥ 0 (bw < 1/4); straight and code 3: 0. Overflow only counts for
  // the arc (the other modes do not use the radicand).
  wire            is_arc = (mode_3q == 2'd1);
  wire            is_flat = (mode_3q == 2'd2);
  wire [AwW-1:0]  g_flat = aw_3q - {{(AwW - AbW){1'b0}}, ab_3q};
  wire [AwW-1:0]  g_alt  = is_flat ? g_flat : {AwW{1'b0}};
  wire [HW-1:0]   hg     = is_arc ? h_3q : {{(HW - AwW){1'b0}}, g_alt};
  wire [SbW-1:0]  sb_in  = {tag_3q, w_3q, is_arc, is_arc & ovf_3q, hg};

  wire            sq_valid;
  wire [RootW-1:0] sq_root;
  wire [SbW-1:0]  sb_out;
  rpu_sqrt #(
    .RadW (RadW),
    .SqrtW(SqrtW),
    .TagW (SbW)
  ) u_sqrt (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .valid_i(valid_3q),
    .rad_i  (rad_3q),
    .tag_i  (sb_in),
    .valid_o(sq_valid),
    .root_o (sq_root),
    .tag_o  (sb_out)
  );

  wire [TagW-1:0] sb_tag  = sb_out[SbW-1 -: TagW];
  wire [WW-1:0]   sb_w    = sb_out[HW+2 +: WW];
  wire            sb_arc  = sb_out[HW+1];
  wire            sb_ovf  = sb_out[HW];
  wire [HW-1:0]   sb_hg   = sb_out[HW-1:0];

  // ---- output stage: g = root − h (arc) or the side-band result ----
  // root − h ∈ (−2^S, 2^(CW+1)) (header): its low GW bits are the exact value.
  // The non-arc result is < 2^(CW−2) ≥ 0: GW bits of the field hold it.
  wire [HW:0]     g_arc_full = {1'b0, sq_root} - {1'b0, sb_hg};
  wire [GW-1:0]   g_arc      = g_arc_full[GW-1:0];
  wire [GW-1:0]   g_next     = sb_arc ? g_arc : sb_hg[GW-1:0];
  wire            unused_bits = ^{ww[2*TFrac-1], ww[TFrac-1:0], lw_p[TFrac-1:0], aw_p[TFrac-1:0],
                                  bw_p[TFrac-1:0], ab_p[TFrac-1:0], g_arc_full[HW:GW]};

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_o <= 1'b0;
    else         valid_o <= sq_valid;
  end
  always @(posedge clk_i) begin
    g_o   <= g_next;
    w_o   <= sb_w;
    ovf_o <= sb_ovf;
    tag_o <= sb_tag;
  end
endmodule

`default_nettype wire
