// The ray turned into the z axis (docs/algorithms.md §4, eq 1): an orthonormal frame (e1, e2)
// across the pixel-centre ray, so that the ray/surface hit solves S_x(u, v) = S_y(u, v) = 0 with
// S_x = e1·(S − eye), S_y = e2·(S − eye). The depth of a point is c = W·(S − eye), the float
// tracer's depth (the ray parameter of eye + c·ray_direction(i, j)).
#pragma once

#include <cmath>

#include "common/vec3.h"
#include "scene/camera.h"

namespace rpu::patch {

struct RayFrame {
  Vec3 eye;
  Vec3 dir;     // pixel-centre direction, W component 1 (CameraFrame::ray_direction)
  Vec3 e1, e2;  // orthonormal, perpendicular to dir
  Vec3 forward; // camera W: depth axis
  // Size of the pixel across the ray per unit depth: σ/|dir| (world size at depth c: σ·c/|dir|).
  // On the axis this is σ; away from it the pixel's footprint across the ray narrows to σ·c/|dir|
  // in the radial direction (the screen plane is oblique there), which at a wide field of view
  // (|dir| up to 1/cos of half the diagonal field) is far below σ·c.
  double pixel_angle = 0;

  static RayFrame through_pixel(const scene::CameraFrame& cam, double x, double y) {
    // x, y: continuous pixel coordinates (pixel (i, j) has its centre at (i + 0.5, j + 0.5)).
    RayFrame r;
    r.eye = cam.eye;
    r.dir = cam.W + cam.U * ((x - 0.5 * cam.width) * cam.sigma) +
            cam.V * ((0.5 * cam.height - y) * cam.sigma);
    r.forward = cam.W;
    r.pixel_angle = cam.sigma / length(r.dir);
    const Vec3 d = normalize(r.dir);
    r.e1 = normalize(cam.U - d * dot(cam.U, d));
    r.e2 = cross(d, r.e1);
    return r;
  }
  static RayFrame pixel_centre(const scene::CameraFrame& cam, int i, int j) {
    return through_pixel(cam, i + 0.5, j + 0.5);
  }

  // (S_x, S_y) of eq 1 and the depth c.
  double sx(const Vec3& p) const { return dot(e1, p - eye); }
  double sy(const Vec3& p) const { return dot(e2, p - eye); }
  double depth(const Vec3& p) const { return dot(forward, p - eye); }
  // g(u, v) = S_x² + S_y² (eq 2): the squared distance of the point from the ray.
  double g(const Vec3& p) const {
    const Vec3 q = p - eye;
    const double x = dot(e1, q), y = dot(e2, q);
    return x * x + y * y;
  }
};

}  // namespace rpu::patch
