// rpu_sqrt against its twin (rpu::ref::sqrt_unit, i.e. isqrt(x >> 2S) << S): exhaustive for
// narrow radicands, edge values then seeded random vectors for wide ones; random valid gaps.
#include <deque>
#include <memory>

#include "Vrpu_sqrt.h"
#include "model/units.h"
#include "tb_common.h"

#ifndef RAD_W
#error "RAD_W must be defined to the RadW parameter of the verilated configuration"
#endif
#ifndef SQRT_W
#define SQRT_W 0
#endif

namespace {

using namespace rpu;
using rpu::sim::i128;
using rpu::sim::u128;

struct Item {
  u128 rad;
  i128 expected;
  std::uint32_t tag;
};

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_sqrt");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_sqrt>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_sqrt");
  std::mt19937_64 rng(seed);
  constexpr int kRadW = RAD_W;
  const bool exhaustive = kRadW <= 16;
  const long random_count = sim::vector_count(exhaustive ? 0 : 100000);

  // The operand list: every value (narrow), or edges first and then random values.
  std::deque<u128> operands;
  const u128 max = fixed::max_unsigned(kRadW);
  if (exhaustive) {
    for (u128 x = 0; x <= max; ++x) operands.push_back(x);
  } else {
    for (u128 x : {u128{0}, u128{1}, u128{2}, u128{3}, max, max - 1, max >> 1, (max >> 1) + 1})
      operands.push_back(x);
    for (int k = 1; 2 * k <= kRadW; ++k) {  // perfect squares and their neighbours
      const u128 r = u128{1} << k, sq = r * r;
      for (u128 x : {sq - 1, sq, sq + 1})
        if (x <= max) operands.push_back(x);
    }
    for (long k = 0; k < random_count; ++k) {
      const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
      const int w = 1 + static_cast<int>(rng() % kRadW);  // spread over magnitudes
      operands.push_back(bits & fixed::max_unsigned(w));
    }
  }

  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0;
  std::uint32_t tag = 0;
  const long total = static_cast<long>(operands.size());
  while (matched < total) {
    // Drive: a new operand on ~85 % of the cycles.
    const bool issue = !operands.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const u128 x = operands.front();
      operands.pop_front();
      sim::put(top->rad_i, static_cast<i128>(x), kRadW);
      top->tag_i = tag & 0x1;
      fixed::Overflow ovf;
      expected.push_back({x, ref::sqrt_unit(static_cast<i128>(x), kRadW, SQRT_W, ovf), tag});
      ++tag;
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Item want = expected.front();
      expected.pop_front();
      const u128 got = sim::get_unsigned(top->root_o, 64);
      if (static_cast<i128>(got) != want.expected || top->tag_o != (want.tag & 0x1)) {
        std::printf("FAILURE cycle %ld item %ld: rad = %s expected root %s tag %u, got root %s tag %u\n",
                    cycle, matched, sim::to_string(static_cast<i128>(want.rad)).c_str(),
                    sim::to_string(want.expected).c_str(), want.tag & 1,
                    sim::to_string(static_cast<i128>(got)).c_str(), top->tag_o);
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_sqrt RadW=%d SqrtW=%d: matched %ld items (%s) in %ld cycles\n", kRadW, SQRT_W,
              matched, exhaustive ? "exhaustive" : "edges + random", cycle);
  return 0;
}
