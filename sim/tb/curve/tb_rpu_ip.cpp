// rpu_ip (unrolled or iterative: frame unit, the two ends, K steps, test point) against
// rpu::ref::frame_unit + ip_process + test_point_unit. Real search intervals of curve12, random
// valid gaps, ready_o honoured; every output field is compared: τ, t, X, lo.md, hi.md, the
// overflow bit and the passed-through context.
// A quarter of the pairs are edited (curve12 has no flat guide and no far miss): their guides
// become flat (h from just past the kFlatRatio·L threshold up), arcs or straight, their α, β are
// drawn over the whole Q(3.FT) range; an eighth of the edited pairs are far misses: the curve's
// points pushed to one corner of the X range (a long segment, t near −4) and pr(τ) towards the
// opposite one.
#include <cmath>
#include <vector>

#include "Vrpu_ip.h"
using Dut = Vrpu_ip;
constexpr const char* kName = "rpu_ip";
#include "tb_ip_common.h"

namespace {

struct Item {
  size_t seg;
  ref::SegmentDesc s;  // the segment's descriptor, edited or not
  int edited;          // 0 real, 1 edited guides/interval, 2 far miss
  ref::SearchInterval si;
  ref::IpState want;  // the process's final state
  ref::TestPoint tp;  // its test point
  bool ovf;
  std::uint32_t id;
  unsigned tag;
};

// Edits a quarter of the pairs (see the header); returns 0 (kept), 1 (edited) or 2 (far miss).
int edit_pair(const ref::HwParams& p, std::mt19937_64& rng, ref::SegmentDesc& s,
              ref::SearchInterval& si) {
  if (rng() % 4 != 0) return 0;
  const int CW = p.coord_w, TW = p.t_w();
  const i128 top = (i128{1} << (TW - 1)) - 1;
  if (rng() % 8 == 0) {
    // Far miss: the segment's ends near opposite corners of the ±7/16·2^CW cube (the descriptor
    // formats, rtl/curve/rpu_curve_point.v) and t ≈ −4, so X = p1 + d·t lies near 9·7/16·2^CW on
    // the p1 side, the most the X format is promised to hold; A at the opposite corner and AB the
    // largest away from X (its port width: pr reaches 1.5·2^CW), so md reaches its top bit.
    const i128 lim = (i128{7} << CW) / 16, amax = (i128{1} << (CW - 1)) - 1;
    const i128 dmax = (i128{1} << CW) - 1;
    std::int64_t* p1c[3] = {&s.p1.x, &s.p1.y, &s.p1.z};
    std::int64_t* dc[3] = {&s.d.x, &s.d.y, &s.d.z};
    decltype(si.A.x)* ac[3] = {&si.A.x, &si.A.y, &si.A.z};
    decltype(si.AB.x)* abc[3] = {&si.AB.x, &si.AB.y, &si.AB.z};
    for (int c = 0; c < 3; ++c) {
      const i128 sgn = rng() % 2 ? 1 : -1;
      const i128 e1 = sgn * (lim - static_cast<i128>(rng() % 4096));
      const i128 e2 = -sgn * (lim - static_cast<i128>(rng() % 4096));
      *p1c[c] = static_cast<std::int64_t>(e1);
      *dc[c] = static_cast<std::int64_t>(e2 - e1);
      *ac[c] = -sgn * (amax - static_cast<i128>(rng() % 4096));
      *abc[c] = -sgn * (dmax - static_cast<i128>(rng() % 4096));
    }
    s.L2 = i128{s.d.x} * s.d.x + i128{s.d.y} * s.d.y + i128{s.d.z} * s.d.z;
    // Guide 1 an arc of the largest heights (h up to kFlatRatio·L ≈ 2^(CW+4.6): its top bits
    // set), guide 2 straight: for t ≈ −4 the guides vanish (w = 0), X is p1 + d·t.
    const double L = std::sqrt(static_cast<double>(s.L2));
    s.guide[0].mode = ref::GuideMode::kArc;
    s.guide[0].h = static_cast<std::int64_t>(
        std::llround(L * sim::uniform(rng, 8, ref::HwParams::kFlatRatio)));
    s.guide[1].mode = ref::GuideMode::kStraight;
    si.alpha = -top + static_cast<i128>(rng() % 4096);
    si.beta = static_cast<i128>(rng() % 4096);
    return 2;
  }
  for (ref::GuideDesc& g : s.guide)
    if (rng() % 4 != 0) sim::edit_guide(p, s.L2, rng, g, {.octave_shift = -6});
  if (rng() % 2 == 0) {  // α, β anywhere in Q(3.FT)
    si.alpha = sim::random_signed(rng, TW);
    si.beta = sim::random_signed(rng, TW);
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Dut> tb(kName, argc, argv);
  auto& rng = tb.rng;
  const auto [sc, p, m] = sim::quantized_demo_scene("curve12");
  const long count = tb.vectors(UNROLLED ? 20000 : 4000);

  std::vector<Item> items;
  std::uint32_t id = 0;
  long n_edited = 0, n_far = 0, n_md_top = 0;
  const int MdW = sim::md_width(p);
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    ref::SegmentDesc s = m.curve_segments[pair.seg];
    const int edited = edit_pair(p, rng, s, pair.si);
    n_edited += edited != 0;
    n_far += edited == 2;
    fixed::Overflow ovf;
    const ref::PairFrame f = ref::frame_unit(p, s, pair.si, ovf);
    const ref::IpState want = ref::ip_process(p, s, f, ovf);
    const ref::TestPoint tp = ref::test_point_unit(p, s, pair.si, want.tau, ovf);
    n_md_top += (want.lo.md >> (MdW - 1)) != 0 || (want.hi.md >> (MdW - 1)) != 0;
    items.push_back({pair.seg, s, edited, pair.si, want, tp, ovf.flag, id++, 0});
  }

  sim::Stream<Dut, Item> s{.tag_w = 0};
  s.inputs = [&](sim::Inputs& in, Dut& t, const Item& it) {
    sim::pair_inputs(in, t, p, it.s, it.si);
    in.bits("frame", t.fr_i, sim::pack_frame_desc(it.s.frame))
        .bits("fg", t.fg_i, sim::pack_frame_guides(it.s.frame));
    in("ctx", t.ctx_i, it.id, 32);
  };
  s.outputs = [&](sim::Outputs& o, const Dut& t, const Item& it) {
    sim::ip_outputs(o, t.state_o, p, it.want, it.tp);
    o("ovf", t.ovf_o, it.ovf, 1)("ctx", t.ctx_o, it.id, 32);
  };
  s.what = [](const Item& it) {
    return "segment " + std::to_string(it.seg) + (it.edited == 2 ? " (far miss)" : it.edited ? " (edited)" : "");
  };
  // Every other 2048 cycles a burst with valid_i always high: the iterative form's start FIFO
  // fills to its depth and ready_o's credit count is tested at its limit.
  s.traffic.valid_at = [](long cycle) { return (cycle >> 11) & 1 ? 100 : 85; };
  s.timeout = 40 * static_cast<long>(items.size()) + 5000;
#if UNROLLED
  s.latency = sim::kSameLatency;  // pipelines (the iterative form's latency follows the load)
#endif
#if !UNROLLED
  // Throughput of the iterative form: in a burst (valid_i always high, the start FIFO full since
  // the previous phase issued faster than 1/K), one result per K cycles; counted from 512 cycles
  // into the burst to its end; checked for bursts that had items all along.
  long burst_out = 0, burst_cycles = 0;
  s.monitor = [&](const Dut& t, const sim::Cycle& c) -> std::string {
    const long phase = c.cycle & 2047;
    if ((c.cycle >> 11) & 1 && phase >= 512 && c.left > 0) {
      ++burst_cycles;
      burst_out += t.valid_o;
    }
    std::string e;
    if (phase == 2047 && burst_cycles == 2048 - 512 && burst_out * p.K() + 8 * p.K() < burst_cycles)
      e = std::to_string(burst_out) + " results in " + std::to_string(burst_cycles) +
          " burst cycles, expected about one per K = " + std::to_string(p.K()) +
          " cycles (ready_o or the start FIFO throttles)";
    if (phase == 2047) burst_out = burst_cycles = 0;
    return e;
  };
#endif
  if (!tb.run(items, s)) return 1;
  return tb.pass("%s n=%d n1=%d metric %d %s, %.3f items/cycle; pairs edited %ld (far misses %ld), "
                 "results with md's top bit %ld",
                 kName, IP_N, IP_N1, METRIC, UNROLLED ? "unrolled" : "iterative",
                 static_cast<double>(tb.matched()) / static_cast<double>(tb.cycle()), n_edited,
                 n_far, n_md_top);
}
