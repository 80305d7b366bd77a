# rpu_candidate: real curve12 intervals, random and edge τ, both metrics; a quarter of the pairs
# edited (flat/arc/straight/code-3 guides, the longest segments, α and β over the whole range).
rpu_verilated_test(tb_rpu_candidate TOP rpu_candidate TB tb/curve/tb_rpu_candidate.cpp)
rpu_verilated_test(tb_rpu_candidate_sq TOP rpu_candidate TB tb/curve/tb_rpu_candidate.cpp
                   PARAMS -GMetric=1
                   DEFS METRIC=1)
