// rpu_candidate against rpu::ref::candidate_evaluator: real search intervals of curve12 (every
// segment, pixels around its projection), random and edge τ indices, random valid gaps.
#include <algorithm>
#include <deque>
#include <memory>

#include "Vrpu_candidate.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

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
  const int CW = p.coord_w, DW = CW + 1, TW = p.t_w(), UW = p.unit_w();
  const long count = sim::vector_count(100000);

  std::deque<Item> items;
  while (static_cast<long>(items.size()) < count) {
    const size_t k = rng() % m.curve_segments.size();
    const ref::SegmentDesc& s = m.curve_segments[k];
    int ci, cj;
    const Vec3 world = scene::curve_point(sc.curve_segments[k].geom,
                                          std::uniform_real_distribution<double>(0, 1)(rng));
    if (!scene::project_to_pixel(sc.camera, world, ci, cj)) continue;
    ci = std::clamp(ci + static_cast<int>(rng() % 5) - 2, 0, m.camera.width - 1);
    cj = std::clamp(cj + static_cast<int>(rng() % 5) - 2, 0, m.camera.height - 1);
    const ref::RayGenOut ray = ref::ray_generator(p, m.camera, ci, cj);
    fixed::Overflow o;
    const ref::SearchInterval si = ref::sphere_unit(p, m.camera.eye, ray.vhat, s, o);
    if (!si.pred1) continue;
    for (int r = 0; r < 8; ++r) {
      const std::uint64_t full = std::uint64_t{1} << p.n;
      const std::uint64_t edges[] = {0, full, 1, full - 1, full / 2};
      const std::uint64_t mm = r < 2 ? edges[rng() % 5] : rng() % (full + 1);
      fixed::Overflow ovf;
      Item it{k, si, mm, ref::candidate_evaluator(p, s, si, mm, ovf), false};
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
      const ref::SegmentDesc& s = m.curve_segments[it.seg];
      sim::put(top->m_i, static_cast<i128>(it.m), p.n + 1);
      sim::put_vec3(top->a_i, it.si.A.x, it.si.A.y, it.si.A.z, CW);
      sim::put_vec3(top->ab_i, it.si.AB.x, it.si.AB.y, it.si.AB.z, DW);
      sim::put(top->alpha_i, it.si.alpha, TW);
      sim::put(top->beta_i, it.si.beta, TW);
      sim::put_vec3(top->p1_i, s.p1.x, s.p1.y, s.p1.z, CW);
      sim::put_vec3(top->d_i, s.d.x, s.d.y, s.d.z, DW);
      sim::put(top->l2_i, s.L2, 2 * CW + 3);
      const ref::GuideDesc& g1 = s.guide[0];
      const ref::GuideDesc& g2 = s.guide[1];
      top->mode1_i = static_cast<unsigned>(g1.mode);
      sim::put(top->h1_i, g1.h, CW + 5);
      sim::put(top->a1_i, g1.a, CW);
      sim::put(top->b1_i, g1.b, p.t_frac);
      sim::put_vec3(top->u1_i, g1.u.x, g1.u.y, g1.u.z, UW);
      top->mode2_i = static_cast<unsigned>(g2.mode);
      sim::put(top->h2_i, g2.h, CW + 5);
      sim::put(top->a2_i, g2.a, CW);
      sim::put(top->b2_i, g2.b, p.t_frac);
      sim::put_vec3(top->u2_i, g2.u.x, g2.u.y, g2.u.z, UW);
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
