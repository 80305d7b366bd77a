// rpu_surface_ip (unrolled or iterative) against its twin rpu::ref::surface_ip, bit for bit: hit
// (the twin's !miss), τ_K, the overflow bit, the passed-through context and the latency
// (ref::surface_ip_latency) of every item, in order.
// Pieces: the setup twin's (ref::surface_setup) on every surface of scenes/surf_*.json at this
// build's parameters, for camera pixels, image-border pixels, grazing and range-plane rays, eyes
// inside the bounding sphere (camera_rays, inside_rays of tb_surface_common.h), also with the
// indicator fields redrawn within the indicator's port contract (overflowing lanes); pieces the
// setup finds empty go in with run_i = 0 and random lA', lB' − lA' (nothing may be flagged); and
// random pieces anywhere in the LW range. Random valid gaps, junk between items, ready_o
// honoured. RPU_VECTORS scales the counts; RPU_SEED sets the seed.
#include <algorithm>
#include <deque>
#include <memory>

#include "Vrpu_surface_ip.h"
#include "model/surface/rpu_surface_ip.h"
#include "model/surface/rpu_surface_latency.h"
#include "model/surface/rpu_surface_setup.h"
#include "tb_surface_common.h"

#ifndef RPU_SOURCE_DIR
#error "RPU_SOURCE_DIR must be defined (see sim/tests/surface/rpu_surface_ip.cmake)"
#endif
#ifndef IP_N
#define IP_N 16
#endif
#ifndef IP_N1
#define IP_N1 2
#endif
#ifndef UNROLLED
#define UNROLLED 0
#endif
#ifndef SURF_W
#define SURF_W 24
#endif
#ifndef ANGLE_W
#define ANGLE_W 20
#endif
#ifndef TURNS
#define TURNS 8
#endif
#ifndef CTX_W
#define CTX_W 24
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

ref::HwParams make_params() {
  ref::HwParams p;
  p.n = IP_N;
  p.n1 = IP_N1;
  p.unrolled = UNROLLED != 0;
  p.surf_w = SURF_W;
  p.angle_w = ANGLE_W;
  p.validate();
  return p;
}
const ref::HwParams kP = make_params();
const int LW = kP.surf_w;
constexpr int kCtxW = CTX_W, kTurns = TURNS;
const char* const kTypeName[] = {"ellipsoid", "relief", "spiral", "snail", "rocket"};
enum Kind { kScene, kEdited, kRandomPiece, kKinds };
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
  long issued = 0;
};

void drive_item(Vrpu_surface_ip& top, const Item& it) {
  top.run_i = it.su.valid;
  sim::PortBits la, lab;
  la.add(it.su.lA.x, LW);
  la.add(it.su.lA.y, LW);
  la.add(it.su.lA.z, LW);
  lab.add(it.su.lAB.x, LW + 1);
  lab.add(it.su.lAB.y, LW + 1);
  lab.add(it.su.lAB.z, LW + 1);
  la.to(top.la_i);
  lab.to(top.lab_i);
  top.x_negative_i = it.su.x_negative;
  top.last_turn_i = it.su.last_turn;
  sim::drive_indicator_fields(top, kP, *it.d);
  sim::put(top.ctx_i, it.ctx, kCtxW);
}

void drive_junk(Vrpu_surface_ip& top, std::mt19937_64& rng) {
  const auto r = [&](int w) { return sim::random_bits(rng, w); };
  top.run_i = static_cast<unsigned>(r(1));
  sim::PortBits la, lab;
  la.add(r(3 * LW), 3 * LW);
  lab.add(r(3 * (LW + 1)), 3 * (LW + 1));
  la.to(top.la_i);
  lab.to(top.lab_i);
  top.x_negative_i = static_cast<unsigned>(r(1));
  top.last_turn_i = static_cast<unsigned>(r(1));
  sim::drive_indicator_junk(top, kP, rng);
  sim::put(top.ctx_i, r(kCtxW), kCtxW);
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_surface_ip");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_surface_ip>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_surface_ip");
  std::mt19937_64 rng(seed);
  const long latency = ref::surface_ip_latency(kP);
  const long scale = std::max<long>(1, sim::vector_count(1));
  std::printf("tb_rpu_surface_ip: LW %d, AW %d, %d turn lanes, n %d, n1 %d, %s, latency %ld\n", LW,
              kP.angle_w, kTurns, kP.n, kP.n1, kP.unrolled ? "unrolled" : "iterative", latency);

  std::deque<scene::CompiledScene> scenes;
  const std::vector<sim::SurfCase> cases = sim::load_surface_cases(RPU_SOURCE_DIR, kP, scenes);
  for (const sim::SurfCase& S : cases)
    if (S.d.full_turns >= kTurns) {
      std::printf("FAILURE: %s: full_turns %d does not fit %d turn lanes\n", S.name.c_str(),
                  S.d.full_turns, kTurns);
      return 1;
    }

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
        Item it;
        it.kind = kind;
        it.surf = r.surf;
        it.ray = r;
        it.piece = piece;
        it.d = d;
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
      Item it;
      it.kind = kRandomPiece;
      it.surf = s;
      it.d = &S.d;
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

  long n_run = 0, n_hit = 0, n_ovf = 0, n_kind[kKinds] = {}, n_type_hit[5] = {},
       n_type_miss[5] = {};
  for (const Item& it : items) {
    const int t = static_cast<int>(it.d->type);
    ++n_kind[it.kind];
    n_run += it.su.valid;
    n_hit += it.hit;
    n_ovf += it.ovf;
    if (it.su.valid) ++(it.hit ? n_type_hit[t] : n_type_miss[t]);
  }
  std::printf("tb_rpu_surface_ip: %zu items (%ld scene pieces, %ld edited, %ld random): %ld run, "
              "%ld hits, %ld overflow\n  hit/missed per type:",
              items.size(), n_kind[kScene], n_kind[kEdited], n_kind[kRandomPiece], n_run, n_hit,
              n_ovf);
  for (int t = 0; t < 5; ++t) std::printf(" %s %ld/%ld,", kTypeName[t], n_type_hit[t], n_type_miss[t]);
  std::printf("\n");
  for (int t = 0; t < 5; ++t)
    if (n_type_hit[t] < 10 || n_type_miss[t] < 10) {
      std::printf("FAILURE: the vectors are too weak: %s has %ld hits and %ld misses\n",
                  kTypeName[t], n_type_hit[t], n_type_miss[t]);
      return 1;
    }
  if (n_ovf < 10 || n_run == static_cast<long>(items.size())) {
    std::printf("FAILURE: the vectors are too weak (under 10 overflows, or no empty piece)\n");
    return 1;
  }

  // ---- run ----
  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  size_t next = 0;
  long cycle = 0, matched = 0;
  const long total = static_cast<long>(items.size());
  while (matched < total) {
    const bool offer = next < items.size() && rng() % 100 < 85;
    top->valid_i = offer;
    if (offer) drive_item(*top, items[next]);
    else drive_junk(*top, rng);
    const bool taken = offer && top->ready_o;  // ready_o: registers only, settled
    sim::tick(*top, *ctx);
    if (taken) {
      Item it = items[next++];
      it.issued = cycle;
      expected.push_back(it);
    }
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no item outstanding\n", cycle);
        return 1;
      }
      const Item it = expected.front();
      expected.pop_front();
      const bool hit = top->hit_o, ovf = top->ovf_o;
      const auto tau = static_cast<std::uint64_t>(sim::get_unsigned(top->tau_o, kP.n));
      const auto got_ctx = static_cast<std::uint32_t>(sim::get_unsigned(top->ctx_o, kCtxW));
      if (hit != it.hit || ovf != it.ovf || tau != (it.hit ? it.tau : 0) || got_ctx != it.ctx ||
          cycle - it.issued != latency) {
        const ref::SurfaceDesc& d = *it.d;
        std::printf(
            "FAILURE cycle %ld item %ld: %s (%s), %s, %s ray, piece %d\n"
            "  inputs   run %d lA' %s lB'-lA' %s x_negative %d last_turn %d ctx %u\n"
            "           sx %lld sy %lld sz %lld r2 %s kd %lld ke2 %lld rho0 %lld a_turn %lld "
            "k_turn %lld full_turns %d a %lld b %lld fin %lld·2^-%d cone %lld·2^-%d\n"
            "  expected hit %d tau %llu ovf %d latency %ld\n"
            "  actual   hit %d tau %llu ovf %d latency %ld ctx %u\n",
            cycle, matched, cases[static_cast<size_t>(it.surf)].name.c_str(),
            kTypeName[static_cast<int>(d.type)], kKindName[it.kind],
            it.kind == kRandomPiece ? "no" : sim::kRaySourceName[it.ray.src], it.piece,
            it.su.valid, sim::str(it.su.lA).c_str(), sim::str(it.su.lAB).c_str(),
            it.su.x_negative, it.su.last_turn, it.ctx, static_cast<long long>(d.sx),
            static_cast<long long>(d.sy), static_cast<long long>(d.sz),
            sim::to_string(d.r2).c_str(), static_cast<long long>(d.kd),
            static_cast<long long>(d.ke2), static_cast<long long>(d.rho0),
            static_cast<long long>(d.a_turn), static_cast<long long>(d.k_turn), d.full_turns,
            static_cast<long long>(d.rocket_a), static_cast<long long>(d.rocket_b),
            static_cast<long long>(d.fin.m), d.fin.s, static_cast<long long>(d.cone.m), d.cone.s,
            it.hit, static_cast<unsigned long long>(it.hit ? it.tau : 0), it.ovf, latency, hit,
            static_cast<unsigned long long>(tau), ovf, cycle - it.issued, got_ctx);
        return 1;
      }
      ++matched;
    }
    if (cycle > 20 * total * (kP.K() + 2) + 4 * latency) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->valid_i = 0;
  for (long k = 0; k < latency + 8; ++k) {
    sim::tick(*top, *ctx);
    if (top->valid_o) {
      std::printf("FAILURE: valid_o after the last item\n");
      return 1;
    }
  }
  std::printf("tb_rpu_surface_ip: matched %ld items (%ld cycles)\n", matched, cycle);
  return 0;
}
