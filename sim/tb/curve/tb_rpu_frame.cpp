// rpu_frame against rpu::ref::frame_unit: real pairs of curve12 (every segment, pixels around
// its projection) with their frame descriptors; a quarter with the descriptor's flat-guide
// constants drawn (curve12 has no flat guide); a quarter with every input drawn over its port
// width (α, β over Q(3.FT), A and B − A anywhere, e1, e2, c2, s2 over their formats, s over
// [20, CoordW + 18]): x0 … y1 saturate (ovf_o); random valid gaps and a random tag per item.
#include <vector>

#include "Vrpu_frame.h"
#include "tb_ip_common.h"

struct Item {
  size_t seg;
  int kind;  // 0 real, 1 flat constants drawn, 2 random inputs
  ref::SegmentDesc s;
  ref::SearchInterval si;
  unsigned tag;
  ref::PairFrame want;
  bool ovf;
};

namespace {
using H = ref::HwParams;
constexpr int kEW = H::kFrameMant + 2, kCW2 = H::kFrameCosFrac + 2,
              kAW = H::kFrameFlatFrac - 3;
}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_frame> tb("tb_rpu_frame", argc, argv);
  auto& rng = tb.rng;
  const auto [sc, p, m] = sim::quantized_demo_scene("curve12");
  const int CW = p.coord_w, DW = p.diff_w(), TW = p.t_w(), n = p.n;
  const int XW = H::kCandXW, CaW = kCW2 + p.t_frac + 3;
  const int FS = H::kFrameWFrac - H::kFrameGuideFrac;
  const int W0W = H::kFrameWFrac + 2 * n + 6, W1W = H::kFrameWFrac + n + 8,
            W2W = H::kFrameWFrac + 5;
  const int A0W = W0W - FS, A1W = W1W - FS, A2W = W2W - FS;
  const long count = tb.vectors(50000);

  std::vector<Item> items;
  long n_kind[3] = {0, 0, 0}, n_sat = 0;
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    Item it{pair.seg, static_cast<int>(rng() % 4), m.curve_segments[pair.seg], pair.si,
            static_cast<unsigned>(rng() & 1), {}, false};
    it.kind = it.kind == 3 ? 0 : it.kind;
    ref::FrameDesc& f = it.s.frame;
    if (it.kind >= 1)
      for (ref::FrameGuide& g : f.guide)
        g.a = static_cast<std::int64_t>(rng() % ((std::uint64_t{1} << (kAW - 1)) + 1));
    if (it.kind == 2) {
      for (ref::IVec3* e : {&f.e1, &f.e2})
        *e = {static_cast<std::int64_t>(sim::random_signed(rng, kEW)),
              static_cast<std::int64_t>(sim::random_signed(rng, kEW)),
              static_cast<std::int64_t>(sim::random_signed(rng, kEW))};
      f.s = 20 + static_cast<int>(rng() % static_cast<std::uint64_t>(CW - 1));
      f.c2 = static_cast<std::int64_t>(sim::random_signed(rng, kCW2));
      f.s2 = static_cast<std::int64_t>(sim::random_signed(rng, kCW2));
      it.si.alpha = sim::random_signed(rng, TW);
      it.si.beta = sim::random_signed(rng, TW);
      it.si.A = {sim::random_signed(rng, CW), sim::random_signed(rng, CW), sim::random_signed(rng, CW)};
      it.si.AB = {sim::random_signed(rng, DW), sim::random_signed(rng, DW), sim::random_signed(rng, DW)};
    }
    fixed::Overflow ovf;
    it.want = ref::frame_unit(p, it.s, it.si, ovf);
    it.ovf = ovf.flag;
    ++n_kind[it.kind];
    n_sat += it.ovf ? 1 : 0;
    items.push_back(it);
  }

  sim::Stream<Vrpu_frame, Item> s{.latency = sim::kSameLatency, .tag_w = 0};  // its own tag
  s.inputs = [&](sim::Inputs& in, Vrpu_frame& t, const Item& it) {
    const ref::FrameDesc& f = it.s.frame;
    in.vec("A", t.a_i, it.si.A, CW).vec("AB", t.ab_i, it.si.AB, DW);
    in("alpha", t.alpha_i, it.si.alpha, TW)("beta", t.beta_i, it.si.beta, TW);
    in.vec("p1", t.p1_i, it.s.p1, CW);
    in.bits("frame", t.fr_i, sim::pack_frame_desc(f));
    in.note("e1", sim::str(f.e1)).note("e2", sim::str(f.e2)).note("s", std::to_string(f.s));
    in.note("c2", sim::str(f.c2)).note("s2", sim::str(f.s2));
    in.note("a1", sim::str(f.guide[0].a)).note("a2", sim::str(f.guide[1].a));
    in("tag", t.tag_i, it.tag, 1);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_frame& t, const Item& it) {
    const ref::PairFrame& w = it.want;
    const auto fields = [&](const auto& port, int total, std::vector<std::pair<const char*, i128>> want,
                            std::vector<int> widths) {
      sim::Unpack u(sim::get_bits(port, total));
      for (size_t k = 0; k < want.size(); ++k)
        o.value(want[k].first, want[k].second, u.s(widths[k]));
    };
    fields(t.xy_o, 4 * XW, {{"x0", w.x0}, {"x1", w.x1}, {"y0", w.y0}, {"y1", w.y1}},
           {XW, XW, XW, XW});
    fields(t.cs_o, 4 * CaW, {{"c2a", w.c2a}, {"c2b", w.c2b}, {"s2a", w.s2a}, {"s2b", w.s2b}},
           {CaW, CaW, CaW, CaW});
    fields(t.w_o, W0W + W1W + W2W, {{"w0", w.w[0]}, {"w1", w.w[1]}, {"w2", w.w[2]}},
           {W0W, W1W, W2W});
    fields(t.fa_o, 2 * (A0W + A1W + A2W),
           {{"a1.0", w.a[0][0]}, {"a1.1", w.a[0][1]}, {"a1.2", w.a[0][2]}, {"a2.0", w.a[1][0]},
            {"a2.1", w.a[1][1]}, {"a2.2", w.a[1][2]}},
           {A0W, A1W, A2W, A0W, A1W, A2W});
    o.s("alpha", t.alpha_o, w.alpha, TW).s("beta", t.beta_o, w.beta, TW);
    o("ovf", t.ovf_o, it.ovf, 1)("tag", t.tag_o, it.tag, 1);
  };
  s.what = [](const Item& it) {
    return "segment " + std::to_string(it.seg) +
           (it.kind == 1 ? " (flat constants)" : it.kind == 2 ? " (random inputs)" : "");
  };
  return tb.check(items, s, "%ld real, %ld with flat constants, %ld random; %ld saturated",
                  n_kind[0], n_kind[1], n_kind[2], n_sat);
}
