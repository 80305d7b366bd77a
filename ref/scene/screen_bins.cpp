#include "scene/screen_bins.h"

#include <algorithm>
#include <cmath>

#include "scene/compiled_scene.h"

namespace rpu::scene {
namespace {

// Screen-coordinate interval [lo, hi] of the projection of a sphere onto one screen axis. The
// sphere projected onto the (axis, W) plane is a disk (q_a, q_c) of radius R; the tangent lines
// from the eye have slopes x = (q_a q_c ± R·sqrt(q_a² + q_c² - R²)) / (q_c² - R²). Needs q_c > R.
void axis_interval(double qa, double qc, double R, double& lo, double& hi) {
  const double den = qc * qc - R * R;
  const double root = R * std::sqrt(std::max(0.0, qa * qa + qc * qc - R * R));
  lo = (qa * qc - root) / den;
  hi = (qa * qc + root) / den;
}

}  // namespace

bool sphere_screen_bounds(const CameraFrame& cam, const Vec3& centre, double radius, int& i0,
                          int& i1, int& j0, int& j1) {
  const Vec3 q = centre - cam.eye;
  const double qc = dot(q, cam.W);
  if (qc < -radius) return false;  // entirely behind the eye plane
  i0 = 0;
  i1 = cam.width - 1;
  j0 = 0;
  j1 = cam.height - 1;
  // Reaching (or nearly reaching) the eye plane: the projection is unbounded.
  if (qc <= radius * (1.0 + 1e-9)) return true;
  double xlo, xhi, ylo, yhi;
  axis_interval(dot(q, cam.U), qc, radius, xlo, xhi);
  axis_interval(dot(q, cam.V), qc, radius, ylo, yhi);
  const auto to_col = [&](double x) { return std::floor((x - cam.x_edge(0)) / cam.sigma); };
  const auto to_row = [&](double y) { return std::floor((cam.y_edge(0) - y) / cam.sigma); };
  const double c0 = to_col(xlo) - 1, c1 = to_col(xhi) + 1;
  const double r0 = to_row(yhi) - 1, r1 = to_row(ylo) + 1;
  if (c1 < 0 || c0 > cam.width - 1 || r1 < 0 || r0 > cam.height - 1) return false;
  i0 = static_cast<int>(std::max(c0, 0.0));
  i1 = static_cast<int>(std::min(c1, cam.width - 1.0));
  j0 = static_cast<int>(std::max(r0, 0.0));
  j1 = static_cast<int>(std::min(r1, cam.height - 1.0));
  return true;
}

ScreenBins::ScreenBins(const CameraFrame& cam, const std::vector<CompiledSegment>& segments,
                       int tile, bool enabled)
    : tile_(tile),
      tiles_x_((cam.width + tile - 1) / tile),
      tiles_y_((cam.height + tile - 1) / tile) {
  const size_t tiles = static_cast<size_t>(tiles_x_) * tiles_y_;
  std::vector<std::uint32_t> counts(tiles, 0);
  struct Rect { int t0, t1, u0, u1; bool visible; };
  std::vector<Rect> rects(segments.size());
  for (size_t s = 0; s < segments.size(); ++s) {
    int i0 = 0, i1 = cam.width - 1, j0 = 0, j1 = cam.height - 1;
    const bool visible =
        !enabled || sphere_screen_bounds(cam, segments[s].geom.c0, segments[s].geom.R, i0, i1, j0, j1);
    rects[s] = {i0 / tile, i1 / tile, j0 / tile, j1 / tile, visible};
    if (!visible) continue;
    for (int v = rects[s].u0; v <= rects[s].u1; ++v)
      for (int t = rects[s].t0; t <= rects[s].t1; ++t) ++counts[static_cast<size_t>(v) * tiles_x_ + t];
  }
  offsets_.assign(tiles + 1, 0);
  for (size_t k = 0; k < tiles; ++k) offsets_[k + 1] = offsets_[k] + counts[k];
  items_.resize(offsets_.back());
  std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (size_t s = 0; s < segments.size(); ++s) {
    if (!rects[s].visible) continue;
    for (int v = rects[s].u0; v <= rects[s].u1; ++v)
      for (int t = rects[s].t0; t <= rects[s].t1; ++t)
        items_[fill[static_cast<size_t>(v) * tiles_x_ + t]++] = static_cast<std::uint32_t>(s);
  }
}

}  // namespace rpu::scene
