// rpu_mul: a pipelined exact multiplier p = a × b (both operands signed, or both unsigned), twin
// rpu::ref::mul_unit. The operands are split into tiles that fit one DSP48E1 (25 × 18 signed):
// chunks of ChunkA bits of a and ChunkB bits of b, unsigned, except that the top chunk of a signed
// operand carries the sign (so it may be one bit wider). Each tile product has an input register
// and a product register (the DSP's A/B and M or P registers: no logic between them); the
// shifted tile products are then summed by a binary adder tree with a register after every level.
// The sums are taken modulo 2^(AW+BW), which is exact because the product fits AW + BW bits.
//   Latency = 2 + ceil(log2(tiles)) cycles (rpu_mul_latency.vh), or more when asked, tiles = ceil(AW'/ChunkA) · ceil(BW'/ChunkB) with
//   AW' = AW − Signed, BW' = BW − Signed (e.g. 51 × 23 unsigned: 3 · 2 tiles, latency 5;
//   28 × 28 signed: 2 · 2 tiles, latency 4; 25 × 18 signed: one tile, latency 2).
// Narrow tiles (a chunk of at most LutTile bits) are shift-and-adds in LUTs (below), and with
// SwapSides the operands swap sides when that leaves fewer DSP48E1 tiles at the same tile count.
// One operand pair per cycle, no stall; `tag_i` comes out unchanged with the product (tag_o holds
// the last valid item's tag while valid_o is low).
`default_nettype none
// The default LutTile of every rpu_mul (docs/resources.md, "Narrow tiles"): a DSP48E1 per tile
// only where the tile is wider than this on both sides. A build may set it (+define+).
`ifndef RPU_MUL_LUT_TILE
`define RPU_MUL_LUT_TILE 4
`endif
// The default SwapSides: 0 (the operands keep their sides; 1 trades LUTs for DSP48E1 further).
`ifndef RPU_MUL_SWAP
`define RPU_MUL_SWAP 0
`endif

module rpu_mul #(
  parameter integer AW     = 25,  // width of a (2..126)
  parameter integer BW     = 18,  // width of b (2..126), AW + BW <= 128
  parameter integer Signed = 1,   // 1: a, b and p are two's complement; 0: unsigned
  parameter integer ChunkA = 24,  // unsigned bits of a per tile (2..24)
  parameter integer ChunkB = 17,  // unsigned bits of b per tile (2..17)
  parameter integer TagW   = 1,   // side-band bits (>= 1)
  parameter integer Latency = 0,  // 0: the natural latency; more: extra output registers
                                  // (to line up with a parallel path); never less
  parameter integer LutTile = `RPU_MUL_LUT_TILE,  // a tile with a chunk of at most this many
                                  // unsigned bits is a shift-and-add in LUTs, not a DSP48E1,
                                  // when the product has more than one tile (0: never)
  parameter integer SwapSides = `RPU_MUL_SWAP,  // 1: the operands swap sides when that leaves
                                  // fewer DSP48E1 tiles at the same tile count (latency)
  // Derived (do not override).
  parameter integer PW     = AW + BW
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            valid_i,
  input  wire [AW-1:0]   a_i,
  input  wire [BW-1:0]   b_i,
  input  wire [TagW-1:0] tag_i,
  output wire            valid_o,
  output wire [PW-1:0]   p_o,
  output wire [TagW-1:0] tag_o
);
`include "rpu_mul_latency.vh"
  // DSP48E1 tiles of an aw × bw product (a's chunks on the DSP's A port): the tiles whose chunks
  // both have more than lt bits, or the one tile of a one-tile product.
  function integer rpu_mul_dsp_tiles(input integer aw, input integer bw, input integer s,
                                     input integer ca, input integer cb, input integer lt);
    integer na, nb, ia, ib, wa, wb, cnt;
    begin
      na = (aw - s + ca - 1) / ca;
      nb = (bw - s + cb - 1) / cb;
      cnt = 0;
      for (ia = 0; ia < na; ia = ia + 1)
        for (ib = 0; ib < nb; ib = ib + 1) begin
          wa = ia == na - 1 ? aw - s - ca * (na - 1) : ca;
          wb = ib == nb - 1 ? bw - s - cb * (nb - 1) : cb;
          if (na * nb == 1 || (wa > lt && wb > lt)) cnt = cnt + 1;
        end
      rpu_mul_dsp_tiles = cnt;
    end
  endfunction
  localparam integer NA      = (AW - Signed + ChunkA - 1) / ChunkA;
  localparam integer NB      = (BW - Signed + ChunkB - 1) / ChunkB;
  localparam integer T       = NA * NB;
  // With SwapSides, the operands swap sides (b's chunks on the DSP's A port) when that gives as
  // many tiles (so the same latency) but fewer DSP48E1: e.g. 34 × 28 signed, 4 DSP48E1 as it
  // stands, is 2 DSP and 2 narrow tiles swapped (28's top chunk of 3 bits on the A side).
  localparam integer SNA     = (BW - Signed + ChunkA - 1) / ChunkA;
  localparam integer SNB     = (AW - Signed + ChunkB - 1) / ChunkB;
  localparam integer Swap    = SwapSides != 0 && SNA * SNB == T &&
                               rpu_mul_dsp_tiles(BW, AW, Signed, ChunkA, ChunkB, LutTile) <
                               rpu_mul_dsp_tiles(AW, BW, Signed, ChunkA, ChunkB, LutTile) ? 1 : 0;
  localparam integer UW      = Swap != 0 ? BW : AW;  // the operand on the tiles' A side
  localparam integer VW      = Swap != 0 ? AW : BW;  // ... and on their B side
  localparam integer NU      = Swap != 0 ? SNA : NA;
  localparam integer NV      = Swap != 0 ? SNB : NB;
  localparam integer Natural = `RPU_MUL_LATENCY(AW, BW, Signed, ChunkA, ChunkB);
  localparam integer Levels  = Natural - 2;
  localparam integer Lat     = Latency == 0 ? Natural : Latency;
  localparam integer Extra   = Lat - Natural;
  localparam integer Leaves  = 1 << Levels;      // the tree's width, padded with zero terms
  localparam integer TA     = ChunkA + 1;        // a tile's a operand, signed
  localparam integer TB     = ChunkB + 1;        // a tile's b operand, signed

  initial begin
    if (AW < 2 || AW > 126 || BW < 2 || BW > 126 || PW > 128)
      $fatal(1, "rpu_mul: AW, BW must be in 2..126 with AW + BW <= 128");
    if (Signed != 0 && Signed != 1) $fatal(1, "rpu_mul: Signed must be 0 or 1");
    if (ChunkA < 2 || ChunkA > 24 || ChunkB < 2 || ChunkB > 17)
      $fatal(1, "rpu_mul: ChunkA must be in 2..24 and ChunkB in 2..17");
    if (T > 64) $fatal(1, "rpu_mul: more than 64 tiles");
    if (Latency != 0 && Latency < Natural) $fatal(1, "rpu_mul: Latency below the natural one");
    if (LutTile < 0 || LutTile > 8) $fatal(1, "rpu_mul: LutTile must be in 0..8");
    if (SwapSides != 0 && SwapSides != 1) $fatal(1, "rpu_mul: SwapSides must be 0 or 1");
  end

  // Extra latency (Latency above the natural one) delays the operands before the tiles, so the
  // product leaves from the adder tree's last register (a flip-flop, never a shift-register LUT
  // that would feed the caller's logic from its slow output).
  wire [AW-1:0] a_d;
  wire [BW-1:0] b_d;
  generate
    if (Extra == 0) begin : g_direct
      assign a_d = a_i;
      assign b_d = b_i;
    end else begin : g_delay
      reg [Extra*(AW+BW)-1:0] d_q;
      if (Extra == 1) begin : g_one
        always @(posedge clk_i) d_q <= {a_i, b_i};
      end else begin : g_more
        always @(posedge clk_i) d_q <= {d_q[(Extra-1)*(AW+BW)-1:0], a_i, b_i};
      end
      assign {a_d, b_d} = d_q[Extra*(AW+BW)-1 -: AW+BW];
    end
  endgenerate

  // A narrow tile's product as a sum of shifted copies of the wide operand x, radix-4 Booth
  // recoded: y is the narrow operand, sign-extended from bit n (its chunk's n unsigned bits, then
  // the sign: 0 for all but a signed operand's top chunk). Digit j is
  // d_j = −2·y_(2j+1) + y_(2j) + y_(2j−1) ∈ {−2, …, 2} (y_(−1) = 0), and y = Σ d_j·4^j over
  // j ≤ n/2, so at most three terms for n ≤ 4: two adder levels within the cycle. The sum is
  // taken in the wide operand's width plus LutTile + 3 bits (the narrow operand's bits and sign,
  // two bits of headroom for the partial sums), then sign-extended: short carry chains. One
  // function per wide side (a's chunk: TA bits, b's: TB), as a function's widths are fixed.
  localparam integer NAx = TA + LutTile + 3, NBx = TB + LutTile + 3;
  localparam integer NWA = NAx < TA + TB ? NAx : TA + TB;  // sum width, a's chunk wide
  localparam integer NWB = NBx < TA + TB ? NBx : TA + TB;  // sum width, b's chunk wide
  function automatic signed [TA+TB-1:0] rpu_mul_narrow_wa(input signed [NWA-1:0] x,
                                                          input [TA+TB-1:0] y, input integer n);
    integer j;
    reg signed [NWA-1:0] acc, term;
    begin
      acc = {NWA{1'b0}};
      for (j = 0; j <= 4; j = j + 1)
        if (j <= n / 2) begin
          case ({y[2*j+1], y[2*j], j == 0 ? 1'b0 : y[2*j-1]})
            3'b001, 3'b010: term = x;
            3'b011:         term = x <<< 1;
            3'b100:         term = -(x <<< 1);
            3'b101, 3'b110: term = -x;
            default:        term = {NWA{1'b0}};
          endcase
          acc = acc + (term <<< (2 * j));
        end
      rpu_mul_narrow_wa = {(TA+TB){acc[NWA-1]}};  // sign-extended
      rpu_mul_narrow_wa[NWA-1:0] = acc;
    end
  endfunction
  function automatic signed [TA+TB-1:0] rpu_mul_narrow_wb(input signed [NWB-1:0] x,
                                                          input [TA+TB-1:0] y, input integer n);
    integer j;
    reg signed [NWB-1:0] acc, term;
    begin
      acc = {NWB{1'b0}};
      for (j = 0; j <= 4; j = j + 1)
        if (j <= n / 2) begin
          case ({y[2*j+1], y[2*j], j == 0 ? 1'b0 : y[2*j-1]})
            3'b001, 3'b010: term = x;
            3'b011:         term = x <<< 1;
            3'b100:         term = -(x <<< 1);
            3'b101, 3'b110: term = -x;
            default:        term = {NWB{1'b0}};
          endcase
          acc = acc + (term <<< (2 * j));
        end
      rpu_mul_narrow_wb = {(TA+TB){acc[NWB-1]}};  // sign-extended
      rpu_mul_narrow_wb[NWB-1:0] = acc;
    end
  endfunction

  // The operands on the tiles' sides (swapped or not), extended to whole chunks (sign or zero),
  // so every chunk slice is in range.
  wire [UW-1:0] u_d;
  wire [VW-1:0] v_d;
  generate
    if (Swap != 0) begin : g_swap
      assign u_d = b_d;
      assign v_d = a_d;
    end else begin : g_keep
      assign u_d = a_d;
      assign v_d = b_d;
    end
  endgenerate
  localparam integer AX = NU * ChunkA + 1;
  localparam integer BX = NV * ChunkB + 1;
  wire [AX-1:0] a_x = {{(AX - UW){Signed != 0 ? u_d[UW-1] : 1'b0}}, u_d};
  wire [BX-1:0] b_x = {{(BX - VW){Signed != 0 ? v_d[VW-1] : 1'b0}}, v_d};

  // ---- stage 1: tile operands (DSP A/B registers); stage 2: tile products (M/P registers) ----
  wire [PW-1:0] leaf [0:Leaves-1];
  genvar ia, ib, n;
  generate
    for (ia = 0; ia < NU; ia = ia + 1) begin : g_a
      for (ib = 0; ib < NV; ib = ib + 1) begin : g_b
        // The top chunk of a signed operand takes the extension bit as its sign; the others
        // are unsigned (a zero sign bit).
        wire top_a = Signed != 0 && ia == NU - 1;
        wire top_b = Signed != 0 && ib == NV - 1;
        reg signed [TA-1:0]    ta_q;
        reg signed [TB-1:0]    tb_q;
        reg signed [TA+TB-1:0] tp_q;
        always @(posedge clk_i) begin
          ta_q <= {top_a ? a_x[ia*ChunkA + ChunkA] : 1'b0, a_x[ia*ChunkA +: ChunkA]};
          tb_q <= {top_b ? b_x[ib*ChunkB + ChunkB] : 1'b0, b_x[ib*ChunkB +: ChunkB]};
        end
        // The chunks' unsigned bits: whole chunks, except the top one (what remains of the operand).
        localparam integer WA = ia == NU - 1 ? UW - Signed - ChunkA * (NU - 1) : ChunkA;
        localparam integer WB = ib == NV - 1 ? VW - Signed - ChunkB * (NV - 1) : ChunkB;
        if (T > 1 && WB <= LutTile && WB <= WA) begin : g_lut_b
          // b's chunk is narrow: the sum of a's chunk shifted by each bit of it, the sign bit
          // (of a top chunk of a signed b) with weight −2^WB.
          always @(posedge clk_i)
            tp_q <= rpu_mul_narrow_wa({{(NWA-TA){ta_q[TA-1]}}, ta_q}, {{TA{tb_q[TB-1]}}, tb_q}, WB);
        end else if (T > 1 && WA <= LutTile) begin : g_lut_a
          always @(posedge clk_i)
            tp_q <= rpu_mul_narrow_wb({{(NWB-TB){tb_q[TB-1]}}, tb_q}, {{TB{ta_q[TA-1]}}, ta_q}, WA);
        end else begin : g_dsp
          always @(posedge clk_i) tp_q <= ta_q * tb_q;
        end
        // The tile's weight 2^(ChunkA·ia + ChunkB·ib), the product sign-extended to PW bits
        // (bits at or above PW are dropped: the sums are modulo 2^PW).
        localparam integer Sh = ChunkA * ia + ChunkB * ib;
        localparam integer KeepW = PW - Sh;  // the product bits below 2^PW after the shift
        wire [PW+TA+TB-1:0] ext = {{PW{tp_q[TA+TB-1]}}, tp_q};
        wire [PW-1:0]       shifted;
        if (Sh >= PW) begin : g_out
          assign shifted = {PW{1'b0}};
        end else begin : g_in
          assign shifted = {ext[KeepW-1:0], {Sh{1'b0}}};
        end
        assign leaf[ia * NV + ib] = shifted;
        wire unused_ext = ^ext;
      end
    end
    for (n = T; n < Leaves; n = n + 1) begin : g_pad
      assign leaf[n] = {PW{1'b0}};
    end
  endgenerate

  // ---- stages 3 .. 2+Levels: the adder tree, a register after every level ----
  // node[0 .. Leaves-2] are the sums (heap order: node k = child 2k+1 + child 2k+2), the leaves
  // are node[Leaves-1 .. 2·Leaves-2].
  wire [PW-1:0] node [0:2*Leaves-2];
  generate
    for (n = 0; n < Leaves; n = n + 1) begin : g_leaf
      assign node[Leaves - 1 + n] = leaf[n];
    end
    for (n = 0; n < Leaves - 1; n = n + 1) begin : g_sum
      reg [PW-1:0] s_q;
      always @(posedge clk_i) s_q <= node[2*n + 1] + node[2*n + 2];
      assign node[n] = s_q;
    end
  endgenerate
  assign p_o = node[0];

  // ---- valid and tag, Lat stages ----
  // The tag's last stage is loaded only with a valid operand: a clock enable the stages before it
  // do not have, so it stays a flip-flop when Yosys packs the chain into shift-register LUTs.
  reg [Lat-1:0]  v_q;
  reg [TagW-1:0] tag_last_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) v_q <= {Lat{1'b0}};
    else         v_q <= {v_q[Lat-2:0], valid_i};
  end
  generate
    if (Lat == 1) begin : g_tag1
      always @(posedge clk_i) if (valid_i) tag_last_q <= tag_i;
    end else begin : g_tagn
      reg [(Lat-1)*TagW-1:0] tag_q;
      if (Lat == 2) begin : g_two
        always @(posedge clk_i) tag_q <= tag_i;
      end else begin : g_more
        always @(posedge clk_i) tag_q <= {tag_q[(Lat-2)*TagW-1:0], tag_i};
      end
      always @(posedge clk_i) if (v_q[Lat-2]) tag_last_q <= tag_q[(Lat-1)*TagW-1 -: TagW];
    end
  endgenerate
  assign valid_o = v_q[Lat-1];
  assign tag_o   = tag_last_q;
endmodule

`default_nettype wire
