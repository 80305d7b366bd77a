# rpu_candidate: real curve12 pairs through the frame unit, random and edge τ; a quarter with
# edited frame guides, a quarter with random inputs over the whole port widths. The widest
# step's offsets (Fo = 20) with the seed's metric, the narrowest (Fo = 14, step 0) squared, and
# the iterative form's run-time Fo (8..20 per item) with the seed's metric.
rpu_verilated_test(tb_rpu_candidate TOP rpu_candidate TB tb/curve/tb_rpu_candidate.cpp
                   PARAMS -GFo=20)
rpu_verilated_test(tb_rpu_candidate_sq TOP rpu_candidate TB tb/curve/tb_rpu_candidate.cpp
                   PARAMS -GMetric=1 -GFo=14)
rpu_verilated_test(tb_rpu_candidate_fo TOP rpu_candidate TB tb/curve/tb_rpu_candidate.cpp
                   PARAMS -GFo=0)
