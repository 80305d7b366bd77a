// The indicator's descriptor fields (SurfaceDesc, ref/model/descriptors.h; formats: rpu_indicator's
// header) packed into one word, LSB first. The word travels as one port (desc_i) into
// rpu_surface_top, rpu_surface_ip, rpu_surface_ip_step and rpu_indicator, and rides their buses and
// RAMs. Included inside a module that defines SurfW; each offset is defined from the previous one.
// Its total SdW equals `RPU_SDW (rpu_widths.vh; 15·LW + 61 bits, 421 at LW = 24), which a module
// uses for the port's width.
  localparam integer SdKF    = SurfW;          // Q(1.KF) constants
  localparam integer SdMW    = SurfW + 2;      // ScaledConst mantissas
  localparam integer SdTurnW = SurfW + 8;      // a_turn, k_turn
  localparam integer SdR2W   = 2 * SurfW + 1;  // r2
  localparam integer SdTypeO   = 0;                  // type, 3 bits
  localparam integer SdFullO   = SdTypeO + 3;        // full_turns, 4 bits
  localparam integer SdSxO     = SdFullO + 4;        // sx, KF + 1 bits
  localparam integer SdSyO     = SdSxO + SdKF + 1;   // sy
  localparam integer SdSzO     = SdSyO + SdKF + 1;   // sz
  localparam integer SdR2O     = SdSzO + SdKF + 1;   // r2, 2LW + 1 bits
  localparam integer SdKdO     = SdR2O + SdR2W;      // kd, KF + 2 bits
  localparam integer SdKe2O    = SdKdO + SdKF + 2;   // ke2
  localparam integer SdYamO    = SdKe2O + SdKF + 2;  // y_angle mantissa, MW bits
  localparam integer SdYasO    = SdYamO + SdMW;      // y_angle shift, 8 bits
  localparam integer SdRho0O   = SdYasO + 8;         // rho0, LW bits
  localparam integer SdAturnO  = SdRho0O + SurfW;    // a_turn, LW + 8 bits
  localparam integer SdKturnO  = SdAturnO + SdTurnW; // k_turn
  localparam integer SdRaO     = SdKturnO + SdTurnW; // rocket_a, LW bits
  localparam integer SdRbO     = SdRaO + SurfW;      // rocket_b
  localparam integer SdFinmO   = SdRbO + SurfW;      // fin mantissa, MW bits
  localparam integer SdFinsO   = SdFinmO + SdMW;     // fin shift, 8 bits
  localparam integer SdConemO  = SdFinsO + 8;        // cone mantissa, MW bits
  localparam integer SdConesO  = SdConemO + SdMW;    // cone shift, 8 bits
  localparam integer SdW       = SdConesO + 8;
