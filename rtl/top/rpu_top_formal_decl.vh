// rpu_top's formal-only declarations (included under FORMAL, after its layout headers): in the
// top's proof (RPU_FORMAL_TOP) the search ring's period and passes, and the proof's view of the
// queues of rpu_top.v, the words each holds and their values (rpu_skid, rpu_fifo: f_count_o,
// f_entries_o; connected by `RPU_F_QUEUE), read by rpu_top_props.vh.
`ifdef RPU_FORMAL_TOP
  // The top's proof abstracts the surface unit, and its admission with it, to a ring of 3 cycles
  // and 3 passes (rpu_surface_admit has its own proof at any period).
  localparam integer SfPeriod = 3;
  localparam integer SfPasses = 3;
`endif
  wire [1:0]       f_in_cnt;   // the input skid register
  wire [2*ItW-1:0] f_in_ent;
  wire [FifoLog2+1:0] f_c_cnt, f_t_cnt, f_s_cnt, f_o_cnt;  // the result and order FIFOs
  wire [((1<<FifoLog2)+1)*ResW-1:0] f_c_ent, f_t_ent, f_s_ent;
  wire [((1<<FifoLog2)+1)*2-1:0]    f_o_ent;
