// rpu_latency_check: a simulation-only check that a unit's declared latency is its schedule
// (instantiated under `ifndef SYNTHESIS`, by the macro `RPU_LATENCY_CHECK of rpu_latency_check.vh
// for one stretch, like rpu_surface_ip_step's check of rpu_indicator;
// empty under FORMAL too, since Yosys's formal front end has no $fatal in an always block).
// Each of Segments stretches of the unit's own stages is measured on the first item after reset:
// the cycles from its first in_i[s] to its first out_i[s]. Once every stretch has seen its item,
// their sum must equal Latency (for a unit without sub-units, one stretch from valid_i to
// valid_o; for one with sub-units, the stretches between them, so Latency is the unit's own
// part, as its C++ latency function counts it). A mismatch stops the simulation naming Name.
// Fixed-latency pipelines keep the first item's count for every item; the testbenches check
// each item's latency against the first.
`default_nettype none

module rpu_latency_check #(
  parameter integer Latency  = 1,
  parameter integer Segments = 1,
  parameter         Name     = "unit"
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire [Segments-1:0] in_i,   // a stretch's input valid
  input  wire [Segments-1:0] out_i   // its output valid
);
`ifdef SYNTHESIS
  `define RPU_LATENCY_CHECK_OFF
`elsif FORMAL
  `define RPU_LATENCY_CHECK_OFF
`endif
`ifndef RPU_LATENCY_CHECK_OFF
  reg  [31:0] cyc;
  reg  [31:0] t_in [0:Segments-1];
  reg  [31:0] d [0:Segments-1];
  reg  [Segments-1:0] seen_in, seen_out;
  reg         done;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) cyc <= 32'd0;
    else         cyc <= cyc + 32'd1;
  end
  genvar g;
  generate
    for (g = 0; g < Segments; g = g + 1) begin : g_seg
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          seen_in[g]  <= 1'b0;
          seen_out[g] <= 1'b0;
        end else begin
          if (!seen_in[g] && in_i[g]) begin
            seen_in[g] <= 1'b1;
            t_in[g]    <= cyc;
          end
          if (seen_in[g] && !seen_out[g] && out_i[g]) begin
            seen_out[g] <= 1'b1;
            d[g]        <= cyc - t_in[g];
          end
        end
      end
    end
  endgenerate
  reg [31:0] sum;
  integer s;
  always @(*) begin
    sum = 32'd0;
    for (s = 0; s < Segments; s = s + 1) sum = sum + d[s];
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) done <= 1'b0;
    else if (!done && &seen_out) begin
      done <= 1'b1;
      if (sum != Latency)
        $fatal(1, "%s: the declared latency %0d is not the schedule's %0d cycles", Name, Latency,
               sum);
    end
  end
`else
  wire unused = ^{clk_i, rst_ni, in_i, out_i};
`endif
`undef RPU_LATENCY_CHECK_OFF
endmodule

`default_nettype wire
