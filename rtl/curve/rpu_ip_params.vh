// The parameters every unit of the iterative process shares (rpu_ip, rpu_ip_step,
// rpu_candidate), named and ranged once; included at the head of each unit's parameter list.
// Formats: docs/fixed-point.md. No include guard: each module's list includes it once.
  parameter integer CoordW   = 24,  // position width (12..40)
  parameter integer TFrac    = 24,  // fraction bits of t (8..48)
  parameter integer UnitFrac = 16,  // fraction bits of u_k (8..40)
  parameter integer SqrtW    = 0,   // widest square-root radicand; 0 = exact
  parameter integer N        = 16,  // result bits of τ (1..40)
