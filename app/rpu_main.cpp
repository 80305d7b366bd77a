// rpu: the command line of the ray-processing-unit model (README, "Command line").
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <string_view>

#include <sys/stat.h>
#include <unistd.h>

#include "backends.h"
#include "builtin_scenes.h"
#include "compare.h"
#include "run_record.h"
#include "common/error.h"
#include "common/limits.h"
#include "demo.h"
#include "hw_flags.h"
#include "sweep.h"
#include "image/image_io.h"
#include "common/output_file.h"
#include "model/ref_renderer.h"
#include "patch/patch_shading.h"
#include "scene/compiled_scene.h"
#include "tracer/float_tracer.h"
#include "tracer/surface_shading.h"
#include "volume_cmd.h"

namespace {

using namespace rpu;

// --rtl-fault's value → sim::RtlOptions::fault (0: the flag is absent).
int rtl_fault_code(const std::string& name) {
  if (name.empty()) return 0;
  if (name == "argmin-tie") return 1;
  if (name == "far-hit") return 2;
  throw Error("--rtl-fault", "unknown fault '" + name + "' (argmin-tie, far-hit)");
}

// Hardware parameters and render switches shared by every subcommand.
struct CommonFlags {
  app::HwFlags hw;           // --n ... --angle-w: one flag per entry of ref/model/hw_params.def
  long long threads = 0;    // checked by validate() before use
  bool no_binning = false;
  bool no_grid = false;
  std::string size;          // WxH: overrides the scene's resolution
  int max_side = 0;          // scales the scene's resolution down to at most this side
  bool systemc = false;
  std::string trace_pixel;   // X,Y
  std::string trace_out = "trace.fst";
  std::string rtl_fault;
  bool axi = false;          // rtl: through rpu_axi, the AXI shell
  std::string rtl_exe;       // a cosim_<name> executable instead of a built-in configuration
  long long jobs = 0;        // rtl: Verilated instances over contiguous shares (0 = all cores)
  std::string shard;         // rtl: I/N, only that share, its results to -o
  std::vector<std::string> merge_shards;  // rtl: shard files to check and assemble
  std::string patch_method = "thesis";  // docs/algorithms.md §4: thesis | martin | newton
  std::string patch_map_size;           // WxH of the preliminary map ("" = the image's)
  bool patch_map_full = false;          // full-precision map parameters instead of 8 bits
  std::string patch_start = "map";      // map | random (eq 3, Bézier patches)
  double patch_tolerance = patch::RefineOptions{}.tolerance_pixels;
  int patch_iterations = patch::RefineOptions{}.max_iterations;

  void add_to(CLI::App& app) {
    hw.add_to(app);
    app.add_option("--threads", threads, "worker threads (0 = all cores)")->capture_default_str();
    app.add_flag("--no-binning", no_binning, "test every curve segment on every pixel");
    app.add_flag("--no-grid", no_grid, "test every texture segment on every pixel");
    app.add_option("--size", size, "image size WxH, overriding the scene's camera");
    app.add_option("--max-side", max_side, "scale the scene's image down to at most this side");
    app.add_flag("--systemc", systemc, "rtl: use the SystemC harness (rpu_sc) instead of the C++ one");
    app.add_option("--rtl-exe", rtl_exe,
                   "rtl: run the frame on this co-simulation executable (a cosim_<name> built with "
                   "RPU_COSIM_ONLY, e.g. by rpu sweep or scripts/cosim_build_table.py; "
                   "docs/cosim.md) instead of a configuration built into rpu");
    app.add_option("--jobs", jobs,
                   "rtl: co-simulate the frame on this many Verilated instances at once, each a "
                   "contiguous share of the work items on its own core, as that many units on one "
                   "device (0 = all cores; the image and every result are the same as with 1)")
        ->capture_default_str();
    app.add_option("--shard", shard,
                   "rtl: I/N: co-simulate only share I (0-based) of N and write its checked "
                   "results to -o (a shard file, not an image); merge with --merge-shards "
                   "(docs/cosim.md, e.g. a Slurm job array)");
    app.add_option("--merge-shards", merge_shards,
                   "rtl: check the shard files of --shard I/N (all N, same scene and flags) "
                   "against the model and assemble the image (-o) instead of simulating");
    app.add_option("--trace-pixel", trace_pixel,
                   "rtl: re-run the work items of pixel X,Y with an FST waveform");
    app.add_option("--trace-out", trace_out, "rtl: the waveform file of --trace-pixel")
        ->capture_default_str();
    app.add_option("--patch-method", patch_method,
                   "patches: thesis (map + gradient / steepest descent / Newton-Cramer), martin "
                   "(Martin et al. 2000 BVH + Newton) or newton (map + Newton)")
        ->capture_default_str();
    app.add_option("--patch-map-size", patch_map_size,
                   "patches: preliminary map resolution WxH (default: the image's)");
    app.add_flag("--patch-map-full", patch_map_full,
                 "patches: full-precision map parameters (default: 8 bits, as the thesis)");
    app.add_option("--patch-start", patch_start,
                   "patches: map, or random (eq 3: random starts for Bezier patches)")
        ->capture_default_str();
    app.add_option("--patch-tolerance", patch_tolerance,
                   "patches: convergence, the hit's distance from the ray in pixels")
        ->capture_default_str();
    app.add_option("--patch-iterations", patch_iterations,
                   "patches: iteration budget of the thesis refiners (steps or directions)")
        ->capture_default_str();
    app.add_flag("--axi", axi,
                 "rtl: co-simulate rpu_top inside its AXI shell rpu_axi (docs/axi.md): descriptors "
                 "over AXI4-Lite, items, pixels and results over AXI4-Stream, through bus-"
                 "functional models");
    app.add_flag("--rtl-fault{argmin-tie}", rtl_fault,
                 "rtl: use the build with a deliberately injected fault (tests of the checker): "
                 "argmin-tie (the IP's argmin keeps the last minimum: work-item fields) or, as "
                 "--rtl-fault=far-hit, the resolve keeps the farther hit (pixels)");
  }
  // Refuses out-of-range flags shared by every subcommand (common/limits.h).
  void validate() const {
    limits::check_threads("--threads", threads);
    if (jobs < 0 || jobs > limits::kMaxCosimJobs)
      throw Error("--jobs", fmt::format("must be in [0, {}] (0 = all cores), got {}",
                                        limits::kMaxCosimJobs, jobs));
    if (max_side < 0) throw Error("--max-side", "must be at least 1 (0 = off), got " +
                                                std::to_string(max_side));
  }
  // The scene with the size flags applied; the result is held to the same image-size limit as
  // a scene file's camera.
  scene::Scene load(const std::string& arg) const {
    validate();
    scene::Scene sc = app::load_scene_argument(arg);
    if (!size.empty()) {
      const auto [w, h] = parse_size(size);
      limits::check_image_size("--size", w, h);
      sc.camera.width = static_cast<int>(w);
      sc.camera.height = static_cast<int>(h);
    }
    if (max_side > 0) {
      const long long side = std::max(sc.camera.width, sc.camera.height);
      if (side > max_side) {
        const long long w = std::max(1LL, sc.camera.width * max_side / side);
        const long long h = std::max(1LL, sc.camera.height * max_side / side);
        limits::check_image_size("--max-side", w, h);
        sc.camera.width = static_cast<int>(w);
        sc.camera.height = static_cast<int>(h);
      }
    }
    return sc;
  }
  // "WxH" (x or X) as two integers; any other text is refused naming the flag.
  static std::pair<long long, long long> parse_size(const std::string& text,
                                                    const std::string& flag = "--size") {
    const auto bad = [&] {
      return Error(flag, "must be WxH (two whole numbers, e.g. 640x480), got '" + text + "'");
    };
    const size_t x = text.find_first_of("xX");
    if (x == std::string::npos) throw bad();
    long long v[2] = {0, 0};
    const std::string part[2] = {text.substr(0, x), text.substr(x + 1)};
    for (int k = 0; k < 2; ++k) {
      const char* b = part[k].data();
      const char* e = b + part[k].size();
      const auto [end, ec] = std::from_chars(b, e, v[k]);
      if (part[k].empty() || ec == std::errc::result_out_of_range)
        throw ec == std::errc::result_out_of_range
            ? Error(flag, "image size '" + text + "' is out of range: each side must be in "
                              "[1, " + std::to_string(limits::kMaxImageSide) + "]")
            : bad();
      if (ec != std::errc() || end != e) throw bad();
    }
    return {v[0], v[1]};
  }
  app::BackendOptions backend_options() const {
    validate();
    app::BackendOptions o;
    o.hw = params();
    o.fl = float_options();
    o.ref = ref_options();
    o.patch = patch_options();
    o.systemc = systemc;
    o.rtl_exe = rtl_exe;
    o.jobs = static_cast<int>(jobs);
    o.merge_shards = merge_shards;
    if (!shard.empty()) {
      int i = -1, n = -1;
      char c = 0, extra = 0;
      if (std::sscanf(shard.c_str(), "%d%c%d%c", &i, &c, &n, &extra) != 3 || c != '/' || n < 1 ||
          i < 0 || i >= n || n > limits::kMaxShards)
        throw Error("--shard", fmt::format("must be I/N with 0 <= I < N <= {}, got '{}'",
                                           limits::kMaxShards, shard));
      o.shard = std::make_pair(i, n);
      if (!merge_shards.empty())
        throw Error("--shard", "cannot be combined with --merge-shards (one runs a share, the "
                               "other merges them)");
    }
    if (!rtl_exe.empty()) {
      if (systemc) throw Error("--rtl-exe", "cannot be combined with --systemc (rpu_sc is one harness, "
                                            "--rtl-exe another)");
      if (rtl_fault_code(rtl_fault) != 0)
        throw Error("--rtl-exe", "cannot be combined with --rtl-fault (the fault-injected build is "
                                 "built into rpu)");
      struct stat st {};
      if (::stat(rtl_exe.c_str(), &st) != 0 || !S_ISREG(st.st_mode) ||
          ::access(rtl_exe.c_str(), X_OK) != 0)
        throw Error("--rtl-exe", "'" + rtl_exe + "' is not an executable file (a cosim_<name> "
                                 "from an RPU_COSIM_ONLY build)");
    }
    o.fault = rtl_fault_code(rtl_fault);
    o.axi = axi;
    if (axi && (systemc || !rtl_exe.empty() || o.fault))
      throw Error("--axi", std::string("cannot be combined with ") +
                               (systemc ? "--systemc" : !rtl_exe.empty() ? "--rtl-exe" : "--rtl-fault") +
                               " (the AXI shell is built into rpu as its own configurations)");
    o.trace_path = trace_out;
    if (!trace_pixel.empty()) {
      int x = -1, y = -1;
      char c = 0, extra = 0;
      if (std::sscanf(trace_pixel.c_str(), "%d%c%d%c", &x, &c, &y, &extra) != 3 || c != ',' ||
          x < 0 || y < 0)
        throw Error("--trace-pixel", "must be X,Y (pixel column and row), got '" + trace_pixel + "'");
      o.trace_pixel = std::make_pair(x, y);
      // The waveform's place is checked before the run (a missing directory, a directory or a
      // device would otherwise cost a whole co-simulation and write nothing).
      check_output_path(trace_out, "waveform");
    }
    return o;
  }
  ref::HwParams params() const { return hw.params(); }
  tracer::FloatOptions float_options() const {
    const ref::HwParams p = params();
    tracer::FloatOptions o;
    o.n = p.n;
    o.n1 = p.n1;
    o.surf_n1_first = p.surf_n1_first;
    o.threads = static_cast<int>(threads);
    o.binning = !no_binning;
    o.grid = !no_grid;
    return o;
  }
  patch::PatchRenderOptions patch_options() const {
    patch::PatchRenderOptions o;
    o.method = patch::parse_patch_method(patch_method, "--patch-method");
    if (patch_start == "map") o.start = patch::PatchStart::kMap;
    else if (patch_start == "random") o.start = patch::PatchStart::kRandom;
    else throw Error("--patch-start", "must be map or random, got '" + patch_start + "'");
    if (!patch_map_size.empty()) {
      const auto [w, h] = parse_size(patch_map_size, "--patch-map-size");
      limits::check_image_size("--patch-map-size", w, h);
      o.map.width = static_cast<int>(w);
      o.map.height = static_cast<int>(h);
    }
    o.map.quantised = !patch_map_full;
    if (!(patch_tolerance > 0.0 && patch_tolerance <= 1.0))
      throw Error("--patch-tolerance", fmt::format("must be in (0, 1] pixels, got {}", patch_tolerance));
    if (patch_iterations < 1 || patch_iterations > limits::kMaxPatchIterations)
      throw Error("--patch-iterations",
                  fmt::format("must be in [1, {}] (README, \"Limits\"), got {}",
                              limits::kMaxPatchIterations, patch_iterations));
    o.refine.tolerance_pixels = patch_tolerance;
    o.refine.max_iterations = patch_iterations;
    o.refine.max_evaluations = 4 * patch_iterations;
    o.threads = static_cast<int>(threads);
    return o;
  }
  ref::RefOptions ref_options() const {
    return {static_cast<int>(threads), !no_binning, !no_grid};
  }
};

int render(const std::string& scene_arg, const std::string& backend, const std::string& output,
           const CommonFlags& flags, bool quiet, bool shade) {
  const auto& names = app::backend_names();
  if (std::find(names.begin(), names.end(), backend) == names.end())
    throw Error("--backend", "unknown backend '" + backend + "' (float, float-ip, ref, rtl)");
  app::BackendOptions bo = flags.backend_options();
  bo.shard_out = output;  // --shard: -o is the share's result file
  if ((bo.systemc || bo.trace_pixel || bo.fault || !bo.rtl_exe.empty() || bo.shard ||
       !bo.merge_shards.empty() || bo.axi) && backend != "rtl")
    throw Error(bo.systemc ? "--systemc" : bo.fault ? "--rtl-fault" : bo.axi ? "--axi" :
                !bo.rtl_exe.empty() ? "--rtl-exe" : bo.shard ? "--shard" :
                !bo.merge_shards.empty() ? "--merge-shards" : "--trace-pixel",
                "applies to --backend rtl only");
  if (bo.shard && bo.trace_pixel)
    throw Error("--shard", "cannot be combined with --trace-pixel (trace the pixel in a whole-frame run)");
  if (!bo.merge_shards.empty() && (bo.trace_pixel || bo.systemc || !bo.rtl_exe.empty() || bo.fault))
    throw Error("--merge-shards", "only checks and assembles shard files; --trace-pixel, --systemc, "
                                  "--rtl-exe and --rtl-fault belong to the --shard runs");
  if (bo.shard) check_output_path(output, "shard file");
  else image::check_writable(output);
  if (same_file(scene_arg, output))
    throw Error(output, "is the scene file being rendered; refusing to overwrite the input");
  const scene::CompiledScene sc = scene::compile_scene(flags.load(scene_arg));
  if (shade && backend != "float" && backend != "float-ip")
    throw Error("--shade", "applies to --backend float and float-ip only; the " + backend +
                               " image holds exact colours");
  if (shade && sc.surfaces.empty() && sc.patches.empty())
    throw Error("--shade", "changes nothing: " + scene_arg + " has no surfaces or patches "
                           "(curves and textures are drawn in exact colours)");
  const app::BackendResult r = app::run_backend(backend, sc, bo);
  if (bo.shard) {
    if (!quiet)
      std::cerr << fmt::format("{}: share {} of {} of the {}x{} frame, {} work items, {} cycles "
                               "({} harness, {}), {:.0f} items/s; checked against the model: {}\n",
                               output, bo.shard->first, bo.shard->second, sc.camera.width,
                               sc.camera.height, r.pairs, r.rtl["cycles"].dump(),
                               r.rtl["harness"].get<std::string>(),
                               r.rtl["configuration"].get<std::string>(),
                               r.rtl["items_per_second"].get<double>(),
                               r.rtl_ok ? "equal" : "DIFFERENT");
    for (const auto& line : r.reports) std::cerr << line << "\n";
    if (!r.rtl_ok) {
      std::cerr << "rpu: the RTL differs from the reference model (see above)\n";
      return 2;
    }
    return 0;
  }
  const image::Frame& frame = r.render.frame;
  std::vector<scene::Color> colors;
  for (const auto& p : sc.primitives) colors.push_back(p.color);
  std::vector<float> rgb = image::to_rgb(frame, colors, sc.background);
  if (shade && !r.patch_hits.pixels.empty()) {
    patch::PatchHitMap shown = r.patch_hits;  // pixels a curve or texture won stay flat
    for (size_t k = 0; k < shown.pixels.size(); ++k)
      shown.pixels[k].hit = shown.pixels[k].hit && frame.primitive[k] >= sc.first_patch_primitive;
    patch::shade_patch_pixels(rgb, shown, patch::prepare_surfaces(sc.patches), sc.camera);
  }
  if (shade) tracer::shade_surface_pixels(rgb, frame, sc);  // vector-described surfaces
  image::write_rgb(output, frame.width, frame.height, rgb);
  if (!quiet)
    std::cerr << fmt::format("{}: {}x{} {} in {:.3f} s, {} hit pixels, {} ray/segment pairs\n",
                             output, frame.width, frame.height, backend, r.render.seconds,
                             frame.hit_pixels(), r.pairs);
  if (!quiet && r.patch.is_object())
    std::cerr << fmt::format("patches ({}): {} {:.3f} s, {} {:.3f} s, {} starts ({} converged), {} "
                             "silhouette pixels (no start converged: {} left the domain, {} "
                             "stalled, {} iteration limit, {} singular); {} Newton fallbacks\n",
                             r.patch["method"].get<std::string>(),
                             r.patch.contains("map_seconds") ? "map" : "bvh build",
                             r.patch.value("map_seconds", r.patch.value("bvh_build_seconds", 0.0)),
                             r.patch.contains("refine_seconds") ? "refine" : "trace",
                             r.patch.value("refine_seconds", r.patch.value("trace_seconds", 0.0)),
                             r.patch["starts"].dump(), r.patch["converged"].dump(),
                             r.patch["silhouette_pixels"].dump(),
                             r.patch["silhouette_left_domain"].dump(),
                             r.patch["silhouette_stalled"].dump(),
                             r.patch["silhouette_iteration_limit"].dump(),
                             r.patch["silhouette_singular"].dump(),
                             r.patch["fallback_starts"].dump());
  if (!r.precision_warning.empty()) std::cerr << "rpu: warning: " << r.precision_warning << "\n";
  if (r.overflows > 0)
    std::cerr << fmt::format("rpu: warning: {} work items saturated a datapath value; widen "
                             "--coord-w or the fraction widths\n", r.overflows);
  if (backend == "rtl") {
    if (!quiet)
      std::cerr << fmt::format("rtl ({} harness, {}): {} cycles, latency {}, {:.3f} items/cycle, "
                               "{:.0f} items/s, {:.0f} cycles/s simulated{}\n",
                               r.rtl["harness"].get<std::string>(),
                               r.rtl["configuration"].get<std::string>(), r.rtl["cycles"].dump(),
                               r.rtl["latency_cycles"].dump(), r.rtl["items_per_cycle"].get<double>(),
                               r.rtl["items_per_second"].get<double>(),
                               r.rtl["cycles_per_second"].get<double>(),
                               r.rtl["instances"].get<int>() > 1
                                   ? fmt::format("; {} instances (cycles {}), the frame {} cycles "
                                                 "on that many units",
                                                 r.rtl["instances"].dump(),
                                                 r.rtl["instance_cycles"].dump(),
                                                 r.rtl["frame_cycles"].dump())
                                   : std::string());
    for (const auto& line : r.reports) std::cerr << line << "\n";
    if (!r.trace_log.empty()) std::cerr << r.trace_log;
    if (!r.rtl_ok) {
      std::cerr << "rpu: the RTL differs from the reference model (see above)\n";
      return 2;
    }
  }
  return 0;
}

// Flags that a subcommand accepts (they are shared) but that change nothing there are refused
// with one line naming the flag: `rpu config` prints the parameter set and renders nothing, and
// `rpu demo` runs every scene, where one pixel's waveform or an injected fault mean nothing.
void refuse_flags(const CLI::App& cmd, std::initializer_list<const char*> names,
                  const std::string& why) {
  for (const char* name : names)
    if (cmd.count(name) > 0) throw Error(name, "does not apply to rpu " + cmd.get_name() + ": " + why);
}

int print_config(const CommonFlags& flags) {
  flags.validate();
  const ref::HwParams p = flags.params();
  std::cout << p.describe()
            << fmt::format("threads    = {}\nbinning    = {}\ngrid       = {}\n",
                           flags.threads == 0 ? std::string("all") : std::to_string(flags.threads),
                           flags.no_binning ? "off" : "on", flags.no_grid ? "off" : "on")
            << "Verilated rpu_top configurations (--backend rtl):\n" << app::rtl_configurations();
  return 0;
}

// `rpu config --markdown[=readme]`: the docs' parameter tables, generated from the parameter table
// (the CTest docs_params compares them with docs/fixed-point.md and README.md).
int print_markdown(const CLI::App& cmd, const CommonFlags& flags, const std::string& which) {
  const std::vector<std::string> given = flags.hw.given(cmd);
  if (!given.empty())
    throw Error(given.front(), "does not apply to rpu config --markdown: the tables show the defaults");
  if (which == "docs") std::cout << ref::hw_params_markdown();
  else if (which == "readme") std::cout << ref::hw_params_readme_rows();
  else throw Error("--markdown", "must be docs (the default) or readme, got '" + which + "'");
  return 0;
}

// Output printed on stdout (rpu config, rpu scenes, rpu volume's table) is checked like every
// file rpu writes: a failed write (a full disk, /dev/full, a closed pipe) is one error line and
// exit 1, never a silent loss with exit 0.
int check_stdout(int status) {
  errno = 0;
  std::cout.flush();
  if (!std::cout.good() || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int err = errno;
    std::cerr << "rpu: error: standard output: cannot write"
              << (err != 0 ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
    return 1;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rpu: model of an FPGA ray-processing unit for analytically described primitives: "
               "spatial curves smoothed by spherical interpolation and vector textures (float, "
               "float-ip, the bit-accurate model ref and the Verilated RTL), vector-described "
               "surfaces (float, float-ip, ref) and Bezier/B-spline/NURBS patches (float, "
               "float-ip). Scene files: docs/scene-format.md"};
  app.require_subcommand(1);
  CommonFlags flags;

  auto* render_cmd = app.add_subcommand("render", "render one image");
  std::string scene_arg, backend = "float", output;
  bool quiet = false;
  render_cmd->add_option("scene", scene_arg, "scene file (JSON, docs/scene-format.md) or builtin:NAME")
      ->required();
  render_cmd->add_option("--backend,-b", backend, "float | float-ip | ref | rtl")
      ->capture_default_str();
  render_cmd->add_option("-o,--output", output, "output image (.png, .exr, .ppm, ...)")->required();
  render_cmd->add_flag("-q,--quiet", quiet, "no timing line on stderr");
  bool shade = false;
  render_cmd->add_flag("--shade", shade,
                       "patches and surfaces: Lambert shading with the surface normal (a "
                       "picture; default: exact flat colours)");
  flags.add_to(*render_cmd);

  auto* config_cmd = app.add_subcommand("config", "print the effective parameter set");
  flags.add_to(*config_cmd);
  std::string markdown;
  config_cmd->add_flag("--markdown{docs}", markdown,
                       "print the parameter table of docs/fixed-point.md instead (generated from "
                       "ref/model/hw_params.def), or with --markdown=readme its rows of the "
                       "README's table");

  auto* demo_cmd = app.add_subcommand(
      "demo", "rpu compare on every built-in scene: every backend, the RTL checked, index.html");
  app::DemoOptions demo;
  demo_cmd->add_option("--out", demo.out_dir, "output directory")->capture_default_str();
  demo_cmd->add_flag("--no-rtl", demo.compare.skip_rtl, "skip the RTL (software backends only)");
  demo_cmd->add_option("--surface-max-side", demo.surface_max_side,
                       "scale scenes with surfaces down to at most this side (0 = off): their "
                       "co-simulation takes 142 cycles per surface piece (docs/cosim.md)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  flags.add_to(*demo_cmd);

  auto* compare_cmd = app.add_subcommand(
      "compare", "render with every backend, check the RTL against the model, write a report");
  std::string compare_scene;
  app::CompareOptions compare;
  compare_cmd->add_option("scene", compare_scene, "scene file (JSON) or builtin:NAME")->required();
  compare_cmd->add_option("--out", compare.out_dir, "output directory")->required();
  compare_cmd->add_flag("--no-rtl", compare.skip_rtl, "skip the RTL (software backends only)");
  compare_cmd->add_flag("-q,--quiet", compare.quiet, "no progress on stderr");
  flags.add_to(*compare_cmd);

  auto* sweep_cmd = app.add_subcommand(
      "sweep", "hardware-parameter sweep: accuracy, RTL cycles and resources per configuration");
  app::SweepOptions sweep;
  sweep_cmd->add_option("sweep", sweep.file, "sweep description (JSON, docs/sweeps.md)")
      ->required();
  sweep_cmd->add_option("--out", sweep.out_dir, "output directory")->required();
  sweep_cmd->add_option("-j,--jobs", sweep.jobs, "configurations in parallel (0 = all cores)")
      ->capture_default_str();
  sweep_cmd->add_flag("--no-rtl", sweep.no_rtl, "skip the co-simulated sample");
  sweep_cmd->add_flag("--no-yosys", sweep.no_yosys, "skip the Yosys resource estimates");
  sweep_cmd->add_flag("--emit-jobs", sweep.emit_jobs,
                      "write jobs.txt (one command per configuration) and merge.sh, run nothing");
  sweep_cmd->add_option("--config", sweep.config, "run only this configuration (a jobs.txt line)");
  sweep_cmd->add_flag("--merge", sweep.merge, "only collect the results and write the report");

  auto* list_cmd = app.add_subcommand("scenes", "list the built-in scenes");

  auto* volume_cmd = app.add_subcommand(
      "volume", "volume enclosed by the scene's Bezier patches: exact, graphical, slices");
  std::string volume_scene;
  app::VolumeOptions volume;
  volume_cmd->add_option("scene", volume_scene, "scene file (JSON) or builtin:NAME")->required();
  volume_cmd->add_option("--slices", volume.slices, "slice intervals of the slice method")
      ->capture_default_str();
  volume_cmd->add_option("--slice-grid", volume.slice_grid,
                         "tessellation per patch side for the slice areas")
      ->capture_default_str();
  volume_cmd->add_flag("--no-closure-check", volume.no_closure_check,
                       "print the estimates even for an open or inconsistently oriented model");
  volume_cmd->add_flag("--planar-openings", volume.planar_openings,
                       "accept openings in planes z = const as closed by those planes");

  // A file-size limit (ulimit -f) must make a write fail with EFBIG, which is reported, rather
  // than kill the process half-way through a file.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    std::cerr << "rpu: error: command line: " << what << " (see rpu --help)\n";
    return 1;
  }
  try {
    if (render_cmd->parsed()) return render(scene_arg, backend, output, flags, quiet, shade);
    if (config_cmd->parsed()) {
      refuse_flags(*config_cmd,
                   {"--size", "--max-side", "--systemc", "--trace-pixel", "--trace-out",
                    "--rtl-fault", "--patch-method", "--patch-map-size", "--patch-map-full",
                    "--patch-start", "--patch-tolerance", "--patch-iterations", "--rtl-exe",
                    "--jobs", "--shard", "--merge-shards", "--axi"},
                   "it prints the parameter set and renders nothing");
      if (!markdown.empty()) return check_stdout(print_markdown(*config_cmd, flags, markdown));
      return check_stdout(print_config(flags));
    }
    if (compare_cmd->parsed()) {
      refuse_flags(*compare_cmd, {"--shard", "--merge-shards"},
                   "shards are co-simulated and merged with rpu render --backend rtl");
      compare.backends = flags.backend_options();
      compare.command = app::command_line(argc, argv);
      if (!compare_scene.starts_with("builtin:")) compare.input_file = compare_scene;
      return app::run_compare(compare_scene, flags.load(compare_scene), compare);
    }
    if (demo_cmd->parsed()) {
      refuse_flags(*demo_cmd, {"--trace-pixel", "--trace-out", "--rtl-fault", "--rtl-exe", "--shard",
                               "--merge-shards"},
                   "it compares every built-in scene; use rpu render or rpu compare on one scene");
      demo.compare.backends = flags.backend_options();
      demo.compare.command = app::command_line(argc, argv);
      demo.load = [&](const std::string& arg) { return flags.load(arg); };
      return app::run_demo(demo);
    }
    if (sweep_cmd->parsed()) {
      std::error_code ec;
      sweep.self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
      if (ec) sweep.self = argv[0];
      return app::run_sweep(sweep);
    }
    if (volume_cmd->parsed()) return check_stdout(app::run_volume(volume_scene, volume, std::cout));
    if (list_cmd->parsed()) {
      for (const auto& b : app::builtin_scenes()) std::cout << "builtin:" << b.name << "\n";
      return check_stdout(0);
    }
  } catch (const rpu::Error& e) {
    std::cerr << "rpu: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "rpu: error: out of memory (see README, \"Limits\")\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "rpu: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
