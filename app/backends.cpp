#include "backends.h"

#include <chrono>
#include <cmath>
#include <thread>

#include "common/error.h"
#include "model/descriptors.h"
#if RPU_HAVE_RTL
#include "rtl_backend.h"
#endif

namespace rpu::app {

nlohmann::json hw_params_json(const ref::HwParams& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const ref::HwParamInfo& d : ref::hw_param_table()) {
    const int v = d.get(p);
    if (d.kind == ref::HwParamKind::kChoice) j[std::string(d.key)] = d.text(v);
    else j[std::string(d.key)] = v;
  }
  return j;
}

bool rtl_built() { return RPU_HAVE_RTL != 0; }

std::string rtl_configurations() {
#if RPU_HAVE_RTL
  return sim::describe_rtl_configs();
#else
  return "  (none: this rpu is built without the co-simulation, RPU_SIM=OFF)\n";
#endif
}

bool backend_applies(const std::string& backend, const scene::CompiledScene& sc) {
  if (backend == "float" || backend == "float-ip") return true;
  return sc.patches.empty();  // curves, textures and surfaces: every backend
}

nlohmann::json patch_stats_json(const patch::PatchRenderOptions& o, const patch::PatchRenderStats& s) {
  const bool martin = o.method == patch::PatchMethod::kMartin;
  return {{"method", patch::patch_method_name(o.method)},
          {"start", o.start == patch::PatchStart::kRandom ? "random" : "map"},
          {"map_quantised", o.map.quantised},
          {martin ? "bvh_build_seconds" : "map_seconds", s.map_seconds},
          {martin ? "trace_seconds" : "refine_seconds", s.refine_seconds},
          {"map_triangles", s.map_triangles},
          {"bvh_leaves", s.bvh_leaves},
          {"hit_pixels", s.hit_pixels},
          {"starts", s.starts},
          {"converged", s.converged},
          {"iterations", s.iterations},
          {"evaluations", s.evaluations},
          {"silhouette_pixels", s.silhouette_pixels},
          {"silhouette_left_domain", s.silhouette_left_domain},
          {"silhouette_stalled", s.silhouette_stalled},
          {"silhouette_iteration_limit", s.silhouette_iteration_limit},
          {"silhouette_singular", s.silhouette_singular},
          {"neighbour_hits", s.neighbour_hits},
          {"fallback_starts", s.fallback_starts},
          {"fallback_converged", s.fallback_converged}};
}

namespace {

// World units per unit of the model's depth c·S·2^(FE + kRayGuard) (docs/fixed-point.md), with
// S this model's own normalisation.
double model_depth_unit(const ref::ModelScene& m) {
  return 1.0 / (m.norm.scale * std::ldexp(1.0, m.params.edge_frac + ref::HwParams::kRayGuard));
}

}  // namespace

BackendResult run_backend(const std::string& backend, const scene::CompiledScene& sc,
                          const BackendOptions& o) {
  BackendResult r;
  // Patches have no fixed-point path at all.
  if (!backend_applies(backend, sc))
    throw Error(sc.source + ": patches",
                "the " + backend + " backend has no fixed-point path for parametric patches "
                "(docs/algorithms.md §4); render them with --backend float or float-ip");
  r.render.name = backend;
  patch::PatchRenderOptions po = o.patch;
  po.threads = o.fl.threads;
  po.where = sc.source + ": patches";
  // The memory of a render with patches, before the frame is allocated (README, "Limits").
  if (!sc.patches.empty()) patch::check_patch_render_bytes(sc.camera, po);
  const auto t0 = std::chrono::steady_clock::now();
  if (backend == "float" || backend == "float-ip") {
    tracer::FloatOptions fo = o.fl;
    fo.method = backend == "float" ? tracer::Method::kIdeal : tracer::Method::kIterative;
    tracer::RenderStats stats;
    r.render.frame = tracer::render_float(sc, fo, &stats);
    r.pairs = stats.pairs_tested + stats.texture_pairs_tested + stats.surface_pieces;
    if (!sc.patches.empty()) {
      // The patch methods are themselves the thesis's iterative processes: float and float-ip
      // trace patches alike (--patch-method). Nearest hit wins against curves and textures.
      const std::vector<patch::PatchSurface> surfaces = patch::prepare_surfaces(sc.patches);
      patch::PatchRender pr = patch::render_patches(surfaces, sc.camera, po);
      image::Frame& f = r.render.frame;
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i) {
          const patch::PatchPixel& p = pr.hits.at(i, j);
          const size_t k = f.index(i, j);
          if (p.hit && (f.primitive[k] == image::kBackground || p.depth < f.depth[k])) {
            f.primitive[k] = sc.first_patch_primitive + p.patch;
            f.depth[k] = p.depth;
          }
        }
      r.patch = patch_stats_json(po, pr.stats);
      r.patch_hits = std::move(pr.hits);
    }
  } else if (backend == "ref") {
    const ref::ModelScene model = ref::quantize_scene(sc, o.hw);
    r.precision_warning = model.precision.warning;
    ref::RefStats stats;
    r.render.frame = ref::render_ref(sc, model, o.ref, &stats);
    r.render.depth_unit = model_depth_unit(model);
    r.pairs = stats.curve_pairs + stats.texture_pairs + stats.surface_pieces;
    r.overflows = stats.overflow_pairs;
  } else if (backend == "rtl") {
#if RPU_HAVE_RTL
    const ref::ModelScene model = ref::quantize_scene(sc, o.hw);
    r.precision_warning = model.precision.warning;
    sim::RtlOptions ro;
    ro.ref = o.ref;
    ro.systemc = o.systemc;
    ro.external_exe = o.rtl_exe;
    ro.jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    ro.shard = o.shard;
    ro.shard_out = o.shard_out;
    ro.merge_shards = o.merge_shards;
    ro.fault = o.fault;
    ro.axi = o.axi;
    ro.trace_pixel = o.trace_pixel;
    ro.trace_path = o.trace_path;
    const sim::RtlRender rr = sim::render_rtl(sc, model, ro);
    r.render.depth_unit = model_depth_unit(model);
    r.render.frame = rr.frame;
    r.pairs = rr.stats.items;
    r.reports = rr.reports;
    r.rtl_ok = rr.ok;
    r.trace_log = rr.trace_log;
    const sim::CosimStats& s = rr.stats;
    r.rtl = {{"harness", rr.harness},
             {"configuration", rr.config},
             {"cycles", s.cycles},
             {"pairs", s.items},
             {"curve_pairs", s.curve_items},
             {"texture_pairs", s.texture_items},
             {"surface_pieces", s.surface_items},
             {"pixels_with_work", s.pixels},
             {"latency_cycles", s.latency_cycles},
             {"stall_cycles", s.stall_cycles},
             {"load_cycles", s.load_cycles},
             {"items_per_cycle", s.items_per_cycle()},
             {"sim_seconds", s.sim_seconds},
             {"instances", rr.instances.size()},
             {"frame_cycles", rr.frame_cycles},
             {"instance_cycles", [&rr] {
                nlohmann::json a = nlohmann::json::array();
                for (const sim::CosimStats& i : rr.instances) a.push_back(i.cycles);
                return a;
              }()},
             {"items_per_second", s.sim_seconds > 0 ? s.items / s.sim_seconds : 0.0},
             {"cycles_per_second", s.sim_seconds > 0 ? s.cycles / s.sim_seconds : 0.0},
             {"item_mismatches", rr.item_mismatches},
             {"pixel_stream_mismatches", rr.pixel_mismatches},
             {"timed_out", s.timed_out}};
    if (rr.first_bad.first >= 0)
      r.rtl["first_mismatch_pixel"] = {rr.first_bad.first, rr.first_bad.second};
#else
    throw Error("--backend rtl", "this rpu is built without the co-simulation (RPU_SIM=OFF)");
#endif
  } else {
    throw Error("--backend", "unknown backend '" + backend + "' (float, float-ip, ref, rtl)");
  }
  r.render.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace rpu::app
