// rpu_ip_step (forward differences in the chord's frame) against rpu::ref::ip_step on the model's
// intermediate states: real curve12 pairs, a step k (STEP, or drawn per item when STEP = 0, the
// iterative form), the state entering it from the model's earlier steps and the frame state at its
// τ (frame_state). A quarter of the items have edited frame guides, a quarter random lo/hi md
// (ties and any order for the argmin). Checks the next state {τ, lo.md, hi.md}, the moved frame
// state (frame_state at the next τ), the constants and guides passed through, ovf, k, the
// context and a random tag.
#include <vector>

#include "Vrpu_ip_step.h"
#include "tb_ip_common.h"

#ifndef STEP
#define STEP 1
#endif

namespace {
using H = ref::HwParams;

struct Widths {
  int XW, TW, CaW, W1W, W2W, A1W, A2W, XSW, TSW, CSW, WSW, SSW, ASW, SAW;
  explicit Widths(const ref::HwParams& p) {
    const int FW = H::kFrameWFrac, FG = H::kFrameGuideFrac, n = p.n;
    XW = H::kCandXW;
    TW = p.t_w();
    CaW = H::kFrameCosFrac + 2 + TW;
    W1W = FW + n + 8;
    W2W = FW + 5;
    A1W = W1W - (FW - FG);
    A2W = W2W - (FW - FG);
    XSW = XW + n + 1;
    TSW = TW + n + 1;
    CSW = CaW + n + 1;
    WSW = W1W + n + 2;
    SSW = W1W + 2;
    ASW = A1W + n + 2;
    SAW = A1W + 2;
  }
};

// A port's fields, MSB first: name, value, width (each field two's complement).
struct Field {
  const char* name;
  i128 value;
  int width;
};
using Fields = std::vector<Field>;
sim::Bits pack(const Fields& fs) {
  sim::Concat c;
  for (const Field& f : fs) c.add(f.value, f.width);
  return c.bits();
}
template <class P>
void compare(sim::Outputs& o, const P& port, const Fields& fs) {
  int total = 0;
  for (const Field& f : fs) total += f.width;
  sim::Unpack u(sim::get_bits(port, total));
  for (const Field& f : fs) o.value(f.name, f.value, u.s(f.width));
}
Fields fs_fields(const Widths& w, const ref::FrameState& s) {
  return {{"X", s.X, w.XSW},        {"Y", s.Y, w.XSW},         {"T", s.T, w.TSW},
          {"C2", s.C2, w.CSW},      {"S2", s.S2, w.CSW},       {"W", s.W, w.WSW},
          {"SW", s.SW, w.SSW},      {"A1", s.A[0], w.ASW},     {"SA1", s.SA[0], w.SAW},
          {"A2", s.A[1], w.ASW},    {"SA2", s.SA[1], w.SAW}};
}
Fields pc_fields(const Widths& w, const ref::PairFrame& f) {
  return {{"x1", f.x1, w.XW},     {"y1", f.y1, w.XW},       {"beta", f.beta, w.TW},
          {"c2b", f.c2b, w.CaW},  {"s2b", f.s2b, w.CaW},    {"w2", f.w[2], w.W2W},
          {"a1.2", f.a[0][2], w.A2W}, {"a2.2", f.a[1][2], w.A2W}};
}
Fields fg_fields(const ref::FrameDesc& fd) {
  Fields r;
  const char* names[2][3] = {{"g1.mode", "g1.eta", "g1.eta2"}, {"g2.mode", "g2.eta", "g2.eta2"}};
  for (int k = 0; k < 2; ++k) {
    const ref::FrameGuide& g = fd.guide[k];
    // mode and η are unsigned: one more bit keeps them non-negative in the signed compare
    r.push_back({names[k][0], static_cast<i128>(g.mode), 2});
    r.push_back({names[k][1], g.eta, H::kFrameGuideFrac + 5});
    r.push_back({names[k][2], g.eta2, H::frame_radicand_w()});
  }
  return r;
}

ref::FrameGuide random_guide(std::mt19937_64& rng) {
  ref::FrameGuide g;
  switch (rng() % 4) {
    case 0: g.mode = ref::GuideMode::kStraight; break;
    case 1: g.mode = static_cast<ref::GuideMode>(3); break;
    default: {
      g.mode = ref::GuideMode::kArc;
      const std::int64_t max = std::int64_t{16} << H::kFrameGuideFrac;
      g.eta = static_cast<std::int64_t>(rng() % (max + 1));
      g.eta2 = g.eta * g.eta;
    }
  }
  return g;
}

}  // namespace

struct Item {
  size_t seg;
  int kind;  // 0 real, 1 edited guides, 2 random lo/hi md
  int k;
  ref::FrameDesc fd;
  ref::PairFrame f;
  ref::IpState in, want;
  unsigned tag, ctx;
  bool ovf;
};

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_ip_step> tb("tb_rpu_ip_step", argc, argv);
  auto& rng = tb.rng;
  const auto [sc, p, m] = sim::quantized_demo_scene("curve12");
  const Widths w(p);
  const int MdW = sim::md_width(p);
  const long count = tb.vectors(20000);

  std::vector<Item> items;
  long n_kind[3] = {0, 0, 0}, n_ovf = 0;
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    const ref::SegmentDesc& s0 = m.curve_segments[pair.seg];
    fixed::Overflow o0;
    Item it{pair.seg, static_cast<int>(rng() % 4), STEP, s0.frame,
            ref::frame_unit(p, s0, pair.si, o0), {}, {}, static_cast<unsigned>(rng() & 1),
            static_cast<unsigned>(rng() & 1), false};
    it.kind = it.kind == 3 ? 0 : it.kind;
    if (STEP == 0) it.k = 1 + static_cast<int>(rng() % static_cast<std::uint64_t>(p.K()));
    if (it.kind == 1)
      for (ref::FrameGuide& g : it.fd.guide) g = random_guide(rng);
    ref::SegmentDesc s = s0;
    s.frame = it.fd;
    fixed::Overflow o1;
    ref::IpState st = ref::ip_start(p, s, it.f, o1);
    while (st.k < it.k - 1) st = ref::ip_step(p, s, it.f, st, o1);
    if (it.kind == 2) {
      const i128 lim = i128{1} << (MdW - 1);
      st.lo.md = static_cast<i128>(rng() % 3 == 0 ? 0 : rng()) % lim;
      st.hi.md = rng() % 4 == 0 ? st.lo.md : static_cast<i128>(rng()) % lim;
    }
    it.in = st;
    fixed::Overflow o2;
    it.want = ref::ip_step(p, s, it.f, st, o2);
    it.ovf = o2.flag;
    ++n_kind[it.kind];
    n_ovf += it.ovf ? 1 : 0;
    items.push_back(it);
  }

  sim::Stream<Vrpu_ip_step, Item> str{.latency = sim::kSameLatency, .tag_w = 0};
  str.inputs = [&](sim::Inputs& in, Vrpu_ip_step& t, const Item& it) {
    in("k", t.k_i, it.k, 8);
    in.bits("state", t.state_i, sim::pack_state(p, it.in));
    in.note("tau", std::to_string(it.in.tau)).note("lo.md", sim::str(it.in.lo.md));
    in.note("hi.md", sim::str(it.in.hi.md));
    in.bits("fs", t.fs_i, pack(fs_fields(w, ref::frame_state(p, it.f, it.in.tau))));
    in.bits("pc", t.pc_i, pack(pc_fields(w, it.f)));
    in.bits("fg", t.fg_i, pack(fg_fields(it.fd)));
    in("ctx", t.ctx_i, it.ctx, 1)("tag", t.tag_i, it.tag, 1);
  };
  str.outputs = [&](sim::Outputs& o, const Vrpu_ip_step& t, const Item& it) {
    o("k", t.k_o, it.k, 8);
    sim::state_outputs(o, t.state_o, p, it.want);
    compare(o, t.fs_o, fs_fields(w, ref::frame_state(p, it.f, it.want.tau)));
    compare(o, t.pc_o, pc_fields(w, it.f));
    Fields fg = fg_fields(it.fd);
    for (Field& f : fg) f.value = sim::sign_extend(static_cast<fixed::u128>(f.value), f.width);
    compare(o, t.fg_o, fg);
    o("ovf", t.ovf_o, it.ovf, 1)("ctx", t.ctx_o, it.ctx, 1)("tag", t.tag_o, it.tag, 1);
  };
  str.what = [](const Item& it) {
    return "segment " + std::to_string(it.seg) + " step " + std::to_string(it.k) +
           (it.kind == 1 ? " (edited guides)" : it.kind == 2 ? " (random lo/hi md)" : "");
  };
  return tb.check(items, str, "step %d: %ld real, %ld edited guides, %ld random md; %ld ovf",
                  STEP, n_kind[0], n_kind[1], n_kind[2], n_ovf);
}
