#include "scene/camera.h"

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "scene/segment.h"

namespace rpu::scene {

CameraFrame make_camera_frame(const Camera& camera, const std::string& source) {
  CameraFrame f;
  f.eye = camera.eye;
  const Vec3 forward = camera.target - camera.eye;
  if (forward == Vec3{})
    throw Error(source + ": camera.target", "target coincides with the eye (no view direction)");
  const std::optional<Vec3> W = unit_direction(forward);
  if (!W)
    throw Error(source + ": camera.target", "the view direction target - eye is out of range "
                                            "(not a finite vector)");
  f.W = *W;
  const std::optional<Vec3> up = unit_direction(camera.up);
  if (!up) throw Error(source + ": camera.up", "up vector has zero length");
  const Vec3 right = cross(f.W, *up);
  const double rlen = length(right);
  if (rlen < 1e-9)
    throw Error(source + ": camera.up", "up vector is parallel to the view direction");
  f.U = right / rlen;
  f.V = cross(f.U, f.W);
  f.half = std::tan(camera.fov_deg * std::numbers::pi / 360.0);
  f.width = camera.width;
  f.height = camera.height;
  f.sigma = 2.0 * f.half / camera.width;
  return f;
}

bool capture_test(const CameraFrame& cam, int i, int j, const Vec3& X, double& depth) {
  const Vec3 q = X - cam.eye;
  const double a = dot(q, cam.U), b = dot(q, cam.V), c = dot(q, cam.W);
  if (!(c > 0.0)) return false;
  const bool inside = a - cam.x_edge(i) * c >= 0.0 && cam.x_edge(i + 1) * c - a > 0.0 &&
                      cam.y_edge(j) * c - b >= 0.0 && b - cam.y_edge(j + 1) * c > 0.0;
  if (inside) depth = c;
  return inside;
}

bool project_to_pixel(const CameraFrame& cam, const Vec3& X, int& i, int& j) {
  const Vec3 q = X - cam.eye;
  const double c = dot(q, cam.W);
  if (!(c > 0.0)) return false;
  const double x = dot(q, cam.U) / c, y = dot(q, cam.V) / c;
  const double fi = std::floor((x - cam.x_edge(0)) / cam.sigma);
  const double fj = std::floor((cam.y_edge(0) - y) / cam.sigma);
  if (!(fi >= 0 && fi < cam.width && fj >= 0 && fj < cam.height)) return false;
  i = static_cast<int>(fi);
  j = static_cast<int>(fj);
  return true;
}

}  // namespace rpu::scene
