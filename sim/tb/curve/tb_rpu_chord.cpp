// rpu_chord against its twin rpu::ref::chord_parameter: every inv_s (left and right shifts) with
// the extreme operands, values at the saturation boundary for each shift, then seeded random
// operands (magnitudes spread, inv_m normalised or arbitrary).
#include <vector>

#include "Vrpu_chord.h"
#include "tb_base.h"

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_chord> tb("tb_rpu_chord", argc, argv);
  auto& rng = tb.rng;
  const ref::HwParams p = sim::tb_params();
  const int DotW = 2 * p.diff_w() + 2, IW = p.inv_w, TW = p.t_w(), FT = p.t_frac;
  constexpr int kShW = 7;

  struct Item {
    i128 dot, inv_m;
    int inv_s;
    i128 t;
    bool ovf;
  };
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
  const long count = tb.vectors(200000);
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
  long saturated = 0;
  for (const Item& it : items) saturated += it.ovf;

  sim::Stream<Vrpu_chord, Item> s{.latency = ref::chord_latency(p)};
  s.inputs = [&](sim::Inputs& in, Vrpu_chord& t, const Item& it) {
    in("dot", t.dot_i, it.dot, DotW)("inv_m", t.inv_m_i, it.inv_m, IW)("inv_s", t.inv_s_i, it.inv_s, kShW);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_chord& t, const Item& it) {
    o.s("t", t.t_o, it.t, TW)("ovf", t.ovf_o, it.ovf, 1);
  };
  return tb.check(items, s, "DotW=%d InvW=%d TFrac=%d, %ld saturated", DotW, IW, FT, saturated);
}
