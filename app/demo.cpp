#include "demo.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "builtin_scenes.h"
#include "common/error.h"
#include "image/image_io.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "model/ref_renderer.h"

namespace rpu::app {

scene::Scene load_scene_argument(const std::string& argument) {
  constexpr std::string_view kPrefix = "builtin:";
  if (argument.starts_with(kPrefix)) {
    const std::string name = argument.substr(kPrefix.size());
    std::string known;
    for (const auto& b : builtin_scenes()) {
      if (name == b.name) return scene::parse_scene(b.json, argument);
      known += (known.empty() ? "" : ", ") + std::string(b.name);
    }
    throw Error(argument, "no such built-in scene (known: " + known + ")");
  }
  return scene::load_scene(argument);
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

namespace {

// Pixels that differ between two frames, and in which direction a hit was lost or gained.
struct Agreement {
  size_t differ = 0, only_a = 0, only_b = 0;
};
Agreement compare(const image::Frame& a, const image::Frame& b) {
  Agreement g;
  g.differ = image::count_differing_pixels(a, b);
  for (size_t k = 0; k < a.primitive.size(); ++k) {
    const bool ha = a.primitive[k] != image::kBackground;
    const bool hb = b.primitive[k] != image::kBackground;
    g.only_a += ha && !hb;
    g.only_b += hb && !ha;
  }
  return g;
}

}  // namespace

int run_demo(const DemoOptions& options) {
  namespace fs = std::filesystem;
  fs::create_directories(options.out_dir);
  nlohmann::json summary = nlohmann::json::array();
  std::string md = fmt::format(
      "# Demo renders\n\nn = {}, n1 = {} (K = {}), coord_w = {}, metric = {}.\n\n"
      "Differing pixels (hit only in the first / only in the second).\n\n"
      "| scene | size | segments | hit px float / float-ip / ref | float-ip vs float "
      "| ref vs float-ip | ref vs float | seconds float / float-ip / ref |\n"
      "|---|---|---|---|---|---|---|---|\n",
      options.hw.n, options.hw.n1, options.hw.K(), options.hw.coord_w,
      options.hw.metric == ref::Metric::kAbs ? "abs" : "squared");
  for (const auto& b : builtin_scenes()) {
    scene::Scene sc = scene::parse_scene(b.json, std::string("builtin:") + b.name);
    if (options.max_side > 0) {
      const int side = std::max(sc.camera.width, sc.camera.height);
      if (side > options.max_side) {
        sc.camera.width = std::max(1, sc.camera.width * options.max_side / side);
        sc.camera.height = std::max(1, sc.camera.height * options.max_side / side);
      }
    }
    const scene::CompiledScene compiled = scene::compile_scene(sc);
    std::vector<scene::Color> colors;
    for (const auto& p : compiled.primitives) colors.push_back(p.color);
    nlohmann::json entry = {{"scene", b.name},
                            {"width", sc.camera.width},
                            {"height", sc.camera.height},
                            {"pixels", sc.camera.width * sc.camera.height},
                            {"curve_segments", compiled.curve_segments.size()},
                            {"texture_segments", compiled.texture_segments.size()}};
    constexpr int kBackends = 3;
    const char* names[kBackends] = {"float", "float-ip", "ref"};
    image::Frame frames[kBackends];
    double times[kBackends];
    for (int m = 0; m < kBackends; ++m) {
      const auto t0 = std::chrono::steady_clock::now();
      std::uint64_t pairs = 0, overflows = 0;
      if (m < 2) {
        tracer::FloatOptions fo = options.float_options;
        fo.method = m == 0 ? tracer::Method::kIdeal : tracer::Method::kIterative;
        tracer::RenderStats stats;
        frames[m] = tracer::render_float(compiled, fo, &stats);
        pairs = stats.pairs_tested + stats.texture_pairs_tested;
      } else {
        const ref::ModelScene model = ref::quantize_scene(compiled, options.hw);
        ref::RefStats stats;
        frames[m] = ref::render_ref(compiled, model,
                                    {options.float_options.threads, options.float_options.binning,
                                     options.float_options.grid},
                                    &stats);
        pairs = stats.curve_pairs + stats.texture_pairs;
        overflows = stats.overflow_pairs;
      }
      times[m] = seconds_since(t0);
      const std::string file = fmt::format("{}_{}.png", b.name, names[m]);
      image::write_rgb((fs::path(options.out_dir) / file).string(), sc.camera.width,
                       sc.camera.height, image::to_rgb(frames[m], colors, compiled.background));
      entry[names[m]] = {{"image", file},     {"hit_pixels", frames[m].hit_pixels()},
                         {"pairs", pairs},    {"overflow_pairs", overflows},
                         {"seconds", times[m]}};
    }
    const Agreement ip_f = compare(frames[1], frames[0]);
    const Agreement ref_ip = compare(frames[2], frames[1]);
    const Agreement ref_f = compare(frames[2], frames[0]);
    entry["float_ip_vs_float_mismatched_pixels"] = ip_f.differ;
    entry["ref_vs_float_ip_mismatched_pixels"] = ref_ip.differ;
    entry["ref_vs_float_mismatched_pixels"] = ref_f.differ;
    entry["ref_vs_float_ip"] = {{"hit_only_in_ref", ref_ip.only_a}, {"hit_only_in_float_ip", ref_ip.only_b}};
    entry["float_ip_vs_float"] = {{"hit_only_in_float_ip", ip_f.only_a}, {"hit_only_in_float", ip_f.only_b}};
    summary.push_back(entry);
    const auto cell = [](const Agreement& g) { return fmt::format("{} ({} / {})", g.differ, g.only_a, g.only_b); };
    md += fmt::format("| {} | {}×{} | {} | {} / {} / {} | {} | {} | {} | {:.3f} / {:.3f} / {:.3f} |\n",
                      b.name, sc.camera.width, sc.camera.height,
                      compiled.curve_segments.size() + compiled.texture_segments.size(),
                      frames[0].hit_pixels(), frames[1].hit_pixels(), frames[2].hit_pixels(),
                      cell(ip_f), cell(ref_ip), cell(ref_f), times[0], times[1], times[2]);
    std::cout << fmt::format("{:<10} {}x{}  float-ip vs float {}, ref vs float-ip {}, ref vs float {}\n",
                             b.name, sc.camera.width, sc.camera.height, ip_f.differ, ref_ip.differ,
                             ref_f.differ);
  }
  std::ofstream(fs::path(options.out_dir) / "summary.json") << summary.dump(2) << "\n";
  std::ofstream(fs::path(options.out_dir) / "summary.md") << md;
  std::cout << "wrote " << (fs::path(options.out_dir) / "summary.md").string() << "\n";
  return 0;
}

}  // namespace rpu::app
