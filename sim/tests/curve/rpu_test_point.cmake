# rpu_test_point: real curve12 intervals, random and edge τ; a quarter of the pairs edited
# (flat/arc/straight/code-3 guides, the longest segments, α and β over the whole range).
rpu_verilated_test(tb_rpu_test_point TOP rpu_test_point TB tb/curve/tb_rpu_test_point.cpp)
