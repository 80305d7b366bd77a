// rpu_cordic against its twin (rpu::ref::cordic_vectoring / cordic_rotation), bit for bit, every
// output field, the tag and the latency (ref::cordic_latency) of every item.
//   Narrow (W ≤ 10): vectoring every (x, y) of the W-bit ports (2^(2W) pairs, in range or not:
//   the twin models the wrap-around too); rotation every (x, y) in [−32, 32]² × every angle, and
//   every (x, y) of the ports × 8 angles (the quadrant edges and 1/8 turn).
//   Wide: the edge coordinates (0, ±1, ±2, ±3, the range's ends ±2^(W−2) and their neighbours,
//   the port's extremes) in every pair (× edge angles), then seeded random vectors: random
//   magnitudes in range, and one in ten arbitrary W-bit patterns.
#include <vector>

#include "Vrpu_cordic.h"
#include "model/common/rpu_cordic.h"
#include "tb_base.h"

#if !defined(CORDIC_W) || !defined(CORDIC_AW) || !defined(CORDIC_ITERS) || !defined(CORDIC_MODE)
#error "CORDIC_W, CORDIC_AW, CORDIC_ITERS and CORDIC_MODE must match the verilated parameters"
#endif

constexpr ref::CordicConfig kConfig{CORDIC_W, CORDIC_AW, CORDIC_ITERS};
constexpr bool kVectoring = CORDIC_MODE == 0;
constexpr int kW = CORDIC_W, kAW = CORDIC_AW;

struct Item {
  std::int64_t x, y;
  std::uint64_t angle;
  std::int64_t want_x, want_y;  // x_o, y_o as the ports carry them (vectoring: magnitude, 0)
  std::uint64_t want_angle;     // angle_o (rotation: 0)
};

Item item(std::int64_t x, std::int64_t y, std::uint64_t angle) {
  if (kVectoring) {
    const auto p = ref::cordic_vectoring(kConfig, x, y);
    return {x, y, angle, p.mag, 0, p.angle};
  }
  const auto r = ref::cordic_rotation(kConfig, x, y, angle);
  return {x, y, angle, r.x, r.y, 0};
}

std::int64_t random_pattern(std::mt19937_64& rng) {  // any W-bit two's-complement value
  return static_cast<std::int64_t>(sim::sign_extend(rng() & fixed::max_unsigned(kW), kW));
}
std::int64_t random_in_range(std::mt19937_64& rng) {  // random magnitude, |v| ≤ 2^(W−2)
  const int bits = static_cast<int>(rng() % static_cast<unsigned>(kW - 1));
  const auto mask = static_cast<std::uint64_t>(fixed::max_unsigned(bits));
  std::int64_t v = static_cast<std::int64_t>(rng() & mask);
  if (bits == kW - 2 && rng() % 16 == 0) v = std::int64_t{1} << (kW - 2);
  return (rng() & 1) ? -v : v;
}

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_cordic> tb("tb_rpu_cordic", argc, argv);
  auto& rng = tb.rng;
  const std::uint64_t turn = std::uint64_t{1} << kAW;
  const std::int64_t port_min = -(std::int64_t{1} << (kW - 1)), port_max = -port_min - 1;
  const std::int64_t lim = std::int64_t{1} << (kW - 2);

  std::vector<Item> items;
  const bool exhaustive = kW <= 10;
  const std::vector<std::uint64_t> edge_angles = {
      0, 1, turn / 8, turn / 4 - 1, turn / 4, turn / 2, 3 * turn / 4 - 1, 3 * turn / 4, turn - 1};
  if (exhaustive) {
    for (std::int64_t x = port_min; x <= port_max; ++x)
      for (std::int64_t y = port_min; y <= port_max; ++y) {
        if (kVectoring) {
          items.push_back(item(x, y, rng() % turn));  // the angle input is ignored: junk
        } else {
          for (std::uint64_t a : {std::uint64_t{0}, turn / 8, turn / 4 - 1, turn / 4, turn / 2,
                                  3 * turn / 4 - 1, 3 * turn / 4, rng() % turn})
            items.push_back(item(x, y, a));
        }
      }
    if (!kVectoring)
      for (std::int64_t x = -32; x <= 32; ++x)
        for (std::int64_t y = -32; y <= 32; ++y)
          for (std::uint64_t a = 0; a < turn; ++a) items.push_back(item(x, y, a));
  } else {
    const std::vector<std::int64_t> edges = {0,   1,         -1,       2,        -2,      3,
                                             -3,  lim,       -lim,     lim - 1,  -lim + 1, lim / 2,
                                             -lim / 2, port_max, port_min};
    for (auto x : edges)
      for (auto y : edges) {
        if (kVectoring) {
          items.push_back(item(x, y, 0));
        } else {
          for (auto a : edge_angles) items.push_back(item(x, y, a));
        }
      }
    const long n = tb.vectors(100000);
    for (long k = 0; k < n; ++k) {
      const bool pattern = rng() % 10 == 0;
      const std::int64_t x = pattern ? random_pattern(rng) : random_in_range(rng);
      const std::int64_t y = pattern ? random_pattern(rng) : random_in_range(rng);
      items.push_back(item(x, y, rng() % turn));
    }
  }

  sim::Stream<Vrpu_cordic, Item> s{.latency = ref::cordic_latency(kConfig, kVectoring)};
  s.inputs = [](sim::Inputs& in, Vrpu_cordic& t, const Item& it) {
    in("x", t.x_i, it.x, kW)("y", t.y_i, it.y, kW)("angle", t.angle_i, it.angle, kAW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_cordic& t, const Item& it) {
    if (kVectoring) o("x (magnitude)", t.x_o, it.want_x, kW);
    else o.s("x", t.x_o, it.want_x, kW);
    o.s("y", t.y_o, it.want_y, kW)("angle", t.angle_o, it.want_angle, kAW);
  };
  return tb.check(items, s, "W=%d AW=%d Iters=%d %s, latency %ld, %s", kW, kAW, CORDIC_ITERS,
                  kVectoring ? "vectoring" : "rotation", s.latency,
                  exhaustive ? "exhaustive" : "edges + random");
}
