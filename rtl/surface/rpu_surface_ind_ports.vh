// The indicator's descriptor fields (SurfaceDesc, ref/model/descriptors.h; formats: rpu_indicator's
// header) as input ports, one per field in descriptor order; included in the port lists of
// rpu_indicator, rpu_surface_ip and rpu_surface_top, which declare SurfW (LW), TurnW = LW + 8 and
// R2W = 2LW + 1 (KF = LW and MW = LW + 2 are written as SurfW, SurfW + 2). No include guard: each
// module's list includes it once.
  input  wire [3:0]           full_turns_i,
  input  wire [SurfW:0]       sx_i,          // Q(1.KF), KF + 1 bits unsigned
  input  wire [SurfW:0]       sy_i,
  input  wire [SurfW:0]       sz_i,
  input  wire [R2W-1:0]       r2_i,          // 2LW + 1 bits unsigned
  input  wire [SurfW+1:0]     kd_i,          // Q(1.KF), KF + 2 bits signed
  input  wire [SurfW+1:0]     ke2_i,
  input  wire [SurfW+1:0]     y_angle_m_i,   // ScaledConst m·2^-s: MW bits signed, s 8 bits
  input  wire [7:0]           y_angle_s_i,
  input  wire [SurfW-1:0]     rho0_i,        // llsb, LW bits signed
  input  wire [TurnW-1:0]     a_turn_i,      // llsb per turn, LW + 8 bits signed
  input  wire [TurnW-1:0]     k_turn_i,
  input  wire [SurfW-1:0]     rocket_a_i,    // llsb, LW bits signed
  input  wire [SurfW-1:0]     rocket_b_i,
  input  wire [SurfW+1:0]     fin_m_i,       // ScaledConst, as y_angle
  input  wire [7:0]           fin_s_i,
  input  wire [SurfW+1:0]     cone_m_i,      // ScaledConst, as y_angle
  input  wire [7:0]           cone_s_i,
