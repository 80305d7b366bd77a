// rpu_sqrt: pipelined floor square root, non-restoring, one root digit (two radicand bits) per
// stage, with an optional static pre-shift that limits the radicand width (the model's
// `sqrt_unit`):
//   root_o = isqrt(rad_i >> 2S) << S,  S = 0 when SqrtW == 0 or RadW <= SqrtW,
//                                      else ceil((RadW - SqrtW) / 2)
// Fixed latency of Stages = ceil((RadW - 2S) / 2) cycles, one operand per cycle; `tag_i` rides
// along unchanged (side-band data of the enclosing pipeline). No backpressure inside: the
// enclosing stream reserves room before it issues (rpu_top).
//
// Non-restoring digit recurrence (Li and Chu): with Q the root so far and R the signed partial
// remainder (R = 0 before the first digit), each stage brings down the next two radicand bits d
// and forms
//   R' = 4R + d − (4Q + 1)   if R ≥ 0
//   R' = 4R + d + (4Q + 3)   if R < 0,           Q' = 2Q + (R' ≥ 0).
// R' is exactly the restoring recurrence's trial difference (current remainder − (4Q + 1)), so the
// digits are those of the floor square root and Q needs no final correction (only R would, and R
// is not an output). One adder per stage, its subtract/add choice the sign of the registered R:
// no compare and no restore multiplexer. Widths grow with the stage: after stage s (0-based)
// Q' has s+1 bits and −(2Q'+1) ≤ R' ≤ 2Q', so R' fits s+3 signed bits; the stage computes modulo
// 2^(s+3), dropping the top bit of 4R + d (exact, because the true R' fits). Only the radicand
// bits not yet consumed ride on.
`default_nettype none

module rpu_sqrt #(
  parameter integer RadW  = 58,  // radicand width in bits (3..126)
  parameter integer SqrtW = 0,   // widest radicand the digit pipeline takes; 0 = exact (16..126)
  parameter integer TagW  = 1,   // side-band bits carried with each operand (>= 1)
  // Derived (do not override).
  parameter integer Shift = (SqrtW == 0 || RadW <= SqrtW) ? 0 : (RadW - SqrtW + 1) / 2,
  parameter integer Stages = (RadW - 2 * Shift + 1) / 2,
  parameter integer RootW = Stages + Shift
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             valid_i,
  input  wire [RadW-1:0]  rad_i,
  input  wire [TagW-1:0]  tag_i,
  output wire             valid_o,
  output wire [RootW-1:0] root_o,
  output wire [TagW-1:0]  tag_o
);
  localparam integer EffW = RadW - 2 * Shift;  // radicand bits after the pre-shift
  localparam integer PadW = 2 * Stages;        // padded to whole digits
  // Registered state of stage s (s = 0 .. Stages-1) in triangular slots, packed end to end:
  //   remainder R'  s+3 bits at RemOff(s) = s(s+5)/2           (not kept after the last stage)
  //   root Q'       s+1 bits at RootOff(s) = s(s+1)/2
  //   radicand rest 2(Stages-1-s) bits at RadOff(s) = 2s(Stages-1) - s(s-1) (none after the last)
  localparam integer RemTotW  = (Stages - 1) * (Stages + 4) / 2;
  localparam integer RootTotW = Stages * (Stages + 1) / 2;
  localparam integer RadTotW  = (Stages - 1) * Stages;

  initial begin
    if (RadW < 3 || RadW > 126) $fatal(1, "rpu_sqrt: RadW must be in 3..126");
    if (SqrtW != 0 && (SqrtW < 16 || SqrtW > 126)) $fatal(1, "rpu_sqrt: SqrtW must be 0 or 16..126");
    if (TagW < 1) $fatal(1, "rpu_sqrt: TagW must be >= 1");
  end

  // The pre-shifted radicand, zero-padded to PadW bits.
  wire [PadW-1:0] rad_in;
  generate
    if (PadW > EffW) begin : g_pad
      assign rad_in = {1'b0, rad_i[RadW-1:2*Shift]};
    end else begin : g_nopad
      assign rad_in = rad_i[RadW-1:2*Shift];
    end
    if (Shift > 0) begin : g_dropped
      wire unused_dropped = ^rad_i[2*Shift-1:0];
    end
  endgenerate

  // split_var lets Verilator keep each slot a variable of its own (else every stage's write
  // copies the whole flattened vector: 20× slower simulation); synthesis ignores the comment.
  reg [RemTotW-1:0]     rem_q  /* verilator split_var */;
  reg [RootTotW-1:0]    root_q /* verilator split_var */;
  reg [RadTotW-1:0]     rad_q  /* verilator split_var */;
  reg [Stages*TagW-1:0] tag_q  /* verilator split_var */;
  reg [Stages-1:0]      valid_q;

  genvar s;
  generate
    for (s = 0; s < Stages; s = s + 1) begin : g_stage
      localparam integer W       = s + 3;                  // this stage's remainder width
      localparam integer RadInW  = 2 * (Stages - s);       // radicand bits not yet consumed
      localparam integer RemOff  = s * (s + 5) / 2;
      localparam integer RootOff = s * (s + 1) / 2;
      localparam integer RadOff  = 2 * s * (Stages - 1) - s * (s - 1);
      wire [RadInW-1:0] rad;
      wire [TagW-1:0]   tag;
      wire              vld;
      wire [W-1:0]      next;   // R' modulo 2^W (exact)
      wire              digit;  // R' >= 0
      wire [s:0]        root;   // Q' = {Q, digit}
      if (s == 0) begin : g_first
        // R = 0, Q = 0: R' = d − 1.
        assign rad  = rad_in;
        assign tag  = tag_i;
        assign vld  = valid_i;
        assign next = {1'b0, rad[RadInW-1 -: 2]} - 3'd1;
        assign root = digit;
      end else begin : g_next
        wire [W-2:0] rem_prev  = rem_q[RemOff-(W-1) +: W-1];  // R, s+2 bits signed
        wire [s-1:0] root_prev = root_q[RootOff-s +: s];      // Q, s bits
        wire         neg       = rem_prev[W-2];
        // 4R + d, modulo 2^W (R's sign bit drops out).
        wire [W-1:0] cur       = {rem_prev[W-3:0], rad[RadInW-1 -: 2]};
        // R ≥ 0: cur − (4Q + 1) = cur + ~{0, Q, 0, 1} + 1;  R < 0: cur + {0, Q, 1, 1}.
        wire         sub       = ~neg;
        wire [W-1:0] addend    = {{1'b0, root_prev} ^ {(s + 1){sub}}, 1'b1, neg};
        assign rad  = rad_q[RadOff-RadInW +: RadInW];
        assign tag  = tag_q[(s-1)*TagW +: TagW];
        assign vld  = valid_q[s-1];
        assign next = cur + addend + {{(W - 1){1'b0}}, sub};
        assign root = {root_prev, digit};
      end
      assign digit = ~next[W-1];

      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) valid_q[s] <= 1'b0;
        else         valid_q[s] <= vld;
      end
      always @(posedge clk_i) begin
        root_q[RootOff +: s + 1] <= root;
        tag_q[s*TagW +: TagW]    <= tag;
      end
      if (s < Stages - 1) begin : g_carry
        // The digit stage s+1 reads is loaded only with a valid operand (a clock enable the
        // earlier hops of those two bits do not have): Yosys packs the earlier hops into an SRL
        // but keeps this one a flip-flop, so stage s+1's adder starts at a flip-flop (an SRL's
        // clock-to-out is 1.2 ns slower). Without an operand the digit is a don't-care.
        always @(posedge clk_i) begin
          rem_q[RemOff +: W] <= next;
          if (vld) rad_q[RadOff + RadInW - 4 +: 2] <= rad[RadInW-3 -: 2];
        end
        if (RadInW > 4) begin : g_rest
          always @(posedge clk_i) rad_q[RadOff +: RadInW - 4] <= rad[RadInW-5:0];
        end
      end else begin : g_last
        // The last stage needs only the sign of R'.
        wire unused_last = ^next[W-2:0];
      end
    end
  endgenerate

  assign valid_o = valid_q[Stages-1];
  assign tag_o   = tag_q[(Stages-1)*TagW +: TagW];
  generate
    if (Shift > 0) begin : g_shift
      assign root_o = {root_q[RootTotW-Stages +: Stages], {Shift{1'b0}}};
    end else begin : g_noshift
      assign root_o = root_q[RootTotW-Stages +: Stages];
    end
  endgenerate
endmodule

`default_nettype wire
