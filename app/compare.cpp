#include "compare.h"

#include <chrono>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "common/error.h"
#include "run_record.h"
#include "scene/compiled_scene.h"

namespace rpu::app {

namespace {

nlohmann::json config_json(const BackendOptions& o) {
  nlohmann::json j = hw_params_json(o.hw);
  j["K"] = o.hw.K();
  j["binning"] = o.ref.binning;
  j["grid"] = o.ref.grid;
  j["harness"] = o.systemc ? "systemc" : "c++";
  return j;
}

}  // namespace

int run_compare(const std::string& scene_arg, const scene::Scene& scene,
                const CompareOptions& o, nlohmann::json* metrics_out) {
  namespace fs = std::filesystem;
  check_compare_output(o.out_dir, o.input_file);  // before the work, not only after it
  const scene::CompiledScene sc = scene::compile_scene(scene);
  CompareInput in;
  in.scene = scene_arg;
  in.input_file = o.input_file;
  for (const auto& p : sc.primitives) in.colors.push_back(p.color);
  in.background = sc.background;
  in.config = config_json(o.backends);
  const auto t_start = std::chrono::steady_clock::now();
  for (const auto& p : sc.primitives) in.curve_primitive.push_back(p.kind == scene::Primitive::Kind::kCurve);
  bool rtl_ok = false, rtl_ran = false;
  nlohmann::json not_applicable = nlohmann::json::array(), patch_stats;
  for (const std::string& b : backend_names()) {
    // Patches: float only (docs/algorithms.md §4).
    if (!backend_applies(b, sc)) {
      not_applicable.push_back(b);
      if (!o.quiet)
        std::cerr << fmt::format("  {:<8} not applicable ({})\n", b,
                                 "patches: float only");
      continue;
    }
    if (b == "rtl" && o.skip_rtl) continue;
    BackendResult r = run_backend(b, sc, o.backends);
    if (r.patch.is_object()) patch_stats[b] = r.patch;
    // The model's own precision warning (ref::Precision), once, even with -q.
    if (b == "ref" && !r.precision_warning.empty())
      std::cerr << "rpu: warning: " << r.precision_warning << "\n";
    if (!o.quiet)
      std::cerr << fmt::format("  {:<8} {:>8.3f} s  {} hit pixels, {} pairs\n", b,
                               r.render.seconds, r.render.frame.hit_pixels(), r.pairs);
    if (b == "rtl") {
      rtl_ran = true;
      rtl_ok = r.rtl_ok;
      in.rtl = r.rtl;
      in.mismatch_lines = r.reports;
      if (!r.trace_log.empty()) std::cerr << r.trace_log;
    }
    in.renders.push_back(std::move(r.render));
  }
  if (!sc.patches.empty()) {
    // The other patch methods, as extra float renders (float-thesis, float-newton,
    // float-martin): the same scene, the same depth rule, another root finder.
    for (const patch::PatchMethod m :
         {patch::PatchMethod::kThesis, patch::PatchMethod::kNewton, patch::PatchMethod::kMartin}) {
      if (m == o.backends.patch.method) continue;
      BackendOptions bo = o.backends;
      bo.patch.method = m;
      BackendResult r = run_backend("float", sc, bo);
      r.render.name = std::string("float-") + patch::patch_method_name(m);
      patch_stats[r.render.name] = r.patch;
      if (!o.quiet)
        std::cerr << fmt::format("  {:<8} {:>8.3f} s  {} hit pixels\n", r.render.name,
                                 r.render.seconds, r.render.frame.hit_pixels());
      in.renders.push_back(std::move(r.render));
    }
    in.extra_metrics["patches"] = patch_stats;
  }
  in.extra_metrics["not_applicable"] = not_applicable;
  in.record = run_record(o.command);
  {
    ref::HwParams defaults;
    defaults.unrolled = o.backends.hw.unrolled;
    in.extra_metrics["resources"] =
        docs_resources(o.backends.hw == defaults, o.backends.hw.unrolled, scene_arg);
  }
  in.record["wall_seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  const CompareSummary s = write_compare_report(in, o.out_dir);
  if (metrics_out) *metrics_out = s.metrics;
  const bool rtl_differs = rtl_ran && !(rtl_ok && s.rtl_equals_ref);
  if (!s.warning.empty()) std::cerr << fmt::format("rpu: warning: {}: {}\n", scene_arg, s.warning);
  if (!o.quiet) {
    // A comparison that did not run (a backend not applicable, or --no-rtl) is "n/a".
    const auto count = [&](const char* key) {
      const nlohmann::json v = s.metrics.value(key, nlohmann::json());
      return v.is_null() ? std::string("n/a") : v.dump() + " px";
    };
    std::cerr << fmt::format("{}: {}x{}, rtl vs ref {}, ref vs float-ip {}, ref vs float {}, "
                             "float-ip vs float {}\n",
                             scene_arg, scene.camera.width, scene.camera.height,
                             count("rtl_vs_ref_mismatched_pixels"),
                             count("ref_vs_float_ip_mismatched_pixels"),
                             count("ref_vs_float_mismatched_pixels"),
                             count("float_ip_vs_float_mismatched_pixels"));
    for (const auto& line : in.mismatch_lines) std::cerr << line << "\n";
    std::cerr << fmt::format("{}: report {}\n",
                             !sc.patches.empty() ? "PATCHES (float backends only, ref/rtl not applicable)"
                             : !rtl_ran          ? "NO RTL (--no-rtl)"
                             : rtl_differs       ? "FAIL"
                                                 : "PASS",
                             (fs::path(o.out_dir) / "report.html").string());
  }
  return rtl_differs ? 2 : 0;
}

}  // namespace rpu::app
