// rpu_axis_scatter: a record (RecW bits) taken on a valid/ready port and handed out as an AXI4-
// Stream master in Beats = ceil(RecW / W) beats (beat 0 holds bits 0..W-1; the last beat's
// unused high bits are 0). TVALID, TDATA and TLAST come from flip-flops and the beat counter and
// hold still until taken; TLAST (last_i with the record) is set on its final beat only. A new
// record is taken as the final beat of the previous one leaves, so a one-beat record streams
// at one per cycle. Twin: the record packing of include/rpu_axi_regs.h (docs/axi.md); tested
// through rpu_axi, its handshake proved with rpu_axi's (scripts/formal.sh axi).
`default_nettype none

module rpu_axis_scatter #(
  parameter integer W    = 32,  // TDATA bits (8..1024)
  parameter integer RecW = 32   // record bits (>= 1)
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            valid_i,
  output wire            ready_o,
  input  wire [RecW-1:0] rec_i,
  input  wire            last_i,
  output wire [W-1:0]    tdata_o,
  output wire            tlast_o,
  output wire            tvalid_o,
  input  wire            tready_i,
  output wire            final_o    // the beat on TDATA is the record's last
);
  localparam integer Beats = (RecW + W - 1) / W;
  localparam integer CntW  = Beats > 1 ? $clog2(Beats) : 1;
  initial begin
    if (W < 8 || RecW < 1) $fatal(1, "rpu_axis_scatter: W must be >= 8 and RecW >= 1");
  end

  reg            full_q, last_q;
  reg [RecW-1:0] rec_q;
  reg [CntW-1:0] beat_q;
  localparam integer    LastBeatI = Beats - 1;
  localparam [CntW-1:0] LastBeat = LastBeatI[CntW-1:0];
  wire           final_beat = Beats == 1 || beat_q == LastBeat;
  wire           take = full_q && tready_i && final_beat;

  assign ready_o  = !full_q || take;
  assign tvalid_o = full_q;
  assign tlast_o  = last_q && final_beat;
  assign final_o  = final_beat;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      full_q <= 1'b0;
      beat_q <= '0;
    end else begin
      if (ready_o) full_q <= valid_i;
      if (full_q && tready_i) beat_q <= final_beat ? '0 : beat_q + 1'b1;
    end
  end
  always @(posedge clk_i) begin
    if (valid_i && ready_o) begin
      rec_q  <= rec_i;
      last_q <= last_i;
    end
  end

  wire [Beats*W-1:0] padded;
  if (Beats * W > RecW) begin : g_pad
    assign padded = {{(Beats * W - RecW){1'b0}}, rec_q};
  end else begin : g_nopad
    assign padded = rec_q;
  end
  if (Beats == 1) begin : g_one
    assign tdata_o = padded;
  end else begin : g_many
    assign tdata_o = padded[beat_q*W +: W];
  end
endmodule

`default_nettype wire
