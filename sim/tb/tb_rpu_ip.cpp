// rpu_ip (unrolled or iterative) against rpu::ref::ip_process, and with -DIP_STEP rpu_ip_step
// (k at run time) against rpu::ref::ip_step on the model's intermediate states of every k. Real
// search intervals of curve12, random valid gaps, ready_o honoured (rpu_ip); every state field is
// compared: τ, lo.t, lo.X, lo.md, hi.md, the overflow bit and the passed-through context.
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

struct Item {
  size_t seg;
  ref::SearchInterval si;
  ref::IpState in;    // the state entering the step (IP_STEP only)
  ref::IpState want;  // the state leaving the step or the process
  bool ovf;
  std::uint32_t id;
};

#ifdef IP_STEP
constexpr const char* kName = "rpu_ip_step";
#else
constexpr const char* kName = "rpu_ip";
#endif

}  // namespace

int main(int argc, char** argv) {
  auto ctx = std::make_unique<VerilatedContext>();
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
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    const ref::SegmentDesc& s = m.curve_segments[pair.seg];
#ifdef IP_STEP
    fixed::Overflow o0;
    ref::IpState st = ref::ip_start(p, s, pair.si, o0);
    for (int step = 1; step <= p.K(); ++step) {
      fixed::Overflow ovf;
      const ref::IpState next = ref::ip_step(p, s, pair.si, st, ovf);
      if (rng() % 2 == 0 || step == p.K()) items.push_back({pair.seg, pair.si, st, next, ovf.flag, id++});
      st = next;
    }
#else
    fixed::Overflow ovf;
    items.push_back({pair.seg, pair.si, {}, ref::ip_process(p, s, pair.si, ovf), ovf.flag, id++});
#endif
  }

  sim::reset(*top, *ctx);
  std::deque<Item> pending;
  long matched = 0, cycle = 0;
  const long total = static_cast<long>(items.size());
  while (matched < total) {
    const bool issue = !items.empty() && (rng() % 100) < 85;
#ifdef IP_STEP
    const bool ready = true;
#else
    const bool ready = top->ready_o;  // sampled before the edge, as the hardware does
#endif
    top->valid_i = issue;
    if (issue) {
      const Item& it = items.front();
      sim::drive_pair(*top, p, m.curve_segments[it.seg], it.si);
      sim::put(top->ctx_i, it.id, 32);
#ifdef IP_STEP
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
      if (!ok) {
        std::printf("FAILURE cycle %ld item %ld (id %u, got id %u): segment %zu alpha %s beta %s\n"
                    "  expected tau %llu lo.t %s lo.X (%s, %s, %s) lo.md %s hi.md %s ovf %d\n"
                    "  actual   tau %s lo.t %s lo.X (%s, %s, %s) lo.md %s hi.md %s ovf %d\n",
                    cycle, matched, it.id, got_id, it.seg, sim::to_string(it.si.alpha).c_str(),
                    sim::to_string(it.si.beta).c_str(), static_cast<unsigned long long>(w.tau),
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
    if (cycle > 40 * total + 5000) {
      std::printf("FAILURE: timeout, %ld of %ld matched\n", matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("%s n=%d n1=%d metric %d %s: matched %ld items in %ld cycles (%.3f items/cycle)\n",
              kName, IP_N, IP_N1, METRIC, UNROLLED ? "unrolled" : "iterative", matched, cycle,
              static_cast<double>(matched) / cycle);
  return 0;
}
