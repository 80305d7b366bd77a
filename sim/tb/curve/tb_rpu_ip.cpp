// rpu_ip (unrolled or iterative) against rpu::ref::ip_process, and with -DIP_STEP rpu_ip_step
// (k at run time) against rpu::ref::ip_step on the model's intermediate states of every k. Real
// search intervals of curve12, random valid gaps, ready_o honoured (rpu_ip); every state field is
// compared: τ, lo.t, lo.X, lo.md, hi.md, the overflow bit and the passed-through context (and,
// for the step, the tag).
// A quarter of the pairs are edited (curve12 has no flat guide and no far miss): their guides
// become flat (h from just past the kFlatRatio·L threshold up), arcs or straight, their α, β are
// drawn over the whole Q(3.FT) range; an eighth of the edited pairs are far misses: the curve's
// points pushed to one corner of the X range (a long segment, t near −4) and pr(τ) towards the
// opposite one, so md reaches its top bits. The step's items sometimes enter with lo.md or
// hi.md replaced (0, the largest value or random): the step takes any state, and the argmin
// then picks the candidates next to the replaced end.
#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>

#ifdef IP_STEP
#include "Vrpu_ip_step.h"
using Dut = Vrpu_ip_step;
#else
#include "Vrpu_ip.h"
using Dut = Vrpu_ip;
#endif
#include "scene/scene_json.h"
#include "tb_ip_common.h"

#ifndef IP_N
#define IP_N 16
#endif
#ifndef IP_N1
#define IP_N1 2
#endif
#ifndef METRIC
#define METRIC 0
#endif
#ifndef UNROLLED
#define UNROLLED 1
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

struct Item {
  size_t seg;
  ref::SegmentDesc s;  // the segment's descriptor, edited or not
  int edited;          // 0 real, 1 edited guides/interval, 2 far miss
  ref::SearchInterval si;
  ref::IpState in;    // the state entering the step (IP_STEP only)
  ref::IpState want;  // the state leaving the step or the process
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
    s.guide[0].h = static_cast<std::int64_t>(std::llround(
        L * std::uniform_real_distribution<double>(8, ref::HwParams::kFlatRatio)(rng)));
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

#ifdef IP_STEP
constexpr const char* kName = "rpu_ip_step";
#else
constexpr const char* kName = "rpu_ip";
#endif

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_ip");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Dut>(ctx.get());
  const std::uint64_t seed = sim::test_seed(kName);
  std::mt19937_64 rng(seed);

  const scene::CompiledScene sc = scene::compile_scene(
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/curve12.json"));
  ref::HwParams p;
  p.n = IP_N;
  p.n1 = IP_N1;
  p.metric = METRIC == 0 ? ref::Metric::kAbs : ref::Metric::kSquared;
  p.unrolled = UNROLLED != 0;
  const ref::ModelScene m = ref::quantize_scene(sc, p);
  const long count = sim::vector_count(UNROLLED ? 20000 : 4000);

  std::deque<Item> items;
  std::uint32_t id = 0;
  long n_edited = 0, n_far = 0, n_md_top = 0, n_replaced = 0;
  const int MdW = sim::md_width(p);
  [[maybe_unused]] const i128 md_max = (i128{1} << MdW) - 1;
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    ref::SegmentDesc s = m.curve_segments[pair.seg];
    const int edited = edit_pair(p, rng, s, pair.si);
    n_edited += edited != 0;
    n_far += edited == 2;
#ifdef IP_STEP
    fixed::Overflow o0;
    ref::IpState st = ref::ip_start(p, s, pair.si, o0);
    for (int step = 1; step <= p.K(); ++step) {
      fixed::Overflow ovf;
      const ref::IpState next = ref::ip_step(p, s, pair.si, st, ovf);
      if (rng() % 2 == 0 || step == p.K()) {
        ref::IpState in = st;
        if (rng() % (edited == 2 ? 2 : 16) == 0) {  // replace an end's md: the step takes any
          const unsigned r = static_cast<unsigned>(rng() % 6);
          i128& md = r % 2 ? in.hi.md : in.lo.md;
          md = r < 2 ? 0 : r < 4 ? md_max : static_cast<i128>(rng() & static_cast<u128>(md_max));
          ++n_replaced;
        }
        fixed::Overflow ovf2;
        const ref::IpState want = ref::ip_step(p, s, pair.si, in, ovf2);
        n_md_top += (want.lo.md >> (MdW - 1)) != 0 || (want.hi.md >> (MdW - 1)) != 0;
        items.push_back({pair.seg, s, edited, pair.si, in, want, ovf2.flag, id++,
                         static_cast<unsigned>(rng() & 1)});
      }
      st = next;
    }
#else
    fixed::Overflow ovf;
    const ref::IpState want = ref::ip_process(p, s, pair.si, ovf);
    n_md_top += (want.lo.md >> (MdW - 1)) != 0 || (want.hi.md >> (MdW - 1)) != 0;
    items.push_back({pair.seg, s, edited, pair.si, {}, want, ovf.flag, id++, 0});
#endif
  }

  sim::reset(*top, *ctx);
  std::deque<Item> pending;
  long matched = 0, cycle = 0;
  const long total = static_cast<long>(items.size());
  [[maybe_unused]] long burst_out = 0, burst_cycles = 0;  // the iterative form's throughput
  while (matched < total) {
    // Every other 2048 cycles a burst with valid_i always high: the iterative form's start
    // FIFO fills to its depth and ready_o's credit count is tested at its limit.
    const bool burst = (cycle >> 11) & 1;
    const bool issue = !items.empty() && (burst || (rng() % 100) < 85);
#ifdef IP_STEP
    const bool ready = true;
#else
    const bool ready = top->ready_o;  // sampled before the edge, as the hardware does
#endif
    top->valid_i = issue;
    if (issue) {
      const Item& it = items.front();
      sim::drive_pair(*top, p, it.s, it.si);
      sim::put(top->ctx_i, it.id, 32);
#ifdef IP_STEP
      top->tag_i = it.tag;
      top->k_i = static_cast<unsigned>(it.in.k + 1);
      sim::write_state(top->state_i, p, it.in);
#endif
      if (ready) {
        pending.push_back(it);
        items.pop_front();
      }
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (pending.empty()) {
        std::printf("FAILURE cycle %ld: result with nothing outstanding\n", cycle);
        return 1;
      }
      const Item it = pending.front();
      pending.pop_front();
      const sim::IpStateFields f = sim::read_state(top->state_o, p);
      const ref::IpState& w = it.want;
      const std::uint32_t got_id = static_cast<std::uint32_t>(top->ctx_o);
      const bool ok = f.tau == static_cast<i128>(w.tau) && f.lo_t == w.lo.t && f.x[0] == w.lo.X.x &&
                      f.x[1] == w.lo.X.y && f.x[2] == w.lo.X.z && f.lo_md == w.lo.md &&
                      f.hi_md == w.hi.md && static_cast<bool>(top->ovf_o) == it.ovf &&
                      got_id == it.id;
#ifdef IP_STEP
      const unsigned got_tag = static_cast<unsigned>(top->tag_o);
#else
      const unsigned got_tag = 0;
#endif
      if (!ok || got_tag != it.tag) {
        const ref::SegmentDesc& s = it.s;
        std::printf("FAILURE cycle %ld item %ld (id %u, got id %u; tag %u, got tag %u): segment %zu%s"
                    " alpha %s beta %s\n"
                    "  A (%lld, %lld, %lld) AB (%lld, %lld, %lld) p1 (%lld, %lld, %lld)"
                    " d (%lld, %lld, %lld)\n"
                    "  guides: mode %d h %lld a %lld b %lld | mode %d h %lld a %lld b %lld\n"
                    "  in: k %d tau %llu lo.md %s hi.md %s\n"
                    "  expected tau %llu lo.t %s lo.X (%s, %s, %s) lo.md %s hi.md %s ovf %d\n"
                    "  actual   tau %s lo.t %s lo.X (%s, %s, %s) lo.md %s hi.md %s ovf %d\n",
                    cycle, matched, it.id, got_id, it.tag, got_tag, it.seg,
                    it.edited == 2 ? " (far miss)" : it.edited ? " (edited)" : "",
                    sim::to_string(it.si.alpha).c_str(), sim::to_string(it.si.beta).c_str(),
                    static_cast<long long>(it.si.A.x), static_cast<long long>(it.si.A.y),
                    static_cast<long long>(it.si.A.z), static_cast<long long>(it.si.AB.x),
                    static_cast<long long>(it.si.AB.y), static_cast<long long>(it.si.AB.z),
                    static_cast<long long>(s.p1.x), static_cast<long long>(s.p1.y),
                    static_cast<long long>(s.p1.z), static_cast<long long>(s.d.x),
                    static_cast<long long>(s.d.y), static_cast<long long>(s.d.z),
                    static_cast<int>(s.guide[0].mode), static_cast<long long>(s.guide[0].h),
                    static_cast<long long>(s.guide[0].a), static_cast<long long>(s.guide[0].b),
                    static_cast<int>(s.guide[1].mode), static_cast<long long>(s.guide[1].h),
                    static_cast<long long>(s.guide[1].a), static_cast<long long>(s.guide[1].b),
                    it.in.k, static_cast<unsigned long long>(it.in.tau),
                    sim::to_string(it.in.lo.md).c_str(), sim::to_string(it.in.hi.md).c_str(),
                    static_cast<unsigned long long>(w.tau),
                    sim::to_string(w.lo.t).c_str(), sim::to_string(w.lo.X.x).c_str(),
                    sim::to_string(w.lo.X.y).c_str(), sim::to_string(w.lo.X.z).c_str(),
                    sim::to_string(w.lo.md).c_str(), sim::to_string(w.hi.md).c_str(), it.ovf,
                    sim::to_string(f.tau).c_str(), sim::to_string(f.lo_t).c_str(),
                    sim::to_string(f.x[0]).c_str(), sim::to_string(f.x[1]).c_str(),
                    sim::to_string(f.x[2]).c_str(), sim::to_string(f.lo_md).c_str(),
                    sim::to_string(f.hi_md).c_str(), top->ovf_o);
        return 1;
      }
      ++matched;
    }
#if !UNROLLED && !defined(IP_STEP)
    // Throughput of the iterative form: in a burst (valid_i always high, the start FIFO full
    // since the previous phase issued faster than 1/K), one result per K cycles; counted from
    // 512 cycles into the burst to its end; checked for bursts that had items all along.
    {
      const long phase = cycle & 2047;
      if (burst && phase >= 512 && !items.empty()) {
        ++burst_cycles;
        burst_out += top->valid_o;
      }
      if (phase == 2047 && burst_cycles == 2048 - 512) {  // whole bursts only
        if (burst_out * p.K() + 8 * p.K() < burst_cycles) {
          std::printf("FAILURE cycle %ld: %ld results in %ld burst cycles, expected about one per "
                      "K = %d cycles (ready_o or the start FIFO throttles)\n",
                      cycle, burst_out, burst_cycles, p.K());
          return 1;
        }
      }
      if (phase == 2047) burst_out = burst_cycles = 0;
    }
#endif
    if (cycle > 40 * total + 5000) {
      std::printf("FAILURE: timeout, %ld of %ld matched\n", matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("%s n=%d n1=%d metric %d %s: matched %ld items in %ld cycles (%.3f items/cycle); "
              "pairs edited %ld (far misses %ld), ends' md replaced %ld, results with md's top bit "
              "%ld\n",
              kName, IP_N, IP_N1, METRIC, UNROLLED ? "unrolled" : "iterative", matched, cycle,
              static_cast<double>(matched) / cycle, n_edited, n_far, n_replaced, n_md_top);
  return 0;
}
