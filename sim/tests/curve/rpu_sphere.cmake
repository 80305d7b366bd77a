# rpu_chord alone (every inv_s, saturation edges) and rpu_sphere on curve12 / random scenes /
# range edges / random port values, at the defaults and at a narrow set with a pre-shifted root.
# The default run's 40-bit tag waits in the unit's rpu_tag_queue (32 bits or more); the narrow
# set's 8-bit tag rides the stages.
rpu_verilated_test(tb_rpu_chord TOP rpu_chord TB tb/curve/tb_rpu_chord.cpp
                   PARAMS -GTagW=8)
rpu_verilated_test(tb_rpu_sphere TOP rpu_sphere TB tb/curve/tb_rpu_sphere.cpp
                   PARAMS -GTagW=40)
rpu_verilated_test(tb_rpu_sphere_cw16_s32 EXTRA TOP rpu_sphere TB tb/curve/tb_rpu_sphere.cpp
                   PARAMS -GCoordW=16 -GDirFrac=20 -GTFrac=20 -GInvW=16 -GSqrtW=32 -GTagW=8)
