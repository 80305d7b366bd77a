#include "patch/patch_shading.h"

#include <cmath>

#include "patch/ray_frame.h"

namespace rpu::patch {

void shade_patch_pixels(std::vector<float>& rgb, const PatchHitMap& hits,
                        const std::vector<PatchSurface>& surfaces, const scene::CameraFrame& camera) {
  for (int j = 0; j < hits.height; ++j)
    for (int i = 0; i < hits.width; ++i) {
      const PatchPixel& p = hits.at(i, j);
      if (!p.hit) continue;
      const SurfacePoint sp = surfaces[static_cast<size_t>(p.patch)].evaluate(p.u, p.v);
      Vec3 n = cross(sp.du, sp.dv);
      const double len = length(n);
      double lambert = 1.0;
      if (len > 0 && std::isfinite(len)) {
        n = n / len;
        const Vec3 l = normalize(camera.ray_direction(i, j));
        lambert = std::fabs(dot(n, l));
      }
      const double f = kShadeAmbient + (1.0 - kShadeAmbient) * lambert;
      const size_t k = 3 * (static_cast<size_t>(j) * hits.width + i);
      for (int c = 0; c < 3; ++c) rgb[k + c] = static_cast<float>(rgb[k + c] * f);
    }
}

}  // namespace rpu::patch
