// Vector-described surfaces of docs/algorithms.md §3 (seed 004, Dodonov, Gusiatin, Semikin 2008):
// the primitive as written in a scene file, and its compiled form (local frame, bounding sphere).
// The indicators, ranges and pieces are in surface_geometry.h; docs/surfaces.md has the math.
#pragma once

#include <array>
#include <string>

#include "common/vec3.h"

namespace rpu::scene {

enum class SurfaceType { kEllipsoid, kReliefEllipsoid, kSpiral, kSnail, kRocket };

// "ellipsoid", "relief_ellipsoid", "spiral", "snail", "rocket".
const char* surface_type_name(SurfaceType t);

// The seed's parameters, in the primitive's own local frame (y is the axis). Every parameter is
// optional in the file; the defaults are the seed's (docs/scene-format.md). A type uses only
// its own subset:
//   ellipsoid         a b c y_min y_max            (eq 2; default y_range [-b, 0.5 b])
//   relief_ellipsoid  a b c d e y_min y_max        (eq 3; default y_range [-b, b])
//   spiral            R k a b c phi_max            (eq 5)
//   snail             a phi_max                    (eq 6)
//   rocket            a b c d e                    (eq 7, cone read as a·(1 − (y − b)/e))
struct SurfaceParams {
  double a = 1.0, b = 2.0, c = 1.0, d = 1.0, e = 0.4;
  double R = 0.7, k = 0.5;
  double phi_max = 11.0;
  double y_min = -2.0, y_max = 1.0;
};

// The seed's defaults of a type (docs/scene-format.md): y_range follows b as written there.
SurfaceParams default_surface_params(SurfaceType t);

struct Surface {
  SurfaceType type = SurfaceType::kEllipsoid;
  SurfaceParams p;
  // Placement: local → world is  world = position + Rz·Ry·Rx·(scale · local)  (rotations about
  // x, then y, then z, applied after the uniform scale; degrees).
  Vec3 position{0.0, 0.0, 0.0};
  Vec3 rotation_deg{0.0, 0.0, 0.0};
  double scale = 1.0;
  std::array<double, 3> color{1.0, 1.0, 1.0};
};

// Row-major 3×3 matrix (only what the surfaces need).
struct Mat3 {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
  Vec3 operator*(const Vec3& v) const {
    return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
            m[6] * v.x + m[7] * v.y + m[8] * v.z};
  }
  Mat3 transposed() const { return {{m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]}}; }
};

struct CompiledSurface {
  Surface surface;
  int primitive = 0;      // id in CompiledScene::primitives
  Mat3 rotation;          // Rz·Ry·Rx
  Mat3 to_local;          // rotationᵀ / scale:  local = to_local · (world − position)
  // Bounding sphere of the primitive (every point of the surface within its parameter ranges):
  // local centre and radius, and the same in world units.
  Vec3 local_centre;
  double local_radius = 0.0;
  Vec3 centre;
  double radius = 0.0;

  Vec3 world_to_local(const Vec3& w) const { return to_local * (w - surface.position); }
  Vec3 local_to_world(const Vec3& l) const {
    return surface.position + rotation * (l * surface.scale);
  }
};

// Validates nothing (the scene reader does): builds the frame and the bounding sphere.
CompiledSurface compile_surface(const Surface& s, int primitive);

}  // namespace rpu::scene
