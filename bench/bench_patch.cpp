// Patch ray tracing (docs/algorithms.md §4, issue 13) at 512×512, one ray per pixel, one thread
// (the thesis's Delphi programs were single-threaded): the preliminary map, each refiner from the
// map, and Martin et al. 2000 (BVH build, traversal) on the teapot (Bézier), the column
// (B-spline) and the NURBS torus. docs/patches.md holds the table and the command.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "patch/martin_bvh.h"
#include "patch/patch_renderer.h"
#include "patch/preliminary_map.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"

namespace {

using namespace rpu;
using namespace rpu::patch;

struct Prepared {
  scene::CompiledScene sc;
  std::vector<PatchSurface> surfaces;
};

const Prepared& prepared(const std::string& name) {
  static std::map<std::string, Prepared> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    scene::CompiledScene sc = scene::compile_scene(
        scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json"));
    std::vector<PatchSurface> s = prepare_surfaces(sc.patches);
    it = cache.emplace(name, Prepared{std::move(sc), std::move(s)}).first;
  }
  return it->second;
}

void counters(benchmark::State& state, const PatchRenderStats& s, const scene::CameraFrame& cam) {
  const double pixels = static_cast<double>(cam.width) * cam.height;
  state.counters["hit_px"] = static_cast<double>(s.hit_pixels);
  state.counters["starts/px"] = static_cast<double>(s.starts) / pixels;
  state.counters["evals/start"] = s.starts ? static_cast<double>(s.evaluations) / s.starts : 0.0;
  state.counters["fallbacks"] = static_cast<double>(s.fallback_starts);
  state.counters["silhouette_px"] = static_cast<double>(s.silhouette_pixels);
}

void BM_Map(benchmark::State& state, const char* name) {
  const Prepared& p = prepared(name);
  MapOptions o;
  o.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(build_preliminary_map(p.surfaces, p.sc.camera, o));
}

// Refinement from the (8-bit) map with one refiner for every patch, the thesis's Newton
// fallback included for the gradient refiners.
void BM_Refine(benchmark::State& state, const char* name, Refiner r, double tolerance_pixels = 0.01,
               bool restart_step = false) {
  const Prepared& p = prepared(name);
  PatchRenderOptions o;
  o.threads = 1;
  o.refiner = r;
  o.refine.tolerance_pixels = tolerance_pixels;
  o.refine.steepest_restart_step = restart_step;
  MapOptions mo;
  mo.threads = 1;
  const PreliminaryMap map = build_preliminary_map(p.surfaces, p.sc.camera, mo);
  PatchRenderStats s;
  for (auto _ : state) {
    s = {};
    benchmark::DoNotOptimize(refine_with_map(p.surfaces, map, p.sc.camera, o, s));
  }
  counters(state, s, p.sc.camera);
}

void BM_MartinBuild(benchmark::State& state, const char* name) {
  const Prepared& p = prepared(name);
  for (auto _ : state) benchmark::DoNotOptimize(MartinBvh(p.surfaces));
}

void BM_MartinTrace(benchmark::State& state, const char* name, double tolerance_pixels = 0.01) {
  const Prepared& p = prepared(name);
  MartinOptions mo;
  mo.newton.tolerance_pixels = tolerance_pixels;
  const MartinBvh bvh(p.surfaces, mo);
  PatchRenderStats s;
  for (auto _ : state) {
    s = {};
    benchmark::DoNotOptimize(trace_martin(p.surfaces, bvh, p.sc.camera, 1, s));
  }
  counters(state, s, p.sc.camera);
  state.counters["leaves"] = static_cast<double>(bvh.leaves().size());
}

#define RPU_PATCH_BENCH(scene)                                                                     \
  BENCHMARK_CAPTURE(BM_Map, scene, #scene)->Unit(benchmark::kMillisecond);                        \
  BENCHMARK_CAPTURE(BM_Refine, scene##_gradient, #scene, Refiner::kGradientDescent)               \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Refine, scene##_steepest, #scene, Refiner::kSteepestDescent)               \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Refine, scene##_newton_cramer, #scene, Refiner::kNewtonCramer)             \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Refine, scene##_newton, #scene, Refiner::kNewton)                          \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Refine, scene##_gradient_tol0_1, #scene, Refiner::kGradientDescent, 0.1)   \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Refine, scene##_steepest_tol0_1, #scene, Refiner::kSteepestDescent, 0.1)   \
      ->Unit(benchmark::kMillisecond);                                                             \
  BENCHMARK_CAPTURE(BM_Refine, scene##_steepest_restart, #scene, Refiner::kSteepestDescent, 0.01, \
                    true)->Unit(benchmark::kMillisecond);                                          \
  BENCHMARK_CAPTURE(BM_MartinBuild, scene, #scene)->Unit(benchmark::kMillisecond);                \
  BENCHMARK_CAPTURE(BM_MartinTrace, scene, #scene)->Unit(benchmark::kMillisecond);              \
  BENCHMARK_CAPTURE(BM_MartinTrace, scene##_tol0_1, #scene, 0.1)->Unit(benchmark::kMillisecond);

RPU_PATCH_BENCH(teapot)
RPU_PATCH_BENCH(column)
RPU_PATCH_BENCH(torus)

}  // namespace

BENCHMARK_MAIN();
