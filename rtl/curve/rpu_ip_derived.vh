// The derived widths every unit of the iterative process declares (rpu_ip, rpu_ip_step,
// rpu_candidate), from rpu_widths.vh; included in each unit's parameter list after its "Derived
// (do not override)" line. No include guard: each module's list includes it once.
  parameter integer TW   = `RPU_TW(TFrac),      // t, α, β: Q(3.FT)
  parameter integer DW   = `RPU_DW(CoordW),     // d, AB
  parameter integer L2W  = `RPU_L2W(CoordW),    // L²
  parameter integer RadW = `RPU_GRADW(CoordW),  // h² (guide_radicand_w)
  parameter integer XW   = `RPU_XW(CoordW),     // X
  parameter integer GdW  = `RPU_GDW(CoordW, TFrac, UnitFrac),  // a guide (rpu_guide_desc.vh)
