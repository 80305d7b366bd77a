// rpu_fifo against rpu::ref::Fifo (the register-level twin) and an order scoreboard: random
// writes (also offered while full: they must be dropped) and random reads in traffic phases, from
// free flow to long stalls that fill the FIFO and long droughts that empty it. Every cycle the
// outputs rd_valid_o, rd_data_o and wr_ready_o equal the twin's; every read returns the oldest
// accepted write (nothing lost, duplicated or reordered); a held output (rd_valid_o && !rd_ready_i)
// stays valid and unchanged. The run must have filled the FIFO and drained it (counted, printed,
// required), so it cannot pass without exercising both ends. At some phase changes the reset is
// asserted in the middle of traffic (1..3 cycles, random inputs while it is low): afterwards the
// FIFO must be empty like a fresh twin (a pointer or valid register the reset forgets shows up).
#include <deque>
#include <vector>

#include "Vrpu_fifo.h"
#include "model/common/rpu_fifo.h"
#include "tb_base.h"

#ifndef WIDTH
#define WIDTH 8
#endif
#ifndef LOG2_DEPTH
#define LOG2_DEPTH 8
#endif

int main(int argc, char** argv) {
  constexpr int kWidth = WIDTH, kLog2 = LOG2_DEPTH;
  static_assert(kWidth <= 128, "the testbench compares up to 128-bit entries");
  sim::Testbench<Vrpu_fifo> tb("tb_rpu_fifo", argc, argv);
  Vrpu_fifo& top = tb.top();
  auto& rng = tb.rng;
  const auto pct = [&](int p) { return static_cast<int>(rng() % 100) < p; };
  const u128 mask = fixed::max_unsigned(kWidth);
  const auto rand_data = [&] { return ((static_cast<u128>(rng()) << 64) | rng()) & mask; };
  top.wr_valid_i = 0;
  top.rd_ready_i = 0;
  tb.reset();

  ref::Fifo twin(kLog2);
  std::deque<u128> order;  // accepted writes not yet read
  const long cycles = tb.vectors(200000);
  long reads = 0, writes = 0, dropped = 0, full_cycles = 0, empty_cycles = 0, resets = 0;
  int wr_pct = 50, rd_pct = 50;
  long phase_left = 0;
  bool held = false;
  u128 held_data = 0;
  const auto fail = [&](long cycle, const char* what, u128 expected, u128 actual) {
    return tb.fail("cycle %ld (after %ld resets): %s\n  inputs: wr_valid %d rd_ready %d, fill "
                   "(twin) %zu\n  expected %s\n  actual   %s",
                   cycle, resets, what, static_cast<int>(top.wr_valid_i),
                   static_cast<int>(top.rd_ready_i), twin.mem.size() + (twin.out_valid ? 1 : 0),
                   sim::str(static_cast<i128>(expected)).c_str(),
                   sim::str(static_cast<i128>(actual)).c_str());
  };

  for (long cycle = 0; cycle < cycles; ++cycle) {
    if (phase_left-- <= 0) {
      if (rng() % 4 == 0 && !order.empty()) {  // a reset in the middle of traffic
        top.rst_ni = 0;
        for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k) {
          top.wr_valid_i = rng() & 1;
          sim::put(top.wr_data_i, static_cast<i128>(rand_data()), kWidth);
          top.rd_ready_i = rng() & 1;
          tb.tick();
        }
        top.rst_ni = 1;
        twin = ref::Fifo(kLog2);
        order.clear();
        held = false;
        ++resets;
      }
      phase_left = 1 + static_cast<long>(rng() % 2000);
      const int kind = static_cast<int>(rng() % 6);
      wr_pct = std::vector<int>{100, 90, 50, 10, 100, 0}[kind];
      rd_pct = std::vector<int>{100, 50, 90, 100, 0, 100}[kind];
    }
    const bool wr_valid = pct(wr_pct);
    const u128 data = rand_data();
    const bool rd_ready = pct(rd_pct);
    top.wr_valid_i = wr_valid;
    sim::put(top.wr_data_i, static_cast<i128>(data), kWidth);
    top.rd_ready_i = rd_ready;
    tb.settle();

    // Outputs of this cycle (registers: independent of this cycle's inputs).
    const bool rv = top.rd_valid_o, wr = top.wr_ready_o;
    const u128 rd = sim::get_unsigned(top.rd_data_o, kWidth);
    if (rv != twin.rd_valid()) return fail(cycle, "rd_valid_o", twin.rd_valid(), rv);
    if (wr != twin.wr_ready()) return fail(cycle, "wr_ready_o", twin.wr_ready(), wr);
    if (rv && rd != twin.rd_data()) return fail(cycle, "rd_data_o", twin.rd_data(), rd);
    if (held && (!rv || rd != held_data)) return fail(cycle, "held output changed", held_data, rd);
    if (!wr) ++full_cycles;
    if (!rv && twin.mem.empty()) ++empty_cycles;
    if (rv && rd_ready) {
      if (order.empty()) return fail(cycle, "read from an empty FIFO", 0, rd);
      if (order.front() != rd) return fail(cycle, "read out of order", order.front(), rd);
      order.pop_front();
      ++reads;
    }
    if (wr_valid && wr) {
      order.push_back(data);
      ++writes;
    } else if (wr_valid) {
      ++dropped;
    }
    held = rv && !rd_ready;
    held_data = rd;
    twin.clock(wr_valid, data, rd_ready);
    tb.tick();
  }
  if (full_cycles == 0 || empty_cycles == 0 || reads == 0 || resets == 0)
    return tb.fail("the run did not fill and drain the FIFO and reset it in traffic");
  tb.add_matched(reads);
  return tb.pass("width %d depth %d: %ld writes, %ld reads, %ld writes refused while full, %ld full "
                 "cycles, %ld empty cycles, %ld resets in traffic",
                 kWidth, 1 << kLog2, writes, reads, dropped, full_cycles, empty_cycles, resets);
}
