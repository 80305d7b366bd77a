// rpu_mul against rpu::ref::mul_unit: every operand pair when AW + BW ≤ 16 (exhaustive), else
// the corners (0, ±1, the extremes and their neighbours, one-hot and all-ones chunks) and
// random operands of random magnitude. Random valid gaps and junk on idle cycles; compares the
// product, the tag and the latency of every item, in order. Then a reset in the middle of traffic
// (the pipeline full, valid_i high while the reset is low): nothing may come out afterwards
// except the one operand issued after it (a valid register the reset forgets shows up).
#include <deque>
#include <memory>
#include <vector>

#include "Vrpu_mul.h"
#include "model/common/rpu_mul.h"
#include "tb_common.h"

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

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

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

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_mul");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_mul>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_mul");
  std::mt19937_64 rng(seed);

  struct Op {
    i128 a, b;
  };
  std::deque<Op> ops;
  const bool exhaustive = kAW + kBW <= 16;
  if (exhaustive) {
    for (i128 a = lo(kAW); a <= hi(kAW); ++a)
      for (i128 b = lo(kBW); b <= hi(kBW); ++b) ops.push_back({a, b});
  } else {
    for (i128 a : corners(kAW, kChA))
      for (i128 b : corners(kBW, kChB)) ops.push_back({a, b});
    const long n = sim::vector_count(200000);
    for (long k = 0; k < n; ++k) ops.push_back({random_value(rng, kAW), random_value(rng, kBW)});
  }
  const long total = static_cast<long>(ops.size());

  struct Item {
    Op op;
    i128 p;
    std::uint32_t tag;
    long issued;
  };
  std::deque<Item> expected;
  sim::reset(*top, *ctx);
  long cycle = 0, matched = 0;
  const auto field = [](i128 v, int w) { return static_cast<i128>(static_cast<u128>(v) & fixed::max_unsigned(w)); };
  while (matched < total) {
    const bool issue = !ops.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    Op op{random_value(rng, kAW), random_value(rng, kBW)};  // junk unless issued
    if (issue) {
      op = ops.front();
      ops.pop_front();
    }
    sim::put(top->a_i, field(op.a, kAW), kAW);
    sim::put(top->b_i, field(op.b, kBW), kBW);
    const std::uint32_t tag = static_cast<std::uint32_t>(rng() & 1);
    top->tag_i = tag;
    if (issue) expected.push_back({op, ref::mul_unit(op.a, op.b), tag, cycle});
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Item want = expected.front();
      expected.pop_front();
      const int pw = kAW + kBW;
      const i128 p = kSigned ? sim::get_signed(top->p_o, pw)
                             : static_cast<i128>(sim::get_unsigned(top->p_o, pw));
      const long latency = cycle - want.issued;
      if (p != want.p || top->tag_o != want.tag || latency != kLatency) {
        std::printf("FAILURE cycle %ld item %ld: a %s b %s\n  expected p %s tag %u latency %d\n"
                    "  got      p %s tag %u latency %ld\n",
                    cycle, matched, sim::to_string(want.op.a).c_str(),
                    sim::to_string(want.op.b).c_str(), sim::to_string(want.p).c_str(), want.tag,
                    kLatency, sim::to_string(p).c_str(), static_cast<unsigned>(top->tag_o),
                    latency);
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  // A reset with every stage holding an operand and valid_i high during it: the flushed operands
  // must not come out, the next one must (with its latency).
  for (int k = 0; k < kLatency; ++k) {
    top->valid_i = 1;
    sim::tick(*top, *ctx);
  }
  top->rst_ni = 0;
  for (int k = 0; k < 2; ++k) sim::tick(*top, *ctx);
  top->rst_ni = 1;
  top->valid_i = 0;
  for (int k = 0; k < kLatency + 2; ++k) {
    sim::tick(*top, *ctx);
    if (top->valid_o) {
      std::printf("FAILURE: valid_o %d cycles after a reset in traffic (valid_i high before and "
                  "during the reset, low after)\n", k + 1);
      return 1;
    }
  }
  {
    const Op op{hi(kAW), lo(kBW)};
    top->valid_i = 1;
    sim::put(top->a_i, field(op.a, kAW), kAW);
    sim::put(top->b_i, field(op.b, kBW), kBW);
    top->tag_i = 1;
    sim::tick(*top, *ctx);
    top->valid_i = 0;
    const i128 want = ref::mul_unit(op.a, op.b);
    for (int k = 1; k <= kLatency + 2; ++k) {
      const i128 p = kSigned ? sim::get_signed(top->p_o, kAW + kBW)
                             : static_cast<i128>(sim::get_unsigned(top->p_o, kAW + kBW));
      const bool ok =
          top->valid_o ? (k == kLatency && p == want && top->tag_o == 1) : k != kLatency;
      if (!ok) {
        std::printf("FAILURE after a reset in traffic: a %s b %s: expected p %s tag 1 at latency "
                    "%d, got valid_o %d p %s tag %u at latency %d\n",
                    sim::to_string(op.a).c_str(), sim::to_string(op.b).c_str(),
                    sim::to_string(want).c_str(), kLatency, static_cast<int>(top->valid_o),
                    sim::to_string(p).c_str(), static_cast<unsigned>(top->tag_o), k);
        return 1;
      }
      sim::tick(*top, *ctx);
    }
  }
  top->final();
  std::printf("rpu_mul %d x %d %s, chunks %d x %d (%d tiles), latency %d: matched %ld items (%s)\n",
              kAW, kBW, kSigned ? "signed" : "unsigned", kChA, kChB, kTiles, kLatency, matched,
              exhaustive ? "exhaustive" : "corners + random");
  return 0;
}
