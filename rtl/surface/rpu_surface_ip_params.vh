// The parameters the surface sign search shares (rpu_surface_ip_step, rpu_surface_ip,
// rpu_surface_top), named and ranged once; included in each unit's parameter list. No include
// guard: each module's list includes it once.
  parameter integer SurfW    = 24,  // LW: signed width of surface-local coordinates (16..36)
  parameter integer AngleW   = 20,  // AW: binary-angle bits (12..32, <= LW + 10)
  parameter integer Turns    = 8,   // rpu_indicator's spiral / snail turn lanes (2..8)
  parameter integer N        = 16,  // result bits of τ (1..40)
  parameter integer N1       = 2,   // bits per step (1..8), N % N1 == 0
  parameter integer N1First  = 7,   // bits of step 1 (0: N1, the seed's search; 1..10, at most N used)
  parameter integer Indicators = 0, // indicators of the pass unit (1..64; 0: 2^N1 − 1)
