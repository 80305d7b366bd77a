// rpu_surface_ip (unrolled or iterative) against its twin rpu::ref::surface_ip, bit for bit: hit
// (the twin's !miss), τ_K, the overflow bit, the passed-through context and the latency
// (ref::surface_ip_latency) of every item, in order.
// Pieces: the setup twin's (ref::surface_setup) on every surface of scenes/surf_*.json at this
// build's parameters, for camera pixels, image-border pixels, grazing and range-plane rays, eyes
// inside the bounding sphere (camera_rays, inside_rays of tb_surface_common.h), also with the
// indicator fields redrawn within the indicator's port contract (overflowing lanes); pieces the
// setup finds empty go in with run_i = 0 and random lA', lB' − lA' (nothing may be flagged); and
// random pieces anywhere in the LW range. RPU_VECTORS scales the counts.
#include <algorithm>
#include <deque>
#include <vector>

#include "Vrpu_surface_ip.h"
#include "model/surface/rpu_surface_ip.h"
#include "model/surface/rpu_surface_latency.h"
#include "model/surface/rpu_surface_setup.h"
#include "tb_surface_common.h"

#ifndef TURNS
#define TURNS 8
#endif
#ifndef CTX_W
#define CTX_W 24
#endif

namespace {

const ref::HwParams kP = sim::tb_params();
const int LW = kP.surf_w;
constexpr int kCtxW = CTX_W, kTurns = TURNS;
const char* const* const kTypeName = sim::kSurfaceTypeName;
enum Kind { kScene, kEdited, kRandomPiece };
const char* const kKindName[] = {"scene piece", "edited descriptor", "random piece"};

struct Item {
  Kind kind = kScene;
  int surf = 0;
  sim::SurfRay ray;
  int piece = 0;
  const ref::SurfaceDesc* d = nullptr;
  ref::SurfaceSetupOut su;  // the piece (valid: run_i)
  bool hit = false, ovf = false;
  std::uint64_t tau = 0;
  std::uint32_t ctx = 0;
};

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_surface_ip> tb("tb_rpu_surface_ip", argc, argv);
  auto& rng = tb.rng;
  const long latency = ref::surface_ip_latency(kP, SURF_IND);
  const long scale = std::max<long>(1, tb.vectors(1));
  std::printf("tb_rpu_surface_ip: LW %d, AW %d, %d turn lanes, n %d, n1 %d, first step %d bits, "
              "%d indicators, %d passes, %s, latency %ld\n",
              LW, kP.angle_w, kTurns, kP.n, kP.n1, kP.surface_first_bits(),
              ref::surface_ip_lanes(kP, SURF_IND), ref::surface_ip_passes(kP, SURF_IND),
              kP.unrolled ? "unrolled" : "iterative", latency);

  std::deque<scene::CompiledScene> scenes;
  const std::vector<sim::SurfCase> cases = sim::load_surface_cases(kP, scenes);
  for (const sim::SurfCase& S : cases)
    if (S.d.full_turns >= kTurns)
      return tb.fail("%s: full_turns %d does not fit %d turn lanes", S.name.c_str(), S.d.full_turns,
                     kTurns);

  // ---- the items ----
  std::vector<Item> items;
  std::deque<ref::SurfaceDesc> edited;
  std::uint32_t id = 0;
  const std::uint32_t ctx_mask = static_cast<std::uint32_t>((1ull << kCtxW) - 1);
  const auto expect = [&](Item& it) {
    fixed::Overflow ovf;
    if (it.su.valid) {
      const ref::SurfaceIpState st = ref::surface_ip(kP, *it.d, it.su, ovf);
      it.hit = !st.miss;
      it.tau = st.tau;
    }
    it.ovf = ovf.flag;
    it.ctx = id++ & ctx_mask;
    items.push_back(it);
  };
  const auto add_rays = [&](Kind kind, const std::vector<sim::SurfRay>& rays) {
    for (const sim::SurfRay& r : rays) {
      const ref::SurfaceDesc* d = &cases[static_cast<size_t>(r.surf)].d;
      if (kind == kEdited) {
        edited.push_back(sim::edit_indicator_fields(*d, kP, kTurns, rng));
        d = &edited.back();
      }
      for (int piece : sim::piece_indices(*d, rng)) {
        Item it{.kind = kind, .surf = r.surf, .ray = r, .piece = piece, .d = d};
        fixed::Overflow setup_ovf;
        it.su = ref::surface_setup(kP, r.eye, r.vhat, *d, piece, setup_ovf);
        if (!it.su.valid) {  // junk the unit must ignore (run_i = 0)
          it.su.lA = {sim::random_magnitude(rng, LW), sim::random_magnitude(rng, LW),
                      sim::random_magnitude(rng, LW)};
          it.su.lAB = {sim::random_magnitude(rng, LW), sim::random_magnitude(rng, LW),
                       sim::random_magnitude(rng, LW)};
          it.su.x_negative = rng() % 2;
          it.su.last_turn = rng() % 2;
        }
        expect(it);
      }
    }
  };
  for (int s = 0; s < static_cast<int>(cases.size()); ++s) {
    const sim::SurfCase& S = cases[static_cast<size_t>(s)];
    std::vector<sim::SurfRay> rays, edit_rays;
    sim::camera_rays(kP, S, s, static_cast<int>(200 * scale), rng, rays);
    for (int e = 0; e < 4; ++e)
      sim::inside_rays(kP, sim::inside_eye(S, rng), s, static_cast<int>(10 * scale), rng, rays);
    sim::camera_rays(kP, S, s, static_cast<int>(100 * scale), rng, edit_rays);
    add_rays(kScene, rays);
    add_rays(kEdited, edit_rays);
    // Random pieces: lA', lB' anywhere in the LW range, the branch bits at random.
    for (int n = 0; n < 60 * scale; ++n) {
      Item it{.kind = kRandomPiece, .surf = s, .d = &S.d};
      const auto coord = [&] { return sim::random_magnitude(rng, LW); };
      const ref::WVec3 a{coord(), coord(), coord()}, b{coord(), coord(), coord()};
      it.su.valid = true;
      it.su.lA = a;
      it.su.lAB = b - a;
      it.su.x_negative = rng() % 2;
      it.su.last_turn = S.d.full_turns + 1 < kTurns && rng() % 2;
      expect(it);
    }
  }
  std::shuffle(items.begin(), items.end(), rng);  // mix the surfaces and kinds

  sim::Tally by_kind(kKindName, {"items", "run", "hits", "with overflow"});
  sim::Tally by_type(sim::kSurfaceTypeName, {"hits", "misses"});  // of the pieces run
  for (const Item& it : items) {
    by_kind.add(it.kind, 1, it.su.valid, it.hit, it.ovf);
    by_type.add(static_cast<int>(it.d->type), it.su.valid && it.hit, it.su.valid && !it.hit);
  }
  const long n_run = by_kind.total(1), n_ovf = by_kind.total(3);
  std::printf("tb_rpu_surface_ip: %zu items, %ld run, %ld overflow\n", items.size(), n_run, n_ovf);
  by_kind.print("per kind");
  by_type.print("pieces run per surface type");
  if (tb.weak(by_type.too_weak({0, 1}, 10))) return 1;
  if (n_ovf < 10 || n_run == static_cast<long>(items.size()))
    return tb.fail("the vectors are too weak (under 10 overflows, or no empty piece)");

  sim::Stream<Vrpu_surface_ip, Item> s{.latency = latency};
  s.inputs = [](sim::Inputs& in, Vrpu_surface_ip& t, const Item& it) {
    in("run", t.run_i, it.su.valid, 1).fields("lA'", t.la_i, std::array{it.su.lA.x, it.su.lA.y, it.su.lA.z}, LW);
    in.fields("lB' - lA'", t.lab_i, std::array{it.su.lAB.x, it.su.lAB.y, it.su.lAB.z}, LW + 1);
    in("x_negative", t.x_negative_i, it.su.x_negative, 1)("last_turn", t.last_turn_i, it.su.last_turn, 1);
    sim::indicator_inputs(in, t, kP, *it.d);
    in("ctx", t.ctx_i, it.ctx, kCtxW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_surface_ip& t, const Item& it) {
    o("hit", t.hit_o, it.hit, 1)("tau", t.tau_o, it.hit ? static_cast<i128>(it.tau) : 0, kP.n);
    o("ovf", t.ovf_o, it.ovf, 1)("ctx", t.ctx_o, it.ctx, kCtxW);
  };
  s.what = [&](const Item& it) {
    return cases[static_cast<size_t>(it.surf)].name + " (" + kTypeName[static_cast<int>(it.d->type)] +
           "), " + kKindName[it.kind] + ", " +
           (it.kind == kRandomPiece ? "no" : sim::kRaySourceName[it.ray.src]) + " ray, piece " +
           std::to_string(it.piece);
  };
  s.timeout = 20 * static_cast<long>(items.size()) * (kP.K() + 2) + 4 * latency;
  return tb.check(items, s);
}
