// `RPU_LATENCY_CHECK(latency, name): a unit's simulation-only check that its declared latency is
// its schedule, from valid_i to valid_o (rtl/common/rpu_latency_check.v); nothing under
// SYNTHESIS (Yosys reads with it defined). One line at the end of a fixed-latency unit.
`ifndef RPU_LATENCY_CHECK_VH
`define RPU_LATENCY_CHECK_VH
`ifdef SYNTHESIS
`define RPU_LATENCY_CHECK(lat, name)
`else
`define RPU_LATENCY_CHECK(lat, name) \
  rpu_latency_check #(.Latency(lat), .Segments(1), .Name(name)) u_latency_check ( \
    .clk_i, .rst_ni, .in_i(valid_i), .out_i(valid_o));
`endif
`endif
