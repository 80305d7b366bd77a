// rpu_candidate against rpu::ref::candidate_evaluator: real search intervals of curve12 (every
// segment, pixels around its projection), random and edge τ indices, random valid gaps, a random
// tag per item (checked). A quarter of the pairs are edited: curve12 has no flat guide, so their
// guides become flat (h just above the kFlatRatio·L threshold up to far beyond it, a and b as the
// descriptor compiler forms them), arcs, straight or the unused mode code 3; and their α, β are
// drawn over the whole Q(3.FT) range or at its ends, so t saturates both ways (ovf_o) and falls
// below 0 (where the guides vanish). A third of the edited pairs take the longest segments the
// descriptor formats hold, both guides flat just past the threshold (a, b largest: their low bits
// reach g) and t in [1/4, 3/4].
#include <algorithm>
#include <cmath>
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
using sim::u128;

struct Item {
  size_t seg;
  ref::SegmentDesc s;  // the segment's descriptor, edited or not
  bool edited;
  ref::SearchInterval si;
  std::uint64_t m;
  unsigned tag;
  ref::Candidate want;
  bool ovf;
};

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_candidate");
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
      const std::uint64_t edges[] = {0, full, 1, full - 1, full / 2};
      const std::uint64_t mm = r < 2 ? edges[rng() % 5] : rng() % (full + 1);
      fixed::Overflow ovf;
      Item it{pair.seg, s,  edited, pair.si, mm, static_cast<unsigned>(rng() & 1),
              ref::candidate_evaluator(p, s, pair.si, mm, ovf), false};
      it.ovf = ovf.flag;
      n_sat += it.ovf ? 1 : 0;
      n_neg += it.want.t < 0 ? 1 : 0;
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
      sim::drive_pair(*top, p, it.s, it.si);
      top->tag_i = it.tag;
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
                      static_cast<bool>(top->ovf_o) == it.ovf && top->tag_o == it.tag;
      if (!ok) {
        std::printf("FAILURE cycle %ld item %ld: segment %zu%s m = %llu alpha %s beta %s\n"
                    "  guides: mode %d h %lld a %lld b %lld | mode %d h %lld a %lld b %lld\n"
                    "  expected t %s X (%s, %s, %s) pr (%s, %s, %s) md %s ovf %d tag %u\n"
                    "  actual   t %s X (%s, %s, %s) pr (%s, %s, %s) md %s ovf %d tag %u\n",
                    cycle, matched, it.seg, it.edited ? " (edited)" : "",
                    static_cast<unsigned long long>(it.m),
                    sim::to_string(it.si.alpha).c_str(), sim::to_string(it.si.beta).c_str(),
                    static_cast<int>(it.s.guide[0].mode), static_cast<long long>(it.s.guide[0].h),
                    static_cast<long long>(it.s.guide[0].a),
                    static_cast<long long>(it.s.guide[0].b),
                    static_cast<int>(it.s.guide[1].mode), static_cast<long long>(it.s.guide[1].h),
                    static_cast<long long>(it.s.guide[1].a),
                    static_cast<long long>(it.s.guide[1].b),
                    sim::to_string(w.t).c_str(), sim::to_string(w.X.x).c_str(),
                    sim::to_string(w.X.y).c_str(), sim::to_string(w.X.z).c_str(),
                    sim::to_string(w.pr.x).c_str(), sim::to_string(w.pr.y).c_str(),
                    sim::to_string(w.pr.z).c_str(), sim::to_string(w.md).c_str(), it.ovf, it.tag,
                    sim::to_string(t).c_str(), sim::to_string(x[0]).c_str(),
                    sim::to_string(x[1]).c_str(), sim::to_string(x[2]).c_str(),
                    sim::to_string(pr[0]).c_str(), sim::to_string(pr[1]).c_str(),
                    sim::to_string(pr[2]).c_str(), sim::to_string(md).c_str(), top->ovf_o,
                    static_cast<unsigned>(top->tag_o));
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
  std::printf("rpu_candidate metric %d: matched %ld items (%ld pairs edited, %ld of them long "
              "flat; %ld saturated, %ld with t < 0) in %ld cycles\n",
              METRIC, matched, n_edited, n_long, n_sat, n_neg, cycle);
  return 0;
}
