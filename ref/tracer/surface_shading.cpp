#include "tracer/surface_shading.h"

#include <cmath>

#include "patch/patch_shading.h"
#include "scene/surface_geometry.h"

namespace rpu::tracer {

// Central-difference step of the gradient, relative to the local bounding radius: far below the
// features (the snail's thinnest visible sections are ~1e-3 of its radius), far above rounding.
constexpr double kGradientStep = 1e-6;

Vec3 surface_normal(const scene::CompiledSurface& s, const Vec3& X, const Vec3& v) {
  const scene::SurfaceGeometry g(s.surface);
  const Vec3 local_gradient = g.gradient(s.world_to_local(X), kGradientStep * s.local_radius);
  // local = Rᵀ(world − position)/scale: the inverse transpose takes a local normal to R·n.
  Vec3 n = s.rotation * local_gradient;
  const double len = length(n);
  if (!(len > 0.0) || !std::isfinite(len)) return {};
  n = n / len;
  return dot(n, v) > 0.0 ? -n : n;
}

void shade_surface_pixels(std::vector<float>& rgb, const image::Frame& frame,
                          const scene::CompiledScene& sc) {
  if (sc.surfaces.empty()) return;
  const scene::CameraFrame& cam = sc.camera;
  const int first = sc.first_surface_primitive;
  const int last = first + static_cast<int>(sc.surfaces.size());
  for (int j = 0; j < frame.height; ++j)
    for (int i = 0; i < frame.width; ++i) {
      const size_t k = frame.index(i, j);
      const int id = frame.primitive[k];
      if (id < first || id >= last) continue;
      const Vec3 v = cam.ray_direction(i, j);
      // depth = (X − h)·W = t·(v·W)
      const Vec3 X = cam.eye + v * (frame.depth[k] / dot(v, cam.W));
      const Vec3 n = surface_normal(sc.surfaces[static_cast<size_t>(id - first)], X, v);
      const double lambert = n == Vec3{} ? 1.0 : -dot(n, normalize(v));
      const double f = patch::kShadeAmbient + (1.0 - patch::kShadeAmbient) * lambert;
      for (int c = 0; c < 3; ++c) rgb[3 * k + c] = static_cast<float>(rgb[3 * k + c] * f);
    }
}

}  // namespace rpu::tracer
