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
endmodule

`default_nettype wire
