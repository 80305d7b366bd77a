#include "model/ref_renderer.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "model/units.h"
#include "scene/screen_bins.h"

namespace rpu::ref {

image::Frame render_ref(const scene::CompiledScene& sc, const ModelScene& m,
                        const RefOptions& o, RefStats* stats) {
  const HwParams& p = m.params;
  const CameraDesc& cam = m.camera;
  image::Frame frame(cam.width, cam.height);
  const scene::ScreenBins bins(sc.camera, sc.curve_segments, 8, o.binning);
  // The grid is looked up at the model's own p0 (converted back to world units), so its
  // regions only need to absorb that conversion: grow them by 2 LSB.
  const scene::ClassificationGrid grid =
      scene::ClassificationGrid::build(sc.texture_segments, 2.0, 2.0 / m.norm.scale);
  std::atomic<int> next_row{0};
  std::atomic<std::uint64_t> curve_pairs{0}, texture_pairs{0}, overflow_pairs{0};
  const auto worker = [&] {
    std::uint64_t n_curve = 0, n_texture = 0, n_ovf = 0;
    for (int j; (j = next_row.fetch_add(1)) < cam.height;) {
      for (int i = 0; i < cam.width; ++i) {
        const RayGenOut ray = ray_generator(p, cam, i, j);
        Resolve resolve;
        for (auto k : bins.segments_for_pixel(i, j)) {
          const SegmentDesc& s = m.curve_segments[k];
          const PairResult r = process_curve_pair(p, cam, ray, s);
          ++n_curve;
          n_ovf += r.overflow;
          if (r.hit) resolve.offer(r.depth, s.primitive);
        }
        if (!m.texture_segments.empty()) {
          const PlanePoint pp = ray_plane_unit(p, cam, ray.vhat);
          if (pp.valid) {
            const auto test = [&](const SegmentDesc& s) {
              Overflow ovf;
              ++n_texture;
              const bool covers = texture_unit(p, s, pp.p0, ovf).covers;
              n_ovf += ovf.flag;
              if (covers) resolve.offer(pp.depth, s.primitive);
            };
            if (o.grid) {
              const double x = static_cast<double>(pp.p0.x) / m.norm.scale + m.norm.offset.x;
              const double y = static_cast<double>(pp.p0.y) / m.norm.scale + m.norm.offset.y;
              for (auto k : grid.lookup(x, y)) test(m.texture_segments[k]);
            } else {
              for (const auto& s : m.texture_segments) test(s);
            }
          }
        }
        const size_t idx = frame.index(i, j);
        frame.primitive[idx] = resolve.any ? resolve.primitive : image::kBackground;
        frame.depth[idx] = resolve.any ? static_cast<double>(resolve.depth) : 0.0;
      }
    }
    curve_pairs += n_curve;
    texture_pairs += n_texture;
    overflow_pairs += n_ovf;
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned n_threads = o.threads > 0 ? static_cast<unsigned>(o.threads) : hw;
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < n_threads; ++t) pool.emplace_back(worker);
  worker();
  pool.clear();
  if (stats) {
    stats->curve_pairs = curve_pairs;
    stats->texture_pairs = texture_pairs;
    stats->overflow_pairs = overflow_pairs;
  }
  return frame;
}

}  // namespace rpu::ref
