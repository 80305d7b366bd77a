// rpu_guide_pair: both guide offsets g_1(t), g_2(t) of the closed-form curve at one t (the
// model's `guide_weight`, then `guide_unit` for each guide), with the work both share done once:
//   w  = floor(tc·(2^FT − tc) / 2^FT),  tc = clamp(t, 0, 2^FT)             Q(0.FT), ≤ 1/4
//   lw = floor(L2·w / 2^FT)                                                 (one product for both)
//   per guide k, by its mode:
//   arc      (1): g = sqrt_unit(h² + lw) − h   (RadW = 2·CW+10 radicand, saturated to RadW bits
//                 (sets ovf_o), then rpu_sqrt with its SqrtW pre-shift)
//   flat     (2): g = aw − floor(aw·bw / 2^FT), aw = floor(a·w / 2^FT), bw = floor(b·w / 2^FT)
//   straight (0, and the unused code 3): g = 0
// h² is a per-segment constant: with HhIn = 1 the caller supplies it (hh1_i, hh2_i = h1², h2²,
// computed once per pair; rpu_ip does), so a candidate evaluator multiplies no h; with
// HhIn = 0 the unit squares h itself in stage 2 and hh*_i are ignored.
// The arc's h, or the finished flat/straight result, rides through each square root's side band
// (one field), so every mode has the same fixed latency: Latency = 3 + Stages(rpu_sqrt) + 1
// cycles (33 at the defaults, 24 with SqrtW = 40). One operand per cycle, no stall; `tag_i`
// comes out unchanged with the results (a tag of 32 bits or more through an rpu_tag_queue beside
// the stages).
//
// g is signed: with a pre-shifted square root (SqrtW > 0) the root may fall below h, so the arc
// gives g ∈ (−2^S, 0] where the exact g is 0 (S = the pre-shift; docs/fixed-point.md bound).
// Over every port value g ∈ (−2^S, 2^(CW+1)) (g ≤ sqrt(floor(L2·w)) < 2^(CW+1/2)), which fits
// CW+2 signed bits since S ≤ CW−3; within the descriptor formats g ≤ L/2 < 2^CW.
`default_nettype none
`include "rpu_latency_check.vh"
`include "rpu_widths.vh"

module rpu_guide_pair #(
  parameter integer CoordW = 24,  // CW: signed width of positions (12..40)
  parameter integer TFrac  = 24,  // FT: fraction bits of t and w (8..48, 2·CW+3+FT <= 126)
  parameter integer SqrtW  = 0,   // widest radicand of the square root; 0 = exact (16..126)
  parameter integer HhIn   = 0,   // 1: h² comes in on hh1_i/hh2_i; 0: squared here
  parameter integer TagW   = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer TW   = `RPU_TW(TFrac),       // t: Q(3.FT), signed
  parameter integer WW   = TFrac - 1,       // w ≤ 2^(FT−2): FT−1 bits, unsigned
  parameter integer HW   = `RPU_HW(CoordW),      // h ≤ 16·L < 16·√3·2^CW < 2^(CW+5), unsigned
  parameter integer AW   = CoordW,          // a = L²/(2h) < L/32, unsigned
  parameter integer L2W  = `RPU_L2W(CoordW),  // L2 = |d|² ≤ 3·2^(2CW), unsigned
  parameter integer RadW = `RPU_GRADW(CoordW), // h², the radicand: guide_radicand_w()
  parameter integer GW   = `RPU_PRW(CoordW),      // g, signed (see above)
  parameter integer GsW  = `RPU_GSW(CoordW, TFrac) // a guide's shape (rpu_guide_shape.vh)
) (
  input  wire                   clk_i,
  input  wire                   rst_ni,
  input  wire                   valid_i,
  input  wire [TW-1:0]          t_i,     // chord parameter, Q(3.FT) signed
  input  wire [L2W-1:0]         l2_i,    // |d|², LSB²
  // A guide's shape {mode, h, a, b} (rpu_guide_shape.vh): mode 0 straight, 1 arc, 2 flat (3 acts
  // as straight); h, LSB (arc); a = L²/(2h), LSB, and b = L²/(4h²), Q(0.FT) (flat).
  input  wire [GsW-1:0]         g1_i,
  input  wire [RadW-1:0]        hh1_i,   // h1², LSB² (HhIn = 1)
  input  wire [GsW-1:0]         g2_i,
  input  wire [RadW-1:0]        hh2_i,
  input  wire [TagW-1:0]        tag_i,
  output wire                   valid_o,
  output wire signed [GW-1:0]   g1_o,    // guide offsets, LSB
  output wire signed [GW-1:0]   g2_o,
  output wire [WW-1:0]          w_o,     // w = tc·(1 − tc), Q(0.FT)
  output wire                   ovf_o,   // an arc's radicand saturated (sticky bit of the pair)
  output wire [TagW-1:0]        tag_o
);
  // rpu_sqrt's derived widths (the same formulas; RadW is even, so its RootW equals HW).
  localparam integer SqShift  = (SqrtW == 0 || RadW <= SqrtW) ? 0 : (RadW - SqrtW + 1) / 2;
  localparam integer SqStages = (RadW - 2 * SqShift + 1) / 2;
  localparam integer RootW    = SqStages + SqShift;
  localparam integer LwW      = L2W + WW - TFrac;    // floor(L2·w): 2·CW+2 bits (< 2^(2CW+1))
  localparam integer AwW      = AW + WW - TFrac;     // floor(a·w): CW−1 bits (< 2^(CW−2))
  localparam integer AbW      = AwW + WW - TFrac;    // floor(aw·bw): CW−2 bits (< 2^(CW−4))

  initial begin
    if (CoordW < 12 || CoordW > 40) $fatal(1, "rpu_guide_pair: CoordW must be in 12..40");
    if (TFrac < 8 || TFrac > 48) $fatal(1, "rpu_guide_pair: TFrac must be in 8..48");
    if (2 * CoordW + 3 + TFrac > 126)
      $fatal(1, "rpu_guide_pair: 2*CoordW+3+TFrac must be <= 126");
    if (HhIn != 0 && HhIn != 1) $fatal(1, "rpu_guide_pair: HhIn must be 0 or 1");
    if (TagW < 1) $fatal(1, "rpu_guide_pair: TagW must be >= 1");
    if (RootW != HW) $fatal(1, "rpu_guide_pair: internal: root width differs from h width");
  end

`include "rpu_mul_latency.vh"
`include "rpu_guide_shape.vh"
  // The multipliers' latencies. The flat path (aw and bw, then aw·bw) and the arc path (lw,
  // then one register for the radicand) meet at the roots: the shorter is padded (rpu_mul's
  // Latency parameter).
  localparam integer LatW    = `RPU_MUL_LAT(TFrac, TFrac, 0);
  localparam integer LatLw   = `RPU_MUL_LAT(L2W, WW, 0);
  localparam integer LatAw   = `RPU_MUL_LAT(AW, WW, 0);
  localparam integer LatBw   = `RPU_MUL_LAT(TFrac, WW, 0);
  localparam integer LatAb   = `RPU_MUL_LAT(AwW, WW, 0);
  localparam integer LatHh   = `RPU_MUL_LAT(HW, HW, 0);
  localparam integer LatAwBw = LatAw > LatBw ? LatAw : LatBw;
  localparam integer LatProd = (LatAwBw + LatAb > LatLw ? LatAwBw + LatAb : LatLw) + 1;
  // The unit's latency (what the testbenches and the enclosing units count on).
  localparam integer Latency = LatW + LatProd + SqStages + 1;
  // The caller's tag: a wide one waits in a queue (rpu_tag_queue), the stages carry PTagW bits.
  localparam integer PTagW = `RPU_PTAGW(TagW);

  initial begin
    if (HhIn == 0 && LatHh > LatW + LatProd - 1)
      $fatal(1, "rpu_guide_pair: internal: h² arrives after the radicand sum");
    if (GsW != GsWords) $fatal(1, "rpu_guide_pair: GsW is derived; do not override it");
  end

  // ---- w = floor(tc·(2^FT − tc) / 2^FT) ----
  // tc = clamp(t, 0, 2^FT). Both ends give w = 0, so only x = tc mod 2^FT matters: x = t for
  // 0 ≤ t < 2^FT, else 0; and (2^FT − tc) mod 2^FT = (−x) mod 2^FT (x = 0 → product 0 either way).
  wire             t_neg  = t_i[TW-1];
  wire             t_big  = ~t_neg & (|t_i[TW-2:TFrac]);  // t ≥ 2^FT
  wire [TFrac-1:0] x      = (t_neg | t_big) ? {TFrac{1'b0}} : t_i[TFrac-1:0];
  wire [TFrac-1:0] x_comp = -x;
  wire [HW-1:0]    h1     = g1_i[GsHO +: GsHW];
  wire [HW-1:0]    h2     = g2_i[GsHO +: GsHW];
  // What the rest needs rides in the w multiplier's tag: {tag, L2, per guide {mode, h, a, b}};
  // h² (HhIn = 1) likewise.
  localparam integer GIn   = GsW;
  localparam integer HhTW  = HhIn != 0 ? 2 * RadW : 1;
  // w's tag, LSB first: {tag, L2, guide 1, guide 2, h²}.
  localparam integer WtG1O  = HhTW + GIn;
  localparam integer WtL2O  = HhTW + 2 * GIn;
  localparam integer WtTagO = WtL2O + L2W;
  localparam integer WTagW  = WtTagO + PTagW;
  wire [PTagW-1:0]   ptag_in, ptag_out;
  rpu_tag_queue #(.TagW(TagW), .Latency(Latency)) u_tagq (
    .clk_i, .rst_ni, .valid_i, .tag_i, .ptag_o(ptag_in), .out_valid_i(valid_o), .ptag_i(ptag_out),
    .tag_o);
  wire [HhTW-1:0]    hh_in;
  generate
    if (HhIn != 0) begin : g_hh_tag
      assign hh_in = {hh1_i, hh2_i};
      wire unused_h = ^{h1, h2};  // h² comes in: h is only read from the shape's tag
    end else begin : g_no_hh_tag
      assign hh_in = 1'b0;
    end
  endgenerate
  wire               w_valid;
  wire [2*TFrac-1:0] ww;
  wire [WTagW-1:0]   w_tag;
  rpu_mul #(.AW(TFrac), .BW(TFrac), .Signed(0), .TagW(WTagW)) u_w (
    .clk_i, .rst_ni, .valid_i, .a_i(x), .b_i(x_comp),
    .tag_i({ptag_in, l2_i, g1_i, g2_i, hh_in}),
    .valid_o(w_valid), .p_o(ww), .tag_o(w_tag));
  // ww ≤ 2^(2FT−2): bit 2FT−1 is zero; the low FT bits are the floor's dropped fraction.
  wire [WW-1:0]   w      = ww[2*TFrac-2:TFrac];
  wire [PTagW-1:0] tag_w = w_tag[WtTagO +: PTagW];
  wire [L2W-1:0]  l2_w   = w_tag[WtL2O +: L2W];
  wire [GIn-1:0]  gin_w [0:1];
  assign gin_w[0] = w_tag[WtG1O +: GIn];
  assign gin_w[1] = w_tag[HhTW +: GIn];
  wire [HhTW-1:0] hh_w   = w_tag[HhTW-1:0];

  // h² with HhIn = 0: squared from the ports beside w, then delayed to the radicand sum.
  wire [RadW-1:0] hh_sum [0:1];
  genvar k;

  // ---- lw = floor(L2·w / 2^FT), shared; w, tag, and per guide {mode, h} ride in its tag ----
  // lw's tag, LSB first: {tag, w, {mode, h} of guide 1 and 2, h²}.
  localparam integer LtWO   = HhTW + 2 * (2 + HW);
  localparam integer LtTagO = LtWO + WW;
  localparam integer LTagW  = LtTagO + PTagW;
  wire               lw_valid;
  wire [L2W+WW-1:0]  lw_p;
  wire [LTagW-1:0]   lw_tag;
  rpu_mul #(.AW(L2W), .BW(WW), .Signed(0), .TagW(LTagW), .Latency(LatProd - 1)) u_lw (
    .clk_i, .rst_ni, .valid_i(w_valid), .a_i(l2_w), .b_i(w),
    .tag_i({tag_w, w, gin_w[0][GIn-1 -: 2 + HW], gin_w[1][GIn-1 -: 2 + HW], hh_w}),
    .valid_o(lw_valid), .p_o(lw_p), .tag_o(lw_tag));
  wire [LwW-1:0]  lw      = lw_p[L2W+WW-1:TFrac];
  wire [PTagW-1:0] tag_l  = lw_tag[LtTagO +: PTagW];
  wire [WW-1:0]   w_l     = lw_tag[LtWO +: WW];
  wire [HhTW-1:0] hh_l    = lw_tag[HhTW-1:0];
  wire [1:0]      mode_l [0:1];
  wire [HW-1:0]   h_l    [0:1];
  assign {mode_l[0], h_l[0], mode_l[1], h_l[1]} = lw_tag[HhTW + 2*(2+HW) - 1 : HhTW];

  // ---- per guide: the radicand h² + lw (arc) and aw − floor(aw·bw) (flat) ----
  wire            valid_r;
  wire [WW-1:0]   w_r;
  wire [PTagW-1:0] tag_r;
  rpu_stage #(.W(WW + PTagW)) u_r (
    .clk_i, .rst_ni, .valid_i(lw_valid), .d_i({w_l, tag_l}), .valid_o(valid_r),
    .q_o({w_r, tag_r}));
  wire [1:0]      is_arc_r, ovf_r;
  wire [HW-1:0]   hg_r  [0:1];
  wire [RadW-1:0] rad_r [0:1];
  generate
    for (k = 0; k < 2; k = k + 1) begin : g_guide
      // h²: from the ports (HhIn = 1, through the tags) or squared here.
      if (HhIn != 0) begin : g_hh_in
        assign hh_sum[k] = hh_l[(1-k)*RadW +: RadW];
      end else begin : g_hh_sq
        wire [2*HW-1:0] hh_p;
        wire            hh_v_unused, hh_t_unused;
        // h enters with the operand and leaves LatW + LatProd − 1 cycles later, with lw.
        rpu_mul #(.AW(HW), .BW(HW), .Signed(0), .TagW(1), .Latency(LatW + LatProd - 1)) u_hh (
          .clk_i, .rst_ni, .valid_i, .a_i(k == 0 ? h1 : h2), .b_i(k == 0 ? h1 : h2),
          .tag_i(1'b0), .valid_o(hh_v_unused), .p_o(hh_p), .tag_o(hh_t_unused));
        assign hh_sum[k] = hh_p;
        wire unused_hh = ^{hh_v_unused, hh_t_unused};
      end

      // The arc: h² + lw, saturated to RadW bits. The sum is < 2^RadW + 2^(2CW+1) < 2^(RadW+1):
      // its top bit is the overflow.
      wire [RadW:0]   rad_sum = {1'b0, hh_sum[k]} + {{(RadW + 1 - LwW){1'b0}}, lw};
      wire            rad_ovf = rad_sum[RadW];
      reg [RadW-1:0]  rad_q;
      reg             ovf_q;
      reg [1:0]       mode_q;
      reg [HW-1:0]    h_q;
      always @(posedge clk_i) begin
        rad_q  <= rad_ovf ? {RadW{1'b1}} : rad_sum[RadW-1:0];
        ovf_q  <= rad_ovf;
        mode_q <= mode_l[k];
        h_q    <= h_l[k];
      end

      // The flat form: aw = floor(a·w), bw = floor(b·w), then floor(aw·bw); aw rides along.
      wire [GIn-1:0]      gk = gin_w[k];
      wire [AW-1:0]       a_k = gk[TFrac +: AW];
      wire [TFrac-1:0]    b_k = gk[TFrac-1:0];
      wire [AW+WW-1:0]    aw_p;
      wire [TFrac+WW-1:0] bw_p;
      wire                aw_v, bw_v_unused, aw_t_unused, bw_t_unused;
      rpu_mul #(.AW(AW), .BW(WW), .Signed(0), .TagW(1), .Latency(LatAwBw)) u_aw (
        .clk_i, .rst_ni, .valid_i(w_valid), .a_i(a_k), .b_i(w), .tag_i(1'b0),
        .valid_o(aw_v), .p_o(aw_p), .tag_o(aw_t_unused));
      rpu_mul #(.AW(TFrac), .BW(WW), .Signed(0), .TagW(1), .Latency(LatAwBw)) u_bw (
        .clk_i, .rst_ni, .valid_i(w_valid), .a_i(b_k), .b_i(w), .tag_i(1'b0),
        .valid_o(bw_v_unused), .p_o(bw_p), .tag_o(bw_t_unused));
      wire [AwW-1:0]      aw = aw_p[AW+WW-1:TFrac];
      wire [WW-1:0]       bw = bw_p[TFrac+WW-1:TFrac];  // b < 2^FT: bw < 2^(FT−2)
      wire [AwW+WW-1:0]   ab_p;
      wire [AwW-1:0]      aw_d;
      wire                ab_v_unused;
      rpu_mul #(.AW(AwW), .BW(WW), .Signed(0), .TagW(AwW), .Latency(LatProd - 1 - LatAwBw)) u_ab (
        .clk_i, .rst_ni, .valid_i(aw_v), .a_i(aw), .b_i(bw), .tag_i(aw),
        .valid_o(ab_v_unused), .p_o(ab_p), .tag_o(aw_d));
      wire [AbW-1:0]      ab = ab_p[AwW+WW-1:TFrac];
      // Flat: aw − floor(aw·bw) ≥ 0 (bw < 1/4); straight and code 3: 0. Overflow only counts
      // for the arc (the other modes do not use the radicand).
      reg [AwW-1:0]   flat_q;
      always @(posedge clk_i) flat_q <= aw_d - {{(AwW - AbW){1'b0}}, ab};
      wire            is_arc  = (mode_q == 2'd1);
      wire            is_flat = (mode_q == 2'd2);
      assign is_arc_r[k] = is_arc;
      assign ovf_r[k]    = is_arc & ovf_q;
      assign hg_r[k]     = is_arc ? h_q : {{(HW - AwW){1'b0}}, is_flat ? flat_q : {AwW{1'b0}}};
      assign rad_r[k]    = rad_q;
      wire unused_prod = ^{aw_p[TFrac-1:0], bw_p[TFrac-1:0], ab_p[TFrac-1:0],
                           bw_v_unused, aw_t_unused, bw_t_unused, ab_v_unused, gk[GIn-1:GIn-2-HW]};
    end
  endgenerate

  // ---- the two square roots; the rest rides in their side bands ----
  localparam integer Sb1W = PTagW + WW + 2 + HW;
  localparam integer Sb2W = 2 + HW;
  wire             sq1_valid, sq2_valid_unused;
  wire [RootW-1:0] root1, root2;
  wire [Sb1W-1:0]  sb1;
  wire [Sb2W-1:0]  sb2;
  rpu_sqrt #(.RadW(RadW), .SqrtW(SqrtW), .TagW(Sb1W)) u_sqrt1 (
    .clk_i, .rst_ni, .valid_i(valid_r), .rad_i(rad_r[0]),
    .tag_i({tag_r, w_r, is_arc_r[0], ovf_r[0], hg_r[0]}),
    .valid_o(sq1_valid), .root_o(root1), .tag_o(sb1));
  rpu_sqrt #(.RadW(RadW), .SqrtW(SqrtW), .TagW(Sb2W)) u_sqrt2 (
    .clk_i, .rst_ni, .valid_i(valid_r), .rad_i(rad_r[1]),
    .tag_i({is_arc_r[1], ovf_r[1], hg_r[1]}),
    .valid_o(sq2_valid_unused), .root_o(root2), .tag_o(sb2));

  wire [PTagW-1:0] sb_tag = sb1[Sb1W-1 -: PTagW];
  wire [WW-1:0]   sb_w   = sb1[HW+2 +: WW];

  // ---- output stage: g = root − h (arc) or the side-band result ----
  // root − h ∈ (−2^S, 2^(CW+1)) (header): its low GW bits are the exact value.
  // The non-arc result is < 2^(CW−2) ≥ 0: GW bits of the field hold it.
  wire [HW:0]   g1_arc_full = {1'b0, root1} - {1'b0, sb1[HW-1:0]};
  wire [HW:0]   g2_arc_full = {1'b0, root2} - {1'b0, sb2[HW-1:0]};
  wire [GW-1:0] g1_next = sb1[HW+1] ? g1_arc_full[GW-1:0] : sb1[GW-1:0];
  wire [GW-1:0] g2_next = sb2[HW+1] ? g2_arc_full[GW-1:0] : sb2[GW-1:0];
  wire unused_bits = ^{ww[2*TFrac-1], ww[TFrac-1:0], lw_p[TFrac-1:0], g1_arc_full[HW:GW],
                       g2_arc_full[HW:GW], sq2_valid_unused, hh_l, hh1_i, hh2_i};

  rpu_stage #(.W(2*GW + WW + 1 + PTagW)) u_out (
    .clk_i, .rst_ni, .valid_i(sq1_valid),
    .d_i({g1_next, g2_next, sb_w, sb1[HW] | sb2[HW], sb_tag}),
    .valid_o, .q_o({g1_o, g2_o, w_o, ovf_o, ptag_out}));
  `RPU_LATENCY_CHECK(Latency, "rpu_guide_pair")
endmodule

`default_nettype wire
