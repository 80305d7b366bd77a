// rpu_test_point against rpu::ref::test_point_unit: real search intervals of curve12 (every
// segment, pixels around its projection), random and edge τ indices, random valid gaps, a random
// tag per item (checked). A quarter of the pairs are edited: curve12 has no flat guide, so their
// guides become flat (h just above the kFlatRatio·L threshold up to far beyond it, a and b as the
// descriptor compiler forms them), arcs, straight or the unused mode code 3; and their α, β are
// drawn over the whole Q(3.FT) range or at its ends, so t saturates both ways (ovf_o) and falls
// below 0 (where the guides vanish). A third of the edited pairs take the longest segments the
// descriptor formats hold, both guides flat just past the threshold (a, b largest: their low bits
// reach g) and t in [1/4, 3/4].
#include <algorithm>
#include <vector>

#include "Vrpu_test_point.h"
#include "tb_ip_common.h"

struct Item {
  size_t seg;
  ref::SegmentDesc s;  // the segment's descriptor, edited or not
  bool edited;
  ref::SearchInterval si;
  std::uint64_t m;
  unsigned tag;
  ref::TestPoint want;
  bool ovf;
};

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_test_point> tb("tb_rpu_test_point", argc, argv);
  auto& rng = tb.rng;
  const auto [sc, p, m] = sim::quantized_demo_scene("curve12");
  const int CW = p.coord_w, TW = p.t_w();
  const long count = tb.vectors(100000);

  std::vector<Item> items;
  long n_edited = 0, n_long = 0, n_sat = 0, n_neg = 0;
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    ref::SegmentDesc s = m.curve_segments[pair.seg];
    const bool edited = rng() % 4 == 0;
    if (edited && rng() % 3 == 0) {
      // The longest segments the descriptor formats hold (ends near opposite corners of the
      // ±7/16·2^CW cube) with both guides flat just past the threshold: a = L²/2h is then
      // largest (≈ 2^(CW−4.4)), so the low bits of a and b reach g; t within [1/4, 3/4].
      const i128 lim = (i128{7} << CW) / 16;
      std::int64_t* p1c[3] = {&s.p1.x, &s.p1.y, &s.p1.z};
      std::int64_t* dc[3] = {&s.d.x, &s.d.y, &s.d.z};
      for (int c = 0; c < 3; ++c) {
        const i128 e1 = rng() % 2 ? lim - static_cast<i128>(rng() % 4096)
                                  : -lim + static_cast<i128>(rng() % 4096);
        const i128 e2 = e1 > 0 ? -lim + static_cast<i128>(rng() % 4096)
                               : lim - static_cast<i128>(rng() % 4096);
        *p1c[c] = static_cast<std::int64_t>(std::clamp(e1, -lim, lim));
        *dc[c] = static_cast<std::int64_t>(std::clamp(e2, -lim, lim) - *p1c[c]);
      }
      s.L2 = i128{s.d.x} * s.d.x + i128{s.d.y} * s.d.y + i128{s.d.z} * s.d.z;
      for (ref::GuideDesc& g : s.guide) {
        g.u = {};
        sim::edit_guide(p, s.L2, rng, g, {.unused_mode = true, .flat_near_threshold = true});
      }
      const i128 one = i128{1} << p.t_frac;
      pair.si.alpha = one / 4 + static_cast<i128>(rng() % static_cast<std::uint64_t>(one / 4));
      pair.si.beta = static_cast<i128>(rng() % static_cast<std::uint64_t>(one / 4));
      ++n_edited;
      ++n_long;
    } else if (edited) {
      for (ref::GuideDesc& g : s.guide)
        if (rng() % 4 != 0) sim::edit_guide(p, s.L2, rng, g, {.unused_mode = true});
      switch (rng() % 4) {
        case 0:  // α, β anywhere in Q(3.FT)
          pair.si.alpha = sim::random_signed(rng, TW);
          pair.si.beta = sim::random_signed(rng, TW);
          break;
        case 1: {  // the range ends: t saturates high or low along the interval
          const i128 t_max = (i128{1} << (TW - 1)) - 1, t_min = -(i128{1} << (TW - 1));
          pair.si.alpha = rng() % 2 ? t_max - static_cast<i128>(rng() % 4)
                                    : t_min + static_cast<i128>(rng() % 4);
          pair.si.beta = rng() % 2 ? t_max : t_min;
          break;
        }
        case 2:  // t just below 0 over the interval
          pair.si.alpha = -static_cast<i128>(rng() % (std::uint64_t{1} << p.t_frac));
          pair.si.beta = -static_cast<i128>(rng() % (std::uint64_t{1} << p.t_frac));
          break;
        default:  // the real interval
          break;
      }
      ++n_edited;
    }
    for (int r = 0; r < 8; ++r) {
      const std::uint64_t full = std::uint64_t{1} << p.n;
      const std::uint64_t edges[] = {0, full - 1, 1, full - 2, full / 2};
      const std::uint64_t mm = r < 2 ? edges[rng() % 5] : rng() % full;
      fixed::Overflow ovf;
      Item it{pair.seg, s,  edited, pair.si, mm, static_cast<unsigned>(rng() & 1),
              ref::test_point_unit(p, s, pair.si, mm, ovf), false};
      it.ovf = ovf.flag;
      n_sat += it.ovf ? 1 : 0;
      n_neg += it.want.t < 0 ? 1 : 0;
      items.push_back(it);
    }
  }

  sim::Stream<Vrpu_test_point, Item> s{.latency = sim::kSameLatency, .tag_w = 0};  // its own tag
  s.inputs = [&](sim::Inputs& in, Vrpu_test_point& t, const Item& it) {
    in("tau", t.tau_i, static_cast<i128>(it.m), p.n)("tag", t.tag_i, it.tag, 1);
    sim::pair_inputs(in, t, p, it.s, it.si);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_test_point& t, const Item& it) {
    o.s("t", t.t_o, it.want.t, TW).vec("X", t.x_o, it.want.X, CW + 3);
    o("ovf", t.ovf_o, it.ovf, 1)("tag", t.tag_o, it.tag, 1);
  };
  s.what = [](const Item& it) { return "segment " + std::to_string(it.seg) + (it.edited ? " (edited)" : ""); };
  return tb.check(items, s,
                  "%ld pairs edited, %ld of them long flat; %ld saturated, %ld with t < 0", n_edited, n_long, n_sat, n_neg);
}
