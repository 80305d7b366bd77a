// rpu_resolve: the pixel-resolve unit, twin of rpu::ref::Resolve. Takes the per-work-item
// results of one pixel after another (pixel order; `last_i` marks the last work item of a pixel)
// and emits one result per pixel when its last item arrives:
//   any_hit_o = some item of the pixel hit;
//   depth_o, primitive_o = the winning hit: the smaller depth (signed), on equal depth the
//   smaller primitive id (unsigned), exactly `Resolve::offer`; both 0 when no item hit.
// Items that do not hit are ignored (their depth and primitive are don't-care).
//
// Unlike the fixed-latency arithmetic units this is a valid/ready stream with real
// backpressure (`valid_i/ready_o` in, `valid_o/ready_i` out). The output is a skid register in
// the style of Forencich's verilog-axis axis_register (SKID) / PULP's spill_register: an output
// register plus one spill slot, so `valid_o`, the result fields and `ready_o` all come straight
// from flip-flops and no combinational path runs from `ready_i` to `ready_o`. Throughput is one
// work item per cycle while the consumer keeps up. `ready_o` is low only while the spill slot is
// full (the output register holds a result that is not taken and another result is waiting);
// it stalls non-last items too, which keeps `ready_o` a plain register.
`default_nettype none

module rpu_resolve #(
  parameter integer PixW   = 28,  // pixel index width (1..64), passed through
  parameter integer DepthW = 64,  // signed depth width, as rpu_capture's depth_o (2..128)
  parameter integer PrimW  = 16   // unsigned primitive id width (1..31)
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  // Work-item results, in pixel order.
  input  wire              valid_i,
  output wire              ready_o,
  input  wire [PixW-1:0]   pixel_i,
  input  wire              last_i,     // the last work item of this pixel
  input  wire              hit_i,
  input  wire [DepthW-1:0] depth_i,    // signed
  input  wire [PrimW-1:0]  primitive_i,
  // One result per pixel.
  output wire              valid_o,
  input  wire              ready_i,
  output wire [PixW-1:0]   pixel_o,
  output wire              any_hit_o,
  output wire [DepthW-1:0] depth_o,    // signed; 0 when !any_hit_o
  output wire [PrimW-1:0]  primitive_o // 0 when !any_hit_o
);
  localparam integer ResW = PixW + 1 + DepthW + PrimW;  // {pixel, any, depth, primitive}

  initial begin
    if (PixW < 1 || PixW > 64) $fatal(1, "rpu_resolve: PixW must be in 1..64");
    if (DepthW < 2 || DepthW > 128) $fatal(1, "rpu_resolve: DepthW must be in 2..128");
    if (PrimW < 1 || PrimW > 31) $fatal(1, "rpu_resolve: PrimW must be in 1..31");
  end

  // ---- the running best of the current pixel ----
  reg              any_q;     // a hit has been offered (the accumulator's valid bit)
  reg [DepthW-1:0] depth_q;   // meaningful only while any_q
  reg [PrimW-1:0]  prim_q;

  wire accept = valid_i && ready_o;

  // Resolve::offer: take the item if it hits and (nothing yet, or it is nearer, or as near with
  // a smaller id).
  wire signed [DepthW-1:0] d_new = depth_i;
  wire signed [DepthW-1:0] d_old = depth_q;
  wire nearer = d_new < d_old;
  wire take = hit_i && (!any_q || nearer || (d_new == d_old && primitive_i < prim_q));

  wire              best_any   = any_q || hit_i;
  wire [DepthW-1:0] best_depth = take ? depth_i : (any_q ? depth_q : {DepthW{1'b0}});
  wire [PrimW-1:0]  best_prim  = take ? primitive_i : (any_q ? prim_q : {PrimW{1'b0}});

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)     any_q <= 1'b0;
    else if (accept) any_q <= best_any && !last_i;  // a new pixel starts after its last item
  end
  always @(posedge clk_i) begin
    if (accept) begin
      depth_q <= best_depth;
      prim_q  <= best_prim;
    end
  end

  // ---- output skid register: out (visible) and spill (the one extra result) ----
  wire           push   = accept && last_i;     // a pixel's result is ready
  wire [ResW-1:0] result = {pixel_i, best_any, best_depth, best_prim};

  reg             out_valid_q, spill_valid_q;
  reg [ResW-1:0]  out_q, spill_q;

  // The spill slot is empty exactly when the unit can take an item (so ready_o is a register).
  assign ready_o = !spill_valid_q;

  wire out_free = ready_i || !out_valid_q;  // the output register can load this cycle

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_valid_q   <= 1'b0;
      spill_valid_q <= 1'b0;
    end else if (spill_valid_q) begin
      // Stalled (nothing accepted): drain the spill slot into the output register.
      if (ready_i) begin
        out_valid_q   <= 1'b1;
        spill_valid_q <= 1'b0;
      end
    end else if (out_free) begin
      out_valid_q <= push;
    end else if (push) begin
      spill_valid_q <= 1'b1;  // output held: park the new result
    end
  end
  always @(posedge clk_i) begin
    if (spill_valid_q) begin
      if (ready_i) out_q <= spill_q;
    end else if (out_free) begin
      if (push) out_q <= result;
    end else if (push) begin
      spill_q <= result;
    end
  end

  assign valid_o     = out_valid_q;
  assign pixel_o     = out_q[ResW-1 -: PixW];
  assign any_hit_o   = out_q[DepthW + PrimW];
  assign depth_o     = out_q[PrimW +: DepthW];
  assign primitive_o = out_q[0 +: PrimW];

`ifdef FORMAL
  // ---- formal properties (scripts/formal.sh, docs/verification.md) ----
  // Standalone (RPU_FORMAL_RESOLVE: this module is the proof's top) the reset is assumed at the
  // first cycle, every input is free, and an arbitrary pixel result is tracked through the skid
  // register. As rpu_top's submodule only the control properties are asserted (no datapath bit
  // enters that proof).
  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
`ifdef RPU_FORMAL_RESOLVE
  always @(*) if (!f_past_valid) assume(!rst_ni);
`endif
  // Pixel results owed: +1 per accepted last item, −1 per result taken at the output.
  reg  [1:0] f_owed;
  wire       f_out_take = valid_o && ready_i;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_owed <= 2'd0;
    else         f_owed <= f_owed + {1'b0, push} - {1'b0, f_out_take};
  end
  always @(*) begin
    if (!rst_ni) assert(!valid_o);
    if (rst_ni) begin
      // One pixel out per last item in: the results owed are exactly those held.
      assert(f_owed == {1'b0, out_valid_q} + {1'b0, spill_valid_q});
      assert(f_owed <= 2'd2);
      // The spill slot only holds a result behind the output register's.
      assert(!spill_valid_q || out_valid_q);
    end
  end
  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_ni) && rst_ni && $past(valid_o && !ready_i)) begin
      // AXI-Stream output: valid stays high, the result stable, until taken.
      assert(valid_o);
      assert(pixel_o == $past(pixel_o));
`ifdef RPU_FORMAL_RESOLVE
      assert(any_hit_o == $past(any_hit_o));
      assert(depth_o == $past(depth_o));
      assert(primitive_o == $past(primitive_o));
`endif
    end
  end
`ifdef RPU_FORMAL_RESOLVE
  // Tracked result: f_pick (free) chooses one pushed result; f_ahead counts the results in front
  // of it (0 or 1). It must reach the output unchanged, in order, and leave exactly once.
  (* anyseq *) wire f_pick;
  reg            f_track, f_done, f_ahead;
  reg [ResW-1:0] f_res;
  wire [ResW-1:0] f_out = {pixel_o, any_hit_o, depth_o, primitive_o};
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_track <= 1'b0;
      f_done  <= 1'b0;
    end else if (push && f_pick && !f_track && !f_done) begin
      f_track <= 1'b1;
      f_res   <= result;
      // In front: the results held, less the one taken this cycle.
      f_ahead <= (out_valid_q && !f_out_take) || spill_valid_q;
    end else if (f_track && f_out_take) begin
      if (!f_ahead) begin
        f_track <= 1'b0;
        f_done  <= 1'b1;
      end
      f_ahead <= 1'b0;
    end
  end
  always @(*) if (rst_ni) begin
    if (f_track) begin
      assert({1'b0, f_ahead} < f_owed);
      if (!f_ahead) assert(out_valid_q && f_out == f_res);
      else          assert(spill_valid_q && spill_q == f_res);
    end
    assert(!(f_track && f_done));
    // A pixel with no hit leaves all zero (the spill slot's condition is its invariant).
    if (valid_o && !any_hit_o) assert(depth_o == {DepthW{1'b0}} && primitive_o == {PrimW{1'b0}});
    if (spill_valid_q && !spill_q[DepthW + PrimW])
      assert(spill_q[DepthW + PrimW - 1:0] == {(DepthW + PrimW){1'b0}});
  end
  // Reachability: the spill slot in use (ready_o low), the tracked result out from the spill
  // slot, a pixel with a hit out.
  always @(*) if (rst_ni) begin
    cover(spill_valid_q && !ready_i);
    cover(f_done && !f_track && f_owed == 2'd0);
    cover(f_track && f_ahead && spill_valid_q);
    cover(valid_o && any_hit_o);
  end
`endif
`endif
endmodule

`default_nettype wire
