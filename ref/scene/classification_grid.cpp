#include "scene/classification_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/compiled_scene.h"

namespace rpu::scene {
namespace {

// Region a texture segment can colour: within w_0 of its curve, which lies in the interpolation
// disk (c_0, L/2), or within w_0 of an end point (pr2): all inside the disk (c_0, L/2 + w_0).
double reach(const CompiledSegment& s, double margin) { return s.geom.R + s.half_width + margin; }

}  // namespace

ClassificationGrid ClassificationGrid::build(const std::vector<CompiledSegment>& segments,
                                             double target_per_cell, double margin) {
  ClassificationGrid g;
  if (segments.empty()) return g;
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
  double xmax = -xmin, ymax = -xmin, area = 0.0;
  for (const auto& s : segments) {
    const double r = reach(s, margin);
    xmin = std::min(xmin, s.geom.c0.x - r);
    xmax = std::max(xmax, s.geom.c0.x + r);
    ymin = std::min(ymin, s.geom.c0.y - r);
    ymax = std::max(ymax, s.geom.c0.y + r);
    area += 4.0 * r * r;
  }
  // Cell size: each segment's bounding square covers about (2r/cell + 1)² cells; pick the cell
  // so that the summed footprint is ~target_per_cell entries per cell of the grid, capped so
  // that the grid stays small (≤ 1024² cells).
  const double width = xmax - xmin, height = ymax - ymin;
  const double extent = std::max(width, height);
  double cell = std::sqrt(std::max(area, 1e-300) / (target_per_cell * segments.size()));
  cell = std::max(cell, extent / 1024.0);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::max(extent, 1.0);
  g.x0_ = xmin;
  g.y0_ = ymin;
  g.cell_ = cell;
  g.nx_ = static_cast<int>(std::floor(width / cell)) + 1;  // covers [xmin, xmax] inclusive
  g.ny_ = static_cast<int>(std::floor(height / cell)) + 1;
  const auto clamp_cell = [](double v, int n) {
    return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1);
  };
  std::vector<std::uint32_t> counts(static_cast<size_t>(g.nx_) * g.ny_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      g.offsets_.assign(counts.size(), 0);
      for (size_t k = 0; k + 1 < counts.size(); ++k) g.offsets_[k + 1] = g.offsets_[k] + counts[k];
      g.items_.resize(g.offsets_.back());
      fill.assign(g.offsets_.begin(), g.offsets_.end() - 1);
    }
    for (size_t idx = 0; idx < segments.size(); ++idx) {
      const auto& s = segments[idx];
      const double r = reach(s, margin);
      const int i0 = clamp_cell((s.geom.c0.x - r - g.x0_) / cell, g.nx_);
      const int i1 = clamp_cell((s.geom.c0.x + r - g.x0_) / cell, g.nx_);
      const int j0 = clamp_cell((s.geom.c0.y - r - g.y0_) / cell, g.ny_);
      const int j1 = clamp_cell((s.geom.c0.y + r - g.y0_) / cell, g.ny_);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const size_t k = static_cast<size_t>(j) * g.nx_ + i;
          if (pass == 0) ++counts[k];
          else g.items_[fill[k]++] = static_cast<std::uint32_t>(idx);
        }
    }
  }
  return g;
}

ClassificationGrid::Span ClassificationGrid::lookup(double x, double y) const {
  if (nx_ == 0) return {nullptr, nullptr};
  const double fx = std::floor((x - x0_) / cell_), fy = std::floor((y - y0_) / cell_);
  if (!(fx >= 0 && fx < nx_ && fy >= 0 && fy < ny_)) return {nullptr, nullptr};
  const size_t k = static_cast<size_t>(fy) * nx_ + static_cast<size_t>(fx);
  return {items_.data() + offsets_[k], items_.data() + offsets_[k + 1]};
}

}  // namespace rpu::scene
