// rpu_cordic against its twin (rpu::ref::cordic_vectoring / cordic_rotation), bit for bit, every
// output field, the tag and the latency (ref::cordic_latency) of every item, in order; random
// valid gaps with junk on the idle cycles.
//   Narrow (W ≤ 10): vectoring every (x, y) of the W-bit ports (2^(2W) pairs, in range or not:
//   the twin models the wrap-around too); rotation every (x, y) in [−32, 32]² × every angle, and
//   every (x, y) of the ports × 8 angles (the quadrant edges and 1/8 turn).
//   Wide: the edge coordinates (0, ±1, ±2, ±3, the range's ends ±2^(W−2) and their neighbours,
//   the port's extremes) in every pair (× edge angles), then seeded random vectors: random
//   magnitudes in range, and one in ten arbitrary W-bit patterns.
#include <deque>
#include <memory>
#include <vector>

#include "Vrpu_cordic.h"
#include "model/common/rpu_cordic.h"
#include "tb_common.h"

#if !defined(CORDIC_W) || !defined(CORDIC_AW) || !defined(CORDIC_ITERS) || !defined(CORDIC_MODE)
#error "CORDIC_W, CORDIC_AW, CORDIC_ITERS and CORDIC_MODE must match the verilated parameters"
#endif
#ifndef TAG_W
#define TAG_W 1
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

constexpr ref::CordicConfig kConfig{CORDIC_W, CORDIC_AW, CORDIC_ITERS};
constexpr bool kVectoring = CORDIC_MODE == 0;
constexpr int kW = CORDIC_W, kAW = CORDIC_AW, kTagW = TAG_W;

struct Op {
  std::int64_t x, y;
  std::uint64_t angle;
};

struct Expected {
  std::int64_t x, y;     // x_o, y_o as the ports carry them (vectoring: magnitude, 0)
  std::uint64_t angle;   // angle_o (rotation: 0)
};

Expected twin(const Op& op) {
  if (kVectoring) {
    const auto p = ref::cordic_vectoring(kConfig, op.x, op.y);
    return {p.mag, 0, p.angle};
  }
  const auto r = ref::cordic_rotation(kConfig, op.x, op.y, op.angle);
  return {r.x, r.y, 0};
}

std::int64_t signed_field(u128 u, int w) {
  const u128 sign = u128{1} << (w - 1);
  return static_cast<std::int64_t>(static_cast<i128>((u ^ sign) - sign));
}
std::int64_t random_pattern(std::mt19937_64& rng) {  // any W-bit two's-complement value
  return signed_field(rng() & fixed::max_unsigned(kW), kW);
}
std::int64_t random_in_range(std::mt19937_64& rng) {  // random magnitude, |v| ≤ 2^(W−2)
  const int bits = static_cast<int>(rng() % static_cast<unsigned>(kW - 1));
  const auto mask = static_cast<std::uint64_t>(fixed::max_unsigned(bits));
  std::int64_t v = static_cast<std::int64_t>(rng() & mask);
  if (bits == kW - 2 && rng() % 16 == 0) v = std::int64_t{1} << (kW - 2);
  return (rng() & 1) ? -v : v;
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_cordic");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_cordic>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_cordic");
  std::mt19937_64 rng(seed);
  const int latency = ref::cordic_latency(kConfig, kVectoring);
  const std::uint64_t turn = std::uint64_t{1} << kAW;
  const std::int64_t port_min = -(std::int64_t{1} << (kW - 1)), port_max = -port_min - 1;
  const std::int64_t lim = std::int64_t{1} << (kW - 2);

  std::deque<Op> ops;
  const bool exhaustive = kW <= 10;
  const std::vector<std::uint64_t> edge_angles = {
      0, 1, turn / 8, turn / 4 - 1, turn / 4, turn / 2, 3 * turn / 4 - 1, 3 * turn / 4, turn - 1};
  if (exhaustive) {
    for (std::int64_t x = port_min; x <= port_max; ++x)
      for (std::int64_t y = port_min; y <= port_max; ++y) {
        if (kVectoring) {
          ops.push_back({x, y, rng() % turn});  // the angle input is ignored: junk
        } else {
          for (std::uint64_t a : {std::uint64_t{0}, turn / 8, turn / 4 - 1, turn / 4, turn / 2,
                                  3 * turn / 4 - 1, 3 * turn / 4, rng() % turn})
            ops.push_back({x, y, a});
        }
      }
    if (!kVectoring)
      for (std::int64_t x = -32; x <= 32; ++x)
        for (std::int64_t y = -32; y <= 32; ++y)
          for (std::uint64_t a = 0; a < turn; ++a) ops.push_back({x, y, a});
  } else {
    const std::vector<std::int64_t> edges = {0,   1,         -1,       2,        -2,      3,
                                             -3,  lim,       -lim,     lim - 1,  -lim + 1, lim / 2,
                                             -lim / 2, port_max, port_min};
    for (auto x : edges)
      for (auto y : edges) {
        if (kVectoring) {
          ops.push_back({x, y, 0});
        } else {
          for (auto a : edge_angles) ops.push_back({x, y, a});
        }
      }
    const long n = sim::vector_count(100000);
    for (long k = 0; k < n; ++k) {
      const bool pattern = rng() % 10 == 0;
      const std::int64_t x = pattern ? random_pattern(rng) : random_in_range(rng);
      const std::int64_t y = pattern ? random_pattern(rng) : random_in_range(rng);
      ops.push_back({x, y, rng() % turn});
    }
  }
  const long total = static_cast<long>(ops.size());

  struct Item {
    Op op;
    Expected want;
    std::uint32_t tag;
    long issued;
  };
  std::deque<Item> expected;
  sim::reset(*top, *ctx);
  long cycle = 0, matched = 0;
  const std::uint32_t tag_mask = (1u << kTagW) - 1;
  while (matched < total) {
    // A new operand on ~85 % of the cycles; junk on the others.
    const bool issue = !ops.empty() && (rng() % 100) < 85;
    Op op{random_pattern(rng), random_pattern(rng), rng() % turn};
    if (issue) {
      op = ops.front();
      ops.pop_front();
    }
    top->valid_i = issue;
    sim::put(top->x_i, op.x, kW);
    sim::put(top->y_i, op.y, kW);
    sim::put(top->angle_i, static_cast<i128>(op.angle), kAW);
    const std::uint32_t tag = static_cast<std::uint32_t>(rng()) & tag_mask;
    top->tag_i = tag;
    if (issue) expected.push_back({op, twin(op), tag, cycle});
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Item it = expected.front();
      expected.pop_front();
      const u128 xo = sim::get_unsigned(top->x_o, kW), yo = sim::get_unsigned(top->y_o, kW);
      const Expected got{kVectoring ? static_cast<std::int64_t>(xo) : signed_field(xo, kW),
                         signed_field(yo, kW),
                         static_cast<std::uint64_t>(sim::get_unsigned(top->angle_o, kAW))};
      const std::uint32_t got_tag = top->tag_o;
      const long lat = cycle - it.issued;
      if (got.x != it.want.x || got.y != it.want.y || got.angle != it.want.angle ||
          got_tag != it.tag || lat != latency) {
        std::printf("FAILURE cycle %ld item %ld: x %lld y %lld angle %llu\n"
                    "  expected x_o %lld y_o %lld angle_o %llu tag %u latency %d\n"
                    "  got      x_o %lld y_o %lld angle_o %llu tag %u latency %ld\n",
                    cycle, matched, static_cast<long long>(it.op.x),
                    static_cast<long long>(it.op.y), static_cast<unsigned long long>(it.op.angle),
                    static_cast<long long>(it.want.x), static_cast<long long>(it.want.y),
                    static_cast<unsigned long long>(it.want.angle), it.tag, latency,
                    static_cast<long long>(got.x), static_cast<long long>(got.y),
                    static_cast<unsigned long long>(got.angle), got_tag, lat);
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
  std::printf("rpu_cordic W=%d AW=%d Iters=%d %s, latency %d: matched %ld items (%s) in %ld "
              "cycles\n",
              kW, kAW, CORDIC_ITERS, kVectoring ? "vectoring" : "rotation", latency, matched,
              exhaustive ? "exhaustive" : "edges + random", cycle);
  return 0;
}
