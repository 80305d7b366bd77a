# rpu_candidate: real curve12 intervals, random and edge τ, both metrics; a quarter of the pairs
# edited (flat/arc/straight/code-3 guides, the longest segments, α and β over the whole range).
set(RPU_CANDIDATE_RTL ${RPU_RTL_DIR}/rpu_candidate.v ${RPU_RTL_DIR}/rpu_guide_pair.v
    ${RPU_RTL_DIR}/rpu_curve_point.v ${RPU_RTL_DIR}/rpu_sqrt.v ${RPU_RTL_DIR}/rpu_mul.v)
rpu_verilated_test(tb_rpu_candidate TOP rpu_candidate TB tb/tb_rpu_candidate.cpp
                   SOURCES ${RPU_CANDIDATE_RTL} DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
rpu_verilated_test(tb_rpu_candidate_sq TOP rpu_candidate TB tb/tb_rpu_candidate.cpp
                   SOURCES ${RPU_CANDIDATE_RTL} PARAMS -GMetric=1
                   DEFS RPU_SOURCE_DIR="${PROJECT_SOURCE_DIR}" METRIC=1)
