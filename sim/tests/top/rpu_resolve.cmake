# rpu_resolve: 100,000 random pixels of 0..12 work items (pooled depths and ids: many exact
# ties), random valid gaps and backpressure phases, against ref::Resolve; the defaults and a
# narrow configuration (pixel index wrapping at 6 bits, 3-bit ids, 20-bit depths); a wide one
# (128-bit depths, 31-bit ids, 64-bit pixels) is opt-in.
rpu_verilated_test(tb_rpu_resolve TOP rpu_resolve TB tb/top/tb_rpu_resolve.cpp)
rpu_verilated_test(tb_rpu_resolve_narrow EXTRA TOP rpu_resolve TB tb/top/tb_rpu_resolve.cpp
                   PARAMS -GPixW=6 -GDepthW=20 -GPrimW=3)
rpu_verilated_test(tb_rpu_resolve_wide EXTRA TOP rpu_resolve TB tb/top/tb_rpu_resolve.cpp
                   PARAMS -GPixW=64 -GDepthW=128 -GPrimW=31)
