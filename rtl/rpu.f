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

+incdir+common
+incdir+curve
+incdir+surface
+incdir+top
+incdir+axi

// common: the shared arithmetic blocks
common/rpu_fifo.v
common/rpu_tag_queue.v
common/rpu_stage.v
common/rpu_skid.v
common/rpu_latency_check.v
common/rpu_delay.v
common/rpu_add3.v
common/rpu_mul.v
common/rpu_mul_vec.v
// header: common/rpu_mul_latency.vh
// header: common/rpu_widths.vh
// header: common/rpu_latency_check.vh
// header: common/rpu_formal_ports.vh
common/rpu_sqrt.v
common/rpu_div.v
common/rpu_cordic.v

// curve: the curve path (sphere, K-step IP process, capture)
curve/rpu_chord.v
curve/rpu_sphere.v
curve/rpu_guide_pair.v
curve/rpu_curve_point.v
curve/rpu_frame.v
curve/rpu_candidate.v
curve/rpu_test_point.v
curve/rpu_ip_step.v
curve/rpu_ip.v
curve/rpu_capture.v
// header: curve/rpu_guide_desc.vh
// header: curve/rpu_guide_shape.vh
// header: curve/rpu_ip_params.vh
// header: curve/rpu_ip_derived.vh
// header: curve/rpu_frame_fn.vh

// texture: the texture path
texture/rpu_ray_plane.v
texture/rpu_texture.v

// surface: the vector-described surfaces
surface/rpu_surface_vsub.v
surface/rpu_indicator.v
surface/rpu_surface_setup.v
surface/rpu_surface_ip.v
surface/rpu_surface_ip_step.v
surface/rpu_surface_top.v
surface/rpu_surface_admit.v
// header: surface/rpu_surface_desc.vh
// header: surface/rpu_surface_ip_params.vh
// header: surface/rpu_surface_state.vh
// header: surface/rpu_surface_setup_ports.vh
// header: surface/rpu_surface_latency.vh

// top: ray generation, the pixel resolve, the top level
top/rpu_ray_gen.v
top/rpu_resolve.v
top/rpu_top.v
// header: top/rpu_top_params.vh
// header: top/rpu_cam_desc.vh
// header: top/rpu_seg_desc.vh
// header: top/rpu_top_words.vh
// header: top/rpu_surf_desc.vh
// header: top/rpu_top_props.vh
// header: top/rpu_top_formal_decl.vh
// header: top/rpu_top_formal_ray.vh
// header: top/rpu_top_formal_paths.vh
// header: top/rpu_top_formal_surface.vh

// axi: the AXI4-Lite / AXI4-Stream shell around rpu_top (docs/axi.md)
axi/rpu_axis_gather.v
axi/rpu_axis_scatter.v
axi/rpu_axil_port.v
axi/rpu_axi.v
// header: axi/rpu_axi_regs.vh
// header: axi/rpu_axi_props.vh
// header: axi/rpu_axi_formal_top.vh
// header: axi/rpu_axil_port_props.vh
