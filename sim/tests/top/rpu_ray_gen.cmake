# rpu_ray_gen (with rpu_sqrt and rpu_div): camera descriptors of scenes/curve12.json and
# scenes/airfield.json from the scene compiler. Default widths (FV = 24, FE = 16): every pixel of
# curve12, the corners, 40,000 random airfield pixels and alternating cameras; FV = FE = 12: a
# few thousand random pixels of both scenes, shrunk to 32 pixels a side (a pixel must span 64
# direction LSBs for the compiler to accept the view). Both then take 3,500 synthetic cameras
# (random edge vectors over the port range, directions within the header's preconditions, and
# v·v = k² − 1).
rpu_verilated_test(tb_rpu_ray_gen TOP rpu_ray_gen TB tb/top/tb_rpu_ray_gen.cpp
                   PARAMS -GTagW=40 -GDirFrac=24 -GEdgeFrac=16 -GIdxW=14
                   DEFS RAYGEN_FULL=1)
rpu_verilated_test(tb_rpu_ray_gen_fv12_fe12 EXTRA TOP rpu_ray_gen TB tb/top/tb_rpu_ray_gen.cpp
                   PARAMS -GDirFrac=12 -GEdgeFrac=12 -GIdxW=14)
