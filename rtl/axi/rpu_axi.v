// rpu_axi: rpu_top as a drop-in IP (docs/axi.md): an AXI4-Lite slave for control, status,
// identification, performance counters and the descriptor RAMs, an AXI4-Stream slave for work
// items, an AXI4-Stream master for pixels and one for per-item results (ItemResults = 1), and
// an interrupt on frame done. The register map and the stream records are generated from one
// source (rtl/axi/rpu_axi_regmap.json -> rpu_axi_regs.vh, include/rpu_axi_regs.h, docs/axi.md).
// The datapath is rpu_top's, unchanged.
//   A frame: the host writes each descriptor into the staging window DESC_DATA and commits it
//   (DESC_COMMIT: camera, segment or surface RAM), writes CTRL.START, then streams the frame's
//   work items (TLAST on the last one) and takes the pixels (TLAST on the last one) and item
//   results. DONE (and irq_o with IRQ_EN) rises when the TLAST item's every pixel and result is
//   handed out; until then the item stream waits after the TLAST item (STATUS.DRAINING).
//   Bad host behaviour sets a cause bit of ERROR and has a defined answer (docs/axi.md): an
//   item while idle is discarded and counted, a commit during a frame or outside a RAM is
//   refused with SLVERR, an access outside the map gets DECERR, a surface item on a build
//   without surfaces is answered with the overflow bit, TLAST on an item that is not its
//   pixel's last ends the pixel with it.
//   Latency beside rpu_top's: an item record on its final beat enters rpu_top directly; a pixel
//   or result record takes one cycle into its output register, then one beat per cycle.
`default_nettype none
`include "rpu_widths.vh"

module rpu_axi #(
  // The shell's own.
  parameter integer AxisW       = 64,     // TDATA bits of s_item and m_pix: 32, 64 or 128
  parameter integer ResAxisW    = AxisW,  // TDATA bits of m_res: 32, 64, 128, 256 or 512
  parameter integer ItemResults = 1,      // 1: the per-item result stream m_res is built
  // rpu_top's (the same names, ranges and defaults; its derived widths last).
`include "rpu_top_params.vh"
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  // AXI4-Lite slave: registers and the descriptor window (byte addresses, 32-bit data).
  input  wire [11:0]       s_axil_awaddr_i,
  input  wire [2:0]        s_axil_awprot_i,
  input  wire              s_axil_awvalid_i,
  output wire              s_axil_awready_o,
  input  wire [31:0]       s_axil_wdata_i,
  input  wire [3:0]        s_axil_wstrb_i,
  input  wire              s_axil_wvalid_i,
  output wire              s_axil_wready_o,
  output wire [1:0]        s_axil_bresp_o,
  output wire              s_axil_bvalid_o,
  input  wire              s_axil_bready_i,
  input  wire [11:0]       s_axil_araddr_i,
  input  wire [2:0]        s_axil_arprot_i,
  input  wire              s_axil_arvalid_i,
  output wire              s_axil_arready_o,
  output wire [31:0]       s_axil_rdata_o,
  output wire [1:0]        s_axil_rresp_o,
  output wire              s_axil_rvalid_o,
  input  wire              s_axil_rready_i,
  // AXI4-Stream slave: work items (record ITEM).
  input  wire [AxisW-1:0]  s_item_tdata_i,
  input  wire              s_item_tlast_i,
  input  wire              s_item_tvalid_i,
  output wire              s_item_tready_o,
  // AXI4-Stream master: pixels (record PIXEL).
  output wire [AxisW-1:0]  m_pix_tdata_o,
  output wire              m_pix_tlast_o,
  output wire              m_pix_tvalid_o,
  input  wire              m_pix_tready_i,
  // AXI4-Stream master: per-item results (record RESULT; TVALID stays low with ItemResults 0).
  output wire [ResAxisW-1:0] m_res_tdata_o,
  output wire              m_res_tlast_o,
  output wire              m_res_tvalid_o,
  input  wire              m_res_tready_i,
  // Frame done (STATUS.DONE while CTRL.IRQ_EN), a level.
  output wire              irq_o
);
  localparam integer DescMaxW  = CamW > SegW ? (CamW > SurfDW ? CamW : SurfDW)
                                             : (SegW > SurfDW ? SegW : SurfDW);
  localparam integer DescWords = (DescMaxW + 31) / 32;
`include "rpu_axi_regs.vh"

  initial begin
    if (AxisW != 32 && AxisW != 64 && AxisW != 128)
      $fatal(1, "rpu_axi: AxisW must be 32, 64 or 128");
    if (ResAxisW != 32 && ResAxisW != 64 && ResAxisW != 128 && ResAxisW != 256 && ResAxisW != 512)
      $fatal(1, "rpu_axi: ResAxisW must be 32, 64, 128, 256 or 512");
    if (ItemResults < 0 || ItemResults > 1) $fatal(1, "rpu_axi: ItemResults must be 0 or 1");
    if (DescWords > WinDescDataMax)
      $fatal(1, "rpu_axi: a descriptor is wider than the DESC_DATA window");
  end

  // ---- AXI4-Lite (writes wait while a soft reset runs) ----
  wire        srst_on;
  wire        wr, rd;
  wire [11:0] wr_addr, rd_addr;
  wire [31:0] wr_data, rd_data;
  wire [3:0]  wr_strb;
  wire [1:0]  wr_resp, rd_resp;
  rpu_axil_port #(.AddrW(12)) u_lite (
    .clk_i, .rst_ni, .wr_hold_i(srst_on),
    .awaddr_i(s_axil_awaddr_i), .awvalid_i(s_axil_awvalid_i), .awready_o(s_axil_awready_o),
    .wdata_i(s_axil_wdata_i), .wstrb_i(s_axil_wstrb_i), .wvalid_i(s_axil_wvalid_i),
    .wready_o(s_axil_wready_o), .bresp_o(s_axil_bresp_o), .bvalid_o(s_axil_bvalid_o),
    .bready_i(s_axil_bready_i), .araddr_i(s_axil_araddr_i), .arvalid_i(s_axil_arvalid_i),
    .arready_o(s_axil_arready_o), .rdata_o(s_axil_rdata_o), .rresp_o(s_axil_rresp_o),
    .rvalid_o(s_axil_rvalid_o), .rready_i(s_axil_rready_i),
    .wr_o(wr), .wr_addr_o(wr_addr), .wr_data_o(wr_data), .wr_strb_o(wr_strb), .wr_resp_i(wr_resp),
    .rd_o(rd), .rd_addr_o(rd_addr), .rd_data_i(rd_data), .rd_resp_i(rd_resp)
  );
  wire unused_prot = ^{s_axil_awprot_i, s_axil_arprot_i, wr_addr[1:0], rd_addr[1:0]};
  wire [31:0] wmask = {{8{wr_strb[3]}}, {8{wr_strb[2]}}, {8{wr_strb[1]}}, {8{wr_strb[0]}}};
  wire [31:0] wbits = wr_data & wmask;  // command and W1C bits: unstrobed bytes write 0
  wire [9:0]  wr_word = wr_addr[11:2];
  wire [9:0]  rd_word = rd_addr[11:2];
  localparam integer WinLoI = WinDescData / 4;
  localparam integer WinHiI = WinDescData / 4 + DescWords;
  localparam [9:0] WinLo = WinLoI[9:0];
  localparam [9:0] WinHi = WinHiI[9:0];
  wire        wr_win = wr_word >= WinLo && wr_word < WinHi;
  wire        rd_win = rd_word >= WinLo && rd_word < WinHi;
  wire [9:0]  wr_k = wr_word - WinLo;
  localparam integer KW = DescWords > 1 ? $clog2(DescWords) : 1;
  wire [KW-1:0] rd_k = rd_word[KW-1:0] - WinLo[KW-1:0];  // the window word (modulo 2^KW)
  wire [1:0]  wr_acc = reg_access(wr_word);
  wire [1:0]  rd_acc = reg_access(rd_word);

  // ---- frame state, soft reset ----
  reg        busy_q, drain_q, done_q, irq_en_q;
  reg [2:0]  srst_q;                   // soft reset: rpu_top held in reset while non-zero
  reg        top_rst_nq;
  reg [ErrorCauses-1:0] err_q;
  reg [31:0] discarded_q, frames_q;
  // This frame's records between the item stream and the output registers (load: the last
  // record entered the output register; out: its final beat left), so TLAST and DONE need no
  // totals: at most the items rpu_top admits, plus the input and output registers.
  localparam integer PendW = FifoLog2 + 3;
  reg [PendW-1:0] res_load_q, pix_load_q, res_out_q, pix_out_q;
  reg [63:0] cycles_q;
  reg [31:0] curve_in_q, tex_in_q, surf_in_q, curve_out_q, tex_out_q, surf_out_q;
  reg [31:0] pix_cnt_q, hits_q, in_stall_q, out_stall_q;
  assign srst_on = srst_q != 3'd0;

  // ---- descriptor staging and commit ----
  // A byte's flip-flops take its WSTRB as their clock enable (no merge logic).
  reg [DescWords*32-1:0] stage;
  genvar k, b;
  for (k = 0; k < DescWords; k = k + 1) begin : g_stage
    localparam integer WordI = k;
    localparam [9:0] Word = WordI[9:0];
    for (b = 0; b < 4; b = b + 1) begin : g_byte
      always @(posedge clk_i) begin
        if (wr && wr_win && wr_k == Word && wr_strb[b]) stage[k*32+b*8 +: 8] <= wr_data[b*8 +: 8];
      end
    end
  end
  wire [1:0]  cm_target = wbits[DescCommitTargetB +: DescCommitTargetW];
  wire [15:0] cm_addr   = wbits[DescCommitAddrB +: DescCommitAddrW];
  wire        cm_in_range = cm_target == 2'd0 ? cm_addr == 16'd0
                          : cm_target == 2'd1 ? (cm_addr >> SegAddrW) == 16'd0
                          : cm_target == 2'd2 ? (cm_addr >> SurfAddrW) == 16'd0 : 1'b0;
  wire        wr_commit = wr && wr_word == WordDescCommit;
  wire        commit    = wr_commit && !busy_q && cm_in_range;
  // One register stage between the commit and the RAM write (the staging bits fan out wide).
  reg                 cam_we_q, seg_we_q, surf_we_q;
  reg [SegAddrW-1:0]  seg_addr_q;
  reg [SurfAddrW-1:0] surf_addr_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cam_we_q  <= 1'b0;
      seg_we_q  <= 1'b0;
      surf_we_q <= 1'b0;
    end else begin
      cam_we_q  <= commit && cm_target == 2'd0;
      seg_we_q  <= commit && cm_target == 2'd1;
      surf_we_q <= commit && cm_target == 2'd2;
    end
  end
  always @(posedge clk_i) begin
    if (commit) begin
      seg_addr_q  <= cm_addr[SegAddrW-1:0];
      surf_addr_q <= cm_addr[SurfAddrW-1:0];
    end
  end
  // The kind of each segment (its descriptor's top bit), for the per-kind input counters: a
  // block RAM read as the item enters rpu_top, counted the cycle after.
  (* ram_style = "block" *) reg tex_mem [0:(1<<SegAddrW)-1];
  reg tex_q;
  always @(posedge clk_i) begin
    if (seg_we_q) tex_mem[seg_addr_q] <= stage[SegW-1];
    tex_q <= tex_mem[it_seg];
  end

  // ---- work items: gather, gate, count ----
  wire              g_valid, g_last, g_ready;
  wire [RItemW-1:0] g_rec;
  wire [SegAddrW-1:0] it_seg = g_rec[ItemSegO +: ItemSegW];
  wire              top_ready, g_ready_bus;
  rpu_axis_gather #(.W(AxisW), .RecW(RItemW)) u_gather (
    .clk_i, .rst_ni, .clear_i(srst_on),
    .tdata_i(s_item_tdata_i), .tlast_i(s_item_tlast_i), .tvalid_i(s_item_tvalid_i && !srst_on),
    .tready_o(g_ready_bus), .valid_o(g_valid), .ready_i(g_ready), .rec_o(g_rec), .last_o(g_last)
  );
  assign s_item_tready_o = g_ready_bus && !srst_on;
  wire running  = busy_q && !drain_q;
  wire idle     = !busy_q;
  assign g_ready = idle || (running && top_ready);    // idle: taken and discarded
  wire it_take  = g_valid && g_ready && running;       // into rpu_top
  wire it_drop  = g_valid && idle;
  wire it_last  = g_rec[ItemLastO];
  wire it_surf  = g_rec[ItemSurfO];

  // ---- rpu_top ----
  wire                res_valid, res_ready, res_last, res_surf, res_tex, res_pred1, res_hit;
  wire                res_ovf;
  wire [IdW-1:0]      res_id;
  wire [IdxW-1:0]     res_i, res_j, pix_i, pix_j;
  wire [SegAddrW-1:0] res_seg;
  wire [1:0]          res_piece, res_pieces;
  wire [PrimW-1:0]    res_prim, pix_prim;
  wire [DepthW-1:0]   res_depth, pix_depth;
  wire [N-1:0]        res_tau;
  wire [TW-1:0]       res_t;
  wire [3*XW-1:0]     res_x;
  wire                pix_valid, pix_ready, pix_hit;
`ifdef RPU_FORMAL_AXI
`include "rpu_axi_formal_top.vh"
`else
  rpu_top #(
    .CoordW(CoordW), .DirFrac(DirFrac), .TFrac(TFrac), .UnitFrac(UnitFrac), .EdgeFrac(EdgeFrac),
    .InvW(InvW), .SqrtW(SqrtW), .N(N), .N1(N1), .Metric(Metric), .Unrolled(Unrolled),
    .SegAddrW(SegAddrW), .IdxW(IdxW), .IdW(IdW), .PrimW(PrimW), .FifoLog2(FifoLog2),
    .Surfaces(Surfaces), .SurfW(SurfW), .AngleW(AngleW), .Turns(Turns), .N1First(N1First),
    .Indicators(Indicators), .SurfAddrW(SurfAddrW), .TW(TW), .XW(XW), .CamW(CamW), .SegW(SegW),
    .SurfDW(SurfDW), .DepthW(DepthW)
  ) u_top (
    .clk_i, .rst_ni(top_rst_nq),
    .cam_we_i(cam_we_q), .cam_data_i(stage[CamW-1:0]),
    .seg_we_i(seg_we_q), .seg_addr_i(seg_addr_q), .seg_data_i(stage[SegW-1:0]),
    .surf_we_i(surf_we_q), .surf_addr_i(surf_addr_q), .surf_data_i(stage[SurfDW-1:0]),
    .item_valid_i(g_valid && running), .item_ready_o(top_ready),
    .item_id_i(g_rec[ItemIdO +: ItemIdW]), .item_i_i(g_rec[ItemIO +: ItemIW]),
    .item_j_i(g_rec[ItemJO +: ItemJW]), .item_seg_i(it_seg), .item_last_i(it_last || g_last),
    .item_surf_i(it_surf), .item_piece_i(g_rec[ItemPieceO +: ItemPieceW]),
    .res_valid_o(res_valid), .res_ready_i(res_ready), .res_id_o(res_id), .res_i_o(res_i),
    .res_j_o(res_j), .res_seg_o(res_seg), .res_last_o(res_last), .res_surf_o(res_surf),
    .res_piece_o(res_piece), .res_tex_o(res_tex), .res_pieces_o(res_pieces),
    .res_prim_o(res_prim), .res_pred1_o(res_pred1), .res_hit_o(res_hit),
    .res_depth_o(res_depth), .res_tau_o(res_tau), .res_t_o(res_t), .res_x_o(res_x),
    .res_ovf_o(res_ovf),
    .pix_valid_o(pix_valid), .pix_ready_i(pix_ready), .pix_i_o(pix_i), .pix_j_o(pix_j),
    .pix_hit_o(pix_hit), .pix_depth_o(pix_depth), .pix_prim_o(pix_prim)
  );
`endif

  // ---- pixels and item results: scatter into beats ----
  localparam [PendW-1:0] PendOne = 1;
  wire pix_last = drain_q && pix_load_q == PendOne;
  wire pix_take = pix_valid && pix_ready;
  wire [RPixelW-1:0] pix_rec;
  assign pix_rec[PixelIO +: PixelIW]         = pix_i;
  assign pix_rec[PixelJO +: PixelJW]         = pix_j;
  assign pix_rec[PixelHitO]                  = pix_hit;
  assign pix_rec[PixelDepthO +: PixelDepthW] = pix_depth;
  assign pix_rec[PixelPrimO +: PixelPrimW]   = pix_prim;
  wire pix_final;
  rpu_axis_scatter #(.W(AxisW), .RecW(RPixelW)) u_pix (
    .clk_i, .rst_ni, .valid_i(pix_valid), .ready_o(pix_ready),
    .rec_i(pix_rec), .last_i(pix_last),
    .tdata_o(m_pix_tdata_o), .tlast_o(m_pix_tlast_o), .tvalid_o(m_pix_tvalid_o),
    .tready_i(m_pix_tready_i), .final_o(pix_final)
  );
  // A record on an output port when a soft reset comes is still handed out (the AXI4-Stream
  // rule) but belongs to no frame: it is not counted (stale).
  reg  pix_stale_q, res_stale_q;
  wire pix_leave = m_pix_tvalid_o && m_pix_tready_i && pix_final;
  wire pix_out   = pix_leave && !pix_stale_q;
  wire res_take = res_valid && res_ready;
  wire res_leave;
  wire res_out = res_leave && !res_stale_q;
  if (ItemResults != 0) begin : g_res
    wire res_last_frame = drain_q && res_load_q == PendOne;
    wire final_beat;
    wire [RResultW-1:0] rec;
    assign rec[ResultIdO +: ResultIdW]         = res_id;
    assign rec[ResultIO +: ResultIW]           = res_i;
    assign rec[ResultJO +: ResultJW]           = res_j;
    assign rec[ResultSegO +: ResultSegW]       = res_seg;
    assign rec[ResultLastO]                    = res_last;
    assign rec[ResultSurfO]                    = res_surf;
    assign rec[ResultPieceO +: ResultPieceW]   = res_piece;
    assign rec[ResultTexO]                     = res_tex;
    assign rec[ResultPiecesO +: ResultPiecesW] = res_pieces;
    assign rec[ResultPrimO +: ResultPrimW]     = res_prim;
    assign rec[ResultPred1O]                   = res_pred1;
    assign rec[ResultHitO]                     = res_hit;
    assign rec[ResultDepthO +: ResultDepthW]   = res_depth;
    assign rec[ResultTauO +: ResultTauW]       = res_tau;
    assign rec[ResultTO +: ResultTW]           = res_t;
    assign rec[ResultXO +: ResultXW]           = res_x;
    assign rec[ResultOvfO]                     = res_ovf;
    rpu_axis_scatter #(.W(ResAxisW), .RecW(RResultW)) u_res (
      .clk_i, .rst_ni, .valid_i(res_valid), .ready_o(res_ready),
      .rec_i(rec),
      .last_i(res_last_frame),
      .tdata_o(m_res_tdata_o), .tlast_o(m_res_tlast_o), .tvalid_o(m_res_tvalid_o),
      .tready_i(m_res_tready_i), .final_o(final_beat)
    );
    assign res_leave = m_res_tvalid_o && m_res_tready_i && final_beat;
  end else begin : g_no_res
    assign res_ready      = 1'b1;
    assign res_leave      = 1'b0;
    assign m_res_tdata_o  = '0;
    assign m_res_tlast_o  = 1'b0;
    assign m_res_tvalid_o = 1'b0;
    wire unused_res = ^{m_res_tready_i, res_id, res_i, res_j, res_seg, res_last, res_piece,
                        res_pieces, res_prim, res_pred1, res_hit, res_depth, res_tau, res_t,
                        res_x, res_ovf};
  end

  wire frame_end = drain_q && pix_out_q == '0 && (ItemResults == 0 || res_out_q == '0);

  // ---- control and status writes ----
  wire wr_ctrl   = wr && wr_word == WordCtrl;
  wire start     = wr_ctrl && wbits[CtrlStartB] && !busy_q && !srst_on;
  wire start_bad = wr_ctrl && wbits[CtrlStartB] && busy_q;
  wire srst_req  = wr_ctrl && wbits[CtrlSoftResetB];
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      pix_stale_q <= 1'b0;
      res_stale_q <= 1'b0;
    end else begin
      if (srst_req) pix_stale_q <= m_pix_tvalid_o && !pix_leave;
      else if (pix_leave) pix_stale_q <= 1'b0;
      if (srst_req) res_stale_q <= m_res_tvalid_o && !res_leave;
      else if (res_leave) res_stale_q <= 1'b0;
    end
  end
  wire wr_ro     = wr && !wr_win && wr_acc == 2'd1;
  wire wr_ok     = wr_win || wr_acc[1];
  wire rd_known  = rd_win || rd_acc != 2'd0;
  assign wr_resp = wr_ro ? 2'b10                                   // SLVERR: read only
                 : !wr_ok ? 2'b11                                  // DECERR: no such register
                 : wr_commit && !commit ? 2'b10 : 2'b00;           // SLVERR: commit refused
  assign rd_resp = rd_known ? 2'b00 : 2'b11;
  wire [ErrorCauses-1:0] err_set;
  assign err_set[ErrorItemIdleB]    = it_drop;
  assign err_set[ErrorDescBusyB]    = wr_commit && busy_q;
  assign err_set[ErrorBadAddrB]     = (wr && (wr_ro || !wr_ok)) || (rd && !rd_known);
  assign err_set[ErrorUnbuiltKindB] = it_take && it_surf && Surfaces == 0;
  assign err_set[ErrorBadLastB]     = it_take && g_last && !it_last;
  assign err_set[ErrorStartBusyB]   = start_bad;
  assign err_set[ErrorDescRangeB]   = wr_commit && !busy_q && !cm_in_range;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      srst_q     <= 3'd4;  // a reset is a soft reset too: the synchronous clears run
      top_rst_nq <= 1'b0;
      irq_en_q   <= 1'b0;
    end else begin
      srst_q     <= srst_req ? 3'd4 : srst_on ? srst_q - 3'd1 : 3'd0;
      top_rst_nq <= !(srst_req || (srst_on && srst_q != 3'd1));
      if (wr_ctrl && wr_strb[0]) irq_en_q <= wr_data[CtrlIrqEnB];
    end
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
      drain_q <= 1'b0;
      done_q <= 1'b0;
      err_q <= '0;
      res_out_q <= '0;
      pix_out_q <= '0;
      res_load_q <= '0;
      pix_load_q <= '0;
    end else if (srst_on) begin
      res_out_q <= '0;
      pix_out_q <= '0;
      res_load_q <= '0;
      pix_load_q <= '0;
      busy_q <= 1'b0;
      drain_q <= 1'b0;
      done_q <= 1'b0;
      err_q <= '0;
    end else begin
      err_q <= (err_q & ~(wr_word == WordError && wr ? wbits[ErrorCauses-1:0]
                                                             : {ErrorCauses{1'b0}})) | err_set;
      // +1 as an item (a pixel's last item) enters rpu_top, -1 as its record leaves.
      res_load_q <= res_load_q + {{(PendW-1){1'b0}}, it_take} - {{(PendW-1){1'b0}}, res_take};
      res_out_q  <= res_out_q + {{(PendW-1){1'b0}}, it_take} - {{(PendW-1){1'b0}}, res_out};
      pix_load_q <= pix_load_q + {{(PendW-1){1'b0}}, it_take && (it_last || g_last)}
                  - {{(PendW-1){1'b0}}, pix_take};
      pix_out_q  <= pix_out_q + {{(PendW-1){1'b0}}, it_take && (it_last || g_last)}
                  - {{(PendW-1){1'b0}}, pix_out};
      if (start) begin
        busy_q <= 1'b1;
        done_q <= 1'b0;
      end else begin
        if (wr && wr_word == WordStatus && wbits[StatusDoneB]) done_q <= 1'b0;
        if (it_take && g_last) drain_q <= 1'b1;
        if (busy_q && frame_end) begin
          busy_q <= 1'b0;
          drain_q <= 1'b0;
          done_q <= 1'b1;
        end
      end
    end
  end

  // ---- performance counters: cleared by START and by a reset (srst_q is 4 in a reset), then
  // counting while busy; a synchronous clear (the flip-flops' own reset pin) ----
  always @(posedge clk_i) begin
    if (srst_on) begin
      discarded_q <= '0;
      frames_q <= '0;
    end else begin
      if (it_drop) discarded_q <= discarded_q + 32'd1;
      if (busy_q && frame_end && !start) frames_q <= frames_q + 32'd1;
    end
  end
  reg seg_take_q;  // a segment item entered rpu_top last cycle (tex_q: its kind)
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) seg_take_q <= 1'b0;
    else seg_take_q <= it_take && !it_surf;
  end
  always @(posedge clk_i) begin
    if (start || srst_on) begin
      cycles_q <= '0;
      {curve_in_q, tex_in_q, surf_in_q, curve_out_q, tex_out_q, surf_out_q} <= '0;
      {pix_cnt_q, hits_q, in_stall_q, out_stall_q} <= '0;
    end else if (busy_q) begin
      cycles_q <= cycles_q + 64'd1;
      if (it_take && it_surf) surf_in_q <= surf_in_q + 32'd1;
      if (seg_take_q && tex_q) tex_in_q <= tex_in_q + 32'd1;
      if (seg_take_q && !tex_q) curve_in_q <= curve_in_q + 32'd1;
      if (res_take && res_surf) surf_out_q <= surf_out_q + 32'd1;
      if (res_take && !res_surf && res_tex) tex_out_q <= tex_out_q + 32'd1;
      if (res_take && !res_surf && !res_tex) curve_out_q <= curve_out_q + 32'd1;
      if (pix_out) pix_cnt_q <= pix_cnt_q + 32'd1;
      if (pix_take && pix_hit) hits_q <= hits_q + 32'd1;
      if (s_item_tvalid_i && !s_item_tready_o) in_stall_q <= in_stall_q + 32'd1;
      if ((m_pix_tvalid_o && !m_pix_tready_i) || (m_res_tvalid_o && !m_res_tready_i))
        out_stall_q <= out_stall_q + 32'd1;
    end
  end
  assign irq_o = done_q && irq_en_q;

  // ---- reads ----
  reg [31:0] rd_val;
  wire [31:0] ctrl_val   = {31'd0, irq_en_q} << CtrlIrqEnB;
  wire [31:0] status_val = ({31'd0, busy_q} << StatusBusyB) | ({31'd0, done_q} << StatusDoneB)
                         | ({31'd0, |err_q} << StatusErrorB) | ({31'd0, drain_q} << StatusDrainingB);
  always @(*) begin
    case (rd_word)
      WordCtrl:        rd_val = ctrl_val;
      WordStatus:      rd_val = status_val;
      WordError:       rd_val = {{(32 - ErrorCauses){1'b0}}, err_q};
      WordDiscarded:   rd_val = discarded_q;
      WordFrames:      rd_val = frames_q;
      WordDescCommit:  rd_val = 32'd0;
      WordCyclesLo:    rd_val = cycles_q[31:0];
      WordCyclesHi:    rd_val = cycles_q[63:32];
      WordCurveIn:     rd_val = curve_in_q;
      WordTextureIn:   rd_val = tex_in_q;
      WordSurfaceIn:   rd_val = surf_in_q;
      WordCurveOut:    rd_val = curve_out_q;
      WordTextureOut:  rd_val = tex_out_q;
      WordSurfaceOut:  rd_val = surf_out_q;
      WordPixelsOut:   rd_val = pix_cnt_q;
      WordHitsOut:     rd_val = hits_q;
      WordInStall:     rd_val = in_stall_q;
      WordOutStall:    rd_val = out_stall_q;
      default:         rd_val = id_read(rd_word);  // the identification block, or 0
    endcase
  end
  assign rd_data  = rd_win ? stage[rd_k*32 +: 32] : rd_val;

`ifdef FORMAL
`include "rpu_axi_props.vh"
`endif
endmodule

`default_nettype wire
