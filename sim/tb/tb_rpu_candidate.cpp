// rpu_candidate against rpu::ref::candidate_evaluator: real search intervals of curve12 (every
// segment, pixels around its projection), random and edge τ indices, random valid gaps.
#include <deque>
#include <memory>

#include "Vrpu_candidate.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_ip_common.h"

#ifndef METRIC
#define METRIC 0
#endif

namespace {

using namespace rpu;
using sim::i128;

struct Item {
  size_t seg;
  ref::SearchInterval si;
  std::uint64_t m;
  ref::Candidate want;
  bool ovf;
};

}  // namespace

int main(int argc, char** argv) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_candidate>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_candidate");
  std::mt19937_64 rng(seed);

  const scene::CompiledScene sc = scene::compile_scene(
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/curve12.json"));
  ref::HwParams p;
  p.metric = METRIC == 0 ? ref::Metric::kAbs : ref::Metric::kSquared;
  const ref::ModelScene m = ref::quantize_scene(sc, p);
  const int CW = p.coord_w, TW = p.t_w();
  const long count = sim::vector_count(100000);

  std::deque<Item> items;
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    const ref::SegmentDesc& s = m.curve_segments[pair.seg];
    for (int r = 0; r < 8; ++r) {
      const std::uint64_t full = std::uint64_t{1} << p.n;
      const std::uint64_t edges[] = {0, full, 1, full - 1, full / 2};
      const std::uint64_t mm = r < 2 ? edges[rng() % 5] : rng() % (full + 1);
      fixed::Overflow ovf;
      Item it{pair.seg, pair.si, mm, ref::candidate_evaluator(p, s, pair.si, mm, ovf), false};
      it.ovf = ovf.flag;
      items.push_back(it);
    }
  }

  sim::reset(*top, *ctx);
  std::deque<Item> pending;
  long matched = 0, cycle = 0;
  const long total = static_cast<long>(items.size());
  while (matched < total) {
    const bool issue = !items.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Item& it = items.front();
      sim::put(top->m_i, static_cast<i128>(it.m), p.n + 1);
      sim::drive_pair(*top, p, m.curve_segments[it.seg], it.si);
      top->tag_i = static_cast<unsigned>(pending.size() & 1);
      pending.push_back(it);
      items.pop_front();
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      const Item it = pending.front();
      pending.pop_front();
      const ref::Candidate& w = it.want;
      const int XW = CW + 3, PrW = CW + 2;
      const int MdW = METRIC == 0 ? CW + 4 : 2 * CW + 8;
      const i128 t = sim::get_signed(top->t_o, TW);
      const i128 x[3] = {sim::get_comp(top->x_o, 0, XW), sim::get_comp(top->x_o, 1, XW),
                         sim::get_comp(top->x_o, 2, XW)};
      const i128 pr[3] = {sim::get_comp(top->pr_o, 0, PrW), sim::get_comp(top->pr_o, 1, PrW),
                          sim::get_comp(top->pr_o, 2, PrW)};
      const i128 md = static_cast<i128>(sim::get_unsigned(top->md_o, MdW));
      const bool ok = t == w.t && x[0] == w.X.x && x[1] == w.X.y && x[2] == w.X.z &&
                      pr[0] == w.pr.x && pr[1] == w.pr.y && pr[2] == w.pr.z && md == w.md &&
                      static_cast<bool>(top->ovf_o) == it.ovf;
      if (!ok) {
        std::printf("FAILURE cycle %ld item %ld: segment %zu m = %llu alpha %s beta %s\n"
                    "  expected t %s X (%s, %s, %s) pr (%s, %s, %s) md %s ovf %d\n"
                    "  actual   t %s X (%s, %s, %s) pr (%s, %s, %s) md %s ovf %d\n",
                    cycle, matched, it.seg, static_cast<unsigned long long>(it.m),
                    sim::to_string(it.si.alpha).c_str(), sim::to_string(it.si.beta).c_str(),
                    sim::to_string(w.t).c_str(), sim::to_string(w.X.x).c_str(),
                    sim::to_string(w.X.y).c_str(), sim::to_string(w.X.z).c_str(),
                    sim::to_string(w.pr.x).c_str(), sim::to_string(w.pr.y).c_str(),
                    sim::to_string(w.pr.z).c_str(), sim::to_string(w.md).c_str(), it.ovf,
                    sim::to_string(t).c_str(), sim::to_string(x[0]).c_str(),
                    sim::to_string(x[1]).c_str(), sim::to_string(x[2]).c_str(),
                    sim::to_string(pr[0]).c_str(), sim::to_string(pr[1]).c_str(),
                    sim::to_string(pr[2]).c_str(), sim::to_string(md).c_str(), top->ovf_o);
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout, %ld of %ld matched\n", matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_candidate metric %d: matched %ld items in %ld cycles\n", METRIC, matched, cycle);
  return 0;
}
