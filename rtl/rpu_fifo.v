// rpu_fifo: a first-word-fall-through FIFO whose storage has a registered (synchronous) read, so
// that Yosys maps it into block RAM (RAMB18/36) instead of LUT RAM, and whose output comes
// straight from that read register. Twin: rpu::ref::Fifo (ref/model/rpu_fifo.h), a plain queue.
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
endmodule

`default_nettype wire
