// rpu: the command line of the ray-processing-unit model (SCENE.md, "Command line").
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <iostream>

#include "builtin_scenes.h"
#include "common/error.h"
#include "demo.h"
#include "image/image_io.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"
#include "tracer/float_tracer.h"

namespace {

using namespace rpu;

// Hardware parameters and render switches shared by every subcommand.
struct CommonFlags {
  ref::HwParams hw;
  std::string metric = "abs";
  std::string ip_mode = "unrolled";
  int threads = 0;
  bool no_binning = false;
  bool no_grid = false;

  void add_to(CLI::App& app) {
    app.add_option("--n", hw.n, "result bits of the iterative process (K = n/n1 steps)")
        ->capture_default_str();
    app.add_option("--n1", hw.n1, "bits resolved per step (2^n1 candidates per step)")
        ->capture_default_str();
    app.add_option("--coord-w", hw.coord_w, "signed width of positions (LSB = 1 unit)")
        ->capture_default_str();
    app.add_option("--dir-frac", hw.dir_frac, "fraction bits of the ray direction")
        ->capture_default_str();
    app.add_option("--t-frac", hw.t_frac, "fraction bits of the chord parameter t")
        ->capture_default_str();
    app.add_option("--unit-frac", hw.unit_frac, "fraction bits of the guide unit vectors")
        ->capture_default_str();
    app.add_option("--edge-frac", hw.edge_frac, "fraction bits of the PVP edge vectors")
        ->capture_default_str();
    app.add_option("--inv-w", hw.inv_w, "mantissa bits of 1/L^2")->capture_default_str();
    app.add_option("--sqrt-w", hw.sqrt_w, "widest square-root radicand (0 = exact)")
        ->capture_default_str();
    app.add_option("--metric", metric, "distance metric: abs (|d|, the seed's) or squared")
        ->capture_default_str();
    app.add_option("--ip", ip_mode, "K-step process: unrolled (one pair per cycle) or iterative")
        ->capture_default_str();
    app.add_option("--threads", threads, "worker threads (0 = all cores)")->capture_default_str();
    app.add_flag("--no-binning", no_binning, "test every curve segment on every pixel");
    app.add_flag("--no-grid", no_grid, "test every texture segment on every pixel");
  }
  ref::HwParams params() const {
    ref::HwParams p = hw;
    if (metric == "abs") p.metric = ref::Metric::kAbs;
    else if (metric == "squared") p.metric = ref::Metric::kSquared;
    else throw Error("--metric", "must be abs or squared, got '" + metric + "'");
    if (ip_mode == "unrolled") p.unrolled = true;
    else if (ip_mode == "iterative") p.unrolled = false;
    else throw Error("--ip", "must be unrolled or iterative, got '" + ip_mode + "'");
    p.validate();
    return p;
  }
  tracer::FloatOptions float_options() const {
    const ref::HwParams p = params();
    tracer::FloatOptions o;
    o.n = p.n;
    o.n1 = p.n1;
    o.threads = threads;
    o.binning = !no_binning;
    o.grid = !no_grid;
    return o;
  }
  ref::RefOptions ref_options() const { return {threads, !no_binning, !no_grid}; }
};

int render(const std::string& scene_arg, const std::string& backend, const std::string& output,
           const CommonFlags& flags, bool quiet) {
  tracer::FloatOptions o = flags.float_options();
  if (backend != "float" && backend != "float-ip" && backend != "ref")
    throw Error("--backend", "backend '" + backend + "' is not built yet (available: float, "
                "float-ip, ref)");
  image::check_writable(output);
  const scene::CompiledScene sc = scene::compile_scene(app::load_scene_argument(scene_arg));
  const auto t0 = std::chrono::steady_clock::now();
  image::Frame frame;
  std::uint64_t pairs = 0, overflows = 0;
  if (backend == "ref") {
    const ref::ModelScene model = ref::quantize_scene(sc, flags.params());
    ref::RefStats stats;
    frame = ref::render_ref(sc, model, flags.ref_options(), &stats);
    pairs = stats.curve_pairs + stats.texture_pairs;
    overflows = stats.overflow_pairs;
  } else {
    o.method = backend == "float" ? tracer::Method::kIdeal : tracer::Method::kIterative;
    tracer::RenderStats stats;
    frame = tracer::render_float(sc, o, &stats);
    pairs = stats.pairs_tested + stats.texture_pairs_tested;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<scene::Color> colors;
  for (const auto& p : sc.primitives) colors.push_back(p.color);
  image::write_rgb(output, frame.width, frame.height, image::to_rgb(frame, colors, sc.background));
  if (!quiet)
    std::cerr << fmt::format("{}: {}x{} {} in {:.3f} s, {} hit pixels, {} ray/segment pairs\n",
                             output, frame.width, frame.height, backend, secs, frame.hit_pixels(),
                             pairs);
  if (overflows > 0)
    std::cerr << fmt::format("rpu: warning: {} work items saturated a datapath value; widen "
                             "--coord-w or the fraction widths\n", overflows);
  return 0;
}

int print_config(const CommonFlags& flags) {
  const ref::HwParams p = flags.params();
  std::cout << p.describe()
            << fmt::format("threads    = {}\nbinning    = {}\ngrid       = {}\n",
                           flags.threads == 0 ? std::string("all") : std::to_string(flags.threads),
                           flags.no_binning ? "off" : "on", flags.no_grid ? "off" : "on");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rpu: model of an FPGA ray-processing unit for curves smoothed by spherical "
               "interpolation and vector textures"};
  app.require_subcommand(1);
  CommonFlags flags;

  auto* render_cmd = app.add_subcommand("render", "render one image");
  std::string scene_arg, backend = "float", output;
  bool quiet = false;
  render_cmd->add_option("scene", scene_arg, "scene file (JSON, SCENE.md) or builtin:NAME")
      ->required();
  render_cmd->add_option("--backend,-b", backend, "float | float-ip | ref")->capture_default_str();
  render_cmd->add_option("-o,--output", output, "output image (.png, .exr, .ppm, ...)")->required();
  render_cmd->add_flag("-q,--quiet", quiet, "no timing line on stderr");
  flags.add_to(*render_cmd);

  auto* config_cmd = app.add_subcommand("config", "print the effective parameter set");
  flags.add_to(*config_cmd);

  auto* demo_cmd = app.add_subcommand("demo", "render every built-in scene with every backend");
  app::DemoOptions demo;
  demo_cmd->add_option("--out", demo.out_dir, "output directory")->capture_default_str();
  demo_cmd->add_option("--max-side", demo.max_side, "scale scenes down to at most this side");
  flags.add_to(*demo_cmd);

  auto* list_cmd = app.add_subcommand("scenes", "list the built-in scenes");

  CLI11_PARSE(app, argc, argv);
  try {
    if (render_cmd->parsed()) return render(scene_arg, backend, output, flags, quiet);
    if (config_cmd->parsed()) return print_config(flags);
    if (demo_cmd->parsed()) {
      demo.float_options = flags.float_options();
      demo.hw = flags.params();
      return app::run_demo(demo);
    }
    if (list_cmd->parsed()) {
      for (const auto& b : app::builtin_scenes()) std::cout << "builtin:" << b.name << "\n";
      return 0;
    }
  } catch (const rpu::Error& e) {
    std::cerr << "rpu: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "rpu: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
