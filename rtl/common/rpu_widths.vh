// Derived widths of the datapath, one formula each (docs/fixed-point.md, "Parameters"; the C++
// twins have the same formulas as HwParams functions). A module declares the ones it uses as
// derived parameters, e.g.  parameter integer TW = `RPU_TW(TFrac),  so a width is written once
// here and nowhere else.
`define RPU_TW(tfrac)        ((tfrac) + 3)          // t, α, β, w: Q(3.FT)
`define RPU_DW(coordw)       ((coordw) + 1)         // differences of positions: d, A − p1, B − A
`define RPU_UW(unitfrac)     ((unitfrac) + 2)       // guide unit vectors u_k: Q(2.FU)
`define RPU_HW(coordw)       ((coordw) + 5)         // guide height h (h ≤ 16·L)
`define RPU_L2W(coordw)      (2 * (coordw) + 3)     // L² = |d|²
`define RPU_R2W(coordw)      (2 * (coordw) + 1)     // R² of the interpolation sphere, w0²
`define RPU_XW(coordw)       ((coordw) + 3)         // curve point X
`define RPU_PRW(coordw)      ((coordw) + 2)         // ray point pr
`define RPU_VW(dirfrac)      (4 + (dirfrac))        // unnormalised direction v: Q(4.FV)
`define RPU_VHATW(dirfrac)   (2 + (dirfrac))        // unit direction v̂: Q(2.FV)
`define RPU_VGW(dirfrac)     (4 + (dirfrac) + 14)   // v with the ray generator's 14 guard bits
`define RPU_EGW(edgefrac)    (4 + (edgefrac) + 14)  // PVP edge vectors: Q(4.FE+14)
`define RPU_GRADW(coordw)    (2 * (coordw) + 10)    // guide radicand h² + L²·w
`define RPU_MD2W(coordw)     (2 * (coordw) + 8)     // |pr − X|² (dist_radicand_w)
`define RPU_DEPTHW(coordw, edgefrac) ((coordw) + 4 + `RPU_EGW(edgefrac) + 2)  // depth c = (X − h)·W

// A unit's caller tag of RPU_TAGQ_MINW bits or more waits in a queue (rpu_tag_queue) instead of
// riding the unit's stages, which then carry RPU_PTAGW(tagw) bits.
`define RPU_TAGQ_MINW        32
`define RPU_PTAGW(tagw)      ((tagw) >= `RPU_TAGQ_MINW ? 1 : (tagw))

// One guide: its shape {mode, h, a, b} (rpu_guide_shape.vh) and the descriptor {shape, u}
// (rpu_guide_desc.vh); the layout headers check their totals against these.
`define RPU_GSW(coordw, tfrac) (2 + `RPU_HW(coordw) + (coordw) + (tfrac))
`define RPU_GDW(coordw, tfrac, unitfrac) (`RPU_GSW(coordw, tfrac) + 3 * `RPU_UW(unitfrac))

// The indicator's part of a surface descriptor (rpu_surface_desc.vh), one word: 15·LW + 61 bits.
`define RPU_SDW(surfw)       (15 * (surfw) + 61)

// The candidate evaluator in the chord's 2-D frame (docs/fixed-point.md, "The candidate in the
// chord's frame"; HwParams::kFrame*, kCand*): fixed formats in units of the chord length L.
`define RPU_FX               24                     // frame coordinates x, y
`define RPU_FG               17                     // guides' offsets ĝ = g/L
`define RPU_FW               28                     // w = t(1−t)
`define RPU_FP               23                     // t, c2·t, s2·t into the guide products
`define RPU_FOB              14                     // md fraction bits of step 0 ...
`define RPU_FOMAX            20                     // ... growing by n1 per step up to this
`define RPU_MDFRAC(n1, k)    (`RPU_FOB + (n1) * (k) < `RPU_FOMAX ? `RPU_FOB + (n1) * (k) : `RPU_FOMAX)
`define RPU_CXW              (`RPU_FX + 3)          // candidate x, y (|x| < 4)
`define RPU_CTW              (`RPU_FP + 4)          // candidate t, c2·t, s2·t (|t| < 8)
`define RPU_CWW              (`RPU_FW + 8)          // candidate w (|w| < 128)
`define RPU_CAW              (`RPU_FG + 3)          // a flat guide's offset (|ĝ| < 4)
`define RPU_FRADW            (2 * `RPU_FG + 9)      // an arc guide's radicand η² + w (η ≤ 16)
`define RPU_ETAW             (`RPU_FG + 5)          // η, unsigned
`define RPU_FGDW             (2 + `RPU_ETAW + `RPU_FRADW)  // a frame guide {mode, η, η²}
`define RPU_FEM              16                     // frame vectors' mantissa: |m| < 2^(FEM+1)
`define RPU_FEW              (`RPU_FEM + 2)         // e1, e2 components, signed
`define RPU_FSW              6                      // the frame exponent s (20 ≤ s ≤ 63)
`define RPU_FC               16                     // c2, s2: Q(1.FC)
`define RPU_FCW              (`RPU_FC + 2)
`define RPU_FA               24                     // a flat guide's 1/(2η): Q(.FA) ≤ 2^-5
`define RPU_FAW              (`RPU_FA - 3)          // signed
// The frame descriptor {e1, e2, s, c2, s2, a1, a2} (rpu_frame_desc.vh).
`define RPU_FRDW             (6 * `RPU_FEW + `RPU_FSW + 2 * `RPU_FCW + 2 * `RPU_FAW)
// The pair's frame coefficients (rpu_frame's outputs; n = N, FT = TFrac).
`define RPU_FW0W(n)          (`RPU_FW + 2 * (n) + 6)   // W's constant term
`define RPU_FW1W(n)          (`RPU_FW + (n) + 8)       // W's m term
`define RPU_FW2W             (`RPU_FW + 5)             // W's m² term
`define RPU_FCAW(tfrac)      (`RPU_FCW + (tfrac) + 3)  // c2·α, c2·β, s2·α, s2·β
// The surface sign search (rtl/surface/rpu_surface_state.vh): indicators of one pass unit (ind,
// or 2^n1 − 1 when ind = 0), and the width of an item's search state.
`define RPU_SLANES(n1, ind)   ((ind) != 0 ? (ind) : (1 << (n1)) - 1)
`define RPU_SSTW(n, n1, ind)  (3 * (n) + 34 + `RPU_SLANES(n1, ind) * ((n) + 1))
