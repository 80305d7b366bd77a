#include "demo.h"

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "builtin_scenes.h"
#include "common/error.h"
#include "image/image_io.h"
#include "report_text.h"
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

int run_demo(const DemoOptions& options) {
  namespace fs = std::filesystem;
  // The same rules as compare --out: not empty, a directory (created if missing).
  check_compare_output(options.out_dir, "");
  {
    std::error_code ec;
    fs::create_directories(options.out_dir, ec);
    if (ec || !fs::is_directory(options.out_dir))
      throw Error(options.out_dir, "cannot create the output directory" +
                                       (ec ? ": " + ec.message() : std::string()));
  }
  nlohmann::json summary = nlohmann::json::array();
  const ref::HwParams& hw = options.compare.backends.hw;
  std::string md = fmt::format(
      "# Demo: every built-in scene through every backend\n\n"
      "n = {}, n1 = {} (K = {}), coord_w = {}, metric = {}, IP {}. Mismatched pixels per pair; "
      "RTL cycles from the co-simulation.\n\n"
      "| scene | size | rtl vs ref | ref vs float-ip | ref vs float | float-ip vs float | pairs "
      "| cycles | latency | co-sim s | items/s | cycles/s | report |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      hw.n, hw.n1, hw.K(), hw.coord_w, hw.metric == ref::Metric::kAbs ? "abs" : "squared",
      hw.unrolled ? "unrolled" : "iterative");
  std::string rows_html;
  int status = 0;
  // The scenes run concurrently, one per core (each co-simulation is single-threaded); each
  // scene's renders then use one thread, and its progress is printed when it is done.
  const auto& scenes = builtin_scenes();
  std::vector<scene::Scene> loaded;
  for (const auto& b : scenes) {
    const std::string arg = std::string("builtin:") + b.name;
    loaded.push_back(options.load ? options.load(arg) : load_scene_argument(arg));
    scene::Camera& c = loaded.back().camera;
    const int side = std::max(c.width, c.height), cap = options.surface_max_side;
    if (!loaded.back().surfaces.empty() && cap > 0 && side > cap) {
      c.width = std::max(1, static_cast<int>(static_cast<long long>(c.width) * cap / side));
      c.height = std::max(1, static_cast<int>(static_cast<long long>(c.height) * cap / side));
    }
  }
  std::vector<nlohmann::json> metrics(scenes.size());
  std::vector<int> codes(scenes.size(), 0);
  std::vector<std::string> errors(scenes.size());
  // Backends a scene's primitives have no path through (compare's "not_applicable": ref and rtl
  // for patches).
  const auto not_applicable = [&](size_t k) {
    const auto it = metrics[k].find("not_applicable");
    std::string list;
    if (it != metrics[k].end() && it->is_array())
      for (const auto& b : *it) list += (list.empty() ? "" : ", ") + b.get<std::string>();
    return list;
  };
  std::atomic<size_t> next{0};
  std::mutex print_mu;
  const auto worker = [&] {
    for (size_t k; (k = next.fetch_add(1)) < scenes.size();) {
      const std::string arg = std::string("builtin:") + scenes[k].name;
      CompareOptions co = options.compare;
      co.out_dir = (fs::path(options.out_dir) / scenes[k].name).string();
      co.quiet = true;
      co.backends.fl.threads = 1;
      co.backends.ref.threads = 1;
      try {
        codes[k] = run_compare(arg, loaded[k], co, &metrics[k]);
      } catch (const std::exception& e) {
        errors[k] = e.what();
        codes[k] = 1;
      }
      std::lock_guard<std::mutex> lock(print_mu);
      std::cerr << fmt::format("{} ({}x{}): {}\n", arg, loaded[k].camera.width,
                               loaded[k].camera.height,
                               !errors[k].empty() ? "error: " + errors[k]
                               : codes[k] != 0    ? "FAIL, see " + co.out_dir + "/report.html"
                               : !not_applicable(k).empty()
                                   ? fmt::format("patches: float backends and every patch method "
                                                 "({} not applicable)", not_applicable(k))
                               : co.skip_rtl      ? std::string("software backends only (--no-rtl)")
                                                  : std::string("PASS, rtl == ref"));
    }
  };
  {
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < std::min<size_t>(hw, scenes.size()); ++t) pool.emplace_back(worker);
    worker();
  }
  for (size_t k = 0; k < scenes.size(); ++k) {
    if (!errors[k].empty()) throw Error("", errors[k]);  // already names the scene
    const auto& b = scenes[k];
    const scene::Scene& sc = loaded[k];
    nlohmann::json& m = metrics[k];
    const int rc = codes[k];
    status = std::max(status, rc);
    m["scene"] = b.name;
    m["report"] = std::string(b.name) + "/report.html";
    summary.push_back(m);
    // Scenes with backends not applicable (patches) have no ref or rtl render: their
    // cells read "n/a", not "null".
    const bool float_only = !not_applicable(k).empty();
    const auto cell = [&](const char* key) -> std::string {
      if (m.contains(key) && !m[key].is_null()) return m[key].dump();
      return float_only ? "n/a" : "null";
    };
    const nlohmann::json rtl = m.value("rtl", nlohmann::json());
    const auto num = [&](const char* key, const char* f) {
      return rtl.is_object() && rtl.contains(key) && rtl[key].is_number()
                 ? fmt::format(fmt::runtime(f), rtl[key].get<double>())
                 : std::string("—");
    };
    md += fmt::format("| {} | {}×{} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | "
                      "{}/report.html |\n",
                      b.name, sc.camera.width, sc.camera.height,
                      cell("rtl_vs_ref_mismatched_pixels"), cell("ref_vs_float_ip_mismatched_pixels"),
                      cell("ref_vs_float_mismatched_pixels"),
                      cell("float_ip_vs_float_mismatched_pixels"), cell("pairs"), cell("cycles"),
                      cell("latency_cycles"), num("sim_seconds", "{:.1f}"),
                      num("items_per_second", "{:.0f}"), num("cycles_per_second", "{:.0f}"),
                      b.name);
    // A thumbnail (the float render, in the scene's report directory) and the scene's own
    // one-line description.
    rows_html += fmt::format("<tr><td><a href=\"{0}/report.html\"><img src=\"{0}/float.png\" "
                             "alt=\"{0}\" class=\"thumb\"></a></td>"
                             "<td><a href=\"{0}/report.html\">{0}</a><br><small>{9}</small></td>"
                             "<td>{1}&times;{2}</td>"
                             "<td>{3}</td><td>{4}</td><td>{5}</td><td>{6}</td><td>{7}</td>"
                             "<td>{8}</td></tr>\n",
                             b.name, sc.camera.width, sc.camera.height,
                             cell("rtl_vs_ref_mismatched_pixels"),
                             cell("ref_vs_float_ip_mismatched_pixels"),
                             cell("ref_vs_float_mismatched_pixels"),
                             cell("float_ip_vs_float_mismatched_pixels"), cell("cycles"),
                             rc != 0      ? "FAIL"
                             : float_only ? "n/a (patches)"
                             : options.compare.skip_rtl ? "not run" : "PASS",
                             escape_html(sc.about));
  }
  const fs::path out(options.out_dir);
  write_text_file(out / "summary.json",
                  summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  write_text_file(out / "summary.md", md);
  write_text_file(out / "index.html",
      "<!doctype html><html><head><meta charset=\"utf-8\"><title>rpu demo</title>"
      "<style>body{font-family:sans-serif}td,th{padding:2px 8px;border-bottom:1px solid #ccc}"
      ".thumb{width:96px;height:auto;image-rendering:pixelated}small{color:#555}"
      "</style></head><body><h1>rpu demo: every built-in scene, every backend</h1>"
      "<table><tr><th></th><th>scene</th><th>size</th><th>rtl vs ref</th><th>ref vs float-ip</th>"
      "<th>ref vs float</th><th>float-ip vs float</th><th>cycles</th><th>RTL = model</th></tr>\n" +
      rows_html + "</table></body></html>\n");
  std::cout << "wrote " << (fs::path(options.out_dir) / "index.html").string() << " and "
            << (fs::path(options.out_dir) / "summary.md").string() << "\n";
  return status;
}

}  // namespace rpu::app
