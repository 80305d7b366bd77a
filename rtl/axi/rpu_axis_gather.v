// rpu_axis_gather: an AXI4-Stream slave that gathers the beats of one record (RecW bits, beat 0
// holds bits 0..W-1, beat k bits kW..kW+W-1; the last beat's unused high bits are ignored) and
// offers the record on a valid/ready port with its final beat: Beats = ceil(RecW / W). The
// earlier beats are taken into a register (tready_o high); the final beat is taken only when
// the record is (tready_o = ready_i), so nothing is held twice and no cycle is lost. TLAST is
// read on the final beat only (last_o). clear_i drops a partly gathered record (a soft reset).
// Twin: the record packing of include/rpu_axi_regs.h (docs/axi.md); tested through rpu_axi.
`default_nettype none

module rpu_axis_gather #(
  parameter integer W    = 32,  // TDATA bits (8..1024)
  parameter integer RecW = 32   // record bits (>= 1)
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            clear_i,
  input  wire [W-1:0]    tdata_i,
  input  wire            tlast_i,
  input  wire            tvalid_i,
  output wire            tready_o,
  output wire            valid_o,
  input  wire            ready_i,
  output wire [RecW-1:0] rec_o,
  output wire            last_o
);
  localparam integer Beats = (RecW + W - 1) / W;
  initial begin
    if (W < 8 || RecW < 1) $fatal(1, "rpu_axis_gather: W must be >= 8 and RecW >= 1");
  end

  wire [Beats*W-1:0] all;
  wire               unused_pad;
  if (Beats == 1) begin : g_one
    assign tready_o = ready_i;
    assign valid_o  = tvalid_i;
    assign all      = tdata_i;
    wire unused_clk = ^{clk_i, rst_ni, clear_i};
  end else begin : g_many
    localparam integer CntW = $clog2(Beats);
    reg [CntW-1:0]        beat_q;
    reg [(Beats-1)*W-1:0] buf_q;
    localparam integer    LastBeatI = Beats - 1;
    localparam [CntW-1:0] LastBeat = LastBeatI[CntW-1:0];
    wire                  final_beat = beat_q == LastBeat;
    assign tready_o = final_beat ? ready_i : 1'b1;
    assign valid_o  = tvalid_i && final_beat;
    assign all      = {tdata_i, buf_q};
    always @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) beat_q <= '0;
      else if (clear_i) beat_q <= '0;
      else if (tvalid_i && tready_o) beat_q <= final_beat ? '0 : beat_q + 1'b1;
    end
    genvar k;
    for (k = 0; k < Beats - 1; k = k + 1) begin : g_beat
      localparam integer    BeatI = k;
      localparam [CntW-1:0] Beat = BeatI[CntW-1:0];
      always @(posedge clk_i) begin
        if (tvalid_i && beat_q == Beat) buf_q[k*W +: W] <= tdata_i;
      end
    end
  end
  assign rec_o  = all[RecW-1:0];
  assign last_o = tlast_i;
  if (Beats * W > RecW) begin : g_pad
    assign unused_pad = ^all[Beats*W-1:RecW];
  end else begin : g_nopad
    assign unused_pad = 1'b0;
  end
endmodule

`default_nettype wire
