// A purpose-built three-level design for the cached hierarchical synthesis flow
// (scripts/synth_hier.py; tests/synth/test_synth_hier.py): a top with two parameter sets of a
// unit, each unit with multipliers, a delay line and a small RAM from blocks/. Same format as
// rtl/rpu.f.
+incdir+blocks
blocks/hier_mul.v
blocks/hier_delay.v
blocks/hier_ram.v
hier_unit.v
hier_top.v
