// The packed words inside rpu_top, LSB first, each offset defined from the previous one:
// the work item, the four edge vectors, the side bands that ride beside the curve and texture
// pipelines, and the result record. Included inside rpu_top after rpu_guide_desc.vh,
// rpu_seg_desc.vh and rpu_cam_desc.vh.

  // The work item as accepted: {piece, surface, last, id, i, j, seg}.
  localparam integer ItSegO  = 0;
  localparam integer ItJO    = ItSegO + SegAddrW;          // pixel row j
  localparam integer ItIO    = ItJO + IdxW;                // pixel column i
  localparam integer ItIdO   = ItIO + IdxW;                // the caller's id
  localparam integer ItLastO = ItIdO + IdW;                // the pixel's last item
  localparam integer ItSurfO = ItLastO + 1;                // 1: a surface piece (seg: surface RAM)
  localparam integer ItPcO   = ItSurfO + 1;                // the piece, 0..2 (surfaces)
  localparam integer ItW     = ItPcO + 2;
  localparam integer ItBW    = ItSurfO;                    // {last, id, i, j, seg}: what the
                                                           //   curve and texture paths carry

  // The pixel's four PVP edge vectors, each 3 × Q(4.FE+14): {left, right, top, bottom}.
  localparam integer EdBottomO = 0;
  localparam integer EdTopO    = EdBottomO + CamEW;
  localparam integer EdRightO  = EdTopO + CamEW;
  localparam integer EdLeftO   = EdRightO + CamEW;
  localparam integer EdgW      = EdLeftO + CamEW;

  // Beside the sphere unit: {item, prim, p1, d, L², g1, g2, edges}; the whole item word, as a
  // surface piece takes the unit's slot too (the surface path branches off after it).
  localparam integer SpEdgesO = 0;
  localparam integer SpFgO    = SpEdgesO + EdgW;           // the frame guides {fg1, fg2}
  localparam integer SpFrO    = SpFgO + SegFgW;            // the frame descriptor
  localparam integer SpGO     = SpFrO + SegFrW;            // both guides, {g1, g2}
  localparam integer SpL2O    = SpGO + 2 * GdW;
  localparam integer SpDO     = SpL2O + SegL2W;
  localparam integer SpP1O    = SpDO + SegDW;
  localparam integer SpPrimO  = SpP1O + SegP1W;
  localparam integer SpItO    = SpPrimO + PrimW;
  localparam integer SphTagW  = SpItO + ItW;

  // Beside the K-step process: {item, prim, pred_1, sphere overflow, edges}.
  localparam integer IcEdgesO = 0;
  localparam integer IcOvfO   = IcEdgesO + EdgW;
  localparam integer IcPred1O = IcOvfO + 1;
  localparam integer IcPrimO  = IcPred1O + 1;
  localparam integer IcItO    = IcPrimO + PrimW;
  localparam integer IpCtxW   = IcItO + ItBW;

  // rpu_ip's state output: {τ_K, t, X, md_lo, md_hi}.
  localparam integer IsMdO    = 0;
  localparam integer IsXO     = IsMdO + 2 * MdW;
  localparam integer IsTO     = IsXO + 3 * XW;
  localparam integer IsTauO   = IsTO + TW;
  localparam integer StW      = IsTauO + N;

  // Beside the capture unit: {item, prim, pred_1, overflow, τ, t, X}; the part below the item
  // is the result record's {prim, pred_1, overflow, τ, t, X} as it stands.
  localparam integer CtXO     = 0;
  localparam integer CtTO     = CtXO + 3 * XW;
  localparam integer CtTauO   = CtTO + TW;
  localparam integer CtOvfO   = CtTauO + N;
  localparam integer CtPred1O = CtOvfO + 1;
  localparam integer CtPrimO  = CtPred1O + 1;
  localparam integer CtItO    = CtPrimO + PrimW;
  localparam integer CapTagW  = CtItO + ItBW;

  // Beside the ray/plane unit: {item, prim, p1, d, L², inv_m, inv_s, g1, g2, w0², round join}.
  localparam integer RpJoinO  = 0;                         // 1: round join (c0's bit 0)
  localparam integer RpW02O   = RpJoinO + 1;
  localparam integer RpGO     = RpW02O + SegR2W;           // both guides, {g1, g2}
  localparam integer RpInvSO  = RpGO + 2 * GdW;
  localparam integer RpInvMO  = RpInvSO + SegInvSW;
  localparam integer RpL2O    = RpInvMO + SegInvMW;
  localparam integer RpDO     = RpL2O + SegL2W;
  localparam integer RpP1O    = RpDO + SegDW;
  localparam integer RpPrimO  = RpP1O + SegP1W;
  localparam integer RpItO    = RpPrimO + PrimW;
  localparam integer RpTagW   = RpItO + ItBW;

  // Beside the texture unit: {item, prim, p0 valid, depth}.
  localparam integer TtDepthO = 0;
  localparam integer TtP0OkO  = TtDepthO + DepthW;
  localparam integer TtPrimO  = TtP0OkO + 1;
  localparam integer TtItO    = TtPrimO + PrimW;
  localparam integer TxTagW   = TtItO + ItBW;

  // A result record (the result port, the output FIFOs): {item, texture, pieces, prim, pred_1,
  // overflow, τ, t, X, hit, depth}; pieces: a surface pair's non-empty pieces (0 otherwise).
  localparam integer RsDepthO = 0;
  localparam integer RsHitO   = RsDepthO + DepthW;
  localparam integer RsXO     = RsHitO + 1;                // {prim, pred_1, overflow, τ, t, X}
  localparam integer RsCtxW   = CtItO;                     //   as the capture side band holds it
  localparam integer RsPcsO   = RsXO + RsCtxW;
  localparam integer RsTexO   = RsPcsO + 2;
  localparam integer RsItO    = RsTexO + 1;
  localparam integer ResW     = RsItO + ItW;
