// rpu_div: pipelined restoring divider, the twin of `rpu::fixed::udiv(num, den, QuotW)`:
//   quot_o = floor(num_i / den_i)  for unsigned operands, den_i != 0 and
//                                  num_i < den_i · 2^QuotW (the quotient fits; the caller
//                                  guarantees it by format, as the model checks it)
// One quotient bit per stage, most significant first: the partial remainder starts as
// num >> QuotW (< den by the precondition), each stage brings down the next dividend bit, compares
// with den and subtracts when not smaller. Fixed latency of QuotW cycles, one operand per cycle;
// `tag_i` rides along unchanged. The low QuotW dividend bits and the quotient share one shift
// register per stage: a dividend bit leaves at the top as a quotient bit enters at the bottom.
`default_nettype none

module rpu_div #(
  parameter integer NumW  = 10,  // dividend width in bits (1..127)
  parameter integer DenW  = 8,   // divisor width in bits (1..126)
  parameter integer QuotW = 10,  // quotient width in bits = pipeline stages (1..126)
  parameter integer TagW  = 1    // side-band bits carried with each operand (>= 1)
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             valid_i,
  input  wire [NumW-1:0]  num_i,
  input  wire [DenW-1:0]  den_i,
  input  wire [TagW-1:0]  tag_i,
  output wire             valid_o,
  output wire [QuotW-1:0] quot_o,
  output wire [TagW-1:0]  tag_o
);
  localparam integer HiW = NumW > QuotW ? NumW - QuotW : 1;  // bits of num >> QuotW (>= 1)

  initial begin
    if (NumW < 1 || NumW > 127) $fatal(1, "rpu_div: NumW must be in 1..127");
    if (DenW < 1 || DenW > 126) $fatal(1, "rpu_div: DenW must be in 1..126");
    if (QuotW < 1 || QuotW > 126) $fatal(1, "rpu_div: QuotW must be in 1..126");
    if (TagW < 1) $fatal(1, "rpu_div: TagW must be >= 1");
  end

  // Initial partial remainder rem0 = num >> QuotW (< den, so it fits DenW bits) and the low
  // QuotW dividend bits low0 (zero-padded when the dividend is narrower).
  wire [DenW-1:0]  rem0;
  wire [QuotW-1:0] low0;
  generate
    if (NumW <= QuotW) begin : g_narrow
      assign rem0 = {DenW{1'b0}};
      if (NumW < QuotW) begin : g_pad
        assign low0 = {{(QuotW - NumW){1'b0}}, num_i};
      end else begin : g_nopad
        assign low0 = num_i;
      end
    end else begin : g_wide
      wire [HiW-1:0] hi = num_i[NumW-1:QuotW];
      assign low0 = num_i[QuotW-1:0];
      if (HiW < DenW) begin : g_hi_ext
        assign rem0 = {{(DenW - HiW){1'b0}}, hi};
      end else if (HiW == DenW) begin : g_hi_same
        assign rem0 = hi;
      end else begin : g_hi_trunc
        // hi < den < 2^DenW: the bits above DenW are zero by the precondition.
        assign rem0 = hi[DenW-1:0];
        wire unused_hi = ^hi[HiW-1:DenW];
      end
    end
  endgenerate

  // Registered state after stage s lives in slot s (s = 0 .. QuotW-1), flattened. split_var
  // lets Verilator keep each slot a variable of its own (else every stage's write copies the
  // whole flattened vector: 20× slower simulation); synthesis ignores the comment.
  reg [QuotW*DenW-1:0]  rem_q /* verilator split_var */;  // partial remainder (< den)
  reg [QuotW*DenW-1:0]  den_q /* verilator split_var */;  // divisor
  reg [QuotW*QuotW-1:0] sh_q  /* verilator split_var */;  // dividend bits left (top), quotient (bottom)
  reg [QuotW*TagW-1:0]  tag_q /* verilator split_var */;
  reg [QuotW-1:0]       valid_q;

  genvar s;
  generate
    for (s = 0; s < QuotW; s = s + 1) begin : g_stage
      wire [DenW-1:0]  rem;
      wire [DenW-1:0]  den;
      wire [QuotW-1:0] sh;
      wire [TagW-1:0]  tag;
      wire             vld;
      if (s == 0) begin : g_first
        assign rem = rem0;
        assign den = den_i;
        assign sh  = low0;
        assign tag = tag_i;
        assign vld = valid_i;
      end else begin : g_next
        assign rem = rem_q[(s-1)*DenW +: DenW];
        assign den = den_q[(s-1)*DenW +: DenW];
        assign sh  = sh_q[(s-1)*QuotW +: QuotW];
        assign tag = tag_q[(s-1)*TagW +: TagW];
        assign vld = valid_q[s-1];
      end
      // Bring down the next dividend bit (the top of the shift register); subtract if not smaller.
      wire [DenW:0] cur  = {rem, sh[QuotW-1]};
      wire          take = cur >= {1'b0, den};
      wire [DenW:0] next = take ? cur - {1'b0, den} : cur;
      wire [QuotW-1:0] sh_next;
      if (QuotW > 1) begin : g_shift
        assign sh_next = {sh[QuotW-2:0], take};
      end else begin : g_single
        assign sh_next = take;
      end

      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) valid_q[s] <= 1'b0;
        else         valid_q[s] <= vld;
      end
      always @(posedge clk_i) begin
        rem_q[s*DenW +: DenW]    <= next[DenW-1:0];
        den_q[s*DenW +: DenW]    <= den;
        sh_q[s*QuotW +: QuotW]   <= sh_next;
        tag_q[s*TagW +: TagW]    <= tag;
      end
      // next < den fits DenW bits.
      wire unused_stage = next[DenW];
    end
  endgenerate

  // The last stage's remainder and divisor are not needed (synthesis drops them).
  wire unused_last = ^{rem_q[(QuotW-1)*DenW +: DenW], den_q[(QuotW-1)*DenW +: DenW]};

  assign valid_o = valid_q[QuotW-1];
  assign quot_o  = sh_q[(QuotW-1)*QuotW +: QuotW];
  assign tag_o   = tag_q[(QuotW-1)*TagW +: TagW];
endmodule

`default_nettype wire
