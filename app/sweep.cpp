// `rpu sweep`: reads the sweep file (sweep_spec), then per configuration measures accuracy
// against the shared float renders (sweep_float_cache), a co-simulated sample (built on demand
// by sweep_cosim_build) and Yosys resources (sweep_yosys), on a worker pool (sweep_pool); stores
// each result and merges them (sweep_merge). Child processes: sweep_process.
#include "sweep.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/limits.h"
#include "model/descriptors.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"
#include "sweep_cosim_build.h"
#include "sweep_float_cache.h"
#include "sweep_merge.h"
#include "sweep_pool.h"
#include "sweep_spec.h"
#include "sweep_yosys.h"
#include "tracer/float_tracer.h"
#if RPU_HAVE_RTL
#include "rtl_backend.h"
#endif

namespace rpu::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// What every configuration of a run shares.
struct SweepRun {
  SweepSpec spec;                                // with --no-rtl / --no-yosys applied
  std::vector<scene::CompiledScene> scenes;      // at the sweep's resolution
  std::optional<scene::CompiledScene> rtl_scene;  // the first scene at the RTL resolution
  std::string fingerprint;
  FloatCache floats;
  std::unique_ptr<YosysRunner> yosys;            // when the spec measures resources
  std::map<std::string, std::string> external;   // configuration id → co-simulation executable
};

// Measures one configuration; never throws (a failure is the row's status and error).
json run_config(SweepRun& run, const SweepConfig& c) {
  const SweepSpec& s = run.spec;
  json row = c.params_json;
  row["config_id"] = c.id;
  row["fingerprint"] = run.fingerprint;
  row["K"] = c.params.n1 > 0 ? c.params.n / c.params.n1 : 0;
  try {
    c.params.validate();
  } catch (const Error& e) {
    row["status"] = "invalid";
    row["error"] = e.what();
    return row;
  }
  try {
    long pixels = 0, vs_ip = 0, vs_f = 0;
    json scenes = json::object();
    for (size_t k = 0; k < s.scenes.size(); ++k) {
      const scene::CompiledScene& sc = run.scenes[k];
      const ref::ModelScene model = ref::quantize_scene(sc, c.params);
      ref::RefOptions ro;
      ro.threads = 1;
      ref::RefStats rs;
      const image::Frame r = ref::render_ref(sc, model, ro, &rs);
      const std::string key = fmt::format("{}@{}x{}", k, s.width, s.height);
      const image::Frame& fip =
          run.floats.get(sc, key, tracer::Method::kIterative, c.params.n, c.params.n1,
                         c.params.surf_n1_first);
      const image::Frame& ff = run.floats.get(sc, key, tracer::Method::kIdeal, 0, 0, 0);
      const long a = static_cast<long>(image::count_differing_pixels(r, fip));
      const long b = static_cast<long>(image::count_differing_pixels(r, ff));
      scenes[s.scenes[k].label] = {{"pixels", s.width * s.height}, {"ref_vs_float_ip", a},
                                   {"ref_vs_float", b}, {"hit_pixels", r.hit_pixels()},
                                   {"overflow_pairs", rs.overflow_pairs}};
      pixels += s.width * s.height;
      vs_ip += a;
      vs_f += b;
    }
    row["scenes"] = scenes;
    row["pixels_total"] = pixels;
    row["ref_vs_float_ip_total"] = vs_ip;
    row["ref_vs_float_total"] = vs_f;

    row["rtl_status"] = "off";
    if (s.rtl) {
#if RPU_HAVE_RTL
      const bool built = has_builtin_rtl(c.params);
      const auto ext = run.external.find(c.id);
      if (!built && ext == run.external.end()) {
        row["rtl_status"] = s.rtl_build ? "build failed" : "no build";
      } else {
        const ref::ModelScene model = ref::quantize_scene(*run.rtl_scene, c.params);
        sim::RtlOptions ro;
        ro.ref.threads = 1;
        if (!built) ro.external_exe = ext->second;
        const sim::RtlRender rr = sim::render_rtl(*run.rtl_scene, model, ro);
        row["rtl_status"] = rr.ok ? "ok" : "failed";
        row["rtl_cycles"] = rr.stats.cycles;
        row["rtl_latency_cycles"] = rr.stats.latency_cycles;
        row["rtl_items"] = rr.stats.items;
        row["rtl_items_per_cycle"] = rr.stats.items_per_cycle();
        row["rtl_sample"] = fmt::format("{} at {}x{}", s.scenes.front().argument, s.rtl_width,
                                        s.rtl_height);
        if (!rr.ok) row["rtl_mismatches"] = rr.item_mismatches + rr.pixel_mismatches;
      }
#else
      row["rtl_status"] = "no build";
#endif
    }
    row["yosys_status"] = "off";
    if (run.yosys) run.yosys->measure(c, row);
    row["status"] = "ok";
  } catch (const std::exception& e) {
    row["status"] = "failed";
    row["error"] = e.what();
  }
  return row;
}

// An all-invalid grid measures nothing: refused like any other mistake in the file.
void check_some_valid(const SweepSpec& s, const std::vector<SweepConfig>& configs) {
  std::string first;
  for (const SweepConfig& c : configs) {
    try {
      c.params.validate();
      return;
    } catch (const Error& e) {
      if (first.empty()) first = e.what();
    }
  }
  throw Error(s.path + ": grid", fmt::format("every configuration is invalid ({} of {}; the first: "
                                             "{})", configs.size(), configs.size(), first));
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  limits::check_threads("--jobs", o.jobs);
  if (o.out_dir.empty()) throw Error("--out", "must name a directory");
  const SweepSpec spec = parse_sweep_file(o.file);
  const std::vector<SweepConfig> configs = expand_grid(spec);
  check_some_valid(spec, configs);
  const fs::path out(o.out_dir);
  std::error_code ec;
  fs::create_directories(out / "configs", ec);
  if (ec) throw Error(o.out_dir, "cannot create the output directory: " + ec.message());

  if (o.emit_jobs) {
    JobCommand job{o.self, fs::absolute(o.file).string(), fs::absolute(out).string(), {}};
    if (o.no_rtl) job.switches.push_back("--no-rtl");
    if (o.no_yosys) job.switches.push_back("--no-yosys");
    emit_jobs(job, configs, out);
    return 0;
  }
  if (o.merge) return merge_results(spec, configs, out);

  SweepRun run;
  run.spec = spec;
  SweepSpec& s = run.spec;
  if (o.no_rtl) s.rtl = false;
  if (o.no_yosys) s.yosys = false;
  const LoadedScenes loaded = load_sweep_scenes(s);
  run.fingerprint = sweep_fingerprint(s, loaded);  // a result made otherwise is not reused

  std::vector<const SweepConfig*> todo;
  for (const SweepConfig& c : configs) {
    if (!o.config.empty() && c.id != o.config) continue;
    if (reusable(result_file(out, c.id), run.fingerprint)) continue;
    todo.push_back(&c);
  }
  if (!o.config.empty() &&
      std::none_of(configs.begin(), configs.end(), [&](const SweepConfig& c) { return c.id == o.config; }))
    throw Error("--config", "no configuration " + o.config + " in " + o.file);
  const size_t total = o.config.empty() ? configs.size() : 1;
  std::cerr << fmt::format("rpu sweep: {} configurations, {} done earlier, {} to run\n", total,
                           total - todo.size(), todo.size());

  if (!todo.empty()) {
    for (size_t k = 0; k < s.scenes.size(); ++k) {
      scene::Scene scn = loaded.scenes[k];
      scn.camera.width = s.width;
      scn.camera.height = s.height;
      run.scenes.push_back(scene::compile_scene(scn));
    }
    if (s.rtl) {
      scene::Scene scn = loaded.scenes.front();
      scn.camera.width = s.rtl_width;
      scn.camera.height = s.rtl_height;
      run.rtl_scene = scene::compile_scene(scn);
    }
  }
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned threads = o.jobs > 0 ? static_cast<unsigned>(o.jobs) : hw;
  // Each configuration's synthesis runs its derived modules on the cores left to it.
  if (!todo.empty() && s.yosys) {
    const unsigned parallel = std::min(threads, static_cast<unsigned>(todo.size()));
    run.yosys = std::make_unique<YosysRunner>(s, out / "yosys_cache",
                                              static_cast<int>(std::max(1u, hw / parallel)));
  }
  if (s.rtl && s.rtl_build) run.external = build_cosim(todo, out, static_cast<int>(threads));

  size_t done = 0;
  std::mutex print_mu;
  const auto t0 = std::chrono::steady_clock::now();
  run_pool(todo.size(), threads, [&](size_t k) {
    const SweepConfig& c = *todo[k];
    const auto t1 = std::chrono::steady_clock::now();
    const json row = run_config(run, c);
    store_result(out, c.id, row);
    const auto now = std::chrono::steady_clock::now();
    const double secs = std::chrono::duration<double>(now - t1).count();
    const double elapsed = std::chrono::duration<double>(now - t0).count();
    std::lock_guard<std::mutex> lock(print_mu);
    const size_t d = ++done;
    std::cerr << fmt::format("[{}/{}] {} n {} n1 {} coord_w {} {}: {} in {:.1f} s{} (eta {:.0f} s)\n",
                             d, todo.size(), c.id, c.params.n, c.params.n1, c.params.coord_w,
                             c.params.unrolled ? "unrolled" : "iterative",
                             row.value("status", "?"), secs,
                             row.contains("error") ? " — " + row["error"].get<std::string>() : "",
                             elapsed / d * (todo.size() - d));
  });
  if (!o.config.empty()) return 0;  // one job of an emitted set: the merge step collects
  return merge_results(spec, configs, out);
}

}  // namespace rpu::app
