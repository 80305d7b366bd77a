// The RTL of the RPU: every source file, one per line, paths relative to this directory (rtl/).
// The one list: the Verilator testbenches and co-simulation builds (sim/rtl_files.cmake),
// scripts/formal.sh, scripts/yosys_report.sh, scripts/mutate.py and `rpu sweep` read it, and
// each lets its top module pick what it needs (Verilator --top-module, Yosys hierarchy -top).
// The CTest rtl_file_list (sim/scripts/rtl_file_list.cmake) checks that it names every
// rtl/**/*.v and *.vh file and that every entry exists.
//
// Verilator reads it as is, paths taken relative to this file:
//   verilator --lint-only -Wall -F rtl/rpu.f --top-module rpu_top
// Lines: a source file, +incdir+DIR (where `include finds the headers), a header as a
// "// header: FILE" comment (included, never compiled on its own), or a // comment.

+incdir+.

// common: the shared arithmetic blocks
rpu_fifo.v
rpu_mul.v
// header: rpu_mul_latency.vh
rpu_sqrt.v
rpu_div.v
rpu_cordic.v

// curve: the curve path (sphere, K-step IP process, capture)
rpu_chord.v
rpu_sphere.v
rpu_guide_pair.v
rpu_curve_point.v
rpu_candidate.v
rpu_ip_step.v
rpu_ip.v
rpu_capture.v

// texture: the texture path
rpu_ray_plane.v
rpu_texture.v

// surface: the vector-described surfaces
rpu_indicator.v
rpu_indicator_add3.v
rpu_indicator_delay.v
rpu_surface_setup.v
rpu_surface_ip.v
rpu_surface_ip_step.v
rpu_surface_top.v
rpu_surface_admit.v
// header: rpu_surface_desc.vh
// header: rpu_surface_latency.vh

// top: ray generation, the pixel resolve, the top level
rpu_ray_gen.v
rpu_resolve.v
rpu_top.v
