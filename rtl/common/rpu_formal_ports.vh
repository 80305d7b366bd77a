// `RPU_F_QUEUE(count, entries): the formal-only ports of a queue (rpu_fifo, rpu_skid: f_count_o
// and f_entries_o, the words held and their values) connected in a proof's build (FORMAL) and
// absent otherwise, so the synthesizable instance reads as hardware. Written after the last
// connection of the port list, without a comma:
//   rpu_skid #(.W(W)) u_q (.clk_i, ..., .data_o(q) `RPU_F_QUEUE(f_q_cnt, f_q_ent));
`ifndef RPU_FORMAL_PORTS_VH
`define RPU_FORMAL_PORTS_VH
`ifdef FORMAL
`define RPU_F_QUEUE(count, entries) , .f_count_o(count), .f_entries_o(entries)
`else
`define RPU_F_QUEUE(count, entries)
`endif
`endif
