// rpu_ip_step (k at run time) against rpu::ref::ip_step: the real intermediate states of curve12
// pairs at every k, random valid gaps; every next-state field compared.
#include <algorithm>
#include <deque>
#include <memory>

#include "Vrpu_ip_step.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

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
  ref::IpState in;
  ref::IpState want;
  bool ovf;
  std::uint32_t id;
};

}  // namespace

int main(int argc, char** argv) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_ip_step>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_ip_step");
  std::mt19937_64 rng(seed);

  const scene::CompiledScene sc = scene::compile_scene(
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/curve12.json"));
  ref::HwParams p;
  p.n = IP_N;
  p.n1 = IP_N1;
  p.metric = METRIC == 0 ? ref::Metric::kAbs : ref::Metric::kSquared;
  p.unrolled = UNROLLED != 0;
  const ref::ModelScene m = ref::quantize_scene(sc, p);
  const int CW = p.coord_w, DW = CW + 1, TW = p.t_w(), UW = p.unit_w(), XW = CW + 3;
  const int MdW = METRIC == 0 ? CW + 4 : 2 * CW + 8;
  const long count = sim::vector_count(UNROLLED ? 20000 : 4000);

  std::deque<Item> items;
  std::uint32_t id = 0;
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
    fixed::Overflow o0;
    ref::IpState st = ref::ip_start(p, s, si, o0);
    for (int step = 1; step <= p.K(); ++step) {
      fixed::Overflow ovf;
      const ref::IpState next = ref::ip_step(p, s, si, st, ovf);
      if (rng() % 2 == 0 || step == p.K()) items.push_back({k, si, st, next, ovf.flag, id++});
      st = next;
    }
  }

  sim::reset(*top, *ctx);
  std::deque<Item> pending;
  long matched = 0, cycle = 0;
  const long total = static_cast<long>(items.size());
  const int CtxW = 32;
  while (matched < total) {
    const bool want_issue = !items.empty() && (rng() % 100) < 85;
    const bool ready = true;
    top->valid_i = want_issue;
    if (want_issue) {
      const Item& it = items.front();
      const ref::SegmentDesc& s = m.curve_segments[it.seg];
      sim::put_vec3(top->a_i, it.si.A.x, it.si.A.y, it.si.A.z, CW);
      sim::put_vec3(top->ab_i, it.si.AB.x, it.si.AB.y, it.si.AB.z, DW);
      sim::put(top->alpha_i, it.si.alpha, TW);
      sim::put(top->beta_i, it.si.beta, TW);
      sim::put_vec3(top->p1_i, s.p1.x, s.p1.y, s.p1.z, CW);
      sim::put_vec3(top->d_i, s.d.x, s.d.y, s.d.z, DW);
      sim::put(top->l2_i, s.L2, 2 * CW + 3);
      top->mode1_i = static_cast<unsigned>(s.guide[0].mode);
      sim::put(top->h1_i, s.guide[0].h, CW + 5);
      sim::put(top->a1_i, s.guide[0].a, CW);
      sim::put(top->b1_i, s.guide[0].b, p.t_frac);
      sim::put_vec3(top->u1_i, s.guide[0].u.x, s.guide[0].u.y, s.guide[0].u.z, UW);
      top->mode2_i = static_cast<unsigned>(s.guide[1].mode);
      sim::put(top->h2_i, s.guide[1].h, CW + 5);
      sim::put(top->a2_i, s.guide[1].a, CW);
      sim::put(top->b2_i, s.guide[1].b, p.t_frac);
      sim::put_vec3(top->u2_i, s.guide[1].u.x, s.guide[1].u.y, s.guide[1].u.z, UW);
      sim::put(top->ctx_i, it.id, CtxW);
      top->k_i = static_cast<unsigned>(it.in.k + 1);
      {
        // state_i = {tau, lo.t, lo.X, lo.md, hi.md}
        const int StW = p.n + TW + 3 * XW + 2 * MdW;
        for (size_t w = 0; w < sizeof(top->state_i) / sizeof(top->state_i[0]); ++w) top->state_i[w] = 0;
        int at = StW;
        const auto put_field = [&](i128 v, int w) {
          at -= w;
          for (int b = 0; b < w; ++b)
            if ((static_cast<fixed::u128>(v) >> b) & 1)
              top->state_i[static_cast<size_t>((at + b) / 32)] |= 1u << ((at + b) % 32);
        };
        put_field(static_cast<i128>(it.in.tau), p.n);
        put_field(it.in.lo.t, TW);
        put_field(it.in.lo.X.z, XW);
        put_field(it.in.lo.X.y, XW);
        put_field(it.in.lo.X.x, XW);
        put_field(it.in.lo.md, MdW);
        put_field(it.in.hi.md, MdW);
      }
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
      const int StW = p.n + TW + 3 * XW + 2 * MdW;
      const auto field = [&](int hi_bit, int width) {
        // state_o packs {tau, lo.t, lo.X, lo.md, hi.md}; read `width` bits below hi_bit.
        fixed::u128 u = 0;
        for (int b = 0; b < width; ++b) {
          const int bit = hi_bit - width + 1 + b;
          const bool v = (top->state_o[static_cast<size_t>(bit / 32)] >> (bit % 32)) & 1;
          if (v) u |= fixed::u128{1} << b;
        }
        return u;
      };
      const auto sext = [](fixed::u128 u, int w) {
        const fixed::u128 sign = fixed::u128{1} << (w - 1);
        return static_cast<i128>((u ^ sign) - sign);
      };
      int at = StW - 1;
      const i128 tau = static_cast<i128>(field(at, p.n));
      at -= p.n;
      const i128 lo_t = sext(field(at, TW), TW);
      at -= TW;
      i128 x[3];
      for (int c = 2; c >= 0; --c) {  // {z, y, x}
        x[c] = sext(field(at, XW), XW);
        at -= XW;
      }
      const i128 lo_md = static_cast<i128>(field(at, MdW));
      at -= MdW;
      const i128 hi_md = static_cast<i128>(field(at, MdW));
      const ref::IpState& w = it.want;
      const std::uint32_t got_id = static_cast<std::uint32_t>(top->ctx_o);
      const bool ok = tau == static_cast<i128>(w.tau) && lo_t == w.lo.t && x[0] == w.lo.X.x &&
                      x[1] == w.lo.X.y && x[2] == w.lo.X.z && lo_md == w.lo.md &&
                      hi_md == w.hi.md && static_cast<bool>(top->ovf_o) == it.ovf &&
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
                    sim::to_string(tau).c_str(), sim::to_string(lo_t).c_str(),
                    sim::to_string(x[0]).c_str(), sim::to_string(x[1]).c_str(),
                    sim::to_string(x[2]).c_str(), sim::to_string(lo_md).c_str(),
                    sim::to_string(hi_md).c_str(), top->ovf_o);
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
  std::printf("rpu_ip_step n=%d n1=%d metric %d %s: matched %ld items in %ld cycles (%.3f items/cycle)\n",
              IP_N, IP_N1, METRIC, UNROLLED ? "unrolled" : "iterative", matched, cycle,
              static_cast<double>(matched) / cycle);
  return 0;
}
