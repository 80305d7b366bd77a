// The classification description of a vector texture (seed 001, list 2): a regular grid of
// square domains on the plane z = 0, each listing the segments that can colour a point in it.
#pragma once

#include <cstdint>
#include <vector>

#include "common/vec3.h"

namespace rpu::scene {

struct CompiledSegment;

class ClassificationGrid {
 public:
  ClassificationGrid() = default;

  // Covers the union of the segments' regions (disk of radius L/2 + w_0 around c_0, which holds
  // every point a segment can colour) with about `target_per_cell` segments per occupied cell.
  // `margin` grows every region (for lookups with a point known only to within that distance).
  static ClassificationGrid build(const std::vector<CompiledSegment>& segments,
                                  double target_per_cell = 2.0, double margin = 0.0);

  // Segment indices listed for the domain containing (x, y); empty outside the grid.
  struct Span {
    const std::uint32_t* begin_;
    const std::uint32_t* end_;
    const std::uint32_t* begin() const { return begin_; }
    const std::uint32_t* end() const { return end_; }
    size_t size() const { return static_cast<size_t>(end_ - begin_); }
  };
  Span lookup(double x, double y) const;

  int columns() const { return nx_; }
  int rows() const { return ny_; }
  double cell_size() const { return cell_; }
  size_t total_entries() const { return items_.size(); }

 private:
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> offsets_;  // nx*ny + 1
  std::vector<std::uint32_t> items_;
};

}  // namespace rpu::scene
