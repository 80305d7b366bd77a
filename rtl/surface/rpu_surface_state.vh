// The search state of one surface work item (rpu_surface_ip_step, rpu_surface_ip), LSB first: what
// the item carries from pass to pass of the sign search (docs/surfaces.md, "The search on a
// piece"). Included inside a module that defines N, N1 and Indicators; its total SsW equals `RPU_SSTW
// (rpu_widths.vh), which a module uses for the port's width.
//   ovf, live        the sticky overflow; the piece is searched and has not missed
//   hi, lo, tau      the current step's interval: its ends' inside bits and its start m (N bits)
//   found, prev      this step: a sign change was seen; the inside bit of the last candidate
//   slo, shi, stau   this step: the first change's interval (ends' bits, start m)
//   mprev            the m of the last candidate (prev)
//   start, first     the next pass is step 1's first (no prev); the item is in step 1
//   done             the search is complete (the item leaves)
//   bits, shift      the step's bits b and its shift (N minus the bits of the steps so far)
//   j0               the step's candidates before this pass (a multiple of the lanes)
//   m                the lanes' candidates, N + 1 bits each
  localparam integer SsLanes = `RPU_SLANES(N1, Indicators);
  localparam integer SsBW    = 4;                  // bits (1..10)
  localparam integer SsShW   = 8;                  // shift (0..N)
  localparam integer SsJW    = 11;                 // j0 (< 2^10)
  localparam integer SsMW    = N + 1;              // one lane's m (0..2^N)
  localparam integer SsOvfO   = 0;
  localparam integer SsLiveO  = SsOvfO + 1;
  localparam integer SsHiO    = SsLiveO + 1;
  localparam integer SsLoO    = SsHiO + 1;
  localparam integer SsTauO   = SsLoO + 1;
  localparam integer SsFoundO = SsTauO + N;
  localparam integer SsPrevO  = SsFoundO + 1;
  localparam integer SsSloO   = SsPrevO + 1;
  localparam integer SsShiO   = SsSloO + 1;
  localparam integer SsStauO  = SsShiO + 1;
  localparam integer SsMprevO = SsStauO + N;
  localparam integer SsStartO = SsMprevO + N;
  localparam integer SsFirstO = SsStartO + 1;
  localparam integer SsDoneO  = SsFirstO + 1;
  localparam integer SsBitsO  = SsDoneO + 1;
  localparam integer SsShiftO = SsBitsO + SsBW;
  localparam integer SsJ0O    = SsShiftO + SsShW;
  localparam integer SsMO     = SsJ0O + SsJW;
  localparam integer SsW      = SsMO + SsLanes * SsMW;
