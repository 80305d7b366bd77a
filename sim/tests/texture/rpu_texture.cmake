# The texture path. rpu_ray_plane (with rpu_div): every ellipse6 pixel, random airfield pixels,
# constructed cameras (eye below / on the plane, v̂_z = 0, grazing rays leaving the range) and
# random port values. rpu_texture (with rpu_chord, rpu_guide_pair, rpu_sqrt, rpu_curve_point):
# (p0, segment) pairs of ellipse6, polyline9 and airfield, p0 from the model's ray/plane point of
# real pixels, segments from the classification grid around p0 and at random, plus descriptor
# edges and exact comparison boundaries. Opt-in extras: a narrow ray/plane set (frames of 32
# pixels: the compiler refuses finer ones at DirFrac 12), the texture unit
# with pre-shifted guide roots (SqrtW 40; CoordW 16 with SqrtW 32 and a 3-bit tag).
rpu_verilated_test(tb_rpu_ray_plane TOP rpu_ray_plane TB tb/texture/tb_rpu_ray_plane.cpp
                   PARAMS -GTagW=40)
rpu_verilated_test(tb_rpu_ray_plane_cw16_fv12 EXTRA TOP rpu_ray_plane
                   TB tb/texture/tb_rpu_ray_plane.cpp
                   PARAMS -GCoordW=16 -GDirFrac=12 -GEdgeFrac=12)
rpu_verilated_test(tb_rpu_texture TOP rpu_texture TB tb/texture/tb_rpu_texture.cpp
                   PARAMS -GTagW=8)
rpu_verilated_test(tb_rpu_texture_s40 EXTRA TOP rpu_texture TB tb/texture/tb_rpu_texture.cpp
                   PARAMS -GSqrtW=40)
rpu_verilated_test(tb_rpu_texture_cw16_s32 EXTRA TOP rpu_texture TB tb/texture/tb_rpu_texture.cpp
                   PARAMS -GCoordW=16 -GTFrac=20 -GUnitFrac=12 -GInvW=16 -GSqrtW=32 -GTagW=3)
