// rpu_surface_admit: admission of work items into a ring of fixed period that each item goes
// round a fixed number of times (the iterative rpu_surface_ip), from in front of a fixed-latency
// pipeline (rpu_surface_setup). An item admitted at cycle t enters the ring at t + D for any
// fixed D and comes back to the ring's input at t + D + j·Period, j = 1 .. Returns; a later item
// admitted at t' collides with it exactly when t' − t is one of those j·Period, whatever D is.
// So the unit mirrors the ring's occupancy at the admission point: a rotating register of Period
// counters, each the returns still due on its phase. ready_o = the phase now passing has none
// due (a compare of a register: no combinational path from the ring); an item offered while
// ready_o is low is not taken and leaves no trace. Period · ⌈log2(Returns + 1)⌉ flip-flops (320
// at the defaults: 80 × 4). tb_rpu_surface_top checks the promise (rpu_surface_top stops the
// simulation if an item reaches the IP without a slot) and the full-load rate.
`default_nettype none

module rpu_surface_admit #(
  parameter integer Period  = 80,  // the ring's period in cycles (2..4096)
  parameter integer Returns = 8    // returns of an item after its first entry (1..255)
) (
  input  wire clk_i,
  input  wire rst_ni,
  input  wire valid_i,
  output wire ready_o
);
  localparam integer CntW = $clog2(Returns + 1);
  localparam [CntW-1:0] Full = Returns[CntW-1:0];

  initial begin
    if (Period < 2 || Period > 4096) $fatal(1, "rpu_surface_admit: Period must be in 2..4096");
    if (Returns < 1 || Returns > 255) $fatal(1, "rpu_surface_admit: Returns must be in 1..255");
  end

  // due_q[0] is the phase passing now; it moves to the top and comes back after Period cycles.
  reg  [Period*CntW-1:0] due_q;
  wire [CntW-1:0]        head = due_q[CntW-1:0];
  wire                   busy = head != {CntW{1'b0}};
  wire [CntW-1:0]        next = busy ? head - 1'b1 : (valid_i ? Full : {CntW{1'b0}});
  assign ready_o = !busy;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) due_q <= {(Period*CntW){1'b0}};
    else         due_q <= {next, due_q[Period*CntW-1:CntW]};
  end

`ifdef FORMAL
  // ---- formal properties (scripts/formal.sh, docs/verification.md) ----
  // Reset at the first cycle (when this module is the proof's top), valid_i free. Each phase
  // counter stays within Returns; an arbitrary admitted item (f_pick) is followed: at every
  // j·Period cycles after its admission (j = 1 .. Returns), when it comes back to the ring's
  // input, its counter is the head and holds Returns − j + 1, so ready_o is low and nothing
  // else is admitted into its slot; after its last return the slot is free again.
`ifdef RPU_FORMAL_ADMIT
  reg f_past_valid = 1'b0;  // only the standalone proof's reset assumption reads it
  always @(posedge clk_i) f_past_valid <= 1'b1;
  always @(*) if (!f_past_valid) assume(!rst_ni);
`endif
  integer f_p;
  always @(*) if (rst_ni)
    for (f_p = 0; f_p < Period; f_p = f_p + 1) assert(due_q[f_p * CntW +: CntW] <= Full);
  always @(*) if (rst_ni) cover(valid_i && !ready_o);
  // The tracked item only in the standalone proof: as rpu_top's submodule, only the counter
  // bound (its divisions would slow the top's solvers for no property of the top's).
`ifdef RPU_FORMAL_ADMIT
  localparam integer FEnd = (Returns + 1) * Period;  // age at which the item's slot is free
  wire accept = valid_i && ready_o;
  (* anyseq *) wire f_pick;
  reg        f_track;
  reg [15:0] f_age;  // cycles since the tracked item's admission, saturating at FEnd + 1
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_track <= 1'b0;
    else if (accept && f_pick && !f_track) begin
      f_track <= 1'b1;
      f_age   <= 16'd1;  // the cycle after the admission
    end else if (f_track && f_age <= FEnd[15:0]) f_age <= f_age + 16'd1;
  end
  // Where and what the tracked item's counter is at age a ≥ 1: slot (Period − a mod Period)
  // mod Period, value Returns − ⌊(a − 1)/Period⌋.
  wire [15:0]     f_slot  = (Period[15:0] - (f_age % Period[15:0])) % Period[15:0];
  wire [15:0]     f_left  = Returns[15:0] - (f_age - 16'd1) / Period[15:0];
  wire [CntW-1:0] f_cnt   = due_q[f_slot * CntW +: CntW];
  always @(*) begin
    if (rst_ni) begin
      if (f_track && f_age != 16'd0 && f_age <= Returns[15:0] * Period[15:0])
        assert({{(16 - CntW){1'b0}}, f_cnt} == f_left);
      if (f_track && f_age != 16'd0 && f_age % Period[15:0] == 16'd0) begin
        if (f_age <= Returns[15:0] * Period[15:0]) assert(!ready_o);  // it returns now
        else if (f_age == FEnd[15:0]) assert(head == {CntW{1'b0}});   // its slot is free
      end
    end
  end
  // Reachability: the tracked item through all returns (and above: an item refused for a
  // returning one).
  always @(*) if (rst_ni) cover(f_track && f_age == FEnd[15:0] && accept);
`endif
`endif
endmodule

`default_nettype wire
