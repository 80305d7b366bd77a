// rpu_mul against rpu::ref::mul_unit: every operand pair when AW + BW ≤ 16 (exhaustive), else
// the corners (0, ±1, the extremes and their neighbours, one-hot and all-ones chunks) and
// random operands of random magnitude. Then a reset in the middle of traffic (the pipeline full,
// valid_i high while the reset is low): nothing may come out afterwards except the one operand
// issued after it (a valid register the reset forgets shows up).
#include <algorithm>
#include <vector>

#include "Vrpu_mul.h"
#include "model/common/rpu_mul.h"
#include "tb_base.h"

#ifndef A_W
#define A_W 25
#endif
#ifndef B_W
#define B_W 18
#endif
#ifndef SIGNED
#define SIGNED 1
#endif
#ifndef CHUNK_A
#define CHUNK_A 24
#endif
#ifndef CHUNK_B
#define CHUNK_B 17
#endif
#ifndef LATENCY
#define LATENCY 0
#endif

constexpr int kAW = A_W, kBW = B_W, kChA = CHUNK_A, kChB = CHUNK_B;
constexpr bool kSigned = SIGNED != 0;
constexpr int kTiles = ((kAW - SIGNED + kChA - 1) / kChA) * ((kBW - SIGNED + kChB - 1) / kChB);
// The natural latency is the twin's formula (one formula for the RTL, the model and the tests).
constexpr int kLatency = LATENCY != 0 ? LATENCY : ref::mul_latency(kAW, kBW, kSigned, kChA, kChB);

i128 lo(int w) { return kSigned ? fixed::min_signed(w) : 0; }
i128 hi(int w) { return kSigned ? fixed::max_signed(w) : static_cast<i128>(fixed::max_unsigned(w)); }
i128 random_value(std::mt19937_64& rng, int w) {
  const int bits = 1 + static_cast<int>(rng() % static_cast<unsigned>(w));
  const u128 u = ((static_cast<u128>(rng()) << 64) | rng()) & fixed::max_unsigned(bits);
  i128 v = static_cast<i128>(u);
  if (kSigned) {
    if (bits == w) v = static_cast<i128>((u ^ (u128{1} << (w - 1))) - (u128{1} << (w - 1)));
    else if (rng() & 1) v = -v;
  }
  return std::clamp(v, lo(w), hi(w));
}
std::vector<i128> corners(int w, int chunk) {
  std::vector<i128> c = {0, 1, 2, lo(w), lo(w) + 1, hi(w), hi(w) - 1};
  if (kSigned) c.insert(c.end(), {-1, -2});
  for (int b = 0; b + 1 < w; b += chunk) {  // chunk boundaries: one-hot and all-ones below
    c.push_back(i128{1} << b);
    c.push_back((i128{1} << b) - 1);
    if (kSigned) c.push_back(-(i128{1} << b));
  }
  std::vector<i128> in;
  for (i128 v : c)
    if (v >= lo(w) && v <= hi(w)) in.push_back(v);
  return in;
}

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_mul> tb("tb_rpu_mul", argc, argv);
  struct Item {
    i128 a, b, p;
  };
  std::vector<Item> items;
  const auto add = [&](i128 a, i128 b) { items.push_back({a, b, ref::mul_unit(a, b)}); };
  const bool exhaustive = kAW + kBW <= 16;
  if (exhaustive) {
    for (i128 a = lo(kAW); a <= hi(kAW); ++a)
      for (i128 b = lo(kBW); b <= hi(kBW); ++b) add(a, b);
  } else {
    for (i128 a : corners(kAW, kChA))
      for (i128 b : corners(kBW, kChB)) add(a, b);
    const long n = tb.vectors(200000);
    for (long k = 0; k < n; ++k) {
      const i128 a = random_value(tb.rng, kAW);
      add(a, random_value(tb.rng, kBW));
    }
  }

  sim::Stream<Vrpu_mul, Item> s{.latency = kLatency};
  s.inputs = [](sim::Inputs& in, Vrpu_mul& t, const Item& it) {
    in("a", t.a_i, it.a, kAW)("b", t.b_i, it.b, kBW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_mul& t, const Item& it) {
    o("p", t.p_o, it.p, kAW + kBW);
  };
  if (!tb.run(items, s)) return 1;

  // A reset with every stage holding an operand and valid_i high during it: the flushed operands
  // must not come out, the next one must (with its latency).
  Vrpu_mul& top = tb.top();
  for (int k = 0; k < kLatency; ++k) {
    top.valid_i = 1;
    tb.tick();
  }
  top.rst_ni = 0;
  for (int k = 0; k < 2; ++k) tb.tick();
  top.rst_ni = 1;
  top.valid_i = 0;
  for (int k = 0; k < kLatency + 2; ++k) {
    tb.tick();
    if (top.valid_o)
      return tb.fail("valid_o %d cycles after a reset in traffic (valid_i high before and during "
                     "the reset, low after)", k + 1);
  }
  const Item it{hi(kAW), lo(kBW), ref::mul_unit(hi(kAW), lo(kBW))};
  top.valid_i = 1;
  sim::put(top.a_i, it.a, kAW);
  sim::put(top.b_i, it.b, kBW);
  top.tag_i = 1;
  tb.tick();
  top.valid_i = 0;
  for (int k = 1; k <= kLatency + 2; ++k) {
    const u128 p = sim::get_unsigned(top.p_o, kAW + kBW);
    const bool ok = top.valid_o ? (k == kLatency && p == sim::low_bits(static_cast<u128>(it.p), kAW + kBW) &&
                                   top.tag_o == 1)
                                : k != kLatency;
    if (!ok)
      return tb.fail("after a reset in traffic: a %s b %s: expected p %s tag 1 at latency %d, "
                     "got valid_o %d p %s tag %u at latency %d",
                     sim::str(it.a).c_str(), sim::str(it.b).c_str(), sim::str(it.p).c_str(),
                     kLatency, static_cast<int>(top.valid_o), sim::str(static_cast<i128>(p)).c_str(),
                     static_cast<unsigned>(top.tag_o), k);
    tb.tick();
  }
  return tb.pass("%d x %d %s, chunks %d x %d (%d tiles), latency %d, %s", kAW, kBW,
                 kSigned ? "signed" : "unsigned", kChA, kChB, kTiles, kLatency,
                 exhaustive ? "exhaustive" : "corners + random");
}
