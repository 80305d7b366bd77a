// rpu_fifo: a first-word-fall-through FIFO whose storage has a registered (synchronous) read, so
// that Yosys maps it into block RAM (RAMB18/36) instead of LUT RAM, and whose output comes
// straight from that read register. Twin: rpu::ref::Fifo (ref/model/common/rpu_fifo.h), a plain queue.
//
// Storage: 2^Log2Depth entries plus the output register (capacity 2^Log2Depth + 1). An entry
// written at cycle c is in the memory after edge c; the memory is read into the output register
// when the register is empty or being taken, so the entry is at rd_data_o from cycle c + 2 (two
// cycles of write-to-read latency, none of throughput: one write and one read per cycle).
// A read never addresses the entry written in the same cycle (the memory is read only when it
// already held an entry before the cycle), so no read-during-write behaviour is relied on.
//
// Handshakes: wr_valid_i/wr_ready_o (ready = the memory is not full) and rd_valid_o/rd_ready_i
// (AXI-Stream rules: rd_valid_o and rd_data_o stay unchanged until taken). rd_valid_o and
// rd_data_o are flip-flops; wr_ready_o is a compare of the pointer registers. The callers in
// this design admit items by credits and never write when wr_ready_o is low; a write while full
// is dropped.
`default_nettype none

module rpu_fifo #(
  parameter integer Width     = 8,  // entry width (1..4096)
  parameter integer Log2Depth = 8   // log2 of the memory depth (1..16)
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             wr_valid_i,
  output wire             wr_ready_o,
  input  wire [Width-1:0] wr_data_i,
  output wire             rd_valid_o,
  input  wire             rd_ready_i,
  output wire [Width-1:0] rd_data_o
`ifdef FORMAL
  ,
  // Formal only (rpu_top's invariants over its queues): the entries held, and entry p from the
  // head (p = 0: the next read) at [p*Width +: Width], meaningful for p < f_count_o.
  output wire [Log2Depth+1:0]                f_count_o,
  output wire [((1<<Log2Depth)+1)*Width-1:0] f_entries_o
`endif
);
  localparam integer Depth = 1 << Log2Depth;

  initial begin
    if (Width < 1 || Width > 4096) $fatal(1, "rpu_fifo: Width must be in 1..4096");
    if (Log2Depth < 1 || Log2Depth > 16) $fatal(1, "rpu_fifo: Log2Depth must be in 1..16");
  end

  reg [Width-1:0]     mem_q [0:Depth-1];
  reg [Log2Depth:0]   wr_q, rd_q;   // memory pointers, one wrap bit
  reg                 out_valid_q;
  reg [Width-1:0]     out_q;

  wire [Log2Depth:0] fill = wr_q - rd_q;
  wire mem_any = wr_q != rd_q;
  wire take    = out_valid_q && rd_ready_i;
  wire load    = mem_any && (!out_valid_q || take);
  wire write   = wr_valid_i && wr_ready_o;
  assign wr_ready_o = fill != Depth[Log2Depth:0];

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wr_q        <= {(Log2Depth+1){1'b0}};
      rd_q        <= {(Log2Depth+1){1'b0}};
      out_valid_q <= 1'b0;
    end else begin
      if (write) wr_q <= wr_q + 1'b1;
      if (load)  rd_q <= rd_q + 1'b1;
      if (load)      out_valid_q <= 1'b1;
      else if (take) out_valid_q <= 1'b0;
    end
  end

  // The block-RAM template: a write port and a read port with enable, the read into a register.
  always @(posedge clk_i) begin
    if (write) mem_q[wr_q[Log2Depth-1:0]] <= wr_data_i;
    if (load)  out_q <= mem_q[rd_q[Log2Depth-1:0]];
  end

  assign rd_valid_o = out_valid_q;
  assign rd_data_o  = out_q;

`ifdef FORMAL
  // ---- formal properties (scripts/formal.sh, docs/verification.md) ----
  // Standalone (RPU_FORMAL_FIFO defined: this module is the proof's top): the reset is assumed
  // at the first cycle, writes and reads are arbitrary, and an arbitrary written entry is
  // tracked through the FIFO (order, data, exactly once). As a submodule only the control
  // properties are asserted (no data bit enters the proof) plus the callers' contract that no
  // write is offered while the memory is full.
  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
  // Entries held: the memory's plus the output register's.
  wire [Log2Depth+1:0] f_count = {1'b0, fill} + {{(Log2Depth+1){1'b0}}, out_valid_q};
  assign f_count_o = f_count;
  genvar f_p;
  generate
    for (f_p = 0; f_p <= Depth; f_p = f_p + 1) begin : g_f_entry
      // The output register holds entry 0 when valid; the memory the rest from slot rd_q.
      localparam [Log2Depth:0] P = f_p;
      wire [Log2Depth:0] slot = rd_q + P - {{Log2Depth{1'b0}}, out_valid_q};
      assign f_entries_o[f_p*Width +: Width] = (f_p == 0 && out_valid_q) ? out_q
                                             : mem_q[slot[Log2Depth-1:0]];
    end
  endgenerate
`ifdef RPU_FORMAL_FIFO
  always @(*) if (!f_past_valid) assume(!rst_ni);
`endif
  always @(*) begin
    if (!rst_ni) assert(!rd_valid_o);
    // The fill count never over- or underflows (the read pointer never passes the write one).
    assert(fill <= Depth[Log2Depth:0]);
    assert(mem_any == (fill != {(Log2Depth+1){1'b0}}));
  end
`ifndef RPU_FORMAL_FIFO
  // The callers (credit-counted, rpu_top and rpu_ip) never offer a write while full.
  always @(*) if (rst_ni) assert(!wr_valid_i || wr_ready_o);
`endif
  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_ni) && rst_ni) begin
      // AXI-Stream read side: valid stays high, and the data stable, until taken.
      if ($past(rd_valid_o && !rd_ready_i)) begin
        assert(rd_valid_o);
`ifdef RPU_FORMAL_FIFO
        assert(rd_data_o == $past(rd_data_o));
`endif
      end
      // Entries come and go only by handshakes.
      assert(f_count == $past(f_count) + {{(Log2Depth+1){1'b0}}, $past(write)}
                                       - {{(Log2Depth+1){1'b0}}, $past(take)});
    end
  end
`ifdef RPU_FORMAL_FIFO
  // Tracked entry: f_pick (free input) chooses one accepted write; f_ahead counts the entries
  // in front of it. Each read takes the entry in front, so the tracked entry must leave exactly
  // when f_ahead is 0, with its data, and once. Every write can be the tracked one, so this is
  // "the k-th read returns the k-th accepted write" for every k within the depth.
  (* anyseq *) wire f_pick;
  reg                 f_track, f_done;
  reg [Width-1:0]     f_data;
  reg [Log2Depth+1:0] f_ahead;
  wire f_start = write && f_pick && !f_track && !f_done;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_track <= 1'b0;
      f_done  <= 1'b0;
    end else if (f_start) begin
      f_track <= 1'b1;
      f_ahead <= f_count - {{(Log2Depth+1){1'b0}}, take};
      f_data  <= wr_data_i;
    end else if (f_track && take) begin
      if (f_ahead == {(Log2Depth+2){1'b0}}) begin
        f_track <= 1'b0;
        f_done  <= 1'b1;
      end
      f_ahead <= f_ahead - 1'b1;
    end
  end
  // Where the tracked entry is: the output register when first, else memory slot
  // rd_q + ahead (− 1 if the output register holds the entry in front).
  wire [Log2Depth+1:0] f_slot = {1'b0, rd_q} + f_ahead
                                - {{(Log2Depth+1){1'b0}}, out_valid_q};
  always @(*) begin
    if (rst_ni && f_track) begin
      assert(f_ahead < f_count);
      if (out_valid_q && f_ahead == {(Log2Depth+2){1'b0}}) assert(out_q == f_data);
      else assert(mem_q[f_slot[Log2Depth-1:0]] == f_data);
      // Taken with its data when it is first.
      if (take && f_ahead == {(Log2Depth+2){1'b0}}) assert(rd_data_o == f_data);
    end
    if (rst_ni) assert(!(f_track && f_done));
  end
  // Reachability: a full FIFO (memory and output register), the tracked entry behind two
  // others, the tracked entry read out, and read while a write comes in.
  always @(*) if (rst_ni) begin
    cover(fill == Depth[Log2Depth:0] && out_valid_q);
    cover(f_track && f_ahead == 2);
    cover(f_done);
    cover(f_track && take && write && f_ahead == {(Log2Depth+2){1'b0}});
  end
`endif
`endif
endmodule

`default_nettype wire
