// Bit-accurate model throughput: ray/curve-segment work items per second on one core (one
// fixed item, and a shuffled list of ~1000 items so caches and branch prediction do not flatter
// the number), at the default parameters and with n1 = 1, n1 = 4 and the squared metric; surface
// piece work items per second on one core, per primitive type; and whole frames of
// `--backend ref` on all cores.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "model/descriptors.h"
#include "model/hw_params.h"
#include "model/ref_renderer.h"
#include "model/surface/rpu_surface_top.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"

namespace {

using namespace rpu;

scene::CompiledScene demo(const char* name) {
  return scene::compile_scene(
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json"));
}

const scene::CompiledScene& curve12() {
  static const scene::CompiledScene sc = demo("curve12");
  return sc;
}

ref::HwParams params(int n1, ref::Metric metric) {
  ref::HwParams p;  // n = 16 and the default formats
  p.n1 = n1;
  p.metric = metric;
  p.validate();
  return p;
}

// One work item as the pipeline receives it: the pixel's ray (from the ray generator) and a
// curve segment's descriptor.
struct WorkItem {
  int i = 0, j = 0;
  std::size_t segment = 0;
  ref::RayGenOut ray;
};

bool passes_pred1(const ref::ModelScene& m, const ref::RayGenOut& ray, std::size_t k) {
  return ref::process_curve_pair(m.params, m.camera, ray, m.curve_segments[k]).interval.pred1;
}

// One item that passes pred_1: the projection of a point of segment 3 (as bench_float), else of
// any segment's midpoint, else the first such pixel of the image.
bool single_item(const scene::CompiledScene& sc, const ref::ModelScene& m, WorkItem& out) {
  std::vector<std::pair<std::size_t, double>> tries = {{3, 0.37}};
  for (std::size_t k = 0; k < sc.curve_segments.size(); ++k) tries.emplace_back(k, 0.5);
  for (const auto& [k, t] : tries) {
    if (k >= sc.curve_segments.size()) continue;
    int i, j;
    if (!scene::project_to_pixel(sc.camera, scene::curve_point(sc.curve_segments[k].geom, t), i, j))
      continue;
    const ref::RayGenOut ray = ref::ray_generator(m.params, m.camera, i, j);
    if (passes_pred1(m, ray, k)) {
      out = {i, j, k, ray};
      return true;
    }
  }
  for (int j = 0; j < m.camera.height; ++j)
    for (int i = 0; i < m.camera.width; ++i) {
      const ref::RayGenOut ray = ref::ray_generator(m.params, m.camera, i, j);
      for (std::size_t k = 0; k < m.curve_segments.size(); ++k)
        if (passes_pred1(m, ray, k)) {
          out = {i, j, k, ray};
          return true;
        }
    }
  return false;
}

// ~`count` distinct items that pass pred_1, shuffled with a fixed seed: half from projections of
// points along every segment (mostly hits), the rest from a strided scan of the whole image
// (pred_1 passes, but mostly misses, as the binned renderer streams them).
std::vector<WorkItem> item_list(const scene::CompiledScene& sc, const ref::ModelScene& m,
                                std::size_t count) {
  std::set<std::tuple<int, int, std::size_t>> seen;
  std::vector<WorkItem> along, scan;
  const std::size_t segs = sc.curve_segments.size();
  const int per_seg = static_cast<int>(count / 2 / std::max<std::size_t>(1, segs)) + 1;
  for (std::size_t k = 0; k < segs; ++k)
    for (int q = 0; q < per_seg; ++q) {
      int i, j;
      const double t = (q + 0.5) / per_seg;
      if (!scene::project_to_pixel(sc.camera, scene::curve_point(sc.curve_segments[k].geom, t), i, j))
        continue;
      const ref::RayGenOut ray = ref::ray_generator(m.params, m.camera, i, j);
      if (passes_pred1(m, ray, k) && seen.insert({i, j, k}).second) along.push_back({i, j, k, ray});
    }
  for (int j = 1; j < m.camera.height; j += 4)
    for (int i = 1; i < m.camera.width; i += 4) {
      const ref::RayGenOut ray = ref::ray_generator(m.params, m.camera, i, j);
      for (std::size_t k = 0; k < segs; ++k)
        if (passes_pred1(m, ray, k) && seen.insert({i, j, k}).second) scan.push_back({i, j, k, ray});
    }
  std::mt19937 rng(12345);
  std::shuffle(scan.begin(), scan.end(), rng);
  if (along.size() + scan.size() > count)
    scan.resize(count - std::min(count, along.size()));
  std::vector<WorkItem> items = std::move(along);
  items.insert(items.end(), scan.begin(), scan.end());
  std::shuffle(items.begin(), items.end(), rng);
  return items;
}

// One core, ray/segment pairs through process_curve_pair (sphere unit, K IP steps, capture).
// `cycle` = false: one fixed item; true: the shuffled list, one item per iteration.
void BM_RefPair(benchmark::State& state, int n1, ref::Metric metric, bool cycle) {
  const scene::CompiledScene& sc = curve12();
  const ref::ModelScene m = ref::quantize_scene(sc, params(n1, metric));
  std::vector<WorkItem> items;
  if (cycle) {
    items = item_list(sc, m, 1000);
  } else {
    WorkItem w;
    if (single_item(sc, m, w)) items.push_back(w);
  }
  if (items.empty()) {
    state.SkipWithError("no ray/segment pair passes pred_1");
    return;
  }
  int hits = 0;
  for (const auto& w : items)
    hits += ref::process_curve_pair(m.params, m.camera, w.ray, m.curve_segments[w.segment]).hit;
  const std::size_t size = items.size();
  std::size_t idx = 0;
  for (auto _ : state) {
    const WorkItem& w = items[idx];
    benchmark::DoNotOptimize(
        ref::process_curve_pair(m.params, m.camera, w.ray, m.curve_segments[w.segment]));
    if (++idx == size) idx = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["K"] = m.params.K();
  state.counters["items"] = static_cast<double>(size);
  state.counters["hit_frac"] = static_cast<double>(hits) / static_cast<double>(size);
  if (!cycle)
    state.SetLabel("pixel (" + std::to_string(items[0].i) + "," + std::to_string(items[0].j) +
                   ") segment " + std::to_string(items[0].segment));
}
BENCHMARK_CAPTURE(BM_RefPair, one_n1_2, 2, ref::Metric::kAbs, false);
BENCHMARK_CAPTURE(BM_RefPair, cycle_n1_2, 2, ref::Metric::kAbs, true);
BENCHMARK_CAPTURE(BM_RefPair, one_n1_1, 1, ref::Metric::kAbs, false);
BENCHMARK_CAPTURE(BM_RefPair, cycle_n1_1, 1, ref::Metric::kAbs, true);
BENCHMARK_CAPTURE(BM_RefPair, one_n1_4, 4, ref::Metric::kAbs, false);
BENCHMARK_CAPTURE(BM_RefPair, cycle_n1_4, 4, ref::Metric::kAbs, true);
BENCHMARK_CAPTURE(BM_RefPair, one_n1_2_squared, 2, ref::Metric::kSquared, false);
BENCHMARK_CAPTURE(BM_RefPair, cycle_n1_2_squared, 2, ref::Metric::kSquared, true);

// One core, surface piece work items through process_surface_piece (sphere unit, local
// transform, cuts, K IP steps of indicator evaluations, depth): ~1000 valid pieces of the demo
// scene, shuffled with a fixed seed (a strided scan of the image, every piece of each pixel).
struct SurfaceItem {
  ref::IVec3 vhat;
  std::size_t surface = 0;
  int piece = 0;
};
void BM_RefSurfacePiece(benchmark::State& state, const char* name) {
  const scene::CompiledScene sc = demo(name);
  const ref::ModelScene m = ref::quantize_scene(sc, ref::HwParams{});
  std::vector<SurfaceItem> items;
  const int stride = std::max(1, static_cast<int>(m.camera.width / 48));
  for (int j = 0; j < m.camera.height; j += stride)
    for (int i = 0; i < m.camera.width; i += stride) {
      const ref::IVec3 vhat = ref::ray_generator(m.params, m.camera, i, j).vhat;
      for (std::size_t k = 0; k < m.surfaces.size(); ++k)
        for (int q = 0; q < ref::surface_piece_items(m.surfaces[k].type); ++q)
          if (ref::process_surface_piece(m.params, m.camera, vhat, m.surfaces[k], q).valid)
            items.push_back({vhat, k, q});
    }
  if (items.empty()) {
    state.SkipWithError("no valid surface piece");
    return;
  }
  std::mt19937 rng(12345);
  std::shuffle(items.begin(), items.end(), rng);
  if (items.size() > 1000) items.resize(1000);
  int hits = 0;
  for (const auto& w : items)
    hits += ref::process_surface_piece(m.params, m.camera, w.vhat, m.surfaces[w.surface], w.piece).hit;
  std::size_t idx = 0;
  for (auto _ : state) {
    const SurfaceItem& w = items[idx];
    benchmark::DoNotOptimize(
        ref::process_surface_piece(m.params, m.camera, w.vhat, m.surfaces[w.surface], w.piece));
    if (++idx == items.size()) idx = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["items"] = static_cast<double>(items.size());
  state.counters["hit_frac"] = static_cast<double>(hits) / static_cast<double>(items.size());
}
BENCHMARK_CAPTURE(BM_RefSurfacePiece, ellipsoid, "surf_ellipsoid");
BENCHMARK_CAPTURE(BM_RefSurfacePiece, relief, "surf_relief");
BENCHMARK_CAPTURE(BM_RefSurfacePiece, spiral, "surf_spiral");
BENCHMARK_CAPTURE(BM_RefSurfacePiece, snail, "surf_snail");
BENCHMARK_CAPTURE(BM_RefSurfacePiece, rocket, "surf_rocket");

// A whole frame of `--backend ref` at full resolution, all cores, default parameters.
void BM_RefFrame(benchmark::State& state, const char* name) {
  const scene::CompiledScene sc = demo(name);
  const ref::ModelScene m = ref::quantize_scene(sc, ref::HwParams{});
  ref::RefOptions o;
  ref::RefStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(ref::render_ref(sc, m, o, &stats));
  const double pixels = static_cast<double>(m.camera.width) * m.camera.height;
  const double pairs = static_cast<double>(stats.curve_pairs + stats.texture_pairs);
  const double cores = std::max(1u, std::thread::hardware_concurrency());
  state.counters["rays/s"] = benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["pairs/s"] = benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["pairs/s/core"] =
      benchmark::Counter(pairs / cores, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["pairs/ray"] = pairs / pixels;
  state.counters["curve_pairs"] = static_cast<double>(stats.curve_pairs);
  state.counters["texture_pairs"] = static_cast<double>(stats.texture_pairs);
  if (stats.surface_pairs > 0) {
    state.counters["surface_pieces"] = static_cast<double>(stats.surface_pieces);
    state.counters["pieces/s/core"] = benchmark::Counter(
        static_cast<double>(stats.surface_pieces) / cores, benchmark::Counter::kIsIterationInvariantRate);
  }
}
BENCHMARK_CAPTURE(BM_RefFrame, curve12, "curve12")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RefFrame, airfield, "airfield")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RefFrame, surf_spiral, "surf_spiral")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RefFrame, surf_mix, "surf_mix")->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
