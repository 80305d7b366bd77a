# rpu_surface_setup on the surf_* scenes' surfaces (camera pixels, rays through and grazing the
# bounding spheres, eyes inside them, rays along the range planes, other end angles; every piece
# index), at the defaults and, opt-in, at CW 20 / LW 32 / AW 16 (world and local piece products
# of different latencies, a 4-tile end-plane product).
rpu_verilated_test(tb_rpu_surface_setup TOP rpu_surface_setup TB tb/surface/tb_rpu_surface_setup.cpp
                   PARAMS -GTagW=8)
rpu_verilated_test(tb_rpu_surface_setup_cw20_lw32 EXTRA TOP rpu_surface_setup
                   TB tb/surface/tb_rpu_surface_setup.cpp
                   PARAMS -GCoordW=20 -GDirFrac=20 -GTFrac=20 -GSurfW=32 -GAngleW=16 -GTagW=8)
