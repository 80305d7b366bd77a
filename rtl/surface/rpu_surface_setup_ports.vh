// The setup's descriptor fields (SurfaceDesc, ref/model/descriptors.h; formats: rpu_surface_setup's
// header) after the bounding sphere and the type, as input ports in descriptor order; included in
// the port lists of rpu_surface_setup and rpu_surface_top, which declare CoordW, MantW, SurfW,
// AngleW and ConstW. The type is rpu_surface_setup's own port; rpu_surface_top reads it from its
// descriptor word (rpu_surface_desc.vh).
// No include guard: each module's list includes it once.
  input  wire [3*CoordW-1:0]  origin_i,      // LSB
  input  wire [9*MantW-1:0]   to_local_i,    // M, row-major, signed entries
  input  wire [6:0]           to_local_s_i,  // unsigned
  input  wire [SurfW-1:0]     y_min_i,       // llsb, signed
  input  wire [SurfW-1:0]     y_max_i,       // llsb, signed
  input  wire [AngleW-1:0]    end_angle_i,   // binary angle
  input  wire [ConstW-1:0]    end_cos_i,     // Q(1.KF), signed
  input  wire [ConstW-1:0]    end_sin_i,     // Q(1.KF), signed
