// rpu_sqrt: pipelined floor square root, digit by digit (two radicand bits per stage), with an
// optional static pre-shift that limits the radicand width (the model's `sqrt_unit`):
//   root_o = isqrt(rad_i >> 2S) << S,  S = 0 when SqrtW == 0 or RadW <= SqrtW,
//                                      else ceil((RadW - SqrtW) / 2)
// Fixed latency of Stages = ceil((RadW - 2S) / 2) cycles, one operand per cycle; `tag_i` rides
// along unchanged (side-band data of the enclosing pipeline). No backpressure inside: the
// enclosing stream reserves room before it issues (rpu_top).
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
  localparam integer RemW = Stages + 2;        // remainder < 2·root + 1 < 2^(Stages+1)

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

  // Registered state after stage s lives in slot s (s = 0 .. Stages-1), flattened. split_var
  // lets Verilator keep each slot a variable of its own (else every stage's write copies the
  // whole flattened vector: 20× slower simulation); synthesis ignores the comment.
  reg [Stages*PadW-1:0]   rad_q  /* verilator split_var */;
  reg [Stages*RemW-1:0]   rem_q  /* verilator split_var */;
  reg [Stages*Stages-1:0] root_q /* verilator split_var */;
  reg [Stages*TagW-1:0]   tag_q  /* verilator split_var */;
  reg [Stages-1:0]        valid_q;

  genvar s;
  generate
    for (s = 0; s < Stages; s = s + 1) begin : g_stage
      wire [PadW-1:0]   rad;
      wire [RemW-1:0]   rem;
      wire [Stages-1:0] root;
      wire [TagW-1:0]   tag;
      wire              vld;
      if (s == 0) begin : g_first
        assign rad  = rad_in;
        assign rem  = {RemW{1'b0}};
        assign root = {Stages{1'b0}};
        assign tag  = tag_i;
        assign vld  = valid_i;
      end else begin : g_next
        assign rad  = rad_q[(s-1)*PadW +: PadW];
        assign rem  = rem_q[(s-1)*RemW +: RemW];
        assign root = root_q[(s-1)*Stages +: Stages];
        assign tag  = tag_q[(s-1)*TagW +: TagW];
        assign vld  = valid_q[s-1];
      end
      // Bring down the next two radicand bits (most significant first); try 4·root + 1.
      wire [RemW+1:0] cur   = {rem, rad[PadW-1-2*s -: 2]};
      wire [RemW+1:0] trial = {{(RemW - Stages){1'b0}}, root, 2'b01};
      wire            take  = cur >= trial;
      wire [RemW+1:0] next  = take ? cur - trial : cur;

      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) valid_q[s] <= 1'b0;
        else         valid_q[s] <= vld;
      end
      always @(posedge clk_i) begin
        rad_q[s*PadW +: PadW]      <= rad;
        rem_q[s*RemW +: RemW]      <= next[RemW-1:0];
        root_q[s*Stages +: Stages] <= {root[Stages-2:0], take};
        tag_q[s*TagW +: TagW]      <= tag;
      end
      // next < 2·root + 1 fits RemW bits; the top of root is zero until the last stage.
      wire unused_stage = ^{next[RemW+1:RemW], root[Stages-1]};
    end
  endgenerate

  // The last stage's radicand and remainder are not needed (synthesis drops them).
  wire unused_last = ^{rad_q[(Stages-1)*PadW +: PadW], rem_q[(Stages-1)*RemW +: RemW]};

  assign valid_o = valid_q[Stages-1];
  assign tag_o   = tag_q[(Stages-1)*TagW +: TagW];
  generate
    if (Shift > 0) begin : g_shift
      assign root_o = {root_q[(Stages-1)*Stages +: Stages], {Shift{1'b0}}};
    end else begin : g_noshift
      assign root_o = root_q[(Stages-1)*Stages +: Stages];
    end
  endgenerate
endmodule

`default_nettype wire
