// Twin of rtl/top/rpu_resolve.v | sim/tb/top/tb_rpu_resolve.cpp | sim/tests/top/rpu_resolve.cmake
// Pixel resolve: nearest hit, equal depth → lower primitive id.
#pragma once

#include <cstdint>

#include "model/datapath.h"

namespace rpu::ref {

struct Resolve {
  bool any = false;
  i128 depth = 0;
  std::int32_t primitive = -1;
  void offer(i128 d, std::int32_t id) {
    if (!any || d < depth || (d == depth && id < primitive)) {
      any = true;
      depth = d;
      primitive = id;
    }
  }
};

}  // namespace rpu::ref
