// Twin of rtl/common/rpu_fifo.v | sim/tb/common/tb_rpu_fifo.cpp | sim/tests/common/rpu_fifo.cmake
// A first-word-fall-through FIFO with a registered read (block RAM), cycle for cycle: the
// memory of 2^log2_depth entries and the output register. The design's other twins are
// item-level and need no FIFO; this one exists so the RTL FIFO is checked against the same
// register-level rules (latency, fill, ready) as it is written, independently of the testbench's
// order scoreboard.
#pragma once

#include <cstdint>
#include <deque>

#include "model/datapath.h"

namespace rpu::ref {

struct Fifo {
  explicit Fifo(int log2_depth) : depth(std::size_t{1} << log2_depth) {}

  // Outputs of the current cycle (before the clock edge), as the RTL's registers hold them.
  bool rd_valid() const { return out_valid; }
  fixed::u128 rd_data() const { return out; }
  bool wr_ready() const { return mem.size() != depth; }

  // One clock edge with these inputs. Returns false when a write was offered while full
  // (dropped, as the RTL drops it).
  bool clock(bool wr_valid, fixed::u128 wr_data, bool rd_ready) {
    const bool take = out_valid && rd_ready;
    const bool load = !mem.empty() && (!out_valid || take);
    const bool write = wr_valid && wr_ready();
    if (load) {
      out = mem.front();
      mem.pop_front();
      out_valid = true;
    } else if (take) {
      out_valid = false;
    }
    if (write) mem.push_back(wr_data);  // after the read: the new entry is never read this edge
    return !wr_valid || write;
  }

  std::size_t depth;
  std::deque<fixed::u128> mem;
  bool out_valid = false;
  fixed::u128 out = 0;
};

}  // namespace rpu::ref
