// Float tracer throughput: rays per second on all cores, per-pair cost, and how render time
// scales with the number of curve segments (binning keeps a ray's candidate list short).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tracer/float_tracer.h"

namespace {

using namespace rpu;

scene::CompiledScene demo(const char* name) {
  return scene::compile_scene(
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json"));
}

// A closed (2,3) torus knot through `points` points, seen whole at 256×256.
scene::CompiledScene torus_knot(int points) {
  scene::Scene s;
  s.source = "torus_knot";
  s.camera = {{0.5, -4.5, 2.5}, {0, 0, 0}, {0, 0, 1}, 45.0, 256, 256};
  scene::Curve c;
  c.closed = true;
  for (int k = 0; k < points; ++k) {
    const double t = 2.0 * std::numbers::pi * k / points;
    const double r = 0.7 + 0.25 * std::cos(3 * t);
    c.points.push_back({r * std::cos(2 * t), r * std::sin(2 * t), 0.25 * std::sin(3 * t)});
  }
  s.curves.push_back(c);
  return scene::compile_scene(s);
}

void render(benchmark::State& state, const scene::CompiledScene& sc, tracer::Method m) {
  tracer::FloatOptions o;
  o.method = m;
  tracer::RenderStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(tracer::render_float(sc, o, &stats));
  const double pixels = static_cast<double>(sc.camera.width) * sc.camera.height;
  state.counters["rays/s"] = benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
  const double pairs = static_cast<double>(stats.pairs_tested + stats.texture_pairs_tested);
  state.counters["pairs/s"] = benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["pairs/ray"] = pairs / pixels;
}

void BM_Demo(benchmark::State& state, const char* name, tracer::Method m) {
  render(state, demo(name), m);
}
BENCHMARK_CAPTURE(BM_Demo, curve12_float, "curve12", tracer::Method::kIdeal)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Demo, curve12_float_ip, "curve12", tracer::Method::kIterative)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Demo, airfield_float, "airfield", tracer::Method::kIdeal)->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_KnotSegments(benchmark::State& state, tracer::Method m) {
  render(state, torus_knot(static_cast<int>(state.range(0))), m);
}
BENCHMARK_CAPTURE(BM_KnotSegments, float, tracer::Method::kIdeal)->Arg(100)->Arg(1000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_KnotSegments, float_ip, tracer::Method::kIterative)->Arg(100)->Arg(1000)->UseRealTime()->Unit(benchmark::kMillisecond);

// One core, one ray/segment pair through the iterative process (n = 16, n1 = 2).
void BM_IterativePair(benchmark::State& state) {
  const scene::CompiledScene sc = demo("curve12");
  const auto& seg = sc.curve_segments[3].geom;
  int px, py;
  scene::project_to_pixel(sc.camera, scene::curve_point(seg, 0.37), px, py);
  for (auto _ : state)
    benchmark::DoNotOptimize(tracer::iterative_pair(sc.camera, seg, px, py, 16, 2));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_IterativePair);

void BM_IdealPair(benchmark::State& state) {
  const scene::CompiledScene sc = demo("curve12");
  const auto& seg = sc.curve_segments[3].geom;
  int px, py;
  scene::project_to_pixel(sc.camera, scene::curve_point(seg, 0.37), px, py);
  for (auto _ : state) benchmark::DoNotOptimize(tracer::ideal_pair(sc.camera, seg, px, py));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_IdealPair);

}  // namespace

BENCHMARK_MAIN();
