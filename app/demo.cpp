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

int run_demo(const DemoOptions& options) {
  namespace fs = std::filesystem;
  fs::create_directories(options.out_dir);
  nlohmann::json summary = nlohmann::json::array();
  std::string md = fmt::format(
      "# Demo renders\n\nn = {}, n1 = {} (K = {}).\n\n"
      "| scene | size | segments | float hit px | float-ip hit px | float-ip vs float differing px "
      "(only float / only float-ip) | float s | float-ip s |\n|---|---|---|---|---|---|---|---|\n",
      options.float_options.n, options.float_options.n1,
      options.float_options.n / options.float_options.n1);
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
                            {"curve_segments", compiled.curve_segments.size()},
                            {"texture_segments", compiled.texture_segments.size()}};
    image::Frame frames[2];
    double times[2];
    const tracer::Method methods[2] = {tracer::Method::kIdeal, tracer::Method::kIterative};
    const char* names[2] = {"float", "float-ip"};
    for (int m = 0; m < 2; ++m) {
      tracer::FloatOptions fo = options.float_options;
      fo.method = methods[m];
      tracer::RenderStats stats;
      const auto t0 = std::chrono::steady_clock::now();
      frames[m] = tracer::render_float(compiled, fo, &stats);
      times[m] = seconds_since(t0);
      const std::string file = fmt::format("{}_{}.png", b.name, names[m]);
      image::write_rgb((fs::path(options.out_dir) / file).string(), sc.camera.width,
                       sc.camera.height, image::to_rgb(frames[m], colors, compiled.background));
      entry[names[m]] = {{"image", file},
                         {"hit_pixels", frames[m].hit_pixels()},
                         {"pairs_tested", stats.pairs_tested},
                         {"seconds", times[m]}};
    }
    const size_t differ = image::count_differing_pixels(frames[0], frames[1]);
    size_t only_float = 0, only_ip = 0;
    for (size_t k = 0; k < frames[0].primitive.size(); ++k) {
      const bool a = frames[0].primitive[k] != image::kBackground;
      const bool b = frames[1].primitive[k] != image::kBackground;
      only_float += a && !b;
      only_ip += b && !a;
    }
    entry["float_ip_vs_float_mismatched_pixels"] = differ;
    entry["hit_only_in_float"] = only_float;
    entry["hit_only_in_float_ip"] = only_ip;
    summary.push_back(entry);
    md += fmt::format("| {} | {}×{} | {} | {} | {} | {} ({} / {}) | {:.3f} | {:.3f} |\n", b.name,
                      sc.camera.width, sc.camera.height,
                      compiled.curve_segments.size() + compiled.texture_segments.size(),
                      frames[0].hit_pixels(), frames[1].hit_pixels(), differ, only_float, only_ip,
                      times[0], times[1]);
    std::cout << fmt::format("{:<10} {}x{}  float {:.2f} s, float-ip {:.2f} s, differing pixels {}\n",
                             b.name, sc.camera.width, sc.camera.height, times[0], times[1], differ);
  }
  std::ofstream(fs::path(options.out_dir) / "summary.json") << summary.dump(2) << "\n";
  std::ofstream(fs::path(options.out_dir) / "summary.md") << md;
  std::cout << "wrote " << (fs::path(options.out_dir) / "summary.md").string() << "\n";
  return 0;
}

}  // namespace rpu::app
