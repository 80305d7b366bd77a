// rpu_sqrt against its twin (rpu::ref::sqrt_unit, i.e. isqrt(x >> 2S) << S): exhaustive for
// narrow radicands, edge values then seeded random vectors for wide ones.
#include <vector>

#include "Vrpu_sqrt.h"
#include "tb_base.h"

#ifndef RAD_W
#error "RAD_W must be defined to the RadW parameter of the verilated configuration"
#endif

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_sqrt> tb("tb_rpu_sqrt", argc, argv);
  constexpr int kRadW = RAD_W;
  const bool exhaustive = kRadW <= 16;
  const long random_count = tb.vectors(exhaustive ? 0 : 100000);

  // The operand list: every value (narrow), or edges first and then random values.
  std::vector<u128> operands;
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
      const u128 bits = (static_cast<u128>(tb.rng()) << 64) | tb.rng();
      const int w = 1 + static_cast<int>(tb.rng() % kRadW);  // spread over magnitudes
      operands.push_back(bits & fixed::max_unsigned(w));
    }
  }
  struct Item {
    u128 rad;
    i128 root;
  };
  std::vector<Item> items;
  for (u128 x : operands) {
    fixed::Overflow ovf;
    items.push_back({x, ref::sqrt_unit(static_cast<i128>(x), kRadW, SQRT_W, ovf)});
  }

  sim::Stream<Vrpu_sqrt, Item> s{.latency = sim::kSameLatency};
  s.inputs = [&](sim::Inputs& in, Vrpu_sqrt& t, const Item& it) {
    in("rad", t.rad_i, static_cast<i128>(it.rad), kRadW);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_sqrt& t, const Item& it) {
    o("root", t.root_o, it.root, 64);
  };
  return tb.check(items, s, "RadW=%d SqrtW=%d, %s", kRadW, SQRT_W,
                  exhaustive ? "exhaustive" : "edges + random");
}
