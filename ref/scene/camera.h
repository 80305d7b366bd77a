// Camera constants, pixel rays and the pixel visibility pyramid (docs/algorithms.md §1.1).
#pragma once

#include <string>

#include "common/vec3.h"
#include "scene/scene.h"

namespace rpu::scene {

// Orthonormal camera frame and the screen geometry. Screen plane at distance 1 along W;
// pixel (i, j) covers x ∈ [x_edge(i), x_edge(i+1)), y ∈ (y_edge(j+1), y_edge(j)].
struct CameraFrame {
  Vec3 eye;          // h
  Vec3 U, V, W;      // right, screen-up, forward
  double half = 0;   // tan(fov/2)
  double sigma = 0;  // pixel size 2·half/width
  int width = 0, height = 0;

  double x_edge(int i) const { return (i - 0.5 * width) * sigma; }
  double y_edge(int j) const { return (0.5 * height - j) * sigma; }
  // v: pixel centre minus eye (not normalised).
  Vec3 ray_direction(int i, int j) const {
    return W + U * ((i + 0.5 - 0.5 * width) * sigma) + V * ((0.5 * height - j - 0.5) * sigma);
  }
};

// Builds the frame; throws rpu::Error (naming `source` and the camera key) when eye = target or
// up is parallel to the view direction.
CameraFrame make_camera_frame(const Camera& camera, const std::string& source);

// The PVP sign test (seed 000, eqs 24–26, in the camera basis): X is captured by pixel (i, j)
// iff c > 0 and a - x_i·c ≥ 0, x_{i+1}·c - a > 0, y_j·c - b ≥ 0, b - y_{j+1}·c > 0 with
// a, b, c the coordinates of X - h along U, V, W. On capture, `depth` receives c.
bool capture_test(const CameraFrame& cam, int i, int j, const Vec3& X, double& depth);

// Pixel containing the projection of X (for tests and binning): false when X is not in front
// of the eye or projects outside the image.
bool project_to_pixel(const CameraFrame& cam, const Vec3& X, int& i, int& j);

}  // namespace rpu::scene
