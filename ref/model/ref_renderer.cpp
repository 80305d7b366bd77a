#include "model/ref_renderer.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "common/error.h"
#include "common/parallel.h"
#include "model/surface/rpu_surface_top.h"
#include "model/units.h"
#include "scene/screen_bins.h"

namespace rpu::ref {

image::Frame render_ref(const scene::CompiledScene& sc, const ModelScene& m,
                        const RefOptions& o, RefStats* stats) {
  // The model has no fixed-point path for patches: never a frame that silently lacks them
  // (run_backend and the sweep refuse such scenes first, naming them).
  if (!sc.patches.empty())
    throw Error(sc.source + ": patches", "the ref backend has no fixed-point path for parametric "
                                         "patches (docs/algorithms.md §4)");
  scene::check_surface_budget(sc);
  require_built_kinds(m);
  const CameraDesc& cam = m.camera;
  image::Frame frame(cam.width, cam.height);
  const scene::ScreenBins bins(sc.camera, sc.curve_segments, 8, o.binning);
  // The grid is looked up at the model's own p0 (converted back to world units), so its
  // regions only need to absorb that conversion: grow them by 2 LSB.
  const scene::ClassificationGrid grid =
      scene::ClassificationGrid::build(sc.texture_segments, 2.0, 2.0 / m.norm.scale);
  std::atomic<std::uint64_t> curve_pairs{0}, texture_pairs{0}, overflow_pairs{0};
  std::atomic<std::uint64_t> surface_pairs{0}, surface_pieces{0};
  struct Row {
    const ModelScene* m;
    const RefOptions* o;
    const scene::ScreenBins* bins;
    const scene::ClassificationGrid* grid;
    image::Frame* frame;
    std::uint64_t curve = 0, texture = 0, ovf = 0, surf = 0, pieces = 0;
    void operator()(int j) {
      const HwParams& p = m->params;
      const CameraDesc& cam = m->camera;
      for (int i = 0; i < cam.width; ++i) {
        const RayGenOut ray = ray_generator(p, cam, i, j);
        Resolve resolve;
        for (auto k : bins->segments_for_pixel(i, j)) {
          const SegmentDesc& s = m->curve_segments[k];
          const PairResult r = process_curve_pair(p, cam, ray, s);
          ++curve;
          ovf += r.overflow;
          if (r.hit) resolve.offer(r.depth, s.primitive);
        }
        if (!m->texture_segments.empty()) {
          const PlanePoint pp = ray_plane_unit(p, cam, ray.vhat);
          if (pp.valid) {
            const auto test = [&](const SegmentDesc& s) {
              Overflow flag;
              ++texture;
              const bool covers = texture_unit(p, s, pp.p0, flag).covers;
              ovf += flag.flag;
              if (covers) resolve.offer(pp.depth, s.primitive);
            };
            if (o->grid) {
              const double x = static_cast<double>(pp.p0.x) / m->norm.scale + m->norm.offset.x;
              const double y = static_cast<double>(pp.p0.y) / m->norm.scale + m->norm.offset.y;
              for (auto k : grid->lookup(x, y)) test(m->texture_segments[k]);
            } else {
              for (const auto& s : m->texture_segments) test(s);
            }
          }
        }
        for (const SurfaceDesc& s : m->surfaces) {
          ++surf;
          const int items = surface_piece_items(s.type);
          for (int k = 0; k < items; ++k) {
            const SurfacePieceResult r = process_surface_piece(p, cam, ray.vhat, s, k);
            pieces += r.valid;
            ovf += r.overflow;
            if (r.hit) resolve.offer(r.depth, s.primitive);
          }
        }
        const size_t idx = frame->index(i, j);
        frame->primitive[idx] = resolve.any ? resolve.primitive : image::kBackground;
        frame->depth[idx] = resolve.any ? static_cast<double>(resolve.depth) : 0.0;
      }
    }
  };
  parallel_rows(cam.height, o.threads, Row{&m, &o, &bins, &grid, &frame},
                [&](const Row& r) {
                  curve_pairs += r.curve;
                  texture_pairs += r.texture;
                  surface_pairs += r.surf;
                  surface_pieces += r.pieces;
                  overflow_pairs += r.ovf;
                });
  if (stats) {
    stats->curve_pairs = curve_pairs;
    stats->texture_pairs = texture_pairs;
    stats->surface_pairs = surface_pairs;
    stats->surface_pieces = surface_pieces;
    stats->overflow_pairs = overflow_pairs;
  }
  return frame;
}

}  // namespace rpu::ref
