// rpu_chord against its twin rpu::ref::chord_parameter: every inv_s (left and right shifts) with
// the extreme operands, values at the saturation boundary for each shift, then seeded random
// operands (magnitudes spread, inv_m normalised or arbitrary); random valid gaps.
#include <deque>
#include <memory>
#include <vector>

#include "Vrpu_chord.h"
#include "model/units.h"
#include "tb_common.h"

#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef T_FRAC
#define T_FRAC 24
#endif
#ifndef INV_W
#define INV_W 18
#endif
#ifndef TAG_W
#define TAG_W 8
#endif

namespace {

using namespace rpu;
using fixed::u128;
using sim::i128;

struct Item {
  i128 dot;
  i128 inv_m;
  int inv_s;
  i128 t;
  bool ovf;
};

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_chord");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_chord>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_chord");
  std::mt19937_64 rng(seed);
  ref::HwParams p;
  p.coord_w = COORD_W;
  p.t_frac = T_FRAC;
  p.inv_w = INV_W;
  p.validate();
  const int DotW = 2 * p.diff_w() + 2, IW = p.inv_w, TW = p.t_w(), FT = p.t_frac;
  constexpr int kShW = 7;
  const int kLatency = ref::chord_latency(p);

  std::vector<Item> items;
  const auto add = [&](i128 dot, i128 inv_m, int inv_s) {
    ref::SegmentDesc s;
    s.inv_m = static_cast<fixed::i64>(inv_m);
    s.inv_s = inv_s;
    fixed::Overflow ovf;
    const i128 t = ref::chord_parameter(p, s, dot, ovf);
    items.push_back({dot, inv_m, inv_s, t, ovf.flag});
  };
  const i128 dmax = fixed::max_signed(DotW), dmin = fixed::min_signed(DotW);
  const i128 mmax = static_cast<i128>(fixed::max_unsigned(IW));
  // Every shift with the extreme operands.
  for (int s = 0; s < (1 << kShW); ++s)
    for (i128 dot : {i128{0}, i128{1}, i128{-1}, dmax, dmin, dmax >> 20, dmin >> 20})
      for (i128 m : {i128{0}, i128{1}, mmax, i128{1} << (IW - 1), (i128{1} << (IW - 2)) + 1})
        add(dot, m, s);
  // The saturation boundary after a right shift by k (inv_m = 1): T·2^k + r around the extremes.
  const i128 tmax = fixed::max_signed(TW), tmin = fixed::min_signed(TW);
  for (int k = 0; FT + k < (1 << kShW); ++k)
    for (i128 t : {tmax, tmax + 1, tmin, tmin - 1, i128{0}, i128{-1}})
      for (int r = 0; r < 2; ++r) {
        const i128 dot = t * (i128{1} << k) + (r ? (i128{1} << k) - 1 : 0);
        if (fixed::fits_signed(dot, DotW)) add(dot, 1, FT + k);
      }
  // Random operands.
  const long count = sim::vector_count(200000);
  for (long k = 0; k < count; ++k) {
    const int b = 1 + static_cast<int>(rng() % DotW);
    const i128 dot = static_cast<i128>(((static_cast<u128>(rng()) << 64) | rng()) &
                                       fixed::max_unsigned(b)) - (i128{1} << (b - 1));
    const i128 m = k % 2 ? static_cast<i128>(rng() & fixed::max_unsigned(IW))
                         : (i128{1} << (IW - 2)) + 1 +
                               static_cast<i128>(rng() % (u128{1} << (IW - 2)));
    const int s = k % 4 < 2 ? static_cast<int>(rng() % (1 << kShW))
                            : FT - 4 + static_cast<int>(rng() % (DotW + 8));  // realistic
    add(dot, m, s);
  }

  sim::reset(*top, *ctx);
  struct Pending {
    size_t index;
    long cycle;
    std::uint32_t tag;
  };
  std::deque<Pending> pending;
  long matched = 0, cycle = 0, saturated = 0;
  size_t next = 0;
  const long total = static_cast<long>(items.size());
  const u128 tag_mask = fixed::max_unsigned(TAG_W);
  while (matched < total) {
    const bool issue = next < items.size() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Item& it = items[next];
      sim::put(top->dot_i, it.dot & static_cast<i128>(fixed::max_unsigned(DotW)), DotW);
      sim::put(top->inv_m_i, it.inv_m, IW);
      sim::put(top->inv_s_i, it.inv_s, kShW);
      const std::uint32_t tag = static_cast<std::uint32_t>(next & tag_mask);
      sim::put(top->tag_i, tag, TAG_W);
      pending.push_back({next, cycle, tag});
      ++next;
    } else {  // junk between operands
      sim::put(top->dot_i, static_cast<i128>(rng() & fixed::max_unsigned(DotW < 64 ? DotW : 64)), DotW);
      sim::put(top->inv_m_i, static_cast<i128>(rng() & fixed::max_unsigned(IW)), IW);
      sim::put(top->inv_s_i, static_cast<i128>(rng() & 0x7F), kShW);
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (pending.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Pending pd = pending.front();
      pending.pop_front();
      const Item& it = items[pd.index];
      const i128 t = sim::get_signed(top->t_o, TW);
      const bool ovf = top->ovf_o;
      const auto tag = static_cast<std::uint32_t>(sim::get_unsigned(top->tag_o, TAG_W));
      if (t != it.t || ovf != it.ovf || tag != pd.tag || cycle - pd.cycle != kLatency) {
        std::printf("FAILURE cycle %ld item %zu: dot = %s inv_m = %s inv_s = %d: expected t %s "
                    "ovf %d tag %u latency %d, got t %s ovf %d tag %u latency %ld\n",
                    cycle, pd.index, sim::to_string(it.dot).c_str(),
                    sim::to_string(it.inv_m).c_str(), it.inv_s, sim::to_string(it.t).c_str(),
                    it.ovf, pd.tag, kLatency, sim::to_string(t).c_str(), ovf, tag,
                    cycle - pd.cycle);
        return 1;
      }
      saturated += it.ovf;
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_chord DotW=%d InvW=%d TFrac=%d: matched %ld items (%ld saturated) in %ld cycles\n",
              DotW, IW, FT, matched, saturated, cycle);
  return 0;
}
